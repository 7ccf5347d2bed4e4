#!/usr/bin/env python3
"""Independent two-point references for the general engine: power laws and the
logarithmic potential (Tee 1998, section 2), solved with mpmath on the ORIGINAL integrals.

Command (from the repository root), one field per run:
    .venv/bin/python scripts/make_general_reference.py power1.5 > data/reference/general_power1.5_mpmath.csv
    .venv/bin/python scripts/make_general_reference.py power3 > data/reference/general_power3_mpmath.csv
    .venv/bin/python scripts/make_general_reference.py logarithmic > data/reference/general_logarithmic_mpmath.csv
    .venv/bin/python scripts/make_general_reference.py harmonic > data/reference/general_harmonic_mpmath.csv
    .venv/bin/python scripts/make_general_reference.py power2 > data/reference/general_power2_mpmath.csv
    .venv/bin/python scripts/make_general_reference.py power32 > data/reference/general_power32_mpmath.csv
    .venv/bin/python scripts/make_general_reference.py power6 > data/reference/general_power6_mpmath.csv

Speed laws v^2 = P(x) (release from rest at radius 1): power law F = 1/r^n,
P = 2 (x^(1-n) - 1)/(n - 1) (power2 is the inverse square of the fast path);
logarithmic potential (F = 1/r), P = -2 log x; harmonic (F = r, inside a uniform planet,
Saitoh's units), P = 1 - x^2.
With the apse R < rho <= 1 the integrals are Tee's (27), (33), (39) as printed:
    Theta(r,R) = int_r^1 dx / (x sqrt((v(R)/R)^2 x^2/v(x)^2 - 1)),
    S(r,R)     = int_r^1 dx / sqrt(1 - (R/v(R))^2 v(x)^2/x^2),
    T(r,R)     = int_r^1 dx / (v(x) sqrt(1 - (R/v(R))^2 v(x)^2/x^2)),
second half-arch 2 F(R,R) - F(r,R) (eq. 29), taken by tanh-sinh quadrature (mp.quad) on
[r, 1] split at R 10^(2k) (the integrands vary on the scale R near the apse). Endpoint
B = (rho, psi) is on the first half-arch iff psi <= Theta(rho, rho).

Each endpoint is made from a target apse radius: psi = Upsilon(R_target) rounded to a
binary128 number (so psi, like rho, is exactly a binary128 number: the quad-precision
solver gets the same problem); then R-bar is solved for that psi by the secant method in
log R (or in u = sqrt(rho - R) next to the apse), and the root is checked to be
bracketed (Upsilon - psi changes sign across it). Everything is done at 55 and at 70
digits (85 and 100 for the ill-conditioned rows of `precisions`); the row is kept only
when R-bar, s and t agree to >= 40 digits, and the values at the higher precision are
written with 45 significant digits.
Columns: class, rho, psi, arch, R, s, t, agreement (digits between the precisions),
cond_R, cond_s, cond_t: |dF/dpsi| psi/F by central differences in log R (in sqrt(rho - R)
next to the apse) at the lower precision (the tables made before these columns existed,
power1.5, power3, power10, logarithmic, lack them; test_central_force measures its own).
"""
import sys

import mpmath as mp


def law(name):
    if name == "logarithmic":
        return lambda x: -2 * mp.log(x)
    if name == "harmonic":
        return lambda x: 1 - x * x
    n = mp.mpf(name[len("power"):])
    return lambda x: 2 * (x ** (1 - n) - 1) / (n - 1)


def breaks(a, b, big_r):
    """a, the points R 100^k inside (a, b), b."""
    pts = [a]
    p = big_r * 100
    while p < b:
        if p > a * 1.5:
            pts.append(p)
        p *= 100
    pts.append(b)
    return pts


def relative_quad(f, points):
    """mp.quad to the working precision relative to the value (mp.quad's own target is
    absolute): a second pass on f divided by the first estimate's size."""
    first = mp.quad(f, points)
    if first == 0:
        return first
    scale = abs(first)
    return scale * mp.quad(lambda x: f(x) / scale, points)


