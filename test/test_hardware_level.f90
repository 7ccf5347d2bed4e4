!> The inverse-square kernel in hardware precision (level_hardware) against the full
!! quad-precision rules, and the solver's use of it.
module test_hardware_level
    use brachistochrone_kinds, only: qp, xp
    use brachistochrone_fast_math, only: hardware_real
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf, ieee_quiet_nan, &
                                             ieee_is_nan
    use brachistochrone_inverse_square, only: inverse_square_model, new_inverse_square_model, &
        evaluate_arch, arch_values, level_fine, level_hardware, level_final, &
        hardware_epsilon, apse_estimate_error
    use brachistochrone_two_point, only: solve_endpoint
    use brachistochrone_solution, only: endpoint_solution
    use testing, only: check, section
    implicit none
    private

    public :: run_hardware_level_tests

contains

    subroutine run_hardware_level_tests()
        type(inverse_square_model) :: model
        type(arch_values) :: hard, fine
        type(endpoint_solution) :: solution
        real(qp) :: rho, big_r, d, worst_angle, worst_slope, slope_hard, slope_fine
        integer :: i, j, half
        logical :: second
        call section('hardware level: 19-digit rules in hardware precision')
        model = new_inverse_square_model()
        worst_angle = 0.0_qp
        worst_slope = 0.0_qp
        do half = 0, 1
            second = half == 1
            do i = 1, 12
                rho = 1.0_qp - 0.999_qp*(real(i - 1, qp)/11.0_qp)**2
                do j = 0, 10
                    ! R from 1e-10 rho to the apse (d from rho down to 1e-30 rho)
                    d = rho*10.0_qp**(-3*j)
                    if (j == 0) d = rho*(1.0_qp - 1.0e-10_qp)
                    big_r = rho - d
                    hard = evaluate_arch(model, level_hardware, second, rho, big_r, d, &
                                         .true., .false.)
                    fine = evaluate_arch(model, level_fine, second, rho, big_r, d, &
                                         .true., .false.)
                    worst_angle = max(worst_angle, abs(hard%angle - fine%angle) &
                                                   /max(abs(fine%angle), 1.0e-3_qp))
                    slope_hard = hard%angle_dr_smooth + hard%boundary_sign*hard%boundary
                    slope_fine = fine%angle_dr_smooth + fine%boundary_sign*fine%boundary
                    worst_slope = max(worst_slope, abs(slope_hard - slope_fine) &
                                                   /max(abs(slope_fine), 1.0_qp))
                end do
            end do
        end do
        print '(a,2es10.2)', '   worst relative difference from the full rules: angle, '// &
            'slope', worst_angle, worst_slope
        call check(worst_angle <= 100.0_qp*hardware_epsilon + 1.0e-18_qp, &
                   'hardware level: angle to 100 roundings of the hardware kind')
        call check(worst_slope <= 1.0e4_qp*hardware_epsilon + 1.0e-16_qp, &
                   'hardware level: d(angle)/dR to 1e4 roundings of the hardware kind')
        call final_level_tests(model)
        ! R, r - R or 1 - r below the hardware range: the quad rules take over
        hard = evaluate_arch(model, level_hardware, .false., 0.5_qp, 1.0e-300_qp, &
                             0.5_qp - 1.0e-300_qp, .true., .false.)
        fine = evaluate_arch(model, level_fine, .false., 0.5_qp, 1.0e-300_qp, &
                             0.5_qp - 1.0e-300_qp, .true., .false.)
        call check(abs(hard%angle - fine%angle) <= 1.0e-16_qp*fine%angle .and. &
                   fine%angle > 0.0_qp, 'hardware level: R = 1e-300 falls back to quad rules')
        ! the solver: a tiny R-bar (first half-arch, psi = 1e-300) still solves
        solution = solve_endpoint(model, 0.5_qp, 1.0e-300_qp)
        call check(solution%has_apse_radius .and. solution%apse_radius > 0.0_qp .and. &
                   solution%apse_radius < 1.0e-150_qp, 'hardware level: psi = 1e-300 solved')
        call conversion_tests()
        call apse_estimate_tests(model)
    end subroutine run_hardware_level_tests

    !> level_final: the values bit for bit those of level_fine, the slopes within their
    !! stated error bounds (and those bounds small).
    subroutine final_level_tests(model)
        type(inverse_square_model), intent(in) :: model
        type(arch_values) :: fine, final
        real(qp) :: rho, big_r, worst_ratio, worst_bound
        integer :: i, j, half
        logical :: same_values
        same_values = .true.
        worst_ratio = 0.0_qp
        worst_bound = 0.0_qp
        do half = 0, 1
            do i = 1, 8
                rho = 1.0_qp - 0.99_qp*real(i - 1, qp)/7.0_qp
                do j = 1, 9
                    big_r = rho*real(j, qp)/10.0_qp
                    fine = evaluate_arch(model, level_fine, half == 1, rho, big_r, &
                                         rho - big_r, .true., .true.)
                    final = evaluate_arch(model, level_final, half == 1, rho, big_r, &
                                          rho - big_r, .true., .true.)
                    same_values = same_values .and. fine%angle == final%angle .and. &
                                  fine%arclength == final%arclength .and. &
                                  fine%time == final%time .and. &
                                  fine%boundary == final%boundary
                    worst_ratio = max(worst_ratio, &
                        abs(final%angle_dr_smooth - fine%angle_dr_smooth) &
                        /max(final%angle_dr_error, tiny(1.0_qp)), &
                        abs(final%arclength_dr_smooth - fine%arclength_dr_smooth) &
                        /max(final%arclength_dr_error, tiny(1.0_qp)))
                    worst_bound = max(worst_bound, final%angle_dr_error &
                        /abs(final%angle_dr_smooth), final%arclength_dr_error &
                        /max(abs(final%arclength_dr_smooth), 1.0_qp))
                end do
            end do
        end do
        print '(a,es10.2,a,es10.2)', '   level_final: slope error / its bound at most', &
            worst_ratio, '; bounds at most', worst_bound
        call check(same_values, 'level_final: angle, s, t as level_fine, bit for bit')
        call check(worst_ratio <= 1.0_qp, 'level_final: slopes within their error bounds')
        call check(worst_bound <= 1.0e-15_qp, 'level_final: slope error bounds below 1e-15')
    end subroutine final_level_tests

    !> hardware_real (binary128 to x87 extended on the bits) against gfortran's own
    !! conversion real(x, xp): the same bits on random values of every binade, the
    !! rounding ties (both parities), just below and above them, significands of all
    !! ones (carry into the exponent), zeros, subnormals, extremes, infinities and NaN.
    subroutine conversion_tests()
        integer(int64), parameter :: half = ishft(1_int64, 48), low49 = ishft(1_int64, 49) - 1
        real(qp) :: x, specials(10)
        real(xp) :: fast, library
        real(qp) :: u(3)
        integer(int64) :: bits(2)
        integer :: i, mismatches
        call section('hardware level: binary128 to hardware precision on the bits')
        mismatches = 0
        do i = 1, 200000
            call random_number(u)
            x = (1.0_qp + u(1))*2.0_qp**int(32760.0_qp*(u(2) - 0.5_qp))
            if (u(3) < 0.3_qp) x = -x
            bits = transfer(x, bits)
            select case (mod(i, 6))
            case (1) ! a tie, the kept last bit odd or even by the draw
                bits(1) = ior(iand(bits(1), not(low49)), half)
            case (2) ! one below a tie
                bits(1) = ior(iand(bits(1), not(low49)), half - 1_int64)
            case (3) ! one above a tie
                bits(1) = ior(iand(bits(1), not(low49)), half + 1_int64)
            case (4) ! all ones: rounds up into the next binade
                bits(1) = -1_int64
                bits(2) = ior(bits(2), ishft(1_int64, 48) - 1_int64)
            end select
            x = transfer(bits, x)
            fast = hardware_real(x)
            library = real(x, xp)
            if (.not. same_bits(fast, library)) mismatches = mismatches + 1
        end do
        call check(mismatches == 0, 'hardware_real = real(x, xp) on 200000 values')
        specials = [0.0_qp, -0.0_qp, tiny(1.0_qp), tiny(1.0_qp)/3.0_qp, -tiny(1.0_qp)/7.0_qp, &
                    huge(1.0_qp), -huge(1.0_qp), ieee_value(1.0_qp, ieee_positive_inf), &
                    1.0_qp + epsilon(1.0_qp), 1.0_qp/3.0_qp]
        mismatches = 0
        do i = 1, size(specials)
            if (.not. same_bits(hardware_real(specials(i)), real(specials(i), xp))) &
                mismatches = mismatches + 1
        end do
        call check(mismatches == 0, 'hardware_real = real(x, xp): zeros, subnormals, extremes')
        call check(ieee_is_nan(hardware_real(ieee_value(1.0_qp, ieee_quiet_nan))), &
                   'hardware_real(NaN) is NaN')
    end subroutine conversion_tests

    !> apse_angle_estimate (hardware table) against apse_angle (the full table, itself
    !! checked against the references) from R = 1e-300 to 1 - 1e-30.
    subroutine apse_estimate_tests(model)
        type(inverse_square_model), intent(in) :: model
        real(qp) :: big_r, exact, worst
        integer :: i, status
        worst = 0.0_qp
        do i = 0, 400
            if (i <= 100) then
                big_r = 10.0_qp**(-3*i)
            else if (i <= 300) then
                big_r = real(i - 100, qp)/201.0_qp
            else
                big_r = 1.0_qp - 10.0_qp**(-0.3_qp*real(i - 300, qp))
            end if
            call model%apse_angle(big_r, exact, status)
            if (exact > 0.0_qp) worst = max(worst, &
                abs(model%apse_angle_estimate(big_r) - exact)/exact)
        end do
        call check(worst <= apse_estimate_error, &
                   'apse_angle_estimate within its documented relative error')
        call check(worst <= 100.0_qp*hardware_epsilon, &
                   'apse_angle_estimate within 100 roundings of the hardware kind')
    end subroutine apse_estimate_tests

    !> a and b have the same value and sign (zeros by sign, infinities equal).
    pure logical function same_bits(a, b)
        real(xp), intent(in) :: a, b
        same_bits = (a == b .and. sign(1.0_xp, a) == sign(1.0_xp, b))
    end function same_bits

end module test_hardware_level
