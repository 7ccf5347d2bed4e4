!> scripts/fast_math_bench.sh's program: brachistochrone_fast_math at an old revision
!! (fm_old) against the working tree's (fm_new), ns per call in dependency chains.
program bench
  use, intrinsic :: iso_fortran_env, only: real64
  use brachistochrone_kinds, only: qp, xp
  use fm_old, only: o_hr => hardware_real, o_qr => quad_real, o_sqrt => fast_sqrt, &
                    o_isqrt => inverse_sqrt
  use fm_new, only: n_hr => hardware_real, n_qr => quad_real, n_sqrt => fast_sqrt, &
                    n_isqrt => inverse_sqrt, n_dr => double_real
  implicit none
  integer, parameter :: n = 200000, reps = 7
  real(qp), allocatable :: v(:)
  real(xp), allocatable :: f(:)
  real(qp) :: x
  real(xp) :: y
  real(real64) :: t0, t1, times(reps, 11)
  real(real64) :: u
  integer :: i, r, k
  character(len=32) :: names(11) = [character(len=32) :: 'x87 round trip old', &
     'x87 round trip new', 'fast_sqrt old', 'fast_sqrt new', 'inverse_sqrt old', &
     'inverse_sqrt new', 'sqrt intrinsic', 'v(i) - x chain (the add)', &
     'x87 round trip libgcc', 'double round trip libgcc', 'double round trip double_real']
  real(real64) :: dd
  allocate (v(n), f(n))
  do i = 1, n
     call random_number(u)
     v(i) = (1.0_qp + real(u, qp)/3.0_qp)*2.0_qp**int(200*u - 100)
     call random_number(u)
     f(i) = real(0.75_real64 + 0.5_real64*u, xp)
     if (mod(i, 2) == 0) f(i) = 1.0_xp/f(i - 1)
  end do
  do r = 1, reps
     do k = 1, 11
        x = 1.5_qp
        call cpu_time(t0)
        select case (k)
        case (1)
           do i = 1, n
              y = o_hr(x)*f(i)
              x = o_qr(y)
           end do
        case (2)
           do i = 1, n
              y = n_hr(x)*f(i)
              x = n_qr(y)
           end do
        case (3)
           do i = 1, n
              x = o_sqrt(v(i) + x)
           end do
        case (4)
           do i = 1, n
              x = n_sqrt(v(i) + x)
           end do
        case (5)
           do i = 1, n
              x = o_isqrt(v(i) + x)
           end do
        case (6)
           do i = 1, n
              x = n_isqrt(v(i) + x)
           end do
        case (7)
           do i = 1, n
              x = sqrt(v(i) + x)
           end do
        case (8)
           do i = 1, n
              x = v(i) - x
           end do
        case (9)
           do i = 1, n
              y = real(x, xp)*f(i)
              x = real(y, qp)
           end do
        case (10)
           do i = 1, n
              dd = real(x, real64)*real(f(i), real64)
              x = real(dd, qp)
           end do
        case (11)
           do i = 1, n
              dd = n_dr(x)*real(f(i), real64)
              x = real(dd, qp)
           end do
        end select
        call cpu_time(t1)
        times(r, k) = (t1 - t0)/n*1e9_real64
        if (x == 12345.0_qp) print *, x
     end do
  end do
  do k = 1, 11
     call sort(times(:, k))
     print '(a32, f9.1, a, f9.1, a, f9.1, a)', names(k), times((reps + 1)/2, k), &
        ' ns  (min', times(1, k), ', max', times(reps, k), ')'
  end do
contains
  subroutine sort(a)
    real(real64), intent(inout) :: a(:)
    integer :: i, j
    real(real64) :: t
    do i = 2, size(a)
       t = a(i); j = i - 1
       do while (j >= 1)
          if (a(j) <= t) exit
          a(j + 1) = a(j); j = j - 1
       end do
       a(j + 1) = t
    end do
  end subroutine
end program