class Field:
    def __init__(self, name):
        self.name = name
        self.p = law(name)
        if name == "logarithmic":
            self.limit = mp.pi / 2
        elif name == "harmonic":
            self.limit = mp.pi / 2
        else:
            self.limit = mp.pi / (mp.mpf(name[len("power"):]) + 1)

    def integrals(self, r, big_r, which):
        p = self.p
        extra = 2 * mp.mp.dps + 20
        with mp.workdps(extra):
            k2 = big_r ** 2 / p(big_r)          # (R/v(R))^2, R exact

        def theta(x):
            px = p(x) if x < 1 else 0
            if px == 0:      # x = 1 to working precision: the integrand's limit
                return mp.mpf(0)
            return 1 / (x * mp.sqrt(x ** 2 / (k2 * px) - 1))

        def length(x):
            return 1 / mp.sqrt(1 - k2 * p(x) / x ** 2)

        def time(x):
            px = p(x) if x < 1 else 0
            if px == 0:      # only at nodes of negligible weight next to x = 1
                return mp.mpf(0)
            return 1 / (mp.sqrt(px) * mp.sqrt(1 - k2 * px / x ** 2))
        fs = {"theta": theta, "s": length, "t": time}
        pts = breaks(r, mp.mpf(1), big_r)
        if len(pts) == 2:
            pts = [pts[0], (pts[0] + pts[1]) / 2, pts[1]]
        out = []
        for w in which:
            f = fs[w]

            def near_apse(u):      # x = R + u^2: the apse's 1/sqrt(x - R) removed
                with mp.workdps(extra):
                    return 2 * u * f(big_r + u * u)

            def near_start(v):     # x = 1 - v^2: the start's 1/sqrt(1 - x) removed
                with mp.workdps(extra):
                    return 2 * v * f(1 - v * v)

            def plain(x):
                with mp.workdps(extra):
                    return f(x)
            total = relative_quad(near_apse, [mp.sqrt(pts[0] - big_r),
                                              mp.sqrt(pts[1] - big_r)])
            if len(pts) > 3:
                total += relative_quad(plain, pts[1:-1])
            total += relative_quad(near_start, [0, mp.sqrt(1 - pts[-2])])
            out.append(total)
        return out

    def upsilon(self, rho, big_r, second):
        th = self.integrals(rho, big_r, ["theta"])[0]
        if second:
            return 2 * self.integrals(big_r, big_r, ["theta"])[0] - th
        return th

    def values(self, rho, big_r, second):
        th, s, t = self.integrals(rho, big_r, ["theta", "s", "t"])
        if second:
            th2, s2, t2 = self.integrals(big_r, big_r, ["theta", "s", "t"])
            th, s, t = 2 * th2 - th, 2 * s2 - s, 2 * t2 - t
        return th, s, t


def solve(field, rho, psi, second, r_target, near_apse):
    """R-bar for Upsilon(R) = psi: a bracket found by expanding steps from R_target, then
    regula falsi with the Anderson-Bjorck correction inside it (in log R, or in
    u = sqrt(rho - R) next to the apse)."""
    if near_apse:
        def radius(y):
            return rho - y * y
        y0 = mp.sqrt(rho - r_target)
        lo_limit, hi_limit = mp.mpf(0), mp.sqrt(rho)
    else:
        radius = mp.exp
        y0 = mp.log(r_target)
        lo_limit, hi_limit = mp.mpf(-11000), mp.log(rho)

    def f(y):
        return field.upsilon(rho, radius(y), second) - psi
    f0 = f(y0)
    h = max(abs(y0), mp.mpf(1)) * mp.mpf(10) ** -24
    f1 = f(min(y0 + h, hi_limit))
    direction = 1 if (f1 - f0) * f0 < 0 else -1
    a, fa = y0, f0
    while True:
        b = min(max(y0 + direction * h, lo_limit), hi_limit)
        fb = f(b)
        if fb * fa <= 0:
            break
        a, fa = b, fb
        h *= 4
        if b in (lo_limit, hi_limit):
            raise RuntimeError("no bracket at rho=%s psi=%s" % (rho, psi))
    small = abs(psi) * mp.mpf(10) ** (-mp.mp.dps + 8)
    width = mp.mpf(10) ** (-mp.mp.dps + 4)
    for _ in range(400):
        if abs(fb) <= small or abs(b - a) <= width * max(abs(b), mp.mpf(1e-30)):
            break
        c = b - fb * (b - a) / (fb - fa)
        fc = f(c)
        if fc * fb < 0:
            a, fa = b, fb
        else:
            m = 1 - fc / fb
            fa = fa * (m if m > 0 else mp.mpf(1) / 2)
        b, fb = c, fc
    else:
        if abs(fb) > abs(psi) * mp.mpf(10) ** (-mp.mp.dps + 15):
            raise RuntimeError("no convergence at rho=%s psi=%s" % (rho, psi))
    return radius(b)


