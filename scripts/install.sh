#!/usr/bin/env bash
# Install with fpm, plus what fpm 0.12 does not install (fortran-lang/fpm issue 996):
# the C header and a pkg-config file.
#   bash scripts/install.sh PREFIX
# PREFIX/bin/brachistochrone, PREFIX/lib/libbrachistochrone.a, PREFIX/include/*.mod (all
# from `fpm install --profile release --no-prune --prefix PREFIX`; --no-prune keeps the
# modules no program uses in the library), PREFIX/include/brachistochrone.h and
# PREFIX/lib/pkgconfig/brachistochrone.pc. The CMake build installs the same and a
# shared library and CMake package (README, "Install and use as a library").
set -euo pipefail
if [ $# -ne 1 ]; then
    echo "usage: $0 PREFIX" >&2
    exit 1
fi
cd "$(dirname "$0")/.."
mkdir -p "$1"
prefix=$(cd "$1" && pwd)
fpm=fpm
[ -x .venv/bin/fpm ] && fpm=.venv/bin/fpm
"$fpm" install --profile release --no-prune --prefix "$prefix"
install -d "$prefix/include" "$prefix/lib/pkgconfig"
install -m 644 include/brachistochrone.h "$prefix/include/"
version=$(sed -n 's/^version *= *"\(.*\)"/\1/p' fpm.toml | head -1)
description=$(sed -n 's/^description *= *"\(.*\)"/\1/p' fpm.toml | head -1)
sed -e "s|@CMAKE_INSTALL_PREFIX@|$prefix|" -e 's|@CMAKE_INSTALL_LIBDIR@|lib|' \
    -e 's|@CMAKE_INSTALL_INCLUDEDIR@|include|' \
    -e 's|@BRACHISTOCHRONE_MODULE_INSTALL_DIR@|include|' \
    -e "s|@PROJECT_DESCRIPTION@|$description|" -e "s|@PROJECT_VERSION@|$version|" \
    cmake/brachistochrone.pc.in > "$prefix/lib/pkgconfig/brachistochrone.pc"
echo "install: $prefix (add $prefix/bin to PATH)"
