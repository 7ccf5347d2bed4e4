#!/usr/bin/env python3
"""Adversarial fuzz of the binary128 primitives against independent values.

    python3 scripts/fuzz_primitives.py HARNESS CHECK [SEED [COUNT]]

CHECK is one of
  conversions  hardware_real, quad_real, double_real bit for bit against gfortran's
               real(x, kind) and against exact rounding (Python integers): ties and
               carries (to the next binade, to infinity), both ends of each range,
               subnormals, zeros, infinities, NaN payloads, unnormal and pseudo-denormal
               x87 encodings (the last: real(y, qp) and quad_real give libgcc's value,
               not the hardware's: reported, not counted as errors);
  roots        fast_sqrt, inverse_sqrt in ulps against mpmath (300 bits): every binade's
               edges, perfect squares and neighbours, next to 4^k, hardware roots near a
               binade edge, random; specials against the intrinsic;
  exp          fast_exp, fast_expm1 against mpmath: every switch of the reduction, the
               overflow and underflow thresholds (subnormal results: exact bits), next to
               k log 2 + {0, 1/2}, table boundaries J/65536, random;
  exp-edges    the same at every binade edge 2^-120 .. 2^14 and at J/65536, J/256, m.
HARNESS is the program scripts/fuzz_primitives.sh builds (it reads "tag hex" lines).
Prints the counts, the worst errors and every failure (roots: above 0.51 ulp for
fast_sqrt, 1 for inverse_sqrt; exp: above 0.75 ulp).
"""
import random
import subprocess
import sys
from fractions import Fraction

import mpmath


Q = dict(p=113, emin=-16382, emax=16383, ebits=15)
D = dict(p=53, emin=-1022, emax=1023, ebits=11)

def q_decode(b):
    s = b >> 127; e = (b >> 112) & 0x7FFF; f = b & ((1 << 112) - 1)
    if e == 0x7FFF:
        return ('nan', s, f) if f else ('inf', s)
    if e == 0:
        return ('num', s, Fraction(f) * Fraction(2) ** (1 - 16383 - 112))
    return ('num', s, Fraction((1 << 112) + f) * Fraction(2) ** (e - 16383 - 112))

def x_decode(se, m):
    s = se >> 15; e = se & 0x7FFF
    if e == 0x7FFF:
        if m >> 63 == 0: return ('invalid', s)
        return ('nan', s, m & ((1 << 63) - 1)) if (m << 1) & ((1 << 64) - 1) else ('inf', s)
    if e == 0:
        return ('num', s, Fraction(m) * Fraction(2) ** (1 - 16383 - 63))  # (pseudo)denormal
    if m >> 63 == 0: return ('invalid', s)   # unnormal
    return ('num', s, Fraction(m) * Fraction(2) ** (e - 16383 - 63))

def d_decode(b):
    s = b >> 63; e = (b >> 52) & 0x7FF; f = b & ((1 << 52) - 1)
    if e == 0x7FF:
        return ('nan', s, f) if f else ('inf', s)
    if e == 0:
        return ('num', s, Fraction(f) * Fraction(2) ** (1 - 1023 - 52))
    return ('num', s, Fraction((1 << 52) + f) * Fraction(2) ** (e - 1023 - 52))

def round_to(v, p, emin, emax):
    """|v| (Fraction > 0) rounded to nearest even: (M, q) with value M 2^q, or None=inf."""
    v = abs(v)
    e = v.numerator.bit_length() - v.denominator.bit_length()
    if Fraction(2) ** e > v: e -= 1
    if Fraction(2) ** (e + 1) <= v: e += 1
    e = max(e, emin)
    q = e - (p - 1)
    t = v / Fraction(2) ** q
    M = t.numerator // t.denominator
    rem = t - M
    if rem > Fraction(1, 2) or (rem == Fraction(1, 2) and M % 2 == 1): M += 1
    if M == 1 << p: M >>= 1; q += 1
    if q + p - 1 > emax: return None
    return M, q

def q_encode(s, v):
    if v == 0: return s << 127
    r = round_to(v, 113, -16382, 16383)
    if r is None: return (s << 127) | (0x7FFF << 112)
    M, q = r
    if M >> 112 == 0: return (s << 127) | M
    return (s << 127) | ((q + 112 + 16383) << 112) | (M - (1 << 112))

