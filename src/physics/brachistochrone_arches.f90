!> Where an endpoint lies on its brachistochrone: the arch codes and their words.
!!
!! Shared by every force law (`two_point` for the inverse-square force re-exports them,
!! `harmonic` uses them for the uniform planet), so that a module can report arches
!! without depending on another force law's solver.
module brachistochrone_arches
    implicit none
    private

    public :: arch_none, arch_first, arch_second, arch_complete, arch_radial, &
              arch_inaccessible, arch_unbounded, arch_word, &
              arch_word_fixed, arch_word_length

    !> Longest arch word.
    integer, parameter :: arch_word_length = 12
    !> No answer (bad input).
    integer, parameter :: arch_none = 0
    !> B is on the first half-arch, before the apse.
    integer, parameter :: arch_first = 1
    !> B is on the second half-arch, after the apse.
    integer, parameter :: arch_second = 2
    !> rho = 1: B is the end of a complete brachistochrone (the particle stops at B).
    integer, parameter :: arch_complete = 3
    !> psi = 0: radial fall along OA (K = 0, R = 0).
    integer, parameter :: arch_radial = 4
    !> psi >= 2 pi/3: no brachistochrone; t is the greatest lower bound kappa(rho).
    integer, parameter :: arch_inaccessible = 5
    !> Repulsive force: an unbounded brachistochrone (no apse) through B.
    integer, parameter :: arch_unbounded = 6

contains

    !> Word for an arch code, as written in the CSV `arch` column.
    pure function arch_word(arch) result(word)
        integer, intent(in) :: arch !! arch code
        character(len=:), allocatable :: word
        word = trim(arch_word_fixed(arch))
    end function arch_word

    !> `arch_word` in a fixed-length, blank-padded result (no allocation: safe in
    !! parallel loops).
    pure function arch_word_fixed(arch) result(word)
        integer, intent(in) :: arch !! arch code
        character(len=arch_word_length) :: word
        select case (arch)
        case (arch_first);        word = 'first'
        case (arch_second);       word = 'second'
        case (arch_complete);     word = 'complete'
        case (arch_radial);       word = 'radial'
        case (arch_inaccessible); word = 'inaccessible'
        case (arch_unbounded);    word = 'unbounded'
        case default;             word = 'none'
        end select
    end function arch_word_fixed

end module brachistochrone_arches
