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
!! The conversions between binary128 and x87 extended (`hardware_real`, `quad_real`) are
!! libgcc's __trunctfxf2 and __extendxftf2 in software, each as costly as a binary128
!! addition; both formats have the same 15-bit exponent, so for normal numbers they are a
!! rounding of the significand to 64 bits (to nearest, ties to even: without a branch) or
!! its extension, done here on the bits. The bits go between the integer, vector and x87
!! registers as the hardware forwards them from a store to the next load without waiting
!! for it to complete: an x87 number is read as the 8 and the 2 bytes its store wrote, a
!! binary128 or x87 number is built in a vector register from two 64-bit words (their
!! bits as real64), not stored as two words and loaded as one.
!!
!! `fast_sqrt` corrects the hardware root s of x with the residual x - s^2 exact in
!! 128-bit integers and the quotient (x - s^2)/(2 s) in hardware precision, added on the
!! bits: within 0.5 ulp and a few thousandths (test_fast_math measures it against the
!! exact residual; libquadmath's sqrtq is up to 0.75 ulp off), about 2.5 times faster
!! than the binary128 correction it replaces.
module brachistochrone_fast_math
    use brachistochrone_kinds, only: qp, xp
    use, intrinsic :: iso_fortran_env, only: real64, int64, int16
    implicit none
    private

    public :: inverse_sqrt, hardware_real, fast_sqrt, quad_real, double_real

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
    !> binary128 stored as two little-endian 64-bit words (`double_real`'s condition).
    logical, parameter :: quad_layout = quad_bits(1) == 0_int64 .and. &
        quad_bits(2) == ishft(int(z'3FFF8', int64), 44)
    logical, parameter :: x87_layout = xp /= real64 .and. digits(1.0_xp) == 64 .and. &
        storage_size(1.0_xp) == 128 .and. quad_bits(1) == 0_int64 .and. &
        quad_bits(2) == ishft(int(z'3FFF8', int64), 44) .and. &
        extended_bits(1) == ishft(3_int64, 62) .and. &
        iand(extended_bits(2), int(z'FFFF', int64)) == int(z'3FFF', int64)

    integer, parameter :: int128 = selected_int_kind(38)
    integer(int64), parameter :: low48 = shiftl(1_int64, 48) - 1_int64, &
        low49 = shiftl(1_int64, 49) - 1_int64, half_49 = shiftl(1_int64, 48), &
        top_bit = shiftl(1_int64, 63), exponent_mask = int(z'7FFF', int64)
    integer(int128), parameter :: low64 = shiftl(1_int128, 64) - 1_int128
    !> 2^52, and 1.5 2^63 whose addition rounds a number below 2^62 to an integer (its
    !! significand bits: the integer plus 1.5 2^63, modulo 2^64)
    real(xp), parameter :: two_52 = 2.0_xp**52, round_shift = 1.5_xp*2.0_xp**63
    integer(int64), parameter :: round_shift_bits = shiftl(3_int64, 62)

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

    !> sqrt(x) for x >= 0, within about an ulp (0.5 ulp and a few thousandths): where `xp`
    !! is x87 extended, the hardware square root s of x (truncated to 64 bits) and one
    !! correction (x - s^2)/(2 s), the residual exact in 128-bit integers, the quotient in
    !! hardware precision and added on the bits (`root_correction`); sqrt itself elsewhere.
    elemental function fast_sqrt(x) result(s)
        real(qp), intent(in) :: x !! non-negative argument
        real(qp) :: s
        integer(int64) :: low, high, exponent, root_bits, root_exponent, correction, fraction
        real(xp) :: root
        if (.not. x87_layout) then
            s = x
            if (x /= 0.0_qp) s = sqrt(x)
            return
        end if
        call quad_parts(x, low, high)
        exponent = shiftr(high, 48)
        ! zero, subnormal, infinite, NaN, negative: the intrinsic (zero without a call; x
        ! rebuilt from its words: its memory is read as two words only)
        if (exponent < 1_int64 .or. exponent > 32766_int64) then
            s = quad_words(low, high)
            if (s /= 0.0_qp) s = sqrt(s)
            return
        end if
        root = sqrt(extended_value(ior(top_bit, ior(shiftl(iand(high, low48), 15), &
                                                    shiftr(low, 49))), exponent))
        call extended_parts(root, root_bits, root_exponent)
        correction = root_correction(low, high, exponent, root_bits, root_exponent)
        ! the root's 63 fraction bits and the correction in their last place (above it by
        ! at most 4: its bits 49 and up); a result in another binade than the root's (root
        ! bits 2^63 + 0..3 or near 2^64): the correction in binary128
        fraction = iand(root_bits, not(top_bit))
        if (fraction >= 4_int64 .and. fraction <= huge(fraction) - 4_int64) then
            fraction = fraction + shifta(correction, 49)
            s = quad_words(ior(shiftl(fraction, 49), iand(correction, low49)), &
                           ior(shiftl(root_exponent, 48), shiftr(fraction, 15)))
        else
            s = quad_words(low, high)
            s = quad_real(root) + quad_real(hardware_real(s - quad_real(root)**2) &
                                            /(2.0_xp*root))
        end if
    end function fast_sqrt

    !> (x - s^2)/(2 s) in units of 2^-112 of s's binade, rounded to an integer (to within
    !! 0.5 and about 2^-9): x positive normal (binary128 words `low`, `high`, biased exponent
    !! `exponent`), s its hardware square root (64-bit significand `root_bits`, biased
    !! exponent `root_exponent`) to about 2^-63. x = X 2^(e-112), s = S 2^(f-63) (X, S
    !! integers, e, f unbiased): x - s^2 = (X 2^(e-2f+14) - S^2) 2^(2f-126) exactly in
    !! 128 bits (e - 2f + 14 is 13, 14 or 15; scaled by 2^-2 to stay below 2^127), below
    !! 2^-61 x: the quotient in hardware precision to 2^-63 of it, plus the dropped terms
    !! (the scalings' truncations, below 2^-10 in all; the Newton step's own error c^2/(2s),
    !! 2^-12) and a rounding to an integer.
    elemental function root_correction(low, high, exponent, root_bits, root_exponent) &
        result(correction)
        integer(int64), intent(in) :: low, high !! x's bits 0-63 and 64-127
        integer(int64), intent(in) :: exponent, root_bits, root_exponent !! see above
        integer(int64) :: correction
        integer(int128) :: scaled, residual, tail
        integer(int64) :: shift
        real(xp) :: quotient
        shift = exponent - 2_int64*root_exponent + 16383_int64 + 12_int64
        scaled = ior(shiftl(int(ior(iand(high, low48), shiftl(1_int64, 48)), int128), 64), &
                     iand(int(low, int128), low64))
        ! S^2/4 = 2^124 + 2^62 S' + S'^2/4 with S = 2^63 + S' (S'^2/4 truncated)
        tail = int(iand(root_bits, not(top_bit)), int128)
        residual = shiftl(scaled, int(shift)) - (shiftl(1_int128, 124) + shiftl(tail, 62) + &
                                                 shiftr(tail*tail, 2))
        ! in units of 2^(2f-121) (below 2^61), divided by 2 S 2^-112 = S/2 2^-110 ...
        ! (the reciprocal first: it need not wait for the residual)
        quotient = real(int(shifta(residual, 3), int64), xp) &
                   *(two_52/real(shiftr(root_bits, 1), xp))
        ! ... rounded to an integer by the hardware addition (to nearest, ties to even)
        correction = transfer(quotient + round_shift, correction) - round_shift_bits
    end function root_correction

    !> real(y, qp) on the bits for normal y where `xp` is x87 extended (the library's
    !! __extendxftf2 otherwise).
    elemental function quad_real(y) result(x)
        real(xp), intent(in) :: y !! any value
        real(qp) :: x
        integer(int64) :: significand, sign_exponent
        if (.not. x87_layout) then
            x = real(y, qp)
            return
        end if
        call extended_parts(y, significand, sign_exponent)
        ! zero, subnormal, infinite, NaN or unnormal: the library's conversion (of the
        ! same value rebuilt from the parts: y's memory is read as they were only)
        if (iand(sign_exponent + 1_int64, exponent_mask) <= 1_int64 .or. &
            significand >= 0_int64) then
            x = real(extended_value(significand, sign_exponent), qp)
            return
        end if
        x = quad_words(shiftl(significand, 49), &
                       ior(shiftl(sign_exponent, 48), shiftr(shiftl(significand, 1), 16)))
    end function quad_real

    !> real(x, xp), the same bits, faster for normal x where `xp` is x87 extended.
    elemental function hardware_real(x) result(y)
        real(qp), intent(in) :: x !! any value
        real(xp) :: y
        integer(int64) :: bits(2), significand, sign_exponent, round_up
        if (.not. x87_layout) then
            y = real(x, xp)
            return
        end if
        bits = transfer(x, bits)
        sign_exponent = shiftr(bits(2), 48)
        ! zero, subnormal, infinite or NaN: the library's conversion (of x rebuilt from
        ! its words: x's memory is read as two words only)
        if (iand(sign_exponent + 1_int64, exponent_mask) <= 1_int64) then
            y = real(quad_words(bits(1), bits(2)), xp)
            return
        end if
        ! the 64-bit significand with its explicit leading bit, plus one where the 49 bits
        ! dropped are above half its last place or half of it with that place odd (no
        ! branch: the rounding is data); a carry out of it: the next binade (or infinity)
        round_up = shiftr(iand(bits(1), low49) + (half_49 - 1_int64) + &
                          iand(shiftr(bits(1), 49), 1_int64), 49)
        significand = ior(top_bit, ior(shiftl(iand(bits(2), low48), 15), &
                                       shiftr(bits(1), 49))) + round_up
        sign_exponent = sign_exponent + merge(1_int64, 0_int64, significand == 0_int64)
        y = extended_value(ior(significand, top_bit), sign_exponent)
    end function hardware_real

    !> real(x, real64), the same bits, on the bits where the result is a normal double
    !! (libgcc's __trunctfdf2 otherwise): the 112-bit fraction rounded to 52 (to nearest,
    !! ties to even, without a branch), a carry stepping the exponent (to infinity past
    !! the largest double), the exponent rebiased; no memory between the words and the
    !! vector register.
    elemental function double_real(x) result(d)
        real(qp), intent(in) :: x !! any value
        real(real64) :: d
        integer(int64), parameter :: low60 = shiftl(1_int64, 60) - 1_int64, &
                                     half_60 = shiftl(1_int64, 59)
        integer(int64) :: low, high, exponent, round_up
        call quad_parts(x, low, high)
        exponent = iand(shiftr(high, 48), exponent_mask) - (16383_int64 - 1023_int64)
        if (exponent < 1_int64 .or. exponent > 2046_int64 .or. .not. quad_layout) then
            d = real(quad_words(low, high), real64)
            return
        end if
        round_up = shiftr(iand(low, low60) + (half_60 - 1_int64) + &
                          iand(shiftr(low, 60), 1_int64), 60)
        d = transfer(ior(iand(high, top_bit), ior(shiftl(exponent, 52), &
                         ior(shiftl(iand(high, low48), 4), shiftr(low, 60)))) + round_up, d)
    end function double_real

    !> The significand (with its explicit leading bit) and the sign and biased exponent of
    !! an x87 extended y, read as the 8 and the 2 bytes the hardware store writes (a read
    !! across them waits for the store to complete).
    elemental subroutine extended_parts(y, significand, sign_exponent)
        real(xp), intent(in) :: y !! any value (x87 layout)
        integer(int64), intent(out) :: significand !! bits 0-63
        integer(int64), intent(out) :: sign_exponent !! bits 64-79, sign at bit 15
        integer(int16) :: words(8)
        significand = transfer(y, significand)
        words = transfer(y, words)
        sign_exponent = iand(int(words(5), int64), int(z'FFFF', int64))
    end subroutine extended_parts

    !> The two 64-bit words of a binary128 x, low (bits 0-63) and high.
    elemental subroutine quad_parts(x, low, high)
        real(qp), intent(in) :: x !! any value
        integer(int64), intent(out) :: low, high !! bits 0-63 and 64-127
        integer(int64) :: words(2)
        words = transfer(x, words)
        low = words(1)
        high = words(2)
    end subroutine quad_parts

    !> The x87 extended number of these bits, built in a vector register (one 16-byte
    !! store that the hardware load can read from directly, not two).
    elemental function extended_value(significand, sign_exponent) result(y)
        integer(int64), intent(in) :: significand !! bits 0-63
        integer(int64), intent(in) :: sign_exponent !! bits 64-79 (the low 16 bits)
        real(xp) :: y
        y = transfer([transfer(significand, 1.0_real64), transfer(sign_exponent, 1.0_real64)], y)
    end function extended_value

    !> The binary128 number of these two 64-bit words, built in a vector register (the
    !! compiler passes two integer words through memory, a stall before the next load).
    elemental function quad_words(low, high) result(x)
        integer(int64), intent(in) :: low, high !! bits 0-63 and 64-127
        real(qp) :: x
        x = transfer([transfer(low, 1.0_real64), transfer(high, 1.0_real64)], x)
    end function quad_words

end module brachistochrone_fast_math
