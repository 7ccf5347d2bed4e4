!> The general central-force engine against independent values: the inverse-square fast
!! path, Saitoh's closed forms for the harmonic law, Keam's limit pi/(n+1), closed-form
!! fall times.
module test_central_force
    use, intrinsic :: iso_fortran_env, only: output_unit, int64
    use brachistochrone_kinds, only: qp, pi, eps_qp
    use brachistochrone_status, only: status_ok, status_inaccessible, &
                                      status_parameter_out_of_range
    use brachistochrone_closed_forms, only: radial_time
    use brachistochrone_speed_laws, only: speed_law, inverse_square_law, power_law, &
            logarithmic_law, harmonic_law, max_power_exponent
    use brachistochrone_central_force, only: central_force_model, new_central_force_model
    use brachistochrone_inverse_square, only: inverse_square_model, new_inverse_square_model
    use brachistochrone_two_point, only: solve_endpoint
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_arches, only: arch_inaccessible, arch_second, arch_first
    use testing, only: check, check_close, check_digits, section, digits_of_agreement
    use reference_tables, only: csv_table, read_reference
    implicit none
    private

    public :: run_central_force_tests

    !> Power and logarithmic laws with their closed-form fall times switched off (the
    !! engine then takes them by quadrature), against which the closed forms are tested.
    type, extends(power_law) :: quadrature_power_law
    contains
        procedure :: closed_fall => no_closed_fall_power
    end type quadrature_power_law
    type, extends(logarithmic_law) :: quadrature_logarithmic_law
    contains
        procedure :: closed_fall => no_closed_fall_logarithmic
    end type quadrature_logarithmic_law
    type, extends(harmonic_law) :: quadrature_harmonic_law
    contains
        procedure :: closed_fall => no_closed_fall_harmonic
    end type quadrature_harmonic_law
    !> A power law without hardware-precision terms: the engine's double-precision phase
    !! and quad-precision secant steps, against which the hardware path is tested.
    type, extends(power_law) :: secant_power_law
    contains
        procedure :: has_terms_xp => no_terms_xp
    end type secant_power_law

