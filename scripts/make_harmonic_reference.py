#!/usr/bin/env python3
"""Independent mpmath reference values for the harmonic (uniform planet) tunnels.

Command (writes data/reference/harmonic_mpmath.csv, about a minute):

    /work/main/.venv/bin/python scripts/make_harmonic_reference.py

(or .venv/bin/python from a set-up checkout; --out PATH to write elsewhere).

Physics (units R = 1, omega = 1): v(x) = sqrt(1 - x^2) inside a uniform planet,
start A at radius 1 from rest.  Tee (1998) section 2, eqs. (27), (33), (39),
with v(R)/R and v(x) of this law, give on the first half-arch of the
brachistochrone with apse radius R (= Saitoh's R_m/R):

    Theta(r,R) = R Int_r^1 sqrt(1 - x^2) / (x sqrt(x^2 - R^2)) dx
    S(r,R)     = Int_r^1 x sqrt(1 - R^2) / sqrt(x^2 - R^2) dx
    T(r,R)     = Int_r^1 x sqrt(1 - R^2) / sqrt((1 - x^2)(x^2 - R^2)) dx

Method, deliberately different from the Fortran code under test:

* kinds theta, s, t: the integrals above by mpmath's tanh-sinh (mp.quad),
  split at m = (1 + R)/2, with x = R + u^2 on [r, m] and x = 1 - u^2 on
  [m, 1] (the Fortran test uses one sin^2 substitution on [R, 1] instead).
  This removes both 1/sqrt endpoint singularities (mp.quad applied to the
  raw integrals loses about half the digits there, and its nodes can round
  onto the endpoint).  Each value is computed at 60 and at 80 digits and
  accepted only if the two agree to 55 significant digits and the 80-digit
  value agrees to 55 digits with Saitoh's closed forms (eqs. 7-9 and the
  arclength 2 (1 - R^2) sin^2(phi/4)); the script stops if any check fails.
  The value written is the 80-digit quadrature.
* kinds x, y: the rolling-circle form of the hypocycloid (Saitoh 11-12) with
  a = (1 - rho_m)/2 at 100 digits (the Fortran code uses other forms).
* kind endpoint_*: the two-point problem solved for rho_m with mpmath's
  bracketed Anderson-Bjorck iteration in the variable rho_m itself on
  theta = atan2(rho_m sin h, cos h) - rho_m h, h from eq. (7), at 60 digits
  (the Fortran code iterates in another variable with other forms of theta).
* kind route_*: the great-circle angle by the haversine formula (the
  Fortran code uses the atan2 / Vincenty form), then depth R Theta/pi,
  length 2 R (Theta/pi)(2 - Theta/pi), time pi sqrt(R/g) sqrt(1 - rho_m^2)
  with R = 6371 km, g = 9.81 m/s^2, at 60 digits.
* kind tautochrone: the time from rest at r0 to the deepest point,
  Int_rho^r0 x sqrt(1 - rho^2) / sqrt((x^2 - rho^2)(r0^2 - x^2)) dx (ds/dr
  from Tee (33), v^2 = r0^2 - x^2), x = rho + u^2 and x = r0 - u^2 on its two
  halves, by mp.quad at 60 and 80 digits, checked as above against
  (pi/2) sqrt(1 - rho^2).

Inputs are decimal strings, used as their IEEE binary128 roundings (what the
Fortran test reads from this file): with mp.workprec(113): x = mp.mpf(string).
Values are written with 45 significant digits.
"""
import argparse
import datetime
import sys

import mpmath as mp

DIGITS_OUT = 45
QUAD_DPS = (60, 80)
QUAD_AGREE = 55

# (r, R) on the first half-arch, r = R is the deepest point
INTEGRAL_POINTS = [
    ("0.7", "0.3"), ("0.3", "0.3"), ("0.95", "0.05"), ("0.5", "0.49"),
    ("0.999", "0.9"), ("0.1", "0.01"), ("0.9", "0.9"), ("0.5", "0.0001"),
    ("0.99999", "0.5"),
]
# (phi, rho_m) for the Cartesian position
POSITION_POINTS = [
    ("0.000001", "0.3"), ("0.01", "0.7"), ("1.5", "0.2"), ("2.5", "0.8"),
    ("3.14", "0.5"), ("5.0", "0.05"), ("6.2", "0.95"),
]
# (r_B, theta_B)
ENDPOINTS = [
    ("0.5", "0.3"), ("0.5", "1.5"), ("0.9", "0.01"), ("0.2", "3.0"),
    ("0.01", "1.0"), ("0.99", "2.0"), ("0.7", "0.000001"),
]
# shallow tunnels (r_B next to 1, small theta_B: 1 - rho_m down to 3e-21), solved at
# SHALLOW_DPS digits so that 1 - rho_m keeps more than 55 of them
SHALLOW_ENDPOINTS = [
    ("0.99999999999999999999999999999", "1e-20"),
    ("0.99999999999999999999999999999", "1e-10"),
    ("0.9999999999", "1e-10"),
    ("0.999999999999999999", "0.001"),
]
SHALLOW_DPS = 110
# (lat1, lon1, lat2, lon2): New York - Los Angeles, antipodes on the equator
ROUTES = [
    ("40.7128", "-74.0060", "34.0522", "-118.2437"),
    ("0", "0", "0", "180"),
]
# (r0, rho_m)
TAUTOCHRONE = [("1", "0.3"), ("0.6", "0.3"), ("0.31", "0.3"), ("0.9", "0.8")]


