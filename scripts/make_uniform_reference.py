#!/usr/bin/env python3
"""Independent high-precision references for the uniform-gravity module.

Command (from the repository root):

    .venv/bin/python scripts/make_uniform_reference.py

writes data/reference/uniform_brachistochrone_mpmath.csv and
data/reference/pendulum_mpmath.csv.

Brachistochrone (Tee 1998 section 1.3, Saitoh eq. (1)).  Start A at the origin, y
downward, B = (x, y) with x, y > 0.  The cycloid x = a(phi - sin phi),
y = a(1 - cos phi) through B has (phi - sin phi)/(1 - cos phi) = x/y, and then

    a = y/(1 - cos phi),  t = phi sqrt(a/g),  s = 4 a (1 - cos(phi/2)).

Deliberately independent of the Fortran code (src/fields/brachistochrone_uniform_gravity.f90), which
uses series, half-angle forms and two different unknowns to avoid cancellation: here
the textbook formulas above are evaluated as written, and cancellation is beaten by
brute working precision instead: each row is computed at
dps = 63 + 3 floor(|log10(x/y)|) (phi - sin phi ~ phi^3/6 loses about 2 log10(1/phi) digits
for small phi, 1 - cos phi ~ delta^2/2 about log10(x/y) digits near phi = 2 pi).  The
root is found by mpmath's Anderson-Bjorck bracketing solver on
F(phi) = (phi - sin phi)/(1 - cos phi) - x/y, in phi for x/y <= 2 and in
delta = 2 pi - phi above; it is then certified by the sign change of F at
root*(1 -+ 1e-53), and the whole row is recomputed with 20 more digits and must
agree to 50 significant digits.

Pendulum: period = 4 sqrt(L/g) K(m), m = sin^2(theta0/2), with K from mpmath's ellipk
(an AGM) and, independently, from (pi/2) 2F1(1/2, 1/2; 1; m) (hypergeometric series
with analytic continuation near m = 1); both at 150 digits (1 - m is as small as 1e-69
here), required to agree to 60 digits.  The script also checks the Taylor coefficients
of T/(2 pi sqrt(L/g)) = (2/pi) K(sin(theta0/2)) in theta0 that the Fortran tests use.

Inputs are decimal strings; the values used are their IEEE binary128 (113-bit,
round-to-nearest) roundings, exactly what the Fortran tests read, so the references
apply to the very same numbers.  Outputs have 45 significant digits.
"""

import datetime
import random
from fractions import Fraction

import mpmath
from mpmath import mp, mpf

OUT_BRACHISTOCHRONE = "data/reference/uniform_brachistochrone_mpmath.csv"
OUT_PENDULUM = "data/reference/pendulum_mpmath.csv"
DIGITS_OUT = 45


def binary128(text):
    """The binary128 rounding of a decimal string, as an exact mpf."""
    with mp.workprec(113):
        value = mpf(text)
    return +value


def show(value):
    return mpmath.nstr(value, DIGITS_OUT, strip_zeros=False)


def brachistochrone_at(x, y, g, dps):
    """phi, 2 pi - phi, a, t, s at dps digits (plain formulas)."""
    with mp.workdps(dps):
        ratio = x / y

        def f_phi(phi):
            return (phi - mp.sin(phi)) / (1 - mp.cos(phi)) - ratio

        if ratio <= 2:
            def f(u):
                return f_phi(u)
            lo, hi = ratio / 10, min(3 * ratio + mpf(1) / 10, mpf(6))
        else:
            def f(u):
                return f_phi(2 * mp.pi - u)
            estimate = 2 * mp.sqrt(mp.pi / ratio)
            lo, hi = estimate / 2, min(2 * estimate, mp.pi)
        assert f(lo) * f(hi) < 0, (x, y, lo, hi, f(lo), f(hi))
        root = mp.findroot(f, (lo, hi), solver="anderson",
                           tol=mpf(10) ** (-2 * dps + 20), maxsteps=2000, verify=False)
        # F keeps at least dps - 2|log10(x/y)| - 3 digits; a sign change across
        # root (1 -+ 1e-53) is far above that noise and certifies 53 digits of the root
        width = mpf(10) ** -53
        assert f(root * (1 - width)) * f(root * (1 + width)) < 0, "root not certified"
        if ratio <= 2:
            phi = root
            deficit = 2 * mp.pi - phi
        else:
            deficit = root
            phi = 2 * mp.pi - deficit
        a = y / (1 - mp.cos(phi))
        t = phi * mp.sqrt(a / g)
        s = 4 * a * (1 - mp.cos(phi / 2))
        return [+phi, +deficit, +a, +t, +s]


