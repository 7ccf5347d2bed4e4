#!/usr/bin/env python3
"""Independent two-point references for the repulsive inverse-square field (Tee 1998,
sections 2, 3, 6), solved with mpmath on the ORIGINAL integrals (23), (31), (37).

Command (from the repository root; about 80 s of CPU time):
    .venv/bin/python scripts/make_repulsive_two_point_reference.py \
        > data/reference/repulsive_two_point_mpmath.csv
(optional arguments: 0-based case numbers of `cases()` to make only those rows.)

Law (mu = -1, release from rest at radius 1): v^2 = 2 (x - 1)/x, x >= 1 (44). A curve
from A = (1, 0) is fixed by its angular momentum K (16); with x = 1 + w (a change of
the variable of integration only) the integrals are, as printed,
    theta = int dx / (x sqrt(x^2/(K^2 v^2) - 1))          (23)
    s     = int dx / sqrt(1 - K^2 v^2/x^2)                (31)
    t     = int dx / (v sqrt(1 - K^2 v^2/x^2))            (37)
from x = 1 up to rho, r increasing (the positive root, section 2.3.1 "Repulsive force").
Bounded curves (K^2 > 27/8) have the apse R < 3/2 with K = R/v(R) (25), i.e.
K^2 = R^3/(2 (R - 1)); the second half-arch is 2 F(R, R) - F(rho, R) (29), and a complete
arch (rho = 1) is 2 F(R, R). Unbounded curves (K^2 < 27/8) reach every radius.

What the field reports (src/fields/brachistochrone_repulsive_field.f90, `solve`): the
least-time curve, the one sweeping psi itself anticlockwise (m = 0); arch 'unbounded',
'first', 'second' or 'complete' (rho = 1); R = the apse radius R-bar for bounded curves
only. For unbounded curves the program reports no R (has_apse_radius = .false., the
R column of its outputs is empty): the R column here is empty too, and K2 = K^2 is given
for the record (the field interface does not report it).

Quadrature: mp.quad (tanh-sinh) on pieces: x = 1 + u^2 next to the start (the 1/sqrt(x-1)
of t removed), x = R - u^2 next to the apse of bounded curves (the 1/sqrt(R - x)
removed), plain x elsewhere; breakpoints geometric around x = 3/2, where the integrands
of near-critical curves peak (the minimum of x^2/(K^2 v^2) is at x = 3/2 exactly), and
geometric in x for large rho. The integrands are evaluated at 2 dps + 20 digits (the
cancellation in 1 - K^2 v^2/x^2 next to the apse and in x^2/(K^2 v^2) - 1 next to 3/2),
each piece is scaled to its own size (mp.quad's tolerance is absolute).

Each endpoint is made from a target curve (psi = theta(rho) of that curve rounded to a
binary128 number, so psi is exactly the number the quad-precision program reads) or is a
given binary128 psi (then first solved at 25 digits from a rough start). The curve
parameter y (log K^2, log(27/8 - K^2), log(R - 1), log(3/2 - R) or sqrt(R - rho), per
row) is then solved for psi: a bracket (sign change of theta(rho; y) - psi) is found by
expanding steps from the start, then regula falsi with the Anderson-Bjorck correction
inside it. The branch is checked independently: rho >= 3/2 unbounded; for 1 < rho < 3/2
unbounded iff psi < theta_c(rho) (critical curve, K^2 = 27/8), first half-arch iff
theta_c(rho) < psi <= Theta(rho, rho), second beyond; rho = 1 complete.
Everything is done at 50 and at 70 digits (70 and 90 for one ill-conditioned row); a row
is kept only when R, R - 1, s, t agree to >= 40 digits between the two (column
agreement); the values at the higher precision are written with 45 digits.
cond_R, cond_s, cond_t: condition numbers |dF/dpsi| psi/F (central differences in y at
50 digits): an error of one unit in the last place of psi moves F by cond units.
Columns: class, rho, psi, arch, R, R_minus_1, K2, s, t, cond_R, cond_s, cond_t, agreement.
"""
import sys
import time

import mpmath as mp

