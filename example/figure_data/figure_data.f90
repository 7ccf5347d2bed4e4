!> brachistochrone-figure-data: the curves of the figures of the other fields, as CSV.
!!
!!     brachistochrone-figure-data KIND [--points N] [--exponent n] [--rmax r]
!!                                 [--output FILE] [VALUE ...]
!!
!! An example program of the library (`fpm run --example brachistochrone-figure-data`),
!! used by scripts/figures.py. Every number it writes comes from the library's own
!! routines: the closed forms of the hypocycloid and of the cycloid, the general engine's
!! integrals Theta, S, T (Tee eqs. 27, 33, 39) for power laws, the repulsive integrals
!! (28), (34), (40) and the critical curve's closed form. KIND is one of
!!
!!   hypocycloids RHO_M...     tunnels inside a uniform planet (Saitoh 7-10), units
!!                             R = omega = 1: id,rho_m,point,phase,r,theta,s,t,x,y
!!   tunnel-times              surface-to-surface tunnels on the Earth (6371 km,
!!                             9.81 m/s^2) at N central angles from 0 to 180 degrees:
!!                             angle_deg,distance_km,depth_km,length_km,time_min,
!!                             chord_km,chord_time_min
!!   power-arches R...         complete brachistochrones for F = 1/r^n (--exponent n)
!!                             with apse radii 0 < R < 1: id,n,R,point,r,theta,s,t,x,y
!!   power-locus R...          the apsidal locus Theta(R,R) at those R, with the library's
!!                             limit as R -> 0: n,R,theta,s,t,x,y,limit
!!   repulsive-bounded R...    repulsive force, bounded curves with apse 1 < R < 3/2,
!!                             A to A' (both half-arches)
!!   repulsive-unbounded G...  unbounded curves of gap 0 < g <= 3 (g = 3: radial), from
!!                             r = 1 to --rmax (default 6)
!!   repulsive-critical        the critical curve K^2 = 27/8 from r = 1 towards 3/2
!!                             (3 - 2r down to 1e-12, 2.5 turns); the repulsive kinds write
!!                             id,kind,parameter,K2,point,r,theta,s,t,x,y
!!   cycloids XB YB [XB YB...] uniform gravity g = 1, y downward: the cycloid from A =
!!                             (0, 0) through each B: id,x_b,y_b,a,phi_b,t_b,s_b,point,
!!                             phi,x,y
!!   isochrone H...            descent times from rest at heights 0 < h <= 2 to the base
!!                             of the cycloid half-arch alpha = 1 (g = 1), by quadrature
!!                             of Tee's (3)-(4) and closed form, and the simple pendulum
!!                             of the same small-swing period (length 4) from the same
!!                             height: h,time_quadrature,time_closed,pendulum_time
!!
!! --points N (default 201) is the number of points per curve (complete arches: the
!! largest odd number <= N, the apse in the middle). Output: CSV (36
!! significant digits) with '#' provenance lines, to standard output or to FILE (written
!! under a temporary name and renamed when complete). Exit codes: 0 done; 1 usage error
!! (nothing written); 2 a library routine returned an error (nothing written); 3 I/O.
program figure_data
    use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use brachistochrone, only: qp, pi, status_ok, status_word, power_law, &
                               central_force_model, new_central_force_model, &
                               hypocycloid_point, hypocycloid_at, planet_tunnel, plan_tunnel, &
                               uniform_brachistochrone, cycloid_point, isochrone_time, &
                               isochrone_time_quadrature, pendulum_period_quadrature
    use brachistochrone_repulsive, only: repulsive_curve, curve_from_apse, curve_from_gap, &
                                         repulsive_values, critical_values
    use brachistochrone_version, only: program_version
    use brachistochrone_result_output, only: format_real
    use brachistochrone_safe_file, only: safe_file, open_output, finish_output, &
                                         commit_outputs, discard_outputs, safe_ok
    use brachistochrone_command_line, only: get_argument
    use brachistochrone_strings, only: integer_text
    implicit none

    character(len=*), parameter :: name = 'brachistochrone-figure-data'
    integer, parameter :: exit_ok = 0, exit_usage = 1, exit_library = 2, exit_io = 3

    !> One line of the output.
    type :: text_line
        character(len=:), allocatable :: text
    end type text_line

    type(text_line), allocatable :: lines(:)
    integer :: line_count
    character(len=:), allocatable :: kind, output_path
    real(qp), allocatable :: values(:)
    real(qp) :: exponent, r_max
    integer :: points

    allocate (lines(256))
    line_count = 0
    call parse_arguments()
    call add_line('# '//name//' '//program_version)
    call add_line('# command: '//command_line())
    select case (kind)
    case ('hypocycloids');        call hypocycloids()
    case ('tunnel-times');        call tunnel_times()
    case ('power-arches');        call power_arches()
    case ('power-locus');         call power_locus()
    case ('repulsive-bounded');   call repulsive_bounded()
    case ('repulsive-unbounded'); call repulsive_unbounded()
    case ('repulsive-critical');  call repulsive_critical()
    case ('cycloids');            call cycloids()
    case ('isochrone');           call isochrone()
    end select
    call write_output()
    stop exit_ok, quiet=.true.

contains

    ! ------------------------------------------------------------------ the curves

    !> Saitoh's hypocycloids, N equal steps of the rolling angle phi in [0, 2 pi].
    subroutine hypocycloids()
        type(hypocycloid_point) :: p
        integer :: i, k
        call need_values(1, 'minimum radii 0 <= rho_m < 1')
        call add_line('# hypocycloid tunnels from A = (1, 0), units R = omega = 1 '// &
                      '(Saitoh 7-10); phase = rolling angle phi')
        call add_line('id,rho_m,point,phase,r,theta,s,t,x,y')
        do i = 1, size(values)
            if (values(i) < 0.0_qp .or. values(i) >= 1.0_qp) &
                call fail(exit_usage, 'minimum radius must satisfy 0 <= rho_m < 1')
            do k = 1, points
                p = hypocycloid_at(2.0_qp*pi*real(k - 1, qp)/real(points - 1, qp), values(i))
                call check(p%status, 'hypocycloid_at')
                call add_line(integer_text(i)//','//format_real(values(i))//','// &
                              integer_text(k)//','//numbers([p%phase, p%radius, p%angle, &
                                                             p%arclength, p%time, p%x, p%y]))
            end do
        end do
    end subroutine hypocycloids

    !> Tunnels between A at (0, 0) and places on the equator, longitude 0 .. 180 degrees.
    subroutine tunnel_times()
        type(planet_tunnel) :: route
        real(qp) :: longitude
        integer :: k
        call add_line('# brachistochrone tunnels on the Earth (uniform, 6371 km, '// &
                      '9.81 m/s^2) from (0, 0) to (0, angle_deg): plan_tunnel')
        call add_line('angle_deg,distance_km,depth_km,length_km,time_min,chord_km,'// &
                      'chord_time_min')
        do k = 1, points
            longitude = 180.0_qp*real(k - 1, qp)/real(points - 1, qp)
            route = plan_tunnel(0.0_qp, 0.0_qp, 0.0_qp, longitude)
            call check(route%status, 'plan_tunnel')
            call add_line(numbers([longitude, route%surface_distance_km, route%depth_km, &
                                   route%length_km, route%time_minutes, &
                                   route%chord_length_km, route%chord_time_seconds/60.0_qp]))
        end do
    end subroutine tunnel_times

    !> Complete power-law arches: the first half-arch at r = R + (1 - R) sin^2(mu/2), mu
    !! in equal steps from pi (A) to 0 (the apse), the second half by symmetry (eq. 29).
    subroutine power_arches()
        type(central_force_model) :: model
        real(qp), allocatable :: r(:), theta(:), s(:), t(:)
        real(qp) :: big_r, mu
        integer :: i, j, m, status
        call need_values(1, 'apse radii 0 < R < 1')
        model = power_model()
        m = (points - 1)/2
        allocate (r(0:m), theta(0:m), s(0:m), t(0:m))
        call add_line('# complete brachistochrones for the attractive force 1/r^n from A = '// &
                      '(1, 0), by apse radius R (Tee 27, 33, 39, 29; general engine)')
        call add_line('id,n,R,point,r,theta,s,t,x,y')
        do i = 1, size(values)
            big_r = values(i)
            if (.not. (big_r > 0.0_qp .and. big_r < 1.0_qp)) &
                call fail(exit_usage, 'apse radius must satisfy 0 < R < 1')
            do j = 0, m
                mu = pi*real(m - j, qp)/real(m, qp)
                r(j) = big_r + (1.0_qp - big_r)*sin(0.5_qp*mu)**2
                if (j == 0) r(j) = 1.0_qp
                if (j == m) r(j) = big_r
                call model%half_arch(r(j), big_r, .false., theta(j), s(j), t(j), status)
                call check(status, 'central_force_model%half_arch')
            end do
            do j = 0, 2*m
                if (j <= m) then
                    call arch_row(i, big_r, j, r(j), theta(j), s(j), t(j))
                else
                    call arch_row(i, big_r, j, r(2*m - j), 2.0_qp*theta(m) - theta(2*m - j), &
                                  2.0_qp*s(m) - s(2*m - j), 2.0_qp*t(m) - t(2*m - j))
                end if
            end do
        end do
    end subroutine power_arches

    subroutine arch_row(i, big_r, j, r, theta, s, t)
        integer, intent(in) :: i, j
        real(qp), intent(in) :: big_r, r, theta, s, t
        call add_line(integer_text(i)//','//format_real(exponent)//','//format_real(big_r)// &
                      ','//integer_text(j + 1)//','// &
                      numbers([r, theta, s, t, r*cos(theta), r*sin(theta)]))
    end subroutine arch_row

    !> The apsidal locus theta = Theta(R,R), r = R, of a power law.
    subroutine power_locus()
        type(central_force_model) :: model
        real(qp) :: theta, s, t
        integer :: i, status
        call need_values(1, 'apse radii 0 < R < 1')
        model = power_model()
        call add_line('# apsidal locus of the attractive force 1/r^n: theta = Theta(R,R), '// &
                      'r = R; limit = the library''s lim Theta(R,R) as R -> 0 (Keam)')
        call add_line('n,R,theta,s,t,x,y,limit')
        do i = 1, size(values)
            if (.not. (values(i) > 0.0_qp .and. values(i) < 1.0_qp)) &
                call fail(exit_usage, 'apse radius must satisfy 0 < R < 1')
            call model%half_arch(values(i), values(i), .false., theta, s, t, status)
            call check(status, 'central_force_model%half_arch')
            call add_line(numbers([exponent, values(i), theta, s, t, values(i)*cos(theta), &
                                   values(i)*sin(theta), model%law%apse_angle_limit()]))
        end do
    end subroutine power_locus

    function power_model() result(model)
        type(central_force_model) :: model
        if (.not. (exponent > 1.0_qp)) call fail(exit_usage, 'give --exponent n with n > 1')
        model = new_central_force_model(power_law(n=exponent))
    end function power_model

    !> Bounded repulsive curves: r = 1 + (R - 1) sin^2(mu/2), mu in equal steps from 0 (A)
    !! to pi (the apse), then the second half-arch by symmetry (eq. 29) back to r = 1.
    subroutine repulsive_bounded()
        type(repulsive_curve) :: curve
        real(qp), allocatable :: r(:), theta(:), s(:), t(:)
        integer :: i, j, m, status
        call need_values(1, 'apse radii 1 < R < 3/2')
        m = (points - 1)/2
        allocate (r(0:m), theta(0:m), s(0:m), t(0:m))
        call repulsive_header('bounded curves (apse R < 3/2), A to A''; parameter = R')
        do i = 1, size(values)
            call curve_from_apse(values(i), curve, status)
            if (status /= status_ok) call fail(exit_usage, 'apse radius must satisfy 1 < R < 3/2')
            do j = 0, m
                r(j) = 1.0_qp + curve%apse_m1*sin(0.5_qp*pi*real(j, qp)/real(m, qp))**2
                if (j == m) r(j) = curve%apse
                call repulsive_values(curve, r(j), .false., theta(j), s(j), t(j), status)
                call check(status, 'repulsive_values')
            end do
            do j = 0, 2*m
                if (j <= m) then
                    call repulsive_row(i, 'bounded', values(i), curve%k2, j, r(j), theta(j), &
                                       s(j), t(j))
                else
                    call repulsive_row(i, 'bounded', values(i), curve%k2, j, r(2*m - j), &
                                       2.0_qp*theta(m) - theta(2*m - j), &
                                       2.0_qp*s(m) - s(2*m - j), 2.0_qp*t(m) - t(2*m - j))
                end if
            end do
        end do
    end subroutine repulsive_bounded

    !> Unbounded repulsive curves from r = 1 to r_max, at r = a + sqrt(beta) sinh(xi) in
    !! equal steps of xi (dense where the curve turns, near r = 3/2) or equal steps of r
    !! for the radial path (g = 3).
    subroutine repulsive_unbounded()
        type(repulsive_curve) :: curve
        real(qp) :: r, theta, s, t, width, xi_1, xi_2, u
        integer :: i, j, status
        call need_values(1, 'gaps 0 < g <= 3')
        if (.not. (r_max > 1.0_qp .and. ieee_is_finite(r_max))) &
            call fail(exit_usage, '--rmax must be a number > 1')
        call repulsive_header('unbounded curves (K^2 < 27/8), r = 1 .. '// &
                              format_real(r_max)//'; parameter = gap g = 3 - P')
        do i = 1, size(values)
            if (.not. (values(i) > 0.0_qp)) call fail(exit_usage, 'gap must satisfy 0 < g <= 3')
            call curve_from_gap(values(i), curve, status)
            if (status /= status_ok) call fail(exit_usage, 'gap must satisfy 0 < g <= 3')
            width = sqrt(curve%width2)
            if (width > 0.0_qp) then
                xi_1 = asinh((1.0_qp - curve%centre)/width)
                xi_2 = asinh((r_max - curve%centre)/width)
            end if
            do j = 0, points - 1
                u = real(j, qp)/real(points - 1, qp)
                if (width > 0.0_qp) then
                    r = max(1.0_qp, curve%centre + width*sinh(xi_1 + (xi_2 - xi_1)*u))
                else
                    r = 1.0_qp + (r_max - 1.0_qp)*u
                end if
                if (j == 0) r = 1.0_qp
                if (j == points - 1) r = r_max
                call repulsive_values(curve, r, .false., theta, s, t, status)
                call check(status, 'repulsive_values')
                call repulsive_row(i, 'unbounded', values(i), curve%k2, j, r, theta, s, t)
            end do
        end do
    end subroutine repulsive_unbounded

    !> The critical curve at r = 3/2 - e/2, e = 3 - 2r: the first third of the points in
    !! equal steps of r (e from 1 to 1/10), the rest in equal steps of log(e) down to
    !! 1e-12 (about equal steps of theta, which grows like -log(e)/sqrt(3)).
    subroutine repulsive_critical()
        real(qp) :: r, e, theta, s, t, u
        integer :: j, status, first
        if (size(values) > 0) call fail(exit_usage, 'repulsive-critical takes no values')
        call repulsive_header('the critical curve K^2 = 27/8 (closed form), spiralling '// &
                              'onto r = 3/2; parameter = 3 - 2r at the last point')
        first = (points - 1)/3
        do j = 0, points - 1
            if (j < first) then
                e = 1.0_qp - 0.9_qp*real(j, qp)/real(first, qp)
            else
                u = real(j - first, qp)/real(points - 1 - first, qp)
                e = 0.1_qp*10.0_qp**(-11.0_qp*u)
            end if
            r = 1.5_qp - 0.5_qp*e
            call critical_values(r, theta, s, t, status)
            call check(status, 'critical_values')
            call repulsive_row(1, 'critical', 1.0e-12_qp, 27.0_qp/8.0_qp, j, r, theta, s, t)
        end do
    end subroutine repulsive_critical

    subroutine repulsive_header(what)
        character(len=*), intent(in) :: what
        call add_line('# repulsive inverse-square force (mu = -1) from A = (1, 0): '//what// &
                      ' (Tee 28, 34, 40, 29)')
        call add_line('id,kind,parameter,K2,point,r,theta,s,t,x,y')
    end subroutine repulsive_header

    subroutine repulsive_row(i, what, parameter, k2, j, r, theta, s, t)
        integer, intent(in) :: i, j
        character(len=*), intent(in) :: what
        real(qp), intent(in) :: parameter, k2, r, theta, s, t
        call add_line(integer_text(i)//','//what//','//numbers([parameter, k2])//','// &
                      integer_text(j + 1)//','// &
                      numbers([r, theta, s, t, r*cos(theta), r*sin(theta)]))
    end subroutine repulsive_row

    !> Uniform gravity: the cycloid from A through each B, N equal steps of phi in
    !! [0, phi_B].
    subroutine cycloids()
        real(qp) :: phi_b, radius, time, length, phi, x, y
        integer :: i, k, status
        if (size(values) == 0 .or. modulo(size(values), 2) /= 0) &
            call fail(exit_usage, 'cycloids needs pairs x_B y_B (y downward)')
        call add_line('# uniform gravity g = 1, y downward: the brachistochrone cycloid '// &
                      'x = a (phi - sin phi), y = a (1 - cos phi) from A = (0, 0) through B')
        call add_line('id,x_b,y_b,a,phi_b,t_b,s_b,point,phi,x,y')
        do i = 1, size(values)/2
            call uniform_brachistochrone(values(2*i - 1), values(2*i), 1.0_qp, phi_b, radius, &
                                         time, length, status)
            call check(status, 'uniform_brachistochrone')
            if (.not. (radius > 0.0_qp .and. ieee_is_finite(radius))) &
                call fail(exit_usage, 'B must not be straight below A (x_B > 0)')
            do k = 1, points
                phi = phi_b*real(k - 1, qp)/real(points - 1, qp)
                call cycloid_point(radius, phi, x, y, status)
                call check(status, 'cycloid_point')
                call add_line(integer_text(i)//','// &
                              numbers([values(2*i - 1), values(2*i), radius, phi_b, time, &
                                       length])//','//integer_text(k)//','// &
                              numbers([phi, x, y]))
            end do
        end do
    end subroutine cycloids

    !> Descent times to the base of the isochrone (alpha = 1, g = 1) and of the circle of
    !! radius 4 (the pendulum with the same small-swing period), from rest at height h.
    subroutine isochrone()
        real(qp), parameter :: length = 4.0_qp
        real(qp) :: quadrature, closed, period, amplitude
        integer :: i, status
        call need_values(1, 'heights 0 < h <= 2')
        call add_line('# descent time from rest at height h to the base: cycloid '// &
                      'half-arch alpha = 1 (Tee 3-4 by quadrature; closed form pi), '// &
                      'pendulum of length 4 (a quarter period), g = 1')
        call add_line('h,time_quadrature,time_closed,pendulum_time')
        do i = 1, size(values)
            call isochrone_time_quadrature(1.0_qp, 1.0_qp, values(i), quadrature, status)
            call check(status, 'isochrone_time_quadrature')
            call isochrone_time(1.0_qp, 1.0_qp, closed, status)
            call check(status, 'isochrone_time')
            ! height h = L (1 - cos theta0) = 2 L sin^2(theta0/2)
            amplitude = 2.0_qp*asin(sqrt(values(i)/(2.0_qp*length)))
            call pendulum_period_quadrature(length, 1.0_qp, amplitude, period, status)
            call check(status, 'pendulum_period_quadrature')
            call add_line(numbers([values(i), quadrature, closed, 0.25_qp*period]))
        end do
    end subroutine isochrone

    ! ------------------------------------------------------------------ plumbing

    subroutine parse_arguments()
        character(len=:), allocatable :: argument
        integer :: k, ios
        real(qp) :: value
        points = 201
        exponent = 0.0_qp
        r_max = 6.0_qp
        output_path = ''
        kind = ''
        allocate (values(0))
        k = 0
        do while (k < command_argument_count())
            k = k + 1
            argument = get_argument(k)
            select case (argument)
            case ('-h', '--help')
                call usage()
                stop exit_ok, quiet=.true.
            case ('--points', '--exponent', '--rmax', '--output')
                if (k == command_argument_count()) &
                    call fail(exit_usage, argument//' needs a value')
                k = k + 1
                call option_value(argument, get_argument(k))
            case default
                if (len(kind) == 0 .and. verify(argument(1:1), '+-.0123456789') /= 0) then
                    kind = argument
                    cycle
                end if
                read (argument, *, iostat=ios) value
                if (ios /= 0 .or. verify(argument, '+-.0123456789eEdDqQ') /= 0 .or. &
                    .not. ieee_is_finite(value)) &
                    call fail(exit_usage, '"'//argument//'" is not a number (see --help)')
                values = [values, value]
            end select
        end do
        select case (kind)
        case ('hypocycloids', 'tunnel-times', 'power-arches', 'power-locus', &
              'repulsive-bounded', 'repulsive-unbounded', 'repulsive-critical', 'cycloids', &
              'isochrone')
        case default
            call fail(exit_usage, 'unknown or missing KIND "'//kind//'" (see --help)')
        end select
    end subroutine parse_arguments

    subroutine option_value(option, text)
        character(len=*), intent(in) :: option, text
        integer :: ios
        if (option == '--output') then
            output_path = text
            return
        end if
        if (option == '--points') then
            read (text, *, iostat=ios) points
            if (ios /= 0 .or. verify(text, '0123456789') /= 0 .or. points < 3 .or. &
                points > 100000) &
                call fail(exit_usage, '--points needs a whole number 3 <= N <= 100000')
        else if (option == '--exponent') then
            read (text, *, iostat=ios) exponent
            if (ios /= 0 .or. verify(text, '+-.0123456789eEdDqQ') /= 0) &
                call fail(exit_usage, '--exponent needs a number n > 1')
        else
            read (text, *, iostat=ios) r_max
            if (ios /= 0 .or. verify(text, '+-.0123456789eEdDqQ') /= 0) &
                call fail(exit_usage, '--rmax needs a number > 1')
        end if
    end subroutine option_value

    subroutine need_values(count, what)
        integer, intent(in) :: count
        character(len=*), intent(in) :: what
        if (size(values) < count) call fail(exit_usage, kind//' needs '//what)
    end subroutine need_values

    !> Stop with exit 2 when a library routine returned an error status.
    subroutine check(status, routine)
        integer, intent(in) :: status
        character(len=*), intent(in) :: routine
        if (status /= status_ok) &
            call fail(exit_library, routine//' returned '//status_word(status))
    end subroutine check

    subroutine add_line(text)
        character(len=*), intent(in) :: text
        type(text_line), allocatable :: bigger(:)
        if (line_count == size(lines)) then
            allocate (bigger(2*size(lines)))
            bigger(:line_count) = lines(:line_count)
            call move_alloc(bigger, lines)
        end if
        line_count = line_count + 1
        lines(line_count)%text = text
    end subroutine add_line

    !> The values with 36 significant digits, separated by commas.
    function numbers(x) result(line)
        real(qp), intent(in) :: x(:)
        character(len=:), allocatable :: line
        integer :: i
        line = format_real(x(1))
        do i = 2, size(x)
            line = line//','//format_real(x(i))
        end do
    end function numbers

    !> Write every line to standard output, or to FILE (replaced when it exists; a
    !! regular file or link only), through the checked writer (`brachistochrone_safe_file`).
    subroutine write_output()
        type(safe_file) :: out(1)
        character(len=:), allocatable :: message
        integer :: status, i
        if (len(output_path) == 0) then
            call open_output(out(1), '-', .true., status, message)
        else
            call open_output(out(1), output_path, .true., status, message)
        end if
        if (status /= safe_ok) call fail(exit_io, message)
        do i = 1, line_count
            call out(1)%put(lines(i)%text)
        end do
        call finish_output(out(1), status, message)
        if (status == safe_ok) call commit_outputs(out, status, message)
        if (status /= safe_ok) then
            call discard_outputs(out)
            call fail(exit_io, message)
        end if
    end subroutine write_output

    function command_line() result(text)
        character(len=:), allocatable :: text
        integer :: length
        call get_command(length=length)
        allocate (character(len=length) :: text)
        call get_command(text)
    end function command_line

    subroutine usage()
        write (output_unit, '(a)') 'usage: '//name//' KIND [--points N] [--exponent n] '// &
            '[--rmax r] [--output FILE] [VALUE ...]'
        write (output_unit, '(a)') 'KIND: hypocycloids RHO_M..., tunnel-times, power-arches '// &
            'R... (--exponent n),'
        write (output_unit, '(a)') '      power-locus R... (--exponent n), repulsive-bounded '// &
            'R..., repulsive-unbounded G...,'
        write (output_unit, '(a)') '      repulsive-critical, cycloids XB YB ..., isochrone H...'
        write (output_unit, '(a)') 'CSV to standard output or FILE. Exit codes: 0 done; 1 '// &
            'usage; 2 library error; 3 I/O. Version '//program_version//'.'
    end subroutine usage

    subroutine fail(code, text)
        integer, intent(in) :: code
        character(len=*), intent(in) :: text
        write (error_unit, '(a)') name//': '//text
        stop code, quiet=.true.
    end subroutine fail

end program figure_data
