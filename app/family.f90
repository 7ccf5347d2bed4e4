!> `brachistochrone family`: complete brachistochrones and the apsidal locus, by apse radius.
!!
!!     brachistochrone family [--curves OUT.csv] [--points N] [--locus OUT.csv] [--force]
!!                            R1 [R2 ...]
!!
!! The brachistochrones from A are a one-parameter family (Tee 1998, sec. 4): this
!! subcommand samples the members named by their apse radii R (figures 9-14 of the
!! paper), and the apsidal locus theta = Theta(R,R) (figure 7), with the library's
!! `curve` module. Outputs are CSV files with provenance comments, written to a temporary
!! name and renamed when complete. Exit codes: 0 done; 1 usage error (nothing written);
!! 3 I/O error. (Until 0.2.0 this was the program `brachistochrone-family`.)
module brachistochrone_app_family
    use, intrinsic :: iso_fortran_env, only: error_unit, output_unit, compiler_version, &
                                             compiler_options
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use brachistochrone, only: qp, inverse_square_model, new_inverse_square_model, &
                               curve_samples, sample_complete_arch, apsidal_locus, &
                               status_ok, status_word
    use brachistochrone_version, only: program_name, program_version
    use brachistochrone_endpoint_input, only: max_curve_points
    use brachistochrone_result_output, only: format_real, temporary_name, commit_file
    use brachistochrone_run_support, only: timestamp
    use brachistochrone_strings, only: integer_text
    use brachistochrone_command_line, only: get_argument
    implicit none
    private

    public :: run_family

    character(len=*), parameter :: name = program_name//' family'
    integer, parameter :: exit_ok = 0, exit_usage = 1, exit_io = 3
    type(inverse_square_model) :: model
    character(len=:), allocatable :: curves_path, locus_path, command, date
    real(qp), allocatable :: radii(:)
    type(curve_samples), allocatable :: arches(:)
    type(curve_samples) :: locus
    integer :: points
    logical :: force

