!> Physics against independent values: closed forms, the paper's limits, SciPy's
!! QUADPACK on the original integrals, Tee's Table 1 and a 45-digit mpmath reference.
module test_physics
    use, intrinsic :: iso_fortran_env, only: output_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_quiet_nan
    use brachistochrone_kinds, only: qp, pi, eps_qp
    use brachistochrone_status, only: status_ok, status_inaccessible, &
                                      status_rho_out_of_range, status_psi_out_of_range, &
                                      status_not_finite, status_invalid_argument, &
                                      status_outside_domain
    use brachistochrone_closed_forms, only: radial_time, kappa_time, fall_to_centre_time, &
                            second_arch_radial_time, &
                            apse_angle_limit, inaccessible_angle, radial_fall_time
    use brachistochrone_quadrature, only: univariate_integrand, gauss_legendre, integrate_adaptive
    use brachistochrone_chebyshev, only: chebyshev_table
    use brachistochrone_inverse_square, only: whole_tables_by_quadrature
    use brachistochrone_inverse_square, only: inverse_square_model, new_inverse_square_model, &
            evaluate_arch, &
            arch_values, level_fine
    use brachistochrone_two_point, only: solve_endpoint, solve_endpoint_secant
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_arches, only: arch_first, arch_second, arch_complete, arch_radial, &
                                      arch_inaccessible, arch_word
    use reference_tables, only: csv_table, read_reference
    use testing, only: check, check_close, check_digits, section, digits_of_agreement
    implicit none
    private

    public :: run_physics_tests

    !> Integrand of the radial fall time (46) after x = 1 - y^2: sqrt(2) sqrt(1 - y^2).
    type, extends(univariate_integrand) :: fall_integrand
    contains
        procedure :: evaluate => fall_evaluate
    end type fall_integrand

