#!/usr/bin/env bash
# Build and run, as a new user would, everything README "Install and use as a library"
# describes; each example checks its own results against independent values (Tee's
# Table 1 as published, closed forms) and prints "NAME: ok". Called by scripts/test.sh.
#   1. CMake: configure, build (static and shared library, program, tests), ctest,
#      install into a temporary prefix; fpm and CMake compile the same sources.
#   2. example/cmake_user: find_package(brachistochrone) against that prefix.
#   3. example/c_user: gcc against the installed header, static and shared library.
#   4. example/python: ctypes on NumPy arrays, brachistochrone_solve_many.
#   5. example/fpm_user: an fpm project with its own quadrature/roots/strings modules
#      that depends on this package by path.
#   6. scripts/install.sh (fpm install --prefix, the header, pkg-config), c_user against
#      it, then the README's Slurm snippet as written (on a small table) and the merge.
# Usage: bash scripts/examples.sh        Exit status non-zero if anything failed.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
export PATH="$root/.venv/bin:$PATH"
work=$(mktemp -d "${TMPDIR:-/tmp}/brachistochrone-examples.XXXXXX")
trap 'rm -rf "$work"' EXIT
version=$(sed -n 's/^version *= *"\(.*\)"/\1/p' fpm.toml | head -1)

step() { echo "examples: $*"; }
# Run a command with its output in a log, shown only if it fails.
quiet() {
    local log="$work/log.$RANDOM"
    if ! "$@" >"$log" 2>&1; then
        cat "$log" >&2
        echo "examples: FAILED: $*" >&2
        exit 1
    fi
}
# Run an example; it must exit 0 and print the line "$1: ok".
expect_ok() {
    local name=$1
    shift
    local out
    if ! out=$("$@" 2>&1) || ! grep -qx "$name: ok" <<<"$out"; then
        echo "$out" >&2
        echo "examples: FAILED: $name ($*)" >&2
        exit 1
    fi
    echo "$out" | sed 's/^/    /'
}

step "CMake build, ctest and install (prefix $work/prefix)"
quiet cmake -S . -B "$work/build" -DCMAKE_INSTALL_PREFIX="$work/prefix"
quiet cmake --build "$work/build" -j 2
quiet ctest --test-dir "$work/build" --output-on-failure
quiet cmake --install "$work/build"
step "fpm and CMake compile the same sources"
quiet fpm build --profile release
python3 scripts/check_sources.py "$work/build"

step "example/cmake_user: find_package(brachistochrone)"
quiet cmake -S example/cmake_user -B "$work/cmake_user" -DCMAKE_PREFIX_PATH="$work/prefix"
quiet cmake --build "$work/cmake_user"
expect_ok cmake_user "$work/cmake_user/cmake_user"

step "example/c_user: gcc, installed header, static and shared library (pkg-config)"
export PKG_CONFIG_PATH="$work/prefix/lib/pkgconfig"
lib="$work/prefix/lib"
cc=(gcc -std=c11 -pthread -Wall -Wextra -O2 example/c_user/main.c)
# shellcheck disable=SC2046
quiet "${cc[@]}" $(pkg-config --cflags brachistochrone) "$lib/libbrachistochrone.a" \
    -lgfortran -lquadmath -lgomp -lm -o "$work/c_user_static"
# shellcheck disable=SC2046
quiet "${cc[@]}" $(pkg-config --cflags --libs brachistochrone) -lquadmath -lm \
    -Wl,-rpath,"$lib" -o "$work/c_user_shared"
expect_ok c_user "$work/c_user_static"
expect_ok c_user "$work/c_user_shared"

step "example/python: ctypes and NumPy on the shared library"
expect_ok python python example/python/solve_many.py "$lib/libbrachistochrone.so"

step "example/fpm_user: its own quadrature, roots, strings modules; the package by path"
(cd example/fpm_user && quiet fpm build --profile release)
expect_ok fpm_user bash -c 'cd example/fpm_user && fpm run --profile release 2>/dev/null'
user_output=$(cd example/fpm_user && fpm run --profile release 2>/dev/null)
grep -qx "library version $version" <<<"$user_output"

step "fpm install --prefix (scripts/install.sh), PATH, and the README's Slurm snippet"
quiet bash scripts/install.sh "$work/fpm"
test -f "$work/fpm/bin/brachistochrone"
test -f "$work/fpm/lib/libbrachistochrone.a"
test -f "$work/fpm/include/brachistochrone.mod"
# the whole library: one object per source file under src/
test "$(ar t "$work/fpm/lib/libbrachistochrone.a" | wc -l)" -eq "$(find src -name '*.[fF]90' | wc -l)"
# shellcheck disable=SC2046
quiet "${cc[@]}" $(PKG_CONFIG_PATH="$work/fpm/lib/pkgconfig" pkg-config --static --cflags \
    --libs brachistochrone) -o "$work/c_user_fpm"
expect_ok c_user "$work/c_user_fpm"
mkdir "$work/slurm"
rows=40
python3 scripts/make_table.py "$rows" "$work/slurm/big.nml"
snippet=$(sed -n '/^ *#SBATCH --array/,/--unsolved-ok$/p' README.md | sed 's/^ *//')
grep -q '^#SBATCH --array=1-10$' <<<"$snippet"
(
    cd "$work/slurm"
    export PATH="$work/fpm/bin:$PATH"
    test "$(command -v brachistochrone)" = "$work/fpm/bin/brachistochrone"
    for k in 1 2 3 4 5 6 7 8 9 10; do
        SLURM_ARRAY_TASK_ID=$k bash -euc "$snippet"
    done
    brachistochrone merge merged.csv part{10..1}.csv
    grep -qx "# input: big.nml, rows 1 to $rows of $rows" merged.csv
    brachistochrone big.nml --csv whole.csv --no-table --quiet
    diff <(grep -v '^#' merged.csv) <(grep -v '^#' whole.csv)
    test "$(brachistochrone --version)" = "brachistochrone $version"
)
echo "    the Slurm array over 10 slices of $rows rows equals one run"
step "all examples passed"
