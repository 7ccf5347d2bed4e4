!> Uniform gravity: the cycloid as brachistochrone and isochrone, and the simple
!! pendulum for contrast (Tee 1998, section 1; Saitoh, eq. (1)).
!!
!! Gravity g points down. For the brachistochrone the start A is the origin, y is
!! measured DOWNWARD and x >= 0 horizontally. The curve of quickest descent from rest at
!! A to B = (x_B, y_B) is the cycloid with its cusp at A
!!
!!     x = a (phi - sin phi),   y = a (1 - cos phi) = 2 a sin^2(phi/2),
!!
!! traced by a circle of radius a rolling under the line y = 0. On it the speed is
!! v = sqrt(2 g y) = 2 sqrt(g a) sin(phi/2) and ds = 2 a sin(phi/2) d phi, so
!! dt = sqrt(a/g) d phi: t = phi sqrt(a/g) and s = 4 a (1 - cos(phi/2)) = 8 a sin^2(phi/4).
!!
!! For the isochrone (tautochrone) the height is measured UPWARD from the base of a
!! half-arch with rolling-circle radius alpha (Tee's eq. (1)); its heights are
!! 0 <= y <= 2 alpha. The time of descent from rest at height h is Tee's eq. (3)-(4),
!! pi sqrt(alpha/g) for every h.
!!
!! Every routine is `elemental`, checks its arguments and returns a status; on an error
!! all outputs are 0.
module brachistochrone_uniform_gravity
    use brachistochrone_kinds, only: qp, pi, eps_qp
    use brachistochrone_status, only: status_ok, status_not_finite, status_no_convergence, &
                                      status_above_start, status_parameter_out_of_range
    use brachistochrone_roots, only: root_function, newton_bracketed
    use brachistochrone_quadrature, only: univariate_integrand, gauss_legendre_rule, &
            gauss_legendre, integrate_adaptive
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_positive_inf
    implicit none
    private

    public :: uniform_brachistochrone, cycloid_point
    public :: isochrone_time, isochrone_time_quadrature
    public :: joined_arches_period, joined_arches_period_quadrature
    public :: complete_elliptic_k, pendulum_period, pendulum_period_quadrature

    !> 2 pi to working precision.
    real(qp), parameter :: two_pi = 2.0_qp*pi
    !> Largest argument for which phi - sin phi is summed as a series (see
    !! `cubic_remainder`); above it the direct difference loses less than one bit.
    real(qp), parameter :: series_limit = 2.0_qp
    !> Upper end of both brachistochrone brackets (phi in [0, 3.5] or 2 pi - phi in
    !! [0, 3.5]); each contains pi, where the two formulations meet, with a margin.
    real(qp), parameter :: bracket_end = 3.5_qp
    !> Relative tolerance of the Newton iterations on phi and 2 pi - phi.
    real(qp), parameter :: root_tolerance = 4.0_qp*eps_qp
    !> Limit on evaluations in each Newton iteration (about 6 are used).
    integer, parameter :: max_root_steps = 100
    !> Nodes of the Gauss-Legendre rule on each panel of the adaptive quadratures.
    integer, parameter :: quadrature_nodes = 20
    !> Relative tolerance of the adaptive quadratures.
    real(qp), parameter :: quadrature_tolerance = 4.0_qp*eps_qp

    !> (phi - sin phi)/(1 - cos phi) - x_B/y_B as a function of phi, for x_B <= (pi/2) y_B
    !! (then phi_B <= pi: B is on the descending half of the arch or at its bottom).
    type, extends(root_function) :: steep_equation
        real(qp) :: ratio = 0.0_qp !! x_B/y_B, in (0, pi/2]
    contains
        procedure :: evaluate => steep_evaluate
    end type steep_equation

    !> sqrt((1 - cos phi)/(phi - sin phi)) - sqrt(y_B/x_B) as a function of the deficit
    !! delta = 2 pi - phi, for x_B > (pi/2) y_B (phi_B > pi).
    type, extends(root_function) :: shallow_equation
        real(qp) :: root_ratio = 0.0_qp !! sqrt(y_B/x_B), in [0, sqrt(2/pi))
    contains
        procedure :: evaluate => shallow_evaluate
    end type shallow_equation

    !> Integrand of Tee's eq. (4) for the cycloid half-arch of radius alpha, after
    !! z = sin^2(theta): f'(y) sqrt(y) at y = h sin^2(theta), from the parametric form.
    type, extends(univariate_integrand) :: cycloid_integrand
        real(qp) :: alpha = 0.0_qp  !! rolling-circle radius
        real(qp) :: height = 0.0_qp !! release height h, 0 < h <= 2 alpha
    contains
        procedure :: evaluate => cycloid_integrand_evaluate
    end type cycloid_integrand

    !> Integrand of Tee's eq. (4) for the circle of radius L (the simple pendulum),
    !! after z = sin^2(theta), divided by sqrt(L/2), in u = pi/2 - theta:
    !! 1/sqrt(sin^2 u + k'^2 cos^2 u).
    type, extends(univariate_integrand) :: circle_integrand
        real(qp) :: complement = 1.0_qp !! k' = cos(theta0/2)
    contains
        procedure :: evaluate => circle_integrand_evaluate
    end type circle_integrand

contains

    ! ------------------------------------------------------------------------------------
    ! Cancellation-free pieces of the cycloid
    ! ------------------------------------------------------------------------------------

    !> (phi - sin phi)/phi^3 without cancellation: for |phi| <= 2 the alternating series
    !! sum_k (-1)^k phi^(2k)/(2k+3)! (its terms decrease from the first, 1/6, and the sum is
    !! at least 0.136, so it keeps full relative precision; at most 22 terms), above it the
    !! direct difference, which loses at most a factor 1/(1 - sin(2)/2) < 2 there.
    elemental function cubic_remainder(phi) result(value)
        real(qp), intent(in) :: phi
        real(qp) :: value
        real(qp) :: square, term
        integer :: k
        if (abs(phi) > series_limit) then
            value = (phi - sin(phi))/phi**3
            return
        end if
        square = phi*phi
        term = 1.0_qp/6.0_qp
        value = term
        k = 0
        do while (abs(term) > 0.25_qp*eps_qp*value .and. k < 40)
            k = k + 1
            term = -term*square/real((2*k + 2)*(2*k + 3), qp)
            value = value + term
        end do
    end function cubic_remainder

    !> phi - sin phi to full relative precision for every phi (phi^3 times
    !! `cubic_remainder` for |phi| <= 2).
    elemental function angle_minus_sine(phi) result(value)
        real(qp), intent(in) :: phi
        real(qp) :: value
        if (abs(phi) > series_limit) then
            value = phi - sin(phi)
        else
            value = phi*phi*phi*cubic_remainder(phi)
        end if
    end function angle_minus_sine

    !> sin(x)/x, 1 at x = 0.
    elemental function sinc(x) result(value)
        real(qp), intent(in) :: x
        real(qp) :: value
        if (x == 0.0_qp) then
            value = 1.0_qp
        else
            value = sin(x)/x
        end if
    end function sinc

    ! ------------------------------------------------------------------------------------
    ! 1. The brachistochrone through B
    ! ------------------------------------------------------------------------------------

    !> The brachistochrone from rest at A = (0, 0) to B = (x_B, y_B) under uniform gravity
    !! g (y downward): the cycloid x = a(phi - sin phi), y = a(1 - cos phi) with its cusp at
    !! A, reaching B at phi = phi_B in (0, 2 pi) where
    !!
    !!     (phi_B - sin phi_B)/(1 - cos phi_B) = x_B/y_B.
    !!
    !! The left side increases from 0 (phi -> 0) to infinity (phi -> 2 pi). It is solved by
    !! a bracketed Newton iteration in one of two unknowns, so that phi_B keeps its full
    !! relative precision at both ends and 2 pi - phi_B (`phi_deficit`) at the upper one:
    !!
    !! - x_B <= (pi/2) y_B (phi_B <= pi): unknown phi, equation
    !!   h(phi) = 2 phi R(phi)/sinc^2(phi/2) = x_B/y_B with R = (phi - sin phi)/phi^3 from
    !!   its series (no cancellation, no phi^3 to underflow) and 1 - cos phi written as
    !!   2 sin^2(phi/2) = (phi^2/2) sinc^2(phi/2). h(phi) = phi/3 (1 + phi^2/30 + ...), so
    !!   phi_B = 3 r - 9 r^3/10 + O(r^5) as r = x_B/y_B -> 0: a relative change of r moves
    !!   phi_B by the same relative amount (condition number 1), and the Newton iteration,
    !!   which starts from that expansion, gets phi_B to a few ulps however small r is.
    !! - x_B > (pi/2) y_B (phi_B > pi): unknown delta = 2 pi - phi, equation
    !!   m(delta) = sin(delta/2) sqrt(2/(2 pi - (delta - sin delta))) = sqrt(y_B)/sqrt(x_B),
    !!   the inverse square root of the same ratio. As y_B/x_B -> 0,
    !!   m = delta/(2 sqrt(pi)) (1 - delta^2/24 + O(delta^3)), linear in delta, so delta is
    !!   found to full relative precision: delta = 2 sqrt(pi w) (1 + pi w/6 + ...) with
    !!   w = y_B/x_B, and the ratio x_B/y_B itself, which may overflow, is never formed.
    !!
    !! Then a is formed from the better-conditioned coordinate, a = y_B/(2 sin^2(phi/2)) on
    !! the steep side and a = x_B/(phi - sin phi) on the shallow side, and
    !! t = phi sqrt(a/g) = sqrt(2 y_B/g)/sinc(phi/2) (steep) or (2 pi - delta) sqrt(a/g),
    !! s = 8 a sin^2(phi/4) = y_B/cos^2(phi/4) (steep) or 8 a cos^2(delta/4) (shallow).
    !!
    !! Special cases: x_B = 0 < y_B is free fall down the vertical (phi = 0,
    !! t = sqrt(2 y_B/g), s = y_B; the cycloid degenerates, a -> infinity, and `radius` is
    !! returned as 0, "does not exist"); B = A gives phi = a = t = s = 0; y_B = 0 < x_B is
    !! the complete arch (phi = 2 pi, a = x_B/(2 pi), t = 2 pi sqrt(a/g) = sqrt(2 pi x_B/g)
    !! as in Saitoh, s = 8 a; the particle arrives at rest). When x_B/y_B is so small that
    !! a ~ 2 y_B/phi_B^2 exceeds huge (below about 4e-2467 for y_B = 1), `radius` is
    !! +infinity while phi, t and s stay accurate.
    elemental subroutine uniform_brachistochrone(x_b, y_b, g, phi, radius, time, &
                                                 arclength, status, phi_deficit)
        real(qp), intent(in) :: x_b        !! horizontal distance of B from A, >= 0
        real(qp), intent(in) :: y_b        !! depth of B below A (y downward), >= 0
        real(qp), intent(in) :: g          !! gravitational acceleration, > 0
        real(qp), intent(out) :: phi       !! rolling angle phi_B at B, in [0, 2 pi]
        real(qp), intent(out) :: radius    !! rolling-circle radius a (0 for free fall)
        real(qp), intent(out) :: time      !! descent time t from A to B
        real(qp), intent(out) :: arclength !! arclength s from A to B
        !> status_ok, status_not_finite, status_parameter_out_of_range (g <= 0 or
        !! x_B < 0), status_above_start (y_B < 0), status_no_convergence (not expected)
        integer, intent(out) :: status
        !> 2 pi - phi_B to full relative precision (0 for the complete arch)
        real(qp), intent(out), optional :: phi_deficit
        real(qp) :: deficit

        phi = 0.0_qp
        radius = 0.0_qp
        time = 0.0_qp
        arclength = 0.0_qp
        deficit = 0.0_qp
        if (present(phi_deficit)) phi_deficit = 0.0_qp
        if (.not. (ieee_is_finite(x_b) .and. ieee_is_finite(y_b) .and. ieee_is_finite(g))) then
            status = status_not_finite
            return
        end if
        if (g <= 0.0_qp .or. x_b < 0.0_qp) then
            status = status_parameter_out_of_range
            return
        end if
        if (y_b < 0.0_qp) then
            status = status_above_start
            return
        end if
        status = status_ok

        if (x_b == 0.0_qp) then
            ! free fall down the vertical (or B = A): the limit phi -> 0
            deficit = two_pi
            time = sqrt(2.0_qp)*sqrt(y_b)/sqrt(g)
            arclength = y_b
        else if (y_b == 0.0_qp) then
            ! B level with A: the complete arch, arriving at rest
            phi = two_pi
            radius = x_b/two_pi
            time = two_pi*sqrt(radius)/sqrt(g)
            arclength = 8.0_qp*radius
        else if (x_b <= 0.5_qp*pi*y_b) then
            call steep_arch(x_b, y_b, g, phi, radius, time, arclength, deficit, status)
            if (status /= status_ok) return
        else
            call shallow_arch(x_b, y_b, g, phi, radius, time, arclength, deficit, status)
            if (status /= status_ok) return
        end if
        if (present(phi_deficit)) phi_deficit = deficit
    end subroutine uniform_brachistochrone

    !> B with x_B <= (pi/2) y_B: the unknown is phi in (0, pi], from the ratio
    !! r = x_B/y_B <= pi/2 (which cannot overflow). On failure the outputs stay as given.
    elemental subroutine steep_arch(x_b, y_b, g, phi, radius, time, arclength, deficit, &
                                    status)
        real(qp), intent(in) :: x_b, y_b, g
        real(qp), intent(inout) :: phi, radius, time, arclength, deficit
        integer, intent(out) :: status
        type(steep_equation) :: steep
        real(qp) :: first_guess, half
        integer :: steps
        status = status_ok
        steep%ratio = x_b/y_b
        if (steep%ratio > 0.0_qp) then
            first_guess = 3.0_qp*steep%ratio*(1.0_qp - 0.3_qp*steep%ratio**2)
            call newton_bracketed(steep, 0.0_qp, -1.0_qp, bracket_end, 1.0_qp, &
                                  first_guess, root_tolerance, 0.0_qp, max_root_steps, &
                                  phi, steps, status)
            if (status /= status_ok) then
                phi = 0.0_qp
                return
            end if
        end if
        deficit = two_pi - phi
        half = 0.5_qp*phi
        if (phi > 0.0_qp) then
            ! halved first: y_B near huge with phi near pi must not overflow
            radius = (0.5_qp*y_b/sin(half))/sin(half)
        else
            ! x_B/y_B underflowed: a is beyond the range of real(qp)
            radius = ieee_value(radius, ieee_positive_inf)
        end if
        time = sqrt(2.0_qp)*(sqrt(y_b)/sqrt(g))/sinc(half)
        arclength = y_b/cos(0.25_qp*phi)**2
    end subroutine steep_arch

    !> B with x_B > (pi/2) y_B: the unknown is the deficit delta = 2 pi - phi in
    !! [0, pi), from w = sqrt(y_B/x_B). On failure the outputs stay as given.
    elemental subroutine shallow_arch(x_b, y_b, g, phi, radius, time, arclength, deficit, &
                                      status)
        real(qp), intent(in) :: x_b, y_b, g
        real(qp), intent(inout) :: phi, radius, time, arclength, deficit
        integer, intent(out) :: status
        type(shallow_equation) :: shallow
        real(qp) :: first_guess
        integer :: steps
        shallow%root_ratio = sqrt(y_b)/sqrt(x_b)
        first_guess = 2.0_qp*sqrt(pi)*shallow%root_ratio* &
                      (1.0_qp + pi*shallow%root_ratio**2/6.0_qp)
        call newton_bracketed(shallow, 0.0_qp, -1.0_qp, bracket_end, 1.0_qp, &
                              first_guess, root_tolerance, 0.0_qp, max_root_steps, &
                              deficit, steps, status)
        if (status /= status_ok) then
            deficit = 0.0_qp
            return
        end if
        phi = two_pi - deficit
        radius = x_b/(two_pi - angle_minus_sine(deficit))
        time = phi*sqrt(radius)/sqrt(g)
        arclength = 8.0_qp*radius*cos(0.25_qp*deficit)**2
    end subroutine shallow_arch

    !> h(phi) - r and h'(phi) for the steep case: h = (phi - sin phi)/(1 - cos phi)
    !! = 2 phi R(phi)/sinc^2(phi/2) with R = (phi - sin phi)/phi^3, and
    !! h' = 1 - h cot(phi/2) = 1 - 4 R cos(phi/2)/sinc^3(phi/2) (1/3 at phi = 0).
    pure subroutine steep_evaluate(self, x, f, df, status)
        class(steep_equation), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp), intent(out) :: f, df
        integer, intent(out) :: status
        real(qp) :: remainder, half_sinc
        remainder = cubic_remainder(x)
        half_sinc = sinc(0.5_qp*x)
        f = 2.0_qp*x*remainder/half_sinc**2 - self%ratio
        df = 1.0_qp - 4.0_qp*remainder*cos(0.5_qp*x)/half_sinc**3
        status = status_ok
    end subroutine steep_evaluate

    !> m(delta) - w and m'(delta) for the shallow case, with P = 2 pi - (delta - sin delta)
    !! = phi - sin phi: m = sin(delta/2) sqrt(2/P),
    !! m' = sqrt(2/P) (cos(delta/2)/2 + sin^3(delta/2)/P) > 0.
    pure subroutine shallow_evaluate(self, x, f, df, status)
        class(shallow_equation), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp), intent(out) :: f, df
        integer, intent(out) :: status
        real(qp) :: p, root, half_sine
        p = two_pi - angle_minus_sine(x)
        root = sqrt(2.0_qp/p)
        half_sine = sin(0.5_qp*x)
        f = half_sine*root - self%root_ratio
        df = root*(0.5_qp*cos(0.5_qp*x) + half_sine**3/p)
        status = status_ok
    end subroutine shallow_evaluate

    !> A point of the cycloid x = a(phi - sin phi), y = a(1 - cos phi) (y downward), with
    !! phi - sin phi by its series for small phi and 1 - cos phi = 2 sin^2(phi/2), so both
    !! keep full relative precision. Near phi = 2 pi pass `phi_deficit` = 2 pi - phi as
    !! returned by `uniform_brachistochrone`: for phi > pi it is used in place of phi
    !! (x = a(2 pi - (delta - sin delta)), y = 2 a sin^2(delta/2)).
    elemental subroutine cycloid_point(radius, phi, x, y, status, phi_deficit)
        real(qp), intent(in) :: radius !! rolling-circle radius a >= 0
        real(qp), intent(in) :: phi    !! rolling angle, 0 <= phi <= 2 pi
        real(qp), intent(out) :: x     !! horizontal coordinate
        real(qp), intent(out) :: y     !! vertical coordinate, downward
        !> status_ok, status_not_finite, status_parameter_out_of_range
        integer, intent(out) :: status
        real(qp), intent(in), optional :: phi_deficit !! 2 pi - phi, if known more exactly
        real(qp) :: delta
        x = 0.0_qp
        y = 0.0_qp
        if (.not. (ieee_is_finite(radius) .and. ieee_is_finite(phi))) then
            status = status_not_finite
            return
        end if
        if (radius < 0.0_qp .or. phi < 0.0_qp .or. phi > two_pi) then
            status = status_parameter_out_of_range
            return
        end if
        if (present(phi_deficit)) then
            if (.not. ieee_is_finite(phi_deficit)) then
                status = status_not_finite
                return
            end if
            if (phi_deficit < 0.0_qp .or. phi_deficit > two_pi) then
                status = status_parameter_out_of_range
                return
            end if
        end if
        status = status_ok
        delta = two_pi - phi
        if (present(phi_deficit)) delta = phi_deficit
        ! products ordered so that neither phi^3 nor sin^2 underflows on its own when a is
        ! huge (x_B/y_B -> 0 gives a ~ 2 y_B/phi^2 with phi ~ 3 x_B/y_B)
        if (phi <= 1.0_qp) then
            x = (((radius*phi)*phi)*phi)*cubic_remainder(phi)
        else if (phi <= pi) then
            x = radius*angle_minus_sine(phi)
        else
            x = radius*(two_pi - angle_minus_sine(delta))
        end if
        if (phi <= pi) then
            y = (radius*sin(0.5_qp*phi))*(2.0_qp*sin(0.5_qp*phi))
        else
            y = (radius*sin(0.5_qp*delta))*(2.0_qp*sin(0.5_qp*delta))
        end if
    end subroutine cycloid_point

    ! ------------------------------------------------------------------------------------
    ! 2. The isochrone
    ! ------------------------------------------------------------------------------------

    !> Checks g > 0 and a radius > 0, both finite; status_ok or the reason.
    elemental function check_positive(radius, g) result(status)
        real(qp), intent(in) :: radius, g
        integer :: status
        if (.not. (ieee_is_finite(radius) .and. ieee_is_finite(g))) then
            status = status_not_finite
        else if (radius <= 0.0_qp .or. g <= 0.0_qp) then
            status = status_parameter_out_of_range
        else
            status = status_ok
        end if
    end function check_positive

    !> Huygens's isochrone: the time of descent from rest anywhere on a cycloid half-arch
    !! of rolling-circle radius alpha (axis vertical, concave up) to its base,
    !! pi sqrt(alpha/g) (Tee, section 1).
    elemental subroutine isochrone_time(alpha, g, time, status)
        real(qp), intent(in) :: alpha  !! rolling-circle radius, > 0
        real(qp), intent(in) :: g      !! gravitational acceleration, > 0
        real(qp), intent(out) :: time  !! pi sqrt(alpha/g)
        !> status_ok, status_not_finite, status_parameter_out_of_range
        integer, intent(out) :: status
        time = 0.0_qp
        status = check_positive(alpha, g)
        if (status /= status_ok) return
        time = pi*sqrt(alpha)/sqrt(g)
    end subroutine isochrone_time

    !> The same descent time by numerical quadrature of Tee's eq. (3)-(4),
    !! T sqrt(2g) = int_0^1 f'(hz) sqrt(hz) dz/sqrt(z(1-z)), where s = f(y) is the
    !! arclength of the half-arch from its base and h the release height.
    !!
    !! Substitution: z = sin^2(theta) (y = h sin^2 theta), so dz/sqrt(z(1-z)) = 2 d theta
    !! on [0, pi/2]; it removes both inverse-square-root endpoint singularities, 1/sqrt(h-y)
    !! at the release point and f'(y) ~ 1/sqrt(y) at the base, leaving
    !! T = sqrt(2/g) int_0^(pi/2) f'(y) sqrt(y) d theta with an analytic integrand.
    !! f'(y) = ds/dy is evaluated at each node from the parametric form (1): with
    !! sin(eta/2) = sqrt(y/(2 alpha)), cos(eta/2) = sqrt((2 alpha - y)/(2 alpha)),
    !! dx/d eta = 2 alpha cos^2(eta/2), dy/d eta = 2 alpha sin(eta/2) cos(eta/2) and
    !! ds/d eta = hypot(dx/d eta, dy/d eta) -- not from the closed form (6). For the
    !! cycloid the integrand is then constant (that is the isochrone property: eq. (6)),
    !! so this checks the chain (1) -> (3) -> (4) -> substitution -> quadrature; the
    !! pendulum (`pendulum_period_quadrature`) runs the same path on a varying integrand.
    !! Adaptive Gauss-Legendre (20 nodes per panel), relative tolerance 4 eps.
    elemental subroutine isochrone_time_quadrature(alpha, g, height, time, status)
        real(qp), intent(in) :: alpha  !! rolling-circle radius, > 0
        real(qp), intent(in) :: g      !! gravitational acceleration, > 0
        real(qp), intent(in) :: height !! release height above the base, 0 < h <= 2 alpha
        real(qp), intent(out) :: time  !! descent time to the base
        !> status_ok, status_not_finite, status_parameter_out_of_range,
        !! status_no_convergence
        integer, intent(out) :: status
        time = 0.0_qp
        status = check_height(alpha, g, height)
        if (status /= status_ok) return
        call cycloid_descent(alpha, g, height, time, status)
    end subroutine isochrone_time_quadrature

    !> Checks alpha, g > 0 and 0 < height <= 2 alpha, all finite.
    elemental function check_height(alpha, g, height) result(status)
        real(qp), intent(in) :: alpha, g, height
        integer :: status
        status = check_positive(alpha, g)
        if (status /= status_ok) return
        if (.not. ieee_is_finite(height)) then
            status = status_not_finite
        else if (height <= 0.0_qp .or. height > 2.0_qp*alpha) then
            status = status_parameter_out_of_range
        end if
    end function check_height

    !> Descent time on the cycloid half-arch by quadrature (arguments already checked).
    pure subroutine cycloid_descent(alpha, g, height, time, status)
        real(qp), intent(in) :: alpha, g, height
        real(qp), intent(out) :: time
        integer, intent(out) :: status
        type(cycloid_integrand) :: integrand
        type(gauss_legendre_rule) :: rule
        real(qp) :: value, error
        integrand%alpha = alpha
        integrand%height = height
        rule = gauss_legendre(quadrature_nodes)
        call integrate_adaptive(integrand, 0.0_qp, 0.5_qp*pi, rule, quadrature_tolerance, &
                                0.0_qp, value, error, status)
        time = 0.0_qp
        if (status /= status_ok) return
        time = sqrt(2.0_qp)*value/sqrt(g)
    end subroutine cycloid_descent

    !> f'(y) sqrt(y) = sqrt(y) (ds/d eta)/(dy/d eta) at y = h sin^2(theta) on the cycloid
    !! x = alpha (eta + sin eta), y = alpha (1 - cos eta) (Tee's eq. (1)).
    pure function cycloid_integrand_evaluate(self, x) result(value)
        class(cycloid_integrand), intent(in) :: self
        real(qp), intent(in) :: x !! theta
        real(qp) :: value
        real(qp) :: y, diameter, half_sine, half_cosine, dx_deta, dy_deta
        y = self%height*sin(x)**2
        diameter = 2.0_qp*self%alpha
        half_sine = sqrt(y/diameter)
        half_cosine = sqrt((diameter - y)/diameter)
        dx_deta = diameter*half_cosine**2
        dy_deta = diameter*half_sine*half_cosine
        value = sqrt(y)*hypot(dx_deta, dy_deta)/dy_deta
    end function cycloid_integrand_evaluate

    !> Two opposed cycloid half-arches with radii alpha and beta joined at their bases
    !! (Tee, section 1.2.2): the oscillation period 2 pi (sqrt(alpha) + sqrt(beta))/sqrt(g),
    !! the same for every amplitude.
    elemental subroutine joined_arches_period(alpha, beta, g, period, status)
        real(qp), intent(in) :: alpha   !! rolling-circle radius of one half-arch, > 0
        real(qp), intent(in) :: beta    !! rolling-circle radius of the other, > 0
        real(qp), intent(in) :: g       !! gravitational acceleration, > 0
        real(qp), intent(out) :: period !! 2 pi (sqrt(alpha) + sqrt(beta))/sqrt(g)
        !> status_ok, status_not_finite, status_parameter_out_of_range
        integer, intent(out) :: status
        period = 0.0_qp
        status = check_positive(alpha, g)
        if (status == status_ok) status = check_positive(beta, g)
        if (status /= status_ok) return
        period = 2.0_qp*pi*(sqrt(alpha) + sqrt(beta))/sqrt(g)
    end subroutine joined_arches_period

    !> The joined half-arches' period as the sum of four quarter-period quadratures
    !! (`isochrone_time_quadrature`): released at height h on one side, the particle
    !! descends that half-arch, rises to the same height h on the other, and returns:
    !! period = 2 (T_alpha(h) + T_beta(h)). The height must lie on both half-arches,
    !! 0 < h <= 2 min(alpha, beta).
    elemental subroutine joined_arches_period_quadrature(alpha, beta, g, height, period, &
                                                         status)
        real(qp), intent(in) :: alpha   !! rolling-circle radius of one half-arch, > 0
        real(qp), intent(in) :: beta    !! rolling-circle radius of the other, > 0
        real(qp), intent(in) :: g       !! gravitational acceleration, > 0
        real(qp), intent(in) :: height  !! turning height, 0 < h <= 2 min(alpha, beta)
        real(qp), intent(out) :: period !! oscillation period
        !> status_ok, status_not_finite, status_parameter_out_of_range,
        !! status_no_convergence
        integer, intent(out) :: status
        real(qp) :: time_alpha, time_beta
        period = 0.0_qp
        status = check_height(alpha, g, height)
        if (status == status_ok) status = check_height(beta, g, height)
        if (status /= status_ok) return
        call cycloid_descent(alpha, g, height, time_alpha, status)
        if (status /= status_ok) return
        call cycloid_descent(beta, g, height, time_beta, status)
        if (status /= status_ok) return
        period = 2.0_qp*(time_alpha + time_beta)
    end subroutine joined_arches_period_quadrature

    ! ------------------------------------------------------------------------------------
    ! 3. The simple pendulum
    ! ------------------------------------------------------------------------------------

    !> K(k) = pi/(2 AGM(1, k')) from the complementary modulus k' in (0, 1]. The AGM
    !! converges quadratically; it stops once a and b agree to 2 eps, after which one more
    !! step leaves a correct to rounding (at most about 12 steps for k' >= 1e-40).
    elemental function elliptic_k_from_complement(complement) result(value)
        real(qp), intent(in) :: complement
        real(qp) :: value
        real(qp) :: a, b, a_next
        integer :: step
        a = 1.0_qp
        b = complement
        do step = 1, 64
            a_next = 0.5_qp*(a + b)
            b = sqrt(a*b)
            a = a_next
            if (abs(a - b) <= 2.0_qp*eps_qp*a) exit
        end do
        a = 0.5_qp*(a + b)
        value = 0.5_qp*pi/a
    end function elliptic_k_from_complement

    !> Complete elliptic integral of the first kind
    !! K(k) = int_0^(pi/2) d theta/sqrt(1 - k^2 sin^2 theta) = pi/(2 AGM(1, sqrt(1 - k^2))),
    !! with sqrt(1 - k^2) formed as sqrt((1 - k)(1 + k)). K(0) = pi/2; K -> infinity as
    !! |k| -> 1, like log(4/k').
    elemental subroutine complete_elliptic_k(modulus, value, status)
        real(qp), intent(in) :: modulus !! k, -1 < k < 1
        real(qp), intent(out) :: value  !! K(k)
        !> status_ok, status_not_finite, status_parameter_out_of_range (|k| >= 1)
        integer, intent(out) :: status
        value = 0.0_qp
        if (.not. ieee_is_finite(modulus)) then
            status = status_not_finite
        else if (abs(modulus) >= 1.0_qp) then
            status = status_parameter_out_of_range
        else
            value = elliptic_k_from_complement(sqrt((1.0_qp - abs(modulus))* &
                                                    (1.0_qp + abs(modulus))))
            status = status_ok
        end if
    end subroutine complete_elliptic_k

    !> Checks a pendulum: length, g > 0 and 0 <= amplitude with cos(amplitude/2) > 0, all
    !! finite; returns k' = cos(amplitude/2).
    pure subroutine check_pendulum(length, g, amplitude, complement, status)
        real(qp), intent(in) :: length, g, amplitude
        real(qp), intent(out) :: complement
        integer, intent(out) :: status
        complement = 0.0_qp
        status = check_positive(length, g)
        if (status /= status_ok) return
        if (.not. ieee_is_finite(amplitude)) then
            status = status_not_finite
            return
        end if
        if (amplitude < 0.0_qp .or. amplitude > pi) then
            status = status_parameter_out_of_range
            return
        end if
        complement = cos(0.5_qp*amplitude)
        if (complement <= 0.0_qp) then
            complement = 0.0_qp
            status = status_parameter_out_of_range
        end if
    end subroutine check_pendulum

    !> Period of the simple pendulum of length L released from rest at angle theta0 from
    !! the downward vertical: 4 sqrt(L/g) K(sin(theta0/2)), with k' = cos(theta0/2) passed
    !! to the AGM directly (no 1 - k^2). It grows with the amplitude from
    !! 2 pi sqrt(L/g) (theta0 -> 0) and tends to infinity like
    !! 4 sqrt(L/g) log(4/cos(theta0/2)) as theta0 -> pi (the pendulum balancing on top).
    !! Every amplitude 0 <= theta0 <= pi of real(qp) has a finite period: the nearest
    !! real(qp) `pi` is 8.7e-35 below the true pi, so cos(pi/2) = 4.3e-35 > 0 and the
    !! period there is about 4 sqrt(L/g) x 80.5; larger amplitudes are refused.
    elemental subroutine pendulum_period(length, g, amplitude, period, status)
        real(qp), intent(in) :: length    !! pendulum length L, > 0
        real(qp), intent(in) :: g         !! gravitational acceleration, > 0
        real(qp), intent(in) :: amplitude !! theta0 in radians, 0 <= theta0 <= pi
        real(qp), intent(out) :: period   !! 4 sqrt(L/g) K(sin(theta0/2))
        !> status_ok, status_not_finite, status_parameter_out_of_range
        integer, intent(out) :: status
        real(qp) :: complement
        period = 0.0_qp
        call check_pendulum(length, g, amplitude, complement, status)
        if (status /= status_ok) return
        period = 4.0_qp*sqrt(length)/sqrt(g)*elliptic_k_from_complement(complement)
    end subroutine pendulum_period

    !> The pendulum period by quadrature of Tee's eq. (3)-(4) for the circle of radius L,
    !! independent of the AGM. The bob's path from the bottom has s = L theta,
    !! y = L(1 - cos theta) (height), so f'(y) = L/sqrt(y (2L - y)) and
    !! f'(y) sqrt(y) = L/sqrt(2L - y); the release height is h = 2L k^2, k = sin(theta0/2).
    !! With the substitution z = sin^2(theta) of `isochrone_time_quadrature`,
    !! 2L - y = 2L (cos^2 theta + k'^2 sin^2 theta) (written so: no cancellation as
    !! k -> 1) and the quarter period is sqrt(L/g) int_0^(pi/2) d theta/
    !! sqrt(cos^2 theta + k'^2 sin^2 theta). The integrand peaks (1/k') at theta = pi/2 in
    !! a width of about k'; it is integrated in u = pi/2 - theta,
    !! int_0^(pi/2) du/sqrt(sin^2 u + k'^2 cos^2 u), so that the nodes next to the peak
    !! (u small) carry full relative precision: in theta their rounding, about
    !! eps pi/2 absolute, would change the integrand by eps pi/(2k') relative (2000 eps
    !! at k' = 1e-3). Panels are bisected adaptively (20-node Gauss-Legendre, relative
    !! tolerance 4 eps); status_no_convergence where that would need more than the
    !! integrator's 40 levels (measured: converges for theta0 = pi - 1e-11, k' = 5e-12;
    !! fails from pi - 1e-12, k' = 5e-13).
    elemental subroutine pendulum_period_quadrature(length, g, amplitude, period, status)
        real(qp), intent(in) :: length    !! pendulum length L, > 0
        real(qp), intent(in) :: g         !! gravitational acceleration, > 0
        real(qp), intent(in) :: amplitude !! theta0 in radians, 0 <= theta0 <= pi
        real(qp), intent(out) :: period   !! the period, four quarter periods
        !> status_ok, status_not_finite, status_parameter_out_of_range,
        !! status_no_convergence
        integer, intent(out) :: status
        type(circle_integrand) :: integrand
        type(gauss_legendre_rule) :: rule
        real(qp) :: value, error
        period = 0.0_qp
        call check_pendulum(length, g, amplitude, integrand%complement, status)
        if (status /= status_ok) return
        rule = gauss_legendre(quadrature_nodes)
        call integrate_adaptive(integrand, 0.0_qp, 0.5_qp*pi, rule, quadrature_tolerance, &
                                0.0_qp, value, error, status)
        if (status /= status_ok) return
        period = 4.0_qp*sqrt(length)/sqrt(g)*value
    end subroutine pendulum_period_quadrature

    !> 1/sqrt(sin^2 u + k'^2 cos^2 u), u = pi/2 - theta.
    pure function circle_integrand_evaluate(self, x) result(value)
        class(circle_integrand), intent(in) :: self
        real(qp), intent(in) :: x !! u = pi/2 - theta
        real(qp) :: value
        value = 1.0_qp/sqrt(sin(x)**2 + (self%complement*cos(x))**2)
    end function circle_integrand_evaluate

end module brachistochrone_uniform_gravity
