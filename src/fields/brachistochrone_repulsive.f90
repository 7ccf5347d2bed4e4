!> Brachistochrones for the repulsive inverse-square force, mu = -1 (Tee 1998, sec. 2, 3, 6).
!!
!! Start A = (1, 0) at rest, v^2 = 2(r - 1)/r for r >= 1 (44). A brachistochrone is the
!! orbit of a free particle with speed 1/v and angular momentum K (17)-(22); with
!! Q(x) = x^3 - 2 K^2 (x - 1) the integrals (23), (31), (37) read, for r increasing,
!!   theta = K sqrt2 int sqrt(x-1)/(x sqrt Q) dx,   s = int x^(3/2)/sqrt Q dx,
!!   t     = int x^2/(sqrt2 sqrt(x-1) sqrt Q) dx                      (from x = 1 to r).
!! (The printed (52) lacks the square root over Q.)
!!
!! **One parameter for every curve.** Q always has one negative root r3 = -P, P > 0.
!! Dividing Q by (x + P) gives
!!   2 K^2 = P^3/(1 + P),    Q(x) = (x + P) ((x - P/2)^2 + P^2 (3 - P)/(4 (P + 1))),
!! so with the *gap* g = 3 - P (kept as its own number, never as 3 - P rounded):
!!   g > 0 (K^2 < 27/8): no real root above 1: unbounded curves; the near-double complex
!!         pair is a +- i sqrt(beta), a = P/2, beta = P^2 g/(4 (P + 1)) (relative accuracy
!!         of beta is that of g, however small);
!!   g = 0 (K^2 = 27/8): Q = (x - 3/2)^2 (x + 3), the critical curve;
!!   g < 0 (K^2 > 27/8): roots r1 = R < 3/2 < r2, the apse R and the gap d = r2 - R =
!!         P sqrt(-g/(P + 1)), R - 1 = 2/((P + 1)(P - 2 + d)), all without cancellation.
!! Also 27/4 - 2 K^2 = g (9 - 2g)^2/(4 (4 - g)): g is proportional to the distance of K^2
!! from 27/8 (from the apse, g = -4 (3-2R)^2/((R-1)(S+3)(sqrt((R+3)(R-1)) + 3 - R)),
!! S = sqrt((R+3)/(R-1)), second order in 3 - 2R as K^2 has its minimum there).
!!
!! **Precision near the double root.** As g -> 0 the integrands get a peak of width
!! sqrt(beta) (unbounded, at x = a) or sqrt(d) (bounded, at the apse). Every difference to
!! the peak is carried exactly: unbounded, x = a +- sqrt(beta) sinh(xi) makes
!! (x - a)^2 + beta = beta cosh^2(xi) and cancels the peak against dx exactly, leaving a
!! smooth integrand in xi; bounded, x = R - (R - 1) sin^2(nu/2) makes R - x and x - 1 exact
!! products, and near the apse sin(nu/2) = sqrt(d/(R-1)) sinh(xi) turns r2 - x =
!! d + (R - x) into d cosh^2(xi) in the same way. So no rounding is amplified by
!! 1/sqrt(beta) or 1/sqrt(d): the integrals keep ~33 digits with g down to
!! `critical_floor` (where a = (3 - g)/2 itself is no longer resolved against sqrt(beta)).
!! The start x = 1 is regular through x - 1 = L sigma^2 (unbounded) or the nu map.
!!
!! **Structure of the two-point problem** (derived here, verified in test_repulsive):
!! every integrand above increases with K at fixed x, so theta(r; K), s and t increase
!! with K on the unbounded family and on the first half-arch of the bounded one (K^2 =
!! R^3/(2(R-1)) decreases as R grows to 3/2). For B = (rho, psi):
!! * rho >= 3/2: only unbounded curves reach rho; theta(rho; K) increases from 0 (K = 0,
!!   radial) to infinity as K^2 -> 27/8- (theta ~ -log(g)/sqrt3: each extra turn needs g
!!   smaller by exp(-2 pi sqrt3) ~ 1.9e-5). Every target angle has exactly one
!!   brachistochrone, and t increases with the target angle: the least time is the one of
!!   least swept angle, psi itself (2 pi - psi turning the other way is never smaller).
!! * 1 < rho < 3/2: the unbounded curves give theta(rho) in (0, theta_c(rho)), theta_c the
!!   critical curve's angle (finite since rho < 3/2); the first half-arches (R from 3/2
!!   down to rho) continue it to (theta_c, Theta(rho, rho)], the second half-arches (R from
!!   rho back up to 3/2) to (Theta(rho, rho), infinity) since Theta(R, R) ~ log(1/d).
!!   One continuous monotone branch: again exactly one brachistochrone per target angle,
!!   times increasing along the branch.
!! * rho = 1: only complete arches return to radius 1; 2 Theta(R, R) runs from 0 (R -> 1,
!!   locally a uniform field: a cycloid of height R - 1 spanning pi (R - 1)) to infinity.
!! * rho = 3/2: as for rho > 3/2 (no bounded curve reaches 3/2, the critical one only
!!   spirals towards it).
!! The targets are psi + 2 pi m (turning anticlockwise) and 2 pi (m + 1) - psi (the mirror
!! image, turning clockwise), m = 0, 1, ...; both are reported. The least time is the
!! anticlockwise m = 0 (two mirror-image minima when psi = pi).
!! **Cost of a turn.** The many-turn curves spend their extra turns next to the circle
!! r = 3/2, the circle where the angular speed v/r = sqrt(2(r-1)/r^3) is largest (its
!! inverse r/v is the K of a circular path, K^2 = r^3/(2(r-1)) minimal = 27/8): each
!! extra turn costs asymptotically 2 pi sqrt(27/8) = 11.5429... in time, and g shrinks
!! by exp(-2 pi sqrt3) per turn;
!! both limits are approached like O(g) (measured in test_repulsive).
!!
!! **The solver** (`solve_repulsive`; the unknown lambda = log g or log(3 - 2R) of each
!! branch). The pieces above are integrated on fixed Gauss-Legendre panels chosen once
!! per curve from the located singularities (`brachistochrone_repulsive_panels`; the sinh
!! and nu maps in rational form, so a node needs square roots only). The root is found
!! in hardware precision (x87 extended, about 19 digits: the bracket walked down from the
!! branch's top, then regula falsi), then one binary128 evaluation of theta, s, t at that
!! root x0 and a Newton step on the slopes d theta/d lambda, d s/d lambda obtained by
!! the complex step in hardware precision (curve, pieces' ends and panels all carried
!! through x + i h dx/dlambda); t by Hamilton-Jacobi, dt/d theta = K at fixed rho. The
!! step is accepted when its error, 1e-17 |dx| + curvature dx^2 (the curvature and a
!! cross-check of the slope from the quadratic through x0 and two of the root finder's
!! iterates 1e-8 .. 1e-2 away, one more evaluation 1e-6 away when only one is there, else
!! central differences), is below a rounding of lambda;
!! else a second binary128 evaluation and the secant through both (certified by the
!! residual's decrease), else the adaptive solver (`solve_branch`), which also takes
!! the curves whose panels decline (g or 3 - 2R below about 1e-41). Next to the apse
!! (R - rho below 1e-4 of 3 - 2 rho and rho - 1) the unknown is u = sqrt(R - rho)
!! instead: theta is linear in u there (theta = Theta(rho, rho) -+ 2 A u, A =
!! sqrt((rho - 1)/(rho (3 - 2 rho)))), and the curve keeps R - rho = u^2 exactly
!! (`r_gap`), which lambda would form by cancellation, also where u^2 is below R's
!! rounding (R = rho in binary128: the pieces and the complex step take R - rho from
!! r_gap, the step h = 1e-20 u, since sqrt(R - r) = u + i h needs h << u). There the
!! root is found by binary128 Newton steps in u, each certified as above
!! (`apse_newton`), from the hardware phase's root, or, with |Theta(rho, rho) - psi|
!! below 1e-16 psi (below what that phase resolves), from the law's u = |Theta(rho,
!! rho) - psi|/(2 A) directly. On the second half-arch the
!! values 2 F(R) - F(r) are taken as F(r) + 2 (F(R) - F(r)), the difference integrated
!! on its own pieces (`complement_pieces`): no cancellation next to the apse, and
!! fewer nodes than the whole half-arch.
!! **Next to the start** (tiny psi): on the unbounded branch next to the radial path
!! (P below 1/2 by the small-K law theta = (2/3) ((1 - 1/rho) P)^(3/2) (1 + O(P))) the
!! unknown is log P (`near_radial`; the curve keeps P exactly, `set_from_p`), bracketed
!! from that law: log g = log(3 - P) would carry P only to eps absolutely. The branch
!! split theta_c(rho) is taken from its series for rho - 1 < 0.04 (theta_c ~ 8 sqrt3 u^3,
!! the closed form's u-terms cancel), so that first and second half-arches with
!! rho - 1 down to 2^-112 are not sent to the unbounded branch. The secant step builds
!! its curve from x1's by the step itself (x cannot resolve it when |lambda| eps is
!! above it).
module brachistochrone_repulsive
    use brachistochrone_kinds, only: qp, pi, eps_qp, xp
    use brachistochrone_status, only: status_ok, status_psi_out_of_range, &
                                      status_not_finite, status_invalid_argument, &
                                      status_no_convergence, status_rho_below_start, &
                                      keep_first, first_failure
    use brachistochrone_quadrature, only: univariate_integrand, gauss_legendre_rule, &
            gauss_legendre, integrate_adaptive
    use brachistochrone_roots, only: root_function, bracketed_secant, anderson_bjorck_update
    use brachistochrone_quad_math, only: expm1
    use brachistochrone_fast_math, only: inverse_sqrt, fast_sqrt, hardware_real, quad_real
    use brachistochrone_solution, only: endpoint_status, region_outside
    use brachistochrone_arches, only: arch_unbounded, arch_first, arch_second
    use brachistochrone_repulsive_panels, only: panel_rules, new_panel_rules, panel_piece, &
            panel_curve, panel_integrals, panel_angle_xp, integrands, panel_slopes_xp, &
            max_pieces, piece_start, &
            piece_below, piece_above, piece_far, piece_arch, piece_apse, piece_arch_start
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan, ieee_value, &
                                             ieee_positive_inf
    use, intrinsic :: iso_fortran_env, only: real64
    implicit none
    private

    public :: repulsive_curve, repulsive_solution
    public :: curve_from_k2, curve_from_gap, curve_from_apse, curve_from_apse_gap
    public :: repulsive_values, critical_values, repulsive_radial_time
    public :: solve_repulsive
    public :: critical_k2, critical_floor
    public :: panel_values, panel_rules, new_panel_rules

    !> K^2 of the critical brachistochrone.
    real(qp), parameter :: critical_k2 = 27.0_qp/8.0_qp
    !> Smallest |g| (and 3 - 2R) used by the solver: about eps^1.75 ~ 1e-59, where
    !! sqrt(beta) ~ 1e-30 is still far above the rounding of a = (3 - g)/2.
    real(qp), parameter :: critical_floor = eps_qp**1.75_qp
    !> The critical curve's theta by its series below u = sqrt((r-1)/(r+3)) = 1/10
    !! (r - 1 below about 0.04; the series' ratio 9u^2 = 0.09 there, 35 terms)
    real(qp), parameter :: critical_series_end = 0.1_qp

    real(qp), parameter :: sqrt2 = sqrt(2.0_qp), sqrt3 = sqrt(3.0_qp), log_three = log(3.0_qp)
    !> Relative accuracy asked of each integral piece.
    real(qp), parameter :: integral_tolerance = 2.0_qp*eps_qp
    !> Breakpoints of the unbounded integrals: start piece up to x = 27/20, far piece
    !! beyond 4 (27/20 rather than 5/4: 3.5% fewer binary128 operations on the
    !! field-timing grid, the start piece's rule a little longer, the peak's shorter)
    real(qp), parameter :: start_end = 1.35_qp, far_start = 4.0_qp
    !> Bounded curves: R - r from 3 - 2r above this radius, from r - 1 below it
    real(qp), parameter :: gap_switch = 1.25_qp
    !> 3/2 - start_end: the reach of the pieces below the peak
    real(qp), parameter :: peak_reach = 1.5_qp - start_end
    integer, parameter :: max_steps = 300
    !> The apse's sinh map reaches `stretch` widths from the near-double root, in
    !! t = tanh(xi/2), where 1 - t (rounded absolutely) stays above 1/9, so that a node
    !! costs a few eps at most
    real(qp), parameter :: stretch = 8.0_qp
    !> The peak's sinh map (unbounded curves) reaches `peak_stretch` widths, in
    !! t = tanh(xi/4) (h/sqrt(beta) = sinh(xi) = 4t (1 + t^2)/(1 - t^2)^2): its poles
    !! t = +-1 stay twice as far (in xi) from the piece as in tanh(xi/2), so a piece
    !! needs about half the nodes, and 1 - t stays above 1/4 (16 widths rather than
    !! 32: 1.5% fewer binary128 operations on the field-timing grid)
    real(qp), parameter :: peak_stretch = 16.0_qp
    !> sin(nu/2) where the apse's sinh map hands over to the nu map (the map's own
    !! singularity is at sin(nu/2) = 1: at 1/2 its rule needs a third fewer nodes; at
    !! 0.35 the two pieces need 1% fewer binary128 operations on the field-timing grid,
    !! but the complete arches lose 0.7 digits against the mpmath references)
    real(qp), parameter :: apse_split = 0.5_qp
    integer, parameter :: want_angle = 1, want_length = 2, want_time = 3
    !> The radius argument that means the apse of a bounded curve (R itself may round to
    !! 1 when R - 1 is below binary128's spacing there)
    real(qp), parameter :: the_apse = -1.0_qp
    !> Added to arch_first, arch_second: the solver's unknown is u = sqrt(R - rho) (next
    !! to the apse, where R - rho would be formed by cancellation from lambda)
    integer, parameter :: near_apse = 100
    !> Next to the apse: |Theta(rho, rho) - psi| below this fraction of psi is below
    !! what the hardware phase resolves (its noise about 1e-19 of psi): the root is
    !! started from the square-root law and found by binary128 Newton steps
    real(qp), parameter :: apse_resolution = 1.0e-16_qp
    !> Binary128 Newton steps next to the apse at most (`apse_newton`)
    integer, parameter :: apse_iterations = 6
    !> The unbounded branch next to the radial path (P below 1/2): the unknown is
    !! log P, P = 3 - g (theta ~ (2/3) ((1 - 1/rho) P)^(3/2): log g = log(3 - P) would
    !! carry P only to eps absolutely, K^2 ~ P^3/2 to eps/P relatively)
    integer, parameter :: near_radial = 50
    !> More digits asked of the panels of F(R) - F(r) on the second half-arch when they
    !! end at r (counted twice; at 35 digits measured up to 7 eps off mpmath at R - 1 =
    !! 1e-20); none for a complete arch (r = 1: the difference is F(R) itself)
    real(real64), parameter :: complement_digits = 2.0_real64

    !> One brachistochrone from A, by its parameter. Build it with a `curve_from_*`.
    type :: repulsive_curve
        real(qp) :: k2 = 0.0_qp        !! K^2 (angular momentum of the free particle, squared)
        real(qp) :: k = 0.0_qp         !! K
        real(qp) :: gap = 3.0_qp       !! g = 3 - P: > 0 unbounded, 0 critical, < 0 bounded
        real(qp) :: p = 0.0_qp         !! P = -r3, the negative root of Q negated
        logical :: bounded = .false.   !! has an apse R < 3/2
        real(qp) :: centre = 0.0_qp    !! a = P/2 (unbounded, critical)
        real(qp) :: width2 = 0.0_qp    !! beta (unbounded): Q = (x + P)((x - a)^2 + beta)
        real(qp) :: apse = 0.0_qp      !! R (bounded)
        real(qp) :: apse_m1 = 0.0_qp   !! R - 1 (bounded)
        real(qp) :: apse_gap = 0.0_qp  !! 3 - 2R (bounded)
        real(qp) :: split = 0.0_qp     !! d = r2 - R (bounded)
        !> R - r for the radius r = r_gap_radius when the curve was made from it (exact;
        !! -1: none, R - r is then formed from 3 - 2R or R - 1)
        real(qp) :: r_gap = -1.0_qp
        real(qp) :: r_gap_radius = 0.0_qp  !! the radius r of r_gap
    end type repulsive_curve

    !> One brachistochrone of the two-point problem.
    type :: repulsive_solution
        real(qp) :: target = 0.0_qp     !! swept angle: psi + 2 pi m or 2 pi (m+1) - psi
        integer :: winding = 0          !! m
        logical :: clockwise = .false.  !! mirror image (reaches B turning clockwise)
        integer :: arch = arch_unbounded !! arch_unbounded, arch_first or arch_second
        type(repulsive_curve) :: curve  !! K, g and (bounded) R
        real(qp) :: angle = 0.0_qp      !! theta(rho) recomputed on the solution
        real(qp) :: arclength = 0.0_qp  !! s
        real(qp) :: time = 0.0_qp       !! t
        integer :: steps = 0            !! evaluations of theta by the root finder
        integer :: status = status_ok   !! status_ok or the reason
    end type repulsive_solution

    type, extends(univariate_integrand) :: repulsive_integrand
        integer :: kind = want_angle
        integer :: piece = piece_start
        real(qp) :: k = 0.0_qp, p = 0.0_qp, a = 0.0_qp, beta = 0.0_qp
        real(qp) :: span = 0.0_qp, rm1 = 0.0_qp, d = 0.0_qp
        logical :: stretched = .false.
    contains
        procedure :: evaluate => integrand_evaluate
    end type repulsive_integrand

    !> The hardware-precision iterates of `falsi_xp` (x, theta - target).
    type :: iterates
        integer :: n = 0
        real(qp) :: x(62) = 0.0_qp, f(62) = 0.0_qp
    end type iterates

    !> theta(rho) - target in the solver's unknown lambda (log g or log(3 - 2R)).
    type, extends(root_function) :: angle_mismatch
        real(qp) :: rho = 1.0_qp, target = 0.0_qp
        integer :: arch = arch_unbounded
        type(gauss_legendre_rule) :: rule  !! the 20-point rule, built once per solve
    contains
        procedure :: evaluate => mismatch_evaluate
    end type angle_mismatch

contains

    !> The curve with K^2 = k2 >= 0 (g to full relative accuracy from 27/8 - k2 near the
    !! critical value: the fixed point g = 8 c (4 - g)/(9 - 2g)^2, c = 27/8 - K^2).
    pure subroutine curve_from_k2(k2, curve, status)
        real(qp), intent(in) :: k2                  !! K^2 >= 0
        type(repulsive_curve), intent(out) :: curve !! the curve
        integer, intent(out) :: status              !! status_ok or the reason
        real(qp) :: p, p_new, g, g_new, c
        integer :: i
        status = status_ok
        if (.not. ieee_is_finite(k2)) then
            status = status_not_finite
            return
        else if (k2 < 0.0_qp) then
            status = status_invalid_argument
            return
        end if
        if (k2 == 0.0_qp) then
            call set_from_gap(3.0_qp, curve)
            return
        end if
        ! P^3 - 2 K^2 (P + 1) = 0: convex and increasing past the root; Newton from above
        p = 1.0_qp + sqrt(2.0_qp*k2)
        do i = 1, 400
            p_new = p - (p**3 - 2.0_qp*k2*(p + 1.0_qp))/(3.0_qp*p**2 - 2.0_qp*k2)
            if (.not. (p_new < p)) exit
            p = p_new
        end do
        g = 3.0_qp - p
        if (abs(g) < 1.0_qp) then
            c = critical_k2 - k2
            do i = 1, 400
                g_new = 8.0_qp*c*(4.0_qp - g)/(9.0_qp - 2.0_qp*g)**2
                if (g_new == g) exit
                g = g_new
            end do
        end if
        call set_from_gap(g, curve)
        curve%k2 = k2
        curve%k = sqrt(k2)
    end subroutine curve_from_k2

    !> The curve with gap g = 3 - P (g <= 3): g > 0 unbounded, 0 critical, < 0 bounded.
    pure subroutine curve_from_gap(g, curve, status)
        real(qp), intent(in) :: g                   !! gap, g <= 3
        type(repulsive_curve), intent(out) :: curve !! the curve
        integer, intent(out) :: status              !! status_ok or the reason
        status = status_ok
        if (.not. ieee_is_finite(g)) then
            status = status_not_finite
        else if (g > 3.0_qp) then
            status = status_invalid_argument
        else
            call set_from_gap(g, curve)
        end if
    end subroutine curve_from_gap

    !> The bounded curve with apse R, 1 < R < 3/2.
    pure subroutine curve_from_apse(big_r, curve, status)
        real(qp), intent(in) :: big_r               !! apse radius, 1 < R < 3/2
        type(repulsive_curve), intent(out) :: curve !! the curve
        integer, intent(out) :: status              !! status_ok or the reason
        status = status_ok
        if (.not. ieee_is_finite(big_r)) then
            status = status_not_finite
        else if (big_r <= 1.0_qp .or. big_r >= 1.5_qp) then
            status = status_invalid_argument
        else
            call set_bounded(big_r - 1.0_qp, 3.0_qp - 2.0_qp*big_r, curve)
        end if
    end subroutine curve_from_apse

    !> The bounded curve with apse R = (3 - e)/2 given by e = 3 - 2R in (0, 1): resolves
    !! R arbitrarily close to 3/2.
    pure subroutine curve_from_apse_gap(apse_gap, curve, status)
        real(qp), intent(in) :: apse_gap            !! e = 3 - 2R, 0 < e < 1
        type(repulsive_curve), intent(out) :: curve !! the curve
        integer, intent(out) :: status              !! status_ok or the reason
        status = status_ok
        if (.not. ieee_is_finite(apse_gap)) then
            status = status_not_finite
        else if (apse_gap <= 0.0_qp .or. apse_gap >= 1.0_qp) then
            status = status_invalid_argument
        else
            call set_bounded(0.5_qp*(1.0_qp - apse_gap), apse_gap, curve)
        end if
    end subroutine curve_from_apse_gap

    pure subroutine set_from_gap(g, curve)
        real(qp), intent(in) :: g
        type(repulsive_curve), intent(out) :: curve
        real(qp) :: p
        p = 3.0_qp - g
        curve%gap = g
        curve%p = p
        curve%k2 = p**3/(2.0_qp*(1.0_qp + p))
        curve%k = fast_sqrt(curve%k2)
        if (g >= 0.0_qp) then
            curve%bounded = .false.
            curve%centre = 0.5_qp*p
            curve%width2 = p*p*g/(4.0_qp*(p + 1.0_qp))
        else
            curve%bounded = .true.
            curve%split = p*fast_sqrt(-g/(p + 1.0_qp))
            curve%apse_m1 = 2.0_qp/((p + 1.0_qp)*(p - 2.0_qp + curve%split))
            curve%apse = 1.0_qp + curve%apse_m1
            if (curve%apse_m1 < 0.25_qp) then
                curve%apse_gap = 1.0_qp - 2.0_qp*curve%apse_m1
            else
                curve%apse_gap = g + curve%split
            end if
        end if
    end subroutine set_from_gap

    !> The unbounded curve with P = 3 - g given (0 < P < 3), P kept exactly (next to the
    !! radial path, where 3 - g would round P to eps absolutely).
    pure subroutine set_from_p(p, curve)
        real(qp), intent(in) :: p
        type(repulsive_curve), intent(out) :: curve
        call set_from_gap(3.0_qp - p, curve)
        curve%p = p
        curve%k2 = p**3/(2.0_qp*(1.0_qp + p))
        curve%k = fast_sqrt(curve%k2)
        curve%centre = 0.5_qp*p
        curve%width2 = p*p*curve%gap/(4.0_qp*(p + 1.0_qp))
    end subroutine set_from_p

    pure subroutine set_bounded(apse_m1, apse_gap, curve)
        real(qp), intent(in) :: apse_m1, apse_gap   ! R - 1 and 3 - 2R, consistent
        type(repulsive_curve), intent(out) :: curve
        real(qp) :: big_r, s, e
        big_r = 1.0_qp + apse_m1
        e = apse_gap
        s = fast_sqrt((big_r + 3.0_qp)/apse_m1)
        curve%bounded = .true.
        curve%apse = big_r
        curve%apse_m1 = apse_m1
        curve%apse_gap = e
        curve%split = 2.0_qp*big_r*e/(apse_m1*(s + 3.0_qp))
        curve%gap = -4.0_qp*e*e/(apse_m1*(s + 3.0_qp)* &
                                 (fast_sqrt((big_r + 3.0_qp)*apse_m1) + 3.0_qp - big_r))
        curve%p = 2.0_qp*big_r + curve%split
        curve%k2 = big_r**3/(2.0_qp*apse_m1)
        curve%k = fast_sqrt(curve%k2)
    end subroutine set_bounded

    !> The integrand of one piece (`brachistochrone_repulsive_panels%integrands`).
    pure function integrand_evaluate(self, x) result(y)
        class(repulsive_integrand), intent(in) :: self
        real(qp), intent(in) :: x          ! the piece's variable
        real(qp) :: y
        real(qp) :: values(3)
        call integrands(panel_curve(bounded=self%piece >= piece_arch, k=self%k, p=self%p, &
                                    a=self%a, beta=self%beta, span=self%span, rm1=self%rm1, &
                                    d=self%d), &
                        panel_piece(kind=self%piece, stretched=self%stretched), x, values)
        y = values(self%kind)
    end function integrand_evaluate

    pure subroutine add_piece(f, piece, lower, upper, rule, total, status)
        type(repulsive_integrand), intent(inout) :: f
        integer, intent(in) :: piece
        real(qp), intent(in) :: lower, upper
        type(gauss_legendre_rule), intent(in) :: rule
        real(qp), intent(inout) :: total
        integer, intent(inout) :: status
        real(qp) :: value, error
        integer :: stat
        if (.not. (upper > lower)) return
        f%piece = piece
        call integrate_adaptive(f, lower, upper, rule, integral_tolerance, 0.0_qp, value, &
                                error, stat)
        total = total + value
        call keep_first(status, stat)
    end subroutine add_piece

    !> One integral (kind) from radius 1 to r along the first (half-)arch, adaptively.
    pure subroutine first_integral(curve, kind, r, rule, value, status)
        type(repulsive_curve), intent(in) :: curve
        integer, intent(in) :: kind
        real(qp), intent(in) :: r
        type(gauss_legendre_rule), intent(in) :: rule
        real(qp), intent(out) :: value
        integer, intent(out) :: status
        type(repulsive_integrand) :: f
        type(panel_piece) :: pieces(max_pieces)
        integer :: n, i
        value = 0.0_qp
        status = status_ok
        call plan_pieces(curve, r, .false., pieces, n, f%span)
        f%kind = kind
        f%k = curve%k
        f%p = curve%p
        f%rm1 = curve%apse_m1
        f%d = curve%split
        f%a = curve%centre
        f%beta = curve%width2
        do i = 1, n
            f%stretched = pieces(i)%stretched
            call add_piece(f, pieces(i)%kind, pieces(i)%lower, pieces(i)%upper, rule, value, &
                           status)
        end do
    end subroutine first_integral

    !> The pieces (variable and interval) of the integrals from radius 1 to r along the
    !! first (half-)arch, and the start piece's span (unbounded). No piece when r = 1.
    !! `rough`: the square roots and tanh maps of the ends in hardware precision (about
    !! 1e-19), for the hardware-precision integrals only.
    pure subroutine plan_pieces(curve, r, rough, pieces, n, span)
        type(repulsive_curve), intent(in) :: curve
        real(qp), intent(in) :: r
        logical, intent(in) :: rough
        type(panel_piece), intent(out) :: pieces(max_pieces)
        integer, intent(out) :: n
        real(qp), intent(out) :: span
        real(qp) :: r_gap, c, s_mid, sin_mid, v_mid, v_r, big
        n = 0
        span = 0.0_qp
        if (r == 1.0_qp) return
        if (curve%bounded) then
            ! R - r from 3 - 2r (exact near 3/2) and the stored 3 - 2R: R itself may not
            ! be representable next to 3/2 (R = 3/2 - d/2 with d below eps)
            if (r == the_apse) then
                r_gap = 0.0_qp
            else if (curve%r_gap >= 0.0_qp .and. r == curve%r_gap_radius) then
                ! kept exactly (R itself rounds to r when R - r is below its rounding)
                r_gap = curve%r_gap
            else if (r >= curve%apse) then
                r_gap = 0.0_qp    ! the apse (R itself may be rounded: r = R is the apse)
            else if (r > gap_switch) then
                r_gap = 0.5_qp*((3.0_qp - 2.0_qp*r) - curve%apse_gap)
            else
                r_gap = curve%apse_m1 - (r - 1.0_qp)
            end if
            r_gap = max(r_gap, 0.0_qp)
            if (rough .and. range(1.0_xp) >= range(1.0_qp)) then
                call bounded_pieces_xp(curve, r, r_gap, pieces, n)
                return
            end if
            ! nu from nu_r to pi (x from r down to 1), in v = tan(nu/4) from v_r to 1;
            ! within `stretch` widths sqrt(d) of the apse (and nu < pi/3) the sinh map
            ! sin(nu/2) = c sinh(xi), c = sqrt(d/(R-1)), in w = tanh(xi/2), split where
            ! sinh(xi) = s_mid, so that both pieces meet at the same point to a few ulps
            c = rt(curve%split/curve%apse_m1)
            s_mid = min(stretch, apse_split/c)
            sin_mid = min(c*s_mid, 1.0_qp)
            v_mid = sin_mid/(1.0_qp + rt((1.0_qp - sin_mid)*(1.0_qp + sin_mid)))
            ! tan(nu_r/4) = tan(phi/2), phi = atan2(sqrt(r_gap), sqrt(r - 1))
            big = 0.0_qp
            v_r = 0.0_qp
            if (r_gap > 0.0_qp) then
                big = rt(r_gap + (r - 1.0_qp))
                v_r = rt(r_gap)/(rt(r - 1.0_qp) + big)
            end if
            if (v_r < v_mid) then
                call add(pieces, n, piece_apse, .false., ht(rt(r_gap/curve%split)), &
                         ht(s_mid))
                call add(pieces, n, piece_arch, .false., v_mid, 1.0_qp)
            else if (r - 1.0_qp < r_gap) then
                ! r next to the start: in mu = pi - nu from 0, so that the short interval
                ! keeps its relative accuracy as r -> 1
                call add(pieces, n, piece_arch_start, .false., 0.0_qp, &
                         rt(r - 1.0_qp)/(rt(r_gap) + big))
            else
                call add(pieces, n, piece_arch, .false., v_r, 1.0_qp)
            end if
            return
        end if
        span = min(r, start_end) - 1.0_qp
        call add(pieces, n, piece_start, .false., 0.0_qp, 1.0_qp)
        if (r <= start_end) return
        ! distances to the peak a = 3/2 - g/2 formed from 3/2 - r (exact near 3/2) and g,
        ! never from a rounded a: the peak's height 1/sqrt(beta) would amplify that
        associate (g2 => 0.5_qp*curve%gap)
            if (g2 < peak_reach) call peak_pieces(pieces, n, piece_below, &
                                               max((1.5_qp - r) - g2, 0.0_qp), peak_reach - g2)
            if ((1.5_qp - r) - g2 < 0.0_qp) call peak_pieces(pieces, n, piece_above, &
                    max(g2 - peak_reach, 0.0_qp), (min(r, far_start) - 1.5_qp) + g2)
        end associate
        if (r > far_start) call add(pieces, n, piece_far, .false., far_start/r, 1.0_qp)
    contains
        !> `root` (or hardware sqrt when rough and the hardware's exponent range is
        !! binary128's, as x87's is).
        elemental function rt(x) result(y)
            real(qp), intent(in) :: x
            real(qp) :: y
            if (rough .and. range(1.0_xp) >= range(1.0_qp)) then
                y = quad_real(sqrt(max(hardware_real(x), 0.0_xp)))
            else
                y = root(x)
            end if
        end function rt

        !> `half_tanh` (or in hardware precision when rough).
        elemental function ht(s) result(t)
            real(qp), intent(in) :: s
            real(qp) :: t
            real(xp) :: sx
            if (rough .and. range(1.0_xp) >= range(1.0_qp)) then
                sx = hardware_real(s)
                t = quad_real(sx/(1.0_xp + sqrt(1.0_xp + sx*sx)))
            else
                t = half_tanh(s)
            end if
        end function ht

        !> `quarter_tanh` in hardware precision (`on_map` then refines it when not
        !! rough), or in binary128 where the hardware's exponent range is smaller.
        elemental function qt(s) result(t)
            real(qp), intent(in) :: s
            real(qp) :: t
            real(xp) :: sx, ch
            if (range(1.0_xp) >= range(1.0_qp)) then
                sx = hardware_real(s)
                ch = sqrt(0.5_xp*(1.0_xp + sqrt(1.0_xp + sx*sx)))
                t = quad_real(0.5_xp*sx/(ch*(1.0_xp + ch)))
            else
                t = quarter_tanh(s)
            end if
        end function qt

        !> t moved (one Newton step) so that the map's h = sqrt(beta) 4t (1 + t^2)/(1 -
        !! t^2)^2, formed as the integrands form it, is h to a few roundings: an error
        !! of t itself would move h by up to 8 times more (not when rough).
        elemental function on_map(t, h, width) result(t_new)
            real(qp), intent(in) :: t, h, width
            real(qp) :: t_new, inv, h_t, slope
            t_new = t
            if (rough .or. .not. t > 0.0_qp) return
            inv = 1.0_qp/((1.0_qp - t)*(1.0_qp + t))
            h_t = (4.0_qp*width)*(t*(1.0_qp + t*t))*(inv*inv)
            slope = h_t*(1.0_qp/t + 2.0_qp*t/(1.0_qp + t*t) + 4.0_qp*t*inv)
            t_new = t - (h_t - h)/slope
        end function on_map

        !> h from h_lo to h_hi (distance to the peak at a): in the sinh map
        !! h = sqrt(beta) sinh(xi), in t = tanh(xi/4), up to `peak_stretch` widths
        !! sqrt(beta), plain h beyond.
        pure subroutine peak_pieces(pieces, n, kind, h_lo, h_hi)
            type(panel_piece), intent(inout) :: pieces(:)
            integer, intent(inout) :: n
            integer, intent(in) :: kind
            real(qp), intent(in) :: h_lo, h_hi
            real(qp) :: width, h_mid
            real(xp) :: width_x
            if (.not. (h_hi > h_lo)) return
            width = rt(curve%width2)
            if (curve%width2 > 0.0_qp .and. h_lo < peak_stretch*width) then
                h_mid = width*peak_stretch
                width_x = hardware_real(width)
                call add(pieces, n, kind, .true., &
                         on_map(qt(quad_real(hardware_real(h_lo)/width_x)), h_lo, width), &
                         on_map(qt(min(quad_real(hardware_real(h_hi)/width_x), &
                                       peak_stretch)), min(h_hi, h_mid), width))
                if (h_hi > h_mid) call add(pieces, n, kind, .false., h_mid, h_hi)
            else
                call add(pieces, n, kind, .false., h_lo, h_hi)
            end if
        end subroutine peak_pieces
    end subroutine plan_pieces

    !> The pieces of `plan_pieces` on a bounded curve (R - r = r_gap given) for the
    !! hardware-precision integrals: every end in hardware precision (about 1e-19),
    !! from the curve's numbers rounded once.
    pure subroutine bounded_pieces_xp(curve, r, r_gap, pieces, n)
        type(repulsive_curve), intent(in) :: curve
        real(qp), intent(in) :: r, r_gap
        type(panel_piece), intent(inout) :: pieces(max_pieces)
        integer, intent(inout) :: n
        real(xp) :: gap, rm1, d, c, s_mid, sin_mid, v_mid, v_r, big, r_m1
        gap = hardware_real(r_gap)
        rm1 = hardware_real(curve%apse_m1)
        d = hardware_real(curve%split)
        r_m1 = hardware_real(r - 1.0_qp)
        c = sqrt(d/rm1)
        s_mid = min(real(stretch, xp), real(apse_split, xp)/c)
        sin_mid = min(c*s_mid, 1.0_xp)
        v_mid = sin_mid/(1.0_xp + sqrt((1.0_xp - sin_mid)*(1.0_xp + sin_mid)))
        big = 0.0_xp
        v_r = 0.0_xp
        if (gap > 0.0_xp) then
            big = sqrt(gap + r_m1)
            v_r = sqrt(gap)/(sqrt(r_m1) + big)
        end if
        if (v_r < v_mid) then
            call add(pieces, n, piece_apse, .false., quad_real(half_tanh_xp(sqrt(gap/d))), &
                     quad_real(half_tanh_xp(s_mid)))
            call add(pieces, n, piece_arch, .false., quad_real(v_mid), 1.0_qp)
        else if (r_m1 < gap) then
            call add(pieces, n, piece_arch_start, .false., 0.0_qp, &
                     quad_real(sqrt(r_m1)/(sqrt(gap) + big)))
        else
            call add(pieces, n, piece_arch, .false., quad_real(v_r), 1.0_qp)
        end if
    end subroutine bounded_pieces_xp

    !> tanh(asinh(s)/2) in hardware precision, s >= 0.
    elemental function half_tanh_xp(s) result(t)
        real(xp), intent(in) :: s
        real(xp) :: t
        t = s/(1.0_xp + sqrt(1.0_xp + s*s))
    end function half_tanh_xp

    !> tanh(asinh(s)/4) = sinh(xi/2)/(1 + cosh(xi/2)), cosh(xi/2) = sqrt((1 + sqrt(1 +
    !! s^2))/2), sinh(xi/2) = s/(2 cosh(xi/2)) (xi = asinh(s)), s >= 0: no cancellation.
    elemental function quarter_tanh(s) result(t)
        real(qp), intent(in) :: s
        real(qp) :: t, ch
        ch = root(0.5_qp*(1.0_qp + root(1.0_qp + s*s)))
        t = 0.5_qp*s/(ch*(1.0_qp + ch))
    end function quarter_tanh

    !> tanh(asinh(s)/2) = s/(1 + sqrt(1 + s^2)), s >= 0.
    elemental function half_tanh(s) result(t)
        real(qp), intent(in) :: s
        real(qp) :: t
        t = s/(1.0_qp + root(1.0_qp + s*s))
    end function half_tanh

    !> sqrt(x) for x >= 0 within 2 ulp, from `inverse_sqrt` (a third of sqrt's cost): for
    !! the pieces' ends, where it is formed many times per endpoint.
    elemental function root(x) result(y)
        real(qp), intent(in) :: x
        real(qp) :: y
        y = 0.0_qp
        if (x > 0.0_qp) y = x*inverse_sqrt(x)
    end function root

    pure subroutine add(pieces, n, kind, stretched, lower, upper)
        type(panel_piece), intent(inout) :: pieces(:)
        integer, intent(inout) :: n
        integer, intent(in) :: kind
        logical, intent(in) :: stretched
        real(qp), intent(in) :: lower, upper
        if (.not. (upper > lower)) return
        n = n + 1
        pieces(n) = panel_piece(kind=kind, stretched=stretched, lower=lower, upper=upper)
    end subroutine add

    !> theta, s, t at radius r along `curve` from A. Unbounded curves (g >= 0): any
    !! 1 <= r <= +Infinity (theta converges; s and t are then +Infinity); the critical
    !! curve only r < 3/2 (it spirals towards 3/2). Bounded: 1 <= r <= R on the first
    !! half-arch, or on the second (`second`, eq. 29: 2 F(R) - F(r)) back to radius 1.
    pure subroutine repulsive_values(curve, r, second, angle, length, time, status)
        type(repulsive_curve), intent(in) :: curve !! the curve
        real(qp), intent(in) :: r                  !! radius
        logical, intent(in) :: second              !! on the second half-arch (bounded)
        real(qp), intent(out) :: angle, length, time !! theta, s, t at r
        integer, intent(out) :: status             !! status_ok or the reason
        type(gauss_legendre_rule) :: rule
        real(qp) :: apse(3)
        integer :: stat(6)
        angle = 0.0_qp
        length = 0.0_qp
        time = 0.0_qp
        if (ieee_is_nan(r)) then
            status = status_not_finite
            return
        end if
        if (r < 1.0_qp .or. (curve%bounded .and. r > curve%apse) .or. &
            (.not. curve%bounded .and. second) .or. &
            (curve%gap == 0.0_qp .and. r >= 1.5_qp)) then
            status = status_invalid_argument
            return
        end if
        rule = gauss_legendre(20)
        call first_integral(curve, want_angle, r, rule, angle, stat(1))
        if (ieee_is_finite(r)) then
            call first_integral(curve, want_length, r, rule, length, stat(2))
            call first_integral(curve, want_time, r, rule, time, stat(3))
        else
            length = ieee_value(length, ieee_positive_inf)
            time = length
            stat(2:3) = status_ok
        end if
        stat(4:6) = status_ok
        if (second) then
            call first_integral(curve, want_angle, the_apse, rule, apse(1), stat(4))
            call first_integral(curve, want_length, the_apse, rule, apse(2), stat(5))
            call first_integral(curve, want_time, the_apse, rule, apse(3), stat(6))
            angle = 2.0_qp*apse(1) - angle
            length = 2.0_qp*apse(2) - length
            time = 2.0_qp*apse(3) - time
        end if
        status = first_failure(stat)
    end subroutine repulsive_values

    !> theta, s, t at radius r as `repulsive_values` (same pieces), on fixed Gauss panels
    !! chosen from the located singularities (`brachistochrone_repulsive_panels`); the
    !! angle alone (`angle_only`) in hardware precision, about 19 digits. status:
    !! status_ok or status_no_convergence (too many panels: integrate adaptively).
    pure subroutine panel_values(curve, r, second, rules, angle_only, values, status)
        type(repulsive_curve), intent(in) :: curve !! the curve
        real(qp), intent(in) :: r                  !! radius, 1 <= r (<= R if bounded)
        logical, intent(in) :: second              !! on the second half-arch (bounded)
        type(panel_rules), intent(in) :: rules     !! the Gauss rules
        logical, intent(in) :: angle_only          !! theta in hardware precision only
        real(qp), intent(out) :: values(3)         !! theta, s, t (s, t: 0 if angle_only)
        integer, intent(out) :: status             !! status_ok or the reason
        type(panel_piece) :: pieces(max_pieces), apse_pieces(max_pieces), &
                             between(max_pieces)
        type(panel_curve) :: c
        real(qp) :: rest(3), span
        integer :: stat, n, n_apse, n_between
        c = panel_curve(bounded=curve%bounded, k=curve%k, p=curve%p, a=curve%centre, &
                        beta=curve%width2, rm1=curve%apse_m1, d=curve%split)
        call plan_pieces(curve, r, angle_only, pieces, n, c%span)
        call integrate(pieces(1:n), 0.0_real64, values, status)
        if (second) then
            ! 2 F(R) - F(r) = F(r) + 2 (F(R) - F(r)), the difference on its own pieces
            call plan_pieces(curve, the_apse, angle_only, apse_pieces, n_apse, span)
            call complement_pieces(pieces(1:n), apse_pieces(1:n_apse), between, n_between)
            call integrate(between(1:n_between), merge(complement_digits, 0.0_real64, &
                           n > 0), rest, stat)
            call keep_first(status, stat)
            values = values + 2.0_qp*rest
        end if
    contains
        pure subroutine integrate(some, extra, v, st)
            type(panel_piece), intent(in) :: some(:)
            real(real64), intent(in) :: extra
            real(qp), intent(out) :: v(3)
            integer, intent(out) :: st
            v = 0.0_qp
            if (angle_only) then
                call panel_angle_xp(rules, c, some, v(1), st)
            else
                call panel_integrals(rules, c, some, v, st, extra)
            end if
        end subroutine integrate
    end subroutine panel_values

    !> theta of the critical curve by its series in u (0 <= u < 1/3):
    !! 2 sqrt3 sum_k (9^k - (-3)^k) u^(2k+1)/(2k+1), k >= 1 (= 8 sqrt3 u^3 + ...); the
    !! closed form loses eps/(2 u^2) of it to the cancellation of its two u-terms.
    pure function critical_angle_series(u) result(angle)
        real(qp), intent(in) :: u
        real(qp) :: angle
        real(qp) :: u2, p9, p3, term
        integer :: k
        u2 = u*u
        p9 = u
        p3 = u
        angle = 0.0_qp
        do k = 1, 200
            p9 = 9.0_qp*u2*p9
            p3 = -3.0_qp*u2*p3
            term = (p9 - p3)/real(2*k + 1, qp)
            angle = angle + term
            if (abs(term) <= 0.25_qp*eps_qp*angle) exit
        end do
        angle = 2.0_qp*sqrt3*angle
    end function critical_angle_series

    !> `critical_angle_series` in hardware precision (u < 1/10: 20 terms at most).
    pure function critical_angle_series_xp(u) result(angle)
        real(xp), intent(in) :: u
        real(xp) :: angle
        real(xp) :: u2, p9, p3, term
        integer :: k
        u2 = u*u
        p9 = u
        p3 = u
        angle = 0.0_xp
        do k = 1, 200
            p9 = 9.0_xp*u2*p9
            p3 = -3.0_xp*u2*p3
            term = (p9 - p3)/real(2*k + 1, xp)
            angle = angle + term
            if (abs(term) <= 0.25_xp*epsilon(1.0_xp)*angle) exit
        end do
        angle = 2.0_xp*sqrt(3.0_xp)*angle
    end function critical_angle_series_xp

    !> The critical brachistochrone K^2 = 27/8, Q = (x - 3/2)^2 (x + 3), in closed form
    !! (1 <= r < 3/2). With u = sqrt((r-1)/(r+3)) (so x = (1+3u^2)/(1-u^2)),
    !! theta's integrand becomes 16u^2/((1+3u^2)(1-9u^2)) du and t's
    !! 2 sqrt2 (1+3u^2)^2/((1-9u^2)(1-u^2)^2) du; with w = sqrt(r/(r+3)) s's becomes
    !! 12 w^4/((1-3w^2)(1-w^2)^2) dw. Partial fractions give
    !!   theta = (2/sqrt3) atanh(3u) - 2 atan(sqrt3 u),
    !!   s     = sqrt3 (atanh(sqrt3 w) - atanh(sqrt3/2)) - (sqrt(r(r+3)) - 2),
    !!   t     = (3 atanh(3u) - atanh(u) - sqrt((r-1)(r+3)))/sqrt2.
    !! As r -> 3/2, 1 - 9u^2 = 4(3-2r)/(r+3) and 1 - 3w^2 = (3-2r)/(r+3) -> 0: theta, s, t
    !! grow like -log(3 - 2r)/sqrt3, -(sqrt3/2) log(3-2r), -(3/(2 sqrt2)) log(3-2r): the
    !! curve spirals round O infinitely often towards the circle r = 3/2, in infinite
    !! time. The atanh near 1 are taken from 3 - 2r (exact there) to keep the digits;
    !! theta for u < `critical_series_end` by its series (`critical_angle_series`).
    pure subroutine critical_values(r, angle, length, time, status)
        real(qp), intent(in) :: r                    !! radius, 1 <= r < 3/2
        real(qp), intent(out) :: angle, length, time !! theta, s, t at r
        integer, intent(out) :: status               !! status_ok or the reason
        real(qp) :: u, w, e, atanh_3u, atanh_3w
        angle = 0.0_qp
        length = 0.0_qp
        time = 0.0_qp
        if (.not. ieee_is_finite(r)) then
            status = status_not_finite
            return
        else if (r < 1.0_qp .or. r >= 1.5_qp) then
            status = status_invalid_argument
            return
        end if
        status = status_ok
        u = sqrt((r - 1.0_qp)/(r + 3.0_qp))
        w = sqrt(r/(r + 3.0_qp))
        e = 3.0_qp - 2.0_qp*r
        atanh_3u = log(1.0_qp + 3.0_qp*u) - 0.5_qp*log(4.0_qp*e/(r + 3.0_qp))
        atanh_3w = log(1.0_qp + sqrt3*w) - 0.5_qp*log(e/(r + 3.0_qp))
        if (u < critical_series_end) then
            angle = critical_angle_series(u)
        else
            angle = 2.0_qp/sqrt3*atanh_3u - 2.0_qp*atan(sqrt3*u)
        end if
        length = sqrt3*(atanh_3w - atanh(0.5_qp*sqrt3)) - (sqrt(r*(r + 3.0_qp)) - 2.0_qp)
        time = (3.0_qp*atanh_3u - atanh(u) - sqrt((r - 1.0_qp)*(r + 3.0_qp)))/sqrt2
    end subroutine critical_values

    !> Time of the radial motion (K = 0) from rest at radius 1 to r >= 1, eq. (49):
    !! t = (sqrt(r (r - 1)) + asinh(sqrt(r - 1)))/sqrt2.
    pure function repulsive_radial_time(r) result(time)
        real(qp), intent(in) :: r !! radius, r >= 1
        real(qp) :: time
        time = (sqrt(r*(r - 1.0_qp)) + asinh(sqrt(r - 1.0_qp)))/sqrt2
    end function repulsive_radial_time

    !> The curve of the solver's unknown lambda: unbounded g = exp(lambda); bounded
    !! 3 - 2R = exp(lambda), R - 1 = -expm1(lambda)/2 (accurate as R -> 1 too).
    pure subroutine curve_of_lambda(arch, lambda, curve, rho)
        integer, intent(in) :: arch
        real(qp), intent(in) :: lambda
        type(repulsive_curve), intent(out) :: curve
        real(qp), intent(in), optional :: rho !! the endpoint (arch + near_apse only)
        if (arch > near_apse) then
            call set_near_apse(rho, lambda*lambda, curve)
        else if (arch == arch_unbounded) then
            call set_from_gap(exp(lambda), curve)
        else if (arch == near_radial) then
            call set_from_p(exp(lambda), curve)
        else
            call set_bounded(-0.5_qp*expm1(lambda), exp(lambda), curve)
        end if
    end subroutine curve_of_lambda

    !> A curve within about 1e-19 of lambda's (relative), exactly one of the family:
    !! g (unbounded) or 3 - 2R, or R - 1 where that is the smaller (bounded), is
    !! lambda's in hardware precision, rounded there and taken as exact, and the other
    !! numbers follow from it in binary128 (no binary128 exponential: the Newton step
    !! of `solve_branch_fast` moves from whatever curve it starts at); next to the
    !! apse, or where the hardware's exponent range is smaller, `curve_of_lambda`.
    pure subroutine curve_near_lambda(arch, lambda, curve, rho)
        integer, intent(in) :: arch
        real(qp), intent(in) :: lambda
        type(repulsive_curve), intent(out) :: curve
        real(qp), intent(in) :: rho
        real(xp) :: x, e
        real(qp) :: m
        if (arch > near_apse .or. arch == near_radial .or. &
            range(1.0_xp) < range(1.0_qp)) then
            call curve_of_lambda(arch, lambda, curve, rho)
            return
        end if
        x = real(lambda, xp)
        e = exp(x)
        if (arch == arch_unbounded) then
            call set_from_gap(real(e, qp), curve)
        else if (e >= 0.5_xp) then
            ! R - 1 = -expm1(x)/2 = sinh(x/2) exp(x/2) the smaller: 3 - 2R = 1 - 2 (R - 1)
            m = real(-sinh(0.5_xp*x)*exp(0.5_xp*x), qp)
            call set_bounded(m, 1.0_qp - 2.0_qp*m, curve)
        else
            call set_bounded(0.5_qp*(1.0_qp - real(e, qp)), real(e, qp), curve)
        end if
    end subroutine curve_near_lambda

    !> `curve_of_lambda` at x = x0 + dx from the curve at x0 (curve0, made by
    !! `curve_of_lambda` or `curve_near_lambda`), |dx| <= 1e-12: exp(x0 + dx) = exp(x0)
    !! (1 + dx + dx^2/2) to a rounding, no binary128 exponential; next to the apse
    !! `curve_of_lambda` at x.
    pure subroutine curve_after_step(arch, curve0, dx, x, curve, rho)
        integer, intent(in) :: arch
        type(repulsive_curve), intent(in) :: curve0
        real(qp), intent(in) :: dx, x, rho
        type(repulsive_curve), intent(out) :: curve
        real(qp) :: step
        if (arch > near_apse .or. .not. abs(dx) <= 1.0e-12_qp) then
            call curve_of_lambda(arch, x, curve, rho)
            return
        end if
        ! exp(x) = exp(x0) + exp(x0) expm1(dx), expm1(x) = expm1(x0) + exp(x0) expm1(dx)
        step = dx*(1.0_qp + 0.5_qp*dx)
        if (arch == arch_unbounded) then
            call set_from_gap(curve0%gap + curve0%gap*step, curve)
        else if (arch == near_radial) then
            call set_from_p(curve0%p + curve0%p*step, curve)
        else
            call set_bounded(curve0%apse_m1 - 0.5_qp*(curve0%apse_gap*step), &
                             curve0%apse_gap + curve0%apse_gap*step, curve)
        end if
    end subroutine curve_after_step

    !> The bounded curve with apse R = rho + r_gap, R - rho kept exactly.
    pure subroutine set_near_apse(rho, r_gap, curve)
        real(qp), intent(in) :: rho, r_gap
        type(repulsive_curve), intent(out) :: curve
        call set_bounded((rho - 1.0_qp) + r_gap, (3.0_qp - 2.0_qp*rho) - 2.0_qp*r_gap, curve)
        curve%r_gap = r_gap
        curve%r_gap_radius = rho
    end subroutine set_near_apse

    !> `curve_of_lambda` with exp and expm1 in hardware precision (about 1e-19): for
    !! the hardware-precision evaluations, at a fraction of binary128's cost.
    pure subroutine rough_curve_of_lambda(arch, lambda, curve, rho)
        integer, intent(in) :: arch
        real(qp), intent(in) :: lambda
        type(repulsive_curve), intent(out) :: curve
        real(qp), intent(in) :: rho
        real(xp) :: x, e
        x = hardware_real(lambda)
        e = exp(x)
        if (arch > near_apse) then
            call set_near_apse(rho, real(x*x, qp), curve)
        else if (arch == arch_unbounded) then
            call set_from_gap_rough(e, curve)
        else if (arch == near_radial) then
            call set_from_gap_rough(3.0_xp - e, curve, e)
        else
            ! expm1(x) = 2 sinh(x/2) exp(x/2), accurate as x -> 0
            call set_bounded_rough(-sinh(0.5_xp*x)*exp(0.5_xp*x), e, curve)
        end if
    end subroutine rough_curve_of_lambda

    !> `set_bounded` in hardware precision (R - 1 and 3 - 2R exact as given, the
    !! curve's other numbers to about 1e-19), no binary128 square root or division.
    pure subroutine set_bounded_rough(apse_m1, apse_gap, curve)
        real(xp), intent(in) :: apse_m1, apse_gap
        type(repulsive_curve), intent(out) :: curve
        real(xp) :: big_r, s, split, k2
        if (range(1.0_xp) < range(1.0_qp)) then
            call set_bounded(quad_real(apse_m1), quad_real(apse_gap), curve)
            return
        end if
        big_r = 1.0_xp + apse_m1
        s = sqrt((big_r + 3.0_xp)/apse_m1)
        split = 2.0_xp*big_r*apse_gap/(apse_m1*(s + 3.0_xp))
        k2 = big_r**3/(2.0_xp*apse_m1)
        curve%bounded = .true.
        curve%apse_m1 = quad_real(apse_m1)
        curve%apse = 1.0_qp + curve%apse_m1
        curve%apse_gap = quad_real(apse_gap)
        curve%split = quad_real(split)
        curve%gap = quad_real(-4.0_xp*apse_gap*apse_gap/(apse_m1*(s + 3.0_xp)* &
                              (sqrt((big_r + 3.0_xp)*apse_m1) + 3.0_xp - big_r)))
        curve%p = quad_real(2.0_xp*big_r + split)
        curve%k2 = quad_real(k2)
        curve%k = quad_real(sqrt(k2))
    end subroutine set_bounded_rough

    !> `set_from_gap` of an unbounded curve (g > 0) in hardware precision: the
    !! curve's numbers to about 1e-19 (g itself exact), no binary128 square root.
    pure subroutine set_from_gap_rough(g, curve, p_exact)
        real(xp), intent(in) :: g
        type(repulsive_curve), intent(out) :: curve
        real(xp), intent(in), optional :: p_exact !! P = 3 - g itself (`near_radial`)
        real(xp) :: p, k2
        if (range(1.0_xp) < range(1.0_qp)) then
            call set_from_gap(quad_real(g), curve)
            if (present(p_exact)) call set_from_p(quad_real(p_exact), curve)
            return
        end if
        p = 3.0_xp - g
        if (present(p_exact)) p = p_exact
        k2 = p**3/(2.0_xp*(1.0_xp + p))
        curve%gap = quad_real(g)
        curve%p = quad_real(p)
        curve%k2 = quad_real(k2)
        curve%k = quad_real(sqrt(k2))
        curve%bounded = .false.
        curve%centre = quad_real(0.5_xp*p)
        curve%width2 = quad_real(p*p*g/(4.0_xp*(p + 1.0_xp)))
    end subroutine set_from_gap_rough

    pure subroutine mismatch_evaluate(self, x, f, df, status)
        class(angle_mismatch), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp), intent(out) :: f, df
        integer, intent(out) :: status
        type(repulsive_curve) :: curve
        real(qp) :: angle, apse
        integer :: stat
        df = 0.0_qp
        call curve_of_lambda(self%arch, x, curve)
        call first_integral(curve, want_angle, self%rho, self%rule, angle, status)
        if (self%arch == arch_second) then
            call first_integral(curve, want_angle, the_apse, self%rule, apse, stat)
            angle = 2.0_qp*apse - angle
            call keep_first(status, stat)
        end if
        f = angle - self%target
    end subroutine mismatch_evaluate

    !> The brachistochrone from A through B = (rho, psi) sweeping the angle `target`
    !! (> 0) on the branch `arch`, whose unknown lambda has the known end value
    !! f_top = theta - target at lambda_top; lambda is walked down until f changes sign.
    pure subroutine solve_branch(rho, target, arch, lambda_top, f_top, solution)
        real(qp), intent(in) :: rho, target, lambda_top, f_top
        integer, intent(in) :: arch
        type(repulsive_solution), intent(inout) :: solution
        type(angle_mismatch) :: fun
        real(qp) :: lo, f_lo, hi, f_hi, x, df, floor
        integer :: steps, status, walks
        fun%rho = rho
        fun%target = target
        fun%arch = arch
        fun%rule = gauss_legendre(20)
        solution%arch = arch
        floor = log(critical_floor)
        hi = lambda_top
        f_hi = f_top
        lo = hi
        walks = 0
        x = lambda_top
        steps = 0
        ! f_top = 0: the target is the angle at the top of the branch (B is the apse)
        do while (f_top /= 0.0_qp)
            lo = max(lo - 4.0_qp, floor)
            call fun%evaluate(lo, f_lo, df, status)
            walks = walks + 1
            if (status /= status_ok) then
                solution%status = status
                return
            end if
            if ((f_lo > 0.0_qp) .neqv. (f_hi > 0.0_qp)) then
                ! bounded: lambda -> 0 as R -> 1 (R - 1 = -expm1(lambda)/2), relative only
                call bracketed_secant(fun, lo, f_lo, hi, f_hi, 4.0_qp*eps_qp, &
                                      merge(4.0_qp*eps_qp, tiny(1.0_qp), &
                                      arch == arch_unbounded), max_steps, x, steps, status)
                if (status /= status_ok) then
                    solution%status = status
                    return
                end if
                exit
            end if
            if (lo <= floor) then
                ! the angle is not reached before g (or 3 - 2R) = critical_floor
                solution%status = status_no_convergence
                return
            end if
            hi = lo
            f_hi = f_lo
        end do
        solution%steps = steps + walks
        call curve_of_lambda(arch, x, solution%curve)
        call repulsive_values(solution%curve, rho, arch == arch_second, &
                              solution%angle, solution%arclength, solution%time, status)
        solution%status = status
        ! the curve found must sweep the target (its error is far below 1e-20 of it
        ! wherever the secant converged; an unresolved unknown is a failure, not a value)
        if (status == status_ok .and. .not. abs(solution%angle - target) <= &
            1.0e-20_qp*target) solution%status = status_no_convergence
    end subroutine solve_branch

    !> theta(rho) - target on the curve of lambda, in hardware precision (fast panels).
    pure subroutine mismatch_xp(rho, target, arch, rules, lambda, f, status)
        real(qp), intent(in) :: rho, target, lambda
        integer, intent(in) :: arch
        type(panel_rules), intent(in) :: rules
        real(qp), intent(out) :: f
        integer, intent(out) :: status
        type(repulsive_curve) :: curve
        real(qp) :: values(3)
        call rough_curve_of_lambda(arch, lambda, curve, rho)
        call panel_values(curve, rho, mod(arch, near_apse) == arch_second, rules, .true., &
                          values, status)
        f = values(1) - target
    end subroutine mismatch_xp

    !> d theta/d lambda and d s/d lambda at radius r (second half-arch: 2 F(R) - F(r))
    !! on the curve of lambda, by the complex step in hardware precision (about 18
    !! digits; `panel_slopes_xp`), and theta, s, t there in binary128 on the same
    !! pieces; on the second half-arch as F(r) + 2 (F(R) - F(r)), the difference
    !! integrated on its own pieces (`complement_pieces`: no cancellation next to the
    !! apse, and fewer nodes than F(R)). status, value_status: status_ok or a failure
    !! of the slopes, of the values.
    pure subroutine lambda_slopes(arch, curve, r, rules, slopes, status, values, &
                                  value_status)
        integer, intent(in) :: arch
        type(repulsive_curve), intent(in) :: curve
        real(qp), intent(in) :: r
        type(panel_rules), intent(in) :: rules
        real(qp), intent(out) :: slopes(2), values(3)
        integer, intent(out) :: status, value_status
        real(qp) :: apse(2), rest(3)
        type(panel_piece) :: pieces(max_pieces), apse_pieces(max_pieces), &
                             between(max_pieces)
        type(panel_curve) :: c
        integer :: stat, n, n_apse, n_between
        c = panel_curve(bounded=curve%bounded, k=curve%k, p=curve%p, a=curve%centre, &
                        beta=curve%width2, rm1=curve%apse_m1, d=curve%split)
        call one_end(r, c, slopes, status, pieces, n)
        call panel_integrals(rules, c, pieces(1:n), values, value_status)
        if (mod(arch, near_apse) == arch_second) then
            call one_end(the_apse, c, apse, stat, apse_pieces, n_apse)
            call keep_first(status, stat)
            slopes = 2.0_qp*apse - slopes
            call complement_pieces(pieces(1:n), apse_pieces(1:n_apse), between, n_between)
            call panel_integrals(rules, c, between(1:n_between), rest, stat, &
                                 merge(complement_digits, 0.0_real64, n > 0))
            call keep_first(value_status, stat)
            values = values + 2.0_qp*rest
        end if
    contains
        pure subroutine one_end(radius, c, v, st, pieces, n)
            real(qp), intent(in) :: radius
            type(panel_curve), intent(inout) :: c
            real(qp), intent(out) :: v(2)
            integer, intent(out) :: st
            type(panel_piece), intent(out) :: pieces(max_pieces)
            integer, intent(out) :: n
            complex(xp) :: cc(7), lower_c(max_pieces), upper_c(max_pieces)
            real(xp) :: h
            ! the step 1e-40, next to the apse far below u = sqrt(R - rho) (the end
            ! sqrt(R - r) = u + i h is analytic only for h << u)
            h = 1.0e-40_xp
            if (curve%r_gap > 0.0_qp) h = min(h, 1.0e-20_xp*sqrt(real(curve%r_gap, xp)))
            v = 0.0_qp
            call plan_pieces(curve, radius, .false., pieces, n, c%span)
            call complex_step(curve, radius, h, c%span, pieces(1:n), cc, lower_c, upper_c, &
                              arch == near_radial)
            call panel_slopes_xp(rules, c, pieces(1:n), lower_c(1:n), upper_c(1:n), cc, h, &
                                 v, st)
        end subroutine one_end
    end subroutine lambda_slopes

    !> The pieces of F(R) - F(r) on a bounded curve (apse R, 1 <= r <= R) from those of
    !! F(r) and of F(R) (`plan_pieces`): the apse's sinh map from the apse to r's end
    !! when r's first piece is in it, else the sinh map's whole piece and the nu map
    !! from its end to r (v_r = tan(nu_r/4) = (1 - m)/(1 + m) from r's piece in
    !! m = tan(mu_r/4), mu = pi - nu, next to the start).
    pure subroutine complement_pieces(pieces_r, pieces_apse, between, n)
        type(panel_piece), intent(in) :: pieces_r(:), pieces_apse(:)
        type(panel_piece), intent(out) :: between(max_pieces)
        integer, intent(out) :: n
        real(qp) :: v_r
        integer :: i
        n = 0
        if (size(pieces_r) == 0) then
            between(1:size(pieces_apse)) = pieces_apse
            n = size(pieces_apse)
            return
        end if
        if (pieces_r(1)%kind == piece_apse) then
            call add(between, n, piece_apse, .false., 0.0_qp, pieces_r(1)%lower)
            return
        end if
        if (pieces_r(1)%kind == piece_arch_start) then
            v_r = (1.0_qp - pieces_r(1)%upper)/(1.0_qp + pieces_r(1)%upper)
        else
            v_r = pieces_r(1)%lower
        end if
        do i = 1, size(pieces_apse)
            if (pieces_apse(i)%kind == piece_apse) then
                call add(between, n, piece_apse, .false., pieces_apse(i)%lower, &
                         pieces_apse(i)%upper)
            else if (pieces_apse(i)%kind == piece_arch) then
                call add(between, n, piece_arch, .false., pieces_apse(i)%lower, v_r)
            end if
        end do
    end subroutine complement_pieces

    !> The curve's numbers [K, P, a, beta, span, R - 1, d] and the ends of its pieces
    !! (`plan_pieces`) at radius r as complex hardware numbers x + i h dx/dlambda, the
    !! unknown lambda = log g (unbounded) or log(3 - 2R) (bounded) moved by i h.
    pure subroutine complex_step(curve, r, h, span, pieces, cc, lower_c, upper_c, radial)
        type(repulsive_curve), intent(in) :: curve
        real(qp), intent(in) :: r, span
        real(xp), intent(in) :: h
        type(panel_piece), intent(in) :: pieces(:)
        complex(xp), intent(out) :: cc(7), lower_c(:), upper_c(:)
        logical, intent(in) :: radial !! unbounded, the unknown log P (dg = -P dlambda)
        complex(xp) :: g, p, big_r, rm1, e, d, rg, c, s_mid, sin_mid, big, a, width
        real(xp) :: sg, se
        integer :: i
        ! every real part is the binary128 value rounded (differences near the peak or
        ! the apse are formed there); the complex operations only carry the derivatives
        cc = (0.0_xp, 0.0_xp)
        if (.not. curve%bounded) then
            sg = real(curve%gap, xp)
            if (radial) sg = -real(curve%p, xp)
            g = cmplx(real(curve%gap, xp), sg*h, xp)
            p = cmplx(real(curve%p, xp), -sg*h, xp)
            a = 0.5_xp*p
            width = sqrt(p*p*g/(4.0_xp*(p + 1.0_xp)))
            cc = [sqrt(p**3/(2.0_xp*(1.0_xp + p))), p, a, width*width, &
                  cmplx(real(span, xp), 0.0_xp, xp), (0.0_xp, 0.0_xp), (0.0_xp, 0.0_xp)]
            cc(1:4) = real_part(cc(1:4), [curve%k, curve%p, curve%centre, curve%width2])
            width = real_part(width, sqrt(curve%width2))
            do i = 1, size(pieces)
                select case (pieces(i)%kind)
                case (piece_start)
                    lower_c(i) = 0.0_xp
                    upper_c(i) = 1.0_xp
                case (piece_far)
                    lower_c(i) = real(far_start/r, xp)
                    upper_c(i) = 1.0_xp
                case default
                    call peak_ends(pieces(i)%kind, pieces(i)%stretched, &
                                   i > 1 .and. pieces(max(i - 1, 1))%stretched .and. &
                                   pieces(max(i - 1, 1))%kind == pieces(i)%kind, &
                                   lower_c(i), upper_c(i))
                end select
            end do
            lower_c(1:size(pieces)) = real_part(lower_c(1:size(pieces)), pieces%lower)
            upper_c(1:size(pieces)) = real_part(upper_c(1:size(pieces)), pieces%upper)
            return
        end if
        se = real(curve%apse_gap, xp)
        e = cmplx(se, se*h, xp)
        rm1 = cmplx(real(curve%apse_m1, xp), -0.5_xp*se*h, xp)
        if (curve%r_gap >= 0.0_qp) then
            ! the unknown is u = sqrt(R - rho): d(R - rho) = dR = 2u du
            sg = 2.0_xp*sqrt(real(curve%r_gap, xp))
            e = cmplx(se, -2.0_xp*sg*h, xp)
            rm1 = cmplx(real(curve%apse_m1, xp), sg*h, xp)
        end if
        big_r = 1.0_xp + rm1
        d = 2.0_xp*big_r*e/(rm1*(sqrt((big_r + 3.0_xp)/rm1) + 3.0_xp))
        d = real_part(d, curve%split)
        cc = [sqrt(big_r**3/(2.0_xp*rm1)), 2.0_xp*big_r + d, (0.0_xp, 0.0_xp), &
              (0.0_xp, 0.0_xp), (0.0_xp, 0.0_xp), rm1, d]
        cc(1:2) = [real_part(cc(1), curve%k), real_part(cc(2), curve%p)]
        ! as in plan_pieces (R - r with its binary128 real part)
        if (r == the_apse) then
            rg = 0.0_xp
        else if (curve%r_gap >= 0.0_qp .and. r == curve%r_gap_radius) then
            rg = cmplx(real(curve%r_gap, xp), 2.0_xp*sqrt(real(curve%r_gap, xp))*h, xp)
        else if (r >= curve%apse) then
            rg = 0.0_xp
        else if (r > gap_switch) then
            rg = real_part(-0.5_xp*e, 0.5_qp*((3.0_qp - 2.0_qp*r) - curve%apse_gap))
        else
            rg = real_part(rm1, curve%apse_m1 - (r - 1.0_qp))
        end if
        if (.not. real(rg) > 0.0_xp) rg = 0.0_xp
        c = sqrt(d/rm1)
        s_mid = real(apse_split, xp)/c
        if (real(s_mid) > real(stretch, xp)) s_mid = real(stretch, xp)
        sin_mid = c*s_mid
        if (real(sin_mid) > 1.0_xp) sin_mid = 1.0_xp
        big = 0.0_xp
        if (real(rg) > 0.0_xp) big = sqrt(rg + real(r - 1.0_qp, xp))
        do i = 1, size(pieces)
            upper_c(i) = 1.0_xp
            select case (pieces(i)%kind)
            case (piece_apse)
                lower_c(i) = half_tanh_c(sqrt(rg/d))
                upper_c(i) = half_tanh_c(s_mid)
            case (piece_arch_start)
                lower_c(i) = 0.0_xp
                upper_c(i) = sqrt(real(r - 1.0_qp, xp))/(sqrt(rg) + big)
            case default
                if (i > 1) then
                    lower_c(i) = sin_mid/(1.0_xp + sqrt((1.0_xp - sin_mid)*(1.0_xp + sin_mid)))
                else
                    lower_c(i) = sqrt(rg)/(sqrt(real(r - 1.0_qp, xp)) + big)
                end if
            end select
        end do
        lower_c(1:size(pieces)) = real_part(lower_c(1:size(pieces)), pieces%lower)
        upper_c(1:size(pieces)) = real_part(upper_c(1:size(pieces)), pieces%upper)
    contains
        !> The ends of a piece below or above the peak (`plan_pieces`' peak_pieces).
        pure subroutine peak_ends(kind, stretched, after_stretched, lower, upper)
            integer, intent(in) :: kind
            logical, intent(in) :: stretched, after_stretched
            complex(xp), intent(out) :: lower, upper
            complex(xp) :: h_lo, h_hi
            real(qp) :: ac
            ac = 0.5_qp*curve%gap   ! 3/2 - a, as in plan_pieces
            if (kind == piece_below) then
                h_lo = 0.0_xp
                if ((1.5_qp - r) - ac > 0.0_qp) h_lo = real_part(a, (1.5_qp - r) - ac)
                h_hi = real_part(a, peak_reach - ac)
            else
                h_lo = 0.0_xp
                if (ac > peak_reach) h_lo = real_part(-a, ac - peak_reach)
                h_hi = real_part(-a, (min(r, far_start) - 1.5_qp) + ac)
            end if
            if (stretched) then
                lower = quarter_tanh_c(h_lo/width)
                upper = h_hi/width
                if (real(upper) > real(peak_stretch, xp)) upper = real(peak_stretch, xp)
                upper = quarter_tanh_c(upper)
            else if (after_stretched) then
                lower = width*real(peak_stretch, xp)
                upper = h_hi
            else
                lower = h_lo
                upper = h_hi
            end if
        end subroutine peak_ends
    end subroutine complex_step

    !> The complex number with the imaginary part of z and the real part x (rounded).
    elemental function real_part(z, x) result(w)
        complex(xp), intent(in) :: z
        real(qp), intent(in) :: x
        complex(xp) :: w
        w = cmplx(real(x, xp), aimag(z), xp)
    end function real_part

    !> `quarter_tanh` in complex hardware precision.
    elemental function quarter_tanh_c(s) result(t)
        complex(xp), intent(in) :: s
        complex(xp) :: t, ch
        ch = sqrt(0.5_xp*(1.0_xp + sqrt(1.0_xp + s*s)))
        t = 0.5_xp*s/(ch*(1.0_xp + ch))
    end function quarter_tanh_c

    !> tanh(asinh(s)/2) = s/(1 + sqrt(1 + s^2)) in complex hardware precision.
    elemental function half_tanh_c(s) result(t)
        complex(xp), intent(in) :: s
        complex(xp) :: t
        t = s/(1.0_xp + sqrt(1.0_xp + s*s))
    end function half_tanh_c

    !> The fast path of `solve_branch`: the bracket and the root to about 1e-17 on
    !! hardware-precision panels (regula falsi with the Anderson-Bjorck correction), the
    !! slope and curvature there from its iterates (`history_slope`) or differences; one
    !! binary128 evaluation and the Newton step on the complex-step slopes (see the module
    !! notes); else two binary128 evaluations of theta, s, t: at that root x0 and at its
    !! Newton step x1. The secant through both
    !! gives the root x; s and t are interpolated there. Certified when |f(x1)| <= 1e-6
    !! |f(x0)| (the step converged as Newton's does) and the secant's and the
    !! interpolation's error, curvature |x - x0| |x - x1|, is below a rounding of x.
    !! `done` is false otherwise (or on any failure): the caller then solves adaptively.
    pure subroutine solve_branch_fast(rho, target, arch, lambda_top, f_top, rules, &
                                      solution, done)
        real(qp), intent(in) :: rho, target, lambda_top, f_top
        integer, intent(in) :: arch
        type(panel_rules), intent(in) :: rules
        type(repulsive_solution), intent(inout) :: solution
        logical, intent(out) :: done
        real(qp) :: lo, f_lo, hi, f_hi, x0, fx0, x1, x, h, f_plus, f_minus, slope
        real(qp) :: curvature, v0(3), v1(3), f0, f1, floor, rate(3), slopes(2), dx
        real(qp) :: scale, check
        integer :: status, steps, stat(2)
        type(repulsive_curve) :: curve
        type(iterates) :: seen
        logical :: found, from_law
        done = .false.
        if (f_top == 0.0_qp) return
        floor = log(critical_floor)
        hi = lambda_top
        f_hi = f_top
        lo = hi
        steps = 0
        ! theta - target below what the hardware phase resolves next to the apse
        from_law = arch > near_apse .and. abs(f_top) <= apse_resolution*target
        if (from_law) then
            ! the root from the square-root law (f = f_top -+ 2 A u + O(u^2): f there is 0
            ! to O(u^2))
            lo = 0.0_qp
            hi = sqrt(0.25_qp*(3.0_qp - 2.0_qp*rho))
            x0 = min(abs(f_top)/(2.0_qp*sqrt((rho - 1.0_qp)/(rho*(3.0_qp - 2.0_qp*rho)))), &
                     0.5_qp*hi)
            fx0 = 0.0_qp
        else if (arch > near_apse) then
            call near_apse_bracket(rho, target, arch, f_top, rules, lo, f_lo, hi, f_hi, &
                                   steps, status)
            if (status /= status_ok) return
        else if (arch == near_radial) then
            call near_radial_bracket(rho, target, rules, lo, f_lo, hi, f_hi, steps, status)
            if (status /= status_ok) return
        else
            do
                lo = max(lo - 4.0_qp, floor)
                call mismatch_xp(rho, target, arch, rules, lo, f_lo, status)
                steps = steps + 1
                if (status /= status_ok) return
                if ((f_lo > 0.0_qp) .neqv. (f_hi > 0.0_qp)) exit
                if (lo <= floor) return
                hi = lo
                f_hi = f_lo
            end do
        end if
        seen%n = 0
        if (.not. from_law) then
            call falsi_xp(rho, target, arch, rules, lo, f_lo, hi, f_hi, x0, fx0, steps, &
                          status, seen)
            if (status /= status_ok) return
        end if
        stat = status_ok
        call history_slope(seen, x0, fx0, lambda_scale(arch, x0), slope, curvature, h, found)
        if (arch < near_apse .and. .not. found) then
            ! one more iterate 1e-6 away (one evaluation, not the two of central
            ! differences) usually completes the quadratic
            h = min(1.0e-6_qp*lambda_scale(arch, x0), 0.5_qp*(hi - x0))
            if (h > 1.0e-8_qp*lambda_scale(arch, x0) .and. seen%n < size(seen%x)) then
                seen%n = seen%n + 1
                seen%x(seen%n) = x0 + h
                call mismatch_xp(rho, target, arch, rules, x0 + h, seen%f(seen%n), stat(1))
                steps = steps + 1
                if (stat(1) /= status_ok) return
                call history_slope(seen, x0, fx0, lambda_scale(arch, x0), slope, &
                                   curvature, h, found)
            end if
        end if
        if (arch < near_apse .and. found) then
            ! slope and curvature from the quadratic through x0 and two earlier iterates
            check = 1.0e-6_qp
            steps = steps - 2
        else if (arch > near_apse) then
            ! u may be far below the hardware phase's noise: one-sided differences over
            ! 1e-3 of the square-root law's reach, from x0 up (theta is smooth in u
            ! there); the slope cross-check to 1e-2
            h = 1.0e-3_qp*sqrt(0.25_qp*min(3.0_qp - 2.0_qp*rho, rho - 1.0_qp))
            call mismatch_xp(rho, target, arch, rules, x0 + h, f_plus, stat(1))
            call mismatch_xp(rho, target, arch, rules, x0 + 2.0_qp*h, f_minus, stat(2))
            slope = (f_plus - fx0)/h
            curvature = abs(f_minus - 2.0_qp*f_plus + fx0)/(h*h)/abs(2.0_qp*slope) + 1.0_qp
            check = 1.0e-2_qp
        else
            h = min(1.0e-6_qp*lambda_scale(arch, x0), 0.5_qp*(x0 - lo), 0.5_qp*(hi - x0))
            if (.not. h > 0.0_qp) return
            call mismatch_xp(rho, target, arch, rules, x0 + h, f_plus, stat(1))
            call mismatch_xp(rho, target, arch, rules, x0 - h, f_minus, stat(2))
            slope = (f_plus - f_minus)/(2.0_qp*h)
            curvature = abs(f_plus - 2.0_qp*fx0 + f_minus)/(h*h)/abs(2.0_qp*slope) + 1.0_qp
            check = 1.0e-6_qp
        end if
        steps = steps + 2
        if (any(stat /= status_ok)) return
        if (arch > near_apse) then
            call apse_newton(rho, target, arch, rules, [x0, lo, hi], slope, &
                             curvature, check*abs(slope) + 1.0e-17_qp*target/h, steps, &
                             solution, done)
            return
        end if
        ! one binary128 evaluation, the Newton step on the complex-step slopes
        call curve_near_lambda(arch, x0, curve, rho)
        call lambda_slopes(arch, curve, rho, rules, slopes, stat(2), v0, stat(1))
        f0 = v0(1) - target
        if (any(stat /= status_ok)) return
        steps = steps + 1
        ! the error of x that moves theta, s or t by a rounding
        scale = lambda_scale(arch, x0)
        ! the cross-check against the central difference, to its rounding noise
        if (abs(slopes(1) - slope) <= check*abs(slopes(1)) + 1.0e-17_qp*target/h) then
            dx = -f0/slopes(1)
            x = x0 + dx
            if (x > lo .and. x < hi .and. 1.0e-17_qp*abs(dx) + curvature*dx*dx <= &
                2.0_qp*eps_qp*scale) then
                call newton_solution(rho, arch, curve, x0, dx, v0, slopes, f0, steps, &
                                     solution)
                done = .true.
                return
            end if
        end if
        ! the complex-step slope when it is within 1e-3 of the differences' (their own
        ! error when the curvature is large; the secant below certifies it by the
        ! residual's decrease)
        if (abs(slopes(1) - slope) <= 1.0e-3_qp*abs(slopes(1))) slope = slopes(1)
        ! else a second binary128 evaluation at the Newton step, and the secant (v0 again
        ! at x0 itself: the curve of `curve_near_lambda` may be 1e-19 away)
        if ((arch == arch_unbounded .or. arch == arch_first .or. arch == arch_second) .and. &
            range(1.0_xp) >= range(1.0_qp)) then
            call curve_of_lambda(arch, x0, curve, rho)
            call panel_values(curve, rho, mod(arch, near_apse) == arch_second, rules, &
                              .false., v0, stat(1))
            f0 = v0(1) - target
            steps = steps + 1
            if (stat(1) /= status_ok) return
        end if
        x1 = x0 - f0/slope
        call curve_of_lambda(arch, x1, curve, rho)
        call panel_values(curve, rho, mod(arch, near_apse) == arch_second, rules, .false., &
                          v1, stat(2))
        f1 = v1(1) - target
        steps = steps + 2
        if (any(stat /= status_ok) .or. .not. (x1 > lo .and. x1 < hi)) return
        if (f1 == f0 .or. abs(x1 - x0) > 1.0e-12_qp*scale) return
        if (abs(f1) > 1.0e-6_qp*abs(f0) .and. abs(f1) > 4.0_qp*eps_qp*target) &
            return
        rate = (v1 - v0)/(x1 - x0)
        ! the curve from x1's by the step dx itself (x may not resolve it: |lambda| eps)
        dx = -f1/rate(1)
        x = x1 + dx
        if (curvature*abs((x1 - x0) + dx)*abs(dx) > eps_qp*scale) return
        call curve_after_step(arch, curve, dx, x, solution%curve, rho)
        solution%arch = mod(arch, near_apse)
        solution%angle = v1(1) + rate(1)*dx
        solution%arclength = v1(2) + rate(2)*dx
        solution%time = v1(3) + rate(3)*dx
        solution%steps = steps
        solution%status = status_ok
        done = .true.
    end subroutine solve_branch_fast

    !> Next to the apse (the unknown u = sqrt(R - rho), R - rho = u^2 kept exactly): Newton
    !! steps in u on binary128 evaluations of theta, s, t with the complex-step slopes
    !! (`lambda_slopes`) from u = start(1) (the hardware phase's root, or the square-root
    !! law's when theta - target is below what that phase resolves), each step certified
    !! as `solve_branch_fast`'s: accepted when 1e-17 |du| + curvature du^2 is below a
    !! rounding of u (the u that moves theta, s or t by a rounding), else taken and
    !! evaluated again (at most `apse_iterations`; theta is analytic in u next to u = 0,
    !! so each step squares the relative error). `slope`: the hardware phase's
    !! difference slope, which the first complex-step slope must match to `tolerance`.
    !! `done` false on any failure or a step leaving (start(2), start(3)).
    pure subroutine apse_newton(rho, target, arch, rules, start, slope, curvature, &
                                tolerance, steps, solution, done)
        real(qp), intent(in) :: rho, target, start(3), slope, curvature, tolerance
        integer, intent(in) :: arch
        type(panel_rules), intent(in) :: rules
        integer, intent(inout) :: steps
        type(repulsive_solution), intent(inout) :: solution
        logical, intent(out) :: done
        type(repulsive_curve) :: curve
        real(qp) :: u, v(3), slopes(2), f, dx, scale
        integer :: stat(2), i
        done = .false.
        u = start(1)
        do i = 1, apse_iterations
            call curve_of_lambda(arch, u, curve, rho)
            call lambda_slopes(arch, curve, rho, rules, slopes, stat(2), v, stat(1))
            steps = steps + 1
            if (any(stat /= status_ok) .or. slopes(1) == 0.0_qp) return
            if (i == 1 .and. .not. abs(slopes(1) - slope) <= tolerance) return
            f = v(1) - target
            ! the error of u that moves theta, s or t by a rounding
            scale = 1.0_qp/max(abs(slopes(1))/target, abs(slopes(2)/v(2)), &
                               abs(curve%k*slopes(1)/v(3)), tiny(1.0_qp))
            dx = -f/slopes(1)
            if (.not. (u + dx > start(2) .and. u + dx < start(3))) return
            if (1.0e-17_qp*abs(dx) + curvature*dx*dx <= 2.0_qp*eps_qp*scale) then
                call newton_solution(rho, arch, curve, u, dx, v, slopes, f, steps, &
                                     solution)
                done = .true.
                return
            end if
            u = u + dx
        end do
    end subroutine apse_newton

    !> The solution of the certified Newton step dx from x0 (curve, values v0 and
    !! slopes there, f0 = theta - target): theta and s along the slopes, t by
    !! Hamilton-Jacobi (at fixed rho dt/dtheta = K, the conserved momentum).
    pure subroutine newton_solution(rho, arch, curve, x0, dx, v0, slopes, f0, steps, &
                                    solution)
        real(qp), intent(in) :: rho, x0, dx, v0(3), slopes(2), f0
        integer, intent(in) :: arch, steps
        type(repulsive_curve), intent(in) :: curve
        type(repulsive_solution), intent(inout) :: solution
        type(repulsive_curve) :: middle
        call curve_after_step(arch, curve, dx, x0 + dx, solution%curve, rho)
        ! (K at the midpoint to 1e-19 is ample: it multiplies f0, below 1e-16)
        call rough_curve_of_lambda(arch, x0 + 0.5_qp*dx, middle, rho)
        solution%arch = mod(arch, near_apse)
        solution%angle = v0(1) + slopes(1)*dx
        solution%arclength = v0(2) + slopes(2)*dx
        solution%time = v0(3) - middle%k*f0
        solution%steps = steps
        solution%status = status_ok
    end subroutine newton_solution

    !> The bracket of u = sqrt(R - rho) next to the apse, from the square-root law there:
    !! theta(rho) = Theta(rho, rho) -+ 2 A u + O(u^2) on the first (second) half-arch,
    !! A = sqrt((rho - 1)/(rho (3 - 2 rho))) (from Q'(R) = R^2 (2R - 3)/(R - 1)), widened
    !! by factors 4 until theta - target changes sign (R - rho up to (3 - 2 rho)/4).
    !! status: status_ok, status_no_convergence (no bracket) or an evaluation's failure.
    pure subroutine near_apse_bracket(rho, target, arch, f_top, rules, lo, f_lo, hi, f_hi, &
                                      steps, status)
        real(qp), intent(in) :: rho, target, f_top
        integer, intent(in) :: arch
        type(panel_rules), intent(in) :: rules
        real(qp), intent(out) :: lo, f_lo, hi, f_hi
        integer, intent(inout) :: steps
        integer, intent(out) :: status
        real(qp) :: centre, top
        integer :: i
        centre = abs(f_top)/(2.0_qp*sqrt((rho - 1.0_qp)/(rho*(3.0_qp - 2.0_qp*rho))))
        top = sqrt(0.25_qp*(3.0_qp - 2.0_qp*rho))
        lo = 0.5_qp*min(centre, top)
        hi = min(2.0_qp*centre, top)
        call mismatch_xp(rho, target, arch, rules, lo, f_lo, status)
        if (status /= status_ok) return
        call mismatch_xp(rho, target, arch, rules, hi, f_hi, status)
        steps = steps + 2
        do i = 1, 40
            if (status /= status_ok) return
            if ((f_lo > 0.0_qp) .neqv. (f_hi > 0.0_qp)) return
            ! f -> f_top as u -> 0
            if ((f_hi > 0.0_qp) .eqv. (f_top > 0.0_qp)) then
                if (hi >= top) exit
                lo = hi
                f_lo = f_hi
                hi = min(4.0_qp*hi, top)
                call mismatch_xp(rho, target, arch, rules, hi, f_hi, status)
            else
                hi = lo
                f_hi = f_lo
                lo = 0.25_qp*lo
                call mismatch_xp(rho, target, arch, rules, lo, f_lo, status)
            end if
            steps = steps + 1
        end do
        status = status_no_convergence
    end subroutine near_apse_bracket

    !> The bracket of log P next to the radial path from theta ~ (2/3) ((1 - 1/rho) P)^(3/2)
    !! (small K: Q ~ x^3, K^2 ~ P^3/2; theta is a little above it at that P), widened by
    !! steps doubling from 1/2 until theta - target changes sign, P below 2.9.
    !! status: status_ok, status_no_convergence (no bracket) or an evaluation's failure.
    pure subroutine near_radial_bracket(rho, target, rules, lo, f_lo, hi, f_hi, steps, status)
        real(qp), intent(in) :: rho, target
        type(panel_rules), intent(in) :: rules
        real(qp), intent(out) :: lo, f_lo, hi, f_hi
        integer, intent(inout) :: steps
        integer, intent(out) :: status
        real(qp) :: estimate, width, top
        integer :: i
        top = log(2.9_qp)
        estimate = (2.0_qp*log(1.5_qp*target) - 3.0_qp*log((rho - 1.0_qp)/rho))/3.0_qp
        width = 0.5_qp
        lo = min(estimate - 0.0625_qp, top - width)
        hi = min(estimate + 0.0625_qp, top)
        call mismatch_xp(rho, target, near_radial, rules, lo, f_lo, status)
        if (status /= status_ok) return
        call mismatch_xp(rho, target, near_radial, rules, hi, f_hi, status)
        steps = steps + 2
        do i = 1, 40
            if (status /= status_ok) return
            if (f_lo <= 0.0_qp .and. f_hi > 0.0_qp) return
            if (f_hi <= 0.0_qp) then
                if (hi >= top) exit
                lo = hi
                f_lo = f_hi
                hi = min(hi + width, top)
                call mismatch_xp(rho, target, near_radial, rules, hi, f_hi, status)
            else
                hi = lo
                f_hi = f_lo
                lo = lo - width
                call mismatch_xp(rho, target, near_radial, rules, lo, f_lo, status)
            end if
            width = 2.0_qp*width
            steps = steps + 1
        end do
        status = status_no_convergence
    end subroutine near_radial_bracket

    !> The scale of lambda's absolute error: 1 for unbounded curves (g = exp(lambda));
    !! on bounded ones R - 1 = -expm1(lambda)/2 is relative to lambda as R -> 1, so
    !! min(1, |lambda|).
    elemental function lambda_scale(arch, lambda) result(scale)
        integer, intent(in) :: arch
        real(qp), intent(in) :: lambda
        real(qp) :: scale
        scale = 1.0_qp
        if (arch == arch_first .or. arch == arch_second) &
            scale = max(min(1.0_qp, abs(lambda)), tiny(1.0_qp))
        if (arch > near_apse) scale = max(abs(lambda), tiny(1.0_qp))
    end function lambda_scale

    !> The slope and curvature (|f''|/|2 f'| + 1, as from central differences) at the last
    !! iterate x0 from the quadratic through it and the two nearest earlier iterates at
    !! least 1e-8 (relative to `scale`, so that the hardware noise, 1e-19 of the target,
    !! stays below 1e-11 of the slope) and at most 1e-2 from it, the product of their
    !! distances below 1e-8 (the quadratic's own error); h: the nearer distance
    !! (the noise of the slope is about 1e-19 target/h). `found` false when there are no
    !! such two iterates (the caller then takes central differences).
    pure subroutine history_slope(seen, x0, f0, scale, slope, curvature, h, found)
        type(iterates), intent(in) :: seen
        real(qp), intent(in) :: x0, f0, scale
        real(qp), intent(out) :: slope, curvature, h
        logical, intent(out) :: found
        real(qp) :: d(2), x(2), f(2), dist, s1, s2, second
        integer :: i, j
        slope = 0.0_qp
        curvature = 0.0_qp
        h = 0.0_qp
        d = huge(1.0_qp)
        x = 0.0_qp
        f = 0.0_qp
        do i = 1, seen%n
            dist = abs(seen%x(i) - x0)
            if (dist < 1.0e-8_qp*scale .or. dist > 1.0e-2_qp*scale) cycle
            if ((d(1) < huge(1.0_qp) .and. seen%x(i) == x(1)) .or. &
                (d(2) < huge(1.0_qp) .and. seen%x(i) == x(2))) cycle
            j = merge(1, 2, dist < d(1))
            if (j == 2 .and. .not. dist < d(2)) cycle
            if (j == 1) then
                d(2) = d(1)
                x(2) = x(1)
                f(2) = f(1)
            end if
            d(j) = dist
            x(j) = seen%x(i)
            f(j) = seen%f(i)
        end do
        ! the quadratic's error in the slope, about f'''(x0) d1 d2/6, far below the check
        found = d(2) < huge(1.0_qp) .and. d(1)*d(2) <= 1.0e-8_qp*scale*scale
        if (.not. found) return
        s1 = (f(1) - f0)/(x(1) - x0)
        s2 = (f(2) - f0)/(x(2) - x0)
        second = (s2 - s1)/(x(2) - x(1))
        slope = s1 + second*(x0 - x(1))
        found = slope /= 0.0_qp
        if (.not. found) return
        curvature = abs(second)/abs(slope) + 1.0_qp
        h = d(1)
    end subroutine history_slope

    !> Regula falsi (Anderson-Bjorck) on the hardware-precision mismatch from the bracket
    !! [lo, hi], to 1e-17 of lambda or to the evaluations' noise; x, fx: the last iterate.
    !! status: status_ok or an evaluation's failure (running out of steps is not one:
    !! the result is only the start of the binary128 phase, which certifies).
    pure subroutine falsi_xp(rho, target, arch, rules, lo, f_lo, hi, f_hi, x, fx, steps, &
                             status, seen)
        real(qp), intent(in) :: rho, target, lo, f_lo, hi, f_hi
        integer, intent(in) :: arch
        type(panel_rules), intent(in) :: rules
        real(qp), intent(out) :: x, fx
        integer, intent(inout) :: steps
        integer, intent(out) :: status
        !> every iterate (x, f) (the bracket's ends first), for `history_slope`
        type(iterates), intent(out) :: seen
        real(qp) :: a, b, fa, fb
        integer :: side, i
        a = lo
        b = hi
        fa = f_lo
        fb = f_hi
        side = 0
        status = status_ok
        x = b
        fx = fb
        seen%n = 2
        seen%x(1:2) = [a, b]
        seen%f(1:2) = [fa, fb]
        do i = 1, 60
            x = (a*fb - b*fa)/(fb - fa)
            if (.not. (x > min(a, b) .and. x < max(a, b))) x = 0.5_qp*(a + b)
            call mismatch_xp(rho, target, arch, rules, x, fx, status)
            steps = steps + 1
            seen%n = seen%n + 1
            seen%x(seen%n) = x
            seen%f(seen%n) = fx
            if (status /= status_ok) return
            if (abs(fx) <= 1.0e-18_qp*target) return
            call anderson_bjorck_update(x, fx, a, fa, b, fb, side)
            if (abs(b - a) <= 1.0e-17_qp*lambda_scale(arch, x)) return
        end do
    end subroutine falsi_xp

    !> The two-point problem: every brachistochrone from A = (1, 0) to B = (rho, psi)
    !! sweeping an angle psi + 2 pi m (anticlockwise) or 2 pi (m + 1) - psi (clockwise,
    !! the mirror image), m = 0..max_windings, in increasing order of the swept angle
    !! (which is also increasing time, see the module notes); `best` indexes the least
    !! time. One solution per target angle (the branch through rho is monotone).
    !! Solutions that need g or 3 - 2R below `critical_floor` carry
    !! status_no_convergence.
    pure subroutine solve_repulsive(rho, psi, max_windings, solutions, best, status, mirror, &
                                    rules)
        real(qp), intent(in) :: rho        !! endpoint radius, rho >= 1
        real(qp), intent(in) :: psi        !! endpoint angle, 0 <= psi <= pi
        integer, intent(in) :: max_windings !! largest m (>= 0)
        type(repulsive_solution), allocatable, intent(out) :: solutions(:) !! by angle
        integer, intent(out) :: best       !! index of the least time (0 if none)
        integer, intent(out) :: status     !! status_ok or the reason for bad input
        !> Also the clockwise mirror images (default .true.); without them only the
        !! anticlockwise targets psi + 2 pi m, which include the least time
        logical, intent(in), optional :: mirror
        !> Gauss rules of the fast panels (`new_panel_rules`; built here when absent)
        type(panel_rules), intent(in), optional :: rules
        type(panel_rules) :: own_rules
        real(qp) :: target, angle_critical, angle_apse
        integer :: m, sense, n
        logical :: mirror_distinct
        best = 0
        allocate (solutions(0))
        status = endpoint_status(rho, psi, region_outside)
        if (status /= status_ok) then
            return
        else if (max_windings < 0) then
            status = status_invalid_argument
            return
        end if
        if (.not. present(rules)) own_rules = new_panel_rules()
        if (present(rules)) then
            call branch_angles(rho, rules, angle_critical, angle_apse, status)
        else
            call branch_angles(rho, own_rules, angle_critical, angle_apse, status)
        end if
        if (status /= status_ok) return
        mirror_distinct = psi > 0.0_qp .and. psi < pi
        if (present(mirror)) mirror_distinct = mirror_distinct .and. mirror
        deallocate (solutions)
        allocate (solutions(merge(2, 1, mirror_distinct)*(max_windings + 1)))
        n = 0
        do m = 0, max_windings
            do sense = 0, merge(1, 0, mirror_distinct)
                n = n + 1
                if (sense == 0) then
                    target = psi + 2.0_qp*pi*real(m, qp)
                else
                    target = 2.0_qp*pi*real(m + 1, qp) - psi
                end if
                solutions(n)%target = target
                solutions(n)%winding = m
                solutions(n)%clockwise = sense == 1
                if (present(rules)) then
                    call solve_target(rho, target, angle_critical, angle_apse, rules, &
                                      solutions(n))
                else
                    call solve_target(rho, target, angle_critical, angle_apse, own_rules, &
                                      solutions(n))
                end if
            end do
        end do
        best = least_time(solutions)
    end subroutine solve_repulsive

    !> For 1 < rho < 3/2, the angles at rho of the critical curve and of the curve with
    !! its apse at rho, which split the targets among the branches (0 otherwise); both
    !! in hardware precision (`solve_target` takes them in binary128 when a target is
    !! within 1e-15 of one). status: status_ok or the first failure of those integrals.
    pure subroutine branch_angles(rho, rules, angle_critical, angle_apse, status)
        real(qp), intent(in) :: rho
        type(panel_rules), intent(in) :: rules
        real(qp), intent(out) :: angle_critical, angle_apse
        integer, intent(out) :: status
        type(repulsive_curve) :: curve
        real(qp) :: values(3)
        real(xp) :: u, e
        integer :: stat(3)
        angle_critical = 0.0_qp
        angle_apse = 0.0_qp
        status = status_ok
        if (.not. (rho > 1.0_qp .and. rho < 1.5_qp)) return
        ! the critical curve's angle of `critical_values` (3 - 2 rho formed in binary128)
        u = sqrt(real((rho - 1.0_qp)/(rho + 3.0_qp), xp))
        e = real((3.0_qp - 2.0_qp*rho)/(rho + 3.0_qp), xp)
        angle_critical = real(2.0_xp/sqrt(3.0_xp)*(log(1.0_xp + 3.0_xp*u) - &
                              0.5_xp*log(4.0_xp*e)) - 2.0_xp*atan(sqrt(3.0_xp)*u), qp)
        ! next to the start theta_c ~ 8 sqrt3 u^3: the closed form's two u-terms cancel
        if (u < real(critical_series_end, xp)) &
            angle_critical = real(critical_angle_series_xp(u), qp)
        stat(1) = status_ok
        call curve_from_apse(rho, curve, stat(2))
        call panel_values(curve, rho, .false., rules, .true., values, stat(3))
        angle_apse = values(1)
        if (stat(3) /= status_ok) call apse_angle_exact(rho, rules, angle_apse, stat(3))
        status = first_failure(stat)
    end subroutine branch_angles

    !> Theta(rho, rho) of the curve with its apse at rho, in binary128: fast panels, or
    !! adaptively when they decline. status: status_ok or the integral's failure.
    pure subroutine apse_angle_exact(rho, rules, angle_apse, status)
        real(qp), intent(in) :: rho
        type(panel_rules), intent(in) :: rules
        real(qp), intent(out) :: angle_apse
        integer, intent(out) :: status
        type(repulsive_curve) :: curve
        real(qp) :: values(3)
        call curve_from_apse(rho, curve, status)
        call panel_values(curve, rho, .false., rules, .false., values, status)
        angle_apse = values(1)
        if (status /= status_ok) then
            call first_integral(curve, want_angle, rho, gauss_legendre(20), angle_apse, &
                                status)
        end if
    end subroutine apse_angle_exact

    !> The curve from A through (rho, target): the radial path for target 0, else the
    !! branch that holds the target (complete arches when rho = 1).
    pure subroutine solve_target(rho, target, angle_critical_xp, angle_apse_xp, rules, &
                                 solution)
        real(qp), intent(in) :: rho, target, angle_critical_xp, angle_apse_xp
        type(panel_rules), intent(in) :: rules
        type(repulsive_solution), intent(inout) :: solution
        integer :: stat_values, near
        real(qp) :: angle_apse, angle_critical, dummy(2)
        angle_apse = angle_apse_xp
        angle_critical = angle_critical_xp
        if (rho > 1.0_qp .and. rho < 1.5_qp .and. &
            abs(target - angle_critical) <= 1.0e-15_qp*target) then
            call critical_values(rho, angle_critical, dummy(1), dummy(2), stat_values)
        end if
        if (rho > 1.0_qp .and. rho < 1.5_qp .and. &
            abs(target - angle_apse) <= 1.0e-15_qp*target) then
            call apse_angle_exact(rho, rules, angle_apse, stat_values)
            if (stat_values /= status_ok) then
                solution%status = stat_values
                return
            end if
        end if
        if (target == 0.0_qp .or. below_range(rho, target)) then
            ! psi = 0, m = 0: the radial path (K = 0); B = A when rho = 1. A target so small
            ! that K^2 underflows (`below_range`): s and t are the radial path's to O(K^2)
            call set_from_gap(3.0_qp, solution%curve)
            solution%arch = arch_unbounded
            call repulsive_values(solution%curve, rho, .false., solution%angle, &
                                  solution%arclength, solution%time, stat_values)
            solution%angle = target
            solution%status = stat_values
        else if (rho == 1.0_qp) then
            ! complete arches: lambda = log(3 - 2R) up to 0 (R -> 1, angle -> 0)
            call solve_fast_or_slow(rho, target, arch_second, 0.0_qp, -target, &
                                    rules, solution)
        else if (rho >= 1.5_qp .or. target < angle_critical) then
            ! next to the radial path (P below 1/2 by theta's small-K law) the unknown is
            ! log P, else log g
            near = merge(near_radial, arch_unbounded, 2.0_xp*log(1.5_xp*real(target, xp)) - &
                         3.0_xp*(log(real(rho - 1.0_qp, xp)) - log(real(rho, xp))) < &
                         3.0_xp*log(0.5_xp))
            call solve_fast_or_slow(rho, target, near, log_three, -target, rules, solution)
        else
            ! next to the apse (R - rho below 1e-4 of 3 - 2 rho and of rho - 1 by the
            ! square-root law of near_apse_bracket) the unknown is sqrt(R - rho)
            near = merge(near_apse, 0, ((angle_apse - target)/2.0_qp)**2* &
                         (rho*(3.0_qp - 2.0_qp*rho))/(rho - 1.0_qp) < &
                         1.0e-4_qp*min(3.0_qp - 2.0_qp*rho, rho - 1.0_qp))
            call solve_fast_or_slow(rho, target, merge(arch_first, arch_second, &
                                    target <= angle_apse) + near, log(3.0_qp - 2.0_qp*rho), &
                                    angle_apse - target, rules, solution)
        end if
    end subroutine solve_target

    !> Whether K^2 of the curve through (rho, target) is below the smallest normal
    !! binary128 number: by theta's small-K law theta = (2/3)((1 - 1/rho) P)^(3/2) and
    !! 2 K^2 = P^3/(1 + P), K^2 ~ (3 theta/2)^2/(2 (1 - 1/rho)^3) (e.g. psi = 1e-3000 at
    !! rho = 1001; in logarithms: nothing underflows). The curve is then the radial path
    !! to far more than 34 digits in s and t (they differ from it by O(K^2)).
    pure logical function below_range(rho, target)
        real(qp), intent(in) :: rho, target
        below_range = rho > 1.0_qp .and. target > 0.0_qp
        if (.not. below_range) return
        ! in hardware precision where its exponent range is binary128's (x87): the
        ! threshold is far from any rounding of the logarithms
        if (range(1.0_xp) >= range(1.0_qp)) then
            below_range = 2.0_xp*log(1.5_xp*real(target, xp)) - log(2.0_xp) &
                - 3.0_xp*log(real((rho - 1.0_qp)/rho, xp)) < real(log(tiny(1.0_qp)), xp)
        else
            below_range = 2.0_qp*log(1.5_qp*target) - log(2.0_qp) &
                - 3.0_qp*log((rho - 1.0_qp)/rho) < log(tiny(1.0_qp))
        end if
    end function below_range

    !> One target on one branch: the fast path, else the adaptive one.
    pure subroutine solve_fast_or_slow(rho, target, arch, lambda_top, f_top, rules, &
                                       solution)
        real(qp), intent(in) :: rho, target, lambda_top, f_top
        integer, intent(in) :: arch
        type(panel_rules), intent(in) :: rules
        type(repulsive_solution), intent(inout) :: solution
        logical :: done
        call solve_branch_fast(rho, target, arch, lambda_top, f_top, rules, solution, done)
        if (arch == near_radial) then
            ! else the unknown log g from the radial path (lambda_top = log 3)
            solution%arch = arch_unbounded
            if (.not. done) call solve_branch_fast(rho, target, arch_unbounded, lambda_top, &
                                                   f_top, rules, solution, done)
        end if
        if (.not. done) call solve_branch(rho, target, merge(arch_unbounded, &
                                          mod(arch, near_apse), arch == near_radial), &
                                          lambda_top, f_top, solution)
    end subroutine solve_fast_or_slow

    !> Index of the solved curve of least time (the first of equal times; 0 if none).
    pure function least_time(solutions) result(best)
        type(repulsive_solution), intent(in) :: solutions(:)
        integer :: best
        integer :: i
        best = 0
        do i = 1, size(solutions)
            if (solutions(i)%status /= status_ok) cycle
            if (best == 0) then
                best = i
            else if (solutions(i)%time < solutions(best)%time) then
                best = i
            end if
        end do
    end function least_time

end module brachistochrone_repulsive
