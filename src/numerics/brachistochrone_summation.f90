!> Compensated (Neumaier) summation: the rounding error of each addition is recovered
!! exactly and accumulated apart, so a sum of n terms errs by about one rounding of the
!! result instead of up to n of them. For one-time work where the last digit matters,
!! such as building tables; the hot loops use plain sums.
module brachistochrone_summation
    use brachistochrone_kinds, only: qp
    implicit none
    private

    public :: compensated_sum

    !> A running sum with its rounding error carried apart.
    type :: compensated_sum
        real(qp) :: total = 0.0_qp       !! the rounded running sum
        real(qp) :: correction = 0.0_qp  !! the accumulated rounding errors
    contains
        procedure :: add     !! add a term
        procedure :: value   !! the sum, total + correction
    end type compensated_sum

contains

    !> Add x to the sum.
    elemental subroutine add(self, x)
        class(compensated_sum), intent(inout) :: self
        real(qp), intent(in) :: x  !! the term
        real(qp) :: t
        t = self%total + x
        if (abs(self%total) >= abs(x)) then
            self%correction = self%correction + ((self%total - t) + x)
        else
            self%correction = self%correction + ((x - t) + self%total)
        end if
        self%total = t
    end subroutine add

    !> The compensated sum.
    elemental function value(self) result(sum)
        class(compensated_sum), intent(in) :: self
        real(qp) :: sum
        sum = self%total + self%correction
    end function value

end module brachistochrone_summation
