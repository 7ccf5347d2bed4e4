!> brachistochrone: solve a table of endpoints read from a namelist file.
!!
!!     brachistochrone [options] FILE.nml      (see --help and the README)
!!     brachistochrone family ...              (complete arches, apsidal locus; family.f90)
!!     brachistochrone tunnel ...              (tunnels through a planet; tunnel.f90)
!!     brachistochrone merge OUT.csv SLICE...  (join job-array slices; merge.f90)
!!
!! The first argument `family` or `tunnel` selects a subcommand (an input file of that
!! name is `./family`).
!! Exit codes: 0 every endpoint solved; 1 usage or input error (nothing written);
!! 2 some endpoints have no solution (files written, their status says why);
!! 3 I/O error (no output file written); 128 + N killed by signal N (no output file
!! written; see brachistochrone_safe_file).
program main
    use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
    !$ use omp_lib, only: omp_set_num_threads, omp_get_max_threads
    use brachistochrone, only: brachistochrone_field, new_field, endpoint_solution, &
                               status_ok, status_message, hardware_arithmetic_ok
    use brachistochrone_version, only: program_name, program_version
    use brachistochrone_endpoint_input, only: endpoint_table, message
    use brachistochrone_command_line, only: run_options, parse_command_line, write_usage, &
                                            max_threads, exit_ok, exit_input
    use brachistochrone_batch_run, only: prepare_run, print_report, solve_rows, deliver_results, &
                                         abandon_outputs, start_results
    use brachistochrone_result_output, only: result_stream
    use brachistochrone_strings, only: integer_text
    use brachistochrone_app_family, only: run_family
    use brachistochrone_app_tunnel, only: run_tunnel
    use brachistochrone_app_merge, only: run_merge
    use brachistochrone_app_support, only: stop_with
    implicit none

    type(run_options) :: options
    type(endpoint_table) :: table
    class(brachistochrone_field), allocatable :: field
    type(endpoint_solution), allocatable :: solutions(:)
    type(message), allocatable :: report(:)
    type(result_stream) :: stream
    character(len=:), allocatable :: problem
    integer :: status, first, last, code, stat
    logical :: finished

    call run_subcommand()
    call parse_command_line(options, status, problem)
    if (options%help) then
        call write_usage(output_unit, program_name)
        write (output_unit, '(a)') 'Subcommands: '//program_name//' merge --help, '// &
            program_name//' family --help, '// &
            program_name//' tunnel --help'
        stop exit_ok, quiet=.true.
    else if (options%version) then
        write (output_unit, '(a)') program_name//' '//program_version
        stop exit_ok, quiet=.true.
    else if (status /= exit_ok) then
        call fail(exit_input, problem)
    end if
    if (.not. hardware_arithmetic_ok()) call fail(exit_input, 'the x87 arithmetic is not '// &
        'at its defaults (64-bit precision, rounding to nearest): a library or the link '// &
        '(gfortran -mpc64, fldcw, fesetround) changed its control word, and the quad-'// &
        'precision results would be wrong; run without that setting')
    !$ if (options%threads > 0) call omp_set_num_threads(options%threads)
    !$ if (options%threads == 0 .and. omp_get_max_threads() > max_threads) &
    !$     call fail(exit_input, 'OMP_NUM_THREADS asks for more than '// &
    !$               integer_text(max_threads)//' threads (the most supported); set it '// &
    !$               'lower or give --threads N')

    call prepare_run(options, table, first, last, report, code, finished)
    if (finished) then
        call print_report(report, code)
        stop code, quiet=.true.
    end if

    call new_field(table%force, table%exponent, field, status)
    if (status /= status_ok) then
        call abandon_outputs()
        call fail(exit_input, table%path//': '//status_message(status))
    end if
    allocate (solutions(first:last), stat=stat)
    if (stat /= 0) then
        call abandon_outputs()
        call fail(exit_input, 'out of memory for the solutions of '// &
                  integer_text(last - first + 1)//' endpoints; solve fewer rows at a time '// &
                  'with --first/--last')
    end if
    ! the CSV and namelist are written while the rows are solved (issue 12)
    call start_results(field, table, first, last, stream, code)
    if (code /= exit_ok) stop code, quiet=.true.
    call solve_rows(field, table, first, last, solutions, .not. options%quiet, stream)

    call deliver_results(options, field, table, first, last, solutions, code, stream)
    stop code, quiet=.true.

contains

    !> `brachistochrone family|tunnel|merge ...` run the subcommand
    !! (which stops); any other first argument returns to the batch program.
    subroutine run_subcommand()
        character(len=8) :: first
        if (command_argument_count() < 1) return
        call get_command_argument(1, first)
        select case (first)
        case ('family');  call run_family(2)
        case ('tunnel');  call run_tunnel(2)
        case ('merge');   call run_merge(2)
        end select
    end subroutine run_subcommand

    subroutine fail(code, text)
        integer, intent(in) :: code
        character(len=*), intent(in) :: text
        call stop_with(program_name, code, text)
    end subroutine fail

end program main
