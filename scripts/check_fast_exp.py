#!/usr/bin/env python3
"""Worst errors in ulps of fast_exp/fast_expm1 (new, old) and libquadmath against mpmath.

    .venv/bin/python scripts/check_fast_exp.py FAST_EXP_BENCH [COUNT [SEED]]

(scripts/bench_fast_exp.sh builds FAST_EXP_BENCH and runs this.) Arguments: COUNT binary128
numbers, |x| log-uniform over 1e-30 .. 11000, both signs; every seventh next to a switch of
the reduction (j/256, j/65536, m + 1/2, 1/2, 1, 127.5, 128, 2^-16, 2^-8, multiples of log 2
/ 2) within 20 ulps. The references: mpmath's exp and expm1 at 60 digits; the error of a
result y is |y - ref| / ulp(ref) (ulp: the spacing of binary128 at |ref|).
"""
import random
import subprocess
import sys
import tempfile

import mpmath as mp

mp.mp.dps = 60


def from_bits(text):
    """The binary128 value of 32 hex digits, as an mpf (exact)."""
    bits = int(text, 16)
    sign = -1 if bits >> 127 else 1
    biased = (bits >> 112) & 0x7FFF
    fraction = bits & ((1 << 112) - 1)
    if biased == 0x7FFF:
        return None
    if biased == 0:
        return sign * mp.ldexp(fraction, -16382 - 112)
    return sign * mp.ldexp(fraction | (1 << 112), biased - 16383 - 112)


def ulp(v):
    """Spacing of binary128 at |v| (normal range)."""
    if v == 0:
        return mp.ldexp(1, -16494)
    _, e = mp.frexp(v)  # |v| = m 2^e, 1/2 <= m < 1
    return mp.ldexp(1, max(e - 113, -16494))


def to_quad_text(v):
    """v rounded to 113 bits, as an exact decimal string (gfortran reads it exactly)."""
    m, e = mp.frexp(v)
    q = mp.ldexp(mp.nint(mp.ldexp(m, 113)), e - 113)
    return mp.nstr(q, 45, strip_zeros=False)


def arguments(count, seed):
    rng = random.Random(seed)
    switches = [0.5, 1.0, 127.5, 128.0, 2.0 ** -16, 2.0 ** -8]
    out = []
    for i in range(count):
        if i % 7 == 0:
            kind = rng.randrange(4)
            if kind == 0:
                base = mp.mpf(rng.randrange(1, 256 * 128)) / 256
            elif kind == 1:
                base = mp.mpf(rng.randrange(1, 256)) / 65536
            elif kind == 2:
                base = mp.mpf(rng.choice(switches))
            else:
                base = rng.randrange(1, 31000) * mp.log(2) / 2
            x = base + rng.randrange(-20, 21) * ulp(base)
        else:
            x = mp.mpf(10) ** rng.uniform(-30, mp.log10(11000))
        if rng.random() < 0.5:
            x = -x
        out.append(to_quad_text(x))
    return out


def main(program, count, seed):
    args = arguments(count, seed)
    with tempfile.NamedTemporaryFile("w", suffix=".txt") as handle:
        handle.write("\n".join(args) + "\n")
        handle.flush()
        lines = subprocess.run([program, "values", handle.name], check=True,
                               stdout=subprocess.PIPE, text=True).stdout.split("\n")
    names = ["new exp", "old exp", "libquadmath exp", "new expm1", "old expm1",
             "libquadmath expm1"]
    worst = [(mp.mpf(0), None)] * 6
    for line in lines:
        fields = line.split()
        if len(fields) != 7:
            continue
        x = from_bits(fields[0])
        references = [mp.exp(x)] * 3 + [mp.expm1(x)] * 3
        for k in range(6):
            y = from_bits(fields[k + 1])
            if y is None:
                continue
            error = abs(y - references[k]) / ulp(references[k])
            if error > worst[k][0]:
                worst[k] = (error, x)
    print(f"worst errors in ulps against mpmath, {len(lines) - 1} arguments "
          f"(|x| 1e-30 .. 11000, both signs):")
    for name, (error, x) in zip(names, worst):
        print(f"  {name:18s} {float(error):6.3f} ulp  at x = {mp.nstr(x, 25) if x else '-'}")


if __name__ == "__main__":
    main(sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 100000,
         int(sys.argv[3]) if len(sys.argv) > 3 else 2026)
