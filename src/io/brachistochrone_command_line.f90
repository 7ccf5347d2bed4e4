!> The command line shared by the batch drivers (serial/OpenMP and MPI).
module brachistochrone_command_line
    use brachistochrone_version, only: program_version
    use brachistochrone_fields, only: field_names
    use brachistochrone_result_output, only: output_request
    use brachistochrone_strings, only: integer_text, escape_text
    implicit none
    private

    public :: run_options, parse_command_line, write_usage, get_argument
    public :: exit_ok, exit_input, exit_unsolved, exit_io, max_threads

    !> Exit codes of the drivers.
    integer, parameter :: exit_ok = 0, exit_input = 1, exit_unsolved = 2, exit_io = 3
    !> Largest --threads accepted (beyond it the OpenMP runtime aborts or crashes).
    integer, parameter :: max_threads = 1024

    !> Everything the command line says.
    type :: run_options
        character(len=:), allocatable :: input_path  !! the namelist file
        type(output_request) :: request              !! files to write
        integer :: first = -1          !! first row (-1: 1)
        integer :: last = -1           !! last row (-1: n)
        integer :: threads = 0         !! OpenMP threads (0: default)
        integer :: slice = 0           !! --slice K/N: K (0: no slice)
        integer :: slices = 0          !! --slice K/N: N
        logical :: unsolved_ok = .false. !! endpoints without a solution still exit 0
        logical :: quiet = .false.     !! no progress on stderr
        logical :: check_only = .false. !! validate only
        logical :: show_table = .true. !! table on stdout
        logical :: help = .false.      !! --help given
        logical :: version = .false.   !! --version given
    end type run_options

