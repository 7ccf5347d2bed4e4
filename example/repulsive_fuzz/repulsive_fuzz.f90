!> repulsive-fuzz: a developer's fuzz of the repulsive field's two-point problem.
!!
!!     fpm run --profile release --example repulsive-fuzz -- COUNT [SHOW [SEED [no-apse]]]
!!     fpm run --profile release --example repulsive-fuzz -- grid REPEATS
!!     fpm run --profile release --example repulsive-fuzz -- one RHO PSI REPEATS
!!
!! COUNT endpoints (the draws from SEED, default 1: the same draws on every run): rho
!! from six classes (1 + 10^-U(3, 34), 1 + U(0.001, 0.5), 3/2 -+ 10^-U(2, 30), U(3/2, 10),
!! 10^U(1, 6), exactly 1) and psi from four (U(0, pi), pi 10^-U(1, 30), pi - pi
!! 10^-U(1, 30), and for 1 < rho < 3/2 the apse's angle Theta(rho, rho) -+ 10^-U(5, 30)
!! of it, else U(0, pi); `no-apse`: U(0, pi) there too). Prints the first SHOW (default
!! 5) unsolved endpoints (with psi's relative offset from the apse's angle), the count of
!! unsolved ones, the median and the slowest CPU time per endpoint and their ratio (issue
!! 11: at most 10); the slowest `retimed` endpoints are timed again (median of 5
!! solves each), "retimed max". `grid REPEATS` solves field-timing's 36 endpoints
!! (rho = 1.001 .. 3, psi = 0.001 pi .. 0.99 pi) REPEATS times and prints nothing else
!! but a count: for operation counts (`perf stat` on libgcc's binary128 routines, runs
!! with two REPEATS subtracted); `grid 1 steps` prints each endpoint's arch and evaluations.
program repulsive_fuzz
    use brachistochrone_run_support, only: sort_times
    use brachistochrone_kinds, only: qp, pi
    use brachistochrone_status, only: status_ok
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_repulsive, only: curve_from_apse, repulsive_curve, repulsive_values
    use brachistochrone_repulsive_field, only: repulsive_field, new_repulsive_field
    implicit none
    integer, parameter :: retimed = 10
    type(repulsive_field) :: field
    type(endpoint_solution) :: s
    type(repulsive_curve) :: curve
    character(len=100) :: text
    real(qp) :: u(3), apse_angle, dummy(2), frac(6), rhos_grid(6)
    real(qp), allocatable :: rhos(:), psis(:), offsets(:)
    real, allocatable :: times(:), order(:)
    real :: t0, t1, again(5), retime_max
    integer :: count, show, seed, seed_size, bad, i, k, repeats, solved, status, worst
    integer, allocatable :: seeds(:)
    logical :: near_apse_class

    field = new_repulsive_field()
    call get_command_argument(1, text)
    if (trim(text) == 'grid') then
        call get_command_argument(2, text)
        read (text, *) repeats
        frac = [1.0e-3_qp, 0.1_qp, 0.3_qp, 0.6_qp, 0.9_qp, 0.99_qp]
        rhos_grid = [1.001_qp, 1.1_qp, 1.3_qp, 1.5_qp, 2.0_qp, 3.0_qp]
        solved = 0
        do k = 1, repeats
            do i = 1, 36
                s = field%solve(rhos_grid((i - 1)/6 + 1), frac(mod(i - 1, 6) + 1)*pi)
                if (s%status == status_ok) solved = solved + 1
                if (repeats == 1 .and. command_argument_count() >= 3) write (*, '(2f8.4,3i4)') &
                    rhos_grid((i - 1)/6 + 1), frac(mod(i - 1, 6) + 1), s%arch, s%steps, s%status
            end do
        end do
        write (*, '(a,i0)') 'solved: ', solved
        stop
    end if
    if (trim(text) == 'one') then
        call get_command_argument(2, text)
        read (text, *) u(1)
        call get_command_argument(3, text)
        read (text, *) u(2)
        call get_command_argument(4, text)
        read (text, *) repeats
        do k = 1, repeats
            s = field%solve(u(1), u(2))
        end do
        write (*, '(a,i0,a,i0,a,i0)') 'status ', s%status, ' arch ', s%arch, ' steps ', s%steps
        write (*, '(3es45.36e4)') s%apse_radius, s%arclength, s%time
        stop
    end if
    read (text, *) count
    show = 5
    seed = 1
    if (command_argument_count() >= 2) then
        call get_command_argument(2, text)
        read (text, *) show
    end if
    if (command_argument_count() >= 3) then
        call get_command_argument(3, text)
        read (text, *) seed
    end if
    near_apse_class = .true.
    if (command_argument_count() >= 4) then
        call get_command_argument(4, text)
        near_apse_class = trim(text) /= 'no-apse'
    end if
    call random_seed(size=seed_size)
    allocate (seeds(seed_size))
    seeds = [(104729*i + 7919*seed, i = 1, seed_size)]
    call random_seed(put=seeds)
    allocate (rhos(count), psis(count), times(count), offsets(count))
    offsets = 0.0_qp
    do i = 1, count
        call random_number(u)
        select case (int(6.0_qp*u(1)))
        case (0)
            rhos(i) = 1.0_qp + 10.0_qp**(-3.0_qp - 31.0_qp*u(2))
        case (1)
            rhos(i) = 1.001_qp + 0.499_qp*u(2)
        case (2)
            rhos(i) = 1.5_qp + sign(10.0_qp**(-2.0_qp - 28.0_qp*u(2)), u(3) - 0.5_qp)
        case (3)
            rhos(i) = 1.5_qp + 8.5_qp*u(2)
        case (4)
            rhos(i) = 10.0_qp**(1.0_qp + 5.0_qp*u(2))
        case default
            rhos(i) = 1.0_qp
        end select
        call random_number(u)
        select case (int(4.0_qp*u(1)))
        case (0)
            psis(i) = pi*u(2)
        case (1)
            psis(i) = pi*10.0_qp**(-1.0_qp - 29.0_qp*u(2))
        case (2)
            psis(i) = pi - pi*10.0_qp**(-1.0_qp - 29.0_qp*u(2))
        case default
            psis(i) = pi*u(2)
            if (rhos(i) > 1.0_qp .and. rhos(i) < 1.5_qp .and. near_apse_class) then
                call curve_from_apse(rhos(i), curve, status)
                call repulsive_values(curve, rhos(i), .false., apse_angle, dummy(1), &
                                      dummy(2), status)
                offsets(i) = sign(10.0_qp**(-5.0_qp - 25.0_qp*u(3)), u(2) - 0.5_qp)
                if (status == status_ok) psis(i) = min(pi, apse_angle*(1.0_qp + offsets(i)))
            end if
        end select
    end do
    bad = 0
    do i = 1, count
        call cpu_time(t0)
        s = field%solve(rhos(i), psis(i))
        call cpu_time(t1)
        times(i) = t1 - t0
        if (s%status /= status_ok) then
            bad = bad + 1
            if (bad <= show) write (*, '(a,es44.35e4,a,es44.35e4,a,i0,a,es9.1)') &
                'unsolved rho = ', rhos(i), ' psi = ', psis(i), ' status ', s%status, &
                ' psi/Theta(rho, rho) - 1 = ', offsets(i)
        end if
    end do
    order = times
    call sort_times(order)
    ! the slowest endpoints again, the median of 5 solves each
    retime_max = 0.0
    worst = 1
    do k = 1, min(retimed, count)
        i = maxloc(times, 1)
        do solved = 1, 5
            call cpu_time(t0)
            s = field%solve(rhos(i), psis(i))
            call cpu_time(t1)
            again(solved) = t1 - t0
        end do
        call sort_times(again)
        if (again(3) > retime_max) then
            retime_max = again(3)
            worst = i
        end if
        times(i) = -1.0
    end do
    write (*, '(a,i0,a,i0)') 'unsolved: ', bad, ' of ', count
    write (*, '(a,es10.3,a,es10.3,a,f0.2)') 'median s: ', order((count + 1)/2), &
        ', max s: ', order(count), ', max/median: ', order(count)/order((count + 1)/2)
    write (*, '(a,es10.3,a,f0.2,a,es12.5,a,es12.5)') 'retimed max s: ', retime_max, &
        ', retimed max/median: ', retime_max/order((count + 1)/2), ' at rho = ', &
        rhos(worst), ' psi = ', psis(worst)

end program repulsive_fuzz
