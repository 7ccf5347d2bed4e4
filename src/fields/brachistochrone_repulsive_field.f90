!> The repulsive inverse-square field (Tee 1998, sec. 6) as a field: the least-time
!! brachistochrone through each endpoint.
!!
!! Every target angle psi + 2 pi m (and its mirror 2 pi (m+1) - psi) has exactly one
!! curve from A, and the time grows with the angle swept, so the least-time curve
!! through B is the one sweeping psi itself (`brachistochrone_repulsive` derives this
!! and lists the curves with more windings). R-bar exists for bounded curves only.
module brachistochrone_repulsive_field
    use brachistochrone_kinds, only: qp
    use brachistochrone_status, only: status_ok, status_no_convergence
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_arches, only: arch_radial, arch_complete, arch_unbounded
    use brachistochrone_field_interface, only: brachistochrone_field
    use brachistochrone_repulsive, only: repulsive_solution, solve_repulsive, panel_rules, &
                                         new_panel_rules
    implicit none
    private

    public :: repulsive_field, new_repulsive_field, least_time_repulsive

    !> F = -mu/r^2 (repulsive): v^2 = 2(r - 1)/r, endpoints rho >= 1.
    !! Make it with `new_repulsive_field` (its Gauss rules copied once); a default-built
    !! value solves the same endpoints, copying the rules (constants, about 0.03 ms) on
    !! every call.
    type, extends(brachistochrone_field) :: repulsive_field
        logical :: has_rules = .false.   !! rules built
        type(panel_rules) :: rules       !! the fast panels' Gauss rules
    contains
        procedure :: solve => repulsive_solve
        procedure :: name => repulsive_name
        procedure :: description => repulsive_description
        procedure :: region => repulsive_region
    end type repulsive_field

contains

    !> The repulsive field with its Gauss rules built (about a millisecond).
    pure function new_repulsive_field() result(field)
        type(repulsive_field) :: field
        field%rules = new_panel_rules()
        field%has_rules = .true.
    end function new_repulsive_field

    !> `least_time_repulsive`.
    pure function repulsive_solve(self, rho, psi) result(solution)
        class(repulsive_field), intent(in) :: self
        real(qp), intent(in) :: rho, psi
        type(endpoint_solution) :: solution
        if (self%has_rules) then
            solution = least_time_repulsive(rho, psi, self%rules)
        else
            solution = least_time_repulsive(rho, psi)
        end if
    end function repulsive_solve

    !> The least-time brachistochrone from A through B = (rho, psi), rho >= 1: arch
    !! arch_radial (psi = 0), arch_unbounded, arch_complete (rho = 1), arch_first or
    !! arch_second; R-bar only for bounded curves. Statuses: status_ok,
    !! status_not_finite, status_rho_below_start, status_psi_out_of_range,
    !! status_no_convergence.
    pure function least_time_repulsive(rho, psi, rules) result(solution)
        real(qp), intent(in) :: rho  !! endpoint radius, rho >= 1
        real(qp), intent(in) :: psi  !! endpoint angle, 0 <= psi <= pi
        !> the fast panels' Gauss rules (`new_panel_rules`), built here when absent
        type(panel_rules), intent(in), optional :: rules
        type(endpoint_solution) :: solution
        type(repulsive_solution), allocatable :: found(:)
        integer :: best, status
        solution%rho = rho
        solution%psi = psi
        ! the least time is the anticlockwise curve sweeping psi itself (module notes of
        ! brachistochrone_repulsive, tested there): its mirror image need not be solved
        call solve_repulsive(rho, psi, 0, found, best, status, mirror=.false., rules=rules)
        solution%status = status
        if (status /= status_ok) return
        if (best == 0) then
            solution%status = status_no_convergence
            if (size(found) > 0) solution%status = found(1)%status
            return
        end if
        associate (b => found(best))
            if (psi == 0.0_qp) then
                solution%arch = arch_radial
            else if (b%arch == arch_unbounded) then
                solution%arch = arch_unbounded
            else if (rho == 1.0_qp) then
                solution%arch = arch_complete
            else
                solution%arch = b%arch
            end if
            solution%has_apse_radius = b%curve%bounded
            if (b%curve%bounded) solution%apse_radius = b%curve%apse
            solution%arclength = b%arclength
            solution%time = b%time
            solution%steps = b%steps
            solution%has_arclength = .true.
            solution%has_time = .true.
        end associate
    end function least_time_repulsive

    pure function repulsive_name(self) result(text)
        class(repulsive_field), intent(in) :: self
        character(len=:), allocatable :: text
        text = 'repulsive'
    end function repulsive_name

    pure function repulsive_description(self) result(text)
        class(repulsive_field), intent(in) :: self
        character(len=:), allocatable :: text
        text = 'repulsive inverse-square force F = -mu/r^2 (Tee 1998, sec. 6), the '// &
               'least-time curve'
    end function repulsive_description

    pure function repulsive_region(self) result(text)
        class(repulsive_field), intent(in) :: self
        character(len=:), allocatable :: text
        text = 'rho >= 1, 0 <= psi <= pi; all accessible'
    end function repulsive_region

end module brachistochrone_repulsive_field
