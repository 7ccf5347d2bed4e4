!> Root finders for a scalar function given as an extensible derived type.
!!
!! - `newton_bracketed`: Newton's method kept inside a bracket [lo, hi] on which f
!!   changes sign; a step that leaves the bracket, or that does not at least halve |f|'s
!!   predicted progress, is replaced by bisection (after Numerical Recipes' rtsafe). It
!!   stops when the predicted error of the last iterate is below the tolerance: with
!!   quadratic convergence the error after a step dx_k is about |dx_k|^2 |dx_k| /
!!   |dx_{k-1}|^2, which saves the confirming evaluation a plain |dx| test needs.
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
              anderson_bjorck_update

    !> A scalar function f(x) with derivative; extend it to carry the problem's data.
    type, abstract :: root_function
    contains
        procedure(evaluate_interface), deferred :: evaluate
    end type root_function

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
    !! used. Converged when the predicted error is <= rel_tol*|x| + abs_tol.
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
        real(qp) :: a, b, fx, dfx, dx, dx_previous, x_new, tolerance, predicted, known_k
        real(qp) :: noise, x_previous, df_previous
        logical :: increasing, newton_step, previous_newton

        steps = 0
        a = lo
        b = hi
        increasing = f_lo < 0.0_qp .or. f_hi > 0.0_qp
        x = min(max(x0, a), b)
        if (.not. ieee_is_finite(x)) x = 0.5_qp*(a + b)
        dx_previous = huge(1.0_qp)
        previous_newton = .false.
        known_k = 0.0_qp
        if (present(curvature)) known_k = max(curvature, 0.0_qp)
        noise = rel_tol
        if (present(accuracy)) noise = accuracy
        status = status_no_convergence
        do while (steps < max_steps)
            call fun%evaluate(x, fx, dfx, status)
            steps = steps + 1
            if (status /= status_ok) return
            if (fx == 0.0_qp) return
            if (present(curvature) .and. steps > 1) then
                if (abs(dfx - df_previous) > 1.0e3_qp*noise*abs(dfx) .and. &
                    x /= x_previous) then
                    curvature = max(curvature, abs(dfx - df_previous) &
                                               /(2.0_qp*abs(dfx)*abs(x - x_previous)))
                    known_k = curvature
                end if
            end if
            x_previous = x
            df_previous = dfx
            ! shrink the bracket
            if ((fx < 0.0_qp) .eqv. increasing) then
                a = x
            else
                b = x
            end if
            x_new = x - fx/dfx
            tolerance = rel_tol*abs(x) + abs_tol
            ! a Newton correction below the tolerance ends the iteration, even where
            ! rounding puts x_new on the bracket end just moved to x
            if (ieee_is_finite(x_new) .and. abs(x_new - x) <= tolerance) then
                x = x_new
                status = status_ok
                return
            end if
            ! otherwise bisect when the Newton step leaves the bracket
            newton_step = ieee_is_finite(x_new) .and. x_new > a .and. x_new < b
            if (.not. newton_step) x_new = 0.5_qp*(a + b)
            dx = x_new - x
            x = x_new
            tolerance = rel_tol*abs(x) + abs_tol
            if (b - a <= tolerance) then
                status = status_ok
                return
            end if
            ! two Newton steps in a row converging quadratically: the error of x is
            ! about |dx|^3/|dx_previous|^2, so the confirming evaluation can be skipped
            if (newton_step .and. previous_newton .and. &
                abs(dx) <= 1.0e-4_qp*abs(dx_previous)) then
                predicted = abs(dx)*(abs(dx)/abs(dx_previous))**2
                if (predicted <= tolerance) then
                    status = status_ok
                    return
                end if
            end if
            ! with the curvature known from an earlier run: error about K dx^2 (x4 margin)
            if (newton_step .and. known_k > 0.0_qp) then
                if (4.0_qp*known_k*dx*dx <= tolerance) then
                    status = status_ok
                    return
                end if
            end if
            ! measure K = |dx|/|dx_previous|^2 while the steps are far above the noise
            if (present(curvature) .and. newton_step .and. previous_newton .and. &
                abs(dx) > 1.0e3_qp*noise*abs(x)) then
                curvature = max(curvature, abs(dx)/dx_previous**2)
                known_k = curvature
            end if
            dx_previous = dx
            previous_newton = newton_step
            status = status_no_convergence
        end do
    end subroutine newton_bracketed

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
