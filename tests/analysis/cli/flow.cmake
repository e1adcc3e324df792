# granpen flow and granpen momentum end to end on a synthetic dump (written at configure
# time) and bad input, and, with lmp_granpen, agreement with compute flow/azimuthal and
# compute momentum/vbin on the frames of a tiny push (lammps_agree: tests/support; the
# kernels on synthetic frames: tests/analysis/core). Included from CMakeLists.txt.

set(FLOW_DIR ${CMAKE_CURRENT_BINARY_DIR}/flow_cli)
# flow_cli_test(NAME -D...) runs flow_cli_run.cmake with those settings (-P goes last:
# cmake reads -D only before it)
function(flow_cli_test name)
  add_test(NAME ${name} COMMAND ${CMAKE_COMMAND} ${ARGN} -P ${CMAKE_CURRENT_SOURCE_DIR}/flow_cli_run.cmake)
endfunction()

# ---- a synthetic dump: grains (type 1, radius 0.2) on a 0.5 cm cubic lattice in a 6 x 6 x 10
# box, 10 layers; a rod (type 2) of 4 spheres of radius 0.2 at 0.8 cm from the axis (3, 3):
# D = 2, tip 0.2 below their centres. v_z by layer (v0 = 320: bounds 32, 4, 1, 0.5): layer 0
# -5, 1 0.75 (noise), 2 2 (slow), 3 10 (intermediate), 4 40 (fast), others 0. Outside
# r > R = 1 each layer holds 132 grains. Two frames, the rod 0.5 lower in the second.
function(granpen_synthetic_dump path with_rod truncate)
  set(vzs "-5" "75e-2" "2" "10" "40" "0" "0" "0" "0" "0")
  set(text "")
  foreach(frame 1 2)
    math(EXPR step "${frame} * 1000")
    set(n 1440)
    if(with_rod)
      set(n 1444)
    endif()
    string(APPEND text "ITEM: TIMESTEP\n${step}\nITEM: NUMBER OF ATOMS\n${n}\nITEM: BOX BOUNDS pp pp fm\n0 6\n0 6\n0 10\n"
      "ITEM: ATOMS id type x y z vx vy vz radius\n")
    set(id 0)
    foreach(k RANGE 9)
      list(GET vzs ${k} vz)
      math(EXPR z "25 + 50 * ${k}")
      foreach(j RANGE 11)
        math(EXPR y "25 + 50 * ${j}")
        foreach(i RANGE 11)
          math(EXPR x "25 + 50 * ${i}")
          math(EXPR id "${id} + 1")
          string(APPEND text "${id} 1 ${x}e-2 ${y}e-2 ${z}e-2 0 0 ${vz} 20e-2\n")
        endforeach()
      endforeach()
    endforeach()
    if(with_rod)
      math(EXPR rz "450 - 50 * ${frame}")
      string(APPEND text "1441 2 380e-2 3 ${rz}e-2 0 0 -320 20e-2\n1442 2 220e-2 3 ${rz}e-2 0 0 -320 20e-2\n"
        "1443 2 3 380e-2 ${rz}e-2 0 0 -320 20e-2\n1444 2 3 220e-2 ${rz}e-2 0 0 -320 20e-2\n")
    endif()
    if(truncate AND frame EQUAL 2)
      string(FIND "${text}" "ITEM: TIMESTEP\n2000" cut)
      math(EXPR cut "${cut} + 400")
      string(SUBSTRING "${text}" 0 ${cut} text)
    endif()
  endforeach()
  file(WRITE ${path} "${text}")
endfunction()
granpen_synthetic_dump(${FLOW_DIR}/lattice.dump ON OFF)
granpen_synthetic_dump(${FLOW_DIR}/no_rod.dump OFF OFF)
granpen_synthetic_dump(${FLOW_DIR}/truncated.dump ON ON)
# its trace: v0 = 320, surface 4.95 (the top layer's tops), depth z = (25 i - 50) / 100
set(trace "# granpen-trace v1\n# units = cgs\n# v0 = 320\n# D = 2\n# g = 981\n# d_g = 0.4\n# rho_g = 3\n# mu = 0.3\n# surface = 4.95\n# dt = 1e-6\nt,z,F\n")
foreach(i RANGE 20)
  math(EXPR z "25 * ${i} - 50")
  math(EXPR F "1000 * ${i}")
  string(APPEND trace "${i}e-3,${z}e-2,${F}\n")
endforeach()
file(WRITE ${FLOW_DIR}/lattice.csv "${trace}")
file(WRITE ${FLOW_DIR}/bad_trace.csv "# granpen-trace v1\n# units = cgs\n# v0 = 320\n# D = 2\nt,z,F\n0,0,0\n")

# the tables each subcommand writes into DIR, with their exact first lines
function(granpen_flow_headers var dir)
  set(${var} "${dir}/flow_fields.csv=r,z,count,phi,phi_centre,vr,vz,T,gammadot,p,I^^${dir}/flow_profile_below.csv=z,vz,vz_se,phi^^${dir}/flow_edge_phi_I.csv=I,phi^^${dir}/flow_strip.csv=z,vz^^${dir}/flow_annulus.csv=t_tilde,z_tip,phi,vz,T^^${dir}/flow_surface.csv=t_tilde,z_tip,vz,grains^^${dir}/flow.json={" PARENT_SCOPE)
