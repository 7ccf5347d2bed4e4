!> The general engine's hardware-precision slope d theta/d Lambda (at fixed r, Lambda =
!! -log R) and its error bound, on which the certified binary128 step (`final_step`)
!! rests, against binary128 central differences of theta itself (`half_arch`, the full
!! quadrature): |slope - reference| within the bound (`angle_slopes`: the bound of
!! `arch_values`, and with the endpoint's terms from binary128, `sharp_jump`), on first
!! and second half-arches from next to the apse to next to the start, R from 0.9 down to
!! 1e-30 (the whole-half-arch, far and no tables), power laws n = 1 + 1e-6 .. 32 and the
!! logarithmic law. The reference: Richardson's extrapolation of central differences at
!! steps h and h/2 in Lambda, its error taken as their difference plus the rounding of
!! theta over the step; points where that exceeds a quarter of the bound are not
!! counted (at most two thirds of them): a bound below the error at any counted point
!! fails (when written: the largest error 11-31% of `arch_values`' bound, 6-21% of
!! `sharp_jump`'s; a bound 1/5 of either fails for some law).
module test_slope_bounds
    use brachistochrone_kinds, only: qp, eps_qp
    use brachistochrone_status, only: status_ok
    use brachistochrone_speed_laws, only: speed_law, power_law, logarithmic_law
    use brachistochrone_central_force, only: central_force_model, new_central_force_model
    use testing, only: check, section
    use, intrinsic :: iso_fortran_env, only: output_unit
    implicit none
    private

    public :: run_slope_bounds_tests

contains

    subroutine run_slope_bounds_tests()
        call section('hardware-precision slopes of the certified step within their bounds')
        call check_law(power_law(n=1.000001_qp), 'power n = 1 + 1e-6')
        call check_law(power_law(n=3.0_qp), 'power n = 3')
        call check_law(power_law(n=10.0_qp), 'power n = 10')
        call check_law(power_law(n=32.0_qp), 'power n = 32')
        call check_law(logarithmic_law(), 'logarithmic')
    end subroutine run_slope_bounds_tests

    !> Every R, r between R and 1, both half-arches: the largest error over its bound
    !! (both bounds) at most 1, the reference sharp enough at a third of the points (not
    !! next to either end, where theta is singular, nor where the slope is far below
    !! theta's rounding over the step: steep laws' second half-arches at small R).
    subroutine check_law(law, name)
        class(speed_law), intent(in) :: law
        character(len=*), intent(in) :: name
        real(qp), parameter :: big_rs(6) = [0.9_qp, 0.3_qp, 0.05_qp, 1.0e-3_qp, &
                                            1.0e-8_qp, 1.0e-30_qp]
        real(qp), parameter :: fractions(8) = [1.0e-6_qp, 0.01_qp, 0.1_qp, 0.3_qp, 0.5_qp, &
                                               0.7_qp, 0.99_qp, 0.999999_qp]
        type(central_force_model) :: model
        real(qp) :: big_r, r, values(4), reference, fd_error, worst(2)
        integer :: i, j, k, status, used, skipped
        logical :: second, ok
        model = new_central_force_model(law)
        worst = 0.0_qp
        used = 0
        skipped = 0
        ok = .true.
        do i = 1, size(big_rs)
            big_r = big_rs(i)
            do j = 1, size(fractions)
                r = big_r + (1.0_qp - big_r)*fractions(j)
                do k = 1, 2
                    second = k == 2
                    call model%angle_slopes(r, big_r, second, values, status)
                    ok = ok .and. status == status_ok
                    if (status /= status_ok) cycle
                    call reference_slope(model, r, big_r, second, reference, fd_error)
                    if (.not. fd_error <= 0.25_qp*min(values(2), values(4))) then
                        skipped = skipped + 1
                        cycle
                    end if
                    used = used + 1
                    worst(1) = max(worst(1), (abs(values(1) - reference) - fd_error)/values(2))
                    worst(2) = max(worst(2), (abs(values(3) - reference) - fd_error)/values(4))
                end do
            end do
        end do
        write (output_unit, '(3a,2f8.4,a,i0,a,i0,a)') '   ', name, &
            ': largest error/bound (hardware g, h | binary128 g, h):', worst, ' (', used, &
            ' points, ', skipped, ' with a reference not sharp enough)'
        call check(ok, name//': slopes evaluated')
        call check(worst(1) <= 1.0_qp, name//': slope within its bound (arch_values)')
        call check(worst(2) <= 1.0_qp, name//': slope within its bound (sharp_jump)')
        call check(used*3 >= used + skipped, name//': reference sharp at a third of points')
    end subroutine check_law

    !> d theta/d Lambda at fixed r by central differences of theta (binary128 quadrature)
    !! at Lambda +- h and +- h/2, Richardson-extrapolated; h = 1e-7 min(1, lambda_r,
    !! delta_r) (lambda_r = log(r/R), delta_r = -log r: theta is singular at both ends);
    !! fd_error: the two steps' difference plus 8 roundings of theta and 4 of Lambda over
    !! the step.
    subroutine reference_slope(model, r, big_r, second, slope, fd_error)
        type(central_force_model), intent(in) :: model
        real(qp), intent(in) :: r, big_r
        logical, intent(in) :: second
        real(qp), intent(out) :: slope, fd_error
        real(qp) :: h, d(2), theta(2), length, time, lambda(2), size
        integer :: m, side, status
        h = 1.0e-10_qp*min(1.0_qp, log(r/big_r), -log(r))
        size = 0.0_qp
        do m = 1, 2
            do side = 1, 2
                ! R exp(-+h): Lambda +- h (the Lambdas themselves from the rounded R's)
                lambda(side) = -log(big_r) + merge(h, -h, side == 1)
                call model%half_arch(r, exp(-lambda(side)), second, theta(side), length, &
                                     time, status)
                lambda(side) = -log(exp(-lambda(side)))
                size = max(size, abs(theta(side)))
            end do
            d(m) = (theta(1) - theta(2))/(lambda(1) - lambda(2))
            h = 0.5_qp*h
        end do
        slope = (4.0_qp*d(2) - d(1))/3.0_qp
        fd_error = abs(d(2) - d(1)) + 8.0_qp*eps_qp*(size + abs(log(big_r)*slope))/h
    end subroutine reference_slope

end module test_slope_bounds
