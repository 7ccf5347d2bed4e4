!> Reading and validating an endpoint table from a namelist file.
!!
!! The file holds the group below (other groups may follow; they are ignored):
!!
!!     &endpoints
!!       n   = 2                 ! number of endpoints, 1 <= n <= max_endpoints
!!       rho = 0.2, 0.5          ! radii, 0 < rho <= 1 (A is at radius 1)
!!       psi = 1.2, 0.1          ! angles in radians, 0 <= psi <= pi
!!       r0  = 0.2, 0.4          ! optional, per row: with r1, use the paper's secant
!!       r1  = 0.1, 0.2
!!       secant_tolerance = 1e-16 ! optional: the secant stops at |R_n - R_(n-1)| < this
!!       curve_points = 201       ! optional: points per curve for --curves (0: none)
!!       force = 'inverse_square' ! optional: the field (see `force_names`)
!!       exponent = 3.0           ! with force = 'power': F = mu/r^exponent, exponent > 1
!!     /
!!
!! The file is checked in three passes and every problem is reported (file, line,
!! group, variable, row, and what a valid value looks like): (1) `namelist_scan` finds
!! the group, its end, every name and value token, so unknown names, values that are not
!! numbers and a missing '/' are named precisely; (2) `n` sizes the arrays (n + 1, filled
!! with a sentinel) and gfortran's `read(nml=)` assigns the values, straight into
!! real(qp); (3) the arrays are checked for too few or too many values, NaN, Infinity,
!! ranges and r0/r1 pairs. Memory is proportional to the table.
module brachistochrone_endpoint_input
    use brachistochrone_kinds, only: qp, pi
    use brachistochrone_namelist_scan, only: group_scan, scan_group
    use brachistochrone_strings, only: integer_text, lower
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    public :: endpoint_table, message, read_endpoint_file, max_endpoints, group_name
    public :: variable_names, max_curve_points, force_names

    !> Largest table accepted (memory grows linearly: about 100 bytes per endpoint).
    integer, parameter :: max_endpoints = 10000000
    !> The namelist group read.
    character(len=*), parameter :: group_name = 'endpoints'
    !> Its variables.
    character(len=*), parameter :: variable_names = &
        'n, rho, psi, r0, r1, secant_tolerance, curve_points, force, exponent'
    !> The force fields `force` may name.
    character(len=*), parameter :: force_names = &
        "'inverse_square', 'power', 'logarithmic', 'harmonic', 'repulsive'"
    !> Most points per curve (`curve_points`); the fewest is 2 (A and B).
    integer, parameter :: max_curve_points = 100000
    !> Value no input can produce: marks an array element the namelist did not set.
    real(qp), parameter :: unset = -huge(1.0_qp)
    !> At most this many per-row messages are listed per variable; the rest are counted.
    integer, parameter :: max_row_messages = 20

    !> One message per problem found in the input.
    type :: message
        character(len=:), allocatable :: text !! the complete message
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
        integer :: curve_points = 0               !! points per curve for --curves (0: none)
        !> The force field: 'inverse_square' (the fast path), 'power', 'logarithmic',
        !! 'harmonic' (the general engine)
        character(len=:), allocatable :: force
        real(qp) :: exponent = 0.0_qp             !! n of F = mu/r^n for force = 'power'
        type(message), allocatable :: errors(:)   !! every problem found; empty if valid
    end type endpoint_table