contains

    subroutine run_central_force_tests()
        call engine_versus_fast_path()
        call harmonic_closed_forms()
        call power_laws()
        call closed_fall_times()
        call fall_time_tables()
        call fast_exponentials()
        call fast_exponentials_spread()
        call fast_exponentials_mpmath()
        call next_to_the_start()
        call two_root_finders()
        call next_to_the_apse_angle()
        call whole_tables()
        call far_tables()
        call deep_tables()
        call conserved_momentum()
        call general_references('power1.5', power_law(n=1.5_qp))
        call general_references('power3', power_law(n=3.0_qp))
        call general_references('logarithmic', logarithmic_law())
        call general_references('power10', power_law(n=10.0_qp))
        call general_references('power6', power_law(n=6.0_qp))
        call general_references('power32', power_law(n=32.0_qp))
        ! (the inverse-square table through the general engine: its edge rows, R-bar = 1e-20
        ! and 1e-30, ended with R-bar = 0 and s to 30 digits before branch i11-edge)
        call general_references('power2', power_law(n=2.0_qp))
        call to_the_limits()
        call to_the_edge()
    end subroutine run_central_force_tests

    !> Endpoints at the edge of the power laws' sectors, psi within 1e-10 .. 1e-32 of
    !! 2 pi/(n+1) (before branch i11-edge: status no_convergence for many with psi within
    !! 1e-17 of it, the early phase not resolving limit - Upsilon): each solved (status ok),
    !! as a solution: |Upsilon(R-bar) - psi| (`half_arch` at the returned R-bar, second
    !! half-arch) within 8 eps psi, s and t = S, T at R-bar to >= 33 digits; where R-bar is
    !! below 1e-35, s and t against their R -> 0 limits (1 - rho) + 2 rho and
    !! 2 t0(0) - t0(rho), t0 by mpmath on int_r^1 dx/v (60 and 45 digits agreeing to 46;
    !! in x = 1 - s^2: the mpmath command in the comment below) to 4 eps.
    !> K = R/v(R) (Tee eq. 25) from the laws' apse constants against R/sqrt(P(R)) by an
    !! independent path: `speed_squared` (expm1 and log; for the power laws only where a
    !! Lambda <= 1, beyond which log R's rounding, a Lambda eps, would dominate) or P(R) =
    !! 2 (R^-a - 1)/a with R^-a by `**`; R from 0.999 down to 1e-30.
    subroutine conserved_momentum()
        real(qp), parameter :: radii(5) = [0.999_qp, 0.5_qp, 0.1_qp, 1.0e-5_qp, 1.0e-30_qp]
        real(qp) :: worst, big_lambda, k, a, p
        integer :: i, j
        type(power_law) :: powers(4)
        type(logarithmic_law) :: logarithmic
        call section('conserved K = R/v(R) from the apse constants')
        powers = [power_law(n=1.1_qp), power_law(n=1.5_qp), power_law(n=6.0_qp), &
                  power_law(n=32.0_qp)]
        worst = 0.0_qp
        do i = 1, size(radii)
            big_lambda = -log(radii(i))
            do j = 1, size(powers)
                a = powers(j)%n - 1.0_qp
                k = powers(j)%conserved(powers(j)%apse_constants(radii(i), &
                    1.0_qp - radii(i), big_lambda))
                if (a*big_lambda <= 1.0_qp) then
                    p = powers(j)%speed_squared(radii(i))
                else
                    p = 2.0_qp*(radii(i)**(-a) - 1.0_qp)/a
                end if
                worst = max(worst, abs(k*sqrt(p)/radii(i) - 1.0_qp)/eps_qp)
            end do
            k = logarithmic%conserved(logarithmic%apse_constants(radii(i), &
                1.0_qp - radii(i), big_lambda))
            worst = max(worst, abs(k*sqrt(logarithmic%speed_squared(radii(i)))/radii(i) &
                                   - 1.0_qp)/eps_qp)
        end do
        write (output_unit, '(a,f0.1)') '   largest error of K / eps: ', worst
        call check(worst <= 16.0_qp, 'K = R/v(R) within 16 eps for power n = 1.1, 1.5, 6, '// &
                   '32 and the logarithmic law, R = 0.999 .. 1e-30')
    end subroutine conserved_momentum

    subroutine to_the_edge()
        real(qp), parameter :: exponents(6) = [1.1_qp, 1.5_qp, 2.0_qp, 3.0_qp, 10.0_qp, &
                                               32.0_qp]
        real(qp), parameter :: radii(4) = [1.0_qp, 0.5_qp, 1.0e-20_qp, 1.0e-30_qp]
        ! (1e-10: the early phase's own target, the edge path's threshold)
        real(qp), parameter :: gaps(5) = [1.0e-10_qp, 1.0e-12_qp, 1.0e-20_qp, 1.0e-28_qp, &
                                          1.0e-32_qp]
        ! 2 t0(0) - t0(rho): mpmath, t0(r) = int_0^sqrt(1-r) 2 s ds/sqrt(P(1 - s^2)),
        ! P(x) = 2 expm1((1-n) log1p(-s^2))/(n-1), mp.quad on [0, .1, .5, .9, sqrt(1-r)]
        ! (n = 3, rho = 0.5 gives 2 - sqrt(3)/2 to 40 digits)
        real(qp), parameter :: limit_t(6, 4) = reshape([ &
            0.0_qp, 0.0_qp, 0.0_qp, 0.0_qp, 0.0_qp, 0.0_qp, &
            1.526326692675333756860035425959304_qp, 1.425084378893371081528350306617925_qp, &
            1.312527711216113580430533190220336_qp, 1.133974596215561353236276829247064_qp, &
            0.0_qp, 0.0_qp, &
            0.0_qp, 0.0_qp, 0.0_qp, 1.0_qp, 0.0_qp, 0.0_qp, &
            0.0_qp, 0.0_qp, 0.0_qp, 1.0_qp, 0.645977837580984503309834651416545_qp, &
            0.382157828065598531754130447768266_qp], [6, 4])
        type(central_force_model) :: model
        type(endpoint_solution) :: a
        real(qp) :: psi, limit, angle, length, time, residual, worst, worst_limit
        integer :: law, i, k, status, failed, limits, most_steps
        call section('central force: to the edge of the sector 2 pi/(n+1)')
        residual = 0.0_qp
        worst = 99.0_qp
        worst_limit = 99.0_qp
        failed = 0
        limits = 0
        most_steps = 0
        do law = 1, size(exponents)
            model = new_central_force_model(power_law(n=exponents(law)))
            limit = 2.0_qp*model%law%apse_angle_limit()
            do i = 1, size(radii)
                do k = 1, size(gaps)
                    psi = limit*(1.0_qp - gaps(k))
                    a = model%solve(radii(i), psi)
                    if (a%status /= status_ok .or. .not. a%apse_radius > 0.0_qp) then
                        failed = failed + 1
                        write (output_unit, '(5x,a,f6.2,2es12.3,i3)') &
                            'unsolved: n, rho, gap, status', exponents(law), radii(i), &
                            gaps(k), a%status
                        cycle
                    end if
                    most_steps = max(most_steps, a%steps)
                    call model%half_arch(radii(i), a%apse_radius, .true., angle, length, &
                                         time, status)
                    residual = max(residual, abs(angle - psi)/(eps_qp*psi))
                    worst = min(worst, digits_of_agreement(length, a%arclength), &
                                digits_of_agreement(time, a%time))
                    if (min(digits_of_agreement(length, a%arclength), &
                            digits_of_agreement(time, a%time)) < 33.0_qp) &
                        write (output_unit, '(5x,a,f6.2,4es12.3,2f7.2,i4)') &
                        'weakest: n, rho, gap, R, |f|/eps psi, digits s, t', &
                        exponents(law), radii(i), gaps(k), a%apse_radius, &
                        abs(angle - psi)/(eps_qp*psi), digits_of_agreement(length, &
                        a%arclength), digits_of_agreement(time, a%time), a%steps
                    if (a%apse_radius < 1.0e-35_qp .and. limit_t(law, i) > 0.0_qp) then
                        limits = limits + 1
                        worst_limit = min(worst_limit, &
                            -log10(abs(a%arclength - (1.0_qp + radii(i)))/(1.0_qp + &
                                   radii(i)) + eps_qp/16.0_qp), &
                            -log10(abs(a%time - limit_t(law, i))/limit_t(law, i) + &
                                   eps_qp/16.0_qp))
                    end if
                end do
            end do
        end do
        write (output_unit, '(a,i0,a,i0,a,i0)') '   n = 1.1 .. 32, 20 endpoints each: '// &
            'unsolved ', failed, ', most evaluations ', most_steps, &
            ', s and t against their R -> 0 limits on ', limits
        write (output_unit, '(a,f6.2,a,f6.2,a,f6.2)') '   worst |Upsilon(R-bar) - psi| in '// &
            'eps psi ', residual, ', fewest digits of s, t = S, T(R-bar) ', worst, &
            ', against the limits ', worst_limit
        call check(failed == 0, 'every endpoint within 1e-10 .. 1e-32 of the edge solved')
        call check(residual <= 8.0_qp, '|Upsilon(R-bar) - psi| <= 8 eps psi at the edge')
        call check(worst >= 33.0_qp, 's and t = S, T at R-bar to >= 33 digits at the edge')
        call check(limits >= 8 .and. worst_limit >= 33.0_qp, &
                   's, t against their R -> 0 limits (mpmath t0) to >= 33 digits')
    end subroutine to_the_edge

    !> The ends of the domain: n -> 1 (the logarithmic law is its limit), the largest
    !! supported exponent, exponents refused beyond it, the logarithmic law up to psi = pi.
    subroutine to_the_limits()
        type(central_force_model) :: near_one, logarithm, steep, beyond
        type(endpoint_solution) :: a, b
        real(qp), parameter :: fractions(7) = [1.0e-3_qp, 0.01_qp, 0.5_qp, 0.9_qp, &
                                               0.99_qp, 0.999_qp, 0.9999_qp]
        real(qp), parameter :: radii(3) = [1.0_qp, 0.5_qp, 0.1_qp]
        real(qp), parameter :: near_pi(6) = [3.135_qp, 3.137_qp, 3.139_qp, 3.14_qp, &
                                             3.1415_qp, 3.14159_qp]
        real(qp) :: worst, psi
        integer :: i, j, solved
        call section('central force: to the limits of the exponent and of the sector')
        near_one = new_central_force_model(power_law(n=1.0_qp + 2.0_qp**(-100)))
        logarithm = new_central_force_model(logarithmic_law())
        worst = 99.0_qp
        do i = 1, 3
            do j = 1, 4
                a = near_one%solve(radii(i), fractions(j)*pi)
                b = logarithm%solve(radii(i), fractions(j)*pi)
                worst = min(worst, digits_of_agreement(a%apse_radius, b%apse_radius), &
                            digits_of_agreement(a%arclength, b%arclength), &
                            digits_of_agreement(a%time, b%time))
            end do
        end do
        write (output_unit, '(a,f6.2)') '   n = 1 + 2^-100 against the logarithmic law, '// &
            'fewest digits of R, s, t: ', worst
        ! they differ by O(n - 1) = 8e-31 relative (times the conditioning near pi)
        call check(worst >= 28.0_qp, 'power law n = 1 + 2^-100 -> logarithmic law')
        steep = new_central_force_model(power_law(n=max_power_exponent))
        solved = 0
        do i = 1, 3
            do j = 1, size(fractions)
                a = steep%solve(radii(i), fractions(j)*2.0_qp*pi/(max_power_exponent + 1))
                if (a%status == status_ok) solved = solved + 1
            end do
        end do
        call check(solved == 3*size(fractions), 'largest supported exponent: every '// &
                   'endpoint of a grid up to 0.9999 of the sector solved')
        beyond = new_central_force_model(power_law(n=2.0_qp*max_power_exponent))
        a = beyond%solve(0.5_qp, 0.01_qp)
        call check(a%status == status_parameter_out_of_range, &
                   'exponent beyond max_power_exponent refused with a status')
        ! logarithmic law up to pi: R-bar down to the binary128 range and below it
        solved = 0
        do j = 1, 6
            psi = near_pi(j)
            a = logarithm%solve(0.5_qp, psi)
            if (a%status == status_ok .and. a%arch == arch_second) solved = solved + 1
        end do
        call check(solved == 6, 'logarithmic law: psi = 3.135 .. 3.14159 solved')
        a = logarithm%solve(0.5_qp, pi)
        call check(a%status == status_inaccessible, 'logarithmic law: psi = pi inaccessible')
    end subroutine to_the_limits

    !> Two-point solutions of the general engine against mpmath on Tee's original
    !! integrals (27), (33), (39) (scripts/make_general_reference.py: bracketed roots, 55
    !! and 70 digits agreeing to >= 40). Each of R-bar, s, t is credited with its
    !! condition number with respect to psi, c = |dF/dpsi| psi/F (an error of one ulp in
    !! Upsilon moves F by c ulps: R-bar next to the edge of the accessible region, and s, t
    !! with it), measured by central differences on the engine's own half-arch values;
    !! the digits printed are raw and credited.
    subroutine general_references(name, law)
        character(len=*), intent(in) :: name
        class(speed_law), intent(in) :: law
        character(len=*), parameter :: classes(9) = [character(len=16) :: 'complete', &
            'complete_small_r', 'first', 'second', 'first_small_r', 'edge_small_r', &
            'near_apse_first', 'near_apse_second', 'all']
        type(central_force_model) :: general
        type(csv_table) :: table
        type(endpoint_solution) :: b
        real(qp) :: rho, psi, expected(3), raw(3), credit(3), worst(3, size(classes))
        real(qp) :: worst_raw(3, size(classes))
        integer :: i, k
        logical :: ok
        call section('central force: '//name//' against mpmath two-point references')
        call read_reference('data/reference/general_'//name//'_mpmath.csv', 30, table, ok)
        if (.not. ok) return
        general = new_central_force_model(law)
        worst = 99.0_qp
        worst_raw = 99.0_qp
        do i = 1, table%row_count()
            rho = table%real_value(i, 'rho')
            psi = table%real_value(i, 'psi')
            expected = [table%real_value(i, 'R'), table%real_value(i, 's'), &
                        table%real_value(i, 't')]
            b = general%solve(rho, psi)
            credit = log10(max(1.0_qp, conditions(general, rho, psi, expected, &
                                                  table%text(i, 'arch') == 'second')))
            raw = [digits_of_agreement(b%apse_radius, expected(1)), &
                   digits_of_agreement(b%arclength, expected(2)), &
                   digits_of_agreement(b%time, expected(3))]
            if (b%status /= 0) raw = 0.0_qp
            if (minval(raw + credit) < 33.0_qp) write (output_unit, '(5x,a,2es12.3,3f7.2)') &
                'weakest: rho, R, digits', rho, expected(1), raw + credit
            do k = 1, size(classes)
                if (table%text(i, 'class') == trim(classes(k)) .or. k == size(classes)) then
                    worst(:, k) = min(worst(:, k), raw + credit)
                    worst_raw(:, k) = min(worst_raw(:, k), raw)
                end if
            end do
        end do
        write (output_unit, '(3x,a,i0,a)') 'fewest digits of R, s, t (raw | credited) on ', &
            table%row_count(), ' endpoints:'
        do k = 1, size(classes)
            if (worst(1, k) < 99.0_qp) write (output_unit, '(5x,a17,3f7.2,a,3f7.2)') &
                classes(k), worst_raw(:, k), ' |', worst(:, k)
        end do
        call check(all(worst(:, size(classes)) >= 32.0_qp), name// &
                   ': R-bar, s, t to >= 32 digits (conditioning credited) on every endpoint')
    end subroutine general_references

    !> Condition numbers of R-bar, s, t with respect to psi at the reference values,
    !! by central differences (step 1e-9 of min(R, rho - R)).
    function conditions(general, rho, psi, expected, second) result(cond)
        type(central_force_model), intent(in) :: general
        real(qp), intent(in) :: rho, psi, expected(3)
        logical, intent(in) :: second
        real(qp) :: cond(3), h, f(3, 2), slope
        integer :: k, status
        cond = 1.0_qp
        h = 1.0e-9_qp*min(expected(1), rho - expected(1))
        if (h <= 0.0_qp) return
        do k = 1, 2
            call general%half_arch(rho, expected(1) + real(2*k - 3, qp)*h, second, &
                                   f(1, k), f(2, k), f(3, k), status)
        end do
        slope = (f(1, 2) - f(1, 1))/(2.0_qp*h)      ! dUpsilon/dR
        cond(1) = psi/abs(expected(1)*slope)
        cond(2:3) = psi*abs((f(2:3, 2) - f(2:3, 1))/(2.0_qp*h*slope))/expected(2:3)
    end function conditions

    subroutine engine_versus_fast_path()
        type(central_force_model) :: general
        type(inverse_square_model) :: fast
        type(endpoint_solution) :: a, b
        real(qp), parameter :: apses(6) = [1.0e-3_qp, 0.05_qp, 0.2_qp, 0.5_qp, 0.8_qp, 0.99_qp]
        real(qp) :: r, big_r, angle(2), length(2), time(2), worst, fall
        integer :: i, j, status, solved
        call section('central force: general engine = inverse-square fast path')
        general = new_central_force_model(inverse_square_law())
        fast = new_inverse_square_model()
        worst = 99.0_qp
        do i = 1, 6
            big_r = apses(i)
            do j = 0, 4
                r = big_r + (1.0_qp - big_r)*real(j, qp)/4.0_qp
                call general%half_arch(r, big_r, j == 2, angle(1), length(1), time(1), &
                                       status)
                call fast%half_arch(r, big_r, j == 2, angle(2), length(2), time(2), status)
                if (r < 1.0_qp) worst = min(worst, digits_of_agreement(angle(1), angle(2)))
                worst = min(worst, digits_of_agreement(length(1), length(2)), &
                            digits_of_agreement(time(1), time(2)))
            end do
        end do
        write (output_unit, '(a,f6.2)') '   fewest digits of Theta, S, T on a grid: ', worst
        call check(worst >= 32.0_qp, 'Theta, S, T agree to >= 32 digits')
        call general%fall_time(0.3_qp, fall, status)
        call check_close(fall, radial_time(0.3_qp), 64.0_qp, 'general fall time = (46)')
        solved = 0
        worst = 99.0_qp
        do i = 1, 5
            do j = 1, 5
                a = general%solve(real(i, qp)/5.0_qp, real(j, qp)*0.4_qp)
                b = solve_endpoint(fast, real(i, qp)/5.0_qp, real(j, qp)*0.4_qp)
                if (a%status == status_ok .and. a%arch == b%arch) solved = solved + 1
                ! R-bar's own conditioning, cond ~ 1.3/R near psi = 2 pi/3, allows
                ! 33 + log10(R) digits there (test_physics measures cond directly)
                worst = min(worst, digits_of_agreement(a%apse_radius, b%apse_radius) &
                            + max(0.0_qp, -1.0_qp - log10(b%apse_radius)), &
                            digits_of_agreement(a%arclength, b%arclength), &
                            digits_of_agreement(a%time, b%time))
            end do
        end do
        write (output_unit, '(a,f6.2)') '   fewest digits of R, s, t on 25 endpoints: ', worst
        call check(solved == 25, 'general two-point solver: same arch on 25 endpoints')
        call check(worst >= 32.0_qp, 'general two-point solver: R, s, t to >= 32 digits')
        a = general%solve(0.5_qp, 2.2_qp)
        call check(a%status == status_inaccessible .and. a%arch == arch_inaccessible, &
                   'general: psi >= 2 pi/3 is inaccessible')
    end subroutine engine_versus_fast_path

    !> Saitoh (7)-(10), units R_E = 1, omega = 1: r^2 = ((1+m^2) + (1-m^2) cos phi)/2,
    !! theta = atan(m tan(phi/2)) - m phi/2, t = (phi/2) sqrt(1 - m^2), m = R_m.
    subroutine harmonic_closed_forms()
        type(central_force_model) :: general
        type(endpoint_solution) :: b
        real(qp), parameter :: minima(5) = [0.01_qp, 0.2_qp, 0.5_qp, 0.7_qp, 0.95_qp]
        real(qp) :: m, phi, r, angle, length, time, theta, worst, solved
        integer :: i, j, status
        call section('central force: harmonic law against Saitoh''s hypocycloid')
        general = new_central_force_model(harmonic_law())
        worst = 99.0_qp
        solved = 99.0_qp
        do i = 1, 5
            m = minima(i)
            call general%half_arch(m, m, .false., angle, length, time, status)
            call check_close(2.0_qp*angle, pi*(1.0_qp - m), 64.0_qp, &
                             'surface angle pi (1 - R_m) (Saitoh)')
            call check_close(2.0_qp*time, pi*sqrt(1.0_qp - m*m), 64.0_qp, &
                             'total time pi sqrt(1 - R_m^2) (10)')
            do j = 1, 3
                phi = pi*real(j, qp)/4.0_qp
                r = sqrt(0.5_qp*((1.0_qp + m*m) + (1.0_qp - m*m)*cos(phi)))
                theta = atan(m*tan(0.5_qp*phi)) - 0.5_qp*m*phi
                call general%half_arch(r, m, .false., angle, length, time, status)
                ! (8) subtracts two terms of size ~ m phi/2: its own rounding is eps times
                ! their size, so measure theta's error on that scale
                worst = min(worst, -log10(abs(angle - theta)/(0.5_qp*m*phi) + eps_qp), &
                            digits_of_agreement(time, 0.5_qp*phi*sqrt(1.0_qp - m*m)))
                ! the two-point problem to the point (r, theta) gives R_m and t(phi) back
                ! (R_m's condition number there is of order 1/m: credited)
                b = general%solve(r, theta)
                solved = min(solved, digits_of_agreement(b%apse_radius, m) &
                             + max(0.0_qp, -log10(m)), &
                             digits_of_agreement(b%time, 0.5_qp*phi*sqrt(1.0_qp - m*m)))
            end do
        end do
        write (output_unit, '(a,f6.2)') '   fewest digits of theta(phi), t(phi): ', worst
        call check(worst >= 32.0_qp, 'theta (8) and t (9) along the hypocycloid, 32 digits')
        write (output_unit, '(a,f6.2)') '   two-point to (r(phi), theta(phi)): fewest digits '// &
            'of R_m, t(phi) ', solved
        call check(solved >= 31.0_qp, 'harmonic two-point: R_m and t (9) to >= 31 digits')
        ! surface to surface: psi = pi (1 - R_m) gives R_m back
        b = general%solve(1.0_qp, pi*0.6_qp)
        call check_close(b%apse_radius, 0.4_qp, 1.0e3_qp, 'two-point, surface to surface')
        call check_close(b%time, pi*sqrt(1.0_qp - 0.16_qp), 1.0e3_qp, &
                         'two-point time pi sqrt(1 - R_m^2)')
    end subroutine harmonic_closed_forms

    !> Power laws: n = 2 is the inverse-square law; Keam: Theta(R,R) -> pi/(n+1),
    !! approached like R^(n-1) (logarithmically for n = 1).
    subroutine power_laws()
        type(central_force_model) :: square, two, three, half_law, logarithm
        real(qp) :: a(2), b(2), angle, worst
        integer :: status, i
        call section('central force: power laws and Keam''s limit pi/(n+1)')
        square = new_central_force_model(inverse_square_law())
        two = new_central_force_model(power_law(n=2.0_qp))
        worst = 99.0_qp
        do i = 1, 4
            call square%apse_angle(real(i, qp)/5.0_qp, a(1), status)
            call two%apse_angle(real(i, qp)/5.0_qp, b(1), status)
            worst = min(worst, digits_of_agreement(b(1), a(1)))
        end do
        call check(worst >= 33.0_qp, 'power law n = 2 reproduces inverse-square')
        three = new_central_force_model(power_law(n=3.0_qp))
        call three%apse_angle(1.0e-10_qp, angle, status)
        call check(status == status_ok .and. abs(angle - pi/4.0_qp) < 1.0e-18_qp, &
                   'n = 3: Theta(R,R) -> pi/4 (|difference| < 1e-18 at R = 1e-10)')
        half_law = new_central_force_model(power_law(n=1.5_qp))
        call half_law%apse_angle(1.0e-20_qp, a(1), status)
        call half_law%apse_angle(1.0e-24_qp, a(2), status)
        call check(abs((pi/2.5_qp - a(1))/(pi/2.5_qp - a(2)) - 100.0_qp) < 1.0e-6_qp, &
                   'n = 1.5: pi/(n+1) - Theta(R,R) ~ R^(1/2)')
        call check(abs(pi/2.5_qp - a(2)) < 4.0e-13_qp, 'n = 1.5: Theta(R,R) -> pi/2.5')
        logarithm = new_central_force_model(logarithmic_law())
        call logarithm%apse_angle(1.0e-8_qp, a(1), status)
        call logarithm%apse_angle(1.0e-40_qp, a(2), status)
        call check(a(1) < a(2) .and. a(2) < pi/2.0_qp .and. pi/2.0_qp - a(2) < 0.01_qp, &
                   'logarithmic potential: Theta(R,R) rises slowly towards pi/2')
    end subroutine power_laws

    !> The whole-half-arch tables (in z = log Lambda, checked at build time) against the
    !! quadrature over all panels (a model without tables): Theta, s, t of both half-arches
    !! at 8 R x 7 r (R from 0.98 to 1.1e-3, the tables' range, with points outside it),
    !! and R, s, t of the two-point problem on a grid, for n = 1.5, 3, 32 and the
    !! logarithmic law.
    subroutine whole_tables()
        type(central_force_model) :: with, without
        type(endpoint_solution) :: a, b
        real(qp) :: big_r, r, x(3), y(3), worst, worst_solve, limit
        real(qp), parameter :: radii(8) = [0.99_qp, 0.98_qp, 0.9_qp, 0.6_qp, 0.3_qp, &
                                           0.05_qp, 1.1e-3_qp, 5.0e-4_qp]
        real(qp), parameter :: fractions(7) = [0.0_qp, 1.0e-20_qp, 1.0e-6_qp, 0.1_qp, &
                                               0.5_qp, 0.9_qp, 1.0_qp]
        integer :: law, i, j, k, m, status
        logical :: second, used
        call section('central force: whole-half-arch tables against all panels')
        worst = 99.0_qp
        worst_solve = 99.0_qp
        used = .true.
        do law = 1, 4
            select case (law)
            case (1)
                with = new_central_force_model(power_law(n=1.5_qp))
                without = new_central_force_model(power_law(n=1.5_qp), tables=.false.)
            case (2)
                with = new_central_force_model(power_law(n=3.0_qp))
                without = new_central_force_model(power_law(n=3.0_qp), tables=.false.)
            case (3)
                with = new_central_force_model(power_law(n=32.0_qp))
                without = new_central_force_model(power_law(n=32.0_qp), tables=.false.)
            case default
                with = new_central_force_model(logarithmic_law())
                without = new_central_force_model(logarithmic_law(), tables=.false.)
            end select
            ! steep laws: pieces at small R fail their check (S, T corrections to
            ! a few digits of themselves) and are not used
            used = used .and. (count(with%whole_ok) >= 8 .or. law == 3) .and. &
                   .not. any(without%whole_ok)
            do i = 1, size(radii)
                big_r = radii(i)
                do j = 1, size(fractions)
                    r = big_r + fractions(j)*(1.0_qp - big_r)
                    do k = 0, 1
                        second = k == 1
                        call with%half_arch(r, big_r, second, x(1), x(2), x(3), status)
                        call without%half_arch(r, big_r, second, y(1), y(2), y(3), status)
                        worst = min(worst, minval([(digits_of_agreement(x(m), y(m)), &
                                                    m = 1, 3)]))
                    end do
                end do
            end do
            limit = 2.0_qp*with%law%apse_angle_limit()
            do i = 1, 4
                do j = 1, 6
                    a = with%solve(0.2_qp*real(i, qp) + 0.2_qp, &
                                   limit*real(2*j - 1, qp)/12.0_qp)
                    b = without%solve(0.2_qp*real(i, qp) + 0.2_qp, &
                                      limit*real(2*j - 1, qp)/12.0_qp)
                    if (a%status /= status_ok .or. b%status /= status_ok) then
                        worst_solve = 0.0_qp
                    else
                        ! R-bar itself is ill-conditioned where it is small (psi near
                        ! the sector's edge): it is compared to 1.5 digits less
                        worst_solve = min(worst_solve, 1.5_qp + &
                                          digits_of_agreement(a%apse_radius, b%apse_radius), &
                                          digits_of_agreement(a%arclength, b%arclength), &
                                          digits_of_agreement(a%time, b%time))
                    end if
                end do
            end do
        end do
        write (output_unit, '(a,2f7.2)') '   fewest digits of theta, s, t (448 points | '// &
            'R (+1.5), s, t on 96 endpoints):', worst, worst_solve
        call check(used, 'tables built and checked on at least 8 of 12 pieces (n = 1.5, '// &
                   '3, logarithmic)')
        call check(worst >= 32.5_qp, 'half-arch values with tables = all panels (32.5 digits)')
        call check(worst_solve >= 32.5_qp, 'two-point R (+1.5), s, t with tables = all panels')
    end subroutine whole_tables

    !> The far tables (Lambda from 11 to 80, R-bar from 1.7e-5 down to 2e-35) against
    !! all panels, for the logarithmic law and power laws n = 1.5, 3, 32: theta, s, t on
    !! both half-arches at apse radii 1e-4 .. 1e-34, and R, s, t of the two-point
    !! problem with R-bar in their range (logarithmic: next to the sector's edge, psi/pi
    !! = 0.95 .. 0.993, R-bar about 1e-5 .. 1e-31; power laws: rho = 1e-8 .. 1e-30 with
    !! psi from 1e-20 to 0.999 of the sector), R-bar's conditioning (d log R/d log psi,
    !! up to 10^4 next to the edge) measured and credited.
    subroutine far_tables()
        real(qp), parameter :: edge(4) = [0.95_qp, 0.98_qp, 0.99_qp, 0.993_qp]
        real(qp), parameter :: small(3) = [1.0e-8_qp, 1.0e-20_qp, 1.0e-30_qp], &
                               part(3) = [1.0e-20_qp, 0.5_qp, 0.999_qp]
        real(qp) :: rho(16), fraction(16)
        integer :: i, j
        call section('central force: far tables against all panels')
        do i = 1, 4
            rho(4*i - 3:4*i) = 0.2_qp*real(i, qp) + 0.2_qp
            fraction(4*i - 3:4*i) = edge
        end do
        call far_law(logarithmic_law(), 'logarithmic', rho, fraction, 4)
        do i = 1, 3
            do j = 1, 3
                rho(3*i + j - 3) = small(i)
                fraction(3*i + j - 3) = part(j)
            end do
        end do
        call far_law(power_law(n=1.5_qp), 'power n = 1.5', rho(1:9), fraction(1:9), 4)
        call far_law(power_law(n=3.0_qp), 'power n = 3', rho(1:9), fraction(1:9), 4)
        call far_law(power_law(n=32.0_qp), 'power n = 32', rho(1:9), fraction(1:9), 3)
    end subroutine far_tables

    !> The deep tables (Lambda from 80 to 11355, R-bar from 2e-35 down to the bottom of
    !! binary128) against all panels, for the logarithmic law and power laws n = 1.1,
    !! 1.5 (every deep piece) and 6 (the pieces whose slopes stay in the hardware range,
    !! Lambda up to about 2000): theta, s, t on both half-arches at apse radii 1e-40 ..
    !! 1e-4900, and R, s, t of the two-point problem with R-bar from 1e-47 down to
    !! 2e-1003 (next to the sector's edge: logarithmic psi/pi = 0.997, 0.9995 at rho =
    !! 0.5, 1: R-bar 3e-73, 4e-435; n = 1.1, 1 - psi/sector = 1e-6, 1e-12: 8e-48, 8e-108;
    !! and rho = 1e-50 .. 1e-1000), R-bar's conditioning measured and credited (as
    !! `far_tables`).
    subroutine deep_tables()
        real(qp) :: rho(4), fraction(4)
        call section('central force: deep tables against all panels')
        rho = [0.5_qp, 1.0_qp, 1.0e-60_qp, 1.0e-1000_qp]
        fraction = [0.997_qp, 0.9995_qp, 0.5_qp, 0.999_qp]
        call far_law(logarithmic_law(), 'logarithmic', rho, fraction, 8, deep=.true.)
        rho = [1.0_qp, 0.5_qp, 1.0e-50_qp, 1.0e-1000_qp]
        fraction = [1.0_qp - 1.0e-6_qp, 1.0_qp - 1.0e-12_qp, 0.5_qp, 0.999_qp]
        call far_law(power_law(n=1.1_qp), 'power n = 1.1', rho, fraction, 8, deep=.true.)
        call far_law(power_law(n=1.5_qp), 'power n = 1.5', rho, fraction, 8, deep=.true.)
        rho = [1.0e-50_qp, 1.0e-50_qp, 1.0e-300_qp, 1.0e-300_qp]
        fraction = [1.0e-20_qp, 0.999_qp, 0.5_qp, 0.999_qp]
        call far_law(power_law(n=6.0_qp), 'power n = 6', rho, fraction, 4, deep=.true.)
    end subroutine deep_tables

    !> `far_tables` for one law: half-arches at the radii, the two-point problem at
    !! (rho, fraction of the sector); at least `pieces` far pieces built and checked
    !! (with `deep`: the deep tables' radii and pieces).
    subroutine far_law(law, name, rho, fraction, pieces, deep)
        class(speed_law), intent(in) :: law
        character(len=*), intent(in) :: name
        real(qp), intent(in) :: rho(:), fraction(:)
        integer, intent(in) :: pieces
        logical, intent(in), optional :: deep
        type(central_force_model) :: with, without
        type(endpoint_solution) :: a, b, c
        real(qp) :: big_r, r, x(3), y(3), worst, worst_solve, limit, credit, radii(7)
        logical :: built
        real(qp), parameter :: fractions(7) = [0.0_qp, 1.0e-20_qp, 1.0e-6_qp, 0.1_qp, &
                                               0.5_qp, 0.9_qp, 1.0_qp]
        integer :: i, j, k, m, status
        radii = [1.0e-4_qp, 1.0e-6_qp, 1.0e-10_qp, 1.0e-16_qp, 1.0e-22_qp, 1.0e-30_qp, &
                 1.0e-34_qp]
        if (present(deep)) radii = [1.0e-40_qp, 1.0e-100_qp, 1.0e-300_qp, 1.0e-800_qp, &
                                    1.0e-1500_qp, 1.0e-3000_qp, 1.0e-4900_qp]
        worst = 99.0_qp
        worst_solve = 99.0_qp
        with = new_central_force_model(law)
        without = new_central_force_model(law, tables=.false.)
        do i = 1, size(radii)
            big_r = radii(i)
            do j = 1, size(fractions)
                r = big_r + fractions(j)*(1.0_qp - big_r)
                do k = 0, 1
                    call with%half_arch(r, big_r, k == 1, x(1), x(2), x(3), status)
                    call without%half_arch(r, big_r, k == 1, y(1), y(2), y(3), status)
                    worst = min(worst, minval([(digits_of_agreement(x(m), y(m)), m = 1, 3)]))
                end do
            end do
        end do
        limit = 2.0_qp*with%law%apse_angle_limit()
        do i = 1, size(rho)
            a = with%solve(rho(i), fraction(i)*limit)
            b = without%solve(rho(i), fraction(i)*limit)
            c = with%solve(rho(i), fraction(i)*limit*(1.0_qp + 1.0e-20_qp))
            if (a%status /= status_ok .or. b%status /= status_ok .or. &
                c%status /= status_ok) then
                worst_solve = 0.0_qp
            else
                ! R-bar's conditioning: log10 of |d log R/d log psi|
                credit = log10(max(1.0_qp, abs(c%apse_radius - a%apse_radius)/ &
                                            (1.0e-20_qp*a%apse_radius)))
                worst_solve = min(worst_solve, credit + &
                                  digits_of_agreement(a%apse_radius, b%apse_radius), &
                                  digits_of_agreement(a%arclength, b%arclength), &
                                  digits_of_agreement(a%time, b%time))
            end if
        end do
        built = count(with%far_ok) >= pieces .and. .not. any(without%far_ok)
        k = count(with%far_ok)
        if (present(deep)) then
            built = count(with%deep_ok) >= pieces .and. .not. any(without%deep_ok)
            k = count(with%deep_ok)
        end if
        write (output_unit, '(3a,i0,a,2f7.2,a,i0,2a)') '   ', name, ': fewest digits of '// &
            'theta, s, t (98 points | R (credited), s, t on ', size(rho), ' endpoints):', &
            worst, worst_solve, ' (', k, trim(merge(' deep pieces)', ' pieces)     ', &
                                                      present(deep)))
        call check(built, 'far tables built and checked ('//name//')')
        call check(worst >= 32.5_qp, 'half-arch values with far tables = all panels ('// &
                   name//')')
        call check(worst_solve >= 32.5_qp, 'two-point R (conditioning credited), s, t with '// &
                   'far tables = all panels ('//name//')')
    end subroutine far_law

    pure subroutine no_closed_fall_power(self, delta_lo, delta_hi, t, found)
        class(quadrature_power_law), intent(in) :: self
        real(qp), intent(in) :: delta_lo, delta_hi
        real(qp), intent(out) :: t
        logical, intent(out) :: found
        t = 0.0_qp
        found = .false.
    end subroutine no_closed_fall_power

    pure subroutine no_closed_fall_logarithmic(self, delta_lo, delta_hi, t, found)
        class(quadrature_logarithmic_law), intent(in) :: self
        real(qp), intent(in) :: delta_lo, delta_hi
        real(qp), intent(out) :: t
        logical, intent(out) :: found
        t = 0.0_qp
        found = .false.
    end subroutine no_closed_fall_logarithmic

    pure logical function no_terms_xp(self)
        class(secant_power_law), intent(in) :: self
        no_terms_xp = .false.
    end function no_terms_xp

    !> B within 1e-16 of its apse angle, not at it (psi = Theta(rho,rho) (1 + k 1e-18)):
    !! the root next to u = 0 from the slope there (`apse_start`, three evaluations)
    !! against the double-precision phase with secant steps: s, t to >= 32 digits, the
    !! gap rho - R-bar (= u^2, u ~ psi - Theta(rho,rho)) with its conditioning
    !! psi/|psi - Theta(rho,rho)| credited.
    subroutine next_to_the_apse_angle()
        type(central_force_model) :: hardware, secant
        type(endpoint_solution) :: a, b
        real(qp), parameter :: radii(4) = [1.0e-30_qp, 1.0e-6_qp, 0.5_qp, 0.99_qp]
        real(qp), parameter :: offsets(6) = [-30.0_qp, -3.0_qp, -1.0_qp, 1.0_qp, 3.0_qp, &
                                             30.0_qp]
        real(qp), parameter :: exponents(4) = [1.5_qp, 6.0_qp, 10.0_qp, 32.0_qp]
        real(qp) :: psi, apse, worst, digits(3)
        integer :: law, i, k, status, most_steps, failed
        call section('central force: B within 1e-16 of its apse angle')
        worst = 99.0_qp
        most_steps = 0
        failed = 0
        do law = 1, 4
            hardware = new_central_force_model(power_law(n=exponents(law)))
            secant = new_central_force_model(secant_power_law(n=exponents(law)))
            do i = 1, size(radii)
                call hardware%apse_angle(radii(i), apse, status)
                do k = 1, size(offsets)
                    psi = apse*(1.0_qp + offsets(k)*1.0e-18_qp)
                    a = hardware%solve(radii(i), psi)
                    b = secant%solve(radii(i), psi)
                    if (a%status /= status_ok .or. b%status /= status_ok) then
                        failed = failed + 1
                        cycle
                    end if
                    most_steps = max(most_steps, a%steps)
                    digits = [digits_of_agreement(a%apse_gap, b%apse_gap) + &
                              log10(psi/abs(psi - apse)), &
                              digits_of_agreement(a%arclength, b%arclength), &
                              digits_of_agreement(a%time, b%time)]
                    if (minval(digits) < 32.0_qp) write (output_unit, &
                        '(5x,a,f6.2,2es12.3,3f7.2)') 'weakest: n, rho, offset, digits', &
                        exponents(law), radii(i), offsets(k), digits
                    worst = min(worst, minval(digits))
                end do
            end do
        end do
        write (output_unit, '(a,f6.2,a,i0,a,i0)') '   n = 1.5, 6, 10, 32, 4 radii, '// &
            '6 offsets: '// &
            'fewest digits (gap credited) ', worst, ', most evaluations ', most_steps, &
            ', unsolved ', failed
        call check(failed == 0 .and. worst >= 32.0_qp, &
                   'next to the apse angle: = double phase and secant steps to >= 32 digits')
        call check(most_steps <= 4, 'next to the apse angle: at most 4 evaluations')
    end subroutine next_to_the_apse_angle

    !> The hardware-precision early phase with one certified full-precision step against
    !! the double-precision phase with secant steps, on a grid of endpoints scaled to the
    !! sector: R-bar, s and t with their conditioning credited. Next to the sector's edge
    !! (psi = (1 - 1e-9) of it) the secant path's s is off (22 digits at n = 10, rho = 1:
    !! s along the secant); there both are checked as solutions instead: Upsilon(R-bar) =
    !! psi and s, t = S, T at R-bar by `half_arch` on the full rules.
    subroutine two_root_finders()
        type(central_force_model) :: hardware, secant
        type(endpoint_solution) :: a, b
        real(qp), parameter :: radii(5) = [1.0e-6_qp, 0.05_qp, 0.5_qp, 0.99_qp, 1.0_qp]
        real(qp), parameter :: fractions(7) = [1.0e-6_qp, 0.01_qp, 0.3_qp, 0.6_qp, 0.9_qp, &
                                               0.999_qp, 1.0_qp - 1.0e-9_qp]
        real(qp) :: angle, length, time, residual
        integer :: status
        real(qp), parameter :: exponents(4) = [1.5_qp, 3.0_qp, 10.0_qp, 32.0_qp]
        real(qp) :: worst, psi, credit(3), digits(3), worst_solution
        integer :: law, i, j, failed
        call section('central force: hardware early phase = double phase and secant steps')
        worst = 99.0_qp
        worst_solution = 99.0_qp
        residual = 0.0_qp
        failed = 0
        do law = 1, 4
            hardware = new_central_force_model(power_law(n=exponents(law)))
            secant = new_central_force_model(secant_power_law(n=exponents(law)))
            do i = 1, size(radii)
                do j = 1, size(fractions)
                    psi = fractions(j)*2.0_qp*hardware%law%apse_angle_limit()
                    a = hardware%solve(radii(i), psi)
                    b = secant%solve(radii(i), psi)
                    if (a%status /= status_ok .or. b%status /= status_ok) then
                        failed = failed + 1
                        cycle
                    end if
                    if (j == size(fractions)) then
                        ! next to the edge, as a solution: Upsilon(R-bar) - psi and s, t
                        ! against S, T there (R-bar far from rho: r - R-bar exact enough)
                        call hardware%half_arch(radii(i), a%apse_radius, &
                                                a%arch /= arch_first, angle, length, time, &
                                                status)
                        residual = max(residual, abs(angle - psi)/(eps_qp*psi))
                        worst_solution = min(worst_solution, digits_of_agreement(length, &
                            a%arclength), digits_of_agreement(time, a%time))
                        cycle
                    end if
                    credit = log10(max(1.0_qp, conditions(hardware, radii(i), psi, &
                        [b%apse_radius, b%arclength, b%time], a%arch == arch_second)))
                    digits = [digits_of_agreement(a%apse_radius, b%apse_radius), &
                              digits_of_agreement(a%arclength, b%arclength), &
                              digits_of_agreement(a%time, b%time)] + credit
                    if (minval(digits) < 32.0_qp) write (output_unit, &
                        '(5x,a,f6.2,2es12.3,3f7.2,2i4)') 'weakest: n, rho, psi, digits', &
                        exponents(law), radii(i), fractions(j), digits, a%steps, b%steps
                    worst = min(worst, minval(digits))
                end do
            end do
        end do
        write (output_unit, '(a,f6.2,a,i0)') '   n = 1.5, 3, 10, 32 on 30 endpoints each: '// &
            'fewest digits (credited) ', worst, ', unsolved ', failed
        write (output_unit, '(a,f6.2,a,f6.2)') '   at the edge: worst |Upsilon(R) - psi| '// &
            'in eps psi ', residual, ', fewest digits of s, t = S, T(R) ', worst_solution
        call check(failed == 0, 'both root finders solve every endpoint')
        call check(worst >= 32.0_qp, 'the two root finders agree to >= 32 digits')
        call check(residual <= 16.0_qp .and. worst_solution >= 33.0_qp, &
                   'hardware path: Upsilon(R-bar) = psi, s and t = S, T at R-bar')
    end subroutine two_root_finders

    pure subroutine no_closed_fall_harmonic(self, delta_lo, delta_hi, t, found)
        class(quadrature_harmonic_law), intent(in) :: self
        real(qp), intent(in) :: delta_lo, delta_hi
        real(qp), intent(out) :: t
        logical, intent(out) :: found
        t = 0.0_qp
        found = .false.
    end subroutine no_closed_fall_harmonic

    !> rho = 1 - 1e-30 (a sliver panel next to the start, which once ended the early
    !! phase's quadrature: 80 iterations) against rho = 1: R-bar, s, t agree to the
    !! difference the endpoints make, in few steps.
    subroutine next_to_the_start()
        type(central_force_model) :: model
        type(endpoint_solution) :: a, b
        ! (psi well above Theta(rho, rho) ~ 1e-15: a tiny psi is a different arch)
        real(qp), parameter :: fractions(4) = [1.0e-6_qp, 1.0e-3_qp, 0.5_qp, &
                                               1.0_qp - 1.0e-6_qp]
        real(qp) :: limit, worst
        integer :: i, law, most
        call section('central force: rho = 1 - 1e-30 against rho = 1')
        worst = 99.0_qp
        most = 0
        do law = 1, 3
            select case (law)
            case (1); model = new_central_force_model(power_law(n=3.0_qp))
            case (2); model = new_central_force_model(power_law(n=1.5_qp))
            case default; model = new_central_force_model(logarithmic_law())
            end select
            limit = 2.0_qp*model%law%apse_angle_limit()
            do i = 1, size(fractions)
                a = model%solve(1.0_qp - 1.0e-30_qp, fractions(i)*limit)
                b = model%solve(1.0_qp, fractions(i)*limit)
                if (a%status /= status_ok .or. b%status /= status_ok) most = 999
                most = max(most, a%steps, b%steps)
                worst = min(worst, digits_of_agreement(a%apse_radius, b%apse_radius), &
                            digits_of_agreement(a%arclength, b%arclength), &
                            digits_of_agreement(a%time, b%time))
            end do
        end do
        write (output_unit, '(a,f6.2,a,i0)') '   12 endpoints: fewest digits ', worst, &
            ', most steps ', most
        ! the endpoints differ by about sqrt(1 - rho)/psi = 1e-9 (psi = 1e-6 of the sector)
        call check(worst >= 8.0_qp, 'rho = 1 - 1e-30 agrees with rho = 1 to their difference')
        call check(most <= 30, 'rho next to 1: at most 30 evaluations')
    end subroutine next_to_the_start

    !> The engine's fast exp and expm1 against libquadmath's, on arguments next to the
    !! table steps j/256 and j/65536, next to m + 1/2 (where the previous version switched
    !! tables e^(+-m)) and up to 130.5, past the tables' end 128, and spread over the range
    !! the integrands use.
    subroutine fast_exponentials()
        use brachistochrone_fast_exp, only: fast_exp, fast_expm1
        use brachistochrone_quad_math, only: expm1
        real(qp) :: x, worst, step
        integer :: j, k, sign_
        call section('central force: fast exp and expm1 against libquadmath')
        worst = 0.0_qp
        do sign_ = -1, 1, 2
            do j = 0, 200
                do k = -2, 2
                    ! next to j/256 + (j mod 7)/65536, a few ulps either side
                    x = real(sign_, qp)*(real(j, qp)/256.0_qp + real(mod(j, 7), qp)/65536.0_qp)
                    x = x + real(k, qp)*spacing(max(abs(x), tiny(1.0_qp)))
                    if (abs(x) < 1.0_qp .and. x /= 0.0_qp) worst = max(worst, &
                        abs(fast_expm1(x) - expm1(x))/(eps_qp*abs(expm1(x))))
                    worst = max(worst, abs(fast_exp(x) - exp(x))/(eps_qp*exp(x)))
                end do
            end do
            ! next to the switches between the tables e^(+-m), m + 1/2, up to 127.5 and
            ! past it (x +- a few ulps)
            do j = 0, 130
                do k = -2, 2
                    x = real(sign_, qp)*(real(j, qp) + 0.5_qp)
                    x = x + real(k, qp)*spacing(x)
                    worst = max(worst, abs(fast_exp(x) - exp(x))/(eps_qp*exp(x)))
                    if (abs(x) < 1.0_qp) worst = max(worst, &
                        abs(fast_expm1(x) - expm1(x))/(eps_qp*abs(expm1(x))))
                end do
            end do
        end do
        ! the reduced argument next to its largest, 2^-16 (the series' tail largest)
        do j = -255, 255
            x = real(j, qp)/256.0_qp + sign(real(mod(abs(j), 256), qp) + 0.999_qp, &
                                          real(j, qp))/65536.0_qp
            if (abs(x) < 1.0_qp .and. x /= 0.0_qp) worst = max(worst, &
                abs(fast_expm1(x) - expm1(x))/(eps_qp*abs(expm1(x))))
            worst = max(worst, abs(fast_exp(x) - exp(x))/(eps_qp*exp(x)))
        end do
        step = 1.0_qp/3.0_qp
        do j = -3000, 3000
            x = real(j, qp)*step
            worst = max(worst, abs(fast_exp(x) - exp(x))/(eps_qp*exp(x)))
        end do
        write (output_unit, '(a,f6.2)') '   worst relative error in eps: ', worst
        call check(worst <= 4.0_qp, 'fast exp, expm1 within 4 eps of libquadmath''s')
    end subroutine fast_exponentials

    !> fast exp and expm1 at 100000 arguments, |x| log-uniform over 1e-30 .. 11000 (a
    !! fixed pseudo-random sequence), and next to the reduction's switches (whole numbers
    !! m (0 .. 255), j/256, j/65536 = j 2^-16, j 2^-8, multiples of log 2/2), against
    !! libquadmath's (which is within 1.5 ulp: mpmath, scripts/check_fast_exp.py): within
    !! 2 ulp of it.
    !! (The previous version was 3 ulp off libquadmath at some of these.)
    subroutine fast_exponentials_spread()
        use brachistochrone_fast_exp, only: fast_exp, fast_expm1
        use brachistochrone_quad_math, only: expm1
        use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf, &
                                                 ieee_negative_inf, ieee_quiet_nan
        integer, parameter :: count = 100000
        real(qp), parameter :: switches(4) = [1.0_qp, 1.0_qp/256, 1.0_qp/65536, &
                                              2.0_qp**(-8)]
        real(qp) :: x, worst(2), u, special(15)
        integer :: i, j
        integer(int64) :: state
        logical :: same
        call section('central force: fast exp and expm1 spread, against libquadmath''s')
        worst = 0.0_qp
        state = 20261130_int64
        do i = 1, count
            u = next_uniform(state)
            if (mod(i, 7) == 0) then
                ! next to a switch (j times one of them, or j log 2/2), within 20 ulps
                j = 1 + int(next_uniform(state)*255.0_qp)
                if (mod(i, 14) == 0) then
                    x = real(j, qp)*switches(1 + mod(i/14, size(switches)))
                else
                    j = j*int(1.0_qp + next_uniform(state)*120.0_qp)
                    x = real(j, qp)*log(2.0_qp)/2
                end if
                x = x + real(int(u*41.0_qp) - 20, qp)*spacing(x)
            else
                x = 10.0_qp**(-30.0_qp + u*(30.0_qp + log10(11000.0_qp)))
            end if
            if (mod(i, 2) == 0) x = -x
            worst(1) = max(worst(1), abs(fast_exp(x) - exp(x))/spacing(exp(x)))
            worst(2) = max(worst(2), abs(fast_expm1(x) - expm1(x))/spacing(expm1(x)))
        end do
        write (output_unit, '(a,2f6.2)') '   worst ulps off libquadmath, exp and expm1: ', &
            worst
        call check(worst(1) <= 2.0_qp, 'fast exp within 2 ulp of libquadmath''s')
        call check(worst(2) <= 2.0_qp, 'fast expm1 within 2 ulp of libquadmath''s')
        ! zeros, subnormals, overflow, underflow, infinities, NaN: as the library
        special = [0.0_qp, -0.0_qp, tiny(1.0_qp)/1.0e10_qp, -tiny(1.0_qp), 11000.5_qp, &
                   -11000.5_qp, 11356.6_qp, -11400.0_qp, 2.0e4_qp, -2.0e4_qp, huge(1.0_qp), &
                   -huge(1.0_qp), ieee_value(1.0_qp, ieee_positive_inf), &
                   ieee_value(1.0_qp, ieee_negative_inf), ieee_value(1.0_qp, ieee_quiet_nan)]
        same = .true.
        do i = 1, size(special)
            x = special(i)
            same = same .and. (fast_exp(x) == exp(x) .or. (x /= x .and. fast_exp(x) /= &
                fast_exp(x))) .and. (fast_expm1(x) == expm1(x) .or. (x /= x .and. &
                fast_expm1(x) /= fast_expm1(x))) .and. sign(1.0_qp, fast_expm1(x)) == &
                sign(1.0_qp, expm1(x))
        end do
        call check(same, 'fast exp, expm1 at zeros, subnormals, +-Inf, NaN, over/underflow')
    end subroutine fast_exponentials_spread

    !> fast exp and expm1 against mpmath (data/reference/fast_exp_mpmath.csv, made by
    !! scripts/make_fast_exp_reference.py: 1500 arguments, |x| 1e-30 .. 11000 and next to
    !! the reduction's switches, the values as hi + lo pairs), errors in ulps of the value
    !! |(y - hi) - lo|/spacing(hi): within 0.75 ulp (the rounding's 0.5 and the pairs' error;
    !! 10^5 arguments, scripts/bench_fast_exp.sh: 0.50 and 0.60; the previous version 2.3
    !! and 3.1, libquadmath 0.50 and 1.45).
    subroutine fast_exponentials_mpmath()
        use brachistochrone_fast_exp, only: fast_exp, fast_expm1
        type(csv_table) :: table
        logical :: ok
        integer :: i
        real(qp) :: x, worst(2), hi, lo
        call section('central force: fast exp and expm1 against mpmath, in ulps')
        call read_reference('data/reference/fast_exp_mpmath.csv', 1500, table, ok)
        if (.not. ok) return
        worst = 0.0_qp
        do i = 1, table%row_count()
            x = table%real_value(i, 'x')
            hi = table%real_value(i, 'exp_hi')
            lo = table%real_value(i, 'exp_lo')
            worst(1) = max(worst(1), abs((fast_exp(x) - hi) - lo)/spacing(hi))
            hi = table%real_value(i, 'expm1_hi')
            lo = table%real_value(i, 'expm1_lo')
            worst(2) = max(worst(2), abs((fast_expm1(x) - hi) - lo)/spacing(hi))
        end do
        write (output_unit, '(a,2f7.3)') '   worst ulps, exp and expm1: ', worst
        call check(worst(1) <= 0.75_qp, 'fast exp within 0.75 ulp of mpmath''s')
        call check(worst(2) <= 0.75_qp, 'fast expm1 within 0.75 ulp of mpmath''s')
    end subroutine fast_exponentials_mpmath

    !> A uniform number in (0, 1) from the state of Park and Miller's minimal standard
    !! generator (state <- 48271 state mod (2^31 - 1); no overflow in 64 bits).
    real(qp) function next_uniform(state) result(u)
        integer(int64), intent(inout) :: state
        state = mod(state*48271_int64, 2147483647_int64)
        u = real(state, qp)/2147483647.0_qp
    end function next_uniform

    !> The closed-form fall times (n = 2: Tee (46); n = 3: sqrt(1 - r^2); other n: the
    !! incomplete beta function's series; logarithmic: sqrt(pi/2) erf(sqrt(-log r)))
    !! against the engine's quadrature of x/v, and the
    !! n = 2 engine (its special paths) against the inverse-square fast path.
    subroutine closed_fall_times()
        type(central_force_model) :: closed, quadrature
        type(inverse_square_model) :: fast
        type(endpoint_solution) :: a, b
        real(qp), parameter :: radii(12) = [0.0_qp, 1.0e-6_qp, 0.3_qp, 0.9_qp, &
                                            1.0_qp - 1.0e-12_qp, 1.0_qp - 1.0e-30_qp, &
                                            0.05_qp, 3.0e-4_qp, 2.0e-22_qp, 1.0e-65_qp, &
                                            0.082_qp, 4.5e-5_qp]
        real(qp), parameter :: exponents(11) = [2.0_qp, 3.0_qp, 1.25_qp, 1.5_qp, 10.0_qp, &
                                                32.0_qp, 1.1_qp, 1.01_qp, 1.0_qp + 1.0e-6_qp, &
                                                1.0_qp + 2.0_qp**(-100), 2.5_qp]
        real(qp) :: t(2), worst
        integer :: law, i, j, status
        call section('central force: closed-form fall times against the quadrature')
        worst = 99.0_qp
        do law = 1, 8 + size(exponents) - 6
            select case (law)
            case (1:6, 9:)
                j = merge(law, law - 2, law <= 6)
                closed = new_central_force_model(power_law(n=exponents(j)), tables=.false.)
                quadrature = new_central_force_model(quadrature_power_law(n=exponents(j)), &
                                                     tables=.false.)
            case (8)
                closed = new_central_force_model(harmonic_law())
                quadrature = new_central_force_model(quadrature_harmonic_law())
            case default
                closed = new_central_force_model(logarithmic_law())
                quadrature = new_central_force_model(quadrature_logarithmic_law())
            end select
            do i = 1, size(radii)
                call closed%fall_time(radii(i), t(1), status)
                call quadrature%fall_time(radii(i), t(2), status)
                worst = min(worst, digits_of_agreement(t(1), t(2)))
            end do
        end do
        write (output_unit, '(a,f6.2)') '   n = 2, 3, 1.25, 1.5, 10, 32, 1.1, 1.01, 1 + 1e-6, ' &
            //'1 + 2^-100, 2.5, logarithmic, harmonic, 12 radii: fewest digits ', worst
        call check(worst >= 32.5_qp, 'closed-form fall times = quadrature to >= 32.5 digits')
        closed = new_central_force_model(power_law(n=2.0_qp))
        fast = new_inverse_square_model()
        worst = 99.0_qp
        do i = 1, 3
            do j = 1, 3
                a = closed%solve(real(i, qp)/3.0_qp, real(j, qp)*0.5_qp)
                b = solve_endpoint(fast, real(i, qp)/3.0_qp, real(j, qp)*0.5_qp)
                worst = min(worst, digits_of_agreement(a%apse_radius, b%apse_radius) &
                            + max(0.0_qp, -1.0_qp - log10(b%apse_radius)), &
                            digits_of_agreement(a%arclength, b%arclength), &
                            digits_of_agreement(a%time, b%time))
            end do
        end do
        write (output_unit, '(a,f6.2)') '   power law n = 2 = fast path, 9 endpoints: ', worst
        call check(worst >= 32.0_qp, 'power law n = 2: R, s, t = fast path to >= 32 digits')
    end subroutine closed_fall_times

    !> The power law's fall time from the tables or coefficients kept by `prepare` and
    !! from the series computed at each call against mpmath on the original integral
    !! (data/reference/power_fall_time_mpmath.csv: 12 exponents from 1 + 2^-100 to 32, delta =
    !! 1e-34 .. 40; n < 3/2: `mild_table_time`'s tables, else the kept series coefficients).
    subroutine fall_time_tables()
        type(csv_table) :: table
        type(power_law) :: tabulated, series
        real(qp) :: n, delta, reference, t(2), worst(2)
        integer :: i
        logical :: ok, found
        call section('central force: the power law''s fall time against mpmath')
        call read_reference('data/reference/power_fall_time_mpmath.csv', 108, table, ok)
        if (.not. ok) return
        worst = 0.0_qp
        do i = 1, table%row_count()
            n = table%real_value(i, 'n')
            delta = table%real_value(i, 'delta')
            reference = table%real_value(i, 't0')
            tabulated = power_law(n=n)
            call tabulated%prepare()
            series = tabulated
            series%fall_table = .false.
            series%mild_table = .false.
            call check(tabulated%fall_table .neqv. tabulated%mild_table, &
                'fall-time coefficients (n >= 3/2) or tables (n < 3/2) kept')
            call tabulated%closed_fall(0.0_qp, delta, t(1), found)
            call series%closed_fall(0.0_qp, delta, t(2), found)
            ! (delta rounded to binary128 moves t0 by at most eps t0/2)
            worst = max(worst, abs(t - reference)/(eps_qp*reference))
        end do
        write (output_unit, '(a,2f7.2)') '   worst error in eps (tables, series): ', worst
        call check(worst(1) <= 8.0_qp, 'fall time from the kept tables = mpmath to 8 eps')
        call check(worst(2) <= 8.0_qp, 'fall time from the series = mpmath to 8 eps')
    end subroutine fall_time_tables

end module test_central_force