KC2 = mp.mpf(27) / 8         # K^2 of the critical curve (exact in binary)
ROUNDED_ONTO_APSE = [0]


def binary128(x):
    """x rounded to the nearest binary128 number (113-bit significand)."""
    _, e = mp.frexp(x)
    return mp.ldexp(mp.nint(mp.ldexp(x, 113 - e)), e - 113)


def high():
    return 3 * mp.mp.dps + 40


class Curve:
    """A curve from A by its exact parameters (kept at 3 dps + 40 digits): unbounded by
    k2 and c = 27/8 - k2, bounded by e1 = R - 1 (and k2 = (1 + e1)^3/(2 e1))."""

    def __init__(self, var, y, rho):
        self.var = var
        with mp.workdps(high()):
            if var in ("logk2", "logc", "critical"):
                self.bounded = False
                if var == "critical":        # K^2 = 27/8 (y unused)
                    self.k2, self.c = KC2, mp.mpf(0)
                elif var == "logk2":
                    self.k2 = mp.exp(y)
                    self.c = KC2 - self.k2
                else:
                    self.c = mp.exp(y)
                    self.k2 = KC2 - self.c
            else:
                self.bounded = True
                if var == "logm1":
                    self.e1 = mp.exp(y)
                elif var == "log32":
                    self.e1 = mp.mpf(1) / 2 - mp.exp(y)
                elif var == "apse_at_rho":   # R = rho (y unused)
                    self.e1 = rho - 1
                else:                        # apse: R = rho + y^2
                    self.e1 = (rho - 1) + y * y
                self.k2 = (1 + self.e1) ** 3 / (2 * self.e1)
                self.c = KC2 - self.k2       # < 0
                self.gap32 = mp.mpf(1) / 2 - self.e1     # 3/2 - R


def integrand(which, k2, w):
    """Tee (23), (31), (37) at x = 1 + w, as printed."""
    x = 1 + w
    v2 = 2 * w / x                        # (44), mu = -1
    q = 1 - k2 * v2 / (x * x)
    if q <= 0:
        # only at a quadrature node that rounds onto the apse (weight below 10^-dps)
        ROUNDED_ONTO_APSE[0] += 1
        return mp.mpf(0)
    if which == "theta":
        return 1 / (x * mp.sqrt(x * x / (k2 * v2) - 1))
    if which == "s":
        return 1 / mp.sqrt(q)
    return 1 / (mp.sqrt(v2) * mp.sqrt(q))


def scaled_quad(g, pts):
    """mp.quad relative to the size of the piece (g > 0 here)."""
    a, b = pts[0], pts[-1]
    scale = abs(g((a + b) / 2)) * abs(b - a)
    if scale == 0:
        scale = mp.mpf(1)
    return scale * mp.quad(lambda z: g(z) / scale, pts)


def inside(points, lo, hi):
    return sorted(p for p in points if lo < p < hi)


def first_arch(curve, w_end, which):
    """F(rho, R) from x = 1 to x = 1 + w_end along the first (half-)arch, for each name
    in `which` (theta, s, t)."""
    ext = 2 * mp.mp.dps + 20
    k2 = curve.k2
    out = []
    for name in which:
        def start(u):                    # x = 1 + u^2
            with mp.workdps(ext):
                return 2 * u * integrand(name, k2, u * u)

        def apse(u):                     # x = R - u^2
            with mp.workdps(ext):
                return 2 * u * integrand(name, k2, curve.e1 - u * u)

        def plain(w):
            with mp.workdps(ext):
                return integrand(name, k2, w)
        total = mp.mpf(0)
        if w_end == 0:
            out.append(total)
            continue
        if curve.bounded:
            mid = curve.e1 / 2
            if w_end <= mid:
                total += scaled_quad(start, [0, mp.sqrt(w_end)])
            else:
                total += scaled_quad(start, [0, mp.sqrt(mid)])
                with mp.workdps(high()):
                    lo = mp.sqrt(curve.e1 - w_end)
                hi = mp.sqrt(curve.e1 - mid)
                width = mp.sqrt(curve.gap32)       # the near-double root's scale
                bps = inside([width * mp.mpf(4) ** k for k in range(-2, 60)], lo, hi)
                total += scaled_quad(apse, [lo] + bps + [hi])
        else:
            first_end = min(w_end, mp.mpf(1) / 4)
            total += scaled_quad(start, [0, mp.sqrt(first_end)])
            if w_end > first_end:
                half = mp.mpf(1) / 2
                h0 = mp.sqrt(mp.mpf(3) / 4 * curve.c / k2)
                pts = [half]
                if h0 > 0:
                    for k in range(0, 60):
                        pts += [half - h0 * mp.mpf(4) ** k, half + h0 * mp.mpf(4) ** k]
                pts += [2 * mp.mpf(4) ** k for k in range(0, 80)]
                total += scaled_quad(plain, [first_end] + inside(pts, first_end, w_end)
                                     + [w_end])
        out.append(total)
    return out


