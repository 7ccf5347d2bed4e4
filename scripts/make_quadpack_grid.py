#!/usr/bin/env python3
"""Independent double-precision reference table for the brachistochrone integrals.

Usage::

    python scripts/make_quadpack_grid.py [--out PATH] [--check] [--mpmath]

Quantities (G. J. Tee 1998, "Isochrones and brachistochrones", section 4.1,
equations (55)-(57); attractive inverse-square force).  For an apse radius
``0 < R < 1`` and ``R <= r <= 1``, with ``Q(x) = x**2 + R*x + R**2/(1-R)``
(which is positive for all real x)::

    Theta(r,R) = sqrt(R^3/(1-R)) * Int_r^1 (1-x) / (x*sqrt((1-x)(x-R)Q(x))) dx
    S(r,R)     = Int_r^1 x^2 / sqrt(x (x-R) Q(x)) dx
    T(r,R)     = Int_r^1 x^2 / sqrt(2 (1-x)(x-R) Q(x)) dx

These ORIGINAL integrals are evaluated directly (the paper's substitutions
(59)-(81) are deliberately NOT used, so the table is an independent check of a
program that does use them).

Method (scipy.integrate.quad = QUADPACK)
---------------------------------------
* Inputs.  Each grid point is a short decimal string, exactly as a Fortran
  program would read it into binary128.  The integrals depend on the
  *differences* ``r-R``, ``1-R`` and ``1-r`` much more sensitively than on
  ``r`` itself (near the apse ``d(Theta)/dr ~ (r-R)**-1/2``).  Forming those
  differences as ``float(r) - float(R)`` would inject an input error of
  ~1e-16/(r-R), i.e. ~1e-7 relative for ``r - R = 1e-9``.  So ``R`` is taken as
  ``float(R_string)`` while ``r-R``, ``1-R`` and ``1-r`` are computed exactly in
  ``decimal.Decimal`` from the strings and only then rounded to double.  All
  results therefore correspond to the decimal inputs to within a few ulps.

* Splitting.  ``[r, 1]`` is split at the midpoint ``m = (1+R)/2``.  On the
  left part the integrand is written in the shifted variable ``u = x - R``
  and on the right part in ``v = 1 - x`` (pure translations of the original
  integral, not a change of its form).  Then every factor ``x - R``, ``1 - x``
  and ``x`` is computed without cancellation, and the endpoint singularities
  sit at ``u = 0`` or ``v = 0`` where QUADPACK's algebraic weight handles them
  analytically.

* Endpoint singularities are removed with ``weight='alg'``
  (QUADPACK QAWS, weight ``(y-a)**alpha * (b-y)**beta``):

  - left part, first sub-interval, only when ``r == R``: the factor
    ``(x-R)**-1/2`` becomes the weight ``u**-1/2`` (``alpha=-1/2``);
    for ``r > R`` that factor is smooth on ``[r,1]`` and stays in the
    integrand;
  - right part (ending at ``x = 1``): the factor ``(1-x)**beta`` becomes the
    weight ``v**beta`` with ``beta = +1/2`` for Theta (its ``(1-x)/sqrt(1-x)``),
    ``-1/2`` for T, and no weight (plain QAGS) for S, which is regular at 1.

* Near-singular region.  For small ``R`` the integrands vary on the scale
  ``R`` near ``x = R`` (factor ``1/x`` and the complex roots of ``Q`` at
  ``|x| ~ R``), and for ``r`` just above ``R`` the factor ``(x-R)**-1/2``
  varies on the scale ``r - R``.  The left part is therefore split at the
  geometric points ``u = h, 2h, 4h, ...`` (i.e. ``x = R + h*2**k``) up to
  ``m``, with ``h = r - R`` if ``r > R`` and ``h = min(R, 1-R)/2`` if
  ``r == R``.  On every sub-interval the nearest singularity of the remaining
  smooth factor is at least one sub-interval length away, so Gauss-Kronrod
  converges fast.  (quad's own ``points`` argument cannot be combined with a
  weight, so the sub-intervals are integrated separately and summed; all
  integrands are positive, so there is no cancellation in the sum.)

* Tolerances: ``epsabs=0``, ``limit=200`` and ``epsrel = 50*eps ~ 1.11e-14``,
  which is the smallest value QUADPACK accepts when ``epsabs = 0`` (the
  requested 1e-14 is rejected by QUADPACK's input check).  The ``*_err``
  columns are the sums of QUADPACK's absolute error estimates over the
  sub-intervals.

* Second method (``--mpmath``): ``mpmath.quad`` (tanh-sinh) at 30 significant
  digits on the original integrands (no weights, no factor removed), with
  ``r``, ``R`` taken exactly from the decimal strings, split at the same
  points and in the same translated variables u, v (needed so that
  tanh-sinh nodes near ``x = R`` and ``x = 1`` keep their distance to the
  endpoint).  The script prints
  the maximum relative difference scipy vs mpmath per quantity and flags any
  row worse than 1e-12.  (Tanh-sinh stops its nodes about 10**-dps from an
  endpoint, so for the x**-1/2 endpoint singularities the 30-digit mpmath
  values are themselves good only to ~1e-17 relative; mpmath's own error
  estimate is printed.  That is ample for checking double precision; use
  ``--mp-dps`` for more.)

Output CSV: ``#`` comment lines (command, versions, date, method), then the
header ``r,R,theta,s,t,theta_err,s_err,t_err``; ``r`` and ``R`` are the
decimal strings used, the other columns are written with ``%.17e``.

``--check`` recomputes the table with scipy and compares it with the stored CSV
(``--out`` or the default path); the exit status is non-zero if any relative
difference exceeds 1e-12 or the set of grid points differs.
"""

