# Bad input gets a clear error naming the keyword: each case is a small deck run by
# lmp_granpen on 1 and 2 ranks; the test passes when the message matches.
set(ERRDECKS ${CMAKE_CURRENT_BINARY_DIR}/error_decks)
file(MAKE_DIRECTORY ${ERRDECKS})
set(ERR_BASE "units cgs
atom_style sphere
atom_modify map array
boundary p p fm
newton off
comm_modify vel yes
region box block 0 8 0 8 0 16 units box
create_box 2 box
lattice sc 0.5 origin 0.5 0.5 0.5
region bed block 0 8 0 8 0 2 units box
create_atoms 1 region bed
set type 1 diameter 0.4
set type 1 density 3.0
group grains type 1
group nothing empty
create_rod 2 2.0 6.0 0.4 0.2 4.0 4.0 3.0 shell density 3.0
group rod type 2
pair_style gran/hertz/history 1e9 1e9 1000 1000 0.3 1
pair_coeff * *
neighbor 0.08 bin
neigh_modify delay 0 exclude type 2 2
timestep 2e-6
")

function(granpen_error_test name regex)
  set(deck ${ERRDECKS}/${name}.lmp)
  string(REPLACE ";" "\n" body "${ARGN}")
  file(WRITE ${deck} "${ERR_BASE}${body}\n")
  foreach(np 1 2)
    add_test(NAME error_${name}_np${np}
      COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${np} $<TARGET_FILE:lmp_granpen> -in ${deck} -log none)
    set_tests_properties(error_${name}_np${np} PROPERTIES ENVIRONMENT "${GRANPEN_TEST_ENV}"
      LABELS "lammps;errors" PROCESSORS ${np} PASS_REGULAR_EXPRESSION "ERROR.*${regex}")
  endforeach()
endfunction()

# fix rod/drive
granpen_error_test(v0_zero "Fix rod/drive v0 must be > 0, got 0" "fix push rod rod/drive 0")
granpen_error_test(v0_negative "Fix rod/drive v0 must be > 0, got -5" "fix push rod rod/drive -5")
granpen_error_test(v0_not_a_number "Expected floating point parameter instead of 'fast'" "fix push rod rod/drive fast")
granpen_error_test(v0_missing "Illegal fix rod/drive command: missing v0" "fix push rod rod/drive")
granpen_error_test(group_missing "Could not find fix group ID" "fix push nosuch rod/drive 100")
granpen_error_test(group_empty "Fix rod/drive group nothing is empty" "fix push nothing rod/drive 100")
granpen_error_test(unknown_keyword "Unknown fix rod/drive keyword: speedy" "fix push rod rod/drive 100 speedy 2")
granpen_error_test(keyword_missing_value "Illegal fix rod/drive depth command: missing argument" "fix push rod rod/drive 100 depth")
granpen_error_test(depth_negative "Fix rod/drive depth must be >= 0, got -1" "fix push rod rod/drive 100 depth -1")
granpen_error_test(at_depth_bad "Fix rod/drive at_depth must be stop or halt, got pause" "fix push rod rod/drive 100 at_depth pause")
granpen_error_test(mount_bad "Fix rod/drive mount needs k > 0, c >= 0, m > 0, got 0 1 1" "fix push rod rod/drive 100 mount 0 1 1")
granpen_error_test(ramp_negative "Fix rod/drive ramp must be >= 0, got -0.1" "fix push rod rod/drive 100 ramp -0.1")
granpen_error_test(grains_missing "Fix rod/drive grains group sand does not exist" "fix push rod rod/drive 100 grains sand")
granpen_error_test(grains_contain_rod "Fix rod/drive grains group all2 contains 764 rod atoms" "group all2 union grains rod" "fix push rod rod/drive 100 grains all2")
granpen_error_test(doubly_integrated "Fix rod/drive: 764 rod atoms are also integrated by fix nve \\(nve/sphere\\)"
  "fix nve all nve/sphere" "fix push rod rod/drive 100" "run 0")
granpen_error_test(surface_not_found "Fix rod/drive surface auto found no grains in group nothing"
  "fix push rod rod/drive 100 grains nothing" "run 0")
granpen_error_test(file_needs_gravity "Fix rod/drive file needs g: define fix gravity or give the g keyword"
  "fix push rod rod/drive 100 file ${ERRDECKS}/never.csv" "run 0")
granpen_error_test(file_needs_cgs_or_si "Fix rod/drive file needs units cgs or si \\(granpen-trace v1\\), not metal"
  "clear" "units metal" "atom_style sphere" "region box block 0 8 0 8 0 16 units box" "create_box 2 box"
  "create_rod 2 2.0 6.0 0.4 0.2 4.0 4.0 3.0 shell" "group rod type 2" "pair_style zero 1.0" "pair_coeff * *"
  "fix push rod rod/drive 100 g 981 file ${ERRDECKS}/never.csv" "run 0")
granpen_error_test(file_unwritable "Fix rod/drive cannot open trace file /nonexistent/dir/t.csv"
  "fix push rod rod/drive 100 g 981 file /nonexistent/dir/t.csv" "run 0")

# compute rod/drag
granpen_error_test(drag_needs_reference "Compute rod/drag needs either drive FIXID or surface VALUE" "compute d rod rod/drag")
granpen_error_test(drag_needs_v0 "Compute rod/drag without drive needs v0 VALUE" "compute d rod rod/drag surface 2.0")
granpen_error_test(drag_drive_wrong_style "Compute rod/drag drive fix grav is gravity, not rod/drive"
  "fix grav grains gravity 981 vector 0 0 -1" "compute d rod rod/drag drive grav" "thermo_style custom step c_d[1]" "run 0")
granpen_error_test(drag_drive_missing "Compute rod/drag drive fix nope does not exist"
  "compute d rod rod/drag drive nope" "thermo_style custom step c_d[1]" "run 0")
granpen_error_test(drag_unknown_keyword "Unknown compute rod/drag keyword: beta" "compute d rod rod/drag surface 2 v0 1 beta 2")
granpen_error_test(drag_bad_v0 "Compute rod/drag v0 must be > 0, got 0" "compute d rod rod/drag surface 2 v0 0")

# compute bed/surface
granpen_error_test(surface_grid_zero "Compute bed/surface grid must be >= 1, got 0" "compute s grains bed/surface grid 0")
granpen_error_test(surface_unknown_keyword "Unknown compute bed/surface keyword: cells" "compute s grains bed/surface cells 4")

# create_rod
granpen_error_test(rod_fill_bad "Create_rod fill must be shell or filled, got hollow"
  "create_rod 2 2.0 6.0 0.4 0.2 4.0 4.0 9.0 hollow")
granpen_error_test(rod_outside_box "Create_rod: rod spans z = 12 to 18, outside the box z = 0 to 16"
  "create_rod 2 2.0 6.0 0.4 0.2 4.0 4.0 12.0 shell")
granpen_error_test(rod_gaps "Create_rod: rod spacing larger than the sphere diameter leaves gaps"
  "create_rod 2 2.0 6.0 0.4 0.5 4.0 4.0 9.0 shell")
# a rod of unbounded sphere count (a mistyped spacing or diameter) is refused by name before
# anything is allocated: it ended in std::bad_alloc
granpen_error_test(rod_too_many_spheres "Create_rod: the rod would have [0-9]+ spheres, more than the 10000000 a rod may have"
  "create_rod 2 2.0 6000.0 1e-5 1e-5 4.0 4.0 1.0 filled")
granpen_error_test(rod_wider_than_box "Create_rod: rod diameter [0-9.e+]+ is not below the box width 8[.0]* in x"
  "create_rod 2 1e7 6.0 0.4 0.2 4.0 4.0 1.0 shell")
granpen_error_test(rod_type_bad "Create_rod atom type 3 is outside 1 to 2" "create_rod 3 2.0 6.0 0.4 0.2 4.0 4.0 9.0 shell")
granpen_error_test(rod_shaft_type_bad "Create_rod shaft_type 3 is outside 1 to 2"
  "create_rod 2 2.0 6.0 0.4 0.2 4.0 4.0 9.0 shell shaft_type 3")
granpen_error_test(rod_density_bad "Create_rod density must be > 0, got 0" "create_rod 2 2.0 6.0 0.4 0.2 4.0 4.0 9.0 shell density 0")

# restore_contact_history: it takes no arguments; and a restart with more gran/hertz/history
# histories (a hybrid of two) than the new pair style defines (one) is refused, not dropped.
# The second deck writes its own restart, one file per rank count (the two run in parallel).
granpen_error_test(restore_history_arguments "Illegal restore_contact_history command: it takes no arguments"
  "restore_contact_history all")
foreach(np 1 2)
  set(deck ${ERRDECKS}/restore_history_too_many_np${np}.lmp)
  file(WRITE ${deck} "${ERR_BASE}pair_style hybrid gran/hertz/history 1e9 1e9 1000 1000 0.3 1 gran/hertz/history 1e9 1e9 1000 1000 0.6 1
pair_coeff * * gran/hertz/history 1
pair_coeff 1 2 gran/hertz/history 2
run 0
write_restart ${ERRDECKS}/restore_history_two_np${np}.restart
clear
read_restart ${ERRDECKS}/restore_history_two_np${np}.restart
pair_style gran/hertz/history 1e9 1e9 1000 1000 0.3 1
pair_coeff * *
restore_contact_history
")
  add_test(NAME error_restore_history_too_many_np${np}
    COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${np} $<TARGET_FILE:lmp_granpen> -in ${deck} -log none)
  set_tests_properties(error_restore_history_too_many_np${np} PROPERTIES ENVIRONMENT "${GRANPEN_TEST_ENV}"
    LABELS "lammps;errors" PROCESSORS ${np} PASS_REGULAR_EXPRESSION
    "ERROR.*Restore_contact_history: the restart holds 2 gran/hertz/history contact histories but the pair style defines 1")
endforeach()
