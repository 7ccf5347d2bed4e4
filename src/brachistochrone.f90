!> The public face of the library: `use brachistochrone` gives a user everything.
!!
!! ```fortran
!! use brachistochrone
!! type(inverse_square_model) :: model
!! type(endpoint_solution) :: b
!! type(curve_samples) :: c
!! model = new_inverse_square_model()
!! b = solve_endpoint(model, 0.2_qp, 1.2_qp)   ! R-bar, s, t in b%apse_radius, ...
!! c = sample_endpoint_curve(model, b, 201)     ! c%r(k), c%theta(k), ... from A to B
!! ```
module brachistochrone
    use brachistochrone_kinds, only: qp, pi, eps_qp
    use brachistochrone_status, only: status_ok, status_inaccessible, &
                                      status_rho_out_of_range, status_psi_out_of_range, &
                                      status_not_finite, status_no_convergence, &
                                      status_outside_domain, status_invalid_argument, &
                                      status_bad_estimates, status_word, status_message
    use brachistochrone_closed_forms, only: fall_to_centre_time, apse_angle_limit, &
            inaccessible_angle, radial_fall_time, kappa_bound, radial_time, kappa_time
    use brachistochrone_inverse_square, only: inverse_square_model, new_inverse_square_model
    use brachistochrone_two_point, only: endpoint_solution, solve_endpoint, solve_endpoint_secant, &
                         arch_none, arch_first, arch_second, arch_complete, arch_radial, &
                         arch_inaccessible, arch_word
    use brachistochrone_uniform_gravity, only: uniform_brachistochrone, cycloid_point, &
            isochrone_time, isochrone_time_quadrature, joined_arches_period, &
            joined_arches_period_quadrature, complete_elliptic_k, pendulum_period, &
            pendulum_period_quadrature
    use brachistochrone_curve, only: curve_samples, sample_endpoint_curve, sample_complete_arch, &
                     apsidal_locus, min_curve_points
    use brachistochrone_speed_laws, only: speed_law, inverse_square_law, power_law, &
            logarithmic_law, harmonic_law
    use brachistochrone_central_force, only: central_force_model, new_central_force_model
    use brachistochrone_harmonic, only: harmonic_planet, harmonic_tunnel, planet_tunnel, &
                                        hypocycloid_point, hypocycloid_at, surface_to_surface, &
                                        solve_harmonic_endpoint, tautochrone_time, plan_tunnel, &
                                        great_circle_angle
    implicit none
    private

    public :: qp, pi, eps_qp
    public :: status_ok, status_inaccessible, status_rho_out_of_range, &
              status_psi_out_of_range, status_not_finite, status_no_convergence, &
              status_outside_domain, status_invalid_argument, status_bad_estimates, &
              status_word, status_message
    public :: fall_to_centre_time, apse_angle_limit, inaccessible_angle, &
              radial_fall_time, kappa_bound, radial_time, kappa_time
    public :: inverse_square_model, new_inverse_square_model
    public :: endpoint_solution, solve_endpoint, solve_endpoint_secant
    public :: arch_none, arch_first, arch_second, arch_complete, arch_radial, &
              arch_inaccessible, arch_word
    public :: speed_law, inverse_square_law, power_law, logarithmic_law, harmonic_law
    public :: central_force_model, new_central_force_model
    public :: harmonic_planet, harmonic_tunnel, planet_tunnel, hypocycloid_point, &
              hypocycloid_at, surface_to_surface, solve_harmonic_endpoint, tautochrone_time, &
              plan_tunnel, great_circle_angle
    public :: uniform_brachistochrone, cycloid_point, isochrone_time, &
              isochrone_time_quadrature, joined_arches_period, joined_arches_period_quadrature, &
              complete_elliptic_k, pendulum_period, pendulum_period_quadrature
    public :: curve_samples, sample_endpoint_curve, sample_complete_arch, apsidal_locus, &
              min_curve_points

end module brachistochrone
