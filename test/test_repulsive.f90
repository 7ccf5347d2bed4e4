!> Repulsive inverse-square brachistochrones (src/physics/repulsive.f90) against
!! independent values: the radial closed form (49), the critical curve in closed form,
!! mpmath at 80 digits on the original integrals (data/reference/repulsive_mpmath.csv,
!! scripts/make_repulsive_reference.py), and the two-point structure derived in the module.
module test_repulsive
    use, intrinsic :: iso_fortran_env, only: output_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf, ieee_quiet_nan, &
                                             ieee_is_finite
    use brachistochrone_kinds, only: qp, pi, eps_qp
    use brachistochrone_status, only: status_ok, status_rho_below_start, &
                                      status_not_finite, status_psi_out_of_range, &
                                      status_invalid_argument
    use brachistochrone_repulsive, only: repulsive_curve, repulsive_solution, curve_from_k2, &
                         curve_from_gap, curve_from_apse, curve_from_apse_gap, &
                         repulsive_values, critical_values, repulsive_radial_time, &
                         solve_repulsive, critical_k2, panel_values, panel_rules, &
                         new_panel_rules
    use brachistochrone_arches, only: arch_unbounded, arch_first, arch_second
    use testing, only: check, check_close, check_digits, section, digits_of_agreement
    use reference_tables, only: csv_table, read_reference
    implicit none
    private

    public :: run_repulsive_tests

    real(qp), save :: worst_reference = 99.0_qp

