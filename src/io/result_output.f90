!> Writing solved endpoint tables: a readable table, CSV, and safe file replacement.
!!
!! Numbers are written with 36 significant digits, enough for every binary128 value to
!! read back to the same bits. Files are written to a temporary name in the target
!! directory and renamed into place only when complete, so a failed or killed run never
!! leaves a partial file under the target name.
module result_output
    use, intrinsic :: iso_c_binding, only: c_char, c_int, c_null_char
    use brachistochrone_kinds, only: qp
    use brachistochrone_status, only: status_word
    use two_point, only: endpoint_solution, arch_word
    implicit none
    private

    public :: format_real, csv_header, csv_row, write_table_header, write_table_row
    public :: commit_file, temporary_name

    !> Header line of the CSV output.
    character(len=*), parameter :: csv_header = 'rho,psi,arch,R,s,t,steps,status'

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

contains

    !> A binary128 value with 36 significant digits (enough to read back the same bits),
    !! in the form 1.84781963328078886097052679178216610e-01.
    pure function format_real(x) result(text)
        real(qp), intent(in) :: x !! value
        character(len=:), allocatable :: text
        character(len=64) :: buffer
        character(len=8) :: exponent_text
        integer :: e_position, exponent
        write (buffer, '(es0.35e4)') x
        e_position = scan(buffer, 'E')
        if (e_position == 0) then
            ! gfortran writes ES0 without an exponent when it is zero; NaN and Infinity
            ! (never produced by the solver) have none either
            text = trim(buffer)
            if (verify(text(1:1), '+-0123456789') == 0) text = text//'e+00'
            return
        end if
        read (buffer(e_position + 1:), '(i5)') exponent
        write (exponent_text, '(sp,i0.2)') exponent
        text = buffer(:e_position - 1)//'e'//trim(exponent_text)
    end function format_real

    !> One CSV row: `rho,psi,arch,R,s,t,steps,status`; empty fields where a value does
    !! not exist (R and s in the sector of inaccessibility, all three on bad input).
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

    !> Header of the readable table.
    subroutine write_table_header(unit)
        integer, intent(in) :: unit !! open formatted unit
        write (unit, '(a)') '# Brachistochrones from A = (1, 0) under attractive '// &
            'inverse-square force (Tee 1998), units mu = 1'
        write (unit, '(a)') '# row  rho, psi -> arch, steps, status; then R-bar, s, t '// &
            '(36 significant digits)'
    end subroutine write_table_header

    !> One endpoint as a block, like a row of Tee's Table 1.
    subroutine write_table_row(unit, row, solution)
        integer, intent(in) :: unit                     !! open formatted unit
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
            if (solution%has_apse_radius) then
                write (unit, '(4x,a)') 't     = '//format_real(solution%time)
            else
                write (unit, '(4x,a)') 't    >= '//format_real(solution%time)// &
                    '  (greatest lower bound kappa(rho); not attained)'
            end if
        end if
    end subroutine write_table_row

    !> Name of the temporary file used while writing `path` (same directory).
    function temporary_name(path) result(name)
        character(len=*), intent(in) :: path !! final file name
        character(len=:), allocatable :: name
        name = path//'.tmp'//integer_text(int(c_getpid()))
    end function temporary_name

    !> Rename the finished temporary file onto `path`; status 0 on success.
    subroutine commit_file(temporary, path, status)
        character(len=*), intent(in) :: temporary !! finished file
        character(len=*), intent(in) :: path      !! final name
        integer, intent(out) :: status            !! 0 on success
        status = int(c_rename(temporary//c_null_char, path//c_null_char))
    end subroutine commit_file

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

    !> Shortest form of an input value that reads back to the same binary128 number.
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

    pure function integer_text(value) result(text)
        integer, intent(in) :: value
        character(len=:), allocatable :: text
        character(len=24) :: buffer
        write (buffer, '(i0)') value
        text = trim(buffer)
    end function integer_text

end module result_output
