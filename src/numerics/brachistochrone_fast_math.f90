!> Elementary functions in quad precision that are cheaper than the library's.
!!
!! binary128 arithmetic is done in software (a multiplication is about 180 machine
!! instructions) and `sqrt` costs about seven multiplications. The integrands need
!! 1/sqrt(q) at every node, so it is computed here from a hardware seed in the widest
!! native precision (x87 extended on x86-64: 64-bit significand, error ~5e-20) refined
!! by one Newton step r <- r (3 - q r^2)/2, which squares the error (~4e-39, below the
!! rounding of binary128) using multiplications only. Where no native kind wider than
!! double exists the seed is double precision and a second step is taken.
!!
!! The conversion of binary128 to x87 extended (`hardware_real`, also used for the seed)
!! is libgcc's __trunctfxf2 in software, as costly as a binary128 addition; both
!! formats have the same 15-bit exponent, so for normal numbers it is a rounding of
!! the significand to 64 bits (to nearest, ties to even) done here on the bits, the
!! same result at about two thirds of the cost.
module brachistochrone_fast_math
    use brachistochrone_kinds, only: qp, xp
    use, intrinsic :: iso_fortran_env, only: real64, int64
    implicit none
    private

    public :: inverse_sqrt, hardware_real, fast_sqrt, quad_real

    !> Widest hardware real kind below quad (x87 extended where available).
    integer, parameter :: seed_kind_candidate = selected_real_kind(18, 4931)
    integer, parameter :: seed_kind = merge(seed_kind_candidate, real64, &
                                            seed_kind_candidate > 0 .and. &
                                            seed_kind_candidate /= qp)
    !> Newton steps needed from that seed.
    integer, parameter :: newton_steps = merge(1, 2, seed_kind /= real64)
    !> Inputs inside this range get the hardware seed; others use 1/sqrt(x).
    real(qp), parameter :: seed_low = 1.0e-300_qp, seed_high = 1.0e300_qp

    !> Bits of 1.5 in `qp` and `xp` (two little-endian 64-bit words): the conversion on
    !! the bits is used only where they are binary128 and x87 extended.
    integer(int64), parameter :: quad_bits(2) = transfer(1.5_qp, [0_int64, 0_int64])
    integer(int64), parameter :: extended_bits(2) = transfer(1.5_xp, [0_int64, 0_int64])
    logical, parameter :: x87_layout = xp /= real64 .and. digits(1.0_xp) == 64 .and. &
        storage_size(1.0_xp) == 128 .and. quad_bits(1) == 0_int64 .and. &
        quad_bits(2) == ishft(int(z'3FFF8', int64), 44) .and. &
        extended_bits(1) == ishft(3_int64, 62) .and. &
        iand(extended_bits(2), int(z'FFFF', int64)) == int(z'3FFF', int64)