def upsilon(curve, rho, arch, which=("theta",)):
    """theta, s, t at B along `arch` (unbounded, first, second, complete)."""
    w_end = rho - 1
    f = first_arch(curve, w_end, which)
    if arch in ("unbounded", "first"):
        return f
    full = first_arch(curve, curve.e1, which)
    return [2 * a - b for a, b in zip(full, f)]


def limits(var, rho):
    """Domain of the unknown y."""
    big = mp.mpf(11000)
    tiny = mp.mpf(10) ** -40             # R = 3/2 is the critical curve, not bounded
    if var in ("logk2", "logc"):          # K^2 and 27/8 - K^2 both > 0
        return -big, mp.log(KC2 * (1 - mp.mpf(10) ** -30))
    if var == "logm1":
        return (mp.log(rho - 1) if rho > 1 else -big), mp.log(mp.mpf(1) / 2 - tiny)
    if var == "log32":
        return mp.log(tiny), mp.log(mp.mpf(3) / 2 - rho)
    return mp.mpf(0), mp.sqrt(mp.mpf(3) / 2 - rho)


def fb_sign(value):
    return value > 0


def solve(rho, psi, arch, var, y0, h):
    """y with theta(rho; y) = psi on `arch`: bracket by expanding steps from y0, then
    Anderson-Bjorck regula falsi inside the bracket."""
    lo_limit, hi_limit = limits(var, rho)

    def f(y):
        return upsilon(Curve(var, y, rho), rho, arch)[0] - psi

    def clamp(y):
        return min(max(y, lo_limit), hi_limit)
    f0 = f(y0)
    if f0 == 0:
        return y0
    noise = abs(psi) * mp.mpf(10) ** (-mp.mp.dps + 8)
    while True:                          # a step whose change of f is above the noise
        f1 = f(clamp(y0 + h))
        if abs(f1 - f0) > noise or fb_sign(f1) != fb_sign(f0):
            break
        if clamp(y0 + h) in (lo_limit, hi_limit):
            raise RuntimeError("flat at rho=%s psi=%s" % (rho, psi))
        h *= 16
    direction = 1 if (f1 - f0) * f0 < 0 else -1
    a, fa = y0, f0
    while True:
        b = clamp(y0 + direction * h)
        fb = f(b)
        if fb * fa <= 0:
            break
        a, fa = b, fb
        h *= 4
        if b in (lo_limit, hi_limit):
            raise RuntimeError("no bracket at rho=%s psi=%s" % (rho, psi))
    width = mp.mpf(10) ** (-mp.mp.dps + 3)
    small = abs(psi) * mp.mpf(10) ** (-mp.mp.dps + 3)
    for _ in range(300):
        if fb == 0 or abs(b - a) <= width * max(abs(b), mp.mpf(1)) or abs(fb) < small:
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
        raise RuntimeError("no convergence at rho=%s psi=%s" % (rho, psi))
    if abs(fb) > abs(psi) * mp.mpf(10) ** (-mp.mp.dps + 12):
        raise RuntimeError("residual %s at rho=%s psi=%s" % (fb, rho, psi))
    return b


