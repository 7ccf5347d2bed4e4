#!/usr/bin/env python3
"""Benchmark: the quad-precision solver against SciPy and mpmath, in one run.

Usage::

    .venv/bin/python scripts/bench.py [--n 10000] [--repeats 5] [--scipy 200]
                                      [--mpmath 3] [--seed 2026] [--output-n 30000]
                                      [--output-runs 3] [--only-output] [--million]

1. Generates N random accessible endpoints (rho uniform in [0.01, 1], psi uniform in
   (0, 2 pi/3)) into bench-out/bench.nml.
2. Times the Fortran default solver on all of them with `brachistochrone-bench`
   (fpm example `example/bench`; release build, one thread and two, median of REPEATS
   passes over the table).
3. Times SciPy in double precision (QUADPACK on the paper's transformed integrals
   (65), (77), (81), brentq on the bracket (0, rho]) on the first K endpoints, at
   epsrel 1e-13 and at 2e-14 (the setting of issue 12), the mean per endpoint over
   the K (the Fortran figure is a mean over the batch), and mpmath at 34 digits
   (mp.quad on the same integrals, findroot with a bracket) on the first M.
4. Prints time per endpoint, endpoints per second and the ratios, plus the digits
   to which SciPy and mpmath agree with the Fortran results on their samples, the
   solver's floor (one full-precision evaluation per endpoint) and the time to format
   a value (`format_quad` against formatted `write`), from the same bench run.
The machine is shared: compare ratios measured in the same run, not absolute times.
"""
import argparse
import math
import pathlib
import random
import statistics
import subprocess
import sys
import time

import mpmath as mp
from scipy.optimize import brentq

ROOT = pathlib.Path(__file__).resolve().parents[1]
FPM = str(ROOT / ".venv" / "bin" / "fpm")


def endpoints(n, seed):
    rng = random.Random(seed)
    return [(f"{rng.uniform(0.01, 1.0):.17g}", f"{rng.uniform(1e-9, 2 * math.pi / 3 - 1e-9):.17g}")
            for _ in range(n)]


def write_nml(path, rows):
    path.write_text("&endpoints\n n = %d\n rho = %s\n psi = %s\n/\n" % (
        len(rows), ",\n  ".join(r for r, _ in rows), ",\n  ".join(p for _, p in rows)))


def fpm_exe(name, example=False):
    kind = ["--example"] if example else []
    out = subprocess.run([FPM, "run", "--profile", "release", *kind, "--runner", "echo", name],
                         cwd=ROOT, check=True, capture_output=True, text=True).stdout
    return str(ROOT / out.strip().splitlines()[-1])


# The alternatives are written as a careful Python user would: the paper's smooth
# transformed integrals (65), (77), (81) with the limits as atan2 of square roots,
# adaptive quadrature, and a bracketed root finder on (0, rho].
def paper_integrals(lib, quad, r, big_r):
    """Theta(r,R) (65), S(r,R) (77), T(r,R) (81) with math/mpmath `lib` and `quad`."""
    omr = 1 - big_r
    lower = lib.atan2(lib.sqrt(r - big_r), lib.sqrt(big_r * (1 - r)))
    zeta = 2 * lib.atan2(lib.sqrt(1 - r), lib.sqrt(r - big_r))

    def f_theta(lam):
        z = lib.cos(lam) ** 2 + big_r * lib.sin(lam) ** 2
        return 2 * (z - big_r) / lib.sqrt(z * z + omr * z + omr)

    def f_s(y):
        x = y * y + big_r
        return 2 * x / lib.sqrt(x + big_r + big_r ** 2 / (omr * x))

    def f_t(angle):
        x = (1 + big_r + omr * lib.cos(angle)) / 2
        return x * x / lib.sqrt(2 * (x * x + big_r * x + big_r ** 2 / omr))

    return (quad(f_theta, lower, lib.pi / 2), quad(f_s, lib.sqrt(r - big_r), lib.sqrt(omr)),
            quad(f_t, 0, zeta))


def solve_with(lib, quad, root, rho, psi):
    second = rho == 1 or psi > paper_integrals(lib, quad, rho, rho)[0]

    def f(big_r):
        value = paper_integrals(lib, quad, rho, big_r)[0]
        if second:
            value = 2 * paper_integrals(lib, quad, big_r, big_r)[0] - value
        return value - psi

    big_r = root(f, rho)
    _, s, t = paper_integrals(lib, quad, rho, big_r)
    if second:
        _, s_apse, t_apse = paper_integrals(lib, quad, big_r, big_r)
        s, t = 2 * s_apse - s, 2 * t_apse - t
    return big_r, s, t


