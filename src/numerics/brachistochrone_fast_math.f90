!> Elementary functions in quad precision that are cheaper than the library's.
!!
!! binary128 arithmetic is done in software (a multiplication is about 180 machine
!! instructions) and `sqrt` costs about seven multiplications. The integrands need
!! 1/sqrt(q) at every node, so it is computed here from a hardware seed in the widest
!! native precision (x87 extended on x86-64: 64-bit significand, error ~5e-20) refined
!! by one Newton step r <- r (3 - q r^2)/2, which squares the error (~4e-39, below the
!! rounding of binary128) using multiplications only. Where no native kind wider than
!! double exists the seed is double precision and a second step is taken.
module brachistochrone_fast_math
    use brachistochrone_kinds, only: qp
    use, intrinsic :: iso_fortran_env, only: real64
    implicit none
    private

    public :: inverse_sqrt

    !> Widest hardware real kind below quad (x87 extended where available).
    integer, parameter :: seed_kind_candidate = selected_real_kind(18, 4931)
    integer, parameter :: seed_kind = merge(seed_kind_candidate, real64, &
                                            seed_kind_candidate > 0 .and. &
                                            seed_kind_candidate /= qp)
    !> Newton steps needed from that seed.
    integer, parameter :: newton_steps = merge(1, 2, seed_kind /= real64)
    !> Inputs inside this range get the hardware seed; others use 1/sqrt(x).
    real(qp), parameter :: seed_low = 1.0e-300_qp, seed_high = 1.0e300_qp

contains

    !> 1/sqrt(x) for x > 0, within 2 ulp.
    elemental function inverse_sqrt(x) result(r)
        real(qp), intent(in) :: x !! positive argument
        real(qp) :: r
        integer :: step
        if (x > seed_low .and. x < seed_high) then
            r = real(1.0_seed_kind/sqrt(real(x, seed_kind)), qp)
            do step = 1, newton_steps
                r = r*(1.5_qp - 0.5_qp*x*(r*r))
            end do
        else
            r = 1.0_qp/sqrt(x)
        end if
    end function inverse_sqrt

end module brachistochrone_fast_math
