!> brachistochrone: solve a table of endpoints read from a namelist file.
!!
!!     brachistochrone [--csv OUT.csv] [--force] FILE.nml
!!
!! Exit codes: 0 every endpoint solved; 1 usage or input error (nothing written);
!! 2 some endpoints have no solution (table written, their status says why); 3 I/O error.
program main
    use, intrinsic :: iso_fortran_env, only: error_unit, output_unit, compiler_version, &
                                              compiler_options
    use brachistochrone, only: qp, inverse_square_model, new_inverse_square_model, &
                               endpoint_solution, solve_endpoint, solve_endpoint_secant, &
                               status_ok
    use endpoint_input, only: endpoint_table, read_endpoint_file
    use result_output, only: csv_header, csv_row, write_table_header, write_table_row, &
                             commit_file, temporary_name
    implicit none

    character(len=*), parameter :: program_name = 'brachistochrone'
    character(len=*), parameter :: program_version = '0.1.0'
    integer, parameter :: exit_ok = 0, exit_input = 1, exit_unsolved = 2, exit_io = 3

    character(len=:), allocatable :: input_path, csv_path
    logical :: force
    type(endpoint_table) :: table
    type(inverse_square_model) :: model
    type(endpoint_solution), allocatable :: solutions(:)
    integer :: i, code

    call parse_arguments(input_path, csv_path, force)
    if (len(csv_path) > 0 .and. .not. force) then
        if (exists(csv_path)) call fail(exit_input, csv_path//' exists; use --force to '// &
                                        'replace it, or choose another --csv name')
    end if

    call read_endpoint_file(input_path, table)
    if (size(table%errors) > 0) then
        do i = 1, size(table%errors)
            write (error_unit, '(a)') program_name//': '//table%errors(i)%text
        end do
        call fail(exit_input, integer_text(size(table%errors))//' problem(s) in '// &
                  input_path//'; nothing was computed or written')
    end if

    model = new_inverse_square_model()
    allocate (solutions(table%n))
    !$omp parallel do schedule(dynamic, 16) default(shared) private(i)
    do i = 1, table%n
        if (table%has_estimates(i)) then
            solutions(i) = solve_endpoint_secant(model, table%rho(i), table%psi(i), &
                                                 table%r0(i), table%r1(i), &
                                                 table%secant_tolerance)
        else
            solutions(i) = solve_endpoint(model, table%rho(i), table%psi(i))
        end if
    end do
    !$omp end parallel do

    if (len(csv_path) > 0) call write_csv(csv_path)
    call write_table_header(output_unit)
    do i = 1, table%n
        call write_table_row(output_unit, i, solutions(i))
    end do

    code = exit_ok
    if (any(solutions%status /= status_ok)) then
        write (error_unit, '(a)') program_name//': '// &
            integer_text(count(solutions%status /= status_ok))//' of '// &
            integer_text(table%n)//' endpoints have no solution; see their status'
        code = exit_unsolved
    end if
    stop code, quiet=.true.

contains

    subroutine write_csv(path)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: temporary
        character(len=512) :: io_message
        integer :: unit, ios, row, status
        temporary = temporary_name(path)
        open (newunit=unit, file=temporary, status='replace', action='write', &
              iostat=ios, iomsg=io_message)
        if (ios /= 0) call fail(exit_io, 'cannot write '//path//': '//trim(io_message))
        write (unit, '(a)', iostat=ios) '# '//program_name//' '//program_version
        write (unit, '(a)', iostat=ios) '# compiler: '//compiler_version()
        write (unit, '(a)', iostat=ios) '# options: '//compiler_options()
        write (unit, '(a)', iostat=ios) '# input: '//input_path//'  date: '//timestamp()
        write (unit, '(a)', iostat=ios) csv_header
        do row = 1, size(solutions)
            if (ios /= 0) exit
            write (unit, '(a)', iostat=ios, iomsg=io_message) csv_row(solutions(row))
        end do
        if (ios /= 0) then
            close (unit, status='delete')
            call fail(exit_io, 'cannot write '//path//': '//trim(io_message))
        end if
        close (unit)
        call commit_file(temporary, path, status)
        if (status /= 0) then
            open (newunit=unit, file=temporary)
            close (unit, status='delete')
            call fail(exit_io, 'cannot rename the finished output onto '//path)
        end if
    end subroutine write_csv

    subroutine parse_arguments(input, csv, overwrite)
        character(len=:), allocatable, intent(out) :: input, csv
        logical, intent(out) :: overwrite
        integer :: k, count_arguments
        character(len=:), allocatable :: argument
        input = ''
        csv = ''
        overwrite = .false.
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
                if (k == count_arguments) call fail(exit_input, '--csv needs a file name')
                k = k + 1
                csv = get_argument(k)
            case ('--force')
                overwrite = .true.
            case default
                if (argument(1:1) == '-') call fail(exit_input, 'unknown option '// &
                                                    argument//' (see --help)')
                if (len(input) > 0) call fail(exit_input, 'only one input file, got '// &
                                              input//' and '//argument)
                input = argument
            end select
        end do
        if (len(input) == 0) then
            call usage(error_unit)
            call fail(exit_input, 'no input file given')
        end if
    end subroutine parse_arguments

    subroutine usage(unit)
        integer, intent(in) :: unit
        write (unit, '(a)') 'usage: '//program_name//' [--csv OUT.csv] [--force] FILE.nml'
        write (unit, '(a)') ''
        write (unit, '(a)') 'Solves the brachistochrone from A = (1, 0) to each endpoint '// &
            '(rho, psi) of the'
        write (unit, '(a)') 'namelist group &endpoints in FILE.nml (attractive '// &
            'inverse-square force, Tee 1998).'
        write (unit, '(a)') '  --csv OUT.csv  also write rho,psi,arch,R,s,t,steps,status '// &
            'to OUT.csv'
        write (unit, '(a)') '  --force        replace OUT.csv if it exists'
        write (unit, '(a)') 'Exit codes: 0 all solved, 1 usage or input error, '// &
            '2 some endpoints unsolved, 3 I/O error.'
    end subroutine usage

    function get_argument(k) result(argument)
        integer, intent(in) :: k
        character(len=:), allocatable :: argument
        integer :: length
        call get_command_argument(k, length=length)
        allocate (character(len=length) :: argument)
        call get_command_argument(k, argument)
    end function get_argument

    logical function exists(path)
        character(len=*), intent(in) :: path
        inquire (file=path, exist=exists)
    end function exists

    subroutine fail(code, text)
        integer, intent(in) :: code
        character(len=*), intent(in) :: text
        write (error_unit, '(a)') program_name//': '//text
        stop code, quiet=.true.
    end subroutine fail

    function timestamp() result(text)
        character(len=:), allocatable :: text
        character(len=8) :: date
        character(len=10) :: time
        character(len=5) :: zone
        call date_and_time(date, time, zone)
        text = date(1:4)//'-'//date(5:6)//'-'//date(7:8)//'T'//time(1:2)//':'// &
               time(3:4)//':'//time(5:6)//zone
    end function timestamp

    pure function integer_text(value) result(text)
        integer, intent(in) :: value
        character(len=:), allocatable :: text
        character(len=24) :: buffer
        write (buffer, '(i0)') value
        text = trim(buffer)
    end function integer_text

end program main
