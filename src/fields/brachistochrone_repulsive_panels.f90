!> Fixed Gauss-Legendre panels for the repulsive field's integrals (the fast evaluator of
!! `brachistochrone_repulsive`).
!!
!! The pieces of an integral (variable, interval) are laid out by
!! `brachistochrone_repulsive`; their substitutions make every integrand analytic on the
!! interval, with singularities at known complex points: the zeros of Q (0 is a pole of
!! theta's integrand, -P and the near-double pair a +- i sqrt(beta) or r2 = R + d branch
!! points), x = 1 where sqrt(x - 1) is not removed, and those of the maps themselves
!! (sin(nu/2) = +-1 in the apse's sinh map, z = 0 in the far map). Mapped into the piece's
!! variable they fix, for each panel, the Bernstein ellipse rho of Gauss convergence
!! (error about rho^(-2n) for n nodes), so the rule is chosen once per curve, in double
!! precision, before any integrand is evaluated (as on the inverse-square fast path). A
!! panel that would need more than `max_nodes` nodes is bisected: near a singularity
!! at one end this makes a geometric mesh. More than `max_panels` panels for one integral
!! is a failure (the caller then integrates adaptively).
!!
!! Two precisions: all three integrals (theta, s, t) in binary128 aiming at 35 digits
!! (37 on the peak's sinh map), and theta alone in the widest hardware precision (`xp`,
!! x87 extended where there is one) aiming at 20 digits, for the root finder's early
!! phase. The binary128 loop (`panel_sums`, one piece kind at a time) forms each node's
!! geometry in binary128 and, in parallel, in `xp` for the seeds of its two square
!! roots, each then one Heron step (`heron`: s + x/s, a division and a sum; the
!! integrands' inverse roots as divisions by them: 4 to 6 binary128 operations a node
!! fewer than inverse square roots by Newton steps, and a division costs about a
!! product; no binary128 number converted per node); the pieces' constant factors are
!! applied once per piece (`piece_factors`, powers of two in `panel_sums`). The
!! hardware-precision loops likewise take the curve's square roots and constants out of
!! the node loop (`angle_sum_xp`, `slopes_sum_c`).
module brachistochrone_repulsive_panels
    use brachistochrone_kinds, only: qp, xp
    use brachistochrone_status, only: status_ok, status_no_convergence
    use brachistochrone_quadrature, only: gauss_legendre_rule, gauss_legendre
    use brachistochrone_fast_math, only: inverse_sqrt, hardware_real, quad_real, fast_sqrt
    use, intrinsic :: iso_fortran_env, only: real64
    implicit none
    private

    public :: panel_rules, new_panel_rules, panel_piece, panel_curve
    public :: panel_integrals, panel_angle_xp, integrands, panel_slopes_xp
    public :: piece_start, piece_below, piece_above, piece_far, piece_arch, piece_apse, &
              piece_arch_start, max_pieces


    !> Piece kinds (the variable of each): sigma from the start, h = |x - a| below/above the
    !! peak (`stretched`: h = sqrt(beta) sinh(xi)), z = 4/x far out, nu of the bounded arch,
    !! xi of the apse's sinh map, mu = pi - nu next to the start.
    integer, parameter :: piece_start = 1, piece_below = 2, piece_above = 3, &
                          piece_far = 4, piece_arch = 5, piece_apse = 6, &
                          piece_arch_start = 7
    integer, parameter :: max_pieces = 6
    !> The ladder of rules and the most panels for one integral.
    integer, parameter :: ladder(*) = [6, 8, 10, 12, 16, 20, 24, 28, 30, 32, 34, 36, 38, &
                                       40, 44, 48]
    integer, parameter :: max_nodes = 48, max_panels = 64
    !> Digits aimed at: binary128 (with a margin over 34) and the hardware phase.
    real(real64), parameter :: quad_digits = 35.0_real64, hardware_digits = 20.5_real64
    !> More digits asked of the peak's sinh map in binary128 (its integrand grows
    !! towards the map's poles t = +-1 near the Bernstein ellipse: measured against
    !! the mpmath references, 35 digits left up to 6 eps)
    real(real64), parameter :: stretched_extra = 2.0_real64
    !> Digits aimed at by the complex-step slopes (used only through a step below 1e-17 of
    !! lambda, so 1e-17 of relative error would do; the hardware rounding is 1e-19)
    real(real64), parameter :: slope_digits = 19.0_real64
    real(qp), parameter :: sqrt2 = sqrt(2.0_qp), far_start = 4.0_qp

    !> One Gauss-Legendre rule on [0, 1]: nodes and weights in both precisions.
    type :: panel_rule
        integer :: n = 0
        real(qp), allocatable :: node(:), weight(:)
        real(xp), allocatable :: node_xp(:), weight_xp(:)
    end type panel_rule

    !> The rules of `ladder`, built once (`new_panel_rules`) and then read only.
    type :: panel_rules
        type(panel_rule) :: rule(size(ladder))
    end type panel_rules

    !> One piece of an integral: its kind, its interval in its variable.
    type :: panel_piece
        integer :: kind = piece_start
        logical :: stretched = .false.
        real(qp) :: lower = 0.0_qp, upper = 0.0_qp
    end type panel_piece

    !> The curve's numbers the integrands need (see `brachistochrone_repulsive`).
    type :: panel_curve
        logical :: bounded = .false.
        real(qp) :: k = 0.0_qp, p = 0.0_qp     !! K, P
        real(qp) :: a = 0.0_qp, beta = 0.0_qp  !! unbounded: Q = (x + P)((x - a)^2 + beta)
        real(qp) :: span = 0.0_qp              !! unbounded: start piece x - 1 = span sigma^2
        real(qp) :: rm1 = 0.0_qp, d = 0.0_qp   !! bounded: R - 1, r2 - R
    end type panel_curve

    !> Per-curve constants of the integrands (`prepare`).
    type :: prepared_curve
        type(panel_curve) :: c
        real(qp) :: k_root2 = 0.0_qp, root_span = 0.0_qp, span_root_span = 0.0_qp
        real(qp) :: root_beta = 0.0_qp, root_ratio = 0.0_qp, root_rm1 = 0.0_qp
        real(qp) :: a_m1 = 0.0_qp, inverse_root_rm1 = 0.0_qp
        !> the start piece's constant factors of theta, s, t: 2 sqrt2 K span^(3/2),
        !! 2 span, sqrt(2 span)
        real(qp) :: start_factor(3) = 0.0_qp
        !> `panel_sums`: 4 sqrt(beta), 2 sqrt(d/(R-1)), 4 (R - 1)
        real(qp) :: root_beta4 = 0.0_qp, root_ratio2 = 0.0_qp, rm1_4 = 0.0_qp
        !> hardware copies for the seeds of `panel_sums`
        real(xp) :: p_x = 0.0_xp, a_x = 0.0_xp, beta_x = 0.0_xp, span_x = 0.0_xp, &
                    a_m1_x = 0.0_xp, rm1_x = 0.0_xp, d_x = 0.0_xp, root_beta4_x = 0.0_xp, &
                    root_ratio2_x = 0.0_xp, rm1_4_x = 0.0_xp
    end type prepared_curve


