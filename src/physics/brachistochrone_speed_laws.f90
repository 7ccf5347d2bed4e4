!> Speed laws v(r) of a particle released from rest at radius 1 in a central field.
!!
!! Energy conservation gives v^2 = 2 (phi(1) - phi(r)) (Tee 1998, eq. 14). A force field
!! enters the general engine (`central_force`) only through
!!   P(x)   = v(x)^2,
!!   D(x,y) = (P(x) - P(y))/(x - y), the divided difference (D(x,x) = P'(x)),
!! both evaluated without cancellation, because the engine's integrands need
!! V(x) = P(x)/(1 - x) = -D(x,1) and (P(x) - P(R))/(x - R) near x = 1 and x = R.
!! Units: radius of A = 1 and |mu| = 1 (inverse-square: Tee's units; harmonic: R_E = 1,
!! omega = 1).
!!
!! The engine's fast path (`arch_terms`) works in logarithmic offsets: for the apse R and
!! a point x of the arch, lambda = log(x/R) from the apse and delta = -log(x) from the
!! start, lambda + delta = Lambda = -log R, each carried exactly by the engine. It needs
!!   q = w(R)/w(x) = (R/x)^2 P(x)/P(R),   1 - q without cancellation,   q/sqrt(P(x)),
!! where w = x^2/P. Power laws (a = n - 1) have, with E(y) = 1 - exp(-a y),
!!   q = exp(-(n+1) lambda) E(delta)/E(Lambda),
!!   1 - q = (1 - exp(-2 lambda)) + exp(-2 lambda) E(lambda)/E(Lambda),
!!   q/sqrt(P) = sqrt(a/2) sqrt(E(delta))/E(Lambda) exp(-(n+1) lambda - a delta/2),
!! all sums of positive terms that neither overflow nor cancel for any R in binary128
!! and any n > 1 (E/a -> y as a -> 0: the logarithmic law, P = 2 delta, is that limit).
!! Other laws get these from P and D (`default_arch_terms`).
module brachistochrone_speed_laws
    use brachistochrone_kinds, only: qp, xp
    use brachistochrone_quad_math, only: expm1, log1p
    use brachistochrone_fast_exp, only: fast_exp, fast_expm1
    use brachistochrone_fast_math, only: inverse_sqrt, hardware_real, fast_sqrt
    use brachistochrone_closed_forms, only: radial_time
    use, intrinsic :: iso_fortran_env, only: real64
    implicit none
    private

    public :: speed_law, inverse_square_law, power_law, logarithmic_law, harmonic_law
    public :: max_power_exponent


    !> Largest force exponent n of `power_law` the general engine accepts (checked against
    !! mpmath at n = 1.5, 3, 10 and converging on a grid up to n = 32; from n of about 100
    !! the integrands' exp(-(n+1) lambda/2) decay outgrows its panel layout next to the
    !! edge of the accessible region). Any n > 1 is accepted below it, n = 1 + 2^-100
    !! included (it agrees with the logarithmic law to O(n - 1)).
    real(qp), parameter :: max_power_exponent = 32.0_qp

    !> Series of the power law's fall time (`power_fall_time`): most terms, 1/k, 1/(2k+1),
    !! (k + 1/2)/(k + 1), log 2.
    integer, parameter :: max_series_terms = 160
    integer :: k_
    real(qp), parameter :: inverse_integer(1:max_series_terms + 1) = &
        [(1.0_qp/real(k_, qp), k_ = 1, max_series_terms + 1)]
    real(qp), parameter :: inverse_odd(0:max_series_terms) = &
        [(1.0_qp/real(2*k_ + 1, qp), k_ = 0, max_series_terms)]
    real(qp), parameter :: half_step(0:max_series_terms) = &
        [((real(k_, qp) + 0.5_qp)/real(k_ + 1, qp), k_ = 0, max_series_terms)]
    real(qp), parameter :: log_two = log(2.0_qp)
    !> Coefficients kept per power law for `tabulated_fall_time` (ratio <= 1/2: at most
    !! 121 terms for 1e-36) and the least a = n - 1 that gets them (below it the series
    !! in W^2 cancels: `mild_fall_time`)
    integer, parameter :: fall_terms = 124
    real(qp), parameter :: table_min_a = 0.5_qp
    !> The fall time of the power laws a = n - 1 < 1/2 (per law, `fall_pieces`): Chebyshev
    !! series on s = sqrt(delta) in [k, k+1], k < mild_pieces (k = 0: t0/s in delta),
    !! interpolants of degree mild_degree; t0(delta >= mild_pieces^2) = t0(mild_pieces^2)
    !! (the rest below 1e-40 of it)
    integer, parameter :: mild_pieces = 10, mild_degree = 40

    !> sqrt(z/sinh z) = sum_m sinh_root(m) z^(2m) (radius pi), for the fall time of the
    !! power laws n < 3 where (n - 1) delta <= 2 log 2 (`mild_fall_time`); 40 digits from
    !! mpmath (taylor(lambda z: sqrt(z/sinh(z)), 0, 80) at 70 digits).
    integer, parameter :: mild_terms = 40
    !> 1/(j + 1/2) for the incomplete gamma functions' recurrence and series
    real(qp), parameter :: inverse_half(0:2*mild_terms + max_series_terms) = &
        [(1.0_qp/(real(k_, qp) + 0.5_qp), k_ = 0, 2*mild_terms + max_series_terms)]
    real(qp), parameter :: sinh_root(0:mild_terms) = [ &
        1.0e0_qp, -8.333333333333333333333333333333333333333e-2_qp, 6.25e-3_qp, &
        -5.042989417989417989417989417989417989418e-4_qp, &
        4.343722442680776014109347442680776014109e-5_qp, &
        -3.896385732323232323232323232323232323232e-6_qp, &
        3.5833354634507908317432126955936479746e-7_qp, &
        -3.349747072060577902729578214587032929185e-8_qp, &
        3.167585434316114761035785000926613127049e-9_qp, &
        -3.021036851737096156278742947805201253256e-10_qp, &
        2.900415787669253041460419685680819465987e-11_qp, &
        -2.799396748375269290000330833169690392468e-12_qp, &
        2.713639320017203700482007716326339699919e-13_qp, &
        -2.640047892184152890324073200737982690296e-14_qp, &
        2.576345276111417982816729253880419663641e-15_qp, &
        -2.520813255420055633867949277570450368858e-16_qp, &
        2.472127507451747074250283620694908877938e-17_qp, &
        -2.429248639502351558272628537939467695867e-18_qp, &
        2.391348018764929546325534307879697167263e-19_qp, &
        -2.357755946411740481256440405565376374944e-20_qp, &
        2.327924615768231866669533139979789887871e-21_qp, &
        -2.301401107906203587724045173661755178386e-22_qp, &
        2.27780735734473662400585763213415032165e-23_qp, &
        -2.256825055267753398663825185279649405166e-24_qp, &
        2.238184113077813437978847334000099299076e-25_qp, &
        -2.221653734513266919675727836676171554971e-26_qp, &
        2.207035426746869403222671127252579043125e-27_qp, &
        -2.194157471766908839292169391163766390714e-28_qp, &
        2.182870510763488759130553249729622318812e-29_qp, &
        -2.17304398619209826110578575113569440814e-30_qp, &
        2.164563251472097105081419736584696185448e-31_qp, &
        -2.157327205261501897742819338394024057059e-32_qp, &
        2.151246341485599259846516438070392896562e-33_qp, &
        -2.146241131533082548150734421018861075117e-34_qp, &
        2.142240673835419615714246699036617377132e-35_qp, &
        -2.139181560193522561415686926967345147643e-36_qp, &
        2.137006918961645339412778460236613907037e-37_qp, &
        -2.135665603431259287116514242103730989369e-38_qp, &
        2.135111500116744217678797448991474082368e-39_qp, &
        -2.13530293659428030211367519475879566002e-40_qp, &
        2.136202172425637372263518718226106429429e-41_qp]

    !> A speed law: v^2 and its divided difference. Attractive laws here: v > 0 for
    !! 0 < r < 1, v(1) = 0.
    !> The exponents whose exp(-a lambda) follows from exp(-lambda) (`power_node_terms`).
    integer, parameter :: exponent_general = 0, exponent_two = 1, exponent_one = 2, &
                          exponent_half = 3

    !> What the power law's node terms take of the apse constants c once per panel: the
    !! slopes' constants in hardware precision and the branches that do not depend on the
    !! node (binary128 comparisons are library calls: a dozen per node before).
    type :: power_node_setup
        real(xp) :: cx(2) = 0.0_xp     !! [a/E(Lambda), R^a] in hardware precision
        integer :: exponent = exponent_general  !! a = 2, 1, 1/2 (exponent_*) or other
        logical :: r_positive = .false.    !! R > 0
        logical :: ra_positive = .false.   !! R^a > 0
        real(qp) :: two_offset = 0.0_qp    !! 2 c(8): exp rather than expm1 of -a lambda
    end type power_node_setup

    type, abstract :: speed_law
    contains
        procedure(scalar_law), deferred :: speed_squared   !! P(x) = v(x)^2
        procedure(pair_law), deferred :: divided_difference !! (P(x) - P(y))/(x - y)
        procedure(limit_law), deferred :: apse_angle_limit !! lim Theta(R,R), R -> 0
        procedure :: passes_centre => no_centre_passage  !! v(0) finite
        procedure :: valid => default_valid  !! parameters inside the supported range
        procedure :: apse_constants => default_apse_constants !! per-apse data for arch_terms
        procedure :: arch_terms => default_arch_terms     !! q, 1 - q, q/v at a node
        !> arch_terms at the nodes of one panel (laws may share exponentials between
        !! nodes placed symmetrically about the panel's midpoint)
        procedure :: panel_terms => default_panel_terms
        !> sqrt(q/(1 - q)) exp(shift) in double precision, for the solver's early phase
        procedure :: theta_ratio64 => default_theta_ratio64
        procedure :: inverse_speed => default_inverse_speed !! 1/v(x) at x = exp(-delta)
        !> x/v(x) at x = exp(-delta), the integrand of the fall time in delta
        procedure :: fall_integrand => default_fall_integrand
        !> The fall time from x = exp(-delta_lo) to exp(-delta_hi) in closed form, where
        !! the law has one (`found`)
        procedure :: closed_fall => default_closed_fall
        procedure :: conserved => default_conserved       !! K = R/v(R) (eq. 25)
        !> Distances (in lambda from the apse, delta from the start) of the nearest
        !! complex singularities of the integrands in those variables
        procedure :: log_scales => default_log_scales
        !> Constants the law keeps for its own methods, computed once (the engine calls
        !! it on its copy of the law; without it the methods compute them each time)
        procedure :: prepare => no_preparation
        !> Whether the law has the hardware-precision terms below (else the engine
        !! takes its double-precision phase and quad-precision secant steps)
        procedure :: has_terms_xp => default_has_terms_xp
        !> Per-apse constants for theta_terms_xp and panel_terms_xp, from Lambda = -log R
        procedure :: apse_constants_xp => default_apse_constants_xp
        !> sqrt(q/(1 - q)) exp(shift), 1 - q and d(log q)/d Lambda at fixed lambda, in
        !! hardware precision
        procedure :: theta_terms_xp => default_theta_terms_xp
        !> g = sqrt(q/(1 - q)) exp(shift) and h = d(log q)/d Lambda/(2 (1 - q)) at a
        !! panel's nodes, in hardware precision (the early phase's sums)
        procedure :: panel_terms_xp => default_panel_terms_xp
    end type speed_law

    abstract interface
        pure function scalar_law(self, x) result(p)
            import :: speed_law, qp
            class(speed_law), intent(in) :: self
            real(qp), intent(in) :: x
            real(qp) :: p
        end function scalar_law
        pure function pair_law(self, x, y) result(d)
            import :: speed_law, qp
            class(speed_law), intent(in) :: self
            real(qp), intent(in) :: x, y
            real(qp) :: d
        end function pair_law
        pure function limit_law(self) result(angle)
            import :: speed_law, qp
            class(speed_law), intent(in) :: self
            real(qp) :: angle
        end function limit_law
    end interface

    !> Attractive inverse-square force, mu = 1: v^2 = 2(1 - x)/x (eq. 44).
    type, extends(speed_law) :: inverse_square_law
    contains
        procedure :: speed_squared => inverse_square_p
        procedure :: divided_difference => inverse_square_d
        procedure :: apse_angle_limit => inverse_square_limit
    end type inverse_square_law

    !> A fall time t0(delta) = sqrt(delta) g(delta) (g analytic, g(0) = sqrt(2)) in pieces
    !! s = sqrt(delta) in [k, k+1] (`build_fall_pieces`, `fall_pieces_time`): per piece
    !! the Chebyshev coefficients in u in [-1, 1] (binary128 and hardware precision), the
    !! last one above 2^-66 (head) and the last one kept (top), and t0(100) (far)
    type :: fall_pieces
        real(qp) :: c(0:mild_degree, 0:mild_pieces - 1) = 0.0_qp
        real(xp) :: c_xp(0:mild_degree, 0:mild_pieces - 1) = 0.0_xp
        integer :: head(0:mild_pieces - 1) = 0, top(0:mild_pieces - 1) = 0
        real(qp) :: far = 0.0_qp
    end type fall_pieces

    !> Attractive power law F = 1/r^n, n > 1: v^2 = 2 (x^(1-n) - 1)/(n - 1).
    type, extends(speed_law) :: power_law
        real(qp) :: n = 2.0_qp !! exponent of the force, n > 1
        !> t0(0) = B(1/a + 1/2, 1/2)/sqrt(2 a), a = n - 1 (`prepare`; 0: not kept)
        real(qp) :: fall_limit = 0.0_qp
        !> The fall time's series with their coefficients computed once (`power_prepare`,
        !! for n >= 3/2: `tabulated_fall_time`): c_k/(2k+1) in W^2 and d_k/(p+k) in y,
        !! in binary128 and hardware precision, and the factors sqrt(2/a), 1/sqrt(2 a)
        logical :: fall_table = .false.
        real(qp) :: fall_w(0:fall_terms) = 0.0_qp, fall_y(0:fall_terms) = 0.0_qp
        real(xp) :: fall_w_xp(0:fall_terms) = 0.0_xp, fall_y_xp(0:fall_terms) = 0.0_xp
        real(qp) :: fall_scale(2) = 0.0_qp
        !> For n < 3/2 (`power_prepare`): the fall time's tables (`fall_pieces`)
        logical :: mild_table = .false.
        type(fall_pieces) :: mild
    contains
        procedure :: speed_squared => power_p
        procedure :: divided_difference => power_d
        procedure :: apse_angle_limit => power_limit
        procedure :: apse_constants => power_apse_constants
        procedure :: arch_terms => power_arch_terms
        procedure :: panel_terms => power_panel_terms
        procedure :: theta_ratio64 => power_theta_ratio64
        procedure :: inverse_speed => power_inverse_speed
        procedure :: fall_integrand => power_fall_integrand
        procedure :: closed_fall => power_closed_fall
        procedure :: conserved => power_conserved
        procedure :: log_scales => power_log_scales
        procedure :: prepare => power_prepare
        procedure :: valid => power_valid
        procedure :: has_terms_xp => power_has_terms_xp
        procedure :: apse_constants_xp => power_apse_constants_xp
        procedure :: theta_terms_xp => power_theta_terms_xp
        procedure :: panel_terms_xp => power_panel_terms_xp
    end type power_law

    !> Logarithmic potential (F = 1/r, the power law n = 1): v^2 = -2 log x.
    type, extends(speed_law) :: logarithmic_law
    contains
        procedure :: speed_squared => logarithmic_p
        procedure :: divided_difference => logarithmic_d
        procedure :: apse_angle_limit => logarithmic_limit
        procedure :: apse_constants => logarithmic_apse_constants
        procedure :: arch_terms => logarithmic_arch_terms
        procedure :: panel_terms => logarithmic_panel_terms
        procedure :: theta_ratio64 => logarithmic_theta_ratio64
        procedure :: inverse_speed => logarithmic_inverse_speed
        procedure :: fall_integrand => logarithmic_fall_integrand
        procedure :: closed_fall => logarithmic_closed_fall
        procedure :: conserved => logarithmic_conserved
        procedure :: log_scales => logarithmic_log_scales
        procedure :: has_terms_xp => logarithmic_has_terms_xp
        procedure :: apse_constants_xp => logarithmic_apse_constants_xp
        procedure :: theta_terms_xp => logarithmic_theta_terms_xp
    end type logarithmic_law

    !> Inside a uniform planet (Saitoh), R_E = 1, omega = 1: v^2 = 1 - x^2.
    type, extends(speed_law) :: harmonic_law
    contains
        procedure :: speed_squared => harmonic_p
        procedure :: divided_difference => harmonic_d
        procedure :: apse_angle_limit => harmonic_limit
        procedure :: passes_centre => harmonic_passes_centre
        procedure :: log_scales => harmonic_log_scales
        procedure :: apse_constants => harmonic_apse_constants
        procedure :: arch_terms => harmonic_arch_terms
        procedure :: theta_ratio64 => harmonic_theta_ratio64
        procedure :: inverse_speed => harmonic_inverse_speed
        procedure :: conserved => harmonic_conserved
        procedure :: closed_fall => harmonic_closed_fall
        procedure :: has_terms_xp => harmonic_has_terms_xp
        procedure :: apse_constants_xp => harmonic_apse_constants_xp
        procedure :: theta_terms_xp => harmonic_theta_terms_xp
    end type harmonic_law

