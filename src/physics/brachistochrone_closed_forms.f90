!> Closed forms of the attractive inverse-square problem (Tee 1998, section 3-4).
!!
!! Units of the paper: mu = 1, the start A at radius 1, released from rest. These are
!! used by the solver and are also the test suite's oracles for the limits the theory
!! proves. Every `acos` of the paper is written as an `atan2` of square roots, which
!! keeps full relative precision at both ends of the range.
module brachistochrone_closed_forms
    use brachistochrone_kinds, only: qp, pi
    use brachistochrone_status, only: status_ok, argument_status
    implicit none
    private

    public :: fall_to_centre_time, apse_angle_limit, inaccessible_angle
    public :: radial_fall_time, kappa_bound
    public :: radial_time, radial_time_of_roots, kappa_time
    public :: second_arch_radial_time

    !> t(0) = pi/sqrt(8), eq. (47): time of radial fall from rest at radius 1 to the centre.
    real(qp), parameter :: fall_to_centre_time = pi/sqrt(8.0_qp)
    !> Least upper bound pi/3 of the apse angle Theta(R,R), eq. (74).
    real(qp), parameter :: apse_angle_limit = pi/3.0_qp
    !> Angle 2 pi/3 where the sector of inaccessibility begins (section 4.2.2).
    real(qp), parameter :: inaccessible_angle = 2.0_qp*pi/3.0_qp

contains

    !> Time t(r) to fall radially from rest at radius 1 to radius r, eq. (46):
    !! t(r) = [acos(2r-1)/2 + sqrt(r(1-r))]/sqrt(2), with acos(2r-1)/2 written as
    !! atan2(sqrt(1-r), sqrt(r)). Pass `complement` = 1 - r when it is known more
    !! accurately than 1 - r can be computed (r within a few ulps of 1 loses relative
    !! precision in 1 - r, and t(r) ~ sqrt(2(1-r)) there). Precondition 0 <= r <= 1
    !! (not checked: use `radial_fall_time` for a checked call).
    elemental function radial_time(r, complement) result(t)
        real(qp), intent(in) :: r                    !! radius, 0 <= r <= 1
        real(qp), intent(in), optional :: complement !! 1 - r, if known exactly
        real(qp) :: t
        real(qp) :: one_minus_r
        if (present(complement)) then
            one_minus_r = complement
        else
            one_minus_r = 1.0_qp - r
        end if
        t = radial_time_of_roots(r, one_minus_r, sqrt(r), sqrt(one_minus_r))
    end function radial_time

    !> `radial_time` from square roots the caller has already computed (the same bits):
    !! t(r) = [atan2(sqrt(1-r), sqrt(r)) + sqrt(r(1-r))]/sqrt(2).
    elemental function radial_time_of_roots(r, one_minus_r, root_r, root_one_minus_r) &
        result(t)
        real(qp), intent(in) :: r                !! radius, 0 <= r <= 1
        real(qp), intent(in) :: one_minus_r      !! 1 - r
        real(qp), intent(in) :: root_r           !! sqrt(r)
        real(qp), intent(in) :: root_one_minus_r !! sqrt(1 - r)
        real(qp) :: t
        t = (atan2(root_one_minus_r, root_r) + sqrt(r*one_minus_r))/sqrt(2.0_qp)
    end function radial_time_of_roots

    !> 2 t(R) - t(r) (the radial part of the time on the second half-arch) with one
    !! arctangent: the angles a = atan2(sqrt(1-R), sqrt(R)), b = atan2(sqrt(1-r),
    !! sqrt(r)) give 2a - b = arg((sqrt(R) + i sqrt(1-R))^2 (sqrt(r) - i sqrt(1-r))),
    !! in [0, pi] for 0 <= R <= r <= 1 (a >= b), where the imaginary part is a sum of
    !! non-negative terms once 2R - 1 < 0 (so the argument stays off the branch cut):
    !! 2 t(R) - t(r) = [2a - b + 2 sqrt(R(1-R)) - sqrt(r(1-r))]/sqrt(2). On 4,000 random
    !! and extreme (R, r) against mpmath: within 2.6 eps (the two-arctangent form 3.2).
    elemental function second_arch_radial_time(big_r, one_minus_big_r, r, one_minus_r, &
                                              root_r, root_one_minus_r) result(t)
        real(qp), intent(in) :: big_r            !! R, 0 <= R <= r
        real(qp), intent(in) :: one_minus_big_r  !! 1 - R
        real(qp), intent(in) :: r                !! radius, r <= 1
        real(qp), intent(in) :: one_minus_r      !! 1 - r
        real(qp), intent(in) :: root_r           !! sqrt(r)
        real(qp), intent(in) :: root_one_minus_r !! sqrt(1 - r)
        real(qp) :: t
        real(qp) :: real_part, imaginary_part, twice_root
        ! (sqrt(R) + i sqrt(1-R))^2 = (2R - 1) + i twice_root
        twice_root = 2.0_qp*sqrt(big_r*one_minus_big_r)
        real_part = (big_r - one_minus_big_r)*root_r + twice_root*root_one_minus_r
        imaginary_part = twice_root*root_r - (big_r - one_minus_big_r)*root_one_minus_r
        t = (atan2(imaginary_part, real_part) + twice_root - sqrt(r*one_minus_r)) &
            /sqrt(2.0_qp)
    end function second_arch_radial_time

    !> kappa(rho) = 2 t(0) - t(rho), eq. (75): the greatest lower bound of the time from A
    !! to any point at radius rho in the sector of inaccessibility. Precondition
    !! 0 <= rho <= 1 (not checked: use `kappa_bound` for a checked call).
    elemental function kappa_time(rho) result(kappa)
        real(qp), intent(in) :: rho !! radius, 0 <= rho <= 1
        real(qp) :: kappa
        kappa = (pi - atan2(sqrt(1.0_qp - rho), sqrt(rho)) - sqrt(rho*(1.0_qp - rho))) &
                /sqrt(2.0_qp)
    end function kappa_time

    !> Checked radial fall time t(r), eq. (46). On a bad argument t = 0 and status is set.
    elemental subroutine radial_fall_time(r, t, status)
        real(qp), intent(in) :: r       !! radius, 0 <= r <= 1
        real(qp), intent(out) :: t      !! time to fall from radius 1 to r
        integer, intent(out) :: status  !! status_ok, status_not_finite, status_invalid_argument
        t = 0.0_qp
        status = argument_status([r], r >= 0.0_qp .and. r <= 1.0_qp)
        if (status == status_ok) t = radial_time(r)
    end subroutine radial_fall_time

    !> Checked kappa(rho), eq. (75). On a bad argument kappa = 0 and status is set.
    elemental subroutine kappa_bound(rho, kappa, status)
        real(qp), intent(in) :: rho     !! radius, 0 <= rho <= 1
        real(qp), intent(out) :: kappa  !! greatest lower bound of the time to radius rho
        integer, intent(out) :: status  !! status_ok, status_not_finite, status_invalid_argument
        kappa = 0.0_qp
        status = argument_status([rho], rho >= 0.0_qp .and. rho <= 1.0_qp)
        if (status == status_ok) kappa = kappa_time(rho)
    end subroutine kappa_bound

end module brachistochrone_closed_forms
