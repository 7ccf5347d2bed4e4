!> `brachistochrone family`: complete brachistochrones and the apsidal locus, by apse radius.
!!
!!     brachistochrone family [--curves OUT.csv] [--points N] [--locus OUT.csv] [--force]
!!                            R1 [R2 ...]
!!
!! The brachistochrones from A are a one-parameter family (Tee 1998, sec. 4): this
!! subcommand samples the members named by their apse radii R (figures 9-14 of the
!! paper), and the apsidal locus theta = Theta(R,R) (figure 7), with the library's
!! `curve` module. Outputs are CSV files with provenance comments, written safely and
!! committed together (`brachistochrone_safe_file`). Exit codes: 0 done; 1 usage error
!! (nothing written); 3 I/O error (nothing written); 128 + N killed by signal N. (Until
!! 0.2.0 this was the program `brachistochrone-family`.)
module brachistochrone_app_family
    use, intrinsic :: iso_fortran_env, only: error_unit, output_unit, compiler_version, &
                                             compiler_options
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use brachistochrone, only: qp, inverse_square_model, new_inverse_square_model, &
                               curve_samples, sample_complete_arch, apsidal_locus, &
                               status_ok, status_word
    use brachistochrone_version, only: program_name, program_version
    use brachistochrone_endpoint_input, only: max_curve_points
    use brachistochrone_result_output, only: format_real
    use brachistochrone_safe_file, only: safe_file, open_output, finish_output, &
            commit_outputs, discard_outputs, same_name, safe_ok, safe_refused
    use brachistochrone_run_support, only: timestamp
    use brachistochrone_strings, only: integer_text
    use brachistochrone_command_line, only: get_argument
    use brachistochrone_app_support, only: stop_with
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
    type(safe_file) :: files(2)    ! curves, locus

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
        if (len(curves_path) > 0 .and. len(locus_path) > 0) then
            if (same_name(curves_path, locus_path)) call fail(exit_usage, '--curves '// &
                curves_path//' and --locus '//locus_path//' are the same file')
        end if
        call open_file(files(1), curves_path)
        call open_file(files(2), locus_path)

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
            call write_file(files(1), 'curves')
        end if
        if (len(locus_path) > 0) then
            locus = apsidal_locus(model, radii)
            call write_file(files(2), 'locus')
        end if
        call commit_all()
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

    !> Write the curves or the locus into its open output.
    subroutine write_file(file, kind)
        type(safe_file), intent(inout) :: file
        character(len=*), intent(in) :: kind
        integer :: i, p
        call file%put('# '//name//' '//program_version)
        call file%put('# compiler: '//compiler_version())
        call file%put('# compiler options: '//compiler_options())
        call file%put('# date: '//date)
        call file%put('# command: '//command)
        if (kind == 'curves') then
            call file%put('# complete brachistochrones from A = (1, 0) to A'' at '// &
                          'radius 1, '//integer_text(points)//' points each at equal steps '// &
                          'of arclength on each half-arch (the apse is a point); id = '// &
                          'position of R')
            call file%put('id,R,point,r,theta,s,t,x,y')
            do i = 1, size(arches)
                if (arches(i)%status /= status_ok) then
                    call file%put('# id '//integer_text(i)//': no curve ('// &
                                  status_word(arches(i)%status)//')')
                    cycle
                end if
                do p = 1, arches(i)%n
                    call file%put(integer_text(i)//','//format_real(radii(i))//','// &
                                  integer_text(p)//','//row(arches(i), p))
                end do
            end do
        else
            call file%put('# apsidal locus theta = Theta(R,R) (eq. 66), r = R; '// &
                          's = S(R,R), t = T(R,R) are the arclength and time from A to '// &
                          'the apse')
            call file%put('R,theta,s,t,x,y')
            do p = 1, locus%n
                call file%put(row(locus, p))
            end do
        end if
    end subroutine write_file

    !> Before any work: refuse an output in the way, create its temporary file.
    subroutine open_file(file, path)
        type(safe_file), intent(inout) :: file
        character(len=*), intent(in) :: path
        integer :: status
        character(len=:), allocatable :: problem
        if (len(path) == 0) return
        call open_output(file, path, force, status, problem)
        if (status /= safe_ok) then
            call discard_outputs(files)
            call fail(merge(exit_usage, exit_io, status == safe_refused), problem)
        end if
    end subroutine open_file

    !> Finish and commit both outputs, or neither.
    subroutine commit_all()
        integer :: status, i
        character(len=:), allocatable :: problem
        do i = 1, size(files)
            call finish_output(files(i), status, problem)
            if (status /= safe_ok) exit
        end do
        if (status == safe_ok) call commit_outputs(files, status, problem)
        if (status /= safe_ok) then
            call discard_outputs(files)
            call fail(merge(exit_usage, exit_io, status == safe_refused), problem)
        end if
    end subroutine commit_all

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
        call stop_with(name, code, text)
    end subroutine fail

    subroutine get_command_line(text)
        character(len=:), allocatable, intent(out) :: text
        integer :: length
        call get_command(length=length)
        allocate (character(len=length) :: text)
        call get_command(text)
    end subroutine get_command_line

end module brachistochrone_app_family
