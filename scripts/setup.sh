#!/usr/bin/env bash
# Set up everything on a fresh Debian machine, then run the main job on a shipped example.
#   - gfortran from apt (and python3-venv if the venv module is missing); OpenMPI from apt
#     (libopenmpi-dev, openmpi-bin) for the MPI driver in mpi/; cmake, pkg-config and gcc
#     for the CMake build and the examples (scripts/examples.sh)
#   - fpm and the Python test packages from PyPI into ./.venv (requirements.txt)
#   - build the release program and run data/table1.nml (Tee 1998, Table 1)
# Usage: bash scripts/setup.sh [--no-run]
set -euo pipefail
cd "$(dirname "$0")/.."

run_example=1
[ "${1:-}" = "--no-run" ] && run_example=0

as_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }

missing=()
command -v gfortran >/dev/null 2>&1 || missing+=(gfortran)
command -v python3 >/dev/null 2>&1 || missing+=(python3)
command -v mpifort >/dev/null 2>&1 || missing+=(libopenmpi-dev)
command -v mpirun >/dev/null 2>&1 || missing+=(openmpi-bin)
command -v cmake >/dev/null 2>&1 || missing+=(cmake)            # the CMake build, examples
command -v pkg-config >/dev/null 2>&1 || missing+=(pkg-config)  # example/c_user
command -v gcc >/dev/null 2>&1 || missing+=(gcc)
if ! python3 -c 'import venv, ensurepip' >/dev/null 2>&1; then missing+=(python3-venv); fi
if [ ${#missing[@]} -gt 0 ]; then
    echo "setup: installing ${missing[*]} from apt" >&2
    as_root apt-get update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >/dev/null
fi

if [ ! -x .venv/bin/python ]; then
    echo "setup: creating .venv" >&2
    python3 -m venv .venv
fi
if ! .venv/bin/python -m pip install -q --disable-pip-version-check -r requirements.txt; then
    echo "setup: pip install failed; is PyPI reachable?" >&2
    exit 1
fi

echo "setup: building (fpm, release profile)" >&2
.venv/bin/fpm build --profile release >/dev/null

if [ "$run_example" = 1 ]; then
    echo "setup: running data/table1.nml" >&2
    .venv/bin/fpm run --profile release brachistochrone -- data/table1.nml
fi
