!> Small text helpers shared by the I/O modules: integer text, lowercase, escaping of
!! control characters for messages and output files, and the exact conversion of
!! decimal text to integers and to real(qp).
module brachistochrone_strings
    use, intrinsic :: iso_c_binding, only: c_char, c_null_char, c_ptr, c_null_ptr, c_float128
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
                                             ieee_negative_inf
    use, intrinsic :: iso_fortran_env, only: int64
    use brachistochrone_kinds, only: qp
    implicit none
    private

    !> Decimal text of an integer (default kind or 64-bit), without blanks.
    interface integer_text
        module procedure integer_text_default, integer_text_int64
    end interface integer_text

    public :: integer_text, put_integer, lower, escape_text, real_from_text, integer_from_text
    public :: text_ok, text_malformed, text_out_of_range

    !> `real_from_text` / `integer_from_text` status: the text is a number of the kind.
    integer, parameter :: text_ok = 0
    !> Status: the text is not a number of the kind asked for.
    integer, parameter :: text_malformed = 1
    !> Status: an integer too large for a default integer.
    integer, parameter :: text_out_of_range = 2

    !> Longest number text converted (longer texts are `text_malformed`).
    integer, parameter :: max_number_length = 4096

    interface
        !> libquadmath's correctly rounded decimal-to-binary128 conversion (the one
        !! gfortran's own `read` of a real(16) uses).
        pure function strtoflt128(text, end) bind(c, name='strtoflt128') result(x)
            import :: c_char, c_ptr, c_float128
            character(kind=c_char), intent(in) :: text(*)
            type(c_ptr), value :: end
            real(c_float128) :: x
        end function strtoflt128
    end interface

