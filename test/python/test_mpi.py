"""The MPI driver (mpi/, run with mpirun -np 2) writes what the serial run writes."""
import os
import shutil
import subprocess

import pytest

from conftest import ROOT
from test_batch import write_table

pytestmark = pytest.mark.skipif(shutil.which("mpirun") is None and not os.environ.get("CI"),
                                reason="OpenMPI not installed (scripts/setup.sh installs it)")


def mpi(*args, cwd):
    return subprocess.run(["bash", str(ROOT / "scripts" / "mpi.sh"), "2", *map(str, args)],
                          cwd=cwd, capture_output=True, text=True, timeout=900)


def comparable(path):
    # the compile flags differ (mpifort adds MPI's); everything else must be identical
    return [l for l in path.read_text().splitlines()
            if not l[2:].startswith("compiler options")]


def test_mpi_run_equals_serial_run(run, tmp_path, monkeypatch):
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")
    nml = tmp_path / "in.nml"
    write_table(nml, 41, estimates=True)
    serial_csv, serial_nml = tmp_path / "serial.csv", tmp_path / "serial.nml"
    serial = run(nml, "--csv", serial_csv, "--nml", serial_nml, "--no-table")
    parallel = mpi(nml, "--csv", "par.csv", "--nml", "par.nml", "--no-table", cwd=tmp_path)
    assert parallel.returncode == serial.returncode, parallel.stderr
    assert comparable(tmp_path / "par.csv") == comparable(serial_csv)
    assert comparable(tmp_path / "par.nml") == comparable(serial_nml)


def test_mpi_curves_equal_serial_curves(run, tmp_path, monkeypatch):
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")
    nml = tmp_path / "in.nml"
    nml.write_text("&endpoints n = 3, rho = 0.2, 0.5, 0.9, psi = 1.2, 2.5, 0.4, "
                   "curve_points = 9 /\n")
    serial = run(nml, "--curves", tmp_path / "serial.csv", "--no-table")
    parallel = mpi(nml, "--curves", "par.csv", "--no-table", cwd=tmp_path)
    assert parallel.returncode == serial.returncode == 2, parallel.stderr
    assert comparable(tmp_path / "par.csv") == comparable(tmp_path / "serial.csv")
    assert "# id 2: no curve (inaccessible)" in (tmp_path / "par.csv").read_text()


def test_mpi_slice_and_input_error(tmp_path):
    nml = tmp_path / "in.nml"
    write_table(nml, 9)
    sliced = mpi(nml, "--first", "3", "--last", "8", "--csv", "s.csv", "--no-table",
                 cwd=tmp_path)
    assert sliced.returncode == 0, sliced.stderr
    rows = [l for l in (tmp_path / "s.csv").read_text().splitlines() if not l.startswith("#")]
    assert len(rows) == 1 + 6
    bad = tmp_path / "bad.nml"
    bad.write_text("&endpoints n = 2, rho = 0.5, psi = 1 /\n")
    failed = mpi(bad, "--csv", "b.csv", cwd=tmp_path)
    assert failed.returncode == 1
    assert "has 1 values but n = 2" in failed.stderr
    assert failed.stderr.count("variable rho: has 1 values") == 1   # once, by rank 0
    assert not (tmp_path / "b.csv").exists()
