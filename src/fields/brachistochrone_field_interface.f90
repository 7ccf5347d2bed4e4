!> The field interface: what every force field of the library is and does.
!!
!! A field is a value of a type that extends `brachistochrone_field`: it solves an
!! endpoint B = (rho, psi) into the shared `endpoint_solution`, names itself (the word
!! of the namelist's `force`, and an exponent where it has one), describes its law, its
!! units and its accessible region, and samples its curves where it supports that.
!! The batch drivers, the outputs and the C interface take a field and never branch on
!! its name; `brachistochrone_fields%new_field` makes one from a name.
!!
!! ```fortran
!! class(brachistochrone_field), allocatable :: field
!! type(endpoint_solution) :: b
!! call new_field('power', 3.0_qp, field, status)
!! b = field%solve(0.5_qp, 1.2_qp)
!! ```
module brachistochrone_field_interface
    use brachistochrone_kinds, only: qp
    use brachistochrone_status, only: status_not_supported
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_curve, only: curve_samples
    implicit none
    private

    public :: brachistochrone_field

    !> A force field: one implementation per field (inverse-square fast path, power and
    !! logarithmic laws through the general engine, harmonic closed forms, repulsive).
    type, abstract :: brachistochrone_field
    contains
        !> The two-point problem: the brachistochrone from A = (1, 0) through B.
        procedure(solve_interface), deferred :: solve
        !> The field's word, as `force` in the namelist ('inverse_square', 'power', ...).
        procedure(text_interface), deferred :: name
        !> The law in words, for table headers and provenance.
        procedure(text_interface), deferred :: description
        !> The endpoints the field accepts and which of them are accessible.
        procedure(text_interface), deferred :: region
        !> The units of the results (default: `units |mu| = 1`; A is at radius 1).
        procedure :: units => default_units
        !> The exponent n of F = mu/r^n (power law), 0 for fields without one.
        procedure :: exponent => no_exponent
        !> The name of the endpoint's coordinate k (1 or 2): `rho`, `psi` (polar, A at
        !! radius 1), or `x`, `y` for uniform gravity; they name the outputs' columns.
        procedure :: coordinate => polar_coordinate
        !> The start A in the field's coordinates: `(1, 0)` (polar), `(0, 0)` (uniform).
        procedure :: start => polar_start
        !> Words after a time that is only a bound (inaccessible endpoints).
        procedure :: bound_note => default_bound_note
        !> The paper's secant method from estimates r0, r1 (default: not supported).
        procedure :: solve_from_estimates => no_estimates
        !> Points along the curve of a solved endpoint (default: not supported).
        procedure :: sample_curve => no_curve
    end type brachistochrone_field

    abstract interface
        !> Solve endpoint B = (rho, psi). The solution's status says what went wrong
        !! first; its has_* flags say which values exist.
        pure function solve_interface(self, rho, psi) result(solution)
            import :: brachistochrone_field, qp, endpoint_solution
            class(brachistochrone_field), intent(in) :: self
            real(qp), intent(in) :: rho   !! endpoint radius
            real(qp), intent(in) :: psi   !! endpoint angle (radians)
            type(endpoint_solution) :: solution
        end function solve_interface
        !> A text about the field.
        pure function text_interface(self) result(text)
            import :: brachistochrone_field
            class(brachistochrone_field), intent(in) :: self
            character(len=:), allocatable :: text
        end function text_interface
    end interface

contains

    pure function default_units(self) result(text)
        class(brachistochrone_field), intent(in) :: self
        character(len=:), allocatable :: text
        text = 'units |mu| = 1'
    end function default_units

    pure function no_exponent(self) result(n)
        class(brachistochrone_field), intent(in) :: self
        real(qp) :: n
        n = 0.0_qp
    end function no_exponent

    pure function polar_coordinate(self, k) result(name)
        class(brachistochrone_field), intent(in) :: self
        integer, intent(in) :: k   !! 1 or 2
        character(len=:), allocatable :: name
        name = merge('rho', 'psi', k == 1)
    end function polar_coordinate

    pure function polar_start(self) result(text)
        class(brachistochrone_field), intent(in) :: self
        character(len=:), allocatable :: text
        text = '(1, 0)'
    end function polar_start

    pure function default_bound_note(self) result(text)
        class(brachistochrone_field), intent(in) :: self
        character(len=:), allocatable :: text
        text = 'greatest lower bound; not attained'
    end function default_bound_note

    !> Default: the field has no secant method; status_not_supported.
    pure function no_estimates(self, rho, psi, r0, r1, tolerance) result(solution)
        class(brachistochrone_field), intent(in) :: self
        real(qp), intent(in) :: rho, psi     !! the endpoint
        real(qp), intent(in) :: r0, r1       !! initial estimates of R-bar
        real(qp), intent(in) :: tolerance    !! stop when |R_n - R_(n-1)| < tolerance
        type(endpoint_solution) :: solution
        solution%rho = rho
        solution%psi = psi
        solution%status = status_not_supported
    end function no_estimates

    !> Default: the field cannot sample its curves; no points, status_not_supported.
    pure function no_curve(self, solution, points) result(samples)
        class(brachistochrone_field), intent(in) :: self
        type(endpoint_solution), intent(in) :: solution !! a solved endpoint
        integer, intent(in) :: points                   !! points wanted, >= 2
        type(curve_samples) :: samples
        samples%status = status_not_supported
    end function no_curve

end module brachistochrone_field_interface
