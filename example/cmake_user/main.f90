!> Links brachistochrone::brachistochrone from find_package. Checks Tee's Table 1 as
!! published (row 5, the complete brachistochrone rho = 1, psi = 2; 15 digits) and the
!! harmonic field against Saitoh's closed form (10): surface to surface at angle pi/3,
!! R_m = 1 - 1/3, t = pi sqrt(1 - R_m^2). Prints "cmake_user: ok", or stops 1.
program cmake_user
    use brachistochrone, only: qp, pi, inverse_square_model, new_inverse_square_model, &
                               endpoint_solution, solve_endpoint, central_force_model, &
                               new_central_force_model, harmonic_law, status_ok
    implicit none
    type(inverse_square_model) :: model
    type(central_force_model) :: planet
    type(endpoint_solution) :: b, h
    real(qp), parameter :: r_m = 2.0_qp/3.0_qp
    logical :: ok

    model = new_inverse_square_model()
    b = solve_endpoint(model, 1.0_qp, 2.0_qp)
    ok = b%status == status_ok .and. abs(b%apse_radius - 0.057854464393370_qp) < 1e-15_qp &
         .and. abs(b%arclength - 1.947547388961997_qp) < 1e-15_qp &
         .and. abs(b%time - 2.221060707125763_qp) < 1e-15_qp
    write (*, '(a,l1)') 'Table 1 row 5 (published digits): ', ok
    planet = new_central_force_model(harmonic_law())
    h = planet%solve(1.0_qp, pi/3.0_qp)
    ok = ok .and. h%status == status_ok .and. abs(h%apse_radius - r_m) < 1e-30_qp .and. &
         abs(h%time - pi*sqrt(1.0_qp - r_m**2)) < 1e-30_qp
    write (*, '(a,l1)') 'harmonic tunnel against Saitoh (10), 30 digits: ', ok
    if (.not. ok) stop 1
    write (*, '(a)') 'cmake_user: ok'
end program cmake_user
