#!/usr/bin/env bash
# Merge the CSV outputs of slices of one table (brachistochrone --first I --last J) into
# one CSV, in the order given: the first file's provenance comments and header, then
# every file's data rows. The headers must agree. Writes to a temporary file and renames.
# Usage: bash scripts/merge_csv.sh OUT.csv PART1.csv PART2.csv ...
set -euo pipefail
if [ $# -lt 2 ]; then
    echo "usage: $0 OUT.csv PART1.csv [PART2.csv ...]" >&2
    exit 1
fi
out=$1
shift
header=$(grep -v -m1 '^#' "$1")
for part in "$@"; do
    this=$(grep -v -m1 '^#' "$part")
    if [ "$this" != "$header" ]; then
        echo "merge_csv: $part has header '$this', expected '$header'" >&2
        exit 1
    fi
done
tmp="$out.tmp$$"
trap 'rm -f "$tmp"' EXIT
{
    grep '^#' "$1"
    echo "# merged from: $*"
    echo "$header"
    for part in "$@"; do
        grep -v '^#' "$part" | tail -n +2
    done
} > "$tmp"
mv "$tmp" "$out"
trap - EXIT