def check_branch(rho, psi, arch):
    """The branch of the least-time curve through (rho, psi), decided from the endpoint
    (module notes of brachistochrone_repulsive, checked here by mpmath)."""
    if rho == 1:
        ok = arch == "complete"
    elif rho >= mp.mpf(3) / 2:
        ok = arch == "unbounded"
    else:
        theta_c = first_arch(Curve("critical", None, rho), rho - 1, ["theta"])[0]
        theta_apse = first_arch(Curve("apse_at_rho", None, rho), rho - 1, ["theta"])[0]
        ok = {"unbounded": psi < theta_c, "first": theta_c < psi <= theta_apse,
              "second": psi > theta_apse}[arch]
    if not ok:
        raise RuntimeError("psi=%s is not on the %s branch at rho=%s" % (psi, arch, rho))


def outputs(curve, rho, arch):
    th, s, t = upsilon(curve, rho, arch, ("theta", "s", "t"))
    big_r = 1 + curve.e1 if curve.bounded else None
    return th, big_r, s, t, (+curve.e1 if curve.bounded else None)


def conditions(rho, psi, arch, var, y):
    """|dF/dpsi| psi/F for F = R, s, t by central differences in y."""
    h = mp.mpf(10) ** -15 * max(abs(y), mp.mpf(1))
    lo = outputs(Curve(var, y - h, rho), rho, arch)
    hi = outputs(Curve(var, y + h, rho), rho, arch)
    mid = outputs(Curve(var, y, rho), rho, arch)
    dpsi = (hi[0] - lo[0])
    cond = []
    for k in (1, 2, 3):
        if mid[k] is None:
            cond.append(None)
        elif k == 1:                     # dR = d(R - 1), exact in e1
            cond.append(abs((hi[4] - lo[4]) / dpsi) * psi / mid[1])
        else:
            cond.append(abs((hi[k] - lo[k]) / dpsi) * psi / mid[k])
    return cond


def endpoint(row):
    """(psi, y, curve values) at the current precision for one row."""
    cls, rho, arch, var, spec = row[:5]
    if spec[0] == "target":
        y0 = spec[1]
        psi = binary128(upsilon(Curve(var, y0, rho), rho, arch)[0])
        h = max(abs(y0), mp.mpf(1)) * mp.mpf(10) ** -24
    else:
        psi = spec[1]
        y0 = spec[2]
        h = max(abs(y0), mp.mpf(1)) * mp.mpf(10) ** -18
    y = solve(rho, psi, arch, var, y0, h)
    return psi, y, outputs(Curve(var, y, rho), rho, arch)


def rough(row):
    """A given psi: its root at 25 digits from a rough start (the row's y0)."""
    cls, rho, arch, var, spec = row[:5]
    with mp.workdps(25):
        y = solve(rho, spec[1], arch, var, spec[2], mp.mpf(1) / 4)
    return (cls, rho, arch, var, ("psi", spec[1], y)) + row[5:]


