!> Writing solved endpoint tables: readable table, CSV, namelist; provenance; safe files.
!!
!! Every output file starts with provenance (program and version, compiler and options,
!! date, input path and rows, and the effective input as a namelist group, so a result
!! file says how it was made and can be run again). Numbers have 36 significant digits,
!! enough for every binary128 value to read back to the same bits. Files are written to
!! a temporary name in the target directory and renamed into place only when complete:
!! a failed or killed run never leaves a partial file under the target name, and an
!! existing file is replaced only when the caller says so.
module brachistochrone_result_output
    use, intrinsic :: iso_c_binding, only: c_char, c_int, c_null_char
    use, intrinsic :: iso_fortran_env, only: compiler_version, compiler_options
    use brachistochrone_kinds, only: qp
    use brachistochrone_status, only: status_word, status_ok, status_inaccessible
    use brachistochrone_version, only: program_name, program_version
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_field_interface, only: brachistochrone_field
    use brachistochrone_arches, only: arch_word
    use brachistochrone_endpoint_input, only: endpoint_table, group_name
    use brachistochrone_strings, only: integer_text
    use brachistochrone_format, only: format_quad
    implicit none
    private

    public :: format_real, csv_header, csv_row, write_table_header, write_table_row
    public :: output_request, write_outputs, provenance_lines, write_results_namelist
    public :: commit_file, temporary_name, finish_file, results_group_name, max_echoed_rows
    public :: write_provenance

    !> Header line of the CSV output.
    character(len=*), parameter :: csv_header = 'rho,psi,arch,R,s,t,steps,status'
    !> Name of the namelist group of the namelist output.
    character(len=*), parameter :: results_group_name = 'results'
    !> The effective input echoed into provenance lists its arrays up to this many rows.
    integer, parameter :: max_echoed_rows = 100000

    !> Which files to write.
    type :: output_request
        character(len=:), allocatable :: csv_path   !! CSV file ('' for none)
        character(len=:), allocatable :: nml_path   !! namelist results file ('' for none)
        character(len=:), allocatable :: table_path !! readable table file ('' for none)
        character(len=:), allocatable :: curves_path !! curve points CSV ('' for none)
        logical :: force = .false.                  !! replace existing files
    end type output_request

    interface
        function c_rename(old, new) bind(c, name='rename') result(code)
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: old(*), new(*)
            integer(c_int) :: code
        end function c_rename
        function c_getpid() bind(c, name='getpid') result(pid)
            import :: c_int
            integer(c_int) :: pid
        end function c_getpid
    end interface

    !> A line of text, for lists of lines.
    type :: line_text
        character(len=:), allocatable :: text
    end type line_text

