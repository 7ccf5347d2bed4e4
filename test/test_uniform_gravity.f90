!> Uniform gravity: the cycloid through B against an independent mpmath reference, its
!! round trip, limits and bad endpoints; the isochrone and joined half-arches by
!! quadrature against their closed forms; the pendulum period against mpmath, its
!! small-amplitude series, its quadrature and its logarithmic limit.
module test_uniform_gravity
    use, intrinsic :: iso_fortran_env, only: output_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
                                             ieee_is_finite
    use brachistochrone_kinds, only: qp, pi, eps_qp
    use brachistochrone_status, only: status_ok, status_not_finite, status_no_convergence, &
                                      status_above_start, status_parameter_out_of_range, &
                                      status_word
    use brachistochrone_uniform_gravity, only: uniform_brachistochrone, cycloid_point, &
            isochrone_time, isochrone_time_quadrature, joined_arches_period, &
            joined_arches_period_quadrature, complete_elliptic_k, pendulum_period, &
            pendulum_period_quadrature
    use reference_tables, only: csv_table, read_reference
    use testing, only: check, check_close, check_digits, section, digits_of_agreement
    implicit none
    private

    public :: run_uniform_gravity_tests

    !> Standard gravity (m/s^2), used where g does not matter.
    real(qp), parameter :: gravity = 9.80665_qp

