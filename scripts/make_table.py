#!/usr/bin/env python3
"""Write a namelist input of N random accessible endpoints (for timings and the README).

    python3 scripts/make_table.py N OUT.nml [--force NAME] [--exponent N] [--seed S]

rho is uniform in [0.01, 1] (repulsive: [1, 4]) and psi uniform inside the field's
accessible angles: (0, 2 pi/3) inverse-square, (0, 2 pi/(n+1)) power law n, (0, pi)
logarithmic, (0, pi] harmonic, (0, pi] repulsive. Deterministic for a given seed.
"""
import argparse
import math
import random


def accessible_angle(force, exponent):
    return {"inverse_square": 2 * math.pi / 3, "power": 2 * math.pi / (exponent + 1),
            "logarithmic": math.pi, "harmonic": math.pi, "repulsive": math.pi}[force]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("n", type=int, help="number of endpoints")
    parser.add_argument("out", help="the namelist file to write")
    parser.add_argument("--force", default="inverse_square",
                        choices=["inverse_square", "power", "logarithmic", "harmonic",
                                 "repulsive"])
    parser.add_argument("--exponent", type=float, default=3.0, help="n of 'power'")
    parser.add_argument("--seed", type=int, default=2026)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    low, high = (1.0, 4.0) if args.force == "repulsive" else (0.01, 1.0)
    top = accessible_angle(args.force, args.exponent) * (1 - 1e-9)
    with open(args.out, "w") as f:
        f.write("&endpoints\n n = %d\n force = '%s'\n" % (args.n, args.force))
        if args.force == "power":
            f.write(" exponent = %r\n" % args.exponent)
        for name, draw in (("rho", lambda: rng.uniform(low, high)),
                           ("psi", lambda: rng.uniform(1e-9, top))):
            f.write(" %s = " % name)
            for k in range(args.n):
                f.write("%.17g%s" % (draw(), ",\n  " if k % 4 == 3 else ", ")
                        if k < args.n - 1 else "%.17g\n" % draw())
        f.write("/\n")


if __name__ == "__main__":
    main()
