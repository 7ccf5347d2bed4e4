!> brachistochrone-mpi: one endpoint table distributed over MPI ranks.
!!
!!     mpirun -np 4 brachistochrone-mpi [options] FILE.nml   (options as brachistochrone)
!!
!! Every rank reads and checks the input (so every rank reaches the same verdict), then
!! solves a contiguous block of the rows (OpenMP threads inside each rank as usual).
!! Rank 0 gathers the solutions, as raw bytes so that every binary128 value arrives
!! bit for bit, and writes the same files, with the same code, as the serial program:
!! the results are identical to a serial run. Exit codes as brachistochrone.
program main
    use, intrinsic :: iso_fortran_env, only: error_unit, output_unit, int8
    use mpi_f08, only: mpi_init, mpi_finalize, mpi_comm_world, mpi_comm_rank, &
                       mpi_comm_size, mpi_gatherv, mpi_bcast, mpi_byte, mpi_integer, &
                       mpi_abort, mpi_logical, mpi_comm, mpi_comm_split_type, &
                       mpi_comm_type_shared, mpi_info_null, mpi_comm_free
    !$ use omp_lib, only: omp_set_num_threads, omp_get_num_procs, omp_get_max_threads
    use brachistochrone, only: brachistochrone_field, new_field, endpoint_solution, &
                               status_ok, status_message
    use brachistochrone_version, only: program_name, program_version
    use brachistochrone_endpoint_input, only: endpoint_table, message
    use brachistochrone_command_line, only: run_options, parse_command_line, write_usage, &
                                            max_threads, exit_ok, exit_input
    use brachistochrone_batch_run, only: prepare_run, print_report, solve_rows, deliver_results, &
                                         abandon_outputs
    implicit none

    type(run_options) :: options
    type(endpoint_table) :: table
    class(brachistochrone_field), allocatable :: field
    type(endpoint_solution), allocatable :: block(:), solutions(:)
    type(endpoint_solution) :: prototype
    type(message), allocatable :: report(:)
    character(len=:), allocatable :: problem
    integer(int8), allocatable :: sent(:), received(:)
    integer, allocatable :: counts(:), displacements(:)
    integer :: rank, ranks, status, i, first, last, my_first, my_last, rows, bytes, code
    logical :: finished

    call mpi_init()
    call mpi_comm_rank(mpi_comm_world, rank)
    call mpi_comm_size(mpi_comm_world, ranks)

    call parse_command_line(options, status, problem)
    if (options%help) then
        if (rank == 0) call write_usage(output_unit, program_name//'-mpi')
        call finish(exit_ok)
    else if (options%version) then
        if (rank == 0) write (output_unit, '(a)') program_name//'-mpi '//program_version
        call finish(exit_ok)
    else if (status /= exit_ok) then
        call fail(exit_input, problem)
    end if
    call set_threads(options%threads)

    ! only rank 0 writes files (and creates their temporary files before the work)
    call prepare_run(options, table, first, last, report, code, finished, &
                     writes_files=rank == 0)
    call mpi_bcast(code, 1, mpi_integer, 0, mpi_comm_world)
    call mpi_bcast(finished, 1, mpi_logical, 0, mpi_comm_world)
    if (finished) then
        if (rank == 0) call print_report(report, code)
        call finish(code)
    end if

    ! contiguous blocks: rank k solves rows my_first..my_last
    rows = last - first + 1
    my_first = first + (rank*rows)/ranks
    my_last = first + ((rank + 1)*rows)/ranks - 1
    call new_field(table%force, table%exponent, field, status)
    if (status /= status_ok) then
        if (rank == 0) call abandon_outputs()
        call fail(exit_input, table%path//': '//status_message(status))
    end if
    allocate (block(my_first:my_last))
    if (my_last >= my_first) call solve_rows(field, table, my_first, my_last, block, &
                                             .not. options%quiet .and. rank == 0)

    ! gather the solutions on rank 0 as bytes
    bytes = storage_size(prototype)/8
    sent = transfer(block, [0_int8], size(block)*bytes)
    allocate (counts(ranks), displacements(ranks))
    do i = 0, ranks - 1
        counts(i + 1) = bytes*(((i + 1)*rows)/ranks - (i*rows)/ranks)
        displacements(i + 1) = bytes*((i*rows)/ranks)
    end do
    allocate (received(merge(rows*bytes, 1, rank == 0)))
    call mpi_gatherv(sent, size(sent), mpi_byte, received, counts, displacements, &
                     mpi_byte, 0, mpi_comm_world)

    code = exit_ok
    if (rank == 0) then
        allocate (solutions(first:last))
        solutions = transfer(received, prototype, rows)
        ! files, curves (with rank 0's OpenMP threads) and table: as the serial program
        call deliver_results(options, field, table, first, last, solutions, code)
    end if
    call mpi_bcast(code, 1, mpi_integer, 0, mpi_comm_world)
    call finish(code)

contains

    !> Every rank reaches the same verdict; rank 0 explains it.
    subroutine fail(exit_code, text)
        integer, intent(in) :: exit_code
        character(len=*), intent(in) :: text
        if (rank == 0) write (error_unit, '(a)') program_name//': '//text
        call finish(exit_code)
    end subroutine fail

    !> Threads per rank: --threads N if given, else OMP_NUM_THREADS if set, else the
    !! node's cores shared among the ranks on the node (at least 1), so that ranks x
    !! threads never oversubscribe a node by default.
    subroutine set_threads(requested)
        integer, intent(in) :: requested !! --threads (0: not given)
        type(mpi_comm) :: node
        integer :: local_ranks, length, env_status
        if (requested > 0) then
            !$ call omp_set_num_threads(requested)
            return
        end if
        call get_environment_variable('OMP_NUM_THREADS', length=length, status=env_status)
        if (env_status == 0 .and. length > 0) then
            !$ if (omp_get_max_threads() > max_threads) call fail(exit_input, &
            !$     'OMP_NUM_THREADS asks for more than the most supported threads; set it lower')
            return
        end if
        call mpi_comm_split_type(mpi_comm_world, mpi_comm_type_shared, rank, &
                                 mpi_info_null, node)
        call mpi_comm_size(node, local_ranks)
        call mpi_comm_free(node)
        !$ call omp_set_num_threads(max(1, omp_get_num_procs()/max(1, local_ranks)))
    end subroutine set_threads

    subroutine finish(exit_code)
        integer, intent(in) :: exit_code
        call mpi_finalize()
        stop exit_code, quiet=.true.
    end subroutine finish

end program main
