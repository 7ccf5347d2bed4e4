!> Uniform gravity (Tee 1998, sec. 1; Saitoh eq. 1) as a field: the cycloid through B.
!!
!! The endpoint is Cartesian: B = (x, y) with x >= 0 across and y >= 0 DOWN from the
!! start A (units g = 1). Its two coordinates are named `x` and `y` in every output, so
!! that nothing reads them as rho and psi. The result's apse radius is the cycloid's
!! rolling-circle radius a (the field's equivalent of R-bar: the curve's one parameter),
!! s and t the arclength and time from A; arch `first` before the lowest point (phi <=
!! pi), `second` after it, `complete` when B is level with A (phi = 2 pi, arriving at
!! rest), `radial` for free fall (x = 0, a = 0).
module brachistochrone_uniform_field
    use brachistochrone_kinds, only: qp, pi
    use brachistochrone_status, only: status_ok
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_arches, only: arch_first, arch_second, arch_complete, arch_radial
    use brachistochrone_field_interface, only: brachistochrone_field
    use brachistochrone_uniform_gravity, only: uniform_brachistochrone
    use brachistochrone_double_quad, only: double_quad_number, two_product
    implicit none
    private

    public :: uniform_field

    !> (pi - pi_qp)/2: the half of pi that binary128's pi leaves out (mpmath, 60 digits).
    real(qp), parameter :: half_pi_tail = 0.5_qp*8.671810130123781024797044014623415e-35_qp

    !> Uniform gravity g = 1 downward: v^2 = 2 y; every point below A is accessible.
    type, extends(brachistochrone_field) :: uniform_field
    contains
        procedure :: solve => uniform_solve
        procedure :: name => uniform_name
        procedure :: description => uniform_description
        procedure :: region => uniform_region
        procedure :: units => uniform_units
        procedure :: coordinate => cartesian_coordinate
        procedure :: start => origin
    end type uniform_field

contains

    !> The cycloid from A through B = (x, y) (`uniform_brachistochrone` with g = 1).
    !! Statuses: status_ok, status_not_finite, status_parameter_out_of_range (x < 0),
    !! status_above_start (y < 0), status_no_convergence (not expected).
    pure function uniform_solve(self, rho, psi) result(solution)
        class(uniform_field), intent(in) :: self
        real(qp), intent(in) :: rho   !! x: horizontal distance of B from A, >= 0
        real(qp), intent(in) :: psi   !! y: depth of B below A, >= 0
        type(endpoint_solution) :: solution
        real(qp) :: phi, radius, time, arclength
        integer :: status
        solution%rho = rho
        solution%psi = psi
        call uniform_brachistochrone(rho, psi, 1.0_qp, phi, radius, time, arclength, status)
        solution%status = status
        if (status /= status_ok) return
        if (rho == 0.0_qp) then
            solution%arch = arch_radial
        else if (psi == 0.0_qp) then
            solution%arch = arch_complete
        else
            ! phi <= pi is x <= (pi/2) y, decided exactly (phi next to pi is not)
            solution%arch = merge(arch_first, arch_second, before_lowest_point(rho, psi))
        end if
        solution%apse_radius = radius
        solution%arclength = arclength
        solution%time = time
        solution%has_apse_radius = .true.
        solution%has_arclength = .true.
        solution%has_time = .true.
    end function uniform_solve

    !> Whether B = (x, y), x, y > 0 finite, is on the descending half of its cycloid
    !! (phi_B < pi), i.e. x < (pi/2) y, decided exactly: both scaled by the same power of
    !! 2, (pi/2) y = two_product(pi_qp/2, y) + half_pi_tail y, and x minus the leading
    !! part is exact when they are close (Sterbenz). x = (pi/2) y has no binary128 solution.
    pure logical function before_lowest_point(x, y)
        real(qp), intent(in) :: x, y
        type(double_quad_number) :: product
        real(qp) :: xs, ys
        integer :: e
        e = exponent(max(x, y))
        xs = scale(x, -e)
        ys = scale(y, -e)
        product = two_product(0.5_qp*pi, ys)
        before_lowest_point = (xs - product%hi) - product%lo - half_pi_tail*ys < 0.0_qp
    end function before_lowest_point

    pure function uniform_name(self) result(text)
        class(uniform_field), intent(in) :: self
        character(len=:), allocatable :: text
        text = 'uniform'
    end function uniform_name

    pure function uniform_description(self) result(text)
        class(uniform_field), intent(in) :: self
        character(len=:), allocatable :: text
        text = 'uniform gravity (Tee 1998, sec. 1): the cycloid; R is its rolling-circle '// &
               'radius a'
    end function uniform_description

    pure function uniform_region(self) result(text)
        class(uniform_field), intent(in) :: self
        character(len=:), allocatable :: text
        text = 'x >= 0 across, y >= 0 down from A; all accessible'
    end function uniform_region

    pure function uniform_units(self) result(text)
        class(uniform_field), intent(in) :: self
        character(len=:), allocatable :: text
        text = 'units g = 1 (any length unit; time in units of sqrt(length/g))'
    end function uniform_units

    pure function origin(self) result(text)
        class(uniform_field), intent(in) :: self
        character(len=:), allocatable :: text
        text = '(0, 0)'
    end function origin

    pure function cartesian_coordinate(self, k) result(name)
        class(uniform_field), intent(in) :: self
        integer, intent(in) :: k   !! 1 or 2
        character(len=:), allocatable :: name
        name = merge('x', 'y', k == 1)
    end function cartesian_coordinate

end module brachistochrone_uniform_field
