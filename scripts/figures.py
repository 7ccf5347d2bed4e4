#!/usr/bin/env python3
"""Regenerate the figures of docs/figures/ (PNG and SVG) from the program's own output.

    .venv/bin/python scripts/figures.py [--out DIR] [--quick] [--data DIR]
                                        [--no-titles] [--pdf] [--dpi N] [--print]

Every number plotted comes from the Fortran programs, run with
`fpm run --profile release ...` on inputs written here:
  - brachistochrone (the batch program): radial fall (psi = 0) with --curves, Tee's
    Table 1 (data/table1.nml plus curve_points) with --curves, and a polar grid of
    endpoints with --csv for the map of least times and the sector of inaccessibility;
  - brachistochrone family: the complete brachistochrones R = 0.9 ... 0.01 (--curves)
    and the apsidal locus (--locus);
  - the example brachistochrone-figure-data (`fpm run --example`): the other fields,
    from the library's routines: Saitoh's hypocycloid tunnels and their times on the
    Earth, the power-law families and apsidal loci (general engine), the repulsive
    bounded, critical and unbounded curves, the uniform-gravity cycloids and isochrone.
Figure 6 (repulsive radial motion) is the K = 0 curve of the repulsive data, with the
closed form (49) evaluated by NumPy beside it for comparison. The dotted R -> 0 limits of
figures 10-14 are assembled from the program's radial-fall curve; circles, chords, the
rays at pi/(n+1) and the unit conversion to minutes are drawn or done here.

Units are the paper's: lengths in units of |OA| (A at radius 1), times in units of
sqrt(|OA|^3/mu) (mu = 1), angles in radians. --quick uses coarse grids (for tests).
For print: --no-titles, --pdf (also write PDF), --dpi N (PNG resolution, default 130);
--print is all three with 300 dpi. Curves are told apart by line style as well as colour,
so the figures survive greyscale printing.
"""
import argparse
import csv
import math
import os
import pathlib
import subprocess
import sys
import tempfile
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
FAMILY_R = [0.9, 0.7, 0.5, 0.3, 0.1, 0.03, 0.01]
T0 = math.pi / math.sqrt(8.0)            # t(0), eq. (47)
SECTOR = 2.0 * math.pi / 3.0             # the sector of inaccessibility begins here
LENGTH = "(unit |OA|)"
TIME = r"(unit $\sqrt{|OA|^3/\mu}$)"
ANGLE = "(rad)"

plt.rcParams.update({"font.size": 11, "axes.titlesize": 12, "legend.fontsize": 9,
                     "figure.dpi": 100, "savefig.dpi": 130, "svg.hashsalt": "brachistochrone",
                     "axes.grid": True, "grid.alpha": 0.3})
# dash patterns told apart in greyscale (dotted is kept for limits and guides)
DASHES = ["-", (0, (6, 2)), (0, (6, 2, 1.5, 2)), (0, (2, 1.5)), (0, (10, 2, 2, 2, 2, 2)),
          (0, (3, 1, 1, 1)), (0, (12, 3))]
# print options (set by main): titles, PDF as well, PNG resolution
OPTIONS = {"titles": True, "pdf": False, "dpi": 130}
EARTH_RADIUS_KM, EARTH_GRAVITY = 6371.0, 9.81          # the library's default planet
SOURCE_EXAMPLE = "brachistochrone-figure-data"


def styled(k, n, cmap=plt.cm.viridis, stop=0.9):
    """Colour k of n along a colour map, and dash pattern k: distinct in greyscale too."""
    return {"color": cmap(stop * k / max(n - 1, 1)), "ls": DASHES[k % len(DASHES)]}


def title(ax, text, **kwargs):
    """Axes title, unless --no-titles."""
    if OPTIONS["titles"]:
        ax.set_title(text, **kwargs)


def fpm():
    """The fpm of the project's .venv, else the one next to this Python, else PATH's."""
    for candidate in (ROOT / ".venv" / "bin" / "fpm", pathlib.Path(sys.executable).parent / "fpm"):
        if candidate.exists():
            return str(candidate)
    return "fpm"


def run(program, *args, allowed=(0,)):
    """fpm run --profile release PROGRAM -- ARGS (from the project root)."""
    command = [fpm(), "run", "--profile", "release", program, "--", *map(str, args)]
    result = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
    if result.returncode not in allowed:
        sys.exit("figures: %s failed (exit %d):\n%s%s" % (" ".join(command), result.returncode,
                                                          result.stdout, result.stderr))
    return result


def read_csv(path):
    """Columns of a CSV written by the programs (comment lines skipped) as float arrays,
    and the text columns as lists."""
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    columns = {}
    for key in rows[0]:
        values = [row[key] for row in rows]
        try:
            columns[key] = np.array([float(v) if v else np.nan for v in values])
        except ValueError:
            columns[key] = values
    return columns


def split_curves(columns, key="id"):
    """{id: {column: array}} from a curves CSV."""
    ids = columns[key]
    return {int(i): {k: v[ids == i] for k, v in columns.items() if not isinstance(v, list)}
            for i in np.unique(ids)}


def write_endpoints(path, rho, psi, curve_points=0, extra=""):
    with open(path, "w") as f:
        f.write("&endpoints\n  n = %d\n" % len(rho))
        f.write("  rho = " + ",\n    ".join("%.17g" % x for x in rho) + "\n")
        f.write("  psi = " + ",\n    ".join("%.17g" % x for x in psi) + "\n")
        if curve_points:
            f.write("  curve_points = %d\n" % curve_points)
        f.write(extra + "/\n")


# ---------------------------------------------------------------------------- data