contains

    !> Read `path` into `table`. On return `size(table%errors) == 0` when the table is
    !! valid; otherwise each element is one complete message and the arrays are empty.
    subroutine read_endpoint_file(path, table)
        character(len=*), intent(in) :: path       !! namelist file
        type(endpoint_table), intent(out) :: table !! the table and its problems
        character(len=:), allocatable :: text
        type(group_scan) :: scan
        integer :: unit, ios, n, a_rho, a_psi, a_r0, a_r1
        character(len=512) :: io_message
        real(qp), allocatable :: rho(:), psi(:), r0(:), r1(:)
        real(qp) :: secant_tolerance
        integer :: curve_points
        character(len=32) :: force
        real(qp) :: exponent
        namelist /endpoints/ n, rho, psi, r0, r1, secant_tolerance, curve_points, force, &
            exponent

        table%path = path
        allocate (table%errors(0))
        call read_text(path, text, ios, io_message)
        if (ios /= 0) then
            call add(table, path//': cannot read the file: '//trim(io_message))
            return
        end if

        ! pass 1: the group's syntax
        scan = scan_group(text, group_name)
        if (.not. scan%found) then
            call add(table, path//': no namelist group &'//group_name//' found'// &
                     trim(merge(' (the file is empty)', '                    ', &
                                len_trim(text) == 0))// &
                     '; the file must contain a group like  &'//group_name// &
                     ' n = 2, rho = 0.5, 0.9, psi = 1.0, 0.4 /')
            return
        end if
        if (len(scan%problem) > 0) then
            call add(table, at(path, scan%problem_line)//'group &'//group_name//': '// &
                     scan%problem)
            return
        end if
        call check_tokens(table, text, scan, n)
        if (size(table%errors) > 0) return

        ! pass 2: gfortran assigns the values
        allocate (rho(n + 1), psi(n + 1), r0(n + 1), r1(n + 1))
        rho = unset
        psi = unset
        r0 = unset
        r1 = unset
        secant_tolerance = 1.0e-16_qp
        curve_points = 0
        force = 'inverse_square'
        exponent = unset
        open (newunit=unit, file=path, status='old', action='read', iostat=ios, &
              iomsg=io_message)
        if (ios == 0) read (unit, nml=endpoints, iostat=ios, iomsg=io_message)
        close (unit)
        if (ios /= 0) then
            call add(table, at(path, scan%line)//'group &'//group_name// &
                     ': the namelist read failed: '//trim(io_message))
            return
        end if

        ! pass 3: counts, values, ranges
        a_rho = assignment_of(scan, 'rho')
        a_psi = assignment_of(scan, 'psi')
        a_r0 = assignment_of(scan, 'r0')
        a_r1 = assignment_of(scan, 'r1')
        call check_array(table, text, scan, 'rho', a_rho, rho, n, .true.)
        call check_array(table, text, scan, 'psi', a_psi, psi, n, .true.)
        call check_array(table, text, scan, 'r0', a_r0, r0, n, .false.)
        call check_array(table, text, scan, 'r1', a_r1, r1, n, .false.)
        if (.not. ieee_is_finite(secant_tolerance) .or. secant_tolerance <= 0.0_qp) then
            call add(table, at(path, line_of(scan, 'secant_tolerance'))//'group &'// &
                     group_name//', variable secant_tolerance: must be a positive '// &
                     'number, for example 1e-16')
        end if
        if (curve_points /= 0 .and. (curve_points < 2 .or. curve_points > max_curve_points)) &
            then
            call add(table, at(path, line_of(scan, 'curve_points'))//'group &'// &
                     group_name//', variable curve_points = '//integer_text(curve_points)// &
                     ': must be 0 (no curves) or 2 <= curve_points <= '// &
                     integer_text(max_curve_points)//' (points per curve, A and B included)')
        end if
        if (trim(force) == 'repulsive') then
            call check_rows(table, text, scan, 'rho', a_rho, rho, n, 'must satisfy rho >= 1'// &
                            ' (force = ''repulsive'': paths move outward from A at radius 1)', &
                            in_repulsive_rho_range)
        else
            call check_rows(table, text, scan, 'rho', a_rho, rho, n, &
                            'must satisfy 0 < rho <= 1 (A is at radius 1)', in_rho_range)
        end if
        call check_rows(table, text, scan, 'psi', a_psi, psi, n, &
                        'must satisfy 0 <= psi <= pi radians (by symmetry use '// &
                        '2*pi - psi for an angle beyond pi)', in_psi_range)
        call check_pairs(table, text, scan, r0, r1, n, a_r0, a_r1)
        call check_force(table, scan, force, exponent, any(r0(1:n) /= unset), curve_points)
        if (size(table%errors) > 0) return

        table%n = n
        table%rho = rho(1:n)
        table%psi = psi(1:n)
        table%has_estimates = r0(1:n) /= unset
        table%r0 = merge(r0(1:n), 0.0_qp, table%has_estimates)
        table%r1 = merge(r1(1:n), 0.0_qp, table%has_estimates)
        table%secant_tolerance = secant_tolerance
        table%curve_points = curve_points
        table%force = trim(force)
        table%exponent = merge(exponent, 0.0_qp, exponent /= unset)
    end subroutine read_endpoint_file

    !> The field and what goes with it: exponent only (and always) with 'power', the
    !! paper's secant method and curves only with 'inverse_square' (its fast path).
    subroutine check_force(table, scan, force, exponent, estimates, curve_points)
        type(endpoint_table), intent(inout) :: table
        type(group_scan), intent(in) :: scan
        character(len=*), intent(in) :: force
        real(qp), intent(in) :: exponent
        logical, intent(in) :: estimates
        integer, intent(in) :: curve_points
        character(len=:), allocatable :: where
        where = at(table%path, line_of(scan, 'force'))//'group &'//group_name
        if (index(force_names, "'"//trim(force)//"'") == 0) then
            call add(table, where//', variable force = '''//trim(force)//''': unknown '// &
                     'field; use one of '//force_names)
            return
        end if
        if (trim(force) == 'power') then
            if (exponent == unset) then
                call add(table, where//', variable exponent: is missing; force = ''power'' '// &
                         'needs the exponent n of F = mu/r^n, n > 1, for example  exponent = 3')
            else if (.not. ieee_is_finite(exponent) .or. exponent <= 1.0_qp) then
                call add(table, at(table%path, line_of(scan, 'exponent'))//'group &'// &
                         group_name//', variable exponent: must be a number > 1 (n = 1 is '// &
                         'force = ''logarithmic'')')
            end if
        else if (exponent /= unset) then
            call add(table, at(table%path, line_of(scan, 'exponent'))//'group &'// &
                     group_name//', variable exponent: applies to force = ''power'' only')
        end if
        if (trim(force) /= 'inverse_square') then
            if (estimates) call add(table, where//': r0, r1 (the paper''s secant method) '// &
                                    'apply to force = ''inverse_square'' only; leave them out')
            if (curve_points /= 0) call add(table, where//': curve_points: curves are '// &
                                            'sampled for force = ''inverse_square'' only')
        end if
    end subroutine check_force

    !> Names known, value tokens well formed, n present and in range.
    subroutine check_tokens(table, text, scan, n)
        type(endpoint_table), intent(inout) :: table
        character(len=*), intent(in) :: text
        type(group_scan), intent(in) :: scan
        integer, intent(out) :: n
        integer :: a, t, ios, star, repeat, shown, count_points
        character(len=:), allocatable :: name, token, value
        real(qp) :: x
        logical :: is_integer

        n = 0
        shown = 0
        do a = 1, scan%count
            name = trim(scan%name(a))
            if (index(', '//variable_names//',', ', '//name//',') == 0) then
                call add(table, at(table%path, scan%name_line(a))//'group &'//group_name// &
                         ': unknown variable "'//name//'"; the variables are '// &
                         variable_names)
                cycle
            end if
            is_integer = name == 'n' .or. name == 'curve_points'
            if (name == 'force') then
                if (scan%last(a) /= scan%first(a)) then
                    call add(table, at(table%path, scan%name_line(a))//'group &'// &
                             group_name//', variable force: needs exactly one quoted name, '// &
                             'for example  force = ''harmonic''')
                else
                    token = text(scan%start(scan%first(a)):scan%finish(scan%first(a)))
                    if (len(token) < 2 .or. index('''"', token(1:1)) == 0 .or. &
                        token(len(token):) /= token(1:1)) then
                        call add(table, at(table%path, scan%name_line(a))//'group &'// &
                                 group_name//', variable force: '//token//' must be quoted, '// &
                                 'for example  force = ''harmonic''')
                    end if
                end if
                cycle
            end if
            do t = scan%first(a), scan%last(a)
                token = text(scan%start(t):scan%finish(t))
                value = token
                star = index(token, '*')
                if (star > 0) then
                    read (token(:star - 1), *, iostat=ios) repeat
                    if (ios /= 0 .or. repeat < 1 .or. &
                        verify(token(:star - 1), '0123456789') /= 0) then
                        call bad_value('a repeat count r*value needs a whole number r >= 1')
                        cycle
                    end if
                    value = token(star + 1:)
                end if
                if (len(value) == 0) cycle            ! null value: leaves the default
                if (is_integer) then
                    if (verify(value, '+-0123456789') /= 0) then
                        call bad_value('write a whole number, for example  '//name// &
                                       ' = '//trim(merge('5  ', '201', name == 'n')))
                        cycle
                    end if
                else
                    read (value, *, iostat=ios) x
                    if (ios /= 0 .or. scan_bad_real(value)) then
                        call bad_value('write a real number such as 0.25 or 1.5e-3')
                        cycle
                    end if
                end if
            end do
        end do
        if (size(table%errors) > 0) return

        a = assignment_of(scan, 'n')
        if (a == 0) then
            call add(table, at(table%path, scan%line)//'group &'//group_name// &
                     ', variable n: is missing; set it to the number of endpoints, for '// &
                     'example  n = 5')
            return
        end if
        if (scan%last(a) /= scan%first(a)) then
            call add(table, at(table%path, scan%name_line(a))//'group &'//group_name// &
                     ', variable n: needs exactly one value, for example  n = 5')
            return
        end if
        token = text(scan%start(scan%first(a)):scan%finish(scan%first(a)))
        read (token, *, iostat=ios) n
        if (ios /= 0 .or. n < 1 .or. n > max_endpoints) then
            call add(table, at(table%path, scan%name_line(a))//'group &'//group_name// &
                     ', variable n: '//token//' is out of range; it must be 1 <= n <= '// &
                     integer_text(max_endpoints))
        end if

        a = assignment_of(scan, 'curve_points')
        if (a > 0) then
            if (scan%last(a) /= scan%first(a)) then
                call add(table, at(table%path, scan%name_line(a))//'group &'//group_name// &
                         ', variable curve_points: needs exactly one value, for example  '// &
                         'curve_points = 201')
            else
                token = text(scan%start(scan%first(a)):scan%finish(scan%first(a)))
                read (token, *, iostat=ios) count_points
                if (len(token) > 0 .and. ios /= 0) then
                    call add(table, at(table%path, scan%name_line(a))//'group &'// &
                             group_name//', variable curve_points: '//token//' is out of '// &
                             'range; it must be 0 (no curves) or 2 <= curve_points <= '// &
                             integer_text(max_curve_points))
                end if
            end if
        end if

    contains

        subroutine bad_value(advice)
            character(len=*), intent(in) :: advice
            shown = shown + 1
            if (shown > max_row_messages) return
            call add(table, at(table%path, scan%token_line(t))//'group &'//group_name// &
                     ', variable '//name//': "'//token//'" is not a valid value; '//advice)
        end subroutine bad_value

    end subroutine check_tokens

    !> Tokens list-directed input accepts as reals but no user means as one.
    pure logical function scan_bad_real(value)
        character(len=*), intent(in) :: value
        scan_bad_real = verify(lower(value), '+-.0123456789edq') /= 0 .and. &
                        .not. any(lower(value) == [character(len=9) :: 'nan', 'inf', &
                                  'infinity', '+inf', '-inf', '+infinity', '-infinity'])
    end function scan_bad_real

    !> Count and finiteness of one array variable.
    subroutine check_array(table, text, scan, name, a, values, n, required)
        type(endpoint_table), intent(inout) :: table
        character(len=*), intent(in) :: text, name
        type(group_scan), intent(in) :: scan
        integer, intent(in) :: a, n
        real(qp), intent(in) :: values(:)
        logical, intent(in) :: required
        integer :: count_set, i, shown

        count_set = count(values(1:n) /= unset)
        if (a == 0 .and. count_set == 0) then
            if (required) call add(table, at(table%path, scan%line)//'group &'// &
                                   group_name//', variable '//name//': is missing; give '// &
                                   'n values, for example  '//name//' = 0.5, 0.9')
            return
        end if
        if (values(n + 1) /= unset) then
            call add(table, at(table%path, line_of(scan, name))//'group &'//group_name// &
                     ', variable '//name//': has more than n = '//integer_text(n)// &
                     ' values; give exactly n values or raise n')
        end if
        if (required .and. count_set < n) then
            call add(table, at(table%path, line_of(scan, name))//'group &'//group_name// &
                     ', variable '//name//': has '//integer_text(count_set)// &
                     ' values but n = '//integer_text(n)//'; give exactly n values')
        end if
        shown = 0
        do i = 1, n
            if (values(i) == unset .or. ieee_is_finite(values(i))) cycle
            shown = shown + 1
            if (shown <= max_row_messages) then
                call add(table, at(table%path, row_line(text, scan, a, i))//'group &'// &
                         group_name//', variable '//name//'('//integer_text(i)//'): is not '// &
                         'a finite number (NaN or Infinity); give a real number')
            end if
        end do
        call add_more(table, name, shown)
    end subroutine check_array

    !> One range check over the rows of a variable.
    subroutine check_rows(table, text, scan, name, a, values, n, rule, valid)
        type(endpoint_table), intent(inout) :: table
        character(len=*), intent(in) :: text, name, rule
        type(group_scan), intent(in) :: scan
        integer, intent(in) :: a, n
        real(qp), intent(in) :: values(:)
        interface
            pure logical function valid(x)
                import :: qp
                real(qp), intent(in) :: x
            end function valid
        end interface
        integer :: i, shown
        character(len=48) :: shown_value
        shown = 0
        do i = 1, n
            if (values(i) == unset .or. .not. ieee_is_finite(values(i))) cycle
            if (valid(values(i))) cycle
            shown = shown + 1
            if (shown > max_row_messages) cycle
            write (shown_value, '(g0.12)') values(i)
            call add(table, at(table%path, row_line(text, scan, a, i))//'group &'// &
                     group_name//', variable '//name//'('//integer_text(i)//') = '// &
                     trim(adjustl(shown_value))//': '//rule)
        end do
        call add_more(table, name, shown)
    end subroutine check_rows

    pure logical function in_rho_range(x)
        real(qp), intent(in) :: x
        in_rho_range = x > 0.0_qp .and. x <= 1.0_qp
    end function in_rho_range

    pure logical function in_repulsive_rho_range(x)
        real(qp), intent(in) :: x
        in_repulsive_rho_range = x >= 1.0_qp
    end function in_repulsive_rho_range

    pure logical function in_psi_range(x)
        real(qp), intent(in) :: x
        in_psi_range = x >= 0.0_qp .and. x <= pi
    end function in_psi_range

    !> r0 and r1 come in pairs, per row.
    subroutine check_pairs(table, text, scan, r0, r1, n, a_r0, a_r1)
        type(endpoint_table), intent(inout) :: table
        character(len=*), intent(in) :: text
        type(group_scan), intent(in) :: scan
        real(qp), intent(in) :: r0(:), r1(:)
        integer, intent(in) :: n, a_r0, a_r1
        integer :: i, shown
        shown = 0
        do i = 1, n
            if ((r0(i) == unset) .eqv. (r1(i) == unset)) cycle
            shown = shown + 1
            if (shown > max_row_messages) cycle
            if (r1(i) == unset) then
                call add(table, at(table%path, row_line(text, scan, a_r0, i))//'group &'// &
                         group_name//', variable r1('//integer_text(i)//'): is missing; give '// &
                         'both r0 and r1 for a row (the paper''s secant method) or neither '// &
                         '(the bracketing solver)')
            else
                call add(table, at(table%path, row_line(text, scan, a_r1, i))//'group &'// &
                         group_name//', variable r0('//integer_text(i)//'): is missing; give '// &
                         'both r0 and r1 for a row (the paper''s secant method) or neither '// &
                         '(the bracketing solver)')
            end if
        end do
        call add_more(table, 'r0, r1', shown)
    end subroutine check_pairs

    subroutine add_more(table, name, shown)
        type(endpoint_table), intent(inout) :: table
        character(len=*), intent(in) :: name
        integer, intent(in) :: shown
        if (shown > max_row_messages) then
            call add(table, table%path//': group &'//group_name//', variable '//name// &
                     ': ... and '//integer_text(shown - max_row_messages)//' more rows like these')
        end if
    end subroutine add_more

    !> The last unsubscripted assignment of a variable (0 if none).
    pure integer function assignment_of(scan, name)
        type(group_scan), intent(in) :: scan
        character(len=*), intent(in) :: name
        integer :: a
        assignment_of = 0
        do a = 1, scan%count
            if (trim(scan%name(a)) == name .and. .not. scan%indexed(a)) assignment_of = a
        end do
    end function assignment_of

    !> Line of the first assignment of a variable, subscripted or not (0 if none).
    pure integer function line_of(scan, name)
        type(group_scan), intent(in) :: scan
        character(len=*), intent(in) :: name
        integer :: a
        line_of = 0
        do a = scan%count, 1, -1
            if (trim(scan%name(a)) == name) line_of = scan%name_line(a)
        end do
    end function line_of

    !> Line holding row i of the variable assigned by assignment a (0 if unknown).
    pure integer function row_line(text, scan, a, i)
        character(len=*), intent(in) :: text
        type(group_scan), intent(in) :: scan
        integer, intent(in) :: a, i
        row_line = 0
        if (a > 0) row_line = scan%value_line(text, a, i)
    end function row_line

    !> "file:line: " (or "file: " when the line is unknown).
    pure function at(path, line) result(prefix)
        character(len=*), intent(in) :: path
        integer, intent(in) :: line
        character(len=:), allocatable :: prefix
        if (line > 0) then
            prefix = path//':'//integer_text(line)//': '
        else
            prefix = path//': '
        end if
    end function at

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

end module brachistochrone_endpoint_input
