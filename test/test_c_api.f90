!> The C interface (module brachistochrone_c_api, include/brachistochrone.h) called as C
!! would call it, through C pointers: Tee's Table 1 as published, Saitoh's closed form (10)
!! for the harmonic field in quad precision, the NaN of values that do not exist, the
!! statuses of bad input, solve_many, the messages, and calls from several OpenMP
!! threads at once. (example/c_user checks the same from C.)
module test_c_api
    use, intrinsic :: iso_c_binding, only: c_char, c_null_char, c_double, c_float128, c_int, &
                                           c_long, c_ptr, c_loc, c_null_ptr, c_f_pointer
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
    use brachistochrone_kinds, only: qp, pi
    use brachistochrone_status, only: status_ok, status_inaccessible, &
                                      status_rho_out_of_range, status_unknown_field, &
                                      status_bad_exponent
    use brachistochrone_c_api, only: brachistochrone_solve, brachistochrone_solve_q, &
                                     brachistochrone_solve_many, &
                                     brachistochrone_status_message, &
                                     brachistochrone_arithmetic_ok
    use testing, only: check, check_digits, section
    implicit none
    private

    public :: run_c_api_tests

    !> Tee (1998), Table 1 as published (rho of rows 1-2 corrected, docs/ERRATA.md).
    real(c_double), parameter :: table_rho(5) = [0.2_c_double, 0.5_c_double, 0.7_c_double, &
                                                 0.9_c_double, 1.0_c_double]
    real(c_double), parameter :: table_psi(5) = [1.2_c_double, 0.1_c_double, 1.8_c_double, &
                                                 0.4_c_double, 2.0_c_double]
    real(c_double), parameter :: table_r(5) = [0.184781963328079_c_double, &
        0.252787093630160_c_double, 0.168913316595188_c_double, 0.838545794202334_c_double, &
        0.057854464393370_c_double]
    real(c_double), parameter :: table_t(5) = [1.127755808164997_c_double, &
        0.914164272619962_c_double, 1.481218910277573_c_double, 1.058599268341289_c_double, &
        2.221060707125763_c_double]

