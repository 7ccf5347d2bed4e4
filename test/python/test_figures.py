"""The figure command (scripts/figures.py) runs and writes every figure as PNG and SVG."""
import subprocess
import sys

from conftest import ROOT

FIGURES = ["fig05_radial_fall_time", "fig06_repulsive_radial_time", "fig07_apsidal_locus",
           "fig08_sector_of_inaccessibility", "fig09_complete_brachistochrones",
           "fig10_r_vs_s", "fig11_r_vs_t", "fig12_s_vs_theta", "fig13_theta_vs_t",
           "fig14_s_vs_t", "table1_brachistochrones", "time_map"]


def test_figure_command_quick(app, tmp_path):
    out, data = tmp_path / "figures", tmp_path / "data"
    result = subprocess.run([sys.executable, str(ROOT / "scripts" / "figures.py"), "--quick",
                             "--out", str(out), "--data", str(data)], cwd=ROOT,
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stdout + result.stderr
    assert sorted(p.stem for p in out.glob("*.png")) == sorted(FIGURES)
    for name in FIGURES:
        png, svg = out / (name + ".png"), out / (name + ".svg")
        assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and png.stat().st_size > 10000
        assert "<svg" in svg.read_text()[:2000] and svg.stat().st_size > 10000
    # the figures come from the programs' own files, kept with --data
    for kept in ("family.csv", "locus.csv", "table1_curves.csv", "grid.csv"):
        assert (data / kept).stat().st_size > 0
