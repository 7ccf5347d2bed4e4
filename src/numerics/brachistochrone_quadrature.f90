!> Quadrature rules in quad precision, with error estimates.
!!
!! Choice of rules (measured on the brachistochrone integrands; see README "Numerics"):
!! - **Gauss-Legendre** with nodes and weights computed here to the last bit (correctly
!!   rounded in practice; see `legendre_root`). After the smoothing substitutions the
!!   integrands are analytic in a neighbourhood of the interval, and an n-point Gauss
!!   rule converges like rho^(-2n), where rho is the Bernstein ellipse reaching the
!!   nearest singularity: about 44 nodes give 34 digits on the worst half-arch, where
!!   Romberg would need tens of thousands of evaluations.
!! - **The trapezoid rule for even periodic integrands**: for a full period it converges
!!   geometrically with the width of the strip of analyticity (Trefethen & Weideman), and
!!   for an even integrand only half the nodes are distinct. Its nodes are nested: the
!!   rule on every second node is the half rule, so the error estimate is free.
!! - `integrate_adaptive`: globally safe bisection of Gauss-Legendre panels, estimate
!!   = |G(panel) - G(left half) - G(right half)|, which bounds the error of the coarser
!!   value and so over-states the error of the value returned. There is no precision
!!   floor: relative tolerances down to a few `epsilon(1.0_qp)` are honoured.
module brachistochrone_quadrature
    use brachistochrone_kinds, only: qp, pi, eps_qp
    use brachistochrone_status, only: status_ok, status_no_convergence, &
                                      status_invalid_argument
    use brachistochrone_double_quad, only: double_quad_number, two_sum, two_product, to_quad, &
                           operator(+), operator(-), operator(*), operator(/)
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
    !> Most Newton steps for one node of a Gauss-Legendre rule, in each precision (from
    !! Tricomi's estimate, n <= 96 needs at most three in quad and one compensated).
    integer, parameter :: max_newton_steps = 20

contains

    !> Gauss-Legendre rule with n nodes. Each node and weight is within 0.501 ulp of the
    !! exact value, so in practice its correct rounding (see `legendre_root`).
    pure function gauss_legendre(n) result(rule)
        integer, intent(in) :: n !! number of nodes, n >= 1
        type(gauss_legendre_rule) :: rule
        type(double_quad_number), allocatable :: ratio(:)
        integer :: i, k

        rule%n = max(n, 1)
        allocate (rule%node(rule%n), rule%weight(rule%n))
        ratio = [(double_quad_number(real(k - 1, qp), 0.0_qp)/k, k = 1, rule%n)]
        do i = 1, (rule%n + 1)/2
            call legendre_root(ratio, i, rule%node(rule%n + 1 - i), &
                               rule%weight(rule%n + 1 - i))
            rule%node(i) = -rule%node(rule%n + 1 - i)
            rule%weight(i) = rule%weight(rule%n + 1 - i)
        end do
    end function gauss_legendre

    !> The i-th largest root x of P_n and its weight w = 2/((1 - x^2) P_n'(x)^2).
    !!
    !! Newton's method in quad on the three-term recurrence finds the root to about an
    !! ulp, the limit in quad, where P_n near its root is rounding noise. But the weight
    !! formula magnifies the error d of a node: d[(1 - x^2) P_n'^2]/dx = 2 x P_n'^2 at a
    !! root (Legendre's equation), a relative change 2 x d/(1 - x^2) of the weight, 800
    !! ulps next to +-1 for n = 48; and P_n' from the quad recurrence carries a few ulps
    !! of rounding. So the last step evaluates P_n(x) and P_{n-1}(x) at the quad estimate
    !! x with an error of order n eps^2 (`legendre_compensated`). The Newton correction
    !! d = P_n/P_n' is then known to many more digits than the ulp, and with
    !! q = x P_n - P_{n-1} = -(1 - x^2) P_n'/n the weight at the root x - d is
    !!
    !!     w = 2 (1 - x^2)/(n q (n q + 2 x P_n)),
    !!
    !! that is 2/[(1 - x^2) P_n'^2 - 2 x P_n P_n'] at x: the second term cancels the
    !! first-order change with the node; the second-order one is below 1e-3 ulp
    !! (`settled`). The node x - d and the weight, evaluated in double-quad arithmetic,
    !! are each rounded to quad once, at the end.
    pure subroutine legendre_root(ratio, i, node, weight)
        !> (k - 1)/k for k = 1..n, n the degree
        type(double_quad_number), intent(in) :: ratio(:)
        integer, intent(in) :: i         !! which root, 1 = the largest, i <= (n + 1)/2
        real(qp), intent(out) :: node    !! the root x_i of P_n
        real(qp), intent(out) :: weight  !! its Gauss-Legendre weight
        type(double_quad_number) :: p, p_previous, q, one_minus_square
        real(qp) :: x, step, p_quad, dp_quad
        integer :: n, iteration

        n = size(ratio)
        if (2*i - 1 == n) then
            x = 0.0_qp        ! the middle root of an odd degree is exact
        else
            x = tricomi_estimate(n, i)
            do iteration = 1, max_newton_steps
                call legendre(ratio, x, p_quad, dp_quad)
                step = p_quad/dp_quad
                x = x - step
                ! Newton's error after this step: about step^2 |x|/(1 - x^2)
                if (settled(n, x, step*step*abs(x)/((1.0_qp - x)*(1.0_qp + x)))) exit
            end do
        end if
        do iteration = 1, max_newton_steps
            call legendre_compensated(ratio, x, p, p_previous)
            q = p*x - p_previous
            one_minus_square = two_sum(1.0_qp, -x)*two_sum(1.0_qp, x)
            step = -(p%hi*one_minus_square%hi)/(real(n, qp)*q%hi)
            if (settled(n, x, step)) exit
            x = x - step
        end do
        node = x - step
        q = q*n
        weight = to_quad((one_minus_square*2)/(q*(q + p*(2.0_qp*x))))
    end subroutine legendre_root

    !> Whether a point x off a root of P_n by `error` is close enough for the first-order
    !! corrections of `legendre_root`: ((n + 1) error)^2/(1 - x^2) <= eps/4096. The
    !! relative second-order terms, [n(n + 1) + 1 + 2 x^2/(1 - x^2)] error^2/(1 - x^2)
    !! for the weight and |x| error^2/(1 - x^2) for the node, are then below 4e-4 eps, as
    !! 2 x^2/(1 - x^2) < 0.35 (n + 1)^2 at every root (the limit for large n at the
    !! outermost root is 2 (n + 1)^2/j_0^2, j_0 = 2.405 the first zero of J_0).
    pure logical function settled(n, x, error)
        integer, intent(in) :: n      !! degree
        real(qp), intent(in) :: x     !! the point
        real(qp), intent(in) :: error !! its distance from the root (an estimate)
        settled = (real(n + 1, qp)*error)**2 <= eps_qp/4096.0_qp*((1.0_qp - x)*(1.0_qp + x))
    end function settled

    !> Tricomi's estimate of the i-th largest root of P_n, with error O(n^-5) inside the
    !! interval and about 2e-6 at the outermost roots for n = 48:
    !! (1 - (n - 1)/(8 n^3) - (39 - 28/sin^2 theta)/(384 n^4)) cos theta,
    !! theta = pi (4i - 1)/(4n + 2).
    pure function tricomi_estimate(n, i) result(x)
        integer, intent(in) :: n !! degree
        integer, intent(in) :: i !! which root, 1 = the largest
        real(qp) :: x
        real(qp) :: theta, degree
        degree = real(n, qp)
        theta = pi*real(4*i - 1, qp)/(4.0_qp*degree + 2.0_qp)
        x = (1.0_qp - (degree - 1.0_qp)/(8.0_qp*degree**3) &
             - (39.0_qp - 28.0_qp/sin(theta)**2)/(384.0_qp*degree**4))*cos(theta)
    end function tricomi_estimate

    !> P_n(x) and its derivative by the three-term recurrence in the form
    !! P_k = x P_{k-1} + ((k - 1)/k) (x P_{k-1} - P_{k-2}), n = size(ratio) >= 1.
    pure subroutine legendre(ratio, x, p, dp)
        type(double_quad_number), intent(in) :: ratio(:) !! (k - 1)/k, k = 1..n
        real(qp), intent(in) :: x                        !! the point, |x| < 1
        real(qp), intent(out) :: p                       !! P_n(x)
        real(qp), intent(out) :: dp                      !! P_n'(x)
        real(qp) :: p_previous, p_next, x_p
        integer :: k
        p_previous = 1.0_qp
        p = x
        do k = 2, size(ratio)
            x_p = x*p
            p_next = x_p + ratio(k)%hi*(x_p - p_previous)
            p_previous = p
            p = p_next
        end do
        dp = real(size(ratio), qp)*(x*p - p_previous)/((x - 1.0_qp)*(x + 1.0_qp))
    end subroutine legendre

    !> P_n(x) and P_{n-1}(x), n = size(ratio) >= 1, with an absolute error of order
    !! n eps^2 for |x| <= 1 (compensated recurrence). The recurrence of `legendre` runs in
    !! quad; two_product and two_sum recover the rounding error of each operation
    !! exactly, and a second, linear recurrence carries their effect forward, with the
    !! rounding of (k - 1)/k. About 14 times the work of `legendre`; the same recurrence
    !! in double-quad arithmetic throughout would take 1.6 times as long again.
    pure subroutine legendre_compensated(ratio, x, p, p_previous)
        type(double_quad_number), intent(in) :: ratio(:) !! (k - 1)/k, k = 1..n
        real(qp), intent(in) :: x                        !! the point
        type(double_quad_number), intent(out) :: p          !! P_n(x)
        type(double_quad_number), intent(out) :: p_previous !! P_{n-1}(x)
        type(double_quad_number) :: x_value, difference, increment, next
        real(qp) :: value, value_previous, error, error_previous, x_error, carried
        integer :: k
        ! P_k = value + error, where value is exactly what `legendre` computes
        value_previous = 1.0_qp
        value = x
        error_previous = 0.0_qp
        error = 0.0_qp
        do k = 2, size(ratio)
            x_value = two_product(x, value)
            x_error = x*error
            ! x P_{k-1} - P_{k-2} = difference%hi + carried
            difference = two_sum(x_value%hi, -value_previous)
            carried = difference%lo + ((x_value%lo + x_error) - error_previous)
            ! ratio (x P_{k-1} - P_{k-2}) = increment%hi + the rest of `error` below
            increment = two_product(ratio(k)%hi, difference%hi)
            next = two_sum(x_value%hi, increment%hi)
            value_previous = value
            error_previous = error
            value = next%hi
            error = next%lo + ((x_value%lo + x_error) + (increment%lo &
                    + (ratio(k)%hi*carried + ratio(k)%lo*difference%hi)))
        end do
        p = two_sum(value, error)
        p_previous = two_sum(value_previous, error_previous)
    end subroutine legendre_compensated

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

end module brachistochrone_quadrature
