!> brachistochrone-bench: time the default solver on an endpoint table.
!!
!!     brachistochrone-bench FILE.nml [REPEATS [THREADS]]
!!
!! Solves every endpoint of FILE.nml REPEATS times (default 5) on THREADS OpenMP threads
!! (default 1) with the program's own loop (`solve_rows`), and prints the median wall
!! time per endpoint, so that scripts/bench.py can compare it with SciPy and mpmath
!! measured in the same run. Output: `key = value` lines.
program bench
    use, intrinsic :: iso_fortran_env, only: int64, error_unit, output_unit
    use brachistochrone, only: qp, brachistochrone_field, new_field, endpoint_solution, &
                               status_ok
    use brachistochrone_endpoint_input, only: endpoint_table, read_endpoint_file
    use brachistochrone_batch_run, only: solve_rows
    !$ use omp_lib, only: omp_set_num_threads
    implicit none
    type(endpoint_table) :: table
    class(brachistochrone_field), allocatable :: field
    type(endpoint_solution), allocatable :: solutions(:)
    integer :: repeats, k, i, length, ios, evaluations, threads
    integer(int64) :: start, finish, rate
    real(qp), allocatable :: seconds(:)
    character(len=:), allocatable :: path
    character(len=32) :: text

    if (command_argument_count() < 1) then
        write (error_unit, '(a)') 'usage: brachistochrone-bench FILE.nml [REPEATS]'
        stop 1, quiet=.true.
    end if
    call get_command_argument(1, length=length)
    allocate (character(len=length) :: path)
    call get_command_argument(1, path)
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
    call new_field(table%force, table%exponent, field, k)
    allocate (solutions(table%n), seconds(repeats))
    do k = 1, repeats
        call system_clock(start, rate)
        call solve_rows(field, table, 1, table%n, solutions, .false.)
        call system_clock(finish)
        seconds(k) = real(finish - start, qp)/real(rate, qp)
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

contains

    function median(values) result(middle)
        real(qp), intent(in) :: values(:)
        real(qp) :: middle, sorted(size(values)), swap
        integer :: a, b
        sorted = values
        do a = 2, size(sorted)
            do b = a, 2, -1
                if (sorted(b - 1) <= sorted(b)) exit
                swap = sorted(b)
                sorted(b) = sorted(b - 1)
                sorted(b - 1) = swap
            end do
        end do
        middle = sorted((size(sorted) + 1)/2)
    end function median

end program bench