def scipy_solver(epsrel):
    """Double precision: QUADPACK (relative tolerance epsrel) and brentq. (At 2e-14
    QUADPACK warns that roundoff limits the accuracy on some integrals: the warning is
    silenced, the digits column says what the results reach.)"""
    import warnings
    from scipy.integrate import IntegrationWarning, quad
    warnings.filterwarnings("ignore", category=IntegrationWarning)
    quadpack = lambda f, a, b: quad(f, a, b, epsabs=0, epsrel=epsrel, limit=200)[0]
    root = lambda f, rho: brentq(f, 1e-12 * rho, rho, xtol=1e-17, rtol=1e-15)
    return lambda rho_s, psi_s: solve_with(math, quadpack, root, float(rho_s), float(psi_s))


def mp_solve(rho_s, psi_s):
    """34 digits: mp.quad (tanh-sinh) and findroot (Anderson-Bjorck on the bracket)."""
    root = lambda f, rho: mp.findroot(f, (rho * mp.mpf("1e-12"), rho), solver="anderson",
                                      tol=mp.mpf(10) ** (-2 * mp.mp.dps + 4))
    return solve_with(mp, lambda f, a, b: mp.quad(f, [a, b]), root, mp.mpf(rho_s),
                      mp.mpf(psi_s))


def timed(function, rows, mean=False):
    """Median (or mean) seconds per endpoint over rows, and the results."""
    times, results = [], []
    for rho_s, psi_s in rows:
        start = time.perf_counter()
        results.append(function(rho_s, psi_s))
        times.append(time.perf_counter() - start)
    return (statistics.fmean(times) if mean else statistics.median(times)), results


def fortran_results(rows, out_dir):
    nml = out_dir / "sample.nml"
    write_nml(nml, rows)
    csv = out_dir / "sample.csv"
    subprocess.run([fpm_exe("brachistochrone"), str(nml), "--csv", str(csv), "--force"],
                   check=True, capture_output=True)
    lines = [l for l in csv.read_text().splitlines() if not l.startswith("#")][1:]
    return [tuple(mp.mpf(x) for x in l.split(",")[3:6]) for l in lines]


def agreement(reference, other):
    worst = 99.0
    for ref, oth in zip(reference, other):
        for a, b in zip(ref, oth):
            diff = abs(mp.mpf(b) / a - 1)
            worst = min(worst, 99.0 if diff == 0 else float(-mp.log10(diff)))
    return worst


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=10000, help="endpoints in the batch")
    parser.add_argument("--repeats", type=int, default=5, help="passes of the Fortran timing")
    parser.add_argument("--scipy", type=int, default=200,
                        help="endpoints timed with SciPy (the mean is taken)")
    parser.add_argument("--mpmath", type=int, default=3, help="endpoints timed with mpmath")
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--output-n", type=int, default=30000,
                        help="endpoints of the output-cost runs of the batch program")
    parser.add_argument("--output-runs", type=int, default=3,
                        help="runs of each kind in the output ratio (the median is taken)")
    parser.add_argument("--only-output", action="store_true",
                        help="only the output ratio (and --million if given)")
    parser.add_argument("--million", action="store_true",
                        help="also 1,000,000 endpoints end to end (--csv, 2 threads) and "
                             "--check of them (about 30 s)")
    args = parser.parse_args(argv)

    out_dir = ROOT / "bench-out"
    out_dir.mkdir(exist_ok=True)
    if args.only_output:
        subprocess.run([FPM, "build", "--profile", "release"], cwd=ROOT, check=True,
                       capture_output=True)
        output_cost(out_dir, args)
        if args.million:
            million(out_dir)
        return 0
    rows = endpoints(args.n, args.seed)
    write_nml(out_dir / "bench.nml", rows)
    subprocess.run([FPM, "build", "--profile", "release"], cwd=ROOT, check=True,
                   capture_output=True)
    def fortran(threads):
        bench = subprocess.run([fpm_exe("brachistochrone-bench", example=True),
                                str(out_dir / "bench.nml"),
                                str(args.repeats), str(threads)], check=True,
                               capture_output=True, text=True)
        return dict(line.split(" = ") for line in bench.stdout.splitlines())

    report = fortran(1)
    fortran_us = float(report["median_us_per_endpoint"])
    report_2 = fortran(2)
    fortran_2_us = float(report_2["median_us_per_endpoint"])

    scipy_tolerances = ("1e-13", "2e-14")
    scipy_runs = [timed(scipy_solver(float(epsrel)), rows[:args.scipy], mean=True)
                  for epsrel in scipy_tolerances]
    mp.mp.dps = 34
    mp_s, mp_results = timed(mp_solve, rows[:args.mpmath])
    sample = fortran_results(rows[:max(args.scipy, args.mpmath)], out_dir)

    print(f"batch: {args.n} random accessible endpoints (seed {args.seed}), "
          f"{report['failed']} failed; {report['mean_upsilon_evaluations']} "
          f"Upsilon evaluations per endpoint")
    print(f"{'method':34} {'us/endpoint':>12} {'endpoints/s':>12} {'ratio':>8} {'digits':>7}")
    rows_out = [
        ("Fortran real(16), this program", fortran_us, 1.0, "32+"),
        ("  the same on 2 threads", fortran_2_us, fortran_2_us / fortran_us, "32+"),
        *((f"SciPy double {epsrel} (mean of {args.scipy})", scipy_s * 1e6,
           scipy_s * 1e6 / fortran_us, f"{agreement(sample, scipy_results):.1f}")
          for epsrel, (scipy_s, scipy_results) in zip(scipy_tolerances, scipy_runs)),
        (f"mpmath 34 digits (median of {args.mpmath})", mp_s * 1e6, mp_s * 1e6 / fortran_us,
         f"{agreement(sample, mp_results):.1f}"),
    ]
    for name, us, ratio, digits in rows_out:
        print(f"{name:34} {us:12.1f} {1e6 / us:12.1f} {ratio:8.1f} {digits:>7}")
    print("ratio = time per endpoint / Fortran's on one thread; digits = fewest significant "
          "digits of R, s, t agreeing with the Fortran results on that sample")
    print(f"2-thread throughput: {fortran_us / fortran_2_us:.2f} x one thread")
    floor_us, cpu_us = (float(report[k]) for k in ("floor_us_per_endpoint",
                                                   "median_cpu_us_per_endpoint"))
    print(f"CPU time: solver {cpu_us:.1f} us per endpoint, floor (its one full-precision "
          f"evaluation with s, t) {floor_us:.1f} us; solver / floor = {cpu_us / floor_us:.2f}")
    fast_ns, write_ns = (float(report[k]) for k in ("format_ns_per_value",
                                                     "format_write_ns_per_value"))
    print(f"formatting a value to 36 digits: {fast_ns:.0f} ns (formatted write "
          f"{write_ns:.0f} ns, {write_ns / fast_ns:.1f} x slower)")
    output_cost(out_dir, args)
    if args.million:
        million(out_dir)
    return 0