def brachistochrone_rows():
    rows = []
    # ratio x/y = 10^k with y = 1
    for k in [-30, -20, -12, -9, -6, -4, -3, -2, -1, 0, 1, 2, 3, 4, 6, 9, 12, 20, 30]:
        rows.append(("1e%d" % k, "1", "9.80665"))
    for text in ["0.3162277660168379", "3.1622776601683793", "0.75", "1.25", "2.5", "5"]:
        rows.append((text, "1", "9.80665"))
    # both sides of the switch x = (pi/2) y between the two unknowns
    for text in ["1.5707963267948966192313216916397513", "1.5707963267948966192313216916397514",
                 "1.5707963267948966192313216916397515", "1.5707963267948966192313216916397516",
                 "1.57", "1.5708"]:
        rows.append((text, "1", "1"))
    # assorted scales and gravities
    rows += [("0.5", "2", "1"), ("3.7", "0.2", "1.62"), ("100", "3", "9.81"),
             ("1e-8", "250", "3.72"), ("2.5e6", "7.5e5", "24.79"), ("1", "1e-15", "1"),
             ("1e-15", "1", "1"), ("123.456", "7.89e-10", "0.001"), ("1e-300", "1e-290", "5"),
             ("4e250", "3e260", "1e-5")]
    rng = random.Random(20260)
    for _ in range(40):
        x = "%.12e" % (10 ** rng.uniform(-6, 6))
        y = "%.12e" % (10 ** rng.uniform(-3, 3))
        g = "%.6f" % rng.uniform(0.5, 30)
        rows.append((x, y, g))
    return rows


def pendulum_rows():
    with mp.workprec(113):
        pi_qp = +mp.pi
    rows = []
    for text in ["1e-8", "1e-4", "0.001", "0.01", "0.1", "0.25", "0.5", "1", "1.5", "2",
                 "2.5", "3", "3.1", "3.14", "3.1415", "3.14159265", "3.14159265358979"]:
        rows.append(("1", "9.80665", text))
    rows.append(("1", "9.80665", mpmath.nstr(pi_qp, 40, strip_zeros=False)))
    rows += [("0.994", "9.81", "0.7853981633974483"), ("2.5", "1.62", "1.0471975511965976"),
             ("1e-3", "3.72", "2.0943951023931955"), ("42", "24.79", "0.3")]
    return rows


def coefficient_check():
    """Taylor coefficients of (2/pi) K(sin(theta/2)) in theta, even powers 0..14."""
    expected = [Fraction(1), Fraction(1, 16), Fraction(11, 3072), Fraction(173, 737280),
                Fraction(22931, 1321205760), Fraction(1319183, 951268147200),
                Fraction(233526463, 2009078326886400),
                Fraction(2673857519, 265928913086054400)]
    with mp.workdps(60):
        series = mp.taylor(lambda th: 2 / mp.pi * mp.ellipk(mp.sin(th / 2) ** 2), 0, 15)
        for i, c in enumerate(expected):
            got = series[2 * i]
            exact = mpf(c.numerator) / c.denominator
            assert abs(got - exact) <= mpf(10) ** -40 * exact, (2 * i, got, exact)
            assert abs(series[2 * i + 1]) < mpf(10) ** -40
    return expected


def main():
    mp.dps = 60
    stamp = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    lines = [
        "# generated by: .venv/bin/python scripts/make_uniform_reference.py",
        "# mpmath %s; plain formulas at dps = 63 + 3 floor(|log10(x/y)|), Anderson-Bjorck root "
        "certified by a sign change, rechecked at dps + 20 (agreement >= 50 digits)"
        % mpmath.__version__,
        "# inputs: x, y, g are decimal strings; the values used are their IEEE binary128 "
        "roundings; outputs rounded to 45 significant digits",
        "# columns: phi = rolling angle at B, deficit = 2 pi - phi, a = rolling-circle "
        "radius, t = time, s = arclength",
        "# date: " + stamp,
        "x,y,g,phi,deficit,a,t,s",
    ]
    for x_text, y_text, g_text in brachistochrone_rows():
        x, y, g = binary128(x_text), binary128(y_text), binary128(g_text)
        dps = 60 + 3 * int(abs(mpmath.log10(x / y))) + 3
        first = brachistochrone_at(x, y, g, dps)
        second = brachistochrone_at(x, y, g, dps + 20)
        for u, v in zip(first, second):
            assert abs(u - v) <= mpf(10) ** -50 * abs(v), (x_text, y_text, u, v)
        lines.append(",".join([x_text, y_text, g_text] + [show(v) for v in second]))
    with open(OUT_BRACHISTOCHRONE, "w") as out:
        out.write("\n".join(lines) + "\n")

    coefficient_check()
    lines = [
        "# generated by: .venv/bin/python scripts/make_uniform_reference.py",
        "# mpmath %s; period = 4 sqrt(L/g) K(sin^2(theta0/2)) at 150 digits, K from ellipk "
        "and from (pi/2) hyp2f1(1/2,1/2;1;m), agreeing to >= 60 digits" % mpmath.__version__,
        "# inputs: L, g, theta0 are decimal strings; the values used are their IEEE "
        "binary128 roundings; period rounded to 45 significant digits",
        "# date: " + stamp,
        "length,g,theta0,period",
    ]
    for l_text, g_text, theta_text in pendulum_rows():
        length, g, theta = binary128(l_text), binary128(g_text), binary128(theta_text)
        with mp.workdps(150):
            m = mp.sin(theta / 2) ** 2
            k_agm = mp.ellipk(m)
            k_hyp = mp.pi / 2 * mp.hyp2f1(mpf(1) / 2, mpf(1) / 2, 1, m)
            assert abs(k_agm - k_hyp) <= mpf(10) ** -60 * k_agm, (theta_text, k_agm, k_hyp)
            period = 4 * mp.sqrt(length / g) * k_agm
        lines.append(",".join([l_text, g_text, theta_text, show(period)]))
    with open(OUT_PENDULUM, "w") as out:
        out.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
