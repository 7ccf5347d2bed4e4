!> brachistochrone: solve a table of endpoints read from a namelist file.
!!
!!     brachistochrone [options] FILE.nml      (see --help and the README)
!!
!! Exit codes: 0 every endpoint solved; 1 usage or input error (nothing written);
!! 2 some endpoints have no solution (files written, their status says why);
!! 3 I/O error.
program main
    use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
    !$ use omp_lib, only: omp_set_num_threads
    use brachistochrone, only: inverse_square_model, new_inverse_square_model, &
                               endpoint_solution, status_ok
    use brachistochrone_version, only: program_name, program_version
    use endpoint_input, only: endpoint_table, read_endpoint_file
    use result_output, only: write_outputs, write_table_header, write_table_row
    use run_support, only: timestamp, integer_text
    use command_line, only: run_options, parse_command_line, write_usage, exit_ok, &
                            exit_input, exit_unsolved, exit_io
    use batch_run, only: solve_rows, check_slice, check_targets
    implicit none

    type(run_options) :: options
    type(endpoint_table) :: table
    type(inverse_square_model) :: model
    type(endpoint_solution), allocatable :: solutions(:)
    character(len=:), allocatable :: message
    integer :: i, status, unsolved, first, last
    logical :: ok

    call parse_command_line(options, status, message)
    if (options%help) then
        call write_usage(output_unit, program_name)
        stop exit_ok, quiet=.true.
    else if (options%version) then
        write (output_unit, '(a)') program_name//' '//program_version
        stop exit_ok, quiet=.true.
    else if (status /= exit_ok) then
        call fail(exit_input, message)
    end if
    !$ if (options%threads > 0) call omp_set_num_threads(options%threads)

    call read_endpoint_file(options%input_path, table)
    if (size(table%errors) > 0) then
        do i = 1, size(table%errors)
            write (error_unit, '(a)') program_name//': '//table%errors(i)%text
        end do
        call fail(exit_input, integer_text(size(table%errors))//' problem(s) in '// &
                  options%input_path//'; nothing was computed or written')
    end if
    first = options%first
    last = options%last
    call check_slice(table, first, last, ok, message)
    if (.not. ok) call fail(exit_input, message)
    if (options%check_only) then
        write (output_unit, '(a)') options%input_path//': '//integer_text(table%n)// &
            ' endpoints, valid'
        stop exit_ok, quiet=.true.
    end if
    call check_targets(options%request, ok, message)
    if (.not. ok) call fail(exit_input, message)

    model = new_inverse_square_model()
    allocate (solutions(first:last))
    call solve_rows(model, table, first, last, solutions, .not. options%quiet)

    call write_outputs(options%request, table, first, last, solutions, timestamp(), &
                       status, message)
    if (status == 1) call fail(exit_input, message)
    if (status /= 0) call fail(exit_io, message)
    if (options%show_table) then
        call write_table_header(output_unit)
        do i = first, last
            call write_table_row(output_unit, i, solutions(i))
        end do
    end if

    unsolved = count(solutions%status /= status_ok)
    if (unsolved > 0) then
        write (error_unit, '(a)') program_name//': '//integer_text(unsolved)//' of '// &
            integer_text(last - first + 1)//' endpoints have no solution; see their status'
        stop exit_unsolved, quiet=.true.
    end if
    stop exit_ok, quiet=.true.

contains

    subroutine fail(code, text)
        integer, intent(in) :: code
        character(len=*), intent(in) :: text
        write (error_unit, '(a)') program_name//': '//text
        stop code, quiet=.true.
    end subroutine fail

end program main