def x_encode(s, v):
    if v == 0: return (s << 15, 0)
    r = round_to(v, 64, -16382, 16383)
    if r is None: return ((s << 15) | 0x7FFF, 1 << 63)
    M, q = r
    if M >> 63 == 0: return (s << 15, M)
    return ((s << 15) | (q + 63 + 16383), M)

def d_encode(s, v):
    if v == 0: return s << 63
    r = round_to(v, 53, -1022, 1023)
    if r is None: return (s << 63) | (0x7FF << 52)
    M, q = r
    if M >> 52 == 0: return (s << 63) | M
    return (s << 63) | ((q + 52 + 1023) << 52) | (M - (1 << 52))

M112 = (1 << 112) - 1


def qb(s, e, f):
    """binary128 bits of sign s, biased exponent e, fraction f."""
    return (s << 127) | (e << 112) | (f & M112)


def enc(v):
    """mpf or Fraction -> the nearest binary128's bits."""
    if isinstance(v, mpmath.mpf):
        m, e = mpmath.frexp(v)
        v = Fraction(int(mpmath.ldexp(m, 400))) * Fraction(2) ** (e - 400)
    v = Fraction(v)
    return q_encode(1 if v < 0 else 0, abs(v))


def q_value_mpf(b):
    d = q_decode(b)
    if d[0] != 'num': return None
    v = d[2]
    return mpmath.mpf(v.numerator) / v.denominator * (-1 if d[1] else 1)

def q_ulp_error(b, exact):
    """|value(b) - exact| in ulps of exact's binade (subnormal floor)."""
    y = q_value_mpf(b)
    if y is None: return mpmath.inf
    if exact == 0: return abs(y) / mpmath.mpf(2) ** (-16494)
    e = int(mpmath.floor(mpmath.log(abs(exact), 2)))
    e = max(e, -16382)
    return abs(y - exact) / mpmath.mpf(2) ** (e - 112)


def run(lines):
    return subprocess.run([HARNESS], input='\n'.join(lines) + '\n', capture_output=True,
                          text=True, check=True).stdout.split('\n')


