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
    use closed_forms, only: fall_to_centre_time, apse_angle_limit, inaccessible_angle, &
                            radial_fall_time, kappa_bound, radial_time, kappa_time
    use inverse_square, only: inverse_square_model, new_inverse_square_model
    use two_point, only: endpoint_solution, solve_endpoint, solve_endpoint_secant, &
                         arch_none, arch_first, arch_second, arch_complete, arch_radial, &
                         arch_inaccessible, arch_word
    use curve, only: curve_samples, sample_endpoint_curve, sample_complete_arch, &
                     apsidal_locus, min_curve_points
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
    public :: curve_samples, sample_endpoint_curve, sample_complete_arch, apsidal_locus, &
              min_curve_points

end module brachistochrone
