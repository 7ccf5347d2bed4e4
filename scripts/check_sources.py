#!/usr/bin/env python3
"""Check that fpm and CMake compile the same library and program sources.

    python3 scripts/check_sources.py CMAKE_BUILD_DIR

fpm's list is the objects of `fpm build --profile release --no-prune --list` (named
after the source path with "/" turned into "_"; --no-prune as for `fpm install`, which
otherwise leaves modules that no program of the package uses out of the library); CMake's is the compile_commands.json of its build
directory (CMAKE_EXPORT_COMPILE_COMMANDS). The Fortran files under src/ (the library) and
app/ (the program) that each compiles must be the same, and every such file in the tree
must be compiled. Exit 0 if so, else 1 with the differences.
"""
import json
import os
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
FPM = ROOT / ".venv" / "bin" / "fpm"


def mangled(relative):
    """fpm's object name for a source path relative to the package root."""
    return relative.replace("/", "_")


def fpm_objects():
    out = subprocess.run([str(FPM) if FPM.exists() else "fpm", "build", "--profile", "release",
                          "--no-prune", "--list"], cwd=ROOT, check=True, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True).stdout  # fpm lists on stderr
    names = set()
    for line in out.split():
        match = re.search(r"/brachistochrone/((?:src|app)_.*\.[fF]90)\.o$", line)
        if match:
            names.add(match.group(1))
    return names


def cmake_files(build_dir):
    files = set()
    database = pathlib.Path(build_dir) / "compile_commands.json"
    for entry in json.loads(database.read_text()):
        name = pathlib.Path(entry["file"])
        if not name.is_absolute():
            name = pathlib.Path(entry["directory"]) / name
        relative = pathlib.Path(os.path.normpath(name)).resolve().relative_to(ROOT)
        if relative.parts[0] in ("src", "app"):
            files.add(relative.as_posix())
    return files


def main(build_dir):
    tree = sorted(p.relative_to(ROOT).as_posix() for d in ("src", "app")
                  for p in (ROOT / d).rglob("*") if p.suffix in (".f90", ".F90"))
    by_name = {mangled(f): f for f in tree}
    problems = []
    if len(by_name) != len(tree):
        problems.append("two source paths give the same fpm object name")
    fpm = fpm_objects()
    cmake = {mangled(f) for f in cmake_files(build_dir)}
    for name in sorted(fpm - cmake):
        problems.append(f"only fpm compiles {by_name.get(name, name)}")
    for name in sorted(cmake - fpm):
        problems.append(f"only CMake compiles {by_name.get(name, name)}")
    for name in sorted(set(by_name) - fpm - cmake):
        problems.append(f"neither build compiles {by_name[name]}")
    for line in problems:
        print("check_sources: " + line, file=sys.stderr)
    if not problems:
        print(f"check_sources: fpm and CMake compile the same {len(fpm)} files under src/ "
              "and app/")
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
