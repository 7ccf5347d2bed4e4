!> Quadrature rules in quad precision, with error estimates.
!!
!! Choice of rules (measured on the brachistochrone integrands; see README "Numerics"):
!! - **Gauss-Legendre** with nodes computed here to full quad precision. After the
!!   smoothing substitutions the integrands are analytic in a neighbourhood of the
!!   interval, and an n-point Gauss rule converges like rho^(-2n), where rho is the
!!   Bernstein ellipse reaching the nearest singularity: about 44 nodes give 34 digits on
!!   the worst half-arch, where Romberg would need tens of thousands of evaluations.
!! - **The trapezoid rule for even periodic integrands**: for a full period it converges
!!   geometrically with the width of the strip of analyticity (Trefethen & Weideman), and
!!   for an even integrand only half the nodes are distinct. Its nodes are nested: the
!!   rule on every second node is the half rule, so the error estimate is free.
!! - `integrate_adaptive`: globally safe bisection of Gauss-Legendre panels, estimate
!!   = |G(panel) - G(left half) - G(right half)|, which bounds the error of the coarser
!!   value and so over-states the error of the value returned. There is no precision
!!   floor: relative tolerances down to a few `epsilon(1.0_qp)` are honoured.
module quadrature
    use brachistochrone_kinds, only: qp, pi, eps_qp
    use brachistochrone_status, only: status_ok, status_no_convergence, &
                                      status_invalid_argument
    implicit none
    private

    public :: gauss_legendre_rule, gauss_legendre
    public :: even_periodic_rule, even_periodic_trapezoid
    public :: univariate_integrand
    public :: integrate, integrate_adaptive

    !> An n-point Gauss-Legendre rule on [-1, 1]: nodes ascending, weights positive.
    type :: gauss_legendre_rule
        integer :: n = 0                      !! number of nodes
        real(qp), allocatable :: node(:)      !! nodes x_k in (-1, 1), ascending
        real(qp), allocatable :: weight(:)    !! weights w_k, summing to 2
    end type gauss_legendre_rule

    !> Trapezoid rule for int_0^pi g(theta) d theta with g even and 2 pi-periodic:
    !! nodes theta_k = pi k/m, k = 0..m, weights pi/m (halved at both ends).
    type :: even_periodic_rule
        integer :: m = 0                      !! number of intervals on [0, pi] (even)
        real(qp), allocatable :: angle(:)     !! theta_k, k = 0..m
        real(qp), allocatable :: weight(:)    !! trapezoid weights, k = 0..m
    end type even_periodic_rule

    !> A function of one real variable to be integrated; extend it to carry parameters.
    type, abstract :: univariate_integrand
    contains
        procedure(evaluate_interface), deferred :: evaluate
    end type univariate_integrand

    abstract interface
        !> Value of the integrand at x.
        pure function evaluate_interface(self, x) result(y)
            import :: univariate_integrand, qp
            class(univariate_integrand), intent(in) :: self
            real(qp), intent(in) :: x
            real(qp) :: y
        end function evaluate_interface
    end interface

    !> Most panels `integrate_adaptive` may evaluate for one integral.
    integer, parameter :: max_panels = 200000
    !> Deepest bisection level of `integrate_adaptive`. Refinement is local, so the work
    !! grows with the depth, not 2**depth: an integrand with structure on the scale 1e-30
    !! of the interval needs about 100 levels near it.
    integer, parameter :: max_depth = 120

