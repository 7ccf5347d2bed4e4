!> exp and expm1 in binary128, several times faster than libquadmath's, for the general
!! engine's integrands (one or two per quadrature node).
!!
!! After an exact reduction of the argument the work is done in pairs of x87 extended
!! numbers (h + l, 64-bit significands: about 128 bits, more than binary128's 113), and
!! only the final sum is rounded to binary128 (`to_quad`, on the bits: no binary128
!! operation on the main paths). The reduction: for |x| < 128, x = J/65536 + r with
!! J = floor(65536 x) = 65536 m + 256 j1 + j2 and 0 <= r < 2^-16, read off the bits of x
!! (r exact as a pair); exp(x) = e^m e^(j1/256) (1 + expm1(j2/65536 + r)), the factors
!! from tables of pairs within 2^-128 (`brachistochrone_fast_exp_tables`, mpmath), e^m
!! as 2^E(m) times a pair in [1, 2). For 128 <= |x| < 11000, x = k log 2 + x' (k log 2 in
!! three parts, the first two exact, x' within about 2^-128), then x' as above, times
!! 2^k on the bits. expm1 for |x| < 2^-8: its series (|x| < 2^-16) or expm1(a + r) =
!! expm1(a) + e^a expm1(r) for a = +-j/65536, r of x's sign (no cancellation); beyond,
!! exp(x) - 1 in pairs (the cancellation, at most 2^8, leaves about 2^-118). expm1(r)
!! (|r| <= 2^-16): Dekker's exact products for r^2 and r^3 (1/6 + ...), the rest in x87.
!! Errors against mpmath at 10^5 arguments (|x| 1e-30 .. 11000, both signs; scripts/
!! bench_fast_exp.sh): exp 0.50, expm1 0.60 units in the last place (the previous
!! binary128 version 2.3 and 3.1, libquadmath 0.50 and 1.45); about 80 ns a call, a
!! quarter of the previous version's time. Where `xp` is not x87 extended: the library's
!! exp and expm1. The pairs need x87 arithmetic at 64 bits, rounding to nearest (the
!! defaults; `brachistochrone_fast_math`'s `hardware_arithmetic_ok` checks them): at 53
!! bits (gfortran -mpc64, fldcw) the results are wrong by up to 10^22 ulp, rounding
!! toward zero or upward by about an ulp. The tables are parameters (no state: safe in
!! threads).
module brachistochrone_fast_exp
    use brachistochrone_kinds, only: qp, xp
    use brachistochrone_fast_exp_tables, only: whole_exponent, whole_scaled, steps, fine, &
                                               ln2_parts
    use brachistochrone_quad_math, only: expm1
    use, intrinsic :: iso_fortran_env, only: int64, real64
    implicit none
    private

    public :: fast_exp, fast_expm1

    integer, parameter :: i128 = selected_int_kind(38)
    !> The pair arithmetic needs x87 extended `xp` and binary128 `qp` bits (1.5 read back).
    logical, parameter :: pairs = digits(1.0_xp) == 64 .and. maxexponent(1.0_xp) == 16384 &
        .and. digits(1.0_qp) == 113 .and. &
        transfer(1.5_qp, 0_i128) == ishft(int(z'3FFF8', i128), 108)
    integer :: j_
    !> Powers of two 2^j, j = -128..128 (exact scalings of pairs).
    real(xp), parameter :: two_to(-128:128) = [(2.0_xp**j_, j_ = -128, 128)]
    !> Veltkamp's splitter for 64-bit significands (two halves of 32 bits).
    real(xp), parameter :: splitter = 2.0_xp**32 + 1.0_xp
    !> 1/6 as a pair; the series' coefficients from 1/24 on.
    real(xp), parameter :: sixth(2) = [1.0_xp/6, real(1.0_qp/6 - real(1.0_xp/6, qp), xp)]
    real(xp), parameter :: coefficients(4) = [1.0_xp/24, 1.0_xp/120, 1.0_xp/720, &
                                              1.0_xp/5040]
    !> Adding and subtracting it rounds |t| < 2^62 to an integer (x87: 64 bits).
    real(xp), parameter :: round_magic = 3.0_xp*2.0_xp**62
    !> The reductions (`reduce`): series only, one fine step, all tables; no pairs.
    integer, parameter :: path_series = 1, path_fine = 2, path_tables = 3, &
                          path_library = 4, path_minus_one = 5
    integer(i128), parameter :: low50 = ishft(1_i128, 50) - 1, low112 = ishft(1_i128, 112) - 1

contains

    !> exp(x) for binary128 x (overflow to +Inf, underflow to 0 as exp does; |x| >= 11000,
    !! Inf and NaN: the library's exp).
    elemental function fast_exp(x) result(y)
        real(qp), intent(in) :: x !! argument
        real(qp) :: y
        if (pairs) then
            y = exponential(x, .false.)
        else
            y = exp(x)
        end if
    end function fast_exp

    !> expm1(x) = exp(x) - 1 to full relative precision (for x >= 128: exp(x)).
    elemental function fast_expm1(x) result(y)
        real(qp), intent(in) :: x !! argument
        real(qp) :: y
        if (pairs) then
            y = exponential(x, .true.)
        else
            y = expm1(x)
        end if
    end function fast_expm1

    !> exp(x), or expm1(x) with `minus_one`: the argument reduced to a pair (`reduce`),
    !! its expm1 (`series`), the tables (`combine`), rounded once (`to_quad`). (Each step
    !! called from here only, so the compiler inlines it: the pairs stay in registers.)
    elemental function exponential(x, minus_one) result(y)
        real(qp), intent(in) :: x
        logical, intent(in) :: minus_one
        real(qp) :: y
        real(xp) :: h, l
        integer :: e, j, k, path
        e = binary_exponent(x)
        if (e < -113) then
            ! (zero and subnormals included: x^2/2 is below half an ulp of x, of 1)
            if (minus_one) then
                y = x
            else
                y = 1.0_qp + x
            end if
            return
        end if
        call reduce(x, e, minus_one, h, l, j, k, path)
        select case (path)
        case (path_library)
            if (minus_one) then
                y = expm1(x)
            else
                y = exp(x)
            end if
        case (path_minus_one)
            y = -1.0_qp
        case default
            call series(h, l)
            call combine(path, j, signbit(x), minus_one, e, h, l, k)
            y = to_quad(h, l, k)
        end select
    end function exponential

    !> The argument x (binary exponent e >= -113) reduced: for |x| < 2^-16 r = x (path
    !! `path_series`); for expm1 and |x| < 2^-8, |x| = j/65536 + r, r of x's sign, j
    !! signed as x (`path_fine`); else x = J/65536 + r, J = floor(65536 x) in j (r >= 0:
    !! `path_tables`), beyond 128 after x = k log 2 + x' (`reduce_large`; else k = 0). r
    !! as the pair (h, l), exact below 128. Also the paths without pairs: the library's exp
    !! (|x| >= 11000, Inf, NaN), -1 (expm1 for x < -80).
    elemental subroutine reduce(x, e, minus_one, h, l, j, k, path)
        real(qp), intent(in) :: x
        integer, intent(in) :: e
        logical, intent(in) :: minus_one
        real(xp), intent(out) :: h, l
        integer, intent(out) :: j, k, path
        j = 0
        k = 0
        h = 0.0_xp
        l = 0.0_xp
        if (e < -16) then
            path = path_series
            call bits_pair(significand(x), e, signbit(x), h, l)
        else if (e < 7) then
            ! (one call: the compiler inlines it)
            path = merge(path_fine, path_tables, minus_one .and. e < -8)
            call reduce_table(x, e, path == path_tables, j, h, l)
            if (path == path_fine .and. signbit(x)) j = -j
            if (minus_one .and. j < -80*65536) path = path_minus_one
        else if (e > 13) then
            path = path_library
        else if (minus_one .and. signbit(x)) then
            path = path_minus_one
        else
            call reduce_large(x, e, h, l, j, k, path)
        end if
    end subroutine reduce

    !> For 128 <= |x| < 16384 (binary exponent e): x = k log 2 + x' (|x'| <= 0.35 + 2^-40,
    !! a pair within about 2^-128: k log 2's first two parts exact), then J = floor(65536
    !! x') and r = x' - J/65536 >= 0 as the pair (h, l) (`path_tables`); beyond 11000
    !! `path_library`.
    elemental subroutine reduce_large(x, e, h, l, j, k, path)
        real(qp), intent(in) :: x
        integer, intent(in) :: e
        real(xp), intent(out) :: h, l
        integer, intent(out) :: j, k, path
        real(xp) :: d, s, u, ue, se, t
        call bits_pair(significand(x), e, signbit(x), h, l)
        path = path_library
        j = 0
        k = 0
        if (abs(h) >= 11000.0_xp) return
        path = path_tables
        k = int(real(h*(1.0_xp/ln2_parts(1)) + sign(0.5_xp, h), real64))
        t = real(k, xp)
        ! h - k ln2_1 exact (both multiples of 2^-56, the difference below 1/2); k ln2_2
        ! exact (48 + 14 bits); Knuth's two-sums for the rest
        d = h - t*ln2_parts(1)
        call two_sum(d, l, u, ue)
        call two_sum(u, -t*ln2_parts(2), s, se)
        l = (ue + se) - t*ln2_parts(3)
        h = s + l
        l = l - (h - s)
        ! J = floor(65536 x') (or one more: r then slightly negative, which the series
        ! takes), r = x' - J/65536 (a two-sum: for x' < 0, |r| may exceed |x'|)
        j = int(real(h*65536.0_xp + 32768.0_xp, real64)) - 32768
        call two_sum(h, -real(j, xp)*two_to(-16), s, se)
        l = l + se
        h = s + l
        l = l - (h - s)
    end subroutine reduce_large

    !> From expm1(r) in (h, l) to the result (h + l) 2^k (|h + l| in [1/2, 8)): for
    !! `path_fine` and `path_tables`, expm1(a + r) = expm1(a) + e^a expm1(r) (a = j/65536,
    !! j's last 8 bits with `path_tables`); for `path_tables` then the factors e^(j1/256)
    !! (the next 8 bits) and e^m (m = floor(J/65536): 2^E(m) times a pair), k added to
    !! E(m); exp adds 1, expm1 (x negative when `negative`, binary exponent e) subtracts it
    !! after the tables, or scales by 2^-e.
    elemental subroutine combine(path, j, negative, minus_one, e, h, l, k)
        integer, intent(in) :: path, j, e
        logical, intent(in) :: negative, minus_one
        real(xp), intent(inout) :: h, l
        integer, intent(inout) :: k
        integer :: a, m
        a = j
        if (path == path_tables) a = iand(j, 255)
        if (a /= 0) call expm1_step(fine(:, a), h, l)
        if (path /= path_tables .and. minus_one) then
            h = h*two_to(-e)
            l = l*two_to(-e)
            k = e
            return
        end if
        call add_one(h, l)
        if (path /= path_tables) return
        a = iand(shifta(j, 8), 255)
        if (a > 0) call times(steps(:, a), h, l)
        m = shifta(j, 16)
        if (m /= 0) then
            call times(whole_scaled(:, m), h, l)
            k = k + whole_exponent(m)
        end if
        if (minus_one) call subtract_one(negative, e, h, l, k)
    end subroutine combine

    !> (h, l, k) <- e^x - 1 from e^x = (h + l) 2^k for 2^-8 <= |x| < 128 (binary exponent
    !! e; x >= -80, so k >= -116), |h + l| in [1/2, 8) after.
    elemental subroutine subtract_one(negative, e, h, l, k)
        logical, intent(in) :: negative
        integer, intent(in) :: e
        real(xp), intent(inout) :: h, l
        integer, intent(inout) :: k
        real(xp) :: s
        if (.not. negative) then
            ! (h + l - 2^-k) 2^k (2^-k below 2^-120 of h: dropped)
            if (k <= 120) then
                s = h - two_to(-k)
                l = l + ((h - s) - two_to(-k))
                h = s
            end if
        else
            ! (h + l) 2^k - 1 in (-1, 0)
            h = h*two_to(k)
            l = l*two_to(k)
            s = h - 1.0_xp
            l = l + (h - (s + 1.0_xp))
            h = s
            k = 0
        end if
        if (e < 0) then
            ! (k = 0 here) the pair to [1/2, 4): times 2^-e
            h = h*two_to(-e)
            l = l*two_to(-e)
            k = e
        end if
    end subroutine subtract_one

    !> expm1(r) for the pair r = h + l (|r| <= 2^-16, |l| <= ulp(h)), in place, within
    !! about 2^-115 of r: r + r^2/2 + r^3 (1/6 + r t), r^2 = p + pe and r^3 (1/6 + ...)
    !! by Dekker's exact products, t = 1/24 + ... + r^3/5040 in x87 (its rounding, 2^-64
    !! of r/24 in 1/6 + r t, is 2^-115.6 of r at most), l by e^h l.
    elemental subroutine series(h, l)
        real(xp), intent(inout) :: h, l
        real(xp) :: a1, a2, b1, b2, c1, c2, p, pe, t, g, gl, q, ql, c, cl, s, se, u, ue
        call split(h, a1, a2)
        p = h*h
        pe = ((a1*a1 - p) + 2.0_xp*a1*a2) + a2*a2
        t = h*(coefficients(1) + h*(coefficients(2) + h*(coefficients(3) &
            + h*coefficients(4))))
        g = sixth(1) + t
        gl = (t - (g - sixth(1))) + sixth(2)
        ! q + ql = h (g + gl), then c + cl = (p + pe)(q + ql)
        call split(g, b1, b2)
        q = h*g
        ql = ((((a1*b1 - q) + a1*b2) + a2*b1) + a2*b2) + h*gl
        call split(p, c1, c2)
        call split(q, b1, b2)
        c = p*q
        cl = ((((c1*b1 - c) + c1*b2) + c2*b1) + c2*b2) + (p*ql + pe*q)
        ! h + p/2 + c by fast two-sums, the low parts summed
        s = h + 0.5_xp*p
        se = 0.5_xp*p - (s - h)
        u = s + c
        ue = c - (u - s)
        l = (((se + ue) + 0.5_xp*pe) + cl) + l*(1.0_xp + h*(1.0_xp + 0.5_xp*h))
        h = u + l
        l = l - (h - u)
    end subroutine series

    !> (h, l) <- a + (h + l) + a (h + l), i.e. expm1(b + r) = expm1(b) + e^b expm1(r) for
    !! the table pair a = expm1(b), (h + l) = expm1(r) (|h| < |a(1)|, a of its sign or
    !! |h| below 2^-40).
    pure subroutine expm1_step(a, h, l)
        real(xp), intent(in) :: a(2)
        real(xp), intent(inout) :: h, l
        real(xp) :: a1, a2, b1, b2, p, pl, u, ue, w, we
        call split(h, a1, a2)
        call split(a(1), b1, b2)
        p = a(1)*h
        pl = ((((a1*b1 - p) + a1*b2) + a2*b1) + a2*b2) + (a(1)*l + a(2)*h)
        u = a(1) + h
        ue = h - (u - a(1))
        w = u + p
        we = p - (w - u)
        l = ((ue + we) + (a(2) + l)) + pl
        h = w + l
        l = l - (h - w)
    end subroutine expm1_step

    !> (h, l) <- 1 + h + l for |h| < 1/2.
    elemental subroutine add_one(h, l)
        real(xp), intent(inout) :: h, l
        real(xp) :: s
        s = 1.0_xp + h
        l = (h - (s - 1.0_xp)) + l
        h = s
    end subroutine add_one

    !> (h, l) <- (h + l)(a(1) + a(2)) for a table pair a: Dekker's exact product of the
    !! high parts, the cross products (l a(2), 2^-128 of the product, dropped); the result
    !! not renormalized (|l| within about ulp(h)).
    pure subroutine times(a, h, l)
        real(xp), intent(in) :: a(2)
        real(xp), intent(inout) :: h, l
        real(xp) :: a1, a2, b1, b2, p
        call split(h, a1, a2)
        call split(a(1), b1, b2)
        p = h*a(1)
        l = ((((a1*b1 - p) + a1*b2) + a2*b1) + a2*b2) + (h*a(2) + l*a(1))
        h = p
    end subroutine times

    !> Veltkamp's split of a into a1 + a2, each of 32 bits or fewer (exact).
    elemental subroutine split(a, a1, a2)
        real(xp), intent(in) :: a
        real(xp), intent(out) :: a1, a2
        real(xp) :: c
        c = splitter*a
        a1 = c - (c - a)
        a2 = a - a1
    end subroutine split

    !> Knuth's two-sum: s + e = a + b exactly.
    elemental subroutine two_sum(a, b, s, e)
        real(xp), intent(in) :: a, b
        real(xp), intent(out) :: s, e
        real(xp) :: v
        s = a + b
        v = s - a
        e = (a - (s - v)) + (b - v)
    end subroutine two_sum

    !> The unbiased binary exponent of x (floor(log2 |x|) for normal x; -16383 for zero
    !! and subnormals, 16384 for Inf and NaN).
    elemental function binary_exponent(x) result(e)
        real(qp), intent(in) :: x
        integer :: e
        e = int(iand(ishft(transfer(x, 0_i128), -112), 32767_i128)) - 16383
    end function binary_exponent

    !> For 2^-16 <= |x| < 128 (binary exponent e): |x| = j/65536 + r, 0 <= r < 2^-16, on
    !! the bits (j, r exact); with `floored`, x = j/65536 + r (j = floor(65536 x), r >= 0),
    !! else j >= 0 and r of x's sign. r as the pair (h, l).
    elemental subroutine reduce_table(x, e, floored, j, h, l)
        real(qp), intent(in) :: x
        integer, intent(in) :: e
        logical, intent(in) :: floored
        integer, intent(out) :: j
        real(xp), intent(out) :: h, l
        integer(i128) :: f
        integer :: shift
        logical :: negative
        shift = 96 - e
        f = significand(x)
        j = int(ishft(f, -shift))
        f = iand(f, ishft(1_i128, shift) - 1)
        negative = signbit(x)
        if (negative .and. floored) then
            j = -j
            negative = .false.
            if (f /= 0) then
                j = j - 1
                f = ishft(1_i128, shift) - f
            end if
        end if
        call bits_pair(f, e, negative, h, l)
    end subroutine reduce_table

    !> The sign bit of x (no binary128 comparison).
    elemental logical function signbit(x)
        real(qp), intent(in) :: x
        signbit = transfer(x, 0_i128) < 0_i128
    end function signbit

    !> The 113-bit significand of normal x (hidden bit included) as an integer.
    elemental function significand(x) result(f)
        real(qp), intent(in) :: x
        integer(i128) :: f
        f = ior(iand(transfer(x, 0_i128), low112), ishft(1_i128, 112))
    end function significand

    !> +-f 2^(e-112) as the pair (h, l), exactly (0 <= f < 2^113, -113 <= e <= 13).
    elemental subroutine bits_pair(f, e, negative, h, l)
        integer(i128), intent(in) :: f
        integer, intent(in) :: e
        logical, intent(in) :: negative
        real(xp), intent(out) :: h, l
        real(xp) :: s, scale
        scale = two_to(e)*two_to(-112)
        s = real(int(ishft(f, -50), int64), xp)*(scale*two_to(50))
        l = real(int(iand(f, low50), int64), xp)*scale
        h = s + l
        l = l - (h - s)
        if (negative) then
            h = -h
            l = -l
        end if
    end subroutine bits_pair

    !> (h + l) 2^k rounded to binary128 (to nearest) on the bits, for |h + l| in
    !! [1/2, 8) and a normal result: the pair renormalized, h's significand (its leading
    !! bit dropped) and l in units of the result's last place, rounded by an x87
    !! addition; the integers through double precision (exact: each below 2^53; no
    !! change of the x87 rounding mode).
    elemental function to_quad(h, l, k) result(y)
        real(xp), intent(in) :: h, l
        integer, intent(in) :: k
        real(qp) :: y
        real(xp), parameter :: three_2_62 = 3.0_xp*2.0_xp**62
        real(xp) :: a, b, t, a1, a2
        integer :: e
        integer(int64) :: s, n
        integer(i128) :: bits
        a = h + l
        b = l - (a - h)
        t = abs(a)
        e = -1
        if (t >= 1.0_xp) e = 0
        if (t >= 2.0_xp) e = 1
        if (t >= 4.0_xp) e = 2
        ! s = t 2^(63-e) - 2^63 from t's halves (t's 32 high bits 2^(63-e) - 3 2^62 is
        ! below 2^62 in size and a multiple of 2^32)
        call split(t, a1, a2)
        s = int(real(a1*two_to(63 - e) - three_2_62, real64), int64) + ishft(1_int64, 62) &
            + int(real(a2*two_to(63 - e), real64), int64)
        t = b*two_to(112 - e)
        if (a < 0.0_xp) t = -t
        ! (h exactly 2^e, l pulling below: the last place is half as large)
        if (s == 0 .and. t < 0.0_xp) t = t + t
        n = int(real((t + round_magic) - round_magic, real64), int64)
        bits = ishft(int(e + k + 16383, i128), 112) + ishft(int(s, i128), 49) + int(n, i128)
        if (a < 0.0_xp) bits = ibset(bits, 127)
        y = transfer(bits, y)
    end function to_quad

end module brachistochrone_fast_exp