def compute(data, quick):
    """Run the programs; return the parsed tables."""
    points = 161 if quick else 801
    n_rho, n_psi = (12, 21) if quick else (80, 121)
    out = {}

    # complete arches and the apsidal locus, by apse radius
    family = data / "family.csv"
    run("brachistochrone", "family", "--force", "--points", points, "--curves", family,
        *FAMILY_R)
    out["family"] = split_curves(read_csv(family))
    locus_r = np.concatenate([1.0 - np.arange(0, 200 if not quick else 40)
                              / (200.0 if not quick else 40.0),
                              np.logspace(np.log10(0.005), -9, 25 if not quick else 8)])
    locus = data / "locus.csv"
    run("brachistochrone", "family", "--force", "--locus", locus, *["%.17g" % r for r in locus_r])
    out["locus"] = read_csv(locus)

    # radial fall to (almost) the centre, sampled by the batch program
    radial = data / "radial.nml"
    write_endpoints(radial, [1e-12], [0.0], curve_points=points)
    run("brachistochrone", radial, "--curves", data / "radial_curves.csv", "--force",
        "--no-table", "--quiet")
    out["radial"] = split_curves(read_csv(data / "radial_curves.csv"))[1]

    # Tee's Table 1 with the paper's secant method, plus curves
    table1 = data / "table1.nml"
    text = (ROOT / "data" / "table1.nml").read_text()
    start = text.index("&endpoints")
    end = text.index("\n/", start)
    table1.write_text(text[:end] + "\n  curve_points = %d" % (points // 2 + 1) + text[end:])
    run("brachistochrone", table1, "--csv", data / "table1.csv", "--curves",
        data / "table1_curves.csv", "--force", "--no-table", "--quiet")
    out["table1"] = read_csv(data / "table1.csv")
    out["table1_curves"] = split_curves(read_csv(data / "table1_curves.csv"))

    # least times on a polar grid over the half disc 0 <= psi <= pi (inaccessible part
    # included: there the program's t is the bound kappa(rho))
    # (psi up to just below 2 pi/3, then from just above it, as the program reads the
    # 17-digit decimals: both colour fields reach the boundary)
    rho = np.linspace(1.0 / n_rho, 1.0, n_rho)
    psi = np.concatenate([np.linspace(0.0, SECTOR * (1.0 - 1e-9), n_psi),
                          np.linspace(SECTOR * (1.0 + 1e-15), math.pi, n_psi // 2)])
    grid = data / "grid.nml"
    rr, pp = np.meshgrid(rho, psi, indexing="ij")
    write_endpoints(grid, rr.ravel(), pp.ravel())
    run("brachistochrone", grid, "--csv", data / "grid.csv", "--force", "--no-table",
        "--quiet", allowed=(0, 2))
    table = read_csv(data / "grid.csv")
    out["grid"] = {"rho": table["rho"].reshape(rr.shape), "psi": table["psi"].reshape(rr.shape),
                   "t": table["t"].reshape(rr.shape),
                   "accessible": (np.array(table["status"]) == "ok").reshape(rr.shape)}

    # what the pictures must show
    for curves in (out["family"], out["table1_curves"]):
        for c in curves.values():
            assert c["theta"].max() < SECTOR, "a curve enters the sector of inaccessibility"
    assert out["locus"]["theta"].max() < math.pi / 3.0, "an apse angle reaches pi/3"
    assert len(out["family"]) == len(FAMILY_R) and len(out["table1_curves"]) == 5
    return out


def example(path, kind, *args):
    """fpm run --profile release --example brachistochrone-figure-data -- KIND ARGS."""
    command = [fpm(), "run", "--profile", "release", "--example", SOURCE_EXAMPLE, "--",
               kind, *map(str, args), "--output", str(path)]
    result = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("figures: %s failed (exit %d):\n%s%s" % (" ".join(command), result.returncode,
                                                          result.stdout, result.stderr))
    return read_csv(path)


TUNNEL_RHO = [0.8, 0.6, 0.4, 0.2, 0.0]                 # Saitoh: minimum radii R_m/R
POWER_N = [1.5, 2.0, 3.0, 6.0]
POWER_R = [0.9, 0.7, 0.5, 0.3, 0.1, 0.01, 0.001]
REPULSIVE_APSES = [1.1, 1.3, 1.45, 1.49]
REPULSIVE_GAPS = [3.0, 1.0, 0.1, 1e-3, 1e-6]           # g = 3 - P; 3: radial
CYCLOID_B = [(1.0, 2.0), (1.0, 1.0), (1.0, 2.0 / math.pi), (1.0, 0.3), (1.0, 0.0)]
ISOCHRONE_H = [2.0 * k / 16 for k in range(1, 17)]


def compute_fields(data, quick):
    """The other fields, from the library through the figure-data example."""
    points = 101 if quick else 241
    out = {}
    out["hypocycloids"] = split_curves(example(data / "hypocycloids.csv", "hypocycloids",
                                               "--points", points, *TUNNEL_RHO))
    out["tunnel_times"] = example(data / "tunnel_times.csv", "tunnel-times", "--points",
                                  37 if quick else 181)
    locus_r = np.concatenate([1.0 - np.arange(1, 40) / 40.0,
                              np.logspace(np.log10(0.02), -12, 12 if quick else 45)])
    out["power"] = {}
    for n in POWER_N:
        arches = example(data / ("power_%g_arches.csv" % n), "power-arches", "--exponent", n,
                         "--points", points, *POWER_R)
        locus = example(data / ("power_%g_locus.csv" % n), "power-locus", "--exponent", n,
                        *["%.17g" % r for r in locus_r])
        out["power"][n] = {"arches": split_curves(arches), "locus": locus}
    out["bounded"] = split_curves(example(data / "repulsive_bounded.csv", "repulsive-bounded",
                                          "--points", points, *REPULSIVE_APSES))
    out["unbounded"] = split_curves(example(data / "repulsive_unbounded.csv",
                                            "repulsive-unbounded", "--points", points,
                                            "--rmax", 8, *REPULSIVE_GAPS))
    out["critical"] = split_curves(example(data / "repulsive_critical.csv",
                                           "repulsive-critical", "--points", points))[1]
    out["cycloids"] = split_curves(example(data / "cycloids.csv", "cycloids", "--points", points,
                                           *["%.17g" % v for b in CYCLOID_B for v in b]))
    out["isochrone"] = example(data / "isochrone.csv", "isochrone",
                               *["%.17g" % h for h in ISOCHRONE_H])

    # what the pictures must show
    for n, family in out["power"].items():
        # (at R = 1e-12 the apse angle equals pi/(n+1) in double precision for n >= 3)
        assert family["locus"]["theta"].max() <= math.pi / (n + 1.0) * (1 + 1e-15), \
            "apse angle past Keam's limit"
        for c in family["arches"].values():
            assert c["theta"].max() < 2.0 * math.pi / (n + 1.0), "arch in the sector"
    times = out["tunnel_times"]
    assert np.all(times["time_min"] <= times["chord_time_min"] * (1 + 1e-12))
    return out


# ---------------------------------------------------------------------------- figures

def save(fig, out, name):
    fig.savefig(out / (name + ".png"), bbox_inches="tight", dpi=OPTIONS["dpi"])
    fig.savefig(out / (name + ".svg"), bbox_inches="tight", metadata={"Date": None})
    if OPTIONS["pdf"]:
        fig.savefig(out / (name + ".pdf"), bbox_inches="tight",
                    metadata={"CreationDate": None, "ModDate": None})
    plt.close(fig)


def plane_axes(ax, xlim=(-0.62, 1.08), ylim=(-0.06, 1.06)):
    """Unit circle, O, A, the rays theta = 0 and theta = 2 pi/3, equal aspect."""
    phi = np.linspace(-0.2, 2.3, 400)
    ax.plot(np.cos(phi), np.sin(phi), color="0.75", lw=0.8)
    for angle in (0.0, SECTOR):
        ax.plot([0, 1.1 * math.cos(angle)], [0, 1.1 * math.sin(angle)], color="0.5", lw=0.8,
                ls="--")
    ax.plot([0, 1], [0, 0], "k.", ms=6)
    ax.annotate("O", (0, 0), xytext=(-12, -12), textcoords="offset points")
    ax.annotate("A", (1, 0), xytext=(4, -12), textcoords="offset points")
    # label the ray on its inaccessible side, where no curve goes
    ax.text(0.45 * math.cos(SECTOR) - 0.07 * math.sin(SECTOR),
            0.45 * math.sin(SECTOR) + 0.07 * math.cos(SECTOR),
            r"$\theta = 2\pi/3$", rotation=-60, ha="center", va="center", fontsize=9,
            color="0.35")
    ax.set_aspect("equal")
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    ax.set_xlabel(r"$x = r\cos\theta$ " + LENGTH)
    ax.set_ylabel(r"$y = r\sin\theta$ " + LENGTH)


def limit_curves(radial):
    """The R -> 0 limits: fall down OA, then rise up the ray at 2 pi/3 (program data)."""
    r, t = radial["r"], radial["t"]
    r = np.append(r, 0.0)
    t = np.append(t, T0)
    return r, t


def figure_5(d, out):
    c = d["radial"]
    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.plot(c["r"], c["t"], color="C0", label="radial fall from A, eq. (46)")
    ax.axhline(T0, color="0.4", ls=":", lw=1)
    ax.annotate(r"$t(0) = \pi/\sqrt{8} = 1.1107207345\ldots$", (0.5, T0),
                xytext=(0, 6), textcoords="offset points", ha="center")
    ax.set_xlim(0, 1)
    ax.set_ylim(0, 1.25)
    ax.set_xlabel("radius $r$ " + LENGTH)
    ax.set_ylabel("time $t$ " + TIME)
    title(ax, "Fig. 5: time to fall from rest at $r = 1$ to radius $r$")
    ax.legend(loc="lower left")
    save(fig, out, "fig05_radial_fall_time")


def figure_6(d, out):
    radial = [c for c in d["unbounded"].values() if c["parameter"][0] == 3.0][0]   # K = 0
    keep = radial["r"] <= 6.0
    r, t = radial["r"][keep], radial["t"][keep]
    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.plot(r, t, color="C3", label="repulsive radial motion (K = 0), eq. (40)")
    closed = np.linspace(1.0, 6.0, 26)
    ax.plot(closed, (np.sqrt(closed * (closed - 1.0)) + np.arcsinh(np.sqrt(closed - 1.0)))
            / math.sqrt(2.0), "o", color="k", ms=3.5, mfc="none",
            label="closed form (49), for comparison")
    ax.plot(r, r / math.sqrt(2.0), color="0.5", ls=":", lw=1,
            label=r"slope $1/\sqrt{2}$ (speed $\to\sqrt{2}$)")
    ax.set_xlim(1, 6)
    ax.set_ylim(0, 5.2)
    ax.set_xlabel("radius $r$ " + LENGTH)
    ax.set_ylabel("time $t$ " + TIME)
    title(ax, r"Fig. 6: time to be repelled from $r = 1$ to radius $r$ ($\mu = -1$)")
    ax.legend(loc="upper left")
    save(fig, out, "fig06_repulsive_radial_time")


def figure_7(d, out):
    locus = d["locus"]
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.2), gridspec_kw={"width_ratios": [1.5, 1]})
    # circular arc of angle 2 pi/3 on the chord OA: centre (1/2, -1/(2 sqrt 3)), radius 1/sqrt 3
    centre = (0.5, -0.5 / math.sqrt(3.0))
    phi = np.linspace(math.pi / 6.0, 5.0 * math.pi / 6.0, 300)
    ax.plot(centre[0] + np.cos(phi) / math.sqrt(3.0), centre[1] + np.sin(phi) / math.sqrt(3.0),
            color="C1", ls="--", label=r"circular arc of angle $2\pi/3$ on the chord OA")
    ax.plot(locus["x"], locus["y"], color="C0",
            label=r"apsidal locus $\theta = \Theta(R,R)$, $r = R$")
    ax.plot([0, 0.45 * math.cos(math.pi / 3)], [0, 0.45 * math.sin(math.pi / 3)], color="0.5",
            ls=":", lw=1, label=r"tangent at O: $\theta = \pi/3$")
    ax.plot([0, 1], [0, 0], "k.-", lw=0.8, ms=6)
    ax.annotate("O", (0, 0), xytext=(-12, -12), textcoords="offset points")
    ax.annotate("A", (1, 0), xytext=(4, -12), textcoords="offset points")
    ax.set_aspect("equal")
    ax.set_xlim(-0.05, 1.08)
    ax.set_ylim(-0.06, 0.45)
    ax.set_xlabel(r"$x = R\cos\Theta(R,R)$ " + LENGTH)
    ax.set_ylabel(r"$y = R\sin\Theta(R,R)$ " + LENGTH)
    title(ax, "Fig. 7: the apsidal locus")
    ax.legend(loc="lower center", bbox_to_anchor=(0.5, 0.1), fontsize=8.5)
    order = np.argsort(locus["R"])
    bx.plot(locus["R"][order], locus["theta"][order], color="C0", label=r"$\Theta(R,R)$")
    bx.axhline(math.pi / 3.0, color="0.4", ls=":", lw=1)
    bx.text(0.03, math.pi / 3.0 + 0.03, r"$\pi/3$: the limit as $R\to 0$, eq. (74)",
            fontsize=9)
    grid = np.linspace(0.6, 1.0, 50)
    bx.plot(grid, 0.5 * math.pi * (1.0 - grid), color="C1", ls="--", lw=1,
            label=r"$(\pi/2)(1-R)$ near $R = 1$")
    bx.set_xlim(0, 1)
    bx.set_ylim(0, 1.2)
    bx.set_xlabel("apse radius $R$ " + LENGTH)
    bx.set_ylabel(r"apse angle $\Theta(R,R)$ " + ANGLE)
    bx.legend(loc="lower left")
    save(fig, out, "fig07_apsidal_locus")


def mirrored(grid, key, accessible):
    """Grid values on the whole disc (psi and -psi), masked outside (in)accessibility."""
    rho, psi, value = grid["rho"], grid["psi"], grid[key].copy()
    value[grid["accessible"] != accessible] = np.nan
    rho2 = np.concatenate([rho[:, ::-1], rho[:, 1:]], axis=1)
    psi2 = np.concatenate([-psi[:, ::-1], psi[:, 1:]], axis=1)
    value2 = np.concatenate([value[:, ::-1], value[:, 1:]], axis=1)
    return rho2 * np.cos(psi2), rho2 * np.sin(psi2), np.ma.masked_invalid(value2)


def disc_axes(ax):
    phi = np.linspace(0, 2 * math.pi, 400)
    ax.plot(np.cos(phi), np.sin(phi), color="0.4", lw=0.8)
    for angle in (SECTOR, -SECTOR):
        ax.plot([0, math.cos(angle)], [0, math.sin(angle)], color="k", lw=1)
    ax.plot([0, 1], [0, 0], "k.", ms=6)
    ax.annotate("O", (0, 0), xytext=(4, -12), textcoords="offset points")
    ax.annotate("A", (1, 0), xytext=(4, -4), textcoords="offset points")
    ax.set_aspect("equal")
    ax.set_xlim(-1.08, 1.12)
    ax.set_ylim(-1.08, 1.08)
    ax.set_xlabel("$x$ " + LENGTH)
    ax.set_ylabel("$y$ " + LENGTH)


def figure_8(d, out):
    x, y, kappa = mirrored(d["grid"], "t", accessible=False)
    fig, ax = plt.subplots(figsize=(6.4, 5.6))
    filled = ax.contourf(x, y, kappa, levels=np.linspace(1.1, 2.25, 24), cmap="magma_r")
    lines = ax.contour(x, y, kappa, levels=[1.2, 1.4, 1.6, 1.8, 2.0], colors="k",
                       linewidths=0.7)
    ax.clabel(lines, fmt="%.1f", fontsize=8)
    fig.colorbar(filled, ax=ax, shrink=0.8,
                 label=r"$\kappa(\rho) = 2t(0) - t(\rho)$, eq. (75) " + TIME)
    disc_axes(ax)
    ax.text(0.45, 0.05, "accessible sector\n" + r"$|\psi| < 2\pi/3$", ha="center", fontsize=10)
    ax.text(-0.5, 0.0, "sector of\ninaccessibility", ha="center", va="center", fontsize=10,
            bbox={"facecolor": "w", "edgecolor": "none", "alpha": 0.8})
    title(ax, r"Fig. 8: sector of inaccessibility $2\pi/3 \leq |\psi| \leq \pi$"
                 "\nwith contours of the least-time bound $\\kappa(\\rho)$ (never attained)",
                 fontsize=11)
    save(fig, out, "fig08_sector_of_inaccessibility")


def figure_9(d, out):
    fig, ax = plt.subplots(figsize=(7, 4.8))
    plane_axes(ax)
    locus = d["locus"]
    ax.plot(locus["x"], locus["y"], color="0.3", ls=":", lw=1, label="apsidal locus")
    for k, (i, c) in enumerate(sorted(d["family"].items())):
        ax.plot(c["x"], c["y"], lw=1.4, label="R = %g" % c["R"][0],
                **styled(k, len(d["family"])))
    title(ax, "Fig. 9: complete brachistochrones from A")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=4)
    save(fig, out, "fig09_complete_brachistochrones")


def family_plot(d, out, name, heading, x_key, y_key, x_label, y_label, limit, xlim, ylim):
    fig, ax = plt.subplots(figsize=(7.4, 4.6))
    for k, (i, c) in enumerate(sorted(d["family"].items())):
        ax.plot(c[x_key], c[y_key], lw=1.4, label="R = %g" % c["R"][0],
                **styled(k, len(d["family"])))
    ax.plot(*limit, color="k", ls=":", lw=1.5, label=r"limit $R \to 0$")
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    ax.set_xlabel(x_label)
    ax.set_ylabel(y_label)
    title(ax, heading)
    # beside the axes: inside, a legend covers curves (fig. 10 did)
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0)
    save(fig, out, name)


def figures_10_to_14(d, out):
    r, t = limit_curves(d["radial"])
    fall_s, rise_s = 1.0 - r, 1.0 + r[::-1]
    fall_t, rise_t = t, 2.0 * T0 - t[::-1]
    s_label, t_label = "arclength $s$ " + LENGTH, "time $t$ " + TIME
    r_label, theta_label = "radius $r$ " + LENGTH, r"angle $\theta$ " + ANGLE
    family_plot(d, out, "fig10_r_vs_s", "Fig. 10: radius against arclength", "s", "r",
                s_label, r_label,
                (np.concatenate([fall_s, rise_s]), np.concatenate([r, r[::-1]])),
                (0, 2.05), (0, 1.02))
    family_plot(d, out, "fig11_r_vs_t", "Fig. 11: radius against time", "t", "r",
                t_label, r_label,
                (np.concatenate([fall_t, rise_t]), np.concatenate([r, r[::-1]])),
                (0, 2.3), (0, 1.02))
    family_plot(d, out, "fig12_s_vs_theta", "Fig. 12: arclength against angle", "theta", "s",
                theta_label, s_label,
                ([0, 0, SECTOR, SECTOR], [0, 1, 1, 2]), (-0.05, 2.2), (0, 2.05))
    family_plot(d, out, "fig13_theta_vs_t", "Fig. 13: angle against time", "t", "theta",
                t_label, theta_label,
                ([0, T0, T0, 2 * T0], [0, 0, SECTOR, SECTOR]), (0, 2.3), (-0.05, 2.2))
    family_plot(d, out, "fig14_s_vs_t", "Fig. 14: arclength against time", "t", "s",
                t_label, s_label,
                (np.concatenate([fall_t, rise_t]), np.concatenate([fall_s, rise_s])),
                (0, 2.3), (0, 2.05))


def figure_table1(d, out):
    fig, ax = plt.subplots(figsize=(7, 4.8))
    plane_axes(ax)
    locus = d["locus"]
    ax.plot(locus["x"], locus["y"], color="0.3", ls=":", lw=1, label="apsidal locus")
    table = d["table1"]
    for k, (i, c) in enumerate(sorted(d["table1_curves"].items())):
        label = r"$\rho = %g,\ \psi = %g$: $\bar R = %.4f$, $t = %.4f$" % (
            table["rho"][i - 1], table["psi"][i - 1], table["R"][i - 1], table["t"][i - 1])
        style = styled(k, 5, plt.cm.plasma, 0.85)
        ax.plot(c["x"], c["y"], lw=1.5, label=label, **style)
        ax.plot(c["x"][-1], c["y"][-1], "o", color=style["color"], ms=5)
    title(ax, "Tee's Table 1: the five brachistochrones from A to B (dots)")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, fontsize=9)
    save(fig, out, "table1_brachistochrones")


