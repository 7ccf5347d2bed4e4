!> Writing solved endpoint tables: readable table, CSV, namelist; provenance; safe files.
!!
!! Every output file starts with provenance (program and version, compiler and options,
!! date, input path and rows, and the effective input as a namelist group, so a result
!! file says how it was made and can be run again). Numbers have 36 significant digits,
!! enough for every binary128 value to read back to the same bits. Every line goes through
!! `brachistochrone_safe_file` (checked write(2), temporary file committed only when
!! complete, all outputs of a run or none): a failed or killed run never leaves a
!! partial file under the target name, and an existing file is replaced only when the
!! caller says so.
module brachistochrone_result_output
    use, intrinsic :: iso_fortran_env, only: compiler_version, compiler_options, int64
    use brachistochrone_kinds, only: qp
    use brachistochrone_status, only: status_word, status_word_fixed, status_ok, &
                                      status_inaccessible
    use brachistochrone_version, only: program_name, program_version
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_field_interface, only: brachistochrone_field
    use brachistochrone_arches, only: arch_word, arch_word_fixed
    use brachistochrone_endpoint_input, only: endpoint_table, group_name
    use brachistochrone_strings, only: integer_text, escape_text, put_integer
    use brachistochrone_format, only: format_quad, write_quad
    use brachistochrone_safe_file, only: safe_file, open_scratch, close_scratch, safe_ok
    implicit none
    private

    public :: format_real, csv_header, csv_row, write_table_header, write_table_row
    public :: output_request, write_outputs, provenance_lines, write_results_namelist
    public :: results_group_name, max_echoed_rows
    public :: write_provenance
    public :: result_stream, start_stream, format_stream_row, write_stream_block, finish_stream

    !> Header line of the CSV output.
    character(len=*), parameter :: csv_header = 'rho,psi,arch,R,s,t,steps,status'
    !> Name of the namelist group of the namelist output.
    character(len=*), parameter :: results_group_name = 'results'
    !> Lines formatted per parallel block of an output, and room for one line.
    integer, parameter :: format_block = 8192, csv_row_length = 256
    !> What `put_lines` writes: CSV rows, or the namelist values of one variable.
    integer, parameter :: csv_rows = 0, value_rho = 1, value_psi = 2, &
                          value_apse_radius = 3, value_arclength = 4, value_time = 5, &
                          value_arch = 6, value_steps = 7, value_status = 8
    !> The variables of the namelist output in file order, and room for one value line.
    integer, parameter :: namelist_columns(8) = [value_rho, value_psi, value_arch, &
                          value_apse_radius, value_arclength, value_time, value_steps, &
                          value_status], value_line_length = 48
    !> Rows per block of a `result_stream`.
    integer, parameter :: stream_block = 2048
    !> The effective input echoed into provenance lists its arrays up to this many rows.
    integer, parameter :: max_echoed_rows = 1000

    !> Which files to write.
    type :: output_request
        character(len=:), allocatable :: csv_path   !! CSV file ('' for none)
        character(len=:), allocatable :: nml_path   !! namelist results file ('' for none)
        character(len=:), allocatable :: table_path !! readable table file ('' for none)
        character(len=:), allocatable :: curves_path !! curve points CSV ('' for none)
        logical :: force = .false.                  !! replace existing files
    end type output_request

    !> A line of text, for lists of lines.
    type :: line_text
        character(len=:), allocatable :: text
    end type line_text

    !> The CSV and namelist outputs written while the rows are solved: `start_stream`
    !! writes the provenance and headings; the threads format each solved row
    !! (`format_stream_row`) into one of two slots of `stream_block` rows, and one
    !! thread at a time writes a finished block (`write_stream_block`, blocks in row
    !! order) while the others solve the next. The CSV gets its rows and the namelist its
    !! first variable directly; the namelist's other variables (one after the other in
    !! the file) go to a scratch file, block by block, and `finish_stream` appends them.
    !! The bytes are those of `write_outputs`.
    type :: result_stream
        logical :: csv = .false.          !! the CSV is written
        logical :: nml = .false.          !! the namelist is written
        integer :: block_rows = stream_block !! rows per block
        character(len=:), allocatable :: date !! the provenance date
        character(len=csv_row_length), allocatable :: csv_lines(:, :)   !! (row, slot)
        integer, allocatable :: csv_lengths(:, :)                       !! (row, slot)
        character(len=value_line_length), allocatable :: nml_lines(:, :, :) !! (var, row, slot)
        integer, allocatable :: nml_lengths(:, :, :)                        !! (var, row, slot)
        character(len=16) :: headings(8) = ''     !! ' RHO=', ' PSI=', ' ARCH=', ...
        type(safe_file) :: spill                  !! the namelist's variables 2..8
        integer(int64), allocatable :: spilled(:, :) !! bytes of variable k of block b
        integer :: blocks = 0                     !! blocks written
    end type result_stream

