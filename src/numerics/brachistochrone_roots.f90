!> Root finders for a scalar function given as an extensible derived type.
!!
!! - `newton_bracketed`: Newton's method kept inside a bracket [lo, hi] on which f
!!   changes sign; a step that leaves the bracket, or that does not at least halve |f|'s
!!   predicted progress, is replaced by bisection (after Numerical Recipes' rtsafe). It
!!   stops when the predicted error of the last iterate is below the tolerance: with
!!   quadratic convergence the error after a step dx_k is about |dx_k|^2 |dx_k| /
!!   |dx_{k-1}|^2, which saves the confirming evaluation a plain |dx| test needs.
!!   The same iteration driven by the caller (`newton_begin`, then `newton_advance` with
!!   each f, f'), for a function that cannot be a root_function without copying data.
!! - `bracketed_secant`: regula falsi with the Anderson-Bjorck correction, for functions
!!   without a derivative: superlinear, and never leaves the bracket.
!! - `secant`: the paper's secant method (Tee 1998, sec. 5.1) with its stopping rule
!!   |x_n - x_(n-1)| < tol and a count of the steps, for reproducing Table 1.
module brachistochrone_roots
    use brachistochrone_kinds, only: qp
    use brachistochrone_status, only: status_ok, status_no_convergence, &
                                      status_outside_domain, status_bad_estimates
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    public :: root_function, newton_bracketed, bracketed_secant, secant, &
              anderson_bjorck_update, newton_iteration, newton_begin, newton_advance

    !> A scalar function f(x) with derivative; extend it to carry the problem's data.
    type, abstract :: root_function
    contains
        procedure(evaluate_interface), deferred :: evaluate
    end type root_function

    !> A `newton_bracketed` run driven by its caller (`newton_begin`, `newton_advance`).
    type :: newton_iteration
        real(qp) :: x = 0.0_qp        !! the point to evaluate next; when done, the root
        integer :: steps = 0          !! evaluations made
        integer :: status = status_no_convergence !! when done: the run's status
        logical :: done = .false.     !! the run has ended
        real(qp) :: curvature = 0.0_qp !! the curvature bound (newton_bracketed's)
        real(qp) :: a = 0.0_qp, b = 0.0_qp           !! the bracket
        real(qp) :: rel_tol = 0.0_qp, abs_tol = 0.0_qp !! the tolerances
        real(qp) :: noise = 0.0_qp    !! accuracy of the evaluations
        real(qp) :: known_k = 0.0_qp  !! the curvature usable for stopping
        real(qp) :: dx_previous = huge(1.0_qp) !! the last step
        real(qp) :: x_previous = 0.0_qp, df_previous = 0.0_qp !! the last point and f'
        integer :: max_steps = 0      !! limit on evaluations
        logical :: increasing = .true.       !! f increases across the bracket
        logical :: previous_newton = .false. !! the last step was Newton's
        logical :: measure = .false.  !! the curvature is measured (present in the call)
    end type newton_iteration

    abstract interface
        !> f(x) and f'(x); status /= 0 where f is undefined at x.
        pure subroutine evaluate_interface(self, x, f, df, status)
            import :: root_function, qp
            class(root_function), intent(in) :: self
            real(qp), intent(in) :: x
            real(qp), intent(out) :: f, df
            integer, intent(out) :: status
        end subroutine evaluate_interface
    end interface

contains

    !> Safeguarded Newton iteration for f(x) = 0 on a bracket.
    !!
    !! Needs f(lo) and f(hi) of opposite signs (or one of them zero); only their signs are
    !! used. Converged when the predicted error is <= rel_tol*|x| + abs_tol. (The loop
    !! over `newton_begin` and `newton_advance`, for a caller that evaluates f itself.)
    pure subroutine newton_bracketed(fun, lo, f_lo, hi, f_hi, x0, rel_tol, abs_tol, &
                                     max_steps, x, steps, status, curvature, accuracy)
        class(root_function), intent(in) :: fun !! the function
        real(qp), intent(in) :: lo, hi          !! bracket, lo < hi
        real(qp), intent(in) :: f_lo, f_hi      !! f at the bracket ends (signs only)
        real(qp), intent(in) :: x0              !! first iterate (clipped into the bracket)
        real(qp), intent(in) :: rel_tol         !! relative tolerance on x
        real(qp), intent(in) :: abs_tol         !! absolute tolerance on x
        integer, intent(in) :: max_steps        !! limit on evaluations of f
        real(qp), intent(out) :: x              !! the root
        integer, intent(out) :: steps           !! evaluations of f made
        integer, intent(out) :: status          !! status_ok, status_no_convergence, ...
        !> In: a bound on K = |f''/(2f')| near the root, measured by an earlier run on a
        !! nearby function (0 if unknown); then one Newton step dx leaves an error of
        !! about K dx^2 and the run may stop after it. Out: the largest K known, including
        !! what this run measured well above the noise: from consecutive Newton steps
        !! (|dx_k|/|dx_(k-1)|^2), and from the derivatives at consecutive points
        !! (|f'_k - f'_(k-1)|/(2 |f'_k| |x_k - x_(k-1)|), a secant estimate of f''/2f').
        real(qp), intent(inout), optional :: curvature
        !> Relative accuracy of the evaluations of f, in units of x (default rel_tol):
        !! K is measured only from steps 1000 times larger.
        real(qp), intent(in), optional :: accuracy
        type(newton_iteration) :: run
        real(qp) :: fx, dfx
        integer :: evaluation_status
        call newton_begin(run, lo, f_lo, hi, f_hi, x0, rel_tol, abs_tol, max_steps, &
                          curvature, accuracy)
        do while (.not. run%done)
            call fun%evaluate(run%x, fx, dfx, evaluation_status)
            call newton_advance(run, fx, dfx, evaluation_status)
        end do
        x = run%x
        steps = run%steps
        status = run%status
        if (present(curvature)) curvature = run%curvature
    end subroutine newton_bracketed

    !> Start a `newton_bracketed` run driven by the caller: then, while .not. run%done,
    !! evaluate f and f' at run%x and pass them to `newton_advance`. The arguments are
    !! newton_bracketed's (curvature: its value in).
    pure subroutine newton_begin(run, lo, f_lo, hi, f_hi, x0, rel_tol, abs_tol, max_steps, &
                                 curvature, accuracy)
        type(newton_iteration), intent(out) :: run !! the run, at its first iterate
        real(qp), intent(in) :: lo, hi, f_lo, f_hi, x0, rel_tol, abs_tol
        integer, intent(in) :: max_steps
        real(qp), intent(in), optional :: curvature, accuracy
        run%a = lo
        run%b = hi
        run%increasing = f_lo < 0.0_qp .or. f_hi > 0.0_qp
        run%x = min(max(x0, run%a), run%b)
        if (.not. ieee_is_finite(run%x)) run%x = 0.5_qp*(run%a + run%b)
        run%rel_tol = rel_tol
        run%abs_tol = abs_tol
        run%max_steps = max_steps
        run%measure = present(curvature)
        if (present(curvature)) then
            run%curvature = curvature
            run%known_k = max(curvature, 0.0_qp)
        end if
        run%noise = rel_tol
        if (present(accuracy)) run%noise = accuracy
        run%done = run%steps >= max_steps
    end subroutine newton_begin

    !> One step of a `newton_begin` run, from f and f' at run%x (and the status of that
    !! evaluation): sets run%done, or the next run%x. When done, run%x is the root,
    !! run%status status_ok, status_no_convergence or the evaluation's failure.
    pure subroutine newton_advance(run, fx, dfx, evaluation_status)
        type(newton_iteration), intent(inout) :: run !! the run
        real(qp), intent(in) :: fx, dfx              !! f, f' at run%x
        integer, intent(in) :: evaluation_status     !! status of that evaluation
        real(qp) :: x, dx, x_new, tolerance, predicted
        logical :: newton_step
        run%steps = run%steps + 1
        run%status = evaluation_status
        run%done = .true.
        if (evaluation_status /= status_ok) return
        if (fx == 0.0_qp) return
        x = run%x
        if (run%measure .and. run%steps > 1) then
            if (abs(dfx - run%df_previous) > 1.0e3_qp*run%noise*abs(dfx) .and. &
                x /= run%x_previous) then
                run%curvature = max(run%curvature, abs(dfx - run%df_previous) &
                                                   /(2.0_qp*abs(dfx)*abs(x - run%x_previous)))
                run%known_k = run%curvature
            end if
        end if
        run%x_previous = x
        run%df_previous = dfx
        ! shrink the bracket
        if ((fx < 0.0_qp) .eqv. run%increasing) then
            run%a = x
        else
            run%b = x
        end if
        x_new = x - fx/dfx
        tolerance = run%rel_tol*abs(x) + run%abs_tol
        ! a Newton correction below the tolerance ends the iteration, even where
        ! rounding puts x_new on the bracket end just moved to x
        if (ieee_is_finite(x_new) .and. abs(x_new - x) <= tolerance) then
            run%x = x_new
            return
        end if
        ! otherwise bisect when the Newton step leaves the bracket
        newton_step = ieee_is_finite(x_new) .and. x_new > run%a .and. x_new < run%b
        if (.not. newton_step) x_new = 0.5_qp*(run%a + run%b)
        dx = x_new - x
        run%x = x_new
        tolerance = run%rel_tol*abs(x_new) + run%abs_tol
        if (run%b - run%a <= tolerance) return
        ! two Newton steps in a row converging quadratically: the error of x is
        ! about |dx|^3/|dx_previous|^2, so the confirming evaluation can be skipped
        if (newton_step .and. run%previous_newton .and. &
            abs(dx) <= 1.0e-4_qp*abs(run%dx_previous)) then
            predicted = abs(dx)*(abs(dx)/abs(run%dx_previous))**2
            if (predicted <= tolerance) return
        end if
        ! with the curvature known from an earlier run: error about K dx^2 (x4 margin)
        if (newton_step .and. run%known_k > 0.0_qp) then
            if (4.0_qp*run%known_k*dx*dx <= tolerance) return
        end if
        ! measure K = |dx|/|dx_previous|^2 while the steps are far above the noise
        if (run%measure .and. newton_step .and. run%previous_newton .and. &
            abs(dx) > 1.0e3_qp*run%noise*abs(x_new)) then
            run%curvature = max(run%curvature, abs(dx)/run%dx_previous**2)
            run%known_k = run%curvature
        end if
        run%dx_previous = dx
        run%previous_newton = newton_step
        run%status = status_no_convergence
        run%done = run%steps >= run%max_steps
    end subroutine newton_advance

    !> Root of f on [lo, hi] (f(lo), f(hi) of opposite signs) by regula falsi with the
    !! Anderson-Bjorck correction; f's derivative is not used. Stops when the bracket
    !! is narrower than rel_tol*|x| + abs_tol or f(x) = 0.
    pure subroutine bracketed_secant(fun, lo, f_lo, hi, f_hi, rel_tol, abs_tol, max_steps, &
                                     x, steps, status)
        class(root_function), intent(in) :: fun !! the function
        real(qp), intent(in) :: lo, hi          !! bracket
        real(qp), intent(in) :: f_lo, f_hi      !! f at the bracket ends
        real(qp), intent(in) :: rel_tol         !! relative tolerance on x
        real(qp), intent(in) :: abs_tol         !! absolute tolerance on x
        integer, intent(in) :: max_steps        !! limit on evaluations of f
        real(qp), intent(out) :: x              !! the root
        integer, intent(out) :: steps           !! evaluations of f made
        integer, intent(out) :: status          !! status_ok or the reason
        real(qp) :: a, b, fa, fb, fx, dfx
        integer :: side
        a = lo
        b = hi
        fa = f_lo
        fb = f_hi
        steps = 0
        side = 0
        x = a
        status = status_ok
        if (fa == 0.0_qp) return
        x = b
        if (fb == 0.0_qp) return
        status = status_no_convergence
        do while (steps < max_steps)
            x = (a*fb - b*fa)/(fb - fa)
            if (.not. (x > min(a, b) .and. x < max(a, b))) x = 0.5_qp*(a + b)
            call fun%evaluate(x, fx, dfx, status)
            steps = steps + 1
            if (status /= status_ok) return
            if (fx == 0.0_qp) return
            call anderson_bjorck_update(x, fx, a, fa, b, fb, side)
            if (abs(b - a) <= rel_tol*abs(x) + abs_tol) then
                status = status_ok
                return
            end if
            status = status_no_convergence
        end do
    end subroutine bracketed_secant

    !> The secant method from x0, x1, stopping when |x_n - x_(n-1)| < tol.
    !!
    !! `steps` counts the new iterates x_2, x_3, ... computed. Iterates must stay in
    !! [domain_lo, domain_hi] (f is evaluated only there); leaving it ends the iteration
    !! with status_outside_domain and x the last iterate inside.
    pure subroutine secant(fun, x0, x1, tol, domain_lo, domain_hi, max_steps, x, steps, &
                           status)
        class(root_function), intent(in) :: fun   !! the function (its df is not used)
        real(qp), intent(in) :: x0, x1            !! the two initial estimates
        real(qp), intent(in) :: tol               !! stop when |x_n - x_(n-1)| < tol
        real(qp), intent(in) :: domain_lo, domain_hi !! where f may be evaluated
        integer, intent(in) :: max_steps          !! limit on steps
        real(qp), intent(out) :: x                !! last iterate
        integer, intent(out) :: steps             !! number of secant steps
        integer, intent(out) :: status            !! status_ok or the reason
        real(qp) :: x_previous, f_previous, fx, dfx, x_new

        steps = 0
        x = x1
        if (x0 == x1 .or. min(x0, x1) < domain_lo .or. max(x0, x1) > domain_hi &
            .or. .not. (ieee_is_finite(x0) .and. ieee_is_finite(x1))) then
            status = status_bad_estimates
            return
        end if
        x_previous = x0
        call fun%evaluate(x_previous, f_previous, dfx, status)
        if (status /= status_ok) return
        call fun%evaluate(x, fx, dfx, status)
        if (status /= status_ok) return
        status = status_no_convergence
        do while (steps < max_steps)
            if (fx == 0.0_qp) then
                status = status_ok
                return
            end if
            if (fx == f_previous) return
            x_new = x - fx*(x - x_previous)/(fx - f_previous)
            steps = steps + 1
            if (.not. ieee_is_finite(x_new) .or. x_new < domain_lo .or. x_new > domain_hi) then
                status = status_outside_domain
                return
            end if
            x_previous = x
            f_previous = fx
            x = x_new
            if (abs(x - x_previous) < tol) then
                status = status_ok
                return
            end if
            call fun%evaluate(x, fx, dfx, status)
            if (status /= status_ok) return
            status = status_no_convergence
        end do
    end subroutine secant


    !> One step of regula falsi with the Anderson-Bjorck correction on a bracket [a, b]
    !! (f(a), f(b) of opposite signs): the new point x replaces the end whose f has the
    !! sign of f(x); when the same end is replaced twice in a row, the other end's f is
    !! scaled by 1 - f(x)/f(replaced end) (by 1/2 when that is not positive).
    pure subroutine anderson_bjorck_update(x, fx, a, fa, b, fb, side)
        real(qp), intent(in) :: x, fx             !! the new point and f there
        real(qp), intent(inout) :: a, fa, b, fb   !! the bracket and f at its ends
        !> +1 when b was replaced last, -1 when a was, 0 before the first step
        integer, intent(inout) :: side
        real(qp) :: scale
        if ((fx > 0.0_qp) .eqv. (fb > 0.0_qp)) then
            if (side == 1) then
                scale = 1.0_qp - fx/fb
                fa = fa*merge(scale, 0.5_qp, scale > 0.0_qp)
            end if
            b = x
            fb = fx
            side = 1
        else
            if (side == -1) then
                scale = 1.0_qp - fx/fa
                fb = fb*merge(scale, 0.5_qp, scale > 0.0_qp)
            end if
            a = x
            fa = fx
            side = -1
        end if
    end subroutine anderson_bjorck_update

end module brachistochrone_roots
