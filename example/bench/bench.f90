!> brachistochrone-bench (an fpm example, a developer tool): time the default solver.
!!
!!     fpm run --profile release --example brachistochrone-bench -- FILE.nml [REPEATS [THREADS]]
!!
!! Solves every endpoint of FILE.nml REPEATS times (default 5) on THREADS OpenMP threads
!! (default 1) with the program's own loop (`solve_rows`), and prints the median wall
!! time per endpoint, so that scripts/bench.py can compare it with SciPy and mpmath
!! measured in the same run. Also times, on the solved endpoints, the floor of the
!! solver (one full-precision evaluation of the inverse-square kernel with s, t and the
!! derivatives, level_final as the solver's last step makes it: what remains when every
!! earlier step is free) and the formatting of
!! the results (rho, psi, R, s, t by `format_quad` against the formatted `write` it
!! replaced, ns per value), and the CPU time to build the field (once per run, not in the
!! per-endpoint figures). Output: `key = value` lines.
program bench
    use, intrinsic :: iso_fortran_env, only: int64, error_unit, output_unit
    use brachistochrone, only: qp, brachistochrone_field, new_field, endpoint_solution, &
                               status_ok
    use brachistochrone_endpoint_input, only: endpoint_table, read_endpoint_file
    use brachistochrone_batch_run, only: solve_rows
    use brachistochrone_version, only: program_version
    use brachistochrone_inverse_square, only: inverse_square_model, new_inverse_square_model, &
                                              evaluate_arch, arch_values, level_final
    use brachistochrone_arches, only: arch_first, arch_second, arch_complete
    use brachistochrone_format, only: format_quad, format_quad_by_write
    !$ use omp_lib, only: omp_set_num_threads
    use brachistochrone_run_support, only: median
    implicit none
    type(endpoint_table) :: table
    class(brachistochrone_field), allocatable :: field
    type(endpoint_solution), allocatable :: solutions(:)
    integer :: repeats, k, i, length, ios, evaluations, threads
    integer(int64) :: start, finish, rate
    real(qp), allocatable :: seconds(:), cpu_seconds(:)
    real :: cpu_start, cpu_finish
    real(qp) :: build_start, build_finish
    character(len=:), allocatable :: path
    character(len=32) :: text

    if (command_argument_count() < 1) then
        write (error_unit, '(a)') 'usage: brachistochrone-bench FILE.nml [REPEATS [THREADS]]'
        stop 1, quiet=.true.
    end if
    call get_command_argument(1, length=length)
    allocate (character(len=length) :: path)
    call get_command_argument(1, path)
    if (path == '--version') then
        write (output_unit, '(a)') 'brachistochrone-bench '//program_version
        stop 0, quiet=.true.
    else if (path == '--help' .or. path == '-h') then
        write (output_unit, '(a)') 'usage: brachistochrone-bench FILE.nml [REPEATS [THREADS]]'
        write (output_unit, '(a)') 'Solves FILE.nml REPEATS times (default 5) on THREADS '// &
            'OpenMP threads (default 1);'
        write (output_unit, '(a)') 'prints the median and best wall time per endpoint as '// &
            'key = value lines.'
        stop 0, quiet=.true.
    end if
    repeats = 5
    if (command_argument_count() >= 2) then
        call get_command_argument(2, text)
        read (text, *, iostat=ios) repeats
        if (ios /= 0 .or. repeats < 1) repeats = 5
    end if
    threads = 1
    if (command_argument_count() >= 3) then
        call get_command_argument(3, text)
        read (text, *, iostat=ios) threads
        if (ios /= 0 .or. threads < 1) threads = 1
    end if
    !$ call omp_set_num_threads(threads)
    call read_endpoint_file(path, table)
    if (size(table%errors) > 0) then
        do i = 1, size(table%errors)
            write (error_unit, '(a)') table%errors(i)%text
        end do
        stop 1, quiet=.true.
    end if
    call cpu_time(build_start)
    call new_field(table%force, table%exponent, field, k)
    call cpu_time(build_finish)
    allocate (solutions(table%n), seconds(repeats), cpu_seconds(repeats))
    do k = 1, repeats
        call cpu_time(cpu_start)
        call system_clock(start, rate)
        call solve_rows(field, table, 1, table%n, solutions, .false.)
        call system_clock(finish)
        call cpu_time(cpu_finish)
        seconds(k) = real(finish - start, qp)/real(rate, qp)
        cpu_seconds(k) = real(cpu_finish - cpu_start, qp)
    end do
    evaluations = sum(solutions%steps)
    write (output_unit, '(a,i0)') 'endpoints = ', table%n
    write (output_unit, '(a,i0)') 'repeats = ', repeats
    write (output_unit, '(a,i0)') 'threads = ', threads
    write (output_unit, '(a,i0)') 'failed = ', count(solutions%status /= status_ok)
    write (output_unit, '(a,f0.3)') 'mean_upsilon_evaluations = ', &
        real(evaluations, qp)/real(table%n, qp)
    write (output_unit, '(a,f0.3)') 'median_us_per_endpoint = ', &
        1.0e6_qp*median(seconds)/real(table%n, qp)
    write (output_unit, '(a,f0.3)') 'best_us_per_endpoint = ', &
        1.0e6_qp*minval(seconds)/real(table%n, qp)
    ! process CPU time (all threads): less disturbed by other users of a shared machine
    write (output_unit, '(a,f0.3)') 'median_cpu_us_per_endpoint = ', &
        1.0e6_qp*median(cpu_seconds)/real(table%n, qp)
    ! the field (for inverse-square the model with its tables), built once per run
    write (output_unit, '(a,f0.1)') 'field_build_cpu_ms = ', 1.0e3_qp*(build_finish - build_start)
    call time_floor_and_format(solutions, repeats)

