!> The user's own quadrature module (the library has brachistochrone_quadrature).
module quadrature
    use brachistochrone, only: qp
    implicit none
    private
    public :: midpoint_rule

contains

    !> Composite midpoint rule for the radial fall time (Tee eq. 46 integrand)
    !! t(rho) = int_rho^1 dx / sqrt(2(1-x)/x), in the variable x = 1 - u^2.
    pure function midpoint_rule(rho, n) result(total)
        real(qp), intent(in) :: rho     !! lower limit
        integer, intent(in) :: n        !! panels
        real(qp) :: total
        real(qp) :: u, h, x
        integer :: k
        h = sqrt(1.0_qp - rho)/real(n, qp)
        total = 0.0_qp
        do k = 1, n
            u = (real(k, qp) - 0.5_qp)*h
            x = 1.0_qp - u*u
            total = total + 2.0_qp*u*sqrt(x/(2.0_qp*u*u))
        end do
        total = total*h
    end function midpoint_rule

end module quadrature
