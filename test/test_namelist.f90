!> The namelist scanner and reader: the standard's namelist rules, every problem in
!! one run, exact conversion, escaping.
module test_namelist
    use brachistochrone_kinds, only: qp
    use brachistochrone_endpoint_input, only: endpoint_table, read_endpoint_text, &
                                              read_endpoint_file
    use brachistochrone_strings, only: escape_text, real_from_text, integer_from_text, &
                                       text_ok, text_malformed, text_out_of_range
    use testing, only: check, section
    use brachistochrone_strings, only: integer_text
    implicit none
    private

    public :: run_namelist_tests

    character(len=*), parameter :: nl = achar(10)

contains

    subroutine run_namelist_tests()
        call standard_rules()
        call groups()
        call every_problem()
        call exact_conversion()
        call escaping()
        call same_as_gfortran()
    end subroutine run_namelist_tests

    !> Read `text` as the file 'in.nml'.
    function table_of(text) result(table)
        character(len=*), intent(in) :: text
        type(endpoint_table) :: table
        call read_endpoint_text(text, 'in.nml', table)
    end function table_of

    !> Does some message contain `fragment`?
    logical function reports(table, fragment)
        type(endpoint_table), intent(in) :: table
        character(len=*), intent(in) :: fragment
        integer :: k
        reports = .false.
        do k = 1, size(table%errors)
            reports = reports .or. index(table%errors(k)%text, fragment) > 0
        end do
    end function reports

    subroutine standard_rules()
        type(endpoint_table) :: t
        call section('namelist: the standard''s input rules')
        t = table_of('&endpoints n = 3'//nl//' rho = 0.2, 0.5, 0.9'//nl//' psi = 3*0.5'// &
                     nl//' r0 = 0.2, ! row 1'//nl//' 0.4, 0.6'//nl//' r1 = 3*0.1 /'//nl)
        call check(size(t%errors) == 0, 'comment between a value and a continuation line')
        call check(t%r0(2) == 0.4_qp .and. t%r0(3) == 0.6_qp .and. all(t%has_estimates), &
                   'the continuation line gives r0(2) = 0.4, r0(3) = 0.6')
        call check(all(t%psi == 0.5_qp) .and. all(t%r1 == 0.1_qp), 'repeat counts 3*0.5')
        t = table_of('&endpoints n = 1, rho = 0.5, psi = 1 /')
        call check(size(t%errors) == 0 .and. t%n == 1, 'final / at the end of the file, '// &
                   'no new line')
        t = table_of('&endpoints n = 1, rho = 0.5, psi = 1, curve_points = 201/')
        call check(size(t%errors) == 0 .and. t%curve_points == 201, '/ straight after a value')
        t = table_of('&endpoints n = 3, rho = 3*0.5, psi = 3*1, r0 = 3*, r1 = 2*, 0.3, '// &
                     'r0(3) = 0.4 /')
        call check(size(t%errors) == 0, 'r* null values and a subscripted element')
        call check(.not. t%has_estimates(1) .and. .not. t%has_estimates(2) .and. &
                   t%has_estimates(3) .and. t%r0(3) == 0.4_qp .and. t%r1(3) == 0.3_qp, &
                   '3* leaves rows unset, r0(3) = 0.4 sets row 3 only')
        t = table_of('&endpoints n = 3, rho = 0.1, , 0.3, psi = , 0.2, 0.3, '// &
                     'rho(2) = 0.2, psi(1:1) = 0.1 /')
        call check(size(t%errors) == 0, 'null values filled by later subscripted assignments')
        call check(t%rho(1) == 0.1_qp .and. t%rho(2) == 0.2_qp .and. t%rho(3) == 0.3_qp &
                   .and. t%psi(1) == 0.1_qp, 'values of null rows come from rho(2), psi(1:1)')
        t = table_of('&endpoints n = 4, rho = 4*0.5, psi = 4*1, rho(2:3) = 0.2, 0.3 /')
        call check(size(t%errors) == 0 .and. t%rho(2) == 0.2_qp .and. t%rho(3) == 0.3_qp &
                   .and. t%rho(4) == 0.5_qp, 'section rho(2:3) = 0.2, 0.3')
        t = table_of('&ENDPOINTS N = 1, Rho = 0.5, PSI = 1, Force = "harmonic" /')
        call check(size(t%errors) == 0 .and. t%force == 'harmonic', &
                   'names in any case, a string in double quotes')
        t = table_of('$endpoints n = 1, rho = 0.5, psi = 1, force = ''harmonic'' $end')
        call check(size(t%errors) == 0 .and. t%force == 'harmonic', &
                   '$endpoints ... $end, a string in single quotes')
        t = table_of('&endpoints n = 1, rho = 0.5, psi = 1, force = ''inverse''''square'' /')
        call check(reports(t, '''inverse''square'''), 'a doubled quote stands for one quote')
        t = table_of('&endpoints n = 1 ! / & '' " &endpoints'//nl//'rho = 0.5 psi = 1.0d0 /')
        call check(size(t%errors) == 0 .and. t%psi(1) == 1.0_qp, &
                   'comment holding / & quotes, blank-separated values, 1.0d0')
        t = table_of('&endpoints n = 2, rho = 0.5'//nl//nl//'! c'//nl//', 0.6, psi = 1, 1 /')
        call check(size(t%errors) == 0 .and. t%rho(2) == 0.6_qp, 'comma on the next line')
    end subroutine standard_rules

    subroutine groups()
        type(endpoint_table) :: t
        call section('namelist: groups')
        t = table_of('&other s = ''&endpoints n = 9 /'' /'//nl// &
                     '&endpoints n = 1, rho = 0.5, psi = 1 /'//nl)
        call check(size(t%errors) == 0 .and. t%n == 1, '&endpoints inside a string of '// &
                   'another group is not the group')
        t = table_of('&other s = "&endpoints n = 1, rho = 0.5, psi = 1 /" /'//nl)
        call check(reports(t, 'no namelist group &endpoints'), &
                   'only &endpoints in a string: no group')
        t = table_of('&endpoints n = 1, rho = 0.5, psi = 1 /'//nl// &
                     '&endpoints n = 2 /'//nl)
        call check(reports(t, 'in.nml:2: group &endpoints: a second group &endpoints'), &
                   'a second group is an error with its line')
        t = table_of('&endpoints n = 1, rho = 0.5, psi = 1'//nl//'&other x = 1 /')
        call check(reports(t, 'is not closed before "&other'), 'group not closed before next')
        t = table_of('&endpoints n = 1, rho = 0.5, psi = 1 /'//nl//'&after x = 1 /'//nl)
        call check(size(t%errors) == 0, 'a group after it is skipped')
    end subroutine groups

    subroutine every_problem()
        type(endpoint_table) :: t
        character(len=:), allocatable :: text
        integer :: k
        call section('namelist: every problem in one run')
        t = table_of('&endpoints'//nl//' n = 2'//nl//' rho = 0.5, 2.0'//nl// &
                     ' psi = 1 1'//nl//' phi = 3'//nl//' psi(2) = abc'//nl//' rho(1 = 5'//nl//'/')
        call check(reports(t, 'in.nml:3: group &endpoints, variable rho(2) = 2.0'), &
                   'range problem reported')
        call check(reports(t, 'in.nml:5: group &endpoints: unknown variable "phi"'), &
                   'unknown name reported with the range problem')
        call check(reports(t, 'in.nml:6: group &endpoints, variable psi(2): "abc"'), &
                   'malformed value reported with them')
        call check(reports(t, 'in.nml:7: group &endpoints, variable rho: bad subscript'), &
                   'syntax problem reported with them')
        call check(t%problems == 4 .and. size(t%errors) == 4, 'exactly these four')
        call check(index(t%errors(1)%text, ':3:') > 0 .and. index(t%errors(4)%text, ':7:') &
                   > 0, 'in line order')
        text = '&endpoints n = 1, rho = 0.5, psi = 1'//nl
        do k = 1, 40000
            text = text//' q = 1'//nl
        end do
        t = table_of(text//'/')
        call check(t%problems == 40000 .and. size(t%errors) == 101 .and. &
                   index(t%errors(101)%text, 'and 39900 more') > 0, &
                   '40,000 unknown names: 100 listed and 39,900 counted')
        call check(index(t%errors(1)%text, 'in.nml:2:') > 0 .and. &
                   index(t%errors(100)%text, 'in.nml:101:') > 0, 'the first 100 by line')
        t = table_of('&endpoints n = 10000000, rho = 0.5, psi = 1 /')
        call check(reports(t, 'variable rho: has 1 values but n = 10000000') .and. &
                   reports(t, 'variable psi: has 1 values but n = 10000000'), &
                   'n = 10000000 with one value: too few values')
        t = table_of('&endpoints n = 2, rho(3) = 0.5, rho(0) = 1, rho(1) = 0.1, 0.2, '// &
                     'psi = 2*1, psi(1:2) = 1, 2, 3 /')
        call check(reports(t, 'rho(3): the subscript must be within 1 .. n = 2') .and. &
                   reports(t, 'rho(0): the subscript') .and. &
                   reports(t, 'rho(1): has 1 element(s) but 2 values') .and. &
                   reports(t, 'psi(1:2): has 2 element(s) but 3 values'), &
                   'subscripts out of range, too many values for an element or section')
        t = table_of('&endpoints n = 3, rho = 0.5, 0.5, 0.5, psi = 1e5000, -Inf, NaN, '// &
                     'r0 = 2*0.5, r1 = 0.2, 0.3, 0.4, secant_tolerance = 0, '// &
                     'curve_points = 1 /')
        call check(reports(t, 'psi(1): is not a finite') .and. &
                   reports(t, 'psi(2): is not a finite') .and. &
                   reports(t, 'psi(3): is not a finite') .and. &
                   reports(t, 'r0(3): is missing') .and. &
                   reports(t, 'secant_tolerance = 0: must be a positive') .and. &
                   reports(t, 'curve_points = 1: must be 0'), &
                   'overflow, Inf, NaN, a lone r1, tolerance and curve points at once')
        t = table_of('&endpoints n = 2, rho = 2*5.0, psi = 2*1 /')
        call check(reports(t, 'rho(1:2) = 5.0: must satisfy 0 < rho <= 1'), &
                   'a repeated bad value names its rows')
        t = table_of('&endpoints n = , rho = 0.5, psi = 1 /')
        call check(reports(t, 'variable n: is missing (or null)'), 'n = null value')
        t = table_of('&endpoints n = 1, n = 2*1, rho = 0.5, psi = 1 /')
        call check(reports(t, 'variable n: needs exactly one value') .and. t%problems == 1, &
                   'n = 2*1: one problem')
        t = table_of('&endpoints n = 1, rho = 0.5, psi = 0*1 /')
        call check(reports(t, 'not a valid repeat count'), 'repeat count 0')
        t = table_of('&endpoints n = 1, rho = 0.5, psi = 1, force = ''harmonic /')
        call check(reports(t, 'has no closing quote'), 'unclosed string')
        t = table_of('&endpoints n = 1, rho = 0.5, n(1) = 2, psi = 1, force = harmonic /')
        call check(reports(t, 'variable n: is not an array') .and. &
                   reports(t, 'force: harmonic must be quoted'), &
                   'a scalar with a subscript, an unquoted string')
    end subroutine every_problem

    !> real_from_text gives the bits of gfortran's read(text, *) on many decimals.
    subroutine exact_conversion()
        character(len=64) :: text
        character(len=*), parameter :: letters = 'eEdDqQ'
        real(qp) :: mine, reference
        integer :: k, status, ios, mismatches, value
        integer(8) :: seed
        call section('namelist: exact decimal conversion')
        mismatches = 0
        seed = 12345
        do k = 1, 4000
            write (text, '(i0,a,i0,a,i0)') next(10**9), '.', next(10**9), &
                letters(mod(k, 6) + 1:mod(k, 6) + 1), next(9000) - 4500
            if (mod(k, 5) == 0) text = '-'//text
            call real_from_text(trim(text), mine, status)
            read (text, *, iostat=ios) reference
            if (status /= text_ok .or. ios /= 0 .or. mine /= reference) then
                mismatches = mismatches + 1
                if (mismatches < 4) print '(3x,a)', 'differs: '//trim(text)
            end if
        end do
        call check(mismatches == 0, '4000 random decimals (e, d, q exponents, 1e-4500 '// &
                   'to 1e4500) convert to the bits read(text, *) gives')
        ! the fast path (up to 34 significant digits, decimal exponent within 48) and its
        ! edges: 1 to 40 digits, leading and trailing zeros, the point anywhere,
        ! exponents -70 .. 70 (some beyond the reach, some with more than 34 digits)
        mismatches = 0
        do k = 1, 60000
            text = random_decimal()
            call real_from_text(trim(text), mine, status)
            read (text, *, iostat=ios) reference
            if (status /= text_ok .or. ios /= 0 .or. .not. same_bits(mine, reference)) then
                mismatches = mismatches + 1
                if (mismatches < 4) print '(3x,a)', 'differs: '//trim(text)
            end if
        end do
        call check(mismatches == 0, '60000 random decimals of 1 to 40 digits, exponents '// &
                   '-70 to 70, convert to the bits read(text, *) gives (signed zeros too)')
        call real_from_text('0.1', mine, status)
        call check(mine == 0.1_qp .and. status == text_ok, '0.1 is the quad 0.1')
        call real_from_text('1.5+3', mine, status)
        call check(mine == 1500.0_qp, 'an exponent without letter, 1.5+3')
        call real_from_text('.5', mine, status)
        call check(mine == 0.5_qp, '.5')
        call real_from_text('1.e-2', mine, status)
        call check(mine == 0.01_qp .and. status == text_ok, '1.e-2')
        call check(malformed('1.5x') .and. malformed('e5') .and. malformed('.') .and. &
                   malformed('1e') .and. malformed('0x10') .and. malformed('1,5') .and. &
                   malformed('+') .and. malformed('nan(1)') .and. malformed('1e5.0') .and. &
                   malformed('-nan') .and. malformed('1 5'), 'malformed reals refused')
        call integer_from_text('2147483647', value, status)
        call check(value == huge(1) .and. status == text_ok, 'huge(1) converts')
        call integer_from_text('2147483648', value, status)
        call check(status == text_out_of_range, 'huge(1) + 1 is out of range')
        call integer_from_text('-12', value, status)
        call check(value == -12 .and. status == text_ok, '-12')
        call integer_from_text('1.0', value, status)
        call check(status == text_malformed, '1.0 is not an integer')
    contains
        integer function next(m)
            integer, intent(in) :: m
            seed = mod(seed*48271_8, 2147483647_8)
            next = int(mod(seed, int(m, 8)))
        end function next
        !> [sign] [zeros] digits [. digits] [zeros] [e exponent], 1 to 40 digits in all
        function random_decimal() result(word)
            character(len=64) :: word
            integer :: digits, point, j, length
            word = ''
            length = 0
            if (next(3) == 0) call add(word, length, '-')
            if (next(4) == 0) call add(word, length, repeat('0', 1 + next(3)))
            digits = 1 + next(40)
            point = next(digits + 2)
            do j = 1, digits
                if (j == point) call add(word, length, '.')
                if (next(6) == 0) then
                    call add(word, length, '0')
                else
                    call add(word, length, achar(iachar('0') + next(10)))
                end if
            end do
            if (next(4) == 0) call add(word, length, repeat('0', 1 + next(5)))
            if (next(3) /= 0) then
                call add(word, length, 'e')
                call add(word, length, trim(adjustl(integer_word(next(141) - 70))))
            end if
        end function random_decimal
        subroutine add(word, length, piece)
            character(len=*), intent(inout) :: word
            integer, intent(inout) :: length
            character(len=*), intent(in) :: piece
            word(length + 1:length + len(piece)) = piece
            length = length + len(piece)
        end subroutine add
        function integer_word(i) result(w)
            integer, intent(in) :: i
            character(len=12) :: w
            write (w, '(i0)') i
        end function integer_word
        logical function same_bits(a, b)
            real(qp), intent(in) :: a, b
            same_bits = transfer(a, 0_8) == transfer(b, 0_8) .and. &
                        all(transfer(a, [0_8, 0_8]) == transfer(b, [0_8, 0_8]))
        end function same_bits
        logical function malformed(word)
            character(len=*), intent(in) :: word
            integer :: s
            real(qp) :: x
            call real_from_text(word, x, s)
            malformed = s == text_malformed
        end function malformed
    end subroutine exact_conversion

    subroutine escaping()
        type(endpoint_table) :: t
        call section('namelist: control characters escaped')
        call check(escape_text('a'//nl//'b'//achar(9)//achar(13)//'\') == 'a\nb\t\r\\', &
                   'new line, tab, return, backslash')
        call check(escape_text(achar(27)//'[31m'//achar(0)//achar(127)) == '\x1B[31m\x00\x7F', &
                   'escape, NUL, DEL as \xNN')
        call check(escape_text('caf'//achar(195)//achar(169)) == 'caf'//achar(195)//achar(169), &
                   'valid UTF-8 (e acute) unchanged')
        call check(escape_text(achar(255)//achar(194)//achar(133)//achar(195)) == &
                   '\xFF\xC2\x85\xC3', 'invalid UTF-8, C1 control NEL, a cut sequence')
        call check(escape_text(achar(226)//achar(128)//achar(174)) == '\xE2\x80\xAE', &
                   'bidirectional override U+202E')
        call read_endpoint_text('&endpoints n = 1, rho = 0.5, psi = ''x'//nl//'y'' /', &
                                'a'//nl//'b.nml', t)
        call check(size(t%errors) == 1 .and. index(t%errors(1)%text, 'a\nb.nml:1:') == 1 .and. &
                   index(t%errors(1)%text, '"x\ny"') > 0 .and. &
                   index(t%errors(1)%text, nl) == 0, 'path and value escaped in the message')
    end subroutine escaping

    !> Random valid files (separators, repeat counts, null values filled by subscripted
    !! assignments, e/d exponents, any case, comments on their own lines) read by this
    !! reader and by gfortran's read(nml=): the same bits. (Comments after a comma before
    !! a continuation line are left out: gfortran misreads those, issue 9.)
    subroutine same_as_gfortran()
        integer, parameter :: files = 300
        character(len=*), parameter :: path = 'build/test_namelist_random.nml'
        type(endpoint_table) :: t
        character(len=:), allocatable :: text
        integer :: k, n, unit, ios, differ, rejected
        integer(8) :: seed
        real(qp) :: rho(8), psi(8)
        namelist /endpoints/ n, rho, psi
        call section('namelist: the same values as gfortran''s read(nml=)')
        seed = 987654321
        differ = 0
        rejected = 0
        do k = 1, files
            n = 1 + next(8)
            text = '! random file'//nl//'&endpoints'//nl//' n = '//digits_of(n)//nl// &
                   list('rho', '0.', n)//list('PSI', '1.', n)//'/'//nl
            open (newunit=unit, file=path, status='replace', action='write', access='stream')
            write (unit) text
            close (unit)
            call read_endpoint_file(path, t)
            rho = -1.0_qp
            psi = -1.0_qp
            open (newunit=unit, file=path, status='old', action='read')
            read (unit, nml=endpoints, iostat=ios)
            close (unit)
            if (size(t%errors) > 0 .or. ios /= 0) then
                rejected = rejected + 1
                if (rejected < 3) print '(3x,a)', 'rejected: '//text
                cycle
            end if
            if (t%n /= n .or. any(t%rho /= rho(:n)) .or. any(t%psi /= psi(:n))) then
                differ = differ + 1
                if (differ < 3) print '(3x,a)', 'differs: '//text
            end if
        end do
        call check(rejected == 0 .and. differ == 0, integer_text(files)//' random valid '// &
                   'files: every value has the bits gfortran''s read(nml=) gives')
    contains
        integer function next(m)
            integer, intent(in) :: m
            seed = mod(seed*48271_8, 2147483647_8)
            next = int(mod(seed, int(m, 8)))
        end function next
        function digits_of(value) result(text)
            integer, intent(in) :: value
            character(len=:), allocatable :: text
            character(len=12) :: buffer
            write (buffer, '(i0)') value
            text = trim(buffer)
        end function digits_of
        !> A value below 1 ('0.') or between 1 and 2 ('1.') with 1 to 40 digits.
        function number(lead) result(text)
            character(len=*), intent(in) :: lead
            character(len=:), allocatable :: text
            integer :: j
            text = lead//digits_of(1 + next(9))
            do j = 1, next(40)
                text = text//digits_of(next(10))
            end do
            select case (next(4))
            case (1); text = text//'e0'
            case (2); text = text//'D+00'
            end select
        end function number
        !> `name = ...` for n rows: plain, repeated, or null values filled later (a
        !! null value is an empty item between commas).
        function list(name, lead, n) result(text)
            character(len=*), intent(in) :: name, lead
            integer, intent(in) :: n
            character(len=:), allocatable :: text, fills, value
            character(len=*), parameter :: separators(4) = [character(len=6) :: ', ', ' ', &
                                                            ','//nl//'    ', ' ,  ']
            integer :: row, r
            logical :: null, previous_null
            text = ' '//name//' = '
            fills = ''
            row = 1
            previous_null = .false.
            do while (row <= n)
                value = number(lead)
                r = 1 + next(n - row + 1)
                null = .false.
                select case (next(3))
                case (0)
                    r = 1
                case (1)
                    value = digits_of(r)//'*'//value
                case (2)
                    null = .true.
                    fills = fills//' '//name//'('//digits_of(row)//') = '//value//nl
                    value = ''
                    r = 1
                end select
                if (row > 1) then
                    if (null .or. previous_null) then
                        text = text//', '
                    else
                        text = text//trim(separators(1 + next(4)))//' '
                    end if
                end if
                text = text//value
                previous_null = null
                row = row + r
            end do
            if (previous_null .and. n > 1) text = text//','
            text = text//nl//'! filled'//nl//fills
        end function list
    end subroutine same_as_gfortran

end module test_namelist
