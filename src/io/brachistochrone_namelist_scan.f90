!> A scanner for one namelist group, for diagnostics gfortran's own read does not give.
!!
!! gfortran reports a bad value as an unknown object name, and a missing group, a
!! missing '/', a bad last entry and an empty file all as "End of file". This scanner
!! walks the group's text once, records every `name = value, value, ...` with the line
!! of each value token, and reports the first syntax problem with its line. It does not
!! assign anything: the program still reads the file with `read(nml=)`, so the
!! standard's namelist semantics stay authoritative. Token positions are kept in
!! integer arrays, so a file of a million values costs a few arrays, not a million
!! strings.
module brachistochrone_namelist_scan
    use brachistochrone_strings, only: integer_text, lower
    implicit none
    private

    public :: group_scan, scan_group

    !> The scanned group.
    type :: group_scan
        logical :: found = .false.          !! the group start was found
        logical :: closed = .false.         !! its terminating '/' was found
        integer :: line = 0                 !! line of the group start
        character(len=:), allocatable :: problem !! first syntax problem ('' if none)
        integer :: problem_line = 0         !! its line
        integer :: count = 0                !! number of assignments
        character(len=32), allocatable :: name(:)   !! lowercase names, index removed
        logical, allocatable :: indexed(:)  !! name(...) = form
        integer, allocatable :: name_line(:) !! line of each name
        integer, allocatable :: first(:)    !! first value token of each assignment
        integer, allocatable :: last(:)     !! last value token of each assignment
        integer :: tokens = 0               !! number of value tokens
        integer, allocatable :: start(:)    !! token start in the text
        integer, allocatable :: finish(:)   !! token end in the text (start-1: null value)
        integer, allocatable :: token_line(:) !! token line
    contains
        procedure :: value_line             !! line of the k-th value of an assignment
    end type group_scan

