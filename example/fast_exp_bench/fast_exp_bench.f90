!> A developer's check of `brachistochrone_fast_exp` against its previous version
!! (module `old_fast_exp`, extracted from git by scripts/bench_fast_exp.sh, which builds
!! and runs this program) and libquadmath:
!!
!!     fast_exp_bench bench          ns per call, per range of |x|, old, new, libquadmath
!!     fast_exp_bench values FILE    for each argument in FILE (one a line): x and the
!!                                   new, old and libquadmath exp and expm1, as hex bits
program fast_exp_bench
    use brachistochrone_kinds, only: qp
    use brachistochrone_quad_math, only: expm1
    use brachistochrone_fast_exp, only: fast_exp, fast_expm1
    use old_fast_exp, only: old_exp => fast_exp, old_expm1 => fast_expm1
    use, intrinsic :: iso_fortran_env, only: int64, output_unit
    implicit none
    character(len=256) :: mode, file
    call get_command_argument(1, mode)
    select case (trim(mode))
    case ('bench')
        call bench()
    case ('values')
        call get_command_argument(2, file)
        call values(trim(file))
    case default
        write (output_unit, '(a)') 'usage: fast_exp_bench bench | values FILE'
        stop 1
    end select

contains

    !> ns per call (CPU time, median of 7 passes over 4096 arguments) in each range.
    subroutine bench()
        integer, parameter :: n = 4096, passes = 7
        real(qp), parameter :: lows(5) = [1.0e-30_qp, 1.0e-4_qp, 0.5_qp, 128.0_qp, 1.0e-6_qp], &
                               highs(5) = [1.0e-5_qp, 0.5_qp, 128.0_qp, 11000.0_qp, 60.0_qp]
        character(len=*), parameter :: names(5) = [character(len=14) :: '1e-30..1e-5', &
            '1e-4..0.5', '0.5..128', '128..11000', '1e-6..60 (-)']
        real(qp) :: x(n), u(n), sink
        real :: t(passes, 6)
        integer :: r, p, f
        write (output_unit, '(a)') '| |x| | old exp | new exp | expq | old expm1 | new expm1 |' &
            //' expm1q |'
        write (output_unit, '(a)') '|---|---|---|---|---|---|---|'
        do r = 1, size(lows)
            call random_number(u)
            x = exp(log(lows(r)) + u*(log(highs(r)) - log(lows(r))))
            if (r < 5) x(2::2) = -x(2::2)
            if (r == 5) x = -x
            sink = 0.0_qp
            do p = 1, passes
                do f = 1, 6
                    t(p, f) = timed(f, x, sink)
                end do
            end do
            write (output_unit, '(a,a,6(a,f7.1),a)') '| ', trim(names(r)), &
                ('| ', median(t(:, f))*1.0e9/n, f = 1, 6), ' |'
            if (sink == 12345.0_qp) write (output_unit, *) sink
        end do
    end subroutine bench

    !> CPU seconds for one pass of function f over x (the results' sum added to sink,
    !! outside the timing).
    real function timed(f, x, sink) result(seconds)
        integer, intent(in) :: f
        real(qp), intent(in) :: x(:)
        real(qp), intent(inout) :: sink
        real(qp) :: y(size(x))
        real :: t0, t1
        integer :: i
        call cpu_time(t0)
        select case (f)
        case (1); y = old_exp(x)
        case (2); y = fast_exp(x)
        case (3); y = exp(x)
        case (4); y = old_expm1(x)
        case (5); y = fast_expm1(x)
        case (6)
            do i = 1, size(x)
                y(i) = expm1(x(i))
            end do
        end select
        call cpu_time(t1)
        seconds = t1 - t0
        sink = sink + sum(y)
    end function timed

    real function median(t)
        real, intent(in) :: t(:)
        real :: s(size(t)), v
        integer :: i, j
        s = t
        do i = 2, size(s)
            v = s(i)
            j = i - 1
            do while (j >= 1)
                if (s(j) <= v) exit
                s(j + 1) = s(j)
                j = j - 1
            end do
            s(j + 1) = v
        end do
        median = s((size(s) + 1)/2)
    end function median

    !> x, then new, old, libquadmath exp and expm1 as 32 hex digits each.
    subroutine values(name)
        character(len=*), intent(in) :: name
        integer :: unit, status
        real(qp) :: x
        open (newunit=unit, file=name, status='old', action='read')
        do
            read (unit, *, iostat=status) x
            if (status /= 0) exit
            write (output_unit, '(7(z32.32,1x))') x, fast_exp(x), old_exp(x), exp(x), &
                fast_expm1(x), old_expm1(x), expm1(x)
        end do
        close (unit)
    end subroutine values

end program fast_exp_bench