def label_positions(lines, labelled):
    """One place for each labelled contour, on its lower (mirrored) half, as far inside
    the disc and the accessible sector as the contour goes: never clipped by the rim."""
    places = []
    for level, segments in zip(lines.levels, lines.allsegs):
        if not any(abs(level - l) < 1e-9 for l in labelled):
            continue
        best, where = -np.inf, None
        for seg in segments:
            for x, y in seg:
                if y >= 0:
                    continue
                r, phi = math.hypot(x, y), abs(math.atan2(y, x))
                room = min(1.0 - r, r * math.sin(max(SECTOR - phi, 0.0)), 0.25)
                if room > best:
                    best, where = room, (x, y)
        if where is not None:
            places.append(where)
    return places


def figure_time_map(d, out):
    x, y, t = mirrored(d["grid"], "t", accessible=True)
    fig, ax = plt.subplots(figsize=(6.6, 5.6))
    filled = ax.contourf(x, y, t, levels=np.linspace(0, 2.3, 24), cmap="viridis")
    levels = np.arange(0.2, 2.3, 0.2)
    lines = ax.contour(x, y, t, levels=levels, colors="w", linewidths=0.6)
    # 0.8, 1.2, 1.6 on the contours, inside the disc; the 2.0 contour runs too close to
    # the rim for an inline label (it was clipped there): its label sits outside, with an
    # arrow
    labelled = levels[3:-2:2]
    ax.clabel(lines, levels=labelled, fmt="%.1f", fontsize=8,
              manual=label_positions(lines, labelled))
    rim = label_positions(lines, [2.0])
    if rim:
        phi = math.atan2(rim[0][1], rim[0][0])
        ax.annotate("2.0", rim[0], xytext=(1.16 * math.cos(phi), 1.16 * math.sin(phi)),
                    fontsize=8, ha="center", va="center",
                    arrowprops={"arrowstyle": "-", "color": "0.3", "lw": 0.6})
    fig.colorbar(filled, ax=ax, shrink=0.8, label="least time $t$ from A " + TIME)
    disc_axes(ax)
    phi = np.linspace(SECTOR, 2 * math.pi - SECTOR, 100)
    ax.fill(np.concatenate([[0], np.cos(phi)]), np.concatenate([[0], np.sin(phi)]),
            facecolor="0.85", edgecolor="none", hatch="//", zorder=0)
    ax.text(-0.55, 0.0, "inaccessible\n(no brachistochrone)", ha="center", va="center",
            fontsize=9, bbox={"facecolor": "w", "edgecolor": "none", "alpha": 0.9})
    title(ax, "Least travel time from A over the accessible sector: the time\n"
                 "of the brachistochrone (%d radii x %d angles, mirrored about OA)"
                 % (d["grid"]["rho"].shape[0], int(d["grid"]["accessible"][-1].sum())),
                 fontsize=11)
    save(fig, out, "time_map")


