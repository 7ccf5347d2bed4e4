!> The attractive inverse-square field (Tee 1998, sec. 3-5) as a field: the fast path.
!!
!! Wraps the tabulated model (`brachistochrone_inverse_square`), the default solver and
!! the paper's secant method (`brachistochrone_two_point`) and the curve sampler
!! (`brachistochrone_curve`) behind the field interface.
module brachistochrone_inverse_square_field
    use brachistochrone_kinds, only: qp
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_field_interface, only: brachistochrone_field
    use brachistochrone_inverse_square, only: inverse_square_model, new_inverse_square_model
    use brachistochrone_two_point, only: solve_endpoint, solve_endpoint_secant
    use brachistochrone_curve, only: curve_samples, sample_endpoint_curve
    implicit none
    private

    public :: inverse_square_field, new_inverse_square_field

    !> F = mu/r^2, attractive: v^2 = 2(1 - r)/r; accessible psi < 2 pi/3.
    type, extends(brachistochrone_field) :: inverse_square_field
        type(inverse_square_model) :: model !! quadrature rules and whole-arch tables
    contains
        procedure :: solve => inverse_square_solve
        procedure :: name => inverse_square_name
        procedure :: description => inverse_square_description
        procedure :: region => inverse_square_region
        procedure :: units => inverse_square_units
        procedure :: bound_note => inverse_square_bound_note
        procedure :: solve_from_estimates => inverse_square_secant
        procedure :: sample_curve => inverse_square_curve
    end type inverse_square_field

contains

    !> The field, with its model built (rules and tables: about 75 ms, once).
    function new_inverse_square_field() result(field)
        type(inverse_square_field) :: field
        field%model = new_inverse_square_model()
    end function new_inverse_square_field

    !> `solve_endpoint`: statuses status_ok, status_not_finite, status_rho_out_of_range,
    !! status_psi_out_of_range, status_inaccessible (t = kappa(rho)), status_no_convergence.
    pure function inverse_square_solve(self, rho, psi) result(solution)
        class(inverse_square_field), intent(in) :: self
        real(qp), intent(in) :: rho, psi
        type(endpoint_solution) :: solution
        solution = solve_endpoint(self%model, rho, psi)
    end function inverse_square_solve

    !> The paper's secant method from r0, r1 (`solve_endpoint_secant`); also
    !! status_outside_domain and status_bad_estimates.
    pure function inverse_square_secant(self, rho, psi, r0, r1, tolerance) result(solution)
        class(inverse_square_field), intent(in) :: self
        real(qp), intent(in) :: rho, psi, r0, r1, tolerance
        type(endpoint_solution) :: solution
        solution = solve_endpoint_secant(self%model, rho, psi, r0, r1, tolerance)
    end function inverse_square_secant

    !> `sample_endpoint_curve`: equal steps of arclength on each half-arch.
    pure function inverse_square_curve(self, solution, points) result(samples)
        class(inverse_square_field), intent(in) :: self
        type(endpoint_solution), intent(in) :: solution
        integer, intent(in) :: points
        type(curve_samples) :: samples
        samples = sample_endpoint_curve(self%model, solution, points)
    end function inverse_square_curve

    pure function inverse_square_name(self) result(text)
        class(inverse_square_field), intent(in) :: self
        character(len=:), allocatable :: text
        text = 'inverse_square'
    end function inverse_square_name

    pure function inverse_square_description(self) result(text)
        class(inverse_square_field), intent(in) :: self
        character(len=:), allocatable :: text
        text = 'attractive inverse-square force (Tee 1998)'
    end function inverse_square_description

    pure function inverse_square_region(self) result(text)
        class(inverse_square_field), intent(in) :: self
        character(len=:), allocatable :: text
        text = '0 < rho <= 1, 0 <= psi <= pi; accessible: psi < 2 pi/3'
    end function inverse_square_region

    pure function inverse_square_units(self) result(text)
        class(inverse_square_field), intent(in) :: self
        character(len=:), allocatable :: text
        text = 'units mu = 1'
    end function inverse_square_units

    pure function inverse_square_bound_note(self) result(text)
        class(inverse_square_field), intent(in) :: self
        character(len=:), allocatable :: text
        text = 'greatest lower bound kappa(rho); not attained'
    end function inverse_square_bound_note

end module brachistochrone_inverse_square_field