contains

    !> A binary128 value with 36 significant digits (enough to read back the same bits),
    !! in the form 1.84781963328078886097052679178216610e-01.
    pure function format_real(x) result(text)
        real(qp), intent(in) :: x !! value
        character(len=:), allocatable :: text
        text = format_quad(x)
    end function format_real

    !> The CSV header of a field: `csv_header`, with the field's coordinates first (`x,y`
    !! for uniform gravity).
    pure function field_csv_header(field) result(header)
        class(brachistochrone_field), intent(in) :: field !! the field solved
        character(len=:), allocatable :: header
        header = field%coordinate(1)//','//field%coordinate(2)//csv_header(8:)
    end function field_csv_header

    !> One CSV row: `rho,psi,arch,R,s,t,steps,status`; empty fields where a value does
    !! not exist (R and s in the sector of inaccessibility).
    pure function csv_row(solution) result(line)
        type(endpoint_solution), intent(in) :: solution !! the solved endpoint
        character(len=:), allocatable :: line
        character(len=csv_row_length) :: buffer
        integer :: length
        call csv_row_into(solution, buffer, length)
        line = buffer(1:length)
    end function csv_row

    !> Header of the readable table: the field, its units.
    subroutine write_table_header(out, field)
        type(safe_file), intent(inout) :: out             !! the output
        class(brachistochrone_field), intent(in) :: field !! the field solved
        call out%put('# Brachistochrones from A = '//field%start()//' under '// &
            field%description()//exponent_note(field)//', '//field%units())
        call out%put('# row  '//coordinate(field, 1)//', '//coordinate(field, 2)// &
            ' -> arch, steps, status; then R-bar, s, t (36 significant digits)')
    end subroutine write_table_header

    !> One endpoint as a block, like a row of Tee's Table 1.
    subroutine write_table_row(out, field, row, solution)
        type(safe_file), intent(inout) :: out           !! the output
        class(brachistochrone_field), intent(in) :: field !! the field solved
        integer, intent(in) :: row                      !! row number in the input
        type(endpoint_solution), intent(in) :: solution !! the solved endpoint
        call out%put('')
        call out%put(integer_text(row)//'  '//coordinate(field, 1)//' = '// &
            short_real(solution%rho)//'  '//coordinate(field, 2)//' = '// &
            short_real(solution%psi)//'  ->  '//arch_word(solution%arch)// &
            ', steps = '//integer_text(solution%steps)//', '//status_word(solution%status))
        if (solution%has_apse_radius) call out%put('    R-bar = '// &
            format_real(solution%apse_radius))
        if (solution%has_arclength) call out%put('    s     = '// &
            format_real(solution%arclength))
        if (solution%has_time) then
            if (solution%status /= status_inaccessible) then
                call out%put('    t     = '//format_real(solution%time))
            else
                call out%put('    t    >= '//format_real(solution%time)// &
                    '  ('//field%bound_note()//')')
            end if
        end if
    end subroutine write_table_row

    !> Provenance: who made the results, how, from what. `date` is an ISO 8601 stamp.
    function provenance_lines(field, table, first, last, date) result(lines)
        class(brachistochrone_field), intent(in) :: field !! the field solved
        type(endpoint_table), intent(in) :: table !! the input
        integer, intent(in) :: first, last        !! rows solved
        character(len=*), intent(in) :: date      !! when
        type(line_text), allocatable :: lines(:)
        lines = [line_text(program_name//' '//program_version), &
                 line_text('compiler: '//compiler_version()), &
                 line_text('compiler options: '//compiler_options()), &
                 line_text('date: '//date), &
                 line_text('field: '//field%name()//', '//field%description()// &
                           exponent_note(field)//', '//field%units()), &
                 line_text('input: '//escape_text(table%path)//', rows '// &
                           integer_text(first)//' to '//integer_text(last)//' of '// &
                           integer_text(table%n)), &
                 line_text('input sha256: '//table%checksum//', '// &
                           integer_text(table%bytes)//' bytes'), &
                 line_text('effective input:')]
        lines = [lines, effective_input(field, table, first, last)]
    end function provenance_lines

    !> Write the provenance (`provenance_lines`) as comment lines starting with `prefix`.
    subroutine write_provenance(out, field, table, first, last, date, prefix)
        type(safe_file), intent(inout) :: out     !! the output
        class(brachistochrone_field), intent(in) :: field !! the field solved
        type(endpoint_table), intent(in) :: table !! the input
        integer, intent(in) :: first, last        !! rows solved
        character(len=*), intent(in) :: date      !! when
        character(len=*), intent(in) :: prefix    !! comment marker, such as '# '
        type(line_text), allocatable :: lines(:)
        integer :: k
        lines = provenance_lines(field, table, first, last, date)
        do k = 1, size(lines)
            call out%put(prefix//lines(k)%text)
        end do
    end subroutine write_provenance

    !> The input as read (after defaults), as a namelist group that reads back the same
    !! rows: values in full precision, null values where a row has no estimates.
    function effective_input(field, table, first, last) result(lines)
        class(brachistochrone_field), intent(in) :: field
        type(endpoint_table), intent(in) :: table
        integer, intent(in) :: first, last
        type(line_text), allocatable :: lines(:)
        integer :: i, rows, count_lines, k
        logical :: echo, estimates
        rows = last - first + 1
        echo = rows <= max_echoed_rows
        estimates = echo .and. any(table%has_estimates(first:last))
        count_lines = 6 + merge(1, 0, field%exponent() /= 0.0_qp) &
                      + merge(2*(rows + 1), 1, echo) &
                      + merge(2*(rows + 1), 0, estimates)
        allocate (lines(count_lines))
        k = 0
        call put('&'//group_name)
        call put('  n = '//integer_text(rows))
        call put('  secant_tolerance = '//format_real(table%secant_tolerance))
        call put('  curve_points = '//integer_text(table%curve_points))
        call put('  force = '''//field%name()//'''')
        if (field%exponent() /= 0.0_qp) call put('  exponent = '//format_real(field%exponent()))
        if (.not. echo) then
            call put('  ! '//coordinate(field, 1)//', '//coordinate(field, 2)// &
                     ', r0, r1: '//integer_text(rows)//' rows, more than '// &
                     integer_text(max_echoed_rows)//' are not echoed; the rows of this '// &
                     'file carry '//coordinate(field, 1)//' and '//coordinate(field, 2))
        else
            call put('  '//coordinate(field, 1)//' =')
            do i = first, last
                call put('    '//format_real(table%rho(i))//',')
            end do
            call put('  '//coordinate(field, 2)//' =')
            do i = first, last
                call put('    '//format_real(table%psi(i))//',')
            end do
            if (estimates) then
                call put('  r0 =')
                do i = first, last
                    call put_estimate(table%r0(i), table%has_estimates(i))
                end do
                call put('  r1 =')
                do i = first, last
                    call put_estimate(table%r1(i), table%has_estimates(i))
                end do
            end if
        end if
        call put('/')
    contains
        subroutine put(text)
            character(len=*), intent(in) :: text
            k = k + 1
            lines(k)%text = text
        end subroutine put
        subroutine put_estimate(value, given)
            real(qp), intent(in) :: value
            logical, intent(in) :: given
            if (given) then
                call put('    '//format_real(value)//',')
            else
                call put('    ,')       ! a null value: this row has no estimates
            end if
        end subroutine put_estimate
    end function effective_input

    !> Write the open outputs among `csv`, `nml` and `text` (the readable table): provenance,
    !! then the rows. Write errors are kept in each file and reported by `finish_output`.
    subroutine write_outputs(csv, nml, text, field, table, first, last, solutions, date)
        type(safe_file), intent(inout) :: csv, nml, text  !! the outputs (open or not)
        class(brachistochrone_field), intent(in) :: field  !! the field solved
        type(endpoint_table), intent(in) :: table          !! the input
        integer, intent(in) :: first, last                 !! rows solved
        type(endpoint_solution), intent(in) :: solutions(first:) !! their solutions
        character(len=*), intent(in) :: date               !! provenance date
        type(line_text), allocatable :: provenance(:)
        integer :: k
        provenance = provenance_lines(field, table, first, last, date)
        if (csv%is_open()) then
            do k = 1, size(provenance)
                call csv%put('# '//provenance(k)%text)
            end do
            call csv%put(field_csv_header(field))
            call put_lines(csv, solutions(first:last), csv_rows)
        end if
        if (nml%is_open()) then
            do k = 1, size(provenance)
                call nml%put('! '//provenance(k)%text)
            end do
            call write_results_namelist(nml, field, solutions)
        end if
        if (text%is_open()) then
            do k = 1, size(provenance)
                call text%put('# '//provenance(k)%text)
            end do
            call write_table_header(text, field)
            do k = first, last
                call write_table_row(text, field, k, solutions(k))
            end do
        end if
    end subroutine write_outputs

    !> Start a `result_stream` into the open outputs among `csv` and `nml`: their
    !! provenance (dated `date`), the CSV header, the namelist up to its first variable's
    !! heading, and the namelist's scratch file. status: `safe_ok`, or the status of
    !! `open_scratch` with `message` (nothing more was written then).
    subroutine start_stream(stream, csv, nml, field, table, first, last, date, status, &
                            message, scratch_memory)
        type(result_stream), intent(out) :: stream         !! the stream
        type(safe_file), intent(inout) :: csv, nml         !! the outputs (open or not)
        class(brachistochrone_field), intent(in) :: field  !! the field solved
        type(endpoint_table), intent(in) :: table          !! the input
        integer, intent(in) :: first, last                 !! rows to solve
        character(len=*), intent(in) :: date               !! provenance date
        integer, intent(out) :: status                     !! safe_ok or why not
        character(len=:), allocatable, intent(out) :: message !! what failed
        integer, intent(in), optional :: scratch_memory    !! for tests: `open_scratch`'s memory
        type(line_text), allocatable :: provenance(:)
        integer :: k
        status = safe_ok
        message = ''
        stream%date = date
        stream%csv = csv%is_open()
        stream%nml = nml%is_open()
        if (.not. (stream%csv .or. stream%nml)) return
        if (stream%nml) then
            call open_scratch(stream%spill, nml%path, status, message, scratch_memory)
            if (status /= safe_ok) return
            do k = 1, size(namelist_columns)
                stream%headings(k) = namelist_heading(field, k)
            end do
            allocate (stream%nml_lines(size(namelist_columns), stream_block, 2), &
                      stream%nml_lengths(size(namelist_columns), stream_block, 2), &
                      stream%spilled(2:size(namelist_columns), &
                                     (last - first + stream_block)/stream_block))
        end if
        if (stream%csv) allocate (stream%csv_lines(stream_block, 2), &
                                  stream%csv_lengths(stream_block, 2))
        provenance = provenance_lines(field, table, first, last, date)
        if (stream%csv) then
            do k = 1, size(provenance)
                call csv%put('# '//provenance(k)%text)
            end do
            call csv%put(field_csv_header(field))
        end if
        if (stream%nml) then
            do k = 1, size(provenance)
                call nml%put('! '//provenance(k)%text)
            end do
            call nml%put('&RESULTS')
            call nml%put(' N='//integer_text(last - first + 1)//',')
            call nml%put(trim(stream%headings(1)))
        end if
    end subroutine start_stream

    !> Format row `row` of a block (1 .. `block_rows`) into slot `slot` (1 or 2): its CSV
    !! row and its namelist values (taken from the CSV row's fields: each value is
    !! formatted once). Called by the OpenMP threads at once, for different rows;
    !! allocates nothing.
    subroutine format_stream_row(stream, slot, row, solution)
        type(result_stream), intent(inout) :: stream    !! the stream
        integer, intent(in) :: slot, row                !! where the lines go
        type(endpoint_solution), intent(in) :: solution !! the solved row
        character(len=csv_row_length) :: line
        integer :: length, ends(8)
        if (stream%csv) then
            call csv_row_into(solution, stream%csv_lines(row, slot), &
                              stream%csv_lengths(row, slot), ends)
            if (stream%nml) call namelist_lines(stream%csv_lines(row, slot) &
                                                (1:stream%csv_lengths(row, slot)), ends, &
                                                stream%nml_lines(:, row, slot), &
                                                stream%nml_lengths(:, row, slot))
        else if (stream%nml) then
            call csv_row_into(solution, line, length, ends)
            call namelist_lines(line(1:length), ends, stream%nml_lines(:, row, slot), &
                                stream%nml_lengths(:, row, slot))
        end if
    end subroutine format_stream_row

    !> The namelist's value lines of one row (`format_line` for each of
    !! `namelist_columns`) from its CSV row `rho,psi,arch,R,s,t,steps,status` (the same
    !! variables in the same order): `  x,`, `  0,` for an empty field, `  "word",` for
    !! arch and status.
    pure subroutine namelist_lines(row, ends, lines, lengths)
        character(len=*), intent(in) :: row             !! the CSV row
        integer, intent(in) :: ends(:)                  !! its fields' ends (`csv_row_into`)
        character(len=*), intent(inout) :: lines(:)     !! value_line_length long
        integer, intent(out) :: lengths(:)              !! characters used
        integer :: k, start, finish, n
        start = 1
        do k = 1, size(namelist_columns)
            finish = ends(k)
            n = finish - start + 1
            if (any(namelist_columns(k) == [value_arch, value_status])) then
                lines(k)(1:3) = '  "'
                lines(k)(4:n + 3) = row(start:finish)
                lines(k)(n + 4:n + 5) = '",'
                lengths(k) = n + 5
            else if (n == 0) then
                lines(k)(1:4) = '  0,'
                lengths(k) = 4
            else
                lines(k)(1:2) = '  '
                lines(k)(3:n + 2) = row(start:finish)
                lines(k)(n + 3:n + 3) = ','
                lengths(k) = n + 3
            end if
            start = finish + 2
        end do
    end subroutine namelist_lines

    !> Write the next block, `rows` rows formatted in slot `slot`: the CSV rows and the
    !! namelist's first variable to the outputs, its other variables to the scratch file.
    !! One thread at a time, blocks in row order.
    subroutine write_stream_block(stream, csv, nml, slot, rows)
        type(result_stream), intent(inout) :: stream  !! the stream
        type(safe_file), intent(inout) :: csv, nml    !! the outputs
        integer, intent(in) :: slot, rows             !! the block
        integer :: row, k
        stream%blocks = stream%blocks + 1
        if (stream%csv) then
            do row = 1, rows
                call csv%put(stream%csv_lines(row, slot)(1:stream%csv_lengths(row, slot)))
            end do
        end if
        if (.not. stream%nml) return
        do row = 1, rows
            call nml%put(stream%nml_lines(1, row, slot)(1:stream%nml_lengths(1, row, slot)))
        end do
        do k = 2, size(namelist_columns)
            do row = 1, rows
                call stream%spill%put(stream%nml_lines(k, row, slot) &
                                      (1:stream%nml_lengths(k, row, slot)))
            end do
            stream%spilled(k, stream%blocks) = sum(int(stream%nml_lengths(k, :rows, slot), &
                                                       int64) + 1_int64)
        end do
    end subroutine write_stream_block

    !> After the last block: the namelist's other variables from the scratch file (each
    !! under its heading) and the end of the group; the scratch file is closed. A write
    !! error of the scratch file is reported as one of the namelist output.
    subroutine finish_stream(stream, nml)
        type(result_stream), intent(inout) :: stream  !! the stream
        type(safe_file), intent(inout) :: nml         !! the namelist output
        integer(int64) :: base
        integer :: k, b
        if (.not. stream%nml) return
        do k = 2, size(namelist_columns)
            call nml%put(trim(stream%headings(k)))
            base = 0                 ! where block b starts: its variables 2..8 in turn
            do b = 1, stream%blocks
                call nml%append_range(stream%spill, base + sum(stream%spilled(2:k - 1, b)), &
                                      stream%spilled(k, b))
                base = base + sum(stream%spilled(:, b))
            end do
        end do
        call nml%put(' /')
        call close_scratch(stream%spill)
    end subroutine finish_stream

    !> One line per solution, formatted by the OpenMP threads `format_block` lines at a
    !! time into fixed-length lines and written in order: the CSV rows (`csv_rows`) or
    !! one namelist value per line (`value_rho` ... `value_time`). The formatting
    !! allocates nothing: deferred-length strings built concurrently give wrong results
    !! with gfortran 12.
    subroutine put_lines(out, solutions, column)
        type(safe_file), intent(inout) :: out                !! the output
        type(endpoint_solution), intent(in) :: solutions(:)  !! the solutions
        integer, intent(in) :: column                        !! what each line holds
        character(len=csv_row_length), allocatable :: lines(:)
        integer, allocatable :: lengths(:)
        integer :: block_first, block_last, k
        allocate (lines(format_block), lengths(format_block))
        block_first = 1
        do while (block_first <= size(solutions))
            block_last = min(size(solutions), block_first + format_block - 1)
            !$omp parallel do schedule(static) default(shared) private(k)
            do k = block_first, block_last
                call format_line(solutions(k), column, lines(k - block_first + 1), &
                                 lengths(k - block_first + 1))
            end do
            !$omp end parallel do
            do k = 1, block_last - block_first + 1
                call out%put(lines(k)(1:lengths(k)))
            end do
            block_first = block_last + 1
        end do
    end subroutine put_lines

    !> The line `column` of one solution: its CSV row, or `  x,` for one namelist value
    !! (`  0,` where the value does not exist; `  "word",` for arch and status).
    pure subroutine format_line(solution, column, line, length)
        type(endpoint_solution), intent(in) :: solution !! the solved endpoint
        integer, intent(in) :: column                   !! csv_rows or value_*
        character(len=*), intent(inout) :: line         !! csv_row_length long
        integer, intent(out) :: length                  !! characters used
        if (column == csv_rows) then
            call csv_row_into(solution, line, length)
            return
        end if
        line(1:2) = '  '
        length = 2
        select case (column)
        case (value_rho)
            call put_value(.true., solution%rho, line, length)
        case (value_psi)
            call put_value(.true., solution%psi, line, length)
        case (value_apse_radius)
            call put_present(solution%has_apse_radius, solution%apse_radius, line, length)
        case (value_arclength)
            call put_present(solution%has_arclength, solution%arclength, line, length)
        case (value_time)
            call put_present(solution%has_time, solution%time, line, length)
        case (value_arch)
            call put_word('"'//arch_word_fixed(solution%arch), line, length)
            call put_quote(line, length)
        case (value_steps)
            call put_integer(solution%steps, line, length)
            call put_word(',', line, length)
        case default
            call put_word('"'//status_word_fixed(solution%status), line, length)
            call put_quote(line, length)
        end select
    end subroutine format_line

    !> `"word",` from `"word,`: the closing quote before the comma.
    pure subroutine put_quote(line, length)
        character(len=*), intent(inout) :: line   !! the line so far, ending in a comma
        integer, intent(inout) :: length          !! its length
        line(length:length + 1) = '",'
        length = length + 1
    end subroutine put_quote

    !> `csv_row` into a fixed-length line, without allocation: line(1:length).
    pure subroutine csv_row_into(solution, line, length, ends)
        type(endpoint_solution), intent(in) :: solution !! the solved endpoint
        character(len=*), intent(inout) :: line         !! csv_row_length long
        integer, intent(out) :: length                  !! characters used
        !> where each of the 8 fields ends (its comma's position - 1; the last: length)
        integer, intent(out), optional :: ends(:)
        integer :: fields(8)
        length = 0
        call put_value(.true., solution%rho, line, length)
        fields(1) = length - 1
        call put_value(.true., solution%psi, line, length)
        fields(2) = length - 1
        call put_word(arch_word_fixed(solution%arch), line, length)
        fields(3) = length - 1
        call put_value(solution%has_apse_radius, solution%apse_radius, line, length)
        fields(4) = length - 1
        call put_value(solution%has_arclength, solution%arclength, line, length)
        fields(5) = length - 1
        call put_value(solution%has_time, solution%time, line, length)
        fields(6) = length - 1
        call put_integer(solution%steps, line, length)
        call put_word(',', line, length)
        fields(7) = length - 1
        call put_word(status_word_fixed(solution%status), line, length)
        length = length - 1          ! no comma after the last field
        fields(8) = length
        if (present(ends)) ends(:8) = fields
    end subroutine csv_row_into

    !> A CSV field and its comma: the value's 36 digits, or nothing when it does not exist.
    pure subroutine put_value(exists, x, line, length)
        logical, intent(in) :: exists             !! the value exists
        real(qp), intent(in) :: x                 !! the value
        character(len=*), intent(inout) :: line   !! the row so far
        integer, intent(inout) :: length          !! its length
        integer :: used
        if (exists) then
            call write_quad(x, line(length + 1:), used)
            length = length + used
        end if
        line(length + 1:length + 1) = ','
        length = length + 1
    end subroutine put_value

    !> A namelist value and its comma: the value, or 0 where it does not exist.
    pure subroutine put_present(exists, x, line, length)
        logical, intent(in) :: exists             !! the value exists
        real(qp), intent(in) :: x                 !! the value
        character(len=*), intent(inout) :: line   !! the line so far
        integer, intent(inout) :: length          !! its length
        if (exists) then
            call put_value(.true., x, line, length)
        else
            call put_word('0', line, length)
        end if
    end subroutine put_present

    !> A word (trailing blanks dropped) and a comma; ',' alone is just the comma.
    pure subroutine put_word(word, line, length)
        character(len=*), intent(in) :: word      !! the word, blank-padded
        character(len=*), intent(inout) :: line   !! the row so far
        integer, intent(inout) :: length          !! its length
        integer :: used
        used = len_trim(word)
        if (word == ',') used = 0
        line(length + 1:length + used) = word(1:used)
        line(length + used + 1:length + used + 1) = ','
        length = length + used + 1
    end subroutine put_word

    !> The results as the namelist group &results (n, rho, psi, arch, r, s, t, steps,
    !! status), which `read(nml=)` gives back bit for bit: one value a line, reals with
    !! 36 significant digits (`format_real`). Where a value does not exist (R and s when
    !! inaccessible) it is written as 0; `status` and `arch` say so.
    subroutine write_results_namelist(out, field, solutions)
        type(safe_file), intent(inout) :: out               !! the output
        class(brachistochrone_field), intent(in) :: field   !! the field solved (names)
        type(endpoint_solution), intent(in) :: solutions(:) !! solved endpoints
        integer :: k
        call out%put('&RESULTS')
        call out%put(' N='//integer_text(size(solutions))//',')
        do k = 1, size(namelist_columns)
            call out%put(trim(namelist_heading(field, k)))
            call put_lines(out, solutions, namelist_columns(k))
        end do
        call out%put(' /')
    end subroutine write_results_namelist


    !> The line before the values of the namelist's k-th variable (`namelist_columns`):
    !! ' RHO=', ' PSI=', ' ARCH=', ' R=', ' S=', ' T=', ' STEPS=', ' STATUS='.
    function namelist_heading(field, k) result(heading)
        class(brachistochrone_field), intent(in) :: field !! the field (coordinate names)
        integer, intent(in) :: k                          !! 1 .. 8
        character(len=16) :: heading
        character(len=*), parameter :: names(8) = [character(len=6) :: '', '', 'ARCH', &
                                                   'R', 'S', 'T', 'STEPS', 'STATUS']
        if (k <= 2) then
            heading = ' '//upper(coordinate(field, k))//'='
        else
            heading = ' '//trim(names(k))//'='
        end if
    end function namelist_heading

    !> Name of the field's coordinate k (1 or 2): rho, psi or x, y.
    pure function coordinate(field, k) result(name)
        class(brachistochrone_field), intent(in) :: field !! the field
        integer, intent(in) :: k                          !! which coordinate
        character(len=:), allocatable :: name
        name = field%coordinate(k)
    end function coordinate

    !> Uppercase copy of ASCII letters.
    pure function upper(text) result(raised)
        character(len=*), intent(in) :: text
        character(len=len(text)) :: raised
        integer :: k
        raised = text
        do k = 1, len(text)
            if (text(k:k) >= 'a' .and. text(k:k) <= 'z') &
                raised(k:k) = achar(iachar(text(k:k)) - 32)
        end do
    end function upper

    !> ` with n = ...` for fields with an exponent, '' for the others.
    pure function exponent_note(field) result(text)
        class(brachistochrone_field), intent(in) :: field
        character(len=:), allocatable :: text
        text = ''
        if (field%exponent() /= 0.0_qp) text = ' with n = '//short_real(field%exponent())
    end function exponent_note

    !> Shortest form of a value that reads back to the same binary128 number.
    pure function short_real(x) result(text)
        real(qp), intent(in) :: x
        character(len=:), allocatable :: text
        character(len=64) :: buffer
        real(qp) :: back
        integer :: digits, ios
        do digits = 1, 36
            write (buffer, '(g0.'//integer_text(digits)//')') x
            read (buffer, *, iostat=ios) back
            if (ios == 0 .and. back == x) exit
        end do
        text = trim(adjustl(buffer))
        if (text(len(text):) == '.') text = text(:len(text) - 1)
    end function short_real

end module brachistochrone_result_output