contains

    !> 1/sqrt(x) for x > 0, within 2 ulp.
    elemental function inverse_sqrt(x) result(r)
        real(qp), intent(in) :: x !! positive argument
        real(qp) :: r
        real(xp) :: x_xp, r_xp
        integer :: step
        if (x87_layout) then
            ! the range test on the hardware copy (no binary128 comparisons); the seed
            ! r within 2^-63, then r + r (1 - x r^2)/2: the residual 1 - x r^2 (exact
            ! subtraction, below 2^-62) in binary128, its product with r/2 in hardware
            ! precision (2^-64 of a term of 2^-63 r), both conversions on the bits
            x_xp = hardware_real(x)
            if (x_xp > 1.0e-4900_xp .and. x_xp < 1.0e4900_xp) then
                r_xp = 1.0_xp/sqrt(x_xp)
                r = quad_real(r_xp)
                r = r + quad_real(0.5_xp*r_xp*hardware_real(1.0_qp - x*(r*r)))
                return
            end if
        else if (x > seed_low .and. x < seed_high) then
            r = real(1.0_seed_kind/sqrt(real(x, seed_kind)), qp)
            do step = 1, newton_steps
                r = r*(1.5_qp - 0.5_qp*x*(r*r))
            end do
            return
        end if
        r = 1.0_qp/sqrt(x)
    end function inverse_sqrt

    !> sqrt(x) for x >= 0, within about an ulp: the hardware square root s and one
    !! correction (x - s^2)/(2 s) (the residual in binary128, the quotient in hardware
    !! precision), where `xp` is x87 extended; sqrt itself elsewhere.
    elemental function fast_sqrt(x) result(s)
        real(qp), intent(in) :: x !! non-negative argument
        real(qp) :: s
        real(xp) :: x_xp, s_xp
        if (x87_layout) then
            x_xp = hardware_real(x)
            ! (both kinds share the exponent range: all of it but its ends, where s^2
            ! or r^2 would leave it; steep laws' far nodes reach 1e-1000 and below)
            if (x_xp > 1.0e-4900_xp .and. x_xp < 1.0e4900_xp) then
                s_xp = sqrt(x_xp)
                s = quad_real(s_xp)
                s = s + quad_real(hardware_real(x - s*s)/(2.0_xp*s_xp))
                return
            end if
        end if
        ! (zero, an end of a range, without a library call)
        s = x
        if (x /= 0.0_qp) s = sqrt(x)
    end function fast_sqrt

    !> real(y, qp) on the bits for normal y where `xp` is x87 extended (the library's
    !! __extendxftf2 otherwise).
    elemental function quad_real(y) result(x)
        real(xp), intent(in) :: y !! any value
        real(qp) :: x
        integer(int64), parameter :: low48 = ishft(1_int64, 48) - 1, &
                                     exponent_mask = int(z'7FFF', int64)
        integer(int64) :: bits(2), sign_exponent
        if (.not. x87_layout) then
            x = real(y, qp)
            return
        end if
        bits = transfer(y, bits)
        sign_exponent = iand(bits(2), int(z'FFFF', int64))
        ! zero, subnormal, infinite, NaN or unnormal: the library's conversion
        if (iand(sign_exponent, exponent_mask) == 0_int64 .or. &
            iand(sign_exponent, exponent_mask) == exponent_mask .or. &
            .not. btest(bits(1), 63)) then
            x = real(y, qp)
            return
        end if
        x = transfer([ishft(bits(1), 49), ior(ishft(sign_exponent, 48), &
                                              iand(ishft(bits(1), -15), low48))], x)
    end function quad_real

    !> real(x, xp), the same bits, faster for normal x where `xp` is x87 extended.
    elemental function hardware_real(x) result(y)
        real(qp), intent(in) :: x !! any value
        real(xp) :: y
        integer(int64), parameter :: low48 = ishft(1_int64, 48) - 1, &
                                     low49 = ishft(1_int64, 49) - 1, &
                                     half = ishft(1_int64, 48), top = ishft(1_int64, 63)
        integer(int64) :: bits(2), significand, rest, sign_exponent
        if (.not. x87_layout) then
            y = real(x, xp)
            return
        end if
        bits = transfer(x, bits)
        sign_exponent = ishft(bits(2), -48)
        ! zero, subnormal, infinite or NaN: the library's conversion
        if (iand(sign_exponent + 1_int64, int(z'7FFF', int64)) <= 1_int64) then
            y = real(x, xp)
            return
        end if
        ! the 64-bit significand with its explicit leading bit, and the 49 bits dropped
        significand = ior(top, ior(ishft(iand(bits(2), low48), 15), ishft(bits(1), -49)))
        rest = iand(bits(1), low49)
        if (rest > half .or. (rest == half .and. btest(significand, 0))) then
            significand = significand + 1_int64
            if (significand == 0_int64) then ! carried out: the next binade (or infinity)
                significand = top
                sign_exponent = sign_exponent + 1_int64
            end if
        end if
        y = transfer([significand, sign_exponent], y)
    end function hardware_real

end module brachistochrone_fast_math
