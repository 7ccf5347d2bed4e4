!> The user's own roots module (the library has brachistochrone_roots).
module roots
    use brachistochrone, only: qp
    implicit none
    private
    public :: bisect_cube_root

contains

    !> The real cube root of a > 0 by bisection (a stand-in for a user's own solver).
    pure function bisect_cube_root(a) result(x)
        real(qp), intent(in) :: a   !! a > 0
        real(qp) :: x, low, high
        integer :: k
        low = 0.0_qp
        high = max(1.0_qp, a)
        do k = 1, 200
            x = 0.5_qp*(low + high)
            if (x**3 > a) then
                high = x
            else
                low = x
            end if
        end do
    end function bisect_cube_root

end module roots
