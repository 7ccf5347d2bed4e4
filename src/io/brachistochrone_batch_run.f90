!> What every batch driver does between reading a table and writing results.
!!
!! Kept out of the library's physics (which never reads, prints or stops) and out of the
!! drivers (which only parse, decide and exit), so the serial/OpenMP program and the MPI
!! program solve rows and write files with the same code and give the same bytes.
module brachistochrone_batch_run
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use brachistochrone_kinds, only: qp
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_field_interface, only: brachistochrone_field
    use brachistochrone_status, only: status_ok, status_no_convergence
    use brachistochrone_endpoint_input, only: endpoint_table, message, read_endpoint_file, &
            max_curve_points
    use brachistochrone_result_output, only: output_request, write_outputs, write_table_header, &
                             write_table_row
    use brachistochrone_curve_output, only: write_curves
    use brachistochrone_version, only: program_name
    use brachistochrone_command_line, only: run_options, exit_ok, exit_input, exit_unsolved, exit_io
    use brachistochrone_run_support, only: progress_type, timestamp
    use brachistochrone_strings, only: integer_text, escape_text
    implicit none
    private

    public :: prepare_run, print_report, solve_rows, deliver_results, check_slice, &
              check_targets

contains

    !> Everything before solving: read and check the input file, the slice and the
    !! output targets. When `finished` is set the driver prints `report` (to stdout when
    !! code = exit_ok, as for --check; to stderr otherwise) and exits with `code`.
    subroutine prepare_run(options, table, first, last, report, code, finished)
        type(run_options), intent(in) :: options       !! the command line
        type(endpoint_table), intent(out) :: table     !! the input
        integer, intent(out) :: first, last           !! the rows to solve
        type(message), allocatable, intent(out) :: report(:) !! lines for the user
        integer, intent(out) :: code                   !! exit code when finished
        logical, intent(out) :: finished               !! the driver should exit now
        character(len=:), allocatable :: text
        logical :: ok
        integer :: i
        code = exit_ok
        finished = .false.
        allocate (report(0))
        call read_endpoint_file(options%input_path, table)
        if (size(table%errors) > 0) then
            report = [(message(program_name//': '//table%errors(i)%text), &
                       i = 1, size(table%errors))]
            report = [report, message(program_name//': '//integer_text(table%problems) &
                      //' problem(s) in '//escape_text(options%input_path)// &
                      '; nothing was computed or written')]
            code = exit_input
            finished = .true.
            return
        end if
        first = options%first
        last = options%last
        call check_slice(table, first, last, ok, text)
        if (ok .and. len(options%request%curves_path) > 0 .and. table%curve_points == 0) then
            ok = .false.
            text = '--curves '//options%request%curves_path//' needs the number of points '// &
                   'per curve: set curve_points = N (2 <= N <= '// &
                   integer_text(max_curve_points)//') in the group &endpoints of '// &
                   escape_text(options%input_path)
        end if
        if (ok .and. .not. options%check_only) call check_targets(options%request, ok, text)
        if (.not. ok) then
            report = [message(program_name//': '//text)]
            code = exit_input
            finished = .true.
        else if (options%check_only) then
            report = [message(escape_text(options%input_path)//': '//integer_text(table%n)// &
                              ' endpoints, valid')]
            finished = .true.
        end if
    end subroutine prepare_run

    !> Print `prepare_run`'s report: stdout for a verdict, stderr for problems.
    subroutine print_report(report, code)
        type(message), intent(in) :: report(:) !! the lines
        integer, intent(in) :: code            !! exit_ok: stdout; otherwise stderr
        integer :: i
        do i = 1, size(report)
            if (code == exit_ok) then
                write (output_unit, '(a)') report(i)%text
            else
                write (error_unit, '(a)') report(i)%text
            end if
        end do
    end subroutine print_report

    !> Everything after solving rows first..last: the result files, the curves and the
    !! table on stdout (as requested), with problems explained on stderr. Returns the
    !! exit code: exit_ok; exit_unsolved when an endpoint has no solution or a solved one
    !! has no curve; exit_input or exit_io when a file could not be written.
    subroutine deliver_results(options, field, table, first, last, solutions, code)
        type(run_options), intent(in) :: options       !! the command line
        class(brachistochrone_field), intent(in) :: field !! the field solved
        type(endpoint_table), intent(in) :: table      !! the input
        integer, intent(in) :: first, last             !! the rows solved
        type(endpoint_solution), intent(in) :: solutions(first:) !! their solutions
        integer, intent(out) :: code                   !! the exit code
        character(len=:), allocatable :: problem, date
        integer :: status, missing, unsolved, i

        date = timestamp()
        missing = 0
        call write_outputs(options%request, field, table, first, last, solutions, date, &
                           status, problem)
        if (status == 0) call write_curves(options%request%curves_path, &
                                           options%request%force, field, table, first, &
                                           last, solutions, date, .not. options%quiet, &
                                           status, problem, missing)
        if (status /= 0) then
            write (error_unit, '(a)') program_name//': '//problem
            code = merge(exit_input, exit_io, status == 1)
            return
        end if
        if (options%show_table) then
            call write_table_header(output_unit, field)
            do i = first, last
                call write_table_row(output_unit, field, i, solutions(i))
            end do
        end if
        code = exit_ok
        unsolved = count(solutions(first:last)%status /= status_ok)
        if (missing > unsolved) then
            write (error_unit, '(a)') program_name//': '//integer_text(missing - unsolved)// &
                ' solved endpoints have no curve; see the comments in '// &
                options%request%curves_path
            code = exit_unsolved
        end if
        if (unsolved > 0) then
            write (error_unit, '(a)') program_name//': '//integer_text(unsolved)//' of '// &
                integer_text(last - first + 1)//' endpoints have no solution; see their status'
            code = exit_unsolved
        end if
    end subroutine deliver_results

    !> Solve rows first..last of the table in `field`, in parallel over OpenMP threads
    !! (dynamic schedule; each row is independent and `pure`, so the results do not
    !! depend on the number of threads), with a progress report on stderr when `report`
    !! is set. Rows with estimates r0, r1 use the field's secant method.
    subroutine solve_rows(field, table, first, last, solutions, report)
        class(brachistochrone_field), intent(in) :: field      !! the force field
        type(endpoint_table), intent(in) :: table              !! the input
        integer, intent(in) :: first, last                     !! rows to solve
        type(endpoint_solution), intent(out) :: solutions(first:) !! their solutions
        logical, intent(in) :: report                          !! progress on stderr
        type(progress_type) :: progress
        integer :: i
        call progress%start(last - first + 1, report)
        !$omp parallel do schedule(dynamic, 16) default(shared) private(i)
        do i = first, last
            if (table%has_estimates(i)) then
                solutions(i) = field%solve_from_estimates(table%rho(i), table%psi(i), &
                                                          table%r0(i), table%r1(i), &
                                                          table%secant_tolerance)
            else
                solutions(i) = field%solve(table%rho(i), table%psi(i))
            end if
            call progress%step()
        end do
        !$omp end parallel do
        call progress%finish()
    end subroutine solve_rows

    !> Resolve the slice (-1 means the table's first or last row) and check it.
    subroutine check_slice(table, first, last, ok, message)
        type(endpoint_table), intent(in) :: table    !! the input
        integer, intent(inout) :: first, last        !! the slice
        logical, intent(out) :: ok                   !! it is a slice of the table
        character(len=:), allocatable, intent(out) :: message !! why not
        if (first == -1) first = 1
        if (last == -1) last = table%n
        ok = first >= 1 .and. last <= table%n .and. first <= last
        message = ''
        if (.not. ok) message = '--first '//integer_text(first)//' --last '// &
            integer_text(last)//' is not a slice of the '//integer_text(table%n)// &
            ' rows of '//table%path//' (need 1 <= first <= last <= n)'
    end subroutine check_slice

    !> Before any work: refuse output files that exist unless `force` is set.
    subroutine check_targets(request, ok, message)
        type(output_request), intent(in) :: request  !! files to write
        logical, intent(out) :: ok                   !! none is in the way
        character(len=:), allocatable, intent(out) :: message !! which one is
        ok = .true.
        message = ''
        if (request%force) return
        call one(request%csv_path)
        call one(request%nml_path)
        call one(request%table_path)
        call one(request%curves_path)
    contains
        subroutine one(path)
            character(len=*), intent(in) :: path
            logical :: exists
            if (.not. ok .or. len(path) == 0) return
            inquire (file=path, exist=exists)
            if (exists) then
                ok = .false.
                message = path//' exists; use --force to replace it, or choose another name'
            end if
        end subroutine one
    end subroutine check_targets

end module brachistochrone_batch_run
