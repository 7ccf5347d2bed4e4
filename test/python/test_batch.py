"""Batch features for pipelines: output formats, provenance, slices, threads, progress,
validation-only runs, and the I/O error path."""
import math
import os
import random
import subprocess
from decimal import Decimal

import pytest

from conftest import read_csv


def write_table(path, n, seed=7, estimates=False):
    rng = random.Random(seed)
    rho = [f"{rng.uniform(0.05, 1.0):.15f}" for _ in range(n)]
    psi = [f"{rng.uniform(0.01, 2.05):.15f}" for _ in range(n)]
    text = "&endpoints\n n = %d\n rho = %s\n psi = %s\n" % (n, ", ".join(rho), ", ".join(psi))
    if estimates:
        text += " r0 = %s\n r1 = %s\n" % (", ".join(f"{0.9 * float(r):.6f}" for r in rho),
                                          ", ".join(f"{0.7 * float(r):.6f}" for r in rho))
    path.write_text(text + "/\n")
    return rho, psi


@pytest.fixture
def env_fixed_date(monkeypatch):
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")


def data_lines(path):
    return [line for line in path.read_text().splitlines() if not line.startswith("#")]


def test_provenance_and_effective_input(run, tmp_path, env_fixed_date):
    nml = tmp_path / "in.nml"
    write_table(nml, 3)
    out = tmp_path / "out.csv"
    assert run(nml, "--csv", out, "--no-table").returncode == 0
    comments, header, rows = read_csv(out)
    text = "\n".join(comments)
    assert "# brachistochrone " in text and "compiler: GCC" in text
    assert "compiler options:" in text
    assert "date: 2023-11-14T22:13:20+0000" in text           # SOURCE_DATE_EPOCH
    assert f"input: {nml}, rows 1 to 3 of 3" in text
    # the echoed input is itself a valid input file giving the same results
    echo = tmp_path / "echo.nml"
    start = comments.index("# effective input:") + 1
    echo.write_text("\n".join(c[2:] for c in comments[start:]) + "\n")
    again = tmp_path / "again.csv"
    assert run(echo, "--csv", again, "--no-table").returncode == 0
    assert data_lines(again) == data_lines(out)


def test_namelist_output_matches_csv(run, tmp_path):
    nml = tmp_path / "in.nml"
    write_table(nml, 4)
    out_csv, out_nml = tmp_path / "out.csv", tmp_path / "out.nml"
    assert run(nml, "--csv", out_csv, "--nml", out_nml, "--no-table").returncode == 0
    text = out_nml.read_text()
    assert text.startswith("! brachistochrone")
    assert "&RESULTS" in text.upper()
    _, _, rows = read_csv(out_csv)
    body = text[text.upper().index("&RESULTS"):]
    r_values = body.upper().split(" R=")[1].split("S=")[0]
    numbers = [Decimal(x.strip()) for x in r_values.replace("\n", " ").split(",") if x.strip()]
    assert [Decimal(r["R"]) for r in rows] == numbers[:len(rows)] or all(
        abs(a - Decimal(r["R"])) < Decimal("1e-35") for a, r in zip(numbers, rows))


def test_table_file(run, tmp_path):
    nml = tmp_path / "in.nml"
    write_table(nml, 2)
    out = tmp_path / "out.txt"
    result = run(nml, "--table", out, "--no-table")
    assert result.returncode == 0 and result.stdout == ""
    assert "R-bar = " in out.read_text()


def test_threads_give_identical_bytes(run, tmp_path, env_fixed_date):
    # 20,000 rows, some inaccessible (empty CSV fields, 0 in the namelist): the rows are
    # solved and formatted by the threads in blocks of 2,048 and written block by block
    # while the next is solved (the namelist's later variables through a scratch file);
    # one output alone, or both in one run, on 1 and 2 threads: the same bytes
    nml = tmp_path / "in.nml"
    rho, psi = write_table(nml, 20000, estimates=False)
    psi = [("2.5" if k % 97 == 5 else p) for k, p in enumerate(psi)]
    nml.write_text("&endpoints\n n = 20000\n rho = %s\n psi = %s\n/\n" % (
        ", ".join(rho), ", ".join(psi)))
    outputs = {}
    for threads in ("1", "2"):
        for kinds in (("csv",), ("nml",), ("csv", "nml")):
            args = []
            for kind in kinds:
                args += [f"--{kind}", tmp_path / f"{threads}{''.join(kinds)}.{kind}"]
            result = run(nml, *args, "--threads", threads, "--no-table", "--quiet")
            assert result.returncode == 2, result.stderr        # the inaccessible rows
            for kind in kinds:
                outputs[threads, kinds, kind] = (
                    tmp_path / f"{threads}{''.join(kinds)}.{kind}").read_bytes()
    for kind in ("csv", "nml"):
        assert len({v for k, v in outputs.items() if k[2] == kind}) == 1, kind
    text = outputs["1", ("nml",), "nml"].decode()
    assert text.count('\n  "inaccessible",') == 2 * sum(p == "2.5" for p in psi)
    assert text.endswith("\n /\n") and not [f for f in os.listdir(tmp_path) if f[0] == "."]


