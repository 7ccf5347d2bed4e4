!> Fields through the field interface (`new_field`) against independent two-point
!! references: mpmath on Tee's original integrals for that field's speed law, bracketed
!! roots, two precisions agreeing to >= 40 digits.
!! * repulsive: data/reference/repulsive_two_point_mpmath.csv
!!   (scripts/make_repulsive_two_point_reference.py; Tee (23), (31), (37), v^2 = 2(x-1)/x);
!! * harmonic (Saitoh's closed forms in the field): data/reference/general_harmonic_mpmath.csv
!!   (scripts/make_general_reference.py harmonic; Tee (27), (33), (39), v^2 = 1 - x^2);
!! * inverse square (the fast path): data/reference/general_power2_mpmath.csv
!!   (scripts/make_general_reference.py power2; v^2 = 2 (1/x - 1));
!! * uniform gravity (Tee sec. 1, not a central field: the cycloid's own equations, g = 1,
!!   endpoints by the field's coordinates x, y): data/reference/uniform_field_mpmath.csv
!!   (scripts/make_uniform_field_reference.py); its R-bar is the rolling radius a.
!! Each of R-bar, s, t is credited with its condition number with respect to psi,
!! c = |dF/dpsi| psi/F (columns cond_R, cond_s, cond_t, computed by mpmath), as in
!! test_central_force; the digits printed are raw and credited, by class of endpoint
!! (the classes of the table, in order). Where the R column is empty (the repulsive
!! field's unbounded curves) the field must report no R-bar.
module test_field_references
    use, intrinsic :: iso_fortran_env, only: output_unit
    use brachistochrone_kinds, only: qp
    use brachistochrone_status, only: status_ok
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_arches, only: arch_word
    use brachistochrone_field_interface, only: brachistochrone_field
    use brachistochrone_fields, only: new_field
    use testing, only: check, section, digits_of_agreement
    use reference_tables, only: csv_table, read_reference
    implicit none
    private

    public :: run_field_reference_tests

    integer, parameter :: class_length = 24

    !> Rows of the repulsive table open (none since branch i11-repulsive: next to the
    !! apse, rows 21-28, the solver's unknown is sqrt(R - rho); rows 37 and 42, rho and R
    !! next to 1, keep their digits; all were below 32 digits on main at 9c4f77a).
    integer, parameter :: repulsive_open(0) = [integer ::]
    !> Rows of the harmonic and inverse-square tables open on main (none known).
    integer, parameter :: harmonic_open(0) = [integer ::], inverse_square_open(0) = [integer ::]
    !> Rows of the uniform table open on main (none: row 15, B within 2e-34 of the lowest
    !! point, is labelled by the exact test x < (pi/2) y).
    integer, parameter :: uniform_open(0) = [integer ::]

contains

    !> Every field with a two-point reference table read through the field interface.
    subroutine run_field_reference_tests()
        call field_references('repulsive', 0.0_qp, &
                              'data/reference/repulsive_two_point_mpmath.csv', repulsive_open)
        call field_references('harmonic', 0.0_qp, &
                              'data/reference/general_harmonic_mpmath.csv', harmonic_open)
        call field_references('inverse_square', 0.0_qp, &
                              'data/reference/general_power2_mpmath.csv', inverse_square_open)
        call field_references('uniform', 0.0_qp, &
                              'data/reference/uniform_field_mpmath.csv', uniform_open)
    end subroutine run_field_reference_tests

    !> Every endpoint of `path` solved by field `name` to >= 32 digits in R, s, t
    !! (conditioning credited), except the rows `open_rows` (known open, printed).
    subroutine field_references(name, exponent, path, open_rows)
        character(len=*), intent(in) :: name, path
        real(qp), intent(in) :: exponent
        integer, intent(in) :: open_rows(:)
        class(brachistochrone_field), allocatable :: field
        type(csv_table) :: table
        character(len=class_length), allocatable :: classes(:)
        real(qp), allocatable :: worst(:, :), worst_raw(:, :)
        real(qp) :: digits(3), worst_checked
        integer :: i, k, status
        logical :: ok
        call section(name//' field: two-point references (independent, mpmath)')
        call read_reference(path, 30, table, ok)
        if (.not. ok) return
        call new_field(name, exponent, field, status)
        call check(status == status_ok, 'new_field('''//name//''')')
        classes = class_names(table)
        allocate (worst(3, size(classes)), worst_raw(3, size(classes)))
        worst = 99.0_qp
        worst_raw = 99.0_qp
        worst_checked = 99.0_qp
        do i = 1, table%row_count()
            call row_digits(field, table, i, any(open_rows == i), digits)
            if (.not. any(open_rows == i)) &
                worst_checked = min(worst_checked, minval(digits + credits(table, i)))
            if (any(open_rows == i) .and. minval(digits + credits(table, i)) >= 32.0_qp) &
                write (output_unit, '(5x,a,i0,a)') 'row ', i, ' is open but now reaches '// &
                '32 digits: take it off the list of open rows'
            do k = 1, size(classes)
                if (table%text(i, 'class') == trim(classes(k)) .or. k == size(classes)) then
                    worst_raw(:, k) = min(worst_raw(:, k), digits)
                    worst(:, k) = min(worst(:, k), digits + credits(table, i))
                end if
            end do
        end do
        write (output_unit, '(3x,a,i0,a)') 'fewest digits of R, s, t (raw | credited) on ', &
            table%row_count(), ' endpoints (99: no R-bar, as required):'
        do k = 1, size(classes)
            write (output_unit, '(5x,a24,3f7.2,a,3f7.2)') classes(k), worst_raw(:, k), ' |', &
                worst(:, k)
        end do
        if (size(open_rows) > 0) write (output_unit, '(3x,a,i0,a)') 'open (issue 11, '// &
            'left out of the check): ', size(open_rows), ' rows, marked (open) above'
        call check(worst_checked >= 32.0_qp, name//': R-bar, s, t to >= 32 digits '// &
                   '(conditioning credited) on every reference endpoint not known open')
    end subroutine field_references

    !> The distinct classes of the table in order of appearance, then 'all'.
    function class_names(table) result(classes)
        type(csv_table), intent(in) :: table
        character(len=class_length), allocatable :: classes(:)
        integer :: i
        allocate (classes(0))
        do i = 1, table%row_count()
            if (.not. any(classes == table%text(i, 'class'))) &
                classes = [character(len=class_length) :: classes, table%text(i, 'class')]
        end do
        classes = [character(len=class_length) :: classes, 'all']
    end function class_names

    !> Raw digits of R, s, t of row i (all 0 for a wrong status, arch or presence of R,
    !! the digits then printed; R 99 where it is absent as required); rows under 33
    !! credited digits are printed.
    subroutine row_digits(field, table, i, open, digits)
        class(brachistochrone_field), intent(in) :: field
        type(csv_table), intent(in) :: table
        integer, intent(in) :: i
        logical, intent(in) :: open    !! a known open row (marked in the print)
        real(qp), intent(out) :: digits(3)
        type(endpoint_solution) :: b
        logical :: has_r
        b = field%solve(table%real_value(i, field%coordinate(1)), &
                        table%real_value(i, field%coordinate(2)))
        has_r = len(table%text(i, 'R')) > 0
        digits = 0.0_qp
        if (b%status /= status_ok) then
            write (output_unit, '(5x,a,i0,a,i0)') 'row ', i, ': status ', b%status
            return
        end if
        digits(1) = 99.0_qp
        if (has_r) digits(1) = digits_of_agreement(b%apse_radius, table%real_value(i, 'R'))
        digits(2) = digits_of_agreement(b%arclength, table%real_value(i, 's'))
        digits(3) = digits_of_agreement(b%time, table%real_value(i, 't'))
        if (.not. same_arch(arch_word(b%arch), table%text(i, 'arch'), &
                            table%real_value(i, field%coordinate(1))) .or. &
            (b%has_apse_radius .neqv. has_r)) then
            write (output_unit, '(5x,a,i0,1x,5a,l2,a,3f7.2)') 'row ', i, &
                table%text(i, 'class'), trim(merge(' (open)', '       ', open)), &
                ': arch ', arch_word(b%arch), ', R-bar given', b%has_apse_radius, &
                ': not the table''s, counted as 0 digits; digits R, s, t', digits
            digits = 0.0_qp
            return
        end if
        if (minval(digits + credits(table, i)) < 33.0_qp) &
            write (output_unit, '(5x,a,i0,1x,3a,3f7.2)') 'weakest: row ', i, &
            table%text(i, 'class'), trim(merge(' (open)', '       ', open)), &
            ', credited digits R, s, t', digits + credits(table, i)
    end subroutine row_digits

    !> The field's arch word is the table's (scripts/make_general_reference.py calls a
    !! complete arch, rho = 1, 'second').
    pure logical function same_arch(word, expected, rho)
        character(len=*), intent(in) :: word, expected
        real(qp), intent(in) :: rho    !! the endpoint's first coordinate
        same_arch = word == expected .or. (word == 'complete' .and. expected == 'second' &
                                           .and. rho == 1.0_qp)
    end function same_arch

    !> log10(max(1, cond)) of R, s, t for row i (0 where no condition number is given).
    function credits(table, i) result(credit)
        type(csv_table), intent(in) :: table
        integer, intent(in) :: i
        real(qp) :: credit(3)
        character(len=*), parameter :: names(3) = [character(len=6) :: 'cond_R', 'cond_s', &
                                                   'cond_t']
        integer :: k
        credit = 0.0_qp
        do k = 1, 3
            if (table%column(trim(names(k))) == 0) cycle
            if (len(table%text(i, trim(names(k)))) > 0) &
                credit(k) = log10(max(1.0_qp, table%real_value(i, trim(names(k)))))
        end do
    end function credits

end module test_field_references
