#!/usr/bin/env python3
"""Independent high-precision reference table for brachistochrones through two points.

Physics (G. J. Tee 1998, sections 4-5, with the corrections of docs/ERRATA.md).
A particle starts from rest at A = (radius 1, angle 0) under the attractive
inverse-square force.  The brachistochrone through A with apse (minimum) radius
R in (0, 1) has, on its first half-arch (radius decreasing from 1 to R), the
angle, arclength and time at radius r in [R, 1] given by the untransformed
elliptic integrals (eqs. 55, 56, 57)

    Theta(r,R) = sqrt(R^3/(1-R)) * Int_r^1 (1-x) / (x sqrt((1-x)(x-R) P(x))) dx
    S(r,R)     = Int_r^1 x^2 / sqrt(x (x-R) P(x)) dx
    T(r,R)     = Int_r^1 x^2 / sqrt(2 (1-x)(x-R) P(x)) dx
    with P(x)  = x^2 + R x + R^2/(1-R)  (positive for all real x).

On the second half-arch the value is 2 F(R,R) - F(r,R) for F in Theta, S, T.
This script evaluates it as F(r,R) + 2 Int_R^r (same integrand), which is the
identical quantity but does not integrate over [r, 1] twice.

For an endpoint B = (rho, psi), 0 < rho <= 1, 0 < psi < 2 pi/3, B is on the
first half-arch iff psi <= Theta(rho, rho) (Theta(1,1) = 0), and the apse radius
Rbar in (0, rho] solves Theta(rho,R) = psi (first arch; increasing in R) or
2 Theta(R,R) - Theta(rho,R) = psi (second arch; decreasing in R).  Then
s = arclength and t = time from A to B follow by the same arch rule at r = rho.

Method (deliberately independent of the paper's smoothing substitutions,
eqs. 59-81, which the program under test uses):

* Quadrature.  The integrals are evaluated in the original variable x by
  tanh-sinh (double-exponential) quadrature on a graded subdivision of [r, 1].
  mpmath's mp.quad was not used: its tanh-sinh nodes are formed as
  x = (b-a)/2 * t + (b+a)/2, so near an endpoint the distance x - a is
  lost to cancellation and the nodes stop at distance ~eps from the endpoint;
  for the 1/sqrt(x-R) and 1/sqrt(1-x) endpoint singularities of these
  integrands that limits mp.quad to about half the working digits
  (|error| ~ 1e-28 at 50 digits for Int_a^1 dx/sqrt(x-a)).  The quadrature
  here (class TanhSinh) keeps, for every node, its distances to both interval
  ends as separately computed numbers (1 - tanh(u) = 2/(1 + exp(2u))), so the
  factors x - R and 1 - x are always formed without cancellation and the
  singular endpoints are integrated to full working precision.
* Subdivision.  Each interval is split (function subdivide) until every piece
  is no longer than GRADING times its distance to the nearest singular point
  of the integrands that is not one of its own ends: x = 0, x = R, x = 1 and
  the complex zeros of P.  For small R this gives points graded
  geometrically (ratio 1 + GRADING = 4) from the scale R near x = R up to
  x = 1, and when r - R is tiny, points r - R + (r - R) 4^k likewise graded
  away from R, so every piece is a well-resolved analytic integral (apart
  from exact endpoint singularities, handled by tanh-sinh).
* Root finding is always bracketed.  Stage 1 (30 digits) brackets Rbar in
  the variable phi with R = rho sin^2(phi), phi in [0, pi/2] (smooth at both
  ends: R -> 0 and the c - sqrt(rho - R) behaviour at R -> rho), and runs the
  Anderson-Bjorck variant of regula falsi with a bisection safeguard (the
  endpoint values at R = 0 are the limits -psi and 2 pi/3 - psi, and at R = rho
  Theta(rho,rho) - psi).  Stage 2 refines Rbar at the working precision in
  the smaller of R and rho - R (in the latter case R = rho - gap is formed
  exactly, so the offsets x - R stay exact even when Rbar is within 1e-20 of
  rho), in a narrow bracket around the stage-1 root whose sign change is
  verified (and widened if needed) before the same safeguarded iteration; it
  stops when the bracket is narrower than 10^-(dps-4) relative or lies inside
  the noise band of the quadrature.

Precision.  Every row is computed twice, at WORK_DPS = 50 and at
CHECK_DPS = 65 decimal digits (each computation has its own stage-2 bracket
and root); the row is accepted only if Rbar, s and t agree to at least
MIN_DIGITS = 42 significant digits.  The values written are those of the
65-digit computation, rounded to 45 significant digits.

Binary128 input rule.  The Fortran program reads rho and psi as decimal
strings straight into IEEE binary128 (113-bit significand, round to nearest).
The CSV stores exactly those input strings, and the computation uses the
binary128-rounded values: with mp.workprec(113): x = mp.mpf(string); x is then
used unchanged at the full working precision.

Usage:
    python scripts/make_reference.py [--out PATH] [--check N]

Without --check the whole table is generated and written to --out (default
data/reference/endpoints_mpmath.csv).  With --check N the first N rows of the
existing CSV (--out or default path) are recomputed at WORK_DPS and the script
exits with status 1 if any of R, s, t differs from the stored value by more
than 1e-40 relative.
"""