def conversions(N):
    lines = []
    # hardware_real: low 49 bits patterns x bit 49 parity x high fraction patterns x exponents
    lows = [0, 1, 2, (1 << 48) - 1, 1 << 48, (1 << 48) + 1, (1 << 49) - 1, (1 << 47), 3 << 47]
    # fraction bits 49..111 (63 bits)
    highs = [0, 1, (1 << 63) - 1, (1 << 63) - 2, 1 << 62, random.getrandbits(63)]
    exps = [0, 1, 2, 16382, 16383, 16384, 0x7FFD, 0x7FFE, 0x7FFF]
    for s in (0, 1):
        for e in exps:
            for hi in highs:
                for lo in lows:
                    lines.append('hw ' + format(qb(s, e, (hi << 49) | lo), '032X'))
    for _ in range(N):
        e = random.choice([random.randrange(0, 0x8000), random.choice(exps)])
        f = random.getrandbits(112)
        if random.random() < 0.3: f = (f & ~((1 << 49) - 1)) | random.choice(lows)
        lines.append('hw ' + format(qb(random.getrandbits(1), e, f), '032X'))
    # double_real: 60-bit low patterns; exponents near double's range edges
    dl = [0, 1, (1 << 59) - 1, 1 << 59, (1 << 59) + 1, (1 << 60) - 1, 1 << 58]
    dh = [0, 1, (1 << 52) - 1, (1 << 52) - 2, random.getrandbits(52)]   # bits 60..111
    dexps = [0, 1, 15308, 15309, 15310, 15359, 15360, 15361, 15362, 16383, 17405, 17406, 17407,
             17408, 0x7FFE, 0x7FFF]
    for s in (0, 1):
        for e in dexps:
            for hi in dh:
                for lo in dl:
                    lines.append('dr ' + format(qb(s, e, (hi << 60) | lo), '032X'))
    for _ in range(N):
        e = random.choice([random.randrange(0, 0x8000), random.randrange(15250, 17420),
                           random.choice(dexps)])
        f = random.getrandbits(112)
        if random.random() < 0.3: f = (f & ~((1 << 60) - 1)) | random.choice(dl)
        lines.append('dr ' + format(qb(random.getrandbits(1), e, f), '032X'))
    # quad_real: x87 encodings
    sigs = [0, 1, (1 << 63) - 1, 1 << 63, (1 << 64) - 1, (1 << 63) | 1, 1 << 62, 3 << 62,
            (1 << 63) | (1 << 61), random.getrandbits(63), (1 << 63) | random.getrandbits(63)]
    xexps = [0, 1, 2, 16383, 0x7FFE, 0x7FFF]
    for s in (0, 1):
        for e in xexps:
            for m in sigs:
                lines.append('qr %04X%016X' % ((s << 15) | e, m))
    for _ in range(N):
        e = random.choice([random.randrange(0, 0x8000), random.choice(xexps)])
        m = random.getrandbits(64)
        if random.random() < 0.8: m |= 1 << 63
        lines.append('qr %04X%016X' % ((random.getrandbits(1) << 15) | e, m))
    out = run(lines)
    bad = {}; count = {}; vs_intr = {}
    def note(tag, msg):
        bad.setdefault(tag, []).append(msg)
    for ln in out:
        if not ln: continue
        t = ln.split()
        tag = t[0]; count[tag] = count.get(tag, 0) + 1
        if tag == 'hw':
            b = int(t[1], 16); r = t[2]; i = t[3]
            if r != i: vs_intr[tag] = vs_intr.get(tag, 0) + 1; note(tag, 'intrinsic differs ' + ln)
            d = q_decode(b)
            if d[0] == 'num':
                se, m = x_encode(d[1], d[2])
                exp = '%04X%016X' % (se, m)
                if r != exp: note(tag, 'exact differs %s exp %s' % (ln, exp))
        elif tag == 'dr':
            b = int(t[1], 16); r = t[2]; i = t[3]
            if r != i: vs_intr[tag] = vs_intr.get(tag, 0) + 1; note(tag, 'intrinsic differs ' + ln)
            d = q_decode(b)
            if d[0] == 'num':
                exp = '%016X' % d_encode(d[1], d[2])
                if r != exp: note(tag, 'exact differs %s exp %s' % (ln, exp))
        elif tag == 'qr':
            se = int(t[1][:4], 16); m = int(t[1][4:], 16); r = t[2]; i = t[3]
            if r != i: vs_intr[tag] = vs_intr.get(tag, 0) + 1; note(tag, 'intrinsic differs ' + ln)
            d = x_decode(se, m)
            if d[0] == 'num':
                exp = '%032X' % q_encode(d[1], d[2])
                if r != exp: note(tag, 'exact differs %s exp %s' % (ln, exp))
    print('counts', count, 'vs intrinsic', vs_intr)
    for k, v in bad.items():
        pseudo = [x for x in v if x.startswith(("exact differs qr 0000",
                                                "exact differs qr 8000"))]
        print(k, len(v))
        print("\n".join([x for x in v if x not in pseudo][:8]))
        print("pseudo-denormal qr:", len(pseudo))


