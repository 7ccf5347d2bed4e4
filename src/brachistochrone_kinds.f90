!> Working precision and the constants every module shares.
!!
!! The whole library computes in IEEE binary128 (`real128`): 113-bit significand,
!! about 34 decimal digits. Tolerances are expressed in units of `epsilon(1.0_qp)`.
module brachistochrone_kinds
    use, intrinsic :: iso_fortran_env, only: real64, real128
    implicit none
    private

    public :: qp, pi, eps_qp, xp

    !> Kind of every real in the library: IEEE binary128 (quad precision).
    integer, parameter :: qp = real128
    !> pi to working precision.
    real(qp), parameter :: pi = acos(-1.0_qp)
    !> Machine epsilon of `qp`, about 1.93e-34: the unit of every tolerance.
    real(qp), parameter :: eps_qp = epsilon(1.0_qp)
    integer, parameter :: xp_candidate = selected_real_kind(18, 4931)
    !> The widest hardware real kind below quad: x87 extended on x86-64 (64-bit
    !! significand, epsilon 1.1e-19, the exponent range of binary128), double elsewhere;
    !! for the cheap early phases of the root finders and the slopes of their last steps.
    integer, parameter :: xp = merge(xp_candidate, real64, &
                                     xp_candidate > 0 .and. xp_candidate /= qp)

end module brachistochrone_kinds