contains

    !> Decimal text of an integer, without blanks.
    pure function integer_text_default(value) result(text)
        integer, intent(in) :: value !! the integer
        character(len=:), allocatable :: text
        text = integer_text_int64(int(value, int64))
    end function integer_text_default

    !> `integer_text` for a 64-bit integer.
    pure function integer_text_int64(value) result(text)
        integer(int64), intent(in) :: value !! the integer
        character(len=:), allocatable :: text
        character(len=20) :: buffer
        integer(int64) :: rest
        integer :: k
        ! digits from the right, without internal I/O (safe and fast in parallel loops);
        ! the magnitude is taken digit by digit so that -huge - 1 works too
        k = len(buffer) + 1
        rest = value
        do
            k = k - 1
            buffer(k:k) = achar(iachar('0') + int(abs(mod(rest, 10_int64))))
            rest = rest/10_int64
            if (rest == 0_int64) exit
        end do
        if (value < 0_int64) then
            k = k - 1
            buffer(k:k) = '-'
        end if
        text = buffer(k:)
    end function integer_text_int64

    !> Append the decimal digits of `value` to buffer(length+1:) without allocation or
    !! internal I/O (safe in parallel loops); `length` grows.
    pure subroutine put_integer(value, buffer, length)
        integer, intent(in) :: value               !! the integer
        character(len=*), intent(inout) :: buffer  !! room for 11 more characters
        integer, intent(inout) :: length           !! characters used so far
        character(len=20) :: digits
        integer(int64) :: rest
        integer :: k
        k = len(digits) + 1
        rest = int(value, int64)
        do
            k = k - 1
            digits(k:k) = achar(iachar('0') + int(abs(mod(rest, 10_int64))))
            rest = rest/10_int64
            if (rest == 0_int64) exit
        end do
        if (value < 0) then
            k = k - 1
            digits(k:k) = '-'
        end if
        buffer(length + 1:length + len(digits) - k + 1) = digits(k:)
        length = length + len(digits) - k + 1
    end subroutine put_integer

    !> Lowercase copy of ASCII text.
    pure function lower(text) result(lowered)
        character(len=*), intent(in) :: text !! text
        character(len=len(text)) :: lowered
        integer :: i, code
        lowered = text
        do i = 1, len(text)
            code = iachar(text(i:i))
            if (code >= iachar('A') .and. code <= iachar('Z')) lowered(i:i) = achar(code + 32)
        end do
    end function lower

    !> `text` safe to print on one line of a terminal, a message or an output file:
    !! a backslash becomes `\\`, new line, tab and carriage return `\n`, `\t`, `\r`,
    !! every other control byte (0-31, 127), every byte that is not part of valid UTF-8,
    !! and the UTF-8 encodings of the C1 controls (U+0080-U+009F), the line and
    !! paragraph separators and the bidirectional overrides (U+2028-U+202E,
    !! U+2066-U+2069) become `\xNN` per byte. Valid UTF-8 text otherwise passes
    !! unchanged, so plain names read as written.
    pure function escape_text(text) result(escaped)
        character(len=*), intent(in) :: text !! any bytes
        character(len=:), allocatable :: escaped
        integer :: i, j, k, step, length
        length = 0
        i = 1
        do while (i <= len(text))
            call next_piece(text, i, step, k)
            length = length + k
            i = i + step
        end do
        allocate (character(len=length) :: escaped)
        i = 1
        j = 1
        do while (i <= len(text))
            call next_piece(text, i, step, k)
            escaped(j:j + k - 1) = piece(text, i, step, k)
            j = j + k
            i = i + step
        end do
    end function escape_text

    !> The piece of `text` at i: `step` bytes of input that print as `shown` bytes.
    pure subroutine next_piece(text, i, step, shown)
        character(len=*), intent(in) :: text
        integer, intent(in) :: i
        integer, intent(out) :: step, shown
        integer :: code
        code = iachar(text(i:i))
        step = 1
        if (code == 9 .or. code == 10 .or. code == 13 .or. code == 92) then
            shown = 2
        else if (code < 32 .or. code == 127) then
            shown = 4
        else if (code < 128) then
            shown = 1
        else
            step = utf8_length(text, i)
            if (step > 0) then
                shown = step
            else
                step = 1
                shown = 4
            end if
        end if
    end subroutine next_piece

    pure function piece(text, i, step, shown) result(out)
        character(len=*), intent(in) :: text
        integer, intent(in) :: i, step, shown
        character(len=shown) :: out
        character(len=*), parameter :: hex = '0123456789ABCDEF'
        integer :: code
        code = iachar(text(i:i))
        select case (code)
        case (9); out = '\t'
        case (10); out = '\n'
        case (13); out = '\r'
        case (92); out = '\\'
        case default
            if (shown == 4 .and. step == 1) then
                out = '\x'//hex(code/16 + 1:code/16 + 1)//hex(mod(code, 16) + 1:mod(code, 16) + 1)
            else
                out = text(i:i + step - 1)
            end if
        end select
    end function piece

    !> Length of the valid, printable UTF-8 sequence at i (2 to 4), or 0.
    pure integer function utf8_length(text, i) result(length)
        character(len=*), intent(in) :: text
        integer, intent(in) :: i
        integer :: lead, b2, b3, k
        length = 0
        lead = iachar(text(i:i))
        if (lead >= 194 .and. lead <= 223) then
            k = 2
        else if (lead >= 224 .and. lead <= 239) then
            k = 3
        else if (lead >= 240 .and. lead <= 244) then
            k = 4
        else
            return
        end if
        if (i + k - 1 > len(text)) return
        if (any(iachar([(text(i + b2:i + b2), b2 = 1, k - 1)]) < 128) .or. &
            any(iachar([(text(i + b2:i + b2), b2 = 1, k - 1)]) > 191)) return
        b2 = iachar(text(i + 1:i + 1))
        if (lead == 194 .and. b2 <= 159) return                        ! C1 controls
        if (lead == 224 .and. b2 < 160) return                         ! overlong
        if (lead == 237 .and. b2 > 159) return                         ! surrogates
        if (lead == 240 .and. b2 < 144) return                         ! overlong
        if (lead == 244 .and. b2 > 143) return                         ! beyond U+10FFFF
        if (k == 3 .and. lead == 226) then
            b3 = iachar(text(i + 2:i + 2))
            if (b2 == 128 .and. b3 >= 168 .and. b3 <= 174) return      ! U+2028-U+202E
            if (b2 == 129 .and. b3 >= 166 .and. b3 <= 169) return      ! U+2066-U+2069
        end if
        length = k
    end function utf8_length

    !> Convert a decimal real constant as Fortran writes it: optional sign, digits with
    !! an optional decimal point, an optional exponent (letter e, d or q, or a sign
    !! alone, then digits), or NaN, Inf, Infinity (any case, Inf/Infinity with a sign).
    !! The conversion is libquadmath's `strtoflt128`, correctly rounded and the same
    !! one gfortran's `read` uses, so `x` has exactly the bits `read(text, *) x` gives.
    !! Status `text_ok` or `text_malformed` (then `x` = 0).
    pure subroutine real_from_text(text, x, status)
        character(len=*), intent(in) :: text !! the number, no blanks
        real(qp), intent(out) :: x           !! its value
        integer, intent(out) :: status       !! text_ok or text_malformed
        character(kind=c_char) :: buffer(len(text) + 2)
        integer :: i, j, digits
        x = 0.0_qp
        status = text_malformed
        if (len(text) == 0 .or. len(text) > max_number_length) return
        i = 1
        if (text(1:1) == '+' .or. text(1:1) == '-') i = 2
        if (i > len(text)) return
        if (scan(text(i:i), 'nNiI') > 0) then
            call special_value(text, i, x, status)
            return
        end if
        ! mantissa
        digits = 0
        j = 0
        if (i == 2) then
            j = 1
            buffer(1) = text(1:1)
        end if
        call copy_digits(text, i, buffer, j, digits)
        if (i <= len(text)) then
            if (text(i:i) == '.') then
                j = j + 1
                buffer(j) = '.'
                i = i + 1
                call copy_digits(text, i, buffer, j, digits)
            end if
        end if
        if (digits == 0) return
        ! exponent: a letter e, d or q and an optional sign, or a sign alone
        if (i <= len(text)) then
            j = j + 1
            buffer(j) = 'e'
            if (scan(text(i:i), 'eEdDqQ') > 0) then
                i = i + 1
            else if (scan(text(i:i), '+-') == 0) then
                return
            end if
            if (i > len(text)) return
            if (scan(text(i:i), '+-') > 0) then
                j = j + 1
                buffer(j) = text(i:i)
                i = i + 1
            end if
            digits = 0
            call copy_digits(text, i, buffer, j, digits)
            if (digits == 0 .or. i <= len(text)) return
        end if
        buffer(j + 1) = c_null_char
        x = real(strtoflt128(buffer, c_null_ptr), qp)
        status = text_ok
    end subroutine real_from_text

    !> NaN, Inf or Infinity (any case) from position i of text (after its sign).
    pure subroutine special_value(text, i, x, status)
        character(len=*), intent(in) :: text
        integer, intent(in) :: i
        real(qp), intent(out) :: x
        integer, intent(out) :: status
        character(len=:), allocatable :: word
        x = 0.0_qp
        status = text_malformed
        word = lower(text(i:))
        if (word == 'nan' .and. i == 1) then
            x = ieee_value(x, ieee_quiet_nan)
        else if (word == 'inf' .or. word == 'infinity') then
            x = ieee_value(x, ieee_positive_inf)
            if (text(1:1) == '-') x = ieee_value(x, ieee_negative_inf)
        else
            return
        end if
        status = text_ok
    end subroutine special_value

    !> Copy the digits of word from i into buffer after j.
    pure subroutine copy_digits(word, i, buffer, j, digits)
        character(len=*), intent(in) :: word
        integer, intent(inout) :: i, j, digits
        character(kind=c_char), intent(inout) :: buffer(:)
        do while (i <= len(word))
            if (word(i:i) < '0' .or. word(i:i) > '9') exit
            j = j + 1
            buffer(j) = word(i:i)
            digits = digits + 1
            i = i + 1
        end do
    end subroutine copy_digits

    !> Convert an optionally signed decimal integer. Status `text_ok`, `text_malformed`
    !! (not an integer) or `text_out_of_range` (beyond a default integer); `value` is 0
    !! unless the status is `text_ok`.
    pure subroutine integer_from_text(text, value, status)
        character(len=*), intent(in) :: text !! the integer, no blanks
        integer, intent(out) :: value        !! its value
        integer, intent(out) :: status       !! text_ok, text_malformed or text_out_of_range
        integer :: i, first, digit
        integer, parameter :: limit = huge(1)
        logical :: negative
        value = 0
        status = text_malformed
        if (len(text) == 0) return
        first = 1
        if (text(1:1) == '+' .or. text(1:1) == '-') first = 2
        negative = text(1:1) == '-'
        if (first > len(text)) return
        if (verify(text(first:), '0123456789') /= 0) return
        status = text_ok
        do i = first, len(text)
            digit = iachar(text(i:i)) - iachar('0')
            if (value > (limit - digit)/10) then
                value = 0
                status = text_out_of_range
                return
            end if
            value = 10*value + digit
        end do
        if (negative) value = -value
    end subroutine integer_from_text

end module brachistochrone_strings
