!> The harmonic (uniform planet) tunnels against independent values: Tee's general
!! integrals (27), (33), (39) for v = sqrt(1 - r^2) integrated here in quad precision,
!! an mpmath reference at 45 digits (scripts/make_harmonic_reference.py), the
!! rolling-circle form of the hypocycloid, and the tautochrone property.
module test_harmonic
    use, intrinsic :: iso_fortran_env, only: output_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_quiet_nan
    use brachistochrone_kinds, only: qp, pi, eps_qp, xp
    use brachistochrone_status, only: status_ok, status_not_finite, status_invalid_argument, &
                                      status_rho_out_of_range, status_psi_out_of_range, &
                                      status_latitude_out_of_range, status_bad_planet
    use brachistochrone_quadrature, only: univariate_integrand, gauss_legendre_rule, &
            gauss_legendre, integrate_adaptive
    use brachistochrone_arches, only: arch_first, arch_second, arch_complete, arch_radial
    use brachistochrone_harmonic, only: hypocycloid_point, harmonic_tunnel, harmonic_planet, &
                                        planet_tunnel, hypocycloid_radius, hypocycloid_angle, &
                                        hypocycloid_time, hypocycloid_arclength, &
                                        hypocycloid_position, hypocycloid_phase, &
                                        hypocycloid_angle_at_radius, tunnel_time, &
                                        tunnel_arclength, tunnel_surface_angle, hypocycloid_at, &
                                        surface_to_surface, solve_harmonic_endpoint, &
                                        tautochrone_time, angular_frequency, time_scale, &
                                        great_circle_angle, plan_tunnel, earth_radius_km, &
                                        earth_gravity
    use reference_tables, only: csv_table, read_reference
    use testing, only: check, check_close, check_digits, section, digits_of_agreement
    implicit none
    private

    public :: run_harmonic_tests

    !> Which of Tee's integrals.
    integer, parameter :: tee_theta = 1, tee_arclength = 2, tee_time = 3

    !> Tee's (27), (33), (39) for v(x) = sqrt(1 - x^2) with apse R, in the variable chi of
    !! x = R + (1 - R) cos^2(chi/2), chi in [0, pi] from the surface (chi = 0) to the apse
    !! (chi = pi), which removes the sqrt(1 - x) and 1/sqrt(x - R) endpoint behaviour and
    !! keeps the relative precision of short intervals near the surface. With
    !! sg = cos(chi/2) = sqrt((x - R)/(1 - R)), cg = sin(chi/2) = sqrt((1 - x)/(1 - R)),
    !! |dx| = (1 - R) sg cg dchi:
    !!   (27)  R sqrt(1-x^2)/(x sqrt(x^2-R^2)) dx   = R (1-R) cg^2 sqrt((1+x)/(x+R))/x dchi
    !!   (33)  x sqrt(1-R^2)/sqrt(x^2-R^2) dx       = x sqrt(1-R^2) sqrt(1-R) cg/sqrt(x+R) dchi
    !!   (39)  x sqrt(1-R^2)/sqrt((1-x^2)(x^2-R^2)) dx = x sqrt(1-R^2)/sqrt((1+x)(x+R)) dchi
    !! ((v(R)/R)^2 x^2/v(x)^2 - 1 = (x^2 - R^2)/(R^2 (1 - x^2)) for this speed law.)
    type, extends(univariate_integrand) :: tee_integrand
        integer :: which = tee_theta   !! tee_theta, tee_arclength or tee_time
        real(qp) :: apse = 0.0_qp      !! R
    contains
        procedure :: evaluate => tee_evaluate
    end type tee_integrand

    !> |dP/dphi| of the rolling-circle form (Saitoh 11-12), a = (1 - rho_m)/2.
    type, extends(univariate_integrand) :: rolling_speed
        real(qp) :: depth = 0.0_qp     !! 1 - rho_m
    contains
        procedure :: evaluate => rolling_speed_evaluate
    end type rolling_speed

