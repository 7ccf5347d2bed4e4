!> exp and expm1 in binary128, several times faster than libquadmath's, for the general
!! engine's integrands (one or two per quadrature node).
!!
!! exp(x) = e^(+-m) (1 + expm1(f)), m = nint(|x|) <= 127, f = x -+ m (exact, |f| <= 1/2;
!! e^(+-m) from tables: one rounding, no scaling); beyond, exp(x) = 2^k (1 + expm1(x - k
!! log 2)) (k from double precision: only near x/log 2; k log 2 subtracted in two parts,
!! log 2 split into 60 + 113 bits, so the reduction is exact to about 2^-170 for |k| <
!! 2^14); expm1(x) = exp(x) - 1 for |x| >= 1. Below (and for the reduced argument):
!! |x| = j1/256 + j2/65536 + r (j1, j2 from one double-precision index, |r| < 2^-16,
!! j/65536 converted exactly on the bits, the subtraction exact) and expm1(a + r) =
!! e^a expm1(r) + expm1(a) for each table step a (both terms of one sign: no
!! cancellation). The tables e^a and expm1(a) are constant expressions (rounded by the
!! compiler); expm1(r) is its Taylor series to r^7/7!, the terms from r^4/24 on (below
!! 2^-52 of r) in hardware extended precision where there is one (converted on the bits,
!! `hardware_real`, `quad_real`). Errors: a few units in the last place.
module brachistochrone_fast_exp
    use brachistochrone_kinds, only: qp, xp
    use brachistochrone_fast_math, only: hardware_real, quad_real
    use, intrinsic :: iso_fortran_env, only: real64
    implicit none
    private

    public :: fast_exp, fast_expm1

    integer :: j_
    !> j/256 and -j/256, j = 0..255.
    real(qp), parameter :: steps_plus(0:255) = [(real(j_, qp)/256.0_qp, j_ = 0, 255)]
    real(qp), parameter :: steps_minus(0:255) = -steps_plus
    !> e^(+-j/256) and expm1(+-j/256) = 2 e^(a/2) sinh(a/2) (exp - 1 would lose up to 2.4
    !! digits).
    real(qp), parameter :: exp_table(0:255) = exp(steps_plus)
    real(qp), parameter :: expm1_table(0:255) = &
        2.0_qp*exp(0.5_qp*steps_plus)*sinh(0.5_qp*steps_plus)
    real(qp), parameter :: exp_table_minus(0:255) = exp(steps_minus)
    real(qp), parameter :: expm1_table_minus(0:255) = &
        2.0_qp*exp(0.5_qp*steps_minus)*sinh(0.5_qp*steps_minus)
    !> The same for +-j/65536.
    real(qp), parameter :: fine_plus(0:255) = [(real(j_, qp)/65536.0_qp, j_ = 0, 255)]
    real(qp), parameter :: fine_minus(0:255) = -fine_plus
    real(qp), parameter :: exp_fine(0:255) = exp(fine_plus)
    real(qp), parameter :: expm1_fine(0:255) = &
        2.0_qp*exp(0.5_qp*fine_plus)*sinh(0.5_qp*fine_plus)
    real(qp), parameter :: exp_fine_minus(0:255) = exp(fine_minus)
    real(qp), parameter :: expm1_fine_minus(0:255) = &
        2.0_qp*exp(0.5_qp*fine_minus)*sinh(0.5_qp*fine_minus)
    !> e^m and e^(-m), m = 0..max_whole, for |x| < max_whole + 1/2 (`fast_exp`)
    integer, parameter :: max_whole = 127
    real(qp), parameter :: whole_plus(0:max_whole) = [(real(j_, qp), j_ = 0, max_whole)]
    real(qp), parameter :: exp_whole(0:max_whole) = exp(whole_plus)
    real(qp), parameter :: exp_whole_minus(0:max_whole) = exp(-whole_plus)
    !> log 2 in two parts: high (exact times any |k| < 2^50) and low.
    real(qp), parameter :: ln2 = log(2.0_qp)
    real(qp), parameter :: ln2_high = real(int(ln2*2.0_qp**60, kind=selected_int_kind(18)), &
                                           qp)/2.0_qp**60
    !> log 2 - ln2_high to full precision (mpmath): ln2 - ln2_high would carry the
    !! rounding of ln2 (2^-114), k times, into the reduced argument
    real(qp), parameter :: ln2_low = 6.39062950764503927593536380659998906464430009e-19_qp
    !> 1/log 2 (k needs only to be near x/log 2: the reduction is exact for any k)
    real(qp), parameter :: inverse_ln2 = 1.0_qp/ln2
    !> The widest hardware kind (x87 extended, 64-bit significand) for the series' tail:
    !! with |r| < 2^-16 its terms from r^4/24 on are below 2^-52 of r, so 64 bits there
    !! leave an error below 2^-115 of r. Without such a kind the whole series in qp.
    integer, parameter :: tail_candidate = selected_real_kind(18, 4931)
    integer, parameter :: tail_kind = merge(tail_candidate, real64, tail_candidate > 0 &
                                            .and. tail_candidate /= qp)
    logical, parameter :: tail_in_hardware = precision(1.0_tail_kind) >= 18

