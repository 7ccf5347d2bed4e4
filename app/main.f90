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
    use endpoint_input, only: endpoint_table, message
    use result_output, only: write_outputs, write_table_header, write_table_row
    use curve_output, only: write_curves
    use run_support, only: timestamp
    use strings, only: integer_text
    use command_line, only: run_options, parse_command_line, write_usage, exit_ok, &
                            exit_input, exit_unsolved, exit_io
    use batch_run, only: prepare_run, print_report, solve_rows
    implicit none

    type(run_options) :: options
    type(endpoint_table) :: table
    type(inverse_square_model) :: model
    type(endpoint_solution), allocatable :: solutions(:)
    type(message), allocatable :: report(:)
    character(len=:), allocatable :: problem, date
    integer :: i, status, unsolved, first, last, code, missing
    logical :: finished

    call parse_command_line(options, status, problem)
    if (options%help) then
        call write_usage(output_unit, program_name)
        stop exit_ok, quiet=.true.
    else if (options%version) then
        write (output_unit, '(a)') program_name//' '//program_version
        stop exit_ok, quiet=.true.
    else if (status /= exit_ok) then
        call fail(exit_input, problem)
    end if
    !$ if (options%threads > 0) call omp_set_num_threads(options%threads)

    call prepare_run(options, table, first, last, report, code, finished)
    if (finished) then
        call print_report(report, code)
        stop code, quiet=.true.
    end if

    model = new_inverse_square_model()
    allocate (solutions(first:last))
    call solve_rows(model, table, first, last, solutions, .not. options%quiet)

    date = timestamp()
    call write_outputs(options%request, table, first, last, solutions, date, status, problem)
    if (status == 1) call fail(exit_input, problem)
    if (status /= 0) call fail(exit_io, problem)
    call write_curves(options%request%curves_path, options%request%force, model, table, &
                      first, last, solutions, date, .not. options%quiet, status, problem, &
                      missing)
    if (status == 1) call fail(exit_input, problem)
    if (status /= 0) call fail(exit_io, problem)
    if (options%show_table) then
        call write_table_header(output_unit)
        do i = first, last
            call write_table_row(output_unit, i, solutions(i))
        end do
    end if

    unsolved = count(solutions%status /= status_ok)
    if (missing > unsolved) then
        write (error_unit, '(a)') program_name//': '//integer_text(missing - unsolved)// &
            ' solved endpoints have no curve; see the comments in '// &
            options%request%curves_path
    end if
    if (missing > unsolved .and. unsolved == 0) stop exit_unsolved, quiet=.true.
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