# ---------------------------------------------------------------------------- other fields

def minutes_per_unit():
    """1/omega = sqrt(R/g) in minutes for the library's default Earth."""
    return math.sqrt(EARTH_RADIUS_KM * 1000.0 / EARTH_GRAVITY) / 60.0


def figure_tunnels(d, out):
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 5.2), gridspec_kw={"width_ratios": [1, 1.1]})
    phi = np.linspace(0, 2 * math.pi, 400)
    ax.fill(np.cos(phi), np.sin(phi), facecolor="0.95", edgecolor="0.4", lw=0.8)
    ax.plot([0], [0], "k.", ms=5)
    ax.annotate("O", (0, 0), xytext=(-12, -12), textcoords="offset points")
    ax.annotate("A", (1, 0), xytext=(4, -4), textcoords="offset points")
    scale = minutes_per_unit()
    curves = sorted(d["hypocycloids"].items())
    ends = []
    for k, (i, c) in enumerate(curves):
        rho, minutes = c["rho_m"][0], c["t"][-1] * scale
        ends.append((c["theta"][-1] * EARTH_RADIUS_KM, minutes))
        label = (r"$R_m/R = %g$: %.1f min" % (rho, minutes) if rho > 0 else
                 r"$R_m = 0$: the diameter, %.1f min" % minutes)
        ax.plot(c["x"], c["y"], lw=1.5, label=label, **styled(k, len(curves)))
        ax.plot(c["x"][-1], c["y"][-1], "o", color=styled(k, len(curves))["color"], ms=4)
    for k, (i, c) in enumerate(curves):
        ax.plot([1, c["x"][-1]], [0, c["y"][-1]], color="0.45", lw=0.8, ls=":", zorder=1.5,
                label="straight chords: %.1f min each" % (math.pi * scale) if k == 0 else None)
    ax.set_aspect("equal")
    ax.set_xlim(-1.12, 1.15)
    ax.set_ylim(-0.1, 1.1)
    ax.set_xlabel("$x$ (unit: planet radius $R$)")
    ax.set_ylabel("$y$ (unit: planet radius $R$)")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=2, fontsize=8.5,
              title="from A to the surface at angle $\pi(1 - R_m/R)$ (dots)",
              title_fontsize=8.5)
    title(ax, "Hypocycloid tunnels from A (Saitoh), and the chords")
    times = d["tunnel_times"]
    bx.plot(times["distance_km"], times["time_min"], color="C0", lw=1.6,
            label="brachistochrone (hypocycloid) tunnel")
    bx.plot(times["distance_km"], times["chord_time_min"], color="k", ls="--", lw=1.2,
            label=r"straight tunnel: $\pi\sqrt{R/g}$ = %.1f min" % times["chord_time_min"][0])
    x, y = zip(*ends)
    bx.plot(x, y, "o", color="C0", ms=5, mfc="w", label="the tunnels on the left")
    bx.set_xlim(0, times["distance_km"].max() * 1.02)
    bx.set_ylim(0, 46)
    bx.set_xlabel("great-circle distance from A (km)")
    bx.set_ylabel("travel time from rest to rest (min)")
    bx.legend(loc="lower right")
    title(bx, "Travel time through the Earth (uniform, R = 6371 km, g = 9.81 m/s$^2$)")
    fig.tight_layout()
    save(fig, out, "tunnels_saitoh")