def cases():
    """(class, rho, arch, variable, spec[, precisions]); spec ("target", y) or ("psi",
    psi, rough y); precisions (50, 70) unless given. Next to the critical curve on the
    first half-arch, theta_c(rho) - psi is of second order in 3/2 - R: R is ill conditioned
    (cond ~ 1/(3/2 - R)), so that row is made at 70 and 90 digits, and 3/2 - R much below
    1e-17 is not resolved by a binary128 psi at all."""
    mp.mp.dps = 80
    one = mp.mpf(1)
    b = binary128
    pi_b = b(mp.pi)
    log = mp.log
    rho_3 = b(one + mp.mpf("1e-3"))
    rho_10 = b(one + mp.mpf("1e-10"))
    rho_112 = one + mp.mpf(2) ** -112
    out = [
        # rho >= 3/2: unbounded only
        ("unbounded", mp.mpf(2), "unbounded", "logk2", ("target", log(2))),
        ("unbounded", mp.mpf(2), "unbounded", "logk2", ("psi", one, log(2.6))),
        ("unbounded_small_psi", mp.mpf(2), "unbounded", "logk2", ("target", log(1e-40))),
        ("unbounded", mp.mpf(3) / 2, "unbounded", "logk2", ("target", log(3))),
        ("unbounded_pi", mp.mpf(3) / 2, "unbounded", "logc", ("psi", pi_b, log(1e-4))),
        ("unbounded_pi", mp.mpf(2), "unbounded", "logc", ("psi", pi_b, log(1e-3))),
        ("unbounded_pi", mp.mpf(10), "unbounded", "logc", ("psi", pi_b, log(1e-2))),
        ("unbounded_far", mp.mpf(10) ** 6, "unbounded", "logk2", ("target", log(1))),
        ("unbounded_far", b(mp.mpf(10) ** 20), "unbounded", "logk2", ("target", log(3))),
        # 1 < rho < 3/2, unbounded part (psi < theta_c(rho)), also next to the critical
        ("unbounded", mp.mpf(5) / 4, "unbounded", "logk2", ("target", log(2))),
        ("near_critical", mp.mpf(5) / 4, "unbounded", "logc", ("target", log(1e-10))),
        ("near_critical", mp.mpf(5) / 4, "unbounded", "logc", ("target", log(1e-25))),
        ("near_critical", b(mp.mpf("1.45")), "unbounded", "logc", ("target", log(1e-20))),
        ("unbounded", rho_3, "unbounded", "logk2", ("target", log(2))),
        # first half-arches (theta_c(rho) < psi <= Theta(rho, rho))
        ("first", mp.mpf(5) / 4, "first", "logm1", ("target", log(0.3))),
        ("first", b(mp.mpf("1.45")), "first", "logm1", ("target", log(0.47))),
        ("first_near_critical", mp.mpf(5) / 4, "first", "log32", ("target", log(1e-10)),
         (70, 90)),
        ("first_near_critical", mp.mpf(5) / 4, "first", "log32", ("target", log(1e-16)),
         (70, 90)),
        ("first", rho_3, "first", "logm1", ("target", log(1.5e-3))),
        ("first", rho_10, "first", "logm1", ("target", log(1.5e-10))),
        # within 1e-17 (down to 1e-30) of the apse, both sides
        ("near_apse_first", mp.mpf(5) / 4, "first", "apse", ("target", mp.sqrt(1e-17))),
        ("near_apse_second", mp.mpf(5) / 4, "second", "apse", ("target", mp.sqrt(1e-17))),
        ("near_apse_first", mp.mpf(5) / 4, "first", "apse", ("target", mp.sqrt(1e-25))),
        ("near_apse_second", mp.mpf(5) / 4, "second", "apse", ("target", mp.sqrt(1e-25))),
        ("near_apse_first", rho_3, "first", "apse", ("target", mp.sqrt(1e-20))),
        ("near_apse_second", rho_3, "second", "apse", ("target", mp.sqrt(1e-20))),
        ("near_apse_first", b(mp.mpf("1.45")), "first", "apse", ("target", mp.sqrt(1e-30))),
        ("near_apse_second", b(mp.mpf("1.45")), "second", "apse", ("target", mp.sqrt(1e-30))),
        # second half-arches
        ("second", mp.mpf(5) / 4, "second", "logm1", ("target", log(0.3))),
        ("second_pi", mp.mpf(5) / 4, "second", "logm1", ("psi", pi_b, log(0.45))),
        ("second", rho_3, "second", "logm1", ("target", log(0.2))),
        ("second", rho_3, "second", "logm1", ("psi", one, log(0.25))),
        # rho -> 1+
        ("rho_to_1", rho_10, "second", "logm1", ("psi", one, log(0.25))),
        ("rho_to_1", rho_10, "second", "logm1", ("target", log(4e-10))),
        ("rho_to_1", rho_112, "second", "logm1", ("psi", one, log(0.25))),
        ("rho_to_1", rho_112, "second", "logm1", ("psi", pi_b, log(0.45))),
        ("rho_to_1", rho_112, "second", "logm1", ("target", log(1e-33))),
        # next to the start, rho - 1 tiny: below theta_c(rho) ~ 8 sqrt3 ((rho-1)/4)^(3/2),
        # first half-arches far from their apse (psi << rho - 1 << R - 1) and second
        # half-arches ending next to the start (rho - 1 << R - 1 ~ psi/pi)
        ("near_start_unbounded", b(one + mp.mpf("1e-20")), "unbounded", "logk2",
         ("target", log(2))),
        ("near_start_first", b(one + mp.mpf("3.3e-23")), "first", "logm1",
         ("target", log(2.6e-20))),
        ("near_start_first", b(one + mp.mpf("8e-19")), "first", "logm1",
         ("target", log(6.2e-16))),
        ("near_start_second", b(one + mp.mpf("7.04e-31")), "second", "logm1",
         ("target", log(2.2e-26))),
        ("near_start_second", b(one + mp.mpf("4.4e-32")), "second", "logm1",
         ("target", log(1.3e-24))),
        # complete arches, rho = 1, R -> 1
        ("complete", one, "complete", "logm1", ("psi", one, log(0.25))),
        ("complete", one, "complete", "logm1", ("psi", pi_b, log(0.45))),
        ("complete", one, "complete", "logm1", ("target", log(1e-7))),
        ("complete", one, "complete", "logm1", ("target", log(1e-30))),
        ("complete", one, "complete", "logm1", ("target", log(1e-40))),
        ("complete", one, "complete", "logm1", ("target", log(0.45))),
    ]
    return out