contains

    !> Whether a particle can pass through the centre (finite speed there): then the
    !! limit 2 lim Theta(R,R) of the accessible angle is reached, by the path through O.
    pure logical function no_centre_passage(self)
        class(speed_law), intent(in) :: self
        no_centre_passage = .false.
    end function no_centre_passage

    !> Parameters inside the supported range (no parameters: always).
    pure logical function default_valid(self)
        class(speed_law), intent(in) :: self
        default_valid = .true.
    end function default_valid

    !> 1 < n <= max_power_exponent.
    pure logical function power_valid(self)
        class(power_law), intent(in) :: self
        power_valid = self%n > 1.0_qp .and. self%n <= max_power_exponent
    end function power_valid

    pure logical function harmonic_passes_centre(self)
        class(harmonic_law), intent(in) :: self
        harmonic_passes_centre = .true.
    end function harmonic_passes_centre

    pure function inverse_square_p(self, x) result(p)
        class(inverse_square_law), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp) :: p
        p = 2.0_qp*(1.0_qp - x)/x
    end function inverse_square_p

    pure function inverse_square_d(self, x, y) result(d)
        class(inverse_square_law), intent(in) :: self
        real(qp), intent(in) :: x, y
        real(qp) :: d
        d = -2.0_qp/(x*y)
    end function inverse_square_d

    pure function inverse_square_limit(self) result(angle)
        class(inverse_square_law), intent(in) :: self
        real(qp) :: angle
        angle = acos(-1.0_qp)/3.0_qp
    end function inverse_square_limit

    pure function power_p(self, x) result(p)
        class(power_law), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp) :: p
        ! x^(1-n) - 1 = expm1((1-n) log x), accurate near x = 1
        p = 2.0_qp*expm1((1.0_qp - self%n)*log(x))/(self%n - 1.0_qp)
    end function power_p

    !> (x^a - y^a)/(x - y) = y^(a-1) (t^a - 1)/(t - 1), t = x/y, with
    !! t^a - 1 = expm1(a log t): no cancellation as x -> y.
    pure function power_d(self, x, y) result(d)
        class(power_law), intent(in) :: self
        real(qp), intent(in) :: x, y
        real(qp) :: d, a, u
        a = 1.0_qp - self%n
        u = (x - y)/y
        if (u == 0.0_qp) then
            d = a*y**(a - 1.0_qp)
        else
            d = y**(a - 1.0_qp)*expm1(a*log_ratio(x, y))/u
        end if
        d = 2.0_qp*d/(self%n - 1.0_qp)
    end function power_d

    !> log(x/y) to full relative precision for all x, y > 0: log1p((x - y)/y) while x is
    !! close to y (there log(x/y) would lose the digits of x/y - 1), log(x/y) otherwise
    !! (there log1p(u) with u near -1 would lose the digits of x lost in x - y).
    elemental function log_ratio(x, y) result(l)
        real(qp), intent(in) :: x, y
        real(qp) :: l, u
        u = (x - y)/y
        if (abs(u) < 0.5_qp) then
            l = log1p(u)
        else
            l = log(x/y)
        end if
    end function log_ratio

    !> Keam's result quoted by Tee: the apse angle tends to pi/(n+1) as R -> 0.
    pure function power_limit(self) result(angle)
        class(power_law), intent(in) :: self
        real(qp) :: angle
        angle = acos(-1.0_qp)/(self%n + 1.0_qp)
    end function power_limit

    pure function logarithmic_p(self, x) result(p)
        class(logarithmic_law), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp) :: p
        p = -2.0_qp*log(x)
    end function logarithmic_p

    pure function logarithmic_d(self, x, y) result(d)
        class(logarithmic_law), intent(in) :: self
        real(qp), intent(in) :: x, y
        real(qp) :: d, u
        u = (x - y)/y
        if (u == 0.0_qp) then
            d = -2.0_qp/y
        else
            d = -2.0_qp*log_ratio(x, y)/(x - y)
        end if
    end function logarithmic_d

    pure function logarithmic_limit(self) result(angle)
        class(logarithmic_law), intent(in) :: self
        real(qp) :: angle
        angle = acos(-1.0_qp)/2.0_qp
    end function logarithmic_limit

    pure function harmonic_p(self, x) result(p)
        class(harmonic_law), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp) :: p
        p = (1.0_qp - x)*(1.0_qp + x)
    end function harmonic_p

    pure function harmonic_d(self, x, y) result(d)
        class(harmonic_law), intent(in) :: self
        real(qp), intent(in) :: x, y
        real(qp) :: d
        d = -(x + y)
    end function harmonic_d

    !> The hypocycloid through the centre is the diameter: apse angle pi/2 as R -> 0.
    pure function harmonic_limit(self) result(angle)
        class(harmonic_law), intent(in) :: self
        real(qp) :: angle
        angle = acos(-1.0_qp)/2.0_qp
    end function harmonic_limit

    !> Per-apse constants for `arch_terms`: [R, 1 - R, Lambda = -log R, P(R)] here
    !! (R and 1 - R exact as the engine carries them).
    pure function default_apse_constants(self, big_r, one_minus_big_r, big_lambda) result(c)
        class(speed_law), intent(in) :: self
        real(qp), intent(in) :: big_r            !! apse radius R
        real(qp), intent(in) :: one_minus_big_r  !! 1 - R, exact
        real(qp), intent(in) :: big_lambda       !! -log R
        real(qp) :: c(8)
        c = [big_r, one_minus_big_r, big_lambda, &
             -one_minus_big_r*self%divided_difference(big_r, 1.0_qp), 0.0_qp, 0.0_qp, &
             0.0_qp, 0.0_qp]
    end function default_apse_constants

    !> q = (R/x)^2 P(x)/P(R), 1 - q = (x - R) M/x^2 with M = (x + R) - R^2 D(x,R)/P(R)
    !! (a sum of positive terms for attractive laws), q/sqrt(P(x)), and R/x, at the node
    !! lambda = log(x/R), delta = -log x.
    pure subroutine default_arch_terms(self, c, lambda, delta, q, one_minus_q, q_over_v, &
                                       r_over_x, root_q, log_slope)
        class(speed_law), intent(in) :: self
        real(qp), intent(in) :: c(8)           !! from apse_constants
        real(qp), intent(in) :: lambda, delta  !! offsets from the apse and the start
        real(qp), intent(out) :: q, one_minus_q, q_over_v, r_over_x
        real(qp), intent(out) :: root_q  !! sqrt(q)
        !> d(log q)/d Lambda at fixed lambda in hardware precision (laws with
        !! has_terms_xp; 0 otherwise)
        real(xp), intent(out), optional :: log_slope
        real(qp) :: x, p_x, m
        r_over_x = exp(-lambda)
        x = exp(-delta)
        p_x = -expm1(-delta)*(-self%divided_difference(x, 1.0_qp))
        m = (x + c(1)) - c(1)**2*self%divided_difference(x, c(1))/c(4)
        q = (c(1)/x)**2*p_x/c(4)
        one_minus_q = c(1)*expm1(lambda)*m/x**2
        q_over_v = q/sqrt(p_x)
        root_q = sqrt(q)
        if (present(log_slope)) log_slope = 0.0_xp
    end subroutine default_arch_terms

    !> `arch_terms` at the nodes k = 1..n of one panel. The panel's variable v (lambda
    !! where side = 1, delta where side = 2; side = 0: neither) is mid + offset(k) at
    !! node k, offset(n + 1 - k) = -offset(k); lambda(k), delta(k) from that v.
    pure subroutine default_panel_terms(self, c, side, mid, offset, lambda, delta, q, &
                                        one_minus_q, q_over_v, r_over_x, root_q, log_slope)
        class(speed_law), intent(in) :: self
        real(qp), intent(in) :: c(8), mid
        integer, intent(in) :: side !! 1: v = lambda, 2: v = delta, 0: other
        real(qp), intent(in) :: offset(:), lambda(:), delta(:) !! v - mid and the nodes
        real(qp), intent(out) :: q(:), one_minus_q(:), q_over_v(:), r_over_x(:), root_q(:)
        real(xp), intent(out), optional :: log_slope(:) !! as `arch_terms`
        integer :: k
        do k = 1, size(lambda)
            if (present(log_slope)) then
                call self%arch_terms(c, lambda(k), delta(k), q(k), one_minus_q(k), &
                                     q_over_v(k), r_over_x(k), root_q(k), log_slope(k))
            else
                call self%arch_terms(c, lambda(k), delta(k), q(k), one_minus_q(k), &
                                     q_over_v(k), r_over_x(k), root_q(k))
            end if
        end do
    end subroutine default_panel_terms

    !> 1/v(x) at x = exp(-delta): 1/sqrt((1 - x) V(x)), V = -D(x, 1).
    pure function default_inverse_speed(self, delta) result(w)
        class(speed_law), intent(in) :: self
        real(qp), intent(in) :: delta !! -log x > 0
        real(qp) :: w
        w = 1.0_qp/sqrt(-expm1(-delta)*(-self%divided_difference(exp(-delta), 1.0_qp)))
    end function default_inverse_speed

    !> x/v(x) at x = exp(-delta): exp(-delta)/v.
    pure function default_fall_integrand(self, delta) result(w)
        class(speed_law), intent(in) :: self
        real(qp), intent(in) :: delta !! -log x > 0
        real(qp) :: w
        w = self%inverse_speed(delta)*fast_exp(-delta)
    end function default_fall_integrand

    !> No closed form here: `found` false, t = 0.
    pure subroutine default_closed_fall(self, delta_lo, delta_hi, t, found)
        class(speed_law), intent(in) :: self
        real(qp), intent(in) :: delta_lo, delta_hi  !! 0 <= delta_lo <= delta_hi
        real(qp), intent(out) :: t                  !! the fall time between them
        logical, intent(out) :: found               !! a closed form was used
        t = 0.0_qp
        found = .false.
    end subroutine default_closed_fall

    !> K = R/v(R), the conserved angular momentum of the associated free particle.
    pure function default_conserved(self, c) result(k)
        class(speed_law), intent(in) :: self
        real(qp), intent(in) :: c(8) !! from apse_constants
        real(qp) :: k
        k = c(1)/sqrt(c(4))
    end function default_conserved

    !> [sigma_apse, sigma_start]: inverse-square values (w(x) = w(R) at x = R e^(2 pi i/3)
    !! for small R; P has no other zero).
    !> No constants to keep.
    pure subroutine no_preparation(self)
        class(speed_law), intent(inout) :: self
    end subroutine no_preparation

    !> The fall time to the centre, t0(0) = B(p, 1/2)/sqrt(2 a), p = 1/a + 1/2, for
    !! `power_fall_time` (two gamma functions, about 20 us, per call otherwise); a >= 1/100
    !! (below it the fall time never needs it). For a >= 1/2 also the coefficients of the
    !! fall time's two series (`tabulated_fall_time`): c_0 = 1, c_(k+1) = c_k (k+1-p)/(k+1)
    !! (the binomial series of (1 - w^2)^(p-1)), d_0 = 1, d_(k+1) = d_k (k+1/2)/(k+1).
    pure subroutine power_prepare(self)
        class(power_law), intent(inout) :: self
        real(qp) :: a, p, c, d
        integer :: k
        a = self%n - 1.0_qp
        self%fall_limit = 0.0_qp
        if (a >= 0.01_qp) self%fall_limit = fall_beta(a)/sqrt(2.0_qp*a)
        self%fall_table = a >= table_min_a .and. a == a
        self%mild_table = a > 0.0_qp .and. a < table_min_a
        if (self%mild_table) call build_fall_pieces(a, self%fall_limit, self%mild)
        if (.not. self%fall_table) return
        p = 1.0_qp/a + 0.5_qp
        c = 1.0_qp
        d = 1.0_qp
        do k = 0, fall_terms
            self%fall_w(k) = c/real(2*k + 1, qp)
            self%fall_y(k) = d/(p + real(k, qp))
            c = c*(real(k + 1, qp) - p)/real(k + 1, qp)
            d = d*(real(k, qp) + 0.5_qp)/real(k + 1, qp)
        end do
        self%fall_w_xp = real(self%fall_w, xp)
        self%fall_y_xp = real(self%fall_y, xp)
        self%fall_scale = [sqrt(2.0_qp/a), 1.0_qp/sqrt(2.0_qp*a)]
    end subroutine power_prepare

    !> The fall time's tables of the power law a = n - 1 < 1/2 (a = 0: the logarithmic
    !! law's): per piece the Chebyshev interpolant at the mild_degree + 1 Lobatto points of t0/s
    !! (k = 0, in delta) or t0 (in s), from `power_fall_time` (mild_pieces mild_degree
    !! calls), cut where the coefficients reach the values' rounding.
    pure subroutine build_fall_pieces(a, limit, pieces)
        real(qp), intent(in) :: a
        real(qp), intent(in) :: limit    !! t0(0) where known (`power_prepare`), else 0
        type(fall_pieces), intent(out) :: pieces
        real(qp) :: node(0:mild_degree), f(0:mild_degree), cheb(0:mild_degree)
        real(qp) :: cosines(0:2*mild_degree - 1), delta, pi, line(2)
        integer :: j, k
        pi = acos(-1.0_qp)
        do j = 0, 2*mild_degree - 1
            cosines(j) = cos(pi*real(j, qp)/real(mild_degree, qp))
        end do
        node = cosines(0:mild_degree)
        node(mild_degree) = -1.0_qp
        do k = 0, mild_pieces - 1
            do j = 0, mild_degree
                if (k == 0 .and. j == mild_degree) then
                    f(j) = sqrt(2.0_qp)     ! t0 = sqrt(2 delta) (1 + O(delta))
                else if (k == 0) then
                    delta = 0.5_qp*(node(j) + 1.0_qp)
                    f(j) = power_fall_time(a, delta, limit)/sqrt(delta)
                else
                    delta = (real(k, qp) + 0.5_qp*(node(j) + 1.0_qp))**2
                    f(j) = power_fall_time(a, delta, limit)
                end if
            end do
            ! (of the values less the chord through the ends: coefficients from small sums)
            line = 0.5_qp*[f(0) + f(mild_degree), f(0) - f(mild_degree)]
            cheb = chebyshev_coefficients(cosines, f - line(1) - line(2)*node)
            cheb(0:1) = cheb(0:1) + line
            ! (the rounding of the values makes a floor near eps of them: cut there)
            do j = mild_degree, 1, -1
                if (abs(cheb(j)) > 2.0_qp**(-111)*minval(f)) exit
                cheb(j) = 0.0_qp
            end do
            pieces%c(:, k) = cheb
            call mild_split(cheb, minval(f), pieces%head(k), pieces%top(k))
        end do
        pieces%c_xp = real(pieces%c, xp)
        pieces%far = power_fall_time(a, real(mild_pieces**2, qp), limit)
    end subroutine build_fall_pieces

    !> c_i = (2/N) sum_j'' f_j T_i(u_j) (c_0, c_N and the terms j = 0, N halved) at the
    !! Chebyshev-Lobatto points u_j = cos(pi j/N), T_i(u_j) = cosines(mod(i j, 2N)) (to half
    !! an ulp), N = mild_degree.
    pure function chebyshev_coefficients(cosines, f) result(cheb)
        real(qp), intent(in) :: cosines(0:2*mild_degree - 1), f(0:mild_degree)
        real(qp) :: cheb(0:mild_degree)
        integer :: i, j
        do i = 0, mild_degree
            cheb(i) = 0.5_qp*(f(0) + f(mild_degree)*cosines(mod(i*mild_degree, 2*mild_degree)))
            do j = 1, mild_degree - 1
                cheb(i) = cheb(i) + f(j)*cosines(mod(i*j, 2*mild_degree))
            end do
        end do
        cheb = cheb*(2.0_qp/real(mild_degree, qp))
        cheb(0) = 0.5_qp*cheb(0)
        cheb(mild_degree) = 0.5_qp*cheb(mild_degree)
    end function chebyshev_coefficients

    !> The last coefficient above 2^-66 (head) and 1e-38 (top) of the least value.
    pure subroutine mild_split(cheb, least, head, top)
        real(qp), intent(in) :: cheb(0:mild_degree), least
        integer, intent(out) :: head, top
        integer :: j
        head = 0
        top = 0
        do j = 1, mild_degree
            if (abs(cheb(j)) > 2.0_qp**(-66)*least) head = j
            if (abs(cheb(j)) > 1.0e-38_qp*least) top = j
        end do
    end subroutine mild_split

    !> B(p, 1/2) = Gamma(p) sqrt(pi)/Gamma(p + 1/2), p = 1/a + 1/2.
    pure function fall_beta(a) result(beta)
        real(qp), intent(in) :: a
        real(qp) :: beta, p
        p = 1.0_qp/a + 0.5_qp
        beta = gamma(p)*sqrt(acos(-1.0_qp))/gamma(p + 0.5_qp)
    end function fall_beta

    pure function default_log_scales(self) result(sigma)
        class(speed_law), intent(in) :: self
        real(qp) :: sigma(2)
        sigma = [2.0_qp*acos(-1.0_qp)/3.0_qp, 2.0_qp*acos(-1.0_qp)]
    end function default_log_scales

    !> Harmonic: w(x) = w(R) at x = -R, P = 0 at x = -1: both at distance pi.
    pure function harmonic_log_scales(self) result(sigma)
        class(harmonic_law), intent(in) :: self
        real(qp) :: sigma(2)
        sigma = [acos(-1.0_qp), acos(-1.0_qp)]
    end function harmonic_log_scales

    !> exp(-lambda), 1 - exp(-lambda), 1 - exp(-2 lambda) and exp(-2 lambda), all to full
    !! relative precision (lambda >= 0);
    !! where delta < lambda (nearer the start) exp(-lambda) = R exp(delta), since lambda =
    !! Lambda - delta carries an absolute rounding error of Lambda's size.
    elemental subroutine exp_pair(lambda, delta, big_r, e1, om1, om2, e2, from_start)
        real(qp), intent(in) :: lambda, delta, big_r
        real(qp), intent(out) :: e1, om1, om2, e2
        !> delta < lambda and R > 0, where the caller knows it
        logical, intent(in), optional :: from_start
        real(qp) :: em1
        logical :: start
        if (lambda > 0.5_qp) then
            if (present(from_start)) then
                start = from_start
            else
                start = delta < lambda .and. big_r > 0.0_qp
            end if
            if (start) then
                e1 = big_r*fast_exp(delta)
            else
                e1 = fast_exp(-lambda)
            end if
            om1 = 1.0_qp - e1
            e2 = e1*e1
            om2 = 1.0_qp - e2
        else
            em1 = fast_expm1(-lambda)
            e1 = 1.0_qp + em1
            om1 = -em1
            om2 = -em1*(2.0_qp + em1)
            e2 = e1*e1
        end if
    end subroutine exp_pair

    !> E(y) = 1 - exp(-a y) for y >= 0, accurate for all a y.
    elemental function decay(a, y) result(e)
        real(qp), intent(in) :: a, y
        real(qp) :: e
        e = -fast_expm1(-a*y)
    end function decay

    !> Power law: [Lambda, E(Lambda), a, R^a = exp(-a Lambda), R, 1/E(Lambda), c7, 1/(4a)].
    pure function power_apse_constants(self, big_r, one_minus_big_r, big_lambda) result(c)
        class(power_law), intent(in) :: self
        real(qp), intent(in) :: big_r, one_minus_big_r, big_lambda
        real(qp) :: c(8), a
        a = self%n - 1.0_qp
        ! R^a (powq) rather than exp(-a Lambda): Lambda's rounding would cost a Lambda eps
        c = [big_lambda, decay(a, big_lambda), a, power_of(big_r, a), big_r, 0.0_qp, &
             0.0_qp, 0.0_qp]
        if (a*big_lambda > 0.5_qp) c(2) = 1.0_qp - c(4)
        c(6) = 1.0_qp/c(2)
        ! q/v = sqrt(q) exp(-lambda) R^(a/2) sqrt(a/(2 E(Lambda)))
        c(7) = fast_sqrt(0.5_qp*a*c(4)*c(6))
        ! the offset 1/(4 a) where arch_terms switches from expm1 to exp
        c(8) = 0.25_qp/a
    end function power_apse_constants

    !> x^a (powq) with the exponents of n = 1.5, 2, 3 by one rounding at most (powq, a
    !! logarithm and an exponential in software, costs as much as a dozen nodes).
    elemental function power_of(x, a) result(y)
        real(qp), intent(in) :: x, a
        real(qp) :: y
        if (a == 2.0_qp) then
            y = x*x
        else if (a == 1.0_qp) then
            y = x
        else if (a == 0.5_qp) then
            y = sqrt(x)
        else
            y = x**a
        end if
    end function power_of

    !> Two expm1 per node (one for n = 1.5, 2, 3, where exp(-a lambda) follows from
    !! exp(-lambda); where a delta <= 1/4 E(lambda) and E(delta) follow from either and
    !! E(Lambda)): exp(-lambda) = 1 + expm1(-lambda),
    !! 1 - exp(-2 lambda) = -expm1(-lambda) (2 + expm1(-lambda)), E(lambda) =
    !! -expm1(-a lambda), exp(-a delta) = exp(-a Lambda)/exp(-a lambda).
    pure subroutine power_arch_terms(self, c, lambda, delta, q, one_minus_q, q_over_v, &
                                     r_over_x, root_q, log_slope)
        class(power_law), intent(in) :: self
        real(qp), intent(in) :: c(8), lambda, delta
        real(qp), intent(out) :: q, one_minus_q, q_over_v, r_over_x
        real(qp), intent(out) :: root_q  !! sqrt(q)
        !> d(log q)/d Lambda at fixed lambda in hardware precision (laws with
        !! has_terms_xp; 0 otherwise)
        real(xp), intent(out), optional :: log_slope
        call power_node_terms(c, power_node_constants(c), lambda, delta, q, one_minus_q, &
                              q_over_v, r_over_x, root_q, log_slope)
    end subroutine power_arch_terms

    !> `power_node_setup` of the apse constants c (`power_apse_constants`).
    pure function power_node_constants(c) result(setup)
        real(qp), intent(in) :: c(8)
        type(power_node_setup) :: setup
        setup%cx = [hardware_real(c(3)*c(6)), hardware_real(c(4))]
        if (c(3) == 2.0_qp) then
            setup%exponent = exponent_two
        else if (c(3) == 1.0_qp) then
            setup%exponent = exponent_one
        else if (c(3) == 0.5_qp) then
            setup%exponent = exponent_half
        end if
        setup%r_positive = c(5) > 0.0_qp
        setup%ra_positive = c(4) > 0.0_qp
        setup%two_offset = 2.0_qp*c(8)
    end function power_node_constants

    !> `power_arch_terms` at one node (k: `power_node_constants`).
    pure subroutine power_node_terms(c, setup, lambda, delta, q, one_minus_q, q_over_v, &
                                     r_over_x, root_q, log_slope)
        real(qp), intent(in) :: c(8), lambda, delta
        type(power_node_setup), intent(in) :: setup
        real(qp), intent(out) :: q, one_minus_q, q_over_v, r_over_x, root_q
        real(xp), intent(out), optional :: log_slope
        real(qp) :: a, om1, om2, e1, e2, eam1, ea, e_delta
        logical :: known  ! E(delta) already at hand
        logical :: nearer_start, small_delta  ! delta < lambda, a delta <= 1/4
        a = c(3)
        known = .false.
        e_delta = 0.0_qp
        nearer_start = delta < lambda
        small_delta = delta <= c(8)
        call exp_pair(lambda, delta, c(5), e1, om1, om2, e2, nearer_start .and. setup%r_positive)
        select case (setup%exponent)
        case (exponent_two)
            ! n = 3: exp(-a lambda) = exp(-2 lambda)
            ea = e2
            eam1 = -om2
        case (exponent_one)
            ! n = 2: exp(-a lambda) = exp(-lambda)
            ea = e1
            eam1 = -om1
        case (exponent_half)
            ! n = 1.5: exp(-lambda/2) = sqrt(exp(-lambda)), 1 - it = (1 - e1)/(1 + it)
            ea = root(e1)
            eam1 = -om1/(1.0_qp + ea)
        case default
            call general_exponent_terms(c, setup, lambda, delta, nearer_start, small_delta, ea, &
                                        eam1, e_delta, known)
        end select
        call power_finish_terms(c, setup, lambda, delta, nearer_start, small_delta, e1, om2, e2, &
                                ea, eam1, known, e_delta, q, one_minus_q, q_over_v, &
                                r_over_x, root_q, log_slope)
    end subroutine power_node_terms

    !> exp(-a lambda) = ea, ea - 1 and, where it is at hand (`known`), E(delta) at one node
    !! for an exponent a other than 2, 1, 1/2 (`power_node_terms`).
    pure subroutine general_exponent_terms(c, setup, lambda, delta, nearer_start, small_delta, &
                                           ea, eam1, e_delta, known)
        real(qp), intent(in) :: c(8), lambda, delta
        type(power_node_setup), intent(in) :: setup
        logical, intent(in) :: nearer_start, small_delta  !! delta < lambda, delta <= c(8)
        real(qp), intent(out) :: ea, eam1
        real(qp), intent(inout) :: e_delta
        logical, intent(inout) :: known
        real(qp) :: a
        a = c(3)
        if (small_delta .and. nearer_start .and. setup%ra_positive) then
            ! nearer the start, a delta <= 1/4: E(delta) by expm1 (below) and from it
            ! exp(-a lambda) = R^a/(1 - E(delta)), E(lambda) = (E(Lambda) - E(delta))/
            ! (1 - E(delta)) (lambda >= Lambda/2: at most two bits cancel; one
            ! transcendental for the two)
            e_delta = decay(a, delta)
            known = .true.
            if (lambda > setup%two_offset) then
                ea = c(4)/(1.0_qp - e_delta)
                eam1 = ea - 1.0_qp
            else
                eam1 = (e_delta - c(2))/(1.0_qp - e_delta)
                ea = 1.0_qp + eam1
            end if
        else if (lambda > setup%two_offset) then
            if (nearer_start .and. setup%ra_positive) then
                ! nearer the start: exp(-a lambda) = R^a exp(a delta), exact arguments
                ea = c(4)*fast_exp(a*delta)
            else
                ea = fast_exp(-a*lambda)
            end if
            eam1 = ea - 1.0_qp
        else
            eam1 = fast_expm1(-a*lambda)
            ea = 1.0_qp + eam1
        end if
    end subroutine general_exponent_terms

    !> `power_arch_terms` from exp(-lambda) = e1, 1 - exp(-2 lambda) = om2, e2 =
    !! exp(-2 lambda), ea = exp(-a lambda), eam1 = ea - 1 and, where known, E(delta)
    !! (k: `power_node_constants`; the slope's factors converted on the bits).
    pure subroutine power_finish_terms(c, setup, lambda, delta, nearer_start, small_delta, e1, &
                                       om2, e2, ea, eam1, known, e_delta, q, one_minus_q, &
                                       q_over_v, r_over_x, root_q, log_slope)
        real(qp), intent(in) :: c(8), lambda, delta, e1, om2, e2, ea, eam1
        type(power_node_setup), intent(in) :: setup
        logical, intent(in) :: nearer_start, small_delta  !! delta < lambda, delta <= c(8)
        logical, intent(in) :: known
        real(qp), intent(inout) :: e_delta
        real(qp), intent(out) :: q, one_minus_q, q_over_v, r_over_x, root_q
        real(xp), intent(out), optional :: log_slope
        real(qp) :: a, ea_e_delta
        real(xp) :: ratio_xp, e_delta_xp
        a = c(3)
        if (.not. small_delta .and. setup%ra_positive) then
            ! exp(-a lambda) E(delta) = exp(-a lambda) - R^a (no division; E(delta) >=
            ! 1 - e^(-1/4): at most two bits cancel, as in 1 - R^a/exp(-a lambda))
            ea_e_delta = ea - c(4)
            if (present(log_slope)) ratio_xp = setup%cx(2)/hardware_real(ea_e_delta)
        else if (.not. nearer_start .and. setup%ra_positive) then
            ! nearer the apse, a delta <= 1/4: exp(-a lambda) E(delta) = E(Lambda) -
            ! E(lambda) (delta >= Lambda/2: at most two bits cancel; no expm1)
            ea_e_delta = c(2) + eam1
            if (present(log_slope)) ratio_xp = setup%cx(2)/hardware_real(ea_e_delta)
        else
            if (.not. known) e_delta = decay(a, delta)
            ea_e_delta = ea*e_delta
            if (present(log_slope)) then
                ! exp(-a delta)/E(delta) (1 - E(delta) in hardware precision where a delta
                ! <= 1/4, as where c(4) > 0 here)
                e_delta_xp = hardware_real(e_delta)
                if (setup%ra_positive) then
                    ratio_xp = (1.0_xp - e_delta_xp)/e_delta_xp
                else
                    ratio_xp = hardware_real(1.0_qp - e_delta)/e_delta_xp
                end if
            end if
        end if
        root_q = e1*root(ea_e_delta*c(6))
        q = root_q*root_q
        one_minus_q = om2 + e2*(-eam1)*c(6)
        q_over_v = root_q*e1*c(7)
        r_over_x = e1
        ! a E(lambda) exp(-a delta)/(E(Lambda) E(delta)) (see power_theta_terms_xp)
        if (present(log_slope)) log_slope = setup%cx(1)*(-hardware_real(eam1))*ratio_xp
    end subroutine power_finish_terms

    !> `power_arch_terms` on one panel. Where the panel's variable v is lambda (side 1)
    !! or delta (side 2), exp and expm1 of -lambda, -a lambda or a delta at the nodes
    !! v = mid +- t come from their values at mid and at t (`pair_exps`): one exponential
    !! per node pair and one division instead of two exponentials. On the apse side
    !! exp(-lambda), exp(-a lambda) with exact arguments; on the start side, as in
    !! `power_arch_terms`, R exp(delta), R^a exp(a delta) or E(delta) (where a delta <=
    !! 1/4), there only where lambda > 1/2 and every node would take those forms there;
    !! elsewhere node by node.
    pure subroutine power_panel_terms(self, c, side, mid, offset, lambda, delta, q, &
                                      one_minus_q, q_over_v, r_over_x, root_q, log_slope)
        class(power_law), intent(in) :: self
        real(qp), intent(in) :: c(8), mid
        integer, intent(in) :: side
        real(qp), intent(in) :: offset(:), lambda(:), delta(:)
        real(qp), intent(out) :: q(:), one_minus_q(:), q_over_v(:), r_over_x(:), root_q(:)
        real(xp), intent(out), optional :: log_slope(:)
        real(qp), dimension(size(lambda)) :: e1, em1, ea, eam1, e_delta
        real(qp) :: a
        type(power_node_setup) :: setup
        integer :: k
        logical :: known
        a = c(3)
        known = .false.
        e_delta = 0.0_qp
        setup = power_node_constants(c)
        if (.not. pair_terms_apply(c, side, lambda, delta)) then
            ! node by node (the root panels above all)
            do k = 1, size(lambda)
                if (present(log_slope)) then
                    call power_node_terms(c, setup, lambda(k), delta(k), q(k), one_minus_q(k), &
                                          q_over_v(k), r_over_x(k), root_q(k), log_slope(k))
                else
                    call power_node_terms(c, setup, lambda(k), delta(k), q(k), one_minus_q(k), &
                                          q_over_v(k), r_over_x(k), root_q(k))
                end if
            end do
            return
        end if
        if (side == 1) then
            call pair_exps(-1.0_qp, mid, offset, e1, em1)
            if (setup%exponent == exponent_general) call pair_exps(-a, mid, offset, ea, eam1)
        else
            call pair_exps(1.0_qp, mid, offset, e1, em1)
            e1 = c(5)*e1
            em1 = -(1.0_qp - e1)
            if (setup%exponent == exponent_general) then
                if (minval(delta) > c(8)) then
                    call pair_exps(a, mid, offset, ea, eam1)
                    ea = c(4)*ea
                    eam1 = ea - 1.0_qp
                else
                    ! E(delta) as in power_arch_terms where a delta <= 1/4
                    ! (1 - E(delta) = exp(-a delta) as computed, not by a difference)
                    call pair_exps(-a, mid, offset, ea, eam1)
                    e_delta = -eam1
                    known = .true.
                    where (lambda > 2.0_qp*c(8))
                        ea = c(4)/ea
                        eam1 = ea - 1.0_qp
                    elsewhere
                        eam1 = (e_delta - c(2))/ea
                        ea = 1.0_qp + eam1
                    end where
                end if
            end if
        end if
        select case (setup%exponent)
        case (exponent_two)
            ea = e1*e1
            eam1 = em1*(2.0_qp + em1)
        case (exponent_one)
            ea = e1
            eam1 = em1
        case (exponent_half)
            ea = root(e1)
            eam1 = em1/(1.0_qp + ea)
        end select
        do k = 1, size(lambda)
            if (present(log_slope)) then
                call power_finish_terms(c, setup, lambda(k), delta(k), delta(k) < lambda(k), &
                                        delta(k) <= c(8), e1(k), -em1(k)*(2.0_qp + em1(k)), &
                                        e1(k)*e1(k), ea(k), eam1(k), known, e_delta(k), q(k), &
                                        one_minus_q(k), q_over_v(k), r_over_x(k), root_q(k), &
                                        log_slope(k))
            else
                call power_finish_terms(c, setup, lambda(k), delta(k), delta(k) < lambda(k), &
                                        delta(k) <= c(8), e1(k), -em1(k)*(2.0_qp + em1(k)), &
                                        e1(k)*e1(k), ea(k), eam1(k), known, e_delta(k), q(k), &
                                        one_minus_q(k), q_over_v(k), r_over_x(k), root_q(k))
            end if
        end do
    end subroutine power_panel_terms

    !> Exponents with exp(-a lambda) from exp(-lambda) (n = 1.5, 2, 3).
    elemental logical function special_exponent(a)
        real(qp), intent(in) :: a
        special_exponent = a == 2.0_qp .or. a == 1.0_qp .or. a == 0.5_qp
    end function special_exponent

    !> Whether `power_panel_terms` takes its pairs: a linear panel of an even rule; on
    !! the start side R and R^a normal (R exp(delta) <= 1) and lambda > 1/2 (1 - R
    !! exp(delta) loses at most 1.4 bits), and for general a either a delta > 1/4 and a
    !! lambda > 1/2 at every node or, where a delta <= 1/4, lambda > delta or a lambda >
    !! 1/2 (E(Lambda) - E(delta) then loses at most two bits, as there).
    pure logical function pair_terms_apply(c, side, lambda, delta) result(ok)
        real(qp), intent(in) :: c(8), lambda(:), delta(:)
        integer, intent(in) :: side
        ok = (side == 1 .or. side == 2) .and. mod(size(lambda), 2) == 0
        if (.not. ok .or. side == 1) return
        ok = c(4) > 2.0_qp**(-16000) .and. c(5) > 2.0_qp**(-16000) .and. &
             minval(lambda) > 0.5_qp
        if (.not. ok .or. special_exponent(c(3))) return
        if (minval(delta) > c(8)) then
            ok = minval(lambda) > 2.0_qp*c(8)
        else
            ok = all(lambda > 2.0_qp*c(8) .or. (delta < lambda .and. delta <= c(8)))
        end if
    end function pair_terms_apply

    !> exp(s v) and expm1(s v) at v = mid + offset(k), offset(n + 1 - k) = -offset(k)
    !! (s mid <= 0 where expm1 is wanted): both at mid once, then per pair w = -|s
    !! offset(k)|, x = expm1(w) and y = exp(w) (one exponential; the other from it
    !! without loss) and one division: the node at s mid + w gets e y and e_m1 + e x
    !! (one sign), its partner e/y and e_m1 - e x/y (about log2(mid/(mid - |offset|))
    !! bits cancel: 1.3 at most on panels with hi <= 4 lo, as the engine's linear ones).
    pure subroutine pair_exps(s, mid, offset, ev, em1v)
        real(qp), intent(in) :: s, mid, offset(:)
        real(qp), intent(out) :: ev(:), em1v(:)
        real(qp) :: centre, centre_m1, x, y, w
        integer :: k, n, far, near
        n = size(offset)
        if (abs(s*mid) < 0.5_qp) then
            centre_m1 = fast_expm1(s*mid)
            centre = 1.0_qp + centre_m1
        else
            centre = fast_exp(s*mid)
            centre_m1 = centre - 1.0_qp
        end if
        do k = 1, n/2
            w = -abs(s*offset(k))
            if (w > -0.5_qp) then
                x = fast_expm1(w)
                y = 1.0_qp + x
            else
                y = fast_exp(w)
                x = y - 1.0_qp
            end if
            far = merge(k, n + 1 - k, s*offset(k) <= 0.0_qp)
            near = n + 1 - far
            ev(far) = centre*y
            em1v(far) = centre_m1 + centre*x
            ev(near) = centre/y
            em1v(near) = centre_m1 - ev(near)*x
        end do
    end subroutine pair_exps

    !> sqrt(z): the hardware square root and one correction (`fast_sqrt`, within an ulp).
    elemental function root(z) result(r)
        real(qp), intent(in) :: z
        real(qp) :: r
        r = fast_sqrt(z)
    end function root

    !> 1/v = sqrt(a/2) exp(-a delta/2)/sqrt(E(delta)).
    pure function power_inverse_speed(self, delta) result(w)
        class(power_law), intent(in) :: self
        real(qp), intent(in) :: delta
        real(qp) :: w, a
        a = self%n - 1.0_qp
        w = sqrt(0.5_qp*a/decay(a, delta))*fast_exp(-0.5_qp*a*delta)
    end function power_inverse_speed

    !> x/v = exp(-(a/2 + 1) delta)/sqrt(2 E(delta)/a); n = 3: x^2/sqrt(1 - x^2); n = 2:
    !! x^2/sqrt(2 x (1 - x)) (one exp less).
    pure function power_fall_integrand(self, delta) result(w)
        class(power_law), intent(in) :: self
        real(qp), intent(in) :: delta
        real(qp) :: w, a, em1, x, e
        a = self%n - 1.0_qp
        if (a == 2.0_qp .or. a == 1.0_qp) then
            em1 = fast_expm1(-delta)
            x = 1.0_qp + em1
            if (a == 2.0_qp) then
                w = x*x*inverse_sqrt(-em1*(2.0_qp + em1))
            else
                w = x*x*inverse_sqrt(-2.0_qp*x*em1)
            end if
        else
            if (a*delta < 0.5_qp) then
                e = -fast_expm1(-a*delta)
            else
                e = 1.0_qp - fast_exp(-a*delta)
            end if
            w = fast_exp(-(0.5_qp*a + 1.0_qp)*delta)*inverse_sqrt(2.0_qp*e/a)
        end if
    end function power_fall_integrand

    !> n = 3: t0(x) = sqrt(1 - x^2); n = 2: the inverse-square fall time (Tee eq. 46);
    !! other n: a series of incomplete gamma functions or an incomplete beta function
    !! (`power_fall_time`; n >= 3/2: `tabulated_fall_time`, the same series' coefficients
    !! kept by `power_prepare`). (exp and expm1: `fast_exp`'s, within 0.6 ulp, about nine
    !! times faster than libquadmath's; t0(1) = 0 not evaluated.)
    pure subroutine power_closed_fall(self, delta_lo, delta_hi, t, found)
        class(power_law), intent(in) :: self
        real(qp), intent(in) :: delta_lo, delta_hi
        real(qp), intent(out) :: t
        logical, intent(out) :: found
        real(qp) :: a
        a = self%n - 1.0_qp
        found = a > 0.0_qp
        t = 0.0_qp
        if (self%n == 3.0_qp) then
            t = fast_sqrt(-fast_expm1(-2.0_qp*delta_hi))
            if (delta_lo > 0.0_qp) t = t - fast_sqrt(-fast_expm1(-2.0_qp*delta_lo))
        else if (self%n == 2.0_qp) then
            t = inverse_square_fall(delta_hi)
            if (delta_lo > 0.0_qp) t = t - inverse_square_fall(delta_lo)
        else if (self%fall_table) then
            t = tabulated_fall_time(self, delta_hi)
            if (delta_lo > 0.0_qp) t = t - tabulated_fall_time(self, delta_lo)
        else if (self%mild_table) then
            t = mild_fall(delta_hi)
            if (delta_lo > 0.0_qp) t = t - mild_fall(delta_lo)
        else if (found) then
            t = power_fall_time(a, delta_hi, self%fall_limit)
            if (delta_lo > 0.0_qp) t = t - power_fall_time(a, delta_lo, self%fall_limit)
        end if
    contains
        !> The inverse-square fall time to x = exp(-delta), x and 1 - x each from the
        !! exponential that gives it to its relative precision.
        pure real(qp) function inverse_square_fall(delta)
            real(qp), intent(in) :: delta
            real(qp) :: x, e
            if (delta < 0.5_qp) then
                e = fast_expm1(-delta)
                inverse_square_fall = radial_time(1.0_qp + e, -e)
            else
                x = fast_exp(-delta)
                inverse_square_fall = radial_time(x, 1.0_qp - x)
            end if
        end function inverse_square_fall

        !> n < 3/2: the tables (`fall_pieces_time`), the series at delta <= 0
        pure real(qp) function mild_fall(delta)
            real(qp), intent(in) :: delta
            if (delta > 0.0_qp) then
                mild_fall = fall_pieces_time(self%mild, delta)
            else
                mild_fall = power_fall_time(a, delta, self%fall_limit)
            end if
        end function mild_fall
    end subroutine power_closed_fall

    !> The fall time from 1 to x = exp(-delta) of the power law a = n - 1 < 2 where
    !! a min(delta, 100) <= 2 log 2 (beyond delta = 100 it is t0(100) to within exp(-100)):
    !! x/v = exp(-b u) sqrt(z/sinh z)/sqrt(2 u), b = 1 + a/4, z = a u/2, so that
    !! t0 = (2 b)^(-1/2) sum_m C_m (a/(2 b))^(2m) gamma(2m + 1/2, b delta) (C_m:
    !! `sinh_root`; z <= log 2: the terms fall like (z/pi)^(2m), at most 28 of them).
    !! The lower incomplete gamma functions: from sqrt(pi) erf(sqrt(x)) upward (x >= 2 and
    !! 2 m a <= 8, where the recurrence loses less than the terms' fall gains) or from
    !! Kummer's series at the top downward (sums of positive terms): a few roundings.
    pure function mild_fall_time(a, delta) result(t)
        real(qp), intent(in) :: a, delta
        real(qp) :: t, b, x, w, total, power, sum, term
        real(qp) :: gam(0:2*mild_terms), p(0:2*mild_terms)
        real(real64) :: ratio
        integer :: m, top, j, k
        b = 1.0_qp + 0.25_qp*a
        x = b*min(delta, 100.0_qp)
        w = (0.5_qp*a/b)**2
        ! terms while 0.2 (z/pi)^(2m) exceeds 1e-37 (z/pi <= log(2)/pi: at most 28)
        ratio = real(0.5_qp*a*min(delta, 100.0_qp), real64)/acos(-1.0_real64)
        top = 1
        if (ratio > 0.0_real64) top = min(mild_terms, max(1, &
            ceiling(log(5.0e-37_real64)/(2.0_real64*log(ratio)))))
        ! p(j) = x^(j + 1/2) exp(-x), gam(j) = gamma(j + 1/2, x)
        p(0) = sqrt(x)*fast_exp(-x)
        do j = 1, 2*top
            p(j) = p(j - 1)*x
        end do
        if (x >= 2.0_qp .and. real(2*top, qp)*a <= 8.0_qp) then
            ! (the upward recurrence multiplies gam(0)'s rounding by about Gamma(2m + 1/2),
            ! the weights by (a/(2 pi b))^(2m): below (2 m a/(2 pi b e))^(2m) < 0.5^(2m))
            gam(0) = sqrt(acos(-1.0_qp))*erf(sqrt(x))
            do j = 1, 2*top
                gam(j) = (real(j, qp) - 0.5_qp)*gam(j - 1) - p(j - 1)
            end do
        else
            sum = 1.0_qp
            term = 1.0_qp
            do k = 1, max_series_terms
                term = term*x*inverse_half(2*top + k)
                sum = sum + term
                if (term <= 1.0e-36_qp*sum) exit
            end do
            gam(2*top) = p(2*top)*inverse_half(2*top)*sum
            do j = 2*top - 1, 0, -1
                gam(j) = (gam(j + 1) + p(j))*inverse_half(j)
            end do
        end if
        total = 0.0_qp
        power = 1.0_qp
        do m = 0, top
            total = total + sinh_root(m)*power*gam(2*m)
            power = power*w
        end do
        t = total/sqrt(2.0_qp*b)
    end function mild_fall_time

    !> The fall time from 1 to x = exp(-delta) of the power law a = n - 1 (`mild_fall_time`
    !! where a < 2 and a min(delta, 100) <= 2 log 2; otherwise, where p = 1/a + 1/2 < 73):
    !! t0 = I(y)/sqrt(2 a), I(y) = int_y^1 t^(p-1) (1-t)^(-1/2) dt, y = x^a, p = 1/a + 1/2
    !! (t = y). For y >= 1/2, with 1 - t = w^2, I = 2 sum_k c_k W^(2k+1)/(2k+1), W^2 = 1 - y,
    !! c_k the binomial series of (1 - w^2)^(p-1); below, I = B(p, 1/2) - sum_k d_k
    !! y^(p+k)/(p+k), d_k = (1/2)_k/k!. Both series have ratio at most 1/2 (terms of one
    !! sign after the first few); about 115 terms for 36 digits. The terms from where
    !! they fall below 2^-64 of the sum (the tail, below 2^-63 of it) in hardware
    !! precision (`series_tail`: an error below 1e-17 of the tail, 1e-36 of the sum).
    pure function power_fall_time(a, delta, limit) result(t)
        real(qp), intent(in) :: a, delta
        real(qp), intent(in) :: limit  !! t0(0) where known (`power_prepare`), else 0
        real(qp) :: t, p, w2, power, c, term, total, y
        real(qp), parameter :: head = 2.0_qp**(-64)
        integer :: k
        if (a < 2.0_qp .and. a*min(delta, 100.0_qp) <= 2.0_qp*log_two) then
            t = mild_fall_time(a, delta)
            return
        end if
        p = 1.0_qp/a + 0.5_qp
        total = 0.0_qp
        if (a*delta <= log_two) then
            w2 = -fast_expm1(-a*delta)
            power = sqrt(w2)
            c = 1.0_qp
            do k = 0, max_series_terms
                term = c*power*inverse_odd(k)
                total = total + term
                if (abs(term) <= 1.0e-36_qp*abs(total)) exit
                c = c*(real(k + 1, qp) - p)*inverse_integer(k + 1)
                power = power*w2
                ! past the terms of both signs (k + 1 > p - 1)
                if (abs(term) <= head*abs(total) .and. real(k, qp) > p) then
                    total = total + series_tail(.true., k + 1, c, power, w2, p, total)
                    exit
                end if
            end do
            t = 2.0_qp*total/sqrt(2.0_qp*a)
        else
            y = fast_exp(-a*delta)
            power = fast_exp(-(1.0_qp + 0.5_qp*a)*delta)   ! y^p
            c = 1.0_qp
            do k = 0, max_series_terms
                term = c*power/(p + real(k, qp))
                total = total + term
                if (term <= 1.0e-36_qp*total) exit
                c = c*half_step(k)
                power = power*y
                if (term <= head*total) then
                    total = total + series_tail(.false., k + 1, c, power, y, p, total)
                    exit
                end if
            end do
            if (limit > 0.0_qp) then
                t = limit - total/sqrt(2.0_qp*a)
            else
                t = (fall_beta(a) - total)/sqrt(2.0_qp*a)
            end if
        end if
    end function power_fall_time

    !> `power_fall_time`'s two series (a >= 1/2, no `mild_fall_time`) with the coefficients
    !! kept by `power_prepare`: t0 = sqrt(2/a) W sum_k w_k u^k, u = W^2 = 1 - y <= 1/2, or
    !! t0 = t0(0) - y^p sum_k y_k y^k/sqrt(2 a), y = exp(-a delta) < 1/2, by Horner's rule
    !! (`fall_series`): no divisions, two operations per term.
    pure function tabulated_fall_time(law, delta) result(t)
        type(power_law), intent(in) :: law
        real(qp), intent(in) :: delta
        real(qp) :: t, a, u, y
        a = law%n - 1.0_qp
        if (a*delta <= log_two) then
            u = -fast_expm1(-a*delta)
            t = law%fall_scale(1)*fast_sqrt(u)*fall_series(law%fall_w, law%fall_w_xp, u)
        else
            y = fast_exp(-a*delta)
            t = law%fall_limit - fast_exp(-(1.0_qp + 0.5_qp*a)*delta)*law%fall_scale(2)* &
                fall_series(law%fall_y, law%fall_y_xp, y)
        end if
    end function tabulated_fall_time

    !> A fall time from its tables (`build_fall_pieces`), delta > 0: s = sqrt(delta) in
    !! [k, k+1], u = 2 (s - k) - 1 (k = 0: u = 2 delta - 1, t0 = s P(u)), by Clenshaw's
    !! recurrence (`clenshaw`); t0(100) beyond delta = 100.
    pure function fall_pieces_time(pieces, delta) result(t)
        type(fall_pieces), intent(in) :: pieces
        real(qp), intent(in) :: delta
        real(qp) :: t, s, u
        integer :: k
        if (delta >= real(mild_pieces**2, qp)) then
            t = pieces%far
            return
        end if
        s = fast_sqrt(delta)
        if (delta < 1.0_qp) then
            k = 0
            u = 2.0_qp*delta - 1.0_qp
        else
            k = min(mild_pieces - 1, int(s))
            u = 2.0_qp*(s - real(k, qp)) - 1.0_qp
        end if
        t = clenshaw(pieces%c(:, k), pieces%c_xp(:, k), pieces%head(k), pieces%top(k), u)
        if (k == 0) t = s*t
    end function fall_pieces_time

    !> sum_i c_i T_i(u), i <= top, |u| <= 1, by Clenshaw's recurrence, the coefficients
    !! after `head` (below 2^-66 of the sum) in hardware precision.
    pure function clenshaw(c, c_xp, head, top, u) result(total)
        real(qp), intent(in) :: c(0:mild_degree), u
        real(xp), intent(in) :: c_xp(0:mild_degree)
        integer, intent(in) :: head, top
        real(qp) :: total, b1, b2, b0, u2
        real(xp) :: x1, x2, x0, u2_xp
        integer :: i
        x1 = 0.0_xp
        x2 = 0.0_xp
        u2_xp = 2.0_xp*hardware_real(u)
        do i = top, head + 1, -1
            x0 = c_xp(i) + u2_xp*x1 - x2
            x2 = x1
            x1 = x0
        end do
        b1 = real(x1, qp)
        b2 = real(x2, qp)
        u2 = 2.0_qp*u
        do i = head, 1, -1
            b0 = c(i) + u2*b1 - b2
            b2 = b1
            b1 = b0
        end do
        total = c(0) + u*b1 - b2
    end function clenshaw

    !> sum_k c_k r^k, 0 <= r <= 1/2, |c_k| <= 1 falling slower than r^k: the terms to
    !! r^k < 1e-36 (after the first, the sums' least terms relative to their first), those
    !! from r^k < 2^-64 on in hardware precision (their error below 1e-37 of the sum).
    pure function fall_series(c, c_xp, r) result(total)
        real(qp), intent(in) :: c(0:fall_terms), r
        real(xp), intent(in) :: c_xp(0:fall_terms)
        real(qp) :: total
        real(xp) :: tail, r_xp
        real(real64) :: log_r
        integer :: top, head, k
        total = c(0)
        if (r <= 0.0_qp) return
        log_r = log(max(real(r, real64), tiny(1.0_real64)))
        top = min(fall_terms, 1 + ceiling(log(1.0e-36_real64)/log_r))
        head = min(top, 1 + ceiling(log(2.0_real64**(-64))/log_r))
        if (top > head) then
            r_xp = hardware_real(r)
            tail = c_xp(top)
            do k = top - 1, head + 1, -1
                tail = tail*r_xp + c_xp(k)
            end do
            total = c(head) + r*real(tail, qp)
        else
            total = c(top)
        end if
        do k = head - 1, 0, -1
            total = total*r + c(k)
        end do
    end function fall_series

    !> The tail of `power_fall_time`'s series from term k on (c, power: its coefficient
    !! and power there, ratio: the power's ratio; `binomial`: the series in W, else the
    !! one in y), in hardware precision, until the terms fall below 1e-36 of `total`.
    pure function series_tail(binomial, k, c, power, ratio, p, total) result(tail)
        logical, intent(in) :: binomial
        integer, intent(in) :: k
        real(qp), intent(in) :: c, power, ratio, p, total
        real(qp) :: tail
        real(xp) :: c_x, power_x, ratio_x, p_x, term, sum, least
        integer :: j
        c_x = real(c, xp)
        power_x = real(power, xp)
        ratio_x = real(ratio, xp)
        p_x = real(p, xp)
        least = real(1.0e-36_qp*abs(total), xp)
        sum = 0.0_xp
        do j = k, max_series_terms
            if (binomial) then
                term = c_x*power_x/real(2*j + 1, xp)
                c_x = c_x*(real(j + 1, xp) - p_x)/real(j + 1, xp)
            else
                term = c_x*power_x/(p_x + real(j, xp))
                c_x = c_x*(real(j, xp) + 0.5_xp)/real(j + 1, xp)
            end if
            sum = sum + term
            if (abs(term) <= least) exit
            power_x = power_x*ratio_x
        end do
        tail = real(sum, qp)
    end function series_tail

    !> K = R/v(R) = sqrt(a/(2 E(Lambda))) R^(1 + a/2) = R c(7) (no exponential: c(7) =
    !! sqrt(a R^a/(2 E(Lambda))) from `power_apse_constants`).
    pure function power_conserved(self, c) result(k)
        class(power_law), intent(in) :: self
        real(qp), intent(in) :: c(8)
        real(qp) :: k
        k = c(5)*c(7)
    end function power_conserved

    !> w(x) = w(R) at lambda = 2 pi i/(n+1) (small R); P(x) = 0 at delta = 2 pi i/(n-1).
    pure function power_log_scales(self) result(sigma)
        class(power_law), intent(in) :: self
        real(qp) :: sigma(2)
        sigma = [2.0_qp*acos(-1.0_qp)/(self%n + 1.0_qp), &
                 2.0_qp*acos(-1.0_qp)/max(self%n - 1.0_qp, 1.0e-3_qp)]
    end function power_log_scales

    !> Logarithmic law: [Lambda, 0, 0, 0, R, 0].
    pure function logarithmic_apse_constants(self, big_r, one_minus_big_r, big_lambda) &
        result(c)
        class(logarithmic_law), intent(in) :: self
        real(qp), intent(in) :: big_r, one_minus_big_r, big_lambda
        real(qp) :: c(8)
        c = [big_lambda, 0.0_qp, 0.0_qp, 0.0_qp, big_r, 1.0_qp/big_lambda, &
             inverse_sqrt(2.0_qp*big_lambda), 0.0_qp]
    end function logarithmic_apse_constants

    !> The power law's terms in the limit a -> 0: E(y)/a -> y, P = 2 delta.
    pure subroutine logarithmic_arch_terms(self, c, lambda, delta, q, one_minus_q, &
                                           q_over_v, r_over_x, root_q, log_slope)
        class(logarithmic_law), intent(in) :: self
        real(qp), intent(in) :: c(8), lambda, delta
        real(qp), intent(out) :: q, one_minus_q, q_over_v, r_over_x
        real(qp), intent(out) :: root_q  !! sqrt(q)
        !> d(log q)/d Lambda at fixed lambda in hardware precision (laws with
        !! has_terms_xp; 0 otherwise)
        real(xp), intent(out), optional :: log_slope
        real(qp) :: om1, om2, e1, e2
        call exp_pair(lambda, delta, c(5), e1, om1, om2, e2)
        ! c(6) = 1/Lambda, c(7) = 1/sqrt(2 Lambda)
        root_q = e1*root(delta*c(6))
        q = root_q*root_q
        one_minus_q = om2 + e2*lambda*c(6)
        q_over_v = root_q*e1*c(7)
        r_over_x = e1
        if (present(log_slope)) log_slope = real(lambda, xp)/(real(delta, xp)*real(c(1), xp))
    end subroutine logarithmic_arch_terms

    !> `logarithmic_arch_terms` on one panel: exp(-lambda) by node pairs (`pair_exps`)
    !! where `power_panel_terms` takes them for n = 2 (the same forms), else node by node.
    pure subroutine logarithmic_panel_terms(self, c, side, mid, offset, lambda, delta, q, &
                                            one_minus_q, q_over_v, r_over_x, root_q, &
                                            log_slope)
        class(logarithmic_law), intent(in) :: self
        real(qp), intent(in) :: c(8), mid
        integer, intent(in) :: side
        real(qp), intent(in) :: offset(:), lambda(:), delta(:)
        real(qp), intent(out) :: q(:), one_minus_q(:), q_over_v(:), r_over_x(:), root_q(:)
        real(xp), intent(out), optional :: log_slope(:)
        real(qp), dimension(size(lambda)) :: e1, em1, e2, om1, om2
        real(xp) :: inverse_lambda
        integer :: k
        inverse_lambda = 1.0_xp/hardware_real(c(1))
        if (.not. pair_terms_apply([c(1:2), 1.0_qp, 1.0_qp, c(5:8)], side, lambda, delta)) then
            ! node by node (the root panels above all), as logarithmic_arch_terms
            do k = 1, size(lambda)
                call exp_pair(lambda(k), delta(k), c(5), e1(k), om1(k), om2(k), e2(k))
            end do
            root_q = e1*root(delta*c(6))
            q = root_q*root_q
            one_minus_q = om2 + e2*lambda*c(6)
            q_over_v = root_q*e1*c(7)
            r_over_x = e1
            if (present(log_slope)) log_slope = hardware_real(lambda)*inverse_lambda/ &
                                                hardware_real(delta)
            return
        end if
        if (side == 1) then
            call pair_exps(-1.0_qp, mid, offset, e1, em1)
        else
            call pair_exps(1.0_qp, mid, offset, e1, em1)
            e1 = c(5)*e1
            em1 = -(1.0_qp - e1)
        end if
        e2 = e1*e1
        ! as logarithmic_arch_terms; 1 - exp(-2 lambda) = -em1 (2 + em1)
        root_q = e1*root(delta*c(6))
        q = root_q*root_q
        one_minus_q = -em1*(2.0_qp + em1) + e2*lambda*c(6)
        q_over_v = root_q*e1*c(7)
        r_over_x = e1
        if (present(log_slope)) log_slope = hardware_real(lambda)*inverse_lambda/ &
                                            hardware_real(delta)
    end subroutine logarithmic_panel_terms

    pure function logarithmic_inverse_speed(self, delta) result(w)
        class(logarithmic_law), intent(in) :: self
        real(qp), intent(in) :: delta
        real(qp) :: w
        w = 1.0_qp/sqrt(2.0_qp*delta)
    end function logarithmic_inverse_speed

    pure function logarithmic_fall_integrand(self, delta) result(w)
        class(logarithmic_law), intent(in) :: self
        real(qp), intent(in) :: delta
        real(qp) :: w
        w = fast_exp(-delta)*inverse_sqrt(2.0_qp*delta)
    end function logarithmic_fall_integrand

    !> t0 = sqrt(pi/2) erf(sqrt(delta)) (x/v = exp(-delta)/sqrt(2 delta)); differences of
    !! erfc where both arguments exceed 1. (`fall_pieces` with a = 0 would be 0.65 us
    !! faster per call, 1.7 us now, but up to 3 eps off, against about 1 eps here.)
    pure subroutine logarithmic_closed_fall(self, delta_lo, delta_hi, t, found)
        class(logarithmic_law), intent(in) :: self
        real(qp), intent(in) :: delta_lo, delta_hi
        real(qp), intent(out) :: t
        logical, intent(out) :: found
        found = .true.
        if (delta_lo > 1.0_qp) then
            t = erfc(fast_sqrt(delta_lo)) - erfc(fast_sqrt(delta_hi))
        else
            t = erf(fast_sqrt(delta_hi)) - erf(fast_sqrt(delta_lo))
        end if
        t = sqrt(0.5_qp*acos(-1.0_qp))*t
    end subroutine logarithmic_closed_fall

    !> K = R/v(R) = R/sqrt(2 Lambda) = R c(7) (`logarithmic_apse_constants`).
    pure function logarithmic_conserved(self, c) result(k)
        class(logarithmic_law), intent(in) :: self
        real(qp), intent(in) :: c(8)
        real(qp) :: k
        k = c(5)*c(7)
    end function logarithmic_conserved

    !> w(x) = w(R) at lambda = i pi (small R); P has no zero but x = 1.
    pure function logarithmic_log_scales(self) result(sigma)
        class(logarithmic_law), intent(in) :: self
        real(qp) :: sigma(2)
        sigma = [acos(-1.0_qp), 1.0e3_qp]
    end function logarithmic_log_scales

    !> Double precision sqrt(q/(1 - q)) exp(shift) (here through the quad-precision
    !! terms). The shift keeps the values in range: q ~ R^(n+1) underflows double
    !! precision long before binary128 (the early phase of tiny R-bar).
    pure function default_theta_ratio64(self, c, lambda, delta, shift) result(g)
        class(speed_law), intent(in) :: self
        real(qp), intent(in) :: c(8)                 !! from apse_constants
        real(real64), intent(in) :: lambda, delta    !! offsets from the apse and the start
        real(real64), intent(in) :: shift            !! log of the scale factor
        real(real64) :: g
        real(qp) :: q, one_minus_q, q_over_v, r_over_x, root_q
        call self%arch_terms(c, real(lambda, qp), real(delta, qp), q, one_minus_q, &
                             q_over_v, r_over_x, root_q)
        g = real(sqrt(q/one_minus_q)*exp(real(shift, qp)), real64)
    end function default_theta_ratio64

    pure function power_theta_ratio64(self, c, lambda, delta, shift) result(g)
        class(power_law), intent(in) :: self
        real(qp), intent(in) :: c(8)
        real(real64), intent(in) :: lambda, delta, shift
        real(real64) :: g, a, e2, e_big, om2, e_lambda
        a = real(c(3), real64)
        e_big = real(c(2), real64)
        e2 = exp(-2.0_real64*lambda)
        om2 = -expm1_64(-2.0_real64*lambda)
        ! n = 3: E(lambda) = 1 - exp(-2 lambda)
        e_lambda = om2
        if (a /= 2.0_real64) e_lambda = -expm1_64(-a*lambda)
        g = sqrt((-expm1_64(-a*delta))/(om2*e_big + e2*e_lambda)) &
            *exp(shift - 0.5_real64*(a + 2.0_real64)*lambda)
    end function power_theta_ratio64

    pure function logarithmic_theta_ratio64(self, c, lambda, delta, shift) result(g)
        class(logarithmic_law), intent(in) :: self
        real(qp), intent(in) :: c(8)
        real(real64), intent(in) :: lambda, delta, shift
        real(real64) :: g, e2, big
        big = real(c(1), real64)
        e2 = exp(-2.0_real64*lambda)
        g = sqrt(delta/(-expm1_64(-2.0_real64*lambda)*big + e2*lambda))*exp(shift - lambda)
    end function logarithmic_theta_ratio64

    !> expm1 in double precision (a series below 1e-5, where exp(y) - 1 cancels).
    elemental function expm1_64(y) result(e)
        real(real64), intent(in) :: y
        real(real64) :: e
        if (abs(y) < 1.0e-5_real64) then
            e = y*(1.0_real64 + y*(0.5_real64 + y/6.0_real64))
        else if (abs(y) < 0.5_real64) then
            e = 2.0_real64*exp(0.5_real64*y)*sinh(0.5_real64*y)
        else
            e = exp(y) - 1.0_real64
        end if
    end function expm1_64

    !> Harmonic law: [Lambda, 1 - R^2, 0, 0, R, 0].
    pure function harmonic_apse_constants(self, big_r, one_minus_big_r, big_lambda) &
        result(c)
        class(harmonic_law), intent(in) :: self
        real(qp), intent(in) :: big_r, one_minus_big_r, big_lambda
        real(qp) :: c(8)
        c = [big_lambda, one_minus_big_r*(1.0_qp + big_r), 0.0_qp, 0.0_qp, big_r, 0.0_qp, &
             0.0_qp, 0.0_qp]
        c(6) = 1.0_qp/c(2)
        c(7) = sqrt(c(6))
    end function harmonic_apse_constants

    !> P = 1 - x^2: q = exp(-2 lambda) (1 - x^2)/(1 - R^2), 1 - q = (1 - exp(-2 lambda))/
    !! (1 - R^2), q/v = q/sqrt(1 - x^2).
    pure subroutine harmonic_arch_terms(self, c, lambda, delta, q, one_minus_q, q_over_v, &
                                        r_over_x, root_q, log_slope)
        class(harmonic_law), intent(in) :: self
        real(qp), intent(in) :: c(8), lambda, delta
        real(qp), intent(out) :: q, one_minus_q, q_over_v, r_over_x
        real(qp), intent(out) :: root_q  !! sqrt(q)
        !> d(log q)/d Lambda at fixed lambda in hardware precision (laws with
        !! has_terms_xp; 0 otherwise)
        real(xp), intent(out), optional :: log_slope
        real(qp) :: e1, om1, om2, e2, p_x
        call exp_pair(lambda, delta, c(5), e1, om1, om2, e2)
        p_x = -fast_expm1(-2.0_qp*delta)
        ! c(6) = 1/(1 - R^2), c(7) = sqrt(c(6))
        root_q = e1*root(p_x*c(6))
        q = root_q*root_q
        one_minus_q = om2*c(6)
        q_over_v = root_q*e1*c(7)
        r_over_x = e1
        ! 2 x^2 (1 - exp(-2 lambda))/((1 - x^2)(1 - R^2)), x = R/exp(-lambda)
        if (present(log_slope)) log_slope = 2.0_xp*(real(c(5), xp)/real(e1, xp))**2* &
            real(om2, xp)*real(c(6), xp)/real(p_x, xp)
    end subroutine harmonic_arch_terms

    pure function harmonic_theta_ratio64(self, c, lambda, delta, shift) result(g)
        class(harmonic_law), intent(in) :: self
        real(qp), intent(in) :: c(8)
        real(real64), intent(in) :: lambda, delta, shift
        real(real64) :: g
        g = sqrt((-expm1_64(-2.0_real64*delta))/(-expm1_64(-2.0_real64*lambda))) &
            *exp(shift - lambda)
    end function harmonic_theta_ratio64

    pure function harmonic_inverse_speed(self, delta) result(w)
        class(harmonic_law), intent(in) :: self
        real(qp), intent(in) :: delta
        real(qp) :: w
        w = 1.0_qp/sqrt(-fast_expm1(-2.0_qp*delta))
    end function harmonic_inverse_speed

    pure function harmonic_conserved(self, c) result(k)
        class(harmonic_law), intent(in) :: self
        real(qp), intent(in) :: c(8)
        real(qp) :: k
        k = c(5)/sqrt(c(2))
    end function harmonic_conserved

    pure logical function default_has_terms_xp(self)
        class(speed_law), intent(in) :: self
        default_has_terms_xp = .false.
    end function default_has_terms_xp

    pure logical function power_has_terms_xp(self)
        class(power_law), intent(in) :: self
        power_has_terms_xp = .true.
    end function power_has_terms_xp

    pure logical function logarithmic_has_terms_xp(self)
        class(logarithmic_law), intent(in) :: self
        logarithmic_has_terms_xp = .true.
    end function logarithmic_has_terms_xp

    !> No hardware-precision terms: zeros (see has_terms_xp).
    pure function default_apse_constants_xp(self, big_lambda) result(c)
        class(speed_law), intent(in) :: self
        real(xp), intent(in) :: big_lambda  !! -log R
        real(xp) :: c(5)
        c = 0.0_xp
    end function default_apse_constants_xp

    !> No hardware-precision terms: zeros (see has_terms_xp).
    pure subroutine default_theta_terms_xp(self, c, lambda, delta, shift, rough, g, &
                                           one_minus_q, log_slope, exp_shift)
        class(speed_law), intent(in) :: self
        real(xp), intent(in) :: c(5)                 !! from apse_constants_xp
        real(xp), intent(in) :: lambda, delta        !! offsets from the apse and the start
        real(xp), intent(in) :: shift                !! log of the scale factor of g
        logical, intent(in) :: rough                 !! transcendentals in double precision
        real(xp), intent(out) :: g                   !! sqrt(q/(1 - q)) exp(shift)
        real(xp), intent(out) :: one_minus_q         !! 1 - q
        real(xp), intent(out) :: log_slope           !! d(log q)/d Lambda at fixed lambda
        !> exp(shift) where the caller has it (one exponential per evaluation rather than
        !! one per node; 0: not at hand); the laws then scale the node's own decay
        !! factors by it where they stay in range (`scaled_decay`)
        real(xp), intent(in), optional :: exp_shift
        g = 0.0_xp
        one_minus_q = 1.0_xp
        log_slope = 0.0_xp
    end subroutine default_theta_terms_xp

    !> `theta_terms_xp` node by node, h = log_slope/(2 (1 - q)).
    pure subroutine default_panel_terms_xp(self, c, lambda, delta, shift, rough, exp_shift, &
                                           g, h)
        class(speed_law), intent(in) :: self
        real(xp), intent(in) :: c(5)                 !! from apse_constants_xp
        real(xp), intent(in) :: lambda(:), delta(:)  !! the nodes' offsets (`theta_terms_xp`)
        real(xp), intent(in) :: shift                !! log of the scale factor of g
        logical, intent(in) :: rough                 !! transcendentals in double precision
        real(xp), intent(in) :: exp_shift            !! exp(shift), 0: not at hand
        real(xp), intent(out) :: g(:)                !! sqrt(q/(1 - q)) exp(shift)
        real(xp), intent(out) :: h(:)                !! d(log q)/d Lambda/(2 (1 - q))
        real(xp) :: one_minus_q, log_slope
        integer :: k
        do k = 1, size(lambda)
            call self%theta_terms_xp(c, lambda(k), delta(k), shift, rough, g(k), &
                                     one_minus_q, log_slope, exp_shift)
            h(k) = 0.5_xp*log_slope/one_minus_q
        end do
    end subroutine default_panel_terms_xp

    !> exp(-y) and E = 1 - exp(-y) = -expm1(-y), y >= 0, both to full relative precision
    !! in hardware precision (`table_exp_xp`), or `rough`ly: for y >= 1/2 in double
    !! precision (E then loses nothing), below it as the full ones (cheaper than double
    !! precision's exp and sinh for E without cancellation).
    elemental subroutine exp_and_decay_xp(y, e, one_minus_e, rough)
        real(xp), intent(in) :: y
        real(xp), intent(out) :: e, one_minus_e
        logical, intent(in) :: rough
        real(real64) :: e64
        if (rough .and. y >= 0.5_xp) then
            e64 = exp(-real(y, real64))
            e = real(e64, xp)
            one_minus_e = real(1.0_real64 - e64, xp)
        else
            call table_exp_xp(y, e, one_minus_e)
        end if
    end subroutine exp_and_decay_xp

    !> exp(-y) (and 1 - exp(-y) for y >= 0) in hardware precision for |y| <= 11000, both
    !! within about an ulp: y = (64 m + j) log(2)/64 + r, 0 <= r < log(2)/64 for y >= 0
    !! (k log(2)/64 exact in two parts), exp(-y) = 2^-m 2^(-j/64) (1 - E(r)), E(r) =
    !! -expm1(-r) by its Taylor series (8 terms, the next below 2^-70 of it); for m = 0
    !! (y < 0.69) 1 - exp(-y) = (1 - 2^(-j/64)) + 2^(-j/64) E(r) (positive terms), else
    !! 1 - exp(-y). Both tables rounded from binary128 constants; k and 2^-m on the bits
    !! of the x87 format (no library calls: several times cheaper than the library's long
    !! double exp). Elsewhere (|y| > 11000, or no x87 format) the library's exp, and for
    !! 0 <= y < 1/2 1 - exp(-y) by its Taylor series (18 terms).
    elemental subroutine table_exp_xp(y, e, one_minus_e)
        use, intrinsic :: iso_fortran_env, only: int64
        real(xp), intent(in) :: y
        real(xp), intent(out) :: e, one_minus_e
        integer, parameter :: decay_terms = 18
        integer :: i_, i, j
        integer(int64) :: k, m
        real(xp), parameter :: power(0:63) = &
            [(real(2.0_qp**(-real(i_, qp)/64.0_qp), xp), i_ = 0, 63)]
        real(xp), parameter :: decay(0:63) = &
            [(real(1.0_qp - 2.0_qp**(-real(i_, qp)/64.0_qp), xp), i_ = 0, 63)]
        real(xp), parameter :: inverse(2:decay_terms) = &
            [(1.0_xp/real(i_, xp), i_ = 2, decay_terms)]
        ! the Taylor coefficients of -expm1(-r), (-1)^(i+1)/i!
        real(xp), parameter :: c(8) = [(real((-1.0_qp)**(i_ + 1)/gamma(real(i_ + 1, qp)), &
                                             xp), i_ = 1, 8)]
        ! log(2)/64 in two parts, the first with 43 significant bits (k times it exact
        ! for |k| < 2^21)
        real(qp), parameter :: step = log(2.0_qp)/64.0_qp
        real(xp), parameter :: step_hi = real(anint(step*2.0_qp**49)*2.0_qp**(-49), xp)
        real(xp), parameter :: step_lo = real(step - real(step_hi, qp), xp)
        real(real64), parameter :: per_step = real(64.0_qp/log(2.0_qp), real64)
        integer(int64), parameter :: one_bits(2) = transfer(1.0_xp, [0_int64, 0_int64])
        logical, parameter :: x87 = digits(1.0_xp) == 64 .and. &
            storage_size(1.0_xp) == 128 .and. one_bits(1) == ishft(1_int64, 63) .and. &
            iand(one_bits(2), 65535_int64) == 16383_int64
        real(xp) :: r, r2, em
        if (.not. (x87 .and. abs(y) <= 11000.0_xp)) then
            if (y >= 0.0_xp .and. y < 0.5_xp) then
                one_minus_e = 1.0_xp
                do i = decay_terms, 2, -1
                    one_minus_e = 1.0_xp - y*one_minus_e*inverse(i)
                end do
                one_minus_e = y*one_minus_e
                e = 1.0_xp - one_minus_e
            else
                e = exp(-y)
                one_minus_e = 1.0_xp - e
            end if
            return
        end if
        ! k = y 64/log(2) rounded down for y >= 0 (r >= 0 up to the double-precision
        ! product's rounding: 1 - exp(-y) below adds positive terms), toward 0 below
        k = int(real(y, real64)*per_step, int64)
        j = int(iand(k, 63_int64))
        r = (y - real(k, xp)*step_hi) - real(k, xp)*step_lo
        ! r plus the rest (below r/2: the last rounding dominates), in pairs of terms
        r2 = r*r
        em = r + r2*((c(2) + r*c(3)) + r2*((c(4) + r*c(5)) + r2*((c(6) + r*c(7)) + &
                                                                 r2*c(8))))
        e = power(j) - power(j)*em
        if (k >= 0_int64 .and. k < 64_int64) then
            one_minus_e = decay(j) + power(j)*em
        else
            ! times 2^-m (|m| < 16000: a normal power of two; in double precision where
            ! |m| < 1000)
            m = (k - j)/64_int64
            if (abs(m) < 1000_int64) then
                e = e*real(transfer(ishft(1023_int64 - m, 52), 1.0_real64), xp)
            else
                e = e*transfer([ishft(1_int64, 63), 16383_int64 - m], 1.0_xp)
            end if
            one_minus_e = 1.0_xp - e
        end if
    end subroutine table_exp_xp

    !> The largest y for which exp(-y) is normal in the kind the early phase's terms take
    !! it in: double precision where `rough`, else the hardware kind (`table_exp_xp`).
    elemental function normal_reach(rough) result(y)
        logical, intent(in) :: rough
        real(xp) :: y
        y = merge(700.0_xp, 11000.0_xp, rough)
    end function normal_reach

    !> exp(shift - y) from exp(-y) = `decay` at hand: exp(shift) decay where the caller
    !! gives exp(shift) (`exp_shift` > 0) and decay (0: not normal, or not at hand), else
    !! `scaled_exp`.
    elemental function scaled_decay(shift, y, decay, rough, exp_shift) result(e)
        real(xp), intent(in) :: shift, y, decay
        logical, intent(in) :: rough
        real(xp), intent(in), optional :: exp_shift
        real(xp) :: e
        if (present(exp_shift)) then
            if (exp_shift > 0.0_xp .and. decay > 0.0_xp) then
                e = exp_shift*decay
                return
            end if
        end if
        e = scaled_exp(shift - y, rough)
    end function scaled_decay

    !> exp(y) in hardware precision, or `rough`ly in double precision (0 below its range).
    elemental function scaled_exp(y, rough) result(e)
        real(xp), intent(in) :: y
        logical, intent(in) :: rough
        real(xp) :: e
        real(xp) :: one_minus_e
        if (rough) then
            e = real(exp(real(max(y, -745.0_xp), real64)), xp)
        else
            call table_exp_xp(-y, e, one_minus_e)
        end if
    end function scaled_exp

    !> Power law: [Lambda, E(Lambda), a, exp(-a Lambda), a/(2 E(Lambda))].
    pure function power_apse_constants_xp(self, big_lambda) result(c)
        class(power_law), intent(in) :: self
        real(xp), intent(in) :: big_lambda
        real(xp) :: c(5), a
        a = hardware_real(self%n - 1.0_qp)
        c = [big_lambda, 0.0_xp, a, 0.0_xp, 0.0_xp]
        call exp_and_decay_xp(a*big_lambda, c(4), c(2), .false.)
        c(5) = 0.5_xp*a*(1.0_xp/c(2))
    end function power_apse_constants_xp

    !> Power law: q = exp(-(a+2) lambda) E(delta)/E(Lambda), 1 - q = (1 - exp(-2 lambda))
    !! + exp(-2 lambda) E(lambda)/E(Lambda) and, since exp(-a lambda) E(delta) =
    !! exp(-a lambda) - exp(-a Lambda), d(log q)/d Lambda = a E(lambda) exp(-a delta)/
    !! (E(Lambda) E(delta)). Two exponentials per node at most: exp(-a delta) =
    !! exp(-a Lambda)/exp(-a lambda) where a delta >= 1/2 (E(delta) loses under a bit) and
    !! exp(-a Lambda) is normal, and exp(shift - (a+2) lambda/2) = exp(shift) sqrt(exp(-2
    !! lambda) exp(-a lambda)) with `exp_shift` (`scaled_decay`).
    pure subroutine power_theta_terms_xp(self, c, lambda, delta, shift, rough, g, &
                                         one_minus_q, log_slope, exp_shift)
        class(power_law), intent(in) :: self
        real(xp), intent(in) :: c(5), lambda, delta, shift
        logical, intent(in) :: rough
        real(xp), intent(out) :: g, one_minus_q, log_slope
        real(xp), intent(in), optional :: exp_shift
        real(xp) :: e2, om2, ea, e_lambda, ead, e_delta, top, decay
        call power_exps_xp(c, lambda, delta, rough, e2, om2, ea, e_lambda, ead, e_delta, &
                           one_minus_q)
        ! (exp(-2 lambda), exp(-a lambda) normal: from double precision where `rough`)
        top = normal_reach(rough)
        ! exp(-(a+2) lambda/2) from both where their product is normal
        decay = 0.0_xp
        if (merge(max(2.0_xp, c(3)), c(3) + 2.0_xp, rough)*lambda <= top) decay = sqrt(e2*ea)
        g = sqrt(e_delta/(one_minus_q*c(2)))* &
            scaled_decay(shift, 0.5_xp*(c(3) + 2.0_xp)*lambda, decay, rough, exp_shift)
        log_slope = c(3)*e_lambda*ead/(c(2)*e_delta)
    end subroutine power_theta_terms_xp

    !> Power law: `panel_terms_xp` by `power_node_xp` where exp(-(a+2) lambda/2) and
    !! exp(shift) are at hand in range (`power_theta_terms_xp`'s condition), else by
    !! `power_theta_terms_xp`.
    pure subroutine power_panel_terms_xp(self, c, lambda, delta, shift, rough, exp_shift, &
                                         g, h)
        class(power_law), intent(in) :: self
        real(xp), intent(in) :: c(5), lambda(:), delta(:), shift, exp_shift
        logical, intent(in) :: rough
        real(xp), intent(out) :: g(:), h(:)
        real(xp) :: top, rate, one_minus_q, log_slope
        integer :: k
        ! (exp(-2 lambda) exp(-a lambda) normal where rate lambda <= top, as there)
        top = normal_reach(rough)
        rate = merge(max(2.0_xp, c(3)), c(3) + 2.0_xp, rough)
        do k = 1, size(lambda)
            if (exp_shift > 0.0_xp .and. rate*lambda(k) <= top) then
                call power_node_xp(c, lambda(k), delta(k), rough, exp_shift, g(k), h(k))
            else
                call power_theta_terms_xp(self, c, lambda(k), delta(k), shift, rough, g(k), &
                                          one_minus_q, log_slope, exp_shift)
                h(k) = 0.5_xp*log_slope/one_minus_q
            end if
        end do
    end subroutine power_panel_terms_xp

    !> `power_panel_terms_xp` at one node where exp(-2 lambda), exp(-a lambda) and their
    !! product are normal and exp(shift) = exp_shift > 0: g in the operations of
    !! `power_theta_terms_xp` there (bit for bit: the early phase's root next to the
    !! sector's edge, and so the certification of the first binary128 step, responds to
    !! g's last bits), h = a E(lambda) exp(-a delta)/(2 E(Lambda) E(delta) P), P = 1 - q,
    !! with one division where the slope and its 1/P took two.
    pure subroutine power_node_xp(c, lambda, delta, rough, exp_shift, g, h)
        real(xp), intent(in) :: c(5), lambda, delta, exp_shift
        logical, intent(in) :: rough
        real(xp), intent(out) :: g, h
        real(xp) :: e2, om2, ea, e_lambda, ead, e_delta, one_minus_q
        call power_exps_xp(c, lambda, delta, rough, e2, om2, ea, e_lambda, ead, e_delta, &
                           one_minus_q)
        g = sqrt(e_delta/(one_minus_q*c(2)))*(exp_shift*sqrt(e2*ea))
        h = c(5)*e_lambda*ead/(e_delta*one_minus_q)
    end subroutine power_node_xp

    !> exp(-2 lambda) = e2, 1 - it = om2, exp(-a lambda) = ea, E(lambda) = e_lambda,
    !! exp(-a delta) = ead, E(delta) = e_delta and 1 - q for `power_theta_terms_xp` and
    !! `power_node_xp` (the same operations for both: g's last bits matter next to the
    !! sector's edge, see `power_node_xp`).
    pure subroutine power_exps_xp(c, lambda, delta, rough, e2, om2, ea, e_lambda, ead, &
                                  e_delta, one_minus_q)
        real(xp), intent(in) :: c(5), lambda, delta
        logical, intent(in) :: rough
        real(xp), intent(out) :: e2, om2, ea, e_lambda, ead, e_delta, one_minus_q
        logical :: known  ! E(delta) at hand
        known = .false.
        ead = 0.0_xp
        e_delta = 0.0_xp
        if (c(3) == 1.0_xp) then
            ! n = 2: exp(-2 lambda) and its decay from exp(-lambda)'s
            call exp_and_decay_xp(lambda, ea, e_lambda, rough)
            e2 = ea*ea
            om2 = e_lambda*(1.0_xp + ea)
        else
            call exp_and_decay_xp(2.0_xp*lambda, e2, om2, rough)
            if (c(3) == 2.0_xp) then
                ! n = 3: exp(-a lambda) = exp(-2 lambda)
                ea = e2
                e_lambda = om2
            else if (c(3) == 0.5_xp) then
                ! n = 1.5: exp(-lambda/2) = exp(-2 lambda)^(1/4), 1 - exp(-2 lambda) =
                ! (1 - it) (1 + it) (1 + it^2)
                ea = sqrt(sqrt(e2))
                e_lambda = om2/((1.0_xp + ea)*(1.0_xp + ea*ea))
            else if (c(3)*delta <= 0.25_xp .and. delta < lambda .and. &
                     c(3)*lambda <= 0.5_xp) then
                ! nearer the start: E(lambda) = (E(Lambda) - E(delta))/(1 - E(delta)) (as
                ! `power_arch_terms`: at most two bits cancel; one exponential for both)
                call exp_and_decay_xp(c(3)*delta, ead, e_delta, rough)
                known = .true.
                e_lambda = (c(2) - e_delta)/ead
                ea = 1.0_xp - e_lambda
            else
                call exp_and_decay_xp(c(3)*lambda, ea, e_lambda, rough)
            end if
        end if
        if (.not. known) then
            if (c(3)*delta <= 0.25_xp .and. lambda <= delta) then
                ! nearer the apse: exp(-a lambda) E(delta) = E(Lambda) - E(lambda)
                e_delta = (c(2) - e_lambda)/ea
                ead = 1.0_xp - e_delta
            else if (c(3)*delta >= 0.5_xp .and. c(4) > tiny(1.0_xp) .and. &
                     c(3)*lambda <= normal_reach(rough)) then
                ! exp(-a delta) = exp(-a Lambda)/exp(-a lambda) (exp(-a lambda) normal:
                ! from double precision where `rough`)
                ead = c(4)/ea
                e_delta = 1.0_xp - ead
            else
                call exp_and_decay_xp(c(3)*delta, ead, e_delta, rough)
            end if
        end if
        one_minus_q = om2 + e2*e_lambda/c(2)
    end subroutine power_exps_xp

    !> Logarithmic law: [Lambda, 0, 0, 0, 0].
    pure function logarithmic_apse_constants_xp(self, big_lambda) result(c)
        class(logarithmic_law), intent(in) :: self
        real(xp), intent(in) :: big_lambda
        real(xp) :: c(5)
        c = [big_lambda, 0.0_xp, 0.0_xp, 0.0_xp, 0.0_xp]
    end function logarithmic_apse_constants_xp

    !> Logarithmic law: q = exp(-2 lambda) delta/Lambda, 1 - q = (1 - exp(-2 lambda)) +
    !! exp(-2 lambda) lambda/Lambda, d(log q)/d Lambda = lambda/(delta Lambda).
    pure subroutine logarithmic_theta_terms_xp(self, c, lambda, delta, shift, rough, g, &
                                               one_minus_q, log_slope, exp_shift)
        class(logarithmic_law), intent(in) :: self
        real(xp), intent(in) :: c(5), lambda, delta, shift
        logical, intent(in) :: rough
        real(xp), intent(out) :: g, one_minus_q, log_slope
        real(xp), intent(in), optional :: exp_shift
        real(xp) :: e2, om2, decay
        call exp_and_decay_xp(2.0_xp*lambda, e2, om2, rough)
        one_minus_q = om2 + e2*lambda/c(1)
        ! exp(-lambda) = sqrt(exp(-2 lambda)) where that is normal
        decay = 0.0_xp
        if (2.0_xp*lambda <= normal_reach(rough)) decay = sqrt(e2)
        g = sqrt(delta/(one_minus_q*c(1)))*scaled_decay(shift, lambda, decay, rough, exp_shift)
        log_slope = lambda/(delta*c(1))
    end subroutine logarithmic_theta_terms_xp

    pure logical function harmonic_has_terms_xp(self)
        class(harmonic_law), intent(in) :: self
        harmonic_has_terms_xp = .true.
    end function harmonic_has_terms_xp

    !> Harmonic law: [Lambda, 1 - R^2, 0, 0, 0].
    pure function harmonic_apse_constants_xp(self, big_lambda) result(c)
        class(harmonic_law), intent(in) :: self
        real(xp), intent(in) :: big_lambda
        real(xp) :: c(5), e
        c = [big_lambda, 0.0_xp, 0.0_xp, 0.0_xp, 0.0_xp]
        call exp_and_decay_xp(2.0_xp*big_lambda, e, c(2), .false.)
    end function harmonic_apse_constants_xp

    !> Harmonic law: q = exp(-2 lambda) (1 - x^2)/(1 - R^2), 1 - q = (1 - exp(-2 lambda))/
    !! (1 - R^2), d(log q)/d Lambda = 2 x^2 (1 - exp(-2 lambda))/((1 - x^2)(1 - R^2)).
    pure subroutine harmonic_theta_terms_xp(self, c, lambda, delta, shift, rough, g, &
                                            one_minus_q, log_slope, exp_shift)
        class(harmonic_law), intent(in) :: self
        real(xp), intent(in) :: c(5), lambda, delta, shift
        logical, intent(in) :: rough
        real(xp), intent(out) :: g, one_minus_q, log_slope
        real(xp), intent(in), optional :: exp_shift
        real(xp) :: e2, om2, x2, p_x, decay
        call exp_and_decay_xp(2.0_xp*lambda, e2, om2, rough)
        call exp_and_decay_xp(2.0_xp*delta, x2, p_x, rough)
        one_minus_q = om2/c(2)
        ! exp(-lambda) = sqrt(exp(-2 lambda)) where that is normal
        decay = 0.0_xp
        if (2.0_xp*lambda <= normal_reach(rough)) decay = sqrt(e2)
        g = sqrt(p_x/om2)*scaled_decay(shift, lambda, decay, rough, exp_shift)
        log_slope = 2.0_xp*x2*om2/(p_x*c(2))
    end subroutine harmonic_theta_terms_xp

    !> Harmonic law: t0 = acos(x) = 2 asin(sqrt((1 - x)/2)).
    pure subroutine harmonic_closed_fall(self, delta_lo, delta_hi, t, found)
        class(harmonic_law), intent(in) :: self
        real(qp), intent(in) :: delta_lo, delta_hi
        real(qp), intent(out) :: t
        logical, intent(out) :: found
        found = .true.
        t = 2.0_qp*(asin(sqrt(-0.5_qp*expm1(-delta_hi))) - asin(sqrt(-0.5_qp*expm1(-delta_lo))))
    end subroutine harmonic_closed_fall

end module brachistochrone_speed_laws