from __future__ import annotations

import argparse
import csv
import datetime
import math
import os
import sys
import time
import warnings
from decimal import Decimal, localcontext

import numpy as np
import scipy
from scipy.integrate import IntegrationWarning, quad

DEFAULT_OUT = os.path.normpath(os.path.join(
    os.path.dirname(os.path.abspath(__file__)), os.pardir, "data", "reference", "quadpack_grid.csv"
))
HEADER = ["r", "R", "theta", "s", "t", "theta_err", "s_err", "t_err"]

# QUADPACK rejects epsrel < max(50*eps, 5e-29) when epsabs <= 0.
EPSREL = max(1e-14, 50.0 * np.finfo(float).eps)
LIMIT = 200
CHECK_TOL = 1e-12
MP_DPS = 30

R_VALUES = ["1e-4", "1e-3", "0.01", "0.05", "0.1", "0.2", "0.3", "0.5", "0.7", "0.9", "0.99", "0.999"]
# r = R + f*(1-R) for these fractions f (f = 0 is the apse itself).
R_FRACTIONS = ["0", "1e-6", "0.01", "0.1", "0.5", "0.9", "0.999999"]
# R values that also get the trivial row r = 1 (all three integrals vanish).
R_WITH_R_EQ_1 = {"1e-3", "0.1", "0.5", "0.9", "0.999"}
SIG_DIGITS = 12


# --------------------------------------------------------------------------
# Grid
# --------------------------------------------------------------------------
def _dec_str(x: Decimal) -> str:
    """Shortest plain (non-exponent) decimal string for ``x``."""
    s = format(x.normalize(), "f")
    return s


def make_grid() -> list[tuple[str, str]]:
    """Return the list of (r_string, R_string) grid points."""
    grid = []
    for R_s in R_VALUES:
        R = Decimal(R_s)
        R_str = _dec_str(R)
        for f_s in R_FRACTIONS:
            with localcontext() as ctx:
                ctx.prec = 50
                r_exact = R + Decimal(f_s) * (1 - R)
            with localcontext() as ctx:
                ctx.prec = SIG_DIGITS
                r = +r_exact  # round to SIG_DIGITS significant digits
            r = min(max(r, R), Decimal(1))
            if f_s != "0" and not (R < r < 1):
                raise ValueError(f"grid point r={r} not strictly inside (R={R}, 1)")
            grid.append((R_str if f_s == "0" else _dec_str(r), R_str))
        if R_s in R_WITH_R_EQ_1:
            grid.append(("1", R_str))
    return grid


# --------------------------------------------------------------------------
# scipy / QUADPACK evaluation
# --------------------------------------------------------------------------
class _Warnings:
    """Collects IntegrationWarnings raised by quad (one list per table)."""

    def __init__(self):
        self.items: list[str] = []


def _quad(func, a, b, wlog: _Warnings, tag: str, alpha=0.0, beta=0.0):
    """quad on [a,b] with optional algebraic weight (y-a)**alpha (b-y)**beta."""
    kw = dict(epsabs=0.0, epsrel=EPSREL, limit=LIMIT)
    if alpha != 0.0 or beta != 0.0:
        kw.update(weight="alg", wvar=(alpha, beta))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", IntegrationWarning)
        val, err = quad(func, a, b, **kw)
    for w in caught:
        wlog.items.append(f"{tag} [{a!r},{b!r}]: {' '.join(str(w.message).split())}")
    return val, err


