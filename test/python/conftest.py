"""Shared fixtures: the release build of the program, and a runner for it."""
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
FPM = ROOT / ".venv" / "bin" / "fpm"


@pytest.fixture(scope="session")
def app():
    """Path of the built `brachistochrone` executable (release profile)."""
    subprocess.run([str(FPM), "build", "--profile", "release"], cwd=ROOT, check=True,
                   capture_output=True)
    out = subprocess.run([str(FPM), "run", "--profile", "release", "--runner", "echo",
                          "brachistochrone"], cwd=ROOT, check=True, capture_output=True,
                         text=True).stdout.strip().splitlines()[-1]
    path = (ROOT / out).resolve()
    assert path.exists(), out
    return path


@pytest.fixture
def run(app):
    """Run the program with arguments; returns the CompletedProcess (text mode)."""
    def _run(*args, cwd=ROOT):
        return subprocess.run([str(app), *map(str, args)], cwd=cwd, capture_output=True,
                              text=True, timeout=600)
    return _run


def read_csv(path):
    """Comment lines and rows (dicts of strings) of a CSV written by the program."""
    comments, rows, header = [], [], None
    for line in pathlib.Path(path).read_text().splitlines():
        if line.startswith("#"):
            comments.append(line)
        elif header is None:
            header = line
        else:
            rows.append(dict(zip(header.split(","), line.split(","))))
    return comments, header, rows