contains

    pure function tee_evaluate(self, x) result(y)
        class(tee_integrand), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp) :: y
        real(qp) :: big_r, sg, cg, radius
        big_r = self%apse
        sg = cos(0.5_qp*x)
        cg = sin(0.5_qp*x)
        radius = big_r + (1.0_qp - big_r)*sg*sg
        select case (self%which)
        case (tee_theta)
            y = big_r*(1.0_qp - big_r)*cg*cg*sqrt((1.0_qp + radius)/(radius + big_r))/radius
        case (tee_arclength)
            y = radius*sqrt((1.0_qp - big_r)*(1.0_qp + big_r))*sqrt(1.0_qp - big_r)*cg &
                /sqrt(radius + big_r)
        case default
            y = radius*sqrt((1.0_qp - big_r)*(1.0_qp + big_r)) &
                /sqrt((1.0_qp + radius)*(radius + big_r))
        end select
    end function tee_evaluate

    pure function rolling_speed_evaluate(self, x) result(y)
        class(rolling_speed), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp) :: y
        real(qp) :: a, b
        a = 0.5_qp*self%depth
        b = 1.0_qp - a
        y = hypot(a*b*(sin(a*x) + sin(b*x)), a*b*(cos(a*x) - cos(b*x)))
    end function rolling_speed_evaluate

    !> Tee's integral from radius r to 1 (first half-arch) for apse R, numerically.
    function tee_value(which, r, big_r, rule) result(value)
        integer, intent(in) :: which
        real(qp), intent(in) :: r, big_r
        type(gauss_legendre_rule), intent(in) :: rule
        real(qp) :: value
        type(tee_integrand) :: integrand
        real(qp) :: upper, error
        integer :: status
        integrand%which = which
        integrand%apse = big_r
        upper = 2.0_qp*atan2(sqrt(1.0_qp - r), sqrt(r - big_r))
        ! 1024 eps: the panel test bounds the coarser rule's error and the finer sum
        ! returned is far better. integrate_adaptive shares the tolerance by panel width,
        ! so where the integrand peaks (Theta near the apse for small R, about 40 times its
        ! mean at R = 1e-3) a panel's share is about 1024/40 eps of its value; much less
        ! and it bisects on rounding noise
        call integrate_adaptive(integrand, 0.0_qp, upper, rule, 1024.0_qp*eps_qp, 0.0_qp, &
                                value, error, status)
        if (status /= status_ok) value = -huge(1.0_qp)
    end function tee_value

    subroutine run_harmonic_tests()
        call closed_form_tests()
        call tee_integral_tests()
        call reference_tests()
        call two_point_tests()
        call tautochrone_tests()
        call physical_unit_tests()
    end subroutine run_harmonic_tests

    subroutine closed_form_tests()
        real(qp), parameter :: rhos(6) = [0.0_qp, 1.0e-6_qp, 0.2_qp, 0.5_qp, 0.8_qp, &
                                          0.999_qp]
        type(rolling_speed) :: speed
        type(hypocycloid_point) :: point
        real(qp) :: rho, phi, x, y, a, previous, theta, worst_xy, worst_r, worst_sym
        real(qp) :: value, error, step, d, slope, change, alpha, x_mirror, y_mirror
        integer :: i, k, status
        logical :: increasing
        call section('harmonic: hypocycloid closed forms (Saitoh 7-10)')
        worst_xy = 0.0_qp
        worst_r = 0.0_qp
        worst_sym = 0.0_qp
        do i = 1, size(rhos)
            rho = rhos(i)
            call check(hypocycloid_radius(0.0_qp, rho) == 1.0_qp .and. &
                       hypocycloid_angle(0.0_qp, rho) == 0.0_qp .and. &
                       hypocycloid_time(0.0_qp, rho) == 0.0_qp .and. &
                       hypocycloid_arclength(0.0_qp, rho) == 0.0_qp, 'phi = 0 is A')
            call check_close(hypocycloid_radius(pi, rho), rho, 4.0_qp, &
                             'phi = pi: r = rho_m (deepest point)', floor=1.0_qp)
            call check_close(hypocycloid_radius(2.0_qp*pi, rho), 1.0_qp, 4.0_qp, &
                             'phi = 2 pi: r = 1 (surface)')
            call check_close(hypocycloid_angle(2.0_qp*pi, rho), tunnel_surface_angle(rho), &
                             8.0_qp, 'theta(2 pi) = pi (1 - rho_m)')
            call check_close(hypocycloid_time(2.0_qp*pi, rho), tunnel_time(rho), 4.0_qp, &
                             't(2 pi) = T = pi sqrt(1 - rho_m^2) (10)')
            call check_close(hypocycloid_arclength(2.0_qp*pi, rho), tunnel_arclength(rho), &
                             4.0_qp, 's(2 pi) = 2 (1 - rho_m^2)')
            if (rho > 0.0_qp) then
                ! at the deepest point: from the radius (well conditioned), and from the phase,
                ! where the rounding of phi moves the point by eps*R, so theta by eps/rho_m
                call check_close(hypocycloid_angle_at_radius(rho, rho, .false.), &
                                 0.5_qp*pi*(1.0_qp - rho), 8.0_qp, &
                                 'theta at radius rho_m = (pi/2)(1 - rho_m)')
                call check_close(hypocycloid_angle(pi, rho), 0.5_qp*pi*(1.0_qp - rho), &
                                 8.0_qp/rho, 'theta(pi) = (pi/2)(1 - rho_m): continuous '// &
                                 'through tan(phi/2) = inf (8 eps/rho_m)')
            end if
            ! theta increasing over [0, 2 pi], through phi = pi and the series limit phi = 2
            increasing = .true.
            previous = -1.0_qp
            do k = 0, 2000
                phi = 2.0_qp*pi*real(k, qp)/2000.0_qp
                theta = hypocycloid_angle(phi, rho)
                if (rho > 0.0_qp .or. abs(phi - pi) > 0.01_qp) then
                    increasing = increasing .and. theta >= previous
                end if
                previous = theta
            end do
            call check(increasing, 'theta nondecreasing on 2001 phases in [0, 2 pi]')
            if (rho > 0.0_qp) then
                ! through phi = pi: theta(pi + e) - theta(pi - e) = e (1 - rho_m^2)/rho_m
                step = 1.0e-20_qp
                slope = (1.0_qp - rho)*(1.0_qp + rho)/(2.0_qp*rho)
                change = hypocycloid_angle(pi + step, rho) - hypocycloid_angle(pi - step, rho)
                call check(abs(change - 2.0_qp*step*slope) <= 1.0e-10_qp*change, &
                           'theta continuous through phi = pi: jump over +-1e-20 = '// &
                           '2e-20 dtheta/dphi')
                ! across the switch from the series (phi <= 2) to the direct forms:
                ! dtheta/dphi = rho_m (1 - rho_m^2) sin^2(h)/(2 r^2), h = phi/2
                step = 16.0_qp*eps_qp
                slope = rho*(1.0_qp - rho)*(1.0_qp + rho)*sin(1.0_qp)**2 &
                        /(2.0_qp*hypocycloid_radius(2.0_qp, rho)**2)
                change = hypocycloid_angle(2.0_qp + step, rho) &
                         - hypocycloid_angle(2.0_qp - step, rho)
                call check(abs(change - 2.0_qp*step*slope) <= &
                           8.0_qp*eps_qp*hypocycloid_angle(2.0_qp, rho), &
                           'theta continuous at the series limit phi = 2 (8 eps)')
            end if
            do k = 0, 64
                phi = 2.0_qp*pi*real(k, qp)/64.0_qp
                call hypocycloid_position(phi, rho, x, y)
                ! independent: the rolling circle, Saitoh (11)-(12), a = (1 - rho_m)/2
                a = 0.5_qp*(1.0_qp - rho)
                worst_xy = max(worst_xy, &
                               abs(x - ((1.0_qp - a)*cos(a*phi) + a*cos((1.0_qp - a)*phi))), &
                               abs(y - ((1.0_qp - a)*sin(a*phi) - a*sin((1.0_qp - a)*phi))))
                worst_r = max(worst_r, abs(hypot(x, y) - hypocycloid_radius(phi, rho)))
                ! symmetry: P(2 pi - phi) is P(phi) mirrored in the line OM to the deepest
                ! point, at angle alpha = (pi/2)(1 - rho_m)
                alpha = 0.5_qp*pi*(1.0_qp - rho)
                call hypocycloid_position(2.0_qp*pi - phi, rho, x_mirror, y_mirror)
                worst_sym = max(worst_sym, &
                    hypot(x_mirror - (x*cos(2.0_qp*alpha) + y*sin(2.0_qp*alpha)), &
                          y_mirror - (x*sin(2.0_qp*alpha) - y*cos(2.0_qp*alpha))))
            end do
            ! arclength: s(phi) against the integral of |dP/dphi| of the rolling circle
            speed%depth = 1.0_qp - rho
            do k = 1, 4
                phi = 0.5_qp*pi*real(k, qp)
                call integrate_adaptive(speed, 0.0_qp, phi, gauss_legendre(20), &
                                        64.0_qp*eps_qp, 0.0_qp, value, error, status)
                call check_close(hypocycloid_arclength(phi, rho), value, 16.0_qp, &
                                 's(phi) = integral of |dP/dphi| (rolling circle)')
            end do
        end do
        write (output_unit, '(a,3es10.2)') '   worst |(x,y) - rolling circle|, '// &
            '|hypot(x,y) - r|, symmetry: ', worst_xy, worst_r, worst_sym
        call check(worst_xy <= 16.0_qp*eps_qp, '(x, y) = rolling circle (11)-(12) to 16 eps')
        call check(worst_r <= 8.0_qp*eps_qp, 'hypot(x, y) = r(phi) (7) to 8 eps')
        call check(worst_sym <= 16.0_qp*eps_qp, 'mirror symmetric about the deepest point')

        ! shallow tunnels: depth given exactly
        d = 1.0e-20_qp
        call check_close(tunnel_surface_angle(1.0_qp - d, depth=d), pi*d, 2.0_qp, &
                         'depth given: surface angle pi*depth at depth 1e-20')
        call check_close(tunnel_time(1.0_qp - d, depth=d), pi*sqrt(d*(2.0_qp - d)), 4.0_qp, &
                         'depth given: T = pi sqrt(d (2 - d)) at depth 1e-20')
        call check_close(hypocycloid_angle(2.0_qp*pi, 1.0_qp - d, depth=d), pi*d, 16.0_qp, &
                         'depth given: theta(2 pi) = pi*depth at depth 1e-20')

        ! checked evaluation
        point = hypocycloid_at(1.0_qp, 0.3_qp)
        call check(point%status == status_ok .and. point%angle == hypocycloid_angle(1.0_qp, &
                   0.3_qp) .and. point%radius == hypocycloid_radius(1.0_qp, 0.3_qp), &
                   'hypocycloid_at agrees with the elemental forms')
        point = hypocycloid_at(7.0_qp, 0.3_qp)
        call check(point%status == status_invalid_argument .and. point%radius == 0.0_qp, &
                   'hypocycloid_at refuses phi > 2 pi')
        point = hypocycloid_at(1.0_qp, 1.5_qp)
        call check(point%status == status_invalid_argument, 'hypocycloid_at refuses rho_m > 1')
        point = hypocycloid_at(1.0_qp, 0.3_qp, depth=0.6_qp)
        call check(point%status == status_invalid_argument, &
                   'hypocycloid_at refuses depth /= 1 - rho_m')
        point = hypocycloid_at(ieee_value(1.0_qp, ieee_quiet_nan), 0.3_qp)
        call check(point%status == status_not_finite, 'hypocycloid_at refuses NaN')
    end subroutine closed_form_tests

    !> Closed forms against Tee's integrals evaluated numerically here (first half-arch
    !! directly, second half-arch as 2 F(R,R) - F(r,R), Tee's eq. 29 and sec. 2.4-2.5).
    subroutine tee_integral_tests()
        real(qp), parameter :: apses(9) = [1.0e-3_qp, 0.01_qp, 0.1_qp, 0.3_qp, 0.5_qp, &
                                           0.7_qp, 0.9_qp, 0.99_qp, 0.999_qp]
        real(qp), parameter :: fractions(8) = [0.0_qp, 1.0e-9_qp, 0.01_qp, 0.25_qp, 0.5_qp, &
                                               0.75_qp, 0.99_qp, 1.0_qp - 1.0e-9_qp]
        type(gauss_legendre_rule) :: rule
        real(qp) :: big_r, r, phi, numeric(3), apse_values(3), closed(3), least(3)
        real(qp) :: digits
        integer :: i, j, k, points
        character(len=*), parameter :: names(3) = [character(len=9) :: 'theta', 's', 't']
        call section('harmonic: closed forms against Tee''s integrals (27), (33), (39)')
        rule = gauss_legendre(20)
        least = 99.0_qp
        points = 0
        do i = 1, size(apses)
            big_r = apses(i)
            do k = 1, 3
                apse_values(k) = tee_value(k, big_r, big_r, rule)
            end do
            do j = 1, size(fractions)
                r = big_r + (1.0_qp - big_r)*fractions(j)
                do k = 1, 3
                    numeric(k) = tee_value(k, r, big_r, rule)
                end do
                ! first half-arch. theta from (8) at the radius r (h from (7)), not through
                ! phi: near the deepest point of a deep tunnel a rounding of phi moves
                ! theta by eps/R (R = 1e-3: 31.2 digits); s and t are well conditioned in phi
                phi = hypocycloid_phase(r, big_r, .false.)
                closed = [hypocycloid_angle_at_radius(r, big_r, .false.), &
                          hypocycloid_arclength(phi, big_r), hypocycloid_time(phi, big_r)]
                do k = 1, 3
                    digits = digits_of_agreement(closed(k), numeric(k))
                    least(k) = min(least(k), digits)
                    call check_digits(closed(k), numeric(k), 32.0_qp, &
                                      'first arch: closed '//trim(names(k))//' = Tee integral')
                end do
                ! second half-arch
                phi = hypocycloid_phase(r, big_r, .true.)
                closed = [hypocycloid_angle_at_radius(r, big_r, .true.), &
                          hypocycloid_arclength(phi, big_r), hypocycloid_time(phi, big_r)]
                do k = 1, 3
                    digits = digits_of_agreement(closed(k), 2.0_qp*apse_values(k) - numeric(k))
                    least(k) = min(least(k), digits)
                    call check_digits(closed(k), 2.0_qp*apse_values(k) - numeric(k), 32.0_qp, &
                                      'second arch: closed '//trim(names(k))// &
                                      ' = 2 F(R,R) - F(r,R)')
                end do
                points = points + 2
            end do
        end do
        write (output_unit, '(a,i0,a,3f7.2)') '   ', points, &
            ' points (r, R), R = 1e-3 .. 0.999; fewest digits theta, s, t:', least
    end subroutine tee_integral_tests

    !> Against data/reference/harmonic_mpmath.csv (45 digits; see the script's header).
    subroutine reference_tests()
        type(csv_table) :: table
        type(harmonic_tunnel) :: tunnel
        type(planet_tunnel) :: route
        logical :: ok
        integer :: i, status, rows
        real(qp) :: a, b, expected, actual, least, x, y, phi
        character(len=:), allocatable :: kind
        call section('harmonic: against the 45-digit mpmath reference')
        call read_reference('data/reference/harmonic_mpmath.csv', 80, table, ok)
        if (.not. ok) return
        least = 99.0_qp
        rows = 0
        do i = 1, table%row_count()
            kind = table%text(i, 'kind')
            a = table%real_value(i, 'a')
            b = table%real_value(i, 'b')
            expected = table%real_value(i, 'value')
            select case (kind)
            case ('theta', 's', 't')
                phi = hypocycloid_phase(a, b, .false.)
                select case (kind)
                case ('theta'); actual = hypocycloid_angle(phi, b)
                case ('s');     actual = hypocycloid_arclength(phi, b)
                case default;   actual = hypocycloid_time(phi, b)
                end select
            case ('x', 'y')
                call hypocycloid_position(a, b, x, y)
                actual = merge(x, y, kind == 'x')
            case ('endpoint_rho', 'endpoint_time', 'endpoint_s')
                tunnel = solve_harmonic_endpoint(a, b)
                call check(tunnel%status == status_ok, 'reference endpoint solved')
                select case (kind)
                case ('endpoint_rho');  actual = tunnel%min_radius
                case ('endpoint_time'); actual = tunnel%time
                case default;           actual = tunnel%arclength
                end select
            case ('route_angle', 'route_depth_km', 'route_length_km', 'route_time_s')
                route = plan_tunnel(a, b, table%real_value(i, 'c'), table%real_value(i, 'd'))
                call check(route%status == status_ok, 'reference route planned')
                select case (kind)
                case ('route_angle');     actual = route%central_angle
                case ('route_depth_km');  actual = route%depth_km
                case ('route_length_km'); actual = route%length_km
                case default;             actual = route%time_seconds
                end select
            case ('tautochrone')
                call tautochrone_time(a, b, actual, status)
                call check(status == status_ok, 'reference tautochrone integrated')
            case default
                call check(.false., 'known kind in harmonic reference: '//kind)
                cycle
            end select
            rows = rows + 1
            least = min(least, digits_of_agreement(actual, expected))
            call check_digits(actual, expected, 32.0_qp, 'mpmath reference: '//kind//' '// &
                              table%text(i, 'a')//' '//table%text(i, 'b'))
        end do
        write (output_unit, '(a,i0,a,f7.2)') '   ', rows, ' reference values; fewest digits', &
            least
    end subroutine reference_tests

    subroutine two_point_tests()
        real(qp), parameter :: radii(10) = [1.0e-6_qp, 0.01_qp, 0.1_qp, 0.3_qp, 0.5_qp, &
                                            0.7_qp, 0.9_qp, 0.99_qp, 0.999999_qp, 1.0_qp]
        real(qp), parameter :: angles(11) = [1.0e-15_qp, 1.0e-6_qp, 0.001_qp, 0.1_qp, &
                                             0.5_qp, 1.0_qp, 1.5_qp, 2.0_qp, 2.5_qp, 3.0_qp, &
                                             3.14159_qp]
        type(harmonic_tunnel) :: tunnel
        type(gauss_legendre_rule) :: rule
        real(qp) :: r, theta, apse, worst_position, worst_theta, worst_at_radius, nan
        real(qp) :: expected, mirror, x, y, candidates(size(angles) + 2)
        integer :: i, j, k, failures, most_steps, wrong_arch, checked
        logical :: near_apse
        call section('harmonic: two-point problem')
        ! (a) surface to surface
        do k = 1, 8
            theta = pi*real(k, qp)/8.0_qp
            tunnel = surface_to_surface(theta)
            call check(tunnel%status == status_ok .and. tunnel%arch == arch_complete, &
                       'surface to surface solved')
            call check_close(tunnel%min_radius, 1.0_qp - theta/pi, 2.0_qp, &
                             'surface: rho_m = 1 - Theta/pi', floor=1.0_qp)
            call check_close(hypocycloid_angle(2.0_qp*pi, tunnel%min_radius, tunnel%depth), &
                             theta, 8.0_qp, 'surface: the tunnel ends at angle Theta')
            expected = pi*sqrt(1.0_qp - (1.0_qp - theta/pi)**2)
            call check_close(tunnel%time, expected, 8.0_qp, &
                             'surface: time pi sqrt(1 - rho_m^2)')
            call check_close(tunnel%arclength, 2.0_qp*(1.0_qp - (1.0_qp - theta/pi)**2), &
                             8.0_qp, 'surface: length 2 (1 - rho_m^2)')
        end do
        tunnel = surface_to_surface(0.0_qp)
        call check(tunnel%status == status_ok .and. tunnel%time == 0.0_qp .and. &
                   tunnel%min_radius == 1.0_qp, 'surface: Theta = 0 is the empty tunnel')
        tunnel = surface_to_surface(4.0_qp)
        call check(tunnel%status == status_psi_out_of_range, 'surface: Theta > pi refused')

        ! (b) interior endpoints: the solution must pass through B. The position at the
        ! returned phase is compared absolutely (units of R): near the centre a rounding of
        ! phi moves theta by eps/r, so theta(phi) is compared relatively only for
        ! 0.1 <= r_B <= 0.99 away from the deepest point. The angle at radius r_B (no phase)
        ! is compared relatively where r_B - rho_m > r_B/100: near the deepest point theta
        ! depends on sqrt(r_B - rho_m), and the rounding of rho_m alone moves it by more.
        worst_position = 0.0_qp
        worst_theta = 0.0_qp
        worst_at_radius = 0.0_qp
        failures = 0
        wrong_arch = 0
        most_steps = 0
        checked = 0
        do i = 1, size(radii)
            r = radii(i)
            apse = 0.5_qp*pi*(1.0_qp - r)
            ! the grid, and just before and after the deepest point
            candidates = [angles, apse*(1.0_qp - 1.0e-12_qp), apse*(1.0_qp + 1.0e-12_qp)]
            do j = 1, size(candidates)
                theta = candidates(j)
                tunnel = solve_harmonic_endpoint(r, theta)
                if (tunnel%status /= status_ok .or. tunnel%min_radius < 0.0_qp .or. &
                    tunnel%min_radius > r) then
                    failures = failures + 1
                    write (output_unit, '(a,2es12.4,a,i0)') '   unsolved ', r, theta, &
                        ' status ', tunnel%status
                    cycle
                end if
                most_steps = max(most_steps, tunnel%steps)
                if (r < 1.0_qp .and. ((theta <= apse) .neqv. (tunnel%arch == arch_first))) &
                    wrong_arch = wrong_arch + 1
                call hypocycloid_position(tunnel%phase, tunnel%min_radius, x, y, &
                                          tunnel%depth)
                worst_position = max(worst_position, hypot(x - r*cos(theta), &
                                                           y - r*sin(theta)))
                near_apse = abs(theta - apse) < 1.0e-6_qp*apse
                if (r >= 0.1_qp .and. r <= 0.99_qp .and. .not. near_apse) then
                    worst_theta = max(worst_theta, abs(hypocycloid_angle(tunnel%phase, &
                        tunnel%min_radius, tunnel%depth) - theta)/theta)
                end if
                ! theta(r_B; rho_m) ~ c sqrt(r_B - rho_m) as rho_m -> r_B: the rounding of
                ! rho_m alone moves it by about eps r_B/(r_B - rho_m) relative
                if (r - tunnel%min_radius > 0.01_qp*r) then
                    checked = checked + 1
                    worst_at_radius = max(worst_at_radius, abs(hypocycloid_angle_at_radius(r, &
                        tunnel%min_radius, tunnel%arch /= arch_first, tunnel%depth) &
                        - theta)/theta)
                end if
            end do
        end do
        write (output_unit, '(a,i0,a,3f6.1,a,i0)') '   ', size(radii)*(size(angles) + 2), &
            ' endpoints; worst |P(phi) - B|, rel. theta(phi), rel. theta(r_B) in eps:', &
            worst_position/eps_qp, worst_theta/eps_qp, worst_at_radius/eps_qp, &
            '; most Newton steps ', most_steps
        call check(failures == 0, 'every endpoint 0 < r_B <= 1, 0 < theta_B < pi solved')
        call check(most_steps <= 2 .or. digits(1.0_xp) < 64, &
                   'after the early phase in x87 extended, at most 2 binary128 evaluations')
        call check(wrong_arch == 0, 'before/after the deepest point as theta_B vs apse angle')
        call check(worst_position <= 4.0_qp*eps_qp, 'solutions pass through B (4 eps * R)')
        call check(worst_theta <= 16.0_qp*eps_qp, 'theta(phi_B) = theta_B (16 eps)')
        call check(worst_at_radius <= 16.0_qp*eps_qp .and. checked > 80, &
                   'theta at radius r_B = theta_B where r_B - rho_m > r_B/100 (16 eps)')

        ! time and arclength at B against Tee's integrals (independent of the solver)
        rule = gauss_legendre(20)
        do k = 1, 4
            r = 0.2_qp*real(k, qp)
            theta = 0.7_qp*real(k, qp)
            tunnel = solve_harmonic_endpoint(r, theta)
            if (tunnel%arch == arch_first) then
                expected = tee_value(tee_time, r, tunnel%min_radius, rule)
                mirror = tee_value(tee_arclength, r, tunnel%min_radius, rule)
            else
                expected = 2.0_qp*tee_value(tee_time, tunnel%min_radius, tunnel%min_radius, &
                                            rule) - tee_value(tee_time, r, tunnel%min_radius, rule)
                mirror = 2.0_qp*tee_value(tee_arclength, tunnel%min_radius, &
                                          tunnel%min_radius, rule) &
                         - tee_value(tee_arclength, r, tunnel%min_radius, rule)
            end if
            call check_digits(tunnel%time, expected, 32.0_qp, 'endpoint time = Tee (39)')
            call check_digits(tunnel%arclength, mirror, 32.0_qp, 'endpoint s = Tee (33)')
        end do

        ! B at its deepest point to within the rounding of theta_B (0.1 pi against the
        ! apse angle (pi/2)(1 - 0.8)): rho_m = r_B, s = 1 - r_B^2, t = (pi/2) sqrt(1 - r_B^2)
        ! to first order in the gap; the Newton iteration meets a double root there
        tunnel = solve_harmonic_endpoint(0.8_qp, 0.1_qp*pi)
        call check(tunnel%status == status_ok .and. tunnel%steps <= 3, &
                   'B at its deepest point within a rounding: solved in <= 3 steps')
        call check_close(tunnel%min_radius, 0.8_qp, 4.0_qp, 'deepest point: rho_m = r_B')
        call check_close(tunnel%arclength, 0.36_qp, 8.0_qp, 'deepest point: s = 1 - r_B^2')
        call check_close(tunnel%time, 0.3_qp*pi, 8.0_qp, &
                         'deepest point: t = (pi/2) sqrt(1 - r_B^2)')

        ! shallow B (r_B next to 1, theta_B near the apse angle's scale): d theta/d beta
        ! is Y - h X, which cancelled there (up to 37 binary128 steps, derivative zeroed in
        ! hardware precision); the angle at r_B on the tunnel found, from its depth, must
        ! be theta_B
        call shallow(1.0_qp - 4.2e-16_qp, 5.5e-16_qp)
        call shallow(1.0_qp - 1.7e-18_qp, 1.4e-19_qp)
        call shallow(1.0_qp - 1.0e-29_qp, 3.6e-30_qp)
        call shallow(1.0_qp - 5.5e-11_qp, 8.6e-11_qp)

        ! special endpoints
        tunnel = solve_harmonic_endpoint(0.4_qp, 0.0_qp)
        call check(tunnel%status == status_ok .and. tunnel%arch == arch_radial .and. &
                   tunnel%min_radius == 0.0_qp, 'theta_B = 0: radial fall, rho_m = 0')
        call check_close(tunnel%time, acos(0.4_qp), 4.0_qp, 'radial fall: t = acos(r_B)')
        call check_close(tunnel%arclength, 0.6_qp, 4.0_qp, 'radial fall: s = 1 - r_B')
        tunnel = solve_harmonic_endpoint(0.4_qp, pi)
        call check(tunnel%status == status_ok .and. tunnel%arch == arch_second .and. &
                   tunnel%min_radius == 0.0_qp, 'theta_B = pi: diametral tunnel, rho_m = 0')
        call check_close(tunnel%time, 0.5_qp*pi + asin(0.4_qp), 4.0_qp, &
                         'diametral: t = pi/2 + asin(r_B)')
        call check_close(tunnel%arclength, 1.4_qp, 4.0_qp, 'diametral: s = 1 + r_B')
        tunnel = solve_harmonic_endpoint(0.4_qp, 0.3_qp*pi)
        call check(tunnel%status == status_ok .and. tunnel%min_radius == 0.4_qp, &
                   'theta_B = apse angle: B is the deepest point, rho_m = r_B')
        call check_close(tunnel%time, 0.5_qp*pi*sqrt(1.0_qp - 0.4_qp**2), 4.0_qp, &
                         'deepest point: t = (pi/2) sqrt(1 - r_B^2)')
        tunnel = solve_harmonic_endpoint(1.0e-30_qp, 1.0_qp)
        call check(tunnel%status == status_ok .and. tunnel%min_radius <= 1.0e-30_qp .and. &
                   abs(tunnel%time - 0.5_qp*pi) < 2.0e-30_qp, &
                   'r_B -> 0: the diametral tunnel, time to the centre pi/2')
        ! next to the centre the tunnel is the straight line y = rho_m (parallel to OA), so
        ! sin(theta_B) = rho_m/r_B: r_B^2 underflows here (the derivative must not use it)
        do k = 1, 3
            theta = merge(0.5_qp, merge(1.2_qp, 1.0e-300_qp, k == 2), k == 1)
            tunnel = solve_harmonic_endpoint(1.0e-4000_qp, theta)
            expected = 1.0e-4000_qp*sin(theta)
            call check(tunnel%status == status_ok .and. tunnel%arch == arch_first .and. &
                       abs(tunnel%min_radius - expected) <= 8.0_qp*eps_qp*expected, &
                       'r_B = 1e-4000: rho_m = r_B sin(theta_B), the straight line near O')
        end do
        ! rho_m = r_B theta_B/(d theta/d beta) below half the smallest subnormal: 0
        tunnel = solve_harmonic_endpoint(1.0e-300_qp, 1.0e-4900_qp)
        call check(tunnel%status == status_ok .and. tunnel%arch == arch_first .and. &
                   tunnel%min_radius == 0.0_qp .and. abs(tunnel%time - 0.5_qp*pi) < 4.0_qp* &
                   eps_qp, 'rho_m below the smallest binary128 number: 0, the straight tunnel')
        tunnel = solve_harmonic_endpoint(1.0e-4000_qp, 1.0e-4900_qp)
        call check(tunnel%status == status_ok .and. tunnel%min_radius == 0.0_qp, &
                   'r_B = 1e-4000, theta_B = 1e-4900: rho_m underflows to 0')
        tunnel = solve_harmonic_endpoint(1.0_qp, 2.0_qp)
        call check(tunnel%status == status_ok .and. tunnel%arch == arch_complete .and. &
                   abs(tunnel%min_radius - (1.0_qp - 2.0_qp/pi)) <= 2.0_qp*eps_qp, &
                   'r_B = 1 is surface to surface')
        tunnel = solve_harmonic_endpoint(0.0_qp, 1.0_qp)
        call check(tunnel%status == status_rho_out_of_range, 'r_B = 0 refused')
        tunnel = solve_harmonic_endpoint(1.5_qp, 1.0_qp)
        call check(tunnel%status == status_rho_out_of_range, 'r_B > 1 refused')
        tunnel = solve_harmonic_endpoint(0.5_qp, -0.1_qp)
        call check(tunnel%status == status_psi_out_of_range, 'theta_B < 0 refused')
        tunnel = solve_harmonic_endpoint(0.5_qp, 3.5_qp)
        call check(tunnel%status == status_psi_out_of_range, &
                   'theta_B > pi refused (mirror: 2 pi - theta_B)')
        nan = ieee_value(1.0_qp, ieee_quiet_nan)
        tunnel = solve_harmonic_endpoint(0.5_qp, nan)
        call check(tunnel%status == status_not_finite .and. ieee_is_finite(tunnel%time) .and. &
                   ieee_is_finite(tunnel%min_radius), 'NaN refused, outputs defined')
    contains
        subroutine shallow(r_b, theta_b)
            real(qp), intent(in) :: r_b, theta_b
            type(harmonic_tunnel) :: t
            character(len=40) :: label
            write (label, '(a,es9.2,a,es9.2)') '1 - r_B =', real(1.0_qp - r_b), &
                ', theta_B =', real(theta_b)
            t = solve_harmonic_endpoint(r_b, theta_b)
            call check(t%status == status_ok .and. t%steps <= 4, &
                       'shallow B solved in <= 4 steps: '//trim(label))
            call check_close(hypocycloid_angle_at_radius(r_b, t%min_radius, &
                             t%arch == arch_second, t%depth), theta_b, 16.0_qp, &
                             'shallow B: theta(r_B) = theta_B: '//trim(label))
        end subroutine shallow
    end subroutine two_point_tests

    subroutine tautochrone_tests()
        real(qp), parameter :: rhos(6) = [0.0_qp, 1.0e-3_qp, 0.3_qp, 0.7_qp, 0.99_qp, &
                                          0.999999_qp]
        real(qp), parameter :: fractions(7) = [1.0e-20_qp, 1.0e-6_qp, 0.01_qp, 0.3_qp, &
                                               0.7_qp, 0.999_qp, 1.0_qp]
        real(qp) :: rho, r0, time, expected, least, low, high
        integer :: i, j, status
        call section('harmonic: the hypocycloid is a tautochrone')
        least = 99.0_qp
        do i = 1, size(rhos)
            rho = rhos(i)
            ! (pi/2) sqrt(1 - rho_m^2): half of T (10)
            expected = 0.5_qp*pi*sqrt((1.0_qp - rho)*(1.0_qp + rho))
            low = huge(1.0_qp)
            high = -huge(1.0_qp)
            do j = 1, size(fractions)
                r0 = rho + (1.0_qp - rho)*fractions(j)
                call tautochrone_time(r0, rho, time, status)
                call check(status == status_ok, 'tautochrone integral converged')
                call check_digits(time, expected, 32.0_qp, &
                                  'time from rest at r0 to the deepest point = (pi/2) '// &
                                  'sqrt(1 - rho_m^2)')
                least = min(least, digits_of_agreement(time, expected))
                low = min(low, time)
                high = max(high, time)
            end do
            call check((high - low)/expected <= 1.0e-32_qp, &
                       'tautochrone: the same time from every r0 (spread <= 1e-32)')
        end do
        write (output_unit, '(a,f7.2)') '   42 release points, r0 - rho_m from 1e-20 (1 - '// &
            'rho_m) to 1 - rho_m; fewest digits', least
        call tautochrone_time(0.3_qp, 0.3_qp, time, status)
        call check(status == status_ok .and. time == 0.0_qp, &
                   'tautochrone: released at the deepest point, time 0')
        call tautochrone_time(0.2_qp, 0.3_qp, time, status)
        call check(status == status_invalid_argument .and. time == 0.0_qp, &
                   'tautochrone: r0 < rho_m refused')
        call tautochrone_time(0.5_qp, 1.0_qp, time, status)
        call check(status == status_invalid_argument, 'tautochrone: rho_m = 1 refused')
    end subroutine tautochrone_tests

    subroutine physical_unit_tests()
        ! New York (40.7128 N, 74.0060 W) to Los Angeles (34.0522 N, 118.2437 W)
        real(qp), parameter :: ny_lat = 40.7128_qp, ny_lon = -74.0060_qp
        real(qp), parameter :: la_lat = 34.0522_qp, la_lon = -118.2437_qp
        real(qp), parameter :: degree = pi/180.0_qp
        type(planet_tunnel) :: route
        type(harmonic_planet) :: mars
        real(qp) :: p(3), q(3), chord, angle, antipodal
        call section('harmonic: physical units (R = 6371 km, g = 9.81 m/s^2)')
        route = plan_tunnel(ny_lat, ny_lon, la_lat, la_lon)
        write (output_unit, '(a,f9.3,a,f9.3,a,f9.3,a,f8.3,a,f7.3,a)') &
            '   New York - Los Angeles: great circle ', route%surface_distance_km, &
            ' km, deepest ', route%depth_km, ' km, tunnel ', route%length_km, ' km, ', &
            route%time_seconds, ' s = ', route%time_minutes, ' min'
        call check(route%status == status_ok, 'NY-LA planned')
        ! independent central angle: the chord between the unit vectors, 2 asin(chord/2)
        p = [cos(ny_lat*degree)*cos(ny_lon*degree), cos(ny_lat*degree)*sin(ny_lon*degree), &
             sin(ny_lat*degree)]
        q = [cos(la_lat*degree)*cos(la_lon*degree), cos(la_lat*degree)*sin(la_lon*degree), &
             sin(la_lat*degree)]
        chord = norm2(p - q)
        angle = 2.0_qp*asin(0.5_qp*chord)
        call check_digits(route%central_angle, angle, 32.0_qp, &
                          'NY-LA: central angle = 2 asin(|P - Q|/2)')
        call check_digits(route%chord_length_km, earth_radius_km*chord, 32.0_qp, &
                          'NY-LA: chord = R |P - Q|')
        call check_digits(route%depth_km, earth_radius_km*angle/pi, 32.0_qp, &
                          'NY-LA: depth R Theta/pi')
        call check_digits(route%time_seconds, &
                          pi*sqrt(6371000.0_qp/9.81_qp)*sqrt(1.0_qp - (1.0_qp - angle/pi)**2), &
                          32.0_qp, 'NY-LA: time pi sqrt(R/g) sqrt(1 - rho_m^2)')
        call check(abs(route%depth_km - 1252.79_qp) < 0.01_qp .and. &
                   abs(route%time_minutes - 25.127_qp) < 0.001_qp, &
                   'NY-LA: about 1252.8 km deep, 25.13 min')
        call check(route%chord_length_km < route%surface_distance_km .and. &
                   route%surface_distance_km < route%length_km, &
                   'NY-LA: chord < great circle < hypocycloid')
        call check_close(route%chord_time_seconds, pi*time_scale(harmonic_planet()), 2.0_qp, &
                         'every straight chord takes pi/omega')
        ! antipodes: the straight diametral tunnel, pi sqrt(R/g)
        route = plan_tunnel(0.0_qp, 0.0_qp, 0.0_qp, 180.0_qp)
        antipodal = pi*sqrt(6371000.0_qp/9.81_qp)
        write (output_unit, '(a,f10.4,a,f8.4,a)') '   antipodal tunnel: ', &
            route%time_seconds, ' s = ', route%time_minutes, ' min'
        call check_close(route%time_seconds, antipodal, 8.0_qp, &
                         'antipodal: time pi sqrt(R/g)')
        call check_close(route%depth_km, earth_radius_km, 8.0_qp, 'antipodal: through the centre')
        call check_close(route%length_km, 2.0_qp*earth_radius_km, 8.0_qp, &
                         'antipodal: length 2R')
        call check(abs(route%time_minutes - 42.196_qp) < 0.001_qp, &
                   'antipodal: 42.2 min (Saitoh''s "roughly 41 min" is 1.2 min short)')
        call check_close(route%time_seconds, route%chord_time_seconds, 8.0_qp, &
                         'antipodal: the hypocycloid is the diameter (chord time)')
        call check_close(1.0_qp/angular_frequency(harmonic_planet()), &
                         time_scale(harmonic_planet()), 2.0_qp, 'time scale = 1/omega')
        ! longitudes across the date line, identical places, the poles
        call check_close(great_circle_angle(0.0_qp, 170.0_qp, 0.0_qp, -170.0_qp), &
                         20.0_qp*degree, 8.0_qp, 'great circle across the date line')
        call check(great_circle_angle(10.0_qp, 20.0_qp, 10.0_qp, 20.0_qp) == 0.0_qp, &
                   'great circle: same place, angle 0')
        call check_close(great_circle_angle(90.0_qp, 0.0_qp, -90.0_qp, 33.0_qp), pi, 4.0_qp, &
                         'great circle: pole to pole is pi')
        call check_close(great_circle_angle(45.0_qp, 0.0_qp, 45.0_qp, 1.0e-20_qp), &
                         1.0e-20_qp*degree*cos(45.0_qp*degree), 16.0_qp, &
                         'great circle keeps its digits for near points')
        route = plan_tunnel(10.0_qp, 20.0_qp, 10.0_qp, 20.0_qp)
        call check(route%status == status_ok .and. route%time_seconds == 0.0_qp, &
                   'same place: empty tunnel')
        ! another planet
        mars = harmonic_planet(radius_km=3389.5_qp, gravity=3.721_qp)
        route = plan_tunnel(0.0_qp, 0.0_qp, 0.0_qp, 180.0_qp, mars)
        call check_close(route%time_seconds, pi*sqrt(3389500.0_qp/3.721_qp), 8.0_qp, &
                         'planet overridden (Mars-sized): pi sqrt(R/g)')
        ! statuses
        route = plan_tunnel(91.0_qp, 0.0_qp, 0.0_qp, 0.0_qp)
        call check(route%status == status_latitude_out_of_range .and. &
                   route%time_seconds == 0.0_qp, 'latitude > 90 refused')
        route = plan_tunnel(0.0_qp, 0.0_qp, 0.0_qp, 1.0_qp, harmonic_planet(gravity=0.0_qp))
        call check(route%status == status_bad_planet, 'g = 0 refused')
        route = plan_tunnel(0.0_qp, ieee_value(1.0_qp, ieee_quiet_nan), 0.0_qp, 1.0_qp)
        call check(route%status == status_not_finite, 'NaN longitude refused')
        call check(earth_radius_km == 6371.0_qp .and. earth_gravity == 9.81_qp, &
                   'defaults R = 6371 km, g = 9.81 m/s^2')
    end subroutine physical_unit_tests

end module test_harmonic
