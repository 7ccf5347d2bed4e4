!> Curve sampling: the points lie on the brachistochrone (checked against its differential
!! equations by finite differences, and against the symmetry about the apse), at equal
!! steps of arclength, from A to exactly B.
!!
!! What is independent: the sampler finds each point by Newton's method on the library's
!! S(r,R), then evaluates Theta, S, T there by quadrature. The finite-difference checks
!! use only the sampled numbers and the closed forms of eqs. (18), (21), (15), (44), (53);
!! the symmetry check compares the two half-arches, which the library computes by different
!! quadratures (the first from A, the second from the apse plus a periodic rule).
module test_curves
    use, intrinsic :: iso_fortran_env, only: output_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    use brachistochrone_kinds, only: qp, pi, eps_qp
    use brachistochrone_status, only: status_ok, status_inaccessible, &
                                      status_invalid_argument, status_not_finite
    use brachistochrone_closed_forms, only: radial_time, inaccessible_angle, apse_angle_limit
    use brachistochrone_inverse_square, only: inverse_square_model, new_inverse_square_model
    use brachistochrone_two_point, only: solve_endpoint, solve_endpoint_secant
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_arches, only: arch_first, arch_second, arch_complete, arch_radial
    use brachistochrone_curve, only: curve_samples, sample_endpoint_curve, sample_complete_arch, &
                     apsidal_locus
    use testing, only: check, check_close, section
    implicit none
    private

    public :: run_curve_tests

