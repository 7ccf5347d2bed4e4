#!/usr/bin/env bash
# Regenerate src/fields/brachistochrone_inverse_square_tables.f90 (the inverse-square
# model's whole-half-arch tables as constants) from the quadrature, then check that the
# library rebuilt with it passes the tests of the tables:
#
#     bash scripts/make_inverse_square_tables.sh
#
# Run it after changing the whole-half-arch integrands, rules or table layout in
# brachistochrone_inverse_square (the test "shipped inverse-square tables" fails until then).
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$PWD/.venv/bin:$PATH"
out=src/fields/brachistochrone_inverse_square_tables.f90
tmp=$(mktemp "$out.XXXXXX")
trap 'rm -f "$tmp"' EXIT
fpm run --profile release --example inverse-square-tables > "$tmp"
grep -q '^end module brachistochrone_inverse_square_tables$' "$tmp"
mv "$tmp" "$out"
trap - EXIT
echo "wrote $out"
