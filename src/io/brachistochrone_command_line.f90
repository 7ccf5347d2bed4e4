!> The command line shared by the batch drivers (serial/OpenMP and MPI).
module brachistochrone_command_line
    use brachistochrone_version, only: program_version
    use brachistochrone_fields, only: field_names
    use brachistochrone_result_output, only: output_request
    implicit none
    private

    public :: run_options, parse_command_line, write_usage, get_argument
    public :: exit_ok, exit_input, exit_unsolved, exit_io

    !> Exit codes of the drivers.
    integer, parameter :: exit_ok = 0, exit_input = 1, exit_unsolved = 2, exit_io = 3

    !> Everything the command line says.
    type :: run_options
        character(len=:), allocatable :: input_path  !! the namelist file
        type(output_request) :: request              !! files to write
        integer :: first = -1          !! first row (-1: 1)
        integer :: last = -1           !! last row (-1: n)
        integer :: threads = 0         !! OpenMP threads (0: default)
        logical :: quiet = .false.     !! no progress on stderr
        logical :: check_only = .false. !! validate only
        logical :: show_table = .true. !! table on stdout
        logical :: help = .false.      !! --help given
        logical :: version = .false.   !! --version given
    end type run_options

contains

    !> Parse the arguments. status = exit_ok, or exit_input with `message` set.
    subroutine parse_command_line(options, status, message)
        type(run_options), intent(out) :: options         !! the options
        integer, intent(out) :: status                    !! exit_ok or exit_input
        character(len=:), allocatable, intent(out) :: message !! what is wrong
        integer :: k, count_arguments
        character(len=:), allocatable :: argument, value

        options%input_path = ''
        options%request%csv_path = ''
        options%request%nml_path = ''
        options%request%table_path = ''
        options%request%curves_path = ''
        options%request%force = .false.
        status = exit_ok
        message = ''
        count_arguments = command_argument_count()
        k = 0
        do while (k < count_arguments)
            k = k + 1
            argument = get_argument(k)
            select case (argument)
            case ('-h', '--help')
                options%help = .true.
                return
            case ('--version')
                options%version = .true.
                return
            case ('--csv', '--nml', '--table', '--curves', '--first', '--last', '--threads')
                if (k == count_arguments) then
                    call problem(argument//' needs a value')
                    return
                end if
                k = k + 1
                value = get_argument(k)
                select case (argument)
                case ('--csv');     options%request%csv_path = value
                case ('--nml');     options%request%nml_path = value
                case ('--table');   options%request%table_path = value
                case ('--curves');  options%request%curves_path = value
                case ('--first');   options%first = whole_number(value)
                case ('--last');    options%last = whole_number(value)
                case ('--threads')
                    options%threads = whole_number(value)
                    if (options%threads < 1) call problem('--threads needs a number >= 1')
                end select
                if (status /= exit_ok) return
            case ('--force')
                options%request%force = .true.
            case ('--quiet')
                options%quiet = .true.
            case ('--no-table')
                options%show_table = .false.
            case ('--check')
                options%check_only = .true.
            case default
                if (argument(1:1) == '-') then
                    call problem('unknown option '//argument//' (see --help)')
                    return
                end if
                if (len(options%input_path) > 0) then
                    call problem('only one input file, got '//options%input_path//' and '// &
                                 argument)
                    return
                end if
                options%input_path = argument
            end select
        end do
        if (len(options%input_path) == 0) then
            call problem('no input file given (see --help)')
        end if

    contains

        integer function whole_number(text)
            character(len=*), intent(in) :: text
            integer :: ios
            whole_number = 0
            read (text, *, iostat=ios) whole_number
            if (ios /= 0 .or. len(text) == 0 .or. verify(text, '0123456789') /= 0) then
                call problem(argument//' needs a whole number, got "'//text//'"')
            end if
        end function whole_number

        subroutine problem(text)
            character(len=*), intent(in) :: text
            status = exit_input
            message = text
        end subroutine problem

    end subroutine parse_command_line

    !> The usage text.
    subroutine write_usage(unit, driver)
        integer, intent(in) :: unit             !! where to write
        character(len=*), intent(in) :: driver  !! executable name, for the first line
        write (unit, '(a)') 'usage: '//driver//' [options] FILE.nml'
        write (unit, '(a)') ''
        write (unit, '(a)') 'Solves the brachistochrone from A = (1, 0) to each endpoint '// &
            '(rho, psi) of the namelist'
        write (unit, '(a)') 'group &endpoints in FILE.nml, in the field that its variable '// &
            'force names (Tee 1998):'
        write (unit, '(a)') '  '//field_names//';'
        write (unit, '(a)') '  default ''inverse_square'' (attractive, F = mu/r^2); '// &
            '''power'' needs exponent = n > 1.'
        write (unit, '(a)') 'Prints a table; every output names the field it solved.'
        write (unit, '(a)') '  --csv OUT.csv       write rho,psi,arch,R,s,t,steps,status'
        write (unit, '(a)') '  --nml OUT.nml       write the results as namelist group '// &
            '&results (reads back bit for bit)'
        write (unit, '(a)') '  --table OUT.txt     write the readable table to a file'
        write (unit, '(a)') '  --curves OUT.csv    write id,point,r,theta,s,t,x,y along each '// &
            'brachistochrone'
        write (unit, '(a)') '                      (curve_points = N in &endpoints: N points '// &
            'from A to B)'
        write (unit, '(a)') '  --no-table          do not print the table on stdout'
        write (unit, '(a)') '  --first I --last J  solve rows I..J only (1-based, '// &
            'inclusive): one job of an array'
        write (unit, '(a)') '  --threads N         OpenMP threads (default: '// &
            'OMP_NUM_THREADS, or all cores)'
        write (unit, '(a)') '  --force             replace output files that exist'
        write (unit, '(a)') '  --quiet             no progress report on stderr'
        write (unit, '(a)') '  --check             only validate FILE.nml'
        write (unit, '(a)') '  --version, --help'
        write (unit, '(a)') 'Exit codes: 0 all solved; 1 usage or input error (nothing '// &
            'written); 2 some endpoints'
        write (unit, '(a)') 'have no solution (files written, see their status); 3 I/O '// &
            'error. Version '//program_version//'.'
    end subroutine write_usage

    !> The k-th command-line argument, of its own length.
    function get_argument(k) result(argument)
        integer, intent(in) :: k !! position, 1-based
        character(len=:), allocatable :: argument
        integer :: length
        call get_command_argument(k, length=length)
        allocate (character(len=length) :: argument)
        call get_command_argument(k, argument)
    end function get_argument

end module brachistochrone_command_line
