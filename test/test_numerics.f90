!> Quadrature and root finders against known integrals and roots.
module test_numerics
    use brachistochrone_kinds, only: qp, pi, eps_qp
    use brachistochrone_status, only: status_ok
    use brachistochrone_quadrature, only: gauss_legendre_rule, gauss_legendre, &
            computed_gauss_legendre, univariate_integrand, integrate, integrate_adaptive, &
            even_periodic_rule, even_periodic_trapezoid
    use brachistochrone_roots, only: root_function, newton_bracketed, secant
    use brachistochrone_chebyshev, only: chebyshev_table, chebyshev_points, chebyshev_fit
    use brachistochrone_summation, only: compensated_sum
    use brachistochrone_double_quad, only: double_quad_number, two_sum, two_product, &
                           operator(*), operator(/), operator(-)
    use reference_tables, only: csv_table, read_reference
    use testing, only: check, check_close, section
    use, intrinsic :: iso_fortran_env, only: output_unit
    implicit none
    private

    public :: run_numerics_tests

    !> x^k
    type, extends(univariate_integrand) :: power
        integer :: k = 0
    contains
        procedure :: evaluate => power_evaluate
    end type power

    !> 1/(1 + a x^2)
    type, extends(univariate_integrand) :: runge
        real(qp) :: a = 1.0_qp
    contains
        procedure :: evaluate => runge_evaluate
    end type runge

    !> exp(x)
    type, extends(univariate_integrand) :: exponential
    contains
        procedure :: evaluate => exponential_evaluate
    end type exponential

    !> x^3 - c
    type, extends(root_function) :: cubic
        real(qp) :: c = 2.0_qp
    contains
        procedure :: evaluate => cubic_evaluate
    end type cubic

