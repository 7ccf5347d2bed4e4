"""Force fields chosen in the namelist (force = ...), end to end, against closed forms
and the inverse-square fast path."""
import math
from decimal import Decimal

import mpmath as mp
import pytest

from conftest import read_csv

mp.mp.dps = 40


def solve(run, tmp_path, rho, psi, extra):
    nml = tmp_path / "in.nml"
    nml.write_text("&endpoints n = %d, rho = %s, psi = %s %s /\n"
                   % (len(rho), ", ".join(rho), ", ".join(psi), extra))
    out = tmp_path / "out.csv"
    if out.exists():
        out.unlink()
    result = run(nml, "--csv", out, "--no-table")
    return result, (read_csv(out)[2] if out.exists() else None)


def test_power_law_two_is_the_inverse_square_fast_path(run, tmp_path):
    rho = ["0.2", "0.5", "0.9", "1.0"]
    psi = ["1.2", "0.1", "0.4", "2.0"]
    _, general = solve(run, tmp_path, rho, psi, "force = 'power', exponent = 2")
    _, fast = solve(run, tmp_path, rho, psi, "")
    for a, b in zip(general, fast):
        assert a["arch"] == b["arch"]
        for key in ("R", "s", "t"):
            assert abs(mp.mpf(a[key]) / mp.mpf(b[key]) - 1) < mp.mpf("1e-31"), key


def test_harmonic_tunnels_against_saitoh(run, tmp_path):
    """Surface to surface: psi = pi (1 - R_m), T = pi sqrt(1 - R_m^2) (units R_E = omega = 1);
    the antipode by the straight diametral tunnel, T = pi."""
    minima = ["0.1", "0.4", "0.75"]
    psi = [mp.nstr(mp.pi * (1 - mp.mpf(m)), 36) for m in minima] + [mp.nstr(mp.pi, 40)]
    result, rows = solve(run, tmp_path, ["1.0"] * 3 + ["0.5"], psi, "force = 'harmonic'")
    assert result.returncode == 0, result.stderr
    for m, row in zip(minima, rows):
        assert row["arch"] == "complete"
        assert abs(mp.mpf(row["R"]) - mp.mpf(m)) < mp.mpf("1e-30")
        assert abs(mp.mpf(row["t"]) - mp.pi * mp.sqrt(1 - mp.mpf(m) ** 2)) < mp.mpf("1e-30")
    # psi = pi read into binary128 is just below pi: R-bar ~ 1e-34, t -> pi - acos(rho)
    last = rows[3]
    assert mp.mpf(last["R"]) < mp.mpf("1e-30")
    assert abs(mp.mpf(last["t"]) - (mp.pi - mp.acos(mp.mpf("0.5")))) < mp.mpf("1e-30")


def test_logarithmic_and_power_laws_respect_their_sectors(run, tmp_path):
    # F = 1/r^3: accessible psi < 2 pi/4; logarithmic: psi < pi
    result, rows = solve(run, tmp_path, ["0.5", "0.5"], ["1.5", "1.6"],
                         "force = 'power', exponent = 3")
    assert result.returncode == 2
    assert rows[0]["status"] == "ok" and rows[1]["status"] == "inaccessible"
    result, rows = solve(run, tmp_path, ["0.5", "0.5"], ["2.5", "0.3"], "force = 'logarithmic'")
    assert result.returncode == 0 and all(r["status"] == "ok" for r in rows)


@pytest.mark.parametrize("extra,fragment", [
    ("force = 'gravity'", "unknown field"),
    ("force = harmonic", "must be quoted"),
    ("force = 'power'", "variable exponent: is missing"),
    ("force = 'power', exponent = 1", "must be a number > 1"),
    ("force = 'harmonic', exponent = 3", "applies to force = 'power' only"),
    ("force = 'harmonic', r0 = 0.3, r1 = 0.2", "apply to force = 'inverse_square' only"),
])
def test_field_input_errors(run, tmp_path, extra, fragment):
    result, rows = solve(run, tmp_path, ["0.5"], ["1.0"], extra)
    assert result.returncode == 1
    assert fragment in result.stderr, result.stderr
    assert rows is None


