!> Exact binary128-to-decimal conversion: 36 significant digits, correctly rounded,
!! in integer arithmetic: about 85 ns a value on this project's machine, 10 times faster
!! than a formatted `write` for values near 1 and 70 times for random binary128 values
!! (whose large exponents make `write` slower). `write_quad` writes into a caller's
!! buffer without allocating (for formatting rows in parallel), `format_quad` returns
!! the text.
!!
!! A finite nonzero x = m 2^e (m < 2^113 the significand, subnormals included) with
!! decimal exponent k = floor(log10 |x|) has the 36 digits D = round(|x| 10^(35-k)),
!! 10^35 <= D < 10^36. With 35 - k = 27 a + b, 0 <= b < 27:
!!
!!     |x| 10^(35-k) = m 10^b (T + f) 2^(s+e),
!!
!! where 10^(27 a) = (T + f) 2^s, T the 240-bit integer of the table
!! (`brachistochrone_decimal_powers`, exact integers from Python), 0 <= f < 1. The
!! product P = m 10^b T is formed exactly in 60-bit limbs (128-bit integer products);
!! V = P 2^(s+e) then differs from the true value by less than m 10^b 2^(s+e) < 2^-115
!! (P has at least 238 + bits(m 10^b) bits and V < 2^123), from below. D is the integer
!! part of V plus one if its fraction exceeds 1/2. Taking 62 bits of the fraction, F:
!! F <= 2^61 - 2 means the true fraction is below 1/2 and F >= 2^61 + 1 above it; the
!! two values in between (the only ones where the error could matter, among them every
!! exact tie) are handed to the library's correctly rounded conversion (formatted
!! `write`, `format_quad_by_write`), which never happens for a random value (chance
!! 2^-61) and does for exact ties such as (2^113 - 1)/8. A wrong first guess of k
!! (integer part of V outside [10^35, 10^36)) is corrected and the product retaken;
!! rounding up to 10^36 gives 10^35 and k + 1. The first guess of k comes from the
!! leading 53 bits (`decimal_exponent`), so the product is usually formed once.
!!
!! The text form is that of `format_quad_by_write`: d.ddd...e+XX with 35 digits after
!! the point and an exponent of at least two digits with its sign; zero is
!! 0.000...e+00 (-0.000...e+00 for negative zero); NaN is `NaN`, infinities `Inf` and
!! `-Inf`.
module brachistochrone_format
    use, intrinsic :: iso_fortran_env, only: int64, real64
    use brachistochrone_kinds, only: qp
    use brachistochrone_decimal_powers, only: power_step, power_limbs, power_exponent
    implicit none
    private

    public :: format_quad, write_quad, format_quad_by_write, quad_text_length

    !> Longest text of `format_quad`: sign, 36 digits, point, e, exponent sign, 4 digits.
    integer, parameter :: quad_text_length = 44

    !> 128-bit integers (a GNU extension: integer(16)).
    integer, parameter :: i16 = selected_int_kind(38)
    integer(i16), parameter :: limb_mask = 2_i16**60 - 1
    integer(i16), parameter :: half = 2_i16**61, mask62 = 2_i16**62 - 1
    integer(i16), parameter :: lowest = 10_i16**35, beyond = 10_i16**36
    integer(i16), parameter :: ten18 = 10_i16**18
    !> 35 zeros, for the text of zero.
    character(len=35), parameter :: zeros = repeat('0', 35)
    integer :: i_
    !> 10^b for b = 0 .. power_step - 1.
    integer(i16), parameter :: ten_to(0:26) = [(10_i16**i_, i_=0, 26)]
    !> The two-digit strings 00 .. 99.
    character(len=200), parameter :: pairs = &
        '00010203040506070809101112131415161718192021222324252627282930313233343536373839'// &
        '40414243444546474849505152535455565758596061626364656667686970717273747576777879'// &
        '8081828384858687888990919293949596979899'

