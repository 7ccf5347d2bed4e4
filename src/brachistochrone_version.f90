!> Name and version of the program, shared by every driver and written into outputs.
module brachistochrone_version
    implicit none
    private

    public :: program_name, program_version

    !> Name written into output provenance.
    character(len=*), parameter :: program_name = 'brachistochrone'
    !> Version (semantic versioning).
    character(len=*), parameter :: program_version = '0.2.0'

end module brachistochrone_version
