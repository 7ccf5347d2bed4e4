#!/usr/bin/env bash
# The general engine against the inverse-square fast path, every field in one go:
#
#     bash scripts/engine_table.sh [REPEATS]
#
# runs `engine-timing FIELD N REPEATS extreme` (fpm example, release build; CPU time,
# one thread, the same 30 endpoints scaled to each sector, each time the median of
# REPEATS passes, default 3) for the power laws n = 1 + 1e-6, 1.1, 1.5, 2, 3, 6, 10, 32,
# the logarithmic law and the harmonic law through the engine, and prints one markdown
# table: us per endpoint, the ratio to the fast path measured in the same run, the
# slowest grid endpoint and the worst of the 15 extreme endpoints over the grid's median,
# unsolved endpoints and the model build.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$PWD/.venv/bin:$PATH"
repeats=${1:-3}
fpm build --profile release > /dev/null 2>&1
exe=$(fpm run --profile release --example engine-timing --runner echo 2>/dev/null | tail -1)
echo "| field | us/endpoint | fast path us | ratio | slowest / median | worst extreme / median | unsolved | model build s |"
echo "|---|---|---|---|---|---|---|---|"
for spec in "power 1.000001" "power 1.1" "power 1.5" "power 2" "power 3" "power 6" \
            "power 10" "power 32" "logarithmic 0" "harmonic 0"; do
    set -- $spec
    "$exe" "$1" "$2" "$repeats" extreme | awk -v field="$1" -v n="$2" '
        /general engine, mean s per endpoint/ { general = $NF * 1e6 }
        /fast path, mean s per endpoint/      { fast = $NF * 1e6 }
        /ratio general\/fast/                 { ratio = $NF }
        /slowest endpoint/                    { slowest = $NF }
        /endpoints not solved/                { unsolved = $NF }
        /model build, s =/                    { split($0, b, "= "); split(b[2], c, " "); build = c[1] }
        /worst extreme endpoint/              { extreme = $NF }
        END {
            name = (field == "power") ? "power n = " n : field
            if (field == "harmonic") name = "harmonic law through the engine"
            printf "| %s | %.1f | %.1f | %s | %s | %s | %s | %s |\n", name, general, fast, \
                ratio, slowest, extreme, unsolved, build
        }'
done
