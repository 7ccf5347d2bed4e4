#!/usr/bin/env bash
# Run every test: the Fortran unit tests (fpm test, debug profile with bounds checks),
# the end-to-end Python tests of the built program (pytest, SciPy/mpmath oracles), and
# the CMake build and the examples (scripts/examples.sh: ctest, fpm/C/CMake/Python users).
# Needs scripts/setup.sh to have run once. Exit status non-zero if anything failed.
set -uo pipefail
cd "$(dirname "$0")/.."
if [ ! -x .venv/bin/fpm ]; then
    echo "test: .venv is missing; run: bash scripts/setup.sh --no-run" >&2
    exit 1
fi
export PATH="$PWD/.venv/bin:$PATH"

fpm test 2>&1 | grep -v '^\['
fortran_status=${PIPESTATUS[0]}

python -m pytest -q test/python
python_status=$?

bash scripts/examples.sh
examples_status=$?

if [ "$fortran_status" -ne 0 ] || [ "$python_status" -ne 0 ] || [ "$examples_status" -ne 0 ]; then
    echo "test: FAILED (fpm test exit $fortran_status, pytest exit $python_status," \
         "examples exit $examples_status)" >&2
    exit 1
fi
