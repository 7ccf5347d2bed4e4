"""Seeded random mutations of the shipped example namelists fed to the program: every
outcome must be a clean verdict (exit 0, 1 or 2), never a crash or runtime error, no
file left behind on exit 1, no NaN in any output."""
import concurrent.futures
import os
import pathlib
import random
import re
import subprocess
import tempfile

from conftest import ROOT

CASES = int(os.environ.get("FUZZ_CASES", "2000"))  # mutated files given to --check
REAL_RUNS = 60        # of them, also run for real with --csv
SEED = int(os.environ.get("FUZZ_SEED", "20261130"))

# The shipped example files and the valid examples the tests use.
EXAMPLES = [p.read_text() for p in sorted((ROOT / "data").glob("*.nml"))] + [
    "&endpoints n = 3, rho = 3*0.5, psi = 2*0.1, 0.2,\n r0 = , 0.4, , r1 = , 0.2, /\n",
    "! a comment\n&endpoints n = 3, rho = 0.2, 0.5, 0.9,\n"
    " psi = 1.2, 0.1, 0.4  r0 = 0.2, , 0.8  r1 = 0.1, , 0.7 /\n",
    "&endpoints\n n = 4\n rho = 0.5,\n       0.6,\n       0.7,\n       0.9\n"
    " psi = 4*0.1\n curve_points = 5 /\n",
    "&endpoints n = 2, rho = 0.5, 0.9, psi = 1.0, 0.4, force = 'harmonic' /",
    "&endpoints n = 2, rho = 0.5, 0.9, psi = 1.0, 0.4, force = 'power', exponent = 3 /\n",
    "&other s = '&endpoints n = 9 /' /\n$endpoints N = 2, RHO = 0.5, 0.9, PSI(1:2) = 1, 2"
    " $end\n",
    "&endpoints n = 2, rho = 1.5, 2, psi = 0.5, 1, force = \"repulsive\" /\n",
]

TOKENS = [",", ",,", "/", "&", "&endpoints", "$end", "!", "! c\n", "'", '"', "*", "3*",
          "=", "(", ")", "(2)", "(1:2)", "\n", " ", "1e99999", "-1e-99999", "NaN", "-Inf",
          "99999999999999999999", "2147483648*1", "n = 10000000", "0*", "\t", "\r\n",
          "\x00", "\x1b[2J", "\xff", "rho(0) = 1", "psi = ", "0.5", "x"]

RUNTIME_ERROR = re.compile(r"Fortran runtime error|Backtrace|Segmentation|"
                           r"Operating system error|Program received signal", re.I)


def mutate(text, rng):
    data = bytearray(text.encode("latin-1"))
    for _ in range(rng.randint(1, 4)):
        kind = rng.randrange(7)
        at = rng.randrange(len(data) + 1)
        if kind == 0 and data:                       # flip a byte
            at = min(at, len(data) - 1)
            data[at] ^= 1 << rng.randrange(8)
        elif kind == 1:                              # insert a token
            data[at:at] = rng.choice(TOKENS).encode("latin-1")
        elif kind == 2 and data:                     # delete a run
            del data[at:at + rng.randint(1, 8)]
        elif kind == 3:                              # truncate
            del data[at:]
        elif kind == 4:                              # duplicate a line
            lines = bytes(data).split(b"\n")
            k = rng.randrange(len(lines))
            lines.insert(k, lines[k])
            data = bytearray(b"\n".join(lines))
        elif kind == 5 and data:                     # replace a digit
            digits = [i for i, c in enumerate(data) if 48 <= c <= 57]
            if digits:
                data[rng.choice(digits)] = ord(rng.choice("0123456789"))
        else:                                        # swap two lines
            lines = bytes(data).split(b"\n")
            i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
            lines[i], lines[j] = lines[j], lines[i]
            data = bytearray(b"\n".join(lines))
    return bytes(data)


def run_case(app, index, data, real):
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        nml = tmp / "in.nml"
        nml.write_bytes(data)
        args = [str(app), "--check", "in.nml"]
        if real:
            args = [str(app), "in.nml", "--csv", "out.csv", "--no-table", "--quiet"]
        result = subprocess.run(args, cwd=tmp, capture_output=True, timeout=120)
        out = result.stdout.decode("latin-1")
        err = result.stderr.decode("latin-1")
        problems = []
        if result.returncode not in (0, 1, 2):
            problems.append(f"exit code {result.returncode}")
        if RUNTIME_ERROR.search(out + err):
            problems.append("runtime error text")
        left = sorted(p.name for p in tmp.iterdir())
        if result.returncode == 1 and left != ["in.nml"]:
            problems.append(f"files left on exit 1: {left}")
        if re.search(r"(?i)\bnan\b", out):
            problems.append("NaN on stdout")
        if real and result.returncode in (0, 2):
            csv = tmp / "out.csv"
            if not csv.exists():
                problems.append("no CSV after exit 0/2")
            elif re.search(r"(?i)\bnan\b", csv.read_text(errors="replace")):
                problems.append("NaN in the CSV")
        if "\x1b" in err or "\x00" in err:
            problems.append("control character in a message")
        return index, result.returncode, problems, data


def test_fuzz_mutations_of_the_examples(app):
    rng = random.Random(SEED)
    cases = [mutate(rng.choice(EXAMPLES), rng) for _ in range(CASES)]
    real = set(rng.sample(range(CASES), REAL_RUNS))
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        outcomes = list(pool.map(lambda k: run_case(app, k, cases[k], k in real),
                                 range(CASES)))
    failures = [(k, code, problems, data) for k, code, problems, data in outcomes if problems]
    codes = [code for _, code, _, _ in outcomes]
    print(f"{CASES} cases ({REAL_RUNS} real runs): exit 0: {codes.count(0)}, "
          f"1: {codes.count(1)}, 2: {codes.count(2)}, failures: {len(failures)}")
    assert not failures, "\n".join(f"case {k} exit {code}: {problems}: {data!r}"
                                   for k, code, problems, data in failures[:10])
    assert codes.count(0) > CASES // 20 and codes.count(1) > CASES // 4   # both kinds met
