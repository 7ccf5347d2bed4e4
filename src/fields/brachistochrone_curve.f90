!> Points along a brachistochrone from A, at equal steps of arclength (Tee 1998, sec. 2-4).
!!
!! A curve is sampled from A = (1, 0) to its end B: the endpoint of a solved two-point
!! problem, or A' at radius 1 for the complete brachistochrone with apse radius R. Each
!! point carries r, theta, s, t and Cartesian x = r cos(theta), y = r sin(theta), all
!! evaluated at the same radius r by the library's quadrature, to full quad precision.
!!
!! Spacing. A, the apse (when the curve passes it) and B are points of the sample. The
!! intervals are shared between the two half-arches in proportion to their arclengths,
!! and within a half-arch the points are at equal steps of s (so the steps of the two
!! halves differ only by the rounding of that share: for the complete arch with an even
!! number of intervals they are equal). With 2 points the sample is A and B only.
!!
!! Inversion. The radius where S(r,R) = s_k (or 2 S(R,R) - S(r,R) = s_k after the apse) is
!! found by a safeguarded Newton iteration in the unknown u = sqrt(r - R): with (21),
!! ds/dr = -1/sqrt(1 - K^2 v^2/r^2) and K^2 v^2/r^2 = R^3 (1-r)/((1-R) r^3), so
!! 1 - K^2 v^2/r^2 = (r - R) p(r)/r^3, p(r) = r^2 + R r + R^2/(1-R), and
!!
!!     ds/du = -+ 2 r^(3/2) / sqrt(p(r))        (r = R + u^2),
!!
!! finite and smooth through the apse (u = 0), where ds/dr is infinite. The first
!! iterate extrapolates u(s) quadratically from the previous points; Newton runs on the
!! 17-digit rules until a step moves r by less than 1e-8 r (the next iterate is then as
!! good as those rules), then on the full rules, on the whole bracket again, until the
!! next step would move r by less than eps r: about one 17-digit and two full
!! evaluations per point. A point is a representable radius r, and d = r - R (exact near
!! the apse) is what `evaluate_arch` gets, so theta, s, t are those of that r; s then
!! meets its target to within |ds/dr| ulp(r), which near the apse exceeds eps s. The
!! derivative only steers the iteration: every reported value is a quadrature at r.
!!
!! Radial fall (psi = 0, R = 0) samples the segment r = 1 - s. The apsidal locus
!! (theta = Theta(R,R), r = R, for given R) comes with S(R,R) and T(R,R).
module brachistochrone_curve
    use brachistochrone_kinds, only: qp, eps_qp
    use brachistochrone_status, only: status_ok, status_invalid_argument, &
                                      status_not_finite, status_no_convergence
    use brachistochrone_closed_forms, only: radial_time
    use brachistochrone_inverse_square, only: inverse_square_model, evaluate_arch, arch_values, &
            level_fine, &
            level_coarse
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_arches, only: arch_first, arch_second, arch_complete, arch_radial
    use brachistochrone_roots, only: root_function, newton_bracketed
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    public :: curve_samples, sample_endpoint_curve, sample_complete_arch, apsidal_locus
    public :: min_curve_points

    !> Fewest points of a sampled curve (A and B).
    integer, parameter :: min_curve_points = 2

    !> Root-finder evaluations allowed per point and phase.
    integer, parameter :: max_iterations = 300
    !> Relative Newton step in u below which the 17-digit phase hands over to the full
    !! rules (the error after it is about the step squared times the curvature).
    real(qp), parameter :: coarse_tolerance = 1.0e-8_qp

    !> Points along one curve, from A (index 1) to its end (index n).
    type :: curve_samples
        integer :: n = 0                    !! number of points (0 when there is no curve)
        integer :: status = status_ok       !! status_ok, or why there is no curve
        real(qp) :: apse_radius = 0.0_qp    !! R of the curve (0 for radial fall)
        integer :: apse_index = 0           !! index of the apse point (0: not sampled)
        real(qp), allocatable :: r(:)       !! radius
        real(qp), allocatable :: theta(:)   !! polar angle from OA (radians)
        real(qp), allocatable :: s(:)       !! arclength from A
        real(qp), allocatable :: t(:)       !! time from A
        real(qp), allocatable :: x(:)       !! r cos(theta)
        real(qp), allocatable :: y(:)       !! r sin(theta)
    end type curve_samples

    !> One point of a half-arch with the unknown that found it.
    type :: arch_point
        real(qp) :: u = 0.0_qp      !! sqrt(r - R)
        real(qp) :: r = 0.0_qp      !! radius
        real(qp) :: theta = 0.0_qp  !! angle
        real(qp) :: s = 0.0_qp      !! arclength
        real(qp) :: t = 0.0_qp      !! time
        real(qp) :: slope = 0.0_qp  !! ds/du
    end type arch_point

    !> The brachistochrone being sampled.
    type :: arch_shape
        real(qp) :: big_r = 0.0_qp            !! apse radius R
        real(qp) :: one_minus_big_r = 0.0_qp  !! 1 - R
    end type arch_shape

    !> Arclength from A minus a target, as a function of u on one half-arch.
    type, extends(root_function) :: arclength_gap
        type(inverse_square_model) :: model   !! the evaluator
        type(arch_shape) :: shape             !! the curve
        integer :: level = level_coarse       !! precision of the rules
        logical :: second = .false.           !! second half-arch
        real(qp) :: target = 0.0_qp           !! the arclength wanted
    contains
        procedure :: evaluate => arclength_gap_evaluate
    end type arclength_gap

