"""The figure command (scripts/figures.py) runs and writes every figure as PNG and SVG (and,
for print, PDF at 300 dpi without titles); the plotted data of the other fields agree with
closed forms that the library does not use to make them."""
import csv
import math
import struct
import subprocess
import sys

import pytest

from conftest import ROOT

FIGURES = ["fig05_radial_fall_time", "fig06_repulsive_radial_time", "fig07_apsidal_locus",
           "fig08_sector_of_inaccessibility", "fig09_complete_brachistochrones",
           "fig10_r_vs_s", "fig11_r_vs_t", "fig12_s_vs_theta", "fig13_theta_vs_t",
           "fig14_s_vs_t", "table1_brachistochrones", "time_map",
           "tunnels_saitoh", "power_law_families", "power_law_apse_angle", "repulsive_curves",
           "uniform_cycloids"]
EARTH_RADIUS_M, EARTH_GRAVITY = 6371.0e3, 9.81


@pytest.fixture(scope="module")
def made(app, tmp_path_factory):
    """One quick run for print (titles off, PDF, 300 dpi), keeping the programs' data."""
    tmp_path = tmp_path_factory.mktemp("figures")
    out, data = tmp_path / "figures", tmp_path / "data"
    result = subprocess.run([sys.executable, str(ROOT / "scripts" / "figures.py"), "--quick",
                             "--print", "--out", str(out), "--data", str(data)], cwd=ROOT,
                            capture_output=True, text=True, timeout=900)
    assert result.returncode == 0, result.stdout + result.stderr
    return out, data


def rows(path):
    with open(path) as f:
        return [{k: (v if k in ("kind",) else float(v)) for k, v in row.items()}
                for row in csv.DictReader(line for line in f if not line.startswith("#"))]


def png_dpi(path):
    """Horizontal resolution from the pHYs chunk (pixels per metre -> dots per inch)."""
    data = path.read_bytes()
    at = data.index(b"pHYs")
    per_metre, = struct.unpack(">I", data[at + 4:at + 8])
    return per_metre * 0.0254


def test_every_figure_in_every_format(made):
    out, data = made
    assert sorted(p.stem for p in out.glob("*.png")) == sorted(FIGURES)
    for name in FIGURES:
        png, svg, pdf = (out / (name + ext) for ext in (".png", ".svg", ".pdf"))
        assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and png.stat().st_size > 10000
        assert round(png_dpi(png)) == 300, name
        assert "<svg" in svg.read_text()[:2000] and svg.stat().st_size > 10000
        assert pdf.read_bytes()[:5] == b"%PDF-" and pdf.stat().st_size > 5000
    # --print leaves the titles out
    assert "Fig. 10" not in (out / "fig10_r_vs_s.svg").read_text()
    # the figures come from the programs' own files, kept with --data
    for kept in ("family.csv", "locus.csv", "table1_curves.csv", "grid.csv",
                 "hypocycloids.csv", "tunnel_times.csv", "power_3_arches.csv",
                 "repulsive_critical.csv", "cycloids.csv", "isochrone.csv"):
        assert (data / kept).stat().st_size > 0


def test_tunnel_times_against_saitoh(made):
    """Straight tunnel: pi sqrt(R/g) = 42.2 min for every chord; the hypocycloid between
    surface points at central angle Theta: pi sqrt(1 - (1 - Theta/pi)^2) sqrt(R/g) (Saitoh
    eq. 10 with R_m/R = 1 - Theta/pi)."""
    table = rows(made[1] / "tunnel_times.csv")
    minutes = math.pi * math.sqrt(EARTH_RADIUS_M / EARTH_GRAVITY) / 60.0
    assert abs(minutes - 42.196) < 5e-4
    for row in table:
        assert abs(row["chord_time_min"] - minutes) < 1e-12 * minutes
        rho = 1.0 - row["angle_deg"] / 180.0
        assert abs(row["time_min"] - minutes * math.sqrt(1.0 - rho * rho)) < 1e-12 * minutes
    assert abs(table[-1]["time_min"] - minutes) < 1e-12 * minutes       # antipodes
    for row in rows(made[1] / "hypocycloids.csv"):
        if row["point"] == 1:
            assert row["r"] == 1.0 and row["theta"] == 0.0
    ends = {}
    for row in rows(made[1] / "hypocycloids.csv"):
        ends[row["id"]] = row
    for row in ends.values():
        rho = row["rho_m"]
        assert abs(row["t"] - math.pi * math.sqrt(1.0 - rho * rho)) < 1e-13
        assert abs(row["theta"] - math.pi * (1.0 - rho)) < 1e-13


