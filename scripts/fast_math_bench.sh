#!/usr/bin/env bash
# Microbenchmark of brachistochrone_fast_math, the old version against the current one in
# one run (ns per call, median of 7 passes of 200000 calls, CPU time; each call's
# argument depends on the previous result, as in the engine's nodes):
#
#     bash scripts/fast_math_bench.sh [OLD_REV]     (default 23b1243, before session 8)
#
# builds the module at OLD_REV (renamed fm_old) and the working tree's (fm_new) with
# gfortran -O3 -funroll-loops as fpm's release profile, separately compiled like the
# library's callers (no inlining across modules). The fast_sqrt/inverse_sqrt chains
# include one binary128 addition per call (x = f(v(i) + x)), timed alone on its own line.
set -euo pipefail
cd "$(dirname "$0")/.."
rev=${1:-23b1243}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
git show "$rev:src/numerics/brachistochrone_fast_math.f90" \
    | sed 's/brachistochrone_fast_math/fm_old/g' > "$dir/fm_old.f90"
sed 's/brachistochrone_fast_math/fm_new/g' src/numerics/brachistochrone_fast_math.f90 \
    > "$dir/fm_new.f90"
cp src/brachistochrone_kinds.f90 scripts/fast_math_bench.f90 "$dir/"
cd "$dir"
flags="-O3 -funroll-loops -fPIC"
for f in brachistochrone_kinds fm_old fm_new fast_math_bench; do gfortran $flags -c $f.f90; done
gfortran $flags -o bench fast_math_bench.o fm_old.o fm_new.o brachistochrone_kinds.o
./bench
