!> engine-timing: per-endpoint time of the general engine against the inverse-square fast
!! path on the same endpoints, in one run, one thread.
!!
!!     fpm run --profile release --example engine-timing -- [FIELD [EXPONENT [REPEATS
!!         [extreme]]]]
!!
!! FIELD is power (default), logarithmic or harmonic; EXPONENT the power law's n (default
!! 3). The endpoints: a grid rho = 0.05 .. 1, psi in (0, 2 lim Theta) scaled to the
!! field's accessible region (the same relative grid for the fast path's 2 pi/3). Prints
!! the median over REPEATS passes (default 3) of the CPU time per endpoint (each pass
!! solves every endpoint 4 times; CPU time, not wall time, because the machine is shared),
!! the ratio of the means, the slowest endpoint relative to the median endpoint, and the
!! CPU time of the model's build (Gauss rules and whole-half-arch tables). With `extreme`,
!! then the time of each of 15 extreme endpoints relative to the grid's median endpoint
!! (`time_extremes`: rho = 1e-30, 1e-6, 1 - 1e-30 with psi = 1e-30, 1/2 and 1 - 1e-6 of
!! the sector; psi within 1e-10 and 1e-14 of the sector's edge at rho = 1/2 and 1; rho = 1
!! with psi = 1e-6 and 1e-12), its status and R-bar (issue 11: at most 10x the median).
program engine_timing
    use, intrinsic :: iso_fortran_env, only: output_unit
    use brachistochrone_kinds, only: qp, pi
    use brachistochrone_speed_laws, only: speed_law, power_law, logarithmic_law, harmonic_law
    use brachistochrone_central_force, only: central_force_model, new_central_force_model
    use brachistochrone_inverse_square, only: inverse_square_model, new_inverse_square_model
    use brachistochrone_two_point, only: solve_endpoint
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_status, only: status_ok
    use brachistochrone_run_support, only: median
    implicit none
    integer, parameter :: n_rho = 5, n_psi = 6
    type(central_force_model) :: general
    type(inverse_square_model) :: fast
    type(endpoint_solution) :: solution
    character(len=64) :: field, text
    real(qp) :: exponent, limit, rho(n_rho), frac(n_psi)
    real(qp), allocatable :: t_general(:, :), t_fast(:, :), worst(:)
    integer :: repeats, k, i, j, failed, r
    integer, parameter :: inner = 4
    real :: start, finish, build

    field = 'power'
    exponent = 3.0_qp
    repeats = 3
    if (command_argument_count() >= 1) call get_command_argument(1, field)
    if (command_argument_count() >= 2) then
        call get_command_argument(2, text)
        read (text, *) exponent
    end if
    if (command_argument_count() >= 3) then
        call get_command_argument(3, text)
        read (text, *) repeats
    end if
    text = ''
    if (command_argument_count() >= 4) call get_command_argument(4, text)
    call cpu_time(start)
    select case (field)
    case ('logarithmic'); general = new_central_force_model(logarithmic_law())
    case ('harmonic');    general = new_central_force_model(harmonic_law())
    case default;         general = new_central_force_model(power_law(n=exponent))
    end select
    call cpu_time(finish)
    build = finish - start
    fast = new_inverse_square_model()
    limit = 2.0_qp*general%law%apse_angle_limit()
    rho = [0.05_qp, 0.25_qp, 0.5_qp, 0.8_qp, 1.0_qp]
    frac = [1.0e-3_qp, 0.1_qp, 0.3_qp, 0.6_qp, 0.9_qp, 0.99_qp]
    allocate (t_general(n_rho*n_psi, repeats), t_fast(n_rho*n_psi, repeats))
    failed = 0
    do k = 1, repeats
        do i = 1, n_rho
            do j = 1, n_psi
                call cpu_time(start)
                do r = 1, inner
                    solution = general%solve(rho(i), frac(j)*limit)
                end do
                call cpu_time(finish)
                if (solution%status /= status_ok .and. k == 1) failed = failed + 1
                t_general((i - 1)*n_psi + j, k) = real(finish - start, qp)/inner
                call cpu_time(start)
                do r = 1, inner
                    solution = solve_endpoint(fast, rho(i), frac(j)*2.0_qp*pi/3.0_qp)
                end do
                call cpu_time(finish)
                t_fast((i - 1)*n_psi + j, k) = real(finish - start, qp)/inner
            end do
        end do
    end do
    ! per endpoint: the median over the repeats; then the mean over endpoints
    worst = [(median(t_general(i, :)), i = 1, n_rho*n_psi)]
    write (output_unit, '(a,a,a,f0.3)') 'field = ', trim(field), ', exponent = ', &
        real(exponent)
    write (output_unit, '(a,es10.3)') 'general engine, mean s per endpoint = ', &
        sum(worst)/size(worst)
    write (output_unit, '(a,es10.3)') 'fast path, mean s per endpoint = ', &
        sum([(median(t_fast(i, :)), i = 1, n_rho*n_psi)])/size(worst)
    write (output_unit, '(a,f8.2)') 'ratio general/fast = ', sum(worst)/ &
        sum([(median(t_fast(i, :)), i = 1, n_rho*n_psi)])
    write (output_unit, '(a,f8.2)') 'slowest endpoint / median endpoint = ', &
        maxval(worst)/median(worst)
    write (output_unit, '(a,i0)') 'endpoints not solved = ', failed
    write (output_unit, '(a,f0.3,a,i0,a,*(l1))') 'model build, s = ', build, &
        ' (whole-half-arch tables: ', count(general%whole_ok), ' pieces checked; far, deep: ', &
        general%far_ok, general%deep_ok
    if (text == 'extreme') call time_extremes(general, limit, repeats, median(worst))
