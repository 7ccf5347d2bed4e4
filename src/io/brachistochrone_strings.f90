!> Small text helpers shared by the I/O modules.
module brachistochrone_strings
    implicit none
    private

    public :: integer_text, lower

contains

    !> Decimal text of an integer, without blanks.
    pure function integer_text(value) result(text)
        integer, intent(in) :: value !! the integer
        character(len=:), allocatable :: text
        character(len=24) :: buffer
        write (buffer, '(i0)') value
        text = trim(buffer)
    end function integer_text

    !> Lowercase copy of ASCII text.
    pure function lower(text) result(lowered)
        character(len=*), intent(in) :: text !! text
        character(len=len(text)) :: lowered
        integer :: i, code
        lowered = text
        do i = 1, len(text)
            code = iachar(text(i:i))
            if (code >= iachar('A') .and. code <= iachar('Z')) lowered(i:i) = achar(code + 32)
        end do
    end function lower

end module brachistochrone_strings
