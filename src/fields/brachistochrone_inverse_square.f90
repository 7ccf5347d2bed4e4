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
!! c and s are rational in the node (`sweep_values`: 23 binary128 operations a node).
!!
!! The whole half-arch (lambda in [0, pi/2]: Theta(R,R), eq. 66, and the S and T
!! corrections) depends on R alone. Divided by 1-R (Theta, S) or sqrt(1-R) (T) these are
!! analytic on a neighbourhood of [0, 1]: the nearest singularity is at R = 3/2, where q
!! vanishes at lambda = 0 (another at R = -3, where q's zeros in cos^2 lambda meet). They
!! are tabulated as piecewise Chebyshev series (`whole_tables_by_quadrature`, shipped as
!! constants in `brachistochrone_inverse_square_tables`, so building a model is a copy); an
!! evaluation then costs a Horner sum of at most 21 terms instead of a quadrature.
!! Second half-arch (eq. 29): F = 2 F(R,R) - F(r,R) = F(R,R) + int_0^L, one panel.
module brachistochrone_inverse_square
    use brachistochrone_kinds, only: qp, pi, eps_qp, xp
    use brachistochrone_status, only: status_ok, argument_status
    use brachistochrone_closed_forms, only: radial_time_of_roots, second_arch_radial_time
    use brachistochrone_fast_math, only: hardware_real
    use brachistochrone_chebyshev, only: chebyshev_table, chebyshev_points, chebyshev_fit, &
                                         chebyshev_table_xp, hardware_copy, &
                                         chebyshev_table_from_powers
    use brachistochrone_inverse_square_tables, only: whole_power_1, whole_power_2, &
                                                     whole_power_3, whole_used
    use brachistochrone_summation, only: compensated_sum
    use brachistochrone_quadrature, only: gauss_legendre_rule, gauss_legendre
    use, intrinsic :: iso_fortran_env, only: real64
    implicit none
    private

    public :: inverse_square_model, new_inverse_square_model
    public :: evaluate_arch, arch_values, level_fine, level_coarse, level_rough, level_digits
    public :: level_hardware, level_final, hardware_epsilon
    public :: whole_tables_by_quadrature, table_pieces, table_points

    !> Rule set selector: full quad precision.
    integer, parameter :: level_fine = 1
    !> Rule set selector: about 15 digits, for the first iterations of a root finder.
    integer, parameter :: level_coarse = 2
    !> Rule set selector: about 9 digits, for the first steps of a root finder.
    integer, parameter :: level_rough = 3
    !> Rule set selector: the level_coarse rules in the widest hardware precision
    !! (`xp`: angle and d(angle)/dR only), for a root finder's first steps at a small
    !! fraction of the cost of software quad; falls back to level_coarse where `xp`
    !! could underflow.
    integer, parameter :: level_hardware = 4
    !> Rule set selector: the full rules, the values (angle, s, t) in binary128 and the
    !! d/dR pieces of the integrals in hardware precision (`xp`, relative error about
    !! 1e-18): for a last Newton step whose size is already below 1e-17, where the
    !! slopes' error is negligible, at about two thirds of the cost of level_fine.
    integer, parameter :: level_final = 5
    !> Relative rounding of `xp` (the level_hardware evaluations are about 100 times
    !! less accurate).
    real(qp), parameter :: hardware_epsilon = real(epsilon(1.0_xp), qp)
    public :: apse_estimate_error
    !> Bound on the relative error of `apse_angle_estimate` (the table's cut 1e-20 and
    !! the rounding of its Horner sum, far below this on x87; double is 1000x coarser).
    real(qp), parameter :: apse_estimate_error = 1.0e4_qp*hardware_epsilon
    !> Below this, R, r - R or 1 - r are too small for level_hardware.
    real(qp), parameter :: hardware_floor = 1.0e-250_qp

    !> Most Gauss nodes on one panel: the worst panel (R -> 0, a whole half-arch in the
    !! eta variable) needs 46 for Theta, 48 for s and t (8e-36 there).
    integer, parameter :: max_nodes = 48
    !> Fewest Gauss nodes on a panel.
    integer, parameter :: min_nodes = 6
    !> Digits aimed at by the node choice: fine (with a margin over 34) and coarse.
    real(qp), parameter :: fine_digits = 36.0_qp, coarse_digits = 17.0_qp, &
                           hardware_digits = 19.0_qp, &
                           rough_digits = 9.0_qp
    !> Pieces of [0, 1] and points per piece of the whole-half-arch tables: the slowest
    !! piece, next to R = 1 (Bernstein radius 18 from the singularity at 3/2), reaches
    !! the rounding level at 26 terms.
    integer, parameter :: table_pieces = 16, table_points = 32

    !> One Gauss-Legendre rule with the node data the sweeps use.
    type :: gauss_nodes
        integer :: n = 0                          !! number of nodes
        real(qp), allocatable :: offset(:)        !! (1 + x_k)/2 for the nodes x_k
        real(qp), allocatable :: double_weight(:) !! 2 w_k for the weights w_k
        real(xp), allocatable :: offset_xp(:)        !! offset in hardware precision
        real(xp), allocatable :: double_weight_xp(:) !! double_weight in hardware precision
    end type gauss_nodes

    !> The inverse-square evaluator: quadrature rules built once, then used read-only
    !! (so one model can be shared by all threads).
    type :: inverse_square_model
        !> Gauss rules with n = 2j nodes in element j (j = min_nodes/2 .. max_nodes/2)
        type(gauss_nodes) :: gauss(max_nodes/2)
        !> d Theta(R,R)/dR at R = 0 (about -0.8096): the slope of the apse angle there
        real(qp) :: apse_slope_at_zero = 0.0_qp
        !> The whole half-arch as functions of R in [0, 1]: Theta(R,R)/(1-R), and the
        !! S and T corrections over lambda in [0, pi/2] without their factors (1-R) and
        !! sqrt(1-R) (see `whole_half_arch`)
        type(chebyshev_table) :: whole(3)
        !> Theta(R,R)/(1-R) of `whole` in hardware precision, for level_hardware
        type(chebyshev_table_xp) :: whole_xp
        !> The Theta and S tables of `whole` in hardware precision with all their terms,
        !! for the derivatives at level_final
        type(chebyshev_table_xp) :: whole_slopes_xp(2)
    contains
        procedure :: half_arch      !! Theta, S, T on the first or second half-arch
        procedure :: theta          !! Theta(r,R), eq. (55)
        procedure :: arclength      !! S(r,R), eq. (56)
        procedure :: travel_time    !! T(r,R), eq. (57)
        procedure :: apse_angle     !! Theta(R,R), eq. (66)
        procedure :: apse_angle_estimate !! Theta(R,R) in hardware precision
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
        !> d(arclength)/dR = arclength_dr_smooth + boundary_sign * arclength_boundary
        !! / sqrt(r - R) (with both the derivative and arclength requested)
        real(qp) :: arclength_dr_smooth = 0.0_qp
        real(qp) :: arclength_boundary = 0.0_qp  !! its 1/sqrt(r - R) coefficient, >= 0
        !> Bounds on the absolute errors of angle_dr_smooth and arclength_dr_smooth from
        !! their hardware-precision sums (level_final; 0 on the other levels)
        real(qp) :: angle_dr_error = 0.0_qp
        real(qp) :: arclength_dr_error = 0.0_qp
    end type arch_values

contains

    !> Digits aimed at by a precision level (level_fine, level_coarse, level_rough).
    elemental function level_digits(level) result(digits)
        integer, intent(in) :: level !! the level
        real(qp) :: digits
        select case (level)
        case (level_coarse);  digits = coarse_digits
        case (level_rough);   digits = rough_digits
        case (level_hardware); digits = hardware_digits
        case (level_final);    digits = fine_digits
        case default;         digits = fine_digits
        end select
    end function level_digits

    !> Build the quadrature rules and the whole-half-arch tables (the only costly step,
    !! about 55 ms on one thread: do it once and share the model). The rules, the table
    !! points and the fits are shared among the OpenMP threads (each one computed as on
    !! one thread, so the model is the same bits for any number of threads).
    function new_inverse_square_model() result(model)
        type(inverse_square_model) :: model
        real(qp) :: angle, slope
        integer :: j, k
        do j = min_nodes/2, max_nodes/2
            call set_rule(model, j)
        end do
        do k = 1, 3
            model%whole(k) = chebyshev_table_from_powers(0.0_qp, 1.0_qp, whole_power(k), &
                                                         whole_used(:, k))
        end do
        model%whole_xp = hardware_copy(model%whole(1), 0.1_qp*10.0_qp**(-hardware_digits))
        do k = 1, 2
            model%whole_slopes_xp(k) = hardware_copy(model%whole(k))
            model%whole_slopes_xp(k)%used = model%whole(k)%used
        end do
        ! d Theta(R,R)/dR at R = 0 (Theta(R,R) = pi/3 - 0.8095502 R + ...), with
        ! Theta(R,R) = (1 - R) A(R): A'(0) - A(0)
        call model%whole(1)%evaluate(0.0_qp, angle, slope)
        model%apse_slope_at_zero = slope - angle
    end function new_inverse_square_model

    !> The power form of whole-half-arch table k (1: Theta, 2: S, 3: T correction) as
    !! shipped in `brachistochrone_inverse_square_tables`.
    pure function whole_power(k) result(power)
        integer, intent(in) :: k
        real(qp) :: power(0:table_points - 1, table_pieces)
        select case (k)
        case (1); power = whole_power_1
        case (2); power = whole_power_2
        case default; power = whole_power_3
        end select
    end function whole_power

    !> The tables of the whole half-arch integrals in R (`whole_half_arch`, on the largest
    !! rule of `model`), computed: the quadrature at the Chebyshev points of every piece
    !! by the threads, then the three fits. What `scripts/make_inverse_square_tables.sh`
    !! writes into `brachistochrone_inverse_square_tables` (which the model uses: this
    !! takes about 40 ms) and the tests check the shipped tables against.
    function whole_tables_by_quadrature(model) result(whole)
        type(inverse_square_model), intent(in) :: model !! with its Gauss rules
        type(chebyshev_table) :: whole(3)
        integer, parameter :: points_count = table_points*table_pieces
        real(qp) :: points(table_points, table_pieces)
        real(qp) :: values(table_points, table_pieces, 3)
        integer :: item, k, piece
        points = chebyshev_points(0.0_qp, 1.0_qp, table_pieces, table_points)
        !$omp parallel default(shared) private(item, k, piece)
        !$omp do schedule(dynamic, 1)
        do item = 1, points_count
            k = mod(item - 1, table_points) + 1
            piece = (item - 1)/table_points + 1
            values(k, piece, :) = whole_half_arch(model, points(k, piece))
        end do
        !$omp end do
        ! the values are about 1 with rounding errors below eps, which put noise of about
        ! eps/5 in the coefficients: those below eps/2 are dropped
        !$omp do schedule(dynamic, 1)
        do k = 1, 3
            whole(k) = chebyshev_fit(0.0_qp, 1.0_qp, values(:, :, k), 0.5_qp*eps_qp)
        end do
        !$omp end do
        !$omp end parallel
    end function whole_tables_by_quadrature

    !> Gauss rule j of the model: 2j nodes on [0, 1], weights doubled.
    subroutine set_rule(model, j)
        type(inverse_square_model), intent(inout) :: model
        integer, intent(in) :: j
        type(gauss_legendre_rule) :: rule
        rule = gauss_legendre(2*j)
        model%gauss(j)%n = 2*j
        model%gauss(j)%offset = 0.5_qp*(1.0_qp + rule%node)
        model%gauss(j)%double_weight = 2.0_qp*rule%weight
        model%gauss(j)%offset_xp = real(model%gauss(j)%offset, xp)
        model%gauss(j)%double_weight_xp = real(model%gauss(j)%double_weight, xp)
    end subroutine set_rule

    !> The integrals over the whole half-arch lambda in [0, pi/2]:
    !! [int 2 c^2/Q, int 2 c^3/(Q D), int 2 c^2/(Q D)], that is Theta(R,R)/(1-R) and the
    !! S and T corrections without their factors 1-R and sqrt(1-R). For the tables, so
    !! accuracy first: two panels split at pi/4, each far inside the reach of the
    !! 48-point rule, summed with compensation.
    pure function whole_half_arch(model, big_r) result(values)
        type(inverse_square_model), intent(in) :: model
        real(qp), intent(in) :: big_r
        real(qp) :: values(3)
        type(compensated_sum) :: sums(3)
        real(qp) :: one_minus_big_r, upper, v, v2, jacobian, c, s, c2, z, q, root_q, term
        integer :: k, panel
        one_minus_big_r = 1.0_qp - big_r
        upper = tan(0.125_qp*pi)
        associate (rule => model%gauss(max_nodes/2))
        do panel = 1, 2
            do k = 1, rule%n
                v = upper*rule%offset(k)
                v2 = v*v
                jacobian = 1.0_qp/(1.0_qp + v2)
                ! panel 1 from the apse (v = tau), panel 2 from A (v = eta)
                c = merge(1.0_qp - v2, v + v, panel == 1)*jacobian
                s = merge(v + v, 1.0_qp - v2, panel == 1)*jacobian
                c2 = c*c
                z = big_r + one_minus_big_r*c2
                q = z*(z + one_minus_big_r) + one_minus_big_r
                root_q = sqrt(q)
                term = rule%double_weight(k)*jacobian*c2/root_q
                call sums(1)%add(term)
                term = term/(1.0_qp + s*root_q)
                call sums(2)%add(term*c)
                call sums(3)%add(term)
            end do
        end do
        end associate
        values = upper*sums%value()
    end function whole_half_arch

    !> Gauss nodes needed on the panel v in [0, upper] for `digits` digits of Theta.
    !!
    !! The Theta integrand is analytic except at the zeros of q, where cos(2 lambda) = w,
    !! w = -2/(1-R) + i sqrt((3+R)/(1-R)) (or -w for the variable from A), and at the
    !! poles v = +-i of the half-angle substitution. In v = tan(lambda/2) the zeros of q
    !! sit at +-t, +-1/t with t = tan(acos(w)/4), written without trigonometry as
    !! t = sin(theta/2)/(1 + cos(theta/2)), theta = acos(w), where sin(theta/2) =
    !! sqrt((1-w)/2) and cos(theta/2) = sqrt((1+w)/2) (principal roots: 0 <= Re theta
    !! <= pi). An n-point Gauss rule then errs by about rho^(-2n), rho the Bernstein
    !! ellipse through the nearest of them (mapped to [-1, 1]): for a point zeta that
    !! is rho = a + sqrt(a^2 - 1), a = (|zeta| + |zeta - upper|)/upper the semi-axis of
    !! the ellipse with foci 0 and upper through zeta (of +-t the one with Re >= 0 is
    !! nearer). Double precision is ample for choosing n; the test suite checks the
    !! result against the references.
    pure function nodes_needed(big_r, upper, from_apse, digits) result(n)
        real(qp), intent(in) :: big_r, upper, digits
        logical, intent(in) :: from_apse
        integer :: n
        real(real64) :: r, one_minus_r, u, axis, rho_min, w_re, w_im, sin_re, sin_im
        real(real64) :: cos_re, cos_im, denominator, t_re, t_im, t2
        n = min_nodes
        if (big_r >= 1.0_qp .or. upper <= 0.0_qp) return
        r = real(big_r, real64)
        one_minus_r = 1.0_real64 - r
        w_re = merge(-2.0_real64, 2.0_real64, from_apse)/one_minus_r
        w_im = merge(1.0_real64, -1.0_real64, from_apse)*sqrt((3.0_real64 + r)/one_minus_r)
        call half_root(1.0_real64 - w_re, -w_im, sin_re, sin_im)
        call half_root(1.0_real64 + w_re, w_im, cos_re, cos_im)
        cos_re = 1.0_real64 + cos_re
        denominator = cos_re*cos_re + cos_im*cos_im
        t_re = abs(sin_re*cos_re + sin_im*cos_im)/denominator
        t_im = (sin_im*cos_re - sin_re*cos_im)/denominator
        t2 = t_re*t_re + t_im*t_im
        u = real(upper, real64)
        ! the nearest of t (Re >= 0), 1/t = conj(t)/|t|^2 and i
        axis = min(sqrt(t2) + sqrt((t_re - u)**2 + t_im*t_im), &
                   (1.0_real64 + sqrt((t_re - u*t2)**2 + t_im*t_im)/sqrt(t2))/sqrt(t2), &
                   1.0_real64 + sqrt(1.0_real64 + u*u))/u
        rho_min = axis + sqrt((axis - 1.0_real64)*(axis + 1.0_real64))
        if (rho_min <= 1.0_real64 + 1.0e-6_real64) then
            n = max_nodes
        else
            n = ceiling(real(digits, real64)*log(10.0_real64)/(2.0_real64*log(rho_min))) + 2
            n = min(max_nodes, max(min_nodes, n + mod(n, 2)))
        end if
    end function nodes_needed

    !> sqrt((x + i y)/2), principal branch, in real arithmetic (x + i y /= 0).
    pure subroutine half_root(x, y, re, im)
        real(real64), intent(in) :: x, y
        real(real64), intent(out) :: re, im
        real(real64) :: modulus
        modulus = sqrt(x*x + y*y)
        if (x >= 0.0_real64) then
            re = sqrt(0.25_real64*(modulus + x))
            im = 0.25_real64*y/re
        else
            im = sign(sqrt(0.25_real64*(modulus - x)), y)
            re = 0.25_real64*y/im
        end if
    end subroutine half_root

    !> The kernel: angle (and optionally arclength, time, d(angle)/dR) at radius r on the
    !! first (`second = .false.`) or second half-arch of the brachistochrone with apse R.
    !! The caller passes d = r - R separately so that endpoints near the apse keep full
    !! precision. Preconditions (not checked): 0 < R < 1, 0 <= d, R + d = r <= 1.
    pure function evaluate_arch(self, level, second, r, big_r, d, want_derivative, &
                                want_length_time) result(values)
        type(inverse_square_model), intent(in) :: self
        integer, intent(in) :: level            !! level_fine or level_coarse
        logical, intent(in) :: second           !! second half-arch (after the apse)
        real(qp), intent(in) :: r               !! radius of the point
        real(qp), intent(in) :: big_r           !! apse radius R
        real(qp), intent(in) :: d               !! r - R, computed by the caller
        logical, intent(in) :: want_derivative  !! compute the d/dR pieces
        logical, intent(in) :: want_length_time !! compute arclength and time
        type(arch_values) :: values

        if (level == level_hardware .and. .not. want_length_time .and. &
            min(big_r, 1.0_qp - r) > hardware_floor .and. (d == 0.0_qp .or. d > hardware_floor)) &
            then
            values = arch_hardware(self, second, r, big_r, d)
        else
            values = arch_with_rules(self, merge(level_coarse, level, level == level_hardware), &
                                     second, r, big_r, d, want_derivative, want_length_time)
        end if
    end function evaluate_arch

    !> `evaluate_arch` at level_hardware: angle and d(angle)/dR in hardware precision
    !! (`xp`) on the level_coarse rules (1 - r and d come from quad: the apse keeps its
    !! digits).
    pure function arch_hardware(model, second, r, big_r, d) result(values)
        type(inverse_square_model), intent(in) :: model
        logical, intent(in) :: second
        real(qp), intent(in) :: r, big_r, d
        type(arch_values) :: values
        real(xp) :: rr, br, dd, one_minus_r, one_minus_big_r, cos_l, sin_l, z_l, q_l
        real(xp) :: upper_apse, upper_start, part(2), whole, whole_slope, whole_factor
        integer :: rule_apse, rule_start

        rr = hardware_real(r)
        br = hardware_real(big_r)
        dd = hardware_real(d)
        one_minus_r = hardware_real(1.0_qp - r)
        one_minus_big_r = one_minus_r + dd
        cos_l = sqrt(br*one_minus_r/(rr*one_minus_big_r))
        sin_l = sqrt(dd/(rr*one_minus_big_r))
        upper_apse = sin_l/(1.0_xp + cos_l)
        upper_start = cos_l/(1.0_xp + sin_l)
        rule_start = rule_index(big_r, real(upper_start, qp), .false., hardware_digits)
        whole_factor = 0.0_xp
        whole = 0.0_xp
        whole_slope = 0.0_xp
        values%boundary_sign = 1.0_qp
        if (second) then
            call model%whole_xp%evaluate(br, whole, whole_slope)
            rule_apse = rule_index(big_r, real(upper_apse, qp), .true., hardware_digits)
            values%boundary_sign = -1.0_qp
            if (rule_apse <= rule_start) then
                part = sweep_hardware(model, rule_apse, br, one_minus_big_r, upper_apse, .true.)
                whole_factor = 1.0_xp
            else
                part = -sweep_hardware(model, rule_start, br, one_minus_big_r, upper_start, &
                                     .false.)
                whole_factor = 2.0_xp
            end if
        else
            part = sweep_hardware(model, rule_start, br, one_minus_big_r, upper_start, .false.)
        end if
        values%angle = real(whole_factor*one_minus_big_r*whole + part(1), qp)
        values%angle_dr_smooth = real(whole_factor*(one_minus_big_r*whole_slope - whole) &
                                      + part(2), qp)
        z_l = br/rr
        q_l = z_l*z_l + one_minus_big_r*(1.0_xp + z_l)
        values%boundary = real(sqrt(br)*one_minus_r*sqrt(one_minus_r) &
                               /(rr*one_minus_big_r*sqrt(q_l)), qp)
    end function arch_hardware

    !> `sweep` in hardware precision (`xp`), angle and d(angle)/dR only.
    pure function sweep_hardware(model, j, big_r, one_minus_big_r, upper, from_apse) &
        result(sums)
        type(inverse_square_model), intent(in) :: model
        integer, intent(in) :: j
        real(xp), intent(in) :: big_r, one_minus_big_r, upper
        logical, intent(in) :: from_apse
        real(xp) :: sums(2)
        real(xp) :: v, jacobian, c, s, c2, z, q, theta_term, inverse
        integer :: k
        sums = 0.0_xp
        if (upper <= 0.0_xp) return
        associate (rule => model%gauss(j))
        do k = 1, rule%n
            v = upper*rule%offset_xp(k)
            call node_geometry_xp(v, big_r, one_minus_big_r, from_apse, jacobian, c, s, &
                                  c2, z, q)
            inverse = 1.0_xp/sqrt(q)
            theta_term = rule%double_weight_xp(k)*jacobian*c2*inverse
            sums(1) = sums(1) + theta_term
            sums(2) = sums(2) - theta_term*(inverse*inverse)*(z*(z + z) + &
                      one_minus_big_r*(z + 1.0_xp + (z + z + one_minus_big_r)*(s*s)))
        end do
        end associate
        sums(1) = sums(1)*upper*one_minus_big_r
        sums(2) = sums(2)*0.5_xp*upper
    end function sweep_hardware

    !> `evaluate_arch` for one precision level.
    pure function arch_with_rules(model, level, second, r, big_r, d, want_derivative, &
                                  want_length_time) result(values)
        type(inverse_square_model), intent(in) :: model
        integer, intent(in) :: level
        logical, intent(in) :: second, want_derivative, want_length_time
        real(qp), intent(in) :: r, big_r, d
        type(arch_values) :: values
        real(qp) :: one_minus_r, one_minus_big_r, cos_l, sin_l, z_l, q_l, length_ratio
        real(qp) :: part(5), whole(3), whole_slope(3), correction_scale, digits
        real(qp) :: slope_error(2)
        real(qp) :: upper_apse, upper_start, whole_factor, length_integral, time_integral
        real(qp) :: root_big_r, root_one_minus_r, root_one_minus_big_r, root_q_l
        integer :: rule_apse, rule_start

        digits = level_digits(level)
        one_minus_r = 1.0_qp - r
        one_minus_big_r = one_minus_r + d
        cos_l = sqrt(big_r*one_minus_r/(r*one_minus_big_r))
        sin_l = sqrt(d/(r*one_minus_big_r))
        ! square roots shared by the boundary term, the T factors and the radial times
        root_big_r = 0.0_qp
        root_one_minus_r = 0.0_qp
        root_one_minus_big_r = 0.0_qp
        root_q_l = 0.0_qp
        if (want_derivative .or. want_length_time) then
            root_big_r = sqrt(big_r)
            root_one_minus_r = sqrt(one_minus_r)
        end if
        if (want_length_time) root_one_minus_big_r = sqrt(one_minus_big_r)

        ! One Gauss panel, from the apse (lambda in [0, L]) or from A ([L, pi/2]), and on
        ! the second half-arch the whole-half-arch tables: F = whole_factor * whole + part.
        ! - First half-arch: int_L^(pi/2). (whole - int_0^L would often be cheaper, but
        !   cancels: the integrand is largest near the apse.)
        ! - Second half-arch: whole + int_0^L = 2 whole - int_L^(pi/2), whichever panel
        !   needs fewer nodes (the result is >= whole: the difference costs one bit).
        upper_apse = sin_l/(1.0_qp + cos_l)
        upper_start = cos_l/(1.0_qp + sin_l)
        rule_start = rule_index(big_r, upper_start, .false., digits)
        if (second) then
            call whole_half_arch_table(model, level, big_r, want_length_time, &
                                       want_derivative, whole, whole_slope, slope_error)
            rule_apse = rule_index(big_r, upper_apse, .true., digits)
            if (rule_apse <= rule_start) then
                call sweep(model, rule_apse, big_r, one_minus_big_r, upper_apse, .true., &
                           want_derivative, want_length_time, level == level_final, &
                           root_one_minus_big_r, part)
                whole_factor = 1.0_qp
            else
                call sweep(model, rule_start, big_r, one_minus_big_r, upper_start, .false., &
                           want_derivative, want_length_time, level == level_final, &
                           root_one_minus_big_r, part)
                whole_factor = 2.0_qp
                part = -part
            end if
            values%boundary_sign = -1.0_qp
        else
            call sweep(model, rule_start, big_r, one_minus_big_r, upper_start, .false., &
                       want_derivative, want_length_time, level == level_final, &
                           root_one_minus_big_r, part)
            whole_factor = 0.0_qp
            whole = 0.0_qp
            whole_slope = 0.0_qp
            slope_error = 0.0_qp
            values%boundary_sign = 1.0_qp
        end if
        values%angle = whole_factor*one_minus_big_r*whole(1) + part(1)
        values%angle_dr_smooth = whole_factor*(one_minus_big_r*whole_slope(1) - whole(1)) &
                                 + part(2)
        if (level == level_final) then
            ! sums of terms of one sign, each within a few roundings of xp; the tables'
            ! slopes in xp (`table_slope_xp`)
            values%angle_dr_error = 100.0_qp*hardware_epsilon*abs(part(2)) &
                                    + whole_factor*one_minus_big_r*slope_error(1)
            values%arclength_dr_error = big_r*(100.0_qp*hardware_epsilon*abs(part(5)) &
                                        + whole_factor*one_minus_big_r*slope_error(2))
        end if

        if (want_derivative) then
            z_l = big_r/r
            q_l = z_l*z_l + one_minus_big_r*(1.0_qp + z_l)
            root_q_l = sqrt(q_l)
            values%boundary = root_big_r*one_minus_r*root_one_minus_r &
                              /(r*one_minus_big_r*root_q_l)
        end if

        if (want_length_time) then
            correction_scale = big_r*root_big_r/sqrt(2.0_qp)
            ! the S and T corrections: I = whole_factor * whole + part as for the angle
            length_integral = whole_factor*one_minus_big_r*whole(2) + part(3)
            time_integral = whole_factor*root_one_minus_big_r*whole(3) + part(4)
            if (second) then
                values%arclength = (one_minus_big_r + d) + big_r*length_integral
                values%time = second_arch_radial_time(big_r, one_minus_big_r, r, one_minus_r, &
                                                     sqrt(r), root_one_minus_r) &
                              + correction_scale*time_integral
            else
                values%arclength = one_minus_r + big_r*length_integral
                values%time = radial_time_of_roots(r, one_minus_r, sqrt(r), root_one_minus_r) &
                              + correction_scale*time_integral
            end if
            if (want_derivative) then
                ! dS/dR: S = (1 - r) + R I on the first half-arch, (1 + r - 2R) + R I on
                ! the second; the moving limit adds R G(L) |L'(R)|, G the S integrand,
                ! G(L)/Theta integrand(L) = cos L/(1 + sin L Q(L))
                length_ratio = cos_l/(1.0_qp + sin_l*root_q_l)
                values%arclength_boundary = big_r*length_ratio*values%boundary
                values%arclength_dr_smooth = merge(-2.0_qp, 0.0_qp, second) &
                    + length_integral + big_r*(whole_factor*(one_minus_big_r*whole_slope(2) &
                                                             - whole(2)) + part(5))
            end if
        end if
    end function arch_with_rules

    !> The whole-half-arch integrals at R from the tables, to the level's accuracy:
    !! whole = [Theta(R,R)/(1-R), S and T corrections without 1-R, sqrt(1-R)] and, with
    !! `want_slopes`, the R-derivatives of the first two (the second only when
    !! `want_length_time`). At level_final the derivatives are taken in hardware
    !! precision (`table_slope_xp`), with bounds on their errors in `slope_error`.
    pure subroutine whole_half_arch_table(model, level, big_r, want_length_time, &
                                          want_slopes, whole, slope, slope_error)
        type(inverse_square_model), intent(in) :: model
        integer, intent(in) :: level
        real(qp), intent(in) :: big_r
        logical, intent(in) :: want_length_time, want_slopes
        real(qp), intent(out) :: whole(3), slope(3), slope_error(2)
        real(qp) :: tolerance
        integer :: k
        whole = 0.0_qp
        slope = 0.0_qp
        slope_error = 0.0_qp
        ! (the T correction's slope is not needed: see two_point's Hamilton-Jacobi step)
        if (level == level_final .or. (level == level_fine .and. .not. want_slopes)) then
            call model%whole(1)%evaluate(big_r, whole(1))
            if (want_length_time) then
                call model%whole(2)%evaluate(big_r, whole(2))
                call model%whole(3)%evaluate(big_r, whole(3))
            end if
            if (want_slopes) then
                do k = 1, merge(2, 1, want_length_time)
                    call table_slope_xp(model%whole_slopes_xp(k), hardware_real(big_r), &
                                        slope(k), slope_error(k))
                end do
            end if
        else if (level == level_fine) then
            call model%whole(1)%evaluate(big_r, whole(1), slope(1))
            if (want_length_time) then
                call model%whole(2)%evaluate(big_r, whole(2), slope(2))
                call model%whole(3)%evaluate(big_r, whole(3))
            end if
        else
            ! the tables' values are about 1: an absolute tolerance a tenth of the level's
            tolerance = 0.1_qp*10.0_qp**(-level_digits(level))
            call model%whole(1)%evaluate(big_r, whole(1), slope(1), tolerance)
            if (want_length_time) then
                call model%whole(2)%evaluate(big_r, whole(2), slope(2), tolerance)
                call model%whole(3)%evaluate(big_r, whole(3), tolerance=tolerance)
            end if
        end if
    end subroutine whole_half_arch_table

    !> The derivative p'(x) of a table's hardware copy (all its terms) by Horner in `xp`,
    !! with a bound on its error: the rounding of the Horner sums and of the coefficients,
    !! (4n + 2) eps sum_j j |a_j| |t|^(j-1) (n terms), and the rounding of x to `xp`
    !! (relative eps/2; t = 2 (x - lower)/width - (2 piece - 1) is exact for the tables'
    !! power-of-two widths), eps |x| sum_j j (j-1) |a_j| |t|^(j-2) (2/width), all times
    !! 2/width, the chain-rule factor.
    pure subroutine table_slope_xp(table, x, slope, error)
        type(chebyshev_table_xp), intent(in) :: table
        real(xp), intent(in) :: x
        real(qp), intent(out) :: slope, error
        real(xp) :: position, t, value, derivative, size_value, size_slope, size_curve
        integer :: piece, j, n
        position = (x - table%lower)/table%width
        piece = min(table%pieces, max(1, int(position) + 1))
        t = 2.0_xp*(position - real(piece - 1, xp)) - 1.0_xp
        n = table%used(piece)
        value = table%power(n - 1, piece)
        size_value = abs(value)
        derivative = 0.0_xp
        size_slope = 0.0_xp
        size_curve = 0.0_xp
        do j = n - 2, 0, -1
            size_curve = size_curve*abs(t) + 2.0_xp*size_slope
            derivative = derivative*t + value
            size_slope = size_slope*abs(t) + size_value
            value = value*t + table%power(j, piece)
            size_value = size_value*abs(t) + abs(table%power(j, piece))
        end do
        slope = real(derivative*(2.0_xp/table%width), qp)
        error = hardware_epsilon*real((real(4*n + 2, xp)*size_slope &
                + abs(x)*size_curve*(2.0_xp/table%width))*(2.0_xp/table%width), qp)
    end subroutine table_slope_xp

    !> The Gauss rule (element of model%gauss) for the panel v in [0, upper].
    pure function rule_index(big_r, upper, from_apse, digits) result(j)
        real(qp), intent(in) :: big_r, upper, digits
        logical, intent(in) :: from_apse
        integer :: j
        ! s and t converge at the rate Theta does (their extra zeros, of D, lie farther
        ! out: at tau = -1 as R -> 0), and the margin of fine_digits covers their larger
        ! constants: with 2 more nodes the sums change by rounding alone (measured on
        ! 16,000 final sweeps, random and extreme endpoints: the same share of values
        ! beyond 2 eps of a 48-node reference, largest 6.5 against 5.5 eps), with 2 fewer
        ! they lose up to 6e4 eps
        j = nodes_needed(big_r, upper, from_apse, digits)/2
    end function rule_index

    !> Gauss-Legendre sweep over v in [0, upper] of the integrands
    !! (Theta, dTheta/dR, S correction, T correction, d(S correction)/dR);
    !! v = tau from the apse or v = eta from the start, both with
    !! d lambda = 2 dv/(1 + v^2). The last entry is filled only with both flags set.
    pure subroutine sweep(model, j, big_r, one_minus_big_r, upper, from_apse, &
                          want_derivative, want_length_time, hardware_slopes, &
                          root_one_minus_big_r, sums)
        type(inverse_square_model), intent(in) :: model
        integer, intent(in) :: j  !! the rule: model%gauss(j), from `rule_index`
        real(qp), intent(in) :: big_r, one_minus_big_r, upper
        logical, intent(in) :: from_apse, want_derivative, want_length_time
        logical, intent(in) :: hardware_slopes !! the d/dR sums in `xp` (level_final)
        real(qp), intent(in) :: root_one_minus_big_r !! sqrt(1 - R) (with want_length_time)
        real(qp), intent(out) :: sums(5)

        sums = 0.0_qp
        if (upper <= 0.0_qp) return
        call sweep_values(model%gauss(j), big_r, one_minus_big_r, upper, from_apse, &
                          want_derivative, want_length_time, hardware_slopes, sums)
        ! common factors: Theta 2(1-R) c^2/Q; S 2(1-R) c^3/(QD); T 2 sqrt(1-R) c^2/(QD);
        ! d/dR of the S integrand: -2 c^3/(QD) - (1-R) c^3 q_R (D + sQ)/(Q^3 D^2)
        sums(1) = sums(1)*upper*one_minus_big_r
        sums(2) = sums(2)*0.5_qp*upper
        sums(5) = -sums(3)*upper - 0.5_qp*one_minus_big_r*sums(5)*upper
        sums(3) = sums(3)*upper*one_minus_big_r
        if (want_length_time) sums(4) = sums(4)*upper*root_one_minus_big_r
    end subroutine sweep

    !> The node loop of `sweep`, in few binary128 operations (in software a division
    !! costs about one and a half multiplications):
    !! c and s as quotients, q = 1 + x (1 + R + x) with x = (1 - R) c^2, and Q = sqrt(q)
    !! by one Heron step (Q0 + q/Q0)/2 from the `xp` node of `node_xp` (relative error
    !! a few roundings of `xp`, so the step's error is below 1e-36; a second step where
    !! `xp` is only double), scaled by powers of two so that no doubling or halving is
    !! left in the loop. The values do not depend on how the d/dR sums are taken
    !! (`node_xp` or `add_slopes_qp`). Raw sums: Theta, d Theta/dR, S, T, d S/dR.
    pure subroutine sweep_values(rule, big_r, one_minus_big_r, upper, from_apse, &
                                 want_derivative, want_length_time, hardware_slopes, sums)
        type(gauss_nodes), intent(in) :: rule
        real(qp), intent(in) :: big_r, one_minus_big_r, upper
        logical, intent(in) :: from_apse, want_derivative, want_length_time
        logical, intent(in) :: hardware_slopes !! the d/dR sums in `xp`, else binary128
        real(qp), intent(inout) :: sums(5)
        integer, parameter :: heron_steps = merge(1, 2, digits(1.0_xp) >= 64)
        real(qp) :: v, v2, d, c, s, c2, x, q, h, theta_term, lengths, one_plus_big_r
        real(qp) :: c_scale, s_scale, x_factor, lengths_offset
        real(xp) :: slopes(2), upper_xp, big_r_xp, one_minus_big_r_xp, root_q_xp
        integer :: k, step
        logical :: quad_slopes

        quad_slopes = want_derivative .and. .not. hardware_slopes
        slopes = 0.0_xp
        one_plus_big_r = 1.0_qp + big_r
        upper_xp = hardware_real(upper)
        big_r_xp = hardware_real(big_r)
        one_minus_big_r_xp = hardware_real(one_minus_big_r)
        ! the loop takes c/c_scale, s/s_scale and h = 2 sqrt(q) (the factor 2 of the
        ! node's 2v and the 1/2 of the Heron step stay out of it: every quantity is an
        ! exact power of two times the true one, the sums are rescaled at the end)
        c_scale = merge(1.0_qp, 2.0_qp, from_apse)
        s_scale = 3.0_qp - c_scale
        x_factor = one_minus_big_r*(c_scale*c_scale)
        lengths_offset = 2.0_qp/s_scale
        do k = 1, rule%n
            call node_xp(upper_xp*rule%offset_xp(k), rule%double_weight_xp(k), big_r_xp, &
                         one_minus_big_r_xp, from_apse, want_derivative .and. hardware_slopes, &
                         want_length_time, root_q_xp, slopes)
            v = upper*rule%offset(k)
            v2 = v*v
            d = 1.0_qp + v2
            if (from_apse) then
                c = (1.0_qp - v2)/d
                s = v/d
            else
                c = v/d
                s = (1.0_qp - v2)/d
            end if
            c2 = c*c
            x = x_factor*c2
            q = 1.0_qp + x*(one_plus_big_r + x)
            h = real(root_q_xp, qp)
            do step = 2, heron_steps
                h = 0.5_qp*(h + q/h)
            end do
            h = h + q/h
            theta_term = rule%double_weight(k)*c2/(d*h)
            sums(1) = sums(1) + theta_term
            if (want_length_time) then
                lengths = theta_term/(lengths_offset + s*h)
                sums(3) = sums(3) + lengths*c
                sums(4) = sums(4) + lengths
            end if
            if (quad_slopes) call add_slopes_qp(big_r, one_minus_big_r, c_scale*c, &
                s_scale*s, (c_scale*c_scale)*c2, 0.5_qp*h, &
                (2.0_qp*c_scale*c_scale)*theta_term, want_length_time, sums)
        end do
        ! theta_term is Theta's term/(2 c_scale^2), lengths T's s_scale/(4 c_scale^2)
        sums(1) = sums(1)*(2.0_qp*c_scale*c_scale)
        sums(3) = sums(3)*(4.0_qp*c_scale*c_scale*c_scale/s_scale)
        sums(4) = sums(4)*(4.0_qp*c_scale*c_scale/s_scale)
        if (want_derivative .and. hardware_slopes) sums([2, 5]) = real(slopes, qp)
    end subroutine sweep_values

    !> One node of `sweep_values` in hardware precision: sqrt(q) (the seed of the Heron
    !! step) and, when wanted, the d/dR integrands added to `slopes`, with
    !! dq/dR = (2z + 1 - R) s^2 - (1 + z) = -2 c^2 z (no cancellation). The slope sums'
    !! terms each have one sign and a relative error of a few roundings of `xp`.
    pure subroutine node_xp(v, weight, big_r, one_minus_big_r, from_apse, &
                            want_derivative, want_length_time, root_q, slopes)
        real(xp), intent(in) :: v, weight, big_r, one_minus_big_r
        logical, intent(in) :: from_apse, want_derivative, want_length_time
        real(xp), intent(out) :: root_q
        real(xp), intent(inout) :: slopes(2)
        real(xp) :: jacobian, c, s, c2, z, q, inverse, theta_term, s_big_q, inverse_d
        call node_geometry_xp(v, big_r, one_minus_big_r, from_apse, jacobian, c, s, c2, z, q)
        root_q = sqrt(q)
        if (.not. want_derivative) return
        inverse = 1.0_xp/root_q
        theta_term = weight*c2*inverse*jacobian
        slopes(1) = slopes(1) - theta_term*(inverse*inverse)*(z*(z + z) + &
                    one_minus_big_r*(z + 1.0_xp + (z + z + one_minus_big_r)*(s*s)))
        if (want_length_time) then
            s_big_q = s*root_q
            inverse_d = 1.0_xp/(1.0_xp + s_big_q)
            slopes(2) = slopes(2) - theta_term*inverse_d*c*(2.0_xp*c2*z) &
                        *(1.0_xp + s_big_q + s_big_q)*(inverse*inverse)*inverse_d
        end if
    end subroutine node_xp

    !> The node's geometry in hardware precision: jacobian 1/(1 + v^2) of the half-angle
    !! variable v, c = cos lambda and s = sin lambda (swapped from the start), c^2,
    !! z = R + (1 - R) c^2 and q = z (z + 1 - R) + 1 - R.
    pure subroutine node_geometry_xp(v, big_r, one_minus_big_r, from_apse, jacobian, c, &
                                     s, c2, z, q)
        real(xp), intent(in) :: v, big_r, one_minus_big_r
        logical, intent(in) :: from_apse
        real(xp), intent(out) :: jacobian, c, s, c2, z, q
        real(xp) :: v2
        v2 = v*v
        jacobian = 1.0_xp/(1.0_xp + v2)
        if (from_apse) then
            c = (1.0_xp - v2)*jacobian
            s = (v + v)*jacobian
        else
            c = (v + v)*jacobian
            s = (1.0_xp - v2)*jacobian
        end if
        c2 = c*c
        z = big_r + one_minus_big_r*c2
        q = z*(z + one_minus_big_r) + one_minus_big_r
    end subroutine node_geometry_xp

    !> The d/dR integrands of `node_xp` in binary128, added to the raw sums 2 and 5.
    pure subroutine add_slopes_qp(big_r, one_minus_big_r, c, s, c2, root_q, theta_term, &
                                  want_length_time, sums)
        real(qp), intent(in) :: big_r, one_minus_big_r, c, s, c2, root_q, theta_term
        logical, intent(in) :: want_length_time
        real(qp), intent(inout) :: sums(5)
        real(qp) :: z, inverse, s_big_q, inverse_d
        z = big_r + one_minus_big_r*c2
        inverse = 1.0_qp/root_q
        sums(2) = sums(2) - theta_term*(inverse*inverse)*(z*(z + z) + &
                  one_minus_big_r*(z + 1.0_qp + (z + z + one_minus_big_r)*(s*s)))
        if (want_length_time) then
            s_big_q = s*root_q
            inverse_d = 1.0_qp/(1.0_qp + s_big_q)
            sums(5) = sums(5) - theta_term*inverse_d*c*(2.0_qp*c2*z) &
                      *(1.0_qp + s_big_q + s_big_q)*(inverse*inverse)*inverse_d
        end if
    end subroutine add_slopes_qp

    !> Check 0 < R < 1, R <= r <= 1, all finite.
    pure function check_radii(r, big_r) result(status)
        real(qp), intent(in) :: r, big_r
        integer :: status
        status = argument_status([r, big_r], big_r > 0.0_qp .and. big_r < 1.0_qp .and. &
                                             r >= big_r .and. r <= 1.0_qp)
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
        values = evaluate_arch(self, level_fine, second, r, big_r, r - big_r, .false., .true.)
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
        values = evaluate_arch(self, level_fine, .false., r, big_r, r - big_r, .false., .false.)
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

    !> Theta(R,R), eq. (66): the apse angle, from its table (`whole_half_arch`).
    !! Strictly decreasing from pi/3 (R -> 0) to 0 (R -> 1); R = 1 gives 0.
    pure subroutine apse_angle(self, big_r, value, status)
        class(inverse_square_model), intent(in) :: self
        real(qp), intent(in) :: big_r  !! apse radius, 0 < R <= 1
        real(qp), intent(out) :: value !! Theta(R,R); 0 on error
        integer, intent(out) :: status !! status_ok or the reason
        real(qp) :: scaled
        value = 0.0_qp
        status = argument_status([big_r], big_r > 0.0_qp .and. big_r <= 1.0_qp)
        if (status /= status_ok) return
        call self%whole(1)%evaluate(big_r, scaled)
        value = (1.0_qp - big_r)*scaled
    end subroutine apse_angle

    !> Theta(R,R) from the hardware-precision copy of its table (`whole_xp`, cut at
    !! 1e-20): relative error below `apse_estimate_error`, at a small fraction of the
    !! cost of `apse_angle`; for decisions that need the full value only when close.
    !! Precondition (not checked): 0 < R <= 1.
    pure function apse_angle_estimate(self, big_r) result(value)
        class(inverse_square_model), intent(in) :: self
        real(qp), intent(in) :: big_r  !! apse radius, 0 < R <= 1
        real(qp) :: value
        real(xp) :: scaled
        call self%whole_xp%evaluate(hardware_real(big_r), scaled)
        value = real(hardware_real(1.0_qp - big_r)*scaled, qp)
    end function apse_angle_estimate

end module brachistochrone_inverse_square