contains

    !> Each extreme endpoint's CPU time (median of `repeats` passes of `inner` solves)
    !! relative to `grid_median`, with its status and R-bar; the worst ratio last.
    subroutine time_extremes(model, limit, repeats, grid_median)
        type(central_force_model), intent(in) :: model
        real(qp), intent(in) :: limit, grid_median
        integer, intent(in) :: repeats
        real(qp) :: rho_x(15), psi_x(15), times(repeats), ratio, worst_ratio
        type(endpoint_solution) :: sol
        integer :: e, k, r
        real :: t0, t1
        rho_x = [1.0e-30_qp, 1.0e-30_qp, 1.0e-30_qp, 1.0e-6_qp, 1.0e-6_qp, 1.0e-6_qp, &
                 1.0_qp - 1.0e-30_qp, 1.0_qp - 1.0e-30_qp, 1.0_qp - 1.0e-30_qp, &
                 0.5_qp, 0.5_qp, 1.0_qp, 1.0_qp, 1.0_qp, 1.0_qp]
        psi_x = [[1.0e-30_qp, 0.5_qp, 1.0_qp - 1.0e-6_qp, 1.0e-30_qp, 0.5_qp, &
                  1.0_qp - 1.0e-6_qp, 1.0e-30_qp, 0.5_qp, 1.0_qp - 1.0e-6_qp, &
                  1.0_qp - 1.0e-10_qp, 1.0_qp - 1.0e-14_qp, 1.0_qp - 1.0e-10_qp, &
                  1.0_qp - 1.0e-14_qp]*limit, 1.0e-6_qp, 1.0e-12_qp]
        worst_ratio = 0.0_qp
        write (output_unit, '(a)') 'extreme endpoints: rho, psi/sector, status, R-bar, '// &
            'us, time/grid median'
        do e = 1, size(rho_x)
            do k = 1, repeats
                call cpu_time(t0)
                do r = 1, inner
                    sol = model%solve(rho_x(e), psi_x(e))
                end do
                call cpu_time(t1)
                times(k) = real(t1 - t0, qp)/inner
            end do
            ratio = median(times)/grid_median
            worst_ratio = max(worst_ratio, ratio)
            write (output_unit, '(2es11.3,i4,es11.3,f9.1,f8.2)') real(rho_x(e)), &
                real(psi_x(e)/limit), sol%status, real(sol%apse_radius), &
                real(median(times))*1.0e6, real(ratio)
        end do
        write (output_unit, '(a,f8.2)') 'worst extreme endpoint / grid median = ', &
            worst_ratio
    end subroutine time_extremes
end program engine_timing