def test_repulsive_field_end_to_end(run, tmp_path):
    """force = 'repulsive' (rho >= 1): radial time (49); a bounded brachistochrone's angle
    at rho recomputed by mpmath on the original integral (28) with K^2 = R^3/(2(R - 1))."""
    result, rows = solve(run, tmp_path, ["5.0", "1.2", "2.0"], ["0", "0.3", "1.0"],
                         "force = 'repulsive'")
    assert result.returncode == 0, result.stderr
    rho = mp.mpf(5)
    t49 = (mp.sqrt(rho * (rho - 1)) + mp.log(mp.sqrt(rho) + mp.sqrt(rho - 1))) / mp.sqrt(2)
    assert rows[0]["arch"] == "radial" and abs(mp.mpf(rows[0]["t"]) - t49) < mp.mpf("1e-32")
    assert rows[1]["arch"] == "first"
    big_r, r = mp.mpf(rows[1]["R"]), mp.mpf("1.2")
    k2 = big_r ** 3 / (2 * (big_r - 1))
    v2 = lambda x: 2 * (x - 1) / x
    theta = mp.quad(lambda x: 1 / (x * mp.sqrt(x * x / (k2 * v2(x)) - 1)), [1, r])
    assert abs(theta - mp.mpf("0.3")) < mp.mpf("1e-30")
    assert rows[2]["arch"] == "unbounded" and rows[2]["R"] == ""
    result, rows = solve(run, tmp_path, ["0.5"], ["1.0"], "force = 'repulsive'")
    assert result.returncode == 1 and "rho >= 1" in result.stderr


def test_uniform_gravity_batch_against_the_cycloid(run, tmp_path):
    """force = 'uniform' with Cartesian x, y (B below A, y downward, g = 1): the
    rolling-circle radius a, s and t against the cycloid solved with mpmath at 50
    digits (x = a (phi - sin phi), y = a (1 - cos phi), t = phi sqrt(a),
    s = 8 a sin^2(phi/4)); the inputs are dyadic, so exact in binary128."""
    points = [("1", "1"), ("2", "0.5"), ("0.25", "3"), ("10", "0.125"), ("3", "3"),
              ("0.0078125", "1"), ("64", "1")]
    nml = tmp_path / "u.nml"
    nml.write_text("&endpoints n = %d, force = 'uniform', x = %s, y = %s /\n" % (
        len(points), ", ".join(x for x, _ in points), ", ".join(y for _, y in points)))
    out = tmp_path / "u.csv"
    result = run(nml, "--csv", out, "--no-table")
    assert result.returncode == 0, result.stderr
    comments, header, rows = read_csv(out)
    assert header == "x,y,arch,R,s,t,steps,status"
    assert any(line.startswith("# field: uniform") for line in comments)
    with mp.workdps(50):
        for (xs, ys), row in zip(points, rows):
            x, y = mp.mpf(xs), mp.mpf(ys)
            # (phi - sin phi)/(1 - cos phi) increases from 0 to infinity on (0, 2 pi):
            # bisection to far below 1e-40
            lo, hi = mp.mpf(0), 2 * mp.pi
            for _ in range(180):
                mid = (lo + hi) / 2
                if (mid - mp.sin(mid)) * y < (1 - mp.cos(mid)) * x:
                    lo = mid
                else:
                    hi = mid
            phi = (lo + hi) / 2
            a = y / (1 - mp.cos(phi))
            expected = {"R": a, "t": phi * mp.sqrt(a), "s": 8 * a * mp.sin(phi / 4) ** 2}
            assert row["arch"] == ("first" if phi <= mp.pi else "second")
            for key, value in expected.items():
                assert abs(mp.mpf(row[key]) / value - 1) < mp.mpf("1e-32"), (xs, ys, key)


def test_uniform_gravity_takes_x_y_only(run, tmp_path):
    nml = tmp_path / "bad.nml"
    nml.write_text("&endpoints n = 1, force = 'uniform', rho = 0.5, psi = 1 /\n")
    result = run(nml, "--check")
    assert result.returncode == 1
    assert "give x (across) and y (down from A), not rho and psi" in result.stderr
    nml.write_text("&endpoints n = 1, rho = 0.5, psi = 1, x = 1, y = 1 /\n")
    result = run(nml, "--check")
    assert result.returncode == 1 and "force = 'uniform' only" in result.stderr
