!> engine-fuzz: a developer's fuzz of the general engine's two-point problem.
!!
!!     fpm run --profile release --example engine-fuzz -- N COUNT [SHOW [SEED]]
!!
!! N is the power law's exponent (0: the logarithmic law), COUNT the number of draws.
!! rho from (0, 1] with clusters at 1e-30, 1 - 1e-30 and 1; psi with clusters within
!! 1e-30 .. 1e-6 of the sector's edge 2 lim Theta and of 0 (the draws from SEED, default
!! 1: the same draws on every run). Prints the first SHOW (default 5) unsolved endpoints (rho,
!! psi, status, evaluations), the count of unsolved ones, the median and the largest CPU
!! time per endpoint, their ratio (issue 11: at most 10) and where the slowest one is.
!! The slowest `retimed` endpoints of the pass are timed again (median of 5 solves each,
!! so that a single interrupted solve does not count as the slowest): "retimed max".
!! Endpoints within 1e-10 of the edge (second half-arch, R-bar > 0) are checked as
!! solutions: the largest |Upsilon(R-bar) - psi| / (eps psi), Upsilon by `half_arch`.
program engine_fuzz
    use brachistochrone_run_support, only: sort_times
    use brachistochrone_kinds, only: qp, eps_qp
    use brachistochrone_speed_laws, only: power_law, logarithmic_law
    use brachistochrone_central_force, only: central_force_model, new_central_force_model
    use brachistochrone_solution, only: endpoint_solution
    implicit none
    type(central_force_model) :: m
    type(endpoint_solution) :: s
    character(len=64) :: text
    real(qp) :: n, limit, rho, psi, u(3), worst_rho, worst_psi, angle, length, time, residual
    integer :: status, checked
    real :: t0, t1
    real, allocatable :: times(:), order(:)
    real(qp), allocatable :: rhos(:), psis(:)
    integer, parameter :: retimed = 10
    real :: again(5), retime_max
    integer :: i, k, count, bad, solved, show, worst_steps, seed_size, seed
    integer, allocatable :: seeds(:)
    call get_command_argument(1, text)
    read (text, *) n
    call get_command_argument(2, text)
    read (text, *) count
    show = 5
    if (command_argument_count() >= 3) then
        call get_command_argument(3, text)
        read (text, *) show
    end if
    seed = 1
    if (command_argument_count() >= 4) then
        call get_command_argument(4, text)
        read (text, *) seed
    end if
    call random_seed(size=seed_size)
    seeds = [(seed + 7919*i, i = 1, seed_size)]
    call random_seed(put=seeds)
    if (n > 0) then
        m = new_central_force_model(power_law(n=n))
    else
        m = new_central_force_model(logarithmic_law())
    end if
    limit = 2.0_qp*m%law%apse_angle_limit()
    allocate (times(count), rhos(count), psis(count))
    bad = 0
    solved = 0
    worst_rho = 0.0_qp
    worst_psi = 0.0_qp
    worst_steps = 0
    residual = 0.0_qp
    checked = 0
    do i = 1, count
        call random_number(u)
        select case (mod(i, 5))
        case (0); rho = u(1)
        case (1); rho = 10.0_qp**(-30.0_qp*u(1))
        case (2); rho = 1.0_qp - 10.0_qp**(-30.0_qp*u(1))
        case (3); rho = 1.0_qp
        case default; rho = 10.0_qp**(-3.0_qp*u(1))
        end select
        select case (mod(i/5, 4))
        case (0); psi = limit*u(2)
        case (1); psi = limit*(1.0_qp - 10.0_qp**(-30.0_qp*u(2)))
        case (2); psi = limit*10.0_qp**(-30.0_qp*u(2))
        case default; psi = limit*(1.0_qp - 10.0_qp**(-6.0_qp*u(2)))
        end select
        if (rho <= 0.0_qp .or. psi <= 0.0_qp .or. psi >= limit) cycle
        call cpu_time(t0)
        s = m%solve(rho, psi)
        call cpu_time(t1)
        solved = solved + 1
        times(solved) = t1 - t0
        rhos(solved) = rho
        psis(solved) = psi
        if (s%status /= 0) then
            bad = bad + 1
            if (bad <= show) print '(a,2es42.33e4,2i5)', 'unsolved', rho, psi, s%status, &
                s%steps
        end if
        if (s%status == 0 .and. psi > limit*(1.0_qp - 1.0e-10_qp) .and. &
            s%apse_radius > 0.0_qp) then
            call m%half_arch(rho, s%apse_radius, .true., angle, length, time, status)
            residual = max(residual, abs(angle - psi)/(eps_qp*psi))
            checked = checked + 1
        end if
        if (times(solved) >= maxval(times(1:solved))) then
            worst_rho = rho
            worst_psi = psi
            worst_steps = s%steps
        end if
    end do
    order = times(1:solved)
    call sort_times(order)
    retime_max = 0.0
    do i = 1, solved
        if (times(i) < order(max(1, solved - retimed + 1))) cycle
        do k = 1, 5
            call cpu_time(t0)
            s = m%solve(rhos(i), psis(i))
            call cpu_time(t1)
            again(k) = t1 - t0
        end do
        call sort_times(again)
        if (again(3) > retime_max) then
            retime_max = again(3)
            worst_rho = rhos(i)
            worst_psi = psis(i)
            worst_steps = s%steps
        end if
    end do
    times(1:solved) = order
    if (show > 0) print '(a,2es42.33e4)', 'slowest', worst_rho, worst_psi
    print '(a,f10.6,a,i0,a,f8.1,a,f8.1,a,f6.1,a,f6.1,a,2es12.4,a,i0)', 'n=', real(n), &
        ' unsolved=', bad, ' median us=', times(solved/2)*1e6, ' max us=', &
        times(solved)*1e6, ' max/median=', times(solved)/times(solved/2), &
        ' retimed max/median=', retime_max/times(solved/2), ' at rho, 1 - psi/edge', &
        real(worst_rho), real(1.0_qp - worst_psi/limit), ' steps ', worst_steps
    print '(a,i0,a,f7.2)', '   edge endpoints checked ', checked, &
        ', largest |Upsilon(R-bar) - psi|/(eps psi) ', real(residual)
end program engine_fuzz
