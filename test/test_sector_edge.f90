!> The power laws next to the edge of their sector 2 pi/(n+1) where the two parts of
!! limit - Upsilon cross (n < 3/2, rho tiny: the first half-arch's angle P ~ (R/rho)^((n+1)/2)
!! dominates at the early phase's root, A ~ C R^(n-1) at R-bar): few evaluations, and the
!! right R-bar, s and t. Before branch i11-edge (session 7) these endpoints took 20
!! evaluations and 21x the median time of `engine-fuzz -- 1.3 2000 0`: the Newton step in
!! log R (-100 and more) was taken as R + R expm1(dy), which is 0 below dy = -78, and the
!! edge steps then bisected log R down from the bottom of the binary128 range.
module test_sector_edge
    use, intrinsic :: iso_fortran_env, only: output_unit
    use brachistochrone_kinds, only: qp, eps_qp
    use brachistochrone_status, only: status_ok
    use brachistochrone_speed_laws, only: power_law
    use brachistochrone_central_force, only: central_force_model, new_central_force_model
    use brachistochrone_solution, only: endpoint_solution
    use testing, only: check, section
    implicit none
    private

    public :: run_sector_edge_tests

    !> Most evaluations (`steps`: the model's hardware-precision ones and the full ones)
    !! of an endpoint next to the edge beyond those of the endpoint at the same rho just
    !! outside the edge path (psi = limit (1 - 1.01e-10): the same early phase, whose
    !! target is limit - Upsilon = 1e-10 limit, then usually one full evaluation): for
    !! the four endpoints of `crossing_endpoints` (one full evaluation, one of the
    !! model's), and their neighbours (one or two full ones and a few of the model's).
    !! Before branch i11-edge: 10 for all of them.
    integer, parameter :: most_extra = 3, most_extra_neighbours = 7

contains

    subroutine run_sector_edge_tests()
        call crossing_endpoints()
        call crossing_neighbours()
    end subroutine run_sector_edge_tests

    !> Four endpoints (n = 1.3: the slowest of `engine-fuzz -- 1.3 2000 0` and two of its
    !! neighbours; n = 1.25), psi = limit (1 - gap): status ok, at most most_extra
    !! evaluations beyond the early phase, |Upsilon(R-bar) - psi| within 8 eps psi
    !! (`half_arch` at the returned R-bar), and, R-bar being below 1e-90, s and t at their
    !! R -> 0 limits to 8 eps: s = 1 + rho and t = 2 t0(0) - t0(rho) = t0(0) +
    !! int_0^rho dx/v(x), v^2 = 2 (x^(1-n) - 1)/(n - 1), by mpmath at 50 and 70 digits
    !! (agreeing to 50; tanh-sinh, t0(0) in x = 1 - s^2 with P = 2 expm1((1 - n)
    !! log1p(-s^2))/(n - 1)), and by the beta functions (B(a, 1/2) + B(rho^(n-1); a,
    !! 1/2))/sqrt(2 (n - 1)), a = 1/2 + 1/(n - 1) (the same 40 digits).
    subroutine crossing_endpoints()
        real(qp), parameter :: exponents(4) = [1.3_qp, 1.3_qp, 1.3_qp, 1.25_qp]
        real(qp), parameter :: radii(4) = [5.051177057340264867526214662040258e-26_qp, &
                                           5.623e-29_qp, 1.0e-24_qp, 1.0e-30_qp]
        real(qp), parameter :: gaps(4) = [1.8999e-30_qp, 1.0e-32_qp, 3.162e-31_qp, &
                                          1.0e-32_qp]
        real(qp), parameter :: times(4) = [1.207350648459442777736429330498213912_qp, &
                                           1.207350648459442777736429330495484464_qp, &
                                           1.207350648459442777736429330580078973_qp, &
                                           1.214850803402678270668404958219720989_qp]
        type(central_force_model) :: model
        type(endpoint_solution) :: a
        real(qp) :: limit, psi, angle, length, time, residual, error_s, error_t
        integer :: i, status, extra
        call section('sector edge: n < 3/2, P and A crossing between the early root and R-bar')
        do i = 1, size(radii)
            model = new_central_force_model(power_law(n=exponents(i)))
            limit = 2.0_qp*model%law%apse_angle_limit()
            psi = limit*(1.0_qp - gaps(i))
            a = model%solve(radii(i), psi)
            extra = extra_steps(model, radii(i), limit, a)
            call check(a%status == status_ok .and. a%apse_radius > 0.0_qp, &
                       'edge endpoint solved, R-bar > 0')
            if (.not. (a%status == status_ok .and. a%apse_radius > 0.0_qp)) cycle
            call model%half_arch(radii(i), a%apse_radius, .true., angle, length, time, &
                                 status)
            residual = abs(angle - psi)/(eps_qp*psi)
            error_s = abs(a%arclength - (1.0_qp + radii(i)))/(eps_qp*(1.0_qp + radii(i)))
            error_t = abs(a%time - times(i))/(eps_qp*times(i))
            write (output_unit, '(a,f5.2,2es10.2,a,i0,a,i0,a,es10.3,a,3f6.2)') &
                '   n, rho, gap ', exponents(i), radii(i), gaps(i), ': evaluations ', &
                a%steps, ' (', extra, ' beyond the early phase), R-bar ', a%apse_radius, &
                ', |f|, s, t errors / eps ', residual, error_s, error_t
            call check(extra <= most_extra, 'edge endpoint in at most 3 evaluations '// &
                       'beyond the early phase')
            call check(residual <= 8.0_qp, 'edge endpoint: |Upsilon(R-bar) - psi| <= 8 eps psi')
            call check(error_s <= 8.0_qp, 'edge endpoint: s = 1 + rho to 8 eps')
            call check(error_t <= 8.0_qp, 'edge endpoint: t = t0(0) + int_0^rho dx/v to 8 eps')
        end do
    end subroutine crossing_endpoints

    !> Their neighbours: n = 1.2 .. 1.49, rho = 1e-30 .. 1e-20, psi within 1e-32 .. 1e-26
    !! of the edge (relative): every one solved in at most most_extra_neighbours beyond
    !! the early phase, with |Upsilon(R-bar) - psi| within 8 eps psi.
    subroutine crossing_neighbours()
        real(qp), parameter :: exponents(5) = [1.2_qp, 1.3_qp, 1.35_qp, 1.4_qp, 1.49_qp]
        real(qp), parameter :: radii(3) = [1.0e-30_qp, 3.0e-25_qp, 1.0e-20_qp]
        real(qp), parameter :: gaps(3) = [1.0e-32_qp, 2.0e-29_qp, 1.0e-26_qp]
        type(central_force_model) :: model
        type(endpoint_solution) :: a
        real(qp) :: limit, psi, angle, length, time, residual
        integer :: law, i, k, status, most, failed, extra
        most = 0
        failed = 0
        residual = 0.0_qp
        do law = 1, size(exponents)
            model = new_central_force_model(power_law(n=exponents(law)))
            limit = 2.0_qp*model%law%apse_angle_limit()
            do i = 1, size(radii)
                do k = 1, size(gaps)
                    psi = limit*(1.0_qp - gaps(k))
                    a = model%solve(radii(i), psi)
                    if (.not. (a%status == status_ok .and. a%apse_radius > 0.0_qp)) then
                        failed = failed + 1
                        cycle
                    end if
                    extra = extra_steps(model, radii(i), limit, a)
                    if (extra > most_extra_neighbours) &
                        write (output_unit, '(5x,a,f5.2,2es11.3,2i4)') &
                        'slow: n, rho, gap, evaluations (beyond the early phase)', &
                        exponents(law), radii(i), gaps(k), a%steps, extra
                    most = max(most, extra)
                    call model%half_arch(radii(i), a%apse_radius, .true., angle, length, &
                                         time, status)
                    residual = max(residual, abs(angle - psi)/(eps_qp*psi))
                end do
            end do
        end do
        write (output_unit, '(a,i0,a,i0,a,f6.2)') '   n = 1.2 .. 1.49, 45 endpoints: '// &
            'unsolved ', failed, ', most evaluations beyond the early phase ', most, &
            ', worst |f|/eps psi ', residual
        call check(failed == 0, 'edge neighbours all solved')
        call check(most <= most_extra_neighbours, 'edge neighbours in at most 7 '// &
                   'evaluations beyond the early phase')
        call check(residual <= 8.0_qp, 'edge neighbours: |Upsilon(R-bar) - psi| <= 8 eps psi')
    end subroutine crossing_neighbours

    !> Evaluations of the solution a (at rho, next to the edge) beyond those of the
    !! endpoint at rho with psi = limit (1 - 1.01e-10), outside the edge path.
    function extra_steps(model, rho, limit, a) result(extra)
        type(central_force_model), intent(in) :: model
        real(qp), intent(in) :: rho, limit
        type(endpoint_solution), intent(in) :: a
        integer :: extra
        type(endpoint_solution) :: outside
        outside = model%solve(rho, limit*(1.0_qp - 1.01e-10_qp))
        extra = a%steps - outside%steps
    end function extra_steps

end module test_sector_edge