contains

    !> Parse the arguments. status = exit_ok, or exit_input with `message` set.
    !! Options take their value as the next argument or after `=` (`--csv=OUT.csv`); a
    !! value never starts with `-` (so `--csv --force` is an error), except `-` itself,
    !! standard output, for one of --csv, --nml, --table, --curves (the table is then not
    !! printed). `--` ends the options.
    subroutine parse_command_line(options, status, message)
        type(run_options), intent(out) :: options         !! the options
        integer, intent(out) :: status                    !! exit_ok or exit_input
        character(len=:), allocatable, intent(out) :: message !! what is wrong
        integer :: k, count_arguments
        character(len=:), allocatable :: argument, value
        logical :: has_value, options_ended

        options%input_path = ''
        options%request%csv_path = ''
        options%request%nml_path = ''
        options%request%table_path = ''
        options%request%curves_path = ''
        options%request%force = .false.
        status = exit_ok
        message = ''
        options_ended = .false.
        count_arguments = command_argument_count()
        k = 0
        do while (k < count_arguments .and. status == exit_ok)
            k = k + 1
            argument = get_argument(k)
            if (.not. is_option(argument)) then
                call take_input(argument)
                cycle
            end if
            call split_value(argument, value, has_value)
            select case (argument)
            case ('-h', '--help')
                options%help = .true.
                return
            case ('--version')
                options%version = .true.
                return
            case ('--')
                options_ended = .true.
            case ('--csv', '--nml', '--table', '--curves', '--first', '--last', '--threads', &
                  '--slice')
                if (.not. has_value) then
                    if (k == count_arguments) then
                        call problem(argument//' needs a value')
                        exit
                    end if
                    k = k + 1
                    value = get_argument(k)
                end if
                call take_value(argument, value)
            case ('--force', '--quiet', '--no-table', '--check', '--unsolved-ok')
                if (has_value) call problem(escape_text(argument)//' takes no value')
                select case (argument)
                case ('--force');    options%request%force = .true.
                case ('--quiet');    options%quiet = .true.
                case ('--no-table'); options%show_table = .false.
                case ('--unsolved-ok'); options%unsolved_ok = .true.
                case default;        options%check_only = .true.
                end select
            case default
                call problem('unknown option '//escape_text(argument)//' (see --help)')
            end select
        end do
        if (status == exit_ok) call check_outputs()

    contains

        !> An option: starts with -, is not - itself, and no `--` came before.
        logical function is_option(text)
            character(len=*), intent(in) :: text
            is_option = .false.
            if (options_ended .or. len(text) < 2) return
            is_option = text(1:1) == '-'
        end function is_option

        !> `--name=value` -> `--name`, `value`.
        subroutine split_value(text, value, has_value)
            character(len=:), allocatable, intent(inout) :: text
            character(len=:), allocatable, intent(out) :: value
            logical, intent(out) :: has_value
            integer :: equals
            equals = 0
            if (len(text) > 2) then
                if (text(1:2) == '--') equals = index(text, '=')
            end if
            has_value = equals > 0
            value = ''
            if (.not. has_value) return
            value = text(equals + 1:)
            text = text(:equals - 1)
        end subroutine split_value

        subroutine take_input(path)
            character(len=*), intent(in) :: path
            if (len(path) == 0) then
                call problem('an empty argument is not a file name')
            else if (len(options%input_path) > 0) then
                call problem('only one input file, got '//escape_text(options%input_path)// &
                             ' and '//escape_text(path))
            else
                options%input_path = path
            end if
        end subroutine take_input

        subroutine take_value(option, text)
            character(len=*), intent(in) :: option, text
            if (len(text) == 0) then
                call problem(option//' needs a value, got an empty one')
                return
            else if (text(1:1) == '-' .and. text /= '-') then
                call problem(option//' needs a value, got the option "'//escape_text(text)// &
                             '" (a file name starting with - can be written ./'// &
                             escape_text(text)//')')
                return
            end if
            select case (option)
            case ('--csv');     options%request%csv_path = text
            case ('--nml');     options%request%nml_path = text
            case ('--table');   options%request%table_path = text
            case ('--curves');  options%request%curves_path = text
            case ('--first');   options%first = whole_number(option, text)
            case ('--last');    options%last = whole_number(option, text)
            case ('--slice');   call take_slice(text)
            case default
                options%threads = whole_number(option, text)
                if (status == exit_ok .and. (options%threads < 1 .or. &
                    options%threads > max_threads)) call problem('--threads needs a number '// &
                    'from 1 to '//integer_text(max_threads)//', got '//escape_text(text))
            end select
        end subroutine take_value

        !> `K/N`: slice K of N nearly equal slices of the rows, 1 <= K <= N.
        subroutine take_slice(text)
            character(len=*), intent(in) :: text
            integer :: slash
            slash = index(text, '/')
            if (slash > 1 .and. slash < len(text)) then
                options%slice = whole_number('--slice', text(:slash - 1))
                options%slices = whole_number('--slice', text(slash + 1:))
            end if
            if (status /= exit_ok) return
            if (slash <= 1 .or. slash == len(text) .or. options%slices < 1 .or. &
                options%slice < 1 .or. options%slice > options%slices) then
                call problem('--slice needs K/N with 1 <= K <= N (slice K of N, for '// &
                             'example --slice 3/10 or --slice $SLURM_ARRAY_TASK_ID/'// &
                             '$SLURM_ARRAY_TASK_COUNT), got "'//escape_text(text)//'"')
            end if
        end subroutine take_slice

        !> An input is needed; at most one output is standard output, and then the table
        !! is not printed there.
        subroutine check_outputs()
            integer :: dashes
            if (options%help .or. options%version) return
            if (len(options%input_path) == 0) then
                call problem('no input file given (see --help)')
                return
            end if
            if (options%slices > 0 .and. (options%first /= -1 .or. options%last /= -1)) then
                call problem('--slice K/N chooses the rows itself; leave out --first and --last')
                return
            end if
            dashes = count([options%request%csv_path == '-', options%request%nml_path == '-', &
                            options%request%table_path == '-', &
                            options%request%curves_path == '-'])
            if (dashes > 1) then
                call problem('only one output can be standard output (-)')
            else if (dashes == 1) then
                options%show_table = .false.
            end if
        end subroutine check_outputs

        integer function whole_number(option, text)
            character(len=*), intent(in) :: option, text
            integer :: ios
            whole_number = 0
            if (len(text) == 0 .or. len(text) > 9 .or. verify(text, '0123456789') /= 0) then
                ios = 1
            else
                read (text, *, iostat=ios) whole_number
            end if
            if (ios /= 0) call problem(option//' needs a whole number (at most 9 digits), '// &
                                       'got "'//escape_text(text)//'"')
        end function whole_number

        subroutine problem(text)
            character(len=*), intent(in) :: text
            if (status /= exit_ok) return
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
            '''power'' needs exponent = n, 1 < n <= 32;'
        write (unit, '(a)') '  ''uniform'' (gravity g = 1) takes Cartesian x, y (down from A) '// &
            'instead of rho, psi.'
        write (unit, '(a)') 'Prints a table; every output names the field it solved.'
        write (unit, '(a)') '  --csv OUT.csv       write rho,psi,arch,R,s,t,steps,status '// &
            '(OUT = - : stdout)'
        write (unit, '(a)') '  --nml OUT.nml       write the results as namelist group '// &
            '&results (reads back bit for bit)'
        write (unit, '(a)') '  --table OUT.txt     write the readable table to a file'
        write (unit, '(a)') '  --curves OUT.csv    write id,point,r,theta,s,t,x,y along each '// &
            'brachistochrone'
        write (unit, '(a)') '                      (curve_points = N in &endpoints: N points '// &
            'from A to B)'
        write (unit, '(a)') '  --no-table          do not print the table on stdout'
        write (unit, '(a)') '  --first I --last J  solve rows I..J only (1-based, '// &
            'inclusive, J <= n)'
        write (unit, '(a)') '  --slice K/N         solve slice K of N nearly equal slices of '// &
            'the rows (job arrays;'
        write (unit, '(a)') '                      any N <= n; join the CSVs with: '// &
            driver//' merge)'
        write (unit, '(a)') '  --unsolved-ok       exit 0 also when some endpoints have no '// &
            'solution (their status says why)'
        write (unit, '(a)') '  --threads N         OpenMP threads, 1..'// &
            integer_text(max_threads)//' (default: OMP_NUM_THREADS, or all cores)'
        write (unit, '(a)') '  --force             replace output files (regular files or '// &
            'symlinks) that exist'
        write (unit, '(a)') '  --quiet             no progress report on stderr'
        write (unit, '(a)') '  --check             only validate FILE.nml'
        write (unit, '(a)') '  --version, --help'
        write (unit, '(a)') 'Exit codes: 0 all solved; 1 usage or input error (nothing '// &
            'written); 2 some endpoints'
        write (unit, '(a)') 'have no solution (files written, see their status); 3 I/O '// &
            'error (no file written);'
        write (unit, '(a)') '128 + N killed by signal N (no file written; 141: stdout '// &
            'closed). Version '//program_version//'.'
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
