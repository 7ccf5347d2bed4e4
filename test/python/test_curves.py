"""--curves end to end: the CSV's layout and provenance, the curves against the --csv
results and against the independent mpmath evaluation of the original integrals
(55)-(57) in scripts/make_reference.py, spacing, and the error paths."""
import sys
from decimal import Decimal, getcontext

import mpmath as mp
import pytest

from conftest import ROOT, read_csv

sys.path.insert(0, str(ROOT / "scripts"))
import make_reference as reference  # noqa: E402  (tanh-sinh on the untransformed integrals)

getcontext().prec = 60
COLUMNS = "id,point,r,theta,s,t,x,y"
# rows: second half-arch (Table 1 row 1), radial fall, inaccessible, first half-arch,
# complete (rho = 1), second half-arch
RHO = ["0.2", "0.5", "0.7", "0.9", "1.0", "0.35"]
PSI = ["1.2", "0.0", "2.5", "0.4", "2.0", "1.9"]


def write_input(path, points, rho=RHO, psi=PSI):
    path.write_text("&endpoints\n n = %d\n rho = %s\n psi = %s\n curve_points = %d\n/\n"
                    % (len(rho), ", ".join(rho), ", ".join(psi), points))


def curves_by_id(rows):
    curves = {}
    for row in rows:
        curves.setdefault(int(row["id"]), []).append({k: Decimal(v) for k, v in row.items()})
    return curves


@pytest.fixture(scope="module")
def solved(tmp_path_factory, app):
    """One run with --csv and --curves (41 points per curve)."""
    import subprocess
    tmp = tmp_path_factory.mktemp("curves")
    nml = tmp / "in.nml"
    write_input(nml, 41)
    result = subprocess.run([str(app), str(nml), "--csv", str(tmp / "out.csv"), "--curves",
                             str(tmp / "curves.csv"), "--no-table"], capture_output=True,
                            text=True, timeout=600)
    assert result.returncode == 2, result.stderr          # row 3 is inaccessible
    comments, header, rows = read_csv(tmp / "curves.csv")
    _, _, results = read_csv(tmp / "out.csv")
    return comments, header, curves_by_id(rows), results, tmp


def test_layout_and_provenance(solved):
    comments, header, curves, results, tmp = solved
    assert header == COLUMNS
    text = "\n".join(comments)
    assert "# brachistochrone " in text and "compiler: GCC" in text
    assert "effective input:" in text and "curve_points = 41" in text
    assert "# id 3: no curve (inaccessible)" in comments
    assert sorted(curves) == [1, 2, 4, 5, 6]
    for id_, points in curves.items():
        assert [int(p["point"]) for p in points] == list(range(1, 42))
    # same provenance as the results CSV, up to the curves' own comment lines
    main_comments, _, _ = read_csv(tmp / "out.csv")
    assert comments[:len(main_comments)] == main_comments
    assert not list(tmp.glob("*.tmp*"))


def test_curves_run_from_a_to_b(solved):
    _, _, curves, results, _ = solved
    for id_, points in curves.items():
        result = results[id_ - 1]
        a, b = points[0], points[-1]
        assert (a["r"], a["theta"], a["s"], a["t"], a["x"], a["y"]) == (1, 0, 0, 0, 1, 0)
        assert b["r"] == Decimal(result["rho"])
        assert abs(b["s"] - Decimal(result["s"])) <= Decimal("4e-34") * b["s"]
        assert abs(b["t"] - Decimal(result["t"])) <= Decimal("4e-34") * b["t"]
        assert abs(b["theta"] - Decimal(result["psi"])) <= Decimal("2e-33")
        for p, q in zip(points, points[1:]):
            assert q["s"] > p["s"] and q["t"] > p["t"] and q["theta"] >= p["theta"]
        for p in points:
            assert abs(p["x"] ** 2 + p["y"] ** 2 - p["r"] ** 2) < Decimal("1e-33")
            assert p["theta"] < Decimal("2.0943951023931954923")   # 2 pi/3


