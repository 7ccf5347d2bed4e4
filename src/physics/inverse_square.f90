!> Brachistochrones under attractive inverse-square force: Theta, S, T (Tee 1998, sec. 4).
!!
!! Units of the paper: mu = 1, start A at radius 1, angle 0. For apse radius R and a
!! point at radius r on the first half-arch (R <= r <= 1) the paper's integrals (55)-(57)
!! are evaluated in one variable for all three. With z = R/x (eq. 59) and
!! z = cos^2(lambda) + R sin^2(lambda) (eq. 61), c = cos(lambda), s = sin(lambda),
!!
!!     q = z^2 + (1-R)(1+z),   Q = sqrt(q),   D = 1 + s Q,
!!     Theta(r,R) = int_L^{pi/2} 2 (1-R) c^2 / Q                 d lambda     (eq. 65)
!!     S(r,R)     = (1 - r) + R     int_L^{pi/2} 2 (1-R) c^3 / (Q D)  d lambda
!!     T(r,R)     = t(r) + R^(3/2)/sqrt(2) int_L^{pi/2} 2 sqrt(1-R) c^2 / (Q D) d lambda
!!
!! where t(r) is the radial fall time (46) and L the angle of the endpoint,
!! cos L = sqrt(R(1-r)/(r(1-R))), sin L = sqrt((r-R)/(r(1-R))) (the paper's eq. 87,
!! written without the acos that loses half the digits near r = R or r = 1).
!! The S and T forms follow from S = int_r^1 g(R/x) dx with g(z) = ((1-z)p(z))^(-1/2),
!! T = int_r^1 sqrt(x/(2(1-x))) g(R/x) dx, subtracting the radial part (g = 1) exactly:
!! g - 1 = z^2 (z-R)/((1-R) g^-1 (1 + g^-1)) has no cancellation, and unlike the paper's
!! (77) and (81) the remaining integrands do not vary on the scale R near the apse, so
!! the same 48 nodes serve every R in (0, 1).
!!
!! The lambda integrals are taken in trig-free half-angle variables: tau = tan(lambda/2)
!! on [0, L] (from the apse) and eta = tan((pi/2 - lambda)/2) on [L, pi/2] (from A), so
!! c and s are rational in the node; one sqrt and two divisions per node. The full
!! half-arch Theta(R,R) (eq. 66) is an even periodic integral in 2 lambda: trapezoid rule.
!! Second half-arch (eq. 29): F = 2 F(R,R) - F(r,R) = F(R,R) + int_0^L.
module inverse_square
    use brachistochrone_kinds, only: qp, pi, eps_qp
    use brachistochrone_status, only: status_ok, status_invalid_argument, &
                                      status_not_finite
    use closed_forms, only: radial_time
    use fast_math, only: inverse_sqrt
    use quadrature, only: gauss_legendre_rule, gauss_legendre, even_periodic_rule, &
                          even_periodic_trapezoid
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use, intrinsic :: iso_fortran_env, only: real64
    implicit none
    private

    public :: inverse_square_model, new_inverse_square_model
    public :: arch_values, level_fine, level_coarse, level_rough, level_digits

    !> Rule set selector: full quad precision.
    integer, parameter :: level_fine = 1
    !> Rule set selector: about 15 digits, for the first iterations of a root finder.
    integer, parameter :: level_coarse = 2
    !> Rule set selector: about 9 digits, for the first steps of a root finder.
    integer, parameter :: level_rough = 3

    !> Most Gauss nodes on one panel: the worst panel (R -> 0, a whole half-arch in the
    !! eta variable) needs 46 for Theta, 48 for s and t (8e-36 there).
    integer, parameter :: max_nodes = 48
    !> Fewest Gauss nodes on a panel.
    integer, parameter :: min_nodes = 6
    !> Digits aimed at by the node choice: fine (with a margin over 34) and coarse.
    real(qp), parameter :: fine_digits = 36.0_qp, coarse_digits = 17.0_qp, &
                           rough_digits = 9.0_qp
    !> Most intervals on [0, pi] of the periodic rule: relative error 2e-38 at R -> 0 (the
    !! worst case: the singularities then lie closest to the real axis).
    integer, parameter :: max_intervals = 26
    !> Fewest intervals of the periodic rule.
    integer, parameter :: min_intervals = 4

    !> One Gauss-Legendre rule with the node data the sweeps use.
    type :: gauss_nodes
        integer :: n = 0                          !! number of nodes
        real(qp), allocatable :: offset(:)        !! (1 + x_k)/2 for the nodes x_k
        real(qp), allocatable :: double_weight(:) !! 2 w_k for the weights w_k
    end type gauss_nodes

    !> Trapezoid rule on the whole half-arch, tabulated.
    type :: periodic_nodes
        integer :: m = 0                          !! intervals on [0, pi] in 2 lambda
        real(qp), allocatable :: cos2(:)          !! cos^2(lambda_k), k = 0..m
        real(qp), allocatable :: sin2(:)          !! sin^2(lambda_k)
        real(qp), allocatable :: weighted_cos2(:) !! trapezoid weight times cos2
    end type periodic_nodes

    !> The inverse-square evaluator: quadrature rules built once, then used read-only
    !! (so one model can be shared by all threads).
    type :: inverse_square_model
        !> Gauss rules with n = 2j nodes in element j (j = min_nodes/2 .. max_nodes/2)
        type(gauss_nodes) :: gauss(max_nodes/2)
        !> Trapezoid rules with m = 2j intervals in element j (j = min_intervals/2 ..)
        type(periodic_nodes) :: periodic(max_intervals/2)
        !> d Theta(R,R)/dR at R = 0 (about -0.8096): the slope of the apse angle there
        real(qp) :: apse_slope_at_zero = 0.0_qp
    contains
        procedure :: half_arch      !! Theta, S, T on the first or second half-arch
        procedure :: theta          !! Theta(r,R), eq. (55)
        procedure :: arclength      !! S(r,R), eq. (56)
        procedure :: travel_time    !! T(r,R), eq. (57)
        procedure :: apse_angle     !! Theta(R,R), eq. (66)
        procedure :: evaluate_arch  !! the solver's kernel: values and d/dR pieces
    end type inverse_square_model

    !> Angle, arclength and time at radius r of the brachistochrone with apse R, on one
    !! half-arch, with the pieces of d(angle)/dR the root finder needs.
    type :: arch_values
        real(qp) :: angle = 0.0_qp      !! theta at the point
        real(qp) :: arclength = 0.0_qp  !! s at the point (when requested)
        real(qp) :: time = 0.0_qp       !! t at the point (when requested)
        !> d(angle)/dR = angle_dr_smooth + boundary_sign * boundary / sqrt(r - R)
        real(qp) :: angle_dr_smooth = 0.0_qp
        real(qp) :: boundary = 0.0_qp      !! coefficient of the 1/sqrt(r-R) term, >= 0
        real(qp) :: boundary_sign = 1.0_qp !! +1 on the first half-arch, -1 on the second
    end type arch_values

