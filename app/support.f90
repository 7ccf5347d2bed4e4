!> What the program's subcommands share: stopping with a message and an exit code.
!! (Only programs stop; the library returns statuses.)
module brachistochrone_app_support
    use, intrinsic :: iso_fortran_env, only: error_unit
    implicit none
    private

    public :: stop_with

contains

    !> Print `name: text` on stderr and stop with exit code `code`.
    subroutine stop_with(name, code, text)
        character(len=*), intent(in) :: name  !! the program or subcommand, for the message
        integer, intent(in) :: code           !! the exit code
        character(len=*), intent(in) :: text  !! what went wrong
        write (error_unit, '(a)') name//': '//text
        stop code, quiet=.true.
    end subroutine stop_with

end module brachistochrone_app_support
