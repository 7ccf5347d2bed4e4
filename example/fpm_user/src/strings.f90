!> The user's own strings module (the library has brachistochrone_strings).
module strings
    implicit none
    private
    public :: shout

contains

    !> Upper-case copy of `text` (ASCII letters).
    pure function shout(text) result(loud)
        character(len=*), intent(in) :: text
        character(len=len(text)) :: loud
        integer :: k, code
        loud = text
        do k = 1, len(text)
            code = iachar(text(k:k))
            if (code >= iachar('a') .and. code <= iachar('z')) loud(k:k) = achar(code - 32)
        end do
    end function shout

end module strings