contains

    !> The floor (one full-precision evaluation per solved endpoint, at its solution) and
    !! the formatting of rho, psi, R, s, t: medians over `repeats` passes, in process CPU
    !! time (compare with median_cpu_us_per_endpoint of a one-thread run).
    subroutine time_floor_and_format(solutions, repeats)
        type(endpoint_solution), intent(in) :: solutions(:)
        integer, intent(in) :: repeats
        type(inverse_square_model) :: model
        type(arch_values) :: values
        real(qp) :: floor_seconds(repeats), fast(repeats), slow(repeats), sink
        real :: start, finish
        integer :: k, i, solved, formatted
        character(len=:), allocatable :: text
        real(qp), allocatable :: values_out(:)
        model = new_inverse_square_model()
        sink = 0.0_qp
        solved = 0
        do k = 1, repeats
            solved = 0
            call cpu_time(start)
            do i = 1, size(solutions)
                associate (b => solutions(i))
                if (b%status /= status_ok .or. .not. any(b%arch == &
                    [arch_first, arch_second, arch_complete])) cycle
                values = evaluate_arch(model, level_final, b%arch /= arch_first, b%rho, &
                                       b%apse_radius, b%apse_gap, .true., .true.)
                sink = sink + values%time
                solved = solved + 1
                end associate
            end do
            call cpu_time(finish)
            floor_seconds(k) = real(finish - start, qp)
        end do
        values_out = [solutions%rho, solutions%psi, solutions%apse_radius, &
                      solutions%arclength, solutions%time]
        formatted = size(values_out)
        do k = 1, repeats
            call cpu_time(start)
            do i = 1, formatted
                text = format_quad(values_out(i))
                sink = sink + real(len(text), qp)
            end do
            call cpu_time(finish)
            fast(k) = real(finish - start, qp)
            call cpu_time(start)
            do i = 1, formatted
                text = format_quad_by_write(values_out(i))
                sink = sink + real(len(text), qp)
            end do
            call cpu_time(finish)
            slow(k) = real(finish - start, qp)
        end do
        write (output_unit, '(a,f0.3)') 'floor_us_per_endpoint = ', &
            1.0e6_qp*median(floor_seconds)/real(max(solved, 1), qp)
        write (output_unit, '(a,f0.1)') 'format_ns_per_value = ', &
            1.0e9_qp*median(fast)/real(max(formatted, 1), qp)
        write (output_unit, '(a,f0.1)') 'format_write_ns_per_value = ', &
            1.0e9_qp*median(slow)/real(max(formatted, 1), qp)
        if (sink < 0.0_qp) write (output_unit, '(a)') 'unreachable'
    end subroutine time_floor_and_format

end program bench
