!> Double-quad arithmetic: a number held as the unevaluated sum hi + lo of two quad
!! numbers, |lo| <= ulp(hi)/2, about 226 significant bits.
!!
!! Built on the error-free transformations: two_sum (Knuth) gives a + b exactly as a pair,
!! and two_product (Dekker) gives a*b exactly, splitting each factor into two halves of
!! at most 56 bits with the constant 2^57 + 1, since binary128 has no hardware fused
!! multiply-add (exact barring overflow and underflow). The operations follow the
!! double-double algorithms of Hida, Li and Bailey (QD library): each errs by a few
!! units of 2^-224 relative, except that a sum or difference errs by a few units of
!! 2^-224 times the larger operand (cancellation is exact in hi and only exposes the
!! rounding of lo). Each costs 10 to 30 quad operations: for one-time work where quad
!! itself must come out right to the last bit, such as the nodes and weights of a
!! quadrature rule. The transformations need quad arithmetic rounded to nearest and
!! evaluated as written (no value-unsafe optimisations such as -ffast-math).
module brachistochrone_double_quad
    use brachistochrone_kinds, only: qp
    implicit none
    private

    public :: double_quad_number, two_sum, two_product, to_quad
    public :: operator(+), operator(-), operator(*), operator(/)

    !> The number hi + lo, normalised so that hi is the quad rounding of the sum.
    type :: double_quad_number
        real(qp) :: hi = 0.0_qp   !! leading part
        real(qp) :: lo = 0.0_qp   !! trailing part, at most half an ulp of hi
    end type double_quad_number

    !> Sum of two double-quad numbers.
    interface operator(+)
        module procedure add
    end interface operator(+)

    !> Difference of two double-quad numbers, or negation.
    interface operator(-)
        module procedure subtract, negate
    end interface operator(-)

    !> Product with a double-quad, quad or (exactly represented) integer factor.
    interface operator(*)
        module procedure multiply, multiply_quad, multiply_integer
    end interface operator(*)

    !> Quotient by a double-quad or integer divisor.
    interface operator(/)
        module procedure divide, divide_integer
    end interface operator(/)

    !> Veltkamp's splitting constant 2^57 + 1: with t = a*(2^57 + 1), t - (t - a) keeps the
    !! leading 56 bits of a 113-bit significand and the rest fits in 56 bits and a sign,
    !! so products of such halves are exact in quad.
    real(qp), parameter :: splitter = 2.0_qp**57 + 1.0_qp

contains

    !> a + b exactly, as hi = fl(a + b) and lo = the rounding error (Knuth's TwoSum).
    elemental function two_sum(a, b) result(s)
        real(qp), intent(in) :: a !! first term
        real(qp), intent(in) :: b !! second term
        type(double_quad_number) :: s
        real(qp) :: b_virtual
        s%hi = a + b
        b_virtual = s%hi - a
        s%lo = (a - (s%hi - b_virtual)) + (b - b_virtual)
    end function two_sum

    !> a + b exactly when |a| >= |b| (or a = 0), in three operations (Dekker's Fast2Sum).
    elemental function fast_two_sum(a, b) result(s)
        real(qp), intent(in) :: a, b
        type(double_quad_number) :: s
        s%hi = a + b
        s%lo = b - (s%hi - a)
    end function fast_two_sum

    !> a*b exactly, as hi = fl(a*b) and lo = the rounding error (Dekker's TwoProduct).
    elemental function two_product(a, b) result(p)
        real(qp), intent(in) :: a !! first factor
        real(qp), intent(in) :: b !! second factor
        type(double_quad_number) :: p
        real(qp) :: a_high, a_low, b_high, b_low
        call split(a, a_high, a_low)
        call split(b, b_high, b_low)
        p%hi = a*b
        p%lo = ((a_high*b_high - p%hi) + a_high*b_low + a_low*b_high) + a_low*b_low
    end function two_product

    !> a = high + low exactly, each with at most 56 significant bits (Veltkamp).
    elemental subroutine split(a, high, low)
        real(qp), intent(in) :: a
        real(qp), intent(out) :: high, low
        real(qp) :: t
        t = splitter*a
        high = t - (t - a)
        low = a - high
    end subroutine split

    !> hi + lo rounded to quad.
    elemental function to_quad(a) result(x)
        type(double_quad_number), intent(in) :: a !! the double-quad number
        real(qp) :: x
        x = a%hi + a%lo
    end function to_quad

    !> a + b: two_sum of the leading parts, the trailing parts added to its error.
    elemental function add(a, b) result(s)
        type(double_quad_number), intent(in) :: a, b
        type(double_quad_number) :: s
        s = two_sum(a%hi, b%hi)
        s = fast_two_sum(s%hi, s%lo + (a%lo + b%lo))
    end function add

    elemental function negate(a) result(s)
        type(double_quad_number), intent(in) :: a
        type(double_quad_number) :: s
        s = double_quad_number(-a%hi, -a%lo)
    end function negate

    !> a - b = a + (-b).
    elemental function subtract(a, b) result(s)
        type(double_quad_number), intent(in) :: a, b
        type(double_quad_number) :: s
        s = add(a, negate(b))
    end function subtract

    !> a*b: two_product of the leading parts plus the cross terms (lo*lo is below
    !! 2^-226 relative and dropped).
    elemental function multiply(a, b) result(p)
        type(double_quad_number), intent(in) :: a, b
        type(double_quad_number) :: p
        p = two_product(a%hi, b%hi)
        p = fast_two_sum(p%hi, p%lo + (a%hi*b%lo + a%lo*b%hi))
    end function multiply

    !> a*b for a quad factor b.
    elemental function multiply_quad(a, b) result(p)
        type(double_quad_number), intent(in) :: a
        real(qp), intent(in) :: b
        type(double_quad_number) :: p
        p = two_product(a%hi, b)
        p = fast_two_sum(p%hi, p%lo + a%lo*b)
    end function multiply_quad

    !> a*m for a default integer m (at most 31 bits): m needs no splitting, as m times a
    !! 56-bit half of a%hi is exact.
    elemental function multiply_integer(a, m) result(p)
        type(double_quad_number), intent(in) :: a
        integer, intent(in) :: m
        type(double_quad_number) :: p
        real(qp) :: a_high, a_low, factor
        factor = real(m, qp)
        call split(a%hi, a_high, a_low)
        p%hi = a%hi*factor
        p%lo = (factor*a_high - p%hi) + factor*a_low
        p = fast_two_sum(p%hi, p%lo + a%lo*factor)
    end function multiply_integer

    !> a/b: the quad quotient q, then the correction (a - q b)/b, with a - q b formed in
    !! double-quad (its leading parts cancel exactly).
    elemental function divide(a, b) result(q)
        type(double_quad_number), intent(in) :: a, b
        type(double_quad_number) :: q
        type(double_quad_number) :: remainder
        real(qp) :: first
        first = a%hi/b%hi
        remainder = a - b*first
        q = fast_two_sum(first, remainder%hi/b%hi)
    end function divide

    !> a/m for a default integer m, as `divide`.
    elemental function divide_integer(a, m) result(q)
        type(double_quad_number), intent(in) :: a
        integer, intent(in) :: m
        type(double_quad_number) :: q
        type(double_quad_number) :: remainder
        real(qp) :: first
        first = a%hi/real(m, qp)
        remainder = a - double_quad_number(first, 0.0_qp)*m
        q = fast_two_sum(first, remainder%hi/real(m, qp))
    end function divide_integer

end module brachistochrone_double_quad
