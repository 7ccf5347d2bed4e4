!> brachistochrone: solve a table of endpoints read from a namelist file.
!!
!!     brachistochrone [options] FILE.nml
!!
!! Exit codes: 0 every endpoint solved; 1 usage or input error (nothing written);
!! 2 some endpoints have no solution (files written, their status says why);
!! 3 I/O error. See `--help` and the README for the options.
program main
    use, intrinsic :: iso_fortran_env, only: error_unit, output_unit, int64
    !$ use omp_lib, only: omp_set_num_threads, omp_get_max_threads
    use brachistochrone, only: qp, inverse_square_model, new_inverse_square_model, &
                               endpoint_solution, solve_endpoint, solve_endpoint_secant, &
                               status_ok
    use brachistochrone_version, only: program_name, program_version
    use endpoint_input, only: endpoint_table, read_endpoint_file
    use result_output, only: output_request, write_outputs, write_table_header, &
                             write_table_row
    use run_support, only: timestamp, progress_type, integer_text
    implicit none

    integer, parameter :: exit_ok = 0, exit_input = 1, exit_unsolved = 2, exit_io = 3

    character(len=:), allocatable :: input_path, message
    type(output_request) :: request
    type(endpoint_table) :: table
    type(inverse_square_model) :: model
    type(endpoint_solution), allocatable :: solutions(:)
    type(progress_type) :: progress
    integer :: i, first, last, threads, code, status, unsolved
    logical :: quiet, check_only, show_table

    call parse_arguments()
    !$ if (threads > 0) call omp_set_num_threads(threads)

    call read_endpoint_file(input_path, table)
    if (size(table%errors) > 0) then
        do i = 1, size(table%errors)
            write (error_unit, '(a)') program_name//': '//table%errors(i)%text
        end do
        call fail(exit_input, integer_text(size(table%errors))//' problem(s) in '// &
                  input_path//'; nothing was computed or written')
    end if
    if (first == -1) first = 1
    if (last == -1) last = table%n
    if (first < 1 .or. last > table%n .or. first > last) then
        call fail(exit_input, '--first '//integer_text(first)//' --last '// &
                  integer_text(last)//' is not a slice of the '//integer_text(table%n)// &
                  ' rows of '//input_path//' (need 1 <= first <= last <= n)')
    end if
    if (check_only) then
        write (output_unit, '(a)') input_path//': '//integer_text(table%n)// &
            ' endpoints, valid'
        stop exit_ok, quiet=.true.
    end if
    call refuse_existing(request%csv_path)
    call refuse_existing(request%nml_path)
    call refuse_existing(request%table_path)

    model = new_inverse_square_model()
    allocate (solutions(first:last))
    call progress%start(last - first + 1, .not. quiet)
    !$omp parallel do schedule(dynamic, 16) default(shared) private(i)
    do i = first, last
        if (table%has_estimates(i)) then
            solutions(i) = solve_endpoint_secant(model, table%rho(i), table%psi(i), &
                                                 table%r0(i), table%r1(i), &
                                                 table%secant_tolerance)
        else
            solutions(i) = solve_endpoint(model, table%rho(i), table%psi(i))
        end if
        call progress%step()
    end do
    !$omp end parallel do
    call progress%finish()

    call write_outputs(request, table, first, last, solutions, timestamp(), status, message)
    if (status == 1) call fail(exit_input, message)
    if (status /= 0) call fail(exit_io, message)
    if (show_table) then
        call write_table_header(output_unit)
        do i = first, last
            call write_table_row(output_unit, i, solutions(i))
        end do
    end if

    code = exit_ok
    unsolved = count(solutions%status /= status_ok)
    if (unsolved > 0) then
        write (error_unit, '(a)') program_name//': '//integer_text(unsolved)//' of '// &
            integer_text(last - first + 1)//' endpoints have no solution; see their status'
        code = exit_unsolved
    end if
    stop code, quiet=.true.

contains

    subroutine parse_arguments()
        integer :: k, count_arguments
        character(len=:), allocatable :: argument
        input_path = ''
        request%csv_path = ''
        request%nml_path = ''
        request%table_path = ''
        request%force = .false.
        quiet = .false.
        check_only = .false.
        show_table = .true.
        first = -1
        last = -1
        threads = 0
        count_arguments = command_argument_count()
        k = 0
        do while (k < count_arguments)
            k = k + 1
            argument = get_argument(k)
            select case (argument)
            case ('-h', '--help')
                call usage(output_unit)
                stop exit_ok, quiet=.true.
            case ('--version')
                write (output_unit, '(a)') program_name//' '//program_version
                stop exit_ok, quiet=.true.
            case ('--csv')
                request%csv_path = value_of(k, argument)
            case ('--nml')
                request%nml_path = value_of(k, argument)
            case ('--table')
                request%table_path = value_of(k, argument)
            case ('--first')
                first = integer_of(k, argument)
            case ('--last')
                last = integer_of(k, argument)
            case ('--threads')
                threads = integer_of(k, argument)
                if (threads < 1) call fail(exit_input, '--threads needs a number >= 1')
            case ('--force')
                request%force = .true.
            case ('--quiet')
                quiet = .true.
            case ('--no-table')
                show_table = .false.
            case ('--check')
                check_only = .true.
            case default
                if (argument(1:1) == '-') call fail(exit_input, 'unknown option '// &
                                                    argument//' (see --help)')
                if (len(input_path) > 0) call fail(exit_input, 'only one input file, got '// &
                                                   input_path//' and '//argument)
                input_path = argument
            end select
        end do
        if (len(input_path) == 0) then
            call usage(error_unit)
            call fail(exit_input, 'no input file given')
        end if
    end subroutine parse_arguments

    function value_of(k, option) result(value)
        integer, intent(inout) :: k
        character(len=*), intent(in) :: option
        character(len=:), allocatable :: value
        if (k == command_argument_count()) call fail(exit_input, option//' needs a value')
        k = k + 1
        value = get_argument(k)
    end function value_of

    integer function integer_of(k, option)
        integer, intent(inout) :: k
        character(len=*), intent(in) :: option
        character(len=:), allocatable :: text
        integer :: ios
        text = value_of(k, option)
        read (text, *, iostat=ios) integer_of
        if (ios /= 0 .or. verify(text, '0123456789') /= 0) &
            call fail(exit_input, option//' needs a whole number, got '//text)
    end function integer_of

    subroutine refuse_existing(path)
        character(len=*), intent(in) :: path
        logical :: exists
        if (len(path) == 0 .or. request%force) return
        inquire (file=path, exist=exists)
        if (exists) call fail(exit_input, path//' exists; use --force to replace it, '// &
                              'or choose another name')
    end subroutine refuse_existing

    subroutine usage(unit)
        integer, intent(in) :: unit
        write (unit, '(a)') 'usage: '//program_name//' [options] FILE.nml'
        write (unit, '(a)') ''
        write (unit, '(a)') 'Solves the brachistochrone from A = (1, 0) to each endpoint '// &
            '(rho, psi) of the namelist'
        write (unit, '(a)') 'group &endpoints in FILE.nml (attractive inverse-square '// &
            'force, Tee 1998). Prints a table.'
        write (unit, '(a)') '  --csv OUT.csv     write rho,psi,arch,R,s,t,steps,status'
        write (unit, '(a)') '  --nml OUT.nml     write the results as namelist group '// &
            '&results (reads back bit for bit)'
        write (unit, '(a)') '  --table OUT.txt   write the readable table to a file'
        write (unit, '(a)') '  --no-table        do not print the table on stdout'
        write (unit, '(a)') '  --first I --last J  solve rows I..J only (1-based, '// &
            'inclusive), e.g. one job of an array'
        write (unit, '(a)') '  --threads N       OpenMP threads (default: '// &
            'OMP_NUM_THREADS or all cores)'
        write (unit, '(a)') '  --force           replace output files that exist'
        write (unit, '(a)') '  --quiet           no progress report on stderr'
        write (unit, '(a)') '  --check           only validate FILE.nml'
        write (unit, '(a)') 'Exit codes: 0 all solved, 1 usage or input error (nothing '// &
            'written), 2 some endpoints'
        write (unit, '(a)') 'unsolved (files written), 3 I/O error.'
    end subroutine usage

    function get_argument(k) result(argument)
        integer, intent(in) :: k
        character(len=:), allocatable :: argument
        integer :: length
        call get_command_argument(k, length=length)
        allocate (character(len=length) :: argument)
        call get_command_argument(k, argument)
    end function get_argument

    subroutine fail(exit_code, text)
        integer, intent(in) :: exit_code
        character(len=*), intent(in) :: text
        write (error_unit, '(a)') program_name//': '//text
        stop exit_code, quiet=.true.
    end subroutine fail

end program main