def test_bad_slices_are_usage_errors(run, tmp_path):
    nml = tmp_path / "in.nml"
    write_table(nml, 5)
    for args in (("--first", "0"), ("--first", "4", "--last", "2"), ("--last", "6"),
                 ("--first", "x")):
        result = run(nml, *args, "--csv", tmp_path / "o.csv")
        assert result.returncode == 1, args
        assert not (tmp_path / "o.csv").exists()


def test_check_only(run, tmp_path):
    nml = tmp_path / "in.nml"
    write_table(nml, 5)
    result = run(nml, "--check")
    assert result.returncode == 0 and "5 endpoints, valid" in result.stdout
    bad = tmp_path / "bad.nml"
    bad.write_text("&endpoints n = 2, rho = 0.5, psi = 1, 1 /\n")
    assert run(bad, "--check").returncode == 1


def test_a_million_endpoints_validate(run, tmp_path):
    """Memory proportional to the table, no small fixed maximum."""
    n = 1_000_000
    nml = tmp_path / "million.nml"
    with nml.open("w") as f:
        f.write(f"&endpoints\n n = {n}\n rho = {n}*0.5\n psi =\n")
        for k in range(n // 1000):
            f.write(", ".join(["0.1"] * 999 + ["2.5"]) + ",\n")
        f.write("/\n")
    result = run(nml, "--check")
    assert result.returncode == 0, result.stderr
    assert "1000000 endpoints, valid" in result.stdout


def test_progress_on_stderr_and_quiet(run, tmp_path):
    # progress starts after 2 s: 120,000 endpoints take about 5 s on one thread
    nml = tmp_path / "in.nml"
    write_table(nml, 120000)
    loud = run(nml, "--no-table", "--threads", "1")
    assert loud.returncode == 0
    assert loud.stdout == ""
    assert "endpoints/s" in loud.stderr and "%" in loud.stderr
    quiet = run(nml, "--no-table", "--threads", "1", "--quiet")
    assert quiet.stderr == ""


def test_io_error_exit_3_and_no_partial_file(run, tmp_path):
    nml = tmp_path / "in.nml"
    write_table(nml, 2)
    result = run(nml, "--csv", tmp_path / "missing_dir" / "out.csv", "--no-table")
    assert result.returncode == 3
    assert "cannot write" in result.stderr
    assert not (tmp_path / "missing_dir").exists()


def test_provenance_checksum_and_short_echo(run, tmp_path):
    """The provenance identifies the input by its SHA-256 and size (hashlib is the
    oracle); the effective input is echoed only for small inputs."""
    import hashlib
    for rows, echoed in ((5, True), (1500, False)):
        nml = tmp_path / f"in{rows}.nml"
        write_table(nml, rows)
        out = tmp_path / f"out{rows}.csv"
        assert run(nml, "--csv", out, "--no-table", "--quiet").returncode in (0, 2)
        data = nml.read_bytes()
        comments = [l for l in out.read_text().splitlines() if l.startswith("#")]
        assert (f"# input sha256: {hashlib.sha256(data).hexdigest()}, {len(data)} bytes"
                in comments)
        assert any(l.startswith("#   rho =") for l in comments) == echoed


def test_too_many_threads_from_the_environment(app, tmp_path):
    """OMP_NUM_THREADS beyond the supported maximum is refused (it crashed the OpenMP
    runtime); --threads still wins over it."""
    nml = tmp_path / "in.nml"
    write_table(nml, 3)
    env = dict(os.environ, OMP_NUM_THREADS="65536")
    result = subprocess.run([str(app), str(nml), "--quiet"], env=env, capture_output=True,
                            text=True, timeout=60)
    assert result.returncode == 1 and "OMP_NUM_THREADS" in result.stderr
    result = subprocess.run([str(app), str(nml), "--quiet", "--threads", "2"], env=env,
                            capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
