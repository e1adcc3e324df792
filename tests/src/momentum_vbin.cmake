# compute momentum/vbin: the in-process test and bad input (decks on 1 and 2 ranks); its
# example deck: tests/inputs. Included from tests/src/CMakeLists.txt (after error_tests.cmake,
# which defines granpen_error_test).
add_executable(test_momentum_vbin test_momentum_vbin.cpp)
target_link_libraries(test_momentum_vbin PRIVATE granpen_styles granpen_analysis granpen_test_main GTest::gtest)
granpen_mpi_test(momentum_vbin LABEL lammps COMMAND $<TARGET_FILE:test_momentum_vbin>)

# ---- errors, each naming the keyword
set(MVBIN "compute m grains momentum/vbin")
granpen_error_test(mvbin_v0_missing "Illegal compute momentum/vbin command: missing v0" "${MVBIN}")
granpen_error_test(mvbin_v0_zero "Compute momentum/vbin v0 must be > 0, got 0" "${MVBIN} 0 axis 4 4 rmin 1")
granpen_error_test(mvbin_v0_negative "Compute momentum/vbin v0 must be > 0, got -5" "${MVBIN} -5 axis 4 4 rmin 1")
granpen_error_test(mvbin_v0_not_a_number "Expected floating point parameter instead of 'axis'" "${MVBIN} axis 4 4 rmin 1")
granpen_error_test(mvbin_unknown_keyword "Unknown compute momentum/vbin keyword: bins" "${MVBIN} 100 axis 4 4 rmin 1 bins 4")
granpen_error_test(mvbin_keyword_missing_value "Illegal compute momentum/vbin thresholds command: missing argument"
  "${MVBIN} 100 axis 4 4 rmin 1 thresholds 0.1 0.01")
granpen_error_test(mvbin_thresholds_not_decreasing
  "Compute momentum/vbin thresholds must be > 0 and strictly decreasing, got 0.1 0.2 0.01 0.001"
  "${MVBIN} 100 axis 4 4 rmin 1 thresholds 0.1 0.2 0.01 0.001")
granpen_error_test(mvbin_thresholds_equal
  "Compute momentum/vbin thresholds must be > 0 and strictly decreasing, got 0.1 0.01 0.01 0.001"
  "${MVBIN} 100 axis 4 4 rmin 1 thresholds 0.1 0.01 0.01 0.001")
granpen_error_test(mvbin_thresholds_zero
  "Compute momentum/vbin thresholds must be > 0 and strictly decreasing, got 0.1 0.01 0.001 0"
  "${MVBIN} 100 axis 4 4 rmin 1 thresholds 0.1 0.01 0.001 0")
granpen_error_test(mvbin_logbins_n_zero "Compute momentum/vbin logbins N must be >= 1, got 0"
  "${MVBIN} 100 axis 4 4 rmin 1 logbins 0 0.001 0.1")
granpen_error_test(mvbin_logbins_n_huge "Compute momentum/vbin logbins N must be <= 10000, got 2000000000"
  "${MVBIN} 100 axis 4 4 rmin 1 logbins 2000000000 0.001 0.1")
granpen_error_test(mvbin_logbins_range "Compute momentum/vbin logbins needs 0 < fmin < fmax, got 0.1 0.01"
  "${MVBIN} 100 axis 4 4 rmin 1 logbins 4 0.1 0.01")
granpen_error_test(mvbin_logbins_equal "Compute momentum/vbin logbins needs 0 < fmin < fmax, got 0.1 0.1"
  "${MVBIN} 100 axis 4 4 rmin 1 logbins 4 0.1 0.1")
granpen_error_test(mvbin_logbins_fmin_zero "Compute momentum/vbin logbins needs 0 < fmin < fmax, got 0 0.1"
  "${MVBIN} 100 axis 4 4 rmin 1 logbins 4 0 0.1")
granpen_error_test(mvbin_thresholds_and_logbins "Compute momentum/vbin takes thresholds or logbins, not both"
  "${MVBIN} 100 axis 4 4 rmin 1 thresholds 0.1 0.01 0.001 0.0001 logbins 4 0.001 0.1")
granpen_error_test(mvbin_mthreshold_zero "Compute momentum/vbin mthreshold must be > 0, got 0"
  "${MVBIN} 100 axis 4 4 rmin 1 logbins 4 0.001 0.1 mthreshold 0")
granpen_error_test(mvbin_mu_negative "Compute momentum/vbin mu must be >= 0, got -0.3" "${MVBIN} 100 axis 4 4 rmin 1 mu -0.3")
granpen_error_test(mvbin_g_zero "Compute momentum/vbin g must be > 0, got 0" "${MVBIN} 100 axis 4 4 rmin 1 g 0")
granpen_error_test(mvbin_drive_missing "Compute momentum/vbin drive fix nope does not exist"
  "${MVBIN} 100 drive nope" "run 0")
granpen_error_test(mvbin_drive_wrong_style "Compute momentum/vbin drive fix grav is gravity, not rod/drive"
  "fix grav grains gravity 981 vector 0 0 -1" "${MVBIN} 100 drive grav" "run 0")
granpen_error_test(mvbin_region_missing "Compute momentum/vbin region nope does not exist" "${MVBIN} 100 region nope")
granpen_error_test(mvbin_needs_selection
  "Compute momentum/vbin needs drive FIXID, axis X Y with rmin R, or region ID" "${MVBIN} 100")
granpen_error_test(mvbin_needs_selection_mu_only
  "Compute momentum/vbin needs drive FIXID, axis X Y with rmin R, or region ID" "${MVBIN} 100 mu 0.3 g 981")
granpen_error_test(mvbin_axis_needs_rmin "Compute momentum/vbin axis needs rmin R \\(or drive FIXID for the rod radius\\)"
  "${MVBIN} 100 axis 4 4")
granpen_error_test(mvbin_rmin_needs_axis "Compute momentum/vbin rmin needs axis X Y \\(or drive FIXID for the rod axis\\)"
  "${MVBIN} 100 rmin 1")
granpen_error_test(mvbin_rmin_negative "Compute momentum/vbin rmin must be >= 0, got -1" "${MVBIN} 100 axis 4 4 rmin -1")
granpen_error_test(mvbin_needs_g "Compute momentum/vbin needs g: define fix gravity or give the g keyword"
  "${MVBIN} 100 axis 4 4 rmin 1" "run 0")
granpen_error_test(mvbin_drive_needs_g "Compute momentum/vbin needs g: define fix gravity or give the g keyword"
  "fix push rod rod/drive 100 surface 2.0" "${MVBIN} 100 drive push" "thermo_style custom step c_m" "run 0")
