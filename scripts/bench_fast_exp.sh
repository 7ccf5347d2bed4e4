#!/usr/bin/env bash
# fast_exp and fast_expm1 (src/numerics/brachistochrone_fast_exp.f90) against their
# version at a git revision and libquadmath: speed and accuracy.
#
#     bash scripts/bench_fast_exp.sh [REV [COUNT]]     (REV default main, COUNT 100000)
#
# Builds example/fast_exp_bench/fast_exp_bench.f90 with gfortran -O3 (as fpm's release
# profile) against the working tree's modules and REV's fast_exp module (renamed
# old_fast_exp) in a temporary directory, prints ns per call for each range of |x|, then
# the worst errors in ulps of the new, old and libquadmath exp and expm1 against mpmath
# (scripts/check_fast_exp.py) at COUNT arguments: |x| log-uniform over 1e-30 .. 11000, both
# signs, a seventh of them next to the reduction's switches.
set -euo pipefail
cd "$(dirname "$0")/.."
rev=${1:-main}
count=${2:-100000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
git show "$rev:src/numerics/brachistochrone_fast_exp.f90" |
    sed -e 's/^module brachistochrone_fast_exp$/module old_fast_exp/' \
        -e 's/^end module brachistochrone_fast_exp$/end module old_fast_exp/' > "$work/old_fast_exp.f90"
flags="-O3 -funroll-loops -fPIC"
for source in src/brachistochrone_kinds.f90 src/numerics/brachistochrone_quad_math.f90 \
              src/numerics/brachistochrone_fast_math.f90 \
              src/numerics/brachistochrone_fast_exp_tables.f90 \
              src/numerics/brachistochrone_fast_exp.f90 "$work/old_fast_exp.f90"; do
    [ -f "$source" ] || continue
    gfortran $flags -J "$work" -c "$source" -o "$work/$(basename "$source" .f90).o"
done
gfortran $flags -I "$work" example/fast_exp_bench/fast_exp_bench.f90 "$work"/*.o \
    -lquadmath -o "$work/fast_exp_bench"
echo "ns per call (CPU time, median of 7 passes; old = $rev):"
"$work/fast_exp_bench" bench
.venv/bin/python scripts/check_fast_exp.py "$work/fast_exp_bench" "$count"