endfunction()
function(granpen_momentum_headers var dir)
  set(${var} "${dir}/momentum_classes.csv=t_tilde,z_tip,class,count,p_up^^${dir}/momentum_drag.csv=t_tilde,z_tip,F,mu_g_M^^${dir}/momentum.json={" PARENT_SCOPE)
endfunction()
granpen_flow_headers(FLOW_HEADERS ${FLOW_DIR}/out)
granpen_momentum_headers(MOM_HEADERS ${FLOW_DIR}/mom)
granpen_flow_headers(DECK_FLOW_HEADERS ${FLOW_DIR}/deck_flow)
granpen_momentum_headers(DECK_MOM_HEADERS ${FLOW_DIR}/deck_mom)
set(CLI $<TARGET_FILE:granpen-cli>)
# granpen flow on the lattice: the tables and the summary (Voronoi by voro++, 8 x 25 bins of d_g)
flow_cli_test(cli_flow_synthetic "-DCMD=${CLI}^^flow^^${FLOW_DIR}/lattice.dump^^--trace^^${FLOW_DIR}/lattice.csv^^--out^^${FLOW_DIR}/out"
  -DRC=0 -DCLEAN=${FLOW_DIR}/out "-DHEADERS=${FLOW_HEADERS}"
  "-DOUT_RE=granpen flow: 2 frames \\(timesteps 1000\\.\\.2000\\).*fields: 8 x 25 bins.*phi: voro\\+\\+.*wrote")
# granpen momentum: 132 grains outside r = 1 in each of fast, intermediate, slow (by layer)
flow_cli_test(cli_momentum_synthetic "-DCMD=${CLI}^^momentum^^${FLOW_DIR}/lattice.dump^^--trace^^${FLOW_DIR}/lattice.csv^^--out^^${FLOW_DIR}/mom"
  -DRC=0 -DCLEAN=${FLOW_DIR}/mom "-DHEADERS=${MOM_HEADERS}"
  "-DOUT_RE=granpen momentum: 2 frames.*z_s = 4\\.95 \\(trace\\).* 1000 +1\\.15 +[0-9.]+ +132 +132 +132 .*drag: ")
# bad input: a truncated frame, a frame without the rod, a broken trace: exit 1, the file
# and line named, nothing written; usage errors exit 2
flow_cli_test(cli_flow_truncated_dump "-DCMD=${CLI}^^flow^^${FLOW_DIR}/truncated.dump^^--out^^${FLOW_DIR}/bad1"
  -DRC=1 -DABSENT=${FLOW_DIR}/bad1 "-DERR_RE=granpen flow: [^\n]*truncated\\.dump:[0-9]+: ")
flow_cli_test(cli_momentum_truncated_dump "-DCMD=${CLI}^^momentum^^${FLOW_DIR}/truncated.dump^^--trace^^${FLOW_DIR}/lattice.csv^^--out^^${FLOW_DIR}/bad2"
  -DRC=1 -DABSENT=${FLOW_DIR}/bad2 "-DERR_RE=granpen momentum: [^\n]*truncated\\.dump:[0-9]+: ")
flow_cli_test(cli_flow_no_rod "-DCMD=${CLI}^^flow^^${FLOW_DIR}/no_rod.dump^^--out^^${FLOW_DIR}/bad3"
  -DRC=1 -DABSENT=${FLOW_DIR}/bad3 "-DERR_RE=no_rod\\.dump:1: frame \\(timestep 1000\\) has no atoms of rod type 2; give --rod-type, or --axis X Y and --tip Z")
flow_cli_test(cli_flow_rod_by_options "-DCMD=${CLI}^^flow^^${FLOW_DIR}/no_rod.dump^^--axis^^3^^3^^--tip^^3.8^^--D^^2^^--zs^^4.95^^--out^^${FLOW_DIR}/opt"
  -DRC=0 -DCLEAN=${FLOW_DIR}/opt "-DOUT_RE=granpen flow: 2 frames.*D = 2 cm \\(option\\)")
flow_cli_test(cli_momentum_bad_trace "-DCMD=${CLI}^^momentum^^${FLOW_DIR}/lattice.dump^^--trace^^${FLOW_DIR}/bad_trace.csv^^--out^^${FLOW_DIR}/bad4"
  -DRC=1 -DABSENT=${FLOW_DIR}/bad4 "-DERR_RE=bad_trace\\.csv:[0-9]+: ")
flow_cli_test(cli_momentum_needs_trace "-DCMD=${CLI}^^momentum^^${FLOW_DIR}/lattice.dump"
  -DRC=2 "-DERR_RE=--trace TRACE is required")
# a bin width that would give more bins than the grid's limit: refused before allocating
flow_cli_test(cli_flow_tiny_dr "-DCMD=${CLI}^^flow^^${FLOW_DIR}/lattice.dump^^--trace^^${FLOW_DIR}/lattice.csv^^--dr^^1e-9^^--out^^${FLOW_DIR}/bad5"
  -DRC=2 -DABSENT=${FLOW_DIR}/bad5 "-DERR_RE=dr 1e-09 gives 3e\\+09 bins over the range 3: more than the limit of 1000000 bins")
