!> What every batch driver does between reading a table and writing results.
!!
!! Kept out of the library's physics (which never reads, prints or stops) and out of the
!! drivers (which only parse, decide and exit), so the serial/OpenMP program and the MPI
!! program solve rows and write files with the same code and give the same bytes.
module brachistochrone_batch_run
    use, intrinsic :: iso_fortran_env, only: error_unit, int64
    use brachistochrone_kinds, only: qp
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_field_interface, only: brachistochrone_field
    use brachistochrone_status, only: status_ok, status_no_convergence
    use brachistochrone_endpoint_input, only: endpoint_table, message, read_endpoint_file, &
            max_curve_points
    use brachistochrone_result_output, only: output_request, write_outputs, write_table_header, &
                             write_table_row, result_stream, start_stream, format_stream_row, &
                             write_stream_block, finish_stream
    use brachistochrone_curve_output, only: write_curves
    use brachistochrone_safe_file, only: safe_file, open_output, finish_output, finish_outputs, &
            commit_outputs, discard_outputs, same_file, same_name, standard_output, safe_ok, &
            safe_refused
    use brachistochrone_version, only: program_name
    use brachistochrone_command_line, only: run_options, exit_ok, exit_input, exit_unsolved, &
                                            exit_io
    use brachistochrone_run_support, only: progress_type, timestamp
    use brachistochrone_strings, only: integer_text, escape_text
    implicit none
    private

    public :: prepare_run, print_report, solve_rows, deliver_results, check_slice, &
              check_targets, abandon_outputs, start_results

    !> The outputs of this run (CSV, namelist, table, curves, and the table on standard
    !! output), opened by `prepare_run` before any endpoint is solved, so that a missing
    !! or read-only directory or an output in the way is found before the work.
    type(safe_file), save :: outputs(5)
    integer, parameter :: csv_file = 1, nml_file = 2, table_file = 3, curves_file = 4, &
                          table_on_stdout = 5