contains

    !> x with 36 significant digits, correctly rounded (to nearest), in the form
    !! 1.84781963328078886097052679178216610e-01; reads back to the same bits.
    pure function format_quad(x) result(text)
        real(qp), intent(in) :: x !! value
        character(len=:), allocatable :: text
        character(len=quad_text_length) :: buffer
        integer :: length
        call write_quad(x, buffer, length)
        text = buffer(1:length)
    end function format_quad

    !> `format_quad` into a caller's buffer, without allocation: the text is
    !! buffer(1:length), at most `quad_text_length` characters.
    pure subroutine write_quad(x, buffer, length)
        real(qp), intent(in) :: x                  !! value
        character(len=*), intent(inout) :: buffer  !! at least quad_text_length long
        integer, intent(out) :: length             !! characters written
        integer(i16) :: bits, m, v
        integer :: biased, e, k
        logical :: negative, settled

        bits = transfer(x, 0_i16)
        negative = bits < 0
        biased = int(ibits(bits, 112, 15))
        m = iand(bits, 2_i16**112 - 1)
        length = 0
        if (negative .and. .not. (biased == 32767 .and. m /= 0)) then
            buffer(1:1) = '-'
            length = 1
        end if
        if (biased == 32767) then
            call append(merge('NaN', 'Inf', m /= 0), buffer, length)
            return
        end if
        if (biased == 0 .and. m == 0) then
            call append('0.'//zeros//'e+00', buffer, length)
            return
        end if
        if (biased == 0) then
            e = -16382 - 112
        else
            m = m + 2_i16**112
            e = biased - 16383 - 112
        end if
        call round_digits(m, e, v, k, settled)
        if (.not. settled) then
            length = 0
            call append(format_quad_by_write(x), buffer, length)
            return
        end if
        call put_digits(v, buffer(length + 1:length + 37))
        buffer(length + 38:length + 38) = 'e'
        length = length + 38
        call put_exponent(k, buffer, length)
    end subroutine write_quad

    !> buffer(length+1:) = piece; length grows.
    pure subroutine append(piece, buffer, length)
        character(len=*), intent(in) :: piece
        character(len=*), intent(inout) :: buffer
        integer, intent(inout) :: length
        buffer(length + 1:length + len(piece)) = piece
        length = length + len(piece)
    end subroutine append

    !> The 36 digits D (10^35 <= D < 10^36) and decimal exponent k of m 2^e, correctly
    !! rounded; `settled` false (D, k undefined) when the fraction is within 2^-61 of a
    !! tie, for the caller to use the library's conversion.
    pure subroutine round_digits(m, e, v, k, settled)
        integer(i16), intent(in) :: m
        integer, intent(in) :: e
        integer(i16), intent(out) :: v
        integer, intent(out) :: k
        logical, intent(out) :: settled
        integer(i16) :: fraction
        integer :: attempt
        k = decimal_exponent(m, e)
        settled = .false.
        v = 0
        do attempt = 1, 4
            call scaled(m, e, 35 - k, v, fraction)
            if (v >= beyond) then
                k = k + 1
                cycle
            end if
            if (v < lowest) then
                k = k - 1
                cycle
            end if
            if (fraction == half - 1 .or. fraction == half) return
            if (fraction > half) v = v + 1
            if (v == beyond) then
                v = lowest
                k = k + 1
            end if
            settled = .true.
            return
        end do
    end subroutine round_digits

    !> V = m 10^q 2^e split into its integer part and 62 bits of its fraction, from
    !! the table (see the module's description); the fraction may be low by 2^-115.
    pure subroutine scaled(m, e, q, v, fraction)
        integer(i16), intent(in) :: m
        integer, intent(in) :: e, q
        integer(i16), intent(out) :: v, fraction
        integer(int64) :: w(0:3), p(0:9)
        integer(i16) :: carry, column
        integer :: a, b, i, j, shift
        b = modulo(q, power_step)
        a = (q - b)/power_step
        ! w = m 10^b in four limbs of 60 bits (m < 2^113, 10^b < 2^87)
        call product_2x2(m, ten_to(b), w)
        ! p = w T: 64 x 64 -> 128-bit products (one machine multiplication each)
        carry = 0
        do j = 0, 7
            column = carry
            do i = max(0, j - 3), min(3, j)
                column = column + int(w(i), i16)*int(power_limbs(j - i + 1, a), i16)
            end do
            p(j) = int(iand(column, limb_mask), int64)
            carry = shifta(column, 60)
        end do
        p(8:9) = 0
        shift = -(e + power_exponent(a))
        v = bits_at(p, shift) + shiftl(bits_at(p, shift + 62), 62)
        fraction = bits_at(p, shift - 62)
    end subroutine scaled

    !> The product of m < 2^113 and p < 2^87 in four limbs of 60 bits.
    pure subroutine product_2x2(m, p, w)
        integer(i16), intent(in) :: m, p
        integer(int64), intent(out) :: w(0:3)
        integer(int64) :: m0, m1, p0, p1
        integer(i16) :: column
        m0 = int(iand(m, limb_mask), int64)
        m1 = int(shifta(m, 60), int64)
        p0 = int(iand(p, limb_mask), int64)
        p1 = int(shifta(p, 60), int64)
        column = int(m0, i16)*int(p0, i16)
        w(0) = int(iand(column, limb_mask), int64)
        column = shifta(column, 60) + int(m0, i16)*int(p1, i16) + int(m1, i16)*int(p0, i16)
        w(1) = int(iand(column, limb_mask), int64)
        column = shifta(column, 60) + int(m1, i16)*int(p1, i16)
        w(2) = int(iand(column, limb_mask), int64)
        w(3) = int(shifta(column, 60), int64)
    end subroutine product_2x2

    !> The 62 bits of the limb number p (60-bit limbs) from bit `position` up.
    pure function bits_at(p, position) result(bits)
        integer(int64), intent(in) :: p(0:9)
        integer, intent(in) :: position
        integer(i16) :: bits
        integer :: i, offset
        i = position/60
        offset = position - 60*i
        bits = shiftr(int(p(i), i16), offset) + shiftl(int(p(i + 1), i16), 60 - offset)
        if (offset > 58) bits = bits + shiftl(int(p(i + 2), i16), 120 - offset)
        bits = iand(bits, mask62)
    end function bits_at

    !> floor(log10(m 2^e)) for 0 < m < 2^113, or one less when log10(m 2^e) is within
    !! about 1e-6 above an integer (the caller corrects that): log2 of the leading 53 bits
    !! by the series ln(1 + t) = 2 atanh(t/(2 + t)) to five terms, which errs low by less
    !! than 2e-6, less a margin of 1e-7 for rounding, so never above the true value.
    pure function decimal_exponent(m, e) result(k)
        integer(i16), intent(in) :: m
        integer, intent(in) :: e
        integer :: k
        integer :: length, shift
        real(real64) :: t, s, s2, log2
        length = 128 - leadz(m)
        shift = max(length - 53, 0)
        t = real(int(shiftr(m, shift), int64), real64)*2.0_real64**(1 - (length - shift)) &
            - 1.0_real64
        s = t/(2.0_real64 + t)
        s2 = s*s
        log2 = (2.0_real64/log(2.0_real64))*s*(1.0_real64 + s2*(1.0_real64/3.0_real64 + &
               s2*(0.2_real64 + s2*(1.0_real64/7.0_real64 + s2/9.0_real64))))
        k = floor((real(e + length - 1, real64) + log2 - 1.0e-7_real64) &
                  *log10(2.0_real64))
    end function decimal_exponent

    !> The 36 digits of 10^35 <= v < 10^36 as d.ddd... (37 characters).
    pure subroutine put_digits(v, text)
        integer(i16), intent(in) :: v
        character(len=37), intent(out) :: text
        character(len=18) :: high_digits
        integer(int64) :: high
        high = int(v/ten18, int64)
        call put_18(int(v - int(high, i16)*ten18, int64), text(20:37))
        call put_18(high, high_digits)
        text(1:1) = high_digits(1:1)
        text(2:2) = '.'
        text(3:19) = high_digits(2:18)
    end subroutine put_digits

    !> 0 <= value < 10^18 as 18 digits with leading zeros: two independent halves of
    !! nine digits (short dependency chains), two digits at a time.
    pure subroutine put_18(value, text)
        integer(int64), intent(in) :: value
        character(len=18), intent(out) :: text
        integer(int64) :: upper
        upper = value/1000000000_int64
        call put_9(int(upper), text(1:9))
        call put_9(int(value - upper*1000000000_int64), text(10:18))
    end subroutine put_18

    !> 0 <= value < 10^9 as 9 digits with leading zeros.
    pure subroutine put_9(value, text)
        integer, intent(in) :: value
        character(len=9), intent(out) :: text
        integer :: rest, pair, i
        rest = value
        do i = 8, 2, -2
            pair = mod(rest, 100)
            rest = rest/100
            text(i:i + 1) = pairs(2*pair + 1:2*pair + 2)
        end do
        text(1:1) = achar(48 + rest)
    end subroutine put_9

    !> Append the exponent k as a sign and at least two digits after buffer(1:n); n grows.
    pure subroutine put_exponent(k, buffer, n)
        integer, intent(in) :: k
        character(len=*), intent(inout) :: buffer
        integer, intent(inout) :: n
        integer :: magnitude, width, i
        magnitude = abs(k)
        buffer(n + 1:n + 1) = merge('-', '+', k < 0)
        width = 2
        if (magnitude >= 100) width = 3
        if (magnitude >= 1000) width = 4
        do i = n + 1 + width, n + 2, -1
            buffer(i:i) = achar(48 + mod(magnitude, 10))
            magnitude = magnitude/10
        end do
        n = n + 1 + width
    end subroutine put_exponent

    !> The same text by the library's formatted `write` (es0.35e4, correctly rounded by
    !! libquadmath) and string surgery: the reference for `format_quad`, and its
    !! fallback for the rare values within 2^-61 of a rounding tie.
    pure function format_quad_by_write(x) result(text)
        real(qp), intent(in) :: x !! value
        character(len=:), allocatable :: text
        character(len=64) :: buffer
        character(len=8) :: exponent_text
        integer :: e_position, exponent
        write (buffer, '(es0.35e4)') x
        e_position = scan(buffer, 'E')
        if (e_position == 0) then
            ! gfortran writes ES0 without an exponent when it is zero; NaN and Infinity
            ! have none either
            text = trim(buffer)
            if (verify(text(1:1), '+-0123456789') == 0 .and. &
                verify(text(len(text):), '0123456789') == 0) text = text//'e+00'
            return
        end if
        read (buffer(e_position + 1:), '(i5)') exponent
        write (exponent_text, '(sp,i0.2)') exponent
        text = buffer(:e_position - 1)//'e'//trim(exponent_text)
    end function format_quad_by_write

end module brachistochrone_format