contains

    pure function power_evaluate(self, x) result(y)
        class(power), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp) :: y
        y = x**self%k
    end function power_evaluate

    pure function runge_evaluate(self, x) result(y)
        class(runge), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp) :: y
        y = 1.0_qp/(1.0_qp + self%a*x*x)
    end function runge_evaluate

    pure function exponential_evaluate(self, x) result(y)
        class(exponential), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp) :: y
        y = exp(x)
    end function exponential_evaluate

    pure subroutine cubic_evaluate(self, x, f, df, status)
        class(cubic), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp), intent(out) :: f, df
        integer, intent(out) :: status
        f = x**3 - self%c
        df = 3.0_qp*x*x
        status = status_ok
    end subroutine cubic_evaluate

    subroutine run_numerics_tests()
        type(gauss_legendre_rule) :: rule
        type(even_periodic_rule) :: periodic
        type(power) :: monomial
        type(runge) :: bump
        type(exponential) :: e
        type(cubic) :: f
        real(qp) :: value, error, x, total, curvature
        integer :: k, status, steps
        character(len=40) :: name

        call section('numerics: Gauss-Legendre rule')
        rule = gauss_legendre(20)
        call check(rule%n == 20, 'rule has 20 nodes')
        call check(all(rule%node(2:) > rule%node(:19)), 'nodes ascending')
        call check_close(sum(rule%weight), 2.0_qp, 8.0_qp, 'weights sum to 2')
        ! exact for polynomials of degree <= 2n - 1: int_0^1 x^k = 1/(k+1)
        do k = 0, 39, 3
            monomial%k = k
            write (name, '(a,i0)') 'exact on [0,1] for x^', k
            call check_close(integrate(monomial, 0.0_qp, 1.0_qp, rule), &
                             1.0_qp/real(k + 1, qp), 16.0_qp, trim(name))
        end do
        rule = gauss_legendre(48)
        call check_close(integrate(e, 0.0_qp, 1.0_qp, rule), exp(1.0_qp) - 1.0_qp, &
                         8.0_qp, 'int_0^1 exp = e - 1 (48 nodes)')
        bump%a = 1.0_qp
        call check_close(integrate(bump, 0.0_qp, 1.0_qp, rule), pi/4.0_qp, 8.0_qp, &
                         'int_0^1 1/(1+x^2) = pi/4 (48 nodes)')
        rule = gauss_legendre(7)
        call check(abs(rule%node(4)) == 0.0_qp, 'odd rule has the node 0')
        call gauss_reference_tests()
        call gauss_table_tests()

        call section('numerics: adaptive Gauss-Legendre with error estimate')
        rule = gauss_legendre(16)
        bump%a = 2500.0_qp    ! Runge function with poles at +-i/50
        call integrate_adaptive(bump, -1.0_qp, 1.0_qp, rule, 1.0e-32_qp, 0.0_qp, value, &
                                error, status)
        call check(status == status_ok, 'adaptive converges')
        call check_close(value, 2.0_qp*atan(50.0_qp)/50.0_qp, 64.0_qp, &
                         'int 1/(1+2500x^2) = 2 atan(50)/50')
        call check(abs(value - 2.0_qp*atan(50.0_qp)/50.0_qp) <= max(error, 8*eps_qp*value), &
                   'error estimate bounds the true error')
        call check(error <= 1.0e-32_qp*value, 'error estimate within tolerance')

        call section('numerics: periodic trapezoid rule')
        ! int_0^pi d theta/(2 + cos theta) = pi/sqrt(3)
        periodic = even_periodic_trapezoid(40)
        total = 0.0_qp
        do k = 0, periodic%m
            total = total + periodic%weight(k)/(2.0_qp + cos(periodic%angle(k)))
        end do
        call check_close(total, pi/sqrt(3.0_qp), 16.0_qp, 'int d theta/(2+cos) = pi/sqrt 3')

        call section('numerics: root finders')
        f%c = 2.0_qp
        call newton_bracketed(f, 0.0_qp, -2.0_qp, 2.0_qp, 6.0_qp, 1.9_qp, 4.0_qp*eps_qp, &
                              0.0_qp, 100, x, steps, status)
        call check(status == status_ok, 'newton converges on x^3 = 2')
        call check_close(x, exp(log(2.0_qp)/3.0_qp), 8.0_qp, 'newton: cube root of 2')
        call check(steps < 20, 'newton: fewer than 20 steps from a poor start')
        ! the curvature it measures: |f''/(2 f')| = 1/x at the root of x^3 - 2
        curvature = 0.0_qp
        call newton_bracketed(f, 0.0_qp, -2.0_qp, 2.0_qp, 6.0_qp, 1.3_qp, 1.0e-16_qp, &
                              0.0_qp, 100, x, steps, status, curvature, 1.0e-30_qp)
        call check(curvature > 0.5_qp/x .and. curvature < 2.0_qp/x, &
                   'newton measures f''''/(2f'''') within a factor 2')
        call secant(f, 1.0_qp, 1.5_qp, 1.0e-30_qp, 0.0_qp, 2.0_qp, 100, x, steps, status)
        call check(status == status_ok, 'secant converges on x^3 = 2')
        call check_close(x, exp(log(2.0_qp)/3.0_qp), 8.0_qp, 'secant: cube root of 2')
        call secant(f, 1.0_qp, 1.0_qp, 1.0e-30_qp, 0.0_qp, 2.0_qp, 100, x, steps, status)
        call check(status /= status_ok, 'secant rejects equal estimates')

        call chebyshev_tests()
        call summation_tests()
        call double_quad_tests()
    end subroutine run_numerics_tests

    !> The tabulated rules (even n = 2..80, constants generated by mpmath) against the
    !! rules computed by Newton's method in quad (`computed_gauss_legendre`): every node
    !! and weight within 1 ulp, and the count of bit-identical values printed. Also the
    !! rules just outside the table (odd n, n = 82) come from the computation.
    subroutine gauss_table_tests()
        type(gauss_legendre_rule) :: table, computed
        integer :: n, identical, values, worst_n
        real(qp) :: worst, error
        character(len=60) :: name
        identical = 0
        values = 0
        worst = 0.0_qp
        worst_n = 0
        do n = 2, 80, 2
            table = gauss_legendre(n)
            computed = computed_gauss_legendre(n)
            write (name, '(a,i0,a)') 'Gauss-Legendre table n = ', n, ': within 1 ulp'
            if (table%n /= n .or. size(table%node) /= n .or. size(table%weight) /= n) then
                call check(.false., trim(name))
                cycle
            end if
            error = max(maxval(abs(table%node - computed%node)/spacing(computed%node)), &
                        maxval(abs(table%weight - computed%weight) &
                               /spacing(computed%weight)))
            call check(error <= 1.0_qp .and. all(table%node(2:) > table%node(:n - 1)), &
                       trim(name))
            if (error > worst) worst_n = n
            worst = max(worst, error)
            identical = identical + count(table%node == computed%node) &
                        + count(table%weight == computed%weight)
            values = values + 2*n
        end do
        write (output_unit, '(a,i0,a,i0,a,f5.2,a,i0,a)') '   tabulated rules: ', identical, &
            ' of ', values, ' values bit-identical to the quad Newton iteration; largest &
            &difference ', worst, ' ulp (n = ', worst_n, ')'
        table = gauss_legendre(7)
        computed = computed_gauss_legendre(7)
        call check(all(table%node == computed%node), 'odd n: the rule is computed')
        table = gauss_legendre(82)
        call check(table%n == 82 .and. abs(sum(table%weight) - 2.0_qp) <= 64.0_qp*eps_qp, &
                   'n = 82, beyond the table: the rule is computed')
    end subroutine gauss_table_tests

    !> The rules n = 2..48 and 96 against data/reference/gauss_legendre_mpmath.csv
    !! (mpmath at 80 digits, checked against Golub-Welsch; see the script's header): every
    !! node within 1 eps absolute, every weight within 2 eps relative, in both halves.
    !! The reference holds the nodes x_k >= 0, rounded to quad on reading (0.5 ulp), so
    !! a value that is the correct rounding of the exact one matches it exactly.
    subroutine gauss_reference_tests()
        integer, parameter :: largest = 96
        type(csv_table) :: table
        type(gauss_legendre_rule) :: rule
        logical :: ok
        integer :: i, n, k, mirror, rows(largest), exact, values
        real(qp) :: node, weight, node_error(largest), weight_error(largest)
        character(len=60) :: name

        call read_reference('data/reference/gauss_legendre_mpmath.csv', 600, table, ok)
        if (.not. ok) return
        rows = 0
        node_error = 0.0_qp
        weight_error = 0.0_qp
        exact = 0
        values = 0
        do i = 1, table%row_count()
            n = nint(table%real_value(i, 'n'))
            k = nint(table%real_value(i, 'k'))
            node = table%real_value(i, 'node')
            weight = table%real_value(i, 'weight')
            if (n < 1 .or. n > largest .or. k < 1 .or. k > (n + 1)/2) then
                call check(.false., 'Gauss-Legendre reference row in range: '//table%text(i, 'n'))
                cycle
            end if
            if (rule%n /= n) rule = gauss_legendre(n)
            rows(n) = rows(n) + 1
            mirror = n + 1 - k   ! reference node k = the k-th largest
            node_error(n) = max(node_error(n), abs(rule%node(mirror) - node), &
                                abs(rule%node(k) + node))
            weight_error(n) = max(weight_error(n), abs(rule%weight(mirror) - weight)/weight, &
                                  abs(rule%weight(k) - weight)/weight)
            exact = exact + count([rule%node(mirror), -rule%node(k)] == node) &
                    + count([rule%weight(mirror), rule%weight(k)] == weight)
            values = values + 4
        end do
        do n = 1, largest
            if (rows(n) == 0) cycle
            write (name, '(a,i0,a)') 'Gauss-Legendre n = ', n, ': reference has every node'
            call check(rows(n) == (n + 1)/2, trim(name))
            write (name, '(a,i0,a)') 'Gauss-Legendre n = ', n, ': nodes within 1 eps'
            call check(node_error(n) <= eps_qp, trim(name))
            write (name, '(a,i0,a)') 'Gauss-Legendre n = ', n, ': weights within 2 eps'
            call check(weight_error(n) <= 2.0_qp*eps_qp, trim(name))
        end do
        write (output_unit, '(a,i0,a,2f9.3,a,i0,a,i0)') '   ', count(rows > 0), &
            ' rules; largest node, weight error in eps:', maxval(node_error)/eps_qp, &
            maxval(weight_error)/eps_qp, '; equal to the rounded reference: ', exact, &
            ' of ', values
    end subroutine gauss_reference_tests

    !> The error-free transformations and double-quad operations on cases whose exact
    !! results are known by hand.
    subroutine double_quad_tests()
        type(double_quad_number) :: exact_product, exact_sum, one, third, square, residual
        real(qp) :: tiny_part

        call section('numerics: double-quad arithmetic')
        tiny_part = 2.0_qp**(-120)
        exact_sum = two_sum(1.0_qp, tiny_part)
        call check(exact_sum%hi == 1.0_qp .and. exact_sum%lo == tiny_part, &
                   'two_sum: 1 + 2^-120 exactly')
        ! (2^56 + 1)(2^57 + 1) = 2^113 + 2^57 + 2^56 + 1: a tie at the spacing 2 of quad
        ! there, rounded to the even 2^113 + 2^57 + 2^56, leaving 1
        exact_product = two_product(2.0_qp**56 + 1.0_qp, 2.0_qp**57 + 1.0_qp)
        call check(exact_product%hi == 2.0_qp**113 + 2.0_qp**57 + 2.0_qp**56 .and. &
                   exact_product%lo == 1.0_qp, 'two_product: (2^56 + 1)(2^57 + 1) exactly')
        ! (1 + 2^-60)^2 = 1 + 2^-59 + 2^-120
        exact_product = two_product(1.0_qp + 2.0_qp**(-60), 1.0_qp + 2.0_qp**(-60))
        call check(exact_product%hi == 1.0_qp + 2.0_qp**(-59) .and. &
                   exact_product%lo == tiny_part, 'two_product: (1 + 2^-60)^2 exactly')
        ! 1/3 to double-quad precision: 3 (1/3) - 1 and (1/3)^2/(1/3) - 1/3 at rounding level
        one = double_quad_number(1.0_qp, 0.0_qp)
        third = one/3
        residual = third*3 - one
        call check(abs(residual%hi) <= 4.0_qp*eps_qp**2, 'double-quad: 3 (1/3) = 1 to 4 eps^2')
        square = third*third
        residual = square/third - third
        call check(abs(residual%hi) <= 4.0_qp*eps_qp**2*third%hi, &
                   'double-quad: (1/3)^2/(1/3) = 1/3 to 4 eps^2')
        call check(abs(third%lo) > 0.0_qp .and. abs(third%lo) <= 0.5_qp*spacing(third%hi), &
                   'double-quad: 1/3 has a trailing part below half an ulp')
    end subroutine double_quad_tests

    !> Piecewise Chebyshev interpolation of 1/(x + 2) on [-1, 1]: values and slopes
    !! against the closed forms, the noise cut and the truncation to a tolerance.
    subroutine chebyshev_tests()
        real(qp) :: points(32, 8), x, value, slope, worst_value, worst_slope
        type(chebyshev_table) :: table
        integer :: k

        call section('numerics: piecewise Chebyshev interpolation')
        points = chebyshev_points(-1.0_qp, 1.0_qp, 8, 32)
        call check(all(points(:, 1) > -1.0_qp .and. points(:, 1) < -0.75_qp) .and. &
                   all(points(:, 8) > 0.75_qp .and. points(:, 8) < 1.0_qp), &
                   'points lie inside their pieces')
        table = chebyshev_fit(-1.0_qp, 1.0_qp, 1.0_qp/(points + 2.0_qp), 4.0_qp*eps_qp)
        ! pole at -2: Bernstein radius 9 + sqrt 80 on the first piece (27 terms for 34
        ! digits), larger on the others
        call check(all(table%used < 32) .and. all(table%used > 10), &
                   'noise cut keeps 11-31 of 32 terms per piece')
        print '(a,8i3)', '   terms per piece', table%used
        worst_value = 0.0_qp
        worst_slope = 0.0_qp
        do k = 0, 400
            x = -1.0_qp + real(k, qp)/200.0_qp
            call table%evaluate(x, value, slope)
            worst_value = max(worst_value, abs(value*(x + 2.0_qp) - 1.0_qp))
            worst_slope = max(worst_slope, abs(slope + 1.0_qp/(x + 2.0_qp)**2))
        end do
        print '(a,2es10.2)', '   worst relative value, absolute slope error in eps', &
            worst_value/eps_qp, worst_slope/eps_qp
        ! the interpolant carries the rounding of the values, coefficients and Clenshaw
        ! sum (a few eps); its derivative carries that noise times at most
        ! (terms - 1)^2 (2/width) by Markov's inequality
        call check(worst_value <= 8.0_qp*eps_qp, '1/(x+2): values within 8 eps on 401 points')
        call check(worst_slope <= 8.0_qp*eps_qp*real(maxval(table%used) - 1, qp)**2*8.0_qp, &
                   '1/(x+2): slopes within Markov''s bound on 8 eps of noise')
        call table%evaluate(0.3_qp, value, slope, 1.0e-12_qp)
        call check(abs(value - 1.0_qp/2.3_qp) <= 1.0e-12_qp .and. &
                   abs(value - 1.0_qp/2.3_qp) > 1.0e-30_qp, &
                   'a tolerance of 1e-12 drops terms and keeps the error below it')
    end subroutine chebyshev_tests

    !> Compensated summation recovers what plain summation rounds away.
    subroutine summation_tests()
        type(compensated_sum) :: sum
        real(qp) :: plain, x
        integer :: k

        call section('numerics: compensated summation')
        sum = compensated_sum()
        call sum%add(1.0_qp)
        call sum%add(1.0e-40_qp)
        call sum%add(-1.0_qp)
        call check(sum%value() == 1.0e-40_qp, '1 + 1e-40 - 1 = 1e-40 exactly')
        ! 10^5 copies of 0.1: the exact sum is 10^5 x, one rounding away from 1e5*x
        x = 0.1_qp
        sum = compensated_sum()
        plain = 0.0_qp
        do k = 1, 100000
            call sum%add(x)
            plain = plain + x
        end do
        call check(abs(sum%value() - 1.0e5_qp*x) <= spacing(1.0e4_qp), &
                   'sum of 1e5 copies of 0.1 within one rounding')
        call check(abs(plain - 1.0e5_qp*x) > 8.0_qp*spacing(1.0e4_qp), &
                   'the plain sum is off by more (the test can fail)')
    end subroutine summation_tests

end module test_numerics
