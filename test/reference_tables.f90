!> Readers for the independent reference tables in data/reference/.
module reference_tables
    use brachistochrone_kinds, only: qp
    use testing, only: check
    implicit none
    private

    public :: csv_table, read_csv, read_reference

    !> A CSV file as text fields: header names and rows of fields.
    type :: field
        character(len=:), allocatable :: text
    end type field

    type :: csv_row
        type(field), allocatable :: fields(:)
    end type csv_row

    !> Comment lines (#) skipped; the first other line is the header.
    type :: csv_table
        type(field), allocatable :: header(:)
        type(csv_row), allocatable :: rows(:)
    contains
        procedure :: column
        procedure :: text
        procedure :: real_value
        procedure :: row_count
    end type csv_table

contains

    !> Read a CSV file; ok = .false. if it cannot be opened.
    subroutine read_csv(path, table, ok)
        character(len=*), intent(in) :: path
        type(csv_table), intent(out) :: table
        logical, intent(out) :: ok
        integer :: unit, ios
        character(len=4096) :: line
        logical :: have_header
        allocate (table%rows(0))
        open (newunit=unit, file=path, status='old', action='read', iostat=ios)
        ok = ios == 0
        if (.not. ok) return
        have_header = .false.
        do
            read (unit, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (len_trim(line) == 0 .or. line(1:1) == '#') cycle
            if (.not. have_header) then
                table%header = split(trim(line))
                have_header = .true.
            else
                table%rows = [table%rows, csv_row(split(trim(line)))]
            end if
        end do
        close (unit)
    end subroutine read_csv

    !> Read a reference table as a checked step of a test: `ok` only when the file was
    !! read and has at least `min_rows` rows.
    subroutine read_reference(path, min_rows, table, ok)
        character(len=*), intent(in) :: path     !! the CSV file
        integer, intent(in) :: min_rows          !! rows the test needs
        type(csv_table), intent(out) :: table    !! the table
        logical, intent(out) :: ok               !! read, with enough rows
        character(len=16) :: count
        call read_csv(path, table, ok)
        ok = ok .and. table%row_count() >= min_rows
        write (count, '(i0)') min_rows
        call check(ok, path//' read (at least '//trim(count)//' rows)')
    end subroutine read_reference

    pure function split(line) result(fields)
        character(len=*), intent(in) :: line
        type(field), allocatable :: fields(:)
        integer :: start, comma
        allocate (fields(0))
        start = 1
        do
            comma = index(line(start:), ',')
            if (comma == 0) then
                fields = [fields, field(line(start:))]
                exit
            end if
            fields = [fields, field(line(start:start + comma - 2))]
            start = start + comma
        end do
    end function split

    !> Index of a named column (0 if absent).
    pure integer function column(self, name)
        class(csv_table), intent(in) :: self
        character(len=*), intent(in) :: name
        integer :: k
        column = 0
        do k = 1, size(self%header)
            if (self%header(k)%text == name) column = k
        end do
    end function column

    pure integer function row_count(self)
        class(csv_table), intent(in) :: self
        row_count = size(self%rows)
    end function row_count

    !> Field text of row i, column `name`.
    pure function text(self, i, name) result(value)
        class(csv_table), intent(in) :: self
        integer, intent(in) :: i
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: value
        value = self%rows(i)%fields(self%column(name))%text
    end function text

    !> Field of row i, column `name`, read into real(qp) (so "0.1" is the quad 0.1).
    function real_value(self, i, name) result(value)
        class(csv_table), intent(in) :: self
        integer, intent(in) :: i
        character(len=*), intent(in) :: name
        real(qp) :: value
        character(len=:), allocatable :: field_text
        field_text = self%text(i, name)
        read (field_text, *) value
    end function real_value

end module reference_tables