contains

    pure function fall_evaluate(self, x) result(y)
        class(fall_integrand), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp) :: y
        y = sqrt(2.0_qp)*sqrt(1.0_qp - x*x)
    end function fall_evaluate

    subroutine run_physics_tests()
        type(inverse_square_model) :: model
        model = new_inverse_square_model()
        call closed_form_tests()
        call limit_tests(model)
        call quadpack_tests(model)
        call table1_tests(model)
        call reference_tests(model)
        call special_endpoint_tests(model)
        call robustness_tests(model)
        call derivative_tests(model)
        call whole_arch_tests(model)
        call shipped_table_tests(model)
    end subroutine run_physics_tests

    !> The whole-half-arch tables shipped as constants
    !! (`brachistochrone_inverse_square_tables`) against a fresh computation by the
    !! quadrature (`whole_tables_by_quadrature`): the same terms on every piece and every
    !! power coefficient within 4 eps of the piece's size (bit-identical expected; the count
    !! is printed). A failure means the module is stale: run
    !! scripts/make_inverse_square_tables.sh.
    subroutine shipped_table_tests(model)
        type(inverse_square_model), intent(in) :: model
        type(chebyshev_table) :: fresh(3)
        integer :: k, piece, identical, values
        real(qp) :: worst
        call section('physics: shipped inverse-square tables against the quadrature')
        fresh = whole_tables_by_quadrature(model)
        identical = 0
        values = 0
        worst = 0.0_qp
        do k = 1, 3
            call check(all(fresh(k)%used == model%whole(k)%used) .and. &
                       all(shape(fresh(k)%power) == shape(model%whole(k)%power)), &
                       'shipped table '//achar(iachar('0') + k)//': the same terms per piece')
            if (.not. all(shape(fresh(k)%power) == shape(model%whole(k)%power))) cycle
            do piece = 1, size(fresh(k)%power, 2)
                worst = max(worst, maxval(abs(fresh(k)%power(:, piece) - &
                    model%whole(k)%power(:, piece)))/(eps_qp*fresh(k)%tail(0, piece)))
            end do
            identical = identical + count(fresh(k)%power == model%whole(k)%power)
            values = values + size(fresh(k)%power)
        end do
        call check(worst <= 4.0_qp, 'shipped tables within 4 eps of the quadrature '// &
                   '(else run scripts/make_inverse_square_tables.sh)')
        write (output_unit, '(a,i0,a,i0,a,es9.2,a)') '   ', identical, ' of ', values, &
            ' coefficients bit-identical; largest difference ', worst, ' eps'
    end subroutine shipped_table_tests

    !> The tabulated whole half-arch against mpmath on the original integrals at r = R
    !! (236 dyadic R from 2^-58 to 1 - 2^-58, both sides of every piece boundary).
    !! On the second half-arch at r = R the model uses the tables alone.
    subroutine whole_arch_tests(model)
        type(inverse_square_model), intent(in) :: model
        type(csv_table) :: reference
        logical :: ok
        real(qp) :: big_r, expected(3), actual(3), worst(3), apse
        integer :: i, status, k, bad
        call section('physics: whole half-arch tables against mpmath (original integrals)')
        call read_reference('data/reference/whole_arch_mpmath.csv', 200, reference, ok)
        if (.not. ok) return
        worst = 0.0_qp
        bad = 0
        do i = 1, reference%row_count()
            big_r = reference%real_value(i, 'R')
            expected = [reference%real_value(i, 'theta'), reference%real_value(i, 's'), &
                        reference%real_value(i, 't')]
            call model%half_arch(big_r, big_r, .true., actual(1), actual(2), actual(3), status)
            call model%apse_angle(big_r, apse, status)
            if (apse /= actual(1)) bad = bad + 1
            do k = 1, 3
                worst(k) = max(worst(k), abs(actual(k) - expected(k))/expected(k)/eps_qp)
            end do
        end do
        write (output_unit, '(3x,i0,a,3f6.2)') reference%row_count(), &
            ' radii; worst relative error of Theta(R,R), S(R,R), T(R,R) in eps:', worst
        call check(all(worst <= 4.0_qp), 'tables within 4 eps of mpmath')
        call check(bad == 0, 'apse_angle = the second half-arch at r = R')
    end subroutine whole_arch_tests

    !> What the solver's last step relies on, against central differences:
    !! d(s)/dR from evaluate_arch (the integrand's derivative plus the moving limit), and
    !! Hamilton-Jacobi, dt/dpsi = K = sqrt(R^3/(2(1-R))) at fixed rho.
    !! With h = 1e-9 of the scale, the difference errs by ~h^2 (1e-18) plus eps/h (1e-25).
    subroutine derivative_tests(model)
        type(inverse_square_model), intent(in) :: model
        type(arch_values) :: values, plus, minus
        type(endpoint_solution) :: b, b_plus, b_minus
        real(qp) :: rho(5), fraction(3), big_r, d, h, analytic, difference, worst, conserved
        integer :: i, j, arch
        logical :: second

        call section('physics: d(s)/dR and Hamilton-Jacobi against central differences')
        rho = [0.05_qp, 0.3_qp, 0.6_qp, 0.9_qp, 0.999_qp]
        fraction = [0.02_qp, 0.5_qp, 0.97_qp]
        worst = 0.0_qp
        do arch = 1, 2
            second = arch == 2
            do i = 1, size(rho)
                do j = 1, size(fraction)
                    big_r = fraction(j)*rho(i)
                    d = rho(i) - big_r
                    h = 1.0e-9_qp*min(big_r, d)
                    values = evaluate_arch(model, level_fine, second, rho(i), big_r, d, &
                                                 .true., .true.)
                    plus = evaluate_arch(model, level_fine, second, rho(i), big_r + h, d - h, &
                                               .false., .true.)
                    minus = evaluate_arch(model, level_fine, second, rho(i), big_r - h, &
                                                d + h, .false., .true.)
                    analytic = values%arclength_dr_smooth &
                               + values%boundary_sign*values%arclength_boundary/sqrt(d)
                    difference = (plus%arclength - minus%arclength)/(2.0_qp*h)
                    worst = max(worst, abs(analytic - difference)/abs(difference))
                end do
            end do
        end do
        write (output_unit, '(3x,a,es10.2)') &
            '30 (rho, R) on both half-arches: worst relative |dS/dR - difference|', worst
        call check(worst < 1.0e-15_qp, 'dS/dR agrees with central differences')

        worst = 0.0_qp
        do i = 1, size(rho)
            do j = 1, 3
                b = solve_endpoint(model, rho(i), real(j, qp)*0.6_qp)
                h = 1.0e-9_qp
                b_plus = solve_endpoint(model, rho(i), real(j, qp)*0.6_qp + h)
                b_minus = solve_endpoint(model, rho(i), real(j, qp)*0.6_qp - h)
                conserved = sqrt(b%apse_radius**3/(2.0_qp*(1.0_qp - b%apse_radius)))
                difference = (b_plus%time - b_minus%time)/(2.0_qp*h)
                worst = max(worst, abs(conserved - difference)/conserved)
            end do
        end do
        write (output_unit, '(3x,a,es10.2)') &
            '15 endpoints: worst relative |K - dt/dpsi|', worst
        call check(worst < 1.0e-15_qp, 'dt/dpsi at fixed rho = K (Hamilton-Jacobi)')
    end subroutine derivative_tests

    subroutine closed_form_tests()
        type(fall_integrand) :: fall
        real(qp) :: r, value, error, t, fall_times(10)
        integer :: k, j, status
        call section('physics: radial fall t(r) (46) and kappa(rho) (75)')
        call check_close(radial_time(0.0_qp), pi/sqrt(8.0_qp), 4.0_qp, 't(0) = pi/sqrt(8)')
        ! (47) prints 1.1107207345385916: a misprint in the 12th digit (docs/ERRATA.md)
        call check_digits(fall_to_centre_time, 1.1107207345395916_qp, 16.0_qp, &
                          't(0) = 1.1107207345395916 (16 digits)')
        call check(abs(fall_to_centre_time - 1.1107207345385916_qp) > 5.0e-13_qp, &
                   't(0) /= 1.1107207345385916 as printed in (47)')
        call check(radial_time(1.0_qp) == 0.0_qp, 't(1) = 0')
        call check_close(kappa_time(1.0_qp), pi/sqrt(2.0_qp), 4.0_qp, 'kappa(1) = 2 t(0)')
        call check_close(kappa_time(0.0_qp), pi/sqrt(8.0_qp), 4.0_qp, 'kappa(0) = t(0)')
        do k = 1, 9
            r = real(k, qp)/10.0_qp
            ! independent: the defining integral (46), t = int_0^sqrt(1-r) sqrt(2(1-y^2)) dy
            call integrate_adaptive(fall, 0.0_qp, sqrt(1.0_qp - r), gauss_legendre(24), &
                                    4.0_qp*eps_qp, 0.0_qp, value, error, status)
            call check_close(radial_time(r), value, 16.0_qp, 't(r) = integral (46)')
            call check_close(kappa_time(r), 2.0_qp*pi/sqrt(8.0_qp) - value, 16.0_qp, &
                             'kappa(rho) = 2 t(0) - t(rho)')
            fall_times(k) = value
        end do
        fall_times(10) = 0.0_qp
        ! the second half-arch's radial part 2 t(R) - t(r), one arctangent, against the
        ! integrals (R = j/10 <= r = k/10, r = 1 included)
        do k = 1, 10
            r = real(k, qp)/10.0_qp
            do j = 1, k
                t = second_arch_radial_time(real(j, qp)/10.0_qp, 1.0_qp - real(j, qp)/10.0_qp, &
                                            r, 1.0_qp - r, sqrt(r), sqrt(1.0_qp - r))
                call check_close(t, 2.0_qp*fall_times(j) - fall_times(k), 16.0_qp, &
                                 '2 t(R) - t(r) = integrals (46)')
            end do
        end do
        call check_close(second_arch_radial_time(1.0e-30_qp, 1.0_qp - 1.0e-30_qp, 1.0_qp, &
                                                 0.0_qp, 1.0_qp, 0.0_qp), &
                         2.0_qp*radial_time(1.0e-30_qp), 4.0_qp, '2 t(1e-30) - t(1)')
        call radial_fall_time(1.5_qp, t, status)
        call check(status == status_invalid_argument .and. t == 0.0_qp, &
                   'checked t(r) rejects r > 1')
    end subroutine closed_form_tests

    subroutine limit_tests(model)
        type(inverse_square_model), intent(in) :: model
        real(qp) :: big_r, previous, angle, angle2, length, length2, time, time2
        integer :: k, status
        logical :: decreasing
        call section('physics: limits and properties (sec. 4.2-4.4)')
        decreasing = .true.
        previous = huge(1.0_qp)
        do k = 1, 999
            big_r = real(k, qp)/1000.0_qp
            call model%apse_angle(big_r, angle, status)
            decreasing = decreasing .and. angle < previous .and. status == status_ok
            previous = angle
        end do
        call check(decreasing, 'Theta(R,R) strictly decreasing on R = 0.001 .. 0.999')
        big_r = 1.0e-30_qp
        call model%apse_angle(big_r, angle, status)
        call check(abs(angle - apse_angle_limit) <= big_r, &
                   'Theta(R,R) -> pi/3 as R -> 0 (|Theta - pi/3| <= R at R = 1e-30)')
        call model%half_arch(big_r, big_r, .false., angle, length, time, status)
        call check(abs(length - 1.0_qp) <= big_r, 'S(R,R) -> 1 as R -> 0')
        call check(abs(time - fall_to_centre_time) <= big_r, 'T(R,R) -> pi/sqrt(8) as R -> 0')
        big_r = 1.0_qp - 1.0e-24_qp
        call model%apse_angle(big_r, angle, status)
        ! as R -> 1, z -> 1 and q -> 1 in (66): Theta(R,R) = (pi/2)(1 - R)(1 + O(1-R))
        call check(angle > 0.0_qp .and. abs(angle/(0.5_qp*pi*(1.0_qp - big_r)) - 1.0_qp) &
                   < 1.0e-20_qp, 'Theta(R,R) -> 0 like (pi/2)(1 - R)')
        call model%apse_angle(1.0_qp, angle, status)
        call check(angle == 0.0_qp .and. status == status_ok, 'Theta(1,1) = 0')
        do k = 1, 9
            big_r = real(k, qp)/10.0_qp
            call model%half_arch(big_r, big_r, .false., angle, length, time, status)
            call model%half_arch(big_r, big_r, .true., angle2, length2, time2, status)
            call check_close(angle2, angle, 64.0_qp, 'half-arches agree at the apse: theta')
            call check_close(length2, length, 64.0_qp, 'half-arches agree at the apse: s')
            call check_close(time2, time, 64.0_qp, 'half-arches agree at the apse: t')
            call model%apse_angle(big_r, angle2, status)
            call check_close(angle2, angle, 64.0_qp, 'trapezoid Theta(R,R) = Gauss Theta(R,R)')
            call model%half_arch(1.0_qp, big_r, .true., angle2, length2, time2, status)
            call check_close(angle2, 2.0_qp*angle, 64.0_qp, 'complete arch: theta = 2 Theta(R,R)')
            call check_close(length2, 2.0_qp*length, 64.0_qp, 'complete arch: s = 2 S(R,R)')
            call check_close(time2, 2.0_qp*time, 64.0_qp, 'complete arch: t = 2 T(R,R)')
        end do
        call model%half_arch(0.5_qp, 0.6_qp, .false., angle, length, time, status)
        call check(status == status_invalid_argument, 'Theta(r,R) with r < R is refused')
    end subroutine limit_tests

    subroutine quadpack_tests(model)
        type(inverse_square_model), intent(in) :: model
        type(csv_table) :: grid
        logical :: ok
        integer :: i, status, worst_row
        real(qp) :: r, big_r, angle, length, time, worst, error
        real(qp), parameter :: tolerance = 1.0e-13_qp
        call section('physics: Theta, S, T against SciPy QUADPACK on (55)-(57)')
        call read_reference('data/reference/quadpack_grid.csv', 50, grid, ok)
        if (.not. ok) return
        worst = 0.0_qp
        worst_row = 0
        do i = 1, grid%row_count()
            r = grid%real_value(i, 'r')
            big_r = grid%real_value(i, 'R')
            call model%half_arch(r, big_r, .false., angle, length, time, status)
            error = max(relative(angle, grid%real_value(i, 'theta')), &
                        relative(length, grid%real_value(i, 's')), &
                        relative(time, grid%real_value(i, 't')))
            if (error > worst) then
                worst = error
                worst_row = i
            end if
        end do
        write (output_unit, '(a,es9.2,a,i0,a,i0)') '   worst relative difference ', worst, &
            ' (row ', worst_row, ' of ', grid%row_count()
        call check(worst <= tolerance, 'Theta, S, T agree with QUADPACK to 1e-13')
    contains
        pure real(qp) function relative(a, b)
            real(qp), intent(in) :: a, b
            if (b == 0.0_qp) then
                relative = abs(a)
            else
                relative = abs(a - b)/abs(b)
            end if
        end function relative
    end subroutine quadpack_tests

    subroutine table1_tests(model)
        type(inverse_square_model), intent(in) :: model
        ! Tee (1998) Table 1 as printed, rho of rows 1-2 swapped back (docs/ERRATA.md)
        real(qp), parameter :: rho(5) = [0.2_qp, 0.5_qp, 0.7_qp, 0.9_qp, 1.0_qp]
        real(qp), parameter :: psi(5) = [1.2_qp, 0.1_qp, 1.8_qp, 0.4_qp, 2.0_qp]
        real(qp), parameter :: r0(5) = [0.2_qp, 0.4_qp, 0.6_qp, 0.8_qp, 0.2_qp]
        real(qp), parameter :: r1(5) = [0.1_qp, 0.2_qp, 0.5_qp, 0.7_qp, 0.1_qp]
        integer, parameter :: steps(5) = [10, 7, 7, 7, 6]
        character(len=17), parameter :: printed_r(5) = [character(len=17) :: &
            '0.184781963328079', '0.252787093630160', '0.168913316595188', &
            '0.838545794202334', '0.057854464393370']
        character(len=17), parameter :: printed_s(5) = [character(len=17) :: &
            '0.967544327890300', '0.505594850833648', '1.531621194881120', &
            '0.442680075643429', '1.947547388961997']
        character(len=17), parameter :: printed_t(5) = [character(len=17) :: &
            '1.127755808164997', '0.914164272619962', '1.481218910277573', &
            '1.058599268341289', '2.221060707125763']
        type(endpoint_solution) :: b
        integer :: i
        character(len=8) :: row
        call section('physics: Tee Table 1, the paper''s secant method (every printed digit)')
        do i = 1, 5
            write (row, '(a,i0)') 'row ', i
            b = solve_endpoint_secant(model, rho(i), psi(i), r0(i), r1(i), 1.0e-16_qp)
            call check(b%status == status_ok, trim(row)//': secant converges')
            call check(b%steps == steps(i), trim(row)//': Steps as printed')
            call check(fixed15(b%apse_radius) == printed_r(i), trim(row)//': R-bar printed digits')
            call check(fixed15(b%arclength) == printed_s(i), trim(row)//': s printed digits')
            call check(fixed15(b%time) == printed_t(i), trim(row)//': t printed digits')
        end do
        ! the rows as misprinted have other answers (docs/ERRATA.md)
        b = solve_endpoint(model, 0.5_qp, 1.2_qp)
        call check_digits(b%apse_radius, 0.38719841090429114_qp, 16.0_qp, &
                          'misprinted row 1 (0.5, 1.2) has R-bar = 0.38719841090429114')
        b = solve_endpoint(model, 0.2_qp, 0.1_qp)
        call check_digits(b%apse_radius, 0.06862319813146513_qp, 15.5_qp, &
                          'misprinted row 2 (0.2, 0.1) has R-bar = 0.06862319813146513')
    contains
        function fixed15(x) result(text)
            real(qp), intent(in) :: x
            character(len=17) :: text
            write (text, '(f17.15)') x
        end function fixed15
    end subroutine table1_tests

    subroutine reference_tests(model)
        type(inverse_square_model), intent(in) :: model
        type(csv_table) :: reference
        logical :: ok
        type(endpoint_solution) :: b
        integer :: i, wrong_arch, unsolved
        real(qp) :: rho, psi, digits_r, digits_s, digits_t, min_r, min_s, min_t, required
        real(qp) :: least_margin
        call section('physics: default solver against the 45-digit mpmath reference')
        call read_reference('data/reference/endpoints_mpmath.csv', 100, reference, ok)
        if (.not. ok) return
        min_r = 99.0_qp
        min_s = 99.0_qp
        min_t = 99.0_qp
        least_margin = 99.0_qp
        wrong_arch = 0
        unsolved = 0
        do i = 1, reference%row_count()
            rho = reference%real_value(i, 'rho')
            psi = reference%real_value(i, 'psi')
            b = solve_endpoint(model, rho, psi)
            if (b%status /= status_ok) then
                unsolved = unsolved + 1
                write (output_unit, '(a,i0,2a)') '   unsolved row ', i, ': ', &
                    reference%text(i, 'rho')//', '//reference%text(i, 'psi')
                cycle
            end if
            if (arch_word(b%arch) /= reference%text(i, 'arch') .and. .not. &
                (b%arch == arch_complete .and. reference%text(i, 'arch') == 'second')) then
                wrong_arch = wrong_arch + 1
            end if
            digits_r = digits_of_agreement(b%apse_radius, reference%real_value(i, 'R'))
            digits_s = digits_of_agreement(b%arclength, reference%real_value(i, 's'))
            digits_t = digits_of_agreement(b%time, reference%real_value(i, 't'))
            ! R-bar's own conditioning bounds its digits (README "Accuracy")
            required = min(32.0_qp, 33.0_qp - log10(condition(model, b)))
            least_margin = min(least_margin, digits_r - required)
            if (digits_r < required .or. min(digits_s, digits_t) < 32.0_qp) then
                write (output_unit, '(a,i0,a,3f7.2,a,f6.2)') '   row ', i, &
                    ' digits R, s, t:', digits_r, digits_s, digits_t, '  R needs', required
            end if
            min_r = min(min_r, digits_r)
            min_s = min(min_s, digits_s)
            min_t = min(min_t, digits_t)
        end do
        write (output_unit, '(a,i0,a,3f7.2,a,f6.2)') '   ', reference%row_count(), &
            ' endpoints; fewest digits R, s, t:', min_r, min_s, min_t, &
            '; least R margin over its bound', least_margin
        call check(unsolved == 0, 'every reference endpoint solved')
        call check(wrong_arch == 0, 'half-arch as in the reference')
        call check(least_margin >= 0.0_qp, 'R-bar to min(32, 33 - log10 cond) digits')
        call check(min_s >= 32.0_qp, 's to >= 32 digits on every reference endpoint')
        call check(min_t >= 32.0_qp, 't to >= 32 digits on every reference endpoint')
    end subroutine reference_tests

    !> cond = |Upsilon/(R Upsilon'(R))| by a central difference (only sets a tolerance).
    function condition(model, b) result(cond)
        type(inverse_square_model), intent(in) :: model
        type(endpoint_solution), intent(in) :: b
        real(qp) :: cond, h, up, down, length, time
        integer :: status
        h = 1.0e-12_qp*min(b%apse_radius, b%rho - b%apse_radius)
        if (h <= 0.0_qp) then
            cond = 1.0_qp
            return
        end if
        call model%half_arch(b%rho, b%apse_radius + h, b%arch /= arch_first, up, length, &
                             time, status)
        call model%half_arch(b%rho, b%apse_radius - h, b%arch /= arch_first, down, length, &
                             time, status)
        cond = max(1.0_qp, abs(b%psi*2.0_qp*h/(b%apse_radius*(up - down))))
    end function condition

    subroutine special_endpoint_tests(model)
        type(inverse_square_model), intent(in) :: model
        type(endpoint_solution) :: b
        real(qp) :: nan, angle, length, time
        integer :: status
        call section('physics: special endpoints')
        b = solve_endpoint(model, 0.3_qp, 0.0_qp)
        call check(b%status == status_ok .and. b%arch == arch_radial, 'psi = 0 is radial fall')
        call check(b%apse_radius == 0.0_qp, 'radial fall: R = 0')
        call check_close(b%arclength, 0.7_qp, 4.0_qp, 'radial fall: s = 1 - rho')
        call check_close(b%time, radial_time(0.3_qp), 4.0_qp, 'radial fall: t = t(rho)')
        b = solve_endpoint(model, 1.0_qp, 0.0_qp)
        call check(b%status == status_ok .and. b%arclength == 0.0_qp .and. &
                   b%time == 0.0_qp, 'B = A: s = t = 0')
        b = solve_endpoint(model, 1.0_qp, 1.5_qp)
        call check(b%status == status_ok .and. b%arch == arch_complete, &
                   'rho = 1 is a complete brachistochrone')
        call model%apse_angle(b%apse_radius, angle, status)
        call check_close(2.0_qp*angle, 1.5_qp, 16.0_qp, 'complete: psi = 2 Theta(R,R)')
        call model%half_arch(b%apse_radius, b%apse_radius, .false., angle, length, time, &
                             status)
        call check_close(b%arclength, 2.0_qp*length, 16.0_qp, 'complete: s = 2 S(R,R)')
        call check_close(b%time, 2.0_qp*time, 16.0_qp, 'complete: t = 2 T(R,R)')
        ! R-bar ~ 2.8 rho psi^(2/3): 3e-5267 underflows, 3e-4667 does not
        b = solve_endpoint(model, 1.0e-2000_qp, 1.0e-4900_qp)
        call check(b%status == status_ok .and. b%arch == arch_first .and. &
                   b%apse_radius == 0.0_qp, 'R-bar below the binary128 range: R = 0')
        call check_close(b%arclength, 1.0_qp - 1.0e-2000_qp, 4.0_qp, &
                         'R-bar below the range: s = 1 - rho')
        call check_close(b%time, radial_time(1.0e-2000_qp), 4.0_qp, &
                         'R-bar below the range: t = t(rho)')
        b = solve_endpoint(model, 1.0e-2000_qp, 1.0e-4000_qp)
        call model%half_arch(1.0e-2000_qp, b%apse_radius, .false., angle, length, time, &
                             status)
        call check(b%status == status_ok .and. b%apse_radius > 1.0e-4700_qp .and. &
                   b%apse_radius < 1.0e-4600_qp, 'rho = 1e-2000, psi = 1e-4000: R-bar ~ 3e-4667')
        call check_close(angle, 1.0e-4000_qp, 64.0_qp, &
                         'rho = 1e-2000, psi = 1e-4000: Upsilon(R-bar) = psi')
        ! psi within 1e-30 .. 1e-12 of the edge 2 pi/3 (R-bar -> 0, below what the
        ! hardware rules resolve: about 200 evaluations before `edge_newton`)
        call edge(0.5_qp, 1.0e-30_qp)
        call edge(3.6e-30_qp, 1.0e-30_qp)
        call edge(1.0e-10_qp, 1.0e-20_qp)
        call edge(1.0_qp, 1.0e-12_qp)
        b = solve_endpoint(model, 0.6_qp, inaccessible_angle)
        call check(b%status == status_inaccessible .and. b%arch == arch_inaccessible, &
                   'psi = 2 pi/3 is inaccessible')
        call check(b%has_time .and. .not. b%has_apse_radius .and. .not. b%has_arclength, &
                   'inaccessible: only the time bound is given')
        call check_close(b%time, kappa_time(0.6_qp), 4.0_qp, 'inaccessible: t = kappa(rho)')
        b = solve_endpoint(model, 0.6_qp, 3.0_qp)
        call check(b%status == status_inaccessible, 'psi = 3 is inaccessible')
        b = solve_endpoint(model, 1.5_qp, 1.0_qp)
        call check(b%status == status_rho_out_of_range, 'rho > 1 refused')
        b = solve_endpoint(model, 0.0_qp, 1.0_qp)
        call check(b%status == status_rho_out_of_range, 'rho = 0 refused')
        b = solve_endpoint(model, -0.5_qp, 1.0_qp)
        call check(b%status == status_rho_out_of_range, 'rho < 0 refused')
        b = solve_endpoint(model, 0.5_qp, -0.1_qp)
        call check(b%status == status_psi_out_of_range, 'psi < 0 refused')
        b = solve_endpoint(model, 0.5_qp, 4.0_qp)
        call check(b%status == status_psi_out_of_range, 'psi > pi refused')
        nan = ieee_value(1.0_qp, ieee_quiet_nan)
        b = solve_endpoint(model, nan, 1.0_qp)
        call check(b%status == status_not_finite, 'NaN rho refused')
        b = solve_endpoint(model, 0.5_qp, nan)
        call check(b%status == status_not_finite, 'NaN psi refused')
        call check(ieee_is_finite(b%apse_radius) .and. ieee_is_finite(b%arclength) .and. &
                   ieee_is_finite(b%time), 'refused endpoint: outputs finite')
    contains
        !> B at rho, psi = (2 pi/3)(1 - gap): solved in few evaluations, and the curve
        !! found reaches psi to the rounding of Upsilon (R-bar itself is determined only
        !! to about eps/gap there)
        subroutine edge(rho, gap)
            real(qp), intent(in) :: rho, gap
            type(endpoint_solution) :: e
            real(qp) :: psi, upsilon, s, t
            integer :: stat
            character(len=40) :: label
            write (label, '(a,es9.2,a,es9.2)') 'rho =', real(rho), ', gap =', real(gap)
            psi = inaccessible_angle*(1.0_qp - gap)
            e = solve_endpoint(model, rho, psi)
            call check(e%status == status_ok .and. e%steps <= 12 .and. e%apse_radius > 0.0_qp, &
                       'edge of the sector solved in <= 12 evaluations: '//trim(label))
            call model%half_arch(rho, e%apse_radius, .true., upsilon, s, t, stat)
            call check(abs(upsilon - psi) <= 16.0_qp*eps_qp*psi, &
                       'edge of the sector: Upsilon(R-bar) = psi to 16 eps: '//trim(label))
            call check_close(e%arclength, s, 8.0_qp, 'edge of the sector: s = S(R-bar): ' &
                             //trim(label))
        end subroutine edge
    end subroutine special_endpoint_tests

    !> The default solver on endpoints where the paper's secant from (0.9 rho, 0.7 rho)
    !! steps past R = rho, and on a dense grid of the accessible sector.
    subroutine robustness_tests(model)
        type(inverse_square_model), intent(in) :: model
        type(endpoint_solution) :: b, secant_b
        integer :: i, j, failures, left_domain, solved
        real(qp) :: rho, psi, residual, worst_residual, angle, length, time
        integer :: status
        call section('physics: robustness over the accessible sector')
        failures = 0
        left_domain = 0
        solved = 0
        worst_residual = 0.0_qp
        do i = 1, 20
            rho = real(i, qp)/20.0_qp
            do j = 1, 40
                psi = inaccessible_angle*real(j, qp)/41.0_qp
                b = solve_endpoint(model, rho, psi)
                if (b%status /= status_ok .or. b%apse_radius <= 0.0_qp .or. &
                    b%apse_radius > rho) then
                    failures = failures + 1
                    cycle
                end if
                solved = solved + 1
                ! the angle at B of the brachistochrone found: Upsilon(R-bar) = psi
                if (rho < 1.0_qp .or. b%arch /= arch_complete) then
                    call model%half_arch(rho, b%apse_radius, b%arch /= arch_first, angle, &
                                         length, time, status)
                    residual = abs(angle - psi)/psi
                    worst_residual = max(worst_residual, residual)
                end if
                secant_b = solve_endpoint_secant(model, rho, psi, 0.9_qp*rho, 0.7_qp*rho, &
                                                 1.0e-16_qp)
                if (secant_b%status == status_outside_domain) left_domain = left_domain + 1
            end do
        end do
        write (output_unit, '(a,i0,a,i0,a,es9.2)') '   ', solved, &
            ' solved; paper''s secant from (0.9 rho, 0.7 rho) left (0, rho] on ', &
            left_domain, '; worst |Upsilon(R) - psi|/psi ', worst_residual
        call check(failures == 0, 'default solver solves all 800 grid endpoints')
        call check(worst_residual <= 64.0_qp*eps_qp, 'Upsilon(R-bar) = psi to 64 eps')
        call check(left_domain > 0, 'the paper''s secant does leave (0, rho] somewhere '// &
                   '(reported as a status, not a crash)')
    end subroutine robustness_tests

end module test_physics