contains

    !> The constants of `integrands` for one curve (square roots by `fast_sqrt`).
    pure function prepare(c) result(pc)
        type(panel_curve), intent(in) :: c
        type(prepared_curve) :: pc
        pc%c = c
        pc%k_root2 = c%k*sqrt2
        pc%root_span = fast_sqrt(c%span)
        pc%span_root_span = c%span*pc%root_span
        pc%start_factor = [pc%k_root2*2.0_qp*pc%span_root_span, 2.0_qp*c%span, &
                           sqrt2*pc%root_span]
        pc%root_beta = fast_sqrt(c%beta)
        pc%a_m1 = c%a - 1.0_qp
        if (c%bounded) then
            pc%root_rm1 = fast_sqrt(c%rm1)
            pc%inverse_root_rm1 = 1.0_qp/pc%root_rm1
            pc%root_ratio = fast_sqrt(c%d/c%rm1)
        end if
        pc%root_beta4 = 4.0_qp*pc%root_beta
        pc%root_ratio2 = 2.0_qp*pc%root_ratio
        pc%rm1_4 = 4.0_qp*c%rm1
        pc%p_x = real(c%p, xp)
        pc%a_x = real(c%a, xp)
        pc%beta_x = real(c%beta, xp)
        pc%span_x = real(c%span, xp)
        pc%a_m1_x = real(pc%a_m1, xp)
        pc%rm1_x = real(c%rm1, xp)
        pc%d_x = real(c%d, xp)
        pc%root_beta4_x = real(pc%root_beta4, xp)
        pc%root_ratio2_x = real(pc%root_ratio2, xp)
        pc%rm1_4_x = real(pc%rm1_4, xp)
    end function prepare

    !> The rules of the ladder (about a millisecond: build once, share).
    pure function new_panel_rules() result(rules)
        type(panel_rules) :: rules
        type(gauss_legendre_rule) :: g
        integer :: j
        do j = 1, size(ladder)
            g = gauss_legendre(ladder(j))
            rules%rule(j)%n = ladder(j)
            rules%rule(j)%node = 0.5_qp*(1.0_qp + g%node)
            rules%rule(j)%weight = 0.5_qp*g%weight
            rules%rule(j)%node_xp = real(rules%rule(j)%node, xp)
            rules%rule(j)%weight_xp = real(rules%rule(j)%weight, xp)
        end do
    end function new_panel_rules

    !> theta, s, t (values(1:3)) over the pieces, in binary128. status: status_ok, or
    !! status_no_convergence when a piece needs more than `max_panels` panels.
    pure subroutine panel_integrals(rules, curve, pieces, values, status, extra_digits)
        type(panel_rules), intent(in) :: rules
        type(panel_curve), intent(in) :: curve
        type(panel_piece), intent(in) :: pieces(:)
        real(qp), intent(out) :: values(3)
        integer, intent(out) :: status
        !> digits asked beyond `quad_digits` (default 0)
        real(real64), intent(in), optional :: extra_digits
        real(qp) :: lo(max_panels), hi(max_panels), sums(3), piece_sums(3)
        real(real64) :: digits
        type(prepared_curve) :: pc
        integer :: which(max_panels), count, i, j
        values = 0.0_qp
        status = status_ok
        pc = prepare(curve)
        digits = quad_digits
        if (present(extra_digits)) digits = digits + extra_digits
        do i = 1, size(pieces)
            call plan_panels(curve, pieces(i), digits + merge(stretched_extra, &
                             0.0_real64, pieces(i)%stretched), lo, hi, which, count, status)
            if (status /= status_ok) return
            piece_sums = 0.0_qp
            do j = 1, count
                call panel_sums(pc, rules%rule(which(j)), pieces(i)%kind, &
                                pieces(i)%stretched, lo(j), hi(j), sums)
                piece_sums = piece_sums + sums
            end do
            values = values + piece_factors(pc, pieces(i)%kind, pieces(i)%stretched)* &
                     piece_sums
        end do
    end subroutine panel_integrals

    !> theta over the pieces in hardware precision (about 19 digits). status as for
    !! `panel_integrals`.
    pure subroutine panel_angle_xp(rules, curve, pieces, value, status)
        type(panel_rules), intent(in) :: rules
        type(panel_curve), intent(in) :: curve
        type(panel_piece), intent(in) :: pieces(:)
        real(qp), intent(out) :: value
        integer, intent(out) :: status
        real(xp) :: lo(max_panels), hi(max_panels), c(7), total, piece_total, factor
        integer :: which(max_panels), count, i, j
        value = 0.0_qp
        status = status_ok
        c = hardware_real([curve%k, curve%p, curve%a, curve%beta, curve%span, curve%rm1, curve%d])
        total = 0.0_xp
        do i = 1, size(pieces)
            call plan_panels_xp(curve, pieces(i), hardware_digits, lo, hi, which, count, status)
            if (status /= status_ok) return
            piece_total = 0.0_xp
            do j = 1, count
                piece_total = piece_total + angle_sum_xp(c, pieces(i)%kind, &
                    pieces(i)%stretched, lo(j), hi(j) - lo(j), rules%rule(which(j)))
            end do
            select case (pieces(i)%kind)
            case (piece_start)
                factor = 2.0_xp*c(5)*sqrt(c(5))
            case (piece_below, piece_above)
                factor = merge(4.0_xp, 1.0_xp, pieces(i)%stretched)
            case (piece_far)
                factor = 1.0_xp
            case (piece_apse)
                factor = 4.0_xp*sqrt(c(6))
            case default
                factor = 4.0_xp
            end select
            total = total + factor*piece_total
        end do
        value = real(c(1)*sqrt(2.0_xp)*total, qp)
    end subroutine panel_angle_xp

    !> The derivatives of theta and s over the pieces with respect to the solver's
    !! unknown, by the complex step in hardware precision: the curve's numbers `cc`
    !! (order of `slopes_sum_c`'s c) and the pieces' ends `lower_c`, `upper_c` carry
    !! h d/dlambda in their imaginary parts; the panels and rules are those of the real
    !! pieces, their ends moved with the pieces'. slopes = Im(theta, s)/h, to about the
    !! hardware precision (no cancellation). status as for `panel_integrals`.
    pure subroutine panel_slopes_xp(rules, curve, pieces, lower_c, upper_c, cc, h, slopes, &
                                    status)
        type(panel_rules), intent(in) :: rules
        type(panel_curve), intent(in) :: curve
        type(panel_piece), intent(in) :: pieces(:)
        complex(xp), intent(in) :: lower_c(:), upper_c(:), cc(7)
        real(xp), intent(in) :: h
        real(qp), intent(out) :: slopes(2)
        integer, intent(out) :: status
        real(qp) :: lo(max_panels), hi(max_panels), length
        complex(xp) :: a, b, total(2), sum(2)
        integer :: which(max_panels), count, i, j
        slopes = 0.0_qp
        status = status_ok
        total = (0.0_xp, 0.0_xp)
        do i = 1, size(pieces)
            call plan_panels(curve, pieces(i), slope_digits, lo, hi, which, count, status)
            if (status /= status_ok) return
            length = pieces(i)%upper - pieces(i)%lower
            sum = (0.0_xp, 0.0_xp)
            do j = 1, count
                a = lower_c(i) + real((lo(j) - pieces(i)%lower)/length, xp)* &
                    (upper_c(i) - lower_c(i))
                b = lower_c(i) + real((hi(j) - pieces(i)%lower)/length, xp)* &
                    (upper_c(i) - lower_c(i))
                sum = sum + slopes_sum_c(cc, pieces(i)%kind, pieces(i)%stretched, a, b - a, &
                                         rules%rule(which(j)))
            end do
            total = total + slope_factors(cc, pieces(i)%kind, pieces(i)%stretched)*sum
        end do
        slopes = real(aimag(total)/h, qp)
    end subroutine panel_slopes_xp

    !> 1/sqrt(x) as `inverse_sqrt` (the x87 seed and one Newton step, within 2 ulp) with
    !! x/2 by `scale` (exact, half a binary128 product's cost); `inverse_sqrt` itself
    !! where the hardware kind is double or x is outside 1e-300 .. 1e300.
    elemental function rsqrt(x) result(r)
        real(qp), intent(in) :: x
        real(qp) :: r
        if (xp == real64 .or. .not. (x > 1.0e-300_qp .and. x < 1.0e300_qp)) then
            r = inverse_sqrt(x)
            return
        end if
        r = real(1.0_xp/sqrt(real(x, xp)), qp)
        r = r*(1.5_qp - scale(x, -1)*(r*r))
    end function rsqrt

    !> The weighted sums of theta's and s's integrands over one panel [a, a + width] in
    !! complex hardware precision (the maps of `integrands`), without the piece's
    !! constant factors (`slope_factors`); c = [K, P, a, beta, span, R - 1, d].
    pure function slopes_sum_c(c, kind, stretched, a, width, r) result(total)
        complex(xp), intent(in) :: c(7), a, width
        integer, intent(in) :: kind
        logical, intent(in) :: stretched
        type(panel_rule), intent(in) :: r
        complex(xp) :: total(2)
        if (kind == piece_apse .or. kind == piece_arch .or. kind == piece_arch_start) then
            total = slopes_sum_c_arch(c, kind, a, width, r)
        else
            total = slopes_sum_c_open(c, kind, stretched, a, width, r)
        end if
    end function slopes_sum_c

    !> `slopes_sum_c` on the unbounded curves' pieces.
    pure function slopes_sum_c_open(c, kind, stretched, a, width, r) result(total)
        complex(xp), intent(in) :: c(7), a, width
        integer, intent(in) :: kind
        logical, intent(in) :: stretched
        type(panel_rule), intent(in) :: r
        complex(xp) :: total(2)
        complex(xp) :: v, x, xm1, h, inv, rq, sum(2), root_beta4, am1, z
        integer :: m
        sum = (0.0_xp, 0.0_xp)
        select case (kind)
        case (piece_start)
            do m = 1, r%n
                v = a + width*r%node_xp(m)
                x = 1.0_xp + c(5)*(v*v)
                rq = r%weight_xp(m)*dual_inverse(dual_sqrt((x + c(2))*((x - c(3))**2 + &
                                                                  c(4))))
                sum(1) = sum(1) + dual_divide((v*v)*rq, x)
                sum(2) = sum(2) + v*x*dual_sqrt(x)*rq
            end do
        case (piece_below, piece_above)
            root_beta4 = 4.0_xp*dual_sqrt(c(4))
            am1 = c(3) - 1.0_xp
            do m = 1, r%n
                v = a + width*r%node_xp(m)
                if (stretched) then
                    inv = dual_inverse((1.0_xp - v)*(1.0_xp + v))
                    h = root_beta4*(v*(1.0_xp + v*v))*(inv*inv)
                    z = inv*inv
                else
                    h = v
                    z = dual_inverse(v*v + c(4))
                end if
                if (kind == piece_below) h = -h
                x = c(3) + h
                xm1 = am1 + h
                rq = r%weight_xp(m)*dual_sqrt(dual_divide(z, x + c(2)))
                sum(1) = sum(1) + dual_divide(dual_sqrt(xm1)*rq, x)
                sum(2) = sum(2) + x*dual_sqrt(x)*rq
            end do
        case (piece_far)
            do m = 1, r%n
                v = a + width*r%node_xp(m)
                x = 4.0_xp*dual_inverse(v)
                rq = r%weight_xp(m)*dual_inverse((v*v)*dual_sqrt((x + c(2))* &
                                                                  ((x - c(3))**2 + c(4))))
                sum(1) = sum(1) + dual_divide(dual_sqrt(x - 1.0_xp)*rq, x)
                sum(2) = sum(2) + x*dual_sqrt(x)*rq
            end do
        end select
        total = width*sum
    end function slopes_sum_c_open

    !> `slopes_sum_c` on the bounded curves' pieces.
    pure function slopes_sum_c_arch(c, kind, a, width, r) result(total)
        complex(xp), intent(in) :: c(7), a, width
        integer, intent(in) :: kind
        type(panel_rule), intent(in) :: r
        complex(xp) :: total(2)
        complex(xp) :: v, x, xm1, h, inv, sn, cs, rq, sum(2), ratio2
        integer :: m
        sum = (0.0_xp, 0.0_xp)
        select case (kind)
        case (piece_apse)
            ratio2 = 2.0_xp*dual_sqrt(c(7)/c(6))
            do m = 1, r%n
                v = a + width*r%node_xp(m)
                inv = dual_inverse((1.0_xp - v)*(1.0_xp + v))
                sn = ratio2*v*inv
                cs = dual_sqrt((1.0_xp - sn)*(1.0_xp + sn))
                x = 1.0_xp + c(6)*(cs*cs)
                rq = dual_divide(r%weight_xp(m)*inv, dual_sqrt(x + c(2)))
                sum(1) = sum(1) + dual_divide(cs*rq, x)
                sum(2) = sum(2) + x*dual_sqrt(x)*rq
            end do
        case default
            do m = 1, r%n
                v = a + width*r%node_xp(m)
                inv = dual_inverse(1.0_xp + v*v)
                sn = 2.0_xp*v*inv
                cs = (1.0_xp - v)*(1.0_xp + v)*inv
                if (kind == piece_arch_start) then
                    h = sn
                    sn = cs
                    cs = h
                end if
                xm1 = c(6)*(cs*cs)
                x = 1.0_xp + xm1
                rq = dual_divide(r%weight_xp(m)*inv, dual_sqrt((c(7) + c(6)*(sn*sn))* &
                                                                (x + c(2))))
                sum(1) = sum(1) + dual_divide(xm1*rq, x)
                sum(2) = sum(2) + x*dual_sqrt(x)*cs*rq
            end do
        end select
        total = width*sum
    end function slopes_sum_c_arch

    !> The constant factors of `slopes_sum_c`'s sums on a piece of this kind.
    pure function slope_factors(c, kind, stretched) result(f)
        complex(xp), intent(in) :: c(7)
        integer, intent(in) :: kind
        logical, intent(in) :: stretched
        complex(xp) :: f(2)
        complex(xp) :: k_root2
        k_root2 = c(1)*sqrt(2.0_xp)
        select case (kind)
        case (piece_start)
            f = [k_root2*2.0_xp*c(5)*dual_sqrt(c(5)), 2.0_xp*c(5)]
        case (piece_below, piece_above)
            f = [k_root2, (1.0_xp, 0.0_xp)]
            if (stretched) f = 4.0_xp*f
        case (piece_far)
            f = [4.0_xp*k_root2, (4.0_xp, 0.0_xp)]
        case (piece_apse)
            f = [4.0_xp*k_root2*dual_sqrt(c(6)), (4.0_xp, 0.0_xp)]
        case default
            f = [4.0_xp*k_root2, 4.0_xp*dual_sqrt(c(6))]
        end select
    end function slope_factors

    !> sqrt(z) for the complex step: z = x + i y with x > 0 and |y| far below x (y is
    !! h = 1e-40 times a derivative), sqrt(x) + i y/(2 sqrt(x)), exact to first order
    !! in y, as the complex step needs (libm's csqrtl at a fraction of its cost).
    elemental function dual_sqrt(z) result(r)
        complex(xp), intent(in) :: z
        complex(xp) :: r
        real(xp) :: root
        root = sqrt(real(z))
        if (root > 0.0_xp) then
            r = cmplx(root, 0.5_xp*aimag(z)/root, xp)
        else
            r = sqrt(z)
        end if
    end function dual_sqrt

    !> 1/z for the complex step (z = x + i y, |y| far below |x|): 1/x - i y/x^2, exact
    !! to first order in y (one division, not the three of a complex division).
    elemental function dual_inverse(z) result(r)
        complex(xp), intent(in) :: z
        complex(xp) :: r
        real(xp) :: inverse
        inverse = 1.0_xp/real(z)
        r = cmplx(inverse, -(aimag(z)*inverse)*inverse, xp)
    end function dual_inverse

    !> p/q for the complex step (imaginary parts far below the real ones), exact to
    !! first order in them: one division.
    elemental function dual_divide(p, q) result(r)
        complex(xp), intent(in) :: p, q
        complex(xp) :: r
        real(xp) :: inverse, re
        inverse = 1.0_xp/real(q)
        re = real(p)*inverse
        r = cmplx(re, (aimag(p) - re*aimag(q))*inverse, xp)
    end function dual_divide

    !> The panels of one piece and the rule (index into the ladder) of each, aiming at
    !! `digits`: bisection until every panel's Bernstein ellipse allows the digits with
    !! at most `max_nodes` nodes. status_no_convergence past `max_panels`.
    pure subroutine plan_panels(curve, piece, digits, lo, hi, which, count, status)
        type(panel_curve), intent(in) :: curve
        type(panel_piece), intent(in) :: piece
        real(real64), intent(in) :: digits
        real(qp), intent(out) :: lo(max_panels), hi(max_panels)
        integer, intent(out) :: which(max_panels), count, status
        complex(real64) :: points(16)
        real(qp) :: stack_lo(max_panels), stack_hi(max_panels), a, b
        integer :: top, n, np
        count = 0
        status = status_ok
        if (.not. (piece%upper > piece%lower)) return
        call singular_points(curve, piece, points, np)
        top = 1
        stack_lo(1) = piece%lower
        stack_hi(1) = piece%upper
        do while (top > 0)
            a = stack_lo(top)
            b = stack_hi(top)
            top = top - 1
            n = nodes_for(points(1:np), real(a, real64), real(b, real64), digits)
            if (n <= max_nodes .or. b - a <= 1.0e-3_qp*epsilon(1.0_real64)*abs(b)) then
                if (count >= max_panels) then
                    status = status_no_convergence
                    return
                end if
                count = count + 1
                lo(count) = a
                hi(count) = b
                which(count) = ladder_index(n)
            else
                if (top + 2 > max_panels) then
                    status = status_no_convergence
                    return
                end if
                ! the half nearer the start is integrated first (pushed last)
                stack_lo(top + 1) = 0.5_qp*(a + b)
                stack_hi(top + 1) = b
                stack_lo(top + 2) = a
                stack_hi(top + 2) = 0.5_qp*(a + b)
                top = top + 2
            end if
        end do
    end subroutine plan_panels

    !> `plan_panels` with the panels' ends in hardware precision, for the
    !! hardware-precision integrals (no binary128 arithmetic in the bisection).
    pure subroutine plan_panels_xp(curve, piece, digits, lo, hi, which, count, status)
        type(panel_curve), intent(in) :: curve
        type(panel_piece), intent(in) :: piece
        real(real64), intent(in) :: digits
        real(xp), intent(out) :: lo(max_panels), hi(max_panels)
        integer, intent(out) :: which(max_panels), count, status
        complex(real64) :: points(16)
        real(xp) :: stack_lo(max_panels), stack_hi(max_panels), a, b
        integer :: top, n, np
        count = 0
        status = status_ok
        if (.not. (piece%upper > piece%lower)) return
        call singular_points(curve, piece, points, np)
        top = 1
        stack_lo(1) = hardware_real(piece%lower)
        stack_hi(1) = hardware_real(piece%upper)
        do while (top > 0)
            a = stack_lo(top)
            b = stack_hi(top)
            top = top - 1
            n = nodes_for(points(1:np), real(a, real64), real(b, real64), digits)
            if (n <= max_nodes .or. b - a <= 1.0e-3_xp*epsilon(1.0_real64)*abs(b)) then
                if (count >= max_panels) then
                    status = status_no_convergence
                    return
                end if
                count = count + 1
                lo(count) = a
                hi(count) = b
                which(count) = ladder_index(n)
            else
                if (top + 2 > max_panels) then
                    status = status_no_convergence
                    return
                end if
                ! the half nearer the start is integrated first (pushed last)
                stack_lo(top + 1) = 0.5_xp*(a + b)
                stack_hi(top + 1) = b
                stack_lo(top + 2) = a
                stack_hi(top + 2) = 0.5_xp*(a + b)
                top = top + 2
            end if
        end do
    end subroutine plan_panels_xp

    !> The smallest rule of the ladder with at least n nodes (the largest if none).
    pure function ladder_index(n) result(j)
        integer, intent(in) :: n
        integer :: j
        do j = 1, size(ladder)
            if (ladder(j) >= n) return
        end do
        j = size(ladder)
    end function ladder_index

    !> Gauss nodes for `digits` on [a, b] given the singular points (huge if more than
    !! `max_nodes`). z -+ 1 are formed from the distances to the ends, so that a point
    !! next to an end keeps its relative distance.
    pure function nodes_for(points, a, b, digits) result(n)
        complex(real64), intent(in) :: points(:)
        real(real64), intent(in) :: a, b, digits
        integer :: n
        real(real64) :: rho, rho_min, wanted, half_sum, scale
        integer :: k
        ! the ellipse through z with foci -+1: semi-major axis (|z + 1| + |z - 1|)/2 = c,
        ! rho = c + sqrt(c^2 - 1) (no complex square roots)
        rho_min = huge(1.0_real64)
        scale = 1.0_real64/(b - a)
        do k = 1, size(points)
            half_sum = (modulus(points(k) - a) + modulus(points(k) - b))*scale
            rho = half_sum + sqrt(max((half_sum - 1.0_real64)*(half_sum + 1.0_real64), &
                                      0.0_real64))
            rho_min = min(rho_min, rho)
        end do
        n = huge(1)
        if (.not. rho_min == rho_min .or. rho_min <= 1.0_real64) return
        wanted = digits*log(10.0_real64)/(2.0_real64*log(rho_min))
        if (wanted > real(max_nodes, real64)) return
        n = max(ceiling(wanted), ladder(1))
    end function nodes_for

    !> The singular points of the piece's integrands in its variable (double precision).
    !! Every map's image of a real point is taken in real arithmetic: tanh(asinh(s)/2) =
    !! s/(1 + sqrt(1 + s^2)) =: t, and tanh((i pi - asinh(s))/2) = -1/t; for the nu map,
    !! tan(i asinh(s)/2) = i t and tan(pi/4 + i asinh(s)/2) = (1 + i t)/(1 - i t).
    pure subroutine singular_points(curve, piece, points, np)
        type(panel_curve), intent(in) :: curve
        type(panel_piece), intent(in) :: piece
        complex(real64), intent(out) :: points(16)
        integer, intent(out) :: np
        complex(real64) :: c, i1, z
        real(real64) :: a, p, w, rm1, d, s(3), x(3), t, span
        integer :: k
        i1 = (0.0_real64, 1.0_real64)
        np = 0
        points = (0.0_real64, 0.0_real64)
        p = real(curve%p, real64)
        if (.not. curve%bounded) then
            a = real(curve%a, real64)
            w = sqrt(real(curve%beta, real64))
            select case (piece%kind)
            case (piece_start)
                ! the zeros of x Q(x): 0, -P, a +- i w, at sigma = +-sqrt((x - 1)/span)
                span = real(curve%span, real64)
                do k = 1, 2
                    c = i1*sqrt((merge(0.0_real64, p, k == 1) + 1.0_real64)/span)
                    call add(points, np, c)
                    call add(points, np, -c)
                end do
                c = sqrt(cmplx(a - 1.0_real64, w, real64)/span)
                call add(points, np, c)
                call add(points, np, -c)
                call add(points, np, conjg(c))
                call add(points, np, -conjg(c))
            case (piece_far)
                call add(points, np, (0.0_real64, 0.0_real64))
                call add(points, np, cmplx(4.0_real64, 0.0_real64, real64))
                call add(points, np, cmplx(-4.0_real64/p, 0.0_real64, real64))
                if (abs(cmplx(a, w, real64)) > 0.0_real64) then
                    z = 4.0_real64/cmplx(a, w, real64)
                    call add(points, np, z)
                    call add(points, np, conjg(z))
                end if
            case default
                ! h = -+(x - a): the zeros 0, -P and x = 1 (sqrt(x - 1)); the pair at
                ! h = +-i w is cancelled by the sinh map, else a singularity of the jacobian
                x = [0.0_real64, -p, 1.0_real64]
                do k = 1, 3
                    t = merge(-1.0_real64, 1.0_real64, piece%kind == piece_below)*(x(k) - a)
                    if (piece%stretched) then
                        ! t = tanh(xi/4), xi = asinh(u) + 2 pi i m or i pi - asinh(u) +
                        ! 2 pi i m: t, 1/t, z and conj(z), z = (i - t)/(1 - i t)
                        t = quarter_tanh_64(t/w)
                        call add(points, np, cmplx(t, 0.0_real64, real64))
                        call add(points, np, cmplx(1.0_real64/t, 0.0_real64, real64))
                        z = cmplx(-2.0_real64*t, (1.0_real64 - t)*(1.0_real64 + t), real64)/ &
                            (1.0_real64 + t*t)
                        call add(points, np, z)
                        call add(points, np, conjg(z))
                    else
                        call add(points, np, cmplx(t, 0.0_real64, real64))
                    end if
                end do
                if (piece%stretched) then
                    ! the map's poles t = +-1
                    call add(points, np, (1.0_real64, 0.0_real64))
                    call add(points, np, (-1.0_real64, 0.0_real64))
                else
                    call add(points, np, i1*w)
                    call add(points, np, -i1*w)
                end if
            end select
            return
        end if
        rm1 = real(curve%rm1, real64)
        d = real(curve%d, real64)
        if (piece%kind == piece_apse) then
            ! sin(nu/2) = sqrt(d/(R-1)) sinh(xi) = +-1; x + P = 0; x = 0
            s = [sqrt(rm1/d), sqrt((1.0_real64 + rm1 + p)/d), sqrt((1.0_real64 + rm1)/d)]
            ! in w = tanh(xi/2): +-t, -1/t; the map's poles w = +-1
            do k = 1, 3
                t = half_tanh_64(s(k))
                call add(points, np, cmplx(t, 0.0_real64, real64))
                call add(points, np, cmplx(-t, 0.0_real64, real64))
                call add(points, np, cmplx(-1.0_real64/t, 0.0_real64, real64))
            end do
            call add(points, np, (1.0_real64, 0.0_real64))
            call add(points, np, (-1.0_real64, 0.0_real64))
            return
        end if
        ! nu: cos(nu) = 2 (x - 1)/(R - 1) - 1 at x = R + d (1 + 2 d/(R-1)), 0 and -P
        ! (-(1 + 2 (1 + P)/(R-1))): nu = 2i asinh(sqrt(d/(R-1))) and
        ! pi + 2i asinh(sqrt(1/(R-1))), pi + 2i asinh(sqrt((1 + P)/(R-1)))
        s = [sqrt(d/rm1), sqrt(1.0_real64/rm1), sqrt((1.0_real64 + p)/rm1)]
        ! in v = tan(nu/4) (or tan(mu/4), mu = pi - nu), each with nu + 2 pi k:
        ! tan(nu/4) and -cot(nu/4); nu = 2i asinh(s) gives +-i t, +-i/t, and nu = pi +
        ! 2i asinh(s) gives +-z, +-conj(z), z = (1 + i t)/(1 - i t) (mu = pi - nu swaps
        ! the two forms); the map's poles v = +-i
        do k = 1, 3
            t = half_tanh_64(s(k))
            if ((k == 1) .eqv. (piece%kind /= piece_arch_start)) then
                call add(points, np, cmplx(0.0_real64, t, real64))
                call add(points, np, cmplx(0.0_real64, -t, real64))
                call add(points, np, cmplx(0.0_real64, 1.0_real64/t, real64))
                call add(points, np, cmplx(0.0_real64, -1.0_real64/t, real64))
            else
                z = cmplx((1.0_real64 - t)*(1.0_real64 + t), 2.0_real64*t, real64)/ &
                    (1.0_real64 + t*t)
                call add(points, np, z)
                call add(points, np, -z)
                call add(points, np, conjg(z))
                call add(points, np, -conjg(z))
            end if
        end do
        call add(points, np, i1)
        call add(points, np, -i1)
    end subroutine singular_points

    !> tanh(asinh(s)/4) (any real s, finite): sinh(xi/2)/(1 + cosh(xi/2)).
    elemental function quarter_tanh_64(s) result(t)
        real(real64), intent(in) :: s
        real(real64) :: t, ch
        if (abs(s) < 1.0e150_real64) then
            ch = sqrt(0.5_real64*(1.0_real64 + sqrt(1.0_real64 + s*s)))
            t = 0.5_real64*s/(ch*(1.0_real64 + ch))
        else
            t = sign(1.0_real64, s)
        end if
    end function quarter_tanh_64

    !> tanh(asinh(s)/2) = s/(1 + sqrt(1 + s^2)) (any real s, finite).
    elemental function half_tanh_64(s) result(t)
        real(real64), intent(in) :: s
        real(real64) :: t
        if (abs(s) < 1.0e150_real64) then
            t = s/(1.0_real64 + sqrt(1.0_real64 + s*s))
        else
            t = sign(1.0_real64, s)
        end if
    end function half_tanh_64

    !> |z| without hypot's care for overflow and underflow where neither can happen.
    elemental function modulus(z) result(m)
        complex(real64), intent(in) :: z
        real(real64) :: m
        if (abs(real(z)) < 1.0e150_real64 .and. abs(aimag(z)) < 1.0e150_real64 .and. &
            abs(real(z)) + abs(aimag(z)) > 1.0e-150_real64) then
            m = sqrt(real(z)**2 + aimag(z)**2)
        else
            m = abs(z)
        end if
    end function modulus

    pure subroutine add(points, np, point)
        complex(real64), intent(inout) :: points(:)
        integer, intent(inout) :: np
        complex(real64), intent(in) :: point
        ! points at infinity (or not finite) bound nothing (no hypot: the parts)
        if (.not. (abs(real(point)) < huge(1.0_real64) .and. &
                   abs(aimag(point)) < huge(1.0_real64))) return
        if (np < size(points)) then
            np = np + 1
            points(np) = point
        end if
    end subroutine add

    !> theta, s, t integrands (binary128) at the piece variable v; the formulas of
    !! `brachistochrone_repulsive` (see its notes), with the maps in rational form:
    !! stretched h = sqrt(beta) 4t (1 + t^2)/(1 - t^2)^2 (t = tanh(xi/4), dxi = 4 dt/(1 -
    !! t^2));
    !! bounded sin(nu/2) = 2v/(1 + v^2), cos(nu/2) = (1 - v^2)/(1 + v^2) (v = tan(nu/4),
    !! dnu = 4 dv/(1 + v^2); swapped for mu = pi - nu); apse sin(nu/2) = c 2w/(1 - w^2).
    !! No elementary function but square roots (`inverse_sqrt`, within 2 ulp).
    pure subroutine integrands(c, piece, v, y)
        type(panel_curve), intent(in) :: c   !! the curve's numbers
        type(panel_piece), intent(in) :: piece !! kind (and stretched) of the piece
        real(qp), intent(in) :: v            !! the piece's variable
        real(qp), intent(out) :: y(3)        !! theta, s, t integrands
        call weighted_integrands(prepare(c), piece%kind, piece%stretched, v, 1.0_qp, y)
    end subroutine integrands

    !> `integrands` times the weight w, with the curve's constants prepared.
    pure subroutine weighted_integrands(pc, kind, stretched, v, w, y)
        type(prepared_curve), intent(in) :: pc
        integer, intent(in) :: kind
        logical, intent(in) :: stretched
        real(qp), intent(in) :: v, w
        real(qp), intent(out) :: y(3)
        real(qp), parameter :: half_root2 = 0.5_qp*sqrt2
        real(qp) :: point, xm1, h, sn, cs, rw, rx, ip, inv, one_minus, p2, vv, rip, q
        associate (c => pc%c)
        select case (kind)
        case (piece_start)
            ! (the constant factors folded: a binary128 product costs as much as a sum)
            vv = v*v
            xm1 = c%span*vv
            point = 1.0_qp + xm1
            rw = w*rsqrt((point + c%p)*((point - c%a)**2 + c%beta))
            ip = rsqrt(point)
            p2 = point*point
            rip = ip*rw
            y(1) = pc%start_factor(1)*vv*(ip*rip)
            y(2) = pc%start_factor(2)*v*(p2*rip)
            y(3) = pc%start_factor(3)*(p2*rw)
            return
        case (piece_below, piece_above)
            if (stretched) then
                one_minus = (1.0_qp - v)*(1.0_qp + v)
                inv = 1.0_qp/one_minus
                h = pc%root_beta4*(v*(1.0_qp + v*v))*(inv*inv)
                point = c%a + merge(-h, h, kind == piece_below)
                rw = 4.0_qp*w*inv
                q = point + c%p
            else
                h = v
                point = c%a + merge(-h, h, kind == piece_below)
                rw = w
                q = (v*v + c%beta)*(point + c%p)
            end if
            xm1 = pc%a_m1 + merge(-h, h, kind == piece_below)
        case (piece_far)
            point = far_start/v
            xm1 = point - 1.0_qp
            rw = w*far_start/(v*v)
            q = (point + c%p)*((point - c%a)**2 + c%beta)
        case default
            if (kind == piece_apse) then
                one_minus = (1.0_qp - v)*(1.0_qp + v)
                inv = 2.0_qp/one_minus
                sn = pc%root_ratio*v*inv
                one_minus = (1.0_qp - sn)*(1.0_qp + sn)
                xm1 = c%rm1*one_minus
                point = 1.0_qp + xm1
                ! cos(nu/2) = sqrt(one_minus) enters rw and s's integrand, where it
                ! cancels: two inverse square roots, 1/sqrt(one_minus q), 1/sqrt(x q)
                q = point + c%p
                h = scale(w*inv, 1)
                rw = h*pc%inverse_root_rm1*rsqrt(one_minus*q)
                ip = rsqrt(point*q)
                p2 = point*point
                y(1) = pc%k_root2*xm1*(ip*(ip*q))*rw
                y(2) = p2*(h*ip)
                y(3) = half_root2*(p2*rw)
                return
            else
                inv = 1.0_qp/(1.0_qp + v*v)
                sn = scale(v*inv, 1)
                cs = (1.0_qp - v)*(1.0_qp + v)*inv
                if (kind == piece_arch_start) then
                    h = sn
                    sn = cs
                    cs = h
                end if
                xm1 = c%rm1*cs*cs
                point = 1.0_qp + xm1
                rw = scale(w*inv, 2)*rsqrt((c%d + c%rm1*sn*sn)*(point + c%p))
            end if
            ip = rsqrt(point)
            p2 = point*point
            rip = ip*rw
            y(1) = pc%k_root2*xm1*(ip*rip)
            y(2) = (pc%root_rm1*cs)*(p2*rip)
            y(3) = half_root2*(p2*rw)
            return
        end select
        ! unbounded pieces beyond the start: rw is the weight and jacobian, q the rest of
        ! Q (as in the start piece); two square roots, 1/sqrt(q (x - 1)) and
        ! 1/sqrt(q x), and 1/x = q/sqrt(q x)^2, instead of three
        rx = rsqrt(q*xm1)*rw
        ip = rsqrt(q*point)
        rip = ip*rw
        p2 = point*point
        y(1) = pc%k_root2*(xm1*rx)*(ip*(ip*q))
        y(2) = p2*rip
        y(3) = half_root2*(p2*rx)
        end associate
    end subroutine weighted_integrands

    !> One panel [lo, hi] of a piece for `panel_integrals`: width times the weighted sum
    !! of theta's, s's and t's integrands over the rule r, each integrand divided by its
    !! constant factor (`piece_factors`). The node's geometry is formed in binary128 and,
    !! in parallel, in hardware precision for the seeds of the square roots (`heron`:
    !! a division and a sum each), so that no binary128 number is converted per node.
    !! One loop per piece kind.
    pure subroutine panel_sums(pc, r, kind, stretched, lo, hi, sums)
        type(prepared_curve), intent(in) :: pc
        type(panel_rule), intent(in) :: r
        integer, intent(in) :: kind
        logical, intent(in) :: stretched
        real(qp), intent(in) :: lo, hi
        real(qp), intent(out) :: sums(3)
        real(qp) :: width
        real(xp) :: lo_x, width_x
        width = hi - lo
        lo_x = hardware_real(lo)
        width_x = hardware_real(width)
        select case (kind)
        case (piece_start)
            call start_sums(pc, r, lo, width, lo_x, width_x, sums)
        case (piece_below, piece_above, piece_far)
            call peak_sums(pc, r, kind, stretched, lo, width, lo_x, width_x, sums)
        case (piece_apse)
            call apse_sums(pc, r, lo, width, lo_x, width_x, sums)
        case default
            call arch_sums(pc, r, kind, lo, width, lo_x, width_x, sums)
        end select
        sums = width*sums
    end subroutine panel_sums

    !> `panel_sums` on the start piece (unbounded): x - 1 = span sigma^2.
    pure subroutine start_sums(pc, r, lo, width, lo_x, width_x, sums)
        type(prepared_curve), intent(in) :: pc
        type(panel_rule), intent(in) :: r
        real(qp), intent(in) :: lo, width
        real(xp), intent(in) :: lo_x, width_x
        real(qp), intent(out) :: sums(3)
        real(qp) :: v, a, x, q, g, t, hx
        real(xp) :: vx, xx, qx
        integer :: m
        sums = 0.0_qp
        do m = 1, r%n
            v = lo + width*r%node(m)
            vx = lo_x + width_x*r%node_xp(m)
            a = v*v
            x = 1.0_qp + pc%c%span*a
            q = (x + pc%c%p)*((x - pc%c%a)**2 + pc%c%beta)
            xx = 1.0_xp + pc%span_x*(vx*vx)
            qx = (xx + pc%p_x)*((xx - pc%a_x)**2 + pc%beta_x)
            ! g = w/(2 sqrt(q)), hx = 2 sqrt(x)
            g = r%weight(m)/heron(q, sqrt(qx))
            hx = heron(x, sqrt(xx))
            t = (x*x)*g
            sums(1) = sums(1) + (a*g)/x
            sums(2) = sums(2) + (v*t)/hx
            sums(3) = sums(3) + t
        end do
        sums = [4.0_qp, 16.0_qp, 4.0_qp]*sums
    end subroutine start_sums

    !> `panel_sums` on the unbounded curve's pieces beyond the start: below or above the
    !! peak (h = -+(x - a), in the sinh map when stretched) and far out (x = 4/z).
    pure subroutine peak_sums(pc, r, kind, stretched, lo, width, lo_x, width_x, sums)
        type(prepared_curve), intent(in) :: pc
        type(panel_rule), intent(in) :: r
        integer, intent(in) :: kind
        logical, intent(in) :: stretched
        real(qp), intent(in) :: lo, width
        real(xp), intent(in) :: lo_x, width_x
        real(qp), intent(out) :: sums(3)
        real(qp) :: v, w, x, xm1, q, h, inv, h1, xw
        real(xp) :: vx, xx, xm1x, qx, hx, invx
        integer :: m
        sums = 0.0_qp
        do m = 1, r%n
            v = lo + width*r%node(m)
            vx = lo_x + width_x*r%node_xp(m)
            if (kind == piece_far) then
                x = far_start/v
                xm1 = x - 1.0_qp
                w = r%weight(m)*(x*x)
                q = (x + pc%c%p)*((x - pc%c%a)**2 + pc%c%beta)
                xx = 4.0_xp/vx
                xm1x = xx - 1.0_xp
                qx = (xx + pc%p_x)*((xx - pc%a_x)**2 + pc%beta_x)
            else
                if (stretched) then
                    ! h = sqrt(beta) 4t (1 + t^2)/(1 - t^2)^2, dxi = 4 dt/(1 - t^2)
                    h = (1.0_qp - v)*(1.0_qp + v)
                    inv = 1.0_qp/h
                    ! 1 + v^2 = 2 - (1 - v^2)
                    h = pc%root_beta4*(v*(2.0_qp - h))*(inv*inv)
                    w = r%weight(m)*inv
                    invx = 1.0_xp/((1.0_xp - vx)*(1.0_xp + vx))
                    hx = pc%root_beta4_x*(vx*(1.0_xp + vx*vx))*(invx*invx)
                else
                    h = v
                    w = r%weight(m)
                    hx = vx
                end if
                if (kind == piece_below) then
                    h = -h
                    hx = -hx
                end if
                x = pc%c%a + h
                xm1 = pc%a_m1 + h
                q = x + pc%c%p
                xx = pc%a_x + hx
                xm1x = pc%a_m1_x + hx
                qx = xx + pc%p_x
                if (.not. stretched) then
                    q = (v*v + pc%c%beta)*q
                    qx = (vx*vx + pc%beta_x)*qx
                end if
            end if
            ! h1 = 2 sqrt(q (x - 1)), 2 sqrt(q x)
            h1 = heron(q*xm1, sqrt(qx*xm1x))
            xw = (x*x)*w
            sums(1) = sums(1) + (xm1*w)/(x*h1)
            sums(2) = sums(2) + xw/heron(q*x, sqrt(qx*xx))
            sums(3) = sums(3) + xw/h1
        end do
        sums = 4.0_qp*sums
    end subroutine peak_sums

    !> `panel_sums` on the apse's sinh map (bounded): sin(nu/2) = c 2w/(1 - w^2);
    !! 1/sqrt((1 - sn^2) q) in place of 1/sqrt(q (x - 1)), x - 1 = rm1 (1 - sn^2).
    pure subroutine apse_sums(pc, r, lo, width, lo_x, width_x, sums)
        type(prepared_curve), intent(in) :: pc
        type(panel_rule), intent(in) :: r
        real(qp), intent(in) :: lo, width
        real(xp), intent(in) :: lo_x, width_x
        real(qp), intent(out) :: sums(3)
        real(qp) :: v, w, x, xm1, q, inv, h1, xw, a, b
        real(xp) :: vx, xx, qx, invx, ax, bx
        integer :: m
        sums = 0.0_qp
        do m = 1, r%n
            v = lo + width*r%node(m)
            vx = lo_x + width_x*r%node_xp(m)
            inv = 1.0_qp/((1.0_qp - v)*(1.0_qp + v))
            a = pc%root_ratio2*v*inv
            b = (1.0_qp - a)*(1.0_qp + a)
            xm1 = pc%c%rm1*b
            x = 1.0_qp + xm1
            q = x + pc%c%p
            w = r%weight(m)*inv
            invx = 1.0_xp/((1.0_xp - vx)*(1.0_xp + vx))
            ax = pc%root_ratio2_x*vx*invx
            bx = (1.0_xp - ax)*(1.0_xp + ax)
            xx = 1.0_xp + pc%rm1_x*bx
            qx = xx + pc%p_x
            ! h1 = 2 sqrt(b q), 2 sqrt(x q)
            h1 = heron(b*q, sqrt(bx*qx))
            xw = (x*x)*w
            sums(1) = sums(1) + (xm1*w)/(x*h1)
            sums(2) = sums(2) + xw/heron(x*q, sqrt(xx*qx))
            sums(3) = sums(3) + xw/h1
        end do
        sums = 4.0_qp*sums
    end subroutine apse_sums

    !> `panel_sums` on the nu map (bounded): v = tan(nu/4), or tan(mu/4), mu = pi - nu,
    !! next to the start (piece_arch_start).
    pure subroutine arch_sums(pc, r, kind, lo, width, lo_x, width_x, sums)
        type(prepared_curve), intent(in) :: pc
        type(panel_rule), intent(in) :: r
        integer, intent(in) :: kind
        real(qp), intent(in) :: lo, width
        real(xp), intent(in) :: lo_x, width_x
        real(qp), intent(out) :: sums(3)
        real(qp) :: v, x, xm1, q, inv, g, t, a, b, vv
        real(xp) :: vx, xx, xm1x, qx, invx, ax, bx
        integer :: m
        sums = 0.0_qp
        do m = 1, r%n
            v = lo + width*r%node(m)
            vx = lo_x + width_x*r%node_xp(m)
            vv = v*v
            inv = 1.0_qp/(1.0_qp + vv)
            a = v*inv
            ! (1 - v^2 to a rounding of 1 where v -> 1: b then weights the terms)
            b = (1.0_qp - vv)*inv
            invx = 1.0_xp/(1.0_xp + vx*vx)
            ax = vx*invx
            bx = (1.0_xp - vx)*(1.0_xp + vx)*invx
            if (kind == piece_arch) then
                xm1 = pc%c%rm1*(b*b)
                q = pc%c%d + pc%rm1_4*(a*a)
                xm1x = pc%rm1_x*(bx*bx)
                qx = pc%d_x + pc%rm1_4_x*(ax*ax)
            else
                xm1 = pc%rm1_4*(a*a)
                q = pc%c%d + pc%c%rm1*(b*b)
                xm1x = pc%rm1_4_x*(ax*ax)
                qx = pc%d_x + pc%rm1_x*(bx*bx)
                b = a
            end if
            x = 1.0_qp + xm1
            xx = 1.0_xp + xm1x
            q = q*(x + pc%c%p)
            qx = qx*(xx + pc%p_x)
            ! g = w inv/(2 sqrt(q)); theta's 1/x^(3/2) as (1/sqrt(x))^2 (1/sqrt(x))
            g = (r%weight(m)*inv)/heron(q, sqrt(qx))
            t = (x*x)*g
            sums(1) = sums(1) + (xm1*g)/x
            sums(2) = sums(2) + (b*t)/heron(x, sqrt(xx))
            sums(3) = sums(3) + t
        end do
        sums = [16.0_qp, 16.0_qp, 4.0_qp]*sums
    end subroutine arch_sums

    !> The constant factors of theta's, s's and t's integrands taken out of
    !! `panel_sums`' terms on a piece of this kind.
    pure function piece_factors(pc, kind, stretched) result(f)
        type(prepared_curve), intent(in) :: pc
        integer, intent(in) :: kind
        logical, intent(in) :: stretched
        real(qp) :: f(3)
        real(qp), parameter :: half_root2 = 0.5_qp*sqrt2
        select case (kind)
        case (piece_start)
            f = [pc%k_root2*pc%span_root_span, 0.5_qp*pc%c%span, &
                 half_root2*pc%root_span]
        case (piece_below, piece_above)
            f = [2.0_qp*pc%k_root2, 2.0_qp, sqrt2]
            if (.not. stretched) f = 0.25_qp*f
        case (piece_far)
            f = [0.125_qp*pc%k_root2, 0.125_qp, sqrt2/16.0_qp]
        case (piece_apse)
            f = [2.0_qp*pc%k_root2*pc%inverse_root_rm1, 2.0_qp, sqrt2*pc%inverse_root_rm1]
        case (piece_arch)
            f = [0.5_qp*pc%k_root2, pc%root_rm1, sqrt2]
        case default
            f = [0.5_qp*pc%k_root2, 2.0_qp*pc%root_rm1, sqrt2]
        end select
    end function piece_factors

    !> 2 sqrt(x) from a hardware-precision seed of sqrt(x) (relative error about 1e-18
    !! on x87): one Heron step s + x/s, error about e^2/2 plus a rounding of the
    !! division and of the sum (a second step where the hardware kind is double);
    !! from `inverse_sqrt` where the seed is out of the hardware's range.
    elemental function heron(x, seed) result(r)
        real(qp), intent(in) :: x
        real(xp), intent(in) :: seed
        real(qp) :: r
        if (.not. (seed > 0.0_xp .and. seed < huge(1.0_xp))) then
            r = 0.0_qp
            if (x > 0.0_qp) r = 2.0_qp*(x*inverse_sqrt(x))
            return
        end if
        r = quad_real(seed)
        if (digits(1.0_xp) < 60) r = 0.5_qp*(r + x/r)
        r = r + x/r
    end function heron

    !> The weighted sum of theta's integrand over one panel [start, start + width] in
    !! hardware precision (the maps of `integrands`), without the piece's constant
    !! factor (`panel_angle_xp`): one square root and one or two divisions a node.
    !! c = [K, P, a, beta, span, R - 1, d].
    pure function angle_sum_xp(c, kind, stretched, start, width, r) result(total)
        real(xp), intent(in) :: c(7), start, width
        integer, intent(in) :: kind
        logical, intent(in) :: stretched
        type(panel_rule), intent(in) :: r
        real(xp) :: total
        if (kind == piece_apse .or. kind == piece_arch .or. kind == piece_arch_start) then
            total = angle_sum_xp_arch(c, kind, start, width, r)
        else
            total = angle_sum_xp_open(c, kind, stretched, start, width, r)
        end if
    end function angle_sum_xp

    !> `angle_sum_xp` on the unbounded curves' pieces.
    pure function angle_sum_xp_open(c, kind, stretched, start, width, r) result(total)
        real(xp), intent(in) :: c(7), start, width
        integer, intent(in) :: kind
        logical, intent(in) :: stretched
        type(panel_rule), intent(in) :: r
        real(xp) :: total
        real(xp) :: v, x, xm1, h, inv, z, sum, root_beta4, am1
        integer :: m
        sum = 0.0_xp
        select case (kind)
        case (piece_start)
            do m = 1, r%n
                v = start + width*r%node_xp(m)
                x = 1.0_xp + c(5)*(v*v)
                sum = sum + r%weight_xp(m)*(v*v)/(x*sqrt((x + c(2))*((x - c(3))**2 + c(4))))
            end do
        case (piece_below, piece_above)
            root_beta4 = 4.0_xp*sqrt(c(4))
            am1 = c(3) - 1.0_xp
            do m = 1, r%n
                v = start + width*r%node_xp(m)
                if (stretched) then
                    inv = 1.0_xp/((1.0_xp - v)*(1.0_xp + v))
                    h = root_beta4*(v*(1.0_xp + v*v))*(inv*inv)
                    z = inv*inv
                else
                    h = v
                    z = 1.0_xp/(v*v + c(4))
                end if
                if (kind == piece_below) h = -h
                x = c(3) + h
                xm1 = am1 + h
                sum = sum + r%weight_xp(m)*sqrt(z*xm1/((x + c(2))*(x*x)))
            end do
        case (piece_far)
            do m = 1, r%n
                v = start + width*r%node_xp(m)
                x = 4.0_xp/v
                sum = sum + r%weight_xp(m)*sqrt((x - 1.0_xp)/((x + c(2))* &
                      ((x - c(3))**2 + c(4))*(v*v)))
            end do
        end select
        total = width*sum
    end function angle_sum_xp_open

    !> `angle_sum_xp` on the bounded curves' pieces.
    pure function angle_sum_xp_arch(c, kind, start, width, r) result(total)
        real(xp), intent(in) :: c(7), start, width
        integer, intent(in) :: kind
        type(panel_rule), intent(in) :: r
        real(xp) :: total
        real(xp) :: v, x, xm1, inv, sn, b, z, sum, ratio2, rm1_4
        integer :: m
        sum = 0.0_xp
        select case (kind)
        case (piece_apse)
            ratio2 = 2.0_xp*sqrt(c(7)/c(6))
            do m = 1, r%n
                v = start + width*r%node_xp(m)
                inv = 1.0_xp/((1.0_xp - v)*(1.0_xp + v))
                sn = ratio2*v*inv
                b = (1.0_xp - sn)*(1.0_xp + sn)
                x = 1.0_xp + c(6)*b
                sum = sum + r%weight_xp(m)*inv*sqrt(b/((x + c(2))*(x*x)))
            end do
        case default
            rm1_4 = 4.0_xp*c(6)
            do m = 1, r%n
                v = start + width*r%node_xp(m)
                inv = 1.0_xp/(1.0_xp + v*v)
                sn = v*inv
                b = (1.0_xp - v)*(1.0_xp + v)*inv
                if (kind == piece_arch) then
                    xm1 = c(6)*(b*b)
                    z = c(7) + rm1_4*(sn*sn)
                else
                    xm1 = rm1_4*(sn*sn)
                    z = c(7) + c(6)*(b*b)
                end if
                x = 1.0_xp + xm1
                sum = sum + r%weight_xp(m)*(xm1*inv)/sqrt((x*x)*z*(x + c(2)))
            end do
        end select
        total = width*sum
    end function angle_sum_xp_arch


end module brachistochrone_repulsive_panels