contains

    subroutine run_c_api_tests()
        call section('C interface: Table 1, Saitoh (10), NaN, statuses, threads')
        call check_threads()
        call check_single()
        call check_quad()
        call check_missing_values()
        call check_many()
        call check_kept_fields()
    end subroutine run_c_api_tests

    !> A NUL-terminated copy of `text` (static, so that c_loc is valid).
    function c_string(text) result(chars)
        character(len=*), intent(in) :: text
        character(kind=c_char), allocatable :: chars(:)
        integer :: k
        allocate (chars(len(text) + 1))
        do k = 1, len(text)
            chars(k) = text(k:k)
        end do
        chars(len(text) + 1) = c_null_char
    end function c_string

    !> The message of a status, as a Fortran string.
    function message_of(status) result(text)
        integer(c_int), intent(in) :: status
        character(len=:), allocatable :: text
        character(kind=c_char), pointer :: chars(:)
        integer :: k
        call c_f_pointer(brachistochrone_status_message(status), chars, [201])
        text = ''
        do k = 1, 200
            if (chars(k) == c_null_char) exit
            text = text//chars(k)
        end do
    end function message_of

    subroutine check_single()
        character(kind=c_char), allocatable, target :: force(:)
        real(c_double), target :: r, s, t
        integer(c_int) :: status
        logical :: ok
        integer :: i
        force = c_string('inverse_square')
        ok = .true.
        do i = 1, 5
            status = brachistochrone_solve(c_loc(force), 0.0_c_double, table_rho(i), &
                                           table_psi(i), c_loc(r), c_loc(s), c_loc(t))
            ok = ok .and. status == status_ok .and. abs(r - table_r(i)) <= 1e-15_c_double &
                 .and. abs(t - table_t(i)) <= 1e-15_c_double
        end do
        call check(ok, 'brachistochrone_solve: Table 1 R-bar and t to the published digits')
        force = c_string('power')
        status = brachistochrone_solve(c_loc(force), 2.0_c_double, table_rho(4), &
                                       table_psi(4), c_loc(r), c_null_ptr, c_loc(t))
        call check(status == status_ok .and. abs(r - table_r(4)) <= 1e-15_c_double .and. &
                   abs(t - table_t(4)) <= 1e-15_c_double, &
                   'power with exponent 2 (general engine) gives Table 1 row 4; NULL s')
        status = brachistochrone_solve(c_loc(force), 1.0_c_double, 0.5_c_double, &
                                       1.0_c_double, c_loc(r), c_loc(s), c_loc(t))
        call check(status == status_bad_exponent .and. ieee_is_nan(r) .and. ieee_is_nan(t), &
                   'power with exponent 1: status bad_exponent, NaN outputs')
        force = c_string('gravity')
        status = brachistochrone_solve(c_loc(force), 0.0_c_double, 0.5_c_double, &
                                       1.0_c_double, c_loc(r), c_loc(s), c_loc(t))
        call check(status == status_unknown_field .and. ieee_is_nan(s), &
                   'unknown force: status unknown_field, NaN outputs')
        status = brachistochrone_solve(c_null_ptr, 0.0_c_double, 0.5_c_double, &
                                       1.0_c_double, c_loc(r), c_loc(s), c_loc(t))
        call check(status == status_unknown_field, 'NULL force name: unknown_field')
        call check(message_of(0_c_int) == 'solved' .and. &
                   message_of(-3_c_int) == 'unknown status' .and. &
                   index(message_of(int(status_unknown_field, c_int)), 'inverse_square') > 0, &
                   'brachistochrone_status_message: solved, unknown status, the force names')
        call check(brachistochrone_arithmetic_ok() == 1_c_int, &
                   'brachistochrone_arithmetic_ok: 1 at the x87 defaults')
    end subroutine check_single

    !> Harmonic field, surface to surface at angle pi/3: R_m = 1 - 1/3, t = pi sqrt(1 - R_m^2)
    !! (Saitoh 10), in quad precision through __float128.
    subroutine check_quad()
        character(kind=c_char), allocatable, target :: force(:)
        real(c_float128), target :: r, s, t
        integer(c_int) :: status
        force = c_string('harmonic')
        status = brachistochrone_solve_q(c_loc(force), 0.0_qp, 1.0_qp, pi/3.0_qp, c_loc(r), &
                                         c_loc(s), c_loc(t))
        call check(status == status_ok, 'brachistochrone_solve_q harmonic: solved')
        call check_digits(r, 2.0_qp/3.0_qp, 32.0_qp, 'solve_q harmonic R_m = 2/3')
        call check_digits(t, pi*sqrt(5.0_qp)/3.0_qp, 32.0_qp, &
                          'solve_q harmonic t = pi sqrt(1 - R_m^2) (Saitoh 10)')
        force = c_string('inverse_square')
        status = brachistochrone_solve_q(c_loc(force), 0.0_qp, 1.0_qp, 2.0_qp, c_loc(r), &
                                         c_loc(s), c_loc(t))
        call check(status == status_ok .and. abs(t - 2.221060707125763_qp) < 1e-15_qp, &
                   'solve_q inverse_square: Table 1 row 5')
    end subroutine check_quad

    !> R-bar NaN for radial fall; R-bar and s NaN, t = kappa when inaccessible.
    subroutine check_missing_values()
        character(kind=c_char), allocatable, target :: force(:)
        real(c_double), target :: r, s, t
        integer(c_int) :: status
        real(c_double) :: t0, t_rho
        force = c_string('inverse_square')
        status = brachistochrone_solve(c_loc(force), 0.0_c_double, 0.3_c_double, &
                                       0.0_c_double, c_loc(r), c_loc(s), c_loc(t))
        ! (46): t(r) = (acos(2r - 1)/2 + sqrt(r(1 - r)))/sqrt 2, in double here
        t_rho = (acos(-0.4_c_double)/2 + sqrt(0.21_c_double))/sqrt(2.0_c_double)
        call check(status == status_ok .and. ieee_is_nan(r) .and. &
                   abs(s - 0.7_c_double) < 1e-15_c_double .and. &
                   abs(t - t_rho) < 1e-15_c_double, 'radial fall: no R-bar (NaN), s, t (46)')
        status = brachistochrone_solve(c_loc(force), 0.0_c_double, 0.5_c_double, &
                                       2.5_c_double, c_loc(r), c_loc(s), c_loc(t))
        t0 = acos(-1.0_c_double)/sqrt(8.0_c_double)
        t_rho = (acos(0.0_c_double)/2 + 0.5_c_double)/sqrt(2.0_c_double)
        call check(status == status_inaccessible .and. ieee_is_nan(r) .and. ieee_is_nan(s) &
                   .and. abs(t - (2*t0 - t_rho)) < 1e-15_c_double, &
                   'inaccessible: R-bar and s NaN, t = kappa = 2 t(0) - t(rho) (75)')
        status = brachistochrone_solve(c_loc(force), 0.0_c_double, 1.5_c_double, &
                                       1.0_c_double, c_loc(r), c_loc(s), c_loc(t))
        call check(status == status_rho_out_of_range .and. ieee_is_nan(r) .and. &
                   ieee_is_nan(s) .and. ieee_is_nan(t), 'rho > 1: status, all NaN')
    end subroutine check_missing_values

    subroutine check_many()
        character(kind=c_char), allocatable, target :: force(:)
        real(c_double), target :: rho(6), psi(6), r(6), s(6), t(6)
        integer(c_int), target :: status(6)
        integer(c_int) :: failures
        force = c_string('inverse_square')
        rho = [table_rho, 0.5_c_double]
        psi = [table_psi, 2.5_c_double]
        failures = brachistochrone_solve_many(c_loc(force), 0.0_c_double, 6_c_long, c_loc(rho), &
                                              c_loc(psi), c_loc(r), c_loc(s), c_loc(t), &
                                              c_loc(status))
        call check(failures == 1 .and. all(status(1:5) == status_ok) .and. &
                   status(6) == status_inaccessible, 'solve_many: one failure of six')
        call check(all(abs(r(1:5) - table_r) <= 1e-15_c_double) .and. &
                   all(abs(t(1:5) - table_t) <= 1e-15_c_double) .and. ieee_is_nan(r(6)), &
                   'solve_many: Table 1 to the published digits, NaN where inaccessible')
        failures = brachistochrone_solve_many(c_loc(force), 0.0_c_double, 6_c_long, c_loc(rho), &
                                              c_loc(psi), c_null_ptr, c_null_ptr, c_loc(t), &
                                              c_null_ptr)
        call check(failures == 1, 'solve_many: NULL output arrays')
        failures = brachistochrone_solve_many(c_loc(force), 0.0_c_double, -1_c_long, &
                                              c_loc(rho), c_loc(psi), c_null_ptr, c_null_ptr, &
                                              c_null_ptr, c_null_ptr)
        call check(failures == -1, 'solve_many: n < 0 gives -1')
        force = c_string('no_such_field')
        failures = brachistochrone_solve_many(c_loc(force), 0.0_c_double, 6_c_long, c_loc(rho), &
                                              c_loc(psi), c_loc(r), c_loc(s), c_loc(t), &
                                              c_loc(status))
        call check(failures == 6 .and. all(status == status_unknown_field) .and. &
                   all(ieee_is_nan(t)), 'solve_many: unknown force on every row')
    end subroutine check_many

    !> Fields are kept between calls, keyed by name and exponent, up to 16; more distinct
    !! ones are built per call. 20 power laws with n = 2 + k 2^-40 (each a different
    !! field, all within 2e-11 of the inverse-square law) give Table 1 row 4 to 1e-9, the
    !! kept ones again afterwards; 'power' with n = 3 after n = 2 is not served n = 2's.
    subroutine check_kept_fields()
        character(kind=c_char), allocatable, target :: force(:)
        real(c_double), target :: r, t, r3
        integer(c_int) :: status
        logical :: ok
        integer :: k, pass
        real(c_double), parameter :: step = 2.0_c_double**(-40)
        force = c_string('power')
        ok = .true.
        do pass = 1, 2
            do k = 0, 19
                status = brachistochrone_solve(c_loc(force), 2.0_c_double + k*step, &
                                               table_rho(4), table_psi(4), c_loc(r), &
                                               c_null_ptr, c_loc(t))
                ok = ok .and. status == status_ok .and. &
                     abs(r - table_r(4)) <= 1e-9_c_double .and. &
                     abs(t - table_t(4)) <= 1e-9_c_double
            end do
        end do
        call check(ok, 'C interface: 20 distinct power laws twice (16 kept, 4 built per call)')
        status = brachistochrone_solve(c_loc(force), 3.0_c_double, table_rho(4), &
                                       table_psi(4), c_loc(r3), c_null_ptr, c_null_ptr)
        call check(status == status_ok .and. abs(r3 - table_r(4)) > 1e-3_c_double, &
                   'C interface: power n = 3 after n = 2 is another field')
    end subroutine check_kept_fields

    !> Four OpenMP threads call brachistochrone_solve at once, each on all of Table 1; run
    !! first, so the threads also race to build the shared inverse-square model.
    subroutine check_threads()
        character(kind=c_char), allocatable, target :: force(:)
        real(c_double), target :: r, s, t
        integer(c_int) :: status
        integer :: wrong, i, k
        force = c_string('inverse_square')
        wrong = 0
        !$omp parallel do num_threads(4) schedule(static, 1) default(shared) &
        !$omp private(i, k, r, s, t, status) reduction(+:wrong)
        do k = 1, 8
            do i = 1, 5
                status = brachistochrone_solve(c_loc(force), 0.0_c_double, table_rho(i), &
                                               table_psi(i), c_loc(r), c_loc(s), c_loc(t))
                if (status /= status_ok .or. abs(r - table_r(i)) > 1e-15_c_double .or. &
                    abs(t - table_t(i)) > 1e-15_c_double) wrong = wrong + 1
            end do
        end do
        !$omp end parallel do
        call check(wrong == 0, 'Table 1 from 4 threads at once (first use of the model)')
    end subroutine check_threads

end module test_c_api
