!> `brachistochrone tunnel`: the quickest tunnel between two places on a uniform planet.
!!
!!     brachistochrone tunnel LAT1 LON1 LAT2 LON2 [--radius KM] [--gravity M/S2]
!!
!! Latitudes and longitudes in degrees (north and east positive). Inside a uniform
!! planet gravity is harmonic and the brachistochrone tunnel is a hypocycloid (Saitoh):
!! deepest point R (1 - angle/pi), travel time (pi/omega) sqrt(1 - (R_m/R)^2) from rest
!! to rest, omega = sqrt(g/R). Defaults: R = 6371 km, g = 9.81 m/s^2. Exit codes: 0, or
!! 1 for a usage or input error. (Until 0.2.0 this was the program
!! `brachistochrone-tunnel`.)
module brachistochrone_app_tunnel
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use brachistochrone_kinds, only: qp
    use brachistochrone_status, only: status_ok, status_message
    use brachistochrone_harmonic, only: harmonic_planet, planet_tunnel, plan_tunnel, &
                                        earth_radius_km, earth_gravity
    use brachistochrone_version, only: program_name, program_version
    implicit none
    private

    public :: run_tunnel

    character(len=*), parameter :: name = program_name//' tunnel'

contains

    !> Run the subcommand on the command arguments from number `first` on; stops with the
    !! exit code.
    subroutine run_tunnel(first)
        integer, intent(in) :: first !! index of the subcommand's first argument
        type(harmonic_planet) :: planet
        type(planet_tunnel) :: route
        real(qp) :: coordinates(4)
        call parse_arguments(first, planet, coordinates)
        route = plan_tunnel(coordinates(1), coordinates(2), coordinates(3), coordinates(4), &
                            planet)
        if (route%status /= status_ok) call fail(status_message(route%status))
        call report(planet, route)
        stop 0, quiet=.true.
    end subroutine run_tunnel

    !> The planet and the four coordinates; stops on --help, --version or errors.
    subroutine parse_arguments(first, planet, coordinates)
        integer, intent(in) :: first
        type(harmonic_planet), intent(out) :: planet
        real(qp), intent(out) :: coordinates(4)
        integer :: k, found, ios
        character(len=256) :: argument
        planet = harmonic_planet(radius_km=earth_radius_km, gravity=earth_gravity)
        coordinates = 0.0_qp
        found = 0
        k = first - 1
        do while (k < command_argument_count())
            k = k + 1
            call get_command_argument(k, argument)
            select case (trim(argument))
            case ('-h', '--help')
                call usage(output_unit)
                stop 0, quiet=.true.
            case ('--version')
                write (output_unit, '(a)') name//' '//program_version
                stop 0, quiet=.true.
            case ('--radius', '--gravity')
                if (k == command_argument_count()) call fail(trim(argument)//' needs a value')
                k = k + 1
                if (trim(argument) == '--radius') then
                    call get_command_argument(k, argument)
                    read (argument, *, iostat=ios) planet%radius_km
                else
                    call get_command_argument(k, argument)
                    read (argument, *, iostat=ios) planet%gravity
                end if
                if (ios /= 0) call fail('not a number: '//trim(argument))
            case default
                found = found + 1
                if (found > 4) call fail('expected four numbers LAT1 LON1 LAT2 LON2')
                read (argument, *, iostat=ios) coordinates(found)
                if (ios /= 0) call fail('not a number: '//trim(argument))
            end select
        end do
        if (found /= 4) then
            call usage(error_unit)
            call fail('expected four numbers LAT1 LON1 LAT2 LON2')
        end if
    end subroutine parse_arguments

    !> The tunnel on stdout, in physical units.
    subroutine report(planet, route)
        type(harmonic_planet), intent(in) :: planet
        type(planet_tunnel), intent(in) :: route
        write (output_unit, '(a,f0.3,a,f0.3,a)') 'planet: radius ', planet%radius_km, &
            ' km, surface gravity ', planet%gravity, ' m/s^2'
        write (output_unit, '(a,f0.6,a)') 'central angle:           ', &
            route%central_angle*180.0_qp/acos(-1.0_qp), ' degrees'
        write (output_unit, '(a,f0.3,a)') 'great-circle distance:   ', &
            route%surface_distance_km, ' km'
        write (output_unit, '(a,f0.3,a)') 'brachistochrone tunnel:  ', route%length_km, &
            ' km long (a hypocycloid)'
        write (output_unit, '(a,f0.3,a)') 'deepest point:           ', route%depth_km, &
            ' km below the surface'
        write (output_unit, '(a,f0.3,a,f0.3,a)') 'travel time from rest:   ', &
            route%time_seconds, ' s = ', route%time_minutes, ' min'
        write (output_unit, '(a,f0.3,a,f0.3,a)') 'straight tunnel (chord): ', &
            route%chord_length_km, ' km, ', route%chord_time_seconds/60.0_qp, &
            ' min (the same for every chord)'
    end subroutine report

    subroutine usage(unit)
        integer, intent(in) :: unit
        write (unit, '(a)') 'usage: '//name//' LAT1 LON1 LAT2 LON2 '// &
            '[--radius KM] [--gravity M/S2]'
        write (unit, '(a)') 'The quickest frictionless tunnel between two places on a '// &
            'uniform planet (default: the Earth).'
        write (unit, '(a)') 'Degrees, north and east positive; example: '// &
            '40.7128 -74.0060 34.0522 -118.2437 (New York to Los Angeles).'
        write (unit, '(a)') 'Exit codes: 0 done; 1 usage or input error. Version '// &
            program_version//'.'
    end subroutine usage

    subroutine fail(text)
        character(len=*), intent(in) :: text
        write (error_unit, '(a)') name//': '//text
        stop 1, quiet=.true.
    end subroutine fail

end module brachistochrone_app_tunnel
