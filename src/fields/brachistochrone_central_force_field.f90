!> Power-law and logarithmic fields (Tee 1998, sec. 2) as fields: the general engine.
!!
!! F = mu/r^n (n > 1, `power`) and F = mu/r (`logarithmic`, the case n = 1), solved by
!! `brachistochrone_central_force` for their speed laws.
module brachistochrone_central_force_field
    use brachistochrone_kinds, only: qp
    use brachistochrone_status, only: status_ok, status_bad_exponent
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_field_interface, only: brachistochrone_field
    use brachistochrone_central_force, only: central_force_model, new_central_force_model
    use brachistochrone_speed_laws, only: power_law, logarithmic_law, max_power_exponent
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    public :: central_force_field, new_power_field, new_logarithmic_field

    !> An attractive field with speed law v^2 = P(r) through the general engine.
    type, extends(brachistochrone_field) :: central_force_field
        type(central_force_model) :: model   !! the law and its quadrature rule
        real(qp) :: n = 0.0_qp               !! exponent (power law), 0 for logarithmic
    contains
        procedure :: solve => central_solve
        procedure :: name => central_name
        procedure :: description => central_description
        procedure :: region => central_region
        procedure :: exponent => central_exponent
    end type central_force_field

contains

    !> F = mu/r^n. status: status_ok, or status_bad_exponent unless
    !! 1 < n <= max_power_exponent (32: the range the general engine is tested on; the
    !! field is then the inverse-square law's, n = 2, so that it stays defined).
    subroutine new_power_field(n, field, status)
        real(qp), intent(in) :: n                     !! exponent, n > 1
        type(central_force_field), intent(out) :: field !! the field
        integer, intent(out) :: status                !! status_ok or status_bad_exponent
        status = status_ok
        field%n = n
        if (.not. (ieee_is_finite(n) .and. n > 1.0_qp .and. n <= max_power_exponent)) then
            status = status_bad_exponent
            field%n = 2.0_qp
        end if
        field%model = new_central_force_model(power_law(n=field%n))
    end subroutine new_power_field

    !> F = mu/r: v^2 = -2 log r; accessible psi < pi.
    function new_logarithmic_field() result(field)
        type(central_force_field) :: field
        field%model = new_central_force_model(logarithmic_law())
    end function new_logarithmic_field

    !> The general engine's two-point problem (statuses as `central_force_model%solve`:
    !! status_ok, status_not_finite, status_rho_out_of_range, status_psi_out_of_range,
    !! status_inaccessible, status_no_convergence).
    pure function central_solve(self, rho, psi) result(solution)
        class(central_force_field), intent(in) :: self
        real(qp), intent(in) :: rho, psi
        type(endpoint_solution) :: solution
        solution = self%model%solve(rho, psi)
    end function central_solve

    pure function central_name(self) result(text)
        class(central_force_field), intent(in) :: self
        character(len=:), allocatable :: text
        if (self%n > 0.0_qp) then
            text = 'power'
        else
            text = 'logarithmic'
        end if
    end function central_name

    pure function central_description(self) result(text)
        class(central_force_field), intent(in) :: self
        character(len=:), allocatable :: text
        if (self%n > 0.0_qp) then
            text = 'attractive power-law force F = mu/r^n (Tee 1998, sec. 2)'
        else
            text = 'attractive logarithmic-potential force F = mu/r (Tee 1998, sec. 2)'
        end if
    end function central_description

    pure function central_region(self) result(text)
        class(central_force_field), intent(in) :: self
        character(len=:), allocatable :: text
        if (self%n > 0.0_qp) then
            text = '0 < rho <= 1, 0 <= psi <= pi; accessible: psi < 2 pi/(n+1)'
        else
            text = '0 < rho <= 1, 0 <= psi <= pi; accessible: psi < pi'
        end if
    end function central_region

    pure function central_exponent(self) result(n)
        class(central_force_field), intent(in) :: self
        real(qp) :: n
        n = self%n
    end function central_exponent

end module brachistochrone_central_force_field