def digits(a, b):
    if a == b:
        return 99.0
    return float(-mp.log10(abs(a - b) / abs(b)))


def main():
    only = set(sys.argv[1:])
    rows = []
    for number, row in enumerate(cases()):
        if only and str(number) not in only:
            continue
        started = time.time()
        cls, rho, arch = row[0], +row[1], row[2]
        try:
            if row[4][0] == "psi":
                saved = ROUNDED_ONTO_APSE[0]     # the 25-digit start is not a result
                row = rough(row)
                ROUNDED_ONTO_APSE[0] = saved
            results = []
            low, top = row[5] if len(row) > 5 else (50, 70)
            for dps in (low, top):
                mp.mp.dps = dps
                results.append(endpoint(row))
            mp.mp.dps = low
            psi, y, _ = results[0]
            check_branch(rho, psi, arch)
            cond = conditions(rho, psi, arch, row[3], y)
        except RuntimeError as error:
            print("# dropped %s rho=%s: %s" % (cls, rho, error), file=sys.stderr)
            continue
        (psi_a, _, (_, r_a, s_a, t_a, e_a)), (psi_b, y_b, (_, r_b, s_b, t_b, e_b)) = results
        agree = min(digits(s_a, s_b), digits(t_a, t_b))
        if r_a is not None:
            agree = min(agree, digits(r_a, r_b), digits(e_a, e_b))
        if psi_a != psi_b or agree < 40:
            print("# dropped %s rho=%s: precisions agree to %.1f" % (cls, rho, agree),
                  file=sys.stderr)
            print(digits(s_a, s_b), digits(t_a, t_b), r_a and digits(r_a, r_b),
                  r_a and digits(e_a, e_b), file=sys.stderr)
            continue
        mp.mp.dps = top
        curve = Curve(row[3], y_b, rho)
        rows.append((cls, mp.nstr(rho, 60), mp.nstr(psi_b, 60), arch,
                     mp.nstr(r_b, 45) if r_b is not None else "",
                     mp.nstr(e_b, 45) if r_b is not None else "",
                     mp.nstr(curve.k2, 45), mp.nstr(s_b, 45), mp.nstr(t_b, 45),
                     *[mp.nstr(c, 3) if c is not None else "" for c in cond],
                     "%.1f" % agree))
        print(",".join(rows[-1]), "(%.0f s)" % (time.time() - started), file=sys.stderr,
              flush=True)
    print("# repulsive two-point references: "
          "scripts/make_repulsive_two_point_reference.py (see its docstring)")
    print("# mpmath %s, two precisions (50/70 or 70/90) on Tee (23), (31), (37), "
          "v^2 = 2(x-1)/x; rho, psi are binary128 numbers; R empty for unbounded curves"
          % mp.__version__)
    print("# quadrature nodes rounded onto an apse at 50-90 digits (integrand taken as 0): %d"
          % ROUNDED_ONTO_APSE[0])
    print("class,rho,psi,arch,R,R_minus_1,K2,s,t,cond_R,cond_s,cond_t,agreement")
    for row in rows:
        print(",".join(row))


if __name__ == "__main__":
    main()
