# granpen fit, calibration, collapse and convert end to end on synthetic inputs written at
# configure time (their kernels: tests/analysis/core). Included from CMakeLists.txt.

# A synthetic cgs trace: z = -0.5 .. 5 cm at 0.01 cm (t = 1e-4 s steps, v0 = 100 cm/s),
# F = K z plus a zero-mean pattern orthogonal to z over the window, so the fitted
# k_z is K. Written with integers only: z = ZI/100 cm, F = K/100 * ZI dyne.
function(granpen_synthetic_trace path kz_per_100 extra_header with_pattern)
  set(text "# granpen-trace v1\n# units = cgs\n# v0 = 100\n# D = 2\n# g = 981\n# d_g = 0.4\n# rho_g = 3\n${extra_header}t,z,F\n")
  foreach(i RANGE 0 550)
    math(EXPR zi "${i} - 50")
    if(zi GREATER 0)
      if(with_pattern)
        math(EXPR f "${kz_per_100} * ${zi} + 37 * ((${i} * 7) % 5 - 2)")
      else()
        math(EXPR f "${kz_per_100} * ${zi}")
      endif()
    else()
      set(f 0)
    endif()
    string(APPEND text "${i}e-4,${zi}e-2,${f}\n")
  endforeach()
  file(WRITE ${path} "${text}")
endfunction()

# fit: k_z = 25300 dyne/cm over the default window z >= 3 cm
set(GRANPEN_FIT_DIR ${CMAKE_CURRENT_BINARY_DIR}/fit_cli)
granpen_synthetic_trace(${GRANPEN_FIT_DIR}/kz25300.csv 253 "# mu = 0.3\n" ON)
add_test(NAME cli_fit_synthetic COMMAND granpen-cli fit ${GRANPEN_FIT_DIR}/kz25300.csv
  --json ${GRANPEN_FIT_DIR}/fit.json --csv ${GRANPEN_FIT_DIR}/fit.csv)
set_tests_properties(cli_fit_synthetic PROPERTIES LABELS "unit;cli"
  PASS_REGULAR_EXPRESSION "kz25300\\.csv: v0 = 100 cm/s, k_z = 2\\.5[0-9]*e\\+04 \\+- ")
# a bad trace is reported with file:line and the good one is still fitted
file(WRITE ${GRANPEN_FIT_DIR}/bad/broken.csv
  "# granpen-trace v1\n# units = cgs\n# v0 = 100\n# D = 2\n# g = 981\nt,z,F\n0,0,0\n0.0001,0.01\n")
add_test(NAME cli_fit_bad_and_good COMMAND granpen-cli fit ${GRANPEN_FIT_DIR}/bad ${GRANPEN_FIT_DIR}/kz25300.csv)
set_tests_properties(cli_fit_bad_and_good PROPERTIES LABELS "unit;cli"
  PASS_REGULAR_EXPRESSION "(broken\\.csv:8: row has 2 fields, expected 3.*kz25300\\.csv: v0 = 100 cm/s, k_z = 2\\.5[0-9]*e\\+04|kz25300\\.csv: v0 = 100 cm/s, k_z = 2\\.5[0-9]*e\\+04.*broken\\.csv:8: row has 2 fields, expected 3)")

# calibration: two beds at mu = 0.3 (phi_0 0.58, 0.60), pushes with k_z = 20000 and
# 22000 dyne/cm: phi_0 0.5900 +- 0.0141, k_z 2.1e+04 +- 1.4e+03, alpha = k_z /
# (0.3 * 3 * 981 * 4) = 5.95 +- 0.4
set(GRANPEN_CAL_DIR ${CMAKE_CURRENT_BINARY_DIR}/calibration_cli/sweep)
file(WRITE ${GRANPEN_CAL_DIR}/beds/bed_a.info
  "# granpen bed: preset bench, seed 1, mu 0.3\npreset = bench\nseed = 1\nmu = 0.3\ngrains = 6300\nz_s = 5.7\nphi_0 = 0.58\nwall_seconds = 300\nsteps = 100000\n")
file(WRITE ${GRANPEN_CAL_DIR}/beds/bed_b.info
  "# granpen bed: preset bench, seed 2, mu 0.3\npreset = bench\nseed = 2\nmu = 0.3\ngrains = 6300\nz_s = 5.6\nphi_0 = 0.60\nwall_seconds = 300\nsteps = 100000\n")
