#!/usr/bin/env python3
"""Independent references for `force = 'uniform'` through the field interface (g = 1).

Command (from the repository root; about ten seconds):
    .venv/bin/python scripts/make_uniform_field_reference.py \
        > data/reference/uniform_field_mpmath.csv

Uniform gravity is Tee's section 1 (the classical cycloid), not a central field: its
"original" equations are the cycloid's, x = a (phi - sin phi), y = a (1 - cos phi),
t = phi sqrt(a/g), s = 4 a (1 - cos(phi/2)), solved by `brachistochrone_at` of
scripts/make_uniform_reference.py (plain formulas at dps = 63 + 3 floor(|log10(x/y)|),
Anderson-Bjorck root certified by a sign change), here at that precision and 20 digits
more, agreeing to >= 50 digits. B level with A (y = 0) is the complete arch in closed
form: phi = 2 pi, a = x/(2 pi), s = 8 a, t = 2 pi sqrt(a). g = 1, the field's unit.
The field reports the rolling-circle radius a as its R-bar (the curve's one parameter).

Endpoints of every class: first (phi < pi) and second half-arches (phi > pi), within
1e-17 and 1e-30 of the lowest point (x/y = pi/2) on both sides, the steep end x/y -> 0
(phi -> 0, a -> infinity) down to 1e-30, the flat end x/y -> infinity (phi -> 2 pi, the
edge of the accessible region y -> 0+) up to 1e30, the complete arch y = 0, extreme
scales. x, y are binary128 numbers (written with 60 digits).
cond_R, cond_s, cond_t: |dF/dx| x/F (F = a, s, t) by central differences at the lower
precision (the conditioning with respect to the ratio x/y).
Columns: class, x, y, arch, R (= a), s, t, cond_R, cond_s, cond_t, agreement.
"""
import os
import sys

import mpmath as mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_uniform_reference import brachistochrone_at  # noqa: E402


def binary128(x):
    """x rounded to the nearest binary128 number (113-bit significand)."""
    _, e = mp.frexp(x)
    return mp.ldexp(mp.nint(mp.ldexp(x, 113 - e)), e - 113)


def values(x, y, dps):
    """a, s, t and phi at dps digits."""
    if y == 0:
        with mp.workdps(dps):
            a = x / (2 * mp.pi)
            return [+a, 8 * a, 2 * mp.pi * mp.sqrt(a), 2 * mp.pi]
    phi, _, a, t, s = brachistochrone_at(x, y, mp.mpf(1), dps)
    return [a, s, t, phi]


def working_digits(x, y):
    if y == 0:
        return 60
    return 63 + 3 * int(mp.floor(abs(mp.log10(x / y))))


def cases():
    mp.mp.dps = 80
    b = binary128
    one = mp.mpf(1)
    half_pi = mp.pi / 2
    out = [("first", b(mp.mpf("0.75")), one), ("first", b(mp.mpf("0.3")), b(mp.mpf("2.5"))),
           ("second", b(mp.mpf("2.5")), one), ("second", b(mp.mpf(10)), b(mp.mpf("0.7"))),
           ("first", one, one), ("second", b(mp.mpf(5)), one)]
    out += [("first", b(mp.mpf("0.1")), one), ("second", b(mp.mpf("1.6")), one)]
    for gap in ("1e-17", "1e-24", "1e-30"):
        out.append(("near_bottom_first", b(half_pi * (1 - mp.mpf(gap))), one))
        out.append(("near_bottom_second", b(half_pi * (1 + mp.mpf(gap))), one))
    out.append(("near_bottom", b(half_pi), one))
    for k in (-30, -20, -12, -9, -6, -3):
        out.append(("steep", b(mp.mpf(10) ** k), one))
    for k in (3, 6, 9, 12, 20, 30):
        out.append(("flat_edge", b(mp.mpf(10) ** k), one))
    for x in ("1", "0.001", "1e20"):
        out.append(("complete", b(mp.mpf(x)), mp.mpf(0)))
    out += [("scale", b(mp.mpf("3e-20")), b(mp.mpf("2e-20"))),
            ("scale", b(mp.mpf("3e20")), b(mp.mpf("2e20"))),
            ("scale", b(mp.mpf("1e-300")), b(mp.mpf("1e-290"))),
            ("scale", b(mp.mpf("4e250")), b(mp.mpf("3e260")))]
    return out


def digits(p, q):
    if p == q:
        return 99.0
    return float(-mp.log10(abs(p - q) / abs(q)))


def main():
    print("# uniform field references (g = 1): scripts/make_uniform_field_reference.py "
          "(see its docstring)")
    print("# mpmath %s, cycloid (Tee sec. 1) at dps = 63 + 3 floor(|log10(x/y)|) and 20 "
          "more; x, y are binary128 numbers" % mp.__version__)
    print("class,x,y,arch,R,s,t,cond_R,cond_s,cond_t,agreement")
    for cls, x, y in cases():
        dps = working_digits(x, y)
        low = values(x, y, dps)
        high = values(x, y, dps + 20)
        agree = min(digits(p, q) for p, q in zip(low[:3], high[:3]))
        if agree < 50:
            raise SystemExit("%s x=%s y=%s: precisions agree to %.1f" % (cls, x, y, agree))
        with mp.workdps(dps):
            h = x * mp.mpf(10) ** -20
            minus, plus = values(x - h, y, dps), values(x + h, y, dps)
            cond = [abs((plus[k] - minus[k]) / (2 * h)) * x / low[k] for k in range(3)]
        phi = high[3]
        arch = "complete" if y == 0 else ("first" if phi <= mp.pi else "second")
        mp.mp.dps = dps + 20
        print(",".join([cls, mp.nstr(x, 60), mp.nstr(y, 60), arch]
                       + [mp.nstr(v, 45) for v in high[:3]]
                       + [mp.nstr(c, 3) for c in cond] + ["%.1f" % agree]))


if __name__ == "__main__":
    main()
