# compute flow/azimuthal: bad input gets a clear error (decks on 1 and 2 ranks)
granpen_error_test(flow_no_axis "Compute flow/azimuthal needs axis FIXID \\(a fix rod/drive\\) or axis X Y"
  "compute f grains flow/azimuthal rbin 0.5 zbin 0.5")
granpen_error_test(flow_rbin_zero "Compute flow/azimuthal rbin must be > 0, got 0"
  "compute f grains flow/azimuthal axis 4 4 rbin 0 zbin 0.5")
granpen_error_test(flow_zbin_negative "Compute flow/azimuthal zbin must be > 0, got -1"
  "compute f grains flow/azimuthal axis 4 4 rbin 0.5 zbin -1")
# tiny bins: every count checked as a double against the limit before the cast to int and
# before allocating (1e-9 once gave a misleading message, 6e-10 a 50 GB allocation)
granpen_error_test(flow_rbin_tiny "Compute flow/azimuthal rbin 1e-09 gives 4e\\+09 bins over the range 4: more than the limit of 1000000 bins"
  "compute f grains flow/azimuthal axis 4 4 rbin 1e-9 zbin 0.5")
granpen_error_test(flow_rbin_tinier "Compute flow/azimuthal rbin 6e-10 gives 6.66667e\\+09 bins over the range 4: more than the limit of 1000000 bins"
  "compute f grains flow/azimuthal axis 4 4 rbin 6e-10 zbin 0.5")
granpen_error_test(flow_bins_product "Compute flow/azimuthal rbin 0.001 and zbin 0.001 give 6.4e\\+07 bins: more than the limit of 1000000"
  "compute f grains flow/azimuthal axis 4 4 rbin 0.001 zbin 0.001 zlo 0 zhi 16")
granpen_error_test(flow_rmax_outside "Compute flow/azimuthal rmax 5 reaches outside the box"
  "compute f grains flow/azimuthal axis 4 4 rbin 0.5 zbin 0.5 rmax 5")
granpen_error_test(flow_z_outside "Compute flow/azimuthal bins z = -1 to 4 lie outside the box z = 0 to 16"
  "compute f grains flow/azimuthal axis 4 4 rbin 0.5 zbin 0.5 zlo -1 zhi 4")
granpen_error_test(flow_tip_needs_drive "Compute flow/azimuthal frame tip needs axis FIXID"
  "compute f grains flow/azimuthal axis 4 4 rbin 0.5 zbin 0.5 frame tip zlo -2 zhi 2")
granpen_error_test(flow_voronoi_missing "Compute flow/azimuthal voronoi compute vor does not exist"
  "compute f grains flow/azimuthal axis 4 4 rbin 0.5 zbin 0.5 voronoi vor" "thermo_style custom step c_f[1][3]" "run 0")
granpen_error_test(flow_stress_missing "Compute flow/azimuthal stress compute st does not exist"
  "compute f grains flow/azimuthal axis 4 4 rbin 0.5 zbin 0.5 stress st" "thermo_style custom step c_f[1][3]" "run 0")
granpen_error_test(flow_stress_wrong "Compute flow/azimuthal stress compute ke is not a per-atom stress"
  "compute ke grains ke/atom" "compute f grains flow/azimuthal axis 4 4 rbin 0.5 zbin 0.5 stress ke"
  "thermo_style custom step c_f[1][3]" "run 0")
granpen_error_test(flow_axis_not_drive "Compute flow/azimuthal axis fix grav is gravity, not rod/drive"
  "fix grav grains gravity 981 vector 0 0 -1" "compute f grains flow/azimuthal axis grav rbin 0.5 zbin 0.5"
  "thermo_style custom step c_f[1][3]" "run 0")
granpen_error_test(flow_unknown_keyword "Unknown compute flow/azimuthal keyword: theta"
  "compute f grains flow/azimuthal axis 4 4 rbin 0.5 zbin 0.5 theta 4")
