"""Independent reference values for the repulsive inverse-square brachistochrones.

Command (from the repository root):
    .venv/bin/python scripts/make_repulsive_reference.py > data/reference/repulsive_mpmath.csv

mpmath at 80 digits on the *original* integrals of Tee (1998), (23), (31), (37) with
v^2 = 2(x-1)/x (mu = -1), i.e. with Q(x) = x^3 - 2K^2(x-1):
    theta = int_1^r K sqrt2 sqrt(x-1)/(x sqrt Q) dx,  s = int_1^r x^(3/2)/sqrt Q dx,
    t     = int_1^r x^2/(sqrt2 sqrt(x-1) sqrt Q) dx,
tanh-sinh quadrature on intervals split near the start, the apse and x = 3/2. Bounded
curves take K^2 = R^3/(2(R-1)) from their apse R; second half-arch 2F(R) - F(r) (29).
Every parameter is a dyadic rational, so the quad-precision tests use the same numbers.
Columns: case, K^2 (or R), quantity, r, arch, value (40 digits), error estimate.
Last rows (two_point_*): the two-point problem solved here independently (findroot);
columns case, K^2 or R found, t, rho, target, t (40 digits), angle residual.
"""
import mpmath as mp

mp.mp.dps = 80


def integrals(k2, r, breaks, big_r=None):
    """theta, s, t from 1 to r, each as (value, error). Near x = 1 the variable is
    u = sqrt(x - 1) (x - 1 = u^2 exact); bounded curves near the apse use w = sqrt(R - x)
    with Q = (R - x)(2K^2/R - R x - x^2), the exact quotient of Q by x - R."""
    k = mp.sqrt(k2)

    def parts(xm1, q):
        x = 1 + xm1
        return (k * mp.sqrt(2) * mp.sqrt(xm1) / (x * mp.sqrt(q)),
                x**mp.mpf(1.5) / mp.sqrt(q),
                x**2 / (mp.sqrt(2) * mp.sqrt(xm1) * mp.sqrt(q)))

    def q_of(xm1):
        x = 1 + xm1
        if big_r is None:
            return x**3 - 2 * k2 * xm1
        return (big_r - x) * (2 * k2 / big_r - big_r * x - x**2)

    out = []
    for i in range(3):
        u_end = mp.sqrt(min(r, mp.mpf(1.25)) - 1)
        if big_r is not None:
            u_end = mp.sqrt(min(r - 1, (big_r - 1) / 2))
        v, e = mp.quad(lambda u: 2 * u * parts(u * u, q_of(u * u))[i], [0, u_end],
                       error=True, maxdegree=12)
        top = 1 + u_end**2
        if big_r is not None and r > top:
            # x = R - w^2, w from sqrt(R - r) up to sqrt(R - top)
            w_pts = [mp.sqrt(big_r - r)] + [mp.sqrt(big_r - b) for b in reversed(breaks)
                                           if r > b > top] + [mp.sqrt(big_r - top)]
            g = lambda w: 2 * w * parts(big_r - 1 - w * w,
                                        w * w * (2 * k2 / big_r - big_r * (big_r - w * w)
                                                 - (big_r - w * w)**2))[i]
            v2, e2 = mp.quad(g, w_pts, error=True, maxdegree=12)
            v, e = v + v2, e + e2
        elif r > top:
            pts = [top] + [b for b in breaks if top < b < r] + [r]
            v2, e2 = mp.quad(lambda x: parts(x - 1, q_of(x - 1))[i], pts, error=True,
                             maxdegree=12)
            v, e = v + v2, e + e2
        out.append((v, e))
    return out


def row(case, par, name, r, arch, v, e):
    print(f"{case},{mp.nstr(par, 40)},{name},{mp.nstr(r, 40)},{arch},"
          f"{mp.nstr(v, 40)},{mp.nstr(e, 3)}")


