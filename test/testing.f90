!> Minimal assertion helpers: counts, readable failures, the closing summary line.
module testing
    use, intrinsic :: iso_fortran_env, only: output_unit
    use brachistochrone_kinds, only: qp, eps_qp
    implicit none
    private

    public :: check, check_close, check_digits, summary, section, digits_of_agreement

    integer, save :: passed = 0
    integer, save :: failed = 0

contains

    !> Start a named group of checks.
    subroutine section(name)
        character(len=*), intent(in) :: name !! group name
        write (output_unit, '(a)') '== '//name
    end subroutine section

    !> Record one check.
    subroutine check(condition, name)
        logical, intent(in) :: condition   !! must hold
        character(len=*), intent(in) :: name !! what is checked
        if (condition) then
            passed = passed + 1
        else
            failed = failed + 1
            write (output_unit, '(a)') 'FAIL '//name
        end if
    end subroutine check

    !> |actual - expected| <= tolerance_in_eps * eps * max(|expected|, floor).
    subroutine check_close(actual, expected, tolerance_in_eps, name, floor)
        real(qp), intent(in) :: actual, expected !! values compared
        real(qp), intent(in) :: tolerance_in_eps !! tolerance in units of epsilon(1.0_qp)
        character(len=*), intent(in) :: name     !! what is checked
        real(qp), intent(in), optional :: floor  !! scale used when |expected| is small
        real(qp) :: scale
        logical :: ok
        scale = abs(expected)
        if (present(floor)) scale = max(scale, floor)
        ok = abs(actual - expected) <= tolerance_in_eps*eps_qp*scale
        call check(ok, name)
        if (ok) return
        call show_values(actual, expected)
        write (output_unit, '(a,es10.3,a,es10.3)') '   rel error', &
            abs(actual - expected)/max(scale, tiny(1.0_qp)), ' > ', tolerance_in_eps*eps_qp
    end subroutine check_close

    !> Significant digits to which actual matches expected.
    pure function digits_of_agreement(actual, expected) result(digits)
        real(qp), intent(in) :: actual, expected
        real(qp) :: digits
        if (actual == expected) then
            digits = 36.0_qp
        else
            digits = -log10(abs(actual - expected)/abs(expected))
        end if
    end function digits_of_agreement

    !> actual agrees with expected to at least `digits` significant digits.
    subroutine check_digits(actual, expected, digits, name)
        real(qp), intent(in) :: actual, expected !! values compared
        real(qp), intent(in) :: digits           !! required significant digits
        character(len=*), intent(in) :: name     !! what is checked
        real(qp) :: have
        have = digits_of_agreement(actual, expected)
        call check(have >= digits, name)
        if (have >= digits) return
        call show_values(actual, expected)
        write (output_unit, '(a,f6.2,a,f6.2)') '   digits   ', have, ' < ', digits
    end subroutine check_digits

    !> The two values of a failed comparison.
    subroutine show_values(actual, expected)
        real(qp), intent(in) :: actual, expected
        write (output_unit, '(a,es44.35e4)') '   actual   ', actual
        write (output_unit, '(a,es44.35e4)') '   expected ', expected
    end subroutine show_values

    !> Print `N passed, N failed` and return the exit code (0 when nothing failed).
    function summary() result(code)
        integer :: code
        character(len=32) :: p, f
        write (p, '(i0)') passed
        write (f, '(i0)') failed
        write (output_unit, '(a)') trim(p)//' passed, '//trim(f)//' failed'
        code = merge(0, 1, failed == 0)
    end function summary

end module testing
