!> Every field of the library, made from its name: the one place that maps the words of
!! the namelist's `force` (and of the C interface) to field values.
module brachistochrone_fields
    use brachistochrone_kinds, only: qp
    use brachistochrone_status, only: status_ok, status_unknown_field
    use brachistochrone_field_interface, only: brachistochrone_field
    use brachistochrone_inverse_square_field, only: inverse_square_field, &
            new_inverse_square_field
    use brachistochrone_central_force_field, only: central_force_field, new_power_field, &
            new_logarithmic_field
    use brachistochrone_harmonic_field, only: harmonic_field
    use brachistochrone_repulsive_field, only: new_repulsive_field
    use brachistochrone_uniform_field, only: uniform_field
    implicit none
    private

    public :: new_field, field_names

    !> The names `new_field` knows, quoted as in the namelist.
    character(len=*), parameter :: field_names = &
        "'inverse_square', 'power', 'logarithmic', 'harmonic', 'repulsive', 'uniform'"

contains

    !> The field called `name` (`field_names`); `exponent` is used by 'power' only.
    !! status: status_ok; status_unknown_field (the field is then inverse-square, so it
    !! is always allocated); status_bad_exponent (power with exponent not > 1 or not
    !! finite; the field is then the power law with n = 2).
    subroutine new_field(name, exponent, field, status)
        character(len=*), intent(in) :: name   !! 'inverse_square', 'power', ...
        real(qp), intent(in) :: exponent       !! n of F = mu/r^n, for 'power'
        class(brachistochrone_field), allocatable, intent(out) :: field !! the field
        integer, intent(out) :: status         !! status_ok or the reason
        type(central_force_field) :: central
        status = status_ok
        select case (name)
        case ('inverse_square')
            allocate (field, source=new_inverse_square_field())
        case ('power')
            call new_power_field(exponent, central, status)
            allocate (field, source=central)
        case ('logarithmic')
            allocate (field, source=new_logarithmic_field())
        case ('harmonic')
            allocate (harmonic_field :: field)
        case ('repulsive')
            allocate (field, source=new_repulsive_field())
        case ('uniform')
            allocate (uniform_field :: field)
        case default
            status = status_unknown_field
            allocate (field, source=new_inverse_square_field())
        end select
    end subroutine new_field

end module brachistochrone_fields
