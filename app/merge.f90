!> `brachistochrone merge`: join the CSV files of the slices of one run (a job array).
!!
!!     brachistochrone merge [--force] OUT.csv SLICE1.csv SLICE2.csv ...
!!
!! Each slice is a CSV written by `brachistochrone --csv` for some rows K..L of one input
!! (`--first/--last` or `--slice`). The merge checks that every slice is such a file, that
!! all come from the same input (its SHA-256 and size, the `# input sha256:` line), the same
!! program version, field and settings, that their row ranges cover 1..N exactly once
!! (gaps and overlaps are reported by row numbers, the arguments may come in any order)
!! and that each holds exactly L-K+1 data rows. Then it writes one CSV (OUT `-` is
!! standard output): the provenance of the slice that starts at row 1 with its input line
!! saying `rows 1 to N of N`, a line `# merged from M slices: FILE (rows K to L), ...`,
!! a one-line note in place of the effective-input echo (each slice's echo covers only
!! its rows), the header and every row in row order. Rows are streamed, never all held.
!! Every problem is reported at once (file, line, what is wrong). Exit codes: 0 merged;
!! 1 usage or input error (nothing written); 3 I/O error (nothing written); 128 + N
!! killed by signal N. OUT is written by `brachistochrone_safe_file`.
module brachistochrone_app_merge
    use, intrinsic :: iso_fortran_env, only: error_unit, output_unit, int64
    use brachistochrone_version, only: program_name, program_version
    use brachistochrone_safe_file, only: safe_file, open_output, finish_output, &
            commit_outputs, discard_outputs, same_file, safe_ok, safe_refused, standard_output
    use brachistochrone_strings, only: integer_text, escape_text, integer_from_text, text_ok
    use brachistochrone_command_line, only: get_argument
    use brachistochrone_result_output, only: csv_header
    use brachistochrone_app_support, only: stop_with
    implicit none
    private

    public :: run_merge

    character(len=*), parameter :: name = program_name//' merge'
    character(len=*), parameter :: cartesian_header = 'x,y,'//csv_header(9:)
    integer, parameter :: exit_ok = 0, exit_usage = 1, exit_io = 3
    integer, parameter :: block_size = 1048576      ! bytes read at a time
    integer, parameter :: max_row_problems = 3      ! bad rows reported per slice
    character(len=*), parameter :: input_key = '# input: ', sha_key = '# input sha256: ', &
        field_key = '# field: ', version_key = '# '//program_name//' ', &
        echo_key = '# effective input:', echo_end = '# /'

    !> A file read line by line in large blocks (stream access): the current line is
    !! `buffer(line_start:line_end)`.
    type :: line_reader
        integer :: unit = 0
        logical :: open = .false.
        integer(int64) :: size = 0, done = 0        ! bytes in the file, bytes read
        character(len=:), allocatable :: buffer
        integer :: first = 1, last = 0              ! unread bytes: buffer(first:last)
        integer :: line_start = 1, line_end = 0
        integer :: line_number = 0
        logical :: complete = .true.                ! the line ended with a newline
        integer :: error = 0                        ! iostat of a failed read
    end type line_reader

    !> What a slice's comments say about it.
    type :: slice_info
        character(len=:), allocatable :: path, version, field, sha, settings
        integer :: first = 0, last = 0, n = 0       ! rows first..last of n
        integer :: input_line = 0, sha_line = 0, version_line = 1, field_line = 0
        integer :: header_line = 0                  ! line number of the CSV header
        character(len=:), allocatable :: header     ! the header (rho,psi,... or x,y,...)
        logical :: usable = .false.                 ! the comments parsed
    end type slice_info

    type(slice_info), allocatable :: slices(:)
    integer, allocatable :: order(:)                 ! slices by first row
    character(len=:), allocatable :: out_path, problems
    integer :: count_problems = 0, exit_code = exit_ok
    logical :: force = .false.
    type(safe_file) :: files(1)

