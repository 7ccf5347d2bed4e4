!> The field inside a uniform planet (Saitoh) as a field: closed forms.
!!
!! F = omega^2 r towards the centre, v^2 = 1 - r^2 (units R_E = 1, omega = 1). The
!! brachistochrones are hypocycloids; `solve_harmonic_endpoint` solves an endpoint from
!! Saitoh's closed forms plus one bracketed root, and its results are mapped onto the
!! shared solution: R-bar is the radius of the deepest point rho_m.
module brachistochrone_harmonic_field
    use brachistochrone_kinds, only: qp
    use brachistochrone_status, only: status_ok
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_field_interface, only: brachistochrone_field
    use brachistochrone_harmonic, only: harmonic_tunnel, solve_harmonic_endpoint
    implicit none
    private

    public :: harmonic_field

    !> F = omega^2 r (inside a uniform planet): every 0 <= psi <= pi is accessible.
    type, extends(brachistochrone_field) :: harmonic_field
    contains
        procedure :: solve => harmonic_solve
        procedure :: name => harmonic_name
        procedure :: description => harmonic_description
        procedure :: region => harmonic_region
        procedure :: units => harmonic_units
    end type harmonic_field

contains

    !> Saitoh's hypocycloid through B. Statuses: status_ok, status_not_finite,
    !! status_rho_out_of_range, status_psi_out_of_range, status_no_convergence.
    pure function harmonic_solve(self, rho, psi) result(solution)
        class(harmonic_field), intent(in) :: self
        real(qp), intent(in) :: rho, psi
        type(endpoint_solution) :: solution
        type(harmonic_tunnel) :: tunnel
        solution%rho = rho
        solution%psi = psi
        tunnel = solve_harmonic_endpoint(rho, psi)
        solution%status = tunnel%status
        solution%steps = tunnel%steps
        if (tunnel%status /= status_ok) return
        solution%arch = tunnel%arch
        solution%apse_radius = tunnel%min_radius
        solution%apse_gap = rho - tunnel%min_radius
        solution%arclength = tunnel%arclength
        solution%time = tunnel%time
        solution%has_apse_radius = .true.
        solution%has_arclength = .true.
        solution%has_time = .true.
    end function harmonic_solve

    pure function harmonic_name(self) result(text)
        class(harmonic_field), intent(in) :: self
        character(len=:), allocatable :: text
        text = 'harmonic'
    end function harmonic_name

    pure function harmonic_description(self) result(text)
        class(harmonic_field), intent(in) :: self
        character(len=:), allocatable :: text
        text = 'harmonic force F = omega^2 r inside a uniform planet (Saitoh)'
    end function harmonic_description

    pure function harmonic_region(self) result(text)
        class(harmonic_field), intent(in) :: self
        character(len=:), allocatable :: text
        text = '0 < rho <= 1, 0 <= psi <= pi; all accessible (psi = pi: through the centre)'
    end function harmonic_region

    pure function harmonic_units(self) result(text)
        class(harmonic_field), intent(in) :: self
        character(len=:), allocatable :: text
        text = 'units R_E = 1, omega = sqrt(g/R_E) = 1'
    end function harmonic_units

end module brachistochrone_harmonic_field
