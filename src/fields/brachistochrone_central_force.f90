!> The general engine: brachistochrones for any attractive speed law (Tee 1998, sec. 2).
!!
!! A brachistochrone is the orbit of a free particle with speed 1/v (Jellett). With the
!! apse at R < 1, w(x) = x^2/P(x), P = v^2 and q(x) = w(R)/w(x) in (0, 1], the first
!! half-arch integrals (27), (33), (39) from r to 1 are, in lambda = log(x/R),
!!   Theta = int sqrt(q/(1 - q)) d lambda,
!!   S     = (1 - r) + R int q e^lambda/(sqrt(1-q) (1 + sqrt(1-q))) d lambda,
!!   T     = t0(r) + R int (q/v) e^lambda/(sqrt(1-q) (1 + sqrt(1-q))) d lambda,
!! (S and T: the radial parts 1 - r and the fall time t0(r) = int_r^1 dx/v taken out
!! exactly, 1/sqrt(1-q) - 1 = q/(sqrt(1-q)(1 + sqrt(1-q))): the corrections are positive
!! and nothing cancels at small R). The law supplies q, 1 - q and q/v at the offsets
!! lambda from the apse and delta = -log x from the start, both carried exactly
!! (`speed_law%arch_terms`). Second half-arch (29): 2F(R,R) - F(r,R) = 2 int_0^lambda_r
!! + int_lambda_r^Lambda of the same integrands (Lambda = -log R), and 2 t0(R) - t0(r).
!!
!! Quadrature: fixed Gauss-Legendre rules on panels chosen once per R. The integrands
!! have square-root end singularities at the apse (lambda = 0) and at the start
!! (delta = 0), removed by lambda = b s^2, delta = c s^2 on the end panels (the start's
!! up to delta = 16 c; two such panels meeting in between when Lambda is small; one
!! panel lambda = Lambda s^2 (3 - 2 s), s in [0, 1], removing both when Lambda <= (b +
!! c)/8, R -> 1), and complex singularities at distance sigma_apse, sigma_start from the
!! ends (`log_scales`); the point x = 0 is at lambda = -infinity. Between the end panels
!! the panels grow geometrically (ratio 8, length at most 8 sigma) away from both ends,
!! so the count is O(log log(1/R)); an integral that ends at the endpoint inside the
!! first of them takes one end panel up to it instead, and one that starts at an
!! endpoint on the apse side the root variable continued from it (up to 8 sigma_apse
!! further). The node count of each panel comes from the Bernstein ellipse through the
!! nearest singularity (as on the inverse-square fast path), each singularity counted by
!! the integrands' size there for the digits asked (`bernstein_log`), and the growth of
!! the integrands off the real axis (`rule_for`, `panel_growth`). Away from the apse the
!! integrands decay like exp(-(n+1) lambda/2) or faster: each panel is asked only for
!! the digits its share of each running sum needs, each sum with the growth of its own
!! decay rate (Theta's and T's kappa = pi/sigma_apse, S's at most 2 kappa; `panel_rule`),
!! and panels below 1e-40 of every sum are skipped. Transcendentals:
!! one or two fast exp/expm1 per node (`brachistochrone_fast_exp`; one for n = 2, 3),
!! square roots by a hardware seed and a Newton step. The fall time t0 is in closed form
!! for power laws and the logarithmic law (`speed_law%closed_fall`), a
!! quadrature of x/v otherwise (`fall_piece`).
!!
!! Whole-half-arch tables (as on the fast path): the integrals over [0, Lambda] with
!! weight 1 and their slopes, tabulated once per model on R from about 0.98 down to 1.7e-5
!! (Lambda in [0.02, 11]) as piecewise Chebyshev series in z = log Lambda (equal pieces
!! in z are graded toward R = 1, where the integrals are not analytic), each piece
!! checked at build time against the quadrature between its points and used only if it
!! agrees (`build_whole_tables`; the slopes as their logarithms: a steep law's fall like
!! R^((n+1)/2) across a piece). A full evaluation then integrates only the panels
!! between the endpoint and the nearer end (`table_sums`): the second half-arch is
!! W + int_0^lambda_r or 2W - int_lambda_r^Lambda, the first int_lambda_r^Lambda or
!! W - int_0^lambda_r (if that loses at most a bit). Beyond them, Lambda up to 80 (R down
!! to 2e-35), far tables built and checked the same way (`build_far_tables`, slopes as
!! logarithms: they pass for every law), and on to Lambda = 11355 (the bottom of
!! binary128's range) deep tables (`build_deep_tables`: every piece for the logarithmic
!! law and n = 1 + 1e-6 .. 1.5; steep laws' slopes, falling like R^(n-1), leave the
!! hardware range at Lambda ~ 11355/(n-1): no piece beyond). Elsewhere: all panels.
!!
!! Two-point problem: the root R-bar of Upsilon(R) = psi, in the unknown u = sqrt(rho - R)
!! for R in [rho/2, rho] (R-bar and rho - R-bar exact next to the apse) or y = log R
!! below (tiny R-bar keeps its relative precision, down to the binary128 range).
!! Laws with hardware-precision terms (`speed_law%has_terms_xp`: power and logarithmic)
!! take an early phase in the widest hardware kind (x87 extended; `hardware_phase`):
!! safeguarded Newton steps (inverse Hermite steps through the last two evaluations
!! where there are two) on Theta and its analytic slope d Theta/d Lambda (the
!! integrand's derivative at fixed lambda, g q'/(2 q (1 - q)) with q' = d q/d Lambda
!! from the law, summed on the same nodes, plus the jump of the weights times g at the
!! endpoint), first on 12-digit rules with double-precision transcendentals, then on
!! 20-digit rules, to within the rounding of the hardware kind. Then one full-precision
!! evaluation of Theta, S and T with their slopes in hardware precision (`final_step`):
!! a Newton step of relative size about 1e-18, certified when its curvature and slope
!! errors are below 1e-35 of the unknown (where only the bound of the slopes' endpoint
!! terms in hardware precision stands in the way, those terms from binary128 and the
!! step again: `sharp_jump`; otherwise the next step from there; secant steps as the
!! last resort), s corrected along its slope and t by Hamilton-Jacobi
!! (dt/dpsi = K at fixed rho). B within 1e-16 of its apse angle (below what the early
!! phase resolves) starts from the slope next to u = 0 instead (`apse_start`). psi within
!! 1e-10 of the sector's edge (below what the early phase resolves of limit - Upsilon):
!! the early phase solves for limit - Upsilon = 1e-10 limit, then Newton steps on
!! log((limit - Upsilon)/(limit - psi)) in log R from the root of a model of its two
!! parts (`edge_steps`, `edge_model_point`).
!! Other laws: a double-precision phase (regula falsi with
!! the Anderson-Bjorck correction) and quad-precision secant steps (`quad_phase`).
module brachistochrone_central_force
    use brachistochrone_kinds, only: qp, pi, eps_qp, xp
    use brachistochrone_status, only: status_ok, status_inaccessible, &
                                      status_rho_out_of_range, status_psi_out_of_range, &
                                      status_not_finite, &
                                      status_no_convergence, argument_status, &
                                      status_parameter_out_of_range
    use brachistochrone_fast_math, only: hardware_real, fast_sqrt, quad_real, double_real
    use brachistochrone_fast_exp, only: fast_exp, fast_expm1
    use brachistochrone_fast_log, only: fast_log, fast_log1p
    use brachistochrone_quadrature, only: gauss_legendre_rule, gauss_legendre
    use brachistochrone_speed_laws, only: speed_law
    use brachistochrone_chebyshev, only: chebyshev_table, chebyshev_points, chebyshev_fit, &
                                         chebyshev_table_xp, hardware_copy
    use brachistochrone_solution, only: endpoint_solution, endpoint_status, region_inside
    use brachistochrone_arches, only: arch_first, arch_second, arch_complete, arch_radial, &
                                      arch_inaccessible
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use, intrinsic :: iso_fortran_env, only: real64
    implicit none
    private

    public :: central_force_model, new_central_force_model

    !> Fewest and most Gauss nodes on one panel (even counts only).
    integer, parameter :: min_nodes = 4, max_nodes = 80
    !> Digits aimed at by the full and the double-precision rules.
    real(qp), parameter :: fine_digits = 35.0_qp, coarse_digits = 17.0_qp
    !> Digits aimed at by the hardware-precision rules of the early phase, and by its
    !! rough evaluations (which end at a step below 1e-5: 12 digits place the next
    !! iterate within about 1e-10)
    real(qp), parameter :: hardware_digits = 20.0_qp, rough_digits = 12.0_qp
    !> Digits asked of the rough evaluation at R = rho/2 that chooses the early phase's
    !! unknown and gives its bracket's end (`open_bracket`)
    real(qp), parameter :: bracket_digits = 8.0_qp
    !> Laws whose integrands decay faster than exp(-model_decay lambda) from the apse
    !! (power laws n >= 5) take the early phase's first iterate in u from Theta's shape
    !! (`arcsin_model_root`; the steep ones, `steep_decay`, in any case)
    real(qp), parameter :: model_decay = 3.0_qp
    !> The shapes of the early phase's first-iterate models (`shape_root`)
    integer, parameter :: shape_arcsin = 1, shape_exp = 2
    !> A panel whose bound is below this share of the running sum is skipped.
    real(qp), parameter :: negligible = 1.0e-40_qp
    !> Panel kinds: lambda = b s^2 (from the apse), lambda, delta, delta = c s^2 (from
    !! the start), lambda = Lambda s^2 (3 - 2 s) (s in [0, 1]: the whole of a short arch,
    !! both roots removed; scale Lambda).
    integer, parameter :: kind_apse_root = 1, kind_apse = 2, kind_start = 3, &
                          kind_start_root = 4, kind_full = 5
    !> Most panels for one integral.
    integer, parameter :: max_panels = 160
    !> Lowest log R searched (R above the smallest normal binary128 number).
    real(qp), parameter :: lowest_log_r = -11355.0_qp
    !> The whole-half-arch tables: Lambda = -log R in [table_low, table_high] (R from
    !! about 0.98 down to 1.7e-5), in z = log Lambda on equal pieces (graded toward R = 1,
    !! where the integrals are not analytic), table_points Chebyshev points each.
    real(qp), parameter :: table_low = 0.02_qp, table_high = 11.0_qp
    integer, parameter :: table_pieces = 13, table_points = 33
    !> Laws whose integrands decay faster than exp(-steep_decay lambda) from the apse
    !! (power laws n > 2 steep_decay - 1) take the early phase in u in logarithmic forms
    real(qp), parameter :: steep_decay = 6.0_qp
    !> Growth of the panels between the root panels (`arch_panels`), and their largest
    !! length in units of sigma
    real(qp), parameter :: ladder = 8.0_qp
    !> psi within edge_gap (of the sector 2 lim Theta) of the sector's edge: limit -
    !! Upsilon is below what the early phase resolves, it solves for limit - Upsilon =
    !! edge_gap limit instead (`edge_steps`)
    real(qp), parameter :: edge_gap = 1.0e-10_qp
    !> Full-precision steps at most next to the sector's edge (`edge_steps`)
    integer, parameter :: max_edge_steps = 12
    !> The far tables beyond them: Lambda in [table_high, far_high] (R from 1.7e-5 down
    !! to about 2e-35), far_pieces equal pieces in z = log Lambda (`build_far_tables`).
    real(qp), parameter :: far_high = 80.0_qp
    integer, parameter :: far_pieces = 4, far_points = 33
    !> Whether the hardware kind is x87 extended (64-bit significand): pairs of it then
    !! hold more than binary128's 113 bits (`pair_horner`)
    logical, parameter :: pair_kind = digits(1.0_xp) >= 64
    !> The deep tables beyond those: Lambda in [far_high, deep_high] (R from 2e-35 down to
    !! the bottom of binary128's range), deep_pieces equal pieces in z = log Lambda
    !! (`build_deep_tables`).
    real(qp), parameter :: deep_high = -lowest_log_r
    integer, parameter :: deep_pieces = 8, deep_points = 33

    !> One Gauss-Legendre rule on [0, 1].
    type :: gauss_nodes
        integer :: n = 0
        real(qp), allocatable :: offset(:), weight(:)
        real(real64), allocatable :: offset64(:), weight64(:)
        real(xp), allocatable :: offset_xp(:), weight_xp(:)
    end type gauss_nodes

    !> Five tables on the same pieces (`chebyshev_table`s: `whole`, `far`) in parts for
    !! evaluation (`split_tables`, `table_value`): the powers of t from split(piece, m) on,
    !! whose sum of sizes is below 2^-60 of the value's (the slopes' logarithms, m = 4, 5:
    !! below 2^-10), in hardware precision (tail_xp(j, piece, m)); those below as pairs of
    !! the hardware kind (pair_xp(j, piece, m, 1:2), their sum exact), summed in pairs
    !! where that is within its bound (pair_ok), else in binary128.
    type :: table_parts
        real(xp), allocatable :: tail_xp(:, :, :), pair_xp(:, :, :, :)
        integer, allocatable :: split(:, :)
        logical, allocatable :: pair_ok(:, :)
    end type table_parts

    !> The general engine for one speed law: the law and the Gauss rules.
    type :: central_force_model
        class(speed_law), allocatable :: law      !! the force field
        type(gauss_nodes) :: gauss(max_nodes/2)   !! rules with 2j nodes
        real(qp) :: sigma_apse = 1.0_qp           !! singularity distance, apse side
        real(qp) :: sigma_start = 1.0_qp          !! singularity distance, start side
        !> the panel layouts' constants (`set_layout_constants`, from the sigmas): pi/sigma_apse
        !! (Theta's decay rate), the root panels' scales min(1, sigma/2), the ladder's
        !! longest panels ladder sigma, and the sigmas and the decay rate in double precision
        real(qp) :: decay_apse = pi, root_apse = 0.5_qp, root_start = 0.5_qp
        real(qp) :: ladder_apse = ladder, ladder_start = ladder
        real(real64) :: sigma64(2) = 1.0_real64, decay64 = acos(-1.0_real64)
        !> decay_apse, root_apse, root_start, ladder_apse, ladder_start in hardware precision
        !! (`arch_panels_xp`)
        real(xp) :: layout_xp(5) = [acos(-1.0_xp), 0.5_xp, 0.5_xp, real(ladder, xp), &
                                    real(ladder, xp)]
        !> the whole-half-arch integrals beyond the tables below (Lambda in [table_high,
        !! far_high]), the pieces that passed their check, Theta's and its slope's in
        !! hardware precision (`build_far_tables`)
        type(chebyshev_table) :: far(5)
        logical :: far_ok(far_pieces) = .false.
        type(chebyshev_table_xp) :: far_xp(2)
        !> the same beyond the far tables (Lambda in [far_high, deep_high],
        !! `build_deep_tables`)
        type(chebyshev_table) :: deep(5)
        logical :: deep_ok(deep_pieces) = .false.
        type(chebyshev_table_xp) :: deep_xp(2)
        !> the whole-half-arch integrals (weights 1) in z = log Lambda: Theta, S and T
        !! corrections/R, and their slopes at fixed lambda (as `arch_sums`)
        type(chebyshev_table) :: whole(5)
        !> pieces of the tables that passed their check at build time
        logical :: whole_ok(table_pieces) = .false.
        !> Theta's table and its slope's in hardware precision (powers of t per piece)
        real(xp), allocatable :: whole_xp(:, :, :)
        !> the five whole tables and the five far tables in parts of the hardware kind
        !! (`split_tables`, `table_value`)
        type(table_parts) :: whole_parts, far_parts, deep_parts
    contains
        procedure :: half_arch => general_half_arch    !! theta, s, t at r (eqs. 27-41)
        procedure :: apse_angle => general_apse_angle  !! Theta(R,R)
        procedure :: fall_time => general_fall_time    !! radial fall time from 1 to r
        procedure :: angle_slopes => general_angle_slopes  !! d theta/d Lambda, error bounds
        procedure :: solve => general_solve            !! the two-point problem
    end type central_force_model

    !> A panel in its own variable, with its weight and Bernstein parameter. (No default
    !! initialization: the arrays of max_panels panels in the engine's routines would be
    !! initialized on every call.)
    type :: panel
        integer :: kind
        real(qp) :: lo, hi, scale, weight
        real(real64) :: log_rho
    end type panel

    !> One apse R as the integrals need it: R, 1 - R, Lambda = -log R (all exact), the
    !! law's constants; the endpoint at lambda_r from the apse, delta_r from the start,
    !! and the weights of the integrands below and above it.
    type :: arch_setup
        real(qp) :: big_r = 0.0_qp, one_minus_big_r = 1.0_qp, big_lambda = 0.0_qp
        real(qp) :: c(8) = 0.0_qp
        real(qp) :: lambda_r = 0.0_qp, delta_r = 0.0_qp
        real(qp) :: weight_below = 0.0_qp, weight_above = 1.0_qp
        real(xp) :: cx(5) = 0.0_xp    !! the law's constants in hardware precision
        !> Theta of a first half-arch where known beforehand (psi: the two-point problem's
        !! target), else 0: picks the panels of the early phase (`theta_xp`)
        real(qp) :: angle_hint = 0.0_qp
    end type arch_setup

    !> The endpoint of a two-point problem and the unknown used.
    type :: endpoint_problem
        real(qp) :: rho = 1.0_qp, psi = 0.0_qp, one_minus_rho = 0.0_qp, delta_rho = 0.0_qp
        real(qp) :: fall_rho = 0.0_qp !! t0(rho), once per endpoint
        logical :: second = .false., use_u = .true.
        logical :: use_r = .false.    !! unknown R itself (the quad phase below rho/2)
        real(qp) :: limit = 0.0_qp    !! 2 lim Theta(R,R), R -> 0
        integer :: form = 0           !! 0: Upsilon - psi; 1: log(Upsilon/psi);
                                      !! 2: log((limit - Upsilon)/(limit - psi))
        !> the residual's slope at the lower end of the early phase's bracket in y = log R
        !! (`open_bracket`; 0: unknown)
        real(real64) :: slope_lo = 0.0_real64
    end type endpoint_problem

contains

    !> A general-engine model for `law` (copied in); builds the Gauss rules and the
    !! whole-half-arch tables once (`build_whole_tables`; not with tables = .false.).
    function new_central_force_model(law, tables) result(model)
        class(speed_law), intent(in) :: law !! the speed law
        logical, intent(in), optional :: tables !! build the tables (default .true.)
        type(central_force_model) :: model
        type(gauss_legendre_rule) :: rule
        real(qp) :: sigma(2)
        integer :: j
        allocate (model%law, source=law)
        call model%law%prepare()
        do j = min_nodes/2, max_nodes/2
            rule = gauss_legendre(2*j)
            model%gauss(j)%n = 2*j
            model%gauss(j)%offset = 0.5_qp*(1.0_qp + rule%node)
            model%gauss(j)%weight = 0.5_qp*rule%weight
            model%gauss(j)%offset64 = real(model%gauss(j)%offset, real64)
            model%gauss(j)%weight64 = real(model%gauss(j)%weight, real64)
            model%gauss(j)%offset_xp = real(model%gauss(j)%offset, xp)
            model%gauss(j)%weight_xp = real(model%gauss(j)%weight, xp)
        end do
        sigma = law%log_scales()
        model%sigma_apse = sigma(1)
        model%sigma_start = sigma(2)
        call set_layout_constants(model)
        if (present(tables)) then
            if (.not. tables) return
        end if
        call build_whole_tables(model)
        call build_far_tables(model)
        call build_deep_tables(model)
    end function new_central_force_model

    !> The constants of the panel layouts from the sigmas (the same expressions as where
    !! they are used: the same values).
    pure subroutine set_layout_constants(model)
        type(central_force_model), intent(inout) :: model
        model%decay_apse = pi/model%sigma_apse
        model%root_apse = min(1.0_qp, 0.5_qp*model%sigma_apse)
        model%root_start = min(1.0_qp, 0.5_qp*model%sigma_start)
        model%ladder_apse = ladder*model%sigma_apse
        model%ladder_start = ladder*model%sigma_start
        model%sigma64 = real([model%sigma_apse, model%sigma_start], real64)
        model%decay64 = real(model%decay_apse, real64)
        model%layout_xp = real([model%decay_apse, model%root_apse, model%root_start, &
                                model%ladder_apse, model%ladder_start], xp)
    end subroutine set_layout_constants

    !> The apse data of the whole half-arch (weights 1) at Lambda = -log R.
    pure function whole_setup(model, big_lambda) result(a)
        type(central_force_model), intent(in) :: model
        real(qp), intent(in) :: big_lambda
        type(arch_setup) :: a
        a%big_lambda = big_lambda
        a%big_r = exp(-big_lambda)
        a%one_minus_big_r = -expm1_qp(-big_lambda)
        call finish_setup(model, a, 0.0_qp, big_lambda, .false., .true.)
    end function whole_setup

    !> The whole-half-arch integrals and their slopes (`arch_sums`, weights 1) at
    !! Lambda, as five numbers; every panel on the full rules (`every_panel`: the
    !! slopes' integrands grow toward the start for steep laws, where Theta's are below
    !! `negligible`).
    pure function whole_direct(model, big_lambda) result(values)
        type(central_force_model), intent(in) :: model
        real(qp), intent(in) :: big_lambda
        real(qp) :: values(5)
        real(xp) :: slopes(2)
        call arch_sums(model, whole_setup(model, big_lambda), fine_digits, .true., &
                       values(1:3), slopes, every_panel=.true.)
        values(4:5) = real(slopes, qp)
    end function whole_direct

    !> `whole_direct` at Lambda = exp(z) for every point z of a table: values(k, piece, :)
    !! at points(k, piece), shared among the OpenMP threads (each point is independent
    !! and `whole_direct` is pure, so the values do not depend on the number of threads).
    !! With `least_slope`: 0 beyond a point whose slopes are below it (at least every
    !! point below the first such point evaluated, whatever the threads' order).
    function direct_values(model, points, least_slope) result(values)
        type(central_force_model), intent(in) :: model
        real(qp), intent(in) :: points(:, :)
        real(qp), intent(in), optional :: least_slope
        real(qp) :: values(size(points, 1), size(points, 2), 5), cut
        integer :: item, k, piece
        logical :: beyond
        cut = huge(1.0_qp)
        !$omp parallel do schedule(dynamic, 1) default(shared) private(item, k, piece, beyond)
        do item = 1, size(points)
            k = mod(item - 1, size(points, 1)) + 1
            piece = (item - 1)/size(points, 1) + 1
            !$omp critical (direct_values_cut)
            beyond = points(k, piece) > cut
            !$omp end critical (direct_values_cut)
            values(k, piece, :) = 0.0_qp
            if (beyond) cycle
            values(k, piece, :) = whole_direct(model, exp(points(k, piece)))
            if (.not. present(least_slope)) cycle
            if (all(values(k, piece, 4:5) >= least_slope)) cycle
            !$omp critical (direct_values_cut)
            cut = min(cut, points(k, piece))
            !$omp end critical (direct_values_cut)
        end do
        !$omp end parallel do
    end function direct_values

    !> Tabulate the whole-half-arch integrals in z = log Lambda (piecewise Chebyshev, as
    !! the fast path's tables in R), and check each piece at two points between its
    !! Chebyshev points against the quadrature: a piece is used only if the values agree
    !! to 8 roundings (Theta of itself; the S and T corrections of 1 - R and t0(R), which
    !! s and t exceed where the tables are used) and the slopes to 4 roundings of the
    !! hardware kind (their own precision). About 430 full evaluations: 60-100 ms.
    subroutine build_whole_tables(model)
        type(central_force_model), intent(inout) :: model
        real(qp) :: points(table_points, table_pieces)
        real(qp) :: values(table_points, table_pieces, 5), width, lower, upper
        integer :: piece, m
        logical :: positive
        lower = log(table_low)
        upper = log(table_high)
        points = chebyshev_points(lower, upper, table_pieces, table_points)
        values = direct_values(model, points)
        ! the slopes (positive) as their logarithms: for steep laws they fall like
        ! R^((n+1)/2) across a piece, which a polynomial in the slope itself resolves only
        ! relative to the piece's largest value
        positive = all(values(:, :, 4:5) > 0.0_qp)
        do m = 4, 5
            values(:, :, m) = log(merge(values(:, :, m), 1.0_qp, positive))
        end do
        ! the values carry rounding noise of about eps (the slopes: of the hardware kind,
        ! absolute in their logarithms)
        model%whole = fit_tables(lower, upper, values)
        model%whole_xp = reshape(real([model%whole(1)%power, model%whole(4)%power], xp), &
                                 [table_points, table_pieces, 2])
        model%whole_parts = split_tables(model%whole, values)
        width = (upper - lower)/real(table_pieces, qp)
        do piece = 1, table_pieces
            model%whole_ok(piece) = piece_agrees(model, lower, width, piece, .false.) &
                                    .and. positive
        end do
    end subroutine build_whole_tables

    !> Theta's whole-half-arch table and its slope's at Lambda in hardware precision (as
    !! `whole_lookup`).
    pure subroutine whole_lookup_xp(model, big_lambda, values, found)
        type(central_force_model), intent(in) :: model
        real(xp), intent(in) :: big_lambda
        real(xp), intent(out) :: values(2)
        logical, intent(out) :: found
        real(xp) :: position, t
        integer :: piece, j
        values = 0.0_xp
        found = .false.
        if (big_lambda > real(table_high, xp)) then
            call far_lookup_xp(model, big_lambda, values, found)
            return
        end if
        if (.not. (big_lambda >= real(table_low, xp) .and. &
                   big_lambda <= real(table_high, xp))) return
        position = (log(big_lambda) - log(real(table_low, xp)))/ &
                   (log(real(table_high, xp)) - log(real(table_low, xp)))* &
                   real(table_pieces, xp)
        piece = min(table_pieces, max(1, int(position) + 1))
        if (.not. model%whole_ok(piece)) return
        t = 2.0_xp*(position - real(piece - 1, xp)) - 1.0_xp
        ! (the two Horner sums side by side: two independent chains of dependent steps)
        values = model%whole_xp(table_points, piece, :)
        do j = table_points - 1, 1, -1
            values = values*t + model%whole_xp(j, piece, :)
        end do
        ! the slope's table holds its logarithm
        values(2) = exp(values(2))
        found = .true.
    end subroutine whole_lookup_xp

    !> The tabulated whole-half-arch integrals at Lambda (`whole_direct`'s five numbers,
    !! only the first `wanted` of them evaluated, the rest 0); `found` only inside the
    !! tables' range on a checked piece.
    pure subroutine whole_lookup(model, big_lambda, values, found, wanted)
        type(central_force_model), intent(in) :: model
        real(qp), intent(in) :: big_lambda
        real(qp), intent(out) :: values(5)
        logical, intent(out) :: found
        integer, intent(in) :: wanted  !! how many of the five (1 .. 5)
        real(qp) :: z
        integer :: piece
        values = 0.0_qp
        found = .false.
        if (big_lambda > table_high) then
            call far_lookup(model, big_lambda, values, found, wanted)
            return
        end if
        if (.not. (big_lambda >= table_low .and. big_lambda <= table_high)) return
        z = fast_log(big_lambda)
        piece = min(table_pieces, max(1, int((z - log(table_low))/(log(table_high) - &
                    log(table_low))*real(table_pieces, qp)) + 1))
        if (.not. model%whole_ok(piece)) return
        ! (the five tables share their pieces: t once)
        call tables_at(model%whole, model%whole_parts, z, wanted, values)
        found = .true.
    end subroutine whole_lookup

    !> For the Theta, S and T tables (m <= 3), on each piece the first power of t from
    !! which on the sum of the coefficients' sizes is below 2^-60 of the value's least
    !! size (half the least of the tabulated values): Horner's rule in hardware precision
    !! there (error below ~70 eps(xp) 2^-60 < eps/4 of the value, t's rounding included).
    !! For the slopes' logarithms (m = 4, 5; wanted to about eps(xp)/10 absolute) from
    !! where that sum is below 2^-10 (error below ~70 eps(xp) 2^-10).
    !! The powers below the split as pairs of the hardware kind (hi rounded, lo = a - hi:
    !! exact, a has 113 bits), summed by `pair_horner` where its bound, 12 (split + 1)
    !! 2^-128 times the sum of all the coefficients' sizes, is below 2^-117 of the least
    !! size (and the hardware kind is x87 extended; elsewhere Horner in binary128).
    pure function split_tables(tables, values) result(parts)
        type(chebyshev_table), intent(in) :: tables(5)  !! on the same pieces
        real(qp), intent(in) :: values(:, :, :)  !! the tabulated values (point, piece, m)
        type(table_parts) :: parts
        real(qp) :: least, tail
        integer :: piece, m, j, used, points, pieces
        points = tables(1)%terms
        pieces = tables(1)%pieces
        allocate (parts%tail_xp(0:points - 1, pieces, 5), parts%pair_xp(0:points - 1, &
                  pieces, 5, 2), parts%split(pieces, 5), parts%pair_ok(pieces, 5))
        parts%tail_xp = 0.0_xp
        parts%pair_xp = 0.0_xp
        do m = 1, 5
            do piece = 1, pieces
                ! (no associate: a section's name would start at 1)
                used = tables(m)%used(piece)
                least = 0.5_qp*minval(abs(values(:, piece, m)))
                if (m > 3) least = 2.0_qp**50
                parts%split(piece, m) = used
                tail = 0.0_qp
                do j = used - 1, 1, -1
                    tail = tail + abs(tables(m)%power(j, piece))
                    if (.not. (tail <= 2.0_qp**(-60)*least)) exit
                    parts%split(piece, m) = j
                end do
                associate (a => tables(m)%power(0:used - 1, piece), &
                           split => parts%split(piece, m))
                parts%tail_xp(0:used - 1, piece, m) = hardware_real(a)
                parts%pair_xp(0:used - 1, piece, m, 1) = hardware_real(a)
                parts%pair_xp(0:used - 1, piece, m, 2) = &
                    hardware_real(a - quad_real(parts%pair_xp(0:used - 1, piece, m, 1)))
                parts%pair_ok(piece, m) = pair_kind .and. 12.0_qp*real(split + 1, qp)* &
                    2.0_qp**(-128)*sum(abs(a)) <= 2.0_qp**(-117)*least
                end associate
            end do
        end do
    end function split_tables

    !> The piece of the whole-half-arch tables holding z = log Lambda (the five tables
    !! share their pieces) and t in [-1, 1] there, also as a pair of the hardware kind
    !! (t_pair(1) + t_pair(2) = t exactly: t has 113 bits).
    pure subroutine whole_point(table, z, piece, t, t_pair)
        type(chebyshev_table), intent(in) :: table  !! `whole(1)` (`far(1)`)
        real(qp), intent(in) :: z
        integer, intent(out) :: piece
        real(qp), intent(out) :: t
        real(xp), intent(out) :: t_pair(2)
        real(qp) :: width, position
        width = (table%upper - table%lower)/real(table%pieces, qp)
        position = (z - table%lower)/width
        piece = min(table%pieces, max(1, int(position) + 1))
        t = 2.0_qp*(position - real(piece - 1, qp)) - 1.0_qp
        t_pair(1) = hardware_real(t)
        t_pair(2) = hardware_real(t - quad_real(t_pair(1)))
    end subroutine whole_point

    !> Table m at t on `piece` (`whole_point`): the powers of t from the split on in
    !! hardware precision, the rest in pairs of it (`pair_horner`, where `pair_ok`) or in
    !! quad precision; the slopes (m = 4, 5) from their logarithms (`table_parts`).
    !! (`table`: the m-th of the set `parts` is made from: whole-half-arch, far or deep).
    pure subroutine table_value(table, parts, m, piece, t, t_pair, value)
        type(chebyshev_table), intent(in) :: table
        type(table_parts), intent(in) :: parts
        integer, intent(in) :: m, piece
        real(qp), intent(in) :: t
        real(xp), intent(in) :: t_pair(2)
        real(qp), intent(out) :: value
        real(xp) :: high, low
        integer :: j, split
        split = parts%split(piece, m)
        high = 0.0_xp
        do j = table%used(piece) - 1, split, -1
            high = high*t_pair(1) + parts%tail_xp(j, piece, m)
        end do
        if (parts%pair_ok(piece, m)) then
            call pair_horner(parts%pair_xp(:, piece, m, 1), parts%pair_xp(:, piece, m, 2), &
                             split, t_pair, high, low)
            if (m > 3) then
                ! the slopes' tables hold their logarithms: exp in hardware precision, the
                ! pair's low part taken as a factor
                value = quad_real(exp(high)*(1.0_xp + low))
            else
                value = quad_real(high) + quad_real(low)
            end if
            return
        end if
        value = quad_real(high)
        do j = split - 1, 0, -1
            value = value*t + table%power(j, piece)
        end do
        if (m > 3) then
            ! (as above, from the binary128 logarithm)
            high = hardware_real(value)
            low = hardware_real(value - quad_real(high))
            value = quad_real(exp(high)*(1.0_xp + low))
        end if
    end subroutine table_value

    !> Horner's rule on the powers j < n of t in pairs of the hardware kind (x87 extended,
    !! u = 2^-64): v <- v t + a with v = high + low, t = t_pair(1) + t_pair(2), a = ah(j) +
    !! al(j) (t and a exact), from v = high (the tail's sum), high and low renormalized.
    !! Each step: high t_pair(1) exactly (Dekker's product, Veltkamp's split at 32 bits),
    !! the cross products to u of their u^2 size (low t_pair(2) dropped: u^2 |v t|), the
    !! sum with ah(j) exactly (Knuth's two-sum), the low parts within about 2u of their
    !! sizes (u |p| + u |ah|): at most 12 u^2 (|v t| + |a|) per step, |t| <= 1 scaling it
    !! down in the later steps: in all at most 12 (n + 1) u^2 times the sum of the
    !! coefficients' sizes (|v| <= that sum). (x87 arithmetic in its own precision, no
    !! reassociation: the exact transformations hold.)
    pure subroutine pair_horner(ah, al, n, t_pair, high, low)
        real(xp), intent(in) :: ah(0:), al(0:), t_pair(2)
        integer, intent(in) :: n
        real(xp), intent(inout) :: high
        real(xp), intent(out) :: low
        real(xp), parameter :: splitter = 2.0_xp**32 + 1.0_xp
        real(xp) :: c, t1, t2, v1, v2, p, e, s, b, l
        integer :: j
        c = splitter*t_pair(1)
        t1 = c - (c - t_pair(1))
        t2 = t_pair(1) - t1
        low = 0.0_xp
        do j = n - 1, 0, -1
            c = splitter*high
            v1 = c - (c - high)
            v2 = high - v1
            p = high*t_pair(1)
            e = (((v1*t1 - p) + v1*t2) + v2*t1) + v2*t2
            e = e + (high*t_pair(2) + low*t_pair(1))
            s = p + ah(j)
            b = s - p
            l = ((p - (s - b)) + (ah(j) - b) + e) + al(j)
            ! (two-sum again: s may be small after cancellation)
            high = s + l
            b = high - s
            low = (s - (high - b)) + (l - b)
        end do
    end subroutine pair_horner

    !> The five whole-half-arch tables (Theta, the S and T corrections, the slopes'
    !! logarithms) fitted on the pieces of [lower, upper] through `values` at their
    !! Chebyshev points: the values to half a rounding of binary128, the logarithms to a
    !! tenth of a rounding of the hardware kind (of their largest size, at least 1).
    function fit_tables(lower, upper, values) result(tables)
        real(qp), intent(in) :: lower, upper, values(:, :, :)
        type(chebyshev_table) :: tables(5)
        real(qp), parameter :: slope_noise = real(epsilon(1.0_xp), qp)
        integer :: m
        do m = 1, 5
            tables(m) = chebyshev_fit(lower, upper, values(:, :, m), &
                                      merge(0.5_qp*eps_qp, 0.1_qp*slope_noise/ &
                                      max(1.0_qp, maxval(abs(values(:, :, m)))), m <= 3))
        end do
    end function fit_tables

    !> Tabulate the whole-half-arch integrals beyond the tables (Lambda from table_high
    !! to far_high: R-bar far below 1e-3, the logarithmic law next to its sector's edge,
    !! small rho), on far_pieces pieces in z = log Lambda (far_points Chebyshev points
    !! each; the slopes as their logarithms, as `build_whole_tables`), each checked at
    !! two points against the quadrature to the tolerances of `build_whole_tables`
    !! (every Theta, S, T to 8 roundings of Theta and of what the S and T corrections are
    !! added to, the slopes to 4 roundings of the hardware kind); unchecked pieces are
    !! not used. All four pieces pass for n = 1.5 .. 10 and the logarithmic law, three
    !! for n = 32. About 140 full evaluations: 40-240 ms (n = 32 the most: every panel
    !! between the apse and the start holds a share of the slopes, which decay like
    !! R^((n+1)/2) across the half-arch).
    subroutine build_far_tables(model)
        type(central_force_model), intent(inout) :: model
        real(qp) :: points(far_points, far_pieces), values(far_points, far_pieces, 5)
        real(qp) :: width, lower, upper
        integer :: piece
        lower = log(table_high)
        upper = log(far_high)
        points = chebyshev_points(lower, upper, far_pieces, far_points)
        values = direct_values(model, points)
        ! the slopes as their logarithms (as `build_whole_tables`)
        if (.not. all(values(:, :, 4:5) > 0.0_qp)) return
        values(:, :, 4:5) = log(values(:, :, 4:5))
        model%far = fit_tables(lower, upper, values)
        model%far_xp = [hardware_copy(model%far(1)), hardware_copy(model%far(4))]
        model%far_parts = split_tables(model%far, values)
        width = (upper - lower)/real(far_pieces, qp)
        do piece = 1, far_pieces
            model%far_ok(piece) = piece_agrees(model, lower, width, piece, .true.)
        end do
    end subroutine build_far_tables

    !> Whether piece `piece` of the whole-half-arch tables (`far`: of the far tables), in
    !! z = log Lambda from `lower` in pieces of `width`, agrees with the quadrature at two
    !! points between its Chebyshev points (`table_agrees`).
    pure function piece_agrees(model, lower, width, piece, far) result(agrees)
        type(central_force_model), intent(in) :: model
        real(qp), intent(in) :: lower, width
        integer, intent(in) :: piece
        logical, intent(in) :: far
        logical :: agrees
        real(qp) :: z, direct(5), table(5)
        integer :: side
        agrees = .true.
        do side = 1, 2
            z = lower + width*(real(piece - 1, qp) + merge(0.3_qp, 0.71_qp, side == 1))
            direct = whole_direct(model, exp(z))
            if (far .and. z > log(far_high)) then
                call tables_at(model%deep, model%deep_parts, z, 5, table)
            else if (far) then
                call tables_at(model%far, model%far_parts, z, 5, table)
            else
                call tables_at(model%whole, model%whole_parts, z, 5, table)
            end if
            agrees = table_agrees(model, z, direct, table) .and. agrees
        end do
    end function piece_agrees

    !> A table's five values at z = log Lambda against the quadrature's (`whole_direct`):
    !! the values within 8 roundings of their sizes (Theta itself; for the S and T
    !! corrections, times R, what they are added to where the tables are used: s >= 1 - R,
    !! t >= t0(R), `table_sums`) and the slopes within 4 roundings of the hardware kind.
    pure function table_agrees(model, z, direct, table) result(agrees)
        type(central_force_model), intent(in) :: model
        real(qp), intent(in) :: z, direct(5), table(5)
        logical :: agrees
        real(qp), parameter :: slope_noise = real(epsilon(1.0_xp), qp)
        real(qp) :: sizes(5), big_r
        big_r = exp(-exp(z))
        sizes = [direct(1), max(direct(2), -expm1_qp(-exp(z))/big_r), &
                 max(direct(3), fall_piece(model, 0.0_qp, exp(z))/big_r), &
                 abs(direct(4)), abs(direct(5)) + direct(2)]
        agrees = all(abs(table(1:3) - direct(1:3)) <= 8.0_qp*eps_qp*sizes(1:3)) .and. &
                 all(abs(table(4:5) - direct(4:5)) <= 4.0_qp*slope_noise*sizes(4:5))
    end function table_agrees

    !> The piece of the far tables holding z = log Lambda, if it passed its check.
    pure function far_piece(model, z) result(piece)
        type(central_force_model), intent(in) :: model
        real(qp), intent(in) :: z
        integer :: piece
        piece = 0
        if (.not. (z >= log(table_high) .and. z <= log(far_high))) return
        piece = min(far_pieces, max(1, int((z - log(table_high))/(log(far_high) - &
                    log(table_high))*real(far_pieces, qp)) + 1))
        if (.not. model%far_ok(piece)) piece = 0
    end function far_piece

    !> `whole_lookup` beyond the tables (the far tables).
    pure subroutine far_lookup(model, big_lambda, values, found, wanted)
        type(central_force_model), intent(in) :: model
        real(qp), intent(in) :: big_lambda
        real(qp), intent(out) :: values(5)
        logical, intent(out) :: found
        integer, intent(in) :: wanted
        real(qp) :: z
        if (big_lambda > far_high) then
            call deep_lookup(model, big_lambda, values, found, wanted)
            return
        end if
        values = 0.0_qp
        z = fast_log(big_lambda)
        found = far_piece(model, z) > 0
        if (.not. found) return
        call tables_at(model%far, model%far_parts, z, wanted, values)
    end subroutine far_lookup

    !> The first `wanted` of five tables on the same pieces (whole-half-arch, far or deep)
    !! at z = log Lambda (`whole_point`, `table_value`).
    pure subroutine tables_at(tables, parts, z, wanted, values)
        type(chebyshev_table), intent(in) :: tables(5)
        type(table_parts), intent(in) :: parts   !! `split_tables(tables, ...)`
        real(qp), intent(in) :: z
        integer, intent(in) :: wanted
        real(qp), intent(inout) :: values(5)
        real(qp) :: t
        real(xp) :: t_pair(2)
        integer :: m, piece
        call whole_point(tables(1), z, piece, t, t_pair)
        do m = 1, wanted
            call table_value(tables(m), parts, m, piece, t, t_pair, values(m))
        end do
    end subroutine tables_at


    !> `whole_lookup_xp` beyond the tables (the far tables' hardware copies).
    pure subroutine far_lookup_xp(model, big_lambda, values, found)
        type(central_force_model), intent(in) :: model
        real(xp), intent(in) :: big_lambda
        real(xp), intent(out) :: values(2)
        logical, intent(out) :: found
        integer :: m
        if (big_lambda > real(far_high, xp)) then
            call deep_lookup_xp(model, big_lambda, values, found)
            return
        end if
        values = 0.0_xp
        found = far_piece(model, real(log(big_lambda), qp)) > 0
        if (.not. found) return
        do m = 1, 2
            call model%far_xp(m)%evaluate(log(big_lambda), values(m))
        end do
        values(2) = exp(values(2))   ! the slope's table holds its logarithm
    end subroutine far_lookup_xp

    !> Tabulate the whole-half-arch integrals beyond the far tables (Lambda from far_high
    !! to deep_high: R-bar from 2e-35 down to the bottom of binary128's range; the
    !! logarithmic law and power laws near n = 1 next to their sectors' edges, tiny rho)
    !! as `build_far_tables`, on deep_pieces pieces, each checked the same way. A piece
    !! where a slope falls below the hardware kind's normal range (steep laws: the slopes
    !! fall like R^(n-1)) is not used, nor any beyond it. Pieces used: all eight for the
    !! logarithmic law and n = 1 + 1e-6, 1.1, 1.5; seven for n = 2; n = 3: 1, 2, 4, 5,
    !! 6; n = 6: 1, 3, 4, 5; n = 32: 1, 2 (the others fail their check on the slope of
    !! Theta). About 280 full evaluations: 0.1-0.2 s (with 25 points a piece, n = 1.1's
    !! first three fail: there Theta's approach to its limit is resolved).
    subroutine build_deep_tables(model)
        type(central_force_model), intent(inout) :: model
        real(qp) :: points(deep_points, deep_pieces), values(deep_points, deep_pieces, 5)
        real(qp) :: width, lower, upper
        real(qp), parameter :: least_slope = 2.0_qp**10*real(tiny(1.0_xp), qp)
        logical :: normal(deep_pieces)
        integer :: piece
        lower = log(far_high)
        upper = log(deep_high)
        points = chebyshev_points(lower, upper, deep_pieces, deep_points)
        ! (not beyond the first point whose slopes leave the hardware range: only the
        ! pieces before it are used)
        values = direct_values(model, points, least_slope)
        do piece = 1, deep_pieces
            normal(piece) = all(values(:, piece, 4:5) >= least_slope)
            if (piece > 1) normal(piece) = normal(piece) .and. normal(piece - 1)
            ! the slopes as their logarithms (as `build_whole_tables`); 1 in the pieces
            ! not used
            if (.not. normal(piece)) values(:, piece, 4:5) = 1.0_qp
        end do
        values(:, :, 4:5) = log(values(:, :, 4:5))
        model%deep = fit_tables(lower, upper, values)
        model%deep_parts = split_tables(model%deep, values)
        model%deep_xp = [hardware_copy(model%deep(1)), hardware_copy(model%deep(4))]
        width = (upper - lower)/real(deep_pieces, qp)
        do piece = 1, deep_pieces
            model%deep_ok(piece) = normal(piece)
            if (normal(piece)) model%deep_ok(piece) = piece_agrees(model, lower, width, &
                                                                   piece, .true.)
        end do
    end subroutine build_deep_tables

    !> Whether z = log Lambda is on a checked piece of the deep tables.
    pure function deep_found(model, z) result(found)
        type(central_force_model), intent(in) :: model
        real(qp), intent(in) :: z
        logical :: found
        found = z >= log(far_high) .and. z <= log(deep_high)
        if (found) found = model%deep_ok(min(deep_pieces, max(1, int((z - log(far_high))/ &
                                   (log(deep_high) - log(far_high))*real(deep_pieces, qp)) + 1)))
    end function deep_found

    !> `whole_lookup` beyond the far tables (the deep tables).
    pure subroutine deep_lookup(model, big_lambda, values, found, wanted)
        type(central_force_model), intent(in) :: model
        real(qp), intent(in) :: big_lambda
        real(qp), intent(out) :: values(5)
        logical, intent(out) :: found
        integer, intent(in) :: wanted
        real(qp) :: z
        values = 0.0_qp
        z = fast_log(big_lambda)
        found = deep_found(model, z)
        if (.not. found) return
        call tables_at(model%deep, model%deep_parts, z, wanted, values)
    end subroutine deep_lookup

    !> `whole_lookup_xp` beyond the far tables (the deep tables' hardware copies).
    pure subroutine deep_lookup_xp(model, big_lambda, values, found)
        type(central_force_model), intent(in) :: model
        real(xp), intent(in) :: big_lambda
        real(xp), intent(out) :: values(2)
        logical, intent(out) :: found
        integer :: m
        values = 0.0_xp
        found = deep_found(model, real(log(big_lambda), qp))
        if (.not. found) return
        do m = 1, 2
            call model%deep_xp(m)%evaluate(log(big_lambda), values(m))
        end do
        values(2) = exp(values(2))   ! the slope's table holds its logarithm
    end subroutine deep_lookup_xp

    !> The apse data for R (with 1 - R exact) and the endpoint r = R + d.
    pure function setup_arch(model, big_r, one_minus_big_r, d, delta_r, second, whole) &
        result(a)
        type(central_force_model), intent(in) :: model
        real(qp), intent(in) :: big_r, one_minus_big_r, d, delta_r
        logical, intent(in) :: second, whole
        type(arch_setup) :: a
        a%big_r = big_r
        a%one_minus_big_r = one_minus_big_r
        if (big_r > 0.5_qp) then
            a%big_lambda = -fast_log1p(-one_minus_big_r)
        else
            a%big_lambda = -fast_log(big_r)
        end if
        call finish_setup(model, a, d, delta_r, second, whole)
    end function setup_arch

    !> The same from Lambda = -log R (R may be below the double range).
    pure function setup_arch_log(model, big_lambda, rho, delta_r, second) result(a)
        type(central_force_model), intent(in) :: model
        real(qp), intent(in) :: big_lambda, rho, delta_r
        logical, intent(in) :: second
        type(arch_setup) :: a
        a%big_lambda = big_lambda
        a%big_r = exp(-big_lambda)
        a%one_minus_big_r = -expm1_qp(-big_lambda)
        call finish_setup(model, a, rho - a%big_r, delta_r, second, .false.)
    end function setup_arch_log

    pure subroutine finish_setup(model, a, d, delta_r, second, whole, lambda_r)
        type(central_force_model), intent(in) :: model
        type(arch_setup), intent(inout) :: a
        real(qp), intent(in) :: d, delta_r
        logical, intent(in) :: second, whole
        real(qp), intent(in), optional :: lambda_r  !! log(1 + d/R) where known
        a%c = model%law%apse_constants(a%big_r, a%one_minus_big_r, a%big_lambda)
        a%cx = model%law%apse_constants_xp(real(a%big_lambda, xp))
        if (present(lambda_r)) then
            a%lambda_r = lambda_r
        else if (a%big_r > 0.0_qp .and. d < a%big_r) then
            a%lambda_r = fast_log1p(d/a%big_r)
        else
            a%lambda_r = a%big_lambda - delta_r
        end if
        a%delta_r = delta_r
        if (whole) then
            a%weight_below = 1.0_qp
        else
            a%weight_below = merge(2.0_qp, 0.0_qp, second)
        end if
        a%weight_above = 1.0_qp
    end subroutine finish_setup

    !> expm1 in quad precision (libquadmath's, through log1p's module).
    elemental function expm1_qp(y) result(e)
        use brachistochrone_quad_math, only: expm1
        real(qp), intent(in) :: y
        real(qp) :: e
        e = expm1(y)
    end function expm1_qp

    !> The panels of the arch integrals over lambda in [0, Lambda], split at the endpoint,
    !! ordered away from the apse (the direction in which the integrands decay).
    pure subroutine arch_panels(model, a, panels, count)
        type(central_force_model), intent(in) :: model
        type(arch_setup), intent(in) :: a
        type(panel), intent(out) :: panels(max_panels)
        integer, intent(out) :: count
        real(qp) :: b, c, meet, lo, hi, origin, decay_rate, top
        type(panel) :: start_side(max_panels)
        integer :: n_start
        count = 0
        call root_scales(model, a, b, c)
        if (a%big_lambda <= 0.125_qp*(b + c)) then
            ! a short arch: one panel lambda = Lambda s^2 (3 - 2 s), delta = Lambda (1 -
            ! s)^2 (1 + 2 s), both end singularities removed (about half the nodes of two
            ! root panels meeting in between: the other preimages of the ends, s = 3/2
            ! and -1/2, are the nearest singularities; those of the complex ones stay
            ! far while Lambda <= (b + c)/8; the root scales are the plain ones there)
            call add_split(panels, count, kind_full, 0.0_qp, 1.0_qp, a%big_lambda, &
                           split_full(a%lambda_r, a%delta_r, a%big_lambda), a)
            return
        end if
        if (a%big_lambda <= b + c) then
            ! two root panels meeting in between: lambda = b' s^2 and delta = c' s^2
            b = a%big_lambda*b/(b + c)
            c = a%big_lambda - b
            call add_split(panels, count, kind_apse_root, 0.0_qp, 1.0_qp, b, &
                           split_root(a%lambda_r/b), a)
            call add_split(panels, count, kind_start_root, 0.0_qp, 1.0_qp, c, &
                           split_root(a%delta_r/c), a)
        else
            meet = max(b, min(a%big_lambda - c, a%big_lambda*b/(b + c)))
            if (continued_root(a, b, c)) then
                ! an integral from an endpoint on the apse side: the root variable
                ! continued from it to meet, or ladder sigma_apse further (the apse's
                ! singularities stay away in s: fewer nodes than the root panel's piece
                ! and the ladder's first panels)
                lo = min(meet, a%lambda_r + model%ladder_apse)
                call push(panels, count, panel(kind_apse_root, split_root(a%lambda_r/b), &
                          split_root(lo/b), b, a%weight_above, 1.0_real64))
            else
                ! apse side: lambda = b s^2 on [0, b], then [b, 8b], [8b, 64b], ... to meet
                call add_split(panels, count, kind_apse_root, 0.0_qp, 1.0_qp, b, &
                               split_root(a%lambda_r/b), a)
                lo = b
            end if
            ! where the integrated region starts (the apse unless its weight is 0)
            origin = merge(0.0_qp, a%lambda_r, a%weight_below > 0.0_qp)
            decay_rate = model%decay_apse
            do while (lo < meet)
                ! past exp(-300) of the integrands at the origin: nothing more to add
                if (decay_rate*(lo - origin) > 300.0_qp) exit
                ! growth `ladder`, length at most ladder sigma: the integrands decay like
                ! exp(-pi lambda/sigma_apse), which grows as fast off the real axis
                hi = min(ladder*lo, lo + model%ladder_apse, meet)
                if (hi > 0.75_qp*meet .and. meet - lo <= model%ladder_apse) hi = meet
                call add_split(panels, count, kind_apse, lo, hi, 1.0_qp, a%lambda_r, a)
                lo = hi
            end do
            ! start side, in delta, from meet down to the start
            n_start = 0
            if (decay_rate*(meet - origin) > 300.0_qp) return
            ! delta = c s^2 on [0, top], top up to 2 ladder c (s = 4: the start's
            ! singularities stay away in s; fewer nodes than the root panel and the
            ! ladder's first panels; to meet if that is at most 2.5 ladder c away), then
            ! the ladder
            top = a%big_lambda - meet
            if (top > 2.5_qp*ladder*c) top = 2.0_qp*ladder*c
            call add_split(start_side, n_start, kind_start_root, 0.0_qp, split_root(top/c), &
                           c, split_root(a%delta_r/c), a)
            lo = top
            do while (lo < a%big_lambda - meet)
                hi = min(ladder*lo, lo + model%ladder_start, a%big_lambda - meet)
                if (hi > 0.75_qp*(a%big_lambda - meet) .and. &
                    a%big_lambda - meet - lo <= model%ladder_start) &
                    hi = a%big_lambda - meet
                call add_split(start_side, n_start, kind_start, lo, hi, 1.0_qp, a%delta_r, a)
                lo = hi
            end do
            call append_reversed(panels, count, start_side, n_start)
        end if
    end subroutine arch_panels

    !> The scales of the root panels, lambda = b s^2 and delta = c s^2: half the
    !! singularities' distances (at most 1), except for an integral that ends at the
    !! endpoint (weight 0 beyond it) inside the first ladder panel, which gets one root
    !! panel up to it (fewer nodes than the root panel and the piece of the ladder panel).
    pure subroutine root_scales(model, a, b, c)
        type(central_force_model), intent(in) :: model
        type(arch_setup), intent(in) :: a
        real(qp), intent(out) :: b, c
        b = model%root_apse
        c = model%root_start
        if (a%weight_above == 0.0_qp .and. a%lambda_r > b .and. a%lambda_r <= 4.0_qp*b &
            .and. a%lambda_r + c < a%big_lambda) then
            b = a%lambda_r
        else if (a%weight_below == 0.0_qp .and. a%delta_r > c .and. &
                 a%delta_r <= 4.0_qp*c .and. a%delta_r + b < a%big_lambda) then
            c = a%delta_r
        end if
    end subroutine root_scales

    !> Whether `arch_panels` takes the root variable continued from the endpoint (an
    !! integral from it, weights 0 and 1, the endpoint on the apse side: lambda_r in
    !! [b/4, meet)), b and c the root scales.
    pure logical function continued_root(a, b, c)
        type(arch_setup), intent(in) :: a
        real(qp), intent(in) :: b, c
        continued_root = a%weight_below == 0.0_qp .and. a%lambda_r >= 0.25_qp*b .and. &
            a%lambda_r < max(b, min(a%big_lambda - c, a%big_lambda*b/(b + c))) .and. &
            a%big_lambda > b + c
    end function continued_root

    !> `arch_panels` in hardware precision, for the early phase (`theta_xp`): the same
    !! rules on Lambda, lambda_r and delta_r rounded to the hardware kind, the panels'
    !! ends and splits hardware numbers. Not for binary128 sums (the two sides' ends and
    !! the splits at the endpoint are exact only to the hardware kind's rounding); the
    !! early phase's nodes and sums are in that kind, and its root is checked by the
    !! certified binary128 step (`final_step`).
    pure subroutine arch_panels_xp(model, a, panels, count)
        type(central_force_model), intent(in) :: model
        type(arch_setup), intent(in) :: a
        type(panel), intent(out) :: panels(max_panels)
        integer, intent(out) :: count
        real(xp), parameter :: steps = real(ladder, xp)
        real(xp) :: x(3), b, c, meet, lo, hi, origin, top, rest, longest
        type(panel) :: start_side(max_panels)
        integer :: n_start
        count = 0
        x = hardware_real([a%big_lambda, a%lambda_r, a%delta_r])
        call root_scales_xp(model, a, x, b, c)
        if (x(1) <= 0.125_xp*(b + c)) then
            ! a short arch (rare: R next to 1): `arch_panels`' one panel
            call arch_panels(model, a, panels, count)
            return
        end if
        if (x(1) <= b + c) then
            b = x(1)*b/(b + c)
            c = x(1) - b
            call add_split_xp(panels, count, kind_apse_root, 0.0_xp, 1.0_xp, b, &
                              sqrt(x(2)/b), a)
            call add_split_xp(panels, count, kind_start_root, 0.0_xp, 1.0_xp, c, &
                              sqrt(x(3)/c), a)
            return
        end if
        meet = max(b, min(x(1) - c, x(1)*b/(b + c)))
        longest = model%layout_xp(4)
        if (continued_root_xp(a, x, b, c)) then
            lo = min(meet, x(2) + longest)
            call push(panels, count, panel(kind_apse_root, quad_real(sqrt(x(2)/b)), &
                      quad_real(sqrt(lo/b)), quad_real(b), a%weight_above, 1.0_real64))
        else
            call add_split_xp(panels, count, kind_apse_root, 0.0_xp, 1.0_xp, b, &
                              sqrt(x(2)/b), a)
            lo = b
        end if
        origin = merge(0.0_xp, x(2), a%weight_below > 0.0_qp)
        do while (lo < meet)
            if (model%layout_xp(1)*(lo - origin) > 300.0_xp) exit
            hi = min(steps*lo, lo + longest, meet)
            if (hi > 0.75_xp*meet .and. meet - lo <= longest) hi = meet
            call add_split_xp(panels, count, kind_apse, lo, hi, 1.0_xp, x(2), a)
            lo = hi
        end do
        if (model%layout_xp(1)*(meet - origin) > 300.0_xp) return
        rest = x(1) - meet
        top = rest
        if (top > 2.5_xp*steps*c) top = 2.0_xp*steps*c
        n_start = 0
        call add_split_xp(start_side, n_start, kind_start_root, 0.0_xp, sqrt(top/c), c, &
                          sqrt(x(3)/c), a)
        lo = top
        longest = model%layout_xp(5)
        do while (lo < rest)
            hi = min(steps*lo, lo + longest, rest)
            if (hi > 0.75_xp*rest .and. rest - lo <= longest) hi = rest
            call add_split_xp(start_side, n_start, kind_start, lo, hi, 1.0_xp, x(3), a)
            lo = hi
        end do
        call append_reversed(panels, count, start_side, n_start)
    end subroutine arch_panels_xp

    !> The start side's panels (`side(1:n)`, laid out from the start) appended in the
    !! order away from the apse, as far as `panels` holds them.
    pure subroutine append_reversed(panels, count, side, n)
        type(panel), intent(inout) :: panels(max_panels)
        integer, intent(inout) :: count
        type(panel), intent(in) :: side(max_panels)
        integer, intent(in) :: n
        integer :: k
        do k = n, 1, -1
            if (count >= max_panels) exit
            count = count + 1
            panels(count) = side(k)
        end do
    end subroutine append_reversed

    !> `root_scales` in hardware precision, x = [Lambda, lambda_r, delta_r].
    pure subroutine root_scales_xp(model, a, x, b, c)
        type(central_force_model), intent(in) :: model
        type(arch_setup), intent(in) :: a
        real(xp), intent(in) :: x(3)
        real(xp), intent(out) :: b, c
        b = model%layout_xp(2)
        c = model%layout_xp(3)
        if (a%weight_above == 0.0_qp .and. x(2) > b .and. x(2) <= 4.0_xp*b .and. &
            x(2) + c < x(1)) then
            b = x(2)
        else if (a%weight_below == 0.0_qp .and. x(3) > c .and. x(3) <= 4.0_xp*c .and. &
                 x(3) + b < x(1)) then
            c = x(3)
        end if
    end subroutine root_scales_xp

    !> `continued_root` in hardware precision, x = [Lambda, lambda_r, delta_r].
    pure logical function continued_root_xp(a, x, b, c)
        type(arch_setup), intent(in) :: a
        real(xp), intent(in) :: x(3), b, c
        continued_root_xp = .false.
        if (a%weight_below /= 0.0_qp .or. x(1) <= b + c) return
        continued_root_xp = x(2) >= 0.25_xp*b .and. x(2) < max(b, min(x(1) - c, x(1)*b/(b + c)))
    end function continued_root_xp

    !> `add_split` from hardware-precision ends and split (converted exactly: the same
    !! comparisons and panels).
    pure subroutine add_split_xp(panels, count, kind, lo, hi, scale, split, a)
        type(panel), intent(inout) :: panels(:)
        integer, intent(inout) :: count
        integer, intent(in) :: kind
        real(xp), intent(in) :: lo, hi, scale, split
        type(arch_setup), intent(in) :: a
        call add_split(panels, count, kind, quad_real(lo), quad_real(hi), quad_real(scale), &
                       quad_real(split), a)
    end subroutine add_split_xp

    !> sqrt(z) for the root panels' splits, within an ulp: the hardware kind's square root
    !! and one correction (z - s^2)/(2 s) in it (libquadmath's sqrtq costs about ten
    !! binary128 multiplications); sqrt itself where that kind has no 64-bit significand.
    elemental function split_root(z) result(s)
        real(qp), intent(in) :: z
        real(qp) :: s
        real(xp) :: s0
        if (precision(1.0_xp) < 18 .or. .not. (z > 1.0e-4000_qp .and. z < 1.0e4000_qp)) then
            ! (z = 0, the split at an end: no library call)
            s = z
            if (z /= 0.0_qp) s = sqrt(z)
            return
        end if
        s0 = sqrt(real(z, xp))
        s = real(s0, qp)
        s = s + real(real(z - s*s, xp)/(2.0_xp*s0), qp)
    end function split_root

    !> The split s of a `kind_full` panel at lambda_r (delta_r = Lambda - lambda_r): w^2
    !! (3 - 2 w) = t for the nearer end's offset t = min(lambda_r, delta_r)/Lambda <= 1/2
    !! (s = w or 1 - w), by Newton steps in the hardware kind from w = sqrt(t/3) (below
    !! the root; the cubic is convex there), then two corrections in binary128.
    elemental function split_full(lambda_r, delta_r, big_lambda) result(s)
        real(qp), intent(in) :: lambda_r, delta_r, big_lambda
        real(qp) :: s, t, w
        real(xp) :: tx, wx
        integer :: k
        t = min(lambda_r, delta_r)/big_lambda
        if (.not. (t > 0.0_qp)) then
            w = 0.0_qp
        else
            tx = real(t, xp)
            if (.not. (tx > 0.0_xp)) then
                ! below the hardware kind's range: the cubic term is negligible
                s = merge(sqrt(t/3.0_qp), 1.0_qp - sqrt(t/3.0_qp), lambda_r <= delta_r)
                return
            end if
            wx = sqrt(tx/3.0_xp)
            do k = 1, 8
                wx = wx - (wx*wx*(3.0_xp - 2.0_xp*wx) - tx)/(6.0_xp*wx*(1.0_xp - wx))
            end do
            w = real(wx, qp)
            do k = 1, 2
                w = w - real(real(w*w*(3.0_qp - 2.0_qp*w) - t, xp)/ &
                             (6.0_xp*wx*(1.0_xp - wx)), qp)
            end do
        end if
        s = merge(w, 1.0_qp - w, lambda_r <= delta_r)
    end function split_full

    !> Add the panel [lo, hi] of `kind`, split at `split` (in the panel's variable) into
    !! the parts below and above the endpoint, with their weights; zero weights dropped.
    !! The parts in the order of the variable (`arch_panels` reverses the start side's
    !! list as a whole: the order away from the apse, which `panel_share` counts on).
    pure subroutine add_split(panels, count, kind, lo, hi, scale, split, a)
        type(panel), intent(inout) :: panels(:)
        integer, intent(inout) :: count
        integer, intent(in) :: kind
        real(qp), intent(in) :: lo, hi, scale, split
        type(arch_setup), intent(in) :: a
        real(qp) :: w_lo, w_hi
        logical :: reversed
        ! lambda grows with the variable on apse-side panels, falls on start-side ones
        reversed = kind == kind_start .or. kind == kind_start_root
        w_lo = merge(a%weight_above, a%weight_below, reversed)
        w_hi = merge(a%weight_below, a%weight_above, reversed)
        if (split <= lo) then
            call push(panels, count, panel(kind, lo, hi, scale, w_hi, 1.0_real64))
        else if (split >= hi) then
            call push(panels, count, panel(kind, lo, hi, scale, w_lo, 1.0_real64))
        else
            call push(panels, count, panel(kind, lo, split, scale, w_lo, 1.0_real64))
            call push(panels, count, panel(kind, split, hi, scale, w_hi, 1.0_real64))
        end if
    end subroutine add_split

    !> Append a panel unless its weight is zero or it is empty.
    pure subroutine push(panels, count, p)
        type(panel), intent(inout) :: panels(:)
        integer, intent(inout) :: count
        type(panel), intent(in) :: p
        if (p%weight == 0.0_qp .or. p%hi <= p%lo .or. count >= size(panels)) return
        count = count + 1
        panels(count) = p
    end subroutine push

    !> log of the Bernstein parameter of a panel: the ellipse through the nearest
    !! singularity of the integrands, in the panel's variable (double precision), each
    !! singularity counted by its size: the integrands decay like exp(-kappa lambda)
    !! away from the apse (kappa = pi/sigma_apse, Theta's rate; S's is faster), so one
    !! at the real part lambda* adds about |f(lambda*)| rho*^(-2n) to the error, a share
    !! exp(-kappa (lambda* - lambda_0)) of that of the panel's largest value at lambda_0.
    !! A singularity of weight w (<= 0) on the ellipse rho* is taken as one of weight 1 on
    !! log rho* (1 + w/(D log 10)) for D digits (`digits`, default 35; rule_for's n for D
    !! digits on that ellipse, D log 10/(2 log rho*) (1 + w/(D log 10)), is then exactly
    !! the n for which the singularity's term e^w rho*^(-2n) is below 10^-D), beyond reach
    !! below exp(-D log 10) (skipped before any image or transcendental). With
    !! `unweighted` (integrands not decaying from the apse: `fall_piece`) every
    !! singularity counts. In real arithmetic: the ellipse through an image z has the
    !! panel's ends as foci, rho* = a + sqrt(a^2 - 1) with a = (|z - lo| + |z - hi|)/(hi -
    !! lo) (`ellipse_excess`: a - 1 without cancellation); one of each pair of conjugate
    !! singularities (the same ellipse); one logarithm for all those of weight 0 (the
    !! least a), one for each weighted one unless a bound without logarithm puts it beyond
    !! the least so far (`acosh_below`).
    pure function bernstein_log(model, big_lambda, p, unweighted, digits) result(log_rho)
        type(central_force_model), intent(in) :: model
        real(qp), intent(in) :: big_lambda
        type(panel), intent(in) :: p
        logical, intent(in), optional :: unweighted
        !> the digits asked of the panel (`rule_for`'s); default 35
        real(qp), intent(in), optional :: digits
        real(real64) :: log_rho
        real(real64), parameter :: most = 8.0_real64, none = huge(1.0_real64)
        real(real64) :: re(5), im(5), w(5), excess(5), lo, hi, scale, kappa, near, reach, &
                        side, least, log_min
        logical :: apse_side
        integer :: k
        reach = 35.0_real64*log(10.0_real64)
        if (present(digits)) reach = double_real(max(digits, 2.0_qp))*log(10.0_real64)
        lo = double_real(p%lo)
        hi = double_real(p%hi)
        scale = double_real(p%scale)
        kappa = model%decay64
        if (present(unweighted)) then
            if (unweighted) kappa = 0.0_real64
        end if
        ! singular points as offsets from the panel's own end (apse or start): the end,
        ! its complex singularities, the other end, its complex singularities (one of
        ! each conjugate pair), and 2i (not a singularity but the growth of the factors
        ! exp(-+lambda), exp(-delta) off the real axis, which fewer nodes would not
        ! resolve)
        apse_side = p%kind <= kind_apse .or. p%kind == kind_full
        side = merge(1.0_real64, -1.0_real64, apse_side)
        re = [0.0_real64, 0.0_real64, double_real(big_lambda), double_real(big_lambda), &
              0.0_real64]
        im = [0.0_real64, merge(model%sigma64(1), model%sigma64(2), apse_side), 0.0_real64, &
              merge(model%sigma64(2), model%sigma64(1), apse_side), 2.0_real64]
        ! the panel's point nearest the apse (its largest integrands), from its own end
        select case (p%kind)
        case (kind_apse_root)
            near = scale*lo*lo
        case (kind_apse)
            near = lo
        case (kind_start)
            near = -hi
        case (kind_full)
            near = scale*lo*lo*(3.0_real64 - 2.0_real64*lo)
        case default
            near = -scale*hi*hi
        end select
        do k = 1, 5
            ! weight: log of the integrands' size at the singularity relative to the panel's
            ! largest (the offsets on the start side count toward the start)
            w(k) = 0.0_real64
            if (k <= 4) w(k) = min(0.0_real64, -kappa*(side*re(k) - near))
            excess(k) = none
            if (w(k) <= -reach) cycle
            select case (p%kind)
            case (kind_apse, kind_start)
                excess(k) = ellipse_excess(re(k), im(k), lo, hi)
            case (kind_full)
                excess(k) = full_excess(k, re(k), im(k), scale, lo, hi)
            case default
                ! (the end itself removed by the substitution)
                if (k > 1) excess(k) = root_excess(re(k), im(k), scale, lo, hi)
            end select
        end do
        least = minval(excess, mask=w == 0.0_real64)
        log_min = most
        if (least < none) log_min = min(most, acosh_1p(least))
        do k = 1, 4
            if (.not. (w(k) < 0.0_real64 .and. excess(k) < none)) cycle
            if (acosh_below(excess(k))*reach/(reach + w(k)) >= log_min) cycle
            log_min = min(log_min, acosh_1p(excess(k))*reach/(reach + w(k)))
        end do
        log_rho = max(log_min, 1.0e-3_real64)
    end function bernstein_log

    !> a - 1 for the ellipse with foci lo < hi through z = zr + i zi, a = (|z - lo| + |z -
    !! hi|)/(hi - lo): |z - c| - |zr - c| = zi^2/(|z - c| + |zr - c|) and |zr - lo| + |zr -
    !! hi| - (hi - lo) = 2 max(0, lo - zr, zr - hi), every term >= 0 (no cancellation).
    pure function ellipse_excess(zr, zi, lo, hi) result(e)
        real(real64), intent(in) :: zr, zi, lo, hi
        real(real64) :: e, dl, dh
        dl = abs(zr - lo)
        dh = abs(zr - hi)
        e = 2.0_real64*max(0.0_real64, lo - zr, zr - hi)
        if (zi /= 0.0_real64) e = e + zi*zi/(sqrt(dl*dl + zi*zi) + dl) + &
                                  zi*zi/(sqrt(dh*dh + zi*zi) + dh)
        e = e/(hi - lo)
    end function ellipse_excess

    !> `ellipse_excess` of the nearer preimage of z = zr + i zi (zi >= 0, z /= 0) on a
    !! root panel, s = +-sqrt(z/scale): the principal root by real formulas (its real
    !! part >= 0, so it is the nearer of the two to a panel with lo >= 0: |s - c| <= |-s -
    !! c| for every c >= 0; both where lo < 0).
    pure function root_excess(zr, zi, scale, lo, hi) result(e)
        real(real64), intent(in) :: zr, zi, scale, lo, hi
        real(real64) :: e, xr, xi, m, sr, si
        xr = zr/scale
        xi = zi/scale
        if (xi == 0.0_real64) then
            sr = sqrt(max(xr, 0.0_real64))
            si = sqrt(max(-xr, 0.0_real64))
        else
            m = sqrt(xr*xr + xi*xi)
            if (xr >= 0.0_real64) then
                sr = sqrt(0.5_real64*(m + xr))
                si = 0.5_real64*xi/sr
            else
                si = sqrt(0.5_real64*(m - xr))
                sr = 0.5_real64*xi/si
            end if
        end if
        e = ellipse_excess(sr, si, lo, hi)
        if (lo < 0.0_real64) e = min(e, ellipse_excess(-sr, si, lo, hi))
    end function root_excess

    !> `ellipse_excess` of the nearest preimage of z = zr + i zi on a `kind_full` panel:
    !! s^2 (3 - 2 s) = t = z/scale at s = 1/2 - sin((asin(1 - 2 t) + 2 pi m)/3), m = 0, 1,
    !! 2; the ends' double ones (s = 0 of the apse, k = 1; s = 1 of the start, k = 3)
    !! removed by the substitution, none near the panel for |t| > 1e6.
    pure function full_excess(k, zr, zi, scale, lo, hi) result(e)
        integer, intent(in) :: k
        real(real64), intent(in) :: zr, zi, scale, lo, hi
        real(real64) :: e
        complex(real64) :: t, arc, point
        integer :: m
        e = huge(1.0_real64)
        t = cmplx(zr, zi, real64)/scale
        if (abs(t) > 1.0e6_real64) return
        arc = asin(1.0_real64 - 2.0_real64*t)
        do m = 0, 2
            point = 0.5_real64 - sin((arc + real(2*m, real64)*acos(-1.0_real64))/3.0_real64)
            if ((k == 1 .and. abs(point) < 1.0e-6_real64) .or. &
                (k == 3 .and. abs(1.0_real64 - point) < 1.0e-6_real64)) cycle
            e = min(e, ellipse_excess(real(point), aimag(point), lo, hi))
        end do
    end function full_excess

    !> acosh(1 + e), e >= 0: log(1 + y), y = e + sqrt(e (e + 2)), with Kahan's correction
    !! of log(1 + y).
    elemental function acosh_1p(e) result(l)
        real(real64), intent(in) :: e
        real(real64) :: l, y, v
        y = e + sqrt(e*(e + 2.0_real64))
        v = 1.0_real64 + y
        if (v == 1.0_real64) then
            l = y
        else
            l = log(v)*(y/(v - 1.0_real64))
        end if
    end function acosh_1p

    !> A bound below `acosh_1p(e)` without logarithm (with a margin for its rounding):
    !! log(1 + y) >= 2 y/(2 + y), and >= log y >= (exponent(y) - 1) log 2.
    elemental function acosh_below(e) result(l)
        real(real64), intent(in) :: e
        real(real64) :: l, y
        y = e + sqrt(e*(e + 2.0_real64))
        l = (1.0_real64 - 1.0e-12_real64)*max(2.0_real64*y/(2.0_real64 + y), &
            real(exponent(y) - 1, real64)*log(2.0_real64))
    end function acosh_below

    !> The rule (element of model%gauss) for `digits` digits on a panel. An n-point
    !! rule errs by about M rho^(-2n) on the Bernstein ellipse rho (up to the nearest
    !! singularity, log_rho); the integrands decay like exp(-kappa tau) along the panel,
    !! so M grows like exp(kappa h ((rho + 1/rho)/2 - 1)) on an ellipse about a plain
    !! panel of half-length h (growth = kappa h): the smallest n over a few rho <= the
    !! singular one is taken (a smaller ellipse only where its bound without the growth,
    !! which rises as rho falls, is below the least so far: the same n without its cosh).
    pure function rule_for(log_rho, digits, growth) result(j)
        real(real64), intent(in) :: log_rho
        real(qp), intent(in) :: digits
        real(real64), intent(in) :: growth
        integer :: j, n, k
        real(real64) :: need, best, lr, target
        real(real64), parameter :: fractions(8) = [1.0_real64, 0.7_real64, 0.5_real64, &
            0.35_real64, 0.25_real64, 0.18_real64, 0.12_real64, 0.08_real64]
        target = real(max(digits, 2.0_qp), real64)*log(10.0_real64)
        lr = log_rho
        best = target/(2.0_real64*lr)
        ! without growth the full ellipse is best
        if (growth /= 0.0_real64) then
            best = huge(1.0_real64)
            do k = 1, size(fractions)
                lr = log_rho*fractions(k)
                if (target/(2.0_real64*lr) >= best) exit
                need = (target + growth*(cosh(lr) - 1.0_real64))/(2.0_real64*lr)
                best = min(best, need)
            end do
        end if
        if (best > real(max_nodes, real64)) then
            j = max_nodes/2
        else
            n = ceiling(best) + 2
            j = min(max_nodes/2, max(min_nodes/2, (n + 1)/2))
        end if
    end function rule_for

    !> kappa h of a plain panel, kappa the decay rate; its equivalent for a root panel
    !! continued past s = 1 (`log_rho` set; 0 for the other root panels).
    pure function panel_growth(p, kappa) result(growth)
        type(panel), intent(in) :: p
        real(qp), intent(in) :: kappa
        real(real64) :: growth
        real(real64) :: h, mid, most
        if (p%kind == kind_apse .or. p%kind == kind_start) then
            growth = double_real(kappa*0.5_qp*(p%hi - p%lo))
        else if (p%hi > 1.0_qp) then
            ! a root panel continued past s = 1: on the ellipse s = mid + h cos(z), Im z
            ! = l <= log_rho (cosh l <= most), the integrands' exponent kappa Re(lambda)
            ! (kappa Re(delta)) strays from its value at the panel's end nearest the apse
            ! by at most (cosh l - 1) times the growth below (the apse side: scale h (2
            ! mid + h max(0, most - mid/h)), the second term where the ellipse passes
            ! s = 0; the start side: scale h (2 mid + h (1 + most)))
            h = double_real(0.5_qp*(p%hi - p%lo))
            mid = double_real(0.5_qp*(p%hi + p%lo))
            most = cosh(p%log_rho)
            if (p%kind == kind_apse_root) then
                growth = double_real(kappa*p%scale)*h*(2.0_real64*mid + &
                         h*max(0.0_real64, most - mid/h))
            else
                growth = double_real(kappa*p%scale)*h*(2.0_real64*mid + h*(1.0_real64 + most))
            end if
        else
            growth = 0.0_real64
        end if
    end function panel_growth

    !> lambda, delta and d lambda/dv at the panel variable v.
    elemental subroutine node_point(kind, scale, big_lambda, v, lambda, delta, jacobian)
        integer, intent(in) :: kind
        real(qp), intent(in) :: scale, big_lambda, v
        real(qp), intent(out) :: lambda, delta, jacobian
        select case (kind)
        case (kind_apse_root)
            lambda = scale*v*v
            delta = big_lambda - lambda
            jacobian = 2.0_qp*scale*v
        case (kind_apse)
            lambda = v
            delta = big_lambda - v
            jacobian = 1.0_qp
        case (kind_start)
            delta = v
            lambda = big_lambda - v
            jacobian = 1.0_qp
        case (kind_full)
            lambda = scale*(v*v*(3.0_qp - 2.0_qp*v))
            delta = scale*((1.0_qp - v)**2*(1.0_qp + 2.0_qp*v))
            jacobian = 6.0_qp*scale*(v*(1.0_qp - v))
        case default
            delta = scale*v*v
            lambda = big_lambda - delta
            jacobian = 2.0_qp*scale*v
        end select
    end subroutine node_point

    !> The arch integrals: [Theta, S correction/R, T correction/R] with the weights of
    !! `a`, to `digits` digits (only Theta unless want_length_time).
    pure function arch_integrals(model, a, digits, want_length_time) result(sums)
        type(central_force_model), intent(in) :: model
        type(arch_setup), intent(in) :: a
        real(qp), intent(in) :: digits
        logical, intent(in) :: want_length_time
        real(qp) :: sums(3)
        call arch_sums(model, a, digits, want_length_time, sums)
    end function arch_integrals

    !> `arch_integrals`, and with `slopes` the Lambda-derivatives at fixed lambda of the
    !! Theta and S integrands, d g/d Lambda = g q'/(2 q (1 - q)) and d h/d Lambda =
    !! e^lambda q'/(2 (1 - q)^(3/2)) (q' = d q/d Lambda, from the law's hardware terms),
    !! summed in hardware precision on the same nodes (want_length_time needed).
    pure subroutine arch_sums(model, a, digits, want_length_time, sums, slopes, given, &
                              given_count, every_panel, offset)
        type(central_force_model), intent(in) :: model
        type(arch_setup), intent(in) :: a
        real(qp), intent(in) :: digits
        logical, intent(in) :: want_length_time
        real(qp), intent(out) :: sums(3)
        real(xp), intent(out), optional :: slopes(2)
        !> `arch_panels(model, a, given, given_count)` where the caller has them
        type(panel), intent(in), optional :: given(max_panels)
        integer, intent(in), optional :: given_count
        !> no panel skipped and each on the full rules (the tables' build)
        logical, intent(in), optional :: every_panel
        !> sizes the sums are added to (`table_sums`: the whole half-arch's): the panels
        !! after the first are asked for their shares of the sums plus these
        real(qp), intent(in), optional :: offset(3)
        type(panel) :: panels(max_panels)
        real(qp) :: part(3), last(3), jacobian, q, omq, qv, rx
        real(qp) :: root_omq, common, g(3), root_q, weighted, width, terms(max_nodes, 6), rest
        real(xp) :: part_xp(2), carry(2), carry_all(2), log_slope, g_xp, slopes_k(max_nodes)
        integer :: count, p, k, j
        real(qp) :: shares(3), base(3)
        logical :: all_panels
        base = 0.0_qp
        if (present(offset)) base = abs(offset)
        all_panels = .false.
        if (present(every_panel)) all_panels = every_panel
        if (present(given) .and. present(given_count)) then
            count = given_count
            panels(1:count) = given(1:count)
        else
            call arch_panels(model, a, panels, count)
        end if
        sums = 0.0_qp
        last = 0.0_qp
        if (present(slopes)) slopes = 0.0_xp
        carry_all = 0.0_xp
        do p = 1, count
            associate (pan => panels(p))
            shares = 1.0_qp
            if (p > 1 .and. .not. all_panels) then
                shares = panel_share(pan, last, sums + base, merge(3, 1, want_length_time))
                ! skipped, not ended: a sliver next to a split is followed by a full panel
                if (maxval(shares) < negligible) cycle
            end if
            j = panel_rule(model, a%big_lambda, pan, digits, shares, want_length_time)
            part = 0.0_qp
            part_xp = 0.0_xp
            carry = 0.0_xp
            width = pan%hi - pan%lo
            call panel_nodes(model, a, pan, j, present(slopes), terms, slopes_k)
            do k = 1, model%gauss(j)%n
                ! the Gauss weight folded into the Jacobian (1 on the linear panels)
                if (pan%kind == kind_apse .or. pan%kind == kind_start) then
                    jacobian = model%gauss(j)%weight(k)
                else
                    jacobian = terms(k, 1)*model%gauss(j)%weight(k)
                end if
                q = terms(k, 2)
                omq = terms(k, 3)
                qv = terms(k, 4)
                rx = terms(k, 5)
                root_q = terms(k, 6)
                if (present(slopes)) log_slope = slopes_k(k)
                ! sqrt(1 - q) by a hardware root and one correction, then one division
                ! (g: weighted integrands; jacobian/sqrt(1 - q) = common times the rest
                ! of its denominator)
                root_omq = fast_sqrt(omq)
                if (want_length_time) then
                    rest = rx*(1.0_qp + root_omq)
                    common = jacobian/(root_omq*rest)
                    weighted = common*rest
                    g(2) = q*common
                    g(3) = qv*common
                else
                    weighted = jacobian/root_omq
                    g(2:3) = 0.0_qp
                end if
                g(1) = root_q*weighted
                part = part + g
                if (present(slopes)) then
                    ! g q'/(2 q (1 - q)) and e^lambda q'/(2 (1 - q)^(3/2)) = the same
                    ! times sqrt(q)/rx (weighted)
                    g_xp = hardware_real(g(1))*(0.5_xp*log_slope/hardware_real(omq))
                    ! compensated sums: the error bound of `arch_values` counts on it
                    call add_compensated(part_xp, carry, &
                                         [g_xp, g_xp*(hardware_real(root_q)/hardware_real(rx))])
                end if
                ! the node nearest the next panel
                if (k == merge(1, model%gauss(j)%n, pan%kind >= kind_start .and. &
                               pan%kind <= kind_start_root)) last = abs(g/jacobian)
            end do
            sums = sums + pan%weight*(pan%hi - pan%lo)*part
            if (present(slopes)) call add_compensated(slopes, carry_all, &
                real(pan%weight*(pan%hi - pan%lo), xp)*(part_xp + carry))
            end associate
        end do
    end subroutine arch_sums

    !> The Jacobian and the law's terms (q, 1 - q, q/v, r/x, sqrt q; `terms(k, 1:6)`) at
    !! the nodes of panel `pan` on rule j, and with `want_slopes` d(log q)/d Lambda.
    !! Linear panels' nodes as mid +- t (symmetric: the law may share exponentials).
    pure subroutine panel_nodes(model, a, pan, j, want_slopes, terms, slopes_k)
        type(central_force_model), intent(in) :: model
        type(arch_setup), intent(in) :: a
        type(panel), intent(in) :: pan
        integer, intent(in) :: j
        logical, intent(in) :: want_slopes
        real(qp), intent(out) :: terms(max_nodes, 6)
        real(xp), intent(out) :: slopes_k(max_nodes)
        real(qp) :: mid, t(max_nodes), v(max_nodes), lambda(max_nodes), delta(max_nodes)
        real(qp) :: width
        integer :: n, k, side
        n = model%gauss(j)%n
        width = pan%hi - pan%lo
        side = 0
        if (pan%kind == kind_apse) side = 1
        if (pan%kind == kind_start) side = 2
        mid = pan%lo + 0.5_qp*width
        if (side == 0) then
            ! (the offsets from mid are not used on the root panels; on [0, 1] the nodes
            ! are the rule's offsets)
            if (pan%lo == 0.0_qp .and. width == 1.0_qp) then
                v(1:n) = model%gauss(j)%offset
            else
                v(1:n) = pan%lo + width*model%gauss(j)%offset
            end if
            t(1:n) = 0.0_qp
        else
            do k = 1, n/2
                t(k) = width*(model%gauss(j)%offset(k) - 0.5_qp)
                t(n + 1 - k) = -t(k)
            end do
            v(1:n) = mid + t(1:n)
        end if
        call node_point(pan%kind, pan%scale, a%big_lambda, v(1:n), lambda(1:n), &
                        delta(1:n), terms(1:n, 1))
        slopes_k = 0.0_xp
        if (want_slopes) then
            call model%law%panel_terms(a%c, side, mid, t(1:n), lambda(1:n), delta(1:n), &
                terms(1:n, 2), terms(1:n, 3), terms(1:n, 4), terms(1:n, 5), terms(1:n, 6), &
                slopes_k(1:n))
        else
            call model%law%panel_terms(a%c, side, mid, t(1:n), lambda(1:n), delta(1:n), &
                terms(1:n, 2), terms(1:n, 3), terms(1:n, 4), terms(1:n, 5), terms(1:n, 6))
        end if
    end subroutine panel_nodes

    !> `arch_sums` on the full rules (want_length_time) with the whole-half-arch tables
    !! where they apply (`whole_lookup`): with W the whole integrals, the second half-arch
    !! (weights 2 below the endpoint, 1 above) is W + int_0^lambda_r or 2W -
    !! int_lambda_r^Lambda, the first (0, 1) int_lambda_r^Lambda or W - int_0^lambda_r,
    !! whichever has fewer panels (the subtraction of the first half-arch only if
    !! int_0^lambda_r <= W/2: at most a bit lost). magnitude: the sums of the slopes'
    !! terms' sizes (for the error bounds of `arch_values`).
    pure subroutine table_sums(model, a, sums, slopes, magnitude, expected, fall_r)
        type(central_force_model), intent(in) :: model
        type(arch_setup), intent(in) :: a
        real(qp), intent(out) :: sums(3)
        real(xp), intent(out), optional :: slopes(2), magnitude(2)
        !> Theta's value where it is known (the root finder's psi): the first half-arch
        !! then goes straight to int_lambda_r^Lambda where W - int_0^lambda_r would lose
        !! more than a bit
        real(qp), intent(in), optional :: expected
        real(qp), intent(in), optional :: fall_r  !! t0(r), the fall time to the endpoint
        type(arch_setup) :: below, above
        type(panel) :: panels_below(max_panels), panels_above(max_panels)
        real(qp) :: whole(5), part(3), w_sign, p_sign, sizes(3), offset(3)
        real(xp) :: part_slopes(2), whole_hw(2)
        integer :: n_below, n_above
        logical :: found, use_below
        ! whether the tables apply, and W for the choice, from Theta's table in hardware
        ! precision; the binary128 tables only where W enters the sums
        call whole_lookup_xp(model, hardware_real(a%big_lambda), whole_hw, found)
        found = found .and. a%weight_above == 1.0_qp .and. &
                (a%weight_below == 0.0_qp .or. a%weight_below == 2.0_qp)
        if (.not. found) then
            call all_panels(sums, slopes, magnitude)
            return
        end if
        call split_panels(model, a, below, panels_below, n_below, above, panels_above, &
                          n_above)
        use_below = n_below <= n_above
        if (present(expected) .and. a%weight_below == 0.0_qp) &
            use_below = use_below .and. expected >= 0.5_qp*quad_real(whole_hw(1))
        whole = 0.0_qp
        if (use_below .or. a%weight_below == 2.0_qp) then
            ! the slopes' tables only for the slopes
            call whole_lookup(model, a%big_lambda, whole, found, merge(5, 3, present(slopes)))
            if (.not. found) then
                ! (the two lookups disagree at the edge of a piece)
                call all_panels(sums, slopes, magnitude)
                return
            end if
        end if
        if (a%weight_below == 2.0_qp) then
            w_sign = merge(1.0_qp, 2.0_qp, use_below)
            p_sign = merge(1.0_qp, -1.0_qp, use_below)
        else
            w_sign = merge(1.0_qp, 0.0_qp, use_below)
            p_sign = merge(-1.0_qp, 1.0_qp, use_below)
        end if
        ! (what the part is added to: W, 2 W - part >= W, W - part >= W/2 where kept)
        offset = merge(1.0_qp, 0.5_qp, a%weight_below == 2.0_qp)*whole(1:3)
        if (use_below) then
            call part_sums(below, panels_below, n_below, part, part_slopes)
        else
            call part_sums(above, panels_above, n_above, part, part_slopes)
        end if
        if (a%weight_below == 0.0_qp .and. use_below) then
            ! W - int_0^lambda_r: at most a bit lost, and the endpoint nearer the apse
            ! (delta_r >= Lambda/2: 1 - r >= (1 - R)/2, t0(r) >= t0(R)/2, the sizes the
            ! tables are checked against); the S and T corrections may lose more where
            ! they are below (1 - R)/R and t0(r)/R: their errors are then within the
            ! tables' own, of the sizes s and t exceed
            sizes = 0.0_qp
            if (present(fall_r)) sizes(2:3) = [a%one_minus_big_r, fall_r]/a%big_r
            if (.not. (all(part <= 0.5_qp*whole(1:3) .or. whole(1:3) <= sizes) .and. &
                       a%delta_r >= 0.5_qp*a%big_lambda)) then
                w_sign = 0.0_qp
                p_sign = 1.0_qp
                offset = 0.0_qp
                call part_sums(above, panels_above, n_above, part, part_slopes)
            end if
        end if
        sums = w_sign*whole(1:3) + p_sign*part
        if (present(slopes)) then
            slopes = real(w_sign*whole(4:5), xp) + real(p_sign, xp)*part_slopes
            magnitude = abs(real(w_sign*whole(4:5), xp)) + abs(part_slopes)
        end if
    contains
        !> Every panel (`arch_sums` without the tables).
        pure subroutine all_panels(sums, slopes, magnitude)
            real(qp), intent(out) :: sums(3)
            real(xp), intent(out), optional :: slopes(2), magnitude(2)
            if (present(slopes)) then
                call arch_sums(model, a, fine_digits, .true., sums, slopes)
                magnitude = abs(slopes)
            else
                call arch_sums(model, a, fine_digits, .true., sums)
            end if
        end subroutine all_panels

        pure subroutine part_sums(b, pans, n_pans, part, part_slopes)
            type(arch_setup), intent(in) :: b
            type(panel), intent(in) :: pans(max_panels)
            integer, intent(in) :: n_pans
            real(qp), intent(out) :: part(3)
            real(xp), intent(out) :: part_slopes(2)
            if (present(slopes)) then
                call arch_sums(model, b, fine_digits, .true., part, part_slopes, pans, n_pans, &
                               offset=offset)
            else
                call arch_sums(model, b, fine_digits, .true., part, given=pans, &
                               given_count=n_pans, offset=offset)
                part_slopes = 0.0_xp
            end if
        end subroutine part_sums
    end subroutine table_sums

    !> The apse data and panels of the integrals below the endpoint (weights 1, 0) and
    !! above it (0, 1), as `arch_panels` gives them, from one layout (weights 1, 2, the
    !! panels told apart by their weights) where the two are parts of it: the layout
    !! does not depend on the weights but for the cut of the panels past exp(-300) of
    !! the integrands where the weighted region starts, which the cut never reaches
    !! where the decay rate pi/sigma_apse times Lambda is below 250 (the tables' range
    !! but for the steepest laws), and for the root panel up to an endpoint inside the
    !! first ladder panel (`root_scales`). Elsewhere two layouts. With `hardware` (the
    !! early phase) the layouts of `arch_panels_xp`.
    pure subroutine split_panels(model, a, below, panels_below, n_below, above, &
                                 panels_above, n_above, hardware)
        type(central_force_model), intent(in) :: model
        type(arch_setup), intent(in) :: a
        type(arch_setup), intent(out) :: below, above
        type(panel), intent(out) :: panels_below(max_panels), panels_above(max_panels)
        integer, intent(out) :: n_below, n_above
        logical, intent(in), optional :: hardware
        type(arch_setup) :: both
        type(panel) :: panels(max_panels)
        real(qp) :: b(3), c(3)
        real(xp) :: bx(3), cx(3), x(3)
        integer :: count, p
        logical :: fast, one_layout
        below = a
        below%weight_below = 1.0_qp
        below%weight_above = 0.0_qp
        above = a
        above%weight_below = 0.0_qp
        above%weight_above = 1.0_qp
        count = max_panels
        both = a
        both%weight_below = 1.0_qp
        both%weight_above = 2.0_qp
        fast = .false.
        if (present(hardware)) fast = hardware
        if (fast) then
            x = hardware_real([a%big_lambda, a%lambda_r, a%delta_r])
            call root_scales_xp(model, both, x, bx(1), cx(1))
            call root_scales_xp(model, below, x, bx(2), cx(2))
            call root_scales_xp(model, above, x, bx(3), cx(3))
            one_layout = model%layout_xp(1)*x(1) <= 250.0_xp .and. &
                all(bx == bx(1)) .and. all(cx == cx(1)) .and. &
                .not. continued_root_xp(above, x, bx(3), cx(3))
        else
            call root_scales(model, both, b(1), c(1))
            call root_scales(model, below, b(2), c(2))
            call root_scales(model, above, b(3), c(3))
            one_layout = model%decay_apse*a%big_lambda <= 250.0_qp .and. &
                all(b == b(1)) .and. all(c == c(1)) .and. &
                .not. continued_root(above, b(3), c(3))
        end if
        if (one_layout) call layout(both, panels, count)
        if (count >= max_panels) then
            call layout(below, panels_below, n_below)
            call layout(above, panels_above, n_above)
            return
        end if
        n_below = 0
        n_above = 0
        do p = 1, count
            if (panels(p)%weight == 1.0_qp) then
                n_below = n_below + 1
                panels_below(n_below) = panels(p)
            else
                n_above = n_above + 1
                panels_above(n_above) = panels(p)
                panels_above(n_above)%weight = 1.0_qp
            end if
        end do
    contains
        !> `arch_panels` or `arch_panels_xp`
        pure subroutine layout(setup, list, n)
            type(arch_setup), intent(in) :: setup
            type(panel), intent(out) :: list(max_panels)
            integer, intent(out) :: n
            if (fast) then
                call arch_panels_xp(model, setup, list, n)
            else
                call arch_panels(model, setup, list, n)
            end if
        end subroutine layout
    end subroutine split_panels

    !> Whether the first half-arch (weights 0, 1) must be int_lambda_r^Lambda in the early
    !! phase, W - int_0^lambda_r being bound to fail its check in `theta_xp`
    !! (int_0^lambda_r <= W/2 and delta_r >= Lambda/2): the endpoint nearer the start,
    !! or its Theta (the hint, psi to within the early phase's rounding) below 0.45 W.
    pure logical function above_first(a, whole_angle)
        type(arch_setup), intent(in) :: a
        real(qp), intent(in) :: whole_angle  !! W, Theta of the whole half-arch
        above_first = a%weight_below == 0.0_qp .and. (a%delta_r < 0.5_qp*a%big_lambda .or. &
            (a%angle_hint > 0.0_qp .and. a%angle_hint < 0.45_qp*whole_angle))
    end function above_first

    !> Bounds on a panel's shares of the sums so far: its length in lambda times the
    !! integrands at the nearest node of the previous panel (they decay away from the
    !! apse), for the first `count` sums (the others 0).
    pure function panel_share(pan, last, sums, count) result(share)
        type(panel), intent(in) :: pan
        real(qp), intent(in) :: last(3), sums(3)
        integer, intent(in) :: count
        real(qp) :: share(3), length
        integer :: m
        length = panel_length(pan)
        share = 0.0_qp
        do m = 1, count
            if (sums(m) > 0.0_qp) share(m) = 4.0_qp*length*last(m)/sums(m)
        end do
    end function panel_share

    !> The rule (element of model%gauss) for a panel of `arch_sums`, each sum asked for
    !! `digits` less the digits of its share (`shares`: of Theta, S, T) on the ellipse
    !! and with the growth of its own decay rate (`bernstein_log`, `rule_for`,
    !! `panel_growth`): Theta's integrand sqrt(q/(1 - q)) decays like exp(-kappa lambda),
    !! kappa = pi/sigma_apse, and so does T's, (q/v) e^lambda = sqrt(w(R) q)/R (v =
    !! x/sqrt(w)) over (sqrt(1 - q)(1 + sqrt(1 - q))); S's, q e^lambda over the same, at
    !! most twice as fast. The largest of the rules; a sum whose share is below
    !! `negligible` asks for nothing, and Theta and T nothing beyond S where the shares are
    !! the same (the first panel: the same digits and ellipse, S's growth twice theirs;
    !! one `bernstein_log` then).
    pure function panel_rule(model, big_lambda, pan, digits, shares, want_length_time) &
        result(j)
        type(central_force_model), intent(in) :: model
        real(qp), intent(in) :: big_lambda, digits, shares(3)
        type(panel), intent(in) :: pan
        logical, intent(in) :: want_length_time
        integer :: j
        type(panel) :: p
        real(qp) :: share, wanted
        integer :: group
        p = pan
        j = min_nodes/2
        do group = 1, merge(2, 1, want_length_time)
            ! Theta and T at rate kappa, S at 2 kappa
            share = merge(max(shares(1), merge(shares(3), 0.0_qp, want_length_time)), &
                          shares(2), group == 1)
            if (share < negligible .or. (group == 1 .and. want_length_time .and. &
                                         shares(2) == share)) cycle
            wanted = digits + real(min(0.0_real64, log10(max(double_real(share), &
                                                             1.0e-60_real64))), qp)
            p%log_rho = bernstein_log(model, big_lambda, p, digits=wanted)
            j = max(j, rule_for(p%log_rho, wanted, panel_growth(p, real(group, qp)*pi/ &
                                                                model%sigma_apse)))
        end do
    end function panel_rule

    !> sums = sums + terms with Kahan's compensation (carry: the running correction).
    pure subroutine add_compensated(sums, carry, terms)
        real(xp), intent(inout) :: sums(2), carry(2)
        real(xp), intent(in) :: terms(2)
        real(xp) :: y(2), t(2)
        y = terms + carry
        t = sums + y
        carry = y - (t - sums)
        sums = t
    end subroutine add_compensated

    !> The extent in lambda of a panel.
    pure function panel_length(p) result(length)
        type(panel), intent(in) :: p
        real(qp) :: length
        select case (p%kind)
        case (kind_apse_root, kind_start_root)
            length = p%scale*(p%hi**2 - p%lo**2)
        case (kind_full)
            length = p%scale*(p%hi**2*(3.0_qp - 2.0_qp*p%hi) - p%lo**2*(3.0_qp - 2.0_qp*p%lo))
        case default
            length = p%hi - p%lo
        end select
    end function panel_length

    !> Theta (weighted as in `a`) in double precision, 17-digit rules, as
    !! theta exp(-shift): the integrand is scaled by exp(kappa lambda_0) at the start
    !! lambda_0 of the weighted region (kappa = pi/sigma_apse, its decay rate), so that
    !! Theta ~ R^((n+1)/2) stays in range for every R-bar of binary128.
    pure subroutine theta64(model, a, theta, shift)
        type(central_force_model), intent(in) :: model
        type(arch_setup), intent(in) :: a
        real(real64), intent(out) :: theta, shift
        type(panel) :: panels(max_panels)
        real(real64) :: part, last, v, lambda, delta, jacobian, g, big, scale, share
        integer :: count, p, k, j
        ! (the layout in hardware precision: the sums are in double)
        call arch_panels_xp(model, a, panels, count)
        theta = 0.0_real64
        last = 0.0_real64
        big = double_real(a%big_lambda)
        shift = 0.0_real64
        if (a%weight_below == 0.0_qp) shift = double_real(pi/model%sigma_apse*a%lambda_r)
        do p = 1, count
            associate (pan => panels(p))
            share = 1.0_real64
            if (p > 1 .and. theta > 0.0_real64) then
                share = 4.0_real64*double_real(panel_length(pan))*last/theta
                if (share < 1.0e-20_real64) cycle
            end if
            pan%log_rho = bernstein_log(model, a%big_lambda, pan)
            j = rule_for(pan%log_rho, coarse_digits + &
                         real(min(0.0_real64, log10(max(share, 1.0e-30_real64))), qp), &
                         panel_growth(pan, 2.0_qp*pi/model%sigma_apse))
            scale = double_real(pan%scale)
            part = 0.0_real64
            do k = 1, model%gauss(j)%n
                v = double_real(pan%lo) + double_real(pan%hi - pan%lo)* &
                    model%gauss(j)%offset64(k)
                select case (pan%kind)
                case (kind_apse_root)
                    lambda = scale*v*v
                    delta = big - lambda
                    jacobian = 2.0_real64*scale*v
                case (kind_apse)
                    lambda = v
                    delta = big - v
                    jacobian = 1.0_real64
                case (kind_start)
                    delta = v
                    lambda = big - v
                    jacobian = 1.0_real64
                case (kind_full)
                    lambda = scale*(v*v*(3.0_real64 - 2.0_real64*v))
                    delta = scale*((1.0_real64 - v)**2*(1.0_real64 + 2.0_real64*v))
                    jacobian = 6.0_real64*scale*(v*(1.0_real64 - v))
                case default
                    delta = scale*v*v
                    lambda = big - delta
                    jacobian = 2.0_real64*scale*v
                end select
                g = model%law%theta_ratio64(a%c, lambda, delta, shift)
                part = part + model%gauss(j)%weight64(k)*g*jacobian
                if (k == merge(1, model%gauss(j)%n, pan%kind >= kind_start .and. &
                               pan%kind <= kind_start_root)) last = g
            end do
            theta = theta + double_real(pan%weight)*double_real(pan%hi - pan%lo)*part
            end associate
        end do
    end subroutine theta64

    !> A piece of the radial fall time, int x/v(x) d delta over [delta_lo, delta_hi]
    !! (x = exp(-delta)): t0(r) = piece(0, -log r), t0(R) - t0(r) = piece(-log r, Lambda).
    !! Panels from the start: delta = c s^2 on [0, c], then [c, 4c], [4c, 16c], ...
    pure function fall_piece(model, delta_lo, delta_hi) result(total)
        type(central_force_model), intent(in) :: model
        real(qp), intent(in) :: delta_lo, delta_hi
        real(qp) :: total
        type(panel) :: panels(max_panels)
        type(arch_setup) :: a
        real(qp) :: c, lo, hi, v, delta, lambda, jacobian, g, part, last, share
        integer :: count, p, k, j
        logical :: found
        total = 0.0_qp
        if (delta_hi <= delta_lo) return
        call model%law%closed_fall(delta_lo, delta_hi, total, found)
        if (found) return
        c = min(1.0_qp, 0.5_qp*model%sigma_start)
        ! weight 1 inside [delta_lo, delta_hi] (start-side panels are 'reversed')
        a%weight_above = 0.0_qp
        a%weight_below = 1.0_qp
        count = 0
        if (delta_lo < c) call add_split(panels, count, kind_start_root, 0.0_qp, &
            min(1.0_qp, sqrt(delta_hi/c)), c, sqrt(delta_lo/c), a)
        lo = c
        do while (lo < delta_hi .and. count < max_panels - 2)
            ! x/v decays like exp(-(1 + pi/sigma_start) delta): stop at exp(-300)
            if ((1.0_qp + pi/model%sigma_start)*(lo - delta_lo) > 300.0_qp) exit
            hi = min(4.0_qp*lo, lo + 4.0_qp*model%sigma_start, delta_hi)
            if (hi > delta_lo) call add_split(panels, count, kind_start, lo, hi, 1.0_qp, &
                                              delta_lo, a)
            lo = hi
        end do
        last = 0.0_qp
        do p = 1, count
            associate (pan => panels(p))
            share = 1.0_qp
            if (p > 1 .and. total > 0.0_qp) then
                share = 4.0_qp*panel_length(pan)*last/total
                if (share < negligible) cycle
            end if
            ! singularities: delta = 0 and +-i sigma_start (x = 0 is at infinity)
            pan%log_rho = bernstein_log(model, 1.0e30_qp, pan, .true.)
            j = rule_for(pan%log_rho, fine_digits + &
                         real(min(0.0_real64, log10(max(real(share, real64), &
                                                            1.0e-60_real64))), qp), &
                         panel_growth(pan, 1.0_qp + pi/model%sigma_start))
            part = 0.0_qp
            do k = 1, model%gauss(j)%n
                v = pan%lo + (pan%hi - pan%lo)*model%gauss(j)%offset(k)
                call node_point(pan%kind, pan%scale, 0.0_qp, v, lambda, delta, jacobian)
                g = model%law%fall_integrand(delta)
                part = part + model%gauss(j)%weight(k)*g*jacobian
                if (k == model%gauss(j)%n) last = g
            end do
            total = total + pan%weight*(pan%hi - pan%lo)*part
            end associate
        end do
    end function fall_piece

    !> Theta, S, T at the endpoint for the apse data `a` (first or second half-arch as
    !! the weights say); d = r - R exact, one_minus_r = 1 - r.
    pure subroutine arch_values(model, a, d, one_minus_r, second, fall_r, angle, length, &
                                time, slopes, expected, parts)
        type(central_force_model), intent(in) :: model
        type(arch_setup), intent(in) :: a
        real(qp), intent(in) :: d, one_minus_r
        logical, intent(in) :: second
        real(qp), intent(in) :: fall_r   !! t0(r), the radial fall time to r
        real(qp), intent(out) :: angle, length, time
        !> d angle/d Lambda, d length/d Lambda in hardware precision and bounds on their
        !! absolute errors (the law's hardware terms needed)
        real(xp), intent(out), optional :: slopes(4)
        real(qp), intent(in), optional :: expected  !! the angle where known (`table_sums`)
        !> with slopes: the four without the endpoint's jump terms (`sharp_jump`)
        real(xp), intent(out), optional :: parts(4)
        real(qp) :: sums(3), fall
        logical :: found
        real(xp) :: integral_slopes(2), g, omq, log_slope, root, h, jump, big_r, error
        real(xp) :: magnitude(2), error_jump
        if (present(slopes)) then
            call table_sums(model, a, sums, integral_slopes, magnitude, expected, fall_r)
            ! the endpoint lambda_r = Lambda - delta_r moves with Lambda: the integrands
            ! there times the jump of the weights (g = 0 at the start, delta_r = 0)
            g = 0.0_xp
            h = 0.0_xp
            jump = real(a%weight_below - a%weight_above, xp)
            if (a%delta_r > 0.0_qp .and. a%lambda_r > 0.0_qp) then
                call model%law%theta_terms_xp(a%cx, real(a%lambda_r, xp), &
                                              real(a%delta_r, xp), 0.0_xp, .false., g, omq, &
                                              log_slope)
                root = sqrt(omq)
                h = real(1.0_qp + d/a%big_r, xp)*g*g*root/(1.0_xp + root)
            end if
            big_r = real(a%big_r, xp)
            slopes(1) = integral_slopes(1) + jump*g
            slopes(2) = big_r*(integral_slopes(2) + jump*h - real(sums(2), xp))
            if (second) slopes(2) = slopes(2) + 2.0_xp*big_r
            ! compensated sums of terms of one sign, each within about 20 roundings of
            ! xp: the terms of `arch_sums` from its binary128 nodes' values (and the
            ! tables', checked to 4 roundings), but g and h at lambda_r, delta_r rounded to
            ! xp, where the terms vary like exp(-kappa lambda) (power laws: exp(-a delta),
            ! a < 2 kappa), lambda, delta <= Lambda
            error = 32.0_xp*epsilon(1.0_xp)
            error_jump = epsilon(1.0_xp)*(32.0_xp + real(2.0_qp*model%decay_apse* &
                                                        a%big_lambda, xp))
            slopes(3) = error*magnitude(1) + error_jump*abs(g)
            slopes(4) = big_r*(error*(magnitude(2) + real(sums(2), xp)) + error_jump*abs(h))
            if (present(parts)) then
                parts(1) = integral_slopes(1)
                parts(2) = big_r*(integral_slopes(2) - real(sums(2), xp))
                if (second) parts(2) = parts(2) + 2.0_xp*big_r
                parts(3) = error*magnitude(1)
                parts(4) = big_r*error*(magnitude(2) + real(sums(2), xp))
            end if
        else
            call table_sums(model, a, sums, expected=expected, fall_r=fall_r)
        end if
        if (second) then
            ! 2 t0(R) - t0(r) = t0(r) + 2 (t0(R) - t0(r)); in closed form 2 t0(R) - t0(r)
            ! (fall_r: t0(r) in that closed form, one evaluation less)
            call model%law%closed_fall(0.0_qp, a%big_lambda, fall, found)
            if (found) then
                fall = 2.0_qp*fall - fall_r
            else
                fall = fall_r + 2.0_qp*fall_piece(model, a%delta_r, a%big_lambda)
            end if
            length = (one_minus_r + 2.0_qp*d) + a%big_r*sums(2)
        else
            fall = fall_r
            length = one_minus_r + a%big_r*sums(2)
        end if
        angle = sums(1)
        time = fall + a%big_r*sums(3)
    end subroutine arch_values

    !> The slopes of `arch_values` (`parts`: the four without the endpoint's terms) with
    !! the endpoint's jump terms g, h (the Theta and S integrands at lambda_r times the
    !! jump of the weights) from the law's binary128 terms at the exact lambda_r, delta_r
    !! (one node of the 25-40 of a full evaluation: only where the certification of
    !! `final_step` fails by their error bound). `arch_values` takes g, h in hardware
    !! precision at lambda_r, delta_r rounded to it, where exp(-a delta), exp(-a Lambda)
    !! with arguments up to a Lambda make their error bound grow like Lambda times the
    !! decay rate (n = 32, Lambda = 1.6: 85 eps_xp |g|; the error measured there, against
    !! binary128 differences, about eps_xp |g|).
    !! Here g = sqrt(q)/sqrt(1 - q) and h = (1 + d/R) q/(sqrt(1 - q) (1 + sqrt(1 - q)))
    !! in binary128 from the quadrature's own q, 1 - q, sqrt(q) (each within a few
    !! binary128 roundings, below 1e-30 of themselves: a positive sum, and differences
    !! that lose at most two bits, `speed_law%arch_terms`) are within 2^-100 of
    !! themselves, each rounded once to hardware precision; with the rounding of the sum
    !! it enters (below the rounding of |jump g| plus that of the other part, which
    !! `error magnitude` bounds as in `arch_values`) and, for h, that of R and of R h:
    !! at most four roundings (of eps_xp/2 each): 3 eps_xp |g| and 3 eps_xp R |h| (six
    !! roundings) bound their errors.
    pure subroutine sharp_jump(model, a, d, parts, slopes)
        type(central_force_model), intent(in) :: model
        type(arch_setup), intent(in) :: a
        real(qp), intent(in) :: d
        real(xp), intent(in) :: parts(4)
        real(xp), intent(out) :: slopes(4)
        real(qp) :: q, omq, q_over_v, r_over_x, root_q, root_omq
        real(xp) :: jump, g, h, big_r
        slopes = parts
        if (.not. (a%delta_r > 0.0_qp .and. a%lambda_r > 0.0_qp)) return
        call model%law%arch_terms(a%c, a%lambda_r, a%delta_r, q, omq, q_over_v, r_over_x, &
                                  root_q)
        root_omq = fast_sqrt(omq)
        g = hardware_real(root_q/root_omq)
        h = hardware_real((1.0_qp + d/a%big_r)*q/(root_omq*(1.0_qp + root_omq)))
        jump = real(a%weight_below - a%weight_above, xp)
        big_r = real(a%big_r, xp)
        slopes(1) = parts(1) + jump*g
        slopes(2) = parts(2) + big_r*(jump*h)
        slopes(3) = parts(3) + 3.0_xp*epsilon(1.0_xp)*abs(g)
        slopes(4) = parts(4) + big_r*(3.0_xp*epsilon(1.0_xp)*abs(h))
    end subroutine sharp_jump

    !> theta, s, t at radius r on the first (or second) half-arch with apse R.
    pure subroutine general_half_arch(self, r, big_r, second, angle, length, time, status)
        class(central_force_model), intent(in) :: self
        real(qp), intent(in) :: r        !! radius, R <= r <= 1
        real(qp), intent(in) :: big_r    !! apse radius, 0 < R < 1
        logical, intent(in) :: second    !! second half-arch: 2 F(R,R) - F(r,R)
        real(qp), intent(out) :: angle, length, time !! theta, s, t at r
        integer, intent(out) :: status   !! status_ok or the reason
        type(arch_setup) :: a
        angle = 0.0_qp
        length = 0.0_qp
        time = 0.0_qp
        status = argument_status([r, big_r], big_r > 0.0_qp .and. big_r < 1.0_qp .and. &
                                             r >= big_r .and. r <= 1.0_qp)
        if (status /= status_ok) return
        a = setup_arch(self, big_r, 1.0_qp - big_r, r - big_r, minus_log(r, 1.0_qp - r), &
                       second, .false.)
        call arch_values(self, a, r - big_r, 1.0_qp - r, second, &
                         fall_piece(self, 0.0_qp, a%delta_r), angle, length, time)
    end subroutine general_half_arch

    !> d theta/d Lambda at fixed r (Lambda = -log R) on the first (or second) half-arch
    !! with apse R as the certified steps take it (`final_step`): in hardware precision
    !! with the bound on its error (`arch_values`), and with the endpoint's terms from
    !! binary128 (`sharp_jump`): values = [slope, bound, sharp slope, its bound]; zeros
    !! for a law without hardware-precision terms. For tests of the bounds.
    pure subroutine general_angle_slopes(self, r, big_r, second, values, status)
        class(central_force_model), intent(in) :: self
        real(qp), intent(in) :: r        !! radius, R <= r <= 1
        real(qp), intent(in) :: big_r    !! apse radius, 0 < R < 1
        logical, intent(in) :: second    !! second half-arch: 2 F(R,R) - F(r,R)
        real(qp), intent(out) :: values(4)
        integer, intent(out) :: status   !! status_ok or the reason
        type(arch_setup) :: a
        real(qp) :: angle, length, time
        real(xp) :: slopes(4), parts(4), sharp(4)
        values = 0.0_qp
        status = argument_status([r, big_r], big_r > 0.0_qp .and. big_r < 1.0_qp .and. &
                                             r >= big_r .and. r <= 1.0_qp)
        if (status /= status_ok .or. .not. self%law%has_terms_xp()) return
        a = setup_arch(self, big_r, 1.0_qp - big_r, r - big_r, minus_log(r, 1.0_qp - r), &
                       second, .false.)
        call arch_values(self, a, r - big_r, 1.0_qp - r, second, &
                         fall_piece(self, 0.0_qp, a%delta_r), angle, length, time, slopes, &
                         parts=parts)
        call sharp_jump(self, a, r - big_r, parts, sharp)
        values = real([slopes(1), slopes(3), sharp(1), sharp(3)], qp)
    end subroutine general_angle_slopes

    !> -log r, from 1 - r where r is near 1.
    elemental function minus_log(r, one_minus_r) result(delta)
        real(qp), intent(in) :: r, one_minus_r
        real(qp) :: delta
        if (r > 0.5_qp) then
            delta = -fast_log1p(-one_minus_r)
        else
            delta = -fast_log(r)
        end if
    end function minus_log

    !> Theta(R,R): the apse angle.
    pure subroutine general_apse_angle(self, big_r, value, status)
        class(central_force_model), intent(in) :: self
        real(qp), intent(in) :: big_r    !! apse radius, 0 < R < 1
        real(qp), intent(out) :: value   !! Theta(R,R)
        integer, intent(out) :: status   !! status_ok or the reason
        type(arch_setup) :: a
        real(qp) :: sums(3)
        value = 0.0_qp
        status = argument_status([big_r], big_r > 0.0_qp .and. big_r < 1.0_qp)
        if (status /= status_ok) return
        a = setup_arch(self, big_r, 1.0_qp - big_r, 0.0_qp, &
                       minus_log(big_r, 1.0_qp - big_r), .false., .true.)
        sums = arch_integrals(self, a, fine_digits, .false.)
        value = sums(1)
    end subroutine general_apse_angle

    !> Time of radial fall from rest at radius 1 to radius r (K = 0): int_r^1 dx/v.
    pure subroutine general_fall_time(self, r, value, status)
        class(central_force_model), intent(in) :: self
        real(qp), intent(in) :: r        !! radius, 0 <= r <= 1
        real(qp), intent(out) :: value   !! the time
        integer, intent(out) :: status   !! status_ok or the reason
        real(qp) :: delta
        value = 0.0_qp
        status = argument_status([r], r >= 0.0_qp .and. r <= 1.0_qp)
        if (status /= status_ok .or. r == 1.0_qp) return
        if (r > 0.0_qp) then
            delta = minus_log(r, 1.0_qp - r)
        else
            delta = 1.0e4_qp
        end if
        value = fall_piece(self, 0.0_qp, delta)
    end subroutine general_fall_time

    !> The apse data at the unknown x (u = sqrt(rho - R), R, or y = log R).
    pure function setup_at(model, prob, x) result(a)
        type(central_force_model), intent(in) :: model
        type(endpoint_problem), intent(in) :: prob
        real(qp), intent(in) :: x
        type(arch_setup) :: a
        real(qp) :: d, lambda_r
        if (prob%use_u) then
            ! Lambda = delta_rho + lambda_r, lambda_r = log(1 + u^2/R) (R >= u^2): one
            ! logarithm
            d = x*x
            a%big_r = prob%rho - d
            a%one_minus_big_r = prob%one_minus_rho + d
            lambda_r = fast_log1p(d/a%big_r)
            a%big_lambda = prob%delta_rho + lambda_r
            call finish_setup(model, a, d, prob%delta_rho, prob%second, .false., lambda_r)
        else if (prob%use_r) then
            a = setup_arch(model, x, 1.0_qp - x, prob%rho - x, prob%delta_rho, &
                           prob%second, .false.)
        else
            a = setup_arch_log(model, -x, prob%rho, prob%delta_rho, prob%second)
        end if
    end function setup_at

    !> The apse data `theta64` needs at the unknown x: for laws with hardware-precision
    !! terms all in hardware precision (`setup_xp`: no binary128 logarithms, the law's
    !! constants Lambda, E(Lambda), a from `apse_constants_xp`, which `theta_ratio64` reads
    !! as c(1:3)); otherwise `setup_at`. Only for the early (hardware) phases.
    pure function setup_at64(model, prob, x) result(a)
        type(central_force_model), intent(in) :: model
        type(endpoint_problem), intent(in) :: prob
        real(qp), intent(in) :: x
        type(arch_setup) :: a
        real(xp) :: lambda_slope
        if (model%law%has_terms_xp() .and. .not. prob%use_r) then
            call setup_xp(model, prob, real(x, xp), a, lambda_slope)
            a%c(1:3) = real(a%cx(1:3), qp)
        else
            a = setup_at(model, prob, x)
        end if
    end function setup_at64

    !> The double-precision phase's function (in its `form`) at x.
    pure function residual64(model, prob, x) result(f)
        type(central_force_model), intent(in) :: model
        type(endpoint_problem), intent(in) :: prob
        real(qp), intent(in) :: x
        real(real64) :: f, upsilon, psi, limit, scaled, shift
        call theta64(model, setup_at64(model, prob, x), scaled, shift)
        upsilon = scaled*exp(-shift)
        psi = double_real(prob%psi)
        limit = double_real(prob%limit)
        select case (prob%form)
        case (1)
            ! log(Upsilon/psi) without forming Upsilon or psi (both may underflow double;
            ! the unknown u: the ratio first, log psi's rounding would count)
            if (prob%use_u) then
                f = log(upsilon/psi)
            else
                f = log(max(scaled, tiny(1.0_real64))) - shift - double_real(log(prob%psi))
            end if
        case (2)
            f = log(max(limit - upsilon, tiny(1.0_real64))/(limit - psi))
        case default
            f = upsilon - psi
        end select
    end function residual64

    !> Regula falsi with the Anderson-Bjorck correction on [lo, hi] (f of opposite
    !! signs), in double precision; x the root, slope the secant slope near it.
    pure subroutine double_phase(model, prob, lo, f_lo, hi, f_hi, x, slope, steps)
        type(central_force_model), intent(in) :: model
        type(endpoint_problem), intent(in) :: prob
        real(qp), intent(in) :: lo, hi
        real(real64), intent(in) :: f_lo, f_hi
        real(qp), intent(out) :: x
        real(real64), intent(out) :: slope
        integer, intent(inout) :: steps
        real(real64) :: a, b, fa, fb, c, fc, m, width
        integer :: iteration
        a = real(lo, real64)
        b = real(hi, real64)
        fa = f_lo
        fb = f_hi
        width = abs(b - a)
        slope = (fb - fa)/(b - a)
        c = b
        do iteration = 1, 100
            c = b - fb*(b - a)/(fb - fa)
            if (.not. (c > min(a, b) .and. c < max(a, b))) c = 0.5_real64*(a + b)
            fc = residual64(model, prob, real(c, qp))
            steps = steps + 1
            if (fc /= fb) slope = (fc - fb)/(c - b)
            if (fc == 0.0_real64) exit
            if ((fc > 0.0_real64) .neqv. (fb > 0.0_real64)) then
                a = b
                fa = fb
            else
                m = 1.0_real64 - fc/fb
                fa = fa*merge(m, 0.5_real64, m > 0.0_real64)
            end if
            if (abs(c - b) <= 2.0e-14_real64*max(abs(c), 1.0e-3_real64*width)) then
                b = c
                exit
            end if
            b = c
            fb = fc
        end do
        x = real(c, qp)
    end subroutine double_phase

    !> Theta (weighted as in `a`) and d Theta/d Lambda in hardware precision, on
    !! `hardware_digits` rules, as theta exp(-shift) and slope exp(-shift) (the scaling of
    !! `theta64`). The slope is that of the integrand at fixed lambda (`arch_sums`) plus
    !! the jump of the weights times the integrand at lambda_r = Lambda - delta_r.
    pure subroutine theta_xp(model, a, rough, theta, slope, shift, digits)
        type(central_force_model), intent(in) :: model
        type(arch_setup), intent(in) :: a
        logical, intent(in) :: rough   !! 12-digit rules, transcendentals in double
        real(xp), intent(out) :: theta, slope, shift
        !> the digits asked of the rules (default 12 where `rough`, else 20)
        real(qp), intent(in), optional :: digits
        type(arch_setup) :: below, above
        type(panel) :: panels_below(max_panels), panels_above(max_panels)
        real(xp) :: whole(2), part, part_slope, w_sign, p_sign, g, omq, log_slope
        integer :: n_below, n_above
        logical :: found, use_below
        shift = 0.0_xp
        if (a%weight_below == 0.0_qp) shift = hardware_real(pi/model%sigma_apse*a%lambda_r)
        call whole_lookup_xp(model, hardware_real(a%big_lambda), whole, found)
        found = found .and. a%weight_above == 1.0_qp .and. &
                (a%weight_below == 0.0_qp .or. a%weight_below == 2.0_qp)
        if (found) then
            ! as `table_sums`, Theta scaled by exp(shift)
            if (shift /= 0.0_xp) whole = whole*exp(shift)
            call split_panels(model, a, below, panels_below, n_below, above, panels_above, &
                              n_above, hardware=.true.)
            ! (the hardware-precision evaluations straight to int_lambda_r^Lambda where the
            ! check below is bound to fail)
            use_below = n_below <= n_above .and. &
                        (rough .or. .not. above_first(a, quad_real(whole(1))))
            if (a%weight_below == 2.0_qp) then
                w_sign = merge(1.0_xp, 2.0_xp, use_below)
                p_sign = merge(1.0_xp, -1.0_xp, use_below)
            else
                w_sign = merge(1.0_xp, 0.0_xp, use_below)
                p_sign = merge(-1.0_xp, 1.0_xp, use_below)
            end if
            if (use_below) then
                call panel_theta_xp(model, below, rough, shift, part, part_slope, &
                                    panels_below, n_below, digits)
            else
                call panel_theta_xp(model, above, rough, shift, part, part_slope, &
                                    panels_above, n_above, digits)
            end if
            ! (the rough evaluations, on 12-digit rules for a root to about 1e-10, lose up
            ! to 10 bits)
            if (a%weight_below == 0.0_qp .and. use_below .and. .not. ((part <= &
                0.5_xp*whole(1) .and. a%delta_r >= 0.5_qp*a%big_lambda) .or. &
                (rough .and. part <= 0.999_xp*whole(1)))) then
                w_sign = 0.0_xp
                p_sign = 1.0_xp
                call panel_theta_xp(model, above, rough, shift, part, part_slope, &
                                    panels_above, n_above, digits)
            end if
            theta = w_sign*whole(1) + p_sign*part
            slope = w_sign*whole(2) + p_sign*part_slope
        else
            call panel_theta_xp(model, a, rough, shift, theta, slope, digits=digits)
        end if
        if (a%weight_below /= a%weight_above .and. a%delta_r > 0.0_qp .and. &
            a%lambda_r > 0.0_qp) then
            call model%law%theta_terms_xp(a%cx, hardware_real(a%lambda_r), &
                                          hardware_real(a%delta_r), shift, rough, g, omq, &
                                          log_slope)
            slope = slope + hardware_real(a%weight_below - a%weight_above)*g
        end if
    end subroutine theta_xp

    !> `theta_xp` over the panels of `a` (its weights), without the jump at the endpoint.
    pure subroutine panel_theta_xp(model, a, rough, shift, theta, slope, given, &
                                   given_count, digits)
        type(central_force_model), intent(in) :: model
        type(arch_setup), intent(in) :: a
        logical, intent(in) :: rough   !! 12-digit rules, transcendentals in double
        real(xp), intent(in) :: shift
        real(xp), intent(out) :: theta, slope
        !> `arch_panels(model, a, given, given_count)` where the caller has them
        type(panel), intent(in), optional :: given(max_panels)
        integer, intent(in), optional :: given_count
        real(qp), intent(in), optional :: digits   !! as `theta_xp`'s
        type(panel) :: panels(max_panels)
        real(xp), dimension(max_nodes) :: lambda, delta, jacobian, g, h
        real(xp) :: part(2), last, big, scale, share, lo, width, exp_shift, weighted, weight
        integer :: count, p, k, j, n
        if (present(given) .and. present(given_count)) then
            count = given_count
            panels(1:count) = given(1:count)
        else
            call arch_panels_xp(model, a, panels, count)
        end if
        theta = 0.0_xp
        slope = 0.0_xp
        last = 0.0_xp
        big = hardware_real(a%big_lambda)
        ! the scale factor once for all nodes (0: beyond the hardware kind's range, the
        ! law scales each node by exp(shift - its decay) itself)
        exp_shift = 1.0_xp
        if (shift > 11000.0_xp) then
            exp_shift = 0.0_xp
        else if (shift /= 0.0_xp) then
            exp_shift = exp(shift)
        end if
        do p = 1, count
            associate (pan => panels(p))
            ! (conversions on the bits, `hardware_real`: no library call)
            scale = hardware_real(pan%scale)
            lo = hardware_real(pan%lo)
            width = hardware_real(pan%hi - pan%lo)
            weight = hardware_real(pan%weight)
            share = 1.0_xp
            if (p > 1 .and. theta > 0.0_xp) then
                share = 4.0_xp*panel_length_xp(pan%kind, scale, lo, width)*last/theta
                if (share < 1.0e-24_xp) cycle
            end if
            pan%log_rho = bernstein_log(model, a%big_lambda, pan)
            j = rule_for(pan%log_rho, asked_digits(rough, digits) + &
                         quad_real(min(0.0_xp, log10(max(share, 1.0e-30_xp)))), &
                         panel_growth(pan, 2.0_qp*pi/model%sigma_apse))
            ! the panel's nodes, the law's terms on all of them (one call), the sums
            n = model%gauss(j)%n
            call node_point_xp(pan%kind, scale, big, lo + width*model%gauss(j)%offset_xp, &
                               lambda(1:n), delta(1:n), jacobian(1:n))
            call model%law%panel_terms_xp(a%cx, lambda(1:n), delta(1:n), shift, rough, &
                                          exp_shift, g(1:n), h(1:n))
            part = 0.0_xp
            do k = 1, n
                weighted = model%gauss(j)%weight_xp(k)*g(k)*jacobian(k)
                part(1) = part(1) + weighted
                part(2) = part(2) + weighted*h(k)
            end do
            last = g(merge(1, n, pan%kind >= kind_start .and. pan%kind <= kind_start_root))
            theta = theta + weight*width*part(1)
            slope = slope + weight*width*part(2)
            end associate
        end do
    end subroutine panel_theta_xp

    !> `panel_length` in hardware precision from the panel's scale, lo and width = hi - lo
    !! (for `panel_theta_xp`'s estimate of a panel's share: no binary128 operations).
    elemental function panel_length_xp(kind, scale, lo, width) result(length)
        integer, intent(in) :: kind
        real(xp), intent(in) :: scale, lo, width
        real(xp) :: length
        select case (kind)
        case (kind_apse_root, kind_start_root)
            ! scale (hi^2 - lo^2)
            length = scale*width*(2.0_xp*lo + width)
        case (kind_full)
            ! scale (hi^2 (3 - 2 hi) - lo^2 (3 - 2 lo)), hi = lo + width, without cancellation
            length = scale*width*(3.0_xp*(2.0_xp*lo + width) - &
                                  2.0_xp*(3.0_xp*lo*(lo + width) + width*width))
        case default
            length = width
        end select
    end function panel_length_xp

    !> The digits asked of the early phase's rules: `digits` where given, else
    !! `rough_digits` or `hardware_digits`.
    pure real(qp) function asked_digits(rough, digits)
        logical, intent(in) :: rough
        real(qp), intent(in), optional :: digits
        asked_digits = merge(rough_digits, hardware_digits, rough)
        if (present(digits)) asked_digits = digits
    end function asked_digits

    !> `node_point` in hardware precision.
    elemental subroutine node_point_xp(kind, scale, big_lambda, v, lambda, delta, jacobian)
        integer, intent(in) :: kind
        real(xp), intent(in) :: scale, big_lambda, v
        real(xp), intent(out) :: lambda, delta, jacobian
        select case (kind)
        case (kind_apse_root)
            lambda = scale*v*v
            delta = big_lambda - lambda
            jacobian = 2.0_xp*scale*v
        case (kind_apse)
            lambda = v
            delta = big_lambda - v
            jacobian = 1.0_xp
        case (kind_start)
            delta = v
            lambda = big_lambda - v
            jacobian = 1.0_xp
        case (kind_full)
            lambda = scale*(v*v*(3.0_xp - 2.0_xp*v))
            delta = scale*((1.0_xp - v)**2*(1.0_xp + 2.0_xp*v))
            jacobian = 6.0_xp*scale*(v*(1.0_xp - v))
        case default
            delta = scale*v*v
            lambda = big_lambda - delta
            jacobian = 2.0_xp*scale*v
        end select
    end subroutine node_point_xp

    !> log(ratio) in hardware precision to its relative precision, for a binary128 ratio
    !! (log1p of ratio - 1, exact in binary128, next to 1).
    elemental function log_of_ratio(ratio) result(l)
        real(qp), intent(in) :: ratio
        real(xp) :: l
        if (abs(ratio - 1.0_qp) < 0.5_qp) then
            l = log1p_xp(real(ratio - 1.0_qp, xp))
        else
            l = log(real(ratio, xp))
        end if
    end function log_of_ratio

    !> exp(z) - 1 in hardware precision, z <= 0 (Kahan's correction: 2 exp(z/2) sinh(z/2)
    !! where it is small).
    elemental function expm1_xp(z) result(e)
        real(xp), intent(in) :: z
        real(xp) :: e
        if (abs(z) < 0.5_xp) then
            e = 2.0_xp*exp(0.5_xp*z)*sinh(0.5_xp*z)
        else
            e = exp(z) - 1.0_xp
        end if
    end function expm1_xp

    !> log(1 + z) in hardware precision (Kahan's correction of log(1 + z)).
    elemental function log1p_xp(z) result(l)
        real(xp), intent(in) :: z
        real(xp) :: l, w
        w = 1.0_xp + z
        if (w == 1.0_xp) then
            l = z
        else
            l = log(w)*(z/(w - 1.0_xp))
        end if
    end function log1p_xp

    !> The apse data the hardware-precision phase needs (Lambda, lambda_r, delta_r, the
    !! weights, the law's constants) at its unknown x (u or y = log R), and d Lambda/dx.
    pure subroutine setup_xp(model, prob, x, a, lambda_slope)
        type(central_force_model), intent(in) :: model
        type(endpoint_problem), intent(in) :: prob
        real(xp), intent(in) :: x
        type(arch_setup), intent(out) :: a
        real(xp), intent(out) :: lambda_slope
        real(xp) :: d, big_r, lambda_r, delta_r, big_lambda
        delta_r = hardware_real(prob%delta_rho)
        if (prob%use_u) then
            ! R = rho - u^2 >= rho/2 >= r - R: lambda_r = log(1 + u^2/R)
            d = x*x
            big_r = hardware_real(prob%rho) - d
            lambda_r = log1p_xp(d/big_r)
            big_lambda = delta_r + lambda_r
            lambda_slope = 2.0_xp*x/big_r
        else
            big_lambda = -x
            lambda_r = big_lambda - delta_r
            lambda_slope = -1.0_xp
        end if
        a%big_lambda = quad_real(big_lambda)
        a%lambda_r = quad_real(lambda_r)
        a%delta_r = prob%delta_rho
        a%weight_below = merge(2.0_qp, 0.0_qp, prob%second)
        a%weight_above = 1.0_qp
        if (.not. prob%second) a%angle_hint = prob%psi
        a%cx = model%law%apse_constants_xp(big_lambda)
    end subroutine setup_xp

    !> The early phase's function (in its `form`) and its slope at x, in hardware
    !! precision.
    pure subroutine residual_xp(model, prob, x, rough, f, slope)
        type(central_force_model), intent(in) :: model
        type(endpoint_problem), intent(in) :: prob
        real(xp), intent(in) :: x
        logical, intent(in) :: rough
        real(xp), intent(out) :: f, slope
        type(arch_setup) :: a
        real(xp) :: scaled, scaled_slope, shift, lambda_slope, upsilon, limit, unscale
        call setup_xp(model, prob, x, a, lambda_slope)
        call theta_xp(model, a, rough, scaled, scaled_slope, shift)
        ! exp(-shift) where used (1 on the second half-arch: no library call; form 1 in
        ! y = log R: where it is a normal number)
        unscale = 1.0_xp
        if (shift /= 0.0_xp .and. (prob%form /= 1 .or. prob%use_u .or. &
                                   shift < 11000.0_xp)) unscale = exp(-shift)
        select case (prob%form)
        case (1)
            ! log(Upsilon/psi), the ratio first (as `residual64`) where Upsilon is a normal
            ! number: log Upsilon - log psi would err by roundings of |log psi| (1e-17 at
            ! psi = 1e-30, beyond the certified step's margin), the ratio by its own
            upsilon = scaled*unscale
            if (prob%use_u .or. (upsilon >= tiny(1.0_xp) .and. (shift < 11000.0_xp .or. &
                                                               shift == 0.0_xp))) then
                f = log(upsilon/hardware_real(prob%psi))
            else
                f = log(max(scaled, tiny(1.0_xp))) - shift - log(hardware_real(prob%psi))
            end if
            slope = scaled_slope/scaled*lambda_slope
        case (2)
            upsilon = scaled*unscale
            limit = hardware_real(prob%limit)
            f = log(max(limit - upsilon, tiny(1.0_xp))/hardware_real(prob%limit - prob%psi))
            slope = -scaled_slope*unscale*lambda_slope/(limit - upsilon)
        case default
            f = scaled*unscale - hardware_real(prob%psi)
            slope = scaled_slope*unscale*lambda_slope
        end select
    end subroutine residual_xp

    !> The early phase in hardware precision: Newton steps on the analytic slope, kept in
    !! the bracket [lo, hi] (f of opposite signs at its ends; regula falsi with the
    !! Anderson-Bjorck correction where a Newton step would leave it), and where the
    !! previous evaluation of the same precision is at hand the root of the inverse
    !! cubic Hermite interpolant through both (`hermite_step`); the first iterate from the
    !! bracket's slopes where `open_bracket` has them (steep laws: a quadratic in lambda_r;
    !! y = log R: inverse Hermite through both ends). First `rough`
    !! evaluations (12-digit rules, transcendentals in double precision) until a step is
    !! below 1e-5 of the unknown or the Hermite point's estimated error below 1e-10
    !! (the next iterate then within about 1e-10), then hardware-precision ones (20-digit
    !! rules) until a step is below 1e-12, or its own error by the measured curvature
    !! below 1e-20 of the unknown, or f is within its rounding: by the quadratic
    !! convergence the root is then within the rounding of the hardware kind (usually
    !! one such evaluation; the last Newton step is taken even within the rounding: it
    !! halves the early root's error on average, and the certified step fails less
    !! often). x the root, slope f'(x) (the form's), curvature |f''/2f'| measured
    !! between the iterates (0 if not).
    pure subroutine hardware_phase(model, prob, lo, f_lo, hi, f_hi, x, slope, curvature, &
                                   steps, slope_hi)
        type(central_force_model), intent(in) :: model
        type(endpoint_problem), intent(in) :: prob
        real(qp), intent(in) :: lo, hi
        real(real64), intent(in) :: f_lo, f_hi
        real(qp), intent(out) :: x, slope, curvature
        integer, intent(inout) :: steps
        !> f'(hi) for the unknown u (0: unknown): the first iterate from the quadratic
        !! through f(lo), f(hi), f'(hi) rather than regula falsi
        real(real64), intent(in), optional :: slope_hi
        real(xp) :: a, b, fa, fb, xk, fk, dk, x_new, x_prev, d_prev, floor, noise
        real(xp) :: point(3), newton_error
        integer :: iteration
        logical :: rough
        call first_bracket(lo, f_lo, hi, f_hi, a, fa, b, fb)
        floor = merge(1.0e-3_xp*abs(b - a), 1.0_xp, prob%use_u)
        curvature = 0.0_qp
        x_prev = a
        d_prev = 0.0_xp
        ! the previous evaluation of the same precision (x, f, f'; f' = 0: none), for
        ! the inverse Hermite step
        point = 0.0_xp
        rough = .true.
        xk = falsi()
        if (present(slope_hi) .and. prob%use_u .and. prob%form == 0) then
            if (slope_hi /= 0.0_real64) then
                xk = hermite(real(slope_hi, xp))
                ! (Upsilon's own shape where it fits, for laws decaying at least like
                ! exp(-3 lambda) from the apse: `arcsin_model_root`; slower ones take as
                ! many evaluations from either first iterate on the engine-timing grid)
                if (pi/model%sigma_apse >= model_decay) then
                    x_new = model_point(fa + real(prob%psi, xp), fb + real(prob%psi, xp), &
                                        real(slope_hi, xp), real(prob%psi, xp))
                    if (x_new > 0.0_xp) xk = x_new
                end if
            end if
        end if
        ! the unknown y = log R: the inverse Hermite root through both ends where their
        ! slopes are known (the bracket's residuals and slopes of `open_bracket`)
        if (present(slope_hi) .and. .not. prob%use_u .and. prob%form /= 0 .and. &
            prob%slope_lo /= 0.0_real64) then
            if (slope_hi /= 0.0_real64) then
                xk = inverse_hermite(a, fa, real(prob%slope_lo, xp), b, fb, &
                                     real(slope_hi, xp), falsi())
                ! the curvature measured from the nearer end on (as between iterates)
                x_prev = merge(a, b, abs(xk - a) < abs(xk - b))
                d_prev = real(merge(prob%slope_lo, slope_hi, abs(xk - a) < abs(xk - b)), xp)
            end if
        end if
        ! steep laws (logarithmic forms): f about linear in lambda_r ~ u^2/R near the
        ! root, from f(0) at u = 0: regula falsi in u^2, or the quadratic in lambda_r
        ! through f(0), f(b) and f'(b) where the slope is known
        if (prob%use_u .and. prob%form /= 0 .and. a == 0.0_xp .and. &
            ((fa < 0.0_xp) .neqv. (fb < 0.0_xp))) xk = root_in_square(.true.)
        ! rho next to 1 (second half-arch): Upsilon - Theta(rho,rho) ~ c u^2 but for the
        ! smallest u (falsi would start far below the root; f of opposite signs at a = 0
        ! and b); where the slope at b is known, the root of `exp_model_root`'s model
        if (prob%use_u .and. prob%second .and. prob%one_minus_rho < 1.0e-6_qp .and. &
            ((fa < 0.0_xp) .neqv. (fb < 0.0_xp))) then
            xk = root_in_square(.false.)
            x_new = -1.0_xp
            if (present(slope_hi)) then
                if (slope_hi /= 0.0_real64 .and. prob%form == 0) then
                    x_new = model_point(fa + real(prob%psi, xp), fb + real(prob%psi, xp), &
                                        real(slope_hi, xp), real(prob%psi, xp), .true.)
                else if (slope_hi /= 0.0_real64) then
                    x_new = model_point(exp(fa), exp(fb), exp(fb)*real(slope_hi, xp), &
                                        1.0_xp, .true.)
                end if
            end if
            if (x_new > 0.0_xp) xk = x_new
        end if
        do iteration = 1, 80
            call residual_xp(model, prob, xk, rough, fk, dk)
            steps = steps + 1
            ! |Upsilon''/Upsilon'| = |f''/f' + f'| in the logarithmic forms (1, 2)
            if (d_prev /= 0.0_xp .and. abs(xk - x_prev) > 1.0e-7_xp*floor) &
                curvature = max(curvature, real(abs((dk - d_prev)/((xk - x_prev)*dk) + &
                                                    merge(0.0_xp, dk, prob%form == 0)), qp))
            noise = residual_noise(prob, fk, rough)
            if ((abs(fk) <= noise .and. noise < 1.0e-3_xp) .or. &
                (rough .and. iteration > 10)) then
                ! f within its rounding, and that small (the root as close as this
                ! precision can place it; next to the sector's edge that is far from
                ! 1e-18): on to the hardware-precision rules, or to the full-precision
                ! steps
                x_new = xk
                if (.not. rough) then
                    ! the Newton step within the rounding all the same (the root as
                    ! close as this precision places it)
                    if (xk - fk/dk > min(a, b) .and. xk - fk/dk < max(a, b)) &
                        x_new = xk - fk/dk
                    exit
                end if
                ! with the first bracket again (the rough signs are not sure within
                ! their rounding)
                rough = .false.
                point = 0.0_xp
                call first_bracket(lo, f_lo, hi, f_hi, a, fa, b, fb)
                cycle
            else
                call keep_bracket(xk, fk, a, fa, b, fb)
                x_new = xk - fk/dk
                newton_error = huge(1.0_xp)
                call hermite_step(x_new, newton_error)
                ! (a Newton step below xk's rounding lands on xk, an end of the bracket:
                ! the root as close as this precision places it, not a step for falsi)
                if (.not. (x_new > min(a, b) .and. x_new < max(a, b)) .and. &
                    x_new /= xk) x_new = falsi()
            end if
            point = [xk, fk, dk]
            ! the rough root: the Newton step below 1e-5 (the next iterate within about
            ! 1e-10), or the inverse Hermite step's error below 1e-10 (`hermite_error`)
            if (rough .and. (abs(x_new - xk) <= 1.0e-5_xp*max(abs(xk), floor) .or. &
                             hermite_error() <= 1.0e-10_xp*max(abs(xk), floor))) then
                ! on to the hardware-precision rules
                rough = .false.
                point = 0.0_xp
                call first_bracket(lo, f_lo, hi, f_hi, a, fa, b, fb)
            else if (.not. rough .and. &
                     (abs(x_new - xk) <= 1.0e-12_xp*max(abs(xk), floor) .or. &
                      (curvature > 0.0_qp .and. real(curvature, xp)*(x_new - xk)**2 <= &
                       1.0e-20_xp*max(abs(xk), floor)))) then
                ! the step's own error (|f''/2f'| step^2, twice that measured) below
                ! 1e-20 of the unknown: the root within the rounding of the hardware kind
                exit
            end if
            x_prev = xk
            d_prev = dk
            xk = x_new
        end do
        x = real(x_new, qp)
        slope = real(dk, qp)
        curvature = 0.5_qp*curvature
    contains
        !> The inverse Hermite step's error, estimated: the Newton step's (`newton_error`,
        !! huge where there was no Hermite step) times the ratio of the two steps' errors,
        !! about (x''''/12 x'') f_prev^2 for x(f) (Hermite: x''''/24 f_prev^2 f^2, Newton:
        !! x''/2 f^2), taken as 10 (curvature (x_prev - xk))^2 and at most 1 (measured on
        !! 270 early phases of the engine-timing grid, n = 1 + 1e-6 .. 32, logarithmic: the
        !! Hermite point within 1e-10 in 39 of the 40 where this is below 1e-10 and the
        !! Newton step's error above; an error beyond costs one more hardware-precision
        !! evaluation, the final steps' certification is unchanged)
        pure real(xp) function hermite_error()
            hermite_error = newton_error
            if (curvature > 0.0_qp .and. newton_error < huge(1.0_xp)) hermite_error = &
                newton_error*min(1.0_xp, 10.0_xp*(real(curvature, xp)*(x_prev - xk))**2)
        end function hermite_error

        !> The root of the cubic x(f) through the previous evaluation of the same
        !! precision and this one (values and slopes: inverse Hermite interpolation)
        !! where f is monotone between them and the root is in the bracket; then the
        !! Newton point's distance from it as `newton_error` (the Newton step errs by
        !! about |f''/2f'| step^2, the Hermite step by far less: the two evaluations'
        !! slopes measure f'').
        pure subroutine hermite_step(x_new, newton_error)
            real(xp), intent(inout) :: x_new, newton_error
            real(xp) :: h, s, x_h
            if (point(3) == 0.0_xp .or. (point(3) > 0.0_xp .neqv. dk > 0.0_xp)) return
            h = fk - point(2)
            if (h == 0.0_xp) return
            s = -point(2)/h
            x_h = xk + (2.0_xp*s + 1.0_xp)*(s - 1.0_xp)**2*(point(1) - xk) + &
                  h*s*(s - 1.0_xp)*((s - 1.0_xp)/point(3) + s/dk)
            if (.not. (x_h > min(a, b) .and. x_h < max(a, b))) return
            newton_error = abs(x_h - x_new)
            x_new = x_h
        end subroutine hermite_step

        !> The first iterate for f about linear in lambda_r = log(rho/(rho - u^2)) next
        !! to u = a = 0: the root of the model of `arcsin_model_root` in exp(f) (Upsilon
        !! or limit - Upsilon over its value at the root), else the root in lambda_r of the
        !! quadratic through f(0), f(b) and the slope f'(b) in lambda_r, where slope_hi is
        !! given and `with_slope`; else regula falsi in u^2.
        pure real(xp) function root_in_square(with_slope)
            logical, intent(in) :: with_slope
            real(xp) :: rho, l_b, l
            root_in_square = b*sqrt(fa/(fa - fb))
            if (.not. (present(slope_hi) .and. with_slope)) return
            if (slope_hi == 0.0_real64) return
            rho = real(prob%rho, xp)
            l_b = -log1p_xp(-b*b/rho)
            l = quadratic_root(0.0_xp, fa, l_b, fb, &
                               real(slope_hi, xp)*(rho - b*b)/(2.0_xp*b))
            if (l > 0.0_xp .and. l < l_b) root_in_square = sqrt(-rho*expm1_xp(-l))
            l = model_point(exp(fa), exp(fb), exp(fb)*real(slope_hi, xp), 1.0_xp)
            if (l > 0.0_xp) root_in_square = l
        end function root_in_square

        !> The u in (0, b) where the model of `arcsin_model_root` (`exponential`:
        !! `exp_model_root`) through Q(u = 0) = q0, Q(b) = qb and dQ/du(b) = dqb (in
        !! lambda_r = log(rho/(rho - u^2))) is `target`; -1 if there is none.
        pure real(xp) function model_point(q0, qb, dqb, target, exponential) result(u)
            real(xp), intent(in) :: q0, qb, dqb, target
            logical, intent(in), optional :: exponential
            real(xp) :: rho, l_b, l
            real(real64) :: data(5)
            logical :: use_exp
            u = -1.0_xp
            rho = real(prob%rho, xp)
            l_b = -log1p_xp(-b*b/rho)
            data = real([l_b, q0, qb, dqb*(rho - b*b)/(2.0_xp*b), target], real64)
            use_exp = .false.
            if (present(exponential)) use_exp = exponential
            if (use_exp) then
                l = real(exp_model_root(data(1), data(2), data(3), data(4), data(5)), xp)
            else
                l = real(arcsin_model_root(data(1), data(2), data(3), data(4), data(5)), xp)
            end if
            if (l > 0.0_xp .and. l < l_b) u = sqrt(-rho*expm1_xp(-l))
        end function model_point

        pure real(xp) function falsi()
            falsi = b - fb*(b - a)/(fb - fa)
            if (.not. (falsi > min(a, b) .and. falsi < max(a, b))) falsi = 0.5_xp*(a + b)
        end function falsi

        !> The root in (a, b) of f(b) + f'(b) t + c t^2 (t = x - b) through f(a); falsi
        !! if there is none.
        pure real(xp) function hermite(d)
            real(xp), intent(in) :: d
            hermite = quadratic_root(a, fa, b, fb, d)
            if (.not. (hermite > min(a, b) .and. hermite < max(a, b))) hermite = falsi()
        end function hermite
    end subroutine hardware_phase

    !> The first iterate of the early phase from Theta's shape: for a steep law
    !! (sqrt(q/(1 - q)) ~ exp(-k lambda)/sqrt(1 - exp(-2 k lambda))) Theta(r,R) from the
    !! endpoint at lambda_r to the apse is about arcsin(exp(-k lambda_r))/k, the square
    !! root at the apse and the exponential decay beyond; so are Upsilon and limit -
    !! Upsilon on the second half-arch. The model Q(l) = c1 arcsin(exp(-kappa l)) + c0
    !! through Q(0) = q0, Q(l_b) = qb and Q'(l_b) = dqb (t = arccos(exp(-kappa l_b)) the
    !! root of -log(cos t)/(t tan t) = -dqb l_b/(q0 - qb), which decreases from 1/2 to 0
    !! on (0, pi/2): regula falsi with the Illinois correction); its l in (0, l_b) where
    !! Q(l) = target, or -1 where there is none. (engine-timing grid, n = 32: the first
    !! iterate within 1e-6 rather than 1e-1 for rho <= 1/2; engine-fuzz: 0.76 fewer
    !! evaluations per endpoint for n = 32, 0.18 for n = 6.)
    pure real(real64) function arcsin_model_root(l_b, q0, qb, dqb, target) result(l)
        real(real64), intent(in) :: l_b, q0, qb, dqb, target
        real(real64), parameter :: half_pi = 2.0_real64*atan(1.0_real64)
        real(real64) :: r1, t, c1, c0, kappa, v
        logical :: found
        l = -1.0_real64
        if (q0 == qb .or. .not. l_b > 0.0_real64) return
        r1 = -dqb*l_b/(q0 - qb)
        if (.not. (r1 > 1.0e-6_real64 .and. r1 < 0.5_real64 - 1.0e-6_real64)) return
        call shape_root(shape_arcsin, r1, 1.0e-3_real64, half_pi - 1.0e-8_real64, &
                        1.0e-7_real64, 0.0_real64, 60, t, found)
        if (.not. found) return
        kappa = -log(cos(t))/l_b
        c1 = (q0 - qb)/t
        c0 = q0 - c1*half_pi
        v = (target - c0)/c1
        if (.not. (v > 0.0_real64 .and. v < half_pi .and. kappa > 0.0_real64)) return
        l = -log(sin(v))/kappa
    end function arcsin_model_root

    !> `arcsin_model_root` for a complete arch next to rho = 1 (the second half-arch from
    !! r ~ 1: Upsilon ~ c u^2 ~ c lambda_r, no square root at lambda_r = 0, and limit -
    !! Upsilon decaying like exp(-k lambda_r) for a steep law): the model Q(l) = c1
    !! exp(-kappa l) + c0 through Q(0) = q0, Q(l_b) = qb, Q'(l_b) = dqb (x = kappa l_b
    !! the root of x/(exp(x) - 1) = -dqb l_b/(q0 - qb), which decreases from 1 to 0:
    !! regula falsi with the Illinois correction on x in [1e-3, 60]); its l in (0, l_b)
    !! where Q(l) = target, -1 where there is none. (engine-timing grid: rough
    !! evaluations per solve n = 10 2.00 -> 1.73, n = 32 1.60 -> 1.40; engine-fuzz 0.02
    !! (n = 1 + 1e-6) to 0.23 (n = 32) fewer evaluations per endpoint.)
    pure real(real64) function exp_model_root(l_b, q0, qb, dqb, target) result(l)
        real(real64), intent(in) :: l_b, q0, qb, dqb, target
        real(real64) :: r2, x, c1, c0, kappa, w
        logical :: found
        l = -1.0_real64
        if (q0 == qb .or. .not. l_b > 0.0_real64) return
        r2 = -dqb*l_b/(q0 - qb)
        if (.not. (r2 > 1.0e-12_real64 .and. r2 < 0.999_real64)) return
        call shape_root(shape_exp, r2, 1.0e-3_real64, 60.0_real64, 0.0_real64, &
                        1.0e-9_real64, 80, x, found)
        if (.not. found) return
        kappa = x/l_b
        c1 = (q0 - qb)/(1.0_real64 - exp(-x))
        c0 = q0 - c1
        w = (target - c0)/c1
        if (.not. (w > 0.0_real64 .and. w < 1.0_real64)) return
        l = -log(w)/kappa
    end function exp_model_root

    !> The root z in (lo, hi) of shape(z) = r for the early phase's model shapes, both
    !! decreasing (`shape_arcsin`: -log(cos z)/(z tan z) of `arcsin_model_root`,
    !! `shape_exp`: z/(exp(z) - 1) of `exp_model_root`), by regula falsi with the Illinois
    !! correction until the bracket is below abs_tol + rel_tol z or the residual 0, at
    !! most max_steps steps; not `found` where shape - r has no sign change on [lo, hi].
    pure subroutine shape_root(shape, r, lo, hi, abs_tol, rel_tol, max_steps, z, found)
        integer, intent(in) :: shape, max_steps
        real(real64), intent(in) :: r, lo, hi, abs_tol, rel_tol
        real(real64), intent(out) :: z
        logical, intent(out) :: found
        real(real64) :: z_lo, z_hi, h, h_lo, h_hi
        integer :: k, side
        z_lo = lo
        z_hi = hi
        h_lo = shape_value(z_lo) - r
        h_hi = shape_value(z_hi) - r
        z = lo
        found = h_lo > 0.0_real64 .and. h_hi < 0.0_real64
        if (.not. found) return
        side = 0
        do k = 1, max_steps
            z = (z_lo*h_hi - z_hi*h_lo)/(h_hi - h_lo)
            h = shape_value(z) - r
            if (h > 0.0_real64) then
                z_lo = z
                h_lo = h
                if (side == 1) h_hi = 0.5_real64*h_hi
                side = 1
            else
                z_hi = z
                h_hi = h
                if (side == -1) h_lo = 0.5_real64*h_lo
                side = -1
            end if
            if (z_hi - z_lo < abs_tol + rel_tol*z .or. h == 0.0_real64) exit
        end do
    contains
        pure real(real64) function shape_value(x)
            real(real64), intent(in) :: x
            if (shape == shape_arcsin) then
                shape_value = -log(cos(x))/(x*tan(x))
            else
                shape_value = x/(exp(x) - 1.0_real64)
            end if
        end function shape_value
    end subroutine shape_root

    !> The root of the inverse cubic Hermite interpolant x(f) through (p, f_p, d_p) and
    !! (r, f_r, d_r) (values and slopes) where f is monotone between them and the root
    !! lies between p and r; `fallback` otherwise.
    pure real(xp) function inverse_hermite(p, f_p, d_p, r, f_r, d_r, fallback) result(x)
        real(xp), intent(in) :: p, f_p, d_p, r, f_r, d_r, fallback
        real(xp) :: h, s
        x = fallback
        if (d_p == 0.0_xp .or. d_r == 0.0_xp .or. (d_p > 0.0_xp .neqv. d_r > 0.0_xp)) &
            return
        if ((f_p > 0.0_xp .eqv. f_r > 0.0_xp) .or. (f_r - f_p > 0.0_xp .neqv. &
            (r - p)*d_r > 0.0_xp)) return
        h = f_r - f_p
        s = -f_p/h
        x = r + (2.0_xp*s + 1.0_xp)*(s - 1.0_xp)**2*(p - r) + &
            h*s*(s - 1.0_xp)*((s - 1.0_xp)/d_p + s/d_r)
        if (.not. (x > min(p, r) .and. x < max(p, r))) x = fallback
    end function inverse_hermite

    !> The root in (p, r) of f(r) + d t + c t^2 (t = x - r) through f(p) = f_p, f(r) = f_r
    !! and f'(r) = d; huge if there is none.
    pure real(xp) function quadratic_root(p, f_p, r, f_r, d) result(x)
        real(xp), intent(in) :: p, f_p, r, f_r, d
        real(xp) :: c, disc, q, t(2)
        x = huge(1.0_xp)
        c = (f_p - f_r + d*(r - p))/(r - p)**2
        disc = d*d - 4.0_xp*c*f_r
        if (.not. disc >= 0.0_xp) return
        q = -0.5_xp*(d + sign(sqrt(disc), d))
        if (q == 0.0_xp) return
        t = [f_r/q, merge(q/c, huge(1.0_xp), c /= 0.0_xp)]
        if (r + t(1) > min(p, r) .and. r + t(1) < max(p, r)) then
            x = r + t(1)
        else if (r + t(2) > min(p, r) .and. r + t(2) < max(p, r)) then
            x = r + t(2)
        end if
    end function quadratic_root

    !> The rounding level of the early phase's residual f: Upsilon to about 1e-15
    !! (rough) or 1e-18 of itself; in form 2 divided by limit - Upsilon.
    pure function residual_noise(prob, f, rough) result(noise)
        type(endpoint_problem), intent(in) :: prob
        real(xp), intent(in) :: f
        logical, intent(in) :: rough
        real(xp) :: noise
        noise = merge(1.0e-15_xp, 1.0e-18_xp, rough)
        select case (prob%form)
        case (0)
            noise = noise*real(prob%psi, xp)
        case (2)
            noise = noise*real(prob%limit/(prob%limit - prob%psi), xp)*exp(-f)
        end select
    end function residual_noise

    !> The bracket [a, b] (f(a), f(b) of opposite signs) after f(xk) = fk: xk replaces
    !! b, and a the old b when the signs say so; otherwise f(a) is scaled down
    !! (Anderson-Bjorck).
    pure subroutine keep_bracket(xk, fk, a, fa, b, fb)
        real(xp), intent(in) :: xk, fk
        real(xp), intent(inout) :: a, fa, b, fb
        real(xp) :: m
        if ((fk > 0.0_xp) .eqv. (fb > 0.0_xp)) then
            m = 1.0_xp - fk/fb
            fa = fa*merge(m, 0.5_xp, m > 0.0_xp)
        else
            a = b
            fa = fb
        end if
        b = xk
        fb = fk
    end subroutine keep_bracket

    !> Certified Newton steps (`final_step`) from the early phase's root x: a step not
    !! certified (the root not close enough for the bounds) is taken and the next one
    !! certified (usually; next to the edge of the sector the early root is poorer and
    !! Newton takes up to 4 steps). Not `done`: x and slope for secant steps.
    pure subroutine final_steps(model, prob, x, lo, hi, curvature, solution, done, slope)
        type(central_force_model), intent(in) :: model
        type(endpoint_problem), intent(in) :: prob
        real(qp), intent(inout) :: x
        real(qp), intent(in) :: lo, hi, curvature
        type(endpoint_solution), intent(inout) :: solution
        logical, intent(out) :: done
        real(qp), intent(out) :: slope
        real(qp) :: x_next
        integer :: attempt
        do attempt = 1, 4
            call final_step(model, prob, x, lo, hi, curvature, solution, done, x_next, slope)
            if (done) return
            if (x_next == x) exit
            x = x_next
        end do
    end subroutine final_steps

    !> The bracket [lo, hi] and its residuals in hardware precision.
    pure subroutine first_bracket(lo, f_lo, hi, f_hi, a, fa, b, fb)
        real(qp), intent(in) :: lo, hi
        real(real64), intent(in) :: f_lo, f_hi
        real(xp), intent(out) :: a, fa, b, fb
        a = real(lo, xp)
        b = real(hi, xp)
        fa = real(f_lo, xp)
        fb = real(f_hi, xp)
    end subroutine first_bracket

    !> One certified Newton step on the full rules from the early phase's root x0 (in the
    !! quad phase's unknown, u or R): Upsilon, s, t at x0 with d Upsilon/dx and ds/dx in
    !! hardware precision; accepted (`done`) only if the step's own error (curvature dx^2
    !! and the slope's error times dx) is below 1e-35 of the unknown and the slope of s
    !! moves s by less than a rounding (where only the bound of the slopes' endpoint terms
    !! in hardware precision stands in the way, those terms from binary128 and the step
    !! again: `sharp_jump`); then s is corrected along its slope and t by
    !! Hamilton-Jacobi (t(x) = t(x0) + K (psi - Upsilon(x0))). Otherwise x_next, slope_next
    !! (the Newton point and the slope) for the secant steps of `quad_phase`.
    !! With `previous` (next to the sector's edge, the unknown R: `edge_steps`) the step is
    !! Newton's on F = log((limit - Upsilon)/(limit - psi)) in y = log R (`edge_newton`),
    !! its curvature measured against the point `previous`; x0 itself is accepted where
    !! |Upsilon - psi| is within two roundings of psi (R-bar's conditioning: the step is then
    !! not resolved); `log_form` returns F and F' at x0.
    pure subroutine final_step(model, prob, x0, lo, hi, curvature, solution, done, x_next, &
                               slope_next, previous, log_form)
        type(central_force_model), intent(in) :: model
        type(endpoint_problem), intent(in) :: prob
        real(qp), intent(in) :: x0, lo, hi, curvature
        type(endpoint_solution), intent(inout) :: solution
        logical, intent(out) :: done
        real(qp), intent(out) :: x_next, slope_next
        real(qp), intent(in), optional :: previous(2)   !! y = log R and F'(y) before x0
        real(qp), intent(out), optional :: log_form(2)  !! F, F' at x0 (F = -huge: none)
        type(arch_setup) :: a
        real(xp) :: slopes(4), parts(4)
        real(qp) :: d, angle, s, t, f, lambda_slope, dx, x, floor, curve, error, noise
        integer :: pass
        logical :: edge
        done = .false.
        x_next = x0
        slope_next = 0.0_qp
        if (present(log_form)) log_form = [-huge(1.0_qp), 0.0_qp]
        a = setup_at(model, prob, x0)
        if (prob%use_u) then
            d = x0*x0
            lambda_slope = 2.0_qp*x0/a%big_r
            floor = 1.0e-3_qp*(hi - lo)
            curve = merge(2.0_qp*curvature, 10.0_qp/(hi - lo), curvature > 0.0_qp)
        else
            ! the unknown R: the step in y = log R (dx below), taken as R exp(dy)
            d = prob%rho - a%big_r
            lambda_slope = -1.0_qp
            floor = 1.0_qp
            curve = merge(2.0_qp*curvature, 10.0_qp, curvature > 0.0_qp)
        end if
        call arch_values(model, a, d, prob%one_minus_rho, prob%second, prob%fall_rho, &
                         angle, s, t, slopes, prob%psi, parts)
        solution%steps = solution%steps + 1
        f = angle - prob%psi
        do pass = 1, 2
            slope_next = real(slopes(1), qp)*lambda_slope
            if (.not. (ieee_is_finite(slope_next) .and. slope_next /= 0.0_qp)) return
            dx = -f/slope_next
            noise = 0.0_qp
            edge = present(previous) .and. present(log_form) .and. .not. prob%use_u
            if (edge) then
                call edge_newton(prob, x0, angle, slope_next, previous, dx, curve, noise, &
                                 log_form)
                if (abs(f) <= 2.0_qp*eps_qp*prob%psi) then
                    ! x0 is R-bar as far as Upsilon's rounding places it
                    dx = 0.0_qp
                    curve = 0.0_qp
                    noise = 0.0_qp
                else if (log_form(2) == 0.0_qp) then
                    return
                end if
            end if
            if (prob%use_u) then
                x = x0 + dx
            else
                ! (Upsilon's curvature in log R is about 1/Lambda next to the sector's edge,
                ! in R about 1/R: the Newton step in log R errs far less)
                x = log_step(x0, dx)
            end if
            if (.not. (x > lo .and. x < hi)) then
                if (prob%use_u .and. .not. prob%second) &
                    x_next = ratio_form_point(prob, x0, angle, slope_next, lo, hi, x0)
                return
            end if
            x_next = x
            error = curve*dx*dx + abs(dx)*(real(slopes(3)/abs(slopes(1)), qp) + noise)
            if (.not. prob%use_u) slope_next = slope_next/x0
            ! not certified, but within the bounds without the endpoint's terms g, h in
            ! hardware precision (`arch_values`): those from binary128 (`sharp_jump`, one
            ! node of the 25-40 of an evaluation; the second certified step it saves is 30%
            ! of a solve), and the step again
            if (pass == 2 .or. (certified(error) .and. moves_s(slopes(4)))) exit
            if (.not. (certified(curve*dx*dx + &
                                 abs(dx)*(real(parts(3)/abs(slopes(1)), qp) + noise)) .and. &
                       moves_s(parts(4)))) exit
            call sharp_jump(model, a, d, parts, slopes)
        end do
        if (.not. certified(error)) then
            ! not certified: next to the sector's edge the next point by Newton on
            ! log(limit - Upsilon), nearly linear in log R there (`log_form_point`)
            if (.not. prob%use_u .and. prob%form == 2 .and. .not. edge) &
                x_next = log_form_point(prob, x0, angle, slope_next*x0, lo, hi, x)
            ! first half-arch: by Newton on log(Upsilon/psi) in log u (B next to the start,
            ! rho -> 1, tiny psi: Upsilon ~ (1 - rho)^(3/2)/u, Newton on Upsilon from
            ! below only doubles u)
            if (prob%use_u .and. .not. prob%second) &
                x_next = ratio_form_point(prob, x0, angle, slope_next, lo, hi, x)
            return
        end if
        if (.not. moves_s(slopes(4))) return
        ! (next to the edge the step in log R may be large: s along its slope errs by
        ! |s''| dx^2/2, s - s(R = 0) ~ R, |s''| about |s'| in log R)
        if (edge .and. .not. dx*dx*abs(real(slopes(2), qp)) <= 0.25_qp*eps_qp*abs(s)) return
        solution%arclength = s + real(slopes(2), qp)*lambda_slope*dx
        solution%time = t - model%law%conserved(a%c)*f
        if (prob%use_u) then
            solution%apse_radius = prob%rho - x*x
            solution%apse_gap = x*x
        else
            solution%apse_radius = x
            solution%apse_gap = prob%rho - x
        end if
        solution%has_apse_radius = .true.
        solution%has_arclength = .true.
        solution%has_time = .true.
        solution%status = status_ok
        done = .true.
    contains
        !> The step's error bound below 1e-35 of the unknown (R: relative), or, for the
        !! unknown R (below rho/2), moving Upsilon by less than 1e-35 psi (within the
        !! rounding of psi: R-bar's conditioning, next to the edge of the sector) and s
        !! by less than 1e-35 of itself.
        pure logical function certified(bound)
            real(qp), intent(in) :: bound
            certified = bound <= 1.0e-35_qp*max(abs(x), floor) .or. (.not. prob%use_u .and. &
                        bound*abs(slope_next*x0) <= 1.0e-35_qp*prob%psi .and. &
                        bound*abs(real(slopes(2), qp)*lambda_slope) <= 1.0e-35_qp*abs(s))
        end function certified

        !> The error of s's slope (at most `error_bound`) times the step below a rounding
        !! of s.
        pure logical function moves_s(error_bound)
            real(xp), intent(in) :: error_bound
            moves_s = abs(dx*lambda_slope*real(error_bound, qp)) <= eps_qp*abs(s)
        end function moves_s
    end subroutine final_step

    !> Newton's step dy on F = log((limit - Upsilon)/(limit - psi)) in y = log R at x0
    !! (Upsilon = angle, d Upsilon/dy = upsilon_slope), F nearly linear in y next to the
    !! sector's edge; curve twice |F''/(2F')| measured against `previous` (y, F'(y)), 10
    !! where not measured; noise the relative error of F' from the rounding of limit -
    !! Upsilon; form F, F' at x0 (F' = 0 where limit - Upsilon is not positive: no step).
    pure subroutine edge_newton(prob, x0, angle, upsilon_slope, previous, dy, curve, &
                                noise, form)
        type(endpoint_problem), intent(in) :: prob
        real(qp), intent(in) :: x0, angle, upsilon_slope, previous(2)
        real(qp), intent(out) :: dy, curve, noise, form(2)
        real(qp) :: deficit, y0
        dy = 0.0_qp
        curve = 10.0_qp
        noise = 0.0_qp
        form = [-huge(1.0_qp), 0.0_qp]
        deficit = prob%limit - angle
        if (.not. deficit > 0.0_qp) return
        y0 = log(x0)
        form = [log(deficit/(prob%limit - prob%psi)), -upsilon_slope/deficit]
        if (.not. (form(2) > 0.0_qp .and. ieee_is_finite(form(2)))) then
            form(2) = 0.0_qp
            return
        end if
        dy = -form(1)/form(2)
        noise = 4.0_qp*eps_qp*prob%psi/deficit
        if (previous(2) > 0.0_qp .and. previous(1) /= y0) &
            curve = (abs(form(2) - previous(2)) + 1.0e-18_qp*form(2))/ &
                    (abs(y0 - previous(1))*form(2))
    end subroutine edge_newton

    !> Next to the sector's edge (second half-arch, R-bar < rho/2, limit - psi below
    !! edge_gap limit): limit - Upsilon = D ~ C R^(n-1) (power laws; and (R/rho)^((n+1)/2)
    !! terms), F = log(D/(limit - psi)) is nearly linear and convex in y = log R. The early
    !! phase solved D = early_gap (resolved in hardware precision) at x = R1 with F'(y1) =
    !! early_slope; from there the root of F's tangent (right of R-bar by the convexity,
    !! below lowest_log_r only if R-bar is below the binary128 range: `below_range`), but
    !! the first full evaluation at the root of the model of `edge_model_point` from R1
    !! where it applies (the tangent's root may be far from R-bar: F' is (n + 1)/2 where
    !! P dominates, n - 1 where A does), then Newton steps on F on the full rules
    !! (`final_step` with `previous`; far from the root the next point from
    !! `edge_model_point`), kept inside the bracket [y_lo, y_hi] of F's signs (y_hi = log
    !! hi at first) by bisection. Not `done`: x and the slope d Upsilon/dR for the secant
    !! steps, [lo, hi] the bracket in R.
    pure subroutine edge_steps(model, prob, early_gap, early_slope, x, lo, hi, solution, &
                               done, slope)
        type(central_force_model), intent(in) :: model
        type(endpoint_problem), intent(in) :: prob
        real(qp), intent(in) :: early_gap, early_slope
        real(qp), intent(inout) :: x, lo, hi
        type(endpoint_solution), intent(inout) :: solution
        logical, intent(out) :: done
        real(qp), intent(out) :: slope
        real(qp) :: y, y_lo, y_hi, previous(2), form(2), x_next, y_next
        integer :: attempt
        done = .false.
        slope = 0.0_qp
        ! (the bracket's upper end hi = rho/2, not the early root: limit - psi may equal
        ! early_gap to its rounding)
        y_hi = log(hi)
        y_lo = lowest_log_r
        previous = [log(x), early_slope]
        form = [log(early_gap/(prob%limit - prob%psi)), early_slope]
        y = log(x) - form(1)/early_slope
        if (.not. (early_slope > 0.0_qp .and. ieee_is_finite(y))) return
        if (.not. y > lowest_log_r) then
            call below_range(model, prob, solution)
            done = .true.
            return
        end if
        ! (the early root's limit - Upsilon is resolved to about 1e-9 of itself, its A to
        ! 1e-9/share: with A below 1e-3 of it the model is no better than the tangent)
        y_next = y
        call edge_model_point(model, prob, previous(1), form, y_next, solution%steps, &
                              1.0e-3_qp)
        if (y_next > lowest_log_r .and. y_next < y_hi) y = y_next
        do attempt = 1, max_edge_steps
            if (.not. y > lowest_log_r) then
                call below_range(model, prob, solution)
                done = .true.
                return
            end if
            x = exp(y)
            lo = exp(y_lo)
            hi = exp(y_hi)
            call final_step(model, prob, x, lo, hi, 0.0_qp, solution, done, x_next, slope, &
                            previous, form)
            if (done) return
            if (form(1) > 0.0_qp) then
                y_hi = y
            else
                y_lo = y
            end if
            if (form(2) > 0.0_qp) previous = [y, form(2)]
            y_next = y
            if (x_next /= x .and. x_next > 0.0_qp) y_next = log(x_next)
            if (form(2) > 0.0_qp .and. abs(form(1)) > 1.0e-8_qp) &
                call edge_model_point(model, prob, y, form, y_next, solution%steps)
            if (y_next /= y .and. y_next > y_lo .and. y_next < y_hi) then
                y = y_next
            else
                y = 0.5_qp*(y_lo + y_hi)
            end if
        end do
        lo = exp(y_lo)
        hi = exp(y_hi)
    end subroutine edge_steps

    !> Next to the edge, after a full evaluation at y0 = log R (F, F' = form) not close to
    !! the root: limit - Upsilon = A + P with P = Theta(rho, R) (a first half-arch's angle,
    !! in hardware precision without cancellation) and A = 2 (lim Theta - Theta(R,R))
    !! known at y0 as (limit - Upsilon) - P and taken as A0 exp(a (y - y0)) (power laws:
    !! C R^(n-1)); the root of log((A + P)/(limit - psi)) on that model by Newton steps in
    !! hardware precision (`steps` counted; P evaluated again at each iterate until its
    !! estimate there, P nearly exponential in y, is below 1e-20 A: then the root of A
    !! alone): y_next = log R there (unchanged where the model does not apply). Where the
    !! two terms cross between y0 and R-bar (rho small, n < 3) the Newton point of F
    !! alone would need several more full evaluations; the steps in y may be large (100
    !! and more: F' is n - 1 where A dominates). Also from the early phase's root (F, F'
    !! of the hardware-precision evaluation: `edge_steps`), where A is resolved only if
    !! it is at least `share` of limit - Upsilon (default 1e-6), and P by the rough rules
    !! (12 digits: limit - Upsilon there is resolved to about 1e-9 of itself).
    pure subroutine edge_model_point(model, prob, y0, form, y_next, steps, share)
        type(central_force_model), intent(in) :: model
        type(endpoint_problem), intent(in) :: prob
        real(qp), intent(in) :: y0, form(2)
        real(qp), intent(inout) :: y_next
        integer, intent(inout) :: steps
        real(qp), intent(in), optional :: share
        type(endpoint_problem) :: part
        real(qp) :: gap, d0, p, p_slope, a0, rate, y, big_a, g, dy, least
        real(xp) :: f, slope
        integer :: k
        least = 1.0e-6_qp
        if (present(share)) least = share
        gap = prob%limit - prob%psi
        d0 = gap*exp(form(1))
        part = prob
        part%second = .false.
        part%use_u = .false.
        part%use_r = .false.
        part%form = 1
        ! (a tiny psi: the angle hint that takes theta_xp straight to int_lambda_r^Lambda)
        part%psi = 1.0e-300_qp
        y = y0
        do k = 1, 8
            call residual_xp(model, part, real(y, xp), present(share), f, slope)
            steps = steps + 1
            p = exp(real(f, qp) + log(part%psi))
            p_slope = real(slope, qp)
            if (k == 1) then
                a0 = d0 - p
                ! (P alone, or A not resolved beside it: the Newton point of F stands)
                if (.not. (a0 > least*d0 .and. p > 0.0_qp)) return
                rate = (d0*form(2) - p*p_slope)/a0
                if (.not. (rate > 0.0_qp .and. ieee_is_finite(rate))) return
            end if
            big_a = a0*exp(rate*(y - y0))
            g = log((big_a + p)/gap)
            dy = -g*(big_a + p)/(rate*big_a + p_slope*p)
            if (.not. (ieee_is_finite(dy) .and. abs(dy) < -lowest_log_r)) return
            y = y + dy
            if (abs(dy) <= 1.0e-12_qp*max(1.0_qp, abs(y))) exit
            if (p*exp(p_slope*dy) <= 1.0e-20_qp*a0*exp(rate*(y - y0))) then
                y = y0 + log(gap/a0)/rate
                exit
            end if
        end do
        y_next = y
    end subroutine edge_model_point

    !> The Newton point in u from x0 (the unknown u, first half-arch) on
    !! log(Upsilon/psi) in log u, Upsilon = angle at x0 with d Upsilon/du = upsilon_slope;
    !! `fallback` where it is not defined or leaves (lo, hi). Only a next iterate.
    pure function ratio_form_point(prob, x0, angle, upsilon_slope, lo, hi, fallback) &
        result(x)
        type(endpoint_problem), intent(in) :: prob
        real(qp), intent(in) :: x0, angle, upsilon_slope, lo, hi, fallback
        real(qp) :: x
        real(qp) :: step
        x = fallback
        if (.not. (angle > 0.0_qp .and. x0 > 0.0_qp .and. upsilon_slope /= 0.0_qp)) return
        step = -log(angle/prob%psi)*angle/(x0*upsilon_slope)
        if (.not. (ieee_is_finite(step) .and. abs(step) < 100.0_qp)) return
        step = x0*exp(step)
        if (step > lo .and. step < hi) x = step
    end function ratio_form_point

    !> The Newton point in R from x0 (the unknown R, second half-arch) on
    !! F = log((limit - Upsilon)/(limit - psi)) in y = log R, Upsilon = angle at x0 with
    !! d Upsilon/dy = upsilon_slope: next to the sector's edge limit - Upsilon ~ C R^(n-1)
    !! (power laws), F is nearly linear in y and its Newton step far more accurate than
    !! Upsilon's (whose curvature in y is about n - 1); `fallback` where F is not defined
    !! or the point leaves (lo, hi). Only a next iterate: the certified step is
    !! `final_step`'s own.
    pure function log_form_point(prob, x0, angle, upsilon_slope, lo, hi, fallback) &
        result(x)
        type(endpoint_problem), intent(in) :: prob
        real(qp), intent(in) :: x0, angle, upsilon_slope, lo, hi, fallback
        real(qp) :: x
        real(qp) :: deficit, dy
        x = fallback
        deficit = prob%limit - angle
        if (.not. (deficit > 0.0_qp .and. prob%limit - prob%psi > 0.0_qp .and. &
                   upsilon_slope /= 0.0_qp)) return
        dy = log(deficit/(prob%limit - prob%psi))*deficit/upsilon_slope
        if (.not. ieee_is_finite(dy)) return
        dy = log_step(x0, dy)
        if (dy > lo .and. dy < hi) x = dy
    end function log_form_point

    !> x0 exp(dy), a step dy in log x: x0 + x0 expm1(dy) (exact to a rounding of x0 for
    !! small steps), but x0 exp(dy) for dy < -1/2, where 1 + expm1(dy) keeps only the
    !! digits of exp(dy) above eps (below dy = -78 none: x0 + x0 expm1(dy) = 0, and
    !! next to the sector's edge the Newton step in log R is often -100 or more; expm1's
    !! rounding (`fast_expm1`, within 0.6 ulp) is below an ulp of x0 expm1(dy), far below
    !! x0's rounding)
    elemental function log_step(x0, dy) result(x)
        real(qp), intent(in) :: x0, dy
        real(qp) :: x
        if (dy < -0.5_qp) then
            x = x0*exp(dy)
        else
            x = x0 + x0*fast_expm1(dy)
        end if
    end function log_step

    !> The quad-precision phase from the double phase's root x0 and slope (of the
    !! double phase's form): Newton, then secant steps on Upsilon - psi, each a full
    !! evaluation; the last step taken without one (see the module comment).
    pure subroutine quad_phase(model, prob, x_start, slope64, lo, hi, solution)
        type(central_force_model), intent(in) :: model
        type(endpoint_problem), intent(in) :: prob
        real(qp), intent(in) :: x_start, lo, hi
        real(real64), intent(in) :: slope64
        type(endpoint_solution), intent(inout) :: solution
        type(arch_setup) :: a
        real(qp) :: x(3), f(2), s(2), t(2), slope, step, k_mid, scale, floor
        integer :: iteration
        logical :: stalled
        select case (prob%form)
        case (1)
            slope = prob%psi*real(slope64, qp)
        case (2)
            slope = -(prob%limit - prob%psi)*real(slope64, qp)
        case default
            slope = real(slope64, qp)
        end select
        scale = max(abs(hi - lo), 1.0e-300_qp)
        floor = 1.0e-3_qp*scale
        stalled = .false.
        x(1) = x_start
        call evaluate_full(model, prob, x(1), f(1), s(1), t(1))
        x(2) = clip(x(1) - f(1)/slope)
        do iteration = 1, 12
            call evaluate_full(model, prob, x(2), f(2), s(2), t(2))
            if (f(2) == f(1) .or. x(2) == x(1)) then
                ! no progress: a root only if f is at its rounding
                stalled = abs(f(2)) > 8.0_qp*eps_qp*prob%psi
                if (stalled) exit
                step = 0.0_qp
            else
                step = -f(2)*(x(2) - x(1))/(f(2) - f(1))
            end if
            x(3) = clip(x(2) + step)
            ! predicted error of x(3): about |step| |x(3) - x(1)| |f''/2f'|, with
            ! |f''/2f'| taken as 10/scale (u; R: 10/R, Upsilon varies on the scale R)
            if (prob%use_r) then
                scale = x(2)
                floor = tiny(1.0_qp)
            end if
            if (abs(step) <= 1.0e-17_qp*max(abs(x(2)), floor) .and. &
                abs(step)*abs(x(3) - x(1))*10.0_qp/scale <= &
                1.0e-35_qp*max(abs(x(3)), floor)) exit
            x(1) = x(2)
            f(1) = f(2)
            s(1) = s(2)
            t(1) = t(2)
            x(2) = x(3)
        end do
        solution%steps = solution%steps + iteration + 1
        if (iteration > 12 .or. stalled) then
            solution%status = status_no_convergence
            return
        end if
        ! s along the secant, t by Hamilton-Jacobi: t(x3) = t(x2) + K (psi - Upsilon(x2))
        a = setup_at(model, prob, 0.5_qp*(x(2) + x(3)))
        k_mid = model%law%conserved(a%c)
        a = setup_at(model, prob, x(3))
        if (x(2) /= x(1)) then
            solution%arclength = s(2) + (s(2) - s(1))/(x(2) - x(1))*(x(3) - x(2))
        else
            solution%arclength = s(2)
        end if
        solution%time = t(2) - k_mid*f(2)
        solution%apse_radius = a%big_r
        solution%apse_gap = prob%rho - a%big_r
        if (prob%use_u) solution%apse_gap = x(3)*x(3)
        solution%has_apse_radius = .true.
        solution%has_arclength = .true.
        solution%has_time = .true.
        solution%status = status_ok
    contains
        pure function clip(x_new) result(y)
            real(qp), intent(in) :: x_new
            real(qp) :: y
            y = x_new
            if (.not. (ieee_is_finite(y) .and. y > lo .and. y < hi)) &
                y = max(min(x_new, hi), lo)
        end function clip
    end subroutine quad_phase

    !> Upsilon - psi, s and t at the unknown x, on the full rules.
    pure subroutine evaluate_full(model, prob, x, f, s, t)
        type(central_force_model), intent(in) :: model
        type(endpoint_problem), intent(in) :: prob
        real(qp), intent(in) :: x
        real(qp), intent(out) :: f, s, t
        type(arch_setup) :: a
        real(qp) :: d, angle
        a = setup_at(model, prob, x)
        if (prob%use_u) then
            d = x*x
        else
            d = prob%rho - a%big_r
        end if
        call arch_values(model, a, d, prob%one_minus_rho, prob%second, prob%fall_rho, &
                         angle, s, t, expected=prob%psi)
        f = angle - prob%psi
    end subroutine evaluate_full

    !> The solution when R-bar is below the smallest binary128 number: R-bar = 0 and the
    !! limits s = (1 - rho) + 2 rho [second half-arch] and t = 2 t0(0) - t0(rho) (first
    !! half-arch: s = 1 - rho, t = t0(rho)).
    pure subroutine below_range(model, prob, solution)
        type(central_force_model), intent(in) :: model
        type(endpoint_problem), intent(in) :: prob
        type(endpoint_solution), intent(inout) :: solution
        real(qp) :: fall_rho, fall_0
        integer :: status
        call model%fall_time(prob%rho, fall_rho, status)
        if (prob%second) then
            call model%fall_time(0.0_qp, fall_0, status)
            solution%arclength = prob%one_minus_rho + 2.0_qp*prob%rho
            solution%time = 2.0_qp*fall_0 - fall_rho
        else
            solution%arclength = prob%one_minus_rho
            solution%time = fall_rho
        end if
        solution%apse_radius = 0.0_qp
        solution%apse_gap = prob%rho
        solution%has_apse_radius = .true.
        solution%has_arclength = .true.
        solution%has_time = .true.
        solution%status = status_ok
    end subroutine below_range

    !> The two-point problem for this law: the brachistochrone from A = (1, 0) to
    !! B = (rho, psi) (see the module comment). psi >= 2 lim Theta(R,R) is the sector of
    !! inaccessibility; t is then its greatest lower bound 2 t0(0) - t0(rho), attained
    !! (arch 'radial', through O) where the law lets a particle pass the centre.
    !! Statuses: status_ok; status_inaccessible; status_not_finite,
    !! status_rho_out_of_range, status_psi_out_of_range (bad endpoint);
    !! status_parameter_out_of_range (law outside its range, `speed_law%valid`);
    !! status_no_convergence (not seen on accessible endpoints; reported, not hidden).
    !! R-bar below the binary128 range (logarithmic law, psi within about 1e-4 of pi) is
    !! returned as 0 with s and t at their limits (`below_range`). Next to the sector's
    !! edge R-bar is as close as the rounding of Upsilon places it: |Upsilon(R-bar) - psi|
    !! within a few eps psi (`edge_steps`).
    pure function general_solve(self, rho, psi) result(solution)
        class(central_force_model), intent(in) :: self
        real(qp), intent(in) :: rho   !! endpoint radius, 0 < rho <= 1
        real(qp), intent(in) :: psi   !! endpoint angle, 0 <= psi <= pi
        type(endpoint_solution) :: solution
        type(endpoint_problem) :: prob, early
        real(qp) :: limit, apse_angle_rho, half, x, lo, hi, slope_q, curvature
        real(real64) :: f_lo, f_hi, slope, slope_hi
        logical :: below, hardware, done, near, edge

        solution%rho = rho
        solution%psi = psi
        solution%status = endpoint_status(rho, psi, region_inside)
        if (solution%status /= status_ok) return
        if (.not. self%law%valid()) then
            ! e.g. a power law beyond max_power_exponent
            solution%status = status_parameter_out_of_range
            return
        end if
        limit = self%law%apse_angle_limit()
        if (psi == 0.0_qp .or. psi >= 2.0_qp*limit) then
            call radial_or_beyond(self, rho, psi, limit, solution)
            return
        end if
        call start_problem(self, rho, psi, limit, prob, apse_angle_rho)
        solution%arch = merge(arch_complete, merge(arch_second, arch_first, prob%second), &
                              rho == 1.0_qp)
        if (abs(psi - apse_angle_rho) <= 2.0_qp*eps_qp*psi) then
            ! B at its apse to within two roundings of psi (R-bar = rho - u^2 with u of the
            ! order of that difference; for tiny rho Theta(rho,rho) is pi/(n+1) to far
            ! more than 34 digits, and the root would be sought next to u = 0)
            call at_the_apse(self, prob, solution)
            return
        end if
        half = 0.5_qp*rho
        hardware = self%law%has_terms_xp()
        ! psi within edge_gap of the sector's edge: the early phase (`early`) solves for
        ! limit - Upsilon = edge_gap limit, which it resolves (`edge_steps`)
        edge = hardware .and. prob%limit - psi < edge_gap*prob%limit
        early = prob
        if (edge) early%psi = prob%limit - edge_gap*prob%limit
        call open_bracket(self, early, apse_angle_rho, half, lo, hi, f_lo, f_hi, &
                          solution%steps, below, slope_hi)
        if (edge .and. early%use_u) then
            ! (R-bar above rho/2 after all: the endpoint as it is)
            edge = .false.
            early = prob
            call open_bracket(self, early, apse_angle_rho, half, lo, hi, f_lo, f_hi, &
                              solution%steps, below, slope_hi)
        end if
        prob%use_u = early%use_u
        prob%form = early%form
        if (below) then
            ! R-bar is below the binary128 range (the logarithmic law next to psi = pi):
            ! R-bar underflows to 0, and s, t equal their limits R -> 0 to far more
            ! than 34 digits (they differ from them by O(R) < 1e-4900)
            call below_range(self, prob, solution)
            return
        end if
        near = .false.
        if (hardware .and. prob%use_u .and. prob%rho < 1.0_qp) then
            ! B within 1e-16 of its apse angle (not at it): below what the early phase
            ! resolves; the root from the slope next to u = 0
            if (abs(apse_angle_rho - psi) <= 1.0e-16_qp*psi) &
                call apse_start(self, early, hi, f_lo, x, slope_q, near)
            if (near) then
                curvature = 0.0_qp
                solution%steps = solution%steps + 1
            end if
        end if
        if (near) then
            slope = real(slope_q, real64)
        else if (hardware) then
            call hardware_phase(self, early, lo, f_lo, hi, f_hi, x, slope_q, curvature, &
                                solution%steps, slope_hi)
            slope = real(slope_q, real64)
        else
            call double_phase(self, prob, lo, f_lo, hi, f_hi, x, slope, solution%steps)
        end if
        prob%fall_rho = fall_piece(self, 0.0_qp, prob%delta_rho)
        if (.not. prob%use_u) then
            ! the quad phase in R itself: y = log R resolves R only to eps |log R|
            prob%use_r = .true.
            ! (iterates, not results: `fast_exp`'s few ulps are far below their error)
            x = fast_exp(x)
            slope = slope/real(x, real64)
            lo = fast_exp(lo)
            hi = half
        end if
        if (edge) then
            call edge_steps(self, prob, prob%limit - early%psi, slope_q, x, lo, hi, &
                            solution, done, curvature)
            if (done) return
            slope = real(curvature, real64)
            prob%form = 0
        else if (hardware) then
            call final_steps(self, prob, x, lo, hi, curvature, solution, done, slope_q)
            if (done) return
            slope = real(slope_q, real64)
            prob%form = 0
        end if
        call quad_phase(self, prob, x, slope, lo, hi, solution)
    end function general_solve

    !> psi = 0 (radial fall) or psi at or beyond the sector 2 Theta(0,0): no
    !! brachistochrone (t is the bound 2 t(0) - t(rho)), except the straight path through
    !! the centre of a law that passes it. The status of a fall time that fails is kept.
    pure subroutine radial_or_beyond(self, rho, psi, limit, solution)
        type(central_force_model), intent(in) :: self
        real(qp), intent(in) :: rho, psi, limit
        type(endpoint_solution), intent(inout) :: solution
        real(qp) :: fall_rho, fall_0
        integer :: status
        call self%fall_time(rho, fall_rho, status)
        if (status /= status_ok) then
            solution%status = status
            return
        end if
        if (psi == 0.0_qp) then
            solution%arch = arch_radial
            solution%arclength = 1.0_qp - rho
            solution%time = fall_rho
            solution%has_apse_radius = .true.
            solution%has_arclength = .true.
        else
            call self%fall_time(0.0_qp, fall_0, status)
            if (status /= status_ok) then
                solution%status = status
                return
            end if
            solution%time = 2.0_qp*fall_0 - fall_rho
            if (self%law%passes_centre() .and. psi == 2.0_qp*limit) then
                solution%arch = arch_radial
                solution%arclength = 1.0_qp + rho
                solution%has_apse_radius = .true.
                solution%has_arclength = .true.
            else
                solution%arch = arch_inaccessible
                solution%status = status_inaccessible
            end if
        end if
        solution%has_time = .true.
    end subroutine radial_or_beyond

    !> The problem's data, and the half-arch of B: psi against Theta(rho, rho), in quad
    !! precision only when they are close.
    pure subroutine start_problem(self, rho, psi, limit, prob, apse_angle_rho)
        type(central_force_model), intent(in) :: self
        real(qp), intent(in) :: rho, psi, limit
        type(endpoint_problem), intent(out) :: prob
        real(qp), intent(out) :: apse_angle_rho    !! Theta(rho, rho) (0 when rho = 1)
        type(arch_setup) :: a
        real(qp) :: sums(3), whole(5)
        real(xp) :: whole_xp(2)
        real(real64) :: scaled, shift
        logical :: found
        prob%rho = rho
        prob%psi = psi
        prob%one_minus_rho = 1.0_qp - rho
        prob%delta_rho = minus_log(rho, prob%one_minus_rho)
        prob%limit = 2.0_qp*limit
        apse_angle_rho = 0.0_qp
        found = .false.
        if (rho < 1.0_qp) then
            ! the hardware-precision table first (no binary128 logarithm); the full
            ! table where psi is within 1e-12 of it (the half-arch, `at_the_apse`,
            ! `apse_start` need it to the last bits there)
            call whole_lookup_xp(self, real(prob%delta_rho, xp), whole_xp, found)
            apse_angle_rho = real(whole_xp(1), qp)
            if (.not. found .or. abs(apse_angle_rho - psi) <= 1.0e-12_qp*psi) then
                call whole_lookup(self, prob%delta_rho, whole, found, 1)
                apse_angle_rho = whole(1)
            end if
        end if
        if (rho < 1.0_qp .and. .not. found) then
            a = setup_arch(self, rho, prob%one_minus_rho, 0.0_qp, prob%delta_rho, &
                           .false., .true.)
            call theta64(self, a, scaled, shift)
            apse_angle_rho = real(scaled, qp)*exp(-real(shift, qp))
            if (abs(apse_angle_rho - psi) <= 1.0e-12_qp*psi) then
                sums = arch_integrals(self, a, fine_digits, .false.)
                apse_angle_rho = sums(1)
            end if
        end if
        prob%second = rho == 1.0_qp .or. psi > apse_angle_rho
    end subroutine start_problem

    !> B is the apse of its brachistochrone: R-bar = rho, s and t of the first half-arch.
    pure subroutine at_the_apse(self, prob, solution)
        type(central_force_model), intent(in) :: self
        type(endpoint_problem), intent(in) :: prob
        type(endpoint_solution), intent(inout) :: solution
        type(arch_setup) :: a
        real(qp) :: angle
        a = setup_arch(self, prob%rho, prob%one_minus_rho, 0.0_qp, prob%delta_rho, &
                       .false., .false.)
        call arch_values(self, a, 0.0_qp, prob%one_minus_rho, .false., &
                         fall_piece(self, 0.0_qp, prob%delta_rho), angle, &
                         solution%arclength, solution%time)
        solution%apse_radius = prob%rho
        solution%has_apse_radius = .true.
        solution%has_arclength = .true.
        solution%has_time = .true.
    end subroutine at_the_apse

    !> B next to its apse angle (|f_lo| = |Theta(rho,rho) - psi| below the early phase's
    !! resolution): Upsilon is linear in u next to u = 0 (the square-root end of the
    !! integrals), so the root is u0 = -f_lo/c with c from one hardware-precision residual
    !! at u1 = 1e-6 of the bracket (c to about 1e-6, u0 as well: the certified step's
    !! error ~ (1e-6 u0)^2/bracket is far below 1e-35 u0). `found` unless u0 is not
    !! within 1e-3 of the bracket [0, hi].
    pure subroutine apse_start(model, prob, hi, f_lo, x, slope, found)
        type(central_force_model), intent(in) :: model
        type(endpoint_problem), intent(in) :: prob
        real(qp), intent(in) :: hi
        real(real64), intent(in) :: f_lo
        real(qp), intent(out) :: x, slope
        logical, intent(out) :: found
        real(xp) :: u1, f1, d1, c
        u1 = 1.0e-6_xp*real(hi, xp)
        call residual_xp(model, prob, u1, .false., f1, d1)
        c = (f1 - real(f_lo, xp))/u1
        x = real(-real(f_lo, xp)/c, qp)
        slope = real(c, qp)
        found = x > 0.0_qp .and. x < 1.0e-3_qp*hi .and. ieee_is_finite(x)
    end subroutine apse_start

    !> Which part of (0, rho] holds the root (Upsilon at R = rho/2), its unknown and
    !! bracket: u = sqrt(rho - R) on [0, sqrt(rho/2)], or y = log R on [y_lo, log(rho/2)]
    !! with y_lo found by stepping down; `below` when R-bar is below the binary128 range.
    pure subroutine open_bracket(self, prob, apse_angle_rho, half, lo, hi, f_lo, f_hi, &
                                 steps, below, slope_hi)
        type(central_force_model), intent(in) :: self
        type(endpoint_problem), intent(inout) :: prob !! gets its unknown (use_u, form)
        real(qp), intent(in) :: apse_angle_rho, half
        real(qp), intent(out) :: lo, hi               !! the bracket
        real(real64), intent(out) :: f_lo, f_hi       !! residuals at its ends
        integer, intent(out) :: steps                 !! evaluations made
        logical, intent(out) :: below                 !! R-bar underflows
        !> the residual's slope d f/du at hi (the unknown u, laws with hardware terms;
        !! else 0)
        real(real64), intent(out) :: slope_hi
        real(real64) :: f_half, theta_half, scaled, shift, upsilon_slope, lambda_slope
        real(qp) :: top, next
        real(real64) :: lo_slope, tangent
        integer :: probe
        below = .false.
        prob%use_u = .true.
        upsilon_slope = 0.0_real64
        lambda_slope = 0.0_real64
        slope_hi = 0.0_real64
        prob%slope_lo = 0.0_real64
        if (self%law%has_terms_xp()) then
            ! as a rough early evaluation (with the tables), on bracket_digits rules: the
            ! branch needs only the sign of Upsilon - psi, the first iterate no more
            ! digits (again on the rough rules where Upsilon is within 1e-6 of psi)
            call rough_half(bracket_digits, theta_half, lambda_slope, upsilon_slope)
            if (abs(theta_half - real(prob%psi, real64)) <= &
                1.0e-6_real64*real(prob%psi, real64)) &
                call rough_half(rough_digits, theta_half, lambda_slope, upsilon_slope)
        else
            call theta64(self, setup_at64(self, prob, sqrt(prob%rho - half)), scaled, shift)
            theta_half = scaled*exp(-shift)
        end if
        f_half = theta_half - real(prob%psi, real64)
        steps = 1
        if ((f_half >= 0.0_real64) .neqv. prob%second) then
            ! R-bar < rho/2: unknown y = log R on [y_lo, log(rho/2)]
            prob%use_u = .false.
            prob%form = merge(2, 1, prob%second)
            hi = fast_log(half)
            ! (Upsilon at R = rho/2 as above: the sign the branch was chosen by)
            f_hi = form_of(real(theta_half, qp))
            ! (its slope in y: d Lambda/dy = -1)
            if (prob%form == 2) then
                slope_hi = lambda_slope/(real(prob%limit, real64) - theta_half)
            else
                slope_hi = -lambda_slope/theta_half
            end if
            lo = hi
            top = hi
            next = hi - 8.0_qp
            if (slope_hi > 0.0_real64 .and. f_hi > 0.0_real64) then
                ! the first probe just past the root of f's tangent at R = rho/2 (f nearly
                ! linear in y: log Upsilon ~ (n+1)/2 y for steep laws), 8 below at most:
                ! a bracket about the root for the first iterate, or, where f > 0 there
                ! still, a closer upper end (below)
                tangent = real(hi, real64) - f_hi/slope_hi
                if (ieee_is_finite(tangent)) next = max(next, real(tangent - 0.3_real64* &
                    (real(hi, real64) - tangent) - 1.0e-3_real64, qp))
            end if
            do probe = 1, 40
                lo = max(lowest_log_r, next)
                call bracket_residual(lo, f_lo, lo_slope)
                steps = steps + 1
                if (f_lo < 0.0_real64 .or. lo == lowest_log_r) exit
                next = top - 4.0_qp*2.0_qp**(probe + 1)
                if (lo_slope > 0.0_real64) then
                    ! second half-arch: log((limit - Upsilon)/(limit - psi)) is nearly
                    ! linear in y next to the sector's edge (power laws: limit - Upsilon
                    ! ~ C R^(n-1), R-bar down to 1e-1000 and below): on past its tangent's
                    ! root at this probe where that is further; either half-arch: the
                    ! probe the bracket's upper end where f > 0 is sure (well above the
                    ! rough rounding)
                    tangent = real(lo, real64) - f_lo/lo_slope
                    if (ieee_is_finite(tangent) .and. prob%form == 2) next = min(next, &
                        real(tangent - 2.0_real64 - 0.25_real64*(real(lo, real64) - tangent), qp))
                    if (real(f_lo, xp) > 4.0_xp*residual_noise(prob, real(f_lo, xp), &
                                                               .true.)) then
                        hi = lo
                        f_hi = f_lo
                        slope_hi = lo_slope
                    end if
                end if
            end do
            below = .not. f_lo < 0.0_real64
            prob%slope_lo = lo_slope
            if (lo == hi .or. .not. (ieee_is_finite(slope_hi) .and. &
                                     ieee_is_finite(lo_slope))) then
                slope_hi = 0.0_real64
                prob%slope_lo = 0.0_real64
            end if
        else
            ! R-bar in [rho/2, rho]: unknown u = sqrt(rho - R) on [0, sqrt(rho/2)], in
            ! the forms that follow steep laws (Theta(r,R) ~ (R/r)^((n+1)/2) on the first
            ! half-arch, limit - Upsilon ~ R^(n-1) on the second): log(Upsilon/psi),
            ! log((limit - Upsilon)/(limit - psi)) (Theta(1,1) = 0)
            prob%form = 0
            if (pi/self%sigma_apse > steep_decay) prob%form = merge(2, 1, prob%second)
            lo = 0.0_qp
            hi = fast_sqrt(prob%rho - half)
            f_lo = form_of(apse_angle_rho)
            f_hi = form_of(real(theta_half, qp))
            select case (prob%form)
            case (1)
                slope_hi = upsilon_slope/theta_half
            case (2)
                slope_hi = -upsilon_slope/(real(prob%limit, real64) - theta_half)
            case default
                slope_hi = upsilon_slope
            end select
        end if
    contains
        !> Theta at R = rho/2 and its slopes in Lambda and in u on rules for `digits`
        !! digits (`theta_xp`, rough).
        pure subroutine rough_half(digits, theta, d_lambda, d_u)
            real(qp), intent(in) :: digits
            real(real64), intent(out) :: theta, d_lambda, d_u
            real(xp) :: theta_xp_half, slope_xp, shift_xp
            call theta_xp(self, setup_at64(self, prob, fast_sqrt(prob%rho - half)), &
                          .true., theta_xp_half, slope_xp, shift_xp, digits)
            if (shift_xp /= 0.0_xp) then
                theta_xp_half = theta_xp_half*exp(-shift_xp)
                slope_xp = slope_xp*exp(-shift_xp)
            end if
            theta = real(theta_xp_half, real64)
            ! d Upsilon/du = d Upsilon/d Lambda 2u/R at u = sqrt(rho - half), R = half
            d_lambda = real(slope_xp, real64)
            d_u = d_lambda*real(2.0_qp*fast_sqrt(prob%rho - half)/half, real64)
        end subroutine rough_half

        !> The residual f at y = log R and (laws with hardware terms, else 0) its slope:
        !! a rough early evaluation (with the tables) for laws with hardware terms, else
        !! `residual64`.
        pure subroutine bracket_residual(y, f, y_slope)
            real(qp), intent(in) :: y
            real(real64), intent(out) :: f, y_slope
            real(xp) :: f_xp, slope
            y_slope = 0.0_real64
            if (self%law%has_terms_xp()) then
                call residual_xp(self, prob, real(y, xp), .true., f_xp, slope)
                f = real(f_xp, real64)
                y_slope = real(slope, real64)
            else
                f = residual64(self, prob, y)
            end if
        end subroutine bracket_residual

        !> Upsilon - psi in the problem's form (the logarithms of ratios formed in
        !! binary128, in hardware precision: `log_of_ratio`).
        pure real(real64) function form_of(upsilon)
            real(qp), intent(in) :: upsilon
            select case (prob%form)
            case (1)
                form_of = real(log_of_ratio(upsilon/prob%psi), real64)
            case (2)
                form_of = real(log_of_ratio((prob%limit - upsilon)/(prob%limit - prob%psi)), &
                               real64)
            case default
                form_of = real(upsilon - prob%psi, real64)
            end select
        end function form_of
    end subroutine open_bracket

end module brachistochrone_central_force