def keam_guides(ax, n):
    """Unit circle, A, O and the rays at Keam's angle pi/(n+1) and at 2 pi/(n+1)."""
    keam = math.pi / (n + 1.0)
    phi = np.linspace(-0.1, 2 * keam + 0.25, 300)
    ax.plot(np.cos(phi), np.sin(phi), color="0.75", lw=0.8)
    ax.plot([0, 1.1 * math.cos(keam)], [0, 1.1 * math.sin(keam)], color="k", ls=":", lw=1.0,
            label=r"Keam's limit of the apse angle, $\pi/(n+1)$")
    ax.plot([0, 1.1 * math.cos(2 * keam)], [0, 1.1 * math.sin(2 * keam)], color="0.4",
            ls="--", lw=0.9, label=r"edge of the accessible sector, $2\pi/(n+1)$")
    ax.plot([0, 1], [0, 0], "k.", ms=5)
    ax.annotate("O", (0, 0), xytext=(-10, -11), textcoords="offset points", fontsize=9)
    ax.annotate("A", (1, 0), xytext=(3, -11), textcoords="offset points", fontsize=9)
    ax.set_aspect("equal")


def figure_power_families(d, out):
    fig, axes = plt.subplots(2, 2, figsize=(10.5, 8.4))
    for ax, n in zip(axes.ravel(), POWER_N):
        family = d["power"][n]
        keam_guides(ax, n)
        locus = family["locus"]
        ax.plot(locus["x"], locus["y"], color="0.6", lw=4, alpha=0.5, solid_capstyle="butt",
                zorder=1, label=r"apsidal locus $\theta = \Theta(R,R)$, $r = R$")
        arches = sorted(family["arches"].items())
        for k, (i, c) in enumerate(arches):
            ax.plot(c["x"], c["y"], lw=1.2, label="R = %g" % c["R"][0],
                    **styled(k, len(arches)))
        ax.set_xlim(-0.85, 1.1)
        ax.set_ylim(-0.08, 1.08)
        ax.text(0.97, 0.97, r"$F = 1/r^{%g}$: $\pi/(n+1) = %.4f$" % (n, math.pi / (n + 1)),
                transform=ax.transAxes, ha="right", va="top", fontsize=10,
                bbox={"facecolor": "w", "edgecolor": "0.7", "alpha": 0.9})
        ax.set_xlabel(r"$x = r\cos\theta$ " + LENGTH, fontsize=9)
        ax.set_ylabel(r"$y = r\sin\theta$ " + LENGTH, fontsize=9)
    handles, labels = axes[0, 0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=4, fontsize=9,
               bbox_to_anchor=(0.5, -0.005))
    if OPTIONS["titles"]:
        fig.suptitle("Complete brachistochrones for attractive forces $1/r^n$, "
                     "n = 1.5, 2, 3, 6 (general engine)", fontsize=12)
    fig.tight_layout(rect=(0, 0.09, 1, 1))
    save(fig, out, "power_law_families")


