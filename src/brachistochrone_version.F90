!> Name and version of the program, shared by every driver and written into outputs.
!!
!! The version is `version` in fpm.toml, passed by both builds as the preprocessor macro
!! BRACHISTOCHRONE_VERSION (fpm: `[preprocess.cpp] macros`; CMake reads fpm.toml), so
!! this file is preprocessed (.F90). The continuation lines below put the macro, which
!! is a bare token such as 0.2.0, inside a character literal: cpp in gfortran's
!! traditional mode does not expand macros inside quotes.
module brachistochrone_version
    implicit none
    private

    public :: program_name, program_version

#ifndef BRACHISTOCHRONE_VERSION
#error "BRACHISTOCHRONE_VERSION is not defined: build with fpm or CMake (see README)"
#endif

    !> Name written into output provenance.
    character(len=*), parameter :: program_name = 'brachistochrone'
    !> Version (semantic versioning), `version` in fpm.toml.
    character(len=*), parameter :: program_version = '&
        &BRACHISTOCHRONE_VERSION&
        &'

end module brachistochrone_version
