!> expm1 and log1p in quad precision (from libquadmath), which Fortran lacks.
!!
!! Divided differences of speed laws such as x^a need (x^a - y^a)/(x - y) without
!! cancellation when x is close to y: t^a - 1 = expm1(a log1p(t - 1)).
module brachistochrone_quad_math
    use, intrinsic :: iso_c_binding, only: c_float128
    use brachistochrone_kinds, only: qp
    implicit none
    private

    public :: expm1, log1p

    ! c_float128 (a GNU extension of iso_c_binding) must be the kind of real128: if it
    ! were not, this constant expression would divide by zero and the build would stop
    integer, parameter :: kinds_agree = 1/merge(1, 0, c_float128 == qp)

    interface
        !> exp(x) - 1, accurate for small |x|.
        pure function expm1(x) bind(c, name='expm1q') result(y)
            import :: c_float128
            real(c_float128), value :: x !! argument
            real(c_float128) :: y
        end function expm1
        !> log(1 + x), accurate for small |x|.
        pure function log1p(x) bind(c, name='log1pq') result(y)
            import :: c_float128
            real(c_float128), value :: x !! argument, > -1
            real(c_float128) :: y
        end function log1p
    end interface

end module brachistochrone_quad_math