def make_endpoint(field, rho, r_target, second, near_apse):
    th = field.upsilon(rho, r_target, second)
    psi = binary128(th)
    big_r = solve(field, rho, psi, second, r_target, near_apse)
    _, s, t = field.values(rho, big_r, second)
    return psi, big_r, s, t


def digits(a, b):
    if a == b:
        return 99
    return float(-mp.log10(abs(a - b) / abs(b)))


def binary128(x):
    """x rounded to the nearest binary128 number (113-bit significand)."""
    _, e = mp.frexp(x)
    return mp.ldexp(mp.nint(mp.ldexp(x, 113 - e)), e - 113)


# Apse radii of the complete_small_r and edge_small_r rows, per field where not the
# default. R-bar is ill conditioned there (cond ~ 1/R for the harmonic law and the
# inverse square): rows whose cond exceeds ~1e12 are made at 85 and 100 digits so that
# the two precisions still agree to >= 40 digits.
EDGE_RADII = {"harmonic": ["1e-6", "1e-12", "1e-20"], "power2": ["1e-6", "1e-20", "1e-30"]}


# (low, high) digits per class where a field needs more than the defaults: for n = 32
# R-bar's conditioning at the edge of the sector grows like R^(-(n-1)/2) (about 1e31 at
# R = 0.01), and the first half-arch's tiny psi (1e-739 at R = 1e-45) loses about 30 digits
# in the quadrature: at 55 and 70 digits those rows agreed to only 28-40 (n = 6: one
# first-half-arch row, R = 1e-45 at rho = 0.1, to 38.9).
CLASS_PRECISIONS = {"power32": {"complete_small_r": (110, 130), "edge_small_r": (110, 130),
                                "first_small_r": (85, 100)},
                    "power6": {"first_small_r": (85, 100)}}


def precisions(name, r, cls=None):
    """(low, high) digits for a row with apse radius r (and class cls), as a 1-tuple,
    or ()."""
    if name in ("harmonic", "power2") and mp.mpf(r) < mp.mpf("1e-15") and \
            cls in ("complete_small_r", "edge_small_r"):
        return ((85, 100),)
    if cls in CLASS_PRECISIONS.get(name, {}):
        return (CLASS_PRECISIONS[name][cls],)
    return ()


def conditions(field, rho, big_r, second, near_apse):
    """|dF/dpsi| psi/F for F = R-bar, s, t by central differences in log R (in
    sqrt(rho - R) next to the apse)."""
    if near_apse:
        u = mp.sqrt(rho - big_r)
        radii = [rho - (u * (1 + k * mp.mpf(10) ** -8)) ** 2 for k in (-1, 1)]
    else:
        radii = [big_r * mp.exp(k * mp.mpf(10) ** -12) for k in (-1, 1)]
    lo, hi = (field.values(rho, r, second) for r in radii)
    mid = field.values(rho, big_r, second)
    dpsi = hi[0] - lo[0]
    return [abs((radii[1] - radii[0]) / dpsi) * mid[0] / big_r] + \
        [abs((hi[k] - lo[k]) / dpsi) * mid[0] / mid[k] for k in (1, 2)]


