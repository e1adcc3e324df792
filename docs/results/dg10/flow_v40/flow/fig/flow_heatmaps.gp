# flow_heatmaps.gp, written by granpen. The data are in flow_heatmaps.dat beside it.
# granpen plot flow: heatmaps of data/sims/dg10/dg10_flow/dg10_mu0.3_s1_v40_g981_D2.0.flow/flow/flow_fields.csv in (r, z - z_tip), the rod (r < R = 1 cm, z > 0) in grey;
# colour ranges: phi from the 2nd to the 99th percentile of the filled bins, v_z symmetric about 0,
# gamma-dot and I on log scales over three decades below their 99th percentile.
# Run in this folder: `gnuplot flow_heatmaps.gp` makes flow_heatmaps.png and flow_heatmaps.svg;
# `gnuplot -e "formats='png'" flow_heatmaps.gp` makes only the PNG.
if (!exists("formats")) formats = "png svg"
data = "flow_heatmaps.dat"
do for [fmt in formats] {
  if (fmt eq "png") {
    set terminal pngcairo enhanced size 1700,600 font "sans,12" background rgb "white"
  } else {
    if (fmt ne "svg") { print "unknown format ", fmt, " (png or svg)"; exit status 1 }
    set terminal svg enhanced size 1700,600 font "sans,12" background rgb "white"
  }
  set output "flow_heatmaps." . fmt
  reset
  set encoding utf8
  set multiplot layout 1,4 title "Flow around the rod (25 x 50 bins)" font ",14"

  # ---- (a) packing fraction φ
  unset logscale cb
  unset object
  unset label
  set title "(a) packing fraction φ"
  set xlabel "r (cm)"
  set ylabel "z − z_{tip} (cm)"
  unset cblabel
  set size ratio -1
  set xrange [-1.387778781e-17:5]
  set yrange [-4:6]
  set tics out
  set key off
  set palette defined (0 "#440154", 0.25 "#3b528b", 0.5 "#21918c", 0.75 "#5ec962", 1 "#fde725")
  set cbrange [0.01970238698:0.6130379427]
  set format cb "%g"
  set object 1 rectangle from first 0, first 0 to first 1, first 6 front fillcolor rgb "#707070" fillstyle solid 1.0 border lc rgb "black"
  set label 1 "rod" at first 0.5, first 3 center front textcolor rgb "white"
  plot data index 0 using 1:2:3 with image notitle

  # ---- (b) vertical velocity v_z (cm/s; > 0 up)
  unset logscale cb
  unset object
  unset label
  set title "(b) vertical velocity v_z (cm/s; > 0 up)"
  set xlabel "r (cm)"
  set ylabel "z − z_{tip} (cm)"
  unset cblabel
  set size ratio -1
  set xrange [-1.387778781e-17:5]
  set yrange [-4:6]
  set tics out
  set key off
  set palette defined (-1 "#2166ac", -0.5 "#92c5de", 0 "#f7f7f7", 0.5 "#f4a582", 1 "#b2182b")
  set cbrange [-33.29753994:33.29753994]
  set format cb "%g"
  set object 1 rectangle from first 0, first 0 to first 1, first 6 front fillcolor rgb "#707070" fillstyle solid 1.0 border lc rgb "black"
  set label 1 "rod" at first 0.5, first 3 center front textcolor rgb "white"
  plot data index 0 using 1:2:4 with image notitle

  # ---- (c) shear rate γ̇ (1/s)
  unset logscale cb
  unset object
  unset label
  set title "(c) shear rate γ̇ (1/s)"
  set xlabel "r (cm)"
  set ylabel "z − z_{tip} (cm)"
  unset cblabel
  set size ratio -1
  set xrange [-1.387778781e-17:5]
  set yrange [-4:6]
  set tics out
  set key off
  set palette defined (0 "#000004", 0.25 "#51127c", 0.5 "#b73779", 0.75 "#fc8961", 1 "#fcfdbf")
  set cbrange [0.03964197701:39.64197701]
  set logscale cb
  set format cb "10^{%T}"
  set object 1 rectangle from first 0, first 0 to first 1, first 6 front fillcolor rgb "#707070" fillstyle solid 1.0 border lc rgb "black"
  set label 1 "rod" at first 0.5, first 3 center front textcolor rgb "white"
  plot data index 0 using 1:2:5 with image notitle

  # ---- (d) inertial number I
  unset logscale cb
  unset object
  unset label
  set title "(d) inertial number I"
  set xlabel "r (cm)"
  set ylabel "z − z_{tip} (cm)"
  unset cblabel
  set size ratio -1
  set xrange [-1.387778781e-17:5]
  set yrange [-4:6]
  set tics out
  set key off
  set palette defined (0 "#000004", 0.25 "#51127c", 0.5 "#b73779", 0.75 "#fc8961", 1 "#fcfdbf")
  set cbrange [0.00538452721:5.38452721]
  set logscale cb
  set format cb "10^{%T}"
  set object 1 rectangle from first 0, first 0 to first 1, first 6 front fillcolor rgb "#707070" fillstyle solid 1.0 border lc rgb "black"
  set label 1 "rod" at first 0.5, first 3 center front textcolor rgb "white"
  plot data index 0 using 1:2:6 with image notitle
  unset multiplot
  unset multiplot
  set output
}