contains

    !> Run the subcommand on the command arguments from number `first` on; stops with the
    !! exit code.
    subroutine run_merge(first)
        integer, intent(in) :: first !! index of the subcommand's first argument
        integer :: k, status
        logical :: checked
        character(len=:), allocatable :: problem
        problems = ''
        call parse_arguments(first)
        do k = 1, size(slices)
            call read_comments(slices(k))
        end do
        call check_agreement()
        call check_coverage()
        ! standard output cannot be taken back: check every row before writing any
        checked = out_path == standard_output
        if (checked) call copy_slices()
        if (.not. checked .or. count_problems == 0) then
            call open_output(files(1), out_path, force, status, problem)
            if (status /= safe_ok) call add_problem(problem, &
                merge(exit_usage, exit_io, status == safe_refused))
        end if
        if (.not. checked .or. files(1)%is_open()) call copy_slices()
        if (count_problems == 0) call commit()
        if (count_problems > 0) then
            call discard_outputs(files)
            write (error_unit, '(a)', advance='no') problems
            call fail(exit_code, integer_text(count_problems)//' problem(s); nothing written')
        end if
        stop exit_ok, quiet=.true.
    end subroutine run_merge

    !> Options, OUT and the slices from the command line; stops on --help, --version or
    !! a usage error.
    subroutine parse_arguments(first)
        integer, intent(in) :: first
        character(len=:), allocatable :: argument
        integer :: k
        logical :: options_done
        allocate (slices(0))
        options_done = .false.
        do k = first, command_argument_count()
            argument = get_argument(k)
            if (.not. options_done .and. len(argument) > 1 .and. argument(1:1) == '-') then
                select case (argument)
                case ('-h', '--help')
                    call usage(output_unit)
                    stop exit_ok, quiet=.true.
                case ('--version')
                    write (output_unit, '(a)') name//' '//program_version
                    stop exit_ok, quiet=.true.
                case ('--force')
                    force = .true.
                case ('--')
                    options_done = .true.
                case default
                    call fail(exit_usage, 'unknown option '//escape_text(argument)// &
                              ' (see --help)')
                end select
            else if (.not. allocated(out_path)) then
                out_path = argument
            else
                slices = [slices, slice_info(path=argument)]
            end if
        end do
        if (size(slices) == 0) call fail(exit_usage, 'give OUT.csv and the slices'' CSV '// &
                                         'files (see --help)')
        do k = 1, size(slices)
            if (out_path /= standard_output .and. same_file(out_path, slices(k)%path)) &
                call fail(exit_usage, 'OUT '//escape_text(out_path)//' is the slice '// &
                          escape_text(slices(k)%path)//'; choose another name')
        end do
    end subroutine parse_arguments

    !> First pass over a slice: its provenance comments and header (not its rows).
    subroutine read_comments(slice)
        type(slice_info), intent(inout) :: slice
        type(line_reader) :: reader
        logical :: found, in_echo
        character(len=:), allocatable :: where
        slice%settings = ''
        call open_reader(reader, slice%path)
        if (.not. reader%open) return
        where = escape_text(slice%path)//' line '
        call next_line(reader, found)
        if (.not. found .or. .not. starts(reader, version_key)) then
            call add_problem(escape_text(slice%path)//': not a CSV written by '// &
                             program_name//' --csv (its first line is not "'// &
                             version_key//'VERSION")', exit_usage)
            call close_reader(reader)
            return
        end if
        slice%version = line(reader)
        in_echo = .false.
        do while (found)
            if (.not. starts(reader, '#')) exit
            call parse_comment(slice, reader, in_echo)
            call next_line(reader, found)
        end do
        if (reader%error /= 0) then
            call read_failed(slice%path, reader)
        else if (.not. found) then
            call add_problem(escape_text(slice%path)//': ends before the header line '// &
                             csv_header//' (truncated?)', exit_usage)
        else if (line(reader) /= csv_header .and. line(reader) /= cartesian_header) then
            call add_problem(where//integer_text(reader%line_number)//': header "'// &
                             escape_text(line(reader))//'", expected '//csv_header//' (or '// &
                             cartesian_header//' for uniform gravity)', exit_usage)
        else if (in_echo) then
            call add_problem(escape_text(slice%path)//': the effective input is not '// &
                             'closed by "'//echo_end//'"', exit_usage)
        else
            slice%header_line = reader%line_number
            slice%header = line(reader)
            call check_comments(slice)
        end if
        call close_reader(reader)
    end subroutine read_comments

    !> Take what the merge needs from one comment line of a slice.
    subroutine parse_comment(slice, reader, in_echo)
        type(slice_info), intent(inout) :: slice
        type(line_reader), intent(in) :: reader
        logical, intent(inout) :: in_echo
        integer :: equals
        if (in_echo) then
            if (line(reader) == echo_end) in_echo = .false.
            ! settings: `#   key = value` with a value, except n (the slice's own rows)
            equals = index(line(reader), ' = ')
            if (equals > 0 .and. starts(reader, '#   ') .and. .not. starts(reader, '#    ') &
                .and. .not. starts(reader, '#   n = ')) then
                if (reader%line_end - reader%line_start + 1 > equals + 2) slice%settings = &
                    slice%settings//reader%buffer(reader%line_start + 4:reader%line_end)//'; '
            end if
        else if (starts(reader, field_key)) then
            slice%field = line(reader)
            slice%field_line = reader%line_number
        else if (starts(reader, sha_key)) then
            slice%sha = reader%buffer(reader%line_start + len(sha_key):reader%line_end)
            slice%sha_line = reader%line_number
        else if (starts(reader, input_key)) then
            slice%input_line = reader%line_number
            call parse_rows(slice, line(reader))
        else if (starts(reader, echo_key)) then
            in_echo = .true.
        end if
    end subroutine parse_comment

    !> `rows K to L of N` after the last ", rows " of the input line.
    subroutine parse_rows(slice, text)
        type(slice_info), intent(inout) :: slice
        character(len=*), intent(in) :: text
        integer :: p, to, of, s1, s2, s3
        p = index(text, ', rows ', back=.true.)
        s1 = 1
        s2 = 1
        s3 = 1
        if (p > 0) then
            to = index(text(p:), ' to ') + p - 1
            of = index(text(p:), ' of ') + p - 1
            if (to > p .and. of > to) then
                call integer_from_text(text(p + 7:to - 1), slice%first, s1)
                call integer_from_text(text(to + 4:of - 1), slice%last, s2)
                call integer_from_text(text(of + 4:), slice%n, s3)
            end if
        end if
        if (p == 0 .or. s1 /= text_ok .or. s2 /= text_ok .or. s3 /= text_ok .or. &
            slice%first < 1 .or. slice%last < slice%first .or. slice%n < slice%last) then
            call add_problem(escape_text(slice%path)//' line '// &
                             integer_text(slice%input_line)//': "'//escape_text(text)// &
                             '" does not end in "rows K to L of N" with 1 <= K <= L <= N', &
                             exit_usage)
            slice%input_line = -1
        end if
    end subroutine parse_rows

    !> The comments of one slice name its field, input rows and input checksum.
    subroutine check_comments(slice)
        type(slice_info), intent(inout) :: slice
        character(len=:), allocatable :: file
        integer :: comma
        file = escape_text(slice%path)//': '
        if (slice%field_line == 0) call add_problem(file//'no "'//field_key// &
                                                    '" line in its provenance', exit_usage)
        if (slice%input_line == 0) call add_problem(file//'no "'//input_key// &
            'PATH, rows K to L of N" line in its provenance', exit_usage)
        if (slice%sha_line == 0) then
            call add_problem(file//'no "'//sha_key//'HEX, SIZE bytes" line: written by a '// &
                             'version of '//program_name//' without input checksums; '// &
                             'solve the slice again with this one', exit_usage)
        else
            comma = index(slice%sha, ', ')
            if (comma /= 65 .or. verify(slice%sha(:max(comma - 1, 0)), '0123456789abcdef') &
                /= 0) call add_problem(file//'line '//integer_text(slice%sha_line)// &
                                       ': not 64 hexadecimal digits and a size', exit_usage)
        end if
        slice%usable = slice%field_line > 0 .and. slice%input_line > 0 .and. slice%sha_line > 0
    end subroutine check_comments

    !> Every usable slice agrees with the first usable one: input checksum and size,
    !! version, field, number of rows and settings.
    subroutine check_agreement()
        integer :: k, ref
        ref = findloc(slices%usable, .true., dim=1)
        if (ref == 0) return
        do k = ref + 1, size(slices)
            if (.not. slices(k)%usable) cycle
            associate (a => slices(ref), b => slices(k))
                if (b%sha /= a%sha) call differs(b, b%sha_line, 'input sha256 '//b%sha, &
                    a%sha//': the slices come from different inputs')
                if (b%version /= a%version) call differs(b, b%version_line, &
                    escape_text(b%version(3:)), escape_text(a%version(3:)))
                if (b%field /= a%field) call differs(b, b%field_line, &
                    escape_text(b%field(3:)), escape_text(a%field(3:)))
                if (b%n /= a%n) call differs(b, b%input_line, 'input of '// &
                    integer_text(b%n)//' rows', integer_text(a%n)//' rows')
                if (b%settings /= a%settings) call differs(b, b%header_line, &
                    'effective settings "'//escape_text(b%settings)//'"', '"'// &
                    escape_text(a%settings)//'"')
            end associate
        end do
    contains
        subroutine differs(slice, line_number, this, that)
            type(slice_info), intent(in) :: slice
            integer, intent(in) :: line_number
            character(len=*), intent(in) :: this, that
            call add_problem(escape_text(slice%path)//' line '//integer_text(line_number)// &
                             ': '//this//', but '//escape_text(slices(ref)%path)//' has '// &
                             that, exit_usage)
        end subroutine differs
    end subroutine check_agreement

    !> Sort the usable slices by first row; their ranges must cover 1..N exactly once.
    subroutine check_coverage()
        integer :: k, j, next, before, n
        order = pack([(k, k=1, size(slices))], slices%usable)
        do k = 2, size(order)                 ! insertion sort: few slices
            j = k
            do while (j > 1)
                if (slices(order(j - 1))%first <= slices(order(j))%first) exit
                order(j - 1:j) = order(j:j - 1:-1)
                j = j - 1
            end do
        end do
        if (size(order) == 0 .or. .not. all(slices%usable)) return
        n = slices(order(1))%n
        if (any(slices%n /= n)) return        ! reported by check_agreement
        next = 1                              ! first row not yet covered
        before = 0                            ! the slice that covers up to next - 1
        do k = 1, size(order)
            associate (s => slices(order(k)))
                if (s%first > next) call add_problem(range_text(next, s%first - 1)// &
                    ' of '//integer_text(n)//' in no slice (a missing slice?)', exit_usage)
                if (s%first < next) call add_problem( &
                    range_text(s%first, min(s%last, next - 1))//' in two slices: '// &
                    escape_text(slices(before)%path)//' and '//escape_text(s%path), exit_usage)
                if (s%last + 1 > next) then
                    next = s%last + 1
                    before = order(k)
                end if
            end associate
        end do
        if (next <= n) call add_problem(range_text(next, n)//' of '//integer_text(n)// &
                                        ' in no slice (a missing slice?)', exit_usage)
    end subroutine check_coverage

    !> Check the rows of every slice in row order and copy them to the output if it is
    !! open (it is closed at the first problem).
    subroutine copy_slices()
        integer :: k
        do k = 1, size(order)
            call copy_slice(order(k), k == 1)
            if (count_problems > 0) call discard_outputs(files)
        end do
    end subroutine copy_slices

    !> Second pass over slice `k`: check its rows and copy them to the output (when open);
    !! the first slice in row order also gives the provenance.
    subroutine copy_slice(k, first_slice)
        integer, intent(in) :: k
        logical, intent(in) :: first_slice
        type(line_reader) :: reader
        logical :: found, in_echo
        integer :: rows, bad
        call open_reader(reader, slices(k)%path)
        if (.not. reader%open) return
        in_echo = .false.
        rows = 0
        bad = 0
        call next_line(reader, found)
        do while (found)
            if (reader%line_number < slices(k)%header_line) then
                if (first_slice) call put_comment(k, line(reader), in_echo)
            else if (reader%line_number == slices(k)%header_line) then
                if (first_slice) call files(1)%put(slices(k)%header)
            else
                rows = rows + 1
                call check_row(k, reader, bad)
                call files(1)%put(line(reader))
            end if
            call next_line(reader, found)
        end do
        if (reader%error /= 0) call read_failed(slices(k)%path, reader)
        call close_reader(reader)
        if (reader%error == 0 .and. rows /= slices(k)%last - slices(k)%first + 1) &
            call add_problem(escape_text(slices(k)%path)//': '//integer_text(rows)// &
                ' data rows, but its line '//integer_text(slices(k)%input_line)//' says '// &
                range_text(slices(k)%first, slices(k)%last)//' ('// &
                integer_text(slices(k)%last - slices(k)%first + 1)//' rows): truncated or '// &
                'edited; solve the slice again', exit_usage)
    end subroutine copy_slice

    !> A data row has 8 fields and ends with a newline.
    subroutine check_row(k, reader, bad)
        integer, intent(in) :: k
        type(line_reader), intent(in) :: reader
        integer, intent(inout) :: bad
        integer :: i, commas
        character(len=:), allocatable :: what
        commas = 0
        do i = reader%line_start, reader%line_end
            if (reader%buffer(i:i) == ',') commas = commas + 1
        end do
        if (.not. reader%complete) then
            what = 'the last row has no end of line (the file is truncated)'
        else if (commas /= 7) then
            what = 'not a row of 8 fields '//csv_header
        else
            return
        end if
        bad = bad + 1
        if (bad <= max_row_problems) then
            call add_problem(escape_text(slices(k)%path)//' line '// &
                             integer_text(reader%line_number)//': '//what, exit_usage)
        else if (bad == max_row_problems + 1) then
            call add_problem(escape_text(slices(k)%path)//': more bad rows after line '// &
                             integer_text(reader%line_number - 1)//' (not listed)', exit_usage)
        end if
    end subroutine check_row

    !> Copy one provenance line of the first slice, rewritten for the whole run.
    subroutine put_comment(k, text, in_echo)
        integer, intent(in) :: k
        character(len=*), intent(in) :: text
        logical, intent(inout) :: in_echo
        integer :: j
        character(len=:), allocatable :: merged
        if (in_echo) then
            in_echo = text /= echo_end
        else if (starts_with(text, echo_key)) then
            in_echo = .true.
            call files(1)%put(echo_key//' not repeated here (each slice''s echo covers '// &
                              'only its own rows; the slices'' settings agree)')
        else if (starts_with(text, input_key)) then
            call files(1)%put(text(:index(text, ', rows ', back=.true.) - 1)//', rows 1 to '// &
                              integer_text(slices(k)%n)//' of '//integer_text(slices(k)%n))
        else if (starts_with(text, sha_key)) then
            call files(1)%put(text)
            merged = '# merged from '//integer_text(size(order))//' slices: '
            do j = 1, size(order)
                associate (s => slices(order(j)))
                    if (j > 1) merged = merged//', '
                    merged = merged//escape_text(s%path)//' ('//range_text(s%first, s%last)//')'
                end associate
            end do
            call files(1)%put(merged)
        else
            call files(1)%put(text)
        end if
    end subroutine put_comment

    !> Finish and commit OUT.
    subroutine commit()
        integer :: status
        character(len=:), allocatable :: problem
        call finish_output(files(1), status, problem)
        if (status == safe_ok) call commit_outputs(files, status, problem)
        if (status /= safe_ok) call add_problem(problem, &
                                                merge(exit_usage, exit_io, status == safe_refused))
    end subroutine commit

    !> Open `path` for reading in blocks; on failure a problem is added and the reader
    !! is not open.
    subroutine open_reader(reader, path)
        type(line_reader), intent(out) :: reader
        character(len=*), intent(in) :: path
        integer :: ios
        character(len=256) :: message
        open (newunit=reader%unit, file=path, access='stream', form='unformatted', &
              status='old', action='read', iostat=ios, iomsg=message)
        if (ios == 0) inquire (unit=reader%unit, size=reader%size)
        if (ios == 0 .and. reader%size < 0) then
            close (reader%unit)
            ios = 1
            message = 'not a regular file'
        end if
        if (ios /= 0) then
            call add_problem(escape_text(path)//': cannot read: '//trim(message), exit_usage)
            return
        end if
        allocate (character(len=block_size) :: reader%buffer)
        reader%open = .true.
    end subroutine open_reader

    subroutine close_reader(reader)
        type(line_reader), intent(inout) :: reader
        if (reader%open) close (reader%unit)
        reader%open = .false.
    end subroutine close_reader

    !> The next line (without its newline) as buffer(line_start:line_end); found false at
    !! the end of the file or on a read error (`error`).
    subroutine next_line(reader, found)
        type(line_reader), intent(inout) :: reader
        logical, intent(out) :: found
        integer :: k
        found = .false.
        do
            k = index(reader%buffer(reader%first:reader%last), new_line('a'))
            if (k > 0) then
                reader%line_start = reader%first
                reader%line_end = reader%first + k - 2
                reader%first = reader%first + k
                reader%complete = .true.
                exit
            end if
            if (reader%done >= reader%size) then
                if (reader%first > reader%last) return
                reader%line_start = reader%first
                reader%line_end = reader%last
                reader%first = reader%last + 1
                reader%complete = .false.
                exit
            end if
            call refill(reader)
            if (reader%error /= 0) return
        end do
        found = .true.
        reader%line_number = reader%line_number + 1
    end subroutine next_line

    !> Keep the unread bytes, read the next block after them (the buffer grows for a
    !! line longer than it).
    subroutine refill(reader)
        type(line_reader), intent(inout) :: reader
        character(len=:), allocatable :: kept
        integer :: remaining, count
        remaining = reader%last - reader%first + 1
        kept = reader%buffer(reader%first:reader%last)
        if (remaining > len(reader%buffer) / 2) then
            deallocate (reader%buffer)
            allocate (character(len=2*(remaining + block_size)) :: reader%buffer)
        end if
        reader%buffer(:remaining) = kept
        count = int(min(int(len(reader%buffer) - remaining, int64), reader%size - reader%done))
        read (reader%unit, pos=reader%done + 1, iostat=reader%error) &
            reader%buffer(remaining + 1:remaining + count)
        reader%done = reader%done + count
        reader%first = 1
        reader%last = remaining + count
    end subroutine refill

    !> The current line.
    pure function line(reader) result(text)
        type(line_reader), intent(in) :: reader
        character(len=:), allocatable :: text
        text = reader%buffer(reader%line_start:reader%line_end)
    end function line

    pure logical function starts(reader, prefix)
        type(line_reader), intent(in) :: reader
        character(len=*), intent(in) :: prefix
        starts = reader%line_end - reader%line_start + 1 >= len(prefix)
        if (starts) starts = reader%buffer(reader%line_start:reader%line_start + &
                                           len(prefix) - 1) == prefix
    end function starts

    pure logical function starts_with(text, prefix)
        character(len=*), intent(in) :: text, prefix
        starts_with = len(text) >= len(prefix)
        if (starts_with) starts_with = text(:len(prefix)) == prefix
    end function starts_with

    !> `row K` or `rows K to L`.
    pure function range_text(first, last) result(text)
        integer, intent(in) :: first, last
        character(len=:), allocatable :: text
        if (first == last) then
            text = 'row '//integer_text(first)
        else
            text = 'rows '//integer_text(first)//' to '//integer_text(last)
        end if
    end function range_text

    subroutine read_failed(path, reader)
        character(len=*), intent(in) :: path
        type(line_reader), intent(in) :: reader
        call add_problem(escape_text(path)//': read error after line '// &
                         integer_text(reader%line_number)//' (iostat '// &
                         integer_text(reader%error)//')', exit_io)
    end subroutine read_failed

    !> Note a problem (reported at the end); the exit code is the worst one.
    subroutine add_problem(text, code)
        character(len=*), intent(in) :: text
        integer, intent(in) :: code
        count_problems = count_problems + 1
        problems = problems//name//': '//text//new_line('a')
        exit_code = max(exit_code, code)
    end subroutine add_problem

    subroutine usage(unit)
        integer, intent(in) :: unit
        write (unit, '(a)') 'usage: '//name//' [--force] OUT.csv SLICE1.csv SLICE2.csv ...'
        write (unit, '(a)') ''
        write (unit, '(a)') 'Join the CSV files (--csv) of the slices of one run (--slice '// &
            'K/N, --first/--last) into'
        write (unit, '(a)') 'OUT.csv (- for standard output), rows in row order. The slices,'// &
            ' in any order, must'
        write (unit, '(a)') 'come from the same input (its sha256 and size), version, field'// &
            ' and settings, and'
        write (unit, '(a)') 'cover rows 1..N exactly once; every problem is reported.'
        write (unit, '(a)') '  --force   replace OUT.csv if it exists'
        write (unit, '(a)') 'Exit codes: 0 merged; 1 usage or input error (nothing '// &
            'written); 3 I/O error. Version '//program_version//'.'
    end subroutine usage

    subroutine fail(code, text)
        integer, intent(in) :: code
        character(len=*), intent(in) :: text
        call stop_with(name, code, text)
    end subroutine fail

end module brachistochrone_app_merge