def cases(field):
    """(class, rho, R_target, second, near_apse); rho a binary128 number."""
    mp.mp.dps = 80
    half, tenth = mp.mpf(1) / 2, binary128(mp.mpf("0.1"))
    out = []
    # complete arches rho = 1 with R -> 1 (small psi) and general R
    for gap in ["1e-7", "1e-4", "0.01", "0.3", "0.7"]:
        out.append(("complete", mp.mpf(1), 1 - mp.mpf(gap), True, True))
    # (R-bar's conditioning at the edge grows like R^(-(n-1)/2): steep laws get larger R)
    steep = field.name.startswith("power") and mp.mpf(field.name[len("power"):]) > 5
    small = ["1e-30", "1e-69"] if field.name == "logarithmic" else ["1e-3", "1e-5"]
    if field.name in EDGE_RADII:
        small = EDGE_RADII[field.name]
    for r in (["0.1", "0.03"] if steep else small):
        out.append(("complete_small_r", mp.mpf(1), mp.mpf(r), True, False)
                   + precisions(field.name, r, "complete_small_r"))
    # general endpoints, both half-arches
    for rho in [binary128(mp.mpf("0.9")), half, tenth]:
        for frac in ["0.3", "0.8"]:
            r = rho * mp.mpf(frac)
            out.append(("first", rho, r, False, False))
            out.append(("second", rho, r, True, False))
    # small R on the first half-arch (small psi: well conditioned) and on the second
    # next to the edge of the accessible region (R-bar ill conditioned for power laws)
    edge = ["1e-12", "1e-30", "1e-69"] if field.name == "logarithmic" else ["1e-3", "1e-6"]
    if steep:
        edge = ["0.01", "0.03"]
    if field.name in EDGE_RADII:
        edge = EDGE_RADII[field.name]
    for rho in [half, tenth]:
        for r in ["1e-12", "1e-30", "1e-45"]:
            out.append(("first_small_r", rho, mp.mpf(r), False, False)
                       + precisions(field.name, r, "first_small_r"))
        for r in edge:
            out.append(("edge_small_r", rho, mp.mpf(r), True, False)
                       + precisions(field.name, r, "edge_small_r"))
    # within 1e-17 of the apse, both sides
    for rho in [mp.mpf("0.75"), tenth]:
        for gap in ["1e-17", "1e-25"]:
            r = rho - rho * mp.mpf(gap)
            out.append(("near_apse_first", rho, r, False, True))
            out.append(("near_apse_second", rho, r, True, True))
    return out


def main():
    name = sys.argv[1]
    rows = []
    for case in cases(Field(name)):
        cls, rho, r_target, second, near_apse = case[:5]
        low, high = case[5] if len(case) > 5 else (55, 70)
        results = []
        try:
            for dps in (low, high):
                mp.mp.dps = dps
                field = Field(name)
                results.append(make_endpoint(field, +rho, +r_target, second, near_apse))
            mp.mp.dps = low
            cond = conditions(Field(name), +rho, results[0][1], second, near_apse)
        except RuntimeError as error:
            print("# dropped %s rho=%s: %s" % (cls, rho, error), file=sys.stderr)
            continue
        (psi_a, r_a, s_a, t_a), (psi_b, r_b, s_b, t_b) = results
        agree = min(digits(r_a, r_b), digits(s_a, s_b), digits(t_a, t_b))
        if psi_a != psi_b or agree < 40:
            print("# dropped %s rho=%s: precisions agree to %.1f" % (cls, rho, agree),
                  file=sys.stderr)
            continue
        mp.mp.dps = high
        rows.append((cls, mp.nstr(rho, 45), mp.nstr(psi_b, 60),
                     "second" if second else "first", mp.nstr(r_b, 45), mp.nstr(s_b, 45),
                     mp.nstr(t_b, 45), "%.1f" % agree, *[mp.nstr(c, 3) for c in cond]))
        print(",".join(rows[-1]), file=sys.stderr, flush=True)
    print("# general engine references, field %s: scripts/make_general_reference.py %s"
          % (name, name))
    print("# mpmath 55 and 70 digits (more where precisions() says, see the script) on Tee (27), "
          "(33), (39); psi is a binary128 number")
    print("class,rho,psi,arch,R,s,t,agreement,cond_R,cond_s,cond_t")
    for row in rows:
        print(",".join(row))


if __name__ == "__main__":
    main()
