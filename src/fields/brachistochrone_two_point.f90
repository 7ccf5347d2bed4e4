!> The two-point problem: the brachistochrone from A = (1, 0) to B = (rho, psi).
!!
!! Tee 1998, sec. 5: the brachistochrone through B is found from its apse radius R-bar,
!! the root in (0, rho] of Upsilon(R) = psi, where Upsilon(R) = Theta(rho,R) if B is on
!! the first half-arch (psi <= Theta(rho,rho)) and 2 Theta(R,R) - Theta(rho,R) on the
!! second. The half-arch is decided once, from the endpoint (see docs/ERRATA.md).
!!
!! Two solvers:
!! - `solve_endpoint` (default, no guesses): (0, rho] brackets the root. It is split at
!!   rho/2. In the upper part the unknown is u = sqrt(rho - R): near the apse Upsilon
!!   behaves like c -+ k sqrt(rho - R), which is linear in u, and R-bar = rho - u^2, r - R =
!!   u^2 keep full precision for endpoints next to the apse. In the lower part the unknown
!!   is R itself (second half-arch: Upsilon = 2 pi/3 - 1.619 R + O(R^(3/2))) or log R
!!   (first half-arch: Theta(rho,R) ~ C R^(3/2)), so tiny R-bar keeps its relative
!!   precision. Safeguarded Newton on 19-digit rules evaluated in hardware precision
!!   (x87 extended, `level_hardware`: about a microsecond each), then one step on full
!!   quad-precision rules that also yields s and t (`final_step`), the one
!!   software-binary128 evaluation per endpoint in the usual case; the derivative is
!!   differentiated under the integral sign (eq. 67-71) plus the boundary term of the
!!   moving limit L(R).
!! - `solve_endpoint_secant`: the paper's secant method from R0, R1 with its stopping
!!   rule |R_n - R_(n-1)| < tol and a step count, which reproduces Table 1.
module brachistochrone_two_point
    use brachistochrone_kinds, only: qp, pi, eps_qp, xp
    use brachistochrone_status, only: status_ok, status_inaccessible, status_outside_domain, &
                                      status_no_convergence
    use brachistochrone_solution, only: endpoint_solution, endpoint_status, region_inside
    use brachistochrone_closed_forms, only: radial_time, kappa_time, inaccessible_angle
    use brachistochrone_inverse_square, only: inverse_square_model, evaluate_arch, arch_values, &
            level_fine, level_hardware, level_final, hardware_epsilon, apse_estimate_error
    use brachistochrone_roots, only: root_function, secant, newton_iteration, newton_begin, &
                                     newton_advance
    use brachistochrone_arches, only: arch_first, arch_second, arch_complete, arch_radial, &
                                      arch_inaccessible
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    public :: solve_endpoint, solve_endpoint_secant

    !> Limit on root-finder evaluations per phase.
    integer, parameter :: max_steps = 200
    !> Steps down in log R (by 4 each) looking for the lower end of the bracket.
    integer, parameter :: max_probes = 100
    !> Lowest log R probed: the smallest normal binary128 number. A root below it is
    !! returned as R-bar = 0 (`below_range`).
    real(qp), parameter :: lowest_log_r = log(tiny(1.0_qp))
    !> The phase before the full-precision step runs in hardware precision
    !! (level_hardware, 19-digit rules): its relative tolerance and the accuracy of its
    !! evaluations, from the rounding of the hardware kind (x87 extended: 1.1e-17 and
    !! 1.1e-18, so that the full-precision Newton step is below 1e-17 of the bracket and
    !! `final_step` accepts it; where the widest hardware kind is double, 2.2e-14 and
    !! 2.2e-15, and the full-precision phase takes more steps).
    real(qp), parameter :: hardware_tolerance = 100.0_qp*hardware_epsilon
    real(qp), parameter :: hardware_accuracy = max(1.0e-19_qp, 10.0_qp*hardware_epsilon)
    !> |2 pi/3 - psi| below this share of psi: the hardware rules do not resolve
    !! Upsilon - psi near R = 0 (their error is about 1e-17 psi)
    real(qp), parameter :: edge_resolution = 1.0e-10_qp
    !> Full-precision Newton steps at most next to the sector's edge (`edge_newton`).
    integer, parameter :: max_edge_steps = 40

    !> Unknowns of the default solver.
    integer, parameter :: unknown_u = 1, unknown_r = 2, unknown_log_r = 3

    !> The bracket of the root in the solver's unknown: its ends, the signs of Upsilon -
    !! psi there, a start, the curvature measured so far, and Upsilon - psi at rho/2.
    type :: root_bracket
        real(qp) :: lo = 0.0_qp, hi = 0.0_qp      !! the ends
        real(qp) :: f_lo = 0.0_qp, f_hi = 0.0_qp  !! Upsilon - psi there (signs)
        real(qp) :: x0 = 0.0_qp                   !! start, then the early phase's root
        real(qp) :: curvature = 0.0_qp            !! |f''/2f'| measured (0: unknown)
        real(qp) :: half = 0.0_qp                 !! rho/2
        real(qp) :: f_half = 0.0_qp               !! Upsilon - psi at R = rho/2
    end type root_bracket

    !> The equation of one endpoint, without the model (which the default solver passes
    !! along instead of copying it: its rules and tables are allocatable).
    type :: upsilon_problem
        integer :: level = level_fine
        logical :: second = .false.
        integer :: unknown = unknown_r
        real(qp) :: rho = 0.0_qp
        real(qp) :: psi = 0.0_qp
    contains
        procedure :: radius_of
        procedure :: slope_in_unknown
    end type upsilon_problem

    !> The equation with a copy of the model, as a root_function (the secant method).
    type, extends(root_function) :: upsilon_function
        type(upsilon_problem) :: problem
        type(inverse_square_model) :: model
    contains
        procedure :: evaluate => upsilon_evaluate
    end type upsilon_function

