!> The field interface: every field made by name, solving through one interface, against
!! independent values (Tee's Table 1, Saitoh's closed forms, the radial fall, the
!! repulsive field's own windings), and the statuses of bad names and exponents.
module test_fields
    use, intrinsic :: iso_fortran_env, only: output_unit
    use brachistochrone, only: qp, pi, eps_qp, brachistochrone_field, new_field, &
            endpoint_solution, curve_samples, repulsive_solution, solve_repulsive, &
            repulsive_radial_time, radial_time, kappa_time, status_ok, status_inaccessible, &
            status_unknown_field, status_bad_exponent, status_not_supported, &
            status_rho_below_start, status_rho_out_of_range, status_not_finite, &
            status_above_start, &
            arch_first, arch_second, arch_complete, arch_radial, arch_unbounded, &
            arch_inaccessible, status_word, arch_word
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    use testing, only: check, check_close, check_digits, section
    implicit none
    private

    public :: run_field_tests

    character(len=*), parameter :: names(6) = [character(len=14) :: 'inverse_square', &
        'power', 'logarithmic', 'harmonic', 'repulsive', 'uniform']

contains

    subroutine run_field_tests()
        call factory()
        call inverse_square_table1()
        call harmonic_closed_forms()
        call repulsive_least_time()
        call uniform_cycloids()
        call what_fields_support()
    end subroutine run_field_tests

    !> Every name makes its field; bad names and exponents are statuses, not crashes.
    subroutine factory()
        class(brachistochrone_field), allocatable :: field
        type(endpoint_solution) :: b
        integer :: k, status
        call section('fields: made by name')
        do k = 1, size(names)
            call new_field(trim(names(k)), 3.0_qp, field, status)
            call check(status == status_ok, 'new_field '''//trim(names(k))//''': ok')
            call check(field%name() == trim(names(k)), trim(names(k))//': name round trip')
            call check(len(field%description()) > 0 .and. len(field%region()) > 0 .and. &
                       len(field%units()) > 0, trim(names(k))//': described')
            call check((field%exponent() == 3.0_qp) .eqv. (names(k) == 'power'), &
                       trim(names(k))//': exponent only for the power law')
        end do
        call new_field('gravity', 0.0_qp, field, status)
        call check(status == status_unknown_field .and. allocated(field), &
                   'unknown name: status_unknown_field, field still defined')
        call new_field('power', 1.0_qp, field, status)
        call check(status == status_bad_exponent, 'power, n = 1: status_bad_exponent')
        call new_field('power', ieee_value(1.0_qp, ieee_quiet_nan), field, status)
        call check(status == status_bad_exponent, 'power, n = NaN: status_bad_exponent')
        b = field%solve(0.5_qp, 1.0_qp)
        call check(b%status == status_ok, 'power with a refused exponent still solves (n = 2)')
    end subroutine factory

    !> Tee's Table 1 (rows 1-2 as corrected in docs/ERRATA.md) through the interface:
    !! the default solver and the paper's secant method give the printed digits.
    subroutine inverse_square_table1()
        real(qp), parameter :: rho(5) = [0.2_qp, 0.5_qp, 0.7_qp, 0.9_qp, 1.0_qp]
        real(qp), parameter :: psi(5) = [1.2_qp, 0.1_qp, 1.8_qp, 0.4_qp, 2.0_qp]
        real(qp), parameter :: r0(5) = [0.2_qp, 0.4_qp, 0.6_qp, 0.8_qp, 0.2_qp]
        real(qp), parameter :: r1(5) = [0.1_qp, 0.2_qp, 0.5_qp, 0.7_qp, 0.1_qp]
        real(qp), parameter :: printed_r(5) = [0.184781963328079_qp, 0.252787093630160_qp, &
            0.168913316595188_qp, 0.838545794202334_qp, 0.057854464393370_qp]
        real(qp), parameter :: printed_t(5) = [1.127755808164997_qp, 0.914164272619962_qp, &
            1.481218910277573_qp, 1.058599268341289_qp, 2.221060707125763_qp]
        class(brachistochrone_field), allocatable :: field
        type(endpoint_solution) :: b, c
        integer :: i, status
        call section('fields: inverse square, Tee''s Table 1 through the interface')
        call new_field('inverse_square', 0.0_qp, field, status)
        do i = 1, 5
            b = field%solve(rho(i), psi(i))
            c = field%solve_from_estimates(rho(i), psi(i), r0(i), r1(i), 1.0e-16_qp)
            call check(b%status == status_ok .and. c%status == status_ok, 'row solved')
            call check(abs(b%apse_radius - printed_r(i)) <= 5.0e-16_qp .and. &
                       abs(b%time - printed_t(i)) <= 5.0e-16_qp, &
                       'default solver: R-bar and t to the 15 printed decimals')
            call check(abs(c%apse_radius - printed_r(i)) <= 5.0e-16_qp, &
                       'secant from the paper''s estimates: R-bar as printed')
        end do
        b = field%solve(0.5_qp, 2.5_qp)
        call check(b%status == status_inaccessible .and. b%arch == arch_inaccessible .and. &
                   .not. b%has_apse_radius, 'psi >= 2 pi/3: inaccessible, no R-bar')
        call check_close(b%time, kappa_time(0.5_qp), 0.0_qp, 'inaccessible: t = kappa(rho)')
        b = field%solve(0.0_qp, 1.0_qp)
        call check(b%status == status_rho_out_of_range, 'rho = 0: status_rho_out_of_range')
    end subroutine inverse_square_table1

    !> Saitoh: surface to surface R = 1 - psi/pi, s = 2(1 - R^2), t = pi sqrt(1 - R^2);
    !! psi = 0 the radial fall (t = acos(rho), s = 1 - rho).
    subroutine harmonic_closed_forms()
        real(qp), parameter :: angles(4) = [1.0e-6_qp, 0.1_qp, 1.0_qp, 3.0_qp]
        class(brachistochrone_field), allocatable :: field
        type(endpoint_solution) :: b
        real(qp) :: big_r, depth
        integer :: k, status
        call section('fields: harmonic through Saitoh''s closed forms')
        call new_field('harmonic', 0.0_qp, field, status)
        do k = 1, size(angles)
            b = field%solve(1.0_qp, angles(k))
            big_r = 1.0_qp - angles(k)/pi
            call check(b%status == status_ok .and. b%arch == arch_complete, &
                       'rho = 1: a complete tunnel')
            call check_digits(b%apse_radius, big_r, 33.0_qp, 'rho = 1: R = 1 - psi/pi')
            ! 1 - R^2 = d (2 - d) with the depth d = psi/pi, free of cancellation
            depth = angles(k)/pi
            call check_digits(b%arclength, 2.0_qp*depth*(2.0_qp - depth), 32.0_qp, &
                              'rho = 1: s = 2(1 - R^2)')
            call check_digits(b%time, pi*sqrt(depth*(2.0_qp - depth)), 32.0_qp, &
                              'rho = 1: t = pi sqrt(1 - R^2)')
        end do
        b = field%solve(0.5_qp, 0.0_qp)
        call check(b%arch == arch_radial, 'psi = 0: radial')
        call check_digits(b%time, acos(0.5_qp), 33.0_qp, 'psi = 0: t = acos(rho)')
        call check_digits(b%arclength, 0.5_qp, 33.0_qp, 'psi = 0: s = 1 - rho')
    end subroutine harmonic_closed_forms

    !> The least-time curve is the one of least time among all windings and senses
    !! (`solve_repulsive`), with the arch words of the shared set.
    subroutine repulsive_least_time()
        real(qp), parameter :: rhos(4) = [1.0_qp, 1.25_qp, 2.0_qp, 5.0_qp]
        real(qp), parameter :: psis(3) = [0.4_qp, 1.0_qp, 3.0_qp]
        class(brachistochrone_field), allocatable :: field
        type(endpoint_solution) :: b
        type(repulsive_solution), allocatable :: all(:)
        integer :: i, j, best, status
        call section('fields: repulsive, the least-time curve')
        call new_field('repulsive', 0.0_qp, field, status)
        do i = 1, size(rhos)
            do j = 1, size(psis)
                b = field%solve(rhos(i), psis(j))
                call solve_repulsive(rhos(i), psis(j), 2, all, best, status)
                call check(b%status == status_ok .and. best > 0, 'solved')
                call check(b%time == minval(all%time, all%status == status_ok), &
                           'least time of all windings and senses')
                call check(b%has_apse_radius .neqv. b%arch == arch_unbounded, &
                           'R-bar exactly for bounded curves')
                call check(any(b%arch == [arch_first, arch_second, arch_complete, &
                                          arch_unbounded]), 'arch '//arch_word(b%arch))
                call check((b%arch == arch_complete) .eqv. (rhos(i) == 1.0_qp), &
                           'complete exactly at rho = 1')
            end do
        end do
        b = field%solve(3.0_qp, 0.0_qp)
        call check(b%arch == arch_radial, 'psi = 0: radial')
        call check_close(b%time, repulsive_radial_time(3.0_qp), 4.0_qp, &
                         'psi = 0: the radial time in closed form')
        ! next to the start, rho = 1 + 2^-112: a near-complete arch, locally the uniform
        ! field's cycloid: angle pi (R - 1) (Tee sec. 6), so R - 1 ~ psi/pi
        b = field%solve(nearest(1.0_qp, 2.0_qp), 1.0e-30_qp)
        call check(b%status == status_ok .and. b%arch == arch_second, &
                   'rho = 1 + 2^-112, psi = 1e-30: solved')
        call check(abs((b%apse_radius - 1.0_qp)*pi/1.0e-30_qp - 1.0_qp) < 0.1_qp, &
                   'rho = 1 + 2^-112: R - 1 close to psi/pi (the cycloid limit)')
        b = field%solve(nearest(1.0_qp, 2.0_qp), 3.0_qp)
        call check(b%status == status_ok, 'rho = 1 + 2^-112, psi = 3: solved')
        b = field%solve(0.5_qp, 1.0_qp)
        call check(b%status == status_rho_below_start, 'rho < 1: status_rho_below_start')
        b = field%solve(ieee_value(1.0_qp, ieee_quiet_nan), 1.0_qp)
        call check(b%status == status_not_finite, 'rho = NaN: status_not_finite')
    end subroutine repulsive_least_time

    !> Uniform gravity (g = 1): the cycloid x = a (phi - sin phi), y = a (1 - cos phi)
    !! with t = phi sqrt(a), s = 8 a sin^2(phi/4): its lowest point (pi a, 2a), the
    !! complete arch (2 pi a, 0), free fall (0, y): t = sqrt(2y).
    subroutine uniform_cycloids()
        class(brachistochrone_field), allocatable :: field
        type(endpoint_solution) :: b
        integer :: status
        call section('fields: uniform gravity, the cycloid through B = (x, y)')
        call new_field('uniform', 0.0_qp, field, status)
        call check(field%coordinate(1) == 'x' .and. field%coordinate(2) == 'y', &
                   'coordinates named x, y')
        b = field%solve(3.0_qp*pi, 6.0_qp)
        call check(b%status == status_ok .and. any(b%arch == [arch_first, arch_second]), &
                   'lowest point of a = 3: solved')
        call check_close(b%apse_radius, 3.0_qp, 4.0_qp, 'lowest point: a = 3')
        call check_close(b%time, pi*sqrt(3.0_qp), 4.0_qp, 'lowest point: t = pi sqrt(a)')
        call check_close(b%arclength, 12.0_qp, 4.0_qp, 'lowest point: s = 4 a')
        b = field%solve(2.0_qp*pi, 0.0_qp)
        call check(b%arch == arch_complete, 'level with A: the complete arch')
        call check_close(b%apse_radius, 1.0_qp, 4.0_qp, 'complete arch: a = x/(2 pi)')
        call check_close(b%time, 2.0_qp*pi, 4.0_qp, 'complete arch: t = 2 pi sqrt(a)')
        call check_close(b%arclength, 8.0_qp, 4.0_qp, 'complete arch: s = 8 a')
        b = field%solve(0.0_qp, 0.5_qp)
        call check(b%arch == arch_radial, 'x = 0: free fall')
        call check_close(b%time, 1.0_qp, 2.0_qp, 'free fall from y = 1/2: t = sqrt(2y) = 1')
        b = field%solve(1.0_qp, -1.0_qp)
        call check(b%status == status_above_start, 'y < 0: status_above_start')
    end subroutine uniform_cycloids

    !> Curves are sampled by the inverse-square field; the others say they cannot.
    subroutine what_fields_support()
        class(brachistochrone_field), allocatable :: field
        type(endpoint_solution) :: b
        type(curve_samples) :: c
        integer :: k, status
        call section('fields: curves and estimates')
        do k = 1, size(names)
            call new_field(trim(names(k)), 3.0_qp, field, status)
            b = field%solve(merge(2.0_qp, 0.5_qp, names(k) == 'repulsive'), 0.3_qp)
            if (names(k) == 'uniform') cycle
            c = field%sample_curve(b, 11)
            if (names(k) == 'inverse_square') then
                call check(c%n == 11 .and. c%status == status_ok, 'inverse square: 11 points')
                call check_close(c%r(11), 0.5_qp, 0.0_qp, 'inverse square: the curve ends at B')
            else
                call check(c%n == 0 .and. c%status == status_not_supported, &
                           trim(names(k))//': no curve, '//status_word(c%status))
                b = field%solve_from_estimates(0.5_qp, 0.3_qp, 0.2_qp, 0.1_qp, 1.0e-16_qp)
                call check(b%status == status_not_supported, &
                           trim(names(k))//': estimates not supported')
            end if
        end do
    end subroutine what_fields_support

end module test_fields
