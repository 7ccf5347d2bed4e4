!> Working precision and the constants every module shares.
!!
!! The whole library computes in IEEE binary128 (`real128`): 113-bit significand,
!! about 34 decimal digits. Tolerances are expressed in units of `epsilon(1.0_qp)`.
module brachistochrone_kinds
    use, intrinsic :: iso_fortran_env, only: real128
    implicit none
    private

    public :: qp, pi, eps_qp

    !> Kind of every real in the library: IEEE binary128 (quad precision).
    integer, parameter :: qp = real128
    !> pi to working precision.
    real(qp), parameter :: pi = acos(-1.0_qp)
    !> Machine epsilon of `qp`, about 1.93e-34: the unit of every tolerance.
    real(qp), parameter :: eps_qp = epsilon(1.0_qp)

end module brachistochrone_kinds