def test_equal_steps_and_apse(solved):
    _, _, curves, results, _ = solved
    for id_, points in curves.items():
        big_r = Decimal(results[id_ - 1]["R"])
        s = [p["s"] for p in points]
        apse = [k for k, p in enumerate(points) if p["r"] == big_r]
        arch = results[id_ - 1]["arch"]
        if arch in ("second", "complete"):
            assert len(apse) == 1 and 0 < apse[0] < len(points) - 1, arch
            pieces = [(0, apse[0]), (apse[0], len(points) - 1)]
        else:
            assert not apse
            pieces = [(0, len(points) - 1)]
        for lo, hi in pieces:
            h = (s[hi] - s[lo]) / (hi - lo)
            assert all(abs(s[k + 1] - s[k] - h) < Decimal("1e-30") * h for k in range(lo, hi))


def test_points_against_mpmath(solved):
    """Theta, S, T at a few sampled radii, by tanh-sinh quadrature of (55)-(57) at 40
    digits on the exact binary128 values of r and R read from the files."""
    _, _, curves, results, _ = solved
    mp.mp.dps = 40
    checked = 0
    for id_, picks in ((1, (7, 23, 36)), (4, (20,)), (5, (10, 30))):
        points = curves[id_]
        row = results[id_ - 1]
        with mp.workprec(113):
            big_r = mp.mpf(row["R"])
        apse = next((k for k, p in enumerate(points) if p["r"] == Decimal(row["R"])), None)
        for k in picks:
            with mp.workprec(113):
                r = mp.mpf(str(points[k]["r"]))
            arch = "second" if apse is not None and k > apse else "first"
            for name in ("theta", "s", "t"):
                expected = reference.arch_value(name, r, big_r, arch)
                got = mp.mpf(str(points[k][name]))
                assert abs(got - expected) <= mp.mpf("1e-32") * abs(expected), (id_, k, name)
            checked += 1
    assert checked == 6


def test_threads_and_slices(run, tmp_path, monkeypatch):
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")
    nml = tmp_path / "in.nml"
    write_input(nml, 17)
    one, two, part = tmp_path / "one.csv", tmp_path / "two.csv", tmp_path / "part.csv"
    assert run(nml, "--curves", one, "--threads", "1", "--no-table").returncode == 2
    assert run(nml, "--curves", two, "--threads", "2", "--no-table").returncode == 2
    assert one.read_bytes() == two.read_bytes()
    assert run(nml, "--curves", part, "--first", "4", "--last", "5",
               "--no-table").returncode == 0
    _, _, rows = read_csv(part)
    _, _, whole = read_csv(one)
    assert {r["id"] for r in rows} == {"4", "5"}
    assert rows == [r for r in whole if r["id"] in ("4", "5")]


def test_curves_need_curve_points(run, tmp_path):
    nml = tmp_path / "in.nml"
    nml.write_text("&endpoints n = 1, rho = 0.5, psi = 1 /\n")
    out = tmp_path / "curves.csv"
    result = run(nml, "--curves", out, "--csv", tmp_path / "out.csv")
    assert result.returncode == 1
    assert "curve_points = N" in result.stderr and str(nml) in result.stderr
    assert list(tmp_path.iterdir()) == [nml]
    assert run(nml, "--curves", out, "--check").returncode == 1


def test_existing_curves_file_is_refused(run, tmp_path):
    nml = tmp_path / "in.nml"
    write_input(nml, 3, rho=["0.5"], psi=["1.0"])
    out = tmp_path / "curves.csv"
    out.write_text("keep me\n")
    result = run(nml, "--curves", out)
    assert result.returncode == 1 and "--force" in result.stderr
    assert out.read_text() == "keep me\n"
    assert run(nml, "--curves", out, "--force", "--no-table").returncode == 0
    assert out.read_text().count("\n1,") == 3


def test_curve_points_without_curves_is_harmless(run, tmp_path):
    nml = tmp_path / "in.nml"
    write_input(nml, 5, rho=["0.5"], psi=["1.0"])
    result = run(nml, "--csv", tmp_path / "out.csv", "--no-table")
    assert result.returncode == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in.nml", "out.csv"]