def main():
    print("# repulsive inverse-square brachistochrones, mpmath dps=80, "
          "scripts/make_repulsive_reference.py")
    print("case,parameter,quantity,r,arch,value,error")
    one = mp.mpf(1)
    # unbounded curves, parameter K^2
    for case, k2, radii in (("unbounded", mp.mpf(2), [1.25, 2, 5]),
                            ("unbounded", mp.mpf(1) / 2, [10]),
                            ("near_critical", mp.mpf(27) / 8 - mp.mpf(2)**-10,
                             [1.4375, 1.5625, 3])):
        for r in radii:
            r = mp.mpf(r)
            br = [mp.mpf(1.25), mp.mpf(1.5), mp.mpf(1.5) - mp.mpf(2)**-8,
                  mp.mpf(1.5) + mp.mpf(2)**-8, mp.mpf(2), mp.mpf(4)]
            for name, (v, e) in zip(("theta", "s", "t"), integrals(k2, r, br)):
                row(case, k2, name, r, "first", v, e)
        k = mp.sqrt(k2)
        fa = lambda x: k * mp.sqrt(2) * mp.sqrt(x - 1) / (x * mp.sqrt(x**3 - 2 * k2 * (x - 1)))
        v, e = integrals(k2, mp.mpf(1.25), [])[0]
        v2, e2 = mp.quad(fa, [1.25, 1.5 - mp.mpf(2)**-8, 1.5, 1.5 + mp.mpf(2)**-8, 2, 4,
                              mp.inf], error=True, maxdegree=12)
        v, e = v + v2, e + e2
        row(case, k2, "theta", mp.inf, "first", v, e)
    # bounded curves, parameter R
    for case, big_r, radii in (("bounded", mp.mpf(5) / 4, [1.125]),
                               ("near_critical_bounded", mp.mpf(1.5) - mp.mpf(2)**-20,
                                [1.25])):
        k2 = big_r**3 / (2 * (big_r - 1))
        br = [one + (big_r - 1) / 2, big_r - mp.mpf(10)**-2, big_r - mp.mpf(10)**-4,
              big_r - mp.mpf(10)**-6, big_r - mp.mpf(10)**-8]
        apse = integrals(k2, big_r, br, big_r)
        for name, (v, e) in zip(("theta", "s", "t"), apse):
            row(case, big_r, name, big_r, "apse", v, e)
        for r in radii:
            r = mp.mpf(r)
            first = integrals(k2, r, br, big_r)
            for name, (v, e), (va, ea) in zip(("theta", "s", "t"), first, apse):
                row(case, big_r, name, r, "first", v, e)
                row(case, big_r, name, r, "second", 2 * va - v, 2 * ea + e)


def two_point():
    """The two-point problem solved independently: mp.findroot (secant) on the angle at
    rho, in K^2 (unbounded) or R (bounded), from starting values good to ~6 digits;
    rows give the parameter found and t. (Slow: several minutes.)"""
    br = [mp.mpf(1.25), mp.mpf(1.5) - mp.mpf(2)**-8, mp.mpf(1.5) - mp.mpf(2)**-12,
          mp.mpf(1.5), mp.mpf(1.5) + mp.mpf(2)**-12, mp.mpf(1.5) + mp.mpf(2)**-8,
          mp.mpf(2), mp.mpf(4)]
    for rho, psi, m, guess in ((2, 1, 0, ("2.64508", "2.64510")),
                               (2, 1, 1, ("3.3749884", "3.3749886"))):
        rho, target = mp.mpf(rho), mp.mpf(str(psi)) + 2 * mp.pi * m
        k2 = mp.findroot(lambda k2: integrals(k2, rho, br)[0][0] - target,
                         (mp.mpf(guess[0]), mp.mpf(guess[1])), solver="illinois",
                         verify=False, tol=mp.mpf(10)**-75)
        v = integrals(k2, rho, br)
        print(f"two_point_unbounded,{mp.nstr(k2, 40)},t,{rho},m={m} psi={psi},"
              f"{mp.nstr(v[2][0], 40)},{mp.nstr(v[0][0] - target, 3)}")
    for rho, psi, second, guess in ((1.25, 0.4, False, ("1.26097", "1.26099")),
                                    (1.25, 1, True, ("1.30172", "1.30174")),
                                    (1, 1, True, ("1.24769", "1.24771"))):
        rho, target = mp.mpf(rho), mp.mpf(str(psi))

        def angle(big_r, which=0):
            k2 = big_r**3 / (2 * (big_r - 1))
            brk = [1 + (big_r - 1) / 2, big_r - mp.mpf(10)**-2, big_r - mp.mpf(10)**-4]
            first = integrals(k2, rho, brk, big_r) if rho > 1 else [(0, 0)] * 3
            if not second:
                return first[which][0]
            apse = integrals(k2, big_r, brk, big_r)
            return 2 * apse[which][0] - first[which][0]

        big_r = mp.findroot(lambda x: angle(x) - target, (mp.mpf(guess[0]), mp.mpf(guess[1])),
                            solver="illinois", verify=False, tol=mp.mpf(10)**-75)
        print(f"two_point_{'second' if second else 'first'},{mp.nstr(big_r, 40)},t,{rho},"
              f"psi={psi},{mp.nstr(angle(big_r, 2), 40)},"
              f"{mp.nstr(angle(big_r) - target, 3)}")


if __name__ == "__main__":
    main()
    two_point()
