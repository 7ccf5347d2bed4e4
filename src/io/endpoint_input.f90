!> Reading and validating an endpoint table from a namelist file.
!!
!! The file holds one group (more may follow; they are ignored here):
!!
!!     &endpoints
!!       n   = 2                 ! number of endpoints, 1 <= n <= max_endpoints
!!       rho = 0.2, 0.5          ! radii, 0 < rho <= 1 (A is at radius 1)
!!       psi = 1.2, 0.1          ! angles in radians, 0 <= psi <= pi
!!       r0  = 0.2, 0.4          ! optional, per row: with r1, use the paper's secant
!!       r1  = 0.1, 0.2
!!       secant_tolerance = 1e-16 ! optional: the secant stops at |R_n - R_(n-1)| < this
!!     /
!!
!! gfortran's own namelist diagnostics are poor (a missing group, a missing '/' and an
!! empty file all read as "End of file"), so the file is first scanned here: the group
!! and `n` are located, the arrays are sized n+1 and filled with a sentinel, and after
!! the read every array is checked for too few or too many values. Every problem found
!! is reported (file, group, variable, line, what a valid value looks like); the caller
!! decides what to do with them. Values are read straight into real(qp).
module endpoint_input
    use brachistochrone_kinds, only: qp, pi
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    public :: endpoint_table, read_endpoint_file, max_endpoints, group_name

    !> Largest table accepted (memory grows linearly: about 100 bytes per endpoint).
    integer, parameter :: max_endpoints = 10000000
    !> The namelist group read.
    character(len=*), parameter :: group_name = 'endpoints'
    !> Value no input can produce: marks an array element the namelist did not set.
    real(qp), parameter :: unset = -huge(1.0_qp)
    !> At most this many per-row messages are listed; the rest are counted.
    integer, parameter :: max_row_messages = 20

    !> One message per problem found in the input.
    type :: message
        character(len=:), allocatable :: text
    end type message

    !> The validated endpoint table.
    type :: endpoint_table
        character(len=:), allocatable :: path  !! file it was read from
        integer :: n = 0                       !! number of endpoints
        real(qp), allocatable :: rho(:)        !! endpoint radii
        real(qp), allocatable :: psi(:)        !! endpoint angles (radians)
        real(qp), allocatable :: r0(:)         !! first secant estimate (if has_estimates)
        real(qp), allocatable :: r1(:)         !! second secant estimate (if has_estimates)
        logical, allocatable :: has_estimates(:) !! row uses the paper's secant method
        real(qp) :: secant_tolerance = 1.0e-16_qp !! the paper's stopping rule
        type(message), allocatable :: errors(:)   !! every problem found; empty if valid
    end type endpoint_table