import argparse
import datetime
import math
import random
import sys
import time
from pathlib import Path

import mpmath as mp

WORK_DPS = 50          # main working precision (decimal digits)
CHECK_DPS = 65         # verification precision; these values are written
COARSE_DPS = 30        # precision of the stage-1 bracketing search
OUT_DIGITS = 45        # significant digits written for R, s, t
MIN_DIGITS = 42        # required agreement between WORK_DPS and CHECK_DPS
CHECK_RTOL = mp.mpf('1e-40')   # tolerance of --check
GRADING = 3            # subinterval length <= GRADING * distance to singularity
RANDOM_SEED = 19981111 # seed of the random endpoints (date of the paper)
N_RANDOM = 100         # number of random endpoints
HEADER = 'rho,psi,arch,R,s,t'
DEFAULT_OUT = Path(__file__).resolve().parent.parent / 'data' / 'reference' / 'endpoints_mpmath.csv'


# ---------------------------------------------------------------------------
# Quadrature
# ---------------------------------------------------------------------------

class TanhSinh:
    """Tanh-sinh quadrature on [a, b] whose nodes know their end distances.

    The standard nodes are x_k = tanh(pi/2 sinh(t_k)), t_k = k h, on [-1, 1].
    For each t >= 0 we store the weight w = (pi/2) cosh t / cosh^2(pi/2 sinh t),
    the complement q = 1 - x = 2/(1 + exp(pi sinh t)) and 1 + x = 2 - q, all
    computed directly, so that a node of [a, b] lying at distance c*q from an
    end (c = (b-a)/2) is known by that distance with full relative precision.
    Levels m = 0, 1, ... halve the step h = 2^-m and reuse the nodes of the
    previous levels; nodes are generated until q < 10^-(2 dps + 20), which is
    enough for integrable singularities as strong as 1/sqrt at the ends.
    """

    def __init__(self, dps, max_level=10):
        """Precompute nodes and weights for working precision `dps`."""
        self.dps = dps
        self.levels = []
        with mp.workdps(dps + 10):
            q_min = mp.mpf(10) ** (-(2 * dps + 20))
            half_pi = mp.pi / 2
            for m in range(max_level + 1):
                h = mp.ldexp(1, -m)
                k, step = (0, 1) if m == 0 else (1, 2)
                nodes = []
                while True:
                    t = k * h
                    e = mp.exp(2 * half_pi * mp.sinh(t))
                    q = 2 / (1 + e)
                    w = half_pi * mp.cosh(t) * 4 * e / (1 + e) ** 2
                    nodes.append((w, q, 2 - q))
                    if q < q_min:
                        break
                    k += step
                self.levels.append((h, nodes))

    def integrate(self, f, a, b, rtol):
        """Return Int_a^b f dx, where f(x, dl, dr) gets dl = x - a, dr = b - x.

        Levels are added until two successive estimates agree to `rtol`
        (relative) at level >= 3; since the error of tanh-sinh roughly squares
        from one level to the next, rtol ~ 10^-(dps/2) already gives results
        accurate to the working precision.  The sum over one level stops
        early once the terms (which decay double-exponentially) are below
        eps * 1e-12 of the running estimate.
        """
        c = (b - a) / 2
        tiny = mp.eps * mp.mpf('1e-12')
        total = prev = None
        for m, (h, nodes) in enumerate(self.levels):
            acc = mp.mpf(0)
            start = 0
            if m == 0:
                w0 = nodes[0][0]
                acc = w0 * f(a + c, c, c)
                start = 1
            for w, q, opx in nodes[start:]:
                near = c * q
                far = c * opx
                term = w * (f(b - near, far, near) + f(a + near, near, far))
                acc += term
                ref = prev if prev is not None else acc * h
                if abs(term) * h < tiny * abs(ref):
                    break
            total = acc * h if m == 0 else total / 2 + acc * h
            if m >= 3 and abs(total - prev) <= rtol * abs(total):
                return total * c
            prev = total
        raise ArithmeticError('tanh-sinh quadrature did not converge on [%s, %s]'
                              % (mp.nstr(a, 10), mp.nstr(b, 10)))