contains

    !> A binary128 value with 36 significant digits (enough to read back the same bits),
    !! in the form 1.84781963328078886097052679178216610e-01.
    pure function format_real(x) result(text)
        real(qp), intent(in) :: x !! value
        character(len=:), allocatable :: text
        text = format_quad(x)
    end function format_real

    !> One CSV row: `rho,psi,arch,R,s,t,steps,status`; empty fields where a value does
    !! not exist (R and s in the sector of inaccessibility).
    pure function csv_row(solution) result(line)
        type(endpoint_solution), intent(in) :: solution !! the solved endpoint
        character(len=:), allocatable :: line
        line = format_real(solution%rho)//','//format_real(solution%psi)//','// &
               arch_word(solution%arch)//','// &
               optional_real(solution%has_apse_radius, solution%apse_radius)//','// &
               optional_real(solution%has_arclength, solution%arclength)//','// &
               optional_real(solution%has_time, solution%time)//','// &
               integer_text(solution%steps)//','//status_word(solution%status)
    end function csv_row

    !> Header of the readable table: the field, its units.
    subroutine write_table_header(unit, field)
        integer, intent(in) :: unit                       !! open formatted unit
        class(brachistochrone_field), intent(in) :: field !! the field solved
        write (unit, '(a)') '# Brachistochrones from A = (1, 0) under '// &
            field%description()//exponent_note(field)//', '//field%units()
        write (unit, '(a)') '# row  rho, psi -> arch, steps, status; then R-bar, s, t '// &
            '(36 significant digits)'
    end subroutine write_table_header

    !> One endpoint as a block, like a row of Tee's Table 1.
    subroutine write_table_row(unit, field, row, solution)
        integer, intent(in) :: unit                     !! open formatted unit
        class(brachistochrone_field), intent(in) :: field !! the field solved
        integer, intent(in) :: row                      !! row number in the input
        type(endpoint_solution), intent(in) :: solution !! the solved endpoint
        write (unit, '(a)') ''
        write (unit, '(a)') integer_text(row)//'  rho = '//short_real(solution%rho)// &
            '  psi = '//short_real(solution%psi)//'  ->  '//arch_word(solution%arch)// &
            ', steps = '//integer_text(solution%steps)//', '//status_word(solution%status)
        if (solution%has_apse_radius) write (unit, '(4x,a)') 'R-bar = '// &
            format_real(solution%apse_radius)
        if (solution%has_arclength) write (unit, '(4x,a)') 's     = '// &
            format_real(solution%arclength)
        if (solution%has_time) then
            if (solution%status /= status_inaccessible) then
                write (unit, '(4x,a)') 't     = '//format_real(solution%time)
            else
                write (unit, '(4x,a)') 't    >= '//format_real(solution%time)// &
                    '  ('//field%bound_note()//')'
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
                 line_text('input: '//table%path//', rows '//integer_text(first)//' to '// &
                           integer_text(last)//' of '//integer_text(table%n)), &
                 line_text('effective input:')]
        lines = [lines, effective_input(field, table, first, last)]
    end function provenance_lines

    !> Write the provenance (`provenance_lines`) as comment lines starting with `prefix`.
    subroutine write_provenance(unit, field, table, first, last, date, prefix, ios, &
                                io_message)
        integer, intent(in) :: unit               !! open formatted unit
        class(brachistochrone_field), intent(in) :: field !! the field solved
        type(endpoint_table), intent(in) :: table !! the input
        integer, intent(in) :: first, last        !! rows solved
        character(len=*), intent(in) :: date      !! when
        character(len=*), intent(in) :: prefix    !! comment marker, such as '# '
        integer, intent(out) :: ios               !! iostat of the writes
        character(len=*), intent(inout) :: io_message !! iomsg of the writes
        type(line_text), allocatable :: lines(:)
        integer :: k
        lines = provenance_lines(field, table, first, last, date)
        ios = 0
        do k = 1, size(lines)
            write (unit, '(a)', iostat=ios, iomsg=io_message) prefix//lines(k)%text
            if (ios /= 0) return
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
            call put('  ! rho, psi, r0, r1: '//integer_text(rows)//' rows, more than '// &
                     integer_text(max_echoed_rows)//' are not echoed; the rows of this '// &
                     'file carry rho and psi')
        else
            call put('  rho =')
            do i = first, last
                call put('    '//format_real(table%rho(i))//',')
            end do
            call put('  psi =')
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

    !> Write every requested file. status: 0 ok; 1 a target exists and force is off;
    !! 3 an I/O error (the message says which file). Nothing partial is left behind.
    subroutine write_outputs(request, field, table, first, last, solutions, date, status, &
                             message)
        type(output_request), intent(in) :: request        !! which files
        class(brachistochrone_field), intent(in) :: field  !! the field solved
        type(endpoint_table), intent(in) :: table          !! the input
        integer, intent(in) :: first, last                 !! rows solved
        type(endpoint_solution), intent(in) :: solutions(first:) !! their solutions
        character(len=*), intent(in) :: date               !! provenance date
        integer, intent(out) :: status                     !! 0, 1 or 3
        character(len=:), allocatable, intent(out) :: message !! what went wrong
        type(line_text), allocatable :: provenance(:)

        status = 0
        message = ''
        provenance = provenance_lines(field, table, first, last, date)
        call write_one(request%csv_path, 'csv')
        if (status == 0) call write_one(request%nml_path, 'nml')
        if (status == 0) call write_one(request%table_path, 'table')

    contains

        subroutine write_one(path, kind)
            character(len=*), intent(in) :: path, kind
            character(len=:), allocatable :: temporary
            character(len=512) :: io_message
            integer :: unit, ios, k
            logical :: exists
            if (len(path) == 0) return
            inquire (file=path, exist=exists)
            if (exists .and. .not. request%force) then
                status = 1
                message = path//' exists; use --force to replace it, or choose another name'
                return
            end if
            temporary = temporary_name(path)
            open (newunit=unit, file=temporary, status='replace', action='write', &
                  iostat=ios, iomsg=io_message)
            if (ios /= 0) then
                status = 3
                message = 'cannot write '//path//': '//trim(io_message)
                return
            end if
            select case (kind)
            case ('csv')
                do k = 1, size(provenance)
                    if (ios == 0) write (unit, '(a)', iostat=ios, iomsg=io_message) &
                        '# '//provenance(k)%text
                end do
                if (ios == 0) write (unit, '(a)', iostat=ios, iomsg=io_message) csv_header
                do k = first, last
                    if (ios /= 0) exit
                    write (unit, '(a)', iostat=ios, iomsg=io_message) csv_row(solutions(k))
                end do
            case ('nml')
                do k = 1, size(provenance)
                    if (ios == 0) write (unit, '(a)', iostat=ios, iomsg=io_message) &
                        '! '//provenance(k)%text
                end do
                if (ios == 0) call write_results_namelist(unit, solutions, ios, io_message)
            case ('table')
                do k = 1, size(provenance)
                    if (ios == 0) write (unit, '(a)', iostat=ios, iomsg=io_message) &
                        '# '//provenance(k)%text
                end do
                if (ios == 0) call write_table_header(unit, field)
                do k = first, last
                    call write_table_row(unit, field, k, solutions(k))
                end do
            end select
            call finish_file(unit, temporary, path, ios, io_message, status, message)
        end subroutine write_one

    end subroutine write_outputs

    !> The results as the namelist group &results (n, rho, psi, arch, r, s, t, steps,
    !! status), which `read(nml=)` gives back bit for bit. Where a value does not exist
    !! (R and s when inaccessible) it is written as 0; `status` and `arch` say so.
    subroutine write_results_namelist(unit, solutions, ios, io_message)
        integer, intent(in) :: unit                        !! open formatted unit
        type(endpoint_solution), intent(in) :: solutions(:) !! solved endpoints
        integer, intent(out) :: ios                        !! iostat
        character(len=*), intent(inout) :: io_message      !! iomsg
        integer :: n, k
        real(qp), allocatable :: rho(:), psi(:), r(:), s(:), t(:)
        integer, allocatable :: steps(:)
        character(len=16), allocatable :: arch(:)
        character(len=20), allocatable :: status(:)
        namelist /results/ n, rho, psi, arch, r, s, t, steps, status
        n = size(solutions)
        rho = solutions%rho
        psi = solutions%psi
        r = merge(solutions%apse_radius, 0.0_qp, solutions%has_apse_radius)
        s = merge(solutions%arclength, 0.0_qp, solutions%has_arclength)
        t = merge(solutions%time, 0.0_qp, solutions%has_time)
        steps = solutions%steps
        allocate (arch(n), status(n))
        do k = 1, n
            arch(k) = arch_word(solutions(k)%arch)
            status(k) = status_word(solutions(k)%status)
        end do
        write (unit, nml=results, iostat=ios, iomsg=io_message)
    end subroutine write_results_namelist

    !> Name of the temporary file used while writing `path` (same directory).
    function temporary_name(path) result(name)
        character(len=*), intent(in) :: path !! final file name
        character(len=:), allocatable :: name
        name = path//'.tmp'//integer_text(int(c_getpid()))
    end function temporary_name

    !> Close a temporary output file and rename it onto `path`; on a write error
    !! (`ios` /= 0) or a failed rename delete it instead. status: 0, or 3 with `message`.
    subroutine finish_file(unit, temporary, path, ios, io_message, status, message)
        integer, intent(in) :: unit                   !! the open temporary file
        character(len=*), intent(in) :: temporary     !! its name
        character(len=*), intent(in) :: path          !! the final name
        integer, intent(in) :: ios                    !! iostat of the writes
        character(len=*), intent(in) :: io_message    !! iomsg of the writes
        integer, intent(inout) :: status              !! set to 3 on failure
        character(len=:), allocatable, intent(inout) :: message !! what failed
        integer :: close_status, rename_status, cleanup
        character(len=512) :: close_message
        if (ios /= 0) then
            close (unit, status='delete', iostat=cleanup)
            status = 3
            message = 'cannot write '//path//': '//trim(io_message)
            return
        end if
        rename_status = 0
        close (unit, iostat=close_status, iomsg=close_message)
        if (close_status == 0) call commit_file(temporary, path, rename_status)
        if (close_status /= 0 .or. rename_status /= 0) then
            open (newunit=cleanup, file=temporary, iostat=close_status)
            close (cleanup, status='delete', iostat=close_status)
            status = 3
            message = 'cannot put the finished output in place as '//path
        end if
    end subroutine finish_file

    !> Rename the finished temporary file onto `path`; status 0 on success.
    subroutine commit_file(temporary, path, status)
        character(len=*), intent(in) :: temporary !! finished file
        character(len=*), intent(in) :: path      !! final name
        integer, intent(out) :: status            !! 0 on success
        status = int(c_rename(temporary//c_null_char, path//c_null_char))
    end subroutine commit_file

    !> ` with n = ...` for fields with an exponent, '' for the others.
    pure function exponent_note(field) result(text)
        class(brachistochrone_field), intent(in) :: field
        character(len=:), allocatable :: text
        text = ''
        if (field%exponent() /= 0.0_qp) text = ' with n = '//short_real(field%exponent())
    end function exponent_note

    pure function optional_real(present_, x) result(text)
        logical, intent(in) :: present_
        real(qp), intent(in) :: x
        character(len=:), allocatable :: text
        if (present_) then
            text = format_real(x)
        else
            text = ''
        end if
    end function optional_real

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