def figure_power_apse_angle(d, out):
    fig, ax = plt.subplots(figsize=(7.4, 4.6))
    for k, n in enumerate(POWER_N):
        locus = d["power"][n]["locus"]
        order = np.argsort(locus["R"])
        style = styled(k, len(POWER_N), plt.cm.plasma, 0.8)
        ax.semilogx(locus["R"][order], locus["theta"][order], lw=1.5,
                    label=r"$n = %g$" % n, **style)
        ax.axhline(math.pi / (n + 1), color=style["color"], ls=":", lw=1)
        ax.text(2e-12, math.pi / (n + 1) + 0.015, r"$\pi/%g$" % (n + 1), fontsize=9,
                color=style["color"])
    ax.set_xlim(1e-12, 1)
    ax.set_ylim(0, 1.35)
    ax.set_xlabel("apse radius $R$ " + LENGTH)
    ax.set_ylabel(r"apse angle $\Theta(R,R)$ " + ANGLE)
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0,
              title="force $1/r^n$")
    title(ax, r"Apse angles tend to Keam's limit $\pi/(n+1)$ as $R \to 0$ (dotted)")
    save(fig, out, "power_law_apse_angle")


def repulsive_guides(ax):
    phi = np.linspace(0, 2 * math.pi, 400)
    ax.plot(np.cos(phi), np.sin(phi), color="0.6", lw=0.8)
    ax.plot(1.5 * np.cos(phi), 1.5 * np.sin(phi), color="k", ls=":", lw=1.0,
            label="the circle $r = 3/2$")
    ax.plot([0, 1], [0, 0], "k.", ms=5)
    ax.annotate("O", (0, 0), xytext=(-11, -11), textcoords="offset points", fontsize=9)
    ax.annotate("A", (1, 0), xytext=(3, -11), textcoords="offset points", fontsize=9)
    ax.set_aspect("equal")