_RULES = {}


def rule():
    """Return the TanhSinh rule for the current mp.mp.dps (cached)."""
    dps = mp.mp.dps
    if dps not in _RULES:
        _RULES[dps] = TanhSinh(dps)
    return _RULES[dps]


# ---------------------------------------------------------------------------
# The integrals of Tee (1998), eqs. (55)-(57)
# ---------------------------------------------------------------------------

def complex_zero(R):
    """Upper complex zero of P(x) = x^2 + R x + R^2/(1-R) (the other is its conjugate).

    x = -R/2 + i (R/2) sqrt(4/(1-R) - 1); since R < 1 the discriminant is
    negative (Tee 1998, section 4.1).
    """
    return mp.mpc(-R / 2, R / 2 * mp.sqrt(4 / (1 - R) - 1))


def subdivide(a, b, R):
    """Split [a, b] (R <= a < b <= 1) into pieces suited to tanh-sinh.

    The singular points of the integrands are x = 0, x = R, x = 1 and the
    complex zeros of P.  Each piece [p, q] must satisfy q - p <= GRADING * D,
    where D is the distance from [p, q] to the nearest singular point that is
    not exactly one of its ends (end singularities are what tanh-sinh handles
    well).  A piece that is too long is cut at distance GRADING * D from the
    end nearest to the offending point, giving a geometric grading towards
    it.  The real singular points are compared exactly (R may carry more bits
    than the working precision, see solve_fine); all singular points lie
    outside (a, b), to the left except x = 1.
    """
    zero = complex_zero(R)
    head, tail = [], []
    lo, hi = a, b
    while True:
        left = [lo - x for x in (mp.mpf(0), R) if x != lo] + [abs(zero - lo)]
        right = [1 - hi] if hi != 1 else []
        d_left, d_right = min(left), (min(right) if right else mp.inf)
        if hi - lo <= GRADING * min(d_left, d_right):
            head.append((lo, hi))
            break
        if d_left <= d_right:
            cut = lo + GRADING * d_left
            head.append((lo, cut))
            lo = cut
        else:
            cut = hi - GRADING * d_right
            tail.append((cut, hi))
            hi = cut
    return head + tail[::-1]


