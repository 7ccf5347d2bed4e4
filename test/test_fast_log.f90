!> `fast_log` and `fast_log1p` against libquadmath's logq and log1pq (an independent
!! implementation, within an ulp) at random arguments over the whole range and at the
!! edges of the reduction: next to 1 (both sides), powers of 2, the tables' points
!! 1 + j/128 and 1 + j/2^16, the switch at 3/2, subnormal, the largest and smallest
!! normal numbers; log1p next to its switch at +-2^-8, next to -1, tiny and huge.
module test_fast_log
    use, intrinsic :: iso_fortran_env, only: output_unit, int64
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
    use brachistochrone_kinds, only: qp
    use brachistochrone_fast_log, only: fast_log, fast_log1p
    use brachistochrone_quad_math, only: log1p
    use testing, only: check, section
    implicit none
    private

    public :: run_fast_log_tests

    !> The bound on the error, in units in the last place of the exact value (libquadmath's
    !! own error, below an ulp, included)
    real(qp), parameter :: bound_ulp = 3.0_qp

contains

    subroutine run_fast_log_tests()
        call section('fast log and log1p against libquadmath')
        call log_arguments()
        call log1p_arguments()
        call special_values()
    end subroutine run_fast_log_tests

    !> The error of y against the reference in ulps of the reference.
    elemental function ulps(y, reference) result(e)
        real(qp), intent(in) :: y, reference
        real(qp) :: e
        e = abs(y - reference)/spacing(reference)
    end function ulps

    subroutine log_arguments()
        real(qp) :: x, worst, r
        integer :: j, k, i
        worst = 0.0_qp
        ! next to 1, both sides, a few ulps and powers of 2 away
        do k = -20, 20
            x = 1.0_qp + real(k, qp)*epsilon(1.0_qp)
            if (k /= 0) worst = max(worst, ulps(fast_log(x), log(x)))
            x = 1.0_qp + real(k, qp)*0.5_qp*epsilon(1.0_qp)
            if (k /= 0) worst = max(worst, ulps(fast_log(x), log(x)))
        end do
        do j = 1, 112
            do k = -1, 1, 2
                x = 1.0_qp + real(k, qp)*2.0_qp**(-j)
                worst = max(worst, ulps(fast_log(x), log(x)))
                x = 1.0_qp + real(k, qp)*2.0_qp**(-j)*(1.0_qp + 1.0_qp/3.0_qp)
                worst = max(worst, ulps(fast_log(x), log(x)))
            end do
        end do
        ! the tables' points (1 + j/128 and its half-way points, 1 + j/2^16 next to 1
        ! and next to 1 + 64/128, the switch to c1/2) and powers of 2, +- a few ulps
        do j = 0, 256
            do k = -3, 3
                do i = -4, 30
                    x = (1.0_qp + real(j, qp)/256.0_qp)*2.0_qp**(i*i*i)
                    x = x + real(k, qp)*spacing(x)
                    worst = max(worst, ulps(fast_log(x), log(x)))
                end do
            end do
        end do
        do j = -300, 300
            do k = -2, 2
                x = 1.0_qp + real(j, qp)/65536.0_qp + real(k, qp)*2.0_qp**(-18)
                worst = max(worst, ulps(fast_log(x), log(x)))
                x = 1.5_qp + real(j, qp)/65536.0_qp + real(k, qp)*2.0_qp**(-18)
                worst = max(worst, ulps(fast_log(x), log(x)))
            end do
        end do
        ! the largest, the smallest normal and subnormal numbers
        x = huge(1.0_qp)
        worst = max(worst, ulps(fast_log(x), log(x)))
        x = tiny(1.0_qp)
        worst = max(worst, ulps(fast_log(x), log(x)))
        do j = 1, 112
            x = tiny(1.0_qp)*2.0_qp**(-j)*(1.0_qp + 1.0_qp/real(j + 2, qp))
            worst = max(worst, ulps(fast_log(x), log(x)))
        end do
        ! random significands over every binade
        do j = 1, 20000
            call random_number(r)
            k = int(r*32000.0_qp) - 16000
            call random_number(r)
            x = (1.0_qp + r)*2.0_qp**k
            worst = max(worst, ulps(fast_log(x), log(x)))
            ! and within [1/2, 2], where the sums come closest to cancelling
            call random_number(r)
            x = 0.5_qp + 1.5_qp*r
            worst = max(worst, ulps(fast_log(x), log(x)))
        end do
        write (output_unit, '(a,f6.2)') '   log: worst error in ulps: ', worst
        call check(worst <= bound_ulp, 'fast_log within 3 ulps of libquadmath''s logq')
    end subroutine log_arguments

    subroutine log1p_arguments()
        real(qp) :: x, worst, r
        integer :: j, k
        worst = 0.0_qp
        ! tiny, next to the switch at +-2^-8, next to -1, large
        do j = 1, 16494
            x = 2.0_qp**(-j)*(1.0_qp + 1.0_qp/real(j + 2, qp))
            worst = max(worst, ulps(fast_log1p(x), log1p(x)))
            worst = max(worst, ulps(fast_log1p(-x), log1p(-x)))
        end do
        do k = -6, 6
            x = 2.0_qp**(-8) + real(k, qp)*spacing(2.0_qp**(-8))
            worst = max(worst, ulps(fast_log1p(x), log1p(x)))
            worst = max(worst, ulps(fast_log1p(-x), log1p(-x)))
            x = -1.0_qp + real(abs(k) + 1, qp)*spacing(0.5_qp)
            worst = max(worst, ulps(fast_log1p(x), log1p(x)))
        end do
        do j = 1, 16383
            x = 2.0_qp**j*(1.0_qp + 1.0_qp/real(j + 2, qp))
            if (x < huge(1.0_qp)) worst = max(worst, ulps(fast_log1p(x), log1p(x)))
        end do
        ! random in (-1, 1), in (-2^-8, 2^-8), and in (0, 1e40)
        do j = 1, 20000
            call random_number(r)
            x = 2.0_qp*r - 1.0_qp
            if (x > -1.0_qp) worst = max(worst, ulps(fast_log1p(x), log1p(x)))
            x = (2.0_qp*r - 1.0_qp)*2.0_qp**(-8)
            if (x /= 0.0_qp) worst = max(worst, ulps(fast_log1p(x), log1p(x)))
            x = 10.0_qp**(40.0_qp*r)
            worst = max(worst, ulps(fast_log1p(x), log1p(x)))
        end do
        write (output_unit, '(a,f6.2)') '   log1p: worst error in ulps: ', worst
        call check(worst <= bound_ulp, 'fast_log1p within 3 ulps of libquadmath''s log1pq')
    end subroutine log1p_arguments

    !> Zero, negative and infinite arguments: the intrinsics' values.
    subroutine special_values()
        real(qp) :: zero, one
        zero = 0.0_qp
        one = 1.0_qp
        call check(fast_log(one) == 0.0_qp .and. fast_log1p(zero) == 0.0_qp, &
                   'fast_log(1) = fast_log1p(0) = 0')
        call check(fast_log(zero) < -huge(1.0_qp) .and. fast_log1p(-one) < -huge(1.0_qp), &
                   'fast_log(0) = fast_log1p(-1) = -Inf')
        call check(ieee_is_nan(fast_log(-one)) .and. ieee_is_nan(fast_log1p(-2.0_qp*one)), &
                   'fast_log(-1), fast_log1p(-2): NaN')
        call check(fast_log(huge(1.0_qp)*(one + one)) > huge(1.0_qp), 'fast_log(Inf) = Inf')
    end subroutine special_values

end module test_fast_log
