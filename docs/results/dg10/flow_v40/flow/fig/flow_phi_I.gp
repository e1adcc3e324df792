# flow_phi_I.gp, written by granpen. The data are in flow_phi_I.dat beside it.
# granpen plot flow: phi against I at the rod's bottom edge (data/sims/dg10/dg10_flow/dg10_mu0.3_s1_v40_g981_D2.0.flow/flow/flow_edge_phi_I.csv), the paper's line phi = 0.57 - 0.35 I and a least-squares line.
# Run in this folder: `gnuplot flow_phi_I.gp` makes flow_phi_I.png and flow_phi_I.svg;
# `gnuplot -e "formats='png'" flow_phi_I.gp` makes only the PNG.
if (!exists("formats")) formats = "png svg"
data = "flow_phi_I.dat"
do for [fmt in formats] {
  if (fmt eq "png") {
    set terminal pngcairo enhanced size 1100,620 font "sans,12" background rgb "white"
  } else {
    if (fmt ne "svg") { print "unknown format ", fmt, " (png or svg)"; exit status 1 }
    set terminal svg enhanced size 1100,620 font "sans,12" background rgb "white"
  }
  set output "flow_phi_I." . fmt
  reset
  set encoding utf8
  set multiplot title "Packing fraction against inertial number at the rod edge: fit φ(0) = 0.562 ± 0.003, slope -0.28 ± 0.02" font ",14"

  # ---- panel 1
  set origin 0,0
  set size 1,0.94
  set xlabel "inertial number I"
  set ylabel "packing fraction φ at the rod edge (r = R)"
  set grid lc rgb "#d0d0d0"
  set xrange [0:*]
  set key outside right top Left reverse
  set key spacing 1.25
  set samples 400
  plot data index 0 using 1:2 with points pt 7 ps 1.2 lc rgb "#1f77b4" title "this run", \
       0.57 - 0.35*x with lines lw 1.5 dt 2 lc rgb "#d62728" title "paper: φ = 0.57 − 0.35 I", \
       0.5618936859 + -0.2815223408*x with lines lw 1.5 dt 1 lc rgb "#000000" title "fit: φ = 0.562 − 0.282 I"
  unset multiplot
  unset multiplot
  set output
}