contains

    !> Every repulsive test group.
    subroutine run_repulsive_tests()
        call radial_closed_form()
        call critical_closed_form()
        call mpmath_reference()
        call fixed_panels()
        call second_half_panels()
        call branch_structure()
        call two_point()
        call two_point_mpmath()
        call next_to_the_apse()
        call next_to_the_apse_angle()
        call next_to_the_apse_mpmath()
        call winding_asymptotics()
        call constructors()
        call cycloid_limit()
        call next_to_the_start()
        call bad_input()
    end subroutine run_repulsive_tests

    subroutine radial_closed_form()
        type(repulsive_curve) :: curve
        real(qp), parameter :: radii(4) = [1.0e-20_qp, 0.5_qp, 2.0_qp, 99.0_qp]
        real(qp) :: angle, length, time, r
        integer :: i, status
        call section('repulsive: K = 0 is radial motion, t = (49)')
        call curve_from_k2(0.0_qp, curve, status)
        do i = 1, size(radii)
            r = 1.0_qp + radii(i)
            call repulsive_values(curve, r, .false., angle, length, time, status)
            call check(status == status_ok .and. angle == 0.0_qp, 'radial: theta = 0')
            call check_close(length, r - 1.0_qp, 8.0_qp, 'radial: s = r - 1')
            call check_close(time, repulsive_radial_time(r), 8.0_qp, 'radial: t = (49)')
        end do
    end subroutine radial_closed_form

    subroutine critical_closed_form()
        type(repulsive_curve) :: curve, near
        real(qp), parameter :: radii(5) = [1.0625_qp, 1.25_qp, 1.4375_qp, 1.4990234375_qp, &
                                           1.5_qp - 2.0_qp**(-40)]
        real(qp) :: a(3), b(3), worst, worst_near, r
        integer :: i, j, status
        call section('repulsive: critical curve K^2 = 27/8 in closed form')
        call curve_from_gap(0.0_qp, curve, status)
        call check(curve%k2 == critical_k2, 'critical: K^2 = 27/8')
        worst = 99.0_qp
        worst_near = 99.0_qp
        do i = 1, size(radii)
            r = radii(i)
            call critical_values(r, b(1), b(2), b(3), status)
            call repulsive_values(curve, r, .false., a(1), a(2), a(3), status)
            call check(status == status_ok, 'critical: integrals converge')
            do j = 1, 3
                worst = min(worst, digits_of_agreement(a(j), b(j)))
            end do
            ! g = +-1e-60: unbounded and bounded curves agree with the critical one to
            ! O(g/(3/2 - r)^2) (1e-36 at the last radius): the near-double root is resolved;
            ! 31.5 digits (not 32) as the angle there is a log of 3 - 2r: ~40 eps absolute
            call curve_from_gap(1.0e-60_qp, near, status)
            call repulsive_values(near, r, .false., a(1), a(2), a(3), status)
            do j = 1, 3
                worst_near = min(worst_near, digits_of_agreement(a(j), b(j)))
            end do
            call curve_from_gap(-1.0e-60_qp, near, status)
            call repulsive_values(near, r, .false., a(1), a(2), a(3), status)
            do j = 1, 3
                worst_near = min(worst_near, digits_of_agreement(a(j), b(j)))
            end do
        end do
        write (output_unit, '(a,f6.2)') '   integrals (g = 0) vs closed form, fewest digits: ', &
            worst
        write (output_unit, '(a,f6.2)') '   g = +-1e-60 vs closed form, fewest digits:        ', &
            worst_near
        call check(worst >= 32.0_qp, 'critical: theta, s, t integrals = closed form')
        call check(worst_near >= 31.5_qp, 'critical: g = +-1e-60 = closed form')
        ! the spiral: theta -> infinity as r -> 3/2 (about -log(3 - 2r)/sqrt3)
        call critical_values(1.5_qp - 2.0_qp**(-100), b(1), b(2), b(3), status)
        call check(b(1) > 6.0_qp*2.0_qp*pi, 'critical: six turns before 3/2 - 2^-100')
        call check_close(b(1), -log(2.0_qp**(-99))/sqrt(3.0_qp), 1.0e32_qp, &
                         'critical: theta ~ -log(3 - 2r)/sqrt3 (to O(1))', 1.0_qp)
        call critical_values(1.5_qp, b(1), b(2), b(3), status)
        call check(status == status_invalid_argument, 'critical: r = 3/2 is never reached')
    end subroutine critical_closed_form

    !> One mpmath row: bounded (parameter R) or not (parameter K^2); arch 0 first, 1
    !! second, 2 apse.
    subroutine ref(bounded, parameter, kind, r_in, arch, expected)
        integer, intent(in) :: bounded, kind, arch
        real(qp), intent(in) :: parameter, r_in, expected
        type(repulsive_curve) :: curve
        real(qp) :: v(3), r, have
        integer :: status
        if (bounded == 1) then
            call curve_from_apse(parameter, curve, status)
        else
            call curve_from_k2(parameter, curve, status)
        end if
        r = r_in
        if (r == huge(1.0_qp)) r = ieee_value(r, ieee_positive_inf)
        if (arch == 2) r = curve%apse
        call repulsive_values(curve, r, arch == 1, v(1), v(2), v(3), status)
        call check(status == status_ok, 'mpmath reference: status ok')
        have = digits_of_agreement(v(kind), expected)
        worst_reference = min(worst_reference, have)
        call check_digits(v(kind), expected, 32.5_qp, 'mpmath reference value')
    end subroutine ref

    subroutine mpmath_reference()
        call section('repulsive: theta, s, t against mpmath (80 digits, original integrals)')
        call ref(0, 2.0_qp, 1, 1.25_qp, 0, &
                 0.1503153673364795377413777400831607370603_qp)
        call ref(0, 2.0_qp, 2, 1.25_qp, 0, &
                 0.3081968781880009748911681110922466966128_qp)
        call ref(0, 2.0_qp, 3, 1.25_qp, 0, &
                 0.8542869370951081459206231142045906191353_qp)
        call ref(0, 2.0_qp, 1, 2.0_qp, 0, &
                 0.6833543139198826172847456535466151040376_qp)
        call ref(0, 2.0_qp, 2, 2.0_qp, 0, &
                 1.440509456931057470960729853346853663407_qp)
        call ref(0, 2.0_qp, 3, 2.0_qp, 0, &
                 2.195963826926483544813951243469639118814_qp)
        call ref(0, 2.0_qp, 1, 5.0_qp, 0, &
                 1.270014642580120035392608535630470459778_qp)
        call ref(0, 2.0_qp, 2, 5.0_qp, 0, &
                 4.957241196357012893917692574355698753103_qp)
        call ref(0, 2.0_qp, 3, 5.0_qp, 0, &
                 5.211623875978052471803218759488059902902_qp)
        call ref(0, 2.0_qp, 1, huge(1.0_qp), 0, &
                 1.658186782211470232732915257771101751021_qp)
        call ref(0, 0.5_qp, 1, 10.0_qp, 0, &
                 0.5968374619310927994082428676252042101222_qp)
        call ref(0, 0.5_qp, 2, 10.0_qp, 0, &
                 9.21614251202794694849652253807463313935_qp)
        call ref(0, 0.5_qp, 3, 10.0_qp, 0, &
                 8.210085603882717593826688073452641068719_qp)
        call ref(0, 0.5_qp, 1, huge(1.0_qp), 0, &
                 0.694443053726348236162411275037684594966_qp)
        call ref(0, 3.3740234375_qp, 1, 1.4375_qp, 0, &
                 1.024560378803230273072789236546779116381_qp)
        call ref(0, 3.3740234375_qp, 2, 1.4375_qp, 0, &
                 1.464435655308067772396203255487617672885_qp)
        call ref(0, 3.3740234375_qp, 3, 1.4375_qp, 0, &
                 2.497383062466599567783344450423662876559_qp)
        call ref(0, 3.3740234375_qp, 1, 1.5625_qp, 0, &
                 3.507617046866501084613915077084042300821_qp)
        call ref(0, 3.3740234375_qp, 2, 1.5625_qp, 0, &
                 5.191809106709124114258296078042392258486_qp)
        call ref(0, 3.3740234375_qp, 3, 1.5625_qp, 0, &
                 7.064751408596231452132124573314183020176_qp)
        call ref(0, 3.3740234375_qp, 1, 3.0_qp, 0, &
                 5.322759162773522302248173264906343154813_qp)
        call ref(0, 3.3740234375_qp, 2, 3.0_qp, 0, &
                 9.090955501770870241085143259479373857574_qp)
        call ref(0, 3.3740234375_qp, 3, 3.0_qp, 0, &
                 11.04425410705178253938927719008082946874_qp)
        call ref(0, 3.3740234375_qp, 1, huge(1.0_qp), 0, &
                 6.206349543757123448150889695101818381959_qp)
        call ref(1, 1.25_qp, 1, 1.25_qp, 2, &
                 0.5062816633637656473370533343986577254931_qp)
        call ref(1, 1.25_qp, 2, 1.25_qp, 2, &
                 0.6858463901784349992773014137128890056401_qp)
        call ref(1, 1.25_qp, 3, 1.25_qp, 2, &
                 1.511629455341574255615206637844296146361_qp)
        call ref(1, 1.25_qp, 1, 1.125_qp, 0, &
                 0.09574348562571619383264954386427847675488_qp)
        call ref(1, 1.25_qp, 1, 1.125_qp, 1, &
                 0.9168198411018151008414571249330369742314_qp)
        call ref(1, 1.25_qp, 2, 1.125_qp, 0, &
                 0.1661039663722047248336693807350432835699_qp)
        call ref(1, 1.25_qp, 2, 1.125_qp, 1, &
                 1.20558881398466527372093344669073472771_qp)
        call ref(1, 1.25_qp, 3, 1.125_qp, 0, &
                 0.6206498674779540937671011857918161636757_qp)
        call ref(1, 1.25_qp, 3, 1.125_qp, 1, &
                 2.402609043205194417463312089896776129046_qp)
        call ref(1, 1.49999904632568359375_qp, 1, 1.49999904632568359375_qp, 2, &
                 7.824955674976647296262586398590750489353_qp)
        call ref(1, 1.49999904632568359375_qp, 2, 1.49999904632568359375_qp, 2, &
                 11.62968177286026166874958669536526413447_qp)
        call ref(1, 1.49999904632568359375_qp, 3, 1.49999904632568359375_qp, 2, &
                 14.99346153528675466262072575539990900729_qp)
        call ref(1, 1.49999904632568359375_qp, 1, 1.25_qp, 0, &
                 0.2711091946628360960656012677363481353053_qp)
        call ref(1, 1.49999904632568359375_qp, 1, 1.25_qp, 1, &
                 15.3788021552904584964595715294451528434_qp)
        call ref(1, 1.49999904632568359375_qp, 2, 1.25_qp, 0, &
                 0.4146442619188507309255425610277675260018_qp)
        call ref(1, 1.49999904632568359375_qp, 2, 1.25_qp, 1, &
                 22.84471928380167260657363082970276074293_qp)
        call ref(1, 1.49999904632568359375_qp, 3, 1.25_qp, 0, &
                 1.055446150661995072882886210398106294265_qp)
        call ref(1, 1.49999904632568359375_qp, 3, 1.25_qp, 1, &
                 28.93147691991151425235856530040171172032_qp)
        write (output_unit, '(a,f6.2)') '   fewest digits against mpmath: ', worst_reference
    end subroutine mpmath_reference

    !> The solver's fixed Gauss panels (rules chosen from the located singularities)
    !! against the adaptive integrals (themselves checked against mpmath above): every
    !! kind of piece, unbounded g = 3 .. 3 2^-160, bounded 3 - 2R = 2^-160 .. 1, both
    !! half-arches, radii from 1 + 1e-30 to 100 (3/2 exactly, where the peak sits at the
    !! endpoint); binary128 to a few eps, the hardware precision angle to about 1e-18.
    !! A curve too close to the critical one for `max_panels` must say so (the solver
    !! then integrates adaptively), never return a wrong value: checked down to g and
    !! 3 - 2R of 2^-160; it must not happen above 1e-36.
    subroutine fixed_panels()
        real(qp), parameter :: radii(10) = [1.0_qp + 1.0e-30_qp, 1.001_qp, 1.1_qp, 1.25_qp, &
                                           1.4_qp, 1.499_qp, 1.5_qp, 2.0_qp, 5.0_qp, 100.0_qp]
        type(panel_rules) :: rules
        type(repulsive_curve) :: curve
        real(qp) :: a(3), b(3), x(3), r, worst(3), worst_xp, smallest_failed
        integer :: i, j, kind, second, stat(3)
        call section('repulsive: fixed Gauss panels against the adaptive integrals')
        rules = new_panel_rules()
        worst = 0.0_qp
        worst_xp = 0.0_qp
        smallest_failed = 0.0_qp
        do kind = 1, 2
            do j = 0, 160, 4
                if (kind == 1) then
                    call curve_from_gap(3.0_qp*2.0_qp**(-j), curve, stat(1))
                else
                    call curve_from_apse_gap(0.999_qp*2.0_qp**(-j), curve, stat(1))
                end if
                do i = 1, size(radii)
                    do second = 0, merge(1, 0, curve%bounded)
                        r = radii(i)
                        if (curve%bounded) r = min(r, curve%apse)
                        call repulsive_values(curve, r, second == 1, a(1), a(2), a(3), &
                                              stat(1))
                        call panel_values(curve, r, second == 1, rules, .false., b, stat(2))
                        call panel_values(curve, r, second == 1, rules, .true., x, stat(3))
                        if (stat(2) /= status_ok .or. stat(3) /= status_ok) then
                            smallest_failed = max(smallest_failed, 2.0_qp**(-j))
                            cycle
                        end if
                        worst = max(worst, abs(a - b)/max(abs(a), tiny(1.0_qp))/eps_qp)
                        worst_xp = max(worst_xp, abs(a(1) - x(1))/max(abs(a(1)), tiny(1.0_qp)))
                    end do
                end do
            end do
        end do
        write (output_unit, '(a,3f7.2)') '   binary128 panels vs adaptive, worst theta, s, t '// &
            'in eps: ', worst
        write (output_unit, '(a,es10.2)') '   hardware-precision angle vs adaptive, worst '// &
            'relative: ', worst_xp
        write (output_unit, '(a,es10.2)') '   largest g or 3 - 2R (/3) the panels decline: ', &
            smallest_failed
        call check(smallest_failed < 1.0e-36_qp, 'fixed panels: evaluated down to 1e-36')
        call check(all(worst <= 8.0_qp), 'fixed panels = adaptive to 8 eps')
        call check(worst_xp <= 1.0e-17_qp, 'hardware-precision panels to 1e-17')
    end subroutine fixed_panels

    !> The fixed panels on the second half-arch, taken as F(r) + 2 (F(R) - F(r)) with the
    !! difference on its own pieces, against the adaptive 2 F(R) - F(r): r from next to
    !! the start (1 + (R - 1) 2^-100) to next to the apse (R - (R - 1) 2^-100, where the
    !! difference is in the apse's sinh map), apse R = 1 + 1e-20 .. 3/2 - 1e-20.
    subroutine second_half_panels()
        real(qp), parameter :: apses(5) = [1.0_qp + 1.0e-20_qp, 1.001_qp, 1.25_qp, &
                                           1.49_qp, 1.5_qp - 1.0e-20_qp]
        integer, parameter :: powers(7) = [1, 3, 10, 30, 60, 100, 0]
        type(panel_rules) :: rules
        type(repulsive_curve) :: curve
        real(qp) :: a(3), b(3), r, worst(3)
        integer :: i, j, side, stat(3)
        call section('repulsive: second half-arch panels, F(r) + 2 (F(R) - F(r))')
        rules = new_panel_rules()
        worst = 0.0_qp
        do i = 1, size(apses)
            call curve_from_apse(apses(i), curve, stat(1))
            do j = 1, size(powers)
                do side = 0, 1
                    ! powers 0: r = R itself (the second half-arch's start)
                    if (side == 0) then
                        r = curve%apse - curve%apse_m1*2.0_qp**(-powers(j))
                    else
                        r = 1.0_qp + curve%apse_m1*2.0_qp**(-powers(j))
                    end if
                    if (powers(j) == 0) r = curve%apse
                    call repulsive_values(curve, r, .true., a(1), a(2), a(3), stat(2))
                    call panel_values(curve, r, .true., rules, .false., b, stat(3))
                    call check(all(stat == status_ok), 'second half-arch panels: status ok')
                    worst = max(worst, abs(a - b)/max(abs(a), tiny(1.0_qp))/eps_qp)
                end do
            end do
        end do
        write (output_unit, '(a,3f7.2)') '   panels vs adaptive, worst theta, s, t in eps: ', &
            worst
        call check(all(worst <= 8.0_qp), 'second half-arch panels = adaptive to 8 eps')
    end subroutine second_half_panels

    !> theta(rho) along the branch of curves through rho is increasing: unbounded (g from 3
    !! down to 0), then for rho < 3/2 first half-arches (R from 3/2 down to rho) and second
    !! ones (R from rho back up to 3/2); t increases with it.
    subroutine branch_structure()
        real(qp), parameter :: rhos(4) = [1.25_qp, 1.4375_qp, 1.5_qp, 3.0_qp]
        type(repulsive_curve) :: curve
        real(qp) :: angle, length, time, last_angle, last_time, e
        integer :: i, j, status
        logical :: increasing
        call section('repulsive: theta(rho) and t increase along the branch of curves')
        do i = 1, size(rhos)
            increasing = .true.
            last_angle = -1.0_qp
            last_time = -1.0_qp
            do j = 0, 60
                call curve_from_gap(3.0_qp*2.0_qp**(-j), curve, status)
                if (j == 0) call curve_from_k2(0.0_qp, curve, status)
                call repulsive_values(curve, rhos(i), .false., angle, length, time, status)
                call step()
            end do
            if (rhos(i) < 1.5_qp) then
                do j = 60, 1, -1
                    e = (3.0_qp - 2.0_qp*rhos(i))*2.0_qp**(-j)
                    call curve_from_apse_gap(e, curve, status)
                    call repulsive_values(curve, rhos(i), .false., angle, length, time, status)
                    call step()
                end do
                do j = 0, 60
                    e = (3.0_qp - 2.0_qp*rhos(i))*2.0_qp**(-j)
                    call curve_from_apse_gap(e, curve, status)
                    call repulsive_values(curve, rhos(i), .true., angle, length, time, status)
                    call step()
                end do
            end if
            write (output_unit, '(a,f7.4,a,es10.3)') '   rho = ', rhos(i), &
                ': largest angle on the grid ', last_angle
            call check(increasing, 'theta and t increase along the branch')
        end do
    contains
        subroutine step()
            ! non-decreasing to rounding: near R = 3/2 the first half-arch angle moves by
            ! O(g) = O((3 - 2R)^2), below the quadrature's noise (a few eps: 2 eps per
            ! piece) on the finest steps of the grid
            if (status /= status_ok .or. angle < last_angle*(1.0_qp - 16.0_qp*eps_qp) .or. &
                time < last_time*(1.0_qp - 16.0_qp*eps_qp)) increasing = .false.
            last_angle = angle
            last_time = time
        end subroutine step
    end subroutine branch_structure

    subroutine two_point()
        real(qp), parameter :: rhos(7) = [1.0_qp, 1.125_qp, 1.25_qp, 1.4375_qp, 1.5_qp, 2.0_qp, &
                                           5.0_qp]
        real(qp), parameter :: psis(4) = [0.0_qp, 0.4_qp, 1.0_qp, 3.0_qp]
        type(repulsive_solution), allocatable :: sol(:)
        real(qp) :: worst, residual, apse(3), angle, length, time
        type(repulsive_curve) :: curve
        integer :: i, j, k, best, status, arches(0:6)
        logical :: ordered, all_ok
        call section('repulsive: two-point problem, windings m = 0..2, both senses')
        worst = 0.0_qp
        arches = 0
        do i = 1, size(rhos)
            do j = 1, size(psis)
                if (rhos(i) == 1.0_qp .and. psis(j) == 0.0_qp) cycle
                call solve_repulsive(rhos(i), psis(j), 2, sol, best, status)
                call check(status == status_ok, 'two-point: endpoint accepted')
                all_ok = .true.
                ordered = .true.
                do k = 1, size(sol)
                    if (sol(k)%status /= status_ok) all_ok = .false.
                    ! theta(rho) recomputed on the solved curve by the adaptive integrals
                    call repulsive_values(sol(k)%curve, rhos(i), sol(k)%arch == arch_second, &
                                          angle, length, time, status)
                    residual = abs(angle - sol(k)%target)/max(sol(k)%target, 1.0_qp)
                    worst = max(worst, residual/eps_qp)
                    arches(sol(k)%arch) = arches(sol(k)%arch) + 1
                    if (k > 1) then
                        if (sol(k)%target <= sol(k - 1)%target .or. &
                            sol(k)%time <= sol(k - 1)%time) ordered = .false.
                    end if
                end do
                call check(all_ok, 'two-point: every target solved')
                call check(ordered, 'two-point: time increases with the swept angle')
                call check(best == 1, 'two-point: least time on the least swept angle')
                if (i == 6 .and. j == 3) then
                    write (output_unit, '(a)') '   rho = 2, psi = 1:  m  cw  gap g = 3 - P   t'
                    do k = 1, size(sol)
                        write (output_unit, '(a,i2,l3,es14.6,f40.34)') '   ', sol(k)%winding, &
                            sol(k)%clockwise, sol(k)%curve%gap, sol(k)%time
                    end do
                end if
            end do
        end do
        write (output_unit, '(a,f8.2)') '   worst |theta(rho) - target|/max(target,1) in eps: ', &
            worst
        write (output_unit, '(a,3i4)') '   solutions unbounded, first, second half-arch: ', &
            arches([arch_unbounded, arch_first, arch_second])
        call check(worst <= 16.0_qp, 'two-point: endpoint angle reproduced to 16 eps')
        call check(all(arches([arch_unbounded, arch_first, arch_second]) > 0), &
                   'two-point: every kind of branch exercised')
        ! B at the apse of the curve with R = rho: psi = Theta(rho, rho), top of the branch
        call curve_from_apse(1.25_qp, curve, status)
        call repulsive_values(curve, 1.25_qp, .false., apse(1), apse(2), apse(3), status)
        call solve_repulsive(1.25_qp, apse(1), 0, sol, best, status)
        call check_close(sol(1)%curve%apse, 1.25_qp, 4.0_qp, 'two-point: B at the apse: R = rho')
        call check_close(sol(1)%time, apse(3), 4.0_qp, 'two-point: B at the apse: t = T(R, R)')
        ! psi = 0, m = 0 is the radial path
        call solve_repulsive(2.0_qp, 0.0_qp, 0, sol, best, status)
        call check(size(sol) == 1, 'two-point: psi = 0 has one sense')
        call check_close(sol(1)%time, repulsive_radial_time(2.0_qp), 8.0_qp, &
                         'two-point: psi = 0 is radial, t = (49)')
        ! psi so small that K^2 ~ (3 psi/2)^2/(2 (1 - 1/rho)^3) underflows (1e-6000 at
        ! rho = 1001, psi = 1e-3000): the radial path's s and t to O(K^2); before, the
        ! adaptive fallback returned status ok with theta = 2.4e-49
        call solve_repulsive(1001.0_qp, 1.0e-3000_qp, 0, sol, best, status)
        call check(status == status_ok .and. best == 1 .and. sol(1)%status == status_ok &
                   .and. sol(1)%arch == arch_unbounded, &
                   'two-point: psi = 1e-3000 at rho = 1001 solved (K^2 below the range)')
        call check_close(sol(1)%arclength, 1000.0_qp, 4.0_qp, &
                         'two-point: psi = 1e-3000: s = rho - 1 to O(K^2)')
        call check_close(sol(1)%time, repulsive_radial_time(1001.0_qp), 8.0_qp, &
                         'two-point: psi = 1e-3000: t = (49) to O(K^2)')
        ! just above that range, psi = 1e-2400 (K^2 ~ 1e-4800): solved as a curve
        call solve_repulsive(1001.0_qp, 1.0e-2400_qp, 0, sol, best, status)
        call check(status == status_ok .and. sol(1)%status == status_ok, &
                   'two-point: psi = 1e-2400 at rho = 1001 solved')
        call check_close(sol(1)%angle, 1.0e-2400_qp, 64.0_qp, &
                         'two-point: psi = 1e-2400: the curve sweeps psi')
    end subroutine two_point

    !> Two-point solutions against the problem solved independently by mpmath (findroot on
    !! the original integrals, last rows of data/reference/repulsive_mpmath.csv).
    subroutine two_point_mpmath()
        type(repulsive_solution), allocatable :: sol(:)
        integer :: best, status
        call section('repulsive: two-point solutions against mpmath findroot')
        call solve_repulsive(2.0_qp, 1.0_qp, 1, sol, best, status)
        call check_digits(sol(1)%curve%k2, 2.645088804285968552324521429348058561082_qp, &
                          33.0_qp, 'rho = 2, psi = 1, m = 0: K^2')
        call check_digits(sol(1)%time, 2.681630164465431617080797780894761881585_qp, &
                          33.0_qp, 'rho = 2, psi = 1, m = 0: t')
        call check_digits(sol(3)%curve%k2, 3.374988486845173448639438430583911265415_qp, &
                          33.0_qp, 'rho = 2, psi = 1, m = 1: K^2')
        call check_digits(sol(3)%time, 14.11614078964469775439951871173613963026_qp, &
                          33.0_qp, 'rho = 2, psi = 1, m = 1: t')
        call solve_repulsive(1.25_qp, 0.4_qp, 0, sol, best, status)
        call check(sol(1)%arch == arch_first, 'rho = 5/4, psi = 0.4: first half-arch')
        call check_digits(sol(1)%curve%apse, 1.260982129463187324371251899279339797443_qp, &
                          33.0_qp, 'rho = 5/4, psi = 0.4: R')
        call check_digits(sol(1)%time, 1.302101069487037272664073805610511465792_qp, &
                          33.0_qp, 'rho = 5/4, psi = 0.4: t')
        call solve_repulsive(1.25_qp, 1.0_qp, 0, sol, best, status)
        call check(sol(1)%arch == arch_second, 'rho = 5/4, psi = 1: second half-arch')
        call check_digits(sol(1)%curve%apse, 1.301727301114516485665968712614332589964_qp, &
                          33.0_qp, 'rho = 5/4, psi = 1: R')
        call check_digits(sol(1)%time, 2.472898487362827611486440077335108505319_qp, &
                          33.0_qp, 'rho = 5/4, psi = 1: t')
        call solve_repulsive(1.0_qp, 1.0_qp, 0, sol, best, status)
        call check_digits(sol(1)%curve%apse, 1.247702771295926586612647102385209859044_qp, &
                          33.0_qp, 'rho = 1, psi = 1 (complete arch): R')
        call check_digits(sol(1)%time, 2.998405500762512523847012785093331940808_qp, &
                          33.0_qp, 'rho = 1, psi = 1 (complete arch): t')
    end subroutine two_point_mpmath

    !> B next to the apse, R - rho = 2^-60 and 2^-100 on both half-arches: the curve with
    !! apse R = rho + 2^-k is exact in binary128 and its angle, s and t at rho come from
    !! the adaptive integrals (R - rho formed exactly there); solving for that angle must
    !! give back R and t (t is well conditioned in psi; the solver's unknown there is
    !! sqrt(R - rho), which keeps it exact).
    subroutine next_to_the_apse()
        type(repulsive_curve) :: curve
        type(repulsive_solution), allocatable :: sol(:)
        real(qp), parameter :: rhos(2) = [1.25_qp, 1.4375_qp]
        real(qp) :: v(3), worst_r, worst_t, rho
        integer :: k, i, second, best, status
        call section('repulsive: two-point problem next to the apse (R - rho = 2^-60, 2^-100)')
        worst_r = 99.0_qp
        worst_t = 99.0_qp
        do i = 1, 2
            rho = rhos(i)
            do k = 60, 100, 40
                call curve_from_apse(rho + 2.0_qp**(-k), curve, status)
                do second = 0, 1
                    call repulsive_values(curve, rho, second == 1, v(1), v(2), v(3), status)
                    call solve_repulsive(rho, v(1), 0, sol, best, status, mirror=.false.)
                    call check(status == status_ok .and. sol(1)%status == status_ok .and. &
                               sol(1)%arch == merge(arch_second, arch_first, second == 1), &
                               'next to the apse: solved on the right half-arch')
                    worst_r = min(worst_r, digits_of_agreement(sol(1)%curve%apse - rho, &
                                                               2.0_qp**(-k)))
                    worst_t = min(worst_t, digits_of_agreement(sol(1)%time, v(3)))
                end do
            end do
        end do
        write (output_unit, '(a,2f7.2)') '   fewest digits of R - rho, t: ', worst_r, worst_t
        call check(worst_r >= 15.0_qp, 'next to the apse: R - rho recovered (conditioning: 19)')
        call check(worst_t >= 32.0_qp, 'next to the apse: t to 32 digits')
    end subroutine next_to_the_apse

    !> B next to the apse angle: psi = Theta(rho, rho) (1 +- 1e-8, 1e-17, 1e-25, 1e-30)
    !! (Theta by the adaptive integrals) for rho = 1 + 1e-20, 1.001, 5/4, 1.45 (an apse
    !! angle exists only for 1 < rho < 3/2): below 1e-16 of psi the hardware phase
    !! cannot resolve theta - psi. Every endpoint solved, on the first (-) or second (+)
    !! half-arch; the curve found (R - rho kept exactly) satisfies the angle equation to
    !! a few eps by the adaptive integrals, which give s and t there as well.
    subroutine next_to_the_apse_angle()
        type(repulsive_curve) :: curve
        type(repulsive_solution), allocatable :: sol(:)
        real(qp), parameter :: rhos(4) = [1.0_qp + 1.0e-20_qp, 1.001_qp, 1.25_qp, 1.45_qp]
        real(qp), parameter :: offsets(4) = [1.0e-8_qp, 1.0e-17_qp, 1.0e-25_qp, 1.0e-30_qp]
        real(qp) :: apse_angle, dummy(2), v(3), psi, worst(3)
        integer :: i, k, side, best, status, solved, count
        call section('repulsive: psi within 1e-8 .. 1e-30 of the apse angle, both sides')
        worst = 0.0_qp
        solved = 0
        count = 0
        do i = 1, size(rhos)
            call curve_from_apse(rhos(i), curve, status)
            call repulsive_values(curve, rhos(i), .false., apse_angle, dummy(1), dummy(2), &
                                  status)
            do k = 1, size(offsets)
                do side = -1, 1, 2
                    count = count + 1
                    psi = apse_angle*(1.0_qp + real(side, qp)*offsets(k))
                    call solve_repulsive(rhos(i), psi, 0, sol, best, status, mirror=.false.)
                    if (status /= status_ok .or. sol(1)%status /= status_ok) cycle
                    if (sol(1)%arch /= merge(arch_second, arch_first, side == 1)) cycle
                    solved = solved + 1
                    call repulsive_values(sol(1)%curve, rhos(i), side == 1, v(1), v(2), &
                                          v(3), status)
                    worst(1) = max(worst(1), abs(v(1) - psi)/(eps_qp*psi))
                    worst(2) = max(worst(2), abs(sol(1)%arclength - v(2))/(eps_qp*v(2)))
                    worst(3) = max(worst(3), abs(sol(1)%time - v(3))/(eps_qp*v(3)))
                end do
            end do
        end do
        write (output_unit, '(a,i0,a,i0,a,3f7.2)') '   solved ', solved, ' of ', count, &
            ' on the right half-arch; worst |theta - psi|, s, t against adaptive (eps): ', &
            worst
        call check(solved == count, 'next to the apse angle: every endpoint solved')
        call check(worst(1) <= 8.0_qp, 'next to the apse angle: theta(rho; R-bar) = psi')
        call check(worst(2) <= 8.0_qp .and. worst(3) <= 8.0_qp, &
                   'next to the apse angle: s, t as the adaptive integrals')
    end subroutine next_to_the_apse_angle

    !> B next to the apse angle against mpmath on the original integrals
    !! (data/reference/repulsive_near_apse_mpmath.csv,
    !! scripts/make_repulsive_near_apse_reference.py: psi within 1e-8 .. 1e-30 of
    !! Theta(rho, rho), both half-arches, rho = 1 + 1e-20 .. 1.45): R, s, t to >= 33
    !! digits (R's conditioning credited as in test_field_references).
    subroutine next_to_the_apse_mpmath()
        type(csv_table) :: table
        type(repulsive_solution), allocatable :: sol(:)
        real(qp) :: rho, psi, digits(3), worst(3)
        integer :: i, best, status, solved
        logical :: ok
        call section('repulsive: next to the apse angle against mpmath (1e-8 .. 1e-30)')
        call read_reference('data/reference/repulsive_near_apse_mpmath.csv', 32, table, ok)
        if (.not. ok) return
        worst = 99.0_qp
        solved = 0
        do i = 1, table%row_count()
            rho = table%real_value(i, 'rho')
            psi = table%real_value(i, 'psi')
            call solve_repulsive(rho, psi, 0, sol, best, status, mirror=.false.)
            if (status /= status_ok .or. sol(1)%status /= status_ok) cycle
            if (sol(1)%arch /= merge(arch_second, arch_first, &
                                     table%text(i, 'arch') == 'second')) cycle
            solved = solved + 1
            digits = [digits_of_agreement(sol(1)%curve%apse, table%real_value(i, 'R')) + &
                      log10(max(1.0_qp, table%real_value(i, 'cond_R'))), &
                      digits_of_agreement(sol(1)%arclength, table%real_value(i, 's')), &
                      digits_of_agreement(sol(1)%time, table%real_value(i, 't'))]
            worst = min(worst, digits)
        end do
        write (output_unit, '(a,i0,a,i0,a,3f7.2)') '   solved ', solved, ' of ', &
            table%row_count(), '; fewest digits of R (credited), s, t: ', worst
        call check(solved == table%row_count(), 'next to the apse angle (mpmath): all solved')
        call check(minval(worst) >= 33.0_qp, 'next to the apse angle (mpmath): 33 digits')
    end subroutine next_to_the_apse_mpmath

    !> Each extra turn costs, asymptotically, the time of one turn round the circle
    !! r = 3/2 (where the angular speed v/r is largest): 2 pi r/v = 2 pi sqrt(27/8), and
    !! needs g smaller by exp(-2 pi sqrt3) (theta ~ -log(g)/sqrt3).
    subroutine winding_asymptotics()
        type(repulsive_solution), allocatable :: sol(:)
        real(qp) :: dt, ratio, turn_time, turn_ratio
        integer :: best, status, k
        call section('repulsive: windings, each turn ~ one turn round r = 3/2')
        turn_time = 2.0_qp*pi*sqrt(27.0_qp/8.0_qp)
        turn_ratio = exp(-2.0_qp*pi*sqrt(3.0_qp))
        call solve_repulsive(3.0_qp, 2.0_qp, 5, sol, best, status)
        call check(status == status_ok .and. all(sol%status == status_ok), &
                   'windings: m = 0..5 solved at rho = 3')
        write (output_unit, '(a)') '   rho = 3, psi = 2 anticlockwise: m, g, '// &
            't(m) - t(m-1) - 2 pi Kc, g(m)/g(m-1)/exp(-2 pi sqrt3) - 1'
        do k = 3, size(sol), 2
            dt = sol(k)%time - sol(k - 2)%time - turn_time
            ratio = sol(k)%curve%gap/sol(k - 2)%curve%gap/turn_ratio - 1.0_qp
            write (output_unit, '(a,i3,3es12.3)') '   ', sol(k)%winding, sol(k)%curve%gap, &
                dt, ratio
        end do
        ! both converge like O(g): at m = 5 (g ~ 3e-25) measured 6e-21 and 1e-19
        call check(abs(dt) < 1.0e-18_qp, 'windings: extra turn costs 2 pi sqrt(27/8)')
        call check(abs(ratio) < 1.0e-17_qp, 'windings: g shrinks by exp(-2 pi sqrt3) per turn')
        call check(best == 1, 'windings: least time on m = 0')
    end subroutine winding_asymptotics

    !> The constructors agree: K^2 = R^3/(2(R-1)) gives back the apse R; K^2 just above
    !! and below 27/8 gives the gap from 27/4 - 2K^2 = g (9 - 2g)^2/(4 (4 - g)).
    subroutine constructors()
        type(repulsive_curve) :: a, b
        real(qp) :: c, g
        integer :: status
        call section('repulsive: constructors')
        call curve_from_k2(3.90625_qp, a, status)
        call curve_from_apse(1.25_qp, b, status)
        call check(a%bounded .and. b%bounded, 'K^2 = 3.90625 is bounded')
        call check_close(a%apse, 1.25_qp, 8.0_qp, 'K^2 = 3.90625 has apse 5/4')
        call check_close(a%gap, b%gap, 16.0_qp, 'gap from K^2 = gap from R')
        call check_close(b%k2, 3.90625_qp, 4.0_qp, 'K^2 from R = 5/4')
        c = 2.0_qp**(-100)
        call curve_from_k2(critical_k2 - c, a, status)
        g = a%gap
        call check(.not. a%bounded, 'K^2 = 27/8 - 2^-100 is unbounded')
        call check_close(2.0_qp*c, g*(9.0_qp - 2.0_qp*g)**2/(4.0_qp*(4.0_qp - g)), 8.0_qp, &
                         'gap of K^2 = 27/8 - 2^-100 to full relative accuracy')
        call curve_from_k2(critical_k2 + c, a, status)
        call check(a%bounded .and. a%apse < 1.5_qp, 'K^2 = 27/8 + 2^-100 is bounded')
        call curve_from_apse_gap(1.0e-30_qp, b, status)
        call check_close(b%apse_gap, 1.0e-30_qp, 0.0_qp, 'apse gap 3 - 2R kept exactly')
        call curve_from_gap(-1.0_qp, a, status)
        call curve_from_apse(a%apse, b, status)
        call check_close(b%gap, -1.0_qp, 64.0_qp, 'R of g = -1 gives back g = -1')
        call curve_from_gap(4.0_qp, a, status)
        call check(status == status_invalid_argument, 'g > 3 rejected')
        call curve_from_apse(1.5_qp, a, status)
        call check(status == status_invalid_argument, 'R = 3/2 rejected (critical limit)')
    end subroutine constructors

    !> R -> 1: near A the field is uniform (|F| = 1), so the complete arch tends to the
    !! cycloid of depth R - 1 = 2a: angle 2 pi a = pi (R - 1), time 2 pi sqrt(a).
    !> Endpoints next to the start A with tiny angles (issue 11, "to the limits"; these
    !! ended `no_convergence` or took milliseconds): the critical curve's angle there
    !! (the closed form's two u-terms cancel, theta_c ~ 8 sqrt3 u^3) against its integral
    !! (23); half-arches with rho - 1 down to 1e-31 against the uniform-field cycloid
    !! (locally v^2 = 2 (r - 1): g = 1; x = a (phi - sin phi) = psi, y = a (1 - cos phi)
    !! = rho - 1, R - 1 = 2a, s = 4a (1 - cos(phi/2)), t = phi sqrt(a), to O(R - 1));
    !! unbounded curves next to the radial path against the small-K law
    !! theta = K sqrt2 (2/3) (1 - 1/rho)^(3/2) (1 + O(K^2)), Q = x^3 - 2 K^2 (x - 1).
    subroutine next_to_the_start()
        type(repulsive_curve) :: curve
        type(repulsive_solution), allocatable :: sol(:)
        real(qp), parameter :: dr(4) = [4.3875e-32_qp, 3.30148208668e-23_qp, &
                                        8.029800370179305e-19_qp, 7.04e-31_qp]
        real(qp), parameter :: psis(4) = [4.0589638370536996203140716389895000e-24_qp, &
            7.8342150555173075656052265948391088e-25_qp, &
            1.9225950920634088391076075198062893e-20_qp, 7.0e-26_qp]
        real(qp), parameter :: radii(3) = [1.001_qp, 2.0_qp, 1.0e4_qp]
        real(qp), parameter :: angles(3) = [1.0e-30_qp, 1.0e-60_qp, 1.0e-200_qp]
        real(qp) :: angle, length, time, closed, worst, rho, phi, a, k
        integer :: i, j, best, status, stat
        call section('repulsive: next to the start, tiny angles')
        worst = 0.0_qp
        call curve_from_gap(0.0_qp, curve, status)
        do j = 8, 112, 8
            rho = 1.0_qp + 2.0_qp**(-j)
            call repulsive_values(curve, rho, .false., angle, length, time, status)
            call critical_values(rho, closed, length, time, stat)
            call check(status == status_ok .and. stat == status_ok, 'critical: status ok')
            worst = max(worst, abs(closed - angle)/(eps_qp*angle))
        end do
        write (output_unit, '(a,f6.2)') '   critical theta_c = integral (23), r - 1 = '// &
            '2^-8 .. 2^-112, worst eps: ', worst
        call check(worst <= 8.0_qp, 'critical: theta_c next to the start to 8 eps')
        do i = 1, size(dr)
            rho = 1.0_qp + dr(i)
            call solve_repulsive(rho, psis(i), 0, sol, best, status, mirror=.false.)
            call check(status == status_ok .and. sol(1)%status == status_ok, &
                       'next to the start: solved')
            if (sol(1)%status /= status_ok) cycle
            call check(sol(1)%steps <= 30, 'next to the start: at most 30 evaluations')
            call check_close(sol(1)%angle, psis(i), 8.0_qp, 'next to the start: angle = psi')
            phi = cycloid_phase(psis(i)/(rho - 1.0_qp))
            a = (rho - 1.0_qp)/(2.0_qp*sin(0.5_qp*phi)**2)
            call check(sol(1)%arch == merge(arch_first, arch_second, phi < pi), &
                       'next to the start: the cycloid'//"'"//'s half-arch')
            call check_close(sol(1)%curve%apse_m1, 2.0_qp*a, 1.0e20_qp, &
                             'next to the start: R - 1 = cycloid to O(R - 1)')
            call check_close(sol(1)%arclength, 8.0_qp*a*sin(0.25_qp*phi)**2, 1.0e20_qp, &
                             'next to the start: s = cycloid to O(R - 1)')
            call check_close(sol(1)%time, phi*sqrt(a), 1.0e20_qp, &
                             'next to the start: t = cycloid to O(R - 1)')
        end do
        do i = 1, size(radii)
            do j = 1, size(angles)
                call solve_repulsive(radii(i), angles(j), 0, sol, best, status, &
                                     mirror=.false.)
                call check(status == status_ok .and. sol(1)%status == status_ok .and. &
                           sol(1)%arch == arch_unbounded, 'next to the radial path: solved')
                if (sol(1)%status /= status_ok) cycle
                call check(sol(1)%steps <= 20, 'next to the radial path: <= 20 evaluations')
                call check_close(sol(1)%angle, angles(j), 8.0_qp, &
                                 'next to the radial path: angle = psi')
                k = 3.0_qp*angles(j)/(2.0_qp*sqrt(2.0_qp)*((radii(i) - 1.0_qp)/radii(i))**1.5_qp)
                call check_close(sol(1)%curve%k, k, 8.0_qp, &
                                 'next to the radial path: K = small-K law')
            end do
        end do
    contains
        !> phi in (0, 2 pi) with (phi - sin phi)/(1 - cos phi) = ratio (increasing), by
        !! bisection.
        pure function cycloid_phase(ratio) result(phi)
            real(qp), intent(in) :: ratio
            real(qp) :: phi, lo, hi
            integer :: n
            lo = 0.0_qp
            hi = 2.0_qp*pi
            do n = 1, 200
                phi = 0.5_qp*(lo + hi)
                if ((phi - sin(phi))/(2.0_qp*sin(0.5_qp*phi)**2) < ratio) then
                    lo = phi
                else
                    hi = phi
                end if
            end do
        end function cycloid_phase
    end subroutine next_to_the_start

    subroutine cycloid_limit()
        type(repulsive_curve) :: curve
        real(qp) :: angle, length, time, a, worst_angle, worst_time
        integer :: j, status
        call section('repulsive: complete arch -> cycloid as R -> 1')
        do j = 20, 60, 20
            call curve_from_apse(1.0_qp + 2.0_qp**(-j), curve, status)
            call repulsive_values(curve, 1.0_qp, .true., angle, length, time, status)
            a = 0.5_qp*curve%apse_m1
            worst_angle = abs(angle/(2.0_qp*pi*a) - 1.0_qp)
            worst_time = abs(time/(2.0_qp*pi*sqrt(a)) - 1.0_qp)
            write (output_unit, '(a,i3,2es12.3)') '   R - 1 = 2^-j, j, relative deviations: ', &
                j, worst_angle, worst_time
            call check(status == status_ok .and. worst_angle < 4.0_qp*curve%apse_m1 .and. &
                       worst_time < 4.0_qp*curve%apse_m1, 'cycloid limit to O(R - 1)')
        end do
    end subroutine cycloid_limit

    subroutine bad_input()
        type(repulsive_solution), allocatable :: sol(:)
        integer :: best, status
        real(qp) :: nan
        call section('repulsive: bad endpoints')
        nan = ieee_value(nan, ieee_quiet_nan)
        call solve_repulsive(0.5_qp, 1.0_qp, 1, sol, best, status)
        call check(status == status_rho_below_start .and. size(sol) == 0 .and. best == 0, &
                   'rho < 1: rho_below_start')
        call solve_repulsive(nan, 1.0_qp, 1, sol, best, status)
        call check(status == status_not_finite, 'rho NaN: not_finite')
        call solve_repulsive(2.0_qp, nan, 1, sol, best, status)
        call check(status == status_not_finite, 'psi NaN: not_finite')
        call solve_repulsive(2.0_qp, 4.0_qp, 1, sol, best, status)
        call check(status == status_psi_out_of_range, 'psi > pi: psi_out_of_range')
        call solve_repulsive(2.0_qp, -0.5_qp, 1, sol, best, status)
        call check(status == status_psi_out_of_range, 'psi < 0: psi_out_of_range')
    end subroutine bad_input

end module test_repulsive
