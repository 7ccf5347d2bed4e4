!> Elementary functions in quad precision that are cheaper than the library's.
!!
!! binary128 arithmetic is done in software (a multiplication is about 180 machine
!! instructions) and `sqrt` costs about seven multiplications. The integrands need
!! 1/sqrt(q) at every node, so it is computed here from a hardware seed in the widest
!! native precision (x87 extended on x86-64: 64-bit significand, error ~5e-20) refined
!! by one Newton step, which squares the error (~4e-39, below the rounding of binary128).
!! Where no native kind wider than double exists the seed is double precision and
!! two steps r <- r (3 - q r^2)/2 are taken.
!!
!! The conversions between binary128 and x87 extended (`hardware_real`, `quad_real`) are
!! libgcc's __trunctfxf2 and __extendxftf2 in software, each as costly as a binary128
!! addition; both formats have the same 15-bit exponent, so for normal numbers they are a
!! rounding of the significand to 64 bits (to nearest, ties to even: without a branch) or
!! its extension, done here on the bits. The bits go between the integer, vector and x87
!! registers as the hardware forwards them from a store to the next load without waiting
!! for it to complete: an x87 number is read as the 8 and the 2 bytes its store wrote, a
!! binary128 or x87 number is built in a vector register from two 64-bit words (their
!! bits as real64), not stored as two words and loaded as one (where gfortran still
!! stores an x87 number's two words, its 10-byte load of them measured no slower).
!! `double_real` is libgcc's __trunctfdf2 on the bits likewise.
!!
!! `fast_sqrt` corrects the hardware root s of x with the residual x - s^2 exact in
!! 128-bit integers and the quotient (x - s^2)/(2 s) in hardware precision, added on the
!! bits; `inverse_sqrt` the hardware 1/s the same way (1 - q s exact in integers): both
!! within 0.5 ulp and a few thousandths (test_fast_math measures them against the exact
!! residuals; libquadmath's sqrtq is up to 0.75 ulp off), each about 2.5 times faster than
!! the binary128 corrections they replace.
!!
!! Assumptions (x86-64): the x87 precision control at 64 bits and rounding to nearest,
!! the defaults, which `hardware_arithmetic_ok` checks. A program linked with gfortran's
!! -mpc64 or -mpc32, or one that loads the x87 control word (fldcw, fesetround, a
!! library doing so) breaks them, and then the results are silently wrong (measured:
!! `fast_sqrt` and `fast_exp` by up to 10^22 ulp at 53 bits, `fast_sqrt` of the largest
!! numbers -Inf rounding upward; libquadmath's sqrtq, seeded by sqrtl, itself 32 ulp at
!! 53 bits and 9e18 at 24), as are the engines' pairs of x87 numbers. The conversions
!! on the bits round to nearest in every rounding mode (the library's follow it).
module brachistochrone_fast_math
    use brachistochrone_kinds, only: qp, xp
    use, intrinsic :: iso_fortran_env, only: real64, int64, int16
    implicit none
    private

    public :: inverse_sqrt, hardware_real, fast_sqrt, quad_real, double_real, &
              hardware_arithmetic_ok

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

    !> 1/sqrt(x) for x > 0, within 0.5 ulp and a few thousandths where `xp` is x87
    !! extended (within about an ulp where q is within 4 units of its last place of a power
    !! of two; 2 ulp without x87): q = 1/s from the hardware root s of x, and 1/sqrt(x) =
    !! 1/(s + c) = q (1 + (1 - q s) - c/s) to 2^-125, c the root's correction
    !! (`root_quotient`), 1 - q s exact in 128-bit integers (`inverse_correction`), the
    !! correction added on the bits.
    elemental function inverse_sqrt(x) result(r)
        real(qp), intent(in) :: x !! positive argument
        real(qp) :: r
        integer(int64) :: low, high, exponent, root_bits, root_exponent, bits, inverse_exponent
        real(xp) :: root, inverse, quotient, reciprocal
        logical :: done
        integer :: step
        if (.not. x87_layout) then
            if (x > seed_low .and. x < seed_high) then
                r = real(1.0_seed_kind/sqrt(real(x, seed_kind)), qp)
                do step = 1, newton_steps
                    r = r*(1.5_qp - 0.5_qp*x*(r*r))
                end do
            else
                r = 1.0_qp/sqrt(x)
            end if
            return
        end if
        call quad_parts(x, low, high)
        exponent = shiftr(high, 48)
        ! zero, subnormal, infinite, NaN, negative: the intrinsic
        if (exponent < 1_int64 .or. exponent > 32766_int64) then
            r = 1.0_qp/sqrt(quad_words(low, high))
            return
        end if
        root = sqrt(extended_value(ior(top_bit, ior(shiftl(iand(high, low48), 15), &
                                                    shiftr(low, 49))), exponent))
        inverse = 1.0_xp/root
        call extended_parts(root, root_bits, root_exponent)
        call extended_parts(inverse, bits, inverse_exponent)
        call root_quotient(low, high, exponent, root_bits, root_exponent, quotient, &
                           reciprocal)
        call add_on_bits(bits, inverse_exponent, nearest_integer(inverse_correction(bits, &
                         inverse_exponent, root_bits, root_exponent, quotient, reciprocal)), &
                         r, done)
        if (.not. done) then
            ! (q at the edge of its binade: r + r (1 - x r^2)/2 in binary128)
            r = quad_real(inverse)
            r = r + quad_real(0.5_xp*inverse*hardware_real(1.0_qp - quad_words(low, high) &
                                                           *(r*r)))
        end if
    end function inverse_sqrt

    !> q (1 - q s - c/s) in units of 2^-112 of q's binade: q (64-bit significand `bits` Q,
    !! biased exponent `inverse_exponent`) the hardware 1/s, s (`root_bits` S,
    !! `root_exponent`), c/s = quotient 2^-49/S. q s = Q S 2^-K (K = 126 - e - f from the
    !! unbiased exponents; 126 or 127 as q s is next to 1) and 1 - q s = (2^K - Q S) 2^-K
    !! exactly in 128 bits (Q = 2^63 + Q', S = 2^63 + S': Q S = 2^126 + 2^63 (Q' + S') +
    !! Q' S'); below 2^-63, scaled by 2^-3 into 64 bits; then (x87) Q 2^49 times the
    !! difference, below 2^51, to about 2^-12. Elsewhere (K outside): 0, and
    !! `add_on_bits` is not reached as the binade test fails (see `inverse_sqrt`).
    elemental function inverse_correction(bits, inverse_exponent, root_bits, root_exponent, &
                                          quotient, reciprocal) result(correction)
        integer(int64), intent(in) :: bits, inverse_exponent, root_bits, root_exponent
        real(xp), intent(in) :: quotient !! the root's correction (units of its last place)
        real(xp), intent(in) :: reciprocal !! 2^52/(S/2)
        real(xp) :: correction
        integer(int128) :: q_tail, s_tail, excess
        integer(int64) :: big_k
        big_k = 126_int64 + 2_int64*16383_int64 - inverse_exponent - root_exponent
        q_tail = int(iand(bits, not(top_bit)), int128)
        s_tail = int(iand(root_bits, not(top_bit)), int128)
        excess = merge(shiftl(1_int128, 126), 0_int128, big_k == 127_int64) - &
                 shiftl(q_tail + s_tail, 63) - q_tail*s_tail
        ! Q (1 - q s) 2^49 = (Q/2) (excess/8) 2^(53-K), Q c/s 2^49 = (Q/2) quotient/(S/2)
        correction = real(shiftr(bits, 1), xp)* &
                     (real(int(shifta(excess, 3), int64), xp)* &
                      merge(2.0_xp**(-74), 2.0_xp**(-73), big_k == 127_int64) - &
                      quotient*reciprocal*2.0_xp**(-52))
        if (big_k /= 126_int64 .and. big_k /= 127_int64) correction = 0.0_xp
    end function inverse_correction

    !> sqrt(x) for x >= 0, within 0.5 ulp and a few thousandths where `xp` is x87 extended
    !! (about an ulp elsewhere): the hardware square root s of x (truncated to 64 bits)
    !! and one correction (x - s^2)/(2 s), the residual exact in 128-bit integers, the
    !! quotient in hardware precision (`root_quotient`), added on the bits (`add_on_bits`;
    !! where the sum leaves s's binade, in binary128); the intrinsic for zero, subnormal,
    !! infinite, NaN or negative x.
    elemental function fast_sqrt(x) result(s)
        real(qp), intent(in) :: x !! non-negative argument
        real(qp) :: s
        integer(int64) :: low, high, exponent, root_bits, root_exponent
        real(xp) :: root, quotient, reciprocal
        logical :: done
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
        call root_quotient(low, high, exponent, root_bits, root_exponent, quotient, &
                           reciprocal)
        ! the root's significand and the correction in 2^-49 of its last place; a result
        ! in another binade than the root's: the correction in binary128
        call add_on_bits(root_bits, root_exponent, nearest_integer(quotient), s, done)
        if (.not. done) then
            ! (x below 2^-16127: x 2^256 and its root 2^128, else the residual, 2^-63 x or
            ! less, falls below x87's normal range and loses its last bits; x above
            ! 2^16127: 2^-256 and 2^-128, s^2 not to overflow where s rounds up to 2^8192)
            if (exponent < 256_int64) then
                s = 2.0_qp**(-128)*edge_root(quad_words(low, high)*2.0_qp**256, &
                                             root*2.0_xp**128)
            else if (exponent > 32766_int64 - 256_int64) then
                s = 2.0_qp**128*edge_root(quad_words(low, high)*2.0_qp**(-256), &
                                          root*2.0_xp**(-128))
            else
                s = edge_root(quad_words(low, high), root)
            end if
        end if
    end function fast_sqrt

    !> sqrt(x) from its hardware root s at the edge of a binade: s + (x - s^2)/(2 s), the
    !! residual in binary128 (x - s^2 normal in x87 extended: x above 2^-16127).
    elemental function edge_root(x, root) result(s)
        real(qp), intent(in) :: x !! positive normal argument
        real(xp), intent(in) :: root !! its hardware square root
        real(qp) :: s
        s = quad_real(root) + quad_real(hardware_real(x - quad_real(root)**2)/(2.0_xp*root))
    end function edge_root

    !> (x - s^2)/(2 s) in units of 2^-112 of s's binade (below 2^51; to about 2^-10 of a
    !! unit): x positive normal (binary128 words `low`, `high`, biased exponent
    !! `exponent`), s its hardware square root (64-bit significand `root_bits`, biased
    !! exponent `root_exponent`) to about 2^-63. x = X 2^(e-112), s = S 2^(f-63) (X, S
    !! integers, e, f unbiased): x - s^2 = (X 2^(e-2f+14) - S^2) 2^(2f-126) exactly in
    !! 128 bits (e - 2f + 14 is 13, 14 or 15; scaled by 2^-2 to stay below 2^127), below
    !! 2^-61 x: the quotient in hardware precision to 2^-63 of it, plus the dropped terms
    !! (the scalings' truncations, below 2^-10 in all; the Newton step's own error c^2/(2s),
    !! 2^-12).
    elemental subroutine root_quotient(low, high, exponent, root_bits, root_exponent, &
                                       quotient, reciprocal)
        integer(int64), intent(in) :: low, high !! x's bits 0-63 and 64-127
        integer(int64), intent(in) :: exponent, root_bits, root_exponent !! see above
        real(xp), intent(out) :: quotient !! the correction in units of s's last place
        real(xp), intent(out) :: reciprocal !! 2^52/(S/2)
        integer(int128) :: scaled, residual, tail
        integer(int64) :: shift
        shift = exponent - 2_int64*root_exponent + 16383_int64 + 12_int64
        scaled = ior(shiftl(int(ior(iand(high, low48), shiftl(1_int64, 48)), int128), 64), &
                     iand(int(low, int128), low64))
        ! S^2/4 = 2^124 + 2^62 S' + S'^2/4 with S = 2^63 + S' (S'^2/4 truncated)
        tail = int(iand(root_bits, not(top_bit)), int128)
        residual = shiftl(scaled, int(shift)) - (shiftl(1_int128, 124) + shiftl(tail, 62) + &
                                                 shiftr(tail*tail, 2))
        ! in units of 2^(2f-121) (below 2^61), divided by 2 S 2^-112 = S/2 2^-110 (the
        ! reciprocal first: it need not wait for the residual)
        reciprocal = two_52/real(shiftr(root_bits, 1), xp)
        quotient = real(int(shifta(residual, 3), int64), xp)*reciprocal
    end subroutine root_quotient

    !> Whether the hardware arithmetic of kind `xp` rounds to its full precision (x87:
    !! 64 bits) and to nearest, as this module, `brachistochrone_fast_exp` and the
    !! engines' pairs of x87 numbers assume (see the module's header): a check for a
    !! program to make once before it solves (it costs four additions).
    logical function hardware_arithmetic_ok() result(ok)
        real(xp), volatile :: one, step
        one = 1.0_xp
        step = 2.0_xp**(1 - digits(one))
        ! 1 + ulp, 1 + 3/4 ulp to 1 + ulp and 1 + 1/4 ulp to 1 (nearest), 1 - 1/2 ulp
        ! exact (2^-64 is the spacing below 1)
        ok = one + step /= one .and. one + 0.75_xp*step == one + step .and. &
             one + 0.25_xp*step == one .and. one - 0.5_xp*step /= one
    end function hardware_arithmetic_ok

    !> v (|v| < 2^62) rounded to an integer by the hardware addition of 1.5 2^63 (to
    !! nearest, ties to even), read from the sum's significand.
    elemental function nearest_integer(v) result(k)
        real(xp), intent(in) :: v !! hardware number below 2^62 in magnitude
        integer(int64) :: k
        k = transfer(v + round_shift, k) - round_shift_bits
    end function nearest_integer

    !> The binary128 number of a 64-bit significand (with its leading bit; biased exponent
    !! `exponent`, positive) plus `correction` in units of 2^-49 of its last place, or
    !! `done` false (and x zero) where the sum leaves the significand's binade (its
    !! fraction below 4 or above 2^63 - 5: the correction's bits 49 and up, at most 4).
    elemental subroutine add_on_bits(significand, exponent, correction, x, done)
        integer(int64), intent(in) :: significand, exponent, correction !! see above
        real(qp), intent(out) :: x !! the sum
        logical, intent(out) :: done !! whether it stayed in the binade
        integer(int64) :: fraction
        fraction = iand(significand, not(top_bit))
        done = fraction >= 4_int64 .and. fraction <= huge(fraction) - 4_int64
        x = 0.0_qp
        if (.not. done) return
        fraction = fraction + shifta(correction, 49)
        x = quad_words(ior(shiftl(fraction, 49), iand(correction, low49)), &
                       ior(shiftl(exponent, 48), shiftr(fraction, 15)))
    end subroutine add_on_bits

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