def breakpoints_u(d: float, U: float, R: float, omR: float) -> list[float]:
    """Split points in u = x - R for the left part [d, U] (U = (1-R)/2).

    Geometric: h, 2h, 4h, ... with h = d (r > R) or h = min(R, 1-R)/2 (r == R).
    The first point is the lower limit itself, the last one is U.
    """
    h = d if d > 0.0 else 0.5 * min(R, omR)
    pts = [d] if d > 0.0 else [0.0, min(h, U)]
    p = pts[-1]
    while 2.0 * p < U:
        p *= 2.0
        pts.append(p)
    if pts[-1] < U:
        pts.append(U)
    return pts


def scipy_values(r_s: str, R_s: str, wlog: _Warnings | None = None):
    """Theta, S, T and QUADPACK error estimates at the decimal inputs (r_s, R_s)."""
    if wlog is None:
        wlog = _Warnings()
    rD, RD = Decimal(r_s), Decimal(R_s)
    if not (0 < RD < 1 and RD <= rD <= 1):
        raise ValueError(f"need 0 < R < 1 and R <= r <= 1, got r={r_s}, R={R_s}")
    if rD == 1:
        return (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)

    R = float(RD)
    omR = float(1 - RD)  # 1 - R, exact decimal then rounded
    d = float(rD - RD)  # r - R
    omr = float(1 - rD)  # 1 - r
    c_theta = math.sqrt(R**3 / omR)
    R2q = R * R / omR
    U = 0.5 * omR  # split point m = R + U = 1 - U
    tag = f"r={r_s} R={R_s}"

    def Q(x):
        return x * x + R * x + R2q

    # Full integrands written in terms of (x, x-R, 1-x), each passed in
    # without cancellation.  Factors moved into a QUADPACK weight are dropped
    # from the corresponding "w" variants.
    def th(x, xmR, omx):
        return c_theta * math.sqrt(omx) / (x * math.sqrt(xmR * Q(x)))

    def sf(x, xmR, omx):
        return x * math.sqrt(x) / math.sqrt(xmR * Q(x))

    def tf(x, xmR, omx):
        return x * x / math.sqrt(2.0 * omx * xmR * Q(x))

    tot = np.zeros(3)
    err = np.zeros(3)

    # ---- left part: u = x - R in [d, U] (only if r < m) --------------------
    if d < U:
        pts = breakpoints_u(d, U, R, omR)
        for k in range(len(pts) - 1):
            a, b = pts[k], pts[k + 1]
            if k == 0 and d == 0.0:
                # (x-R)^(-1/2) = u^(-1/2) is the QAWS weight (alpha = -1/2).
                fs = (
                    lambda u: c_theta * math.sqrt(omR - u) / ((R + u) * math.sqrt(Q(R + u))),
                    lambda u: (R + u) * math.sqrt(R + u) / math.sqrt(Q(R + u)),
                    lambda u: (R + u) ** 2 / math.sqrt(2.0 * (omR - u) * Q(R + u)),
                )
                alpha = -0.5
            else:
                fs = tuple(
                    (lambda u, g=g: g(R + u, u, omR - u)) for g in (th, sf, tf)
                )
                alpha = 0.0
            for i, f in enumerate(fs):
                v, e = _quad(f, a, b, wlog, f"{tag} {'tst'[i]} u", alpha=alpha)
                tot[i] += v
                err[i] += e
        V = U
    else:
        V = omr  # whole interval lies in the right part: v in [0, 1-r]

    # ---- right part: v = 1 - x in [0, V] -----------------------------------
    # Theta: (1-x)/sqrt(1-x) = v^(+1/2) -> weight alpha=+1/2 at v=0
    # S    : regular at x=1             -> plain QAGS
    # T    : (1-x)^(-1/2) = v^(-1/2)    -> weight alpha=-1/2 at v=0
    fr = (
        (lambda v: c_theta / ((1.0 - v) * math.sqrt((omR - v) * Q(1.0 - v))), 0.5),
        (lambda v: sf(1.0 - v, omR - v, v), 0.0),
        (lambda v: (1.0 - v) ** 2 / math.sqrt(2.0 * (omR - v) * Q(1.0 - v)), -0.5),
    )
    for i, (f, alpha) in enumerate(fr):
        v, e = _quad(f, 0.0, V, wlog, f"{tag} {'tst'[i]} v", alpha=alpha)
        tot[i] += v
        err[i] += e
    return tuple(tot), tuple(err)


