!> log and log1p in binary128, about twice as fast as libquadmath's logq and log1pq, for
!! the general engine's setups (a few per solve: -log R, log(1 + d/R), log Lambda).
!!
!! x = 2^e m on the bits (m in [1, 2); subnormal x scaled by 2^113 first), and
!! log x = e log 2 + log c1 + log1p(u1), u1 = (m - c1)/c1 for the table point c1 = 1 +
!! j1/128 nearest m (m - c1 exact, |u1| <= 2^-8; for m >= 3/2 the table holds log(c1/2) and
!! e + 1 is taken instead, so that no sum cancels by more than about a bit and x just
!! below 1 has e = 0, c1 = 2, u1 = (m - 2)/2 exact). Then log1p(u1) = log c2 + log1p(u2),
!! c2 = 1 + j2/2^16 nearest 1 + u1 (j2 from the hardware copy of u1; u1 - j2/2^16 exact),
!! u2 = (u1 - j2/2^16)/c2, |u2| <= 2^-17 (1 + 2^-8): log1p(u2) = u2 + u2 (u2 (-1/2 + u2
!! (1/3 + W))), W = u2 (-1/4 + u2/5 - u2^2/6 + u2^3/7) in hardware extended precision
!! (its relative error 2^-63 of a term below 2^-51 of u2). The tables log c1, 1/c1,
!! log c2, 1/c2 are constant expressions (rounded by the compiler); 1/c1, 1/c2 rounded
!! to binary128 give u1, u2 to 2^-112 of themselves. log1p(x): for |x| < 2^-8 the second
!! stage alone (x in place of u1: exact for j1 = 0); otherwise log(w), w = 1 + x, plus
!! the rounding of w, err/w (err exact by Fast2Sum, the quotient in hardware precision).
!! Errors: a few units in the last place (test_fast_log measures them against
!! libquadmath). Zero, negative, infinite and NaN arguments go to the intrinsics.
module brachistochrone_fast_log
    use brachistochrone_kinds, only: qp, xp
    use brachistochrone_fast_math, only: hardware_real, quad_real
    use, intrinsic :: iso_fortran_env, only: int64
    implicit none
    private

    public :: fast_log, fast_log1p

    integer :: j_
    !> c1 = 1 + j/128, j = 0..128, 1/c1, log c1 and log(c1/2) (for m >= 3/2).
    real(qp), parameter :: c1(0:128) = [(1.0_qp + real(j_, qp)/128.0_qp, j_ = 0, 128)]
    real(qp), parameter :: inverse_c1(0:128) = 1.0_qp/c1
    real(qp), parameter :: log_c1(0:128) = log(c1)
    real(qp), parameter :: log_half_c1(0:128) = log(0.5_qp*c1)
    !> j/2^16, j = -256..256, c2 = 1 + j/2^16, 1/c2 and log c2.
    real(qp), parameter :: s2(-256:256) = [(real(j_, qp)/65536.0_qp, j_ = -256, 256)]
    real(qp), parameter :: inverse_c2(-256:256) = 1.0_qp/(1.0_qp + s2)
    real(qp), parameter :: log_c2(-256:256) = log(1.0_qp + s2)
    !> log 2 = ln2_high + ln2_low, ln2_high with 98 bits (e ln2_high exact for |e| < 2^15)
    real(qp), parameter :: ln2 = log(2.0_qp)
    real(qp), parameter :: ln2_high = anint(ln2*2.0_qp**98)/2.0_qp**98
    !> (ln2's own rounding, 2^-114 of it, is relative: e ln2 keeps it)
    real(xp), parameter :: ln2_low = real(ln2 - ln2_high, xp)
    !> 1/3 and the hardware constants of the series' tail
    real(qp), parameter :: third = 1.0_qp/3.0_qp
    real(xp), parameter :: t4 = -0.25_xp, t5 = 0.2_xp, t6 = -1.0_xp/6.0_xp, &
                           t7 = 1.0_xp/7.0_xp
    !> Bits of the high word: the exponent field and the 48 significand bits below it.
    integer(int64), parameter :: low48 = ishft(1_int64, 48) - 1_int64
    integer(int64), parameter :: bias = 16383_int64

contains

    !> log(x) for binary128 x (the intrinsic for x <= 0, infinite or NaN).
    elemental function fast_log(x) result(y)
        real(qp), intent(in) :: x !! argument
        real(qp) :: y
        real(qp) :: m, scaled, s
        integer(int64) :: bits(2), field
        integer :: e, f8, j1
        logical :: upper
        if (.not. log_layout()) then
            y = log(x)
            return
        end if
        bits = transfer(x, bits)
        field = ishft(bits(2), -48)      ! sign and exponent
        e = 0
        if (field == 0_int64 .and. x > 0.0_qp) then
            ! subnormal: scaled into the normal range (exact)
            scaled = x*2.0_qp**113
            bits = transfer(scaled, bits)
            field = ishft(bits(2), -48)
            e = -113
        end if
        if (field <= 0_int64 .or. field >= 32767_int64) then
            ! zero, negative, infinite or NaN
            y = log(x)
            return
        end if
        e = e + int(field - bias)
        ! m in [1, 2): the significand with the exponent field of 1
        m = transfer([bits(1), ior(iand(bits(2), low48), ishft(bias, 48))], m)
        f8 = int(iand(ishft(bits(2), -40), 255_int64))
        j1 = ishft(f8 + 1, -1)
        upper = f8 >= 128
        if (upper) e = e + 1
        ! log1p(u1) + log c1 (or log(c1/2)): a bit of cancellation at most
        s = fine_log1p((m - c1(j1))*inverse_c1(j1))
        if (upper) then
            s = log_half_c1(j1) + s
        else
            s = log_c1(j1) + s
        end if
        if (e == 0) then
            y = s
        else
            y = real(e, qp)*ln2_high + (s + quad_real(real(e, xp)*ln2_low))
        end if
    end function fast_log

    !> log(1 + x) for binary128 x to full relative precision (the intrinsic for x <= -1,
    !! infinite or NaN).
    elemental function fast_log1p(x) result(y)
        real(qp), intent(in) :: x !! argument, > -1
        real(qp) :: y
        real(qp) :: w, err
        real(xp) :: xx
        xx = hardware_real(x)
        if (.not. log_layout() .or. .not. (xx > -1.0_xp .and. xx < huge(1.0_xp))) then
            y = log1p_intrinsic(x)
            return
        end if
        if (abs(xx) < 0.00390625_xp) then
            ! |x| < 2^-8 (its hardware copy: at most 2^-8 itself, the reduction holds)
            y = fine_log1p(x)
            return
        end if
        w = 1.0_qp + x
        ! the rounding of w, exactly (Fast2Sum: the larger term first)
        if (xx < 1.0_xp) then
            err = x - (w - 1.0_qp)
        else
            err = 1.0_qp - (w - x)
        end if
        y = fast_log(w)
        if (err /= 0.0_qp) y = y + quad_real(hardware_real(err)/hardware_real(w))
    end function fast_log1p

    !> log1p(u) for |u| <= 2^-8 (a little beyond: |u2| then slightly above 2^-17).
    elemental function fine_log1p(u) result(y)
        real(qp), intent(in) :: u
        real(qp) :: y
        real(qp) :: u2
        real(xp) :: ux
        integer :: j2
        j2 = max(-256, min(256, nint(hardware_real(u)*65536.0_xp)))
        ! u - j2/2^16 exact (|u| <= 2^-8: its bits end at or above 2^-120, and the
        ! difference is below 2^-17 + ulp), then one rounding by 1/c2 (itself rounded)
        u2 = (u - s2(j2))*inverse_c2(j2)
        ux = hardware_real(u2)
        y = u2 + u2*(u2*(u2*(third + quad_real(ux*(t4 + ux*(t5 + ux*(t6 + ux*t7))))) &
                        - 0.5_qp))
        if (j2 /= 0) y = log_c2(j2) + y
    end function fine_log1p

    !> Whether binary128 and x87 extended are laid out as assumed (the hardware copies of
    !! the series' terms need 64 bits, the bit fields IEEE binary128's).
    pure logical function log_layout()
        log_layout = digits(1.0_xp) == 64 .and. digits(1.0_qp) == 113 .and. &
                     maxexponent(1.0_qp) == 16384
    end function log_layout

    !> The library's log1p (libquadmath), for the arguments fast_log1p does not take.
    elemental function log1p_intrinsic(x) result(y)
        use brachistochrone_quad_math, only: log1p
        real(qp), intent(in) :: x
        real(qp) :: y
        y = log1p(x)
    end function log1p_intrinsic

end module brachistochrone_fast_log
