!> The C interface of the library, declared in include/brachistochrone.h.
!!
!! Five functions with C linkage (bind(C)): solve one endpoint in double or in quad
!! precision (`__float128`), solve many in parallel (OpenMP inside), a message per
!! status, and whether the machine's x87 arithmetic is as the library assumes it. The
!! field is named by a string: 'inverse_square', 'power' (with `exponent`),
!! 'logarithmic', 'harmonic', 'repulsive' (the least-time brachistochrone, as the batch
!! program's CSV). Values that do not exist are NaN: R-bar for radial fall and for
!! unbounded (repulsive) curves, R-bar and s when the endpoint is inaccessible (t is then
!! kappa(rho), the greatest lower bound), all three when the status is an error. Any
!! output pointer may be NULL (that output is not written).
!!
!! Thread safety: the only shared mutable state is a cache of built fields (the
!! inverse-square model's Gauss rules and tables cost about 50 ms of CPU, a power law's
!! rules about as much, the repulsive field's a few ms): the first call that names a field
!! (name and, for 'power', exponent) builds it inside an OpenMP critical section and keeps
!! it; later calls only read it. At most `max_cached` fields are kept; a call naming yet
!! another one builds it for that call only. The messages are filled once the same way.
!! Every function may be called from several threads at once.
!!
!! Statuses (brachistochrone_status): status_ok; status_unknown_field for a name that is
!! not a field's (or NULL); status_bad_exponent for 'power' with an exponent that is not a
!! finite n > 1; otherwise the status of the field's solver for the endpoint:
!! status_inaccessible, status_rho_out_of_range, status_psi_out_of_range,
!! status_not_finite, status_no_convergence, status_rho_below_start ('repulsive').
!!
!! Fields come from the library's factory `new_field` (`prepare_field`), the same as for
!! the batch program, so the C interface solves exactly what the namelist's `force` does.
module brachistochrone_c_api
    use, intrinsic :: iso_c_binding, only: c_int, c_long, c_double, c_float128, c_char, &
                                           c_ptr, c_null_char, c_associated, c_f_pointer, &
                                           c_loc
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_finite
    use brachistochrone, only: qp, endpoint_solution, brachistochrone_field, new_field, &
                               field_names, status_ok, status_unknown_field, &
                               status_message, arch_radial, hardware_arithmetic_ok
    implicit none
    private

    public :: brachistochrone_solve, brachistochrone_solve_q, brachistochrone_solve_many, &
              brachistochrone_status_message, brachistochrone_arithmetic_ok

    !> Longest force name accepted (longer strings are unknown names).
    integer, parameter :: max_name_length = 32
    !> Status codes with a message table entry, and the room for each message.
    integer, parameter :: max_code = 63, message_length = 200

    !> Most fields kept built (distinct names and power-law exponents).
    integer, parameter :: max_cached = 16

    !> A field named by a string, ready to solve endpoints: an entry of the cache, or
    !! (cache full) its own.
    type :: named_field
        class(brachistochrone_field), allocatable :: own
        integer :: entry = 0  !! index in `cache`; 0: `own`
    end type named_field

    !> A built field and what it was built from.
    type :: cached_field
        class(brachistochrone_field), allocatable :: field
        character(len=max_name_length) :: name = ''
        real(qp) :: exponent = 0.0_qp  !! 0 except for 'power'
    end type cached_field

    !> The fields built so far (see the module notes); entries 1..cached are complete and
    !! never change again.
    type(cached_field), save :: cache(max_cached)
    integer, save :: cached = 0
    !> NUL-terminated messages, filled once; c_loc of a column is handed to C.
    character(kind=c_char), save, target :: messages(message_length, -1:max_code)
    logical, save :: messages_ready = .false.

contains

    !> int brachistochrone_solve(const char *force, double exponent, double rho,
    !! double psi, double *apse_radius, double *arclength, double *time)
    !! Returns the status (0 solved; brachistochrone_status_message says why not).
    function brachistochrone_solve(force, exponent, rho, psi, apse_radius, arclength, &
                                   time) result(status) bind(C, name='brachistochrone_solve')
        type(c_ptr), value :: force                 !! field name, NUL-terminated
        real(c_double), value :: exponent           !! n of F = mu/r^n ('power' only)
        real(c_double), value :: rho, psi           !! the endpoint B
        type(c_ptr), value :: apse_radius, arclength, time !! outputs (double *), or NULL
        integer(c_int) :: status
        type(endpoint_solution) :: solution
        solution = solve_named(force, real(exponent, qp), real(rho, qp), real(psi, qp))
        status = int(solution%status, c_int)
        call put_double(apse_radius, solution%apse_radius, has_apse(solution))
        call put_double(arclength, solution%arclength, solution%has_arclength)
        call put_double(time, solution%time, solution%has_time)
    end function brachistochrone_solve

    !> int brachistochrone_solve_q(const char *force, __float128 exponent,
    !! __float128 rho, __float128 psi, __float128 *apse_radius, __float128 *arclength,
    !! __float128 *time): the same in quad precision (all 34 digits; NaN as above).
    function brachistochrone_solve_q(force, exponent, rho, psi, apse_radius, arclength, &
                                     time) result(status) &
                                     bind(C, name='brachistochrone_solve_q')
        type(c_ptr), value :: force                 !! field name, NUL-terminated
        real(c_float128), value :: exponent         !! n of F = mu/r^n ('power' only)
        real(c_float128), value :: rho, psi         !! the endpoint B
        type(c_ptr), value :: apse_radius, arclength, time !! outputs (__float128 *)
        integer(c_int) :: status
        type(endpoint_solution) :: solution
        solution = solve_named(force, real(exponent, qp), real(rho, qp), real(psi, qp))
        status = int(solution%status, c_int)
        call put_quad(apse_radius, solution%apse_radius, has_apse(solution))
        call put_quad(arclength, solution%arclength, solution%has_arclength)
        call put_quad(time, solution%time, solution%has_time)
    end function brachistochrone_solve_q

    !> int brachistochrone_solve_many(const char *force, double exponent, long n,
    !! const double *rho, const double *psi, double *apse_radius, double *arclength,
    !! double *time, int *status): n endpoints in parallel (OpenMP threads, dynamic
    !! schedule; the results do not depend on the number of threads). Returns the number
    !! of endpoints whose status is not 0 (at most INT_MAX), or -1 when n < 0 or rho or
    !! psi is NULL with n > 0. The output arrays (n elements) may be NULL.
    function brachistochrone_solve_many(force, exponent, n, rho, psi, apse_radius, &
                                        arclength, time, status) result(failures) &
                                        bind(C, name='brachistochrone_solve_many')
        type(c_ptr), value :: force                 !! field name, NUL-terminated
        real(c_double), value :: exponent           !! n of F = mu/r^n ('power' only)
        integer(c_long), value :: n                 !! number of endpoints
        type(c_ptr), value :: rho, psi              !! the endpoints (const double *)
        type(c_ptr), value :: apse_radius, arclength, time, status !! outputs, or NULL
        integer(c_int) :: failures
        real(c_double), pointer :: rho_in(:), psi_in(:)
        type(named_field) :: field
        integer(c_int) :: field_status, one_status
        integer(c_long) :: i, count
        type(endpoint_solution) :: solution
        failures = -1
        if (n < 0) return
        if (n == 0) then
            failures = 0
            return
        end if
        if (.not. (c_associated(rho) .and. c_associated(psi))) return
        call c_f_pointer(rho, rho_in, [n])
        call c_f_pointer(psi, psi_in, [n])
        call prepare_field(trim(force_name(force)), real(exponent, qp), field, field_status)
        count = 0
        !$omp parallel do schedule(dynamic, 16) default(shared) &
        !$omp private(i, solution, one_status) reduction(+:count)
        do i = 1, n
            one_status = field_status
            if (field_status == status_ok) then
                solution = solve_in_field(field, real(rho_in(i), qp), real(psi_in(i), qp))
                one_status = solution%status
            else
                solution = endpoint_solution()
            end if
            if (one_status /= status_ok) count = count + 1
            call put_many(apse_radius, i, n, solution%apse_radius, &
                          has_apse(solution))
            call put_many(arclength, i, n, solution%arclength, &
                          solution%has_arclength)
            call put_many(time, i, n, solution%time, solution%has_time)
            call put_status(status, i, n, one_status)
        end do
        !$omp end parallel do
        failures = int(min(count, int(huge(failures), c_long)), c_int)
    end function brachistochrone_solve_many

    !> int brachistochrone_arithmetic_ok(void): 1 where the x87 arithmetic is at its
    !! defaults (precision control at 64 bits, rounding to nearest), as the library's
    !! quad-precision arithmetic assumes, 0 where the program or a library changed them
    !! (gfortran -mpc64, fldcw, fesetround: results would be wrong, by up to 1e22 ulp at
    !! 53 bits). A check to make once, before solving.
    function brachistochrone_arithmetic_ok() result(ok) &
            bind(C, name='brachistochrone_arithmetic_ok')
        integer(c_int) :: ok
        ok = merge(1_c_int, 0_c_int, hardware_arithmetic_ok())
    end function brachistochrone_arithmetic_ok

    !> const char *brachistochrone_status_message(int status): one sentence per status
    !! code, NUL-terminated, in static storage (never freed by the caller); "unknown
    !! status" for a code that is not one.
    function brachistochrone_status_message(status) result(text) &
            bind(C, name='brachistochrone_status_message')
        integer(c_int), value :: status     !! a status returned by the functions above
        type(c_ptr) :: text
        integer :: k, j
        character(len=:), allocatable :: sentence
        !$omp critical (brachistochrone_c_api_messages)
        if (.not. messages_ready) then
            do k = -1, max_code
                sentence = status_message(k)
                if (k < 0) sentence = 'unknown status'
                sentence = sentence(1:min(len(sentence), message_length - 1))
                messages(:, k) = c_null_char
                do j = 1, len(sentence)
                    messages(j, k) = sentence(j:j)
                end do
            end do
            messages_ready = .true.
        end if
        !$omp end critical (brachistochrone_c_api_messages)
        k = -1
        if (status >= 0 .and. status <= max_code) k = status
        text = c_loc(messages(1, k))
    end function brachistochrone_status_message

    !> The field named `name` from the library's factory (`new_field`), built once and
    !! kept (`cache`): status_ok, status_unknown_field, or status_bad_exponent.
    subroutine prepare_field(name, exponent, field, status)
        character(len=*), intent(in) :: name    !! 'inverse_square', 'power', ...
        real(qp), intent(in) :: exponent        !! n of F = mu/r^n, used by 'power' only
        type(named_field), intent(out) :: field !! ready to solve
        integer(c_int), intent(out) :: status   !! what went wrong
        real(qp) :: key
        integer :: code, k
        status = status_unknown_field
        ! ask the factory only about names it knows (it would build a model otherwise)
        if (len(name) == 0 .or. index(field_names, "'"//name//"'") == 0) return
        key = merge(exponent, 0.0_qp, name == 'power')
        code = status_ok
        !$omp critical (brachistochrone_c_api_model)
        do k = 1, cached
            if (cache(k)%name == name .and. cache(k)%exponent == key) field%entry = k
        end do
        if (field%entry == 0 .and. cached < max_cached) then
            call new_field(name, exponent, cache(cached + 1)%field, code)
            if (code == status_ok) then
                cache(cached + 1)%name = name
                cache(cached + 1)%exponent = key
                cached = cached + 1
                field%entry = cached
            end if
        else if (field%entry == 0) then
            call new_field(name, exponent, field%own, code)
        end if
        !$omp end critical (brachistochrone_c_api_model)
        status = int(code, c_int)
    end subroutine prepare_field

    !> Solve endpoint (rho, psi) in the field named at `force`; a bad name or exponent is
    !! the solution's status (its values then do not exist).
    function solve_named(force, exponent, rho, psi) result(solution)
        type(c_ptr), intent(in) :: force      !! field name, NUL-terminated
        real(qp), intent(in) :: exponent      !! n of F = mu/r^n ('power' only)
        real(qp), intent(in) :: rho, psi      !! the endpoint
        type(endpoint_solution) :: solution
        type(named_field) :: field
        integer(c_int) :: status
        call prepare_field(trim(force_name(force)), exponent, field, status)
        if (status == status_ok) then
            solution = solve_in_field(field, rho, psi)
        else
            solution%status = int(status)
        end if
    end function solve_named

    !> Solve endpoint (rho, psi) in a prepared field.
    pure function solve_in_field(field, rho, psi) result(solution)
        type(named_field), intent(in) :: field  !! from prepare_field, status_ok
        real(qp), intent(in) :: rho, psi        !! the endpoint
        type(endpoint_solution) :: solution
        if (field%entry > 0) then
            solution = cache(field%entry)%field%solve(rho, psi)
        else
            solution = field%own%solve(rho, psi)
        end if
    end function solve_in_field

    !> The NUL-terminated string at `force` (at most max_name_length characters; a
    !! longer or NULL string gives a name that is not a field's).
    !! The result is fixed-length (blank-padded): with gfortran 12, functions returning
    !! deferred-length strings give wrong results when threads call them at once, and
    !! the C functions may be called from many threads.
    function force_name(force) result(name)
        type(c_ptr), intent(in) :: force
        character(len=max_name_length) :: name
        character(kind=c_char), pointer :: chars(:)
        integer :: k
        name = '(null)'
        if (.not. c_associated(force)) return
        call c_f_pointer(force, chars, [max_name_length + 1])
        name = ''
        do k = 1, max_name_length + 1
            if (chars(k) == c_null_char) return
            if (k > max_name_length) exit
            name(k:k) = chars(k)
        end do
        name = '(too long)'
    end function force_name

    !> R-bar exists: the solver found one and the curve is not radial fall (R = 0 there,
    !! a limit, not an apse). The solver's flags say whether s and t exist.
    pure logical function has_apse(solution)
        type(endpoint_solution), intent(in) :: solution
        has_apse = solution%has_apse_radius .and. solution%arch /= arch_radial
    end function has_apse

    subroutine put_double(target_address, value, exists)
        type(c_ptr), intent(in) :: target_address
        real(qp), intent(in) :: value
        logical, intent(in) :: exists
        real(c_double), pointer :: out
        if (.not. c_associated(target_address)) return
        call c_f_pointer(target_address, out)
        out = ieee_value(out, ieee_quiet_nan)
        if (exists) out = real(value, c_double)
    end subroutine put_double

    subroutine put_quad(target_address, value, exists)
        type(c_ptr), intent(in) :: target_address
        real(qp), intent(in) :: value
        logical, intent(in) :: exists
        real(c_float128), pointer :: out
        if (.not. c_associated(target_address)) return
        call c_f_pointer(target_address, out)
        out = ieee_value(out, ieee_quiet_nan)
        if (exists) out = value
    end subroutine put_quad

    subroutine put_many(target_address, i, n, value, exists)
        type(c_ptr), intent(in) :: target_address
        integer(c_long), intent(in) :: i, n
        real(qp), intent(in) :: value
        logical, intent(in) :: exists
        real(c_double), pointer :: out(:)
        if (.not. c_associated(target_address)) return
        call c_f_pointer(target_address, out, [n])
        out(i) = ieee_value(out(i), ieee_quiet_nan)
        if (exists) out(i) = real(value, c_double)
    end subroutine put_many

    subroutine put_status(target_address, i, n, status)
        type(c_ptr), intent(in) :: target_address
        integer(c_long), intent(in) :: i, n
        integer(c_int), intent(in) :: status
        integer(c_int), pointer :: out(:)
        if (.not. c_associated(target_address)) return
        call c_f_pointer(target_address, out, [n])
        out(i) = status
    end subroutine put_status

end module brachistochrone_c_api
