#!/usr/bin/env python3
"""mpmath reference for the whole half-arch: Theta(R,R), S(R,R), T(R,R).

Usage::

    .venv/bin/python scripts/make_whole_arch_reference.py [--out PATH] [--dps 50]

The program tabulates these three functions of the apse radius R once per run
(piecewise Chebyshev series, `src/fields/brachistochrone_inverse_square.f90`), so they are checked
here on their own, over the whole of 0 < R < 1: near 0 and 1, next to the ends of the
16 pieces, and on a regular grid. Every R is a dyadic rational (exact in binary128 and
in mpmath), so the program and the reference see the same number.

The integrals are Tee (1998) eqs. (55)-(57) at r = R, in their ORIGINAL form (not the
substitutions the program uses), with Q(x) = x^2 + R x + R^2/(1-R):

    Theta(R,R) = sqrt(R^3/(1-R)) Int_R^1 (1-x)/(x sqrt((1-x)(x-R) Q(x))) dx
    S(R,R)     = Int_R^1 x^2/sqrt(x (x-R) Q(x)) dx
    T(R,R)     = Int_R^1 x^2/sqrt(2 (1-x)(x-R) Q(x)) dx

by mpmath's tanh-sinh quadrature (which handles the inverse square-root end
singularities), after x = R + u^2 and x = 1 - w^2 (split at the midpoint), which
make the integrands smooth, with the u range split at 2^k sqrt(R). Each value is computed at `dps` and at
`dps + 15` digits and kept only if the two agree to 40 digits. About a minute.
"""
import argparse
import pathlib

import mpmath as mp

ROOT = pathlib.Path(__file__).resolve().parents[1]


def radii():
    """Dyadic apse radii: ends, piece boundaries +- tiny offsets, a grid."""
    values = set()
    for j in range(1, 60, 3):
        values.add(mp.mpf(2) ** -j)              # towards 0
        values.add(1 - mp.mpf(2) ** -j)          # towards 1
    for k in range(1, 16):                       # the 16 pieces' ends
        for offset in (0, 2 ** -40, -2 ** -40, 2 ** -12, -2 ** -12):
            values.add(mp.mpf(k) / 16 + offset)
    for k in range(1, 128):                      # a regular grid
        values.add(mp.mpf(2 * k - 1) / 256)
    return sorted(v for v in values if 0 < v < 1)


def whole_arch(big_r):
    """Theta, S, T at r = R by the original integrals (55)-(57)."""
    def q(x):
        return x * x + big_r * x + big_r ** 2 / (1 - big_r)

    # x = R + u^2 near the apse end and x = 1 - w^2 near the start, which removes both
    # inverse square roots; the integrands then vary on the scale sqrt(R) next to
    # u = 0: split there geometrically
    top = 1 - big_r
    half = mp.sqrt(top / 2)

    def apse_side(f):
        # int_R^(R + top/2) f(x, x - R, 1 - x) dx with x - R = u^2
        points = [mp.mpf(0)]
        step = mp.sqrt(big_r)
        while step < half:
            points.append(step)
            step *= 2
        points.append(half)
        return mp.quad(lambda u: 2 * u * f(big_r + u * u, u * u, top - u * u), points)

    def start_side(f):
        # int_(R + top/2)^1 f dx with 1 - x = w^2
        return mp.quad(lambda w: 2 * w * f(1 - w * w, top - w * w, w * w), [0, half])

    def both(f):
        return apse_side(f) + start_side(f)

    theta = mp.sqrt(big_r ** 3 / top) * both(
        lambda x, gap, rest: rest / (x * mp.sqrt(rest * gap * q(x))))
    length = both(lambda x, gap, rest: x * x / mp.sqrt(x * gap * q(x)))
    time = both(lambda x, gap, rest: x * x / mp.sqrt(2 * rest * gap * q(x)))
    return theta, length, time


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=str(ROOT / "data/reference/whole_arch_mpmath.csv"))
    parser.add_argument("--dps", type=int, default=50)
    args = parser.parse_args()
    lines = ["# Theta(R,R), S(R,R), T(R,R) (Tee 1998, eqs. 55-57 at r = R), mpmath "
             f"tanh-sinh at {args.dps} and {args.dps + 15} digits, agreeing to 40",
             "# scripts/make_whole_arch_reference.py; R dyadic (exact in binary128)",
             "R,theta,s,t"]
    for big_r in radii():
        mp.mp.dps = args.dps
        low = whole_arch(big_r)
        mp.mp.dps = args.dps + 15
        high = whole_arch(big_r)
        for a, b in zip(low, high):
            if abs(a - b) > mp.mpf(10) ** -40 * abs(b):
                raise SystemExit(f"R = {big_r}: {a} and {b} disagree")
        mp.mp.dps = 45
        lines.append(",".join(mp.nstr(v, 40, strip_zeros=False) for v in (big_r,) + high))
    pathlib.Path(args.out).write_text("\n".join(lines) + "\n")
    print(f"{len(lines) - 3} radii written to {args.out}")


if __name__ == "__main__":
    main()
