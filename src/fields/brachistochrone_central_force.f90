!> The general engine: brachistochrones for any attractive speed law (Tee 1998, sec. 2).
!!
!! A brachistochrone is the orbit of a free particle with speed 1/v (Jellett). With the
!! apse at R < 1, w(x) = x^2/v(x)^2 and the law's P = v^2, D(x,y) = (P(x)-P(y))/(x-y):
!!   V(x) = P(x)/(1 - x) = -D(x, 1),       M(x) = (x + R) - R^2 D(x, R)/P(R),
!! so that w(x) - w(R) = (x - R) M(x)/((1 - x) V(x)), and the first half-arch integrals
!! (27), (33), (39) from r to 1 read
!!   Theta = int sqrt(w_R V) (1 - x)/(x sqrt M) dx/sqrt((x-R)(1-x)),  w_R = R^2/P(R),
!!   S     = int x sqrt(1 - x)/sqrt(M)       dx/sqrt((x-R)(1-x)),
!!   T     = int x/(sqrt(V) sqrt(M))         dx/sqrt((x-R)(1-x)).
!! The substitution x = R + (1-R) sin^2(mu/2) (the paper's (79) for every law) makes
!! dx/sqrt((x-R)(1-x)) = d mu and keeps x - R = (1-R) sin^2(mu/2), 1 - x = (1-R)
!! cos^2(mu/2) exact, so both the start (v = 0) and the apse are regular. M > 0 is the
!! apse condition w'(R) > 0, true for attractive laws (P' < 0). The integrals are taken
!! by adaptive Gauss-Legendre with an error estimate (`integrate_adaptive`); the second
!! half-arch by (29). This engine is slower than the inverse-square fast path and is
!! checked against it, and against closed forms for the harmonic law and Keam's limit.
module brachistochrone_central_force
    use brachistochrone_kinds, only: qp, pi, eps_qp
    use brachistochrone_status, only: status_ok, status_inaccessible, &
                                      status_rho_out_of_range, status_psi_out_of_range, &
                                      status_not_finite, status_outside_domain, &
                                      status_no_convergence, argument_status
    use brachistochrone_quadrature, only: univariate_integrand, gauss_legendre_rule, &
            gauss_legendre, integrate_adaptive
    use brachistochrone_roots, only: root_function, bracketed_secant
    use brachistochrone_speed_laws, only: speed_law
    use brachistochrone_solution, only: endpoint_solution, endpoint_status, region_inside
    use brachistochrone_arches, only: arch_first, arch_second, arch_complete, arch_radial, &
                                      arch_inaccessible
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    public :: central_force_model, new_central_force_model

    !> Which integral an integrand computes.
    integer, parameter :: want_angle = 1, want_length = 2, want_time = 3, want_fall = 4
    !> Relative accuracy asked of each integral.
    real(qp), parameter :: integral_tolerance = 2.0_qp*eps_qp
    !> Evaluations allowed to the root finder.
    integer, parameter :: max_steps = 300

    !> The general engine for one speed law: the law and a Gauss rule.
    type :: central_force_model
        class(speed_law), allocatable :: law      !! the force field
        type(gauss_legendre_rule) :: rule         !! rule applied on each adaptive panel
    contains
        procedure :: half_arch => general_half_arch    !! theta, s, t at r (eqs. 27-41)
        procedure :: apse_angle => general_apse_angle  !! Theta(R,R)
        procedure :: fall_time => general_fall_time    !! radial fall time from 1 to r
        procedure :: solve => general_solve            !! the two-point problem
    end type central_force_model

    !> One of the integrands above, in mu.
    type, extends(univariate_integrand) :: arch_integrand
        class(speed_law), allocatable :: law
        integer :: kind = want_angle
        real(qp) :: big_r = 0.0_qp, one_minus_big_r = 1.0_qp, p_big_r = 0.0_qp
        real(qp) :: r = 0.0_qp, one_minus_r = 1.0_qp
    contains
        procedure :: evaluate => arch_evaluate
    end type arch_integrand

    !> Upsilon(R) - psi for the root finder, in the unknown u (R = rho - u^2) or R.
    type, extends(root_function) :: general_upsilon
        type(central_force_model) :: model
        real(qp) :: rho = 0.0_qp, psi = 0.0_qp
        logical :: second = .false., apse_unknown = .false.
    contains
        procedure :: evaluate => upsilon_evaluate
    end type general_upsilon

