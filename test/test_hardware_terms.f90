!> The speed laws' hardware-precision terms of the general engine's early phase
!! (`theta_terms_xp`: sqrt(q/(1 - q)) exp(shift), 1 - q, d(log q)/d Lambda) against their
!! closed forms evaluated in binary128 (power laws: q = exp(-(n+1) lambda) E(delta)/E(Lambda),
!! E(y) = 1 - exp(-(n-1) y); logarithmic: q = exp(-2 lambda) delta/Lambda), with and
!! without the scale exp(shift) given once per evaluation, hardware and rough; the same
!! for a panel's nodes (`panel_terms_xp`: g and d(log q)/d Lambda/(2 (1 - q))).
module test_hardware_terms
    use brachistochrone_kinds, only: qp, xp
    use brachistochrone_speed_laws, only: speed_law, power_law, logarithmic_law
    use brachistochrone_quad_math, only: expm1
    use testing, only: check, section
    implicit none
    private

    public :: run_hardware_terms_tests

contains

    subroutine run_hardware_terms_tests()
        real(qp), parameter :: exponents(7) = [1.000001_qp, 1.1_qp, 1.5_qp, 2.0_qp, 3.0_qp, &
                                               6.0_qp, 32.0_qp]
        integer :: k
        call section('hardware-precision terms of the early phase against closed forms')
        do k = 1, size(exponents)
            call check_law(power_law(n=exponents(k)), exponents(k) - 1.0_qp, .false.)
        end do
        call check_law(logarithmic_law(), 0.0_qp, .true.)
    end subroutine run_hardware_terms_tests

    !> Every combination of Lambda, lambda/Lambda, shift, exp(shift) given or not and
    !! rough or not: the largest error of each term over its tolerance (at most 1), the
    !! tolerance (8 + (n+1) Lambda + shift) roundings of the kind used (the exponentials'
    !! arguments carry their rounding).
    subroutine check_law(law, a, logarithmic)
        class(speed_law), intent(in) :: law
        real(qp), intent(in) :: a             !! n - 1 (power laws)
        logical, intent(in) :: logarithmic
        real(qp), parameter :: lambdas(6) = [0.01_qp, 0.3_qp, 2.0_qp, 11.0_qp, 40.0_qp, &
                                             300.0_qp]
        real(qp), parameter :: fractions(7) = [1.0e-6_qp, 0.01_qp, 0.3_qp, 0.5_qp, 0.9_qp, &
                                               0.999_qp, 0.999999_qp]
        real(qp), parameter :: shifts(2) = [0.0_qp, 37.5_qp]
        real(xp) :: c(5), big_x, lambda_x, delta_x, shift_x, g, omq, slope, g_p(1), h_p(1)
        real(qp) :: big, lambda, delta, q, omq_ref, g_ref, slope_ref, unit, worst(5)
        integer :: i, j, s, mode
        logical :: rough
        character(len=64) :: name
        worst = 0.0_qp
        do i = 1, size(lambdas)
            big_x = real(lambdas(i), xp)
            if (.not. logarithmic .and. (a + 2.0_qp)*lambdas(i) > 2000.0_qp) cycle
            c = law%apse_constants_xp(big_x)
            big = real(big_x, qp)
            do j = 1, size(fractions)
                lambda_x = real(big*fractions(j), xp)
                delta_x = big_x - lambda_x
                lambda = real(lambda_x, qp)
                delta = real(delta_x, qp)
                call reference(lambda, delta, big, q, omq_ref, slope_ref)
                do s = 1, size(shifts)
                    shift_x = real(shifts(s), xp)
                    g_ref = sqrt(q/omq_ref)*exp(real(shift_x, qp))
                    do mode = 1, 4
                        rough = mode > 2
                        if (mod(mode, 2) == 1) then
                            call law%theta_terms_xp(c, lambda_x, delta_x, shift_x, rough, &
                                                    g, omq, slope)
                            call law%panel_terms_xp(c, [lambda_x], [delta_x], shift_x, &
                                                    rough, 0.0_xp, g_p, h_p)
                        else
                            call law%theta_terms_xp(c, lambda_x, delta_x, shift_x, rough, &
                                                    g, omq, slope, exp(shift_x))
                            call law%panel_terms_xp(c, [lambda_x], [delta_x], shift_x, &
                                                    rough, exp(shift_x), g_p, h_p)
                        end if
                        unit = merge(2.0_qp**(-52), 2.0_qp**(-63), rough)* &
                               (8.0_qp + (a + 2.0_qp)*big + shifts(s))
                        worst(1) = max(worst(1), abs(real(g, qp)/g_ref - 1.0_qp)/unit)
                        worst(2) = max(worst(2), abs(real(omq, qp)/omq_ref - 1.0_qp)/unit)
                        worst(3) = max(worst(3), abs(real(slope, qp)/slope_ref - 1.0_qp)/unit)
                        worst(4) = max(worst(4), abs(real(g_p(1), qp)/g_ref - 1.0_qp)/unit)
                        worst(5) = max(worst(5), abs(real(h_p(1), qp)/ &
                                                     (0.5_qp*slope_ref/omq_ref) - 1.0_qp)/unit)
                    end do
                end do
            end do
        end do
        if (logarithmic) then
            name = 'logarithmic law'
        else
            write (name, '(a,f9.6)') 'power law n =', real(a + 1.0_qp)
        end if
        call check(all(worst(1:3) <= 1.0_qp), trim(name)//': g, 1 - q, d log q/d Lambda in xp')
        call check(all(worst(4:5) <= 1.0_qp), trim(name)//': panel g, h in xp')
        print '(3a,3f6.3)', '   ', trim(name), ': largest errors of g, 1 - q, slope / '// &
            'tolerance', worst(1:3)
        print '(3a,2f6.3)', '   ', trim(name), ': panel_terms_xp, largest errors of g, h / '// &
            'tolerance', worst(4:5)
    contains
        !> q, 1 - q and d(log q)/d Lambda at fixed lambda in binary128.
        subroutine reference(lambda, delta, big, q, omq, slope)
            real(qp), intent(in) :: lambda, delta, big
            real(qp), intent(out) :: q, omq, slope
            real(qp) :: e_lambda, e_delta, e_big
            if (logarithmic) then
                q = exp(-2.0_qp*lambda)*delta/big
                omq = -expm1(-2.0_qp*lambda) + exp(-2.0_qp*lambda)*lambda/big
                slope = lambda/(delta*big)
            else
                e_lambda = -expm1(-a*lambda)
                e_delta = -expm1(-a*delta)
                e_big = -expm1(-a*big)
                q = exp(-(a + 2.0_qp)*lambda)*e_delta/e_big
                omq = -expm1(-2.0_qp*lambda) + exp(-2.0_qp*lambda)*e_lambda/e_big
                slope = a*e_lambda*exp(-a*delta)/(e_big*e_delta)
            end if
        end subroutine reference
    end subroutine check_law

end module test_hardware_terms