def kernel(name, R):
    """Return the integrand `name` ('theta', 's' or 't') for apse radius R.

    The returned function g(x, xmR, omx) takes x together with x - R and 1 - x
    supplied without cancellation.  The 'theta' kernel omits the constant
    factor sqrt(R^3/(1-R)), which is applied by the caller.
    """
    k = R * R / (1 - R)
    if name == 'theta':
        def g(x, xmR, omx):
            P = x * x + R * x + k
            return mp.sqrt(omx / (xmR * P)) / x        # = (1-x)/(x sqrt((1-x)(x-R)P))
    elif name == 's':
        def g(x, xmR, omx):
            P = x * x + R * x + k
            return x * mp.sqrt(x / (xmR * P))          # = x^2/sqrt(x(x-R)P)
    elif name == 't':
        def g(x, xmR, omx):
            P = x * x + R * x + k
            return x * x / mp.sqrt(2 * omx * xmR * P)  # = x^2/sqrt(2(1-x)(x-R)P)
    else:
        raise ValueError(name)
    return g


def integral(name, a, b, R):
    """Int_a^b of integrand `name` (without the Theta prefactor), R <= a <= b <= 1.

    The interval is subdivided (subdivide) and each piece integrated by
    tanh-sinh, with x - R and 1 - x formed from the node's distance to the
    nearer end of its piece, so that no cancellation occurs near x = R or 1.
    """
    if a == b:
        return mp.mpf(0)
    g = kernel(name, R)
    rtol = mp.mpf(10) ** (-(mp.mp.dps // 2 + 5))
    one = mp.mpf(1)
    total = mp.mpf(0)
    for p, q in subdivide(a, b, R):
        pR, qR, op, oq = p - R, q - R, one - p, one - q

        def f(x, dl, dr):
            if dl <= dr:
                return g(x, pR + dl, op - dl)
            return g(x, qR - dr, oq + dr)
        total += rule().integrate(f, p, q, rtol)
    return total


def theta_factor(R):
    """The constant factor sqrt(R^3/(1-R)) of Theta, eq. (55)."""
    return mp.sqrt(R ** 3 / (1 - R))


def arch_value(name, r, R, arch):
    """Theta, S or T at radius r on the given half-arch of the curve with apse R.

    First arch: F(r,R) = Int_r^1.  Second arch: 2 F(R,R) - F(r,R), computed as
    Int_r^1 + 2 Int_R^r.
    """
    val = integral(name, r, mp.mpf(1), R)
    if arch == 'second':
        val += 2 * integral(name, R, r, R)
    if name == 'theta':
        val *= theta_factor(R)
    return val


def apse_angle_at(rho):
    """Theta(rho, rho), the apse angle of the curve whose apse is at radius rho."""
    if rho == 1:
        return mp.mpf(0)
    return arch_value('theta', rho, rho, 'first')


# ---------------------------------------------------------------------------
# Root finding
# ---------------------------------------------------------------------------

def bracketed_root(f, a, fa, b, fb, done, ftol=0, max_iter=300):
    """Anderson-Bjorck regula falsi with a bisection safeguard.

    f(a) = fa and f(b) = fb must have opposite signs.  Iterates until
    done(a, b) is true for the current bracket, or both bracket ends have
    |f| <= ftol (the bracket lies inside the noise band of f), or a zero is
    hit, or the bracket cannot be split any more; returns the final bracket
    (a, b) with the end of smaller |f| first.  If the bracket has not halved
    within three steps a bisection step is taken, so convergence is
    guaranteed; near a simple root the iteration is superlinear.
    """
    if fa == 0:
        return a, a
    if fb == 0:
        return b, b
    if (fa > 0) == (fb > 0):
        raise ValueError('root not bracketed')
    width0 = abs(b - a)
    since_halving = 0
    fa_true, fb_true = fa, fb          # fa is rescaled by Anderson-Bjorck
    for _ in range(max_iter):
        if done(a, b) or max(abs(fa_true), abs(fb_true)) <= ftol:
            break
        c = (a + b) / 2
        if since_halving < 3:
            secant = b - fb * (b - a) / (fb - fa)
            if min(a, b) < secant < max(a, b):
                c = secant
        if not (min(a, b) < c < max(a, b)):
            break                      # bracket is down to adjacent numbers
        fc = f(c)
        if fc == 0:
            return c, c
        if (fc > 0) != (fb > 0):
            a, fa, fa_true = b, fb, fb_true
        else:
            m = 1 - fc / fb
            fa = fa * (m if m > 0 else mp.mpf('0.5'))
        b, fb, fb_true = c, fc, fc
        if abs(b - a) <= width0 / 2:
            width0 = abs(b - a)
            since_halving = 0
        else:
            since_halving += 1
    else:
        raise ArithmeticError('root finding did not converge')
    return (b, a) if abs(fb_true) <= abs(fa_true) else (a, b)


def angle_residual(rho, psi, arch):
    """Return F(R) = (angle at rho on `arch` of the curve with apse R) - psi."""
    def F(R):
        return arch_value('theta', rho, R, arch) - psi
    return F


def solve_coarse(rho, psi, arch, theta_apse):
    """Stage 1: locate Rbar to ~16 digits at COARSE_DPS digits.

    Works in phi with R = rho sin^2(phi), phi in [0, pi/2]; the end values of
    F are known without quadrature: F(0+) = -psi (first arch) or
    2 pi/3 - psi (second arch), F(rho) = Theta(rho,rho) - psi.
    """
    with mp.workdps(COARSE_DPS):
        rho, psi, theta_apse = +rho, +psi, +theta_apse
        F = angle_residual(rho, psi, arch)

        def G(phi):
            return F(rho * mp.sin(phi) ** 2)

        f0 = -psi if arch == 'first' else 2 * mp.pi / 3 - psi
        f1 = theta_apse - psi
        tol = mp.mpf('1e-17')

        def done(a, b):
            r_a, r_b = rho * mp.sin(a) ** 2, rho * mp.sin(b) ** 2
            gap_a, gap_b = rho * mp.cos(a) ** 2, rho * mp.cos(b) ** 2
            return (abs(r_a - r_b) <= tol * min(r_a, r_b)
                    or abs(gap_a - gap_b) <= tol * min(gap_a, gap_b))

        phi, _ = bracketed_root(G, mp.mpf(0), f0, mp.pi / 2, f1, done)
        return rho * mp.sin(phi) ** 2, rho * mp.cos(phi) ** 2


def solve_fine(rho, psi, arch, theta_apse, R1, gap1):
    """Stage 2: refine the stage-1 root R1 (with rho - R1 = gap1) at mp.dps.

    The unknown v is the smaller of R and gap = rho - R.  When v is the gap,
    R = rho - gap is formed exactly (mp.fsub(..., exact=True)), so that the
    integrals see the offset rho - R with full relative precision; this
    matters when Rbar is within ~1e-20 of rho (endpoint next to the apse)
    or when 1 - Rbar is small (rho = 1, small psi).  A bracket v1 -+ m,
    m = 1e-13 v1, clipped to (0, rho), is checked for a sign change (and
    widened by 10^3 until it has one); then the safeguarded Anderson-Bjorck
    iteration runs until the bracket is narrower than 10^-(dps-4) v or lies
    within the noise band |F| <= 10^-(dps-1) max(1, psi) of the quadrature.
    Returns R.
    """
    F = angle_residual(rho, psi, arch)
    use_gap = gap1 < R1

    def R_of(v):
        """R for the unknown v."""
        return mp.fsub(rho, v, exact=True) if use_gap else v

    def G(v):
        """F as a function of the unknown v."""
        return F(R_of(v))

    f_zero = -psi if arch == 'first' else 2 * mp.pi / 3 - psi  # limit R -> 0+
    f_rho = theta_apse - psi                                   # R = rho
    f_v0, f_vrho = (f_rho, f_zero) if use_gap else (f_zero, f_rho)
    v1 = +(gap1 if use_gap else R1)
    m = mp.mpf('1e-13') * v1
    while True:
        lo, f_lo = (v1 - m, G(v1 - m)) if v1 - m > 0 else (mp.mpf(0), f_v0)
        hi, f_hi = (v1 + m, G(v1 + m)) if v1 + m < rho else (rho, f_vrho)
        if (f_lo > 0) != (f_hi > 0) or f_lo == 0 or f_hi == 0:
            break
        if lo == 0 and hi == rho:
            raise ArithmeticError('no sign change of F on (0, rho)')
        m *= 1000
    tol = mp.mpf(10) ** (-(mp.mp.dps - 4))
    ftol = mp.mpf(10) ** (-(mp.mp.dps - 1)) * max(1, psi)
    v, _ = bracketed_root(G, lo, f_lo, hi, f_hi,
                          lambda a, b: abs(a - b) <= tol * min(abs(a), abs(b)), ftol)
    return R_of(v)


# ---------------------------------------------------------------------------
# Endpoints and rows
# ---------------------------------------------------------------------------

def binary128(text):
    """The IEEE binary128 value (113-bit significand, round to nearest) of a decimal string."""
    with mp.workprec(113):
        return mp.mpf(text)


def compute_row(rho_text, psi_text, dps, coarse=None):
    """Solve one endpoint at `dps` digits: return (arch, R, s, t, coarse).

    `coarse` is the stage-1 result (R1, rho - R1), recomputed if None; it
    only supplies the initial bracket, which is verified at `dps`.
    """
    with mp.workdps(dps):
        rho, psi = binary128(rho_text), binary128(psi_text)
        if not (0 < rho <= 1 and 0 < psi < 2 * mp.pi / 3):
            raise ValueError('endpoint outside the accessible sector: %s, %s' % (rho_text, psi_text))
        theta_apse = apse_angle_at(rho)
        arch = 'first' if psi <= theta_apse else 'second'
        if coarse is None:
            coarse = solve_coarse(rho, psi, arch, theta_apse)
        R = solve_fine(rho, psi, arch, theta_apse, *coarse)
        s = arch_value('s', rho, R, arch)
        t = arch_value('t', rho, R, arch)
        return arch, R, s, t, coarse


def agreement_digits(x, y):
    """Number of agreeing significant digits, -log10(|x-y|/|y|) (99 if equal)."""
    if x == y:
        return 99.0
    return float(-mp.log10(abs(x - y) / abs(y)))


def fmt(x, digits=OUT_DIGITS):
    """Plain scientific notation with `digits` significant digits, e.g. 1.23e-05."""
    with mp.workdps(digits + 20):
        text = mp.nstr(x, digits, strip_zeros=False, min_fixed=1, max_fixed=0)
    mant, _, exp = text.partition('e')   # nstr omits a zero exponent
    e = int(exp or 0)
    return '%se%s%02d' % (mant, '-' if e < 0 else '+', abs(e))


def sig(x, digits):
    """Decimal string of x rounded to `digits` significant digits (input strings)."""
    return mp.nstr(x, digits, strip_zeros=True, min_fixed=-4, max_fixed=6)


def table1_endpoints():
    """Table 1 of Tee (1998), with rows 1-2 corrected per docs/ERRATA.md."""
    return [('0.2', '1.2'), ('0.5', '0.1'), ('0.7', '1.8'), ('0.9', '0.4'), ('1.0', '2.0')]


TABLE1_PRINTED = {  # (rho, psi): (R, s, t) as printed (15 digits)
    ('0.2', '1.2'): ('0.184781963328079', '0.967544327890300', '1.127755808164997'),
    ('0.5', '0.1'): ('0.252787093630160', '0.505594850833648', '0.914164272619962'),
    ('0.7', '1.8'): ('0.168913316595188', '1.531621194881120', '1.481218910277573'),
    ('0.9', '0.4'): ('0.838545794202334', '0.442680075643429', '1.058599268341289'),
    ('1.0', '2.0'): ('0.057854464393370', '1.947547388961997', '2.221060707125763'),
}


def hard_endpoints():
    """Hand-picked difficult endpoints.

    * Near the apsidal locus: psi = Theta(rho,rho) * (1 + d), d in
      {-1e-3, -1e-8, +1e-8, +1e-3}, written with 25 significant digits.
    * Near the inaccessible sector: psi = 2 Theta(R,R) - Theta(rho,R) for
      R in {1e-3, 1e-4, 1e-5}, rounded to 20 significant digits.
    * Tiny psi, rho = 1 with several psi, rho = 0.01 with several psi.
    """
    rows = []
    with mp.workdps(WORK_DPS):
        for rho_text in ['0.01', '0.1', '0.5', '0.9', '0.999']:
            apse = apse_angle_at(binary128(rho_text))
            for d in ['-1e-3', '-1e-8', '1e-8', '1e-3']:
                rows.append((rho_text, sig(apse * (1 + mp.mpf(d)), 25)))
        for rho_text in ['0.01', '0.3', '1.0']:
            rho = binary128(rho_text)
            for R_text in ['1e-3', '1e-4', '1e-5']:
                psi = arch_value('theta', rho, mp.mpf(R_text), 'second')
                rows.append((rho_text, sig(psi, 20)))
    for rho_text in ['0.01', '0.5', '0.99']:
        for psi_text in ['1e-3', '1e-6', '1e-10']:
            rows.append((rho_text, psi_text))
    for psi_text in ['1e-6', '0.01', '0.5', '1.0', '1.5', '2.0', '2.09']:
        rows.append(('1', psi_text))
    for psi_text in ['0.01', '0.3', '0.8', '1.0', '1.2', '1.6', '2.0', '2.09']:
        rows.append(('0.01', psi_text))
    return rows


def random_endpoints(n=N_RANDOM, seed=RANDOM_SEED):
    """n random endpoints: rho ~ U[0.01, 1], psi ~ U(0, 2 pi/3 - 0.01), 17 digits."""
    rng = random.Random(seed)
    rows = []
    while len(rows) < n:
        rho = rng.uniform(0.01, 1.0)
        psi = rng.uniform(0.0, 2 * math.pi / 3 - 0.01)
        if psi <= 0:
            continue
        rows.append(('%.17g' % rho, '%.17g' % psi))
    return rows


# ---------------------------------------------------------------------------
# Driver
# ---------------------------------------------------------------------------

def solve_verified(rho_text, psi_text):
    """Compute a row at WORK_DPS and CHECK_DPS; return (row dict, agreement digits)."""
    arch50, R50, s50, t50, coarse = compute_row(rho_text, psi_text, WORK_DPS)
    arch65, R65, s65, t65, _ = compute_row(rho_text, psi_text, CHECK_DPS, coarse)
    if arch50 != arch65:
        raise ArithmeticError('arch decision differs between precisions')
    with mp.workdps(CHECK_DPS):
        digits = min(agreement_digits(R50, R65), agreement_digits(s50, s65),
                     agreement_digits(t50, t65))
    row = dict(rho=rho_text, psi=psi_text, arch=arch65, R=R65, s=s65, t=t65)
    return row, digits


def check_table1(rows):
    """Compare Table 1 rows with the printed 15-digit values; return list of failures."""
    bad = []
    for row in rows:
        key = (row['rho'], row['psi'])
        if key not in TABLE1_PRINTED:
            continue
        for name, printed in zip(('R', 's', 't'), TABLE1_PRINTED[key]):
            ndec = len(printed.split('.')[1])
            with mp.workdps(40):
                mine = +row[name]
                ok = abs(mine - mp.mpf(printed)) <= mp.mpf(10) ** (-ndec) / 2
            if not ok:
                mine = mp.nstr(mine, ndec + 3)
                bad.append((key, name, printed, mine))
    return bad


def write_csv(path, rows, command):
    """Write the comment header, the column header and the rows."""
    path.parent.mkdir(parents=True, exist_ok=True)
    lines = [
        '# generated by: %s' % command,
        '# mpmath %s; quadrature: own tanh-sinh on graded subdivision of the untransformed'
        ' integrals (Tee 1998 eqs. 55-57)' % mp.__version__,
        '# dps: values computed at %d digits, verified at %d digits (agreement >= %d digits);'
        ' R, s, t rounded to %d significant digits' % (CHECK_DPS, WORK_DPS, MIN_DIGITS, OUT_DIGITS),
        '# inputs: rho, psi are the decimal strings; the values used are their IEEE binary128'
        ' (113-bit, round-to-nearest) roundings',
        '# date: %s' % datetime.datetime.now(datetime.timezone.utc).strftime('%Y-%m-%d %H:%M UTC'),
        HEADER,
    ]
    for r in rows:
        lines.append(','.join([r['rho'], r['psi'], r['arch'], fmt(r['R']), fmt(r['s']), fmt(r['t'])]))
    path.write_text('\n'.join(lines) + '\n')


def read_csv(path):
    """Read the data rows of an existing table as a list of dicts of strings."""
    rows = []
    header = None
    for line in path.read_text().splitlines():
        if not line or line.startswith('#'):
            continue
        if header is None:
            header = line.split(',')
            if line != HEADER:
                raise ValueError('unexpected header: %s' % line)
            continue
        rows.append(dict(zip(header, line.split(','))))
    return rows


def run_check(path, n):
    """Recompute the first n rows of the table at WORK_DPS; return exit status."""
    rows = read_csv(path)[:n]
    failures = 0
    for i, r in enumerate(rows):
        arch, R, s, t, _ = compute_row(r['rho'], r['psi'], WORK_DPS)
        with mp.workdps(WORK_DPS):
            errs = [abs(x - mp.mpf(r[k])) / abs(mp.mpf(r[k])) for x, k in ((R, 'R'), (s, 's'), (t, 't'))]
            ok = arch == r['arch'] and max(errs) <= CHECK_RTOL
            print('%3d rho=%s psi=%s %s max rel diff %s %s' % (
                i + 1, r['rho'], r['psi'], arch, mp.nstr(max(errs), 3), 'ok' if ok else 'FAIL'),
                flush=True)
        failures += not ok
    print('%d of %d rows checked, %d failures' % (len(rows), len(rows), failures))
    return 1 if failures else 0


def main(argv=None):
    """Command line entry point."""
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--out', type=Path, default=DEFAULT_OUT, help='CSV path')
    parser.add_argument('--check', type=int, default=None, metavar='N',
                        help='recompute the first N rows of the existing CSV and compare')
    args = parser.parse_args(argv)
    if args.check is not None:
        return run_check(args.out, args.check)

    command = 'python scripts/make_reference.py' + (
        '' if args.out == DEFAULT_OUT else ' --out %s' % args.out)
    endpoints = table1_endpoints() + hard_endpoints() + random_endpoints()
    rows, worst, excluded = [], 99.0, []
    t_start = time.time()
    for i, (rho_text, psi_text) in enumerate(endpoints):
        t0 = time.time()
        row, digits = solve_verified(rho_text, psi_text)
        status = 'ok'
        if digits < MIN_DIGITS:
            excluded.append((rho_text, psi_text, digits))
            status = 'EXCLUDED'
        else:
            rows.append(row)
            worst = min(worst, digits)
        print('%3d/%d rho=%s psi=%s %s R=%s agree=%.1f %.1fs %s' % (
            i + 1, len(endpoints), rho_text, psi_text, row['arch'], mp.nstr(row['R'], 12),
            digits, time.time() - t0, status), flush=True)
    write_csv(args.out, rows, command)
    bad = check_table1(rows)
    print('rows written: %d, excluded: %d, runtime %.0f s' % (len(rows), len(excluded), time.time() - t_start))
    print('minimum agreement %d vs %d digits: %.1f significant digits' % (WORK_DPS, CHECK_DPS, worst))
    print('smallest Rbar: %s' % mp.nstr(min(r['R'] for r in rows), 10))
    print('Table 1 check: %s' % ('all 15 printed digits reproduced' if not bad else bad))
    for e in excluded:
        print('excluded:', e)
    return 0 if not bad and not excluded else 1


if __name__ == '__main__':
    sys.exit(main())