contains

    subroutine run_curve_tests()
        type(inverse_square_model) :: model
        model = new_inverse_square_model()
        call complete_arch_tests(model)
        call differential_tests(model)
        call endpoint_tests(model)
        call locus_tests(model)
        call error_tests(model)
    end subroutine run_curve_tests

    !> Complete arches: ends, apse, monotonicity, spacing, symmetry about the apse.
    subroutine complete_arch_tests(model)
        type(inverse_square_model), intent(in) :: model
        real(qp), parameter :: radii(6) = [0.999_qp, 0.9_qp, 0.5_qp, 0.1_qp, 0.01_qp, &
                                           1.0e-4_qp]
        type(curve_samples) :: c
        real(qp) :: apse_theta, worst_symmetry(4), big_r, allowed(3)
        integer :: j, k, m, a, status, points
        character(len=16) :: label

        call section('curves: complete arches (401 points)')
        points = 401
        do j = 1, size(radii)
            big_r = radii(j)
            write (label, '(es9.2)') big_r
            c = sample_complete_arch(model, big_r, points)
            call check(c%status == status_ok .and. c%n == points, 'complete arch R ='// &
                       trim(label)//' sampled')
            if (c%n /= points) cycle
            a = c%apse_index
            m = points - 1
            call check(a == points/2 + 1, 'apse in the middle')
            call check(c%r(a) == big_r .and. c%r(1) == 1.0_qp .and. c%r(points) == 1.0_qp, &
                       'r = 1 at A and A'', r = R at the apse exactly')
            call check(c%theta(1) == 0.0_qp .and. c%s(1) == 0.0_qp .and. c%t(1) == 0.0_qp &
                       .and. c%x(1) == 1.0_qp .and. c%y(1) == 0.0_qp, 'A = (1, 0), s = t = 0')
            ! the apse angle by the periodic rule, a different quadrature
            call model%apse_angle(big_r, apse_theta, status)
            call check_close(c%theta(a), apse_theta, 8.0_qp, 'apse angle = Theta(R,R)')
            call check_close(c%theta(points), 2.0_qp*apse_theta, 8.0_qp, &
                             'A'' at angle 2 Theta(R,R)')
            call check(all(c%s(2:) > c%s(:m)) .and. all(c%t(2:) > c%t(:m)), &
                       's and t strictly increasing')
            call check(all(c%r(2:a) < c%r(1:a - 1)) .and. &
                       all(c%r(a + 1:) > c%r(a:m)), 'r falls to R, then rises')
            call check(all(c%theta(2:) > c%theta(:m)), 'theta strictly increasing')
            ! equal steps of s, up to what the rounding of r allows
            call check(spacing_ok(c, big_r), 'equal steps of s')
            ! symmetry about the apse (58): mirror points have the same r and mirrored
            ! theta, s, t, up to the rounding of r (times d/dr) and a few eps
            worst_symmetry = 0.0_qp
            do k = 1, a - 1
                ! the half-arches' s are computed by different means (tables plus one panel
                ! or one whole panel) and agree to a few eps of s; the inversion of s turns
                ! that into a shift along the curve of up to 8 eps s(apse)
                allowed = rounding_effect(c, big_r, a - k) + rounding_effect(c, big_r, a + k) &
                          + shift_effect(c, big_r, a - k, 8.0_qp*eps_qp*c%s(a)) &
                          + shift_effect(c, big_r, a + k, 8.0_qp*eps_qp*c%s(a))
                ! r: a few eps, plus the s tolerance below over |ds/dr| >= 1
                worst_symmetry(1) = max(worst_symmetry(1), abs(c%r(a + k) - c%r(a - k)) &
                                        /(4.0_qp*eps_qp + 32.0_qp*eps_qp*c%s(points)))
                worst_symmetry(2) = max(worst_symmetry(2), &
                                        abs(c%theta(a + k) + c%theta(a - k) - 2*c%theta(a)) &
                                        /(16.0_qp*eps_qp*c%theta(points) + allowed(1)))
                worst_symmetry(3) = max(worst_symmetry(3), &
                                        abs(c%s(a + k) + c%s(a - k) - 2*c%s(a)) &
                                        /(16.0_qp*eps_qp*c%s(points) + allowed(2)))
                worst_symmetry(4) = max(worst_symmetry(4), &
                                        abs(c%t(a + k) + c%t(a - k) - 2*c%t(a)) &
                                        /(16.0_qp*eps_qp*c%t(points) + allowed(3)))
            end do
            write (output_unit, '(3x,a,a,a,4f6.3)') 'R =', trim(label), &
                ': mirror differences of r, theta, s, t / allowed ', worst_symmetry
            call check(all(worst_symmetry <= 1.0_qp), &
                       'mirror points agree in r, theta, s, t')
        end do
    end subroutine complete_arch_tests

    !> Finite differences of the samples (equal steps h in s) against eqs. (18), (21),
    !! (15): r dtheta/ds = K v/r, dr/ds = -+ sqrt(1 - K^2 v^2/r^2), dt/ds = 1/v, with
    !! K^2 = R^3/(2(1-R)) (53), v^2 = 2(1-r)/r (44). A 10th-order central difference on
    !! every point (step h) and on every other point (step 2h): the residual must be small
    !! and fall by about 2^10 with the step, i.e. be the difference formula's truncation.
    subroutine differential_tests(model)
        type(inverse_square_model), intent(in) :: model
        real(qp), parameter :: radii(3) = [0.7_qp, 0.3_qp, 0.05_qp]
        integer, parameter :: counts(3) = [2001, 2001, 8001]
        type(curve_samples) :: c
        real(qp) :: big_r, fine(3), coarse(3)
        integer :: j, points, used
        character(len=16) :: label

        call section('curves: finite differences of the samples against (18), (21), (15)')
        do j = 1, size(radii)
            big_r = radii(j)
            points = counts(j)
            write (label, '(f5.2)') big_r
            c = sample_complete_arch(model, big_r, points)
            if (c%n /= points) then
                call check(.false., 'complete arch sampled for differences')
                cycle
            end if
            call residuals(c, big_r, 1, fine, used)
            call residuals(c, big_r, 2, coarse, used)
            write (output_unit, '(3x,a,a,a,i0,a,3es9.2,a,3f6.0)') 'R = ', trim(label), &
                ', ', used, ' points: (18), (21), (15) residuals ', fine, &
                '; ratio at 2h ', coarse/fine
            call check(all(fine < 1.0e-18_qp), '(18), (21), (15) hold to 1e-18 at R ='// &
                       trim(label))
            call check(all(coarse/fine > 256.0_qp), 'the residual is truncation (h^10)')
        end do
    end subroutine differential_tests

    !> Worst residuals of (18) (relative), (21) (absolute), (15) (relative) by central
    !! differences over points stride apart, at the points 0.15 or more from both ends
    !! (near A and A', theta ~ s^(3/2) and t ~ s^(1/2) are not smooth in s).
    subroutine residuals(c, big_r, stride, worst, used)
        type(curve_samples), intent(in) :: c
        real(qp), intent(in) :: big_r
        integer, intent(in) :: stride
        real(qp), intent(out) :: worst(3)
        integer, intent(out) :: used
        ! 10th-order central difference for the first derivative (offsets 1..5)
        real(qp), parameter :: weights(5) = [5.0_qp/6.0_qp, -5.0_qp/21.0_qp, &
                                             5.0_qp/84.0_qp, -5.0_qp/504.0_qp, &
                                             1.0_qp/1260.0_qp]
        real(qp) :: k_const, h, v, r, dtheta, dr, dt, sign_r
        integer :: k, i, n
        n = c%n
        k_const = sqrt(big_r**3/(2.0_qp*(1.0_qp - big_r)))
        h = real(stride, qp)*c%s(n)/real(n - 1, qp)
        worst = 0.0_qp
        used = 0
        do k = 1 + 5*stride, n - 5*stride
            if (c%s(k) < 0.15_qp .or. c%s(n) - c%s(k) < 0.15_qp) cycle
            dtheta = 0.0_qp
            dr = 0.0_qp
            dt = 0.0_qp
            do i = 1, 5
                dtheta = dtheta + weights(i)*(c%theta(k + i*stride) - c%theta(k - i*stride))
                dr = dr + weights(i)*(c%r(k + i*stride) - c%r(k - i*stride))
                dt = dt + weights(i)*(c%t(k + i*stride) - c%t(k - i*stride))
            end do
            r = c%r(k)
            v = sqrt(2.0_qp*(1.0_qp - r)/r)
            sign_r = merge(-1.0_qp, 1.0_qp, k < c%apse_index)
            worst(1) = max(worst(1), abs(r*(dtheta/h)/(k_const*v/r) - 1.0_qp))
            ! 1 - K^2 v^2/r^2 = (r - R)(r^2 + R r + R^2/(1-R))/r^3: no cancellation at the
            ! apse, where K v/r = 1
            worst(2) = max(worst(2), abs(dr/h - sign_r*sqrt((r - big_r)*(r*r + big_r*r &
                               + big_r*big_r/(1.0_qp - big_r))/r**3)))
            worst(3) = max(worst(3), abs((dt/h)*v - 1.0_qp))
            used = used + 1
        end do
    end subroutine residuals

    !> Curves to solved endpoints end exactly at B; spacing; the arch kinds.
    subroutine endpoint_tests(model)
        type(inverse_square_model), intent(in) :: model
        integer, parameter :: count_endpoints = 12
        real(qp) :: rho(count_endpoints), psi(count_endpoints), apse_theta, worst_theta
        type(endpoint_solution) :: b
        type(curve_samples) :: c
        integer :: j, status, points
        character(len=8) :: label

        call section('curves: from A to solved endpoints')
        rho = [0.2_qp, 0.5_qp, 0.7_qp, 0.9_qp, 1.0_qp, 0.5_qp, 0.3_qp, 1.0_qp, 0.999_qp, &
               0.05_qp, 0.6_qp, 0.6_qp]
        psi = [1.2_qp, 0.1_qp, 1.8_qp, 0.4_qp, 2.0_qp, 2.09_qp, 1.0e-6_qp, 1.0e-3_qp, &
               1.0e-4_qp, 0.5_qp, 0.0_qp, 0.0_qp]
        ! B within 1e-20 of the apse, on both sides
        call model%apse_angle(0.6_qp, apse_theta, status)
        psi(11) = apse_theta*(1.0_qp - 1.0e-20_qp)
        psi(12) = apse_theta*(1.0_qp + 1.0e-20_qp)
        worst_theta = 0.0_qp
        do j = 1, count_endpoints
            write (label, '(i0)') j
            b = solve_endpoint(model, rho(j), psi(j))
            points = merge(101, 50, mod(j, 2) == 0)
            c = sample_endpoint_curve(model, b, points)
            call check(c%status == status_ok .and. c%n == points, 'endpoint '// &
                       trim(label)//' sampled')
            if (c%n /= points) cycle
            call check(c%r(points) == rho(j), 'curve ends at r = rho exactly')
            ! the solver gets s, t of B from its last evaluation by a first-order step, the
            ! curve from an evaluation at R-bar: a few roundings apart
            call check_close(c%s(points), b%arclength, 8.0_qp, 'curve ends at s of B')
            call check_close(c%t(points), b%time, 8.0_qp, 'curve ends at t of B')
            call check_close(c%theta(points), psi(j), 8.0_qp, 'curve ends at theta = psi', &
                             floor=1.0_qp)
            worst_theta = max(worst_theta, abs(c%theta(points) - psi(j))/max(psi(j), 1e-300_qp))
            call check(all(c%s(2:) > c%s(:points - 1)) .and. &
                       all(c%t(2:) > c%t(:points - 1)), 's and t increase along the curve')
            call check(all(c%theta(2:) >= c%theta(:points - 1)), 'theta never decreases')
            call check(all(c%theta < inaccessible_angle), 'never in the inaccessible sector')
            call check(all(abs(c%x**2 + c%y**2 - c%r**2) <= 8.0_qp*eps_qp), &
                       'x^2 + y^2 = r^2')
            call check(spacing_ok(c, b%apse_radius), 'equal steps of s on each half-arch')
            select case (b%arch)
            case (arch_first)
                call check(c%apse_index == 0, 'first half-arch: no apse on the curve')
            case (arch_second, arch_complete)
                call check(c%apse_index > 1 .and. c%apse_index < points, &
                           'second half-arch: the apse is a point')
                if (c%apse_index > 0) call check(c%r(c%apse_index) == b%apse_radius, &
                                                 'apse point at r = R-bar exactly')
            case (arch_radial)
                call check(all(c%theta == 0.0_qp) .and. all(c%y == 0.0_qp) .and. &
                           all(c%s + c%r == 1.0_qp), 'radial fall samples the segment OA')
                call check(all(c%t == radial_time(c%r)), 'radial fall: t = t(r) (46)')
            end select
        end do
        write (output_unit, '(3x,a,es9.2)') 'worst |theta(B) - psi|/psi ', worst_theta
        ! Table 1 row 5 with the paper's secant method also ends at its B
        b = solve_endpoint_secant(model, 1.0_qp, 2.0_qp, 0.2_qp, 0.1_qp, 1.0e-16_qp)
        c = sample_endpoint_curve(model, b, 3)
        call check(c%n == 3 .and. c%apse_index == 2, 'three points: A, apse, B')
        if (c%n == 3) call check_close(c%theta(3), 2.0_qp, 64.0_qp, &
                                       'secant solution: B at psi')
    end subroutine endpoint_tests

    !> Each point is at its target arclength (equal steps within each half-arch, the
    !! intervals shared in proportion to the half-arches' lengths) to within a few eps of
    !! s plus the effect of rounding r (`rounding_effect`); the steps of the two halves
    !! are within the ratio the integer counts allow.
    logical function spacing_ok(c, big_r)
        type(curve_samples), intent(in) :: c
        real(qp), intent(in) :: big_r
        real(qp) :: h1, h2, target, allowed(3)
        integer :: a, n1, n2, k
        a = c%apse_index
        if (a == 0) then
            n1 = c%n - 1
            h1 = c%s(c%n)/real(n1, qp)
            h2 = h1
            n2 = 0
        else
            n1 = a - 1
            n2 = c%n - a
            h1 = c%s(a)/real(n1, qp)
            h2 = (c%s(c%n) - c%s(a))/real(n2, qp)
        end if
        spacing_ok = .true.
        do k = 2, c%n - 1
            if (k <= n1 + 1) then
                target = c%s(1) + h1*real(k - 1, qp)
            else
                target = c%s(a) + h2*real(k - a, qp)
            end if
            allowed = rounding_effect(c, big_r, k)
            spacing_ok = spacing_ok .and. &
                         abs(c%s(k) - target) <= 4.0_qp*eps_qp*c%s(c%n) + allowed(2)
        end do
        ! a share of the intervals off by one would give a worse ratio
        if (n2 > 1 .and. n1 > 1) spacing_ok = spacing_ok .and. &
            max(h1, h2)/min(h1, h2) <= max(real(n1 + 1, qp)/n1, real(n2 + 1, qp)/n2)
    end function spacing_ok

    !> How much theta, s and t of point k move when it shifts by `shift` along the curve:
    !! d theta/ds = K v/r^2 (the conserved r^2 d theta/ds / v = K), dt/ds = 1/v.
    function shift_effect(c, big_r, k, shift) result(effect)
        type(curve_samples), intent(in) :: c
        real(qp), intent(in) :: big_r, shift
        integer, intent(in) :: k
        real(qp) :: effect(3)
        real(qp) :: r, v
        r = c%r(k)
        if (r >= 1.0_qp) then
            effect = 0.0_qp
            return
        end if
        v = sqrt(2.0_qp*(1.0_qp - r)/r)
        effect = shift*[sqrt(big_r**3/(2.0_qp*(1.0_qp - big_r)))*v/(r*r), 1.0_qp, 1.0_qp/v]
    end function shift_effect

    !> How much theta, s and t of point k can move when r moves by one rounding
    !! (2 eps r): |d/dr| from the closed forms (18), (21), (15), with
    !! |ds/dr| = 1/sqrt(1 - K^2 v^2/r^2) = r^(3/2)/sqrt((r - R)(r^2 + R r + R^2/(1-R))).
    function rounding_effect(c, big_r, k) result(effect)
        type(curve_samples), intent(in) :: c
        real(qp), intent(in) :: big_r
        integer, intent(in) :: k
        real(qp) :: effect(3)
        real(qp) :: r, d, ds_dr, k_v_over_r2, v
        r = c%r(k)
        d = r - big_r
        if (d <= 0.0_qp .or. r >= 1.0_qp) then
            effect = 0.0_qp
            return
        end if
        ds_dr = r*sqrt(r)/sqrt(d*(r*r + big_r*r + big_r*big_r/(1.0_qp - big_r)))
        v = sqrt(2.0_qp*(1.0_qp - r)/r)
        k_v_over_r2 = sqrt(big_r**3/(2.0_qp*(1.0_qp - big_r)))*v/(r*r)
        effect = 2.0_qp*eps_qp*r*[k_v_over_r2*ds_dr, ds_dr, ds_dr/v]
    end function rounding_effect

    !> The apsidal locus against the tabulated apse angle and the sampled arches.
    subroutine locus_tests(model)
        type(inverse_square_model), intent(in) :: model
        real(qp) :: radii(41), theta
        type(curve_samples) :: locus, c
        integer :: k, status
        call section('curves: apsidal locus')
        radii = [(1.0_qp - real(k, qp)/40.0_qp, k = 0, 39), 1.0e-6_qp]
        locus = apsidal_locus(model, radii)
        call check(locus%status == status_ok .and. locus%n == size(radii), 'locus sampled')
        if (locus%n /= size(radii)) return
        call check(locus%r(1) == 1.0_qp .and. locus%theta(1) == 0.0_qp .and. &
                   locus%x(1) == 1.0_qp, 'R = 1: the locus starts at A')
        call check(all(locus%theta(2:) > locus%theta(:size(radii) - 1)), &
                   'theta = Theta(R,R) increases as R decreases')
        call check(all(locus%theta < apse_angle_limit), 'below pi/3')
        call check(apse_angle_limit - locus%theta(size(radii)) < 1.0e-5_qp, &
                   'near pi/3 at R = 1e-6')
        do k = 2, size(radii)
            call model%apse_angle(radii(k), theta, status)
            call check_close(locus%theta(k), theta, 8.0_qp, &
                             'locus (Gauss sweep) = tabulated Theta(R,R)')
        end do
        c = sample_complete_arch(model, radii(9), 5)
        call check(c%theta(3) == locus%theta(9) .and. c%s(3) == locus%s(9) .and. &
                   c%t(3) == locus%t(9), 'the complete arch passes through its locus point')
        locus = apsidal_locus(model, [0.5_qp, 0.0_qp])
        call check(locus%status == status_invalid_argument .and. locus%n == 0, &
                   'R = 0 is refused')
    end subroutine locus_tests

    subroutine error_tests(model)
        type(inverse_square_model), intent(in) :: model
        type(curve_samples) :: c
        type(endpoint_solution) :: b
        real(qp) :: nan
        call section('curves: no curve')
        b = solve_endpoint(model, 0.5_qp, 2.5_qp)
        c = sample_endpoint_curve(model, b, 10)
        call check(c%status == status_inaccessible .and. c%n == 0 .and. size(c%r) == 0, &
                   'inaccessible endpoint: no curve, its status')
        b = solve_endpoint(model, 0.5_qp, 1.0_qp)
        c = sample_endpoint_curve(model, b, 1)
        call check(c%status == status_invalid_argument .and. c%n == 0, 'one point refused')
        c = sample_complete_arch(model, 1.0_qp, 10)
        call check(c%status == status_invalid_argument, 'complete arch needs R < 1')
        nan = ieee_value(nan, ieee_quiet_nan)
        c = sample_complete_arch(model, nan, 10)
        call check(c%status == status_not_finite, 'NaN R refused')
        c = sample_complete_arch(model, 0.4_qp, 2)
        call check(c%n == 2 .and. c%apse_index == 0 .and. c%r(2) == 1.0_qp, &
                   'two points: A and A''')
    end subroutine error_tests

end module test_curves