# --------------------------------------------------------------------------
# mpmath cross-check (original integrands, same split points)
# --------------------------------------------------------------------------
def mpmath_values(r_s: str, R_s: str, dps: int = MP_DPS):
    """Theta, S, T by mpmath.quad (tanh-sinh) at ``dps`` digits.

    The integrands are the original formulas (55)-(57), with no factor moved
    into a weight.  As in the scipy evaluation the integration variable is
    translated (u = x - R on the left part, v = 1 - x on the right part):
    otherwise tanh-sinh nodes within 10**-dps of x = R or x = 1 round onto the
    endpoint itself and the differences x - R, 1 - x lose all their digits.
    r - R, 1 - R and 1 - r are formed exactly from the decimal strings.
    """
    import mpmath as mp

    with mp.workdps(dps):
        RD, rD = Decimal(R_s), Decimal(r_s)
        if rD == 1:
            return (mp.mpf(0),) * 3, (mp.mpf(0),) * 3
        R = mp.mpf(R_s)
        omR = mp.mpf(str(1 - RD))
        d = mp.mpf(str(rD - RD))
        omr = mp.mpf(str(1 - rD))
        c = mp.sqrt(R**3 / omR)
        R2q = R * R / omR

        def Q(x):
            return x * x + R * x + R2q

        # Original integrands; xmR = x - R and omx = 1 - x supplied exactly.
        fth = lambda x, xmR, omx: c * omx / (x * mp.sqrt(omx * xmR * Q(x)))
        fs = lambda x, xmR, omx: x * x / mp.sqrt(x * xmR * Q(x))
        ft = lambda x, xmR, omx: x * x / mp.sqrt(2 * omx * xmR * Q(x))

        U = omR / 2
        # Same split points as the scipy evaluation (interior points need not
        # be exact; the end points r, (1+R)/2 and 1 are).
        d_f, U_f = float(rD - RD), 0.5 * float(1 - RD)
        left = d_f < U_f
        if left:
            us = [d] + [mp.mpf(u) for u in breakpoints_u(d_f, U_f, float(RD), float(1 - RD))[1:-1]] + [U]
        vals, errs = [], []
        for f in (fth, fs, ft):
            v, e = mp.mpf(0), mp.mpf(0)
            if left:
                a, ea = mp.quad(lambda u: f(R + u, u, omR - u), us, error=True)
                v, e = v + a, e + ea
            V = U if left else omr
            a, ea = mp.quad(lambda w: f(1 - w, omR - w, w), [0, V], error=True)
            vals.append(v + a)
            errs.append(e + ea)
        return tuple(vals), tuple(errs)


# --------------------------------------------------------------------------
# Table I/O
# --------------------------------------------------------------------------
def compute_table(wlog: _Warnings):
    rows = []
    for r_s, R_s in make_grid():
        vals, errs = scipy_values(r_s, R_s, wlog)
        rows.append((r_s, R_s, vals, errs))
    return rows


def write_csv(path, rows, comments):
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w", newline="") as fh:
        for c in comments:
            fh.write(f"# {c}\n")
        fh.write(",".join(HEADER) + "\n")
        for r_s, R_s, vals, errs in rows:
            fh.write(",".join([r_s, R_s] + ["%.17e" % x for x in (*vals, *errs)]) + "\n")


def read_csv(path):
    with open(path) as fh:
        lines = [ln for ln in fh if not ln.startswith("#")]
    reader = csv.reader(lines)
    header = next(reader)
    if header != HEADER:
        raise ValueError(f"unexpected header {header}")
    out = {}
    for row in reader:
        out[(row[0], row[1])] = tuple(float(x) for x in row[2:5])
    return out


def _rel(a, b):
    return abs(a - b) / abs(b) if b != 0 else abs(a - b)


def run_check(path, rows) -> int:
    stored = read_csv(path)
    computed = {(r, R): v for r, R, v, _ in rows}
    status = 0
    if set(stored) != set(computed):
        print(f"grid mismatch: only stored {sorted(set(stored) - set(computed))}, "
              f"only computed {sorted(set(computed) - set(stored))}")
        status = 1
    worst = [0.0, 0.0, 0.0]
    for key in sorted(set(stored) & set(computed)):
        for i in range(3):
            rd = _rel(computed[key][i], stored[key][i])
            worst[i] = max(worst[i], rd)
            if rd > CHECK_TOL:
                print(f"FAIL r={key[0]} R={key[1]} {('theta', 's', 't')[i]}: "
                      f"stored {stored[key][i]:.17e} computed {computed[key][i]:.17e} rel {rd:.2e}")
                status = 1
    print(f"check {path}: {len(stored)} stored rows; max rel diff theta={worst[0]:.2e} "
          f"s={worst[1]:.2e} t={worst[2]:.2e} -> {'OK' if status == 0 else 'FAILED'}")
    return status


