!> Brachistochrone tunnels inside a uniform planet: the hypocycloid (Saitoh 2007).
!!
!! Inside a uniform sphere of radius R the force is harmonic, F = -omega^2 r with
!! omega = sqrt(g/R), and a particle released from rest on the surface has speed
!! v = omega sqrt(R^2 - r^2) (Saitoh eq. 3). Everything here is in units R = 1,
!! omega = 1 (so v = sqrt(1 - r^2), lengths in planet radii, times in 1/omega), except the
!! routines that take a `harmonic_planet`. Start A at radius 1, angle 0.
!!
!! The brachistochrone from A with minimum radius rho_m (0 <= rho_m <= 1) is the
!! hypocycloid traced by a circle of radius a = (1 - rho_m)/2 rolling inside the
!! surface. With the rolling angle phi in [0, 2 pi] and h = phi/2 (Saitoh 7-10, and
!! derived here where marked):
!!
!!     r(phi)^2   = rho_m^2 + (1 - rho_m^2) cos^2 h                        (7)
!!     theta(phi) = atan(rho_m tan h) - rho_m h                            (8)
!!     t(phi)     = h sqrt(1 - rho_m^2)                                    (9)
!!     s(phi)     = 2 (1 - rho_m^2) sin^2(phi/4)        (derived: ds/dt = v and (9) give
!!                  ds/dphi = (1 - rho_m^2) sin(h)/2; the arch 2(1 - rho_m^2) is the
!!                  hypocycloid's 8 a (1 - a))
!!     x = cos h cos(rho_m h) + rho_m sin h sin(rho_m h),
!!     y = rho_m sin h cos(rho_m h) - cos h sin(rho_m h)   (Saitoh, after eq. 12)
!!
!! The deepest point (the apse) is phi = pi, at angle (pi/2)(1 - rho_m); the tunnel ends
!! on the surface at phi = 2 pi, at angle pi (1 - rho_m), after T = pi sqrt(1 - rho_m^2)
!! (10) along 2 (1 - rho_m^2).
!!
!! **theta without cancellation.** theta = atan2(y, x) exactly (x, y are r cos theta,
!! r sin theta), which is continuous through phi = pi where tan h is infinite, and
!! increasing on [0, 2 pi]. Near A, y ~ rho_m (1 - rho_m^2) h^3/3 is the difference of
!! two terms of size h, so for h <= 1 y comes from its power series
!!
!!     y = (1 - rho_m^2)/2 sum_{k>=1} (-1)^(k+1) E_k h^(2k+1)/(2k+1)!,
!!     E_k = (1 + rho_m)^(2k) - (1 - rho_m)^(2k),
!!     E_(k+1) = (1 + rho_m)^2 E_k + 4 rho_m (1 - rho_m)^(2k)   (positive terms only),
!!
!! and for h > 1 from the product above (rho_m <= 1/2) or from the hypocycloid form
!! y = [(1 + rho_m) sin((1 - rho_m) h) - (1 - rho_m) sin((1 + rho_m) h)]/2, written as
!! (1 - d sin^2 h) sin(d h) - d sin h cos h cos(d h) with d = 1 - rho_m (rho_m > 1/2,
!! where the product cancels as rho_m -> 1): at most half a digit is lost anywhere, and
!! theta keeps its relative precision as theta -> 0. Every closed form accepts an
!! optional `depth` = 1 - rho_m for shallow tunnels, where 1 - rho_m is known better than
!! it can be computed from rho_m.
!!
!! **Conditioning of the phase.** A rounding of phi (or of pi in phi = pi) moves the point
!! by about eps (in units of R) along the tunnel, so theta(phi) by eps/r: near the centre
!! of a deep tunnel (small rho_m, phi near pi) theta(phi) has only about
!! 34 + log10(r) digits although x and y keep their absolute accuracy.
!! `hypocycloid_angle_at_radius` takes the radius instead and has no such loss.
!!
!! **Two-point problem** (`solve_harmonic_endpoint`). For B = (r_B, theta_B), the angle
!! at radius r_B is strictly increasing in rho_m on the first half-arch (from 0 at
!! rho_m = 0 to the apse angle (pi/2)(1 - r_B) at rho_m = r_B) and strictly decreasing on
!! the second (from pi back to the apse angle): every endpoint 0 < r_B < 1,
!! 0 <= theta_B <= pi is reached by exactly one hypocycloid. The unknown is beta in
!! [0, pi/2] with rho_m = r_B sin(beta): then the phase of B is
!! h = atan2(sqrt(1 - r_B^2), +-r_B cos(beta)) (+ before the deepest point, - after), the
!! angle at B is analytic in beta through the deepest point (beta = pi/2), and linear
!! near rho_m = 0, so a bracketed Newton iteration gives rho_m to full relative
!! precision. It evaluates theta with sin h = sqrt(1 - r_B^2)/sqrt(1 - rho_m^2) and
!! cos h = +-r_B cos(beta)/sqrt(1 - rho_m^2) as they are, and r_B - rho_m =
!! 2 r_B sin^2(pi/4 - beta/2), so neither the centre nor the deepest point costs digits.
!! A root beyond beta = pi/4 is sought in gamma = pi/2 - beta (shallow tunnels: r_B next to
!! 1 needs 1 - rho_m = (1 - r_B) + 2 r_B sin^2(gamma/2) to gamma's relative precision), and
!! d theta/d beta = +-(sqrt(1 - r_B^2) - h X) without cancellation (`across_minus_arc`).
!! Special endpoints: theta_B = 0 (radial fall along OA, rho_m = 0),
!! theta_B = pi (the diametral tunnel, B beyond the centre, rho_m = 0), theta_B equal to
!! the apse angle to two roundings (B is the deepest point, rho_m = r_B), r_B = 1 (surface
!! to surface,
!! rho_m = 1 - theta_B/pi); rho_m below half the smallest binary128 number (r_B theta_B
!! below about 3e-4966 on the first half-arch) is returned as 0, the straight tunnel,
!! with s and t at their limits. As r_B -> 0 the solution tends to the straight diametral
!! tunnel (rho_m <= r_B -> 0) and the time to the centre to pi/2. theta_B outside
!! [0, pi] is refused (use 2 pi - theta_B: the mirror image), as is r_B outside (0, 1].
!!
!! **Tautochrone** (`tautochrone_time`): released from rest anywhere on the hypocycloid,
!! a particle reaches the deepest point after (pi/2) sqrt(1 - rho_m^2)/omega, half of T:
!! with v^2 = r0^2 - r^2 and ds = (1 - rho_m^2) sin h dh, c = cos h gives
!! t = sqrt(1 - rho_m^2) int_0^c0 dc/sqrt(c0^2 - c^2) = (pi/2) sqrt(1 - rho_m^2). The
!! routine integrates numerically instead, so that the tests show it.
!!
!! **Physical units** (`plan_tunnel`): between two places (latitude, longitude in
!! degrees) on a uniform planet (default R = 6371 km, g = 9.81 m/s^2), the central angle
!! Theta gives rho_m = 1 - Theta/pi, the depth R Theta/pi, the length 2 R (1 - rho_m^2)
!! and the time pi sqrt(R/g) sqrt(1 - rho_m^2). The antipodal (diametral) tunnel takes
!! pi sqrt(R/g) = 2531.7 s = 42.2 min (Saitoh's "roughly 41 min" is too short by 1.2 min;
!! 41 min would need R = 6000 km).
module brachistochrone_harmonic
    use brachistochrone_kinds, only: qp, pi, eps_qp, xp
    use brachistochrone_status, only: status_ok, status_not_finite, status_invalid_argument, &
                                      status_rho_out_of_range, status_psi_out_of_range, &
                                      status_latitude_out_of_range, &
                                      status_bad_planet
    use brachistochrone_solution, only: endpoint_status, region_inside
    use brachistochrone_arches, only: arch_none, arch_first, arch_second, arch_complete, &
                                      arch_radial
    use brachistochrone_roots, only: root_function, newton_bracketed
    use brachistochrone_quadrature, only: univariate_integrand, gauss_legendre, integrate_adaptive
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    public :: earth_radius_km, earth_gravity
    public :: hypocycloid_point, harmonic_tunnel, harmonic_planet, planet_tunnel
    public :: hypocycloid_radius, hypocycloid_angle, hypocycloid_time, &
              hypocycloid_arclength, hypocycloid_position, hypocycloid_phase, &
              hypocycloid_angle_at_radius
    public :: tunnel_time, tunnel_arclength, tunnel_surface_angle
    public :: hypocycloid_at
    public :: surface_to_surface, solve_harmonic_endpoint
    public :: tautochrone_time
    public :: angular_frequency, time_scale, great_circle_angle, plan_tunnel

    !> Default planet radius: the mean radius of the Earth, 6371 km.
    real(qp), parameter :: earth_radius_km = 6371.0_qp
    !> Default surface gravity: 9.81 m/s^2.
    real(qp), parameter :: earth_gravity = 9.81_qp

    !> Largest half-phase h = phi/2 for which y is summed as a power series.
    real(qp), parameter :: series_limit = 1.0_qp
    !> Most terms of that series (about 22 are used at h = 1).
    integer, parameter :: max_series_terms = 60
    !> Limit on root-finder evaluations.
    integer, parameter :: max_steps = 100
    !> Limit on the evaluations of the early phase in hardware precision (`xp`).
    integer, parameter :: max_early_steps = 40
    !> The early phase stops when its Newton step is below this, relative to beta: near
    !! the rounding level of `xp` (1.1e-19 on x86-64; 8 eps where `xp` is double).
    real(xp), parameter :: early_tolerance = max(1.0e-17_xp, 8.0_xp*epsilon(1.0_xp))
    !> Gauss-Legendre nodes per panel of the tautochrone integral.
    integer, parameter :: tautochrone_nodes = 20
    !> Relative tolerance of the tautochrone quadrature, in eps. The panel test
    !! |G(panel) - G(halves)| bounds the error of the coarser value; the finer sum
    !! returned is far more accurate. A tolerance at the integrand's rounding level (a few
    !! eps) would make `integrate_adaptive` bisect on noise.
    real(qp), parameter :: tautochrone_tolerance = 64.0_qp

    !> A uniform planet: radius and surface gravity (defaults: the Earth).
    type :: harmonic_planet
        real(qp) :: radius_km = earth_radius_km !! radius R in km
        real(qp) :: gravity = earth_gravity     !! surface gravity g in m/s^2
    end type harmonic_planet

    !> One point of a hypocycloid tunnel, in units R = 1, omega = 1.
    type :: hypocycloid_point
        real(qp) :: phase = 0.0_qp     !! rolling angle phi, 0 <= phi <= 2 pi
        real(qp) :: radius = 0.0_qp    !! r(phi), eq. (7)
        real(qp) :: angle = 0.0_qp     !! theta(phi), eq. (8)
        real(qp) :: time = 0.0_qp      !! t(phi) from A, eq. (9)
        real(qp) :: arclength = 0.0_qp !! s(phi) from A
        real(qp) :: x = 0.0_qp         !! r cos(theta)
        real(qp) :: y = 0.0_qp         !! r sin(theta)
        integer :: status = status_ok  !! status_ok, status_not_finite, status_invalid_argument
    end type hypocycloid_point

    !> The brachistochrone tunnel from A = (1, 0) through an endpoint B, units R = omega = 1.
    type :: harmonic_tunnel
        real(qp) :: radius = 0.0_qp     !! r_B as given
        real(qp) :: angle = 0.0_qp      !! theta_B as given (radians)
        integer :: arch = arch_none     !! arch_first (B before the deepest point, or
                                        !! at it), arch_second (after it; also the
                                        !! diametral tunnel, theta_B = pi), arch_complete
                                        !! (B on the surface), arch_radial (theta_B = 0)
        real(qp) :: min_radius = 0.0_qp !! rho_m, the radius of the deepest point
        real(qp) :: depth = 0.0_qp      !! 1 - rho_m, the depth of the deepest point
        real(qp) :: phase = 0.0_qp      !! rolling angle phi at B
        real(qp) :: time = 0.0_qp       !! time from A to B
        real(qp) :: arclength = 0.0_qp  !! arclength from A to B
        real(qp) :: total_time = 0.0_qp      !! pi sqrt(1 - rho_m^2): A to the surface again
        real(qp) :: total_arclength = 0.0_qp !! 2 (1 - rho_m^2)
        real(qp) :: end_angle = 0.0_qp       !! pi (1 - rho_m): where the tunnel surfaces
        integer :: steps = 0            !! root-finder evaluations
        integer :: status = status_ok   !! status code
    end type harmonic_tunnel

    !> The brachistochrone tunnel between two places on a planet's surface, in km and s.
    type :: planet_tunnel
        real(qp) :: central_angle = 0.0_qp       !! angle AOB (radians)
        real(qp) :: surface_distance_km = 0.0_qp !! great-circle distance R * angle
        real(qp) :: min_radius_km = 0.0_qp       !! radius of the deepest point
        real(qp) :: depth_km = 0.0_qp            !! depth of the deepest point
        real(qp) :: length_km = 0.0_qp           !! length of the tunnel
        real(qp) :: time_seconds = 0.0_qp        !! travel time from rest to rest
        real(qp) :: time_minutes = 0.0_qp        !! the same in minutes
        real(qp) :: chord_length_km = 0.0_qp     !! the straight tunnel, for comparison
        real(qp) :: chord_time_seconds = 0.0_qp  !! its travel time pi/omega (any chord)
        integer :: status = status_ok            !! status code
    end type planet_tunnel

    !> theta at B minus theta_B, as a function of beta (rho_m = r_B sin beta), or of
    !! gamma = pi/2 - beta (`complement`: the root beyond pi/4).
    type, extends(root_function) :: endpoint_angle_function
        real(qp) :: radius = 0.0_qp     !! r_B
        real(qp) :: angle = 0.0_qp      !! theta_B
        real(qp) :: side = 1.0_qp       !! +1 before the deepest point, -1 after
        real(qp) :: across = 1.0_qp     !! sqrt(1 - r_B^2)
        logical :: complement = .false. !! the unknown is gamma = pi/2 - beta
    contains
        procedure :: evaluate => endpoint_angle_evaluate
    end type endpoint_angle_function

    !> dt/dw of a release from rest at radius r0, with h = h0 + (pi/2 - h0) w^2.
    type, extends(univariate_integrand) :: tautochrone_integrand
        real(qp) :: min_radius = 0.0_qp !! rho_m
        real(qp) :: depth = 0.0_qp      !! 1 - rho_m
        real(qp) :: start = 0.0_qp      !! h0, the half-phase of the release point
        real(qp) :: span = 0.0_qp       !! pi/2 - h0
    contains
        procedure :: evaluate => tautochrone_evaluate
    end type tautochrone_integrand

contains

    ! ---------------------------------------------------------------- closed forms

    !> 1 - rho_m: the optional depth if given, else computed.
    elemental function depth_of(rho_m, depth) result(d)
        real(qp), intent(in) :: rho_m
        real(qp), intent(in), optional :: depth
        real(qp) :: d
        if (present(depth)) then
            d = depth
        else
            d = 1.0_qp - rho_m
        end if
    end function depth_of

    !> x and y at half-phase h, 0 <= h <= pi, given sin h and cos h as well (the
    !! two-point solver knows them more accurately than sin(h), cos(h) near the centre).
    !! See the module notes for the forms of y; for rho_m > 1/2 and h > 1 the hypocycloid
    !! form is written with sin((1 + rho_m) h) = sin(2h - dh) expanded:
    !! y = (1 - d sin^2 h) sin(d h) - d sin h cos h cos(d h), d = 1 - rho_m.
    elemental subroutine position_kernel(h, sin_h, cos_h, rho_m, d, x, y)
        real(qp), intent(in) :: h, sin_h, cos_h, rho_m, d
        real(qp), intent(out) :: x, y
        real(qp) :: even, odd, power, h2, term, total, plus2, minus2, sign
        integer :: k
        x = cos_h*cos(rho_m*h) + rho_m*sin_h*sin(rho_m*h)
        if (h <= series_limit) then
            even = 0.0_qp
            odd = 1.0_qp
            power = h
            h2 = h*h
            plus2 = (1.0_qp + rho_m)**2
            minus2 = d*d
            total = 0.0_qp
            sign = 1.0_qp
            do k = 1, max_series_terms
                ! even = E_k, odd = (1 - rho_m)^(2k), power = h^(2k+1)/(2k+1)!
                even = plus2*even + 4.0_qp*rho_m*odd
                odd = odd*minus2
                power = power*h2/real((2*k)*(2*k + 1), qp)
                term = even*power
                total = total + sign*term
                if (term <= 0.125_qp*eps_qp*abs(total)) exit
                sign = -sign
            end do
            y = 0.5_qp*d*(1.0_qp + rho_m)*total
        else if (rho_m <= 0.5_qp) then
            y = rho_m*sin_h*cos(rho_m*h) - cos_h*sin(rho_m*h)
        else
            y = (1.0_qp - d*sin_h**2)*sin(d*h) - d*sin_h*cos_h*cos(d*h)
        end if
    end subroutine position_kernel

    !> x and y at half-phase h, 0 <= h <= pi.
    elemental subroutine position_at_half_phase(h, rho_m, d, x, y)
        real(qp), intent(in) :: h, rho_m, d
        real(qp), intent(out) :: x, y
        call position_kernel(h, sin(h), cos(h), rho_m, d, x, y)
    end subroutine position_at_half_phase

    !> theta at half-phase h, 0 <= h <= pi.
    elemental function angle_at_half_phase(h, rho_m, d) result(theta)
        real(qp), intent(in) :: h, rho_m, d
        real(qp) :: theta
        real(qp) :: x, y
        call position_at_half_phase(h, rho_m, d, x, y)
        theta = atan2(y, x)
    end function angle_at_half_phase

    !> theta where the tunnel is at radius r, from sin h = sqrt((1 - r^2)/(1 - rho_m^2)),
    !! cos h = +-sqrt((r^2 - rho_m^2)/(1 - rho_m^2)) (eq. 7) without forming h's sine and
    !! cosine from h: better conditioned than theta(phi) near the centre, where a rounding
    !! of phi moves theta by eps/r. Precondition 0 <= rho_m <= r <= 1 (not checked);
    !! rho_m = 1 gives 0.
    elemental function hypocycloid_angle_at_radius(r, rho_m, after_deepest, depth) &
        result(theta)
        real(qp), intent(in) :: r                   !! radius, rho_m <= r <= 1
        real(qp), intent(in) :: rho_m               !! minimum radius, 0 <= rho_m <= 1
        logical, intent(in) :: after_deepest        !! on the second half-arch
        real(qp), intent(in), optional :: depth     !! 1 - rho_m, if known exactly
        real(qp) :: theta
        real(qp) :: d, scale, across, along, gap, x, y
        d = depth_of(rho_m, depth)
        theta = 0.0_qp
        if (d <= 0.0_qp) return
        scale = sqrt(d*(1.0_qp + rho_m))
        across = sqrt((1.0_qp - r)*(1.0_qp + r))
        ! r - rho_m; for a given depth and r >= 1/2 as depth - (1 - r) (1 - r is exact)
        gap = r - rho_m
        if (present(depth) .and. r >= 0.5_qp) gap = d - (1.0_qp - r)
        along = sqrt(max(gap, 0.0_qp)*(r + rho_m))
        if (after_deepest) along = -along
        call position_kernel(atan2(across, along), across/scale, along/scale, rho_m, d, x, y)
        theta = atan2(y, x)
    end function hypocycloid_angle_at_radius

    !> r(phi) of eq. (7), as sqrt(rho_m^2 + (1 - rho_m^2) cos^2(phi/2)) (no cancellation).
    !! Preconditions 0 <= rho_m <= 1, 0 <= phi <= 2 pi (not checked: `hypocycloid_at`).
    elemental function hypocycloid_radius(phi, rho_m, depth) result(r)
        real(qp), intent(in) :: phi                 !! rolling angle
        real(qp), intent(in) :: rho_m               !! minimum radius
        real(qp), intent(in), optional :: depth     !! 1 - rho_m, if known exactly
        real(qp) :: r
        real(qp) :: d
        d = depth_of(rho_m, depth)
        r = sqrt(rho_m*rho_m + d*(1.0_qp + rho_m)*cos(0.5_qp*phi)**2)
    end function hypocycloid_radius

    !> theta(phi) of eq. (8), computed as atan2(y, x): continuous through phi = pi,
    !! increasing on [0, 2 pi] from 0 to pi (1 - rho_m), full relative precision near A.
    !! At rho_m = 0 (the diameter) it jumps from 0 to pi at the centre, phi = pi. Near the
    !! centre the rounding of phi costs digits (see the module notes).
    elemental function hypocycloid_angle(phi, rho_m, depth) result(theta)
        real(qp), intent(in) :: phi                 !! rolling angle, 0 <= phi <= 2 pi
        real(qp), intent(in) :: rho_m               !! minimum radius, 0 <= rho_m <= 1
        real(qp), intent(in), optional :: depth     !! 1 - rho_m, if known exactly
        real(qp) :: theta
        theta = angle_at_half_phase(0.5_qp*phi, rho_m, depth_of(rho_m, depth))
    end function hypocycloid_angle

    !> t(phi) = (phi/2) sqrt(1 - rho_m^2) of eq. (9), in units of 1/omega.
    elemental function hypocycloid_time(phi, rho_m, depth) result(t)
        real(qp), intent(in) :: phi                 !! rolling angle, 0 <= phi <= 2 pi
        real(qp), intent(in) :: rho_m               !! minimum radius, 0 <= rho_m <= 1
        real(qp), intent(in), optional :: depth     !! 1 - rho_m, if known exactly
        real(qp) :: t
        t = 0.5_qp*phi*sqrt(depth_of(rho_m, depth)*(1.0_qp + rho_m))
    end function hypocycloid_time

    !> s(phi) = 2 (1 - rho_m^2) sin^2(phi/4): arclength from A (derived in the notes).
    elemental function hypocycloid_arclength(phi, rho_m, depth) result(s)
        real(qp), intent(in) :: phi                 !! rolling angle, 0 <= phi <= 2 pi
        real(qp), intent(in) :: rho_m               !! minimum radius, 0 <= rho_m <= 1
        real(qp), intent(in), optional :: depth     !! 1 - rho_m, if known exactly
        real(qp) :: s
        s = 2.0_qp*depth_of(rho_m, depth)*(1.0_qp + rho_m)*sin(0.25_qp*phi)**2
    end function hypocycloid_arclength

    !> Cartesian position (x, y) = r (cos theta, sin theta) at phi, x along OA.
    elemental subroutine hypocycloid_position(phi, rho_m, x, y, depth)
        real(qp), intent(in) :: phi                 !! rolling angle, 0 <= phi <= 2 pi
        real(qp), intent(in) :: rho_m               !! minimum radius, 0 <= rho_m <= 1
        real(qp), intent(out) :: x                  !! r cos(theta)
        real(qp), intent(out) :: y                  !! r sin(theta)
        real(qp), intent(in), optional :: depth     !! 1 - rho_m, if known exactly
        call position_at_half_phase(0.5_qp*phi, rho_m, depth_of(rho_m, depth), x, y)
    end subroutine hypocycloid_position

    !> The rolling angle phi where the tunnel has radius r: eq. (7) inverted,
    !! phi = 2 atan2(sqrt(1 - r^2), sqrt(r^2 - rho_m^2)) before the deepest point, and
    !! 2 pi minus that after it. Precondition rho_m <= r <= 1 (not checked).
    elemental function hypocycloid_phase(r, rho_m, after_deepest) result(phi)
        real(qp), intent(in) :: r              !! radius, rho_m <= r <= 1
        real(qp), intent(in) :: rho_m          !! minimum radius
        logical, intent(in) :: after_deepest   !! the second half-arch (phi >= pi)
        real(qp) :: phi
        phi = 2.0_qp*atan2(sqrt((1.0_qp - r)*(1.0_qp + r)), sqrt((r - rho_m)*(r + rho_m)))
        if (after_deepest) phi = 2.0_qp*pi - phi
    end function hypocycloid_phase

    !> T = pi sqrt(1 - rho_m^2), eq. (10): the time through the whole tunnel (1/omega).
    elemental function tunnel_time(rho_m, depth) result(t)
        real(qp), intent(in) :: rho_m               !! minimum radius, 0 <= rho_m <= 1
        real(qp), intent(in), optional :: depth     !! 1 - rho_m, if known exactly
        real(qp) :: t
        t = pi*sqrt(depth_of(rho_m, depth)*(1.0_qp + rho_m))
    end function tunnel_time

    !> 2 (1 - rho_m^2): the length of the whole tunnel (the hypocycloid arch 8 a (1 - a)).
    elemental function tunnel_arclength(rho_m, depth) result(s)
        real(qp), intent(in) :: rho_m               !! minimum radius, 0 <= rho_m <= 1
        real(qp), intent(in), optional :: depth     !! 1 - rho_m, if known exactly
        real(qp) :: s
        s = 2.0_qp*depth_of(rho_m, depth)*(1.0_qp + rho_m)
    end function tunnel_arclength

    !> pi (1 - rho_m): the central angle between the tunnel's two surface ends.
    elemental function tunnel_surface_angle(rho_m, depth) result(angle)
        real(qp), intent(in) :: rho_m               !! minimum radius, 0 <= rho_m <= 1
        real(qp), intent(in), optional :: depth     !! 1 - rho_m, if known exactly
        real(qp) :: angle
        angle = pi*depth_of(rho_m, depth)
    end function tunnel_surface_angle

    !> Checked evaluation of everything at one phase. On bad input the point holds zeros
    !! and the status: status_not_finite, or status_invalid_argument unless
    !! 0 <= phi <= 2 pi, 0 <= rho_m <= 1 and (if given) depth = 1 - rho_m within 4 eps.
    elemental function hypocycloid_at(phi, rho_m, depth) result(point)
        real(qp), intent(in) :: phi                 !! rolling angle
        real(qp), intent(in) :: rho_m               !! minimum radius
        real(qp), intent(in), optional :: depth     !! 1 - rho_m, if known exactly
        type(hypocycloid_point) :: point
        real(qp) :: d
        if (.not. (ieee_is_finite(phi) .and. ieee_is_finite(rho_m))) then
            point%status = status_not_finite
            return
        end if
        d = depth_of(rho_m, depth)
        if (.not. ieee_is_finite(d)) then
            point%status = status_not_finite
        else if (phi < 0.0_qp .or. phi > 2.0_qp*pi .or. rho_m < 0.0_qp .or. rho_m > 1.0_qp &
                 .or. d < 0.0_qp .or. d > 1.0_qp .or. &
                 abs(d - (1.0_qp - rho_m)) > 4.0_qp*eps_qp) then
            point%status = status_invalid_argument
        else
            point%phase = phi
            point%radius = hypocycloid_radius(phi, rho_m, d)
            call position_at_half_phase(0.5_qp*phi, rho_m, d, point%x, point%y)
            point%angle = atan2(point%y, point%x)
            point%time = hypocycloid_time(phi, rho_m, d)
            point%arclength = hypocycloid_arclength(phi, rho_m, d)
            point%status = status_ok
        end if
    end function hypocycloid_at

    ! ---------------------------------------------------------------- two-point problem

    !> Fill the tunnel's values from rho_m, 1 - rho_m and the half-phase h of B.
    pure subroutine complete_tunnel(tunnel, rho_m, d, h)
        type(harmonic_tunnel), intent(inout) :: tunnel
        real(qp), intent(in) :: rho_m, d, h
        real(qp) :: d_plus
        d_plus = d*(1.0_qp + rho_m)
        tunnel%min_radius = rho_m
        tunnel%depth = d
        tunnel%phase = 2.0_qp*h
        tunnel%time = h*sqrt(d_plus)
        tunnel%arclength = 2.0_qp*d_plus*sin(0.5_qp*h)**2
        tunnel%total_time = pi*sqrt(d_plus)
        tunnel%total_arclength = 2.0_qp*d_plus
        tunnel%end_angle = pi*d
        tunnel%status = status_ok
    end subroutine complete_tunnel

    !> Surface to surface: the tunnel between A and the surface point at central angle
    !! Theta, 0 <= Theta <= pi. rho_m = 1 - Theta/pi (the depth Theta/pi is kept exactly),
    !! B is the end of the arch (phi = 2 pi), time pi sqrt(1 - rho_m^2). Theta = 0 is the
    !! empty tunnel (time 0). Theta outside [0, pi]: status_psi_out_of_range.
    elemental function surface_to_surface(central_angle) result(tunnel)
        real(qp), intent(in) :: central_angle  !! angle AOB in radians
        type(harmonic_tunnel) :: tunnel
        real(qp) :: d
        tunnel%radius = 1.0_qp
        tunnel%angle = central_angle
        if (.not. ieee_is_finite(central_angle)) then
            tunnel%status = status_not_finite
        else if (central_angle < 0.0_qp .or. central_angle > pi) then
            tunnel%status = status_psi_out_of_range
        else
            d = central_angle/pi
            call complete_tunnel(tunnel, 1.0_qp - d, d, pi)
            tunnel%arch = arch_complete
        end if
    end function surface_to_surface

    !> The hypocycloid from A through B = (r_B, theta_B): its minimum radius rho_m and
    !! whether B comes before (arch_first) or after (arch_second) the deepest point, then
    !! the phase, time and arclength at B. Domain 0 < r_B <= 1, 0 <= theta_B <= pi (see
    !! the module notes): every such endpoint has exactly one tunnel. Statuses:
    !! status_not_finite, status_rho_out_of_range, status_psi_out_of_range,
    !! status_no_convergence (not observed).
    elemental function solve_harmonic_endpoint(radius, angle) result(tunnel)
        real(qp), intent(in) :: radius  !! r_B, 0 < r_B <= 1
        real(qp), intent(in) :: angle   !! theta_B in radians, 0 <= theta_B <= pi
        type(harmonic_tunnel) :: tunnel
        type(endpoint_angle_function) :: fun
        real(qp) :: apse_angle, across, f_lo, f_hi, x0, beta, rho_m, d, h, sine, cosine, half
        integer :: status

        tunnel%radius = radius
        tunnel%angle = angle
        tunnel%status = endpoint_status(radius, angle, region_inside)
        if (tunnel%status /= status_ok) then
            return
        else if (radius == 1.0_qp) then
            tunnel = surface_to_surface(angle)
            return
        end if
        across = sqrt((1.0_qp - radius)*(1.0_qp + radius))
        apse_angle = 0.5_qp*pi*(1.0_qp - radius)
        if (angle == 0.0_qp) then
            ! radial fall along OA: the diameter, stopped at B
            call complete_tunnel(tunnel, 0.0_qp, 1.0_qp, atan2(across, radius))
            tunnel%arch = arch_radial
        else if (angle == pi) then
            ! the diametral tunnel, B beyond the centre
            call complete_tunnel(tunnel, 0.0_qp, 1.0_qp, atan2(across, -radius))
            tunnel%arch = arch_second
        else if (abs(angle - apse_angle) <= 2.0_qp*eps_qp*angle) then
            ! B is the deepest point (to two roundings of theta_B: the root would be
            ! gamma = |theta_B - apse angle|/sqrt(1 - r_B^2) < 2.3 eps, which moves rho_m by
            ! eps^2 and h by under 2 eps; Newton's step from the early root overshoots
            ! gamma = 0 there and bisection took 48 steps)
            call complete_tunnel(tunnel, radius, 1.0_qp - radius, 0.5_qp*pi)
            tunnel%arch = arch_first
        else
            fun%radius = radius
            fun%angle = angle
            fun%across = across
            if (angle < apse_angle) then
                fun%side = 1.0_qp
                tunnel%arch = arch_first
                f_lo = -angle
                x0 = 0.5_qp*pi*angle/apse_angle
            else
                fun%side = -1.0_qp
                tunnel%arch = arch_second
                f_lo = pi - angle
                x0 = 0.5_qp*pi*(pi - angle)/(pi - apse_angle)
            end if
            f_hi = apse_angle - angle
            if (fun%side > 0.0_qp .and. angle/(across - radius*atan2(across, radius)) < &
                0.5_qp*(nearest(0.0_qp, 1.0_qp)/radius)) then
                ! rho_m = r_B beta, beta = theta_B/(d theta/d beta at 0) to first order: below
                ! half the smallest subnormal, so rho_m rounds to 0 (the straight tunnel)
                call complete_tunnel(tunnel, 0.0_qp, 1.0_qp, atan2(across, radius))
                return
            end if
            call solve_beta(fun, f_lo, f_hi, x0, beta, tunnel%steps, status)
            call beta_trig(beta, fun%complement, sine, cosine, half)
            call beta_to_rho(radius, sine, half, rho_m, d)
            h = atan2(across, fun%side*radius*cosine)
            call complete_tunnel(tunnel, rho_m, d, h)
            tunnel%status = status
        end if
    end function solve_harmonic_endpoint

    !> beta (or gamma = pi/2 - beta, `fun%complement` on return) by `newton_bracketed`
    !! in binary128 on [0, pi/2], started by `early_beta` (with its K when it converged;
    !! else from x0, K unknown, as without it). A root beta beyond pi/4 is sought in
    !! gamma, which keeps its relative precision as beta -> pi/2: there
    !! 1 - rho_m = (1 - r_B) + 2 r_B sin^2(gamma/2) and, for r_B next to 1 (a shallow
    !! tunnel), s = 2 (1 - rho_m^2) sin^2(h/2) and t have their relative precision only
    !! if gamma has (with beta, r_B = 1 - 1e-29, theta_B = 1e-20 gave s to 24 digits).
    pure subroutine solve_beta(fun, f_lo, f_hi, x0, beta, steps, status)
        type(endpoint_angle_function), intent(inout) :: fun
        real(qp), intent(in) :: f_lo, f_hi, x0  !! f at beta = 0, pi/2; first guess
        real(qp), intent(out) :: beta           !! the root (gamma if fun%complement)
        integer, intent(out) :: steps, status   !! binary128 evaluations, status
        real(qp) :: start, curvature, shallow_start, shallow_curvature
        integer :: more
        fun%complement = .false.
        call early_beta(fun%radius, fun%angle, fun%side, .false., x0, start, curvature)
        if (curvature == 0.0_qp .and. fun%across < 0.5_qp) then
            ! a shallow B (r_B next to 1): theta moves only within gamma of the order of
            ! sqrt(1 - r_B^2) of the deepest point, where the start x0 (linear in beta) is
            ! not; the early phase in gamma from there
            call early_beta(fun%radius, fun%angle, fun%side, .true., fun%across, &
                            shallow_start, shallow_curvature)
            if (shallow_curvature > 0.0_qp) then
                fun%complement = .true.
                start = shallow_start
                curvature = shallow_curvature
            end if
        else if (start > 0.25_qp*pi) then
            ! polish the start in gamma (one or two hardware steps) for its curvature
            fun%complement = .true.
            call early_beta(fun%radius, fun%angle, fun%side, .true., 0.5_qp*pi - start, &
                            start, curvature)
        end if
        call run_newton(start, curvature, beta, steps, status)
        if (status == status_ok .and. .not. fun%complement .and. beta > 0.25_qp*pi) then
            ! found in beta (the early phase failed): on in gamma, to its relative precision
            fun%complement = .true.
            call run_newton(0.5_qp*pi - beta, 0.0_qp, beta, more, status)
            steps = steps + more
        end if
    contains
        !> newton_bracketed on [0, pi/2] in the current unknown (K = curvature if known).
        !! gamma to 4 eps relative keeps 1 - rho_m's; the phase h needs gamma only to
        !! 4 eps sqrt(1 - r_B^2) absolute (B next to its deepest point, gamma ~ 1e-17: f is
        !! quadratic in gamma there and a relative tolerance alone is not reached).
        pure subroutine run_newton(x_start, k, root, used, stat)
            real(qp), intent(in) :: x_start, k
            real(qp), intent(out) :: root
            integer, intent(out) :: used, stat
            real(qp) :: f_0, f_end, abs_tol, k_used
            k_used = k
            f_0 = merge(f_hi, f_lo, fun%complement)
            f_end = merge(f_lo, f_hi, fun%complement)
            abs_tol = merge(4.0_qp*eps_qp*fun%across, 0.0_qp, fun%complement)
            if (k > 0.0_qp) then
                call newton_bracketed(fun, 0.0_qp, f_0, 0.5_qp*pi, f_end, x_start, &
                                      4.0_qp*eps_qp, abs_tol, max_steps, root, used, stat, &
                                      k_used)
            else
                call newton_bracketed(fun, 0.0_qp, f_0, 0.5_qp*pi, f_end, x_start, &
                                      4.0_qp*eps_qp, abs_tol, max_steps, root, used, stat)
            end if
        end subroutine run_newton
    end subroutine solve_beta

    !> sin(beta), cos(beta) and sin(pi/4 - beta/2) from the unknown x: beta itself, or
    !! (complement) gamma = pi/2 - beta, each without forming the other.
    elemental subroutine beta_trig(x, complement, sine, cosine, half)
        real(qp), intent(in) :: x
        logical, intent(in) :: complement
        real(qp), intent(out) :: sine, cosine, half
        if (complement) then
            sine = cos(x)
            cosine = sin(x)
            half = sin(0.5_qp*x)
        else
            sine = sin(x)
            cosine = cos(x)
            half = sin(0.25_qp*pi - 0.5_qp*x)
        end if
    end subroutine beta_trig

    !> rho_m = r sin(beta) and 1 - rho_m = (1 - r) + 2 r sin^2(pi/4 - beta/2), from
    !! sin(beta) and sin(pi/4 - beta/2) (`beta_trig`).
    elemental subroutine beta_to_rho(radius, sine, half, rho_m, d)
        real(qp), intent(in) :: radius, sine, half
        real(qp), intent(out) :: rho_m, d
        rho_m = radius*sine
        d = (1.0_qp - radius) + 2.0_qp*radius*half**2
    end subroutine beta_to_rho

    !> theta(B) - theta_B and its derivative in beta.
    !!
    !! With X = side r cos(beta), Y = sqrt(1 - r^2): X^2 + Y^2 = 1 - rho_m^2, h = atan2(Y, X),
    !! dh/dbeta = side Y rho_m/(1 - rho_m^2), d theta/dh = rho_m Y^2/r^2,
    !! d theta/d rho_m = X Y/((1 - rho_m^2) r^2) - h, d rho_m/dbeta = r cos(beta); their
    !! sum is d theta/d beta = side (Y - h X) (the terms in Y^3 and Y add up to Y), formed
    !! without cancellation by `across_minus_arc`.
    pure subroutine endpoint_angle_evaluate(self, x, f, df, status)
        class(endpoint_angle_function), intent(in) :: self
        real(qp), intent(in) :: x       !! beta (gamma = pi/2 - beta if self%complement)
        real(qp), intent(out) :: f      !! theta at B minus theta_B
        real(qp), intent(out) :: df     !! its derivative in x
        integer, intent(out) :: status  !! status_ok
        real(qp) :: rho_m, d, d_plus, across, along, h, px, py, sine, cosine, half
        call beta_trig(x, self%complement, sine, cosine, half)
        call beta_to_rho(self%radius, sine, half, rho_m, d)
        d_plus = d*(1.0_qp + rho_m)
        across = self%across
        along = self%side*self%radius*cosine
        h = atan2(across, along)
        call position_kernel(h, across/sqrt(d_plus), along/sqrt(d_plus), rho_m, d, px, py)
        f = atan2(py, px) - self%angle
        df = self%side*across_minus_arc(across, along, h)
        if (self%complement) df = -df
        status = status_ok
    end subroutine endpoint_angle_evaluate

    !> Y - h X for h = atan2(Y, X), Y >= 0 (d theta/d beta, side 1): where X > 0 and
    !! z = Y/X <= 1/4 (a shallow B, r_B -> 1 at small beta, where Y and h X agree to
    !! about log10(1/z^2) digits) as X (z - atan z) by its series
    !! z^3/3 - z^5/5 + ..., else directly (at most 6 bits lost at z = 1/4).
    elemental function across_minus_arc(y, x, h) result(d)
        real(qp), intent(in) :: y, x, h
        real(qp) :: d
        real(qp) :: z, z2, power, total, term
        integer :: k
        if (.not. (x > 0.0_qp .and. y <= 0.25_qp*x)) then
            d = y - h*x
            return
        end if
        z = y/x
        z2 = z*z
        power = z*z2
        total = 0.0_qp
        do k = 1, max_series_terms
            term = power/real(2*k + 1, qp)
            total = total + merge(term, -term, mod(k, 2) == 1)
            if (term <= 0.125_qp*eps_qp*total) exit
            power = power*z2
        end do
        d = x*total
    end function across_minus_arc

    !> `across_minus_arc` in hardware precision.
    elemental function across_minus_arc_xp(y, x, h) result(d)
        real(xp), intent(in) :: y, x, h
        real(xp) :: d
        real(xp) :: z, z2, power, total, term
        integer :: k
        if (.not. (x > 0.0_xp .and. y <= 0.25_xp*x)) then
            d = y - h*x
            return
        end if
        z = y/x
        z2 = z*z
        power = z*z2
        total = 0.0_xp
        do k = 1, max_series_terms
            term = power/real(2*k + 1, xp)
            total = total + merge(term, -term, mod(k, 2) == 1)
            if (term <= 0.125_xp*epsilon(1.0_xp)*total) exit
            power = power*z2
        end do
        d = x*total
    end function across_minus_arc_xp

    ! ---------------------------------------------------------------- early phase (xp)

    !> The early phase of `solve_harmonic_endpoint`: a safeguarded Newton iteration in
    !! hardware precision (`xp`) for beta in [0, pi/2] (same signs at the ends as the
    !! binary128 run), from start until its step is below `early_tolerance` relative, or
    !! after `max_early_steps` (then the last iterate). Its result only starts the
    !! binary128 `newton_bracketed`, which certifies the root as before; it takes one or
    !! two binary128 evaluations instead of three to eight. Also K = |f''/(2 f')| near the
    !! root, twice its secant estimate from f' at the last iterate and at a point
    !! 1e-4 min(beta, sqrt(1 - r_B^2)) inside (the scales on which f'' varies) plus the
    !! rounding of f' over that distance, for the binary128 run to stop after a step dx
    !! with 4 K dx^2 below its tolerance (0: unknown, when the early phase did not
    !! converge; then also beta = start).
    pure subroutine early_beta(radius, angle, side, complement, start, beta, curvature)
        real(qp), intent(in) :: radius, angle, side !! r_B, theta_B, +1 or -1
        logical, intent(in) :: complement           !! in gamma = pi/2 - beta
        real(qp), intent(in) :: start               !! first iterate
        real(qp), intent(out) :: beta               !! the approximate root
        real(qp), intent(out) :: curvature          !! K estimate, 0 if unknown
        real(xp), parameter :: hi_end = real(0.5_qp*pi, xp)
        real(xp) :: r, gap, theta, s, lo, hi, x, x_new, f, df, x_eval, df_eval, delta, df_near
        logical :: converged
        logical :: increasing
        integer :: k
        r = real(radius, xp)
        gap = real(1.0_qp - radius, xp)
        theta = real(angle, xp)
        s = real(side, xp)
        lo = 0.0_xp
        hi = hi_end
        increasing = (side > 0.0_qp) .neqv. complement
        x = min(max(real(start, xp), lo), hi)
        beta = start
        curvature = 0.0_qp
        converged = .false.
        do k = 1, max_early_steps
            call endpoint_angle_xp(r, gap, theta, s, complement, x, f, df)
            if (.not. (abs(f) < huge(f) .and. abs(df) < huge(df) .and. df /= 0.0_xp)) return
            x_eval = x
            df_eval = df
            converged = f == 0.0_xp
            if (converged) exit
            if ((f < 0.0_xp) .eqv. increasing) then
                lo = x
            else
                hi = x
            end if
            x_new = x - f/df
            converged = abs(x_new - x) <= early_tolerance*abs(x)
            if (converged .and. .not. (x_new > lo .and. x_new < hi)) exit
            if (.not. (x_new > lo .and. x_new < hi)) x_new = 0.5_xp*(lo + hi)
            x = x_new
            if (converged) exit
        end do
        ! a step cap or an underflow: the binary128 run starts from start, K unknown
        if (.not. converged .or. x <= 0.0_xp) return
        beta = real(x, qp)
        delta = 1.0e-4_xp*min(x_eval, sqrt(gap*(1.0_xp + r)))
        if (.not. (delta > 0.0_xp)) return
        if (x_eval > 0.5_xp*hi_end) delta = -delta
        call endpoint_angle_xp(r, gap, theta, s, complement, x_eval + delta, f, df_near)
        ! plus what the rounding of f' (1e-17 relative at most) could hide
        curvature = real((abs(df_near - df_eval)/abs(df_eval) + 1.0e-17_xp)/abs(delta), qp)
        if (.not. (curvature < huge(1.0_qp))) curvature = 0.0_qp
    end subroutine early_beta

    !> `endpoint_angle_evaluate` in hardware precision: theta(B) - theta_B and its
    !! derivative in the unknown x, from r_B, 1 - r_B (from binary128: r_B may round to 1
    !! in `xp`), theta_B, the side and x = beta (gamma = pi/2 - beta if complement).
    pure subroutine endpoint_angle_xp(radius, gap, angle, side, complement, x, f, df)
        real(xp), intent(in) :: radius, gap, angle, side, x
        logical, intent(in) :: complement
        real(xp), intent(out) :: f, df
        real(xp), parameter :: quarter_pi = real(0.25_qp*pi, xp)
        real(xp) :: rho_m, d, d_plus, across, along, h, px, py, sine, cosine, half
        if (complement) then
            sine = cos(x)
            cosine = sin(x)
            half = sin(0.5_xp*x)
        else
            sine = sin(x)
            cosine = cos(x)
            half = sin(quarter_pi - 0.5_xp*x)
        end if
        rho_m = radius*sine
        d = gap + 2.0_xp*radius*half**2
        d_plus = d*(1.0_xp + rho_m)
        across = sqrt(gap*(1.0_xp + radius))
        along = side*radius*cosine
        h = atan2(across, along)
        call position_kernel_xp(h, across/sqrt(d_plus), along/sqrt(d_plus), rho_m, d, px, py)
        f = atan2(py, px) - angle
        df = side*across_minus_arc_xp(across, along, h)
        if (complement) df = -df
    end subroutine endpoint_angle_xp

    !> `position_kernel` in hardware precision (the same branches, so that theta keeps
    !! its relative precision as beta -> 0).
    pure subroutine position_kernel_xp(h, sin_h, cos_h, rho_m, d, x, y)
        real(xp), intent(in) :: h, sin_h, cos_h, rho_m, d
        real(xp), intent(out) :: x, y
        real(xp) :: even, odd, power, h2, term, total, plus2, minus2, sign
        integer :: k
        x = cos_h*cos(rho_m*h) + rho_m*sin_h*sin(rho_m*h)
        if (h <= real(series_limit, xp)) then
            even = 0.0_xp
            odd = 1.0_xp
            power = h
            h2 = h*h
            plus2 = (1.0_xp + rho_m)**2
            minus2 = d*d
            total = 0.0_xp
            sign = 1.0_xp
            do k = 1, max_series_terms
                even = plus2*even + 4.0_xp*rho_m*odd
                odd = odd*minus2
                power = power*h2/real((2*k)*(2*k + 1), xp)
                term = even*power
                total = total + sign*term
                if (term <= 0.125_xp*epsilon(1.0_xp)*abs(total)) exit
                sign = -sign
            end do
            y = 0.5_xp*d*(1.0_xp + rho_m)*total
        else if (rho_m <= 0.5_xp) then
            y = rho_m*sin_h*cos(rho_m*h) - cos_h*sin(rho_m*h)
        else
            y = (1.0_xp - d*sin_h**2)*sin(d*h) - d*sin_h*cos_h*cos(d*h)
        end if
    end subroutine position_kernel_xp

    ! ---------------------------------------------------------------- tautochrone

    !> Time from rest at radius r0 on the hypocycloid with minimum radius rho_m to its
    !! deepest point, by quadrature of dt = ds/v with v^2 = r0^2 - r^2 (energy from rest at
    !! r0, units omega = 1). The curve is taken from the rolling-circle form (Saitoh
    !! 11-12): ds = |dP/dphi| dphi, P = ((1-a) cos(a phi) + a cos((1-a) phi),
    !! (1-a) sin(a phi) - a sin((1-a) phi)), a = (1 - rho_m)/2, and
    !! r0^2 - r^2 = (1 - rho_m^2) sin(h - h0) sin(h + h0) from (7). The substitution
    !! h = h0 + (pi/2 - h0) w^2 removes the 1/sqrt(h - h0) singularity at the release
    !! point; adaptive Gauss-Legendre in w on [0, 1]. The tautochrone property says the
    !! result is (pi/2) sqrt(1 - rho_m^2) for every r0 in (rho_m, 1] (the tests check it).
    !! At r0 = rho_m the particle is already at the deepest point: time 0. Domain
    !! 0 <= rho_m < 1, rho_m <= r0 <= 1, else status_invalid_argument (time 0).
    elemental subroutine tautochrone_time(start_radius, rho_m, time, status, depth)
        real(qp), intent(in) :: start_radius      !! r0, where the particle is released
        real(qp), intent(in) :: rho_m             !! minimum radius of the hypocycloid
        real(qp), intent(out) :: time             !! time to the deepest point (1/omega)
        integer, intent(out) :: status            !! status code
        real(qp), intent(in), optional :: depth   !! 1 - rho_m, if known exactly
        type(tautochrone_integrand) :: integrand
        real(qp) :: d, error, along, across
        time = 0.0_qp
        d = depth_of(rho_m, depth)
        if (.not. (ieee_is_finite(start_radius) .and. ieee_is_finite(rho_m) .and. &
                   ieee_is_finite(d))) then
            status = status_not_finite
            return
        end if
        if (rho_m < 0.0_qp .or. d <= 0.0_qp .or. start_radius < rho_m .or. &
            start_radius > 1.0_qp .or. abs(d - (1.0_qp - rho_m)) > 4.0_qp*eps_qp) then
            status = status_invalid_argument
            return
        end if
        status = status_ok
        if (start_radius == rho_m) return
        along = sqrt((start_radius - rho_m)*(start_radius + rho_m))
        across = sqrt((1.0_qp - start_radius)*(1.0_qp + start_radius))
        integrand%min_radius = rho_m
        integrand%depth = d
        integrand%start = atan2(across, along)
        integrand%span = atan2(along, across)
        call integrate_adaptive(integrand, 0.0_qp, 1.0_qp, gauss_legendre(tautochrone_nodes), &
                                tautochrone_tolerance*eps_qp, 0.0_qp, time, error, status)
    end subroutine tautochrone_time

    !> dt/dw = |dP/dphi| (dphi/dw) / sqrt(r0^2 - r^2), dphi/dw = 4 (pi/2 - h0) w.
    pure function tautochrone_evaluate(self, x) result(y)
        class(tautochrone_integrand), intent(in) :: self
        real(qp), intent(in) :: x   !! w in [0, 1]
        real(qp) :: y
        real(qp) :: a, b, phi, dx, dy, lead, trail
        a = 0.5_qp*self%depth
        b = 1.0_qp - a
        phi = 2.0_qp*(self%start + self%span*x*x)
        dx = -a*b*(sin(a*phi) + sin(b*phi))
        dy = a*b*(cos(a*phi) - cos(b*phi))
        ! h - h0 = span w^2 and h + h0 = pi - span (2 - w^2), both without cancellation
        lead = sin(self%span*x*x)
        trail = sin(self%span*(2.0_qp - x*x))
        y = hypot(dx, dy)*4.0_qp*self%span*x &
            /sqrt(self%depth*(1.0_qp + self%min_radius)*lead*trail)
    end function tautochrone_evaluate

    ! ---------------------------------------------------------------- physical units

    !> omega = sqrt(g/R) in 1/s.
    elemental function angular_frequency(planet) result(omega)
        type(harmonic_planet), intent(in) :: planet !! the planet
        real(qp) :: omega
        omega = sqrt(planet%gravity/(1000.0_qp*planet%radius_km))
    end function angular_frequency

    !> 1/omega = sqrt(R/g) in seconds: the unit of every time of this module.
    elemental function time_scale(planet) result(seconds)
        type(harmonic_planet), intent(in) :: planet !! the planet
        real(qp) :: seconds
        seconds = sqrt(1000.0_qp*planet%radius_km/planet%gravity)
    end function time_scale

    !> Great-circle central angle (radians) between two places given in degrees, by the
    !! atan2 (Vincenty) form on the sphere, accurate for near and antipodal points alike:
    !! atan2(sqrt(e^2 + n^2), u) with e = cos(lat2) sin(dlon),
    !! n = sin(lat2 - lat1) + 2 sin(lat1) cos(lat2) sin^2(dlon/2),
    !! u = cos(lat2 - lat1) - 2 cos(lat1) cos(lat2) sin^2(dlon/2).
    !! Preconditions: latitudes in [-90, 90], finite longitudes (checked by `plan_tunnel`).
    elemental function great_circle_angle(latitude_1, longitude_1, latitude_2, longitude_2) &
        result(angle)
        real(qp), intent(in) :: latitude_1   !! degrees north of place 1
        real(qp), intent(in) :: longitude_1  !! degrees east of place 1
        real(qp), intent(in) :: latitude_2   !! degrees north of place 2
        real(qp), intent(in) :: longitude_2  !! degrees east of place 2
        real(qp) :: angle
        real(qp), parameter :: degree = pi/180.0_qp
        real(qp) :: phi_1, phi_2, delta_phi, delta_lambda, haver, east, north, up
        phi_1 = latitude_1*degree
        phi_2 = latitude_2*degree
        delta_phi = (latitude_2 - latitude_1)*degree
        delta_lambda = modulo(longitude_2 - longitude_1, 360.0_qp)
        if (delta_lambda > 180.0_qp) delta_lambda = delta_lambda - 360.0_qp
        delta_lambda = delta_lambda*degree
        haver = 2.0_qp*sin(0.5_qp*delta_lambda)**2
        east = cos(phi_2)*sin(delta_lambda)
        north = sin(delta_phi) + sin(phi_1)*cos(phi_2)*haver
        up = cos(delta_phi) - cos(phi_1)*cos(phi_2)*haver
        angle = atan2(hypot(east, north), up)
    end function great_circle_angle

    !> The brachistochrone tunnel between two places (degrees) on a uniform planet (by
    !! default the Earth: 6371 km, 9.81 m/s^2): deepest point, length, travel time from
    !! rest to rest, and the straight chord for comparison (every chord takes pi/omega).
    !! Statuses: status_not_finite, status_latitude_out_of_range, status_bad_planet.
    elemental function plan_tunnel(latitude_1, longitude_1, latitude_2, longitude_2, &
                                   planet) result(route)
        real(qp), intent(in) :: latitude_1   !! degrees north of the start
        real(qp), intent(in) :: longitude_1  !! degrees east of the start
        real(qp), intent(in) :: latitude_2   !! degrees north of the destination
        real(qp), intent(in) :: longitude_2  !! degrees east of the destination
        type(harmonic_planet), intent(in), optional :: planet !! default: the Earth
        type(planet_tunnel) :: route
        type(harmonic_planet) :: body
        type(harmonic_tunnel) :: tunnel
        real(qp) :: big_r, unit_time
        if (present(planet)) body = planet
        if (.not. (ieee_is_finite(latitude_1) .and. ieee_is_finite(longitude_1) .and. &
                   ieee_is_finite(latitude_2) .and. ieee_is_finite(longitude_2) .and. &
                   ieee_is_finite(body%radius_km) .and. ieee_is_finite(body%gravity))) then
            route%status = status_not_finite
            return
        else if (abs(latitude_1) > 90.0_qp .or. abs(latitude_2) > 90.0_qp) then
            route%status = status_latitude_out_of_range
            return
        else if (.not. (body%radius_km > 0.0_qp .and. body%gravity > 0.0_qp)) then
            route%status = status_bad_planet
            return
        end if
        big_r = body%radius_km
        unit_time = time_scale(body)
        route%central_angle = great_circle_angle(latitude_1, longitude_1, latitude_2, &
                                                 longitude_2)
        tunnel = surface_to_surface(route%central_angle)
        route%surface_distance_km = big_r*route%central_angle
        route%min_radius_km = big_r*tunnel%min_radius
        route%depth_km = big_r*tunnel%depth
        route%length_km = big_r*tunnel%total_arclength
        route%time_seconds = unit_time*tunnel%total_time
        route%time_minutes = route%time_seconds/60.0_qp
        route%chord_length_km = 2.0_qp*big_r*sin(0.5_qp*route%central_angle)
        route%chord_time_seconds = pi*unit_time
        route%status = tunnel%status
    end function plan_tunnel

end module brachistochrone_harmonic
