!> Uses the library (`use brachistochrone`) next to the user's own quadrature, roots and
!! strings modules. Checks against independent values: Tee's Table 1 as published (row 4,
!! 15 digits), the closed form of radial fall (46) against the user's midpoint rule, and
!! the library's cube root. Prints one line per check and "fpm_user: ok", or stops 1.
program fpm_user
    use brachistochrone, only: qp, inverse_square_model, new_inverse_square_model, &
                               endpoint_solution, solve_endpoint, radial_time, status_ok
    use brachistochrone_version, only: program_version
    use quadrature, only: midpoint_rule
    use roots, only: bisect_cube_root
    use strings, only: shout
    implicit none
    type(inverse_square_model) :: model
    type(endpoint_solution) :: b
    logical :: ok

    model = new_inverse_square_model()
    b = solve_endpoint(model, 0.9_qp, 0.4_qp)
    ! Tee (1998), Table 1, row 4: R-bar, s, t to the 15 printed digits
    ok = b%status == status_ok .and. abs(b%apse_radius - 0.838545794202334_qp) < 1e-15_qp &
         .and. abs(b%arclength - 0.442680075643429_qp) < 1e-15_qp &
         .and. abs(b%time - 1.058599268341289_qp) < 1e-15_qp
    write (*, '(a,l1)') 'Table 1 row 4 (published digits): ', ok
    ! radial fall: the library's closed form (46) against the user's midpoint rule
    ok = ok .and. abs(radial_time(0.25_qp) - midpoint_rule(0.25_qp, 20000)) < 1e-8_qp
    write (*, '(a,l1)') 'radial fall (46) against the user''s quadrature: ', ok
    ok = ok .and. abs(bisect_cube_root(27.0_qp) - 3.0_qp) < 1e-30_qp
    write (*, '(a)') 'library version '//program_version
    if (.not. ok) then
        write (*, '(a)') shout('fpm_user: failed')
        stop 1
    end if
    write (*, '(a)') 'fpm_user: ok'
end program fpm_user