contains

    !> The curve from A to a solved endpoint B, with `points` points (>= 2). Radial fall
    !! samples the segment from A to B. No curve (n = 0, the solution's status) when the
    !! endpoint has none: inaccessible, or not solved.
    pure function sample_endpoint_curve(model, solution, points) result(samples)
        type(inverse_square_model), intent(in) :: model !! the evaluator
        type(endpoint_solution), intent(in) :: solution !! from solve_endpoint
        integer, intent(in) :: points                   !! number of points, >= 2
        type(curve_samples) :: samples

        if (points < min_curve_points) then
            samples = no_curve(status_invalid_argument)
        else if (solution%status /= status_ok .or. .not. solution%has_apse_radius) then
            samples = no_curve(merge(solution%status, status_invalid_argument, &
                                     solution%status /= status_ok))
        else if (solution%arch == arch_radial) then
            samples = sample_radial(solution%rho, points)
        else if (solution%arch == arch_first .or. solution%arch == arch_second .or. &
                 solution%arch == arch_complete) then
            samples = sample_arch(model, solution%apse_radius, &
                                  (1.0_qp - solution%rho) + solution%apse_gap, &
                                  solution%arch /= arch_first, solution%rho, &
                                  solution%apse_gap, points)
        else
            samples = no_curve(status_invalid_argument)
        end if
    end function sample_endpoint_curve

    !> The complete brachistochrone with apse radius R, 0 < R < 1: from A over the apse
    !! to A' at radius 1 and angle 2 Theta(R,R), with `points` points (>= 2; an odd number
    !! puts the apse in the middle with equal steps on both halves).
    pure function sample_complete_arch(model, big_r, points) result(samples)
        type(inverse_square_model), intent(in) :: model !! the evaluator
        real(qp), intent(in) :: big_r                   !! apse radius R
        integer, intent(in) :: points                   !! number of points, >= 2
        type(curve_samples) :: samples

        if (.not. ieee_is_finite(big_r)) then
            samples = no_curve(status_not_finite)
        else if (big_r <= 0.0_qp .or. big_r >= 1.0_qp .or. points < min_curve_points) then
            samples = no_curve(status_invalid_argument)
        else
            samples = sample_arch(model, big_r, 1.0_qp - big_r, .true., 1.0_qp, &
                                  1.0_qp - big_r, points)
        end if
    end function sample_complete_arch

    !> Points of the apsidal locus theta = Theta(R,R) (eq. 66), r = R, one per given apse
    !! radius 0 < R <= 1 (R = 1 is A itself), with s = S(R,R) and t = T(R,R) at the apse.
    !! `apse_index` is 0. The locus runs from A (R = 1) towards O at angle pi/3 (R -> 0).
    pure function apsidal_locus(model, big_r) result(samples)
        type(inverse_square_model), intent(in) :: model !! the evaluator
        real(qp), intent(in) :: big_r(:)                !! apse radii, 0 < R <= 1
        type(curve_samples) :: samples
        type(arch_values) :: values
        integer :: k

        if (.not. all(ieee_is_finite(big_r))) then
            samples = no_curve(status_not_finite)
            return
        else if (any(big_r <= 0.0_qp .or. big_r > 1.0_qp)) then
            samples = no_curve(status_invalid_argument)
            return
        end if
        call allocate_points(samples, size(big_r))
        do k = 1, size(big_r)
            samples%r(k) = big_r(k)
            if (big_r(k) == 1.0_qp) then
                samples%theta(k) = 0.0_qp
                samples%s(k) = 0.0_qp
                samples%t(k) = 0.0_qp
            else
                values = evaluate_arch(model, level_fine, .false., big_r(k), big_r(k), &
                                             0.0_qp, .false., .true.)
                samples%theta(k) = values%angle
                samples%s(k) = values%arclength
                samples%t(k) = values%time
            end if
        end do
        call set_cartesian(samples)
    end function apsidal_locus

    !> A curve object with no points and the given status.
    pure function no_curve(status) result(samples)
        integer, intent(in) :: status
        type(curve_samples) :: samples
        call allocate_points(samples, 0)
        samples%status = status
    end function no_curve

    pure subroutine allocate_points(samples, n)
        type(curve_samples), intent(inout) :: samples
        integer, intent(in) :: n
        samples%n = n
        allocate (samples%r(n), samples%theta(n), samples%s(n), samples%t(n), &
                  samples%x(n), samples%y(n))
        samples%r = 0.0_qp
        samples%theta = 0.0_qp
        samples%s = 0.0_qp
        samples%t = 0.0_qp
        samples%x = 0.0_qp
        samples%y = 0.0_qp
    end subroutine allocate_points

    pure subroutine set_cartesian(samples)
        type(curve_samples), intent(inout) :: samples
        samples%x = samples%r*cos(samples%theta)
        samples%y = samples%r*sin(samples%theta)
    end subroutine set_cartesian

    !> Radial fall from A to radius rho (eq. 45-46): r = 1 - s, theta = 0, t = t(r),
    !! at equal steps of s; the last point is r = rho exactly.
    pure function sample_radial(rho, points) result(samples)
        real(qp), intent(in) :: rho
        integer, intent(in) :: points
        type(curve_samples) :: samples
        integer :: k
        call allocate_points(samples, points)
        samples%apse_radius = 0.0_qp
        do k = 1, points
            if (k == points) then
                samples%r(k) = rho
            else
                samples%r(k) = 1.0_qp - (1.0_qp - rho)*real(k - 1, qp)/real(points - 1, qp)
            end if
            samples%s(k) = 1.0_qp - samples%r(k)
            samples%t(k) = radial_time(samples%r(k))
        end do
        call set_cartesian(samples)
    end function sample_radial

    !> The curve from A over the brachistochrone with apse R to the point at radius
    !! end_r = R + end_gap, on the first (end_second = .false.) or second half-arch.
    pure function sample_arch(model, big_r, one_minus_big_r, end_second, end_r, end_gap, &
                              points) result(samples)
        type(inverse_square_model), intent(in) :: model
        real(qp), intent(in) :: big_r, one_minus_big_r, end_r, end_gap
        logical, intent(in) :: end_second
        integer, intent(in) :: points
        type(curve_samples) :: samples
        type(arch_shape) :: shape
        type(arch_values) :: values
        type(arch_point) :: start, apse, finish
        integer :: intervals, first_intervals, second_intervals, status

        shape%big_r = big_r
        shape%one_minus_big_r = one_minus_big_r
        call allocate_points(samples, points)
        samples%apse_radius = big_r
        intervals = points - 1

        ! A, and the end B evaluated where the solver evaluated it
        start%u = sqrt(one_minus_big_r)
        start%r = 1.0_qp
        start%slope = arclength_slope(shape, 1.0_qp, .false.)
        values = evaluate_arch(model, level_fine, end_second, end_r, big_r, end_gap, &
                                     .false., .true.)
        finish = arch_point(sqrt(end_gap), end_r, values%angle, values%arclength, &
                            values%time, arclength_slope(shape, end_r, end_second))
        call put_point(samples, 1, start)
        call put_point(samples, points, finish)
        status = status_ok
        if (intervals == 1) then
            ! A and B only
        else if (.not. end_second) then
            call fill(model, shape, samples, start, finish, .false., 1, intervals, status)
        else
            values = evaluate_arch(model, level_fine, .false., big_r, big_r, 0.0_qp, &
                                         .false., .true.)
            apse = arch_point(0.0_qp, big_r, values%angle, values%arclength, values%time, &
                              arclength_slope(shape, big_r, .true.))
            call split(apse%s, finish%s - apse%s, intervals, first_intervals, &
                       second_intervals)
            samples%apse_index = first_intervals + 1
            call put_point(samples, samples%apse_index, apse)
            call fill(model, shape, samples, start, apse, .false., 1, first_intervals, &
                      status)
            if (status == status_ok) then
                call fill(model, shape, samples, apse, finish, .true., samples%apse_index, &
                          second_intervals, status)
            end if
        end if
        if (status /= status_ok) then
            samples = no_curve(status)
            return
        end if
        call set_cartesian(samples)
    end function sample_arch

    !> Store a point at index k.
    pure subroutine put_point(samples, k, point)
        type(curve_samples), intent(inout) :: samples
        integer, intent(in) :: k
        type(arch_point), intent(in) :: point
        samples%r(k) = point%r
        samples%theta(k) = point%theta
        samples%s(k) = point%s
        samples%t(k) = point%t
    end subroutine put_point

    !> Points first + 1 .. first + m - 1 between `from` (index first) and `to` (index
    !! first + m) on one half-arch, at equal steps of s.
    pure subroutine fill(model, shape, samples, from, to, second, first, m, status)
        type(inverse_square_model), intent(in) :: model
        type(arch_shape), intent(in) :: shape
        type(curve_samples), intent(inout) :: samples
        type(arch_point), intent(in) :: from, to
        logical, intent(in) :: second
        integer, intent(in) :: first, m
        integer, intent(out) :: status
        type(arch_point) :: previous, before, point
        real(qp) :: target, step, lo, hi, guess, g1, g0
        integer :: k
        status = status_ok
        previous = from
        before = from
        do k = 1, m - 1
            target = from%s + (to%s - from%s)*real(k, qp)/real(m, qp)
            ! u(s) extrapolated from the last two points (du/ds = 1/slope)
            step = target - previous%s
            g1 = 1.0_qp/previous%slope
            guess = previous%u + step*g1
            if (k > 1) then
                g0 = 1.0_qp/before%slope
                guess = guess + 0.5_qp*step*step*(g1 - g0)/(previous%s - before%s)
            end if
            ! u decreases along the first half-arch and increases along the second
            lo = min(previous%u, to%u)
            hi = max(previous%u, to%u)
            call invert_arclength(model, shape, second, target, lo, hi, guess, point, status)
            if (status /= status_ok) return
            call put_point(samples, first + k, point)
            before = previous
            previous = point
        end do
    end subroutine fill

    !> Share `intervals` (>= 2) between half-arches of lengths l1 and l2: each gets at
    !! least one, and the two steps l1/n1, l2/n2 are as close as the counts allow.
    pure subroutine split(l1, l2, intervals, n1, n2)
        real(qp), intent(in) :: l1, l2
        integer, intent(in) :: intervals
        integer, intent(out) :: n1, n2
        real(qp) :: share, best, ratio
        integer :: candidate
        share = real(intervals, qp)*l1/(l1 + max(l2, 0.0_qp))
        n1 = max(1, min(intervals - 1, nint(share)))
        best = huge(1.0_qp)
        do candidate = max(1, floor(share)), min(intervals - 1, ceiling(share))
            ratio = step_ratio(candidate)
            if (ratio < best) then
                best = ratio
                n1 = candidate
            end if
        end do
        n2 = intervals - n1
    contains
        pure real(qp) function step_ratio(k)
            integer, intent(in) :: k
            real(qp) :: h1, h2
            h1 = l1/real(k, qp)
            h2 = max(l2, 0.0_qp)/real(intervals - k, qp)
            step_ratio = max(h1, h2)/max(min(h1, h2), tiny(1.0_qp))
        end function step_ratio
    end subroutine split

    !> ds/du at radius r, u = sqrt(r - R): -+ 2 r^(3/2)/sqrt(r^2 + R r + R^2/(1-R)).
    pure function arclength_slope(shape, r, second) result(slope)
        type(arch_shape), intent(in) :: shape
        real(qp), intent(in) :: r
        logical, intent(in) :: second
        real(qp) :: slope
        slope = 2.0_qp*r*sqrt(r)/sqrt(r*(r + shape%big_r) &
                                      + shape%big_r*shape%big_r/shape%one_minus_big_r)
        if (.not. second) slope = -slope
    end function arclength_slope

    !> The point at u on one half-arch, on the rules of `level`.
    pure function arch_point_at(model, shape, level, second, u) result(point)
        type(inverse_square_model), intent(in) :: model
        type(arch_shape), intent(in) :: shape
        integer, intent(in) :: level
        logical, intent(in) :: second
        real(qp), intent(in) :: u
        type(arch_point) :: point
        type(arch_values) :: values
        real(qp) :: r
        r = min(1.0_qp, shape%big_r + u*u)
        ! r - R is exact where it is small (r <= 2R), so R + (r - R) = r
        values = evaluate_arch(model, level, second, r, shape%big_r, r - shape%big_r, &
                                     .false., .true.)
        point = arch_point(u, r, values%angle, values%arclength, values%time, &
                           arclength_slope(shape, r, second))
    end function arch_point_at

    !> The point of one half-arch whose arclength from A is `target`: the library's
    !! safeguarded Newton (`newton_bracketed`) in u on the bracket [lo, hi] (the arclength
    !! minus target changes sign on it), first on the 17-digit rules, then on the full
    !! ones from the coarse root. Status: status_ok or the root finder's.
    pure subroutine invert_arclength(model, shape, second, target, lo, hi, guess, point, &
                                     status)
        type(inverse_square_model), intent(in) :: model
        type(arch_shape), intent(in) :: shape
        logical, intent(in) :: second
        real(qp), intent(in) :: target, lo, hi, guess
        type(arch_point), intent(out) :: point
        integer, intent(out) :: status
        type(arclength_gap) :: gap
        real(qp) :: u, f_lo, f_hi
        integer :: steps
        ! s decreases in u on the first half-arch and increases on the second
        f_lo = merge(-1.0_qp, 1.0_qp, second)
        f_hi = -f_lo
        gap = arclength_gap(model=model, shape=shape, level=level_coarse, second=second, &
                            target=target)
        call newton_bracketed(gap, lo, f_lo, hi, f_hi, guess, coarse_tolerance, 0.0_qp, &
                              max_iterations, u, steps, status)
        if (status == status_ok) then
            gap%level = level_fine
            call newton_bracketed(gap, lo, f_lo, hi, f_hi, u, eps_qp, tiny(1.0_qp), &
                                  max_iterations, u, steps, status)
        end if
        point = arch_point_at(model, shape, level_fine, second, u)
    end subroutine invert_arclength

    !> s(u) - target and ds/du on one half-arch, for the root finder.
    pure subroutine arclength_gap_evaluate(self, x, f, df, status)
        class(arclength_gap), intent(in) :: self
        real(qp), intent(in) :: x             !! u = sqrt(r - R)
        real(qp), intent(out) :: f, df        !! s(u) - target, ds/du
        integer, intent(out) :: status        !! status_ok
        type(arch_point) :: point
        point = arch_point_at(self%model, self%shape, self%level, self%second, x)
        f = point%s - self%target
        df = point%slope
        status = status_ok
    end subroutine arclength_gap_evaluate

end module brachistochrone_curve
