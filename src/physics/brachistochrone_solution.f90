!> The one result type of every field, and the one validation of an endpoint.
!!
!! Every field (inverse-square fast path, general engine, harmonic closed forms,
!! repulsive) solves an endpoint B = (rho, psi) into an `endpoint_solution`; the batch
!! drivers, the outputs and the C interface read nothing else. Values that do not exist
!! for an endpoint (R-bar of an unbounded or inaccessible curve, s when inaccessible)
!! are flagged by `has_apse_radius`, `has_arclength`, `has_time`.
module brachistochrone_solution
    use brachistochrone_kinds, only: qp, pi
    use brachistochrone_status, only: status_ok, status_not_finite, &
                                      status_rho_out_of_range, status_psi_out_of_range, &
                                      status_rho_below_start
    use brachistochrone_arches, only: arch_none
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    public :: endpoint_solution, endpoint_status, region_inside, region_outside

    !> Endpoints of attractive fields: 0 < rho <= 1 (the start A is at radius 1).
    integer, parameter :: region_inside = 1
    !> Endpoints of the repulsive field: rho >= 1 (every path moves outward).
    integer, parameter :: region_outside = 2

    !> Everything known about one endpoint after solving, for every field.
    type :: endpoint_solution
        real(qp) :: rho = 0.0_qp          !! endpoint radius
        real(qp) :: psi = 0.0_qp          !! endpoint angle (radians)
        integer :: arch = arch_none       !! arch_first, arch_second, ... (`arch_word`)
        real(qp) :: apse_radius = 0.0_qp  !! R-bar (0 for radial fall)
        !> rho - R-bar as the solver carried it (exact near the apse, where rho - R-bar
        !! computed from the rounded R-bar would lose digits); 0 when there is no R-bar
        real(qp) :: apse_gap = 0.0_qp
        real(qp) :: arclength = 0.0_qp    !! s, arclength from A to B
        real(qp) :: time = 0.0_qp         !! t, time from A to B (its bound if inaccessible)
        integer :: steps = 0              !! root-finder evaluations (secant steps)
        integer :: status = status_ok     !! status code (`status_word`)
        logical :: has_apse_radius = .false. !! R-bar exists
        logical :: has_arclength = .false.   !! s exists
        logical :: has_time = .false.        !! t exists
    end type endpoint_solution

contains

    !> The status of an endpoint before any field-specific work: status_not_finite (NaN
    !! or infinite, checked first), status_rho_out_of_range (region_inside and not
    !! 0 < rho <= 1), status_rho_below_start (region_outside and rho < 1),
    !! status_psi_out_of_range (not 0 <= psi <= pi), else status_ok.
    elemental function endpoint_status(rho, psi, region) result(status)
        real(qp), intent(in) :: rho    !! endpoint radius
        real(qp), intent(in) :: psi    !! endpoint angle (radians)
        integer, intent(in) :: region  !! region_inside or region_outside
        integer :: status
        if (.not. (ieee_is_finite(rho) .and. ieee_is_finite(psi))) then
            status = status_not_finite
        else if (region == region_inside .and. (rho <= 0.0_qp .or. rho > 1.0_qp)) then
            status = status_rho_out_of_range
        else if (region == region_outside .and. rho < 1.0_qp) then
            status = status_rho_below_start
        else if (psi < 0.0_qp .or. psi > pi) then
            status = status_psi_out_of_range
        else
            status = status_ok
        end if
    end function endpoint_status

end module brachistochrone_solution
