#!/usr/bin/env python3
"""Independent references for the repulsive field with B next to the apse of its curve:
psi within 1e-8 .. 1e-30 (relative) of the apse's angle Theta(rho, rho), both half-arches,
below what a hardware-precision root finder resolves (R - rho down to 1e-80).

Command (from the repository root; about 140 s of CPU time):
    .venv/bin/python scripts/make_repulsive_near_apse_reference.py \
        > data/reference/repulsive_near_apse_mpmath.csv

The machinery is scripts/make_repulsive_two_point_reference.py's (its docstring: mpmath
on Tee's ORIGINAL integrals (23), (31), (37), the curve's unknown y = sqrt(R - rho), psi
the binary128 number theta(rho) of the target curve rounded, solved again for y at two
precisions, a row kept only when R, R - 1, s, t agree to >= 40 digits). The rows here:
rho = 1 + 1e-20, 1 + 1e-3, 5/4, 1.45 (binary128 numbers; bounded curves, hence an apse
angle, exist only for 1 < rho < 3/2), u = off Theta(rho, rho)/(2 A) with the square-root
law's A = sqrt((rho - 1)/(rho (3 - 2 rho))) (psi/Theta(rho, rho) - 1 = -+off to first
order), off = 1e-8, 1e-17, 1e-25, 1e-30, first and second half-arch; the precisions
max(60, 50 + 2 log10(1/u) - log10(1/(rho - 1))) digits and 20 more, so that R - rho = u^2 is
carried with 40 digits or more beside R - 1.
"""
import io
import sys
from contextlib import redirect_stdout

import mpmath as mp

sys.path.insert(0, "scripts")
import make_repulsive_two_point_reference as m  # noqa: E402


def cases():
    mp.mp.dps = 80
    b = m.binary128
    one = mp.mpf(1)
    rows = []
    for rho in [one + mp.mpf("1e-20"), one + mp.mpf("1e-3"), mp.mpf(5) / 4, mp.mpf("1.45")]:
        rho = b(rho)
        theta = m.first_arch(m.Curve("apse_at_rho", None, rho), rho - 1, ["theta"])[0]
        a = mp.sqrt((rho - 1) / (rho * (3 - 2 * rho)))
        for off in ["1e-8", "1e-17", "1e-25", "1e-30"]:
            u = b(mp.mpf(off) * theta / (2 * a))
            low = int(max(60, 50 - 2 * mp.log10(u) + mp.log10(rho - 1)))
            for arch in ["first", "second"]:
                rows.append(("near_apse_" + arch, rho, arch, "apse", ("target", u),
                             (low, low + 20)))
    return rows


def main():
    m.cases = cases
    sys.argv = sys.argv[:1]
    out = io.StringIO()
    with redirect_stdout(out):
        m.main()
    for line in out.getvalue().splitlines():
        if line.startswith("# repulsive two-point references"):
            line = ("# repulsive references next to the apse: "
                    "scripts/make_repulsive_near_apse_reference.py (see its docstring)")
        elif line.startswith("# mpmath"):
            line = line.replace("(50/70 or 70/90)", "(66/86 .. 110/130, per row)")
        elif line.startswith("# quadrature nodes"):
            line = line.replace("50-90", "66-130")
        print(line)


if __name__ == "__main__":
    main()
