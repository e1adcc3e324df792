# parting.gp, written by granpen. The data are in parting.dat beside it.
# granpen plot parting: the ratio of two pushes' mean drag in windows of time after contact, one curve per granpen parting --json file, the band of its threshold about 1, and each pair's parting (the first of its windows in a row beyond the threshold) as an open circle.
# Run in this folder: `gnuplot parting.gp` makes parting.png and parting.svg;
# `gnuplot -e "formats='png'" parting.gp` makes only the PNG.
if (!exists("formats")) formats = "png svg"
data = "parting.dat"
do for [fmt in formats] {
  if (fmt eq "png") {
    set terminal pngcairo enhanced size 1300,620 font "sans,12" background rgb "white"
  } else {
    if (fmt ne "svg") { print "unknown format ", fmt, " (png or svg)"; exit status 1 }
    set terminal svg enhanced size 1300,620 font "sans,12" background rgb "white"
  }
  set output "parting." . fmt
  reset
  set encoding utf8
  set multiplot title "When two pushes part: A / B in windows after contact (open circle: the parting)" font ",14"

  # ---- panel 1
  set origin 0,0
  set size 0.64,0.94
  set xlabel "time after contact (ms)"
  set ylabel "drag A / B, mean per window"
  set grid lc rgb "#d0d0d0"
  set xrange [0:15]
  set yrange [0.68463175:1.62212325]
  set key at screen 0.65, screen 0.9 left top Left reverse
  set key spacing 1.25
  set object 10 rectangle from graph 0, first 0.97 to graph 1, first 1.03 behind fillcolor rgb "#808080" fillstyle transparent solid 0.18 noborder
  set samples 400
  plot keyentry with filledcurves fillcolor rgb "#808080" fillstyle transparent solid 0.36 noborder title "within ±3%", \
       data index 0 using 1:2 with linespoints lw 1.5 dt 1 lc rgb "#1f77b4" pt 7 ps 0.7 title "dg10\\_10\\_20\\_D2\\_v100: parts at 4.5 ms", \
       data index 1 using 1:2 with points pt 6 ps 2.2 lc rgb "#1f77b4" notitle, \
       1 with lines lw 1.5 dt 2 lc rgb "#404040" notitle
  unset multiplot
  unset multiplot
  set output
}
