!> Exact binary128-to-decimal conversion: 36 significant digits, correctly rounded,
!! in integer arithmetic, about 30 times faster than a formatted `write`.
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
!! rounding up to 10^36 gives 10^35 and k + 1.
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

    public :: format_quad, format_quad_by_write

    !> 128-bit integers (a GNU extension: integer(16)).
    integer, parameter :: i16 = selected_int_kind(38)
    integer(i16), parameter :: limb_mask = 2_i16**60 - 1
    integer(i16), parameter :: half = 2_i16**61, mask62 = 2_i16**62 - 1
    integer(i16), parameter :: lowest = 10_i16**35, beyond = 10_i16**36
    integer(i16), parameter :: ten18 = 10_i16**18
    !> 35 zeros, for the text of zero.
    character(len=35), parameter :: zeros = repeat('0', 35)

contains

    !> x with 36 significant digits, correctly rounded (to nearest), in the form
    !! 1.84781963328078886097052679178216610e-01; reads back to the same bits.
    pure function format_quad(x) result(text)
        real(qp), intent(in) :: x !! value
        character(len=:), allocatable :: text
        integer(i16) :: bits, m, v, fraction
        integer :: biased, e, k, attempt
        logical :: negative, settled
        character(len=48) :: buffer
        integer :: n

        bits = transfer(x, 0_i16)
        negative = bits < 0
        biased = int(ibits(bits, 112, 15))
        m = iand(bits, 2_i16**112 - 1)
        if (biased == 32767) then
            if (m /= 0) then
                text = 'NaN'
            else
                text = merge('-Inf', ' Inf', negative)
                text = trim(adjustl(text))
            end if
            return
        end if
        if (biased == 0 .and. m == 0) then
            text = '0.'//zeros//'e+00'
            if (negative) text = '-'//text
            return
        end if
        if (biased == 0) then
            e = -16382 - 112
        else
            m = m + 2_i16**112
            e = biased - 16383 - 112
        end if
        k = floor(log10(real(m, real64)) + real(e, real64)*log10(2.0_real64))
        settled = .false.
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
            if (fraction == half - 1 .or. fraction == half) exit
            if (fraction > half) v = v + 1
            if (v == beyond) then
                v = lowest
                k = k + 1
            end if
            settled = .true.
            exit
        end do
        if (.not. settled) then
            text = format_quad_by_write(x)
            return
        end if
        n = 0
        if (negative) then
            buffer(1:1) = '-'
            n = 1
        end if
        call put_digits(v, buffer(n + 1:n + 37))
        n = n + 37
        buffer(n + 1:n + 1) = 'e'
        n = n + 1
        call put_exponent(k, buffer, n)
        text = buffer(1:n)
    end function format_quad

    !> V = m 10^q 2^e split into its integer part and 62 bits of its fraction, from
    !! the table (see the module's description); the fraction may be low by 2^-115.
    pure subroutine scaled(m, e, q, v, fraction)
        integer(i16), intent(in) :: m
        integer, intent(in) :: e, q
        integer(i16), intent(out) :: v, fraction
        integer(i16) :: power, w(0:3), t(0:3), p(0:9), carry, column
        integer :: a, b, i, j, shift
        b = modulo(q, power_step)
        a = (q - b)/power_step
        power = 10_i16**b
        ! w = m 10^b in four limbs of 60 bits (m < 2^113, 10^b < 2^87)
        call product_2x2(m, power, w)
        t = int(power_limbs(:, a), i16)
        carry = 0
        do j = 0, 7
            column = carry
            do i = max(0, j - 3), min(3, j)
                column = column + w(i)*t(j - i)
            end do
            p(j) = iand(column, limb_mask)
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
        integer(i16), intent(out) :: w(0:3)
        integer(i16) :: m0, m1, p0, p1, column
        m0 = iand(m, limb_mask)
        m1 = shifta(m, 60)
        p0 = iand(p, limb_mask)
        p1 = shifta(p, 60)
        column = m0*p0
        w(0) = iand(column, limb_mask)
        column = shifta(column, 60) + m0*p1 + m1*p0
        w(1) = iand(column, limb_mask)
        column = shifta(column, 60) + m1*p1
        w(2) = iand(column, limb_mask)
        w(3) = shifta(column, 60)
    end subroutine product_2x2

    !> The 62 bits of the limb number p (60-bit limbs) from bit `position` up.
    pure function bits_at(p, position) result(bits)
        integer(i16), intent(in) :: p(0:9)
        integer, intent(in) :: position
        integer(i16) :: bits
        integer :: i, offset
        i = position/60
        offset = position - 60*i
        bits = shiftr(p(i), offset) + shiftl(p(i + 1), 60 - offset)
        if (offset > 58) bits = bits + shiftl(p(i + 2), 120 - offset)
        bits = iand(bits, mask62)
    end function bits_at

    !> The 36 digits of 10^35 <= v < 10^36 as d.ddd... (37 characters).
    pure subroutine put_digits(v, text)
        integer(i16), intent(in) :: v
        character(len=37), intent(out) :: text
        integer(int64) :: high, low
        integer :: i
        high = int(v/ten18, int64)
        low = int(v - int(high, i16)*ten18, int64)
        do i = 37, 20, -1
            text(i:i) = achar(48 + int(mod(low, 10_int64)))
            low = low/10_int64
        end do
        do i = 19, 3, -1
            text(i:i) = achar(48 + int(mod(high, 10_int64)))
            high = high/10_int64
        end do
        text(1:1) = achar(48 + int(high))
        text(2:2) = '.'
    end subroutine put_digits

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