def run_program(arguments, threads):
    """Wall time and peak memory (kB) of one run of the batch program (the program's
    path is looked up before the clock starts: `fpm run --runner echo` takes ~0.1 s)."""
    command = ["/usr/bin/time", "-f", "%M", fpm_exe("brachistochrone"), *map(str, arguments),
               "--no-table", "--quiet", "--force", "--threads", str(threads)]
    start = time.perf_counter()
    result = subprocess.run(command, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if result.returncode not in (0, 2):
        raise RuntimeError(result.stderr)
    return seconds, int(result.stderr.strip().splitlines()[-1])


def output_cost(out_dir, args):
    """The batch program end to end: 1 thread solving without output against 2 threads
    writing --csv and --nml (median of --output-runs runs each, taken in turn, same run
    of the script)."""
    table = out_dir / "output.nml"
    write_nml(table, endpoints(args.output_n, args.seed + 1))
    alone_runs, both_runs = [], []
    for _ in range(args.output_runs):
        alone_runs.append(run_program([table], 1)[0])
        both_runs.append(run_program([table, "--csv", out_dir / "o.csv", "--nml",
                                      out_dir / "o.nml"], 2)[0])
    alone, both = statistics.median(alone_runs), statistics.median(both_runs)
    print(f"output: {args.output_n} endpoints, 1 thread solving only {alone:.2f} s, "
          f"2 threads writing --csv and --nml {both:.2f} s; ratio {alone / both:.2f}")


def million(out_dir):
    """1,000,000 endpoints: read, check, solve and write the CSV on 2 threads; --check."""
    table = out_dir / "million.nml"
    write_nml(table, endpoints(1000000, 7))
    seconds, kilobytes = run_program([table, "--csv", out_dir / "million.csv"], 2)
    print(f"1,000,000 endpoints end to end (--csv, 2 threads): {seconds:.1f} s, "
          f"{kilobytes / 1e3:.0f} MB peak ({kilobytes * 1024 / 1e6:.0f} bytes per endpoint)")
    check = statistics.median(run_program([table, "--check"], 1)[0] for _ in range(3))
    print(f"--check of 1,000,000 endpoints: {check:.2f} s")


if __name__ == "__main__":
    sys.exit(main())
