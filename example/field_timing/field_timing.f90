!> field-timing: CPU time per endpoint of any field, by name through
!! `brachistochrone_fields%new_field`, against the inverse-square field on the same
!! relative endpoint grid, in one run, one thread.
!!
!!     fpm run --profile release --example field-timing -- [FIELD [EXPONENT [REPEATS [NO-NEAR]]]]
!!
!! FIELD is any name `new_field` knows (default repulsive); EXPONENT the power law's n
!! (default 3). The grid: 6 radii x 6 angles. Attractive fields: rho = 0.05 .. 1 and psi a
!! fraction of the accessible limit (pi for logarithmic and harmonic, 2 pi/(n+1) for power
!! laws); repulsive: rho = 1 + 1e-3 .. 3 and psi a fraction of pi; inverse-square on the
!! attractive grid with its limit 2 pi/3. Prints the median over REPEATS passes (default
!! 3) of the CPU time per endpoint (each pass solves every endpoint `inner` times), the
!! ratio of the means, and the slowest endpoint relative to the median endpoint. For the
!! repulsive field it also times endpoints next to the start, rho = 1 + 1e-6, 1 + 1e-10
!! and 1 + 2^-112 (median and slowest over the same angles) unless a fourth argument
!! is given.
program field_timing
    use, intrinsic :: iso_fortran_env, only: output_unit
    use brachistochrone_kinds, only: qp, pi
    use brachistochrone_fields, only: new_field
    use brachistochrone_field_interface, only: brachistochrone_field
    use brachistochrone_status, only: status_ok
    use brachistochrone_run_support, only: median
    implicit none
    integer, parameter :: n_rho = 6, n_psi = 6, inner = 4
    class(brachistochrone_field), allocatable :: field, reference
    character(len=64) :: name, text
    real(qp) :: exponent, limit, rho(n_rho), frac(n_psi), near(3)
    real(qp), parameter :: rho_fast(n_rho) = [0.05_qp, 0.25_qp, 0.5_qp, 0.8_qp, 0.95_qp, 1.0_qp]
    real(qp), allocatable :: t_field(:, :), t_fast(:, :), each(:), each_fast(:)
    integer :: repeats, status, k, i, j, failed

    name = 'repulsive'
    exponent = 3.0_qp
    repeats = 3
    if (command_argument_count() >= 1) call get_command_argument(1, name)
    if (command_argument_count() >= 2) then
        call get_command_argument(2, text)
        read (text, *) exponent
    end if
    if (command_argument_count() >= 3) then
        call get_command_argument(3, text)
        read (text, *) repeats
    end if
    call new_field(trim(name), exponent, field, status)
    if (status /= status_ok) then
        write (output_unit, '(a)') 'field-timing: unknown field or exponent: '//trim(name)
        stop 1
    end if
    call new_field('inverse_square', 0.0_qp, reference, status)
    frac = [1.0e-3_qp, 0.1_qp, 0.3_qp, 0.6_qp, 0.9_qp, 0.99_qp]
    select case (trim(name))
    case ('repulsive')
        rho = [1.001_qp, 1.1_qp, 1.3_qp, 1.5_qp, 2.0_qp, 3.0_qp]
        limit = pi
    case ('power')
        rho = rho_fast
        limit = 2.0_qp*pi/(exponent + 1.0_qp)
    case default
        rho = rho_fast
        limit = pi
        if (trim(name) == 'inverse_square') limit = 2.0_qp*pi/3.0_qp
    end select
    allocate (t_field(n_rho*n_psi, repeats), t_fast(n_rho*n_psi, repeats))
    failed = 0
    do k = 1, repeats
        do i = 1, n_rho
            do j = 1, n_psi
                t_field((i - 1)*n_psi + j, k) = time_one(field, rho(i), frac(j)*limit, &
                                                         failed, k == 1)
                t_fast((i - 1)*n_psi + j, k) = time_one(reference, rho_fast(i), &
                    frac(j)*2.0_qp*pi/3.0_qp, failed, .false.)
            end do
        end do
    end do
    ! per endpoint: the median over the repeats; then the mean over endpoints
    each = [(median(t_field(i, :)), i = 1, n_rho*n_psi)]
    each_fast = [(median(t_fast(i, :)), i = 1, n_rho*n_psi)]
    write (output_unit, '(a,a,a,f0.3)') 'field = ', trim(name), ', exponent = ', &
        real(exponent)
    write (output_unit, '(a,es10.3)') 'field, mean s per endpoint = ', sum(each)/size(each)
    write (output_unit, '(a,es10.3)') 'inverse-square fast path, mean s per endpoint = ', &
        sum(each_fast)/size(each_fast)
    write (output_unit, '(a,f8.2)') 'ratio field/fast = ', sum(each)/sum(each_fast)
    write (output_unit, '(a,f8.2)') 'slowest endpoint / median endpoint = ', &
        maxval(each)/median(each)
    write (output_unit, '(a,i0)') 'endpoints not solved = ', failed
    if (trim(name) /= 'repulsive' .or. command_argument_count() >= 4) stop
    near = [1.0e-6_qp, 1.0e-10_qp, 2.0_qp**(-112)]
    do i = 1, size(near)
        failed = 0
        each = [(time_one(field, 1.0_qp + near(i), frac(j)*pi, failed, .true.), &
                 j = 1, n_psi)]
        write (output_unit, '(a,es10.3,a,es10.3,a,es10.3,a,i0)') 'rho = 1 + ', &
            real(near(i)), ': median s per endpoint = ', median(each), ', slowest = ', &
            maxval(each), ', not solved = ', failed
    end do

contains

    !> CPU seconds per solve of (rho, psi) by `f`, over `inner` solves; counts a failure.
    function time_one(f, rho, psi, failed, count) result(seconds)
        class(brachistochrone_field), intent(in) :: f
        real(qp), intent(in) :: rho, psi
        integer, intent(inout) :: failed
        logical, intent(in) :: count
        real(qp) :: seconds
        real :: start, finish
        integer :: r, status
        status = status_ok
        call cpu_time(start)
        do r = 1, inner
            associate (solution => f%solve(rho, psi))
                status = solution%status
            end associate
        end do
        call cpu_time(finish)
        if (count .and. status /= status_ok) failed = failed + 1
        seconds = real(finish - start, qp)/inner
    end function time_one

end program field_timing
