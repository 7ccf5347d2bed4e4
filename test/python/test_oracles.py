"""The program's answers against oracles it shares no code with:
- SciPy (QUADPACK on the original integrals (55)-(57), brentq on a bracket) in double
  precision, for random endpoints of the accessible sector;
- the 45-digit mpmath reference table, through the program's own input and output."""
import math
import random
import sys
from decimal import Decimal

import mpmath as mp
import pytest
from scipy.optimize import brentq

from conftest import ROOT, read_csv

sys.path.insert(0, str(ROOT / "scripts"))
import make_quadpack_grid as quadpack  # noqa: E402  (independent SciPy evaluation)


def theta(r_s, big_r):
    """Theta(r, R) by QUADPACK on eq. (55); r as a decimal string, R a float."""
    return float(quadpack.scipy_values(r_s, repr(big_r))[0][0])


def scipy_solve(rho_s, psi):
    """R-bar, s, t in double precision: brentq on Upsilon(R) = psi over (0, rho]."""
    rho = float(rho_s)
    second = psi > theta(rho_s, rho) if rho < 1 else True

    def upsilon(big_r):
        value = theta(rho_s, big_r)
        if second:
            value = 2 * theta(repr(big_r), big_r) - value
        return value - psi

    big_r = brentq(upsilon, 1e-12 * rho, rho * (1 - 1e-15), xtol=1e-17, rtol=1e-15)
    (_, s1, t1), _ = quadpack.scipy_values(rho_s, repr(big_r))
    if second:
        (_, s_apse, t_apse), _ = quadpack.scipy_values(repr(big_r), repr(big_r))
        return big_r, 2 * s_apse - s1, 2 * t_apse - t1
    return big_r, s1, t1


def run_table(run, tmp_path, rhos, psis):
    nml = tmp_path / "in.nml"
    nml.write_text("&endpoints\n n = %d\n rho = %s\n psi = %s\n/\n"
                   % (len(rhos), ", ".join(rhos), ", ".join(psis)))
    out = tmp_path / "out.csv"
    result = run(nml, "--csv", out)
    assert result.returncode == 0, result.stderr
    return read_csv(out)[2]


def test_random_endpoints_against_scipy(run, tmp_path):
    rng = random.Random(20261122)
    rhos = [f"{rng.uniform(0.05, 1.0):.12f}" for _ in range(8)]
    psis = [f"{rng.uniform(0.05, 2.0):.12f}" for _ in range(8)]
    rows = run_table(run, tmp_path, rhos, psis)
    for rho_s, psi_s, row in zip(rhos, psis, rows):
        big_r, s, t = scipy_solve(rho_s, float(psi_s))
        assert row["status"] == "ok"
        # double precision, with R-bar's conditioning near the apse: 1e-9 relative
        assert float(row["R"]) == pytest.approx(big_r, rel=1e-9), (rho_s, psi_s)
        assert float(row["s"]) == pytest.approx(s, rel=1e-10), (rho_s, psi_s)
        assert float(row["t"]) == pytest.approx(t, rel=1e-10), (rho_s, psi_s)


def test_mpmath_reference_through_the_app(run, tmp_path):
    """Every 10th row of the 45-digit table, solved by the program from its decimal input:
    s and t to >= 32 significant digits, as written in the CSV."""
    _, _, reference = read_csv(ROOT / "data" / "reference" / "endpoints_mpmath.csv")
    sample = reference[::10]
    rows = run_table(run, tmp_path, [r["rho"] for r in sample], [r["psi"] for r in sample])
    mp.mp.dps = 50
    for ref, row in zip(sample, rows):
        for key in ("s", "t"):
            digits = -mp.log10(abs(mp.mpf(row[key]) / mp.mpf(ref[key]) - 1) + mp.mpf(10)**-40)
            assert digits >= 32, (ref["rho"], ref["psi"], key, row[key], ref[key])


def test_reference_tables_are_reproducible():
    """The stored QUADPACK grid is what the script computes now."""
    import subprocess
    result = subprocess.run([sys.executable, str(ROOT / "scripts" / "make_quadpack_grid.py"),
                             "--check"], cwd=ROOT, capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr
