!> Input validation and output formats.
module test_io
    use brachistochrone_kinds, only: qp, pi
    use brachistochrone_status, only: status_inaccessible
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_arches, only: arch_inaccessible
    use brachistochrone_endpoint_input, only: endpoint_table, read_endpoint_file
    use brachistochrone_result_output, only: format_real, csv_row, write_results_namelist
    use brachistochrone_harmonic_field, only: harmonic_field
    use brachistochrone_safe_file, only: safe_file, open_output, finish_output, &
                                         commit_outputs, safe_ok
    use testing, only: check, section
    implicit none
    private

    public :: run_io_tests

contains

    subroutine run_io_tests()
        call format_tests()
        call input_tests()
        call namelist_round_trip()
    end subroutine run_io_tests

    !> The namelist results read back with read(nml=) to the same bits.
    subroutine namelist_round_trip()
        type(endpoint_solution) :: written(4)
        type(harmonic_field) :: polar   ! a field whose coordinates are rho, psi
        integer :: unit, ios, k
        type(safe_file) :: out(1)
        character(len=:), allocatable :: problem
        integer :: n, steps(4)
        real(qp) :: rho(4), psi(4), r(4), s(4), t(4)
        character(len=16) :: arch(4)
        character(len=20) :: status(4)
        namelist /results/ n, rho, psi, arch, r, s, t, steps, status
        call section('io: namelist results round trip')
        do k = 1, 4
            written(k)%rho = 1.0_qp/real(k + 2, qp)
            written(k)%psi = pi/real(k + 1, qp)
            written(k)%apse_radius = 0.1_qp**(k*700)          ! down to 1e-2800
            written(k)%arclength = 1.0_qp + epsilon(1.0_qp)*real(k, qp)
            written(k)%time = nearest(pi, -1.0_qp)**k
            written(k)%steps = k
            written(k)%has_apse_radius = .true.
            written(k)%has_arclength = .true.
            written(k)%has_time = .true.
        end do
        call open_output(out(1), 'build/test_results.nml', .true., ios, problem)
        if (ios == safe_ok) call write_results_namelist(out(1), polar, written)
        if (ios == safe_ok) call finish_output(out(1), ios, problem)
        if (ios == safe_ok) call commit_outputs(out, ios, problem)
        call check(ios == safe_ok, 'results namelist written: '//problem)
        open (newunit=unit, file='build/test_results.nml', status='old', action='read')
        read (unit, nml=results, iostat=ios)
        close (unit)
        call check(ios == 0 .and. n == 4, 'results namelist read back')
        call check(all(rho == written%rho) .and. all(psi == written%psi) .and. &
                   all(r == written%apse_radius) .and. all(s == written%arclength) .and. &
                   all(t == written%time) .and. all(steps == written%steps), &
                   'every value reads back bit for bit')
        call check(all(status == 'ok') .and. arch(1) == 'none', 'words read back')
    end subroutine namelist_round_trip

    subroutine format_tests()
        real(qp) :: values(6), back
        type(endpoint_solution) :: b
        integer :: k
        logical :: same
        character(len=:), allocatable :: text
        call section('io: number format and CSV rows')
        values = [0.1_qp, pi, 1.0e-30_qp/3.0_qp, 2.0_qp/3.0_qp, 1.0_qp, 123456.789_qp]
        same = .true.
        do k = 1, size(values)
            text = format_real(values(k))
            read (text, *) back
            same = same .and. back == values(k)
        end do
        call check(same, 'format_real reads back to the same binary128 bits')
        call check(format_real(1.0_qp) == '1.00000000000000000000000000000000000e+00', &
                   'format_real(1) = 1.000...e+00 (36 significant digits)')
        call check(format_real(0.25_qp) == '2.50000000000000000000000000000000000e-01', &
                   'format_real(0.25) exponent form')
        b%rho = 0.5_qp
        b%psi = 2.5_qp
        b%arch = arch_inaccessible
        b%status = status_inaccessible
        b%time = 1.0_qp
        b%has_time = .true.
        call check(index(csv_row(b), ',inaccessible,,,1.0') > 0 .and. &
                   index(csv_row(b), ',0,inaccessible') > 0, &
                   'inaccessible row: empty R and s, t is the bound')
    end subroutine format_tests

    subroutine input_tests()
        type(endpoint_table) :: table
        call section('io: namelist input and its validation')
        call write_file('build/test_good.nml', '! a comment'//new_line('a')// &
                        '&endpoints n = 3, rho = 0.2, 0.5, 0.9,'//new_line('a')// &
                        ' psi = 1.2, 0.1, 0.4  r0 = 0.2, , 0.8  r1 = 0.1, , 0.7 /')
        call read_endpoint_file('build/test_good.nml', table)
        call check(size(table%errors) == 0, 'valid file accepted')
        call check(table%n == 3, 'n read')
        call check(table%rho(2) == 0.5_qp .and. table%psi(3) == 0.4_qp, &
                   'values read straight into real(qp)')
        call check(table%has_estimates(1) .and. .not. table%has_estimates(2) .and. &
                   table%has_estimates(3), 'r0, r1 optional per row (null values)')
        call check(table%secant_tolerance == 1.0e-16_qp, 'secant_tolerance default 1e-16')
        call check(table%curve_points == 0, 'curve_points default 0 (no curves)')
        call write_file('build/test_curves.nml', '&endpoints n = 1, rho = 0.5, psi = 1, '// &
                        'curve_points = 100000 /')
        call read_endpoint_file('build/test_curves.nml', table)
        call check(size(table%errors) == 0 .and. table%curve_points == 100000, &
                   'curve_points = 100000 read')

        call expect_error('build/test_missing.nml', 'nothing here', '&endpoints', &
                          'missing group')
        call expect_error('build/test_empty.nml', '', '&endpoints', 'empty file')
        call expect_error('build/test_no_n.nml', '&endpoints rho = 0.5, psi = 1 /', &
                          'variable n', 'n missing')
        call expect_error('build/test_few.nml', '&endpoints n = 3, rho = 0.5, 0.6, '// &
                          'psi = 1, 1, 1 /', 'has 2 values but n = 3', 'too few values')
        call expect_error('build/test_many.nml', '&endpoints n = 1, rho = 0.5, 0.6, '// &
                          'psi = 1 /', 'more than n = 1', 'too many values')
        call expect_error('build/test_nan.nml', '&endpoints n = 2, rho = 0.5, NaN, '// &
                          'psi = 1, 1 /', 'rho(2)', 'NaN named with its row')
        call expect_error('build/test_range.nml', '&endpoints n = 2, rho = 0.5, 1e999, '// &
                          'psi = 1, 1 /', '0 < rho <= 1', 'rho = 1e999 out of range')
        call expect_error('build/test_psi.nml', '&endpoints n = 1, rho = 0.5, psi = -1 /', &
                          'psi(1)', 'negative psi')
        call expect_error('build/test_name.nml', '&endpoints n = 1, rho = 0.5, psi = 1, '// &
                          'phi = 2 /', 'unknown variable "phi"', 'unknown variable')
        call expect_error('build/test_r1.nml', '&endpoints n = 1, rho = 0.5, psi = 1, '// &
                          'r0 = 0.3 /', 'r1(1)', 'r0 without r1')
        call expect_error('build/test_bign.nml', '&endpoints n = 2000000000, rho = 0.5, '// &
                          'psi = 1 /', 'out of range', 'n above the limit')
        call expect_error('build/test_cp1.nml', '&endpoints n = 1, rho = 0.5, psi = 1, '// &
                          'curve_points = 1 /', 'curve_points = 1: must be 0', &
                          'one curve point')
        call expect_error('build/test_cp2.nml', '&endpoints n = 1, rho = 0.5, psi = 1, '// &
                          'curve_points = 100001 /', '2 <= curve_points <= 100000', &
                          'too many curve points')
        call expect_error('build/test_cp3.nml', '&endpoints n = 1, rho = 0.5, psi = 1, '// &
                          'curve_points = 2.5 /', 'whole number', 'curve_points not whole')
        call expect_error('build/test_cp4.nml', '&endpoints n = 1, rho = 0.5, psi = 1, '// &
                          'curve_points = 5, 6 /', 'exactly one value', 'two curve_points')
        call expect_error('build/test_cp5.nml', '&endpoints n = 1, rho = 0.5, psi = 1, '// &
                          'curve_points = 99999999999 /', 'out of range', &
                          'curve_points overflows')
        call expect_error('build/test_nofile.nml', '', 'cannot read', 'missing file', &
                          create=.false.)
    end subroutine input_tests

    subroutine expect_error(path, contents, fragment, name, create)
        character(len=*), intent(in) :: path, contents, fragment, name
        logical, intent(in), optional :: create
        type(endpoint_table) :: table
        logical :: found, make
        integer :: k
        make = .true.
        if (present(create)) make = create
        if (make) call write_file(path, contents)
        call read_endpoint_file(path, table)
        found = .false.
        do k = 1, size(table%errors)
            found = found .or. (index(table%errors(k)%text, fragment) > 0 .and. &
                                index(table%errors(k)%text, path) > 0)
        end do
        call check(size(table%errors) > 0 .and. found, 'input error reported: '//name)
        if (.not. found .and. size(table%errors) > 0) print '(3x,a)', table%errors(1)%text
    end subroutine expect_error

    subroutine write_file(path, contents)
        character(len=*), intent(in) :: path, contents
        integer :: unit
        open (newunit=unit, file=path, status='replace', action='write')
        if (len(contents) > 0) write (unit, '(a)') contents
        close (unit)
    end subroutine write_file

end module test_io
