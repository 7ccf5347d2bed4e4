!> fast_sqrt and inverse_sqrt against the intrinsic sqrt over the whole exponent range, and
!! the conversions on the bits (quad_real, hardware_real) against gfortran's own
!! real(y, qp) and real(x, xp), bit for bit, on every class of value.
module test_fast_math
    use brachistochrone_kinds, only: qp, xp
    use brachistochrone_fast_math, only: fast_sqrt, inverse_sqrt, quad_real, hardware_real, &
                                         double_real, hardware_arithmetic_ok
    use, intrinsic :: iso_fortran_env, only: int64, int16, real64
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf, ieee_quiet_nan, &
                                             ieee_negative_inf, ieee_signaling_nan, &
                                             ieee_is_nan
    use testing, only: check, section
    implicit none
    private

    public :: run_fast_math_tests

    integer, parameter :: samples = 200000

contains

    subroutine run_fast_math_tests()
        call section('fast_math: square roots against the intrinsic, conversions on the bits')
        call square_root_tests()
        call quad_real_tests()
        call hardware_real_special_tests()
        call double_real_tests()
        call rounding_mode_tests()
        call thread_tests()
    end subroutine run_fast_math_tests

    !> The primitives in four OpenMP threads (interleaved arguments) give the serial
    !! results bit for bit (their tables are parameters: no state between calls).
    subroutine thread_tests()
        use brachistochrone_fast_exp, only: fast_exp, fast_expm1
        integer, parameter :: count = 20000
        real(qp), allocatable :: x(:), serial(:, :), threaded(:, :)
        integer :: i
        allocate (x(count), serial(6, count), threaded(6, count))
        call random_number(x)
        x = (x - 0.5_qp)*2.0_qp**int(40.0_qp*x - 10.0_qp)
        do i = 1, count
            serial(:, i) = primitives(x(i))
        end do
        !$omp parallel do num_threads(4) schedule(static, 1) default(shared) private(i)
        do i = 1, count
            threaded(:, i) = primitives(x(i))
        end do
        !$omp end parallel do
        call check(all(transfer(serial, [0_int64]) == transfer(threaded, [0_int64])), &
                   'fast_exp, fast_expm1, fast_sqrt, inverse_sqrt, conversions: threads')
    contains
        pure function primitives(v) result(values)
            real(qp), intent(in) :: v
            real(qp) :: values(6)
            values = [fast_exp(v), fast_expm1(v), fast_sqrt(abs(v)), inverse_sqrt(abs(v)), &
                      quad_real(hardware_real(v/3.0_qp)), real(double_real(v), qp)]
        end function primitives
    end subroutine thread_tests

    !> hardware_arithmetic_ok: true in the default environment, false rounding upward or
    !! toward zero; fast_sqrt of the largest numbers rounding upward (the hardware root
    !! rounds up to 2^8192, whose square overflowed: -Inf) positive and finite.
    subroutine rounding_mode_tests()
        use, intrinsic :: ieee_arithmetic, only: ieee_set_rounding_mode, ieee_up, &
                                                 ieee_to_zero, ieee_nearest, &
                                                 ieee_support_rounding
        real(qp) :: roots(3)
        logical :: default_ok, up_ok, zero_ok
        default_ok = hardware_arithmetic_ok()
        if (.not. (ieee_support_rounding(ieee_up, 1.0_xp) .and. &
                   ieee_support_rounding(ieee_to_zero, 1.0_xp))) return
        call ieee_set_rounding_mode(ieee_up)
        up_ok = hardware_arithmetic_ok()
        roots = fast_sqrt([huge(1.0_qp), nearest(huge(1.0_qp), -1.0_qp), &
                           nearest(nearest(huge(1.0_qp), -1.0_qp), -1.0_qp)])
        call ieee_set_rounding_mode(ieee_to_zero)
        zero_ok = hardware_arithmetic_ok()
        call ieee_set_rounding_mode(ieee_nearest)
        call check(default_ok .and. .not. up_ok .and. .not. zero_ok, &
                   'hardware_arithmetic_ok: true by default, false rounding up, to zero')
        call check(all(roots > 2.0_qp**8191 .and. roots <= 2.0_qp**8192), &
                   'fast_sqrt of the largest numbers rounding upward: positive, finite')
    end subroutine rounding_mode_tests

    !> A positive argument of the draw: every binade of binary128's normal range (random
    !! significands), and next to the cases the hardware root treats apart: perfect
    !! squares and their neighbours, powers of four and their neighbours (the root at the
    !! edge of a binade), significands of all ones (x87 truncation), the range's ends.
    function argument(u, i) result(x)
        real(qp), intent(in) :: u(3) !! uniform draws
        integer, intent(in) :: i !! the sample's number: picks the class
        real(qp) :: x
        integer(int64) :: bits(2)
        integer :: k
        k = int(32760.0_qp*(u(2) - 0.5_qp))
        select case (mod(i, 8))
        case (1) ! a perfect square (of an integer up to 2^56) and its neighbours
            x = aint(2.0_qp**(56.0_qp*u(1)))**2*2.0_qp**(2*(k/4))
            if (u(3) < 0.4_qp) x = nearest(x, -1.0_qp)
            if (u(3) > 0.6_qp) x = nearest(x, 1.0_qp)
        case (2) ! next to a power of four (both sides, a few ulps)
            x = 4.0_qp**(k/4)*(1.0_qp + (u(1) - 0.5_qp)*real(int(8*u(3)), qp)*epsilon(x))
        case (3) ! all-ones significand (the binary128 words of the draw's binade)
            bits = transfer(2.0_qp**k, bits)
            bits(1) = -1_int64
            bits(2) = ior(bits(2), shiftl(1_int64, 48) - 1_int64)
            x = transfer(bits, x)
        case (4) ! the ends of the normal range
            x = tiny(x)*(1.0_qp + u(1))*2.0_qp**int(64*u(3))
            if (u(2) < 0.5_qp) x = huge(x)*(1.0_qp - u(1)/4)*2.0_qp**(-int(64*u(3)))
        case default
            x = (1.0_qp + u(1))*2.0_qp**k
        end select
    end function argument

    !> fast_sqrt within an ulp of the intrinsic sqrt (libquadmath's, itself up to about
    !! 0.75 ulp off), and within 0.51 ulp of the exact root (its documented 0.5 ulp and a
    !! few thousandths), the error measured by the exact residual x - s^2 (`root_error`);
    !! inverse_sqrt within 3 ulps of 1/sqrt(x) (its own error and the reference's two
    !! roundings) and within an ulp of the exact value (0.5 ulp and a few thousandths
    !! but next to powers of two; `inverse_root_error`).
    subroutine square_root_tests()
        real(qp) :: u(3), x, root, worst_root, worst_inverse, worst_exact, worst_library, &
                    worst_inverse_exact, exact
        integer :: i, inexact_squares
        worst_root = 0.0_qp
        worst_inverse = 0.0_qp
        worst_exact = 0.0_qp
        worst_library = 0.0_qp
        worst_inverse_exact = 0.0_qp
        inexact_squares = 0
        do i = 1, samples
            call random_number(u)
            x = argument(u, i)
            root = sqrt(x)
            worst_root = max(worst_root, abs(fast_sqrt(x) - root)/spacing(root))
            worst_exact = max(worst_exact, abs(root_error(x, fast_sqrt(x))))
            worst_library = max(worst_library, abs(root_error(x, root)))
            if (root*root == x .and. fast_sqrt(x) /= root) inexact_squares = inexact_squares + 1
            exact = 1.0_qp/root
            worst_inverse = max(worst_inverse, abs(inverse_sqrt(x) - exact)/spacing(exact))
            worst_inverse_exact = max(worst_inverse_exact, &
                                      abs(inverse_root_error(x, inverse_sqrt(x))))
        end do
        print '(a,i0,a,f6.3,a,f6.3,a,f6.3,a)', '   fast_sqrt on ', samples, &
            ' arguments: worst error ', worst_exact, ' ulp (', worst_root, &
            ' from the intrinsic, whose own worst is ', worst_library, ')'
        print '(a,f6.3,a,f6.3,a)', '   inverse_sqrt: worst error ', worst_inverse_exact, &
            ' ulp (', worst_inverse, ' from 1/sqrt(x))'
        call check(worst_root <= 1.0_qp, 'fast_sqrt within an ulp of sqrt, whole range')
        call check(worst_exact <= 0.51_qp, 'fast_sqrt within 0.51 ulp of the exact root')
        call check(inexact_squares == 0, 'fast_sqrt exact on perfect squares')
        call check(worst_inverse <= 3.0_qp, 'inverse_sqrt within 3 ulp of 1/sqrt(x)')
        call check(worst_inverse_exact <= 1.0_qp, 'inverse_sqrt within an ulp of the exact')
        call check(bottom_edge_error() <= 0.51_qp, &
                   'fast_sqrt within 0.51 ulp at binade edges, bottom of the normal range')
        ! (subnormal: the intrinsic at run time; the compiler's own is correctly rounded)
        x = tiny(x)*real(samples, qp)**(-2)
        call check(fast_sqrt(0.0_qp) == 0.0_qp .and. fast_sqrt(4.0_qp) == 2.0_qp .and. &
                   fast_sqrt(x) == sqrt(x) .and. x < tiny(x) .and. &
                   fast_sqrt(ieee_value(x, ieee_positive_inf)) > huge(x) .and. &
                   ieee_is_nan(fast_sqrt(ieee_value(x, ieee_quiet_nan))) .and. &
                   ieee_is_nan(fast_sqrt(-1.0_qp)), &
                   'fast_sqrt: zero, exact, subnormal, infinity, NaN, negative (NaN)')
    end subroutine square_root_tests

    !> fast_sqrt's worst error (`root_error`) next to every power of two from the smallest
    !! normal to 2^-15982 (x = 2^e (1 + j 2^-112) and 2^e (2 - j 2^-112), j = 1 .. 6:
    !! hardware roots at a binade's edge; their residual, about 2^-63 x or less, is below
    !! x87's normal range there).
    function bottom_edge_error() result(worst)
        real(qp) :: worst
        real(qp) :: x
        integer :: e, j
        worst = 0.0_qp
        do e = minexponent(x) - 1, minexponent(x) + 400
            do j = 1, 6
                x = scale(1.0_qp + j*epsilon(x), e)
                worst = max(worst, abs(root_error(x, fast_sqrt(x))))
                x = scale(2.0_qp - j*epsilon(x), e)
                worst = max(worst, abs(root_error(x, fast_sqrt(x))))
            end do
        end do
    end function bottom_edge_error

    !> (s - sqrt(x))/ulp(s) from the exact residual: x and s scaled by 4^k and 2^k into
    !! [1, 4) and [1, 2) (exactly), s^2 = p + e exactly (Dekker's product), x - p exact
    !! (Sterbenz), and s - sqrt(x) = (s^2 - x)/(s + sqrt(x)) = (s^2 - x)/(2 s) to 2^-110.
    function root_error(x, s) result(ulps)
        real(qp), intent(in) :: x, s !! positive normal argument, its computed root
        real(qp) :: ulps
        real(qp) :: xs, ss, p, e
        integer :: k
        k = exponent(s) - 1
        ss = scale(s, -k)
        xs = scale(x, -2*k)
        call two_product(ss, ss, p, e)
        ulps = ((p - xs) + e)/(2.0_qp*ss)/spacing(ss)
    end function root_error

    !> (y - 1/sqrt(x))/ulp(y) from the exact residual 1 - x y^2 (scaled as above; x y^2
    !! = P + E + x e exactly with y^2 = p + e, x p = P + E): 1/sqrt(x) = y/sqrt(1 - rho),
    !! so y - 1/sqrt(x) = -y rho/2 to 2^-110.
    function inverse_root_error(x, y) result(ulps)
        real(qp), intent(in) :: x, y !! positive normal argument, its computed 1/sqrt
        real(qp) :: ulps
        real(qp) :: xs, ys, p, e, big_p, big_e, rho
        integer :: k
        k = exponent(y) - 1
        ys = scale(y, -k)
        xs = scale(x, 2*k)
        call two_product(ys, ys, p, e)
        call two_product(xs, p, big_p, big_e)
        rho = ((1.0_qp - big_p) - big_e) - xs*e
        ulps = -ys*rho/2.0_qp/spacing(ys)
    end function inverse_root_error

    !> a b = p + e exactly (Dekker, Veltkamp's split at 57 bits; no overflow here).
    subroutine two_product(a, b, p, e)
        real(qp), intent(in) :: a, b
        real(qp), intent(out) :: p, e
        real(qp), parameter :: splitter = 2.0_qp**57 + 1.0_qp
        real(qp) :: a_high, a_low, b_high, b_low, t
        t = splitter*a
        a_high = t - (t - a)
        a_low = a - a_high
        t = splitter*b
        b_high = t - (t - b)
        b_low = b - b_high
        p = a*b
        e = ((a_high*b_high - p) + a_high*b_low + a_low*b_high) + a_low*b_low
    end subroutine two_product

    !> quad_real = real(y, qp) bit for bit: random x87 numbers of every exponent and sign,
    !! subnormals, unnormals (explicit bit clear), zeros, infinities, NaNs.
    subroutine quad_real_tests()
        real(qp) :: u(3)
        real(xp) :: y
        integer(int64) :: significand, sign_exponent
        integer :: i, mismatches
        mismatches = 0
        do i = 1, samples
            call random_number(u)
            significand = ior(shiftl(int(u(1)*2.0_qp**62, int64), 2), int(4*u(3), int64))
            sign_exponent = int(32767*u(2), int64)
            select case (mod(i, 10))
            case (1) ! subnormal
                sign_exponent = 0_int64
            case (2) ! unnormal (or a pseudo-denormal)
                if (u(3) < 0.5_qp) sign_exponent = 0_int64
            case (3) ! infinity or NaN
                sign_exponent = 32767_int64
                significand = ior(significand, shiftl(1_int64, 63))
                if (u(3) < 0.3_qp) significand = shiftl(1_int64, 63)
            case (4) ! zero
                significand = 0_int64
                sign_exponent = 0_int64
            case default
                significand = ior(significand, shiftl(1_int64, 63))
            end select
            if (u(3) < 0.5_qp) sign_exponent = ior(sign_exponent, 32768_int64)
            y = x87_number(significand, sign_exponent)
            if (.not. same_quad(quad_real(y), real(y, qp))) mismatches = mismatches + 1
        end do
        call check(mismatches == 0, 'quad_real = real(y, qp) on 200000 values of every class')
        call check(same_quad(quad_real(ieee_value(y, ieee_quiet_nan)), &
                             real(ieee_value(y, ieee_quiet_nan), qp)) .and. &
                   same_quad(quad_real(ieee_value(y, ieee_negative_inf)), &
                             real(ieee_value(y, ieee_negative_inf), qp)) .and. &
                   same_quad(quad_real(tiny(y)/3), real(tiny(y)/3, qp)) .and. &
                   same_quad(quad_real(-0.0_xp), -0.0_qp) .and. &
                   same_quad(quad_real(huge(y)), real(huge(y), qp)), &
                   'quad_real = real(y, qp): NaN, infinity, subnormal, -0, huge')
    end subroutine quad_real_tests

    !> hardware_real (its random values: test_hardware_level) bit for bit on the
    !! classes the library converts: subnormals (to x87 subnormals or zero), NaN
    !! payloads, infinities, zeros, and the rounding up to infinity.
    subroutine hardware_real_special_tests()
        real(qp) :: values(9)
        integer :: i, mismatches
        values = [tiny(1.0_qp)*0.75_qp, -tiny(1.0_qp)*2.0_qp**(-100), 2.0_qp**(-16494), &
                  ieee_value(1.0_qp, ieee_quiet_nan), ieee_value(1.0_qp, ieee_signaling_nan), &
                  ieee_value(1.0_qp, ieee_negative_inf), -0.0_qp, huge(1.0_qp), &
                  -nearest(huge(1.0_qp), -1.0_qp)]
        mismatches = 0
        do i = 1, size(values)
            if (.not. same_x87(hardware_real(values(i)), real(values(i), xp))) &
                mismatches = mismatches + 1
        end do
        call check(mismatches == 0, 'hardware_real = real(x, xp): subnormal, NaN, inf, -0')
    end subroutine hardware_real_special_tests

    !> double_real = real(x, real64) bit for bit: random values of every binade of
    !! binary128 (most out of double's range: overflow, subnormal and zero results),
    !! rounding ties of both parities and their neighbours, all-ones fractions (carry into
    !! the exponent, to infinity at the top), zeros, infinities, NaN.
    subroutine double_real_tests()
        integer(int64), parameter :: half = shiftl(1_int64, 59), low60 = shiftl(1_int64, 60) - 1
        real(qp) :: u(3), x, specials(8)
        integer(int64) :: bits(2)
        integer :: i, mismatches
        mismatches = 0
        do i = 1, samples
            call random_number(u)
            x = (1.0_qp + u(1))*2.0_qp**int(2200.0_qp*(u(2) - 0.5_qp))
            if (mod(i, 7) == 0) x = (1.0_qp + u(1))*2.0_qp**int(32760.0_qp*(u(2) - 0.5_qp))
            if (u(3) < 0.3_qp) x = -x
            bits = transfer(x, bits)
            select case (mod(i, 6))
            case (1) ! a tie
                bits(1) = ior(iand(bits(1), not(low60)), half)
            case (2) ! one below a tie
                bits(1) = ior(iand(bits(1), not(low60)), half - 1_int64)
            case (3) ! one above a tie
                bits(1) = ior(iand(bits(1), not(low60)), half + 1_int64)
            case (4) ! all ones
                bits(1) = -1_int64
                bits(2) = ior(bits(2), shiftl(1_int64, 48) - 1_int64)
            end select
            x = transfer(bits, x)
            if (.not. same_double(double_real(x), real(x, real64))) mismatches = mismatches + 1
        end do
        call check(mismatches == 0, 'double_real = real(x, real64) on 200000 values')
        specials = [0.0_qp, -0.0_qp, ieee_value(x, ieee_negative_inf), &
                    ieee_value(x, ieee_quiet_nan), real(huge(1.0_real64), qp), &
                    real(tiny(1.0_real64), qp)*(1.0_qp - epsilon(x)), tiny(x)/3, huge(x)]
        mismatches = 0
        do i = 1, size(specials)
            if (.not. same_double(double_real(specials(i)), real(specials(i), real64))) &
                mismatches = mismatches + 1
        end do
        call check(mismatches == 0, 'double_real = real(x, real64): zeros, inf, NaN, ends')
    end subroutine double_real_tests

    !> The same double bits.
    pure logical function same_double(a, b)
        real(real64), intent(in) :: a, b
        same_double = transfer(a, 0_int64) == transfer(b, 0_int64)
    end function same_double

    !> The x87 number of these bits.
    pure function x87_number(significand, sign_exponent) result(y)
        integer(int64), intent(in) :: significand, sign_exponent
        real(xp) :: y
        integer(int64) :: words(2)
        words = [significand, sign_exponent]
        y = transfer(words, y)
    end function x87_number

    !> The same binary128 bits.
    pure logical function same_quad(a, b)
        real(qp), intent(in) :: a, b
        same_quad = all(transfer(a, [0_int64, 0_int64]) == transfer(b, [0_int64, 0_int64]))
    end function same_quad

    !> The same x87 bits (the 10 bytes that hold the value).
    pure logical function same_x87(a, b)
        real(xp), intent(in) :: a, b
        integer(int16) :: wa(8), wb(8)
        wa = transfer(a, wa)
        wb = transfer(b, wb)
        same_x87 = all(wa(1:5) == wb(1:5))
    end function same_x87

end module test_fast_math