granpen_synthetic_trace(${GRANPEN_CAL_DIR}/traces/push_a.csv 200 "# mu = 0.3\n# seed = 1\n# bed = bed_a\n" OFF)
granpen_synthetic_trace(${GRANPEN_CAL_DIR}/traces/push_b.csv 220 "# mu = 0.3\n# seed = 2\n# bed = bed_b.restart\n" OFF)
add_test(NAME cli_calibration_synthetic COMMAND granpen-cli calibration ${GRANPEN_CAL_DIR}
  --out ${CMAKE_CURRENT_BINARY_DIR}/calibration_cli/out)
set_tests_properties(cli_calibration_synthetic PROPERTIES LABELS "unit;cli"
  PASS_REGULAR_EXPRESSION "\\| 0\\.3 \\| 2 \\| 0\\.5900 \\+- 0\\.0141 \\| 2 \\| 100 \\| 2\\.1e\\+04 \\+- 1\\.4e\\+03 \\| 5\\.95 \\+- 0\\.4 \\|")

# the collapse front end on the committed bench v0 sweep (6 traces, 3 speeds)
add_test(NAME cli_collapse_bench_sweep COMMAND granpen-cli collapse ${PROJECT_SOURCE_DIR}/data/sims/v0_bench
  --alpha 18.6 --json ${CMAKE_CURRENT_BINARY_DIR}/collapse.json)
set_tests_properties(cli_collapse_bench_sweep PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "granpen collapse: 6 traces.*collapse quality: spread.*peak law: peak ~ v0\\^[0-9.]+ \\+- [0-9.]+ \\(95%")

# granpen convert: fix ave/time output to a trace; bad input names the file and line, and
# leaves no output behind
set(AVE ${CMAKE_CURRENT_BINARY_DIR}/avetime)
file(MAKE_DIRECTORY ${AVE})
set(ave_text "# Time-averaged data for fix trace\n# TimeStep c_fz[1] c_fz[2]\n")
foreach(i RANGE 1 20)
  math(EXPR step "1000 + 50 * ${i}")
  math(EXPR f "7 * ${i}")
  string(APPEND ave_text "${step} ${f} -1\n")
endforeach()
file(WRITE ${AVE}/good.txt "${ave_text}")
string(REPLACE "1500 70 -1" "1500 nan -1" bad_text "${ave_text}")
file(WRITE ${AVE}/nan.txt "${bad_text}")
file(WRITE ${AVE}/vector.txt "# Time-averaged data for fix t\n# TimeStep Number-of-rows\n# Row c_x\n")
add_test(NAME convert_ave_time COMMAND sh -c "'$<TARGET_FILE:granpen-cli>' convert '${AVE}/good.txt' --v0 100 --dt 2e-6 --D 2 --g 981 --out '${AVE}/good.csv' && sed -n '8p;27p' '${AVE}/good.csv'")
# first row: step 1050, step0 = 1050 - 50 = 1000: t = 1e-4 s, z = -0.5 + 100 t = -0.49, F = 7
set_tests_properties(convert_ave_time PROPERTIES LABELS unit
  PASS_REGULAR_EXPRESSION "granpen convert: .*20 rows.*\n0.0001,-0.49,7\n0.002,-0.3,140")
add_test(NAME convert_ave_time_nan COMMAND sh -c "'$<TARGET_FILE:granpen-cli>' convert '${AVE}/nan.txt' --v0 100 --dt 2e-6 --D 2 --g 981 --out '${AVE}/nan.csv'; test ! -e '${AVE}/nan.csv' && test ! -e '${AVE}/nan.csv.tmp' && echo clean")
set_tests_properties(convert_ave_time_nan PROPERTIES LABELS unit PASS_REGULAR_EXPRESSION "nan.txt:12: column c_fz\\[1\\] value 'nan' is not.*clean")
add_test(NAME convert_ave_time_vector COMMAND $<TARGET_FILE:granpen-cli> convert ${AVE}/vector.txt --v0 100 --dt 2e-6 --D 2 --g 981 --out ${AVE}/v.csv)
set_tests_properties(convert_ave_time_vector PROPERTIES LABELS unit PASS_REGULAR_EXPRESSION "vector.txt:2: fix ave/time in vector mode")
add_test(NAME convert_ave_time_column COMMAND $<TARGET_FILE:granpen-cli> convert ${AVE}/good.txt --column c_x --v0 100 --dt 2e-6 --D 2 --g 981 --out ${AVE}/c.csv)
set_tests_properties(convert_ave_time_column PROPERTIES LABELS unit PASS_REGULAR_EXPRESSION "good.txt:2: no column 'c_x' \\(columns: c_fz\\[1\\] c_fz\\[2\\]\\)")

