!> The public face of the library: `use brachistochrone` gives a user every user-facing
!! entity (every field, the result types, every status and arch code a public routine
!! can return) and no internal kernel.
!!
!! ```fortran
!! use brachistochrone
!! class(brachistochrone_field), allocatable :: field
!! type(endpoint_solution) :: b
!! integer :: status
!! call new_field('inverse_square', 0.0_qp, field, status)   ! or 'power', 3.0_qp ...
!! b = field%solve(0.5_qp, 1.2_qp)   ! b%apse_radius, b%arclength, b%time, b%status
!! ```
!!
!! The names of the fields' own APIs keep working: `new_inverse_square_model`,
!! `solve_endpoint`, `solve_endpoint_secant`, `sample_endpoint_curve`,
!! `new_central_force_model`, `solve_repulsive`, `solve_harmonic_endpoint`, ...
module brachistochrone
    use brachistochrone_kinds, only: qp, pi, eps_qp
    use brachistochrone_status, only: status_ok, status_inaccessible, &
            status_rho_out_of_range, status_psi_out_of_range, status_not_finite, &
            status_no_convergence, status_outside_domain, status_invalid_argument, &
            status_bad_estimates, status_latitude_out_of_range, status_bad_planet, &
            status_above_start, status_parameter_out_of_range, status_rho_below_start, &
            status_unknown_field, status_bad_exponent, status_not_supported, &
            status_word, status_message
    use brachistochrone_arches, only: arch_none, arch_first, arch_second, arch_complete, &
            arch_radial, arch_inaccessible, arch_unbounded, arch_word
    use brachistochrone_solution, only: endpoint_solution
    use brachistochrone_closed_forms, only: fall_to_centre_time, apse_angle_limit, &
            inaccessible_angle, radial_fall_time, kappa_bound, radial_time, kappa_time
    use brachistochrone_field_interface, only: brachistochrone_field
    use brachistochrone_fields, only: new_field, field_names
    use brachistochrone_inverse_square_field, only: inverse_square_field, &
            new_inverse_square_field
    use brachistochrone_central_force_field, only: central_force_field, new_power_field, &
            new_logarithmic_field
    use brachistochrone_harmonic_field, only: harmonic_field
    use brachistochrone_repulsive_field, only: repulsive_field, new_repulsive_field, &
            least_time_repulsive
    use brachistochrone_uniform_field, only: uniform_field
    use brachistochrone_inverse_square, only: inverse_square_model, new_inverse_square_model
    use brachistochrone_two_point, only: solve_endpoint, solve_endpoint_secant
    use brachistochrone_curve, only: curve_samples, sample_endpoint_curve, &
            sample_complete_arch, apsidal_locus, min_curve_points
    use brachistochrone_speed_laws, only: speed_law, inverse_square_law, power_law, &
            logarithmic_law, harmonic_law
    use brachistochrone_central_force, only: central_force_model, new_central_force_model
    use brachistochrone_harmonic, only: earth_radius_km, earth_gravity, harmonic_planet, &
            harmonic_tunnel, planet_tunnel, hypocycloid_point, hypocycloid_at, &
            surface_to_surface, solve_harmonic_endpoint, tautochrone_time, plan_tunnel, &
            great_circle_angle
    use brachistochrone_repulsive, only: repulsive_curve, repulsive_solution, &
            curve_from_k2, curve_from_gap, curve_from_apse, curve_from_apse_gap, &
            repulsive_values, critical_values, repulsive_radial_time, solve_repulsive, &
            critical_k2, panel_rules, new_panel_rules
    use brachistochrone_uniform_gravity, only: uniform_brachistochrone, cycloid_point, &
            isochrone_time, isochrone_time_quadrature, joined_arches_period, &
            joined_arches_period_quadrature, complete_elliptic_k, pendulum_period, &
            pendulum_period_quadrature
    use brachistochrone_fast_math, only: hardware_arithmetic_ok
    implicit none
    private

    ! kinds and constants
    public :: qp, pi, eps_qp
    ! status codes (one set for the library) and arch codes
    public :: status_ok, status_inaccessible, status_rho_out_of_range, &
              status_psi_out_of_range, status_not_finite, status_no_convergence, &
              status_outside_domain, status_invalid_argument, status_bad_estimates, &
              status_latitude_out_of_range, status_bad_planet, status_above_start, &
              status_parameter_out_of_range, status_rho_below_start, &
              status_unknown_field, status_bad_exponent, status_not_supported, &
              status_word, status_message
    public :: arch_none, arch_first, arch_second, arch_complete, arch_radial, &
              arch_inaccessible, arch_unbounded, arch_word
    ! the field interface and the result type
    public :: brachistochrone_field, new_field, field_names, endpoint_solution
    public :: inverse_square_field, new_inverse_square_field, central_force_field, &
              new_power_field, new_logarithmic_field, harmonic_field, repulsive_field, &
              new_repulsive_field, least_time_repulsive, uniform_field
    ! closed forms
    public :: fall_to_centre_time, apse_angle_limit, inaccessible_angle, &
              radial_fall_time, kappa_bound, radial_time, kappa_time
    ! inverse-square fast path
    public :: inverse_square_model, new_inverse_square_model, solve_endpoint, &
              solve_endpoint_secant
    public :: curve_samples, sample_endpoint_curve, sample_complete_arch, apsidal_locus, &
              min_curve_points
    ! general engine
    public :: speed_law, inverse_square_law, power_law, logarithmic_law, harmonic_law
    public :: central_force_model, new_central_force_model
    ! harmonic (Saitoh)
    public :: earth_radius_km, earth_gravity, harmonic_planet, harmonic_tunnel, &
              planet_tunnel, hypocycloid_point, hypocycloid_at, surface_to_surface, &
              solve_harmonic_endpoint, tautochrone_time, plan_tunnel, great_circle_angle
    ! repulsive (Tee sec. 6)
    public :: repulsive_curve, repulsive_solution, curve_from_k2, curve_from_gap, &
              curve_from_apse, curve_from_apse_gap, repulsive_values, critical_values, &
              repulsive_radial_time, solve_repulsive, critical_k2, panel_rules, new_panel_rules
    ! uniform gravity (Tee sec. 1)
    public :: uniform_brachistochrone, cycloid_point, isochrone_time, &
              isochrone_time_quadrature, joined_arches_period, joined_arches_period_quadrature, &
              complete_elliptic_k, pendulum_period, pendulum_period_quadrature
    ! the machine's arithmetic as the library assumes it (x87 at 64 bits, to nearest)
    public :: hardware_arithmetic_ok

end module brachistochrone