contains

    !> Read `path` into `table`. On return `size(table%errors) == 0` when the table is
    !! valid; otherwise each element is one complete message and the arrays may be empty.
    subroutine read_endpoint_file(path, table)
        character(len=*), intent(in) :: path      !! namelist file
        type(endpoint_table), intent(out) :: table !! the table and its problems
        character(len=:), allocatable :: text
        integer :: unit, ios, n, n_line, group_line, i, rows
        character(len=512) :: io_message
        real(qp), allocatable :: rho(:), psi(:), r0(:), r1(:)
        real(qp) :: secant_tolerance
        namelist /endpoints/ n, rho, psi, r0, r1, secant_tolerance

        table%path = path
        allocate (table%errors(0))
        call read_text(path, text, ios, io_message)
        if (ios /= 0) then
            call add(table, path//': cannot read the file: '//trim(io_message))
            return
        end if
        group_line = find_group(text)
        if (group_line == 0) then
            call add(table, path//': no namelist group &'//group_name//' found; the file '// &
                     'must contain a group like  &'//group_name// &
                     ' n = 2, rho = 0.5, 0.9, psi = 1.0, 0.4 /')
            return
        end if
        call find_integer(text, 'n', n, n_line, ios)
        if (n_line == 0) then
            call add(table, located(path, group_line, 'n')//'is missing; set it to the '// &
                     'number of endpoints, for example  n = 5')
            return
        else if (ios /= 0) then
            call add(table, located(path, n_line, 'n')//'is not a whole number; write '// &
                     'for example  n = 5')
            return
        else if (n < 1 .or. n > max_endpoints) then
            call add(table, located(path, n_line, 'n')//'= '//int_text(n)// &
                     ' is out of range; it must be 1 <= n <= '//int_text(max_endpoints))
            return
        end if

        allocate (rho(n + 1), psi(n + 1), r0(n + 1), r1(n + 1))
        rho = unset
        psi = unset
        r0 = unset
        r1 = unset
        secant_tolerance = 1.0e-16_qp
        open (newunit=unit, file=path, status='old', action='read', iostat=ios, &
              iomsg=io_message)
        if (ios == 0) read (unit, nml=endpoints, iostat=ios, iomsg=io_message)
        close (unit)
        if (ios /= 0) then
            call add(table, path//': group &'//group_name//' (line '// &
                     int_text(group_line)//'): the namelist could not be read: '// &
                     trim(io_message)//'. Check the names (n, rho, psi, r0, r1, '// &
                     'secant_tolerance), that values are numbers separated by commas or '// &
                     'blanks, and that the group ends with /')
            return
        end if

        call check_array(table, text, 'rho', rho, n, .true.)
        call check_array(table, text, 'psi', psi, n, .true.)
        call check_array(table, text, 'r0', r0, n, .false.)
        call check_array(table, text, 'r1', r1, n, .false.)
        if (.not. ieee_is_finite(secant_tolerance) .or. secant_tolerance <= 0.0_qp) then
            call add(table, located(path, find_line(text, 'secant_tolerance'), &
                     'secant_tolerance')//'must be a positive number, for example 1e-16')
        end if

        rows = 0
        do i = 1, n
            if (rho(i) /= unset .and. ieee_is_finite(rho(i)) .and. &
                (rho(i) <= 0.0_qp .or. rho(i) > 1.0_qp)) then
                call add_row(table, text, 'rho', i, rho(i), &
                             'must satisfy 0 < rho <= 1 (A is at radius 1)', rows)
            end if
            if (psi(i) /= unset .and. ieee_is_finite(psi(i)) .and. &
                (psi(i) < 0.0_qp .or. psi(i) > pi)) then
                call add_row(table, text, 'psi', i, psi(i), &
                             'must satisfy 0 <= psi <= pi radians (by symmetry use '// &
                             '2*pi - psi for an angle beyond pi)', rows)
            end if
            if ((r0(i) == unset) .neqv. (r1(i) == unset)) then
                call add_row(table, text, merge('r1', 'r0', r1(i) == unset), i, 0.0_qp, &
                             'is missing: give both r0 and r1 for a row (the paper''s '// &
                             'secant method) or neither (the bracketing solver)', rows)
            end if
        end do
        if (rows > max_row_messages) then
            call add(table, path//': ... and '//int_text(rows - max_row_messages)// &
                     ' more problems of this kind')
        end if
        if (size(table%errors) > 0) return

        table%n = n
        table%rho = rho(1:n)
        table%psi = psi(1:n)
        table%has_estimates = r0(1:n) /= unset
        table%r0 = merge(r0(1:n), 0.0_qp, table%has_estimates)
        table%r1 = merge(r1(1:n), 0.0_qp, table%has_estimates)
        table%secant_tolerance = secant_tolerance
    end subroutine read_endpoint_file

    !> Count, finiteness and presence of one array variable.
    subroutine check_array(table, text, name, values, n, required)
        type(endpoint_table), intent(inout) :: table
        character(len=*), intent(in) :: text, name
        real(qp), intent(in) :: values(:)
        integer, intent(in) :: n
        logical, intent(in) :: required
        integer :: count_set, i, line, shown

        line = find_line(text, name)
        count_set = count(values(1:n) /= unset)
        if (line == 0) then
            if (required) call add(table, located(table%path, 0, name)//'is missing; '// &
                                   'give n values, for example  '//name//' = 0.5, 0.9')
            return
        end if
        if (values(n + 1) /= unset) then
            call add(table, located(table%path, line, name)//'has more than n = '// &
                     int_text(n)//' values; give exactly n values or raise n')
        end if
        if (required .and. count_set < n) then
            call add(table, located(table%path, line, name)//'has '//int_text(count_set)// &
                     ' values but n = '//int_text(n)//'; give exactly n values')
        end if
        shown = 0
        do i = 1, n
            if (values(i) /= unset .and. .not. ieee_is_finite(values(i))) then
                call add_row(table, text, name, i, 0.0_qp, &
                             'is not a finite number (NaN or Infinity); give a real number', &
                             shown)
            end if
        end do
    end subroutine check_array

    !> Messages about single rows, at most `max_row_messages` of them per file.
    subroutine add_row(table, text, name, row, value, problem, rows)
        type(endpoint_table), intent(inout) :: table
        character(len=*), intent(in) :: text, name, problem
        integer, intent(in) :: row
        real(qp), intent(in) :: value
        integer, intent(inout) :: rows
        character(len=64) :: shown
        rows = rows + 1
        if (rows > max_row_messages) return
        write (shown, '(g0.12)') value
        if (value == 0.0_qp) shown = ''
        call add(table, located(table%path, find_line(text, name), &
                 name//'('//int_text(row)//')')// &
                 trim(merge('= '//shown(1:40), repeat(' ', 42), len_trim(shown) > 0))// &
                 ' '//problem)
    end subroutine add_row

    !> "file:line: group &endpoints, variable v " prefix of a message.
    pure function located(path, line, name) result(prefix)
        character(len=*), intent(in) :: path, name
        integer, intent(in) :: line
        character(len=:), allocatable :: prefix
        if (line > 0) then
            prefix = path//':'//int_text(line)//': group &'//group_name//', variable '// &
                     name//' '
        else
            prefix = path//': group &'//group_name//', variable '//name//' '
        end if
    end function located

    subroutine add(table, text)
        type(endpoint_table), intent(inout) :: table
        character(len=*), intent(in) :: text
        table%errors = [table%errors, message(text)]
    end subroutine add

    !> Whole file as one string with new-line characters.
    subroutine read_text(path, text, ios, io_message)
        character(len=*), intent(in) :: path
        character(len=:), allocatable, intent(out) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: io_message
        integer :: unit, length
        text = ''
        open (newunit=unit, file=path, status='old', action='read', access='stream', &
              form='unformatted', iostat=ios, iomsg=io_message)
        if (ios /= 0) return
        inquire (unit=unit, size=length)
        if (length > 0) then
            text = repeat(' ', length)
            read (unit, iostat=ios, iomsg=io_message) text
        end if
        close (unit)
    end subroutine read_text

    !> Line (1-based) where `&endpoints` starts, 0 if absent. Comments are skipped.
    pure function find_group(text) result(line)
        character(len=*), intent(in) :: text
        integer :: line
        integer :: i, current
        logical :: in_comment
        line = 0
        current = 1
        in_comment = .false.
        do i = 1, len(text)
            if (text(i:i) == new_line('a')) then
                current = current + 1
                in_comment = .false.
            else if (text(i:i) == '!') then
                in_comment = .true.
            else if (.not. in_comment .and. (text(i:i) == '&' .or. text(i:i) == '$')) then
                if (i + len(group_name) <= len(text)) then
                    if (lower(text(i + 1:i + len(group_name))) == group_name) then
                        if (.not. is_name_char(text, i + len(group_name) + 1)) then
                            line = current
                            return
                        end if
                    end if
                end if
            end if
        end do
    end function find_group

    !> Line of the first `name =` inside the group (0 if absent).
    pure function find_line(text, name) result(line)
        character(len=*), intent(in) :: text, name
        integer :: line
        integer :: position
        call locate_assignment(text, name, position, line)
    end function find_line

    !> The integer after `name =`; line = 0 if there is no such assignment.
    subroutine find_integer(text, name, value, line, ios)
        character(len=*), intent(in) :: text, name
        integer, intent(out) :: value, line, ios
        integer :: position, finish
        value = 0
        ios = 0
        call locate_assignment(text, name, position, line)
        if (line == 0) return
        finish = position
        do while (finish <= len(text))
            if (scan(text(finish:finish), ',/!'//new_line('a')) > 0) exit
            finish = finish + 1
        end do
        read (text(position:finish - 1), *, iostat=ios) value
        if (ios == 0 .and. verify(trim(adjustl(text(position:finish - 1))), &
                                  '+-0123456789') /= 0) ios = 1
    end subroutine find_integer

    !> Position just after the '=' of `name =` (or `name(...) =`) within the group, and
    !! its line; line = 0 when absent. Skips comments and quoted strings.
    pure subroutine locate_assignment(text, name, position, line)
        character(len=*), intent(in) :: text, name
        integer, intent(out) :: position, line
        integer :: i, j, current, group_start
        logical :: in_comment, in_group
        character :: quote
        position = 0
        line = 0
        current = 1
        in_comment = .false.
        in_group = .false.
        quote = ' '
        group_start = 0
        i = 1
        do while (i <= len(text))
            if (text(i:i) == new_line('a')) then
                current = current + 1
                in_comment = .false.
            else if (in_comment) then
                continue
            else if (quote /= ' ') then
                if (text(i:i) == quote) quote = ' '
            else if (text(i:i) == '!') then
                in_comment = .true.
            else if (text(i:i) == '"' .or. text(i:i) == "'") then
                quote = text(i:i)
            else if (.not. in_group) then
                if (text(i:i) == '&' .or. text(i:i) == '$') then
                    if (i + len(group_name) <= len(text)) then
                        if (lower(text(i + 1:i + len(group_name))) == group_name .and. &
                            .not. is_name_char(text, i + len(group_name) + 1)) then
                            in_group = .true.
                            i = i + len(group_name)
                        end if
                    end if
                end if
            else if (text(i:i) == '/') then
                return
            else if (.not. is_name_char(text, i - 1) .and. i + len(name) - 1 <= len(text)) then
                if (lower(text(i:i + len(name) - 1)) == name .and. &
                    .not. is_name_char(text, i + len(name))) then
                    j = i + len(name)
                    do while (j <= len(text))
                        if (text(j:j) /= ' ') exit
                        j = j + 1
                    end do
                    if (j <= len(text)) then
                        if (text(j:j) == '(') j = index(text(j:), ')') + j
                    end if
                    do while (j <= len(text))
                        if (text(j:j) /= ' ') exit
                        j = j + 1
                    end do
                    if (j <= len(text)) then
                        if (text(j:j) == '=') then
                            position = j + 1
                            line = current
                            return
                        end if
                    end if
                end if
            end if
            i = i + 1
        end do
    end subroutine locate_assignment

    pure logical function is_name_char(text, i)
        character(len=*), intent(in) :: text
        integer, intent(in) :: i
        is_name_char = .false.
        if (i < 1 .or. i > len(text)) return
        is_name_char = scan(text(i:i), 'abcdefghijklmnopqrstuvwxyz' // &
                            'ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_') > 0
    end function is_name_char

    pure function lower(text) result(lowered)
        character(len=*), intent(in) :: text
        character(len=len(text)) :: lowered
        integer :: i, code
        lowered = text
        do i = 1, len(text)
            code = iachar(text(i:i))
            if (code >= iachar('A') .and. code <= iachar('Z')) lowered(i:i) = achar(code + 32)
        end do
    end function lower

    pure function int_text(value) result(text)
        integer, intent(in) :: value
        character(len=:), allocatable :: text
        character(len=24) :: buffer
        write (buffer, '(i0)') value
        text = trim(buffer)
    end function int_text

end module endpoint_input