def roots(N):
    mpmath.mp.prec = 300
    def qf(v):  # Fraction/int -> bits
        return q_encode(0, Fraction(v))
    args = []
    special = [0, 1 << 127, qb(0, 0x7FFF, 0), qb(1, 0x7FFF, 0), qb(0, 0x7FFF, 1 << 111),
               qb(0, 0x7FFF, 1), qb(1, 0x7FFF, 12345), qb(1, 16383, 0), qb(1, 1, 0), qb(1, 0, 1),
                qb(0, 0, 1), qb(0, 0, M112), qb(0, 0, 1 << 111), qb(0, 1, 0), qb(0, 1, 1),
               qb(0, 0x7FFE, M112),
               qb(0, 0x7FFE, M112 - 1), qb(0, 0x7FFE, 0)]
    args += special
    for e in range(1, 0x7FFF):
        for f in (0, 1, 2, 3, 4, 5, M112, M112 - 1, M112 - 4, M112 - 5):
            if random.random() < 0.06 or e in (1, 2, 16382, 16383, 16384, 0x7FFD, 0x7FFE):
                args.append(qb(0, e, f))
    for _ in range(N):
        r = random.random()
        if r < 0.25:   # perfect squares and neighbours
            n = random.getrandbits(random.randrange(1, 57)) | 1
            b = qf(n * n)
            sh = random.randrange(-8000, 8000)
            e = ((b >> 112) & 0x7FFF) + 2 * sh
            if not 1 <= e <= 0x7FFE: continue
            b = (b & M112) | (e << 112)
            b += random.choice([-2, -1, 0, 0, 1, 2])
            args.append(b)
        elif r < 0.4:   # (2^k (1 +- t))^2 next to 4^k: root at a binade edge
            e = random.randrange(2, 0x7FFD)
            d = random.randrange(1, 1 << random.randrange(1, 70))
            args.append(qb(0, e, d) if random.random() < 0.5 else qb(0, e - 1, M112 + 1 - d))
        elif r < 0.5:   # roots whose 64-bit significand is near 0 / all ones
            k = random.randrange(1, 60)
            s = Fraction(2) ** random.randrange(-8000, 8000) * (
                1 + Fraction(random.choice([-1, 1]) * random.randrange(1, 1 << 8), 1 << (64 + k))
                + Fraction(random.randrange(0, 1 << 40), 1 << 130))
            args.append(q_encode(0, s * s))
        else:
            args.append(qb(0, random.randrange(1, 0x7FFF), random.getrandbits(112)))
    lines = ['sq %032X' % b for b in args] + ['is %032X' % b for b in args]
    out = run(lines)
    worst = {}; n = {}; bad = []
    for ln in out:
        if not ln: continue
        tag, a, r, i = ln.split()
        b = int(a, 16); rb = int(r, 16); ib = int(i, 16)
        d = q_decode(b)
        n[tag] = n.get(tag, 0) + 1
        if d[0] != 'num' or d[2] == 0 or d[1] == 1 or (b >> 112) & 0x7FFF == 0:
            # specials: expect the intrinsic's bits (NaN: a NaN; zero sign)
            if rb != ib and not (q_decode(rb)[0] == 'nan' and q_decode(ib)[0] == 'nan'):
                bad.append('special ' + ln)
            continue
        x = q_value_mpf(b)
        ex = mpmath.sqrt(x) if tag == 'sq' else 1 / mpmath.sqrt(x)
        err = q_ulp_error(rb, ex)
        if err > worst.get(tag, (0,))[0]: worst[tag] = (float(err), ln)
        lim = 0.51 if tag == 'sq' else 1.0
        if err > lim: bad.append('%.4f %s' % (err, ln))
    print('counts', n)
    for k, v in worst.items(): print(k, v)
    print(len(bad)); print('\n'.join(bad[:20]))


def check_exponentials(args):
    """exp and expm1 of the binary128 bit patterns args through the harness, against
    mpmath (exact bits where the result is infinite, zero or subnormal; else in ulps,
    bound 0.75) and libquadmath's special values; prints the counts and the worst."""
    lines = ['ex %032X' % b for b in args] + ['em %032X' % b for b in args]
    out = run(lines)
    worst = {}; n = {}; bad = []; nint = {}
    for ln in out:
        if not ln: continue
        tag, a, r, i = ln.split()
        b = int(a, 16); rb = int(r, 16); ib = int(i, 16)
        n[tag] = n.get(tag, 0) + 1
        d = q_decode(b)
        if d[0] != 'num':
            if rb != ib and not (q_decode(rb)[0] == 'nan' and q_decode(ib)[0] == 'nan'):
                bad.append('special ' + ln)
            continue
        x = q_value_mpf(b)
        if x == 0:
            if rb != ib: bad.append('zero ' + ln)
            continue
        if abs(x) > 12000:
            cr = qb(0, 0x7FFF, 0) if x > 0 else (0 if tag == 'ex' else qb(1, 16383, 0))
            if rb != cr: bad.append('big %s exp %032X' % (ln, cr))
            continue
        ex = mpmath.exp(x) if tag == 'ex' else mpmath.expm1(x)
        cr = enc(ex)
        dc = q_decode(cr)
        if dc[0] != 'num' or (cr & (0x7FFF << 112)) == 0:   # inf, zero or subnormal: exact bits
            if rb != cr:
                bad.append('range %s exp %032X' % (ln, cr))
            continue
        err = q_ulp_error(rb, ex)
        if rb != ib: nint[tag] = nint.get(tag, 0) + 1
        if err > worst.get(tag, (0,))[0]: worst[tag] = (float(err), ln)
        if err > 0.75: bad.append('%.4f %s' % (err, ln))
    print('counts', n, 'differ from libquadmath', nint)
    for k, v in worst.items(): print(k, v)
    print(len(bad)); print('\n'.join(bad[:30]))