flow_cli_test(cli_flow_help "-DCMD=${CLI}^^flow^^--help" -DRC=0 "-DOUT_RE=usage: granpen flow DUMP")
flow_cli_test(cli_momentum_help "-DCMD=${CLI}^^momentum^^--help" -DRC=0 "-DOUT_RE=usage: granpen momentum DUMP")
set_tests_properties(cli_flow_synthetic cli_momentum_synthetic cli_flow_truncated_dump cli_momentum_truncated_dump
  cli_flow_no_rod cli_flow_rod_by_options cli_momentum_bad_trace cli_momentum_needs_trace cli_flow_tiny_dr cli_flow_help
  cli_momentum_help
  PROPERTIES LABELS "unit;cli")

# ---- agreement with the computes on a tiny push (v0 = 100 cm/s to 1 cm, frames every
# 1000 steps): observe_flow_compare.lmp dumps the atoms and writes the computes' output
if(GRANPEN_HAVE_LMP)
  set(CMP ${FLOW_DIR}/deck)
  file(MAKE_DIRECTORY ${CMP})
  add_test(NAME flow_compare_deck
    COMMAND $<TARGET_FILE:lmp_granpen> -in ${PROJECT_SOURCE_DIR}/inputs/in.push -var inputs ${PROJECT_SOURCE_DIR}/inputs
      -var preset tiny -var bed ${BEDS}/bed_tiny.restart -var v0 100 -var depth 1.0
      -var trace ${CMP}/cmp.csv -var observe ${CMAKE_CURRENT_SOURCE_DIR}/observe_flow_compare.lmp -log ${CMP}/cmp.log)
  set_tests_properties(flow_compare_deck PROPERTIES LABELS lammps FIXTURES_REQUIRED tiny_bed FIXTURES_SETUP flow_compare
    TIMEOUT 300 ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMP_NUM_THREADS=1"
    PASS_REGULAR_EXPRESSION "granpen push: done, depth 1.000 cm")
  # every sampled timestep, bin by bin: counts equal, the rest within 1e-9 (round-off)
  add_test(NAME flow_agrees_with_compute COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DAGREE=$<TARGET_FILE:lammps_agree>
    -DDUMP=${CMP}/cmp.csv.dump -DTRACE=${CMP}/cmp.csv -DCOMPUTE=${CMP}/cmp.csv.flow.txt -DOUT=${CMP}/flow
    -P ${CMAKE_CURRENT_SOURCE_DIR}/flow_agree.cmake)
  set_tests_properties(flow_agrees_with_compute PROPERTIES LABELS "lammps;cli" FIXTURES_REQUIRED flow_compare
    PASS_REGULAR_EXPRESSION "granpen flow agrees with compute flow/azimuthal on [0-9]+ timesteps")
  # all frames in one run: the summary and every table
  flow_cli_test(cli_flow_deck
    "-DCMD=${CLI}^^flow^^${CMP}/cmp.csv.dump^^--trace^^${CMP}/cmp.csv^^--stress^^cmp_stress^^--out^^${FLOW_DIR}/deck_flow"
    -DRC=0 -DCLEAN=${FLOW_DIR}/deck_flow "-DHEADERS=${DECK_FLOW_HEADERS}"
    "-DOUT_RE=stress: columns c_cmp_stress\\[1\\.\\.3\\].*lambda_vz = .*rod edge: .*wrote")
  set_tests_properties(cli_flow_deck PROPERTIES LABELS "lammps;cli" FIXTURES_REQUIRED flow_compare)
  # momentum: per frame, counts equal, p_up and mu g M within 1e-9, depth within 1e-7 cm
  flow_cli_test(momentum_agrees_with_compute
    "-DCMD=${CLI}^^momentum^^${CMP}/cmp.csv.dump^^--trace^^${CMP}/cmp.csv^^--out^^${FLOW_DIR}/deck_mom"
    -DRC=0 -DCLEAN=${FLOW_DIR}/deck_mom "-DHEADERS=${DECK_MOM_HEADERS}" "-DOUT_RE=drag: F = ")
  add_test(NAME momentum_agrees_with_compute_check COMMAND $<TARGET_FILE:lammps_agree> momentum
    ${CMP}/cmp.csv.momentum.txt ${CMP}/cmp.csv.mug_m.txt ${FLOW_DIR}/deck_mom/momentum_classes.csv
    ${FLOW_DIR}/deck_mom/momentum_drag.csv)
  set_tests_properties(momentum_agrees_with_compute PROPERTIES LABELS "lammps;cli" FIXTURES_REQUIRED flow_compare
    FIXTURES_SETUP momentum_cli_out)
  set_tests_properties(momentum_agrees_with_compute_check PROPERTIES LABELS "lammps;cli"
    FIXTURES_REQUIRED "flow_compare;momentum_cli_out" PASS_REGULAR_EXPRESSION "agree: largest relative deviation")
endif()
