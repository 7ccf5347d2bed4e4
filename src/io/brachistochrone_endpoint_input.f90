!> Reading and validating an endpoint table from a namelist file (or stdin).
!!
!! The file holds the group below (other groups may come before or after it; they are
!! skipped):
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
!!       exponent = 3.0           ! with force = 'power': F = mu/r^n, exponent > 1
!!     /
!!
!! `brachistochrone_namelist_scan` is the only reader of the group's text (there is no
!! second parse by `read(nml=)` that could disagree): it records every assignment and
!! value with its line. This module converts each value's text exactly once
!! (`real_from_text`: correctly rounded to real(qp), the same bits as `read(text, *)`),
!! checks it and stores it, so the solver gets exactly the values that were checked.
!! Every problem of the file (syntax, names, values, counts, ranges, pairs) is found in
!! one pass and reported with file:line, variable, row and what a valid value looks
!! like; the first `max_problems` by line are listed and the rest counted. Memory is
!! sized from the values present (a row array is allocated only up to the largest row
!! a value sets, never from `n` alone); time is linear in the size of the file.
!! Control characters of the path and of quoted input are escaped in every message.
!!
!! The variables are one table (`variables`: name, kind, one value per row or one in
!! all, required, default, valid range or words, the rule as text for messages); a
!! new variable is a row there, its name in `variable_names` and a field of
!! `endpoint_table` set in `fill_table`. Checks between variables (r0 with r1, what
!! goes with `force`, rho's range for 'repulsive') are in `check_counts`,
!! `check_force` and `rule_of_rows`.
module brachistochrone_endpoint_input
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: iso_c_binding, only: c_int, c_size_t, c_char
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use brachistochrone_fields, only: field_names
    use brachistochrone_kinds, only: qp, pi
    use brachistochrone_sha256, only: sha256_hex
    !$ use omp_lib, only: omp_get_max_threads
    use brachistochrone_speed_laws, only: max_power_exponent
    use brachistochrone_namelist_scan, only: group_scan, scan_group, problem_list
    use brachistochrone_strings, only: integer_text, escape_text, real_from_text, &
                                       integer_from_text, text_ok, text_out_of_range
    implicit none
    private

    public :: endpoint_table, message, read_endpoint_file, read_endpoint_text
    public :: max_endpoints, group_name, variable_names, max_curve_points, force_names
    public :: stdin_path

    !> Largest table accepted (memory grows linearly: about 100 bytes per endpoint).
    integer, parameter :: max_endpoints = 10000000
    !> The namelist group read.
    character(len=*), parameter :: group_name = 'endpoints'
    !> Its variables (the names of `variables`, in messages).
    character(len=*), parameter :: variable_names = &
        'n, rho, psi, r0, r1, x, y, secant_tolerance, curve_points, force, exponent'
    !> The force fields `force` may name.
    character(len=*), parameter :: force_names = field_names
    !> Most points per curve (`curve_points`); the fewest is 2 (A and B).
    integer, parameter :: max_curve_points = 100000
    !> The input path that means standard input.
    character(len=*), parameter :: stdin_path = '-'

    integer, parameter :: kind_integer = 1, kind_real = 2, kind_word = 3

    !> One variable of the group: its name, kind, shape, default and valid values.
    type :: variable_rule
        character(len=16) :: name       !! lowercase name
        integer :: kind                 !! kind_integer, kind_real or kind_word
        logical :: per_row              !! n values, one per endpoint (else one value)
        logical :: required             !! must be given
        character(len=32) :: example    !! a valid assignment, for messages
        real(qp) :: low = -huge(1.0_qp) !! valid numbers: low <= x (low < x if low_open)
        real(qp) :: high = huge(1.0_qp) !! and x <= high (x < high if high_open)
        logical :: low_open = .false.
        logical :: high_open = .false.
        logical :: zero_allowed = .false. !! 0 is valid too (it means "none")
        character(len=80) :: words = ''   !! kind_word: the valid words, quoted
        real(qp) :: default = 0.0_qp      !! value when not given (numbers)
        character(len=16) :: default_word = '' !! value when not given (kind_word)
        character(len=120) :: rule = ''   !! the valid values, for messages
    end type variable_rule

    !> The variables of `&endpoints`: a new variable is a row here and a field of
    !! `endpoint_table` (filled in `fill_table`); rows of rho, psi, r0, r1 are
    !! `row_values`, the others one value each.
    type(variable_rule), parameter :: variables(*) = [ &
        variable_rule('n', kind_integer, .false., .true., 'n = 5', low=1.0_qp, &
                      high=real(max_endpoints, qp), &
                      rule='is out of range; it must be 1 <= n <= 10000000'), &
        variable_rule('rho', kind_real, .true., .true., 'rho = 0.5, 0.9', low=0.0_qp, &
                      low_open=.true., high=1.0_qp, &
                      rule='must satisfy 0 < rho <= 1 (A is at radius 1)'), &
        variable_rule('psi', kind_real, .true., .true., 'psi = 1.0, 0.4', low=0.0_qp, &
                      high=pi, rule='must satisfy 0 <= psi <= pi radians (by symmetry '// &
                      'use 2*pi - psi for an angle beyond pi)'), &
        variable_rule('r0', kind_real, .true., .false., 'r0 = 0.2, 0.4'), &
        variable_rule('r1', kind_real, .true., .false., 'r1 = 0.1, 0.2'), &
        variable_rule('x', kind_real, .true., .false., 'x = 1.0, 3.14159', low=0.0_qp, &
                      rule='must satisfy x >= 0 (force = ''uniform'': the horizontal '// &
                      'distance of B from A)'), &
        variable_rule('y', kind_real, .true., .false., 'y = 0.5, 2.0', low=0.0_qp, &
                      rule='must satisfy y >= 0 (force = ''uniform'': the depth of B '// &
                      'below A, y downward)'), &
        variable_rule('secant_tolerance', kind_real, .false., .false., &
                      'secant_tolerance = 1e-16', low=0.0_qp, low_open=.true., &
                      default=1.0e-16_qp, rule='must be a positive number, for example 1e-16'), &
        variable_rule('curve_points', kind_integer, .false., .false., 'curve_points = 201', &
                      low=2.0_qp, high=real(max_curve_points, qp), zero_allowed=.true., &
                      rule='must be 0 (no curves) or 2 <= curve_points <= 100000 (points '// &
                      'per curve, A and B included)'), &
        variable_rule('force', kind_word, .false., .false., 'force = ''harmonic''', &
                      words=force_names, default_word='inverse_square', &
                      rule='unknown field; use one of '//force_names), &
        variable_rule('exponent', kind_real, .false., .false., 'exponent = 3', low=1.0_qp, &
                      low_open=.true., high=max_power_exponent, &
                      rule='must be a number > 1 and <= 32 (n = 1 is force = '// &
                      '''logarithmic''; the general engine supports n <= 32)')]

    !> rho's range with force = 'repulsive' (paths move outward).
    type(variable_rule), parameter :: repulsive_rho = variable_rule('rho', kind_real, &
        .true., .true., 'rho = 1.5, 2', low=1.0_qp, rule='must satisfy rho >= 1 (force = '// &
        '''repulsive'': paths move outward from A at radius 1)')

    !> One message per problem found in the input.
    type :: message
        character(len=:), allocatable :: text !! the complete message
    end type message

    !> The validated endpoint table.
    type :: endpoint_table
        character(len=:), allocatable :: path  !! file it was read from ('-': stdin), raw
        integer :: n = 0                       !! number of endpoints
        real(qp), allocatable :: rho(:)        !! endpoint radii
        real(qp), allocatable :: psi(:)        !! endpoint angles (radians)
        real(qp), allocatable :: r0(:)         !! first secant estimate (if has_estimates)
        real(qp), allocatable :: r1(:)         !! second secant estimate (if has_estimates)
        logical, allocatable :: has_estimates(:) !! row uses the paper's secant method
        real(qp) :: secant_tolerance = 1.0e-16_qp !! the paper's stopping rule
        integer :: curve_points = 0               !! points per curve for --curves (0: none)
        !> The force field: 'inverse_square' (the fast path), 'power', 'logarithmic',
        !! 'harmonic' (the general engine), 'repulsive'
        character(len=:), allocatable :: force
        real(qp) :: exponent = 0.0_qp             !! n of F = mu/r^n for force = 'power'
        !> The problems found, at most 100 and then one '... and N more' line; empty
        !! if the table is valid
        type(message), allocatable :: errors(:)
        integer :: problems = 0                   !! number of problems found in all
        !> SHA-256 of the input's bytes, 64 hex digits ('' unless asked for)
        character(len=:), allocatable :: checksum
        integer(int64) :: bytes = 0               !! size of the input in bytes
    end type endpoint_table

    !> The rows of one per-row variable as far as values set them.
    type :: row_values
        logical :: given = .false.           !! the variable is assigned
        logical :: broken = .false.          !! an assignment has a syntax problem
        integer :: line = 0                  !! line of its first assignment
        integer(int64) :: count = 0          !! values given (repeats counted, no nulls)
        integer :: rows = 0                  !! rows held below (0: none)
        real(qp), allocatable :: x(:)        !! value of each row held
        integer, allocatable :: at(:)        !! its line (0: not set)
    end type row_values

    !> The one-value variables while reading (indexed like `variables`).
    type :: scalar_values
        real(qp) :: value(size(variables)) = variables%default   !! numbers
        character(len=16) :: word(size(variables)) = variables%default_word !! words
        logical :: given(size(variables)) = .false.   !! a value was given
        logical :: valid(size(variables)) = .true.    !! the last value given is valid
        logical :: reported(size(variables)) = .false. !! a problem with a value
        ! what the checks use, set by `read_scalars`
        integer :: n = 0                     !! n (when have_n)
        logical :: have_n = .false.          !! n given and valid
        character(len=:), allocatable :: force !! the field
        logical :: force_ok = .true.         !! force is a known field
    end type scalar_values

contains

    !> Read `path` (`-`: standard input, read whole) into `table`. On return
    !! `size(table%errors) == 0` when the table is valid; otherwise the errors are
    !! complete messages (the path and quoted input escaped) and the arrays are
    !! unallocated. A file that cannot be read is one error ("cannot read"). With
    !! `checksum`, `table%checksum` is the input's SHA-256 (for provenance), computed on a
    !! second OpenMP thread while the first parses.
    subroutine read_endpoint_file(path, table, checksum)
        character(len=*), intent(in) :: path       !! namelist file, or '-'
        type(endpoint_table), intent(out) :: table !! the table and its problems
        logical, intent(in), optional :: checksum  !! compute table%checksum
        character(len=:), allocatable :: text, problem
        character(len=64) :: digest
        logical :: want_checksum
        integer :: threads
        if (path == stdin_path) then
            call read_stdin(text, problem)
        else
            call read_text(path, text, problem)
        end if
        if (len(problem) > 0) then
            table%path = path
            table%problems = 1
            table%errors = [message(shown_path(path)//': cannot read the file: '// &
                                    escape_text(problem))]
            return
        end if
        want_checksum = .false.
        if (present(checksum)) want_checksum = checksum
        digest = ''
        ! the checksum (about 4 ms per MB) on a second thread while the first parses (8)
        threads = 1
        !$ threads = min(2, omp_get_max_threads())   ! never more than the run may use
        !$omp parallel sections num_threads(threads) if (want_checksum) default(shared)
        !$omp section
        call read_endpoint_text(text, path, table)
        !$omp section
        if (want_checksum) digest = sha256_hex(text)
        !$omp end parallel sections
        table%bytes = len(text, int64)
        table%checksum = trim(digest)
    end subroutine read_endpoint_file

    !> Read the table from `text`, the contents of the file `path` (used in messages).
    subroutine read_endpoint_text(text, path, table)
        character(len=*), intent(in) :: text       !! the whole file
        character(len=*), intent(in) :: path       !! its name, for messages
        type(endpoint_table), intent(out) :: table !! the table and its problems
        type(group_scan) :: scan
        type(problem_list) :: problems
        type(scalar_values) :: s
        type(row_values) :: rows(6)
        integer, allocatable :: variable_of(:)
        integer :: k

        table%path = path
        call scan_group(text, group_name, scan, problems)
        if (.not. scan%found) then
            call problems%add(0, 'no namelist group &'//group_name//' found'// &
                              trim(merge(' (the file is empty)', '                    ', &
                                         len_trim(text) == 0))// &
                              '; the file must contain a group like  &'//group_name// &
                              ' n = 2, rho = 0.5, 0.9, psi = 1.0, 0.4 /')
        else
            allocate (variable_of(scan%count))
            call name_variables(scan, problems, variable_of)
            call read_scalars(text, scan, variable_of, problems, s)
            do k = 1, size(rows)
                call read_rows(text, scan, variable_of, k + 1, s, problems, rows(k))
            end do
            call check_counts(scan, s, rows, problems)
            call check_force(scan, variable_of, s, rows, problems)
        end if
        call report(problems, shown_path(path), table)
        if (table%problems == 0 .and. s%have_n) call fill_table(s, rows, table)
    end subroutine read_endpoint_text

    !> The variable of each assignment (0: unknown name, reported).
    subroutine name_variables(scan, problems, variable_of)
        type(group_scan), intent(in) :: scan
        type(problem_list), intent(inout) :: problems
        integer, intent(out) :: variable_of(:)
        integer :: a, v
        do a = 1, scan%count
            variable_of(a) = 0
            do v = 1, size(variables)
                if (scan%name(a) == variables(v)%name) variable_of(a) = v
            end do
            if (variable_of(a) == 0) then
                call problems%add(scan%name_line(a), 'group &'//group_name// &
                                  ': unknown variable "'//trim(scan%name(a))// &
                                  '"; the variables are '//variable_names)
            else if (scan%indexed(a) .and. .not. variables(variable_of(a))%per_row) then
                call problems%add(scan%name_line(a), 'group &'//group_name//', variable '// &
                                  trim(scan%name(a))//': is not an array; write  '// &
                                  trim(variables(variable_of(a))%example))
                variable_of(a) = 0
            end if
        end do
    end subroutine name_variables

    !> The one-value variables: the last assignment of each wins, every one is checked.
    subroutine read_scalars(text, scan, variable_of, problems, s)
        character(len=*), intent(in) :: text
        type(group_scan), intent(in) :: scan
        integer, intent(in) :: variable_of(:)
        type(problem_list), intent(inout) :: problems
        type(scalar_values), intent(out) :: s
        integer :: a, v, t
        do a = 1, scan%count
            v = variable_of(a)
            if (v == 0) cycle
            if (variables(v)%per_row .or. .not. scan%usable(a)) cycle
            if (sum(int(scan%repeat(scan%first(a):scan%last(a)), int64)) > 1) then
                call problems%add(scan%name_line(a), 'group &'//group_name//', variable '// &
                                  trim(variables(v)%name)//': needs exactly one value, '// &
                                  'for example  '//trim(variables(v)%example))
                s%reported(v) = .true.
                s%valid(v) = .false.
                cycle
            end if
            if (scan%last(a) < scan%first(a)) cycle               ! `name =` : no value
            t = scan%first(a)
            if (scan%finish(t) < scan%start(t)) cycle             ! a null value
            call check_scalar(text(scan%start(t):scan%finish(t)), scan%quoted(t), &
                              scan%value_line(t), v, problems, s)
        end do
        s%have_n = s%given(1) .and. s%valid(1)
        if (s%have_n) s%n = nint(s%value(1))
        s%force = trim(s%word(index_of('force')))
        s%force_ok = s%valid(index_of('force'))
    end subroutine read_scalars

    !> Convert the value `token` of the one-value variable v, check it against the
    !! variable's rule and keep it in `s`.
    subroutine check_scalar(token, quoted, line, v, problems, s)
        character(len=*), intent(in) :: token
        logical, intent(in) :: quoted
        integer, intent(in) :: line, v
        type(problem_list), intent(inout) :: problems
        type(scalar_values), intent(inout) :: s
        character(len=:), allocatable :: where, word
        integer :: value, status
        real(qp) :: x
        where = 'group &'//group_name//', variable '//trim(variables(v)%name)
        s%given(v) = .true.
        s%valid(v) = .false.
        s%reported(v) = .true.            ! until the value passes
        select case (variables(v)%kind)
        case (kind_integer)
            call integer_from_text(token, value, status)
            if (quoted .or. (status /= text_ok .and. status /= text_out_of_range)) then
                call problems%add(line, where//': "'//escape_text(token)//'" is not a '// &
                                  'valid value; write a whole number, for example  '// &
                                  trim(variables(v)%example))
                return
            else if (status == text_out_of_range) then
                if (index(variables(v)%rule, 'out of range') > 0) then
                    call problems%add(line, where//' = '//escape_text(token)//': '// &
                                      trim(variables(v)%rule))
                else
                    call problems%add(line, where//' = '//escape_text(token)//': is out '// &
                                      'of range; '//trim(variables(v)%rule))
                end if
                return
            end if
            x = real(value, qp)
        case (kind_real)
            call real_from_text(token, x, status)
            if (quoted .or. status /= text_ok) then
                call problems%add(line, where//': "'//escape_text(token)//'" is not a '// &
                                  'valid value; write a real number such as 0.25 or 1.5e-3')
                return
            end if
        case (kind_word)
            if (.not. quoted) then
                call problems%add(line, where//': '//escape_text(token)//' must be '// &
                                  'quoted, for example  '//trim(variables(v)%example))
                return
            end if
            word = unquoted(token)
            if (index(variables(v)%words, "'"//word//"'") == 0 .or. len(word) == 0 .or. &
                index(word, "'") > 0 .or. len(word) > len(s%word)) then
                call problems%add(line, where//' = '''//escape_text(word)//''': '// &
                                  trim(variables(v)%rule))
                return
            end if
            s%word(v) = word
            s%valid(v) = .true.
            s%reported(v) = .false.
            return
        end select
        if (.not. in_range(variables(v), x)) then
            call problems%add(line, where//' = '//escape_text(token)//': '// &
                              trim(variables(v)%rule))
            return
        end if
        s%value(v) = x
        s%valid(v) = .true.
        s%reported(v) = .false.
    end subroutine check_scalar

    !> Is x a valid number for variable `rule`? (NaN and Infinity never are.)
    pure logical function in_range(rule, x)
        type(variable_rule), intent(in) :: rule
        real(qp), intent(in) :: x
        in_range = ieee_is_finite(x)
        if (.not. in_range) return
        if (rule%zero_allowed .and. x == 0.0_qp) return
        if (rule%low_open) then
            in_range = x > rule%low
        else
            in_range = x >= rule%low
        end if
        if (rule%high_open) then
            in_range = in_range .and. x < rule%high
        else
            in_range = in_range .and. x <= rule%high
        end if
    end function in_range

    !> Position of a variable in `variables`.
    pure integer function index_of(name)
        character(len=*), intent(in) :: name
        integer :: v
        index_of = 0
        do v = 1, size(variables)
            if (variables(v)%name == name) index_of = v
        end do
    end function index_of

    !> A string's text with each doubled quote made single (the quote is the one
    !! before the text).
    pure function unquoted(token) result(word)
        character(len=*), intent(in) :: token
        character(len=:), allocatable :: word
        integer :: i
        word = ''
        i = 1
        do while (i <= len(token))
            word = word//token(i:i)
            if (token(i:i) == '''' .or. token(i:i) == '"') i = i + 1
            i = i + 1
        end do
        word = trim(adjustl(word))
    end function unquoted

    !> The per-row variable v: every value converted once, checked and kept for its
    !! rows. Rows are held up to the largest row a value sets (at most n), and not at
    !! all when that exceeds the number of values in the whole group (then the group
    !! is invalid anyway: it cannot set n rows of both rho and psi).
    subroutine read_rows(text, scan, variable_of, v, s, problems, r)
        character(len=*), intent(in) :: text
        type(group_scan), intent(in) :: scan
        integer, intent(in) :: variable_of(:), v
        type(scalar_values), intent(in) :: s
        type(problem_list), intent(inout) :: problems
        type(row_values), intent(out) :: r
        integer(int64) :: largest, limit
        integer :: a, status
        character(len=:), allocatable :: where
        type(variable_rule) :: rule
        where = 'group &'//group_name//', variable '//trim(variables(v)%name)
        rule = rule_of_rows(v, s)
        limit = max_endpoints
        if (s%have_n) limit = s%n
        call size_rows(scan, variable_of, v, s, limit, where, problems, r, largest)
        if (largest > 0 .and. largest <= max(scan%total, 1_int64)) then
            allocate (r%x(largest), r%at(largest), stat=status)
            if (status /= 0) then
                call problems%add(r%line, where//': not enough memory for '// &
                                  big_text(largest)//' rows')
            else
                r%rows = int(largest)
                r%at = 0
            end if
        end if
        do a = 1, scan%count
            if (variable_of(a) == v) call read_assignment(text, scan, a, scan%usable(a), rule, &
                                                        limit, where, problems, r)
        end do
    end subroutine read_rows

    !> The assignments of per-row variable v: subscripts and counts checked; `largest`
    !! is the largest row they set (at most `limit`).
    subroutine size_rows(scan, variable_of, v, s, limit, where, problems, r, largest)
        type(group_scan), intent(in) :: scan
        integer, intent(in) :: variable_of(:), v
        type(scalar_values), intent(in) :: s
        integer(int64), intent(in) :: limit
        character(len=*), intent(in) :: where
        type(problem_list), intent(inout) :: problems
        type(row_values), intent(inout) :: r
        integer(int64), intent(out) :: largest
        integer(int64) :: low, count_values
        integer :: a
        largest = 0
        do a = 1, scan%count
            if (variable_of(a) /= v) cycle
            if (.not. r%given) r%line = scan%name_line(a)
            r%given = .true.
            r%broken = r%broken .or. .not. scan%usable(a)
            if (.not. scan%usable(a)) cycle
            low = scan%low(a)
            count_values = sum(int(scan%repeat(scan%first(a):scan%last(a)), int64))
            if (scan%indexed(a)) then
                if (low < 1 .or. scan%high(a) < low .or. scan%high(a) > limit) then
                    call problems%add(scan%name_line(a), where//'('//subscript(scan, a)// &
                                      '): the subscript must be within 1 .. '// &
                                      trim(merge('n =          ', 'max_endpoints', s%have_n))// &
                                      ' '//integer_text(int(limit)))
                    cycle
                end if
                if (count_values > scan%high(a) - low + 1) then
                    call problems%add(scan%name_line(a), where//'('//subscript(scan, a)// &
                                      '): has '//integer_text(int(scan%high(a) - low + 1))// &
                                      ' element(s) but '//big_text(count_values)// &
                                      ' values are given')
                end if
            end if
            if (s%have_n .and. low + count_values - 1 > s%n .and. .not. scan%indexed(a)) then
                call problems%add(scan%name_line(a), where//': has more than n = '// &
                                  integer_text(s%n)//' values; give exactly n values or '// &
                                  'raise n')
            end if
            largest = max(largest, min(low + count_values - 1, limit))
        end do
    end subroutine size_rows

    !> Convert and check the values of assignment a, and keep them if `keep`.
    subroutine read_assignment(text, scan, a, keep, rule, limit, where, problems, r)
        character(len=*), intent(in) :: text, where
        type(group_scan), intent(in) :: scan
        integer, intent(in) :: a
        logical, intent(in) :: keep
        type(variable_rule), intent(in) :: rule
        integer(int64), intent(in) :: limit
        type(problem_list), intent(inout) :: problems
        type(row_values), intent(inout) :: r
        integer(int64) :: row, high
        integer :: t, status, last_row
        real(qp) :: x
        row = scan%low(a)
        high = huge(1_int64)
        if (scan%indexed(a)) then
            high = scan%high(a)
            if (row < 1 .or. high < row .or. high > limit) return
        end if
        do t = scan%first(a), scan%last(a)
            if (row > high) exit
            if (scan%finish(t) >= scan%start(t)) then
                call real_from_text(text(scan%start(t):scan%finish(t)), x, status)
                if (.not. keep) then         ! a broken assignment: only bad texts
                    if (status /= text_ok) call problems%add(scan%value_line(t), &
                        where//': "'//escape_text(text(scan%start(t):scan%finish(t)))// &
                        '" is not a valid value; write a real number such as 0.25 '// &
                        'or 1.5e-3')
                    cycle
                end if
                if (.not. problems%wanted(scan%value_line(t))) then
                    if (status /= text_ok .or. scan%quoted(t) .or. &
                        .not. ieee_is_finite(x)) then
                        call problems%count_one()
                    else if (.not. in_range(rule, x)) then
                        call problems%count_one()
                    end if
                else if (status /= text_ok .or. scan%quoted(t)) then
                    call problems%add(scan%value_line(t), where//'('// &
                        row_range(row, min(row + scan%repeat(t) - 1, high))//'): "'// &
                        escape_text(text(scan%start(t):scan%finish(t)))// &
                        '" is not a valid value; write a real number such as 0.25 or 1.5e-3')
                else if (.not. ieee_is_finite(x)) then
                    call problems%add(scan%value_line(t), where//'('// &
                        row_range(row, min(row + scan%repeat(t) - 1, high))// &
                        '): is not a finite number (NaN or Infinity); give a real number')
                else if (.not. in_range(rule, x)) then
                    call problems%add(scan%value_line(t), where//'('// &
                        row_range(row, min(row + scan%repeat(t) - 1, high))//') = '// &
                        escape_text(text(scan%start(t):scan%finish(t)))//': '// &
                        trim(rule%rule))
                end if
                r%count = r%count + scan%repeat(t)
                if (row <= r%rows) then
                    last_row = int(min(row + scan%repeat(t) - 1, int(r%rows, int64), high))
                    r%x(row:last_row) = x
                    r%at(row:last_row) = scan%value_line(t)
                end if
            end if
            row = row + scan%repeat(t)
        end do
    end subroutine read_assignment

    !> The rule for the rows of per-row variable v: its row of `variables`, or
    !! `repulsive_rho` for rho with force = 'repulsive', or no range for rho while the
    !! field is unknown (its range depends on the field).
    pure function rule_of_rows(v, s) result(rule)
        integer, intent(in) :: v
        type(scalar_values), intent(in) :: s
        type(variable_rule) :: rule
        rule = variables(v)
        if (rule%name /= 'rho') return
        if (.not. s%force_ok) then
            rule = variable_rule('rho', kind_real, .true., .true., '')
        else if (s%force == 'repulsive') then
            rule = repulsive_rho
        end if
    end function rule_of_rows


    !> Required per-row variables given for all n rows; r0 and r1 in pairs.
    subroutine check_counts(scan, s, rows, problems)
        type(group_scan), intent(in) :: scan
        type(scalar_values), intent(in) :: s
        type(row_values), intent(in) :: rows(:)
        type(problem_list), intent(inout) :: problems
        integer :: k, i, set
        character(len=:), allocatable :: where
        if (.not. s%have_n .and. .not. s%reported(1)) call problems%add(scan%line, &
            'group &'//group_name//', variable n: is missing (or null); set it to the '// &
            'number of endpoints, for example  n = 5')
        do k = 1, size(rows)
            where = 'group &'//group_name//', variable '//trim(variables(k + 1)%name)
            if (.not. rows(k)%given) then
                if (required_rows(k + 1, s)) call problems%add(scan%line, where// &
                    ': is missing; give n values, for example  '// &
                    trim(variables(k + 1)%example))
            else if (required_rows(k + 1, s) .and. s%have_n .and. .not. rows(k)%broken) then
                if (rows(k)%rows > 0) then
                    set = count(rows(k)%at(:min(rows(k)%rows, s%n)) /= 0)
                else
                    set = int(min(rows(k)%count, int(s%n, int64)))
                end if
                if (set < s%n) call problems%add(rows(k)%line, where//': has '// &
                    integer_text(set)//' values but n = '//integer_text(s%n)// &
                    '; give exactly n values')
            end if
        end do
        if (.not. s%have_n) return
        do i = 1, min(s%n, max(rows(3)%rows, rows(4)%rows))
            if (row_set(rows(3), i) .eqv. row_set(rows(4), i)) cycle
            if (row_set(rows(3), i)) then
                call problems%add(rows(3)%at(i), 'group &'//group_name//', variable r1('// &
                                  integer_text(i)//'): is missing; give both r0 and r1 '// &
                                  'for a row (the paper''s secant method) or neither '// &
                                  '(the bracketing solver)')
            else
                call problems%add(rows(4)%at(i), 'group &'//group_name//', variable r0('// &
                                  integer_text(i)//'): is missing; give both r0 and r1 '// &
                                  'for a row (the paper''s secant method) or neither '// &
                                  '(the bracketing solver)')
            end if
        end do
    end subroutine check_counts

    !> The per-row variable v must be given: rho and psi for every field but 'uniform',
    !! x and y for 'uniform' (while the field is unknown, as the table says).
    pure logical function required_rows(v, s)
        integer, intent(in) :: v
        type(scalar_values), intent(in) :: s
        logical :: uniform
        uniform = s%force_ok .and. s%force == 'uniform'
        select case (trim(variables(v)%name))
        case ('rho', 'psi')
            required_rows = .not. uniform
        case ('x', 'y')
            required_rows = uniform
        case default
            required_rows = variables(v)%required
        end select
    end function required_rows

    pure logical function row_set(r, i)
        type(row_values), intent(in) :: r
        integer, intent(in) :: i
        row_set = .false.
        if (i <= r%rows) row_set = r%at(i) /= 0
    end function row_set

    !> The field and what goes with it: exponent only (and always) with 'power', the
    !! paper's secant method and curves only with 'inverse_square' (its fast path).
    subroutine check_force(scan, variable_of, s, rows, problems)
        type(group_scan), intent(in) :: scan
        integer, intent(in) :: variable_of(:)
        type(scalar_values), intent(in) :: s
        type(row_values), intent(in) :: rows(:)       !! rho, psi, r0, r1, x, y
        type(problem_list), intent(inout) :: problems
        character(len=:), allocatable :: where
        integer :: line
        logical :: exponent_given
        if (.not. s%force_ok) return
        line = line_of(scan, variable_of, index_of('force'))
        where = 'group &'//group_name
        exponent_given = s%given(index_of('exponent'))
        if (s%force == 'power') then
            if (.not. exponent_given) call problems%add(line, where//', variable '// &
                'exponent: is missing; force = ''power'' needs the exponent n of '// &
                'F = mu/r^n, n > 1, for example  exponent = 3')
        else if (exponent_given) then
            call problems%add(line_of(scan, variable_of, index_of('exponent')), where// &
                              ', variable exponent: applies to force = ''power'' only')
        end if
        call check_coordinates(s, rows, problems)
        if (s%force /= 'inverse_square') then
            if (rows(3)%count > 0) call problems%add(line, where//': r0, r1 (the paper''s '// &
                'secant method) apply to force = ''inverse_square'' only; leave them out')
            if (s%value(index_of('curve_points')) /= 0.0_qp) call problems%add(line, &
                where//': curve_points: curves are sampled for force = ''inverse_square'' only')
        end if
    end subroutine check_force

    !> Cartesian x, y with force = 'uniform' only, and rho, psi with every other field:
    !! the coordinates are never read as each other.
    subroutine check_coordinates(s, rows, problems)
        type(scalar_values), intent(in) :: s
        type(row_values), intent(in) :: rows(:)       !! rho, psi, r0, r1, x, y
        type(problem_list), intent(inout) :: problems
        integer :: k
        logical :: uniform
        uniform = s%force == 'uniform'
        do k = 1, size(rows)
            if (.not. rows(k)%given) cycle
            select case (trim(variables(k + 1)%name))
            case ('rho', 'psi')
                if (uniform) call problems%add(rows(k)%line, 'group &'//group_name// &
                    ', variable '//trim(variables(k + 1)%name)//': force = ''uniform'' '// &
                    'takes Cartesian endpoints: give x (across) and y (down from A), '// &
                    'not rho and psi')
            case ('x', 'y')
                if (.not. uniform) call problems%add(rows(k)%line, 'group &'// &
                    group_name//', variable '//trim(variables(k + 1)%name)//': x and y '// &
                    'are the endpoints of force = ''uniform'' only; this field takes rho '// &
                    'and psi')
            end select
        end do
    end subroutine check_coordinates

    !> Line of the first assignment of variable v (0 if none).
    pure integer function line_of(scan, variable_of, v)
        type(group_scan), intent(in) :: scan
        integer, intent(in) :: variable_of(:), v
        integer :: a
        line_of = 0
        do a = 1, scan%count
            if (variable_of(a) == v) then
                line_of = scan%name_line(a)
                return
            end if
        end do
    end function line_of

    !> The valid table from the values read.
    subroutine fill_table(s, rows, table)
        type(scalar_values), intent(in) :: s
        type(row_values), intent(in) :: rows(:)
        type(endpoint_table), intent(inout) :: table
        integer :: n, i, status
        n = s%n
        allocate (table%rho(n), table%psi(n), table%has_estimates(n), table%r0(n), &
                  table%r1(n), stat=status)
        if (status /= 0) then
            table%problems = 1
            table%errors = [message(escape_text(table%path)//': out of memory for a '// &
                            'table of '//integer_text(n)//' rows; split it into smaller files')]
            return
        end if
        table%n = n
        if (s%force == 'uniform') then
            ! the field's coordinates x, y (the outputs name them so)
            table%rho = rows(5)%x(1:n)
            table%psi = rows(6)%x(1:n)
        else
            table%rho = rows(1)%x(1:n)
            table%psi = rows(2)%x(1:n)
        end if
        do i = 1, n
            table%has_estimates(i) = row_set(rows(3), i)
            table%r0(i) = 0.0_qp
            table%r1(i) = 0.0_qp
            if (table%has_estimates(i)) then
                table%r0(i) = rows(3)%x(i)
                table%r1(i) = rows(4)%x(i)
            end if
        end do
        table%secant_tolerance = s%value(index_of('secant_tolerance'))
        table%curve_points = nint(s%value(index_of('curve_points')))
        table%force = s%force
        table%exponent = merge(s%value(index_of('exponent')), 0.0_qp, &
                              s%given(index_of('exponent')))
    end subroutine fill_table

    !> The problems as messages "file:line: text", then "... and N more".
    subroutine report(problems, path, table)
        type(problem_list), intent(in) :: problems
        character(len=*), intent(in) :: path
        type(endpoint_table), intent(inout) :: table
        integer :: k
        table%problems = problems%total
        allocate (table%errors(problems%kept))
        do k = 1, problems%kept
            if (problems%line(k) > 0) then
                table%errors(k)%text = path//':'//integer_text(problems%line(k))//': '// &
                                       problems%message(k)
            else
                table%errors(k)%text = path//': '//problems%message(k)
            end if
        end do
        if (problems%total > problems%kept) then
            table%errors = [table%errors, message(path//': ... and '// &
                            integer_text(problems%total - problems%kept)// &
                            ' more problems (the first '//integer_text(problems%kept)// &
                            ' by line are listed)')]
        end if
    end subroutine report

    !> The path as shown in messages: control characters escaped, stdin named.
    pure function shown_path(path) result(shown)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: shown
        if (path == stdin_path) then
            shown = '<stdin>'
        else
            shown = escape_text(path)
        end if
    end function shown_path

    !> "i" or "i:j" for rows i..j.
    pure function row_range(first, last) result(text)
        integer(int64), intent(in) :: first, last
        character(len=:), allocatable :: text
        text = big_text(first)
        if (last > first) text = text//':'//big_text(last)
    end function row_range

    !> The subscript of assignment a as written ("i" or "i:j").
    pure function subscript(scan, a) result(text)
        type(group_scan), intent(in) :: scan
        integer, intent(in) :: a
        character(len=:), allocatable :: text
        text = big_text(scan%low(a))
        if (scan%section(a)) text = text//':'//big_text(scan%high(a))
    end function subscript

    pure function big_text(value) result(text)
        integer(int64), intent(in) :: value
        character(len=:), allocatable :: text
        character(len=24) :: buffer
        write (buffer, '(i0)') value
        text = trim(buffer)
    end function big_text

    !> Whole file as one string with new-line characters; `problem` is '' or the cause.
    subroutine read_text(path, text, problem)
        character(len=*), intent(in) :: path
        character(len=:), allocatable, intent(out) :: text
        character(len=:), allocatable, intent(out) :: problem
        integer :: unit, ios, status
        integer(int64) :: length
        character(len=512) :: io_message
        text = ''
        problem = ''
        open (newunit=unit, file=path, status='old', action='read', access='stream', &
              form='unformatted', iostat=ios, iomsg=io_message)
        if (ios /= 0) then
            problem = trim(io_message)
            return
        end if
        inquire (unit=unit, size=length)
        if (length > huge(1) - 1) then
            problem = 'the file has '//big_text(length)//' bytes; the most is '// &
                      integer_text(huge(1) - 1)
        else if (length > 0) then
            deallocate (text)
            allocate (character(len=length) :: text, stat=status)
            if (status /= 0) then
                problem = 'not enough memory for its '//big_text(length)//' bytes'
                text = ''
            else
                read (unit, iostat=ios, iomsg=io_message) text
                if (ios /= 0) problem = trim(io_message)
            end if
        end if
        close (unit)
    end subroutine read_text

    !> Standard input, whole, as one string (read with the C library's `read`, in
    !! blocks, into a buffer that doubles).
    subroutine read_stdin(text, problem)
        character(len=:), allocatable, intent(out) :: text
        character(len=:), allocatable, intent(out) :: problem
        character(len=:), allocatable :: grown
        integer, parameter :: block = 1048576
        integer(c_size_t) :: got
        integer :: length, status
        interface
            function c_read(fd, buffer, count) bind(c, name='read') result(got)
                import :: c_int, c_size_t, c_char
                integer(c_int), value :: fd
                character(kind=c_char), intent(out) :: buffer(*)
                integer(c_size_t), value :: count
                integer(c_size_t) :: got          ! ssize_t: -1 on error
            end function c_read
        end interface
        allocate (character(len=block) :: text)
        problem = ''
        length = 0
        do
            if (len(text) - length < block) then
                if (len(text) > huge(1)/2 - block) then
                    problem = 'standard input is longer than '//integer_text(huge(1)/2)// &
                              ' bytes'
                    exit
                end if
                allocate (character(len=2*len(text)) :: grown, stat=status)
                if (status /= 0) then
                    problem = 'not enough memory for standard input'
                    exit
                end if
                grown(:length) = text(:length)
                call move_alloc(grown, text)
            end if
            got = c_read(0_c_int, text(length + 1:length + block), int(block, c_size_t))
            if (got == 0) exit
            if (got < 0 .or. got > block) then
                problem = 'reading standard input failed'
                exit
            end if
            length = length + int(got)
        end do
        text = text(:length)
    end subroutine read_stdin

end module brachistochrone_endpoint_input
