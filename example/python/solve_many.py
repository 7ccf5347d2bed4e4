#!/usr/bin/env python3
"""Call brachistochrone_solve_many from the shared library through ctypes on NumPy arrays.

    python example/python/solve_many.py PREFIX/lib/libbrachistochrone.so

Solves Tee's Table 1 (the rho of rows 1-2 corrected, docs/ERRATA.md) plus a radial and
an inaccessible endpoint in one call, and checks them against the published digits and
the closed forms (46), (75). Prints the results and "python: ok", or exits 1.
"""
import ctypes
import math
import sys

import numpy as np


def load(path):
    lib = ctypes.CDLL(path)
    doubles = np.ctypeslib.ndpointer(dtype=np.float64, ndim=1, flags="C_CONTIGUOUS")
    ints = np.ctypeslib.ndpointer(dtype=np.intc, ndim=1, flags="C_CONTIGUOUS")
    lib.brachistochrone_solve_many.argtypes = [ctypes.c_char_p, ctypes.c_double,
                                               ctypes.c_long, doubles, doubles, doubles,
                                               doubles, doubles, ints]
    lib.brachistochrone_solve_many.restype = ctypes.c_int
    lib.brachistochrone_status_message.argtypes = [ctypes.c_int]
    lib.brachistochrone_status_message.restype = ctypes.c_char_p
    return lib


def solve_many(lib, force, rho, psi, exponent=0.0):
    """R-bar, s, t (NaN where they do not exist), status and the number of failures."""
    rho = np.ascontiguousarray(rho, dtype=np.float64)
    psi = np.ascontiguousarray(psi, dtype=np.float64)
    n = rho.size
    big_r, s, t = np.empty(n), np.empty(n), np.empty(n)
    status = np.empty(n, dtype=np.intc)
    failures = lib.brachistochrone_solve_many(force.encode(), exponent, n, rho, psi,
                                              big_r, s, t, status)
    return big_r, s, t, status, failures


def radial_time(r):
    """Tee (46): time of the radial fall from rest at 1 to r."""
    return (math.acos(2 * r - 1) / 2 + math.sqrt(r * (1 - r))) / math.sqrt(2)


def main(path):
    lib = load(path)
    rho = np.array([0.2, 0.5, 0.7, 0.9, 1.0, 0.3, 0.5])
    psi = np.array([1.2, 0.1, 1.8, 0.4, 2.0, 0.0, 2.5])
    big_r, s, t, status, failures = solve_many(lib, "inverse_square", rho, psi)
    for row in zip(rho, psi, big_r, s, t, status):
        print("rho %.1f psi %.1f  R-bar %.15f  s %.15f  t %.15f  status %d" % row)
    published = np.array([  # Tee (1998), Table 1: R-bar, s, t
        [0.184781963328079, 0.967544327890300, 1.127755808164997],
        [0.252787093630160, 0.505594850833648, 0.914164272619962],
        [0.168913316595188, 1.531621194881120, 1.481218910277573],
        [0.838545794202334, 0.442680075643429, 1.058599268341289],
        [0.057854464393370, 1.947547388961997, 2.221060707125763]])
    ok = np.allclose(np.column_stack([big_r, s, t])[:5], published, rtol=0, atol=2e-15)
    # radial fall: no R-bar, s = 1 - rho, t = (46); inaccessible: status 1, t = kappa (75)
    ok &= math.isnan(big_r[5]) and abs(s[5] - 0.7) < 1e-15
    ok &= abs(t[5] - radial_time(0.3)) < 1e-15
    ok &= status[6] == 1 and math.isnan(big_r[6]) and math.isnan(s[6])
    ok &= abs(t[6] - (2 * radial_time(0.0) - radial_time(0.5))) < 1e-15
    ok &= failures == 1 and list(status[:6]) == [0] * 6
    print("status 1:", lib.brachistochrone_status_message(1).decode())
    # an unknown force is a status for every row, not a crash
    _, _, t_bad, status_bad, failures_bad = solve_many(lib, "gravity", rho[:2], psi[:2])
    ok &= failures_bad == 2 and status_bad[0] != 0 and bool(np.isnan(t_bad).all())
    print("python: ok" if ok else "python: FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