def run_mpmath(rows, dps: int = MP_DPS):
    """Compare the scipy rows with mpmath; return (max rel diffs, summary lines)."""
    worst = [0.0, 0.0, 0.0]
    where = [None, None, None]
    flagged = []
    mp_err_max = 0.0
    for r_s, R_s, vals, _ in rows:
        mvals, merrs = mpmath_values(r_s, R_s, dps)
        for i in range(3):
            m = float(mvals[i])
            if m != 0:
                mp_err_max = max(mp_err_max, float(merrs[i]) / abs(m))
            rd = _rel(vals[i], m)
            if rd > worst[i]:
                worst[i], where[i] = rd, (r_s, R_s)
            if rd > CHECK_TOL:
                flagged.append(f"r={r_s} R={R_s} {('theta', 's', 't')[i]} rel {rd:.2e}")
    lines = [
        f"mpmath.quad cross-check ({dps} digits, original integrands, same split points): "
        f"max rel diff theta={worst[0]:.2e} (r={where[0][0]},R={where[0][1]}) "
        f"s={worst[1]:.2e} (r={where[1][0]},R={where[1][1]}) "
        f"t={worst[2]:.2e} (r={where[2][0]},R={where[2][1]}); "
        f"max mpmath rel error estimate {mp_err_max:.1e}; rows worse than {CHECK_TOL:g}: {len(flagged)}"
    ]
    return worst, lines, flagged


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=DEFAULT_OUT, help="CSV path (default data/reference/quadpack_grid.csv)")
    ap.add_argument("--check", action="store_true",
                    help="recompute with scipy and compare with the stored CSV instead of writing it")
    ap.add_argument("--mpmath", action="store_true",
                    help="also cross-check every row against mpmath.quad (a few seconds)")
    ap.add_argument("--mp-dps", type=int, default=MP_DPS,
                    help=f"mpmath working precision in decimal digits (default {MP_DPS})")
    args = ap.parse_args(argv)

    t0 = time.time()
    wlog = _Warnings()
    rows = compute_table(wlog)
    t_scipy = time.time() - t0
    print(f"scipy {scipy.__version__}: {len(rows)} rows in {t_scipy:.2f} s, "
          f"{len(wlog.items)} IntegrationWarnings", file=sys.stderr)
    for w in wlog.items:
        print("  warning:", w, file=sys.stderr)

    status = 0
    mp_lines = []
    if args.mpmath:
        t1 = time.time()
        _, mp_lines, flagged = run_mpmath(rows, args.mp_dps)
        for ln in mp_lines:
            print(ln, file=sys.stderr)
        for f in flagged:
            print("  FLAG:", f, file=sys.stderr)
        print(f"mpmath cross-check took {time.time() - t1:.1f} s", file=sys.stderr)
        status |= bool(flagged)

    if args.check:
        status |= run_check(args.out, rows)
        return int(status)

    import mpmath

    comments = [
        "Reference values of Theta(r,R), S(r,R), T(r,R) (Tee 1998, eqs 55-57), original integrals",
        "command: python scripts/make_quadpack_grid.py" + ("".join(" " + a for a in (argv or sys.argv[1:]))),
        f"date: {datetime.datetime.now(datetime.timezone.utc).strftime('%Y-%m-%d %H:%M:%S UTC')}",
        f"scipy {scipy.__version__}, numpy {np.__version__}, mpmath {mpmath.__version__}, "
        f"python {sys.version.split()[0]}",
        f"scipy.integrate.quad (QUADPACK QAGS/QAWS alg weights), epsabs=0, epsrel={EPSREL:.3e}, "
        f"limit={LIMIT}; split at x=(1+R)/2 and geometric x=R+h*2^k; see script docstring",
        "r, R are the exact decimal inputs; r-R, 1-R, 1-r formed exactly in decimal then rounded",
        "*_err = sum of QUADPACK absolute error estimates over sub-intervals",
        f"QUADPACK IntegrationWarnings: {len(wlog.items)}"
        + "".join(f"; {w}" for w in wlog.items),
    ] + mp_lines
    write_csv(args.out, rows, comments)
    print(f"wrote {os.path.normpath(args.out)}", file=sys.stderr)
    return int(status)


if __name__ == "__main__":
    sys.exit(main())