contains

    !> Everything before solving: read and check the input file, the slice and the
    !! output targets, and create the outputs' temporary files (`check_targets`; only
    !! where `writes_files`, default true: rank 0 of the MPI driver). When `finished` is
    !! set the driver prints `report` (to stdout when code = exit_ok, as for --check; to
    !! stderr otherwise) and exits with `code` (exit_input, or exit_io when an output
    !! cannot be created).
    subroutine prepare_run(options, table, first, last, report, code, finished, writes_files)
        type(run_options), intent(in) :: options       !! the command line
        type(endpoint_table), intent(out) :: table     !! the input
        integer, intent(out) :: first, last           !! the rows to solve
        type(message), allocatable, intent(out) :: report(:) !! lines for the user
        integer, intent(out) :: code                   !! exit code when finished
        logical, intent(out) :: finished               !! the driver should exit now
        logical, intent(in), optional :: writes_files  !! open the outputs (default true)
        character(len=:), allocatable :: text
        logical :: ok
        integer :: i
        code = exit_ok
        finished = .false.
        allocate (report(0))
        call read_endpoint_file(options%input_path, table, checksum=.not. options%check_only)
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
        call check_slice(table, options%slice, options%slices, first, last, ok, text)
        if (ok .and. len(options%request%curves_path) > 0 .and. table%curve_points == 0) then
            ok = .false.
            text = '--curves '//escape_text(options%request%curves_path)//' needs the '// &
                   'number of points per curve: set curve_points = N (2 <= N <= '// &
                   integer_text(max_curve_points)//') in the group &endpoints of '// &
                   escape_text(options%input_path)
        end if
        if (ok .and. .not. options%check_only) then
            if (.not. present(writes_files)) then
                call check_targets(options, code, text)
            else if (writes_files) then
                call check_targets(options, code, text)
            end if
            ok = code == exit_ok
        end if
        if (.not. ok) then
            report = [message(program_name//': '//text)]
            if (code == exit_ok) code = exit_input
            finished = .true.
        else if (options%check_only) then
            report = [message(escape_text(options%input_path)//': '//integer_text(table%n)// &
                              ' endpoints, valid')]
            finished = .true.
        end if
    end subroutine prepare_run

    !> Print `prepare_run`'s report: stdout (checked: a failure is exit_io) for a verdict,
    !! stderr for problems.
    subroutine print_report(report, code)
        type(message), intent(in) :: report(:) !! the lines
        integer, intent(inout) :: code         !! exit_ok: stdout; otherwise stderr;
                                               !! set to exit_io when stdout fails
        type(safe_file) :: stdout
        character(len=:), allocatable :: problem
        integer :: i, status
        if (code /= exit_ok) then
            do i = 1, size(report)
                write (error_unit, '(a)') report(i)%text
            end do
            return
        end if
        call open_output(stdout, standard_output, .false., status, problem)
        do i = 1, size(report)
            call stdout%put(report(i)%text)
        end do
        call finish_output(stdout, status, problem)
        if (status /= safe_ok) then
            write (error_unit, '(a)') program_name//': '//problem
            code = exit_io
        end if
    end subroutine print_report

    !> Everything after solving rows first..last: the result files, the curves and the
    !! table on stdout (as requested, into the outputs opened by `prepare_run`), then all
    !! files committed together, with problems explained on stderr. Returns the exit
    !! code: exit_ok; exit_unsolved when an endpoint has no solution or a solved one has
    !! no curve; exit_input when a target appeared during the run or memory ran out;
    !! exit_io when an output could not be written (then no file of the run is left).
    !! With `stream` (`start_results`, then `solve_rows` with it), the CSV and namelist
    !! were written during the solving: only the namelist's end remains of them.
    subroutine deliver_results(options, field, table, first, last, solutions, code, stream)
        type(run_options), intent(in) :: options       !! the command line
        class(brachistochrone_field), intent(in) :: field !! the field solved
        type(endpoint_table), intent(in) :: table      !! the input
        integer, intent(in) :: first, last             !! the rows solved
        type(endpoint_solution), intent(in) :: solutions(first:) !! their solutions
        integer, intent(out) :: code                   !! the exit code
        type(result_stream), intent(inout), optional :: stream !! the streamed outputs
        character(len=:), allocatable :: problem, date
        type(safe_file) :: streamed(2)                 ! not open: written already
        integer :: status, missing, unsolved, i
        logical :: ok

        if (present(stream)) then
            date = stream%date
            call finish_stream(stream, outputs(nml_file))
            call write_outputs(streamed(1), streamed(2), outputs(table_file), field, table, &
                               first, last, solutions, date)
        else
            date = timestamp()
            call write_outputs(outputs(csv_file), outputs(nml_file), outputs(table_file), &
                               field, table, first, last, solutions, date)
        end if
        call write_curves(outputs(curves_file), field, table, first, last, solutions, date, &
                          .not. options%quiet, missing, ok, problem)
        if (.not. ok) then
            call give_up(exit_input, problem)
            return
        end if
        if (outputs(table_on_stdout)%is_open()) then
            call write_table_header(outputs(table_on_stdout), field)
            do i = first, last
                call write_table_row(outputs(table_on_stdout), field, i, solutions(i))
            end do
        end if
        call finish_outputs(outputs, status, problem)
        if (status /= safe_ok) then
            call give_up(exit_io, problem)
            return
        end if
        call commit_outputs(outputs, status, problem)
        if (status /= safe_ok) then
            call give_up(merge(exit_input, exit_io, status == safe_refused), problem)
            return
        end if
        code = exit_ok
        unsolved = count(solutions(first:last)%status /= status_ok)
        if (missing > unsolved) then
            write (error_unit, '(a)') program_name//': '//integer_text(missing - unsolved)// &
                ' solved endpoints have no curve; see the comments in '// &
                escape_text(options%request%curves_path)
            code = exit_unsolved
        end if
        if (unsolved > 0) then
            write (error_unit, '(a)') program_name//': '//integer_text(unsolved)//' of '// &
                integer_text(last - first + 1)//' endpoints have no solution; see their status'
            code = exit_unsolved
        end if
        if (code == exit_unsolved .and. options%unsolved_ok) code = exit_ok

    contains

        subroutine give_up(exit_code, text)
            integer, intent(in) :: exit_code
            character(len=*), intent(in) :: text
            if (any(outputs(:table_on_stdout - 1)%fd >= 0)) then
                write (error_unit, '(a)') program_name//': '//text//'; no output file of '// &
                    'this run was kept'
            else
                write (error_unit, '(a)') program_name//': '//text
            end if
            call abandon_outputs()
            code = exit_code
        end subroutine give_up

    end subroutine deliver_results


    !> Remove the temporary files of this run's outputs (the driver gives up).
    subroutine abandon_outputs()
        call discard_outputs(outputs)
    end subroutine abandon_outputs

    !> Start writing the CSV and namelist outputs (provenance, headers) so that
    !! `solve_rows` can write them while it solves; pass `stream` to both and to
    !! `deliver_results`. code: exit_ok, or exit_io (the namelist's scratch file cannot
    !! be created: the message is printed and no output of the run is left).
    subroutine start_results(field, table, first, last, stream, code)
        class(brachistochrone_field), intent(in) :: field !! the field to solve
        type(endpoint_table), intent(in) :: table         !! the input
        integer, intent(in) :: first, last                !! the rows to solve
        type(result_stream), intent(out) :: stream        !! the streamed outputs
        integer, intent(out) :: code                      !! exit_ok or exit_io
        character(len=:), allocatable :: problem
        integer :: status
        code = exit_ok
        call start_stream(stream, outputs(csv_file), outputs(nml_file), field, table, first, &
                          last, timestamp(), status, problem)
        if (status == safe_ok) return
        write (error_unit, '(a)') program_name//': '//problem//'; no output file of this '// &
            'run was kept'
        call abandon_outputs()
        code = exit_io
    end subroutine start_results

    !> Solve rows first..last of the table in `field`, in parallel over OpenMP threads
    !! (dynamic schedule; each row is independent and `pure`, so the results do not
    !! depend on the number of threads), with a progress report on stderr when `report`
    !! is set. Rows with estimates r0, r1 use the field's secant method. With `stream`
    !! (`start_results`), the rows are solved in blocks, formatted by the threads as they
    !! are solved, and each block is written (in row order) by one thread while the
    !! others solve the next.
    subroutine solve_rows(field, table, first, last, solutions, report, stream)
        class(brachistochrone_field), intent(in) :: field      !! the force field
        type(endpoint_table), intent(in) :: table              !! the input
        integer, intent(in) :: first, last                     !! rows to solve
        type(endpoint_solution), intent(out) :: solutions(first:) !! their solutions
        logical, intent(in) :: report                          !! progress on stderr
        type(result_stream), intent(inout), optional :: stream !! outputs to write meanwhile
        type(progress_type) :: progress
        integer :: i
        call progress%start(last - first + 1, report)
        if (present(stream)) then
            if (stream%csv .or. stream%nml) then
                call solve_in_blocks(field, table, first, last, solutions, stream, progress)
                call progress%finish()
                return
            end if
        end if
        !$omp parallel do schedule(dynamic, 16) default(shared) private(i)
        do i = first, last
            call solve_row(field, table, i, solutions(i), progress)
        end do
        !$omp end parallel do
        call progress%finish()
    end subroutine solve_rows

    !> `solve_rows` with the CSV and namelist written meanwhile: blocks of
    !! `stream%block_rows` rows, each row formatted by the thread that solved it into the
    !! block's slot; after a block, one thread writes it while the others go on with the
    !! next block (the slot of block b is used again only after the barrier that ends
    !! block b + 1, which the writer reaches when it is done).
    subroutine solve_in_blocks(field, table, first, last, solutions, stream, progress)
        class(brachistochrone_field), intent(in) :: field
        type(endpoint_table), intent(in) :: table
        integer, intent(in) :: first, last
        type(endpoint_solution), intent(inout) :: solutions(first:)
        type(result_stream), intent(inout) :: stream
        type(progress_type), intent(inout) :: progress
        integer :: i, block, block_first, block_last, slot
        !$omp parallel default(shared) private(i, block, block_first, block_last, slot)
        do block = 1, (last - first + stream%block_rows)/stream%block_rows
            block_first = first + (block - 1)*stream%block_rows
            block_last = min(last, block_first + stream%block_rows - 1)
            slot = 2 - mod(block, 2)
            !$omp do schedule(dynamic, 4)
            do i = block_first, block_last
                call solve_row(field, table, i, solutions(i), progress)
                call format_stream_row(stream, slot, i - block_first + 1, solutions(i))
            end do
            !$omp end do
            !$omp single
            call write_stream_block(stream, outputs(csv_file), outputs(nml_file), slot, &
                                    block_last - block_first + 1)
            !$omp end single nowait
        end do
        !$omp end parallel
    end subroutine solve_in_blocks

    !> Solve one row of the table (with the field's secant method where it has estimates
    !! r0, r1) and count it in `progress`. Called by the OpenMP threads at once.
    subroutine solve_row(field, table, row, solution, progress)
        class(brachistochrone_field), intent(in) :: field
        type(endpoint_table), intent(in) :: table
        integer, intent(in) :: row
        type(endpoint_solution), intent(out) :: solution
        type(progress_type), intent(inout) :: progress
        if (table%has_estimates(row)) then
            solution = field%solve_from_estimates(table%rho(row), table%psi(row), &
                                                  table%r0(row), table%r1(row), &
                                                  table%secant_tolerance)
        else
            solution = field%solve(table%rho(row), table%psi(row))
        end if
        call progress%step()
    end subroutine solve_row

    !> Resolve the rows to solve: slice K of N nearly equal slices (`slice` > 0: rows
    !! (K-1) n/N + 1 to K n/N, any N <= n), or first..last (-1 means the table's first or
    !! last row), and check them.
    subroutine check_slice(table, slice, slices, first, last, ok, message)
        type(endpoint_table), intent(in) :: table    !! the input
        integer, intent(in) :: slice, slices         !! --slice K/N (0/0: none)
        integer, intent(inout) :: first, last        !! the rows
        logical, intent(out) :: ok                   !! they are rows of the table
        character(len=:), allocatable, intent(out) :: message !! why not
        message = ''
        if (slices > 0) then
            ok = slices <= table%n
            if (.not. ok) then
                message = '--slice '//integer_text(slice)//'/'//integer_text(slices)// &
                    ': '//integer_text(slices)//' slices of the '//integer_text(table%n)// &
                    ' rows of '//escape_text(table%path)//' would leave some empty; use at '// &
                    'most '//integer_text(table%n)//' slices'
                return
            end if
            first = int(int(slice - 1, int64)*table%n/slices) + 1
            last = int(int(slice, int64)*table%n/slices)
            return
        end if
        if (first == -1) first = 1
        if (last == -1) last = table%n
        ok = first >= 1 .and. last <= table%n .and. first <= last
        if (.not. ok) message = '--first '//integer_text(first)//' --last '// &
            integer_text(last)//' is not a slice of the '//integer_text(table%n)// &
            ' rows of '//escape_text(table%path)//' (need 1 <= first <= last <= n; '// &
            '--slice K/N splits any n)'
    end subroutine check_slice

    !> Before any work: refuse outputs that are the same file as another output or as the
    !! input, or that exist (unless --force; with --force a directory, device, FIFO or
    !! socket), then create every output's temporary file, so that a missing or
    !! read-only directory is found now. code: exit_ok; exit_input (a conflict; nothing
    !! was created); exit_io (an output cannot be created; nothing is left).
    subroutine check_targets(options, code, message)
        type(run_options), intent(in) :: options     !! the command line
        integer, intent(out) :: code                 !! exit_ok, exit_input or exit_io
        character(len=:), allocatable, intent(out) :: message !! what is wrong
        character(len=*), parameter :: names(4) = [character(len=8) :: '--csv', '--nml', &
                                                   '--table', '--curves']
        character(len=:), allocatable :: path
        integer :: k, j, status

        code = exit_ok
        status = safe_ok
        message = ''
        do k = 1, size(names)
            path = output_path(options%request, k)
            if (len(path) == 0 .or. path == standard_output) cycle
            if (same_name(path, options%input_path) .or. &
                same_file(path, options%input_path)) then
                code = exit_input
                message = trim(names(k))//' '//escape_text(path)//' is the input file '// &
                          escape_text(options%input_path)//'; choose another name'
                return
            end if
            do j = 1, k - 1
                if (.not. same_name(path, output_path(options%request, j))) cycle
                code = exit_input
                message = trim(names(j))//' '//escape_text(output_path(options%request, j))// &
                          ' and '//trim(names(k))//' '//escape_text(path)//' are the same '// &
                          'file; '// &
                          'give each output its own name'
                return
            end do
        end do
        do k = 1, size(names)
            if (len(output_path(options%request, k)) == 0) cycle
            call open_output(outputs(k), output_path(options%request, k), &
                             options%request%force, status, message)
            if (status /= safe_ok) exit
        end do
        if (status == safe_ok .and. options%show_table) &
            call open_output(outputs(table_on_stdout), standard_output, .false., status, &
                             message)
        if (status /= safe_ok) then
            call abandon_outputs()
            code = merge(exit_input, exit_io, status == safe_refused)
        end if
    end subroutine check_targets

    !> The path of output k: 1 CSV, 2 namelist, 3 table, 4 curves ('' when not asked for).
    pure function output_path(request, k) result(path)
        type(output_request), intent(in) :: request
        integer, intent(in) :: k
        character(len=:), allocatable :: path
        select case (k)
        case (csv_file);    path = request%csv_path
        case (nml_file);    path = request%nml_path
        case (table_file);  path = request%table_path
        case default;       path = request%curves_path
        end select
    end function output_path

end module brachistochrone_batch_run
