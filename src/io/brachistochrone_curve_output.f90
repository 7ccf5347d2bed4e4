!> Writing the points along each solved brachistochrone: one CSV per run (--curves).
!!
!! Header `id,point,r,theta,s,t,x,y`: `id` is the endpoint's row in the input file,
!! `point` runs 1..curve_points from A to B (equal steps of arclength on each half-arch,
!! the apse a point; see `curve`). An endpoint without a curve (inaccessible, or not
!! solved) has no rows, only a comment line `# id I: no curve (STATUS)` in its place.
!! Same provenance and safe writing as the other outputs (`result_output`, `safe_file`).
!! Curves are sampled in parallel (OpenMP) in blocks of rows, written in row order, so
!! memory stays bounded and the file does not depend on the number of threads.
module brachistochrone_curve_output
    use brachistochrone_status, only: status_word
    use brachistochrone_field_interface, only: brachistochrone_field
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_curve, only: curve_samples
    use brachistochrone_endpoint_input, only: endpoint_table
    use brachistochrone_result_output, only: format_real, write_provenance
    use brachistochrone_safe_file, only: safe_file
    use brachistochrone_run_support, only: progress_type
    use brachistochrone_strings, only: integer_text
    implicit none
    private

    public :: curves_header, write_curves, write_curve, curve_row

    !> Header line of the curves CSV.
    character(len=*), parameter :: curves_header = 'id,point,r,theta,s,t,x,y'
    !> Points sampled per block of rows (bounds the memory: about 100 bytes a point).
    integer, parameter :: points_per_block = 200000

contains

    !> CSV row of point k of a curve: `id,point,r,theta,s,t,x,y`.
    pure function curve_row(id, k, samples) result(line)
        integer, intent(in) :: id                   !! the endpoint's row number
        integer, intent(in) :: k                    !! the point, 1..samples%n
        type(curve_samples), intent(in) :: samples  !! the curve
        character(len=:), allocatable :: line
        line = integer_text(id)//','//integer_text(k)//','//format_real(samples%r(k))// &
               ','//format_real(samples%theta(k))//','//format_real(samples%s(k))//','// &
               format_real(samples%t(k))//','//format_real(samples%x(k))//','// &
               format_real(samples%y(k))
    end function curve_row

    !> Write the rows of one curve, or the comment line of an endpoint without one.
    subroutine write_curve(out, id, samples)
        type(safe_file), intent(inout) :: out       !! the output
        integer, intent(in) :: id                   !! the endpoint's row number
        type(curve_samples), intent(in) :: samples  !! its curve
        integer :: k
        if (samples%n == 0) then
            call out%put('# id '//integer_text(id)//': no curve ('// &
                         status_word(samples%status)//')')
            return
        end if
        do k = 1, samples%n
            call out%put(curve_row(id, k, samples))
        end do
    end subroutine write_curve

    !> Sample the curve of every solved row first..last with `table%curve_points` points
    !! and write them to `out` (when it is open). Write errors are kept in `out` and
    !! reported by `finish_output`. `missing` counts the rows without a curve; `ok` is
    !! false when memory for a block of curves could not be allocated (`message` says so).
    subroutine write_curves(out, field, table, first, last, solutions, date, report, &
                            missing, ok, message)
        type(safe_file), intent(inout) :: out              !! the output (open or not)
        class(brachistochrone_field), intent(in) :: field  !! the field solved
        type(endpoint_table), intent(in) :: table          !! the input
        integer, intent(in) :: first, last                 !! rows solved
        type(endpoint_solution), intent(in) :: solutions(first:) !! their solutions
        character(len=*), intent(in) :: date               !! provenance date
        logical, intent(in) :: report                      !! progress on stderr
        integer, intent(out) :: missing                    !! rows without a curve
        logical, intent(out) :: ok                         !! memory was found
        character(len=:), allocatable, intent(out) :: message !! what went wrong
        type(curve_samples), allocatable :: block(:)
        type(progress_type) :: progress
        integer :: block_rows, block_first, block_last, i, stat

        missing = 0
        ok = .true.
        message = ''
        if (.not. out%is_open()) return
        call write_provenance(out, field, table, first, last, date, '# ')
        call out%put('# curves: '//integer_text(table%curve_points)//' points per curve '// &
            'from A to B, equal steps of arclength on each half-arch (the apse is a '// &
            'point); id = input row')
        call out%put(curves_header)

        block_rows = max(1, points_per_block/max(1, table%curve_points))
        call progress%start(last - first + 1, report, 'curves', 'sampled')
        block_first = first
        do while (block_first <= last .and. out%error == 0)
            block_last = min(last, block_first + block_rows - 1)
            allocate (block(block_first:block_last), stat=stat)
            if (stat /= 0) then
                ok = .false.
                message = 'out of memory for the curves of rows '//integer_text(block_first)// &
                          ' to '//integer_text(block_last)
                return
            end if
            !$omp parallel do schedule(dynamic, 1) default(shared) private(i)
            do i = block_first, block_last
                block(i) = field%sample_curve(solutions(i), table%curve_points)
                call progress%step()
            end do
            !$omp end parallel do
            do i = block_first, block_last
                if (block(i)%n == 0) missing = missing + 1
                call write_curve(out, i, block(i))
            end do
            deallocate (block)
            block_first = block_last + 1
        end do
        call progress%finish()
    end subroutine write_curves

end module brachistochrone_curve_output