@pytest.mark.parametrize("n", [1.5, 2.0, 3.0, 6.0])
def test_power_law_apse_angle_tends_to_keam(made, n):
    """The apse angle Theta(R,R) rises towards pi/(n+1) as R -> 0 and stays below it;
    every complete arch ends at radius 1 inside the accessible sector 2 pi/(n+1)."""
    locus = sorted(rows(made[1] / ("power_%g_locus.csv" % n)), key=lambda r: r["R"])
    keam = math.pi / (n + 1.0)
    assert locus[0]["R"] == pytest.approx(1e-12)
    # Keam: Theta(R,R) = pi/(n+1) - O(R^((n-1)/2)) at least (n = 1.5: about 1e-6 here)
    assert 0.0 <= keam - locus[0]["theta"] < 1e-5
    assert all(a["theta"] >= b["theta"] for a, b in zip(locus, locus[1:]))   # decreasing in R
    arches = rows(made[1] / ("power_%g_arches.csv" % n))
    ends = [r for r in arches if r["r"] == 1.0 and r["point"] > 1]
    assert len(ends) == 7
    assert all(0.0 < r["theta"] < 2.0 * keam for r in ends)


def test_repulsive_critical_curve_closed_form(made):
    """K^2 = 27/8: theta = (2/sqrt3) atanh(3u) - 2 atan(sqrt3 u), u = sqrt((r-1)/(r+3))
    (Tee (28) integrated by partial fractions), and the spiral approaches r = 3/2."""
    critical = rows(made[1] / "repulsive_critical.csv")
    for row in critical:
        # (in double precision atanh(3u) loses digits like 1/(3 - 2r): keep to 3 - 2r > 1e-3)
        if 3.0 - 2.0 * row["r"] > 1e-3:
            u = math.sqrt((row["r"] - 1.0) / (row["r"] + 3.0))
            theta = (2.0 / math.sqrt(3.0) * math.atanh(3.0 * u)
                     - 2.0 * math.atan(math.sqrt(3.0) * u))
            assert abs(row["theta"] - theta) < 1e-12 * max(1.0, theta)
    assert critical[-1]["theta"] > 4.0 * math.pi and 1.5 - critical[-1]["r"] < 1e-11
    bounded = rows(made[1] / "repulsive_bounded.csv")
    assert all(1.0 <= r["r"] <= r["parameter"] for r in bounded)


def test_cycloids_and_isochrone(made):
    """Uniform gravity, g = 1: B level with A at distance l takes sqrt(2 pi l) (Saitoh);
    B = (pi a, 2a) is the lowest point, reached at pi sqrt(a) (here a = 1/pi: sqrt(pi));
    the isochrone takes pi sqrt(alpha/g) from every height, the pendulum longer."""
    ends = {}
    for row in rows(made[1] / "cycloids.csv"):
        ends[(row["x_b"], row["y_b"])] = row
    assert abs(ends[(1.0, 0.0)]["t_b"] - math.sqrt(2.0 * math.pi)) < 1e-14
    bottom = [r for (x, y), r in ends.items() if abs(y - 2.0 / math.pi) < 1e-15]
    assert len(bottom) == 1 and abs(bottom[0]["t_b"] - math.sqrt(math.pi)) < 1e-14
    for row in ends.values():
        assert abs(row["x"] - row["x_b"]) < 1e-14 and abs(row["y"] - row["y_b"]) < 1e-14
    for row in rows(made[1] / "isochrone.csv"):
        assert abs(row["time_quadrature"] - math.pi) < 1e-14
        assert row["pendulum_time"] > math.pi


def test_repulsive_radial_motion_closed_form(made):
    """Figure 6 plots the K = 0 curve of the repulsive data (quadrature of Tee (40)):
    t = (sqrt(r (r - 1)) + asinh(sqrt(r - 1)))/sqrt2, eq. (49); theta = 0."""
    radial = [r for r in rows(made[1] / "repulsive_unbounded.csv") if r["parameter"] == 3.0]
    assert len(radial) > 50 and radial[-1]["r"] == 8.0
    for row in radial:
        r = row["r"]
        t = (math.sqrt(r * (r - 1.0)) + math.asinh(math.sqrt(r - 1.0))) / math.sqrt(2.0)
        assert abs(row["t"] - t) < 1e-13 * max(t, 1e-3) and row["theta"] == 0.0


def test_figure_data_program_errors_and_output(app, tmp_path):
    """The example program refuses bad input with exit 1 and a message, and writes a
    complete file under the given name (no temporary left behind)."""
    fpm = str(ROOT / ".venv" / "bin" / "fpm")
    runner = subprocess.run([fpm, "run", "--profile", "release", "--example", "--runner", "echo",
                             "brachistochrone-figure-data"], cwd=ROOT, capture_output=True,
                            text=True, check=True).stdout.strip().splitlines()[-1]
    program = str((ROOT / runner).resolve())
    for args, words in ((["nonsense"], "unknown or missing KIND"),
                        (["power-arches", "0.5"], "--exponent"),
                        (["power-arches", "--exponent", "2", "1.5"], "0 < R < 1"),
                        (["cycloids", "1"], "pairs"),
                        (["hypocycloids", "x0.5"], "not a number")):
        result = subprocess.run([program, *args], capture_output=True, text=True)
        assert result.returncode == 1 and words in result.stderr, (args, result.stderr)
    target = tmp_path / "tunnels.csv"
    result = subprocess.run([program, "tunnel-times", "--points", "3", "--output", str(target)],
                            capture_output=True, text=True)
    assert result.returncode == 0 and result.stdout == ""
    table = rows(target)
    assert [r["angle_deg"] for r in table] == [0.0, 90.0, 180.0]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["tunnels.csv"]