contains

    !> A general-engine model for `law` (copied in).
    function new_central_force_model(law) result(model)
        class(speed_law), intent(in) :: law !! the speed law
        type(central_force_model) :: model
        allocate (model%law, source=law)
        model%rule = gauss_legendre(20)
    end function new_central_force_model

    pure function arch_evaluate(self, x) result(y)
        class(arch_integrand), intent(in) :: self
        real(qp), intent(in) :: x          ! mu
        real(qp) :: y
        real(qp) :: half_sin, half_cos, x_minus_r, one_minus_x, point, v_of, m_of, sigma
        if (self%kind == want_fall) then
            ! radial fall: point = 1 - (1 - r) sigma^2, sigma = x in [0, 1]
            sigma = x
            one_minus_x = self%one_minus_r*sigma*sigma
            point = 1.0_qp - one_minus_x
            v_of = -self%law%divided_difference(point, 1.0_qp)
            y = 2.0_qp*sqrt(self%one_minus_r)/sqrt(v_of)
            return
        end if
        half_sin = sin(0.5_qp*x)
        half_cos = cos(0.5_qp*x)
        x_minus_r = self%one_minus_big_r*half_sin*half_sin
        one_minus_x = self%one_minus_big_r*half_cos*half_cos
        point = self%big_r + x_minus_r
        v_of = -self%law%divided_difference(point, 1.0_qp)
        m_of = (point + self%big_r) - self%big_r**2* &
               self%law%divided_difference(point, self%big_r)/self%p_big_r
        select case (self%kind)
        case (want_angle)
            y = sqrt(self%big_r**2*v_of/self%p_big_r)*one_minus_x/(point*sqrt(m_of))
        case (want_length)
            y = point*sqrt(one_minus_x)/sqrt(m_of)
        case default
            y = point/(sqrt(v_of)*sqrt(m_of))
        end select
    end function arch_evaluate

    !> int over mu in [mu_r, pi] (first half-arch from r to 1) of one integrand.
    pure subroutine arch_integral(self, kind, r, big_r, d, value, status)
        type(central_force_model), intent(in) :: self
        integer, intent(in) :: kind
        real(qp), intent(in) :: r, big_r, d
        real(qp), intent(out) :: value
        integer, intent(out) :: status
        type(arch_integrand) :: f
        real(qp) :: lower, error
        allocate (f%law, source=self%law)
        f%kind = kind
        f%big_r = big_r
        f%r = r
        f%one_minus_r = 1.0_qp - r
        f%one_minus_big_r = f%one_minus_r + d
        f%p_big_r = self%law%speed_squared(big_r)
        lower = 2.0_qp*atan2(sqrt(d), sqrt(f%one_minus_r))
        call integrate_adaptive(f, lower, pi, self%rule, integral_tolerance, 0.0_qp, value, &
                                error, status)
    end subroutine arch_integral

    !> theta, s, t at radius r on the first (or second) half-arch with apse R.
    pure subroutine general_half_arch(self, r, big_r, second, angle, length, time, status)
        class(central_force_model), intent(in) :: self
        real(qp), intent(in) :: r        !! radius, R <= r <= 1
        real(qp), intent(in) :: big_r    !! apse radius, 0 < R < 1
        logical, intent(in) :: second    !! second half-arch: 2 F(R,R) - F(r,R)
        real(qp), intent(out) :: angle, length, time !! theta, s, t at r
        integer, intent(out) :: status   !! status_ok or the reason
        angle = 0.0_qp
        length = 0.0_qp
        time = 0.0_qp
        status = argument_status([r, big_r], big_r > 0.0_qp .and. big_r < 1.0_qp .and. &
                                             r >= big_r .and. r <= 1.0_qp)
        if (status /= status_ok) return
        call arch_values(self, r, big_r, r - big_r, second, angle, length, time, status)
    end subroutine general_half_arch

    pure subroutine arch_values(self, r, big_r, d, second, angle, length, time, status)
        type(central_force_model), intent(in) :: self
        real(qp), intent(in) :: r, big_r, d
        logical, intent(in) :: second
        real(qp), intent(out) :: angle, length, time
        integer, intent(out) :: status
        real(qp) :: apse(3)
        integer :: stat(6)
        call arch_integral(self, want_angle, r, big_r, d, angle, stat(1))
        call arch_integral(self, want_length, r, big_r, d, length, stat(2))
        call arch_integral(self, want_time, r, big_r, d, time, stat(3))
        stat(4:6) = status_ok
        if (second) then
            call arch_integral(self, want_angle, big_r, big_r, 0.0_qp, apse(1), stat(4))
            call arch_integral(self, want_length, big_r, big_r, 0.0_qp, apse(2), stat(5))
            call arch_integral(self, want_time, big_r, big_r, 0.0_qp, apse(3), stat(6))
            angle = 2.0_qp*apse(1) - angle
            length = 2.0_qp*apse(2) - length
            time = 2.0_qp*apse(3) - time
        end if
        status = maxval(stat)
    end subroutine arch_values

    !> Theta(R,R): the apse angle.
    pure subroutine general_apse_angle(self, big_r, value, status)
        class(central_force_model), intent(in) :: self
        real(qp), intent(in) :: big_r    !! apse radius, 0 < R < 1
        real(qp), intent(out) :: value   !! Theta(R,R)
        integer, intent(out) :: status   !! status_ok or the reason
        value = 0.0_qp
        status = argument_status([big_r], big_r > 0.0_qp .and. big_r < 1.0_qp)
        if (status == status_ok) &
            call arch_integral(self, want_angle, big_r, big_r, 0.0_qp, value, status)
    end subroutine general_apse_angle

    !> Time of radial fall from rest at radius 1 to radius r (K = 0): int_r^1 dx/v.
    pure subroutine general_fall_time(self, r, value, status)
        class(central_force_model), intent(in) :: self
        real(qp), intent(in) :: r        !! radius, 0 <= r <= 1
        real(qp), intent(out) :: value   !! the time
        integer, intent(out) :: status   !! status_ok or the reason
        type(arch_integrand) :: f
        real(qp) :: error
        value = 0.0_qp
        status = argument_status([r], r >= 0.0_qp .and. r <= 1.0_qp)
        if (status /= status_ok .or. r == 1.0_qp) return
        allocate (f%law, source=self%law)
        f%kind = want_fall
        f%r = r
        f%one_minus_r = 1.0_qp - r
        call integrate_adaptive(f, 0.0_qp, 1.0_qp, self%rule, integral_tolerance, 0.0_qp, &
                                value, error, status)
    end subroutine general_fall_time

    pure subroutine upsilon_evaluate(self, x, f, df, status)
        class(general_upsilon), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp), intent(out) :: f, df
        integer, intent(out) :: status
        real(qp) :: big_r, d, angle, apse
        integer :: status_apse
        f = 0.0_qp
        df = 0.0_qp
        if (self%apse_unknown) then
            d = x*x
            big_r = self%rho - d
        else
            big_r = x
            d = self%rho - big_r
        end if
        if (.not. (big_r > 0.0_qp .and. big_r < 1.0_qp .and. d >= 0.0_qp)) then
            status = status_outside_domain
            return
        end if
        call arch_integral(self%model, want_angle, self%rho, big_r, d, angle, status)
        if (self%second) then
            call arch_integral(self%model, want_angle, big_r, big_r, 0.0_qp, apse, &
                               status_apse)
            angle = 2.0_qp*apse - angle
            status = max(status, status_apse)
        end if
        f = angle - self%psi
    end subroutine upsilon_evaluate

    !> The two-point problem for this law: the brachistochrone from A = (1, 0) to
    !! B = (rho, psi), by a bracketed secant method on (0, rho] split at rho/2 (unknown
    !! u = sqrt(rho - R) near the apse, R below). psi >= 2 lim Theta(R,R) is the sector
    !! of inaccessibility; t is then its greatest lower bound t(0) + (t(0) - t(rho)),
    !! attained (arch 'radial', through O) where the law lets a particle pass the centre.
    pure function general_solve(self, rho, psi) result(solution)
        class(central_force_model), intent(in) :: self
        real(qp), intent(in) :: rho   !! endpoint radius, 0 < rho <= 1
        real(qp), intent(in) :: psi   !! endpoint angle, 0 <= psi <= pi
        type(endpoint_solution) :: solution
        type(general_upsilon) :: fun
        real(qp) :: apse_angle_rho, limit, half, f_half, f_end, x, big_r, d, fall_rho, fall_0
        real(qp) :: angle, length, time
        integer :: status, steps

        solution%rho = rho
        solution%psi = psi
        solution%status = endpoint_status(rho, psi, region_inside)
        if (solution%status /= status_ok) return
        limit = self%law%apse_angle_limit()
        if (psi == 0.0_qp .or. psi >= 2.0_qp*limit) then
            call self%fall_time(rho, fall_rho, status)
            if (psi == 0.0_qp) then
                solution%arch = arch_radial
                solution%arclength = 1.0_qp - rho
                solution%time = fall_rho
                solution%has_apse_radius = .true.
                solution%has_arclength = .true.
            else
                call self%fall_time(0.0_qp, fall_0, status)
                solution%time = 2.0_qp*fall_0 - fall_rho
                if (self%law%passes_centre() .and. psi == 2.0_qp*limit) then
                    ! the straight path through O (harmonic: the diametral tunnel) attains
                    ! the bound: R = 0, s = 1 + rho
                    solution%arch = arch_radial
                    solution%arclength = 1.0_qp + rho
                    solution%has_apse_radius = .true.
                    solution%has_arclength = .true.
                else
                    solution%arch = arch_inaccessible
                    solution%status = status_inaccessible
                end if
            end if
            solution%has_time = .true.
            return
        end if

        fun%model = self
        fun%rho = rho
        fun%psi = psi
        apse_angle_rho = 0.0_qp
        if (rho < 1.0_qp) call self%apse_angle(rho, apse_angle_rho, status)
        fun%second = rho == 1.0_qp .or. psi > apse_angle_rho
        solution%arch = merge(arch_complete, merge(arch_second, arch_first, fun%second), &
                              rho == 1.0_qp)
        if (psi == apse_angle_rho) then
            big_r = rho
            d = 0.0_qp
        else
            half = 0.5_qp*rho
            fun%apse_unknown = .false.
            call fun%evaluate(half, f_half, x, status)
            if ((f_half >= 0.0_qp) .neqv. fun%second) then
                ! root in (0, rho/2]: Upsilon(0+) = 0 (first) or 2 lim Theta (second)
                f_end = merge(2.0_qp*limit, 0.0_qp, fun%second) - psi
                call bracketed_secant(fun, 0.0_qp, f_end, half, f_half, 4.0_qp*eps_qp, &
                                      tiny(1.0_qp), max_steps, x, steps, status)
                big_r = x
                d = rho - x
            else
                ! root in (rho/2, rho]: unknown u = sqrt(rho - R), Upsilon(u=0) = Theta(rho,rho)
                fun%apse_unknown = .true.
                f_end = apse_angle_rho - psi
                if (rho == 1.0_qp) f_end = -psi
                call bracketed_secant(fun, 0.0_qp, f_end, sqrt(rho - half), f_half, &
                                      4.0_qp*eps_qp, tiny(1.0_qp), max_steps, x, steps, &
                                      status)
                d = x*x
                big_r = rho - d
            end if
            solution%steps = steps + 1
            if (status /= status_ok) then
                solution%status = status
                return
            end if
        end if
        call arch_values(self, rho, big_r, d, fun%second, angle, length, time, status)
        if (status /= status_ok) then
            solution%status = status_no_convergence
            return
        end if
        solution%apse_radius = big_r
        solution%arclength = length
        solution%time = time
        solution%has_apse_radius = .true.
        solution%has_arclength = .true.
        solution%has_time = .true.
    end function general_solve

end module brachistochrone_central_force
