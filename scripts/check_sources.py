#!/usr/bin/env python3
"""Check that fpm and CMake compile the same library and program sources.

    python3 scripts/check_sources.py FPM_COMPILE_COMMANDS CMAKE_COMPILE_COMMANDS

Both builds write compile_commands.json (fpm: build/compile_commands.json; CMake with
CMAKE_EXPORT_COMPILE_COMMANDS). The Fortran files under src/ (the library) and app/
(the program) that each compiles must be the same sets, and every such file in the
tree must be compiled. Exit 0 if so, else 1 with the differences.
"""
import json
import os
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]


def compiled(path):
    """Repository-relative paths of the files under src/ and app/ in a compile database."""
    files = set()
    for entry in json.loads(pathlib.Path(path).read_text()):
        name = pathlib.Path(entry["file"])
        if not name.is_absolute():
            name = pathlib.Path(entry.get("directory", ROOT)) / name
        relative = pathlib.Path(os.path.normpath(name)).resolve().relative_to(ROOT)
        if relative.parts[0] in ("src", "app"):
            files.add(relative.as_posix())
    return files


def main(fpm_db, cmake_db):
    fpm, cmake = compiled(fpm_db), compiled(cmake_db)
    tree = {p.relative_to(ROOT).as_posix() for d in ("src", "app")
            for p in (ROOT / d).rglob("*") if p.suffix in (".f90", ".F90")}
    problems = [f"only fpm compiles {f}" for f in sorted(fpm - cmake)]
    problems += [f"only CMake compiles {f}" for f in sorted(cmake - fpm)]
    problems += [f"neither build compiles {f}" for f in sorted(tree - fpm - cmake)]
    for line in problems:
        print("check_sources: " + line, file=sys.stderr)
    if not problems:
        print(f"check_sources: fpm and CMake compile the same {len(fpm)} files "
              f"under src/ and app/")
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