contains

    !> Every uniform-gravity test group.
    subroutine run_uniform_gravity_tests()
        call round_trip_tests()
        call brachistochrone_reference_tests()
        call asymptotic_tests()
        call limit_tests()
        call bad_endpoint_tests()
        call isochrone_tests()
        call joined_arches_tests()
        call pendulum_reference_tests()
        call pendulum_property_tests()
        call pendulum_status_tests()
    end subroutine run_uniform_gravity_tests

    !> Relative error in units of eps.
    pure function error_in_eps(actual, expected) result(e)
        real(qp), intent(in) :: actual, expected
        real(qp) :: e
        e = abs(actual - expected)/(eps_qp*abs(expected))
    end function error_in_eps

    !> The cycloid through B passes through B: x_B/y_B = 10^(k/8), k = -96..96, both with
    !! y_B = 1 and with x_B = 1, and a few far beyond.
    subroutine round_trip_tests()
        real(qp) :: ratio, x_b, y_b, phi, radius, time, arclength, deficit, x, y, worst
        real(qp), parameter :: far(6) = [1.0e-300_qp, 1.0e-100_qp, 1.0e-30_qp, &
                                         1.0e30_qp, 1.0e100_qp, 1.0e300_qp]
        integer :: k, scaling, status, failures
        call section('uniform gravity: the cycloid through B reproduces B')
        worst = 0.0_qp
        failures = 0
        do scaling = 1, 2
            do k = -96, 96
                ratio = 10.0_qp**(real(k, qp)/8.0_qp)
                if (scaling == 1) then
                    x_b = ratio
                    y_b = 1.0_qp
                else
                    x_b = 1.0_qp
                    y_b = 1.0_qp/ratio
                end if
                call one(x_b, y_b)
            end do
        end do
        write (output_unit, '(a,f6.2,a)') '   x_B/y_B = 1e-12 .. 1e12 (386 endpoints): ' // &
            'worst |x - x_B|, |y - y_B| ', worst, ' eps (relative)'
        call check(failures == 0, 'every endpoint with x_B/y_B in [1e-12, 1e12] solved')
        call check(worst <= 8.0_qp, 'cycloid through B reproduces x_B, y_B to 8 eps')
        worst = 0.0_qp
        do k = 1, size(far)
            call one(far(k), 1.0_qp)
            call one(1.0_qp, 1.0_qp/far(k))
        end do
        ! x_B/y_B = 1e4000 overflows (never formed); x_B/y_B = 1e-2000 gives a = 2e3999
        call one(1.0e2000_qp, 1.0e-2000_qp)
        call one(1.0e-2000_qp, 1.0_qp)
        ! both coordinates near the ends of the exponent range (a = 0.66e4932 for the
        ! largest: y_B/sin(phi/2) alone would overflow)
        call one(1.0e4900_qp, 1.0e4900_qp)
        call one(3.0e4900_qp, 1.0e4900_qp)
        call one(1.0e4932_qp, 1.1e4932_qp)
        call one(1.0e-4900_qp, 1.0e-4900_qp)
        call one(3.0e-4900_qp, 1.0e-4900_qp)
        write (output_unit, '(a,f6.2,a)') '   x_B/y_B = 1e-2000 .. 1e4000, x_B, y_B up to ' // &
            '1.1e4932 and down to 1e-4900: worst ', worst, &
            ' eps'
        call check(failures == 0, 'extreme ratios solved')
        call check(worst <= 8.0_qp, 'extreme ratios reproduce x_B, y_B to 8 eps')
    contains
        subroutine one(x_in, y_in)
            real(qp), intent(in) :: x_in, y_in
            call uniform_brachistochrone(x_in, y_in, gravity, phi, radius, time, arclength, &
                                         status, deficit)
            if (status /= status_ok) then
                failures = failures + 1
                return
            end if
            call cycloid_point(radius, phi, x, y, status, deficit)
            if (status /= status_ok) then
                failures = failures + 1
                return
            end if
            worst = max(worst, error_in_eps(x, x_in), error_in_eps(y, y_in))
        end subroutine one
    end subroutine round_trip_tests

    !> phi, 2 pi - phi, a, t, s against mpmath's plain formulas at 60+ digits.
    subroutine brachistochrone_reference_tests()
        type(csv_table) :: reference
        logical :: ok
        integer :: i, j, status, failures
        real(qp) :: values(5), expected(5), digits(5), fewest(5), x_b, y_b, g
        character(len=*), parameter :: names(5) = ['phi    ', 'deficit', 'a      ', &
                                                   't      ', 's      ']
        call section('uniform gravity: phi, a, t, s against the mpmath reference')
        call read_reference('data/reference/uniform_brachistochrone_mpmath.csv', 80, &
                            reference, ok)
        if (.not. ok) return
        fewest = 99.0_qp
        failures = 0
        do i = 1, reference%row_count()
            x_b = reference%real_value(i, 'x')
            y_b = reference%real_value(i, 'y')
            g = reference%real_value(i, 'g')
            call uniform_brachistochrone(x_b, y_b, g, values(1), values(3), values(4), &
                                         values(5), status, values(2))
            if (status /= status_ok) then
                failures = failures + 1
                cycle
            end if
            do j = 1, 5
                expected(j) = reference%real_value(i, trim(names(j)))
                digits(j) = digits_of_agreement(values(j), expected(j))
            end do
            if (minval(digits) < 32.0_qp) write (output_unit, '(a,i0,a,5f7.2)') '   row ', &
                i, ' digits phi, deficit, a, t, s:', digits
            fewest = min(fewest, digits)
        end do
        write (output_unit, '(a,i0,a,5f7.2)') '   ', reference%row_count(), &
            ' endpoints (x_B/y_B = 1e-30 .. 1e30); fewest digits phi, 2pi-phi, a, t, s:', &
            fewest
        call check(failures == 0, 'every reference endpoint solved')
        do j = 1, 5
            call check(fewest(j) >= 32.0_qp, trim(names(j))//' to >= 32 digits everywhere')
        end do
    end subroutine brachistochrone_reference_tests

    !> The expansions at both ends: phi = 3r - 9r^3/10 + O(r^5) as r = x_B/y_B -> 0, and
    !! 2 pi - phi = 2 sqrt(pi w)(1 + pi w/6 + O(w^(3/2))) as w = y_B/x_B -> 0.
    subroutine asymptotic_tests()
        real(qp) :: phi, radius, time, arclength, deficit, r, w
        integer :: status
        call section('uniform gravity: phi_B at both ends of x_B/y_B')
        r = 1.0e-13_qp
        call uniform_brachistochrone(r, 1.0_qp, gravity, phi, radius, time, arclength, status)
        call check_close(phi, 3.0_qp*r - 0.9_qp*r**3, 4.0_qp, 'x_B/y_B = 1e-13: phi = 3r')
        r = 1.0e-4000_qp
        call uniform_brachistochrone(r, 1.0_qp, gravity, phi, radius, time, arclength, status)
        call check_close(phi, 3.0_qp*r, 4.0_qp, 'x_B/y_B = 1e-4000: phi = 3r')
        call check(.not. ieee_is_finite(radius) .and. radius > 0.0_qp, &
                   'x_B/y_B = 1e-4000: a beyond range is +Inf')
        call check_close(time, sqrt(2.0_qp/gravity), 4.0_qp, 'x_B/y_B = 1e-4000: t = free fall')
        w = 1.0e-26_qp
        call uniform_brachistochrone(1.0_qp, w, gravity, phi, radius, time, arclength, status, &
                                     deficit)
        call check_close(deficit, 2.0_qp*sqrt(pi*w)*(1.0_qp + pi*w/6.0_qp), 4.0_qp, &
                         'y_B/x_B = 1e-26: 2 pi - phi = 2 sqrt(pi w)(1 + pi w/6)')
        call uniform_brachistochrone(1.0e2000_qp, 1.0e-2000_qp, gravity, phi, radius, time, &
                                     arclength, status, deficit)
        call check_close(deficit, 2.0_qp*sqrt(pi)*1.0e-2000_qp, 4.0_qp, &
                         'y_B/x_B = 1e-4000: 2 pi - phi = 2 sqrt(pi w)')
    end subroutine asymptotic_tests

    !> Free fall, B = A, the complete arch (Saitoh's t = sqrt(2 pi l/g)) and continuity
    !! of the cycloid into both limits.
    subroutine limit_tests()
        real(qp) :: phi, radius, time, arclength, deficit, t_limit
        integer :: status
        call section('uniform gravity: free fall, B = A, complete arch')
        call uniform_brachistochrone(0.0_qp, 2.5_qp, 1.62_qp, phi, radius, time, arclength, &
                                     status, deficit)
        call check(status == status_ok .and. phi == 0.0_qp .and. radius == 0.0_qp, &
                   'x_B = 0: free fall, phi = 0, a reported as 0')
        call check_close(time, sqrt(2.0_qp*2.5_qp/1.62_qp), 4.0_qp, &
                         'x_B = 0: t = sqrt(2 y_B/g)')
        call check_close(arclength, 2.5_qp, 0.0_qp, 'x_B = 0: s = y_B')
        call check_close(deficit, 2.0_qp*pi, 0.0_qp, 'x_B = 0: 2 pi - phi = 2 pi')
        t_limit = time
        call uniform_brachistochrone(1.0e-40_qp, 2.5_qp, 1.62_qp, phi, radius, time, &
                                     arclength, status)
        call check_close(time, t_limit, 4.0_qp, 'x_B -> 0: t -> sqrt(2 y_B/g)')
        call check_close(arclength, 2.5_qp, 4.0_qp, 'x_B -> 0: s -> y_B')

        call uniform_brachistochrone(0.0_qp, 0.0_qp, gravity, phi, radius, time, arclength, &
                                     status)
        call check(status == status_ok .and. phi == 0.0_qp .and. radius == 0.0_qp .and. &
                   time == 0.0_qp .and. arclength == 0.0_qp, 'B = A: t = s = 0')

        call uniform_brachistochrone(3.0_qp, 0.0_qp, 1.62_qp, phi, radius, time, arclength, &
                                     status, deficit)
        call check(status == status_ok .and. deficit == 0.0_qp, &
                   'y_B = 0: the complete arch, 2 pi - phi = 0')
        call check_close(phi, 2.0_qp*pi, 0.0_qp, 'complete arch: phi = 2 pi')
        call check_close(radius, 3.0_qp/(2.0_qp*pi), 2.0_qp, 'complete arch: a = x_B/(2 pi)')
        call check_close(time, sqrt(2.0_qp*pi*3.0_qp/1.62_qp), 4.0_qp, &
                         'complete arch: t = sqrt(2 pi l/g) (Saitoh)')
        call check_close(arclength, 4.0_qp*3.0_qp/pi, 4.0_qp, 'complete arch: s = 8a = 4l/pi')
        t_limit = time
        call uniform_brachistochrone(3.0_qp, 1.0e-80_qp, 1.62_qp, phi, radius, time, &
                                     arclength, status, deficit)
        call check_close(time, t_limit, 4.0_qp, 'y_B -> 0: t -> sqrt(2 pi l/g)')
        call check_close(arclength, 4.0_qp*3.0_qp/pi, 4.0_qp, 'y_B -> 0: s -> 4l/pi')
    end subroutine limit_tests

    !> Every bad input gets its status and zero outputs.
    subroutine bad_endpoint_tests()
        real(qp) :: nan, inf
        call section('uniform gravity: bad endpoints and parameters')
        nan = ieee_value(nan, ieee_quiet_nan)
        inf = ieee_value(inf, ieee_positive_inf)
        call expect(1.0_qp, -1.0e-30_qp, gravity, status_above_start, 'y_B < 0: B above A')
        call expect(0.0_qp, -2.0_qp, gravity, status_above_start, 'x_B = 0, y_B < 0: above A')
        call expect(-1.0_qp, 1.0_qp, gravity, status_parameter_out_of_range, 'x_B < 0')
        call expect(1.0_qp, 1.0_qp, 0.0_qp, status_parameter_out_of_range, 'g = 0')
        call expect(1.0_qp, 1.0_qp, -9.8_qp, status_parameter_out_of_range, 'g < 0')
        call expect(nan, 1.0_qp, gravity, status_not_finite, 'x_B NaN')
        call expect(1.0_qp, nan, gravity, status_not_finite, 'y_B NaN')
        call expect(1.0_qp, inf, gravity, status_not_finite, 'y_B infinite')
        call expect(-inf, 1.0_qp, gravity, status_not_finite, 'x_B -infinite')
        call expect(1.0_qp, 1.0_qp, nan, status_not_finite, 'g NaN')
        call expect(1.0_qp, 1.0_qp, inf, status_not_finite, 'g infinite')
        call point_expect(-1.0_qp, 1.0_qp, status_parameter_out_of_range, 'point: a < 0')
        call point_expect(1.0_qp, 7.0_qp, status_parameter_out_of_range, 'point: phi > 2 pi')
        call point_expect(nan, 1.0_qp, status_not_finite, 'point: a NaN')
        call check(status_word(status_above_start) == 'above_start', 'status word above_start')
    contains
        subroutine expect(x_b, y_b, g, code, name)
            real(qp), intent(in) :: x_b, y_b, g
            integer, intent(in) :: code
            character(len=*), intent(in) :: name
            real(qp) :: phi, radius, time, arclength, deficit
            integer :: status
            call uniform_brachistochrone(x_b, y_b, g, phi, radius, time, arclength, status, &
                                         deficit)
            call check(status == code .and. phi == 0.0_qp .and. radius == 0.0_qp .and. &
                       time == 0.0_qp .and. arclength == 0.0_qp .and. deficit == 0.0_qp, &
                       name//': '//status_word(code)//', outputs 0')
        end subroutine expect
        subroutine point_expect(radius, phi, code, name)
            real(qp), intent(in) :: radius, phi
            integer, intent(in) :: code
            character(len=*), intent(in) :: name
            real(qp) :: x, y
            integer :: status
            call cycloid_point(radius, phi, x, y, status)
            call check(status == code .and. x == 0.0_qp .and. y == 0.0_qp, &
                       name//': '//status_word(code)//', outputs 0')
        end subroutine point_expect
    end subroutine bad_endpoint_tests

    !> Tee's eq. (3)-(4) integrated numerically equals pi sqrt(alpha/g) for every release
    !! height h in (0, 2 alpha].
    subroutine isochrone_tests()
        real(qp), parameter :: alphas(3) = [1.0_qp, 0.37_qp, 250.0_qp]
        real(qp), parameter :: gravities(3) = [9.80665_qp, 1.62_qp, 24.79_qp]
        real(qp) :: closed, numeric, height, fewest
        integer :: i, j, status, failures, cases
        call section('uniform gravity: isochrone, Tee (3)-(4) by quadrature')
        fewest = 99.0_qp
        failures = 0
        cases = 0
        do i = 1, size(alphas)
            call isochrone_time(alphas(i), gravities(i), closed, status)
            call check(status == status_ok, 'isochrone closed form solved')
            do j = -20, 40
                if (j <= 0) then
                    height = 2.0_qp*alphas(i)*10.0_qp**j      ! 2 alpha .. 2e-20 alpha
                else
                    height = 2.0_qp*alphas(i)*real(j, qp)/40.0_qp
                end if
                call isochrone_time_quadrature(alphas(i), gravities(i), height, numeric, &
                                               status)
                cases = cases + 1
                if (status /= status_ok) then
                    failures = failures + 1
                    cycle
                end if
                fewest = min(fewest, digits_of_agreement(numeric, closed))
            end do
        end do
        write (output_unit, '(a,i0,a,f6.2)') '   ', cases, &
            ' release heights (2e-20 alpha .. 2 alpha): fewest digits ', fewest
        call check(failures == 0, 'isochrone quadrature converged for every height')
        call check(fewest >= 32.0_qp, 'isochrone quadrature = pi sqrt(alpha/g) to 32 digits')
        call isochrone_time(4.0_qp, 4.0_qp, closed, status)
        call check_close(closed, pi, 1.0_qp, 'isochrone: alpha = g gives pi')
        call isochrone_time_quadrature(1.0_qp, gravity, 0.0_qp, numeric, status)
        call check(status == status_parameter_out_of_range .and. numeric == 0.0_qp, &
                   'isochrone: h = 0 refused')
        call isochrone_time_quadrature(1.0_qp, gravity, 2.0_qp*(1.0_qp + eps_qp), numeric, status)
        call check(status == status_parameter_out_of_range, 'isochrone: h > 2 alpha refused')
        call isochrone_time(-1.0_qp, gravity, closed, status)
        call check(status == status_parameter_out_of_range .and. closed == 0.0_qp, &
                   'isochrone: alpha < 0 refused')
    end subroutine isochrone_tests

    !> Two half-arches joined at their bases: sum of quarter-period quadratures equals
    !! 2 pi (sqrt(alpha) + sqrt(beta))/sqrt(g) (Tee, section 1.2.2).
    subroutine joined_arches_tests()
        real(qp), parameter :: alphas(4) = [1.0_qp, 1.0_qp, 3.0_qp, 0.02_qp]
        real(qp), parameter :: betas(4) = [0.5_qp, 1.0_qp, 0.125_qp, 7.5_qp]
        real(qp) :: closed, numeric, fewest, lowest
        integer :: i, j, status, failures
        call section('uniform gravity: joined half-arches (Tee 1.2.2)')
        fewest = 99.0_qp
        failures = 0
        do i = 1, size(alphas)
            call joined_arches_period(alphas(i), betas(i), gravity, closed, status)
            call check(status == status_ok, 'joined arches closed form solved')
            lowest = 2.0_qp*min(alphas(i), betas(i))
            do j = 1, 20
                call joined_arches_period_quadrature(alphas(i), betas(i), gravity, &
                                                     lowest*real(j, qp)/20.0_qp, numeric, &
                                                     status)
                if (status /= status_ok) then
                    failures = failures + 1
                    cycle
                end if
                fewest = min(fewest, digits_of_agreement(numeric, closed))
            end do
        end do
        write (output_unit, '(a,f6.2)') '   4 pairs x 20 amplitudes: fewest digits ', fewest
        call check(failures == 0, 'joined arches quadrature converged')
        call check(fewest >= 32.0_qp, 'joined arches: 2(T_alpha + T_beta) = closed form, ' // &
                   '32 digits')
        call joined_arches_period(1.0_qp, 1.0_qp, 1.0_qp, closed, status)
        call check_close(closed, 4.0_qp*pi, 1.0_qp, 'equal half-arches: 4 pi sqrt(alpha/g)')
        call joined_arches_period_quadrature(1.0_qp, 0.5_qp, gravity, 1.5_qp, numeric, status)
        call check(status == status_parameter_out_of_range, &
                   'joined arches: h above the smaller arch refused')
    end subroutine joined_arches_tests

    !> The AGM period against mpmath (ellipk and 2F1 at 150 digits).
    subroutine pendulum_reference_tests()
        type(csv_table) :: reference
        logical :: ok
        integer :: i, status, failures
        real(qp) :: period, fewest, digits
        call section('uniform gravity: pendulum period (AGM) against mpmath')
        call read_reference('data/reference/pendulum_mpmath.csv', 20, reference, ok)
        if (.not. ok) return
        fewest = 99.0_qp
        failures = 0
        do i = 1, reference%row_count()
            call pendulum_period(reference%real_value(i, 'length'), &
                                 reference%real_value(i, 'g'), &
                                 reference%real_value(i, 'theta0'), period, status)
            if (status /= status_ok) then
                failures = failures + 1
                cycle
            end if
            digits = digits_of_agreement(period, reference%real_value(i, 'period'))
            if (digits < 32.0_qp) write (output_unit, '(a,a,f7.2)') '   theta0 = ', &
                reference%text(i, 'theta0'), digits
            fewest = min(fewest, digits)
        end do
        write (output_unit, '(a,i0,a,f6.2)') '   ', reference%row_count(), &
            ' amplitudes 1e-8 .. pi: fewest digits ', fewest
        call check(failures == 0, 'every reference amplitude solved')
        call check(fewest >= 32.0_qp, 'pendulum period = mpmath to >= 32 digits')
    end subroutine pendulum_reference_tests

    !> Growth with amplitude, the small-amplitude series, the quadrature of the period
    !! integral, the logarithmic limit theta0 -> pi and K at known points.
    subroutine pendulum_property_tests()
        ! Taylor coefficients of T/(2 pi sqrt(L/g)) in theta0^2 (checked against mpmath by
        ! scripts/make_uniform_reference.py); c(8) is the first one left out of the sum
        real(qp), parameter :: c(0:7) = [1.0_qp, 1.0_qp/16.0_qp, 11.0_qp/3072.0_qp, &
                                         173.0_qp/737280.0_qp, &
                                         22931.0_qp/1321205760.0_qp, &
                                         1319183.0_qp/951268147200.0_qp, &
                                         233526463.0_qp/2009078326886400.0_qp, &
                                         2673857519.0_qp/265928913086054400.0_qp]
        real(qp), parameter :: small(6) = [1.0e-3_qp, 1.0e-2_qp, 5.0e-2_qp, 0.1_qp, &
                                           0.2_qp, 0.3_qp]
        real(qp) :: period, previous, series, tail, amplitude, numeric, fewest, value, complement
        real(qp) :: log_term, worst_ratio
        integer :: i, j, status, failures, status_agm
        logical :: increasing

        call section('uniform gravity: pendulum period, series, quadrature, limits')
        call pendulum_period(1.0_qp, 1.0_qp, 0.0_qp, period, status)
        call check_close(period, 2.0_qp*pi, 2.0_qp, 'theta0 = 0: 2 pi sqrt(L/g)')
        increasing = .true.
        previous = period
        do i = 1, 400
            call pendulum_period(1.0_qp, 1.0_qp, pi*real(i, qp)/400.0_qp, period, status)
            increasing = increasing .and. status == status_ok .and. period > previous
            previous = period
        end do
        call check(increasing, 'period strictly increasing on 400 amplitudes in (0, pi]')

        ! series through theta0^12; remainder bounded by 2 c14 theta^14/(1 - theta^2/pi^2)
        ! (positive coefficients with ratios below 1/pi^2, doubled for safety)
        worst_ratio = 0.0_qp
        do i = 1, size(small)
            call pendulum_period(1.0_qp, 1.0_qp, small(i), period, status)
            series = 0.0_qp
            do j = 6, 0, -1
                series = series*small(i)**2 + c(j)
            end do
            series = 2.0_qp*pi*series
            tail = 2.0_qp*pi*c(7)*small(i)**14
            call check(abs(period - series) <= 2.0_qp*tail/(1.0_qp - (small(i)/pi)**2) + &
                       8.0_qp*eps_qp*period, 'series agrees within its remainder')
            if (tail > 1.0e6_qp*eps_qp*period) worst_ratio = max(worst_ratio, &
                abs((period - series)/tail - 1.0_qp))
        end do
        write (output_unit, '(a,f8.4)') '   series through theta0^12: (AGM - series)/' // &
            '(next term) - 1 at most', worst_ratio
        call check(worst_ratio < 0.05_qp, 'AGM - series is the next series term (5%)')

        ! quadrature of Tee's (4) for the circle
        fewest = 99.0_qp
        failures = 0
        do i = 0, 61
            if (i <= 50) then
                amplitude = pi*real(i, qp)/51.0_qp
            else
                amplitude = pi - 10.0_qp**(-(i - 50))   ! pi - 1e-1 .. pi - 1e-11
            end if
            call pendulum_period(2.0_qp, 3.72_qp, amplitude, period, status)
            call pendulum_period_quadrature(2.0_qp, 3.72_qp, amplitude, numeric, status)
            if (status /= status_ok) then
                failures = failures + 1
                cycle
            end if
            fewest = min(fewest, digits_of_agreement(numeric, period))
        end do
        write (output_unit, '(a,f6.2)') '   quadrature vs AGM, 62 amplitudes 0 .. pi - 1e-11:' &
            // ' fewest digits ', fewest
        call check(failures == 0, 'pendulum quadrature converged up to pi - 1e-11')
        call check(fewest >= 32.0_qp, 'pendulum quadrature = AGM to >= 32 digits')
        ! the binary128 pi is 8.7e-35 below pi: the period is finite (about 322) but the
        ! integrand is sharply peaked; the quadrature either converges to the AGM value
        ! or says no_convergence, never a wrong number
        call pendulum_period_quadrature(1.0_qp, 1.0_qp, pi, numeric, status)
        call pendulum_period(1.0_qp, 1.0_qp, pi, period, status_agm)
        call check((status == status_no_convergence .and. numeric == 0.0_qp) .or. &
                   (status == status_ok .and. digits_of_agreement(numeric, period) >= 32.0_qp), &
                   'quadrature at theta0 = pi: the AGM value or no_convergence, never wrong')

        ! theta0 -> pi: K = L + (k'^2/4)(L - 1) + O(k'^4 L), L = log(4/k')
        do i = 1, 2
            if (i == 1) then
                amplitude = pi                       ! k' = cos(pi/2) = 4.3e-35
            else
                amplitude = 3.14159265358979_qp      ! k' = 1.6e-15
            end if
            complement = cos(0.5_qp*amplitude)
            log_term = log(4.0_qp/complement)
            call pendulum_period(1.0_qp, 1.0_qp, amplitude, period, status)
            call check_close(period, &
                             4.0_qp*(log_term + 0.25_qp*complement**2*(log_term - 1.0_qp)), &
                             8.0_qp, 'theta0 -> pi: K = log(4/k'') + ...')
        end do

        ! K at known points
        call complete_elliptic_k(0.0_qp, value, status)
        call check_close(value, 0.5_qp*pi, 2.0_qp, 'K(0) = pi/2')
        call complete_elliptic_k(sqrt(0.5_qp), value, status)
        call check_close(value, gamma(0.25_qp)**2/(4.0_qp*sqrt(pi)), 8.0_qp, &
                         'K(1/sqrt 2) = Gamma(1/4)^2/(4 sqrt pi)')
        call complete_elliptic_k(-sqrt(0.5_qp), value, status)
        call check_close(value, gamma(0.25_qp)**2/(4.0_qp*sqrt(pi)), 8.0_qp, 'K(-k) = K(k)')
        ! k = 1 - 2^-100 is exact, so k' = sqrt(2^-100 (2 - 2^-100)) is known exactly
        call complete_elliptic_k(1.0_qp - 2.0_qp**(-100), value, status)
        complement = sqrt(2.0_qp**(-100)*(2.0_qp - 2.0_qp**(-100)))
        log_term = log(4.0_qp/complement)
        call check_close(value, log_term + 0.25_qp*complement**2*(log_term - 1.0_qp), 8.0_qp, &
                         'K(1 - 2^-100) = log(4/k'') + ...')
    end subroutine pendulum_property_tests

    !> Bad pendulum parameters and |k| >= 1.
    subroutine pendulum_status_tests()
        real(qp) :: period, value, nan
        integer :: status
        call section('uniform gravity: pendulum bad parameters')
        nan = ieee_value(nan, ieee_quiet_nan)
        call pendulum_period(1.0_qp, gravity, nearest(pi, 2.0_qp), period, status)
        call check(status == status_parameter_out_of_range .and. period == 0.0_qp, &
                   'amplitude above pi refused')
        call pendulum_period(1.0_qp, gravity, -0.1_qp, period, status)
        call check(status == status_parameter_out_of_range, 'negative amplitude refused')
        call pendulum_period(0.0_qp, gravity, 0.1_qp, period, status)
        call check(status == status_parameter_out_of_range, 'L = 0 refused')
        call pendulum_period(1.0_qp, -1.0_qp, 0.1_qp, period, status)
        call check(status == status_parameter_out_of_range, 'g < 0 refused')
        call pendulum_period(1.0_qp, gravity, nan, period, status)
        call check(status == status_not_finite, 'amplitude NaN')
        call complete_elliptic_k(1.0_qp, value, status)
        call check(status == status_parameter_out_of_range .and. value == 0.0_qp, &
                   'K(1) refused (infinite)')
    end subroutine pendulum_status_tests

end module test_uniform_gravity
