!> The CSV and namelist written while the rows are solved (`result_stream`, issue 12)
!! against the writer of whole tables (`write_outputs`): the same bytes, across blocks.
module test_result_stream
    use brachistochrone_kinds, only: qp, pi
    use brachistochrone_status, only: status_inaccessible, status_no_convergence
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_arches, only: arch_inaccessible, arch_first, arch_second
    use brachistochrone_endpoint_input, only: endpoint_table
    use brachistochrone_result_output, only: write_outputs, result_stream, start_stream, &
                                             format_stream_row, write_stream_block, &
                                             finish_stream
    use brachistochrone_harmonic_field, only: harmonic_field
    use brachistochrone_safe_file, only: safe_file, open_output, finish_output, &
                                         commit_outputs, safe_ok
    use testing, only: check, section
    implicit none
    private

    public :: run_result_stream_tests

    character(len=*), parameter :: date = '2026-11-30T00:00:00+0000'

contains

    subroutine run_result_stream_tests()
        type(endpoint_table) :: table
        type(endpoint_solution), allocatable :: solutions(:)
        type(harmonic_field) :: field
        integer, parameter :: n = 2*2048 + 77       ! three blocks, the last one short
        integer :: k
        call section('io: results written while solving = results written at the end')
        table%path = 'in.nml'
        table%n = n
        table%force = 'harmonic'
        table%checksum = repeat('5', 64)
        table%bytes = 1234
        allocate (table%rho(n), table%psi(n), table%r0(n), table%r1(n), &
                  table%has_estimates(n), solutions(n))
        table%has_estimates = .false.
        do k = 1, n
            table%rho(k) = 1.0_qp/real(k + 1, qp)
            table%psi(k) = pi*real(k, qp)/real(n + 1, qp)
            solutions(k) = sample(k, table%rho(k), table%psi(k))
        end do
        call compare(field, table, solutions, .true., .true., 'CSV and namelist')
        call compare(field, table, solutions, .false., .true., 'namelist alone')
        call compare(field, table, solutions(:1), .true., .true., 'one row')
        ! the scratch file's memory (64 MiB) is one block: the rest from the file
        call compare(field, table, solutions, .false., .true., 'scratch on disk', 200000)
    end subroutine run_result_stream_tests

    !> Solutions of every kind: inaccessible (no R, s), unconverged, values from 1e-2800
    !! to 1e+2800, negative, and many steps.
    function sample(k, rho, psi) result(solution)
        integer, intent(in) :: k
        real(qp), intent(in) :: rho, psi
        type(endpoint_solution) :: solution
        solution%rho = rho
        solution%psi = psi
        solution%steps = k*(k - 100)
        solution%has_time = .true.
        solution%time = -pi**(mod(k, 7) - 3)
        if (mod(k, 13) == 4) then
            solution%status = status_inaccessible
            solution%arch = arch_inaccessible
            return
        end if
        if (mod(k, 31) == 1) solution%status = status_no_convergence
        solution%arch = merge(arch_first, arch_second, mod(k, 2) == 0)
        solution%has_apse_radius = .true.
        solution%has_arclength = .true.
        solution%apse_radius = 0.1_qp**mod(k*37, 5600)
        solution%arclength = 10.0_qp**mod(k, 2800) + real(k, qp)
    end function sample

    !> Write the rows both ways into build/ and compare the files' bytes.
    subroutine compare(field, table, solutions, csv, nml, what, scratch_memory)
        type(harmonic_field), intent(in) :: field
        type(endpoint_table), intent(in) :: table
        type(endpoint_solution), intent(in) :: solutions(:)
        logical, intent(in) :: csv, nml
        character(len=*), intent(in) :: what
        integer, intent(in), optional :: scratch_memory
        type(safe_file) :: whole(3), streamed(3)
        type(result_stream) :: stream
        character(len=:), allocatable :: problem
        integer :: status, block, first, last, slot, row
        call open_both(whole, 'build/test_stream_whole', csv, nml, status)
        if (status == safe_ok) call write_outputs(whole(1), whole(2), whole(3), field, table, &
                                                  1, size(solutions), solutions, date)
        if (status == safe_ok) call close_both(whole, status)
        if (status == safe_ok) call open_both(streamed, 'build/test_stream_blocks', csv, nml, &
                                              status)
        if (status == safe_ok) call start_stream(stream, streamed(1), streamed(2), field, &
                                                 table, 1, size(solutions), date, status, &
                                                 problem, scratch_memory)
        if (status == safe_ok) then
            block = 0
            do first = 1, size(solutions), stream%block_rows
                block = block + 1
                last = min(size(solutions), first + stream%block_rows - 1)
                slot = 2 - mod(block, 2)
                do row = last, first, -1                    ! any order within a block
                    call format_stream_row(stream, slot, row - first + 1, solutions(row))
                end do
                call write_stream_block(stream, streamed(1), streamed(2), slot, &
                                        last - first + 1)
            end do
            call finish_stream(stream, streamed(2))
            call close_both(streamed, status)
        end if
        call check(status == safe_ok .and. len(contents('build/test_stream_whole.nml')) > &
                   200*size(solutions), what//': both written')
        if (csv) call check(contents('build/test_stream_whole.csv') == &
                            contents('build/test_stream_blocks.csv'), what//': CSV bytes')
        if (nml) call check(contents('build/test_stream_whole.nml') == &
                            contents('build/test_stream_blocks.nml'), what//': namelist bytes')
    end subroutine compare

    subroutine open_both(files, stem, csv, nml, status)
        type(safe_file), intent(inout) :: files(3)
        character(len=*), intent(in) :: stem
        logical, intent(in) :: csv, nml
        integer, intent(out) :: status
        character(len=:), allocatable :: problem
        status = safe_ok
        if (csv) call open_output(files(1), stem//'.csv', .true., status, problem)
        if (nml .and. status == safe_ok) call open_output(files(2), stem//'.nml', .true., &
                                                          status, problem)
    end subroutine open_both

    subroutine close_both(files, status)
        type(safe_file), intent(inout) :: files(3)
        integer, intent(out) :: status
        character(len=:), allocatable :: problem
        integer :: k
        do k = 1, 2
            call finish_output(files(k), status, problem)
            if (status /= safe_ok) return
        end do
        call commit_outputs(files, status, problem)
    end subroutine close_both

    !> The bytes of a file ('' when it cannot be read).
    function contents(path) result(text)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: text
        integer :: unit, ios, bytes
        text = ''
        open (newunit=unit, file=path, access='stream', form='unformatted', status='old', &
              action='read', iostat=ios)
        if (ios /= 0) return
        inquire (unit=unit, size=bytes)
        deallocate (text)
        allocate (character(len=bytes) :: text)
        read (unit, iostat=ios) text
        close (unit)
        if (ios /= 0) text = ''
    end function contents

end module test_result_stream