def q128(text):
    """The binary128 rounding of a decimal string."""
    with mp.workprec(113):
        return mp.mpf(text)


def fmt(x):
    return mp.nstr(x, DIGITS_OUT, min_fixed=1, max_fixed=0)


def agree(a, b, digits, what):
    if a == b:
        return
    if abs(a - b) > abs(b) * mp.mpf(10) ** (-digits):
        sys.exit(f"check failed: {what}: {mp.nstr(a, 50)} vs {mp.nstr(b, 50)}")


def tee_integral(kind, r, big_r):
    """Theta, S or T of the docstring, with both 1/sqrt endpoint singularities removed
    by x = R + u^2 (on [r, m]) and x = 1 - u^2 (on [m, 1]), m = (1 + R)/2; the factor
    u of dx = 2u du cancels analytically, so no integrand divides by u."""
    q = mp.sqrt(1 - big_r ** 2)
    width = 1 - big_r

    def near_apse(u):                     # x - R = u^2, 1 - x = width - u^2
        x, d1 = big_r + u * u, width - u * u
        if kind == "theta":
            return 2 * big_r * mp.sqrt(d1 * (1 + x)) / (x * mp.sqrt(x + big_r))
        if kind == "s":
            return 2 * x * q / mp.sqrt(x + big_r)
        return 2 * x * q / mp.sqrt(d1 * (1 + x) * (x + big_r))

    def near_surface(u):                  # 1 - x = u^2, x - R = width - u^2
        x, dr = 1 - u * u, width - u * u
        if kind == "theta":
            return 2 * big_r * u * u * mp.sqrt(1 + x) / (x * mp.sqrt(dr * (x + big_r)))
        if kind == "s":
            return 2 * u * x * q / mp.sqrt(dr * (x + big_r))
        return 2 * x * q / mp.sqrt((1 + x) * dr * (x + big_r))

    middle = (1 + big_r) / 2
    if r >= middle:
        return mp.quad(near_surface, [0, mp.sqrt(1 - r)])
    return (mp.quad(near_apse, [mp.sqrt(r - big_r), mp.sqrt(middle - big_r)])
            + mp.quad(near_surface, [0, mp.sqrt(1 - middle)]))


def tautochrone_integral(r0, rho):
    """Int_rho^r0 x sqrt(1 - rho^2)/sqrt((x^2 - rho^2)(r0^2 - x^2)) dx with x = rho + u^2
    and x = r0 - u^2 on the two halves (u cancelled analytically)."""
    q = mp.sqrt(1 - rho ** 2)
    middle = (rho + r0) / 2

    def near_bottom(u):
        x = rho + u * u
        return 2 * x * q / mp.sqrt((x + rho) * (r0 - x) * (r0 + x))

    def near_release(u):
        x = r0 - u * u
        return 2 * x * q / mp.sqrt((x - rho) * (x + rho) * (r0 + x))

    return (mp.quad(near_bottom, [0, mp.sqrt(middle - rho)])
            + mp.quad(near_release, [0, mp.sqrt(r0 - middle)]))


def closed_form(kind, r, big_r):
    h = mp.atan2(mp.sqrt(1 - r * r), mp.sqrt(r * r - big_r ** 2))
    if kind == "theta":
        return mp.atan2(big_r * mp.sin(h), mp.cos(h)) - big_r * h
    if kind == "s":
        return 2 * (1 - big_r ** 2) * mp.sin(h / 2) ** 2
    return h * mp.sqrt(1 - big_r ** 2)


def checked_quad(compute, closed, what):
    values = []
    for dps in QUAD_DPS:
        with mp.workdps(dps):
            values.append(compute())
    agree(values[0], values[1], QUAD_AGREE, what + " (60 vs 80 digits)")
    with mp.workdps(QUAD_DPS[1]):
        agree(closed(), values[1], QUAD_AGREE, what + " (closed form)")
    return values[1]


def theta_at(r, rho, second):
    h = mp.atan2(mp.sqrt(1 - r * r), mp.sqrt(r * r - rho * rho))
    if second:
        h = mp.pi - h
    return mp.atan2(rho * mp.sin(h), mp.cos(h)) - rho * h, h


