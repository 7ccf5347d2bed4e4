#!/usr/bin/env bash
# Build (when needed) and run the MPI driver on one endpoint table:
#   bash scripts/mpi.sh NP FILE.nml [brachistochrone options]
# Needs OpenMPI (scripts/setup.sh installs libopenmpi-dev and openmpi-bin from apt).
# The package in mpi/ is built with the MPI compiler wrapper (FPM_FC=mpifort): fpm's
# `mpi` metapackage crashes in the PyPI build of fpm 0.12 (fortran-lang/fpm issue 1207).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [ $# -lt 2 ]; then
    echo "usage: $0 NP FILE.nml [options]" >&2
    exit 1
fi
np=$1
shift
fpm="$root/.venv/bin/fpm"
if ! log=$(cd "$root/mpi" && FPM_FC=mpifort "$fpm" build --profile release 2>&1); then
    echo "$log" >&2
    exit 1
fi
exe=$(cd "$root/mpi" && FPM_FC=mpifort "$fpm" run --profile release --runner echo \
      brachistochrone-mpi 2>/dev/null | tail -n 1)
extra=(--oversubscribe)
if [ "$(id -u)" -eq 0 ]; then extra+=(--allow-run-as-root); fi
exec mpirun "${extra[@]}" -np "$np" "$root/mpi/$exe" "$@"