contains

    !> Gauss-Legendre rule with n nodes, computed by Newton's method on the three-term
    !! recurrence of P_n in quad precision (nodes and weights accurate to a few ulps).
    pure function gauss_legendre(n) result(rule)
        integer, intent(in) :: n !! number of nodes, n >= 1
        type(gauss_legendre_rule) :: rule
        integer :: i, iteration
        real(qp) :: x, dx, p, dp

        rule%n = max(n, 1)
        allocate (rule%node(rule%n), rule%weight(rule%n))
        do i = 1, (rule%n + 1)/2
            ! Tricomi's estimate of the i-th largest root, then Newton to convergence.
            x = cos(pi*(real(i, qp) - 0.25_qp)/(real(rule%n, qp) + 0.5_qp))
            do iteration = 1, 100
                call legendre(rule%n, x, p, dp)
                dx = p/dp
                x = x - dx
                if (abs(dx) <= eps_qp) exit
            end do
            if (2*i - 1 == rule%n) x = 0.0_qp
            call legendre(rule%n, x, p, dp)
            rule%node(rule%n + 1 - i) = x
            rule%node(i) = -x
            ! 1 - x^2 as (1 - x)(1 + x): exact factors, where 1 - x*x would lose the digits
            ! of the nodes next to +-1 (whose weights it would bias)
            rule%weight(i) = 2.0_qp/(((1.0_qp - x)*(1.0_qp + x))*dp*dp)
            rule%weight(rule%n + 1 - i) = rule%weight(i)
        end do
    end function gauss_legendre

    !> P_n(x) and its derivative by the three-term recurrence.
    pure subroutine legendre(n, x, p, dp)
        integer, intent(in) :: n
        real(qp), intent(in) :: x
        real(qp), intent(out) :: p, dp
        real(qp) :: p_previous, p_next
        integer :: k
        p_previous = 1.0_qp
        p = x
        do k = 2, n
            p_next = (real(2*k - 1, qp)*x*p - real(k - 1, qp)*p_previous)/real(k, qp)
            p_previous = p
            p = p_next
        end do
        if (n == 0) then
            p = 1.0_qp
            dp = 0.0_qp
        else
            dp = real(n, qp)*(x*p - p_previous)/((x - 1.0_qp)*(x + 1.0_qp))
        end if
    end subroutine legendre

    !> Trapezoid rule with m intervals on [0, pi] for even 2 pi-periodic integrands.
    pure function even_periodic_trapezoid(m) result(rule)
        integer, intent(in) :: m !! number of intervals; rounded up to an even number >= 2
        type(even_periodic_rule) :: rule
        integer :: k
        rule%m = max(2, m + mod(m, 2))
        allocate (rule%angle(0:rule%m), rule%weight(0:rule%m))
        do k = 0, rule%m
            rule%angle(k) = pi*real(k, qp)/real(rule%m, qp)
            rule%weight(k) = pi/real(rule%m, qp)
        end do
        rule%weight(0) = 0.5_qp*rule%weight(0)
        rule%weight(rule%m) = 0.5_qp*rule%weight(rule%m)
    end function even_periodic_trapezoid

    !> Integral of f over [a, b] by one application of a Gauss-Legendre rule.
    pure function integrate(f, a, b, rule) result(value)
        class(univariate_integrand), intent(in) :: f !! integrand
        real(qp), intent(in) :: a                    !! lower limit
        real(qp), intent(in) :: b                    !! upper limit
        type(gauss_legendre_rule), intent(in) :: rule !! the rule
        real(qp) :: value
        real(qp) :: centre, half
        integer :: k
        centre = 0.5_qp*(a + b)
        half = 0.5_qp*(b - a)
        value = 0.0_qp
        do k = 1, rule%n
            value = value + rule%weight(k)*f%evaluate(centre + half*rule%node(k))
        end do
        value = half*value
    end function integrate

    !> Adaptive integral of f over [a, b] with an error estimate.
    !!
    !! Accepts a panel when |G(panel) - G(halves)| <= max(abs_tol, rel_tol*|I|) scaled
    !! to the panel's share of the interval; returns the sum of the halves.
    pure subroutine integrate_adaptive(f, a, b, rule, rel_tol, abs_tol, value, error, status)
        class(univariate_integrand), intent(in) :: f  !! integrand
        real(qp), intent(in) :: a                     !! lower limit
        real(qp), intent(in) :: b                     !! upper limit
        type(gauss_legendre_rule), intent(in) :: rule !! rule applied on each panel
        real(qp), intent(in) :: rel_tol               !! requested relative accuracy
        real(qp), intent(in) :: abs_tol               !! requested absolute accuracy
        real(qp), intent(out) :: value                !! estimate of the integral
        real(qp), intent(out) :: error                !! estimate of |value - integral|
        integer, intent(out) :: status                !! status_ok or status_no_convergence
        real(qp) :: whole, tolerance
        integer :: budget

        value = 0.0_qp
        error = 0.0_qp
        if (rule%n < 1 .or. rel_tol < 0.0_qp .or. abs_tol < 0.0_qp) then
            status = status_invalid_argument
            return
        end if
        status = status_ok
        if (a == b) return
        whole = integrate(f, a, b, rule)
        tolerance = max(abs_tol, rel_tol*abs(whole))
        budget = max_panels
        call bisect(a, b, whole, tolerance, 0, value, error, status, budget)

    contains

        !> Accept a panel when |G(panel) - G(halves)| is below its share of the tolerance,
        !! or below the rounding noise of the halves (100 eps of their magnitude: past that
        !! point bisection only chases noise); give up at max_depth or when the budget of
        !! panels is spent, so no input can make the work explode.
        pure recursive subroutine bisect(lo, hi, whole_panel, tol, depth, val, err, stat, &
                                         panels_left)
            real(qp), intent(in) :: lo, hi, whole_panel, tol
            integer, intent(in) :: depth
            real(qp), intent(out) :: val, err
            integer, intent(inout) :: stat
            integer, intent(inout) :: panels_left
            real(qp) :: middle, left, right, val_left, val_right, err_left, err_right
            middle = 0.5_qp*(lo + hi)
            left = integrate(f, lo, middle, rule)
            right = integrate(f, middle, hi, rule)
            panels_left = panels_left - 2
            val = left + right
            err = abs(whole_panel - val)
            if (err <= tol .or. err <= 100.0_qp*eps_qp*(abs(left) + abs(right))) return
            if (.not. (err == err)) then
                stat = status_invalid_argument     ! NaN: the integrand is not defined here
                return
            end if
            if (depth >= max_depth .or. panels_left <= 0 .or. middle <= lo .or. &
                middle >= hi) then
                stat = status_no_convergence
                return
            end if
            call bisect(lo, middle, left, 0.5_qp*tol, depth + 1, val_left, err_left, stat, &
                        panels_left)
            call bisect(middle, hi, right, 0.5_qp*tol, depth + 1, val_right, err_right, stat, &
                        panels_left)
            val = val_left + val_right
            err = err_left + err_right
        end subroutine bisect

    end subroutine integrate_adaptive

end module quadrature
