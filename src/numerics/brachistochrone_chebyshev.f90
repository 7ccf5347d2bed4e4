!> Piecewise Chebyshev interpolation of a smooth function of one variable.
!!
!! The interval [lower, upper] is split into equal pieces; on each the function is
!! interpolated at the n Chebyshev points of the first kind, t_k = cos(pi (k + 1/2)/n),
!! giving the coefficients of p(t) = sum_j c_j T_j(t). For a function analytic inside
!! the Bernstein ellipse of radius r around a piece, c_j falls like r^(-j), so a few
!! dozen terms reach quad precision.
!!
!! For evaluation each piece is also stored in powers of t, p(t) = sum_k a_k t^k: Horner's
!! rule then costs one multiply-add per term (two with the derivative), against
!! Clenshaw's two multiplies and five additions. The conversion is safe when the pieces
!! are short against the distance to the nearest singularity (r well above 1 + sqrt 2,
!! the growth rate of T_j's power coefficients), and then Horner's sum is as accurate
!! as Clenshaw's, dominated by a_0. Evaluation may drop the tail of each piece down to
!! a requested absolute tolerance (fewer terms for a root finder's first steps).
!!
!! Building is in two steps so that the caller can evaluate several functions at the
!! same points in one pass: `chebyshev_points` gives the points, `chebyshev_fit` turns
!! the values there into a `chebyshev_table`. `hardware_copy` gives the same polynomials
!! in the widest hardware kind (`chebyshev_table_xp`) for a root finder's early phase.
module brachistochrone_chebyshev
    use brachistochrone_kinds, only: qp, pi, xp
    use brachistochrone_summation, only: compensated_sum
    implicit none
    private

    public :: chebyshev_table, chebyshev_points, chebyshev_fit, chebyshev_table_from_powers
    public :: chebyshev_table_xp, hardware_copy

    !> A piecewise Chebyshev interpolant on [lower, upper].
    type :: chebyshev_table
        real(qp) :: lower = 0.0_qp   !! left end of the interval
        real(qp) :: upper = 0.0_qp   !! right end of the interval
        integer :: pieces = 0        !! number of equal pieces
        integer :: terms = 0         !! coefficients per piece
        !> c_j of piece k in coefficient(j, k), j = 0 .. terms-1 (c_0 already halved);
        !! from `chebyshev_fit` only (a table made by `chebyshev_table_from_powers` has none)
        real(qp), allocatable :: coefficient(:, :)
        !> The same polynomials in powers of t: a_j of piece k in power(j, k)
        real(qp), allocatable :: power(:, :)
        !> Terms of each piece above the noise of the values (see `chebyshev_fit`)
        integer, allocatable :: used(:)
        !> tail(j, k) = sum of |a_i| over i >= j: the error bound of dropping those terms
        real(qp), allocatable :: tail(:, :)
    contains
        procedure :: evaluate     !! value and derivative at x
        procedure :: terms_for    !! terms needed on a piece for an absolute tolerance
    end type chebyshev_table

    !> A `chebyshev_table`'s polynomials in hardware precision (`xp`), from
    !! `hardware_copy`.
    type :: chebyshev_table_xp
        real(xp) :: lower = 0.0_xp   !! left end of the interval
        real(xp) :: width = 1.0_xp   !! width of a piece
        integer :: pieces = 0        !! number of equal pieces
        real(xp), allocatable :: power(:, :)  !! a_j of piece k in power(j, k)
        integer, allocatable :: used(:)       !! terms evaluated on each piece
    contains
        procedure :: evaluate => evaluate_xp  !! value and derivative at x
    end type chebyshev_table_xp

contains

    !> The n Chebyshev points of the first kind on each of `pieces` equal pieces of
    !! [lower, upper]: x(k, piece), k = 1 .. n, in decreasing order on each piece.
    pure function chebyshev_points(lower, upper, pieces, n) result(x)
        real(qp), intent(in) :: lower   !! left end
        real(qp), intent(in) :: upper   !! right end
        integer, intent(in) :: pieces   !! number of equal pieces, >= 1
        integer, intent(in) :: n        !! points per piece, >= 1
        real(qp) :: x(n, pieces)
        real(qp) :: width, a, t
        integer :: k, piece
        width = (upper - lower)/real(pieces, qp)
        do piece = 1, pieces
            a = lower + real(piece - 1, qp)*width
            do k = 1, n
                t = cos(pi*(real(k, qp) - 0.5_qp)/real(n, qp))
                x(k, piece) = a + 0.5_qp*width*(1.0_qp + t)
            end do
        end do
    end function chebyshev_points

    !> The interpolant through values(k, piece) at chebyshev_points(lower, upper, pieces, n).
    !!
    !! Values carry rounding errors, and so do the coefficients, at about that level:
    !! once the true coefficients have decayed below it, the rest is noise. Each piece
    !! keeps its terms up to the last one above `noise` times its largest coefficient
    !! (default: all terms). Dropping the noise changes the interpolant by about the
    !! noise of the values, and makes it cheaper where the function is smoother.
    pure function chebyshev_fit(lower, upper, values, noise) result(table)
        real(qp), intent(in) :: lower          !! left end (as given to chebyshev_points)
        real(qp), intent(in) :: upper          !! right end
        real(qp), intent(in) :: values(:, :)   !! f at the points, (n, pieces)
        real(qp), intent(in), optional :: noise  !! relative noise level of the values
        type(chebyshev_table) :: table
        real(qp), allocatable :: cosines(:), t_previous(:), t_current(:), t_next(:)
        type(compensated_sum) :: sum
        real(qp) :: mean
        integer :: n, j, k, piece
        n = size(values, 1)
        table%lower = lower
        table%upper = upper
        table%pieces = size(values, 2)
        table%terms = n
        allocate (table%coefficient(0:n - 1, table%pieces), table%tail(0:n, table%pieces), &
                  table%used(table%pieces), table%power(0:n - 1, table%pieces))
        allocate (t_previous(0:n - 1), t_current(0:n - 1), t_next(0:n - 1))
        ! cos(pi j (k - 1/2)/n) = cos(pi m/(2n)) with m = j (2k - 1) mod 4n
        allocate (cosines(0:4*n - 1))
        do j = 0, 4*n - 1
            cosines(j) = cos(pi*real(j, qp)/real(2*n, qp))
        end do
        do piece = 1, table%pieces
            ! c_0 is the mean. The other sums see only the values' departures from it:
            ! with the values themselves, each product's rounding (eps times the values'
            ! size) would land in every coefficient, and the interpolant would carry ~n
            ! such errors; the departures are smaller by the function's variation on the
            ! piece (and, for values within a factor 2 of each other, exact)
            sum = compensated_sum()
            do k = 1, n
                call sum%add(values(k, piece))
            end do
            mean = sum%value()/real(n, qp)
            table%coefficient(0, piece) = mean
            do j = 1, n - 1
                sum = compensated_sum()
                do k = 1, n
                    call sum%add((values(k, piece) - mean)*cosines(mod(j*(2*k - 1), 4*n)))
                end do
                table%coefficient(j, piece) = 2.0_qp*sum%value()/real(n, qp)
            end do
            table%used(piece) = n
            if (present(noise)) then
                associate (c => table%coefficient(:, piece))
                table%used(piece) = max(1, findloc(abs(c) > noise*maxval(abs(c)), .true., &
                                                   dim=1, back=.true.))
                end associate
            end if
            table%coefficient(table%used(piece):, piece) = 0.0_qp
            ! powers of t: add c_j times the power coefficients of T_j, from
            ! T_(j+1) = 2t T_j - T_(j-1)
            t_previous = 0.0_qp
            t_current = 0.0_qp
            t_current(0) = 1.0_qp
            table%power(:, piece) = table%coefficient(0, piece)*t_current
            do j = 1, table%used(piece) - 1
                if (j == 1) then
                    t_next = 0.0_qp
                    t_next(1) = 1.0_qp
                else
                    t_next = -t_previous
                    t_next(1:) = t_next(1:) + 2.0_qp*t_current(:n - 2)
                end if
                t_previous = t_current
                t_current = t_next
                table%power(:, piece) = table%power(:, piece) &
                                        + table%coefficient(j, piece)*t_current
            end do
            table%tail(n, piece) = 0.0_qp
            do j = n - 1, 0, -1
                table%tail(j, piece) = table%tail(j + 1, piece) + abs(table%power(j, piece))
            end do
        end do
    end function chebyshev_fit

    !> A table from its power form (a `chebyshev_table`'s `power` and `used`, e.g. shipped
    !! as constants): the same polynomials, evaluated the same way, bit for bit.
    pure function chebyshev_table_from_powers(lower, upper, power, used) result(table)
        real(qp), intent(in) :: lower          !! left end
        real(qp), intent(in) :: upper          !! right end
        real(qp), intent(in) :: power(0:, :)   !! a_j of piece k in power(j, k)
        integer, intent(in) :: used(:)         !! terms of each piece, 1 .. size(power, 1)
        type(chebyshev_table) :: table
        integer :: j, piece
        table%lower = lower
        table%upper = upper
        table%terms = size(power, 1)
        table%pieces = size(power, 2)
        table%power = power
        table%used = max(1, min(table%terms, used))
        allocate (table%tail(0:table%terms, table%pieces))
        do piece = 1, table%pieces
            table%power(table%used(piece):, piece) = 0.0_qp
            table%tail(table%terms, piece) = 0.0_qp
            do j = table%terms - 1, 0, -1
                table%tail(j, piece) = table%tail(j + 1, piece) + abs(table%power(j, piece))
            end do
        end do
    end function chebyshev_table_from_powers

    !> Terms of piece `piece` needed so that the dropped ones sum to at most `tolerance`.
    pure function terms_for(self, piece, tolerance) result(terms)
        class(chebyshev_table), intent(in) :: self
        integer, intent(in) :: piece         !! the piece, 1 .. pieces
        real(qp), intent(in) :: tolerance    !! absolute tolerance
        integer :: terms
        terms = self%used(piece)
        do while (terms > 1)
            if (self%tail(terms - 1, piece) > tolerance) exit
            terms = terms - 1
        end do
    end function terms_for

    !> Value (and derivative) of the interpolant at x (lower <= x <= upper; points
    !! outside are evaluated on the end pieces). With `tolerance`, each piece's tail is
    !! dropped down to that absolute error.
    pure subroutine evaluate(self, x, value, slope, tolerance)
        class(chebyshev_table), intent(in) :: self
        real(qp), intent(in) :: x                    !! the point
        real(qp), intent(out) :: value               !! p(x)
        real(qp), intent(out), optional :: slope     !! p'(x)
        real(qp), intent(in), optional :: tolerance  !! absolute tolerance (default: all)
        real(qp) :: width, position, t, derivative
        integer :: piece, terms, j
        width = (self%upper - self%lower)/real(self%pieces, qp)
        position = (x - self%lower)/width
        piece = min(self%pieces, max(1, int(position) + 1))
        t = 2.0_qp*(position - real(piece - 1, qp)) - 1.0_qp
        terms = self%used(piece)
        if (present(tolerance)) terms = self%terms_for(piece, tolerance)
        value = self%power(terms - 1, piece)
        if (present(slope)) then
            derivative = 0.0_qp
            do j = terms - 2, 0, -1
                derivative = derivative*t + value
                value = value*t + self%power(j, piece)
            end do
            slope = derivative*(2.0_qp/width)
        else
            do j = terms - 2, 0, -1
                value = value*t + self%power(j, piece)
            end do
        end if
    end subroutine evaluate

    !> `table` in hardware precision: each piece cut at the absolute `tolerance`
    !! (`terms_for`), or with every term when it is absent.
    pure function hardware_copy(table, tolerance) result(series)
        type(chebyshev_table), intent(in) :: table
        real(qp), intent(in), optional :: tolerance  !! absolute tolerance
        type(chebyshev_table_xp) :: series
        integer :: piece
        series%lower = real(table%lower, xp)
        series%width = real((table%upper - table%lower)/real(table%pieces, qp), xp)
        series%pieces = table%pieces
        allocate (series%power(0:table%terms - 1, table%pieces), series%used(table%pieces))
        series%power = real(table%power, xp)
        series%used = table%terms
        if (present(tolerance)) then
            do piece = 1, table%pieces
                series%used(piece) = table%terms_for(piece, tolerance)
            end do
        end if
    end function hardware_copy

    !> Value (and derivative) of the hardware copy at x (Horner; points outside
    !! [lower, upper] are evaluated on the end pieces).
    pure subroutine evaluate_xp(self, x, value, slope)
        class(chebyshev_table_xp), intent(in) :: self
        real(xp), intent(in) :: x                  !! the point
        real(xp), intent(out) :: value             !! p(x)
        real(xp), intent(out), optional :: slope   !! p'(x)
        real(xp) :: position, t, derivative
        integer :: piece, j
        position = (x - self%lower)/self%width
        piece = min(self%pieces, max(1, int(position) + 1))
        t = 2.0_xp*(position - real(piece - 1, xp)) - 1.0_xp
        value = self%power(self%used(piece) - 1, piece)
        derivative = 0.0_xp
        do j = self%used(piece) - 2, 0, -1
            if (present(slope)) derivative = derivative*t + value
            value = value*t + self%power(j, piece)
        end do
        if (present(slope)) slope = derivative*(2.0_xp/self%width)
    end subroutine evaluate_xp

end module brachistochrone_chebyshev