# the window by t~: z >= t~ v0 sqrt(D/g) per trace (v0 = 100, D = 2, g = 981: t~ = 0.5 -> z >= 2.258 cm)
add_test(NAME fit_cli_tmin COMMAND granpen-cli fit ${GRANPEN_FIT_DIR}/kz25300.csv --tmin 0.5)
set_tests_properties(fit_cli_tmin PROPERTIES LABELS unit PASS_REGULAR_EXPRESSION "window t~ >= 0.5.*z 2.26\\.\\.5 cm")
add_test(NAME fit_cli_tmin_and_zmin COMMAND granpen-cli fit ${GRANPEN_FIT_DIR}/kz25300.csv --tmin 0.5 --zmin 1)
set_tests_properties(fit_cli_tmin_and_zmin PROPERTIES LABELS unit PASS_REGULAR_EXPRESSION "give --zmin or --tmin, not both")

# issue 20: a trace without a positive depth term is named and left out, and the command
# still succeeds; only when nothing is left does it fail. A window beyond the data is
# shortened, said. --ensemble: the bench sweep's runs averaged per speed, +- over runs.
set(GRANPEN_LEFT_DIR ${CMAKE_CURRENT_BINARY_DIR}/collapse_left_out)
granpen_synthetic_trace(${GRANPEN_LEFT_DIR}/up_a.csv 253 "# mu = 0.3\n" ON)
granpen_synthetic_trace(${GRANPEN_LEFT_DIR}/up_b.csv 240 "# mu = 0.3\n" ON)
granpen_synthetic_trace(${GRANPEN_LEFT_DIR}/falling.csv -120 "# mu = 0.3\n" OFF)
add_test(NAME cli_collapse_leaves_out_unfittable COMMAND granpen-cli collapse ${GRANPEN_LEFT_DIR})
set_tests_properties(cli_collapse_leaves_out_unfittable PROPERTIES LABELS "unit;cli"
  PASS_REGULAR_EXPRESSION "note: [^\n]*falling\\.csv: no positive depth term[^\n]*left out.*granpen collapse: 2 traces \\(1 left out\\)")
add_test(NAME cli_collapse_nothing_left COMMAND granpen-cli collapse ${GRANPEN_LEFT_DIR}/falling.csv)
set_tests_properties(cli_collapse_nothing_left PROPERTIES LABELS "unit;cli" WILL_FAIL ON)
add_test(NAME cli_fit_window_beyond_the_data COMMAND granpen-cli fit ${GRANPEN_FIT_DIR}/kz25300.csv --zmin 10)
set_tests_properties(cli_fit_window_beyond_the_data PROPERTIES LABELS "unit;cli"
  PASS_REGULAR_EXPRESSION "k_z = 2\\.5[0-9]*e\\+04[^\n]*\n[^\n]*note: k_z window z >= 10 cm does not fit the data \\(deepest z = 5 cm\\): shortened to z = 2\\.5\\.\\.5 cm")
add_test(NAME cli_fit_ensemble_bench COMMAND granpen-cli fit ${PROJECT_SOURCE_DIR}/data/sims/v0_bench --zmin 1 --zmax 3
  --ensemble --json ${CMAKE_CURRENT_BINARY_DIR}/fit_ensemble.json)
set_tests_properties(cli_fit_ensemble_bench PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "ensemble v0 = 100 cm/s, g = 981 cm/s\\^2, D = 2 cm: 2 runs[^\n]*aligned[^\n]*\n(  note[^\n]*\n)*  mean: k_z = [-0-9.e+]+ \\+- [0-9.e+]+ dyne/cm")
# five beds per speed: the committed baseline and data/sims/v0_bench_ensemble
add_test(NAME cli_collapse_ensemble_bench COMMAND granpen-cli collapse ${PROJECT_SOURCE_DIR}/data/sims/v0_bench
  ${PROJECT_SOURCE_DIR}/data/sims/v0_bench_ensemble --alpha 18.6 --ensemble --json ${CMAKE_CURRENT_BINARY_DIR}/collapse_ensemble.json)
set_tests_properties(cli_collapse_ensemble_bench PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "granpen collapse --ensemble: 3 ensembles of 15 runs.*collapse quality: spread of F/F_z across ensembles [0-9.]+ \\+- [0-9.]+ against z.*peak law: peak ~ v0\\^[0-9.]+ \\+- [0-9.]+ \\(95%: \\+- [0-9.]+, over runs.*peak law, two terms \\(of the ensemble means[^\n]*crossover speed c1/c2 = ")
add_test(NAME cli_fit_ensemble_options_need_ensemble COMMAND granpen-cli fit ${GRANPEN_FIT_DIR}/kz25300.csv --bootstrap 50)
set_tests_properties(cli_fit_ensemble_options_need_ensemble PROPERTIES LABELS "unit;cli"
  PASS_REGULAR_EXPRESSION "--bootstrap needs --ensemble")
