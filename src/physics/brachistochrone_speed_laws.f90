!> Speed laws v(r) of a particle released from rest at radius 1 in a central field.
!!
!! Energy conservation gives v^2 = 2 (phi(1) - phi(r)) (Tee 1998, eq. 14). A force field
!! enters the general engine (`central_force`) only through
!!   P(x)   = v(x)^2,
!!   D(x,y) = (P(x) - P(y))/(x - y), the divided difference (D(x,x) = P'(x)),
!! both evaluated without cancellation, because the engine's integrands need
!! V(x) = P(x)/(1 - x) = -D(x,1) and (P(x) - P(R))/(x - R) near x = 1 and x = R.
!! Units: radius of A = 1 and |mu| = 1 (inverse-square: Tee's units; harmonic: R_E = 1,
!! omega = 1).
module brachistochrone_speed_laws
    use brachistochrone_kinds, only: qp
    use brachistochrone_quad_math, only: expm1, log1p
    implicit none
    private

    public :: speed_law, inverse_square_law, power_law, logarithmic_law, harmonic_law

    !> A speed law: v^2 and its divided difference. Attractive laws here: v > 0 for
    !! 0 < r < 1, v(1) = 0.
    type, abstract :: speed_law
    contains
        procedure(scalar_law), deferred :: speed_squared   !! P(x) = v(x)^2
        procedure(pair_law), deferred :: divided_difference !! (P(x) - P(y))/(x - y)
        procedure(limit_law), deferred :: apse_angle_limit !! lim Theta(R,R), R -> 0
        procedure :: passes_centre => no_centre_passage  !! v(0) finite
    end type speed_law

    abstract interface
        pure function scalar_law(self, x) result(p)
            import :: speed_law, qp
            class(speed_law), intent(in) :: self
            real(qp), intent(in) :: x
            real(qp) :: p
        end function scalar_law
        pure function pair_law(self, x, y) result(d)
            import :: speed_law, qp
            class(speed_law), intent(in) :: self
            real(qp), intent(in) :: x, y
            real(qp) :: d
        end function pair_law
        pure function limit_law(self) result(angle)
            import :: speed_law, qp
            class(speed_law), intent(in) :: self
            real(qp) :: angle
        end function limit_law
    end interface

    !> Attractive inverse-square force, mu = 1: v^2 = 2(1 - x)/x (eq. 44).
    type, extends(speed_law) :: inverse_square_law
    contains
        procedure :: speed_squared => inverse_square_p
        procedure :: divided_difference => inverse_square_d
        procedure :: apse_angle_limit => inverse_square_limit
    end type inverse_square_law

    !> Attractive power law F = 1/r^n, n > 1: v^2 = 2 (x^(1-n) - 1)/(n - 1).
    type, extends(speed_law) :: power_law
        real(qp) :: n = 2.0_qp !! exponent of the force, n > 1
    contains
        procedure :: speed_squared => power_p
        procedure :: divided_difference => power_d
        procedure :: apse_angle_limit => power_limit
    end type power_law

    !> Logarithmic potential (F = 1/r, the power law n = 1): v^2 = -2 log x.
    type, extends(speed_law) :: logarithmic_law
    contains
        procedure :: speed_squared => logarithmic_p
        procedure :: divided_difference => logarithmic_d
        procedure :: apse_angle_limit => logarithmic_limit
    end type logarithmic_law

    !> Inside a uniform planet (Saitoh), R_E = 1, omega = 1: v^2 = 1 - x^2.
    type, extends(speed_law) :: harmonic_law
    contains
        procedure :: speed_squared => harmonic_p
        procedure :: divided_difference => harmonic_d
        procedure :: apse_angle_limit => harmonic_limit
        procedure :: passes_centre => harmonic_passes_centre
    end type harmonic_law

contains

    !> Whether a particle can pass through the centre (finite speed there): then the
    !! limit 2 lim Theta(R,R) of the accessible angle is reached, by the path through O.
    pure logical function no_centre_passage(self)
        class(speed_law), intent(in) :: self
        no_centre_passage = .false.
    end function no_centre_passage

    pure logical function harmonic_passes_centre(self)
        class(harmonic_law), intent(in) :: self
        harmonic_passes_centre = .true.
    end function harmonic_passes_centre

    pure function inverse_square_p(self, x) result(p)
        class(inverse_square_law), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp) :: p
        p = 2.0_qp*(1.0_qp - x)/x
    end function inverse_square_p

    pure function inverse_square_d(self, x, y) result(d)
        class(inverse_square_law), intent(in) :: self
        real(qp), intent(in) :: x, y
        real(qp) :: d
        d = -2.0_qp/(x*y)
    end function inverse_square_d

    pure function inverse_square_limit(self) result(angle)
        class(inverse_square_law), intent(in) :: self
        real(qp) :: angle
        angle = acos(-1.0_qp)/3.0_qp
    end function inverse_square_limit

    pure function power_p(self, x) result(p)
        class(power_law), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp) :: p
        ! x^(1-n) - 1 = expm1((1-n) log x), accurate near x = 1
        p = 2.0_qp*expm1((1.0_qp - self%n)*log(x))/(self%n - 1.0_qp)
    end function power_p

    !> (x^a - y^a)/(x - y) = y^(a-1) (t^a - 1)/(t - 1), t = x/y, with
    !! t^a - 1 = expm1(a log t): no cancellation as x -> y.
    pure function power_d(self, x, y) result(d)
        class(power_law), intent(in) :: self
        real(qp), intent(in) :: x, y
        real(qp) :: d, a, u
        a = 1.0_qp - self%n
        u = (x - y)/y
        if (u == 0.0_qp) then
            d = a*y**(a - 1.0_qp)
        else
            d = y**(a - 1.0_qp)*expm1(a*log_ratio(x, y))/u
        end if
        d = 2.0_qp*d/(self%n - 1.0_qp)
    end function power_d

    !> log(x/y) to full relative precision for all x, y > 0: log1p((x - y)/y) while x is
    !! close to y (there log(x/y) would lose the digits of x/y - 1), log(x/y) otherwise
    !! (there log1p(u) with u near -1 would lose the digits of x lost in x - y).
    elemental function log_ratio(x, y) result(l)
        real(qp), intent(in) :: x, y
        real(qp) :: l, u
        u = (x - y)/y
        if (abs(u) < 0.5_qp) then
            l = log1p(u)
        else
            l = log(x/y)
        end if
    end function log_ratio

    !> Keam's result quoted by Tee: the apse angle tends to pi/(n+1) as R -> 0.
    pure function power_limit(self) result(angle)
        class(power_law), intent(in) :: self
        real(qp) :: angle
        angle = acos(-1.0_qp)/(self%n + 1.0_qp)
    end function power_limit

    pure function logarithmic_p(self, x) result(p)
        class(logarithmic_law), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp) :: p
        p = -2.0_qp*log(x)
    end function logarithmic_p

    pure function logarithmic_d(self, x, y) result(d)
        class(logarithmic_law), intent(in) :: self
        real(qp), intent(in) :: x, y
        real(qp) :: d, u
        u = (x - y)/y
        if (u == 0.0_qp) then
            d = -2.0_qp/y
        else
            d = -2.0_qp*log_ratio(x, y)/(x - y)
        end if
    end function logarithmic_d

    pure function logarithmic_limit(self) result(angle)
        class(logarithmic_law), intent(in) :: self
        real(qp) :: angle
        angle = acos(-1.0_qp)/2.0_qp
    end function logarithmic_limit

    pure function harmonic_p(self, x) result(p)
        class(harmonic_law), intent(in) :: self
        real(qp), intent(in) :: x
        real(qp) :: p
        p = (1.0_qp - x)*(1.0_qp + x)
    end function harmonic_p

    pure function harmonic_d(self, x, y) result(d)
        class(harmonic_law), intent(in) :: self
        real(qp), intent(in) :: x, y
        real(qp) :: d
        d = -(x + y)
    end function harmonic_d

    !> The hypocycloid through the centre is the diameter: apse angle pi/2 as R -> 0.
    pure function harmonic_limit(self) result(angle)
        class(harmonic_law), intent(in) :: self
        real(qp) :: angle
        angle = acos(-1.0_qp)/2.0_qp
    end function harmonic_limit

end module brachistochrone_speed_laws