def figure_repulsive(d, out):
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 6.8))
    critical = d["critical"]
    for axis in (ax, bx):
        repulsive_guides(axis)
        axis.plot(critical["x"], critical["y"], color="C3", lw=1.0,
                  label="critical, $K^2 = 27/8$: spirals onto $r = 3/2$")
    bounded = sorted(d["bounded"].items())
    for k, (i, c) in enumerate(bounded):
        ax.plot(c["x"], c["y"], lw=1.3, label="bounded, apse R = %g" % c["parameter"][0],
                **styled(k, len(bounded), plt.cm.viridis, 0.8))
    ax.set_xlim(-1.75, 1.75)
    ax.set_ylim(-1.75, 1.75)
    ax.set_xlabel("$x$ " + LENGTH)
    ax.set_ylabel("$y$ " + LENGTH)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=2, fontsize=8)
    title(ax, "Bounded ($K^2 > 27/8$) and critical brachistochrones")
    unbounded = sorted(d["unbounded"].items())
    for k, (i, c) in enumerate(unbounded):
        g = c["parameter"][0]
        label = ("radial, K = 0" if g == 3 else
                 "unbounded, $K^2 = %.6g$ (g = %g)" % (c["K2"][0], g))
        bx.plot(c["x"], c["y"], lw=1.3, label=label,
                **styled(k + 1, len(unbounded) + 1, plt.cm.cividis, 0.85))
    bx.set_xlim(-6.5, 8.2)
    bx.set_ylim(-5.5, 8.2)
    bx.set_xlabel("$x$ " + LENGTH)
    bx.set_ylabel("$y$ " + LENGTH)
    bx.legend(loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=2, fontsize=8)
    title(bx, "Unbounded brachistochrones ($K^2 < 27/8$), to $r = 8$")
    if OPTIONS["titles"]:
        fig.suptitle(r"Repulsive inverse-square force ($\mu = -1$) from A at rest", fontsize=12)
    fig.tight_layout()
    save(fig, out, "repulsive_curves")


