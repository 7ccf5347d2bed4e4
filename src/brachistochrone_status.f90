!> Status codes returned by every library routine, with their words and messages.
!!
!! The library never prints or stops: each routine returns one of these codes and
!! leaves its outputs defined (zero, or the best value it has). `status_word` gives the
!! short word used in the CSV `status` column, `status_message` a sentence for humans.
module brachistochrone_status
    use brachistochrone_kinds, only: qp
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    public :: status_ok, status_inaccessible, status_rho_out_of_range, &
              status_psi_out_of_range, status_not_finite, status_no_convergence, &
              status_outside_domain, status_invalid_argument, status_bad_estimates, &
              status_latitude_out_of_range, status_bad_planet, &
              status_above_start, status_parameter_out_of_range, &
              status_rho_below_start
    public :: status_unknown_field, status_bad_exponent, status_not_supported
    public :: status_word, status_word_fixed, status_word_length, status_message
    public :: argument_status, keep_first, first_failure

    !> Longest status word.
    integer, parameter :: status_word_length = 24
    !> Success.
    integer, parameter :: status_ok = 0
    !> Endpoint in the sector of inaccessibility (psi >= 2 pi/3): no brachistochrone.
    integer, parameter :: status_inaccessible = 1
    !> Endpoint radius outside 0 < rho <= 1.
    integer, parameter :: status_rho_out_of_range = 2
    !> Endpoint angle outside 0 <= psi <= pi.
    integer, parameter :: status_psi_out_of_range = 3
    !> An input was NaN or infinite.
    integer, parameter :: status_not_finite = 4
    !> An iteration did not converge within its step limit.
    integer, parameter :: status_no_convergence = 5
    !> The paper's secant iteration stepped outside 0 < R <= rho.
    integer, parameter :: status_outside_domain = 6
    !> A routine was called with arguments outside its domain (for example r < R).
    integer, parameter :: status_invalid_argument = 7
    !> Initial estimates for the secant method are unusable (equal, or outside (0, rho]).
    integer, parameter :: status_bad_estimates = 8
    !> A latitude outside -90 <= latitude <= 90 degrees (harmonic tunnels between places).
    integer, parameter :: status_latitude_out_of_range = 9
    !> A planet whose radius or surface gravity is not positive and finite.
    integer, parameter :: status_bad_planet = 10
    !> Uniform gravity: the endpoint B lies above the start A (y_B < 0, y measured
    !! downward), which a particle released from rest at A can never reach.
    integer, parameter :: status_above_start = 11
    !> A physical parameter is outside its domain: gravity, lengths and radii must be
    !! positive, x_B >= 0, release heights within the arch, amplitudes 0 <= theta0 <= pi.
    integer, parameter :: status_parameter_out_of_range = 12
    !> Repulsive field: endpoint radius below the start (rho < 1), never reached.
    integer, parameter :: status_rho_below_start = 13
    !> The field name is not one of the fields the library knows (`field_names`).
    integer, parameter :: status_unknown_field = 14
    !> Power law: the exponent n of F = mu/r^n is outside the supported range 1 < n <= 32.
    integer, parameter :: status_bad_exponent = 15
    !> The field does not support the operation asked for (for example sampling its
    !! curves, or the paper's secant method from initial estimates).
    integer, parameter :: status_not_supported = 16

contains

    !> Keep the first failure: `status` becomes `next` only while it is still status_ok,
    !! so a routine reports what went wrong first, never a `max` of unrelated codes.
    elemental subroutine keep_first(status, next)
        integer, intent(inout) :: status !! the status so far
        integer, intent(in) :: next      !! the status of the next step
        if (status == status_ok) status = next
    end subroutine keep_first

    !> The first code of `statuses` that is not status_ok (status_ok if none is).
    pure function first_failure(statuses) result(status)
        integer, intent(in) :: statuses(:) !! statuses of steps, in the order they ran
        integer :: status
        integer :: k
        status = status_ok
        do k = 1, size(statuses)
            if (statuses(k) /= status_ok) then
                status = statuses(k)
                return
            end if
        end do
    end function first_failure

    !> The status of a routine's real arguments: status_not_finite if any is NaN or
    !! infinite (checked first, since comparisons with NaN are all false), otherwise
    !! status_invalid_argument unless `valid`, else status_ok.
    pure function argument_status(values, valid) result(status)
        real(qp), intent(in) :: values(:)  !! the arguments
        logical, intent(in) :: valid       !! they satisfy the routine's preconditions
        integer :: status
        if (.not. all(ieee_is_finite(values))) then
            status = status_not_finite
        else if (.not. valid) then
            status = status_invalid_argument
        else
            status = status_ok
        end if
    end function argument_status

    !> Short lowercase word for a status code, as written in the CSV `status` column.
    pure function status_word(code) result(word)
        integer, intent(in) :: code !! status code
        character(len=:), allocatable :: word
        word = trim(status_word_fixed(code))
    end function status_word

    !> `status_word` in a fixed-length, blank-padded result (no allocation: safe in
    !! parallel loops).
    pure function status_word_fixed(code) result(word)
        integer, intent(in) :: code !! status code
        character(len=status_word_length) :: word
        select case (code)
        case (status_ok);               word = 'ok'
        case (status_inaccessible);     word = 'inaccessible'
        case (status_rho_out_of_range); word = 'rho_out_of_range'
        case (status_psi_out_of_range); word = 'psi_out_of_range'
        case (status_not_finite);       word = 'not_finite'
        case (status_no_convergence);   word = 'no_convergence'
        case (status_outside_domain);   word = 'secant_left_domain'
        case (status_invalid_argument); word = 'invalid_argument'
        case (status_bad_estimates);    word = 'bad_estimates'
        case (status_latitude_out_of_range); word = 'latitude_out_of_range'
        case (status_bad_planet);       word = 'bad_planet'
        case (status_above_start);      word = 'above_start'
        case (status_parameter_out_of_range); word = 'parameter_out_of_range'
        case (status_rho_below_start);  word = 'rho_below_start'
        case (status_unknown_field);    word = 'unknown_field'
        case (status_bad_exponent);     word = 'bad_exponent'
        case (status_not_supported);    word = 'not_supported'
        case default;                   word = 'unknown_status'
        end select
    end function status_word_fixed

    !> One-sentence explanation of a status code, for error messages.
    pure function status_message(code) result(message)
        integer, intent(in) :: code !! status code
        character(len=:), allocatable :: message
        select case (code)
        case (status_ok)
            message = 'solved'
        case (status_inaccessible)
            message = 'endpoint lies in the field''s sector of inaccessibility (inverse '// &
                      'square: psi >= 2*pi/3; power law n: psi >= 2*pi/(n+1)): no '// &
                      'brachistochrone reaches it; t is the greatest lower bound of the time'
        case (status_rho_out_of_range)
            message = 'rho must satisfy 0 < rho <= 1 (the start A is at radius 1)'
        case (status_psi_out_of_range)
            message = 'psi must satisfy 0 <= psi <= pi (use 2*pi - psi by symmetry)'
        case (status_not_finite)
            message = 'an input value is NaN or infinite'
        case (status_no_convergence)
            message = 'the iteration did not converge within its step limit'
        case (status_outside_domain)
            message = 'the secant iteration stepped outside 0 < R <= rho; give other r0, r1 '// &
                      'or leave them out to use the bracketing solver'
        case (status_invalid_argument)
            message = 'an argument is outside the domain the routine documents (for the '// &
                      'arch integrals: 0 < R <= r <= 1, R < 1)'
        case (status_bad_estimates)
            message = 'initial estimates r0, r1 must differ and lie in 0 < R <= rho'
        case (status_latitude_out_of_range)
            message = 'latitude must satisfy -90 <= latitude <= 90 (degrees)'
        case (status_bad_planet)
            message = 'the planet radius and surface gravity must be positive and finite'
        case (status_above_start)
            message = 'the endpoint lies above the start (y_B < 0 with y downward): a '// &
                      'particle released from rest cannot reach it'
        case (status_parameter_out_of_range)
            message = 'a physical parameter is outside its domain (g, lengths and radii > 0, '// &
                      'x_B >= 0, release height within the arch, 0 <= amplitude <= pi)'
        case (status_rho_below_start)
            message = 'repulsive field: rho must satisfy rho >= 1 (the start A is at radius '// &
                      '1 and every path moves outward)'
        case (status_unknown_field)
            message = 'unknown field: give one of ''inverse_square'', ''power'', '// &
                      '''logarithmic'', ''harmonic'', ''repulsive'', ''uniform'''
        case (status_bad_exponent)
            message = 'the power-law exponent n of F = mu/r^n must satisfy 1 < n <= 32'
        case (status_not_supported)
            message = 'this field does not support the operation (curve sampling, or the '// &
                      'secant method from estimates r0, r1, is inverse-square only)'
        case default
            message = 'unknown status'
        end select
    end function status_message

end module brachistochrone_status
