!> The binary128-to-decimal conversion (brachistochrone_format) over 10^6 values.
!!
!! Oracles, all independent of the conversion: gfortran's own list-directed `read`
!! (every value must read back to the same bits), gfortran's formatted `write`
!! (es0.35e4, libquadmath's correctly rounded conversion: character for character on a
!! sample), exact integers written by `write (i0)` of a 128-bit integer, and the
!! published constants of quadmath.h (FLT128_MAX, FLT128_MIN, FLT128_DENORM_MIN).
module test_format
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, &
                                             ieee_positive_inf, ieee_negative_inf
    use brachistochrone_kinds, only: qp
    use brachistochrone_format, only: format_quad, format_quad_by_write
    use testing, only: check, section
    implicit none
    private

    public :: run_format_tests

    integer, parameter :: i16 = selected_int_kind(38)

    !> Counts of one family of values: read back wrong, differing from `write`, compared.
    type :: tally
        integer :: values = 0, read_back_wrong = 0, compared = 0, differ = 0
    end type tally

contains

    subroutine run_format_tests()
        type(tally) :: total
        call section('format: binary128 to 36 decimal digits')
        call special_values()
        call random_patterns(total)
        call powers(total)
        call decimals_and_integers(total)
        call check(total%values >= 1000000, 'format: at least 10^6 values tested')
        call check(total%read_back_wrong == 0, 'format: every value reads back to its bits')
        call check(total%compared >= 40000 .and. total%differ == 0, &
                   'format: the sample equals write(es0.35e4) character for character')
    end subroutine run_format_tests

    !> Zero, infinities, NaN, the extremes (quadmath.h constants) and a rounding tie.
    subroutine special_values()
        real(qp) :: tie
        call check(format_quad(0.0_qp) == '0.'//repeat('0', 35)//'e+00', 'format: zero')
        call check(format_quad(-0.0_qp) == '-0.'//repeat('0', 35)//'e+00', &
                   'format: negative zero')
        call check(format_quad(ieee_value(1.0_qp, ieee_quiet_nan)) == 'NaN', 'format: NaN')
        call check(format_quad(ieee_value(1.0_qp, ieee_positive_inf)) == 'Inf', &
                   'format: infinity')
        call check(format_quad(ieee_value(1.0_qp, ieee_negative_inf)) == '-Inf', &
                   'format: minus infinity')
        call check(format_quad(huge(1.0_qp)) == '1.18973149535723176508575932662800702e+4932', &
                   'format: FLT128_MAX')
        call check(format_quad(-tiny(1.0_qp)) == '-3.36210314311209350626267781732175260e-4932', &
                   'format: -FLT128_MIN')
        call check(format_quad(tiny(1.0_qp)*epsilon(1.0_qp)) == &
                   '6.47517511943802511092443895822764655e-4966', 'format: FLT128_DENORM_MIN')
        call check(format_quad(1.0_qp) == '1.00000000000000000000000000000000000e+00', &
                   'format: one')
        call check(format_quad(0.1_qp) == '1.00000000000000000000000000000000005e-01', &
                   'format: 0.1 (binary128 0.1000000000000000000000000000000000048...)')
        ! exact ties at the 37th digit: (2^113 - 1)/8 = 1298074214633706907132624082305023.875
        ! and (2^113 - 3)/8 = ...023.625 round to even, as libquadmath does
        tie = (2.0_qp**113 - 1.0_qp)/8.0_qp
        call check(format_quad(tie) == '1.29807421463370690713262408230502388e+33' .and. &
                   format_quad_by_write(tie) == format_quad(tie), 'format: tie ...87|5 -> 88')
        tie = (2.0_qp**113 - 3.0_qp)/8.0_qp
        call check(format_quad(tie) == '1.29807421463370690713262408230502362e+33' .and. &
                   format_quad_by_write(tie) == format_quad(tie), 'format: tie ...62|5 -> 62')
    end subroutine special_values

    !> One value: reads back to its bits; every `every`-th compared with `write`.
    subroutine try(x, every, count)
        real(qp), intent(in) :: x
        integer, intent(in) :: every
        type(tally), intent(inout) :: count
        character(len=:), allocatable :: text
        real(qp) :: y
        integer :: ios
        text = format_quad(x)
        count%values = count%values + 1
        read (text, *, iostat=ios) y
        if (ios /= 0 .or. transfer(y, 0_i16) /= transfer(x, 0_i16)) then
            count%read_back_wrong = count%read_back_wrong + 1
            if (count%read_back_wrong <= 5) print '(a)', '  does not read back: '//text
        end if
        if (mod(count%values, every) == 0) then
            count%compared = count%compared + 1
            if (text /= format_quad_by_write(x)) then
                count%differ = count%differ + 1
                if (count%differ <= 5) print '(a)', '  differs from write: '//text// &
                    ' '//format_quad_by_write(x)
            end if
        end if
    end subroutine try

    !> xorshift64: a reproducible stream of 64-bit patterns (shifts only, no overflow).
    subroutine next(state)
        integer(int64), intent(inout) :: state
        state = ieor(state, shiftl(state, 13))
        state = ieor(state, shiftr(state, 7))
        state = ieor(state, shiftl(state, 17))
    end subroutine next

    !> A random binary128 with the biased exponent in [low, high] and a random sign.
    function random_quad(state, low, high) result(x)
        integer(int64), intent(inout) :: state
        integer, intent(in) :: low, high
        real(qp) :: x
        integer(i16) :: bits, low_word
        integer :: biased
        call next(state)
        low_word = iand(int(state, i16), 2_i16**64 - 1)
        call next(state)
        bits = ior(low_word, shiftl(iand(int(state, i16), 2_i16**48 - 1), 64))
        biased = low + int(modulo(shiftr(state, 48), int(high - low + 1, int64)))
        bits = ior(bits, shiftl(int(biased, i16), 112))
        if (btest(state, 63)) bits = ibset(bits, 127)
        x = transfer(bits, 1.0_qp)
    end function random_quad

    !> Random bit patterns: all finite exponents, subnormals, the extremes.
    subroutine random_patterns(total)
        type(tally), intent(inout) :: total
        type(tally) :: count
        integer(int64) :: state
        integer :: k
        state = 88172645463325252_int64
        do k = 1, 600000
            call try(random_quad(state, 0, 32766), 50, count)
        end do
        do k = 1, 100000
            call try(random_quad(state, 0, 0), 50, count)
        end do
        do k = 1, 100000
            if (mod(k, 2) == 0) then
                call try(random_quad(state, 1, 40), 50, count)
            else
                call try(random_quad(state, 32727, 32766), 50, count)
            end if
        end do
        call report('random bit patterns (incl. 10^5 subnormals, 10^5 extremes)', &
                    count, total)
    end subroutine random_patterns

    !> Every power of two and the powers of ten, each with both neighbours.
    subroutine powers(total)
        type(tally), intent(inout) :: total
        type(tally) :: count
        real(qp) :: x
        character(len=16) :: text
        integer :: j
        do j = minexponent(1.0_qp) - digits(1.0_qp), maxexponent(1.0_qp) - 1
            x = 2.0_qp**j
            call try(x, 20, count)
            call try(nearest(x, 1.0_qp), 20, count)
            if (j > minexponent(1.0_qp) - digits(1.0_qp)) call try(nearest(x, -1.0_qp), 20, count)
        end do
        do j = -4965, 4932
            write (text, '(a,i0)') '1e', j
            read (text, *) x
            call try(x, 1, count)
            call try(nearest(x, 1.0_qp), 1, count)
            call try(nearest(x, -1.0_qp), 1, count)
        end do
        call report('powers of 2 and 10 and their neighbours', count, total)
    end subroutine powers

    !> Short decimals read by gfortran (the nearest binary128 to d e p), and integers
    !! below 2^113, whose 36 digits are exact: their own digits then zeros.
    subroutine decimals_and_integers(total)
        type(tally), intent(inout) :: total
        type(tally) :: count
        integer(int64) :: state
        integer(i16) :: n
        character(len=48) :: text
        character(len=:), allocatable :: expected
        real(qp) :: x
        integer :: k, wrong, length
        state = 2463534242_int64
        do k = 1, 50000
            call next(state)
            write (text, '(i0,a,i0)') modulo(state, 1000000_int64), 'e', &
                modulo(shiftr(state, 20), 9800_int64) - 4900
            read (text, *) x
            call try(x, 10, count)
        end do
        wrong = 0
        do k = 1, 50000
            call next(state)
            n = iand(int(state, i16), 2_i16**63 - 1)
            call next(state)
            n = shiftr(n*iand(int(state, i16), 2_i16**50 - 1), modulo(k, 100))
            x = real(n, qp)
            call try(x, 10, count)
            write (text, '(i0)') n
            length = len_trim(text)
            expected = text(1:1)//'.'//text(2:length)//repeat('0', 36 - length)//'e+'
            if (length <= 10) expected = expected//'0'
            write (text, '(i0)') length - 1
            expected = expected//trim(text)
            if (n > 0 .and. format_quad(x) /= expected) wrong = wrong + 1
        end do
        call check(wrong == 0, 'format: integers below 2^113 give their own digits')
        call report('short decimals and integers', count, total)
    end subroutine decimals_and_integers

    subroutine report(name, count, total)
        character(len=*), intent(in) :: name
        type(tally), intent(in) :: count
        type(tally), intent(inout) :: total
        print '(a,i0,a,i0,a,i0,a)', '  '//name//': ', count%values, ' values, ', &
            count%read_back_wrong, ' not read back, ', count%differ, ' differ from write'
        total%values = total%values + count%values
        total%read_back_wrong = total%read_back_wrong + count%read_back_wrong
        total%compared = total%compared + count%compared
        total%differ = total%differ + count%differ
    end subroutine report

end module test_format