contains

    !> Run the subcommand on the command arguments from number `first` on; stops with the
    !! exit code.
    subroutine run_family(first)
        integer, intent(in) :: first !! index of the subcommand's first argument
        call parse_arguments(first)
        call compute_and_write()
    end subroutine run_family

    !> Options and apse radii from the command line; stops on --help, --version or errors.
    subroutine parse_arguments(first)
        integer, intent(in) :: first
        character(len=:), allocatable :: argument
        integer :: k, count_arguments, ios
        curves_path = ''
        locus_path = ''
        points = 401
        force = .false.
        allocate (radii(0))
        count_arguments = command_argument_count()
        k = first - 1
        do while (k < count_arguments)
            k = k + 1
            argument = get_argument(k)
            select case (argument)
            case ('-h', '--help')
                call usage(output_unit)
                stop exit_ok, quiet=.true.
            case ('--version')
                write (output_unit, '(a)') name//' '//program_version
                stop exit_ok, quiet=.true.
            case ('--force')
                force = .true.
            case ('--curves', '--locus', '--points')
                if (k == count_arguments) call fail(exit_usage, argument//' needs a value')
                k = k + 1
                select case (argument)
                case ('--curves'); curves_path = get_argument(k)
                case ('--locus');  locus_path = get_argument(k)
                case ('--points')
                    argument = get_argument(k)
                    read (argument, *, iostat=ios) points
                    if (ios /= 0 .or. verify(argument, '0123456789') /= 0 .or. &
                        points < 2 .or. points > max_curve_points) &
                        call fail(exit_usage, '--points needs a whole number 2 <= N <= '// &
                                  integer_text(max_curve_points)//', got "'//argument//'"')
                end select
            case default
                call add_radius(argument)
            end select
        end do
    end subroutine parse_arguments

    !> Check the request, sample the curves and write the files; stops with the exit code.
    subroutine compute_and_write()
        integer :: j
        if (size(radii) == 0) call fail(exit_usage, 'no apse radius given (see --help)')
        if (len(curves_path) == 0 .and. len(locus_path) == 0) &
            call fail(exit_usage, 'nothing to write: give --curves OUT.csv and/or '// &
                      '--locus OUT.csv')
        if (any(radii == 1.0_qp) .and. len(curves_path) > 0) &
            call fail(exit_usage, 'apse radius 1 has no complete brachistochrone (it is the '// &
                      'point A); leave it out of --curves')
        call refuse_existing(curves_path)
        call refuse_existing(locus_path)

        call get_command_line(command)
        date = timestamp()
        model = new_inverse_square_model()
        if (len(curves_path) > 0) then
            allocate (arches(size(radii)))
            !$omp parallel do schedule(dynamic, 1) default(shared) private(j)
            do j = 1, size(radii)
                arches(j) = sample_complete_arch(model, radii(j), points)
            end do
            !$omp end parallel do
            call write_file(curves_path, 'curves')
        end if
        if (len(locus_path) > 0) then
            locus = apsidal_locus(model, radii)
            call write_file(locus_path, 'locus')
        end if
        stop exit_ok, quiet=.true.
    end subroutine compute_and_write

    !> Append one apse radius given on the command line, or stop with a usage error.
    subroutine add_radius(argument)
        character(len=*), intent(in) :: argument
        real(qp) :: value
        integer :: ios
        if (argument(1:1) == '-' .and. verify(argument(2:2), '.0123456789') /= 0) &
            call fail(exit_usage, 'unknown option '//argument//' (see --help)')
        read (argument, *, iostat=ios) value
        if (ios /= 0 .or. verify(argument, '+-.0123456789eEdDqQ') /= 0) &
            call fail(exit_usage, '"'//argument//'" is not an apse radius; write a '// &
                      'number 0 < R < 1 such as 0.3')
        if (.not. ieee_is_finite(value) .or. value <= 0.0_qp .or. value > 1.0_qp) &
            call fail(exit_usage, 'apse radius '//argument//' must satisfy 0 < R < 1 '// &
                      '(R = 1 only on the locus, where it is A)')
        radii = [radii, value]
    end subroutine add_radius

    !> Write the curves or the locus to `path` (temporary name, renamed when complete).
    subroutine write_file(path, kind)
        character(len=*), intent(in) :: path, kind
        character(len=:), allocatable :: temporary
        character(len=512) :: io_message
        integer :: unit, ios, i, p, rename_status
        temporary = temporary_name(path)
        open (newunit=unit, file=temporary, status='replace', action='write', iostat=ios, &
              iomsg=io_message)
        if (ios /= 0) call fail(exit_io, 'cannot write '//path//': '//trim(io_message))
        call put_line(unit, '# '//name//' '//program_version, ios, io_message)
        call put_line(unit, '# compiler: '//compiler_version(), ios, io_message)
        call put_line(unit, '# compiler options: '//compiler_options(), ios, io_message)
        call put_line(unit, '# date: '//date, ios, io_message)
        call put_line(unit, '# command: '//command, ios, io_message)
        if (kind == 'curves') then
            call put_line(unit, '# complete brachistochrones from A = (1, 0) to A'' at '// &
                          'radius 1, '//integer_text(points)//' points each at equal steps '// &
                          'of arclength on each half-arch (the apse is a point); id = '// &
                          'position of R', ios, io_message)
            call put_line(unit, 'id,R,point,r,theta,s,t,x,y', ios, io_message)
            do i = 1, size(arches)
                if (arches(i)%status /= status_ok) then
                    call put_line(unit, '# id '//integer_text(i)//': no curve ('// &
                                  status_word(arches(i)%status)//')', ios, io_message)
                    cycle
                end if
                do p = 1, arches(i)%n
                    call put_line(unit, integer_text(i)//','//format_real(radii(i))//','// &
                                  integer_text(p)//','//row(arches(i), p), ios, io_message)
                end do
            end do
        else
            call put_line(unit, '# apsidal locus theta = Theta(R,R) (eq. 66), r = R; '// &
                          's = S(R,R), t = T(R,R) are the arclength and time from A to '// &
                          'the apse', ios, io_message)
            call put_line(unit, 'R,theta,s,t,x,y', ios, io_message)
            do p = 1, locus%n
                call put_line(unit, row(locus, p), ios, io_message)
            end do
        end if
        if (ios /= 0) then
            close (unit, status='delete')
            call fail(exit_io, 'cannot write '//path//': '//trim(io_message))
        end if
        close (unit, iostat=ios, iomsg=io_message)
        rename_status = 0
        if (ios == 0) call commit_file(temporary, path, rename_status)
        if (ios /= 0 .or. rename_status /= 0) then
            open (newunit=unit, file=temporary, iostat=ios)
            close (unit, status='delete', iostat=ios)
            call fail(exit_io, 'cannot put the finished output in place as '//path)
        end if
    end subroutine write_file

    !> Write one line unless an earlier write failed.
    subroutine put_line(unit, line, ios, io_message)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: line
        integer, intent(inout) :: ios
        character(len=*), intent(inout) :: io_message
        if (ios == 0) write (unit, '(a)', iostat=ios, iomsg=io_message) line
    end subroutine put_line

    !> Stop before any work when an output exists and --force is not given.
    subroutine refuse_existing(path)
        character(len=*), intent(in) :: path
        logical :: exists
        if (len(path) == 0 .or. force) return
        inquire (file=path, exist=exists)
        if (exists) call fail(exit_usage, path//' exists; use --force to replace it, or '// &
                              'choose another name')
    end subroutine refuse_existing

    !> r,theta,s,t,x,y of point p.
    function row(c, p) result(line)
        type(curve_samples), intent(in) :: c
        integer, intent(in) :: p
        character(len=:), allocatable :: line
        line = format_real(c%r(p))//','//format_real(c%theta(p))//','// &
               format_real(c%s(p))//','//format_real(c%t(p))//','//format_real(c%x(p))// &
               ','//format_real(c%y(p))
    end function row

    subroutine usage(unit)
        integer, intent(in) :: unit
        write (unit, '(a)') 'usage: '//name//' [--curves OUT.csv] [--points N] '// &
            '[--locus OUT.csv] [--force] R1 [R2 ...]'
        write (unit, '(a)') ''
        write (unit, '(a)') 'Members of the family of brachistochrones from A = (1, 0) '// &
            '(attractive inverse-square'
        write (unit, '(a)') 'force, Tee 1998), named by their apse radii R:'
        write (unit, '(a)') '  --curves OUT.csv  the complete brachistochrones (A to A'' '// &
            'at radius 1), 0 < R < 1:'
        write (unit, '(a)') '                    id,R,point,r,theta,s,t,x,y'
        write (unit, '(a)') '  --points N        points per curve (default 401, 2..'// &
            integer_text(max_curve_points)//'); odd N puts the apse in the middle'
        write (unit, '(a)') '  --locus OUT.csv   the apsidal locus at the same R, 0 < R <= 1:'// &
            ' R,theta,s,t,x,y'
        write (unit, '(a)') '  --force           replace output files that exist'
        write (unit, '(a)') 'Exit codes: 0 done; 1 usage error (nothing written); 3 I/O '// &
            'error. Version '//program_version//'.'
    end subroutine usage

    subroutine fail(code, text)
        integer, intent(in) :: code
        character(len=*), intent(in) :: text
        write (error_unit, '(a)') name//': '//text
        stop code, quiet=.true.
    end subroutine fail

    subroutine get_command_line(text)
        character(len=:), allocatable, intent(out) :: text
        integer :: length
        call get_command(length=length)
        allocate (character(len=length) :: text)
        call get_command(text)
    end subroutine get_command_line

end module brachistochrone_app_family