def figure_uniform(d, out):
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(13, 5.0), gridspec_kw={"width_ratios": [1.3, 1]})
    curves = sorted(d["cycloids"].items())
    for k, (i, c) in enumerate(curves):
        style = styled(k, len(curves), plt.cm.viridis, 0.85)
        label = r"B = (%g, %.3g): $t_B = %.4f$" % (c["x_b"][0], c["y_b"][0], c["t_b"][0])
        ax.plot(c["x"], c["y"], lw=1.5, label=label, **style)
        ax.plot(c["x_b"][0], c["y_b"][0], "o", color=style["color"], ms=5)
        if abs(c["phi_b"][0] - math.pi) < 1e-12:
            ax.annotate("B at the lowest point:\nA to B is a half-arch,\nthe isochrone (right)",
                        (c["x_b"][0], c["y_b"][0]), xytext=(12, -2), textcoords="offset points",
                        fontsize=8.5, va="center")
    ax.plot([0], [0], "k.", ms=6)
    ax.annotate("A", (0, 0), xytext=(-12, -4), textcoords="offset points")
    ax.set_aspect("equal")
    ax.invert_yaxis()
    ax.set_xlim(-0.15, 2.6)
    ax.set_xlabel("$x$ (horizontal)")
    ax.set_ylabel("$y$ (downward)")
    ax.legend(loc="lower right", fontsize=8.5,
              title="cycloids from A through B (dots), $g = 1$", title_fontsize=8.5)
    title(ax, "Uniform gravity: the brachistochrones are cycloids")
    iso = d["isochrone"]
    bx.plot(iso["h"], iso["time_closed"], color="k", lw=1.2,
            label=r"cycloid: $\pi\sqrt{\alpha/g}$ (Huygens)")
    bx.plot(iso["h"], iso["time_quadrature"], "o", color="C0", ms=5, mfc="w",
            label="cycloid: quadrature of Tee (3)-(4)")
    bx.plot(iso["h"], iso["pendulum_time"], color="C3", ls="--", marker="s", ms=4,
            label=r"circle of radius $4\alpha$ (pendulum)")
    bx.set_xlim(0, 2.05)
    bx.set_ylim(3.0, 3.45)
    bx.set_xlabel(r"release height $h$ above the base (unit $\alpha$)")
    bx.set_ylabel(r"time to the base (unit $\sqrt{\alpha/g}$)")
    bx.legend(loc="upper left", fontsize=9)
    title(bx, "The isochrone: the same descent time from every height")
    fig.tight_layout()
    save(fig, out, "uniform_cycloids")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "docs" / "figures",
                        help="directory for the PNG and SVG files (default docs/figures)")
    parser.add_argument("--quick", action="store_true", help="coarse grids (for tests)")
    parser.add_argument("--data", type=pathlib.Path,
                        help="keep the programs' inputs and outputs in this directory")
    parser.add_argument("--no-titles", action="store_true", help="no titles (for print)")
    parser.add_argument("--pdf", action="store_true", help="write PDF files as well")
    parser.add_argument("--dpi", type=int, default=130, help="PNG resolution (default 130)")
    parser.add_argument("--print", action="store_true", dest="for_print",
                        help="for print: --no-titles --pdf --dpi 300")
    args = parser.parse_args()
    OPTIONS["titles"] = not (args.no_titles or args.for_print)
    OPTIONS["pdf"] = args.pdf or args.for_print
    OPTIONS["dpi"] = 300 if args.for_print else args.dpi
    started = time.monotonic()
    args.out.mkdir(parents=True, exist_ok=True)
    os.environ.setdefault("SOURCE_DATE_EPOCH", "1700000000")
    with tempfile.TemporaryDirectory() as scratch:
        data = args.data or pathlib.Path(scratch)
        data.mkdir(parents=True, exist_ok=True)
        build = subprocess.run([fpm(), "build", "--profile", "release"], cwd=ROOT,
                               capture_output=True, text=True)
        if build.returncode != 0:
            sys.exit("figures: fpm build failed:\n" + build.stdout + build.stderr)
        d = compute(data.resolve(), args.quick)
        d.update(compute_fields(data.resolve(), args.quick))
        computed = time.monotonic()
        figure_5(d, args.out)
        figure_6(d, args.out)
        figure_7(d, args.out)
        figure_8(d, args.out)
        figure_9(d, args.out)
        figures_10_to_14(d, args.out)
        figure_table1(d, args.out)
        figure_time_map(d, args.out)
        figure_tunnels(d, args.out)
        figure_power_families(d, args.out)
        figure_power_apse_angle(d, args.out)
        figure_repulsive(d, args.out)
        figure_uniform(d, args.out)
    files = sum(len(list(args.out.glob(pattern))) for pattern in ("*.png", "*.svg", "*.pdf"))
    print("figures: %d files in %s (programs %.1f s, plotting %.1f s)"
          % (files, args.out, computed - started, time.monotonic() - computed))


if __name__ == "__main__":
    main()
