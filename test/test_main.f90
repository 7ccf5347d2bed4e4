!> Test driver: runs every test group and ends with `N passed, N failed`.
program test_main
    use testing, only: summary
    use test_numerics, only: run_numerics_tests
    use test_physics, only: run_physics_tests
    use test_io, only: run_io_tests
    use test_namelist, only: run_namelist_tests
    use test_format, only: run_format_tests
    use test_hardware_level, only: run_hardware_level_tests
    use test_fast_math, only: run_fast_math_tests
    use test_hardware_terms, only: run_hardware_terms_tests
    use test_slope_bounds, only: run_slope_bounds_tests
    use test_central_force, only: run_central_force_tests
    use test_sector_edge, only: run_sector_edge_tests
    use test_curves, only: run_curve_tests
    use test_harmonic, only: run_harmonic_tests
    use test_uniform_gravity, only: run_uniform_gravity_tests
    use test_repulsive, only: run_repulsive_tests
    use test_field_references, only: run_field_reference_tests
    use test_fields, only: run_field_tests
    use test_sha256, only: run_sha256_tests
    use test_c_api, only: run_c_api_tests
    use test_result_stream, only: run_result_stream_tests
    use test_fast_log, only: run_fast_log_tests
    implicit none
    integer :: code
    call run_numerics_tests()
    call run_io_tests()
    call run_namelist_tests()
    call run_format_tests()
    call run_hardware_level_tests()
    call run_fast_math_tests()
    call run_hardware_terms_tests()
    call run_slope_bounds_tests()
    call run_physics_tests()
    call run_central_force_tests()
    call run_sector_edge_tests()
    call run_curve_tests()
    call run_harmonic_tests()
    call run_uniform_gravity_tests()
    call run_repulsive_tests()
    call run_field_reference_tests()
    call run_field_tests()
    call run_sha256_tests()
    call run_c_api_tests()
    call run_result_stream_tests()
    call run_fast_log_tests()
    code = summary()
    if (code /= 0) error stop 1
end program test_main