def endpoint_rows(r_text, theta_text):
    """rho_m, time and arclength of the two-point problem at the working precision."""
    r, theta_b = q128(r_text), q128(theta_text)
    apse = mp.pi / 2 * (1 - r)
    second = theta_b > apse
    g = lambda rho: theta_at(r, rho, second)[0] - theta_b
    rho = mp.findroot(g, (mp.mpf(0), r), solver="anderson",
                      tol=mp.mpf(10) ** (-2 * mp.mp.dps + 2))
    residual = g(rho)
    if abs(residual) > mp.mpf(10) ** -55 * theta_b:
        sys.exit(f"endpoint ({r_text}, {theta_text}): residual {residual}")
    h = theta_at(r, rho, second)[1]
    return [("endpoint_rho", r_text, theta_text, "", "", rho),
            ("endpoint_time", r_text, theta_text, "", "", h * mp.sqrt(1 - rho ** 2)),
            ("endpoint_s", r_text, theta_text, "", "",
             2 * (1 - rho ** 2) * mp.sin(h / 2) ** 2)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="data/reference/harmonic_mpmath.csv")
    args = parser.parse_args()
    rows = []

    for r_text, big_r_text in INTEGRAL_POINTS:
        r, big_r = q128(r_text), q128(big_r_text)
        for kind in ("theta", "s", "t"):
            value = checked_quad(lambda: tee_integral(kind, r, big_r),
                                 lambda: closed_form(kind, r, big_r),
                                 f"{kind}({r_text}, {big_r_text})")
            rows.append((kind, r_text, big_r_text, "", "", value))

    with mp.workdps(100):
        for phi_text, rho_text in POSITION_POINTS:
            phi, rho = q128(phi_text), q128(rho_text)
            a = (1 - rho) / 2
            x = (1 - a) * mp.cos(a * phi) + a * mp.cos((1 - a) * phi)
            y = (1 - a) * mp.sin(a * phi) - a * mp.sin((1 - a) * phi)
            rows.append(("x", phi_text, rho_text, "", "", x))
            rows.append(("y", phi_text, rho_text, "", "", y))

    with mp.workdps(60):
        for r_text, theta_text in ENDPOINTS:
            rows.extend(endpoint_rows(r_text, theta_text))
    with mp.workdps(SHALLOW_DPS):
        for r_text, theta_text in SHALLOW_ENDPOINTS:
            rows.extend(endpoint_rows(r_text, theta_text))
    with mp.workdps(60):
        big_r, g = q128("6371"), q128("9.81")
        for lat1_t, lon1_t, lat2_t, lon2_t in ROUTES:
            lat1, lon1, lat2, lon2 = (mp.radians(q128(t)) for t in
                                      (lat1_t, lon1_t, lat2_t, lon2_t))
            hav = (mp.sin((lat2 - lat1) / 2) ** 2
                   + mp.cos(lat1) * mp.cos(lat2) * mp.sin((lon2 - lon1) / 2) ** 2)
            angle = 2 * mp.asin(mp.sqrt(hav))
            d = angle / mp.pi
            unit = mp.sqrt(1000 * big_r / g)
            values = {
                "route_angle": angle,
                "route_depth_km": big_r * d,
                "route_length_km": 2 * big_r * d * (2 - d),
                "route_time_s": mp.pi * unit * mp.sqrt(d * (2 - d)),
            }
            for kind, value in values.items():
                rows.append((kind, lat1_t, lon1_t, lat2_t, lon2_t, value))

    for r0_text, rho_text in TAUTOCHRONE:
        r0, rho = q128(r0_text), q128(rho_text)
        value = checked_quad(lambda: tautochrone_integral(r0, rho),
                             lambda: mp.pi / 2 * mp.sqrt(1 - rho ** 2),
                             f"tautochrone({r0_text}, {rho_text})")
        rows.append(("tautochrone", r0_text, rho_text, "", "", value))

    stamp = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    with open(args.out, "w") as out:
        out.write("# generated by: python scripts/make_harmonic_reference.py\n")
        out.write(f"# mpmath {mp.__version__}; see the script's docstring for each kind's method\n")
        out.write("# theta, s, t (a = r, b = R): Tee (27), (33), (39) with v = sqrt(1 - x^2), "
                  "mp.quad at 60 and 80 digits, agreeing to 55\n")
        out.write("# x, y (a = phi, b = rho_m): Saitoh (11)-(12); endpoint_* (a = r_B, "
                  "b = theta_B); route_* (a, b, c, d = lat1, lon1, lat2, lon2 in degrees; "
                  "R = 6371 km, g = 9.81 m/s^2); tautochrone (a = r0, b = rho_m)\n")
        out.write("# inputs: decimal strings used as their IEEE binary128 roundings\n")
        out.write(f"# date: {stamp}\n")
        out.write("kind,a,b,c,d,value\n")
        for kind, a, b, c, d, value in rows:
            out.write(f"{kind},{a},{b},{c},{d},{fmt(value)}\n")
    print(f"wrote {len(rows)} rows to {args.out}")


if __name__ == "__main__":
    main()
