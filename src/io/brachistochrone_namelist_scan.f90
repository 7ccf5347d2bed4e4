!> The namelist scanner: the one reader of a namelist group's text.
!!
!! `scan_group` walks the whole file once (time linear in its size) and records, for
!! the group asked for, every assignment `name = values` or `name(i) = ...` or
!! `name(i:j) = ...` with its line, and every value with its line, its repeat count and
!! its text (a null value has empty text). It follows the standard's namelist input
!! rules: `!` starts a comment anywhere outside a string (also between a value and a
!! continuation line), values are separated by commas, blanks or line ends, two commas
!! in a row or a comma straight after `=` give a null value (the element keeps its
!! value), `r*c` repeats a value and `r*` repeats a null value, strings take either
!! quote and a doubled quote stands for itself, names are case-insensitive, the group
!! starts with `&name` or `$name` and ends with `/`, `&end` or `$end` (at the very end
!! of the file too, without a new line). Other groups are skipped as groups, so text
!! like `&endpoints` inside one of their strings or comments is not a group start.
!!
!! Problems do not stop the scan: each is recorded with its line (a second group of
!! the same name, a missing `=`, a stray token, a bad subscript, an unclosed string or
!! group) and scanning resumes at the next name, so a file's syntax and value problems
!! are all reported in one run. The scanner converts nothing: the caller converts each
!! value's text exactly once (`brachistochrone_strings`) and checks it, so the values
!! used are exactly the values checked. Positions are integer arrays (a million values
!! cost a few arrays, not a million strings).
module brachistochrone_namelist_scan
    use, intrinsic :: iso_fortran_env, only: int64
    use brachistochrone_strings, only: integer_text, lower, escape_text, integer_from_text, &
                                       text_ok
    implicit none
    private

    public :: group_scan, scan_group, problem_list, max_problems, name_length

    !> Problems listed in full; beyond these they are only counted.
    integer, parameter :: max_problems = 100
    !> Names are kept to this many characters (longer ones end in '...').
    integer, parameter :: name_length = 32
    !> Longest text of a value or name quoted in a message.
    integer, parameter :: shown_length = 40

    type :: problem_text
        character(len=:), allocatable :: text
    end type problem_text

    !> The first `max_problems` problems in line order (ties in the order found) and
    !! the count of all problems.
    type :: problem_list
        integer :: total = 0                     !! every problem added
        integer :: kept = 0                      !! problems kept (<= max_problems)
        integer :: line(max_problems) = 0        !! their lines (0: no line)
        integer :: order(max_problems) = 0       !! their order of discovery
        type(problem_text) :: text(max_problems) !! their messages
    contains
        procedure :: add => add_problem          !! add one problem
        procedure :: message => problem_message  !! the k-th kept message
        procedure :: wanted                      !! would a problem at this line be kept?
        procedure :: count_one                   !! count a problem that is not kept
    end type problem_list

    !> The scanned group.
    type :: group_scan
        logical :: found = .false.          !! the group start was found
        logical :: closed = .false.         !! its terminating '/' was found
        integer :: line = 0                 !! line of the group start
        integer :: count = 0                !! number of assignments
        character(len=name_length), allocatable :: name(:) !! lowercase names
        integer, allocatable :: name_line(:) !! line of each name
        logical, allocatable :: usable(:)   !! its values are to be used (no syntax problem)
        logical, allocatable :: indexed(:)  !! name(i) = or name(i:j) = form
        logical, allocatable :: section(:)  !! name(i:j) = form
        integer(int64), allocatable :: low(:)  !! subscript i (1 if not indexed)
        integer(int64), allocatable :: high(:) !! subscript j (i for name(i))
        integer, allocatable :: first(:)    !! first value of each assignment
        integer, allocatable :: last(:)     !! last value of each assignment
        integer :: values = 0               !! number of values
        integer, allocatable :: start(:)    !! value text start
        integer, allocatable :: finish(:)   !! value text end (start - 1: null value)
        integer, allocatable :: repeat(:)   !! repeat count r of r*c (1 without)
        integer, allocatable :: value_line(:) !! line of each value
        logical, allocatable :: quoted(:)   !! a string: text between the quotes
        integer(int64) :: total = 0         !! sum of the repeat counts of all values
        !> memory ran out while storing values (those after it were not stored)
        logical :: out_of_memory = .false.
    end type group_scan

    character(len=*), parameter :: blanks = ' '//achar(9)//achar(13)
    !> Characters that end a value that is not a string.
    character(len=*), parameter :: value_ends = ' ,/!='//achar(9)//achar(13)//achar(10)
    integer :: k_
    !> ends_value(iachar(c)): c is in value_ends (a table: the scan's inner loop).
    logical, parameter :: ends_value(0:255) = [(index(value_ends, achar(k_)) > 0, k_ = 0, 255)]
    !> is_blank(iachar(c)): c is a blank, tab or carriage return.
    logical, parameter :: is_blank(0:255) = [(index(blanks, achar(k_)) > 0, k_ = 0, 255)]

contains

    !> Scan the group `&group_name ... /` of `text`, adding syntax problems to
    !! `problems` (each message starts with 'group &group_name').
    subroutine scan_group(text, group_name, g, problems)
        character(len=*), intent(in) :: text       !! the whole file
        character(len=*), intent(in) :: group_name !! lowercase group name
        type(group_scan), intent(out) :: g         !! what was found
        type(problem_list), intent(inout) :: problems !! problems found are added
        integer :: i, line, word_end, word_line
        character(len=:), allocatable :: word

        allocate (g%name(16), g%name_line(16), g%usable(16), g%indexed(16), &
                  g%section(16), g%low(16), g%high(16), g%first(16), g%last(16))
        allocate (g%start(1024), g%finish(1024), g%repeat(1024), g%value_line(1024), &
                  g%quoted(1024))
        i = 1
        line = 1
        do
            call find_group_start(text, i, line)
            if (i > len(text)) exit
            word_end = name_end(text, i + 1)
            word = lower(text(i + 1:word_end))
            word_line = line
            i = word_end + 1
            if (word == group_name) then
                if (g%found) then
                    call problems%add(word_line, 'group &'//group_name//': a second '// &
                                      'group &'//group_name//' (the first is at line '// &
                                      integer_text(g%line)//'); put all values in one group')
                    call skip_group(text, i, line)
                else
                    g%found = .true.
                    g%line = word_line
                    call scan_body(text, group_name, i, line, g, problems)
                end if
            else if (word /= 'end' .and. len(word) > 0) then
                call skip_group(text, i, line)
            end if
        end do
        if (g%out_of_memory) call problems%add(0, 'group &'//group_name//': out of '// &
            'memory after '//integer_text(g%values)//' values; split the table into '// &
            'smaller files or run where more memory is available')
    end subroutine scan_group

    !> Move i to the next '&' or '$' outside comments (past the end if none).
    pure subroutine find_group_start(text, i, line)
        character(len=*), intent(in) :: text
        integer, intent(inout) :: i, line
        do while (i <= len(text))
            select case (text(i:i))
            case (achar(10))
                line = line + 1
            case ('!')
                call skip_comment(text, i)
                cycle
            case ('&', '$')
                return
            end select
            i = i + 1
        end do
    end subroutine find_group_start

    !> Skip another group's body: to its '/' or '&end', or before the next group start.
    pure subroutine skip_group(text, i, line)
        character(len=*), intent(in) :: text
        integer, intent(inout) :: i, line
        integer :: last
        do while (i <= len(text))
            select case (text(i:i))
            case (achar(10))
                line = line + 1
            case ('!')
                call skip_comment(text, i)
                cycle
            case ('''', '"')
                call skip_string(text, i, line, last)
                cycle
            case ('/')
                i = i + 1
                return
            case ('&', '$')
                if (lower(text(i + 1:name_end(text, i + 1))) == 'end') &
                    i = name_end(text, i + 1) + 1
                return
            end select
            i = i + 1
        end do
    end subroutine skip_group

    !> The body of the group, from after its name to its end.
    subroutine scan_body(text, group_name, i, line, g, problems)
        character(len=*), intent(in) :: text, group_name
        integer, intent(inout) :: i, line
        type(group_scan), intent(inout) :: g
        type(problem_list), intent(inout) :: problems
        integer :: name_stop
        character(len=:), allocatable :: where
        where = 'group &'//group_name
        do
            call skip_blanks(text, i, line, commas=.true.)
            if (i > len(text)) exit
            select case (text(i:i))
            case ('/')
                g%closed = .true.
                i = i + 1
                return
            case ('&', '$')
                if (lower(text(i + 1:name_end(text, i + 1))) == 'end') then
                    g%closed = .true.
                    i = name_end(text, i + 1) + 1
                else
                    call problems%add(line, where//': the group &'//group_name//' (line '// &
                                      integer_text(g%line)//') is not closed before "'// &
                                      shown(text, i)//'": end it with /')
                end if
                return
            end select
            if (.not. is_letter(text(i:i))) then
                call problems%add(line, where//': expected a variable name, found "'// &
                                  shown(text, i)//'"')
                call skip_token(text, i, line)
                cycle
            end if
            name_stop = name_end(text, i)
            call add_name(g, text(i:name_stop), line)
            i = name_stop + 1
            call skip_blanks(text, i, line, commas=.false.)
            if (i <= len(text)) then
                if (text(i:i) == '(') call read_subscript(text, i, line, g, problems, where)
            end if
            if (i > len(text)) exit
            if (text(i:i) /= '=') then
                call problems%add(line, where//': expected "=" after '// &
                                  trim(g%name(g%count))//', found "'//shown(text, i)//'"')
                g%usable(g%count) = .false.
            else
                i = i + 1
            end if
            g%first(g%count) = g%values + 1
            call scan_values(text, i, line, g, problems, where)
            g%last(g%count) = g%values
        end do
        call problems%add(line, where//': the group &'//group_name//' (line '// &
                          integer_text(g%line)//') is not closed: end it with /')
    end subroutine scan_body

    !> `(i)` or `(i:j)` after a name; a problem marks the assignment unusable.
    subroutine read_subscript(text, i, line, g, problems, where)
        character(len=*), intent(in) :: text, where
        integer, intent(inout) :: i, line
        type(group_scan), intent(inout) :: g
        type(problem_list), intent(inout) :: problems
        integer :: close_at
        integer(int64) :: low, high
        logical :: ok, section
        close_at = index(text(i:min(len(text), i + 80)), ')')
        ok = close_at > 0
        if (ok) ok = index(text(i:i + close_at - 1), achar(10)) == 0
        if (ok) then
            close_at = i + close_at - 1
            call parse_subscript(text(i + 1:close_at - 1), low, high, section, ok)
        end if
        if (.not. ok) then
            call problems%add(line, where//', variable '//trim(g%name(g%count))// &
                              ': bad subscript "'//shown(text, i)//'"; write '// &
                              trim(g%name(g%count))//'(i) = value or '// &
                              trim(g%name(g%count))//'(i:j) = values')
            g%usable(g%count) = .false.
            do while (i <= len(text))
                if (text(i:i) == ')' .or. scan(text(i:i), '=/'//achar(10)) > 0) exit
                i = i + 1
            end do
            if (i <= len(text)) then
                if (text(i:i) == ')') i = i + 1
            end if
        else
            g%indexed(g%count) = .true.
            g%section(g%count) = section
            g%low(g%count) = low
            g%high(g%count) = high
            i = close_at + 1
        end if
        call skip_blanks(text, i, line, commas=.false.)
    end subroutine read_subscript

    !> `i` or `i:j` (blanks allowed around each part), whole numbers below 10^15.
    pure subroutine parse_subscript(inside, low, high, section, ok)
        character(len=*), intent(in) :: inside
        integer(int64), intent(out) :: low, high
        logical, intent(out) :: section, ok
        integer :: colon
        colon = index(inside, ':')
        section = colon > 0
        if (section) then
            call whole(inside(:colon - 1), low, ok)
            if (ok) call whole(inside(colon + 1:), high, ok)
        else
            call whole(inside, low, ok)
            high = low
        end if
    contains
        pure subroutine whole(part, value, ok)
            character(len=*), intent(in) :: part
            integer(int64), intent(out) :: value
            logical, intent(out) :: ok
            character(len=len(part)) :: word
            integer :: ios, first
            value = 0
            word = adjustl(part)
            first = 1
            if (word(1:min(1, len(word))) == '-' .or. word(1:min(1, len(word))) == '+') first = 2
            ok = len_trim(word) >= first .and. len_trim(word) <= 15
            if (.not. ok) return
            ok = verify(word(first:len_trim(word)), '0123456789') == 0
            if (.not. ok) return
            read (word, *, iostat=ios) value
            ok = ios == 0
        end subroutine whole
    end subroutine parse_subscript

    !> The values of one assignment: up to the next `name =`, the group's end or a
    !! group start. A syntax problem marks the assignment unusable.
    subroutine scan_values(text, i, line, g, problems, where)
        character(len=*), intent(in) :: text, where
        integer, intent(inout) :: i, line
        type(group_scan), intent(inout) :: g
        type(problem_list), intent(inout) :: problems
        integer :: commas, j, r
        logical :: null, closed
        commas = 1                      ! a comma straight after '=' is a null first value
        do
            call skip_blanks(text, i, line, commas=.false.)
            if (i > len(text)) return
            select case (text(i:i))
            case (',')
                commas = commas + 1
                if (commas > 1) call add_value(g, i, i - 1, 1, line, .false.)
                i = i + 1
                cycle
            case ('/', '&', '$')
                return
            case ('=')
                call problems%add(line, where//', variable '//trim(g%name(g%count))// &
                                  ': "=" without a variable name before it')
                g%usable(g%count) = .false.
                i = i + 1
                cycle
            end select
            if (is_letter(text(i:i))) then
                if (starts_assignment(text, i)) return
            end if
            commas = 0
            call repeat_prefix(text, i, line, g, problems, where, r, null)
            if (null) then
                call add_value(g, i, i - 1, r, line, .false.)    ! r* : r null values
            else if (text(i:i) == '''' .or. text(i:i) == '"') then
                call string_value(text, i, line, g, problems, where, r, closed)
                if (.not. closed) return
            else
                j = i
                do while (j <= len(text))
                    if (ends_value(iachar(text(j:j)))) exit
                    j = j + 1
                end do
                call add_value(g, i, j - 1, r, line, .false.)
                i = j
            end if
        end do
    end subroutine scan_values

    !> A repeat count `r*` at i: i moves past it; `null` when no value follows (r*
    !! then a separator). r = 1 without a count.
    subroutine repeat_prefix(text, i, line, g, problems, where, r, null)
        character(len=*), intent(in) :: text, where
        integer, intent(inout) :: i
        integer, intent(in) :: line
        type(group_scan), intent(inout) :: g
        type(problem_list), intent(inout) :: problems
        integer, intent(out) :: r
        logical, intent(out) :: null
        integer :: j, status
        r = 1
        null = .false.
        j = i
        do while (j <= len(text))
            if (text(j:j) < '0' .or. text(j:j) > '9') exit
            j = j + 1
        end do
        if (j == i .or. j > len(text)) return
        if (text(j:j) /= '*') return
        call integer_from_text(text(i:j - 1), r, status)
        if (status /= text_ok .or. r < 1) then
            call problems%add(line, where//', variable '//trim(g%name(g%count))// &
                              ': "'//shown(text, i)//'" is not a valid repeat count; '// &
                              'r*value needs a whole number 1 <= r <= '//integer_text(huge(1)))
            g%usable(g%count) = .false.
            r = 1
        end if
        i = j + 1
        if (i > len(text)) then
            null = .true.
        else
            null = ends_value(iachar(text(i:i))) .and. text(i:i) /= '='
        end if
    end subroutine repeat_prefix

    !> The string value whose opening quote is at i; `closed` is false when it has no
    !! closing quote (a problem; i moves to the end of the text).
    subroutine string_value(text, i, line, g, problems, where, r, closed)
        character(len=*), intent(in) :: text, where
        integer, intent(inout) :: i, line
        type(group_scan), intent(inout) :: g
        type(problem_list), intent(inout) :: problems
        integer, intent(in) :: r
        logical, intent(out) :: closed
        integer :: first_line, opening, last
        first_line = line
        opening = i
        call skip_string(text, i, line, last)
        closed = last > 0
        if (closed) then
            call add_value(g, opening + 1, last - 1, r, first_line, .true.)
        else
            call problems%add(first_line, where//', variable '//trim(g%name(g%count))// &
                              ': the string starting "'//shown(text, opening)// &
                              '" has no closing quote')
            g%usable(g%count) = .false.
            i = len(text) + 1
        end if
    end subroutine string_value

    !> Does a name at i start an assignment: `name =` or `name(...) =` on this line?
    pure logical function starts_assignment(text, i)
        character(len=*), intent(in) :: text
        integer, intent(in) :: i
        integer :: j, close_at
        starts_assignment = .false.
        j = name_end(text, i) + 1
        do while (j <= len(text))
            if (scan(text(j:j), blanks) == 0) exit
            j = j + 1
        end do
        if (j > len(text)) return
        if (text(j:j) == '(') then
            close_at = scan(text(j:min(len(text), j + 80)), ')='//achar(10))
            if (close_at == 0) return
            j = j + close_at - 1
            if (text(j:j) == achar(10)) return
            starts_assignment = text(j:j) == '='       ! a broken subscript: name(1 =
            if (starts_assignment) return
            j = j + 1
            do while (j <= len(text))
                if (scan(text(j:j), blanks) == 0) exit
                j = j + 1
            end do
            if (j > len(text)) return
        end if
        starts_assignment = text(j:j) == '='
    end function starts_assignment

    !> Skip the string whose opening quote is at i: i moves past its closing quote;
    !! `last` is the closing quote's position (0 when there is none: i moves to the end).
    pure subroutine skip_string(text, i, line, last)
        character(len=*), intent(in) :: text
        integer, intent(inout) :: i, line
        integer, intent(out) :: last
        character :: quote
        quote = text(i:i)
        i = i + 1
        last = 0
        do while (i <= len(text))
            if (text(i:i) == achar(10)) then
                line = line + 1
            else if (text(i:i) == quote) then
                if (i < len(text)) then
                    if (text(i + 1:i + 1) == quote) then
                        i = i + 2
                        cycle
                    end if
                end if
                last = i
                i = i + 1
                return
            end if
            i = i + 1
        end do
    end subroutine skip_string

    !> Skip a stray token (a string as a whole) after a problem.
    pure subroutine skip_token(text, i, line)
        character(len=*), intent(in) :: text
        integer, intent(inout) :: i, line
        integer :: last
        if (text(i:i) == '''' .or. text(i:i) == '"') then
            call skip_string(text, i, line, last)
            return
        end if
        i = i + 1
        do while (i <= len(text))
            if (scan(text(i:i), value_ends//'&$''"') > 0) exit
            i = i + 1
        end do
    end subroutine skip_token

    subroutine add_name(g, name, at_line)
        type(group_scan), intent(inout) :: g
        character(len=*), intent(in) :: name
        integer, intent(in) :: at_line
        if (g%count == size(g%name)) then
            g%name = [g%name, g%name]
            g%name_line = [g%name_line, g%name_line]
            g%usable = [g%usable, g%usable]
            g%indexed = [g%indexed, g%indexed]
            g%section = [g%section, g%section]
            g%low = [g%low, g%low]
            g%high = [g%high, g%high]
            g%first = [g%first, g%first]
            g%last = [g%last, g%last]
        end if
        g%count = g%count + 1
        if (len(name) <= name_length) then
            g%name(g%count) = lower(name)
        else
            g%name(g%count) = lower(name(:name_length - 3))//'...'
        end if
        g%name_line(g%count) = at_line
        g%usable(g%count) = .true.
        g%indexed(g%count) = .false.
        g%section(g%count) = .false.
        g%low(g%count) = 1
        g%high(g%count) = 1
        g%first(g%count) = g%values + 1
        g%last(g%count) = g%values
    end subroutine add_name

    subroutine add_value(g, from, to, r, at_line, quoted)
        type(group_scan), intent(inout) :: g
        integer, intent(in) :: from, to, r, at_line
        logical, intent(in) :: quoted
        logical :: ok
        if (g%out_of_memory) return
        if (g%values == size(g%start)) then
            ok = .true.
            call grow(g%start)
            call grow(g%finish)
            call grow(g%repeat)
            call grow(g%value_line)
            call grow_logical(g%quoted)
            if (.not. ok) then
                g%out_of_memory = .true.
                return
            end if
        end if
        g%values = g%values + 1
        g%start(g%values) = from
        g%finish(g%values) = to
        g%repeat(g%values) = r
        g%value_line(g%values) = at_line
        g%quoted(g%values) = quoted
        g%total = g%total + r
    contains
        subroutine grow(array)
            integer, allocatable, intent(inout) :: array(:)
            integer, allocatable :: grown(:)
            integer :: status
            if (.not. ok .or. size(array) > g%values) return
            allocate (grown(2*size(array)), stat=status)
            ok = status == 0
            if (.not. ok) return
            grown(:size(array)) = array
            call move_alloc(grown, array)
        end subroutine grow
        subroutine grow_logical(array)
            logical, allocatable, intent(inout) :: array(:)
            logical, allocatable :: grown(:)
            integer :: status
            if (.not. ok .or. size(array) > g%values) return
            allocate (grown(2*size(array)), stat=status)
            ok = status == 0
            if (.not. ok) return
            grown(:size(array)) = array
            call move_alloc(grown, array)
        end subroutine grow_logical
    end subroutine add_value

    !> Add a problem; keep it if it is among the first `max_problems` by line.
    subroutine add_problem(self, line, text)
        class(problem_list), intent(inout) :: self
        integer, intent(in) :: line            !! its line (0: none)
        character(len=*), intent(in) :: text   !! its message
        integer :: k
        self%total = self%total + 1
        if (self%kept == max_problems) then
            if (line >= self%line(max_problems)) return
            k = max_problems
        else
            self%kept = self%kept + 1
            k = self%kept
        end if
        self%line(k) = line
        self%order(k) = self%total
        self%text(k)%text = text
        do while (k > 1)                      ! keep (line, order) sorted
            if (self%line(k - 1) <= self%line(k)) exit
            call swap(k - 1, k)
            k = k - 1
        end do
    contains
        subroutine swap(a, b)
            integer, intent(in) :: a, b
            character(len=:), allocatable :: held
            self%line([a, b]) = self%line([b, a])
            self%order([a, b]) = self%order([b, a])
            call move_alloc(self%text(a)%text, held)
            call move_alloc(self%text(b)%text, self%text(a)%text)
            call move_alloc(held, self%text(b)%text)
        end subroutine swap
    end subroutine add_problem

    !> Would a problem at `line` be kept? (If not, `count_one` counts it without
    !! building its message.)
    pure logical function wanted(self, line)
        class(problem_list), intent(in) :: self
        integer, intent(in) :: line   !! its line
        wanted = self%kept < max_problems
        if (.not. wanted) wanted = line < self%line(max_problems)
    end function wanted

    !> Count a problem that `wanted` says is not kept.
    pure subroutine count_one(self)
        class(problem_list), intent(inout) :: self
        self%total = self%total + 1
    end subroutine count_one

    !> The k-th kept message (1 <= k <= kept).
    pure function problem_message(self, k) result(text)
        class(problem_list), intent(in) :: self
        integer, intent(in) :: k      !! which
        character(len=:), allocatable :: text
        text = self%text(k)%text
    end function problem_message

    pure subroutine skip_comment(text, i)
        character(len=*), intent(in) :: text
        integer, intent(inout) :: i
        integer :: k
        k = index(text(i:), achar(10))
        if (k == 0) then
            i = len(text) + 1
        else
            i = i + k - 1
        end if
    end subroutine skip_comment

    pure subroutine skip_blanks(text, i, line, commas)
        character(len=*), intent(in) :: text
        integer, intent(inout) :: i, line
        logical, intent(in) :: commas
        do while (i <= len(text))
            if (text(i:i) == achar(10)) then
                line = line + 1
            else if (text(i:i) == '!') then
                call skip_comment(text, i)
                cycle
            else if (.not. (is_blank(iachar(text(i:i))) .or. &
                            (commas .and. text(i:i) == ','))) then
                return
            end if
            i = i + 1
        end do
    end subroutine skip_blanks

    !> Last position of the name starting at i (i - 1 if none).
    pure integer function name_end(text, i)
        character(len=*), intent(in) :: text
        integer, intent(in) :: i
        name_end = i
        do while (name_end <= len(text))
            if (.not. is_name_char(text(name_end:name_end))) exit
            name_end = name_end + 1
        end do
        name_end = name_end - 1
    end function name_end

    pure logical function is_letter(c)
        character, intent(in) :: c
        is_letter = (c >= 'a' .and. c <= 'z') .or. (c >= 'A' .and. c <= 'Z')
    end function is_letter

    pure logical function is_name_char(c)
        character, intent(in) :: c
        is_name_char = is_letter(c) .or. (c >= '0' .and. c <= '9') .or. c == '_'
    end function is_name_char

    !> The text from position i to the end of its line, at most `shown_length`
    !! characters, control characters escaped, for messages.
    pure function shown(text, i) result(part)
        character(len=*), intent(in) :: text
        integer, intent(in) :: i
        character(len=:), allocatable :: part
        integer :: j
        j = i
        do while (j <= len(text) .and. j < i + shown_length)
            if (text(j:j) == achar(10)) exit
            j = j + 1
        end do
        part = escape_text(text(i:j - 1))
        if (j <= len(text)) then
            if (text(j:j) /= achar(10)) part = part//'...'
        end if
    end function shown

end module brachistochrone_namelist_scan