contains

    !> exp(x) for binary128 x (overflow to +Inf, underflow to 0 as exp does). The range
    !! tests on the double-precision copy of x (no binary128 comparisons; rounding to
    !! double keeps |x| < c for the bounds c used, and the sign, zeros included).
    elemental function fast_exp(x) result(y)
        real(qp), intent(in) :: x !! argument
        real(qp) :: y
        real(qp) :: reduced
        real(real64) :: xd
        integer :: k, m
        xd = real(x, real64)
        if (.not. (abs(xd) < 11000.0_real64)) then
            y = exp(x)
            return
        end if
        if (abs(xd) < 0.5_real64) then
            ! no reduction, no scaling
            y = 1.0_qp + small_expm1(x, xd)
            return
        else if (abs(xd) < real(max_whole, real64) + 0.5_real64) then
            ! x = +-m + f, m = nint(|x|) (f exact, |f| <= 1/2), e^(+-m) from the tables
            ! (one rounding) times 1 + expm1(f); (|x| rounded to double may reach a
            ! half-integer: f then just above 1/2)
            m = min(nint(abs(xd)), max_whole)
            if (xd > 0.0_real64) then
                reduced = x - whole_plus(m)
                y = exp_whole(m)*(1.0_qp + small_expm1(reduced, real(reduced, real64)))
            else
                reduced = x + whole_plus(m)
                y = exp_whole_minus(m)*(1.0_qp + small_expm1(reduced, real(reduced, real64)))
            end if
            return
        end if
        ! k need only be near x/log 2 (the reduction below is exact for any k)
        k = nint(xd*real(inverse_ln2, real64))
        reduced = (x - real(k, qp)*ln2_high) - real(k, qp)*ln2_low
        y = scale(1.0_qp + small_expm1(reduced, real(reduced, real64)), k)
    end function fast_exp

    !> expm1(x) = exp(x) - 1 to full relative precision.
    elemental function fast_expm1(x) result(y)
        real(qp), intent(in) :: x !! argument
        real(qp) :: y
        real(real64) :: xd
        xd = real(x, real64)
        if (abs(xd) < 1.0_real64) then
            y = small_expm1(x, xd)
        else
            y = fast_exp(x) - 1.0_qp
        end if
    end function fast_expm1

    !> |x| = a1 + a2 + r for |x| < 1 (a1 = j1/256, a2 = j2/65536 from one double-precision
    !! index j = j1 256 + j2: a rounding up by one step leaves r slightly negative, which
    !! the series takes as well; the subtraction is exact), and expm1(+-r) by its series
    !! to r^7/7! (the remainder is below 1e-38 of it), the terms from r^4/24 on in
    !! hardware precision where there is one (xd: x in double precision, its sign x's).
    elemental subroutine reduce_series(x, xd, j1, j2, series)
        real(qp), intent(in) :: x
        real(real64), intent(in) :: xd
        integer, intent(out) :: j1, j2
        real(qp), intent(out) :: series
        real(qp) :: r
        real(tail_kind) :: rt, tail
        integer :: j
        j = max(0, min(int(abs(xd)*65536.0_real64), 65535))
        j1 = ishft(j, -8)
        j2 = iand(j, 255)
        ! j/65536 = a1 + a2 exactly, converted on the bits (no binary128 addition)
        r = abs(x) - quad_real(real(j, xp)*(1.0_xp/65536))
        if (sign(1.0_real64, xd) < 0.0_real64) r = -r
        if (tail_in_hardware) then
            ! the terms from r^4/24 on in hardware precision (see tail_kind)
            rt = to_tail(r)
            tail = 1.0_tail_kind/24 + rt*(1.0_tail_kind/120 + rt*(1.0_tail_kind/720 &
                   + rt*(1.0_tail_kind/5040)))
            series = r*(1.0_qp + r*(1.0_qp/2 + r*(1.0_qp/6 + r*to_quad(tail))))
        else
            series = r*(1.0_qp + r*(1.0_qp/2 + r*(1.0_qp/6 + r*(1.0_qp/24 + r*(1.0_qp/120 &
                     + r*(1.0_qp/720 + r*(1.0_qp/5040)))))))
        end if
    end subroutine reduce_series

    !> expm1 for |x| < 1: expm1(a + r) = e^a expm1(r) + expm1(a) for
    !! a = a2, then a1 (the terms of one sign: no cancellation); xd = real(x, real64).
    elemental function small_expm1(x, xd) result(y)
        real(qp), intent(in) :: x
        real(real64), intent(in) :: xd
        real(qp) :: y
        integer :: j1, j2
        call reduce_series(x, xd, j1, j2, y)
        if (sign(1.0_real64, xd) > 0.0_real64) then
            if (j2 > 0) y = exp_fine(j2)*y + expm1_fine(j2)
            if (j1 > 0) y = exp_table(j1)*y + expm1_table(j1)
        else
            if (j2 > 0) y = exp_fine_minus(j2)*y + expm1_fine_minus(j2)
            if (j1 > 0) y = exp_table_minus(j1)*y + expm1_table_minus(j1)
        end if
    end function small_expm1

    !> The series' tail in binary128 (x87 extended: on the bits).
    elemental function to_quad(t) result(r)
        real(tail_kind), intent(in) :: t
        real(qp) :: r
        if (tail_kind == xp) then
            r = quad_real(real(t, xp))
        else
            r = real(t, qp)
        end if
    end function to_quad

    !> r in the hardware kind of the series' tail (x87 extended: on the bits).
    elemental function to_tail(r) result(t)
        real(qp), intent(in) :: r
        real(tail_kind) :: t
        if (tail_kind == xp) then
            t = real(hardware_real(r), tail_kind)
        else
            t = real(r, tail_kind)
        end if
    end function to_tail

end module brachistochrone_fast_exp