contains

    !> Scan the group `&group_name ... /` of `text`.
    function scan_group(text, group_name) result(g)
        character(len=*), intent(in) :: text       !! the whole file
        character(len=*), intent(in) :: group_name !! lowercase group name
        type(group_scan) :: g
        integer :: i, line, name_start, name_end, token_end
        logical :: expect_value_separator

        g%problem = ''
        allocate (g%name(16), g%indexed(16), g%name_line(16), g%first(16), &
                  g%last(16))
        allocate (g%start(1024), g%finish(1024), g%token_line(1024))
        i = 1
        line = 1
        ! find the group start, outside comments
        do while (i <= len(text))
            if (text(i:i) == new_line('a')) then
                line = line + 1
            else if (text(i:i) == '!') then
                call skip_comment(text, i)
                cycle
            else if (text(i:i) == '&' .or. text(i:i) == '$') then
                if (matches_word(text, i + 1, group_name)) then
                    g%found = .true.
                    g%line = line
                    i = i + 1 + len(group_name)
                    exit
                end if
            end if
            i = i + 1
        end do
        if (.not. g%found) return

        expect_value_separator = .false.
        do
            call skip_blanks(text, i, line, commas=.true.)
            if (i > len(text)) exit
            if (text(i:i) == '/') then
                g%closed = .true.
                return
            end if
            if ((text(i:i) == '&' .or. text(i:i) == '$') .and. &
                matches_word(text, i + 1, 'end')) then
                g%closed = .true.
                return
            end if
            ! a variable name, optionally subscripted, then '='
            name_start = i
            if (.not. is_letter(text(i:i))) then
                call fail('expected a variable name, found "'//snippet(text, i)//'"')
                return
            end if
            do while (i <= len(text))
                if (.not. is_name_char(text(i:i))) exit
                i = i + 1
            end do
            name_end = i - 1
            call add_name(lower(text(name_start:name_end)), line)
            call skip_blanks(text, i, line, commas=.false.)
            if (i <= len(text)) then
                if (text(i:i) == '(') then
                    g%indexed(g%count) = .true.
                    token_end = index(text(i:), ')')
                    if (token_end == 0) then
                        call fail('unclosed "(" after '//text(name_start:name_end))
                        return
                    end if
                    i = i + token_end
                    call skip_blanks(text, i, line, commas=.false.)
                end if
            end if
            if (i > len(text)) exit
            if (text(i:i) /= '=') then
                call fail('expected "=" after '//text(name_start:name_end)// &
                          ', found "'//snippet(text, i)//'"')
                return
            end if
            i = i + 1
            ! the values: tokens up to the next `name =` or the end of the group
            g%first(g%count) = g%tokens + 1
            call read_values()
            g%last(g%count) = g%tokens
            if (len(g%problem) > 0) return
        end do
        if (len(g%problem) == 0 .and. .not. g%closed) then
            g%problem_line = line
            g%problem = 'the group &'//group_name//' (line '//integer_text(g%line)// &
                           ') is not closed: end it with /'
        end if

    contains

        subroutine read_values()
            integer :: j, k, start_token, commas_seen
            commas_seen = 1       ! a comma straight after '=' is a null first value
            do
                ! separators: blanks, new lines, comments, commas (a second comma in a
                ! row is a null value)
                call skip_blanks(text, i, line, commas=.false.)
                if (i > len(text)) return
                if (text(i:i) == ',') then
                    commas_seen = commas_seen + 1
                    if (commas_seen > 1) call add_token(i, i - 1)
                    i = i + 1
                    cycle
                end if
                if (text(i:i) == '/' .or. text(i:i) == '&' .or. text(i:i) == '$') return
                ! a token; is it the next variable's name?
                start_token = i
                j = i
                do while (j <= len(text))
                    if (scan(text(j:j), ' ,/!='//achar(9)//achar(13)//new_line('a')) > 0) exit
                    if (text(j:j) == '(' .and. is_letter(text(start_token:start_token))) exit
                    j = j + 1
                end do
                k = j
                if (k <= len(text)) then
                    if (text(k:k) == '(') then
                        k = k + max(0, index(text(k:), ')'))
                    end if
                end if
                do while (k <= len(text))
                    if (text(k:k) /= ' ' .and. text(k:k) /= achar(9)) exit
                    k = k + 1
                end do
                if (k <= len(text) .and. is_letter(text(start_token:start_token))) then
                    if (text(k:k) == '=') then
                        i = start_token
                        return
                    end if
                end if
                if (j <= len(text)) then
                    if (text(j:j) == '=') then
                        call fail('"=" without a variable name before it, after "'// &
                                  text(start_token:j - 1)//'"')
                        return
                    end if
                end if
                call add_token(start_token, j - 1)
                commas_seen = 0
                i = j
            end do
        end subroutine read_values

        subroutine add_name(name, at_line)
            character(len=*), intent(in) :: name
            integer, intent(in) :: at_line
            if (g%count == size(g%name)) then
                g%name = [g%name, g%name]
                g%indexed = [g%indexed, g%indexed]
                g%name_line = [g%name_line, g%name_line]
                g%first = [g%first, g%first]
                g%last = [g%last, g%last]
            end if
            g%count = g%count + 1
            g%name(g%count) = name
            g%indexed(g%count) = .false.
            g%name_line(g%count) = at_line
            g%first(g%count) = 1
            g%last(g%count) = 0
        end subroutine add_name

        subroutine add_token(from, to)
            integer, intent(in) :: from, to
            integer, allocatable :: grown(:)
            if (g%tokens == size(g%start)) then
                allocate (grown(2*size(g%start)))
                grown(:g%tokens) = g%start
                call move_alloc(grown, g%start)
                allocate (grown(2*size(g%finish)))
                grown(:g%tokens) = g%finish
                call move_alloc(grown, g%finish)
                allocate (grown(2*size(g%token_line)))
                grown(:g%tokens) = g%token_line
                call move_alloc(grown, g%token_line)
            end if
            g%tokens = g%tokens + 1
            g%start(g%tokens) = from
            g%finish(g%tokens) = to
            g%token_line(g%tokens) = line
        end subroutine add_token

        subroutine fail(message)
            character(len=*), intent(in) :: message
            g%problem = message
            g%problem_line = line
        end subroutine fail

    end function scan_group

    !> Line of the k-th value (counting repeat counts r*c and null values) of assignment a.
    pure integer function value_line(self, text, a, k)
        class(group_scan), intent(in) :: self
        character(len=*), intent(in) :: text
        integer, intent(in) :: a, k
        integer :: t, seen, star, repeat, ios
        value_line = self%name_line(a)
        seen = 0
        do t = self%first(a), self%last(a)
            repeat = 1
            star = index(text(self%start(t):self%finish(t)), '*')
            if (star > 1) then
                read (text(self%start(t):self%start(t) + star - 2), *, iostat=ios) repeat
                if (ios /= 0) repeat = 1
            end if
            seen = seen + repeat
            if (seen >= k) then
                value_line = self%token_line(t)
                return
            end if
        end do
    end function value_line

    pure subroutine skip_comment(text, i)
        character(len=*), intent(in) :: text
        integer, intent(inout) :: i
        do while (i <= len(text))
            if (text(i:i) == new_line('a')) return
            i = i + 1
        end do
    end subroutine skip_comment

    pure subroutine skip_blanks(text, i, line, commas)
        character(len=*), intent(in) :: text
        integer, intent(inout) :: i, line
        logical, intent(in) :: commas
        do while (i <= len(text))
            if (text(i:i) == new_line('a')) then
                line = line + 1
            else if (text(i:i) == '!') then
                call skip_comment(text, i)
                cycle
            else if (.not. (text(i:i) == ' ' .or. text(i:i) == achar(9) .or. &
                            text(i:i) == achar(13) .or. (commas .and. text(i:i) == ','))) then
                return
            end if
            i = i + 1
        end do
    end subroutine skip_blanks

    pure logical function matches_word(text, i, word)
        character(len=*), intent(in) :: text, word
        integer, intent(in) :: i
        matches_word = .false.
        if (i + len(word) - 1 > len(text)) return
        if (lower(text(i:i + len(word) - 1)) /= word) return
        if (i + len(word) <= len(text)) then
            if (is_name_char(text(i + len(word):i + len(word)))) return
        end if
        matches_word = .true.
    end function matches_word

    pure logical function is_letter(c)
        character, intent(in) :: c
        is_letter = (c >= 'a' .and. c <= 'z') .or. (c >= 'A' .and. c <= 'Z')
    end function is_letter

    pure logical function is_name_char(c)
        character, intent(in) :: c
        is_name_char = is_letter(c) .or. (c >= '0' .and. c <= '9') .or. c == '_'
    end function is_name_char

    !> Up to 20 characters of the text from position i, for messages.
    pure function snippet(text, i) result(shown)
        character(len=*), intent(in) :: text
        integer, intent(in) :: i
        character(len=:), allocatable :: shown
        integer :: j
        j = i
        do while (j <= len(text) .and. j < i + 20)
            if (text(j:j) == new_line('a')) exit
            j = j + 1
        end do
        shown = text(i:j - 1)
    end function snippet

end module brachistochrone_namelist_scan
