"""One version number: `version` in fpm.toml, which every program prints with --version,
the preprocessor macro of the same file (see the comment there), the MPI package,
CITATION.cff and CMake (which reads fpm.toml) must all agree; every program and
subcommand answers --help and --version."""
import re
import subprocess

import pytest

from conftest import ROOT, FPM


def toml_version(path):
    return re.search(r'^version\s*=\s*"([^"]+)"', path.read_text(), re.M).group(1)


VERSION = toml_version(ROOT / "fpm.toml")


def test_one_version_everywhere():
    assert re.fullmatch(r"\d+\.\d+\.\d+", VERSION)
    macro = re.search(r'BRACHISTOCHRONE_VERSION=([^"\]]+)"', (ROOT / "fpm.toml").read_text())
    assert macro and macro.group(1) == VERSION
    assert toml_version(ROOT / "mpi" / "fpm.toml") == VERSION
    citation = re.search(r'^version:\s*"([^"]+)"', (ROOT / "CITATION.cff").read_text(), re.M)
    assert citation and citation.group(1) == VERSION
    assert "## Unreleased" in (ROOT / "CHANGELOG.md").read_text()


@pytest.mark.parametrize("words, name", [([], "brachistochrone"),
                                         (["family"], "brachistochrone family"),
                                         (["tunnel"], "brachistochrone tunnel"),
                                         (["merge"], "brachistochrone merge")])
def test_every_program_prints_the_version(run, words, name):
    result = run(*words, "--version")
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == f"{name} {VERSION}"
    help_text = run(*words, "--help")
    assert help_text.returncode == 0 and help_text.stdout.startswith("usage: " + name)


def test_bench_example_prints_the_version(app):
    result = subprocess.run([str(FPM), "run", "--profile", "release", "--example",
                             "brachistochrone-bench", "--", "--version"], cwd=ROOT,
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip().splitlines()[-1] == f"brachistochrone-bench {VERSION}"


def test_outputs_carry_the_version(run, tmp_path):
    out = tmp_path / "t.csv"
    result = run("data/table1.nml", "--csv", out, "--no-table", "--quiet")
    assert result.returncode == 0, result.stderr
    assert out.read_text().splitlines()[0] == f"# brachistochrone {VERSION}"


def test_fpm_run_runs_the_batch_program_alone(app):
    """`fpm run -- FILE.nml` (no program name) runs the one executable: the batch program."""
    result = subprocess.run([str(FPM), "run", "--profile", "release", "--", "data/table1.nml",
                             "--check"], cwd=ROOT, capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    lines = result.stdout.strip().splitlines()      # one program's verdict, nothing else
    assert len(lines) == 1 and "5 endpoints" in lines[0], result.stdout