contains

    !> Digits aimed at by a precision level (level_fine, level_coarse, level_rough).
    elemental function level_digits(level) result(digits)
        integer, intent(in) :: level !! the level
        real(qp) :: digits
        select case (level)
        case (level_coarse);  digits = coarse_digits
        case (level_rough);   digits = rough_digits
        case default;         digits = fine_digits
        end select
    end function level_digits

    !> Build the quadrature rules (the only costly step; do it once and share the model).
    function new_inverse_square_model() result(model)
        type(inverse_square_model) :: model
        type(gauss_legendre_rule) :: rule
        real(qp) :: slope(2)
        integer :: j
        do j = min_nodes/2, max_nodes/2
            rule = gauss_legendre(2*j)
            model%gauss(j)%n = 2*j
            model%gauss(j)%offset = 0.5_qp*(1.0_qp + rule%node)
            model%gauss(j)%double_weight = 2.0_qp*rule%weight
        end do
        do j = min_intervals/2, max_intervals/2
            model%periodic(j) = new_periodic_nodes(2*j)
        end do
        ! d Theta(R,R)/dR at R -> 0 (Theta(R,R) = pi/3 - 0.8095502 R + ...): from the
        ! differentiated integrand (69) at R = 1e-40, where O(R) terms are below rounding
        call periodic_sweep(model%periodic(max_intervals/2), 1.0e-40_qp, 1.0_qp, .true., &
                            slope)
        model%apse_slope_at_zero = slope(2)
    end function new_inverse_square_model

    pure function new_periodic_nodes(intervals) result(nodes)
        integer, intent(in) :: intervals
        type(periodic_nodes) :: nodes
        type(even_periodic_rule) :: rule
        integer :: k
        rule = even_periodic_trapezoid(intervals)
        nodes%m = rule%m
        allocate (nodes%cos2(0:rule%m), nodes%sin2(0:rule%m), nodes%weighted_cos2(0:rule%m))
        do k = 0, rule%m
            ! lambda_k = angle_k / 2 covers [0, pi/2]
            nodes%cos2(k) = cos(0.5_qp*rule%angle(k))**2
            nodes%sin2(k) = sin(0.5_qp*rule%angle(k))**2
            nodes%weighted_cos2(k) = rule%weight(k)*nodes%cos2(k)
        end do
    end function new_periodic_nodes

    !> cos(2 lambda_s) at the zeros of q in the lambda plane (double precision):
    !! w = 2 (z_s - R)/(1 - R) - 1 with z_s = (-(1-R) + i sqrt((1-R)(3+R)))/2.
    pure function singular_cosine(big_r) result(w)
        real(qp), intent(in) :: big_r
        complex(real64) :: w
        real(real64) :: r, omr
        r = real(big_r, real64)
        omr = 1.0_real64 - r
        w = 2.0_real64*(cmplx(-omr, sqrt(omr*(3.0_real64 + r)), real64)/2.0_real64 - r) &
            /omr - 1.0_real64
    end function singular_cosine

    !> Gauss nodes needed on the panel v in [0, upper] for `digits` digits of Theta.
    !!
    !! The Theta integrand is analytic except at the zeros of q, where
    !! cos(2 lambda) = w (`singular_cosine`), and at the poles v = +-i of the half-angle
    !! substitution. In v = tan(lambda/2) the zeros of q sit at +-t, +-1/t with
    !! t = tan(acos(w)/4) (w -> -w for the variable from A). An n-point Gauss rule then
    !! errs by about rho^(-2n), rho the Bernstein ellipse through the nearest of them
    !! (mapped to [-1, 1]). Double precision is ample for choosing n; the test suite checks
    !! the result against the references.
    pure function nodes_needed(big_r, upper, from_apse, digits) result(n)
        real(qp), intent(in) :: big_r, upper, digits
        logical, intent(in) :: from_apse
        integer :: n
        real(real64) :: rho_min
        complex(real64) :: w, t, candidates(5)
        integer :: k
        n = min_nodes
        if (big_r >= 1.0_qp .or. upper <= 0.0_qp) return
        w = singular_cosine(big_r)
        if (.not. from_apse) w = -w
        t = tan(acos(w)/4.0_real64)
        candidates = [t, -t, 1.0_real64/t, -1.0_real64/t, (0.0_real64, 1.0_real64)]
        rho_min = huge(1.0_real64)
        do k = 1, size(candidates)
            rho_min = min(rho_min, bernstein(2.0_real64*candidates(k)/real(upper, real64) &
                                             - 1.0_real64))
        end do
        if (rho_min <= 1.0_real64 + 1.0e-6_real64) then
            n = max_nodes
        else
            n = ceiling(real(digits, real64)*log(10.0_real64)/(2.0_real64*log(rho_min))) + 2
            n = min(max_nodes, max(min_nodes, n + mod(n, 2)))
        end if
    contains
        pure real(real64) function bernstein(x)
            complex(real64), intent(in) :: x
            complex(real64) :: root
            root = sqrt(x*x - 1.0_real64)
            bernstein = max(abs(x + root), abs(x - root))
        end function bernstein
    end function nodes_needed

    !> Intervals on [0, pi] the periodic rule needs for `digits` digits of Theta(R,R).
    !!
    !! In the angle 2 lambda the integrand is 2 pi-periodic and analytic in the strip
    !! |Im| < a, a = Im acos(w) (the zeros of q); the trapezoid rule with 2m points per
    !! period then errs by about exp(-2 m a) (Trefethen & Weideman 2014, thm 3.2).
    !! At R -> 0, a = 1.66 and m = 26 for 38 digits; a grows as R -> 1.
    pure function intervals_needed(big_r, digits) result(m)
        real(qp), intent(in) :: big_r, digits
        integer :: m
        real(real64) :: a
        m = min_intervals
        if (big_r >= 1.0_qp) return
        a = abs(aimag(acos(singular_cosine(big_r))))
        m = ceiling(real(digits, real64)*log(10.0_real64)/(2.0_real64*a)) + 1
        m = min(max_intervals, max(min_intervals, m + mod(m, 2)))
    end function intervals_needed

    !> The kernel: angle (and optionally arclength, time, d(angle)/dR) at radius r on the
    !! first (`second = .false.`) or second half-arch of the brachistochrone with apse R.
    !! The caller passes d = r - R separately so that endpoints near the apse keep full
    !! precision. Preconditions (not checked): 0 < R < 1, 0 <= d, R + d = r <= 1.
    pure function evaluate_arch(self, level, second, r, big_r, d, want_derivative, &
                                want_length_time) result(values)
        class(inverse_square_model), intent(in) :: self
        integer, intent(in) :: level            !! level_fine or level_coarse
        logical, intent(in) :: second           !! second half-arch (after the apse)
        real(qp), intent(in) :: r               !! radius of the point
        real(qp), intent(in) :: big_r           !! apse radius R
        real(qp), intent(in) :: d               !! r - R, computed by the caller
        logical, intent(in) :: want_derivative  !! compute the d/dR pieces
        logical, intent(in) :: want_length_time !! compute arclength and time
        type(arch_values) :: values

        values = arch_with_rules(self, level, second, r, big_r, d, want_derivative, &
                                 want_length_time)
    end function evaluate_arch

    !> `evaluate_arch` for one precision level.
    pure function arch_with_rules(model, level, second, r, big_r, d, want_derivative, &
                                  want_length_time) result(values)
        type(inverse_square_model), intent(in) :: model
        integer, intent(in) :: level
        logical, intent(in) :: second, want_derivative, want_length_time
        real(qp), intent(in) :: r, big_r, d
        type(arch_values) :: values
        real(qp) :: one_minus_r, one_minus_big_r, cos_l, sin_l, z_l, q_l
        real(qp) :: from_start(4), from_apse(4), periodic(2), correction_scale, digits

        digits = level_digits(level)
        one_minus_r = 1.0_qp - r
        one_minus_big_r = one_minus_r + d
        cos_l = sqrt(big_r*one_minus_r/(r*one_minus_big_r))
        sin_l = sqrt(d/(r*one_minus_big_r))

        ! lambda in [L, pi/2]: from A to the point (on the second half-arch only s and t
        ! need this part)
        if (.not. second .or. want_length_time) then
            call sweep(model, digits, big_r, one_minus_big_r, cos_l/(1.0_qp + sin_l), &
                       .false., want_derivative .and. .not. second, want_length_time, &
                       from_start)
        else
            from_start = 0.0_qp
        end if
        if (second) then
            ! lambda in [0, L]: from the apse back out to the point
            call sweep(model, digits, big_r, one_minus_big_r, sin_l/(1.0_qp + cos_l), &
                       .true., want_derivative, want_length_time, from_apse)
            call periodic_sweep(model%periodic(intervals_needed(big_r, digits)/2), big_r, &
                                one_minus_big_r, want_derivative, periodic)
            values%angle = periodic(1) + from_apse(1)
            values%angle_dr_smooth = periodic(2) + from_apse(2)
            values%boundary_sign = -1.0_qp
        else
            values%angle = from_start(1)
            values%angle_dr_smooth = from_start(2)
            values%boundary_sign = 1.0_qp
        end if

        if (want_derivative) then
            z_l = big_r/r
            q_l = z_l*z_l + one_minus_big_r*(1.0_qp + z_l)
            values%boundary = sqrt(big_r)*one_minus_r*sqrt(one_minus_r) &
                              /(r*one_minus_big_r*sqrt(q_l))
        end if

        if (want_length_time) then
            correction_scale = big_r*sqrt(big_r)/sqrt(2.0_qp)
            if (second) then
                values%arclength = (one_minus_big_r + d) &
                                   + big_r*(from_start(3) + 2.0_qp*from_apse(3))
                values%time = 2.0_qp*radial_time(big_r, one_minus_big_r) - radial_time(r) &
                              + correction_scale*(from_start(4) + 2.0_qp*from_apse(4))
            else
                values%arclength = one_minus_r + big_r*from_start(3)
                values%time = radial_time(r) + correction_scale*from_start(4)
            end if
        end if
    end function arch_with_rules

    !> Gauss-Legendre sweep over v in [0, upper] of the four integrands
    !! (Theta, dTheta/dR, S correction, T correction); v = tau from the apse or
    !! v = eta from the start, both with d lambda = 2 dv/(1 + v^2).
    pure subroutine sweep(model, digits, big_r, one_minus_big_r, upper, from_apse, &
                          want_derivative, want_length_time, sums)
        type(inverse_square_model), intent(in) :: model
        real(qp), intent(in) :: digits, big_r, one_minus_big_r, upper
        logical, intent(in) :: from_apse, want_derivative, want_length_time
        real(qp), intent(out) :: sums(4)
        real(qp) :: v, v2, jacobian, c, s, c2, z, q, theta_term, lengths, inverse
        integer :: k, j

        sums = 0.0_qp
        if (upper <= 0.0_qp) return
        j = nodes_needed(big_r, upper, from_apse, digits)/2
        ! s and t converge at the rate Theta does (their extra zeros, of D, lie farther
        ! out: at tau = -1 as R -> 0); 4 more nodes cover their larger constants
        if (want_length_time) j = min(max_nodes/2, j + 1)
        associate (rule => model%gauss(j))
        do k = 1, rule%n
            v = upper*rule%offset(k)
            v2 = v*v
            jacobian = 1.0_qp/(1.0_qp + v2)
            if (from_apse) then
                c = (1.0_qp - v2)*jacobian
                s = (v + v)*jacobian
            else
                c = (v + v)*jacobian
                s = (1.0_qp - v2)*jacobian
            end if
            c2 = c*c
            z = big_r + one_minus_big_r*c2
            q = z*(z + one_minus_big_r) + one_minus_big_r
            inverse = inverse_sqrt(q)
            theta_term = rule%double_weight(k)*jacobian*c2*inverse
            sums(1) = sums(1) + theta_term
            if (want_derivative) then
                sums(2) = sums(2) - theta_term*(inverse*inverse)*(z*(z + z) + &
                          one_minus_big_r*(z + 1.0_qp + (z + z + one_minus_big_r)*(s*s)))
            end if
            if (want_length_time) then
                lengths = theta_term/(1.0_qp + s*(q*inverse))
                sums(3) = sums(3) + lengths*c
                sums(4) = sums(4) + lengths
            end if
        end do
        end associate
        ! common factors: Theta 2(1-R) c^2/Q; S 2(1-R) c^3/(QD); T 2 sqrt(1-R) c^2/(QD)
        sums(1) = sums(1)*upper*one_minus_big_r
        sums(2) = sums(2)*0.5_qp*upper
        sums(3) = sums(3)*upper*one_minus_big_r
        sums(4) = sums(4)*upper*sqrt(one_minus_big_r)
    end subroutine sweep

    !> Trapezoid sweep of Theta(R,R) and its R-derivative over the whole half-arch
    !! lambda in [0, pi/2] (eq. 66-69): an even, pi-periodic integrand in lambda.
    pure subroutine periodic_sweep(rules, big_r, one_minus_big_r, want_derivative, sums)
        type(periodic_nodes), intent(in) :: rules
        real(qp), intent(in) :: big_r, one_minus_big_r
        logical, intent(in) :: want_derivative
        real(qp), intent(out) :: sums(2)
        real(qp) :: z, q, c2, inverse, theta_term
        integer :: k

        sums = 0.0_qp
        do k = 0, rules%m
            c2 = rules%cos2(k)
            z = big_r + one_minus_big_r*c2
            q = z*(z + one_minus_big_r) + one_minus_big_r
            inverse = inverse_sqrt(q)
            theta_term = rules%weighted_cos2(k)*inverse
            sums(1) = sums(1) + theta_term
            if (want_derivative) then
                sums(2) = sums(2) - theta_term*(inverse*inverse)*(z*(z + z) &
                          + one_minus_big_r*(z + 1.0_qp + (z + z + one_minus_big_r) &
                          *rules%sin2(k)))
            end if
        end do
        ! int_0^{pi/2} f d lambda = (1/2) int_0^pi f(angle/2) d angle; Theta factor 2(1-R)
        sums(1) = sums(1)*one_minus_big_r
        sums(2) = 0.5_qp*sums(2)
    end subroutine periodic_sweep

    !> Check 0 < R < 1, R <= r <= 1, all finite.
    pure function check_radii(r, big_r) result(status)
        real(qp), intent(in) :: r, big_r
        integer :: status
        if (.not. (ieee_is_finite(r) .and. ieee_is_finite(big_r))) then
            status = status_not_finite
        else if (big_r <= 0.0_qp .or. big_r >= 1.0_qp .or. r < big_r .or. r > 1.0_qp) then
            status = status_invalid_argument
        else
            status = status_ok
        end if
    end function check_radii

    !> Angle, arclength and time at radius r on the first half-arch (eqs. 55-57) or on
    !! the second (eq. 29: 2 F(R,R) - F(r,R)) of the brachistochrone with apse radius R.
    !! Outputs are 0 unless status == status_ok.
    pure subroutine half_arch(self, r, big_r, second, angle, arclength, time, status)
        class(inverse_square_model), intent(in) :: self
        real(qp), intent(in) :: r        !! radius of the point, R <= r <= 1
        real(qp), intent(in) :: big_r    !! apse radius, 0 < R < 1
        logical, intent(in) :: second    !! .true. for the second half-arch
        real(qp), intent(out) :: angle      !! theta at the point
        real(qp), intent(out) :: arclength  !! s at the point
        real(qp), intent(out) :: time       !! t at the point
        integer, intent(out) :: status      !! status_ok, status_invalid_argument, ...
        type(arch_values) :: values
        angle = 0.0_qp
        arclength = 0.0_qp
        time = 0.0_qp
        status = check_radii(r, big_r)
        if (status /= status_ok) return
        values = self%evaluate_arch(level_fine, second, r, big_r, r - big_r, .false., .true.)
        angle = values%angle
        arclength = values%arclength
        time = values%time
    end subroutine half_arch

    !> Theta(r,R), eq. (55): angle at radius r on the first half-arch.
    pure subroutine theta(self, r, big_r, value, status)
        class(inverse_square_model), intent(in) :: self
        real(qp), intent(in) :: r      !! radius, R <= r <= 1
        real(qp), intent(in) :: big_r  !! apse radius, 0 < R < 1
        real(qp), intent(out) :: value !! Theta(r,R); 0 on error
        integer, intent(out) :: status !! status_ok or the reason
        type(arch_values) :: values
        value = 0.0_qp
        status = check_radii(r, big_r)
        if (status /= status_ok) return
        values = self%evaluate_arch(level_fine, .false., r, big_r, r - big_r, .false., .false.)
        value = values%angle
    end subroutine theta

    !> S(r,R), eq. (56): arclength from A to radius r on the first half-arch.
    pure subroutine arclength(self, r, big_r, value, status)
        class(inverse_square_model), intent(in) :: self
        real(qp), intent(in) :: r      !! radius, R <= r <= 1
        real(qp), intent(in) :: big_r  !! apse radius, 0 < R < 1
        real(qp), intent(out) :: value !! S(r,R); 0 on error
        integer, intent(out) :: status !! status_ok or the reason
        real(qp) :: angle, time
        call self%half_arch(r, big_r, .false., angle, value, time, status)
    end subroutine arclength

    !> T(r,R), eq. (57): time from A to radius r on the first half-arch.
    pure subroutine travel_time(self, r, big_r, value, status)
        class(inverse_square_model), intent(in) :: self
        real(qp), intent(in) :: r      !! radius, R <= r <= 1
        real(qp), intent(in) :: big_r  !! apse radius, 0 < R < 1
        real(qp), intent(out) :: value !! T(r,R); 0 on error
        integer, intent(out) :: status !! status_ok or the reason
        real(qp) :: angle, length
        call self%half_arch(r, big_r, .false., angle, length, value, status)
    end subroutine travel_time

    !> Theta(R,R), eq. (66): the apse angle, by the periodic trapezoid rule.
    !! Strictly decreasing from pi/3 (R -> 0) to 0 (R -> 1); R = 1 gives 0.
    pure subroutine apse_angle(self, big_r, value, status)
        class(inverse_square_model), intent(in) :: self
        real(qp), intent(in) :: big_r  !! apse radius, 0 < R <= 1
        real(qp), intent(out) :: value !! Theta(R,R); 0 on error
        integer, intent(out) :: status !! status_ok or the reason
        real(qp) :: sums(2)
        value = 0.0_qp
        if (.not. ieee_is_finite(big_r)) then
            status = status_not_finite
        else if (big_r <= 0.0_qp .or. big_r > 1.0_qp) then
            status = status_invalid_argument
        else
            call periodic_sweep(self%periodic(intervals_needed(big_r, fine_digits)/2), &
                                big_r, 1.0_qp - big_r, .false., sums)
            value = sums(1)
            status = status_ok
        end if
    end subroutine apse_angle

end module inverse_square