contains

    !> Checks and the special endpoints shared by both solvers. Sets `done` when the
    !! solution is complete without a root finder; otherwise sets the arch and Theta(rho,rho).
    pure subroutine classify(model, rho, psi, solution, apse_angle_rho, done)
        type(inverse_square_model), intent(in) :: model
        real(qp), intent(in) :: rho, psi
        type(endpoint_solution), intent(out) :: solution
        real(qp), intent(out) :: apse_angle_rho
        logical, intent(out) :: done
        integer :: status

        solution%rho = rho
        solution%psi = psi
        apse_angle_rho = 0.0_qp
        done = .true.
        solution%status = endpoint_status(rho, psi, region_inside)
        if (solution%status /= status_ok) then
            return
        else if (psi >= inaccessible_angle) then
            solution%arch = arch_inaccessible
            solution%status = status_inaccessible
            solution%time = kappa_time(rho)
            solution%has_time = .true.
        else if (psi == 0.0_qp) then
            ! radial fall (eq. 45-46): K = 0, R = 0
            solution%arch = arch_radial
            solution%apse_radius = 0.0_qp
            solution%apse_gap = rho
            solution%arclength = 1.0_qp - rho
            solution%time = radial_time(rho)
            solution%has_apse_radius = .true.
            solution%has_arclength = .true.
            solution%has_time = .true.
        else
            done = .false.
            ! Theta(rho, rho) in hardware precision decides the half-arch (and starts the
            ! search) unless psi is within 100 times its error; then the full table
            if (rho < 1.0_qp) then
                apse_angle_rho = model%apse_angle_estimate(rho)
                if (abs(psi - apse_angle_rho) <= 100.0_qp*apse_estimate_error*psi) &
                    call model%apse_angle(rho, apse_angle_rho, status)
            end if
            if (rho == 1.0_qp) then
                solution%arch = arch_complete
            else if (psi <= apse_angle_rho) then
                solution%arch = arch_first
            else
                solution%arch = arch_second
            end if
        end if
    end subroutine classify

    !> R and r - R at the unknown x; `inside` is false outside 0 < R < 1, R <= rho.
    pure subroutine radius_of(self, x, big_r, d, inside)
        class(upsilon_problem), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp), intent(out) :: big_r, d
        logical, intent(out) :: inside
        select case (self%unknown)
        case (unknown_u)
            d = x*x
            big_r = self%rho - d
        case (unknown_log_r)
            big_r = exp(x)
            d = self%rho - big_r
        case default
            big_r = x
            d = self%rho - big_r
        end select
        inside = big_r > 0.0_qp .and. d >= 0.0_qp .and. big_r < 1.0_qp
    end subroutine radius_of

    !> d/dx, in the unknown x, of a quantity whose R-derivative is
    !! smooth + boundary/sqrt(rho - R) (`boundary` signed). Finite at the apse for u.
    pure function slope_in_unknown(self, x, big_r, d, smooth, boundary) result(slope)
        class(upsilon_problem), intent(in) :: self
        real(qp), intent(in) :: x, big_r, d, smooth, boundary
        real(qp) :: slope
        if (self%unknown == unknown_u) then
            ! dR/du = -2u, and u/sqrt(rho - R) = 1
            slope = -2.0_qp*x*smooth - 2.0_qp*boundary
        else
            ! dUpsilon/dR is infinite at the apse (R = rho); no square root for the
            ! error bounds of final_step (boundary 0)
            if (d > 0.0_qp) then
                slope = smooth
                if (boundary /= 0.0_qp) slope = smooth + boundary/sqrt(d)
            else
                slope = sign(huge(1.0_qp), boundary)
            end if
            if (self%unknown == unknown_log_r) slope = big_r*slope
        end if
    end function slope_in_unknown

    !> `upsilon_at` for the root finders.
    pure subroutine upsilon_evaluate(self, x, f, df, status)
        class(upsilon_function), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp), intent(out) :: f, df
        integer, intent(out) :: status
        call upsilon_at(self%problem, self%model, x, f, df, status)
    end subroutine upsilon_evaluate

    !> Upsilon - psi and its derivative in the chosen unknown (log(Upsilon/psi) for
    !! the unknown log R). status: status_ok or status_outside_domain.
    pure subroutine upsilon_at(self, model, x, f, df, status)
        type(upsilon_problem), intent(in) :: self
        type(inverse_square_model), intent(in) :: model
        real(qp), intent(in) :: x
        real(qp), intent(out) :: f, df
        integer, intent(out) :: status
        real(qp) :: big_r, d
        logical :: inside
        type(arch_values) :: values

        f = 0.0_qp
        df = 0.0_qp
        call self%radius_of(x, big_r, d, inside)
        if (.not. inside) then
            status = status_outside_domain
            return
        end if
        status = status_ok
        values = evaluate_arch(model, self%level, self%second, self%rho, big_r, d, &
                                          .true., .false.)
        df = self%slope_in_unknown(x, big_r, d, values%angle_dr_smooth, &
                                   values%boundary_sign*values%boundary)
        if (self%unknown == unknown_log_r) then
            f = log(values%angle/self%psi)
            df = df/values%angle
        else
            f = values%angle - self%psi
        end if
    end subroutine upsilon_at

    !> `newton_bracketed` on Upsilon - psi (same arguments, the model passed along).
    pure subroutine newton_upsilon(fun, model, lo, f_lo, hi, f_hi, x0, rel_tol, abs_tol, x, &
                                   steps, status, curvature, accuracy)
        type(upsilon_problem), intent(in) :: fun
        type(inverse_square_model), intent(in) :: model
        real(qp), intent(in) :: lo, f_lo, hi, f_hi, x0, rel_tol, abs_tol
        real(qp), intent(out) :: x
        integer, intent(out) :: steps, status
        real(qp), intent(inout) :: curvature
        real(qp), intent(in), optional :: accuracy
        type(newton_iteration) :: run
        real(qp) :: f, df
        integer :: evaluation_status
        call newton_begin(run, lo, f_lo, hi, f_hi, x0, rel_tol, abs_tol, max_steps, &
                          curvature, accuracy)
        do while (.not. run%done)
            call upsilon_at(fun, model, run%x, f, df, evaluation_status)
            call newton_advance(run, f, df, evaluation_status)
        end do
        x = run%x
        steps = run%steps
        status = run%status
        curvature = run%curvature
    end subroutine newton_upsilon

    !> Solve the two-point problem for B = (rho, psi) to full quad precision, without
    !! initial estimates. Never fails on an accessible endpoint 0 < rho <= 1,
    !! 0 <= psi < 2 pi/3; other endpoints get a status (see `classify`). An R-bar below
    !! the smallest normal binary128 number (tiny rho and psi, e.g. rho = 1e-2000,
    !! psi = 1e-4900: R-bar ~ 2.8 rho psi^(2/3)) is returned as 0 with s and t at their
    !! limits (`below_range`).
    pure function solve_endpoint(model, rho, psi) result(solution)
        type(inverse_square_model), intent(in) :: model !! the evaluator
        real(qp), intent(in) :: rho                     !! endpoint radius
        real(qp), intent(in) :: psi                     !! endpoint angle
        type(endpoint_solution) :: solution
        type(upsilon_problem) :: fun
        type(root_bracket) :: b
        real(qp) :: apse_angle_rho, x, big_r, d
        integer :: steps, status
        logical :: done, inside, below

        call classify(model, rho, psi, solution, apse_angle_rho, done)
        if (done) return
        fun = upsilon_problem(level=level_fine, second=solution%arch /= arch_first, &
                              rho=rho, psi=psi)
        if (psi == apse_angle_rho) then
            ! B is the apse itself
            call finish(model, solution, fun%second, rho, 0.0_qp)
            return
        end if
        call open_bracket(fun, model, apse_angle_rho, b, solution%steps)
        if (fun%unknown == unknown_log_r) then
            call log_phase(fun, model, b, solution%steps, status, below)
            if (below) then
                call below_range(solution)
                return
            end if
        else if (fun%unknown == unknown_r .and. abs(b%f_lo) <= edge_resolution*psi) then
            ! psi next to the sector's edge 2 pi/3 (R-bar -> 0): Upsilon - psi is below the
            ! resolution of the hardware rules (their Newton steps would wander for
            ! max_steps evaluations)
            call edge_newton(fun, model, b, x, solution%steps, status)
            if (status /= status_ok) then
                solution%status = status
                return
            end if
            call finish(model, solution, fun%second, x, rho - x)
            return
        else
            call hardware_phase(fun, model, b, solution%steps, status)
        end if
        if (status /= status_ok) then
            solution%status = status
            return
        end if
        ! full-precision phase: usually one step, certified by the measured curvature
        fun%level = level_fine
        call final_step(fun, model, b%lo, b%hi, b%x0, b%curvature, solution, done)
        if (done) return
        ! otherwise iterate on, from the Newton step final_step took when in the bracket
        call newton_upsilon(fun, model, b%lo, b%f_lo, b%hi, b%f_hi, b%x0, 4.0_qp*eps_qp, &
                            tiny(1.0_qp), x, steps, status, b%curvature)
        solution%steps = solution%steps + steps
        if (status /= status_ok) then
            solution%status = status
            return
        end if
        call fun%radius_of(x, big_r, d, inside)
        call finish(model, solution, fun%second, big_r, d)
    end function solve_endpoint

    !> The unknown and its bracket: Upsilon at R = rho/2 (in hardware precision unless
    !! the sign is in doubt) says which half of (0, rho] holds the root. Near the apse the
    !! unknown is u = sqrt(rho - R), below rho/2 it is R (second half-arch) or log R
    !! (first half-arch). One evaluation, counted in `steps`.
    pure subroutine open_bracket(fun, model, apse_angle_rho, b, steps)
        type(upsilon_problem), intent(inout) :: fun  !! sets its unknown
        type(inverse_square_model), intent(in) :: model !! the evaluator
        real(qp), intent(in) :: apse_angle_rho       !! Theta(rho, rho)
        type(root_bracket), intent(out) :: b         !! bracket, end signs, start
        integer, intent(out) :: steps                !! evaluations made
        type(arch_values) :: values
        real(qp) :: rho, psi, slope, slope_lo
        logical :: low_region
        rho = fun%rho
        psi = fun%psi
        b%half = 0.5_qp*rho
        values = evaluate_arch(model, level_hardware, fun%second, rho, b%half, &
                               rho - b%half, .true., .false.)
        if (abs(values%angle - psi) < 1.0e-6_qp*psi) then
            values = evaluate_arch(model, level_fine, fun%second, rho, b%half, &
                                   rho - b%half, .true., .false.)
        end if
        b%f_half = values%angle - psi
        low_region = merge(b%f_half <= 0.0_qp, b%f_half >= 0.0_qp, fun%second)
        steps = 1
        b%f_hi = b%f_half
        if (.not. low_region) then
            ! unknown u = sqrt(rho - R) in [0, sqrt(rho/2)]; at u = 0 (the apse)
            ! Upsilon = Theta(rho,rho) and dUpsilon/du = -+ 2 B(rho,rho), with
            ! B(rho,rho) = sqrt((1-rho)/(rho (3 - 2 rho))) in closed form
            fun%unknown = unknown_u
            b%hi = sqrt(rho - b%half)
            b%f_lo = apse_angle_rho - psi
            slope_lo = -2.0_qp*merge(-1.0_qp, 1.0_qp, fun%second) &
                       *sqrt((1.0_qp - rho)/(rho*(3.0_qp - 2.0_qp*rho)))
            slope = -2.0_qp*b%hi*values%angle_dr_smooth &
                    - 2.0_qp*values%boundary_sign*values%boundary
            b%x0 = hermite_start(b%f_lo, slope_lo, b%hi, b%f_hi, slope)
        else if (fun%second) then
            ! unknown R in [0, rho/2]; at R -> 0, Upsilon = 2 pi/3 + 2 Theta_R(0) R
            fun%unknown = unknown_r
            b%hi = b%half
            b%f_lo = inaccessible_angle - psi
            slope_lo = 2.0_qp*model%apse_slope_at_zero
            slope = values%angle_dr_smooth &
                    + values%boundary_sign*values%boundary/sqrt(rho - b%half)
            b%x0 = hermite_start(b%f_lo, slope_lo, b%hi, b%f_hi, slope)
        else
            ! first half-arch, small R: Theta(rho,R) ~ C R^(3/2); unknown log R first
            fun%unknown = unknown_log_r
            b%hi = log(b%half)
            b%x0 = b%hi + (2.0_qp/3.0_qp)*log(psi/values%angle)
        end if
    end subroutine open_bracket

    !> First half-arch below rho/2: Newton in log R on the hardware rules (the lower
    !! end of the bracket found by stepping down, not below the smallest normal
    !! binary128 number), then the bracket and start in R for the full-precision phase.
    !! status: status_ok, status_no_convergence when no lower end is found, or an
    !! evaluation's status; `below` (status_ok) when Upsilon exceeds psi even at the
    !! smallest normal R: R-bar is below the binary128 range.
    pure subroutine log_phase(fun, model, b, steps, status, below)
        type(upsilon_problem), intent(inout) :: fun  !! unknown log R, then R
        type(inverse_square_model), intent(in) :: model !! the evaluator
        type(root_bracket), intent(inout) :: b       !! the bracket, in log R then in R
        integer, intent(inout) :: steps              !! evaluations made
        integer, intent(out) :: status               !! the phase's status
        logical, intent(out) :: below                !! R-bar underflows
        real(qp) :: log_lo, f_lo, f_end, x
        integer :: probe, used
        fun%level = level_hardware
        below = .false.
        log_lo = max(b%x0 - 2.0_qp, lowest_log_r)
        do probe = 1, max_probes
            call upsilon_at(fun, model, log_lo, f_lo, f_end, status)
            steps = steps + 1
            if (status == status_ok .and. f_lo < 0.0_qp) exit
            if (status == status_ok .and. log_lo == lowest_log_r) then
                below = .true.
                return
            end if
            log_lo = max(log_lo - 4.0_qp, lowest_log_r)
        end do
        if (status /= status_ok) return
        if (.not. f_lo < 0.0_qp) then
            status = status_no_convergence
            return
        end if
        b%x0 = max(b%x0, log_lo)
        call newton_upsilon(fun, model, log_lo, f_lo, b%hi, 1.0_qp, b%x0, hardware_tolerance, &
                            0.0_qp, x, used, status, b%curvature, hardware_accuracy)
        steps = steps + used
        call accept_phase(status, b%curvature)
        if (status /= status_ok) return
        ! then R itself at full precision, on the same bracket; with f(R) = g(log R)
        ! the curvature |f''/2f'| = |g'' - g'|/(2 |g'| R) <= (2 |g''/2g'| + 1)/(2R)
        fun%unknown = unknown_r
        b%lo = exp(log_lo)
        b%hi = b%half
        b%f_lo = -1.0_qp
        b%f_hi = b%f_half
        b%x0 = exp(x)
        if (b%curvature > 0.0_qp) b%curvature = (2.0_qp*b%curvature + 1.0_qp)/(2.0_qp*b%x0)
    end subroutine log_phase

    !> Newton on the hardware rules to about 1e-17, which also measures the curvature of
    !! Upsilon - psi: the full-precision phase then usually needs one step. status:
    !! status_ok or an evaluation's status.
    pure subroutine hardware_phase(fun, model, b, steps, status)
        type(upsilon_problem), intent(inout) :: fun  !! the function
        type(inverse_square_model), intent(in) :: model !! the evaluator
        type(root_bracket), intent(inout) :: b       !! bracket; x0 becomes the root
        integer, intent(inout) :: steps              !! evaluations made
        integer, intent(out) :: status               !! the phase's status
        real(qp) :: x
        integer :: used
        x = b%x0
        fun%level = level_hardware
        call newton_upsilon(fun, model, b%lo, b%f_lo, b%hi, b%f_hi, x, hardware_tolerance, &
                            0.0_qp, b%x0, used, status, b%curvature, hardware_accuracy)
        steps = steps + used
        call accept_phase(status, b%curvature)
    end subroutine hardware_phase

    !> The verdict on an early phase: its root is only a start for the full-precision
    !! phase, so a phase that ran out of steps (status_no_convergence, its last iterate
    !! still inside the bracket) is accepted without its curvature (final_step then
    !! certifies nothing and Newton goes on); an evaluation's failure stays a failure.
    pure subroutine accept_phase(status, curvature)
        integer, intent(inout) :: status      !! the phase's status
        real(qp), intent(inout) :: curvature  !! its measured curvature
        if (status == status_no_convergence) then
            status = status_ok
            curvature = 0.0_qp
        end if
    end subroutine accept_phase

    !> The full-precision step, when one suffices: one evaluation at x0 on the full rules,
    !! with s and t there and the slopes of Upsilon and s. The Newton step dx from x0 is
    !! accepted when it stays in the bracket, the curvature measured on the 19-digit
    !! phase certifies it (error about K dx^2 below the tolerance), and it is so short
    !! (|dx| <= 1e-17 of the bracket) that s is linear over it to far below rounding.
    !! The slopes of Upsilon and s enter only through dx, so they are summed in hardware
    !! precision (level_final, about a third less binary128 work); their error bounds
    !! are part of the certification (the step error |dx| err(f')/|f'| and err(s') |dx|
    !! must stay below the tolerance and a rounding of s).
    !! Then the root and s, t there need no further evaluation:
    !! - s(x0 + dx) = s(x0) + s'(x0) dx;
    !! - t by Hamilton-Jacobi: along the extremals from A at fixed rho, dt/dpsi = K, the
    !!   conserved r^2 dtheta/ds / v = sqrt(R^3/(2(1-R))); so t(x0 + dx) = t(x0) +
    !!   K(R(x0 + dx/2)) (psi - Upsilon(x0)), exact to O(dx^3).
    !! Otherwise `done` is false and x0 becomes the Newton step's point if that is in
    !! the bracket, for the caller to iterate on.
    pure subroutine final_step(fun, model, lo, hi, x0, curvature, solution, done)
        type(upsilon_problem), intent(in) :: fun
        type(inverse_square_model), intent(in) :: model
        real(qp), intent(in) :: lo, hi, curvature
        real(qp), intent(inout) :: x0
        type(endpoint_solution), intent(inout) :: solution
        logical, intent(out) :: done
        type(arch_values) :: values
        real(qp) :: big_r, d, f, df, ds, dx, x, start, tolerance, mid_r, mid_d, conserved
        real(qp) :: slope_error
        logical :: inside

        done = .false.
        start = x0
        call fun%radius_of(start, big_r, d, inside)
        if (.not. inside) return
        ! full rules; the slopes (used only for a step below 1e-17) in hardware precision
        values = evaluate_arch(model, level_final, fun%second, fun%rho, big_r, d, &
                               .true., .true.)
        solution%steps = solution%steps + 1
        f = values%angle - fun%psi
        df = fun%slope_in_unknown(start, big_r, d, values%angle_dr_smooth, &
                                  values%boundary_sign*values%boundary)
        dx = -f/df
        x = start + dx
        tolerance = 4.0_qp*eps_qp*abs(x) + tiny(1.0_qp)
        if (.not. (ieee_is_finite(x) .and. x > lo .and. x < hi)) return
        x0 = x
        if (abs(dx) > 1.0e-17_qp*(hi - lo)) return
        ! certified: below the tolerance, or a known curvature K with K dx^2, plus the
        ! part of dx that the slope's error bound moves, below it
        slope_error = abs(dx*fun%slope_in_unknown(start, big_r, d, values%angle_dr_error, &
                                                   0.0_qp)/df)
        if (abs(dx) > tolerance .and. (curvature <= 0.0_qp .or. &
            4.0_qp*curvature*dx*dx + slope_error > tolerance)) return
        ds = fun%slope_in_unknown(start, big_r, d, values%arclength_dr_smooth, &
                                  values%boundary_sign*values%arclength_boundary)
        ! s(x0) + s'(x0) dx: the error of s' moves s by below a rounding
        if (abs(dx*fun%slope_in_unknown(start, big_r, d, values%arclength_dr_error, &
                                        0.0_qp)) > eps_qp*abs(values%arclength)) return
        call fun%radius_of(start + 0.5_qp*dx, mid_r, mid_d, inside)
        conserved = sqrt(mid_r**3/(2.0_qp*((1.0_qp - fun%rho) + mid_d)))
        call fun%radius_of(x, big_r, d, inside)
        if (.not. inside) return
        solution%apse_radius = big_r
        solution%apse_gap = d
        solution%arclength = values%arclength + ds*dx
        solution%time = values%time - conserved*f
        solution%has_apse_radius = .true.
        solution%has_arclength = .true.
        solution%has_time = .true.
        solution%status = status_ok
        done = .true.
    end subroutine final_step

    !> First iterate on [0, h]: the root of the cubic Hermite interpolant of F from
    !! F(0) = f0, F'(0) = slope0, F(h) = fh, F'(h) = slope_h, found by Newton's method on
    !! the cubic kept inside the bracket (F(0), F(h) have opposite signs); regula falsi
    !! if that fails. Exact for rho = 1, where F(u) = pi u^2 - psi + O(u^4). Only a
    !! start to 1e-12: in hardware precision where that has quad's exponent range.
    pure function hermite_start(f0, slope0, h, fh, slope_h) result(x)
        real(qp), intent(in) :: f0, slope0, h, fh, slope_h
        real(qp) :: x
        integer, parameter :: wk = merge(xp, qp, range(1.0_xp) >= range(1.0_qp))
        real(wk) :: c2, c3, delta, delta_slope, lo, hi, p, dp, step, y, a0, a1, width
        integer :: iteration
        a0 = real(f0, wk)
        a1 = real(slope0, wk)
        width = real(h, wk)
        y = width*a0/(a0 - real(fh, wk))
        delta = real(fh, wk) - a0 - a1*width
        delta_slope = real(slope_h, wk) - a1
        c3 = (delta_slope*width - 2.0_wk*delta)/width**3
        c2 = (3.0_wk*delta - delta_slope*width)/width**2
        lo = 0.0_wk
        hi = width
        do iteration = 1, 60
            p = a0 + y*(a1 + y*(c2 + y*c3))
            if ((p < 0.0_wk) .eqv. (a0 < 0.0_wk)) then
                lo = y
            else
                hi = y
            end if
            dp = a1 + y*(2.0_wk*c2 + 3.0_wk*y*c3)
            step = p/dp
            if (.not. (y - step > lo .and. y - step < hi)) step = y - 0.5_wk*(lo + hi)
            y = y - step
            if (abs(step) <= 1.0e-12_wk*width) exit
        end do
        x = real(y, qp)
    end function hermite_start

    !> The second half-arch next to the sector's edge (2 pi/3 - psi = D below
    !! edge_resolution psi): Newton steps in y = log R on F = log(D(R)/D), D(R) = 2 pi/3 -
    !! Upsilon(R) ~ c R + C (R/rho)^(3/2) (F nearly linear in y), on the full rules, from
    !! R = D/c (c = -dUpsilon/dR at 0: D(R) >= c R, so above the root), until F is at the
    !! rounding of Upsilon (8 eps psi/D: R-bar's conditioning at the edge) or the step
    !! below 4 eps. R is returned in x. status_ok, status_no_convergence, or an
    !! evaluation's status.
    pure subroutine edge_newton(fun, model, b, x, steps, status)
        type(upsilon_problem), intent(inout) :: fun  !! the function (unknown R)
        type(inverse_square_model), intent(in) :: model !! the evaluator
        type(root_bracket), intent(in) :: b          !! f_lo = D, hi = rho/2
        real(qp), intent(out) :: x                   !! R-bar
        integer, intent(inout) :: steps              !! evaluations made
        integer, intent(out) :: status               !! the phase's status
        real(qp) :: y, f, df, deficit, big_f, slope, dy, y_hi
        integer :: k
        fun%level = level_fine
        x = b%f_lo/abs(2.0_qp*model%apse_slope_at_zero)
        y_hi = log(b%hi)
        y = min(log(x), y_hi)
        status = status_no_convergence
        do k = 1, max_edge_steps
            x = exp(y)
            call upsilon_at(fun, model, x, f, df, status)
            steps = steps + 1
            if (status /= status_ok) return
            deficit = b%f_lo - f
            if (.not. (deficit > 0.0_qp .and. df < 0.0_qp)) exit
            big_f = log(deficit/b%f_lo)
            status = status_ok
            if (abs(big_f) <= 8.0_qp*eps_qp*fun%psi/b%f_lo) return
            slope = -x*df/deficit
            dy = -big_f/slope
            y = min(max(y + dy, lowest_log_r), y_hi)
            if (abs(dy) <= 4.0_qp*eps_qp) then
                x = exp(y)
                return
            end if
        end do
        status = status_no_convergence
    end subroutine edge_newton

    !> The first half-arch when R-bar is below the smallest normal binary128 number:
    !! R-bar = 0 and s, t at their limits R -> 0, the radial fall 1 - rho and t0(rho)
    !! (they differ from them by O(R) relative, below 1e-4900).
    pure subroutine below_range(solution)
        type(endpoint_solution), intent(inout) :: solution
        solution%apse_radius = 0.0_qp
        solution%apse_gap = solution%rho
        solution%arclength = 1.0_qp - solution%rho
        solution%time = radial_time(solution%rho)
        solution%has_apse_radius = .true.
        solution%has_arclength = .true.
        solution%has_time = .true.
        solution%status = status_ok
    end subroutine below_range

    !> Arclength and time at B once R-bar is known.
    pure subroutine finish(model, solution, second, big_r, d)
        type(inverse_square_model), intent(in) :: model
        type(endpoint_solution), intent(inout) :: solution
        logical, intent(in) :: second
        real(qp), intent(in) :: big_r, d
        type(arch_values) :: values
        values = evaluate_arch(model, level_fine, second, solution%rho, big_r, d, &
                                     .false., .true.)
        solution%apse_radius = big_r
        solution%apse_gap = d
        solution%arclength = values%arclength
        solution%time = values%time
        solution%has_apse_radius = .true.
        solution%has_arclength = .true.
        solution%has_time = .true.
        solution%status = status_ok
    end subroutine finish

    !> The paper's method (sec. 5.1): secant iteration on Upsilon(R) = psi from the
    !! estimates R0, R1, stopping when |R_n - R_(n-1)| < tol (the paper: 1e-16).
    !! `steps` counts the secant steps. An iterate outside 0 < R <= rho ends the run with
    !! status_outside_domain (Theta(rho,R) does not exist there).
    pure function solve_endpoint_secant(model, rho, psi, r0, r1, tol) result(solution)
        type(inverse_square_model), intent(in) :: model !! the evaluator
        real(qp), intent(in) :: rho       !! endpoint radius
        real(qp), intent(in) :: psi       !! endpoint angle
        real(qp), intent(in) :: r0, r1    !! initial estimates of R-bar
        real(qp), intent(in) :: tol       !! stopping tolerance on |R_n - R_(n-1)|
        type(endpoint_solution) :: solution
        type(upsilon_function) :: fun
        real(qp) :: apse_angle_rho, x
        integer :: steps, status
        logical :: done

        call classify(model, rho, psi, solution, apse_angle_rho, done)
        if (done) return
        fun = upsilon_function(problem=upsilon_problem(level=level_fine, &
                               second=solution%arch /= arch_first, unknown=unknown_r, &
                               rho=rho, psi=psi), model=model)
        call secant(fun, r0, r1, tol, 0.0_qp, rho, max_steps, x, steps, status)
        solution%steps = steps
        if (status /= status_ok) then
            solution%status = status
            return
        end if
        call finish(model, solution, fun%problem%second, x, rho - x)
    end function solve_endpoint_secant

end module brachistochrone_two_point