def exps(N, edges_only=False):
    mpmath.mp.prec = 320
    args = []
    specials = [0, 1 << 127, qb(0, 0x7FFF, 0), qb(1, 0x7FFF, 0), qb(0, 0x7FFF, 1 << 111),
                qb(1, 0x7FFF, (1 << 111) | 77), qb(0, 0x7FFF, 5), qb(0, 0, 1), qb(1, 0, 1),
                qb(0, 0, M112), qb(1, 0, M112), qb(0, 1, 0), qb(1, 1, 0), qb(0, 0x7FFE, M112),
                qb(1, 0x7FFE, M112)]
    args += specials
    ln2 = mpmath.log(2)
    thr = [Fraction(2) ** -113, Fraction(2) ** -16, Fraction(2) ** -8, Fraction(128),
           Fraction(16384),
           Fraction(11000), Fraction(80), Fraction(1, 2)]
    for t in thr:
        b = enc(t)
        for s in (0, 1 << 127):
            for k in range(-6, 7):
                args.append((b + k) | s)
    # overflow, smallest normal, subnormal, underflow thresholds
    for v in [mpmath.log(mpmath.mpf(2) ** 16384), mpmath.log(mpmath.mpf(2) ** -16382),
              mpmath.log(mpmath.mpf(2) ** -16494), mpmath.log(mpmath.mpf(2) ** -16495),
              mpmath.log(mpmath.mpf(2) ** 16384 * (1 - mpmath.mpf(2) ** -114))]:
        b = enc(v)
        for k in range(-5, 6):
            args.append(b + k)
    # table boundaries J/65536, j1/256, m, both signs, and +-tiny
    for _ in range(N // 4):
        J = random.randrange(-128 * 65536, 128 * 65536)
        if J == 0: continue
        b = enc(Fraction(J, 65536))
        args.append(b + random.choice([-2, -1, 0, 0, 1, 2]))
    # next to k ln 2 + ln2/2 (k rounding) and k ln 2 (x' tiny), 128 <= |x| < 11000
    for _ in range(N // 4):
        k = random.choice([1, -1]) * random.randrange(185, 15870)
        c = random.choice([0, mpmath.mpf(0.5), -mpmath.mpf(0.5)])
        v = (k + c) * ln2
        if c == 0 and random.random() < 0.5:
            v += mpmath.mpf(random.randrange(1, 1000)) * mpmath.mpf(2) ** random.randrange(-120,
                                                                                     -20)
        b = enc(v)
        args.append(b + random.choice([-1, 0, 1]))
    # log-uniform magnitudes 2^-120 .. 11400
    for _ in range(N // 2):
        v = mpmath.mpf(2) ** random.uniform(-120, 13.48) * random.choice([1, -1])
        args.append(enc(v) ^ random.getrandbits(40))
    check_exponentials(args)


def exp_edges(N):
    mpmath.mp.prec = 320
    args = []
    for e in range(-120, 15):       # every binade's edges, both signs
        b0 = enc(Fraction(2) ** e)
        for k in range(-3, 4):
            for sg in (0, 1 << 127):
                args.append((b0 + k) | sg)
    for J in list(range(-600, 601)) + [256 * i for i in range(-300, 301)] + \
             [65536 * i + d for i in range(-128, 128) for d in (-1, 0, 1)]:
        if J == 0: continue
        b0 = enc(Fraction(J, 65536))
        for k in (-1, 0, 1):
            args.append(b0 + k)
        args.append(enc(Fraction(J, 65536) + Fraction(random.randrange(1, 1 << 20), 1 << 120)))
        args.append(enc(Fraction(J, 65536) - Fraction(random.randrange(1, 1 << 20), 1 << 120)))
    check_exponentials(args)


if __name__ == '__main__':
    HARNESS = sys.argv[1]
    check = sys.argv[2]
    random.seed(int(sys.argv[3]) if len(sys.argv) > 3 else 1)
    count = int(sys.argv[4]) if len(sys.argv) > 4 else 20000
    {'conversions': conversions, 'roots': roots, 'exp': exps, 'exp-edges': exp_edges}[check](count)
