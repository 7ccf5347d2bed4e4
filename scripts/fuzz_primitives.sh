#!/usr/bin/env bash
# Adversarial fuzz of the binary128 primitives (fast_sqrt, inverse_sqrt, hardware_real,
# quad_real, double_real, fast_exp, fast_expm1) against exact integer arithmetic, mpmath
# and gfortran's conversions (scripts/fuzz_primitives.py says what each check covers).
#
#     bash scripts/fuzz_primitives.sh [SEED [COUNT]]      (about 2 minutes at 20000)
#     X87_PC=53 bash scripts/fuzz_primitives.sh           (x87 precision control at 53
#     ROUND=up bash scripts/fuzz_primitives.sh             bits; rounding upward: failures
#                                                          expected, see the modules)
#
# Builds scripts/fuzz_primitives_harness.f90 with the release profile's flags against the
# working tree's modules in a temporary directory.
set -euo pipefail
cd "$(dirname "$0")/.."
seed=${1:-1}
count=${2:-20000}
python=.venv/bin/python
[ -x "$python" ] || python=python3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
flags="-O3 -funroll-loops -fPIC -fopenmp"
for source in src/brachistochrone_kinds.f90 src/numerics/brachistochrone_quad_math.f90 \
              src/numerics/brachistochrone_fast_math.f90 \
              src/numerics/brachistochrone_fast_exp_tables.f90 \
              src/numerics/brachistochrone_fast_exp.f90; do
    gfortran $flags -J "$work" -c "$source" -o "$work/$(basename "$source" .f90).o"
done
gcc -O2 -c scripts/fuzz_primitives_env.c -o "$work/env.o"
gfortran $flags -I "$work" scripts/fuzz_primitives_harness.f90 "$work"/*.o -lquadmath -lm \
    -o "$work/harness"
for check in conversions roots exp exp-edges; do
    echo "== $check"
    "$python" scripts/fuzz_primitives.py "$work/harness" "$check" "$seed" "$count"
done
