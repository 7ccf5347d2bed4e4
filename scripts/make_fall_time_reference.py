#!/usr/bin/env python3
"""Independent references for the power law's radial fall time t0 (issue 11's fall-time
tables), with mpmath on the ORIGINAL integral.

Command (from the repository root):
    .venv/bin/python scripts/make_fall_time_reference.py > data/reference/power_fall_time_mpmath.csv

Power law F = 1/r^n, v^2 = P(x) = 2 (x^(1-n) - 1)/(n - 1) (release from rest at r = 1):
    t0(x) = int_x^1 dx' / v(x'),   x = exp(-delta),
by tanh-sinh quadrature (mp.quad) with the square-root end x' -> 1 removed by
x' = 1 - (1 - x) s^2 (dx' = 2 (1 - x) s ds), at 60 and 80 digits; `agreement` is the
number of digits in which the two agree. delta is written to 40 digits and read by the
test as a binary128 number: the reference is t0 at that decimal delta (its rounding to
binary128 moves t0 by t0'(delta) delta eps, which the test allows for).
"""
import mpmath as mp

# (the first: n = 1 + 2^-100 to 51 digits, read as exactly that binary128 number)
EXPONENTS = ["1.00000000000000000000000000000078886090522101180541", "1.0000000001",
             "1.000001", "1.1", "1.3", "1.5", "1.75", "2.5", "4.3", "6", "10", "32"]
DELTAS = ["1e-34", "1e-12", "0.001", "0.04", "0.3", "1", "2.5", "7", "40"]


def fall_time(n, delta):
    a = n - 1
    x = mp.exp(-delta)
    one_minus_x = -mp.expm1(-delta)

    def integrand(s):
        # x' = 1 - (1 - x) s^2; x'^(-a) - 1 = expm1(-a log x') without cancellation
        xp = 1 - one_minus_x * s * s
        p = 2 * mp.expm1(-a * mp.log1p(-one_minus_x * s * s)) / a
        return 2 * one_minus_x * s / mp.sqrt(p)

    return mp.quad(integrand, [0, 1])


def main():
    print("# power-law fall time t0 = int_x^1 dx/v, x = exp(-delta): "
          "scripts/make_fall_time_reference.py")
    print("# mpmath tanh-sinh on the original integral at 60 and 80 digits")
    print("n,delta,t0,agreement")
    for n_text in EXPONENTS:
        for d_text in DELTAS:
            values = []
            for dps in (60, 80):
                mp.mp.dps = dps
                values.append(fall_time(mp.mpf(n_text), mp.mpf(d_text)))
            mp.mp.dps = 80
            diff = abs(values[0] - values[1])
            agreement = 80.0 if diff == 0 else float(-mp.log10(diff / abs(values[1])))
            print(f"{n_text},{d_text},{mp.nstr(values[1], 45, min_fixed=-5, max_fixed=5)},"
                  f"{agreement:.1f}")


if __name__ == "__main__":
    main()
