# scaling.gp, written by granpen. The data are in scaling.dat beside it.
# granpen plot scaling: each quantity of docs/results/box.csv against the box width with its error bars, and the paper's value (a red line, with its band when it has an error); the dotted line: the paper's own box. Each series is drawn 0.17 aside of the next in x, so that bars at one x stay apart.
# Run in this folder: `gnuplot scaling.gp` makes scaling.png and scaling.svg;
# `gnuplot -e "formats='png'" scaling.gp` makes only the PNG.
if (!exists("formats")) formats = "png svg"
data = "scaling.dat"
do for [fmt in formats] {
  if (fmt eq "png") {
    set terminal pngcairo enhanced size 1300,2020 font "sans,12" background rgb "white"
  } else {
    if (fmt ne "svg") { print "unknown format ", fmt, " (png or svg)"; exit status 1 }
    set terminal svg enhanced size 1300,2020 font "sans,12" background rgb "white"
  }
  set output "scaling." . fmt
  reset
  set encoding utf8
  set multiplot title "Against the box width: granpen ± its error: bench grains at D/d\\_g = 5 (blue circles), dg10 grains at D/d\\_g = 10 (green squares);\nthe paper's value (red; shaded: its error), the paper's box (dotted)" font ",14"

  # ---- panel 1: peak exponent (v\_c to 10 v\_c)   (paper: 2)
  set origin 0,0.7424950495
  set size 0.5,0.1856237624
  set title "peak exponent (v\\_c to 10 v\\_c)   (paper: 2)"
  set xlabel "box width (cm)"
  set ylabel "peak exponent (v\\_c to 10 v\\_c)"
  set grid lc rgb "#d0d0d0"
  set xrange [7:21]
  set yrange [1.2196784:2.0578016]
  unset key
  set arrow 1 from first 20, graph 0 to first 20, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "paper" at first 20, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 0 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "bench grains at D/d_g = 5", \
       data index 1 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#2ca02c" pt 5 ps 1.2 title "dg10 grains at D/d_g = 10", \
       2 with lines lw 1.5 dt 2 lc rgb "#d62728" title "paper: 2"

  # ---- panel 2: peak exponent (means above v_c)   (paper: 2)
  reset
  set encoding utf8
  set origin 0.5,0.7424950495
  set size 0.5,0.1856237624
  set title "peak exponent (means above v_c)   (paper: 2)"
  set xlabel "box width (cm)"
  set ylabel "peak exponent (means above v_c)"
  set grid lc rgb "#d0d0d0"
  set xrange [7:21]
  set yrange [1.39196:2.04504]
  unset key
  set arrow 1 from first 20, graph 0 to first 20, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "paper" at first 20, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 2 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "bench grains at D/d_g = 5", \
       data index 3 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#2ca02c" pt 5 ps 1.2 title "dg10 grains at D/d_g = 10", \
       2 with lines lw 1.5 dt 2 lc rgb "#d62728" title "paper: 2"

  # ---- panel 3: peak exponent at 80 to 200 cm/s (ensemble means)   (paper: 2)
  reset
  set encoding utf8
  set origin 0,0.5568712871
  set size 0.5,0.1856237624
  set title "peak exponent at 80 to 200 cm/s (ensemble means)   (paper: 2)"
  set xlabel "box width (cm)"
  set ylabel "value"
  set grid lc rgb "#d0d0d0"
  set xrange [7:21]
  set yrange [1.5464:2.0336]
  unset key
  set arrow 1 from first 20, graph 0 to first 20, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "paper" at first 20, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 4 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#2ca02c" pt 5 ps 1.2 title "dg10 grains at D/d_g = 10", \
       2 with lines lw 1.5 dt 2 lc rgb "#d62728" title "paper: 2"

  # ---- panel 4: peak over the narrower box's (same bed and v0)   (paper: 1)
  reset
  set encoding utf8
  set origin 0.5,0.5568712871
  set size 0.5,0.1856237624
  set title "peak over the narrower box's (same bed and v0)   (paper: 1)"
  set xlabel "box width (cm)"
  set ylabel "value"
  set grid lc rgb "#d0d0d0"
  set xrange [7:21]
  set yrange [0.90138:1.05682]
  unset key
  set arrow 1 from first 20, graph 0 to first 20, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "paper" at first 20, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 5 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "bench grains at D/d_g = 5", \
       data index 6 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#2ca02c" pt 5 ps 1.2 title "dg10 grains at D/d_g = 10", \
       1 with lines lw 1.5 dt 2 lc rgb "#d62728" title "paper: 1"

  # ---- panel 5: λ_{vz} / D (bench at 50 and dg10 at 40 cm/s)   (paper: 0.98 ± 0.15)
  reset
  set encoding utf8
  set origin 0,0.3712475248
  set size 0.5,0.1856237624
  set title "λ_{vz} / D (bench at 50 and dg10 at 40 cm/s)   (paper: 0.98 ± 0.15)"
  set xlabel "box width (cm)"
  set ylabel "value"
  set grid lc rgb "#d0d0d0"
  set xrange [7:21]
  set yrange [0.3167457548:1.190241055]
  unset key
  set object 10 rectangle from graph 0, first 0.83 to graph 1, first 1.13 behind fillcolor rgb "#d62728" fillstyle transparent solid 0.18 noborder
  set arrow 1 from first 20, graph 0 to first 20, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "paper" at first 20, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot keyentry with filledcurves fillcolor rgb "#d62728" fillstyle transparent solid 0.36 noborder title "paper: 0.98 ± 0.15", \
       data index 7 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "bench grains at D/d_g = 5", \
       data index 8 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#2ca02c" pt 5 ps 1.2 title "dg10 grains at D/d_g = 10", \
       0.98 with lines lw 1.5 dt 2 lc rgb "#d62728" notitle

  # ---- panel 6: drag / (μ g M) (bench at 50 and dg10 at 40 cm/s)   (paper: 1)
  reset
  set encoding utf8
  set origin 0.5,0.3712475248
  set size 0.5,0.1856237624
  set title "drag / (μ g M) (bench at 50 and dg10 at 40 cm/s)   (paper: 1)"
  set xlabel "box width (cm)"
  set ylabel "value"
  set grid lc rgb "#d0d0d0"
  set xrange [7:21]
  set yrange [0.5031366132:2.854405505]
  unset key
  set arrow 1 from first 20, graph 0 to first 20, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "paper" at first 20, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 9 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "bench grains at D/d_g = 5", \
       data index 10 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#2ca02c" pt 5 ps 1.2 title "dg10 grains at D/d_g = 10", \
       1 with lines lw 1.5 dt 2 lc rgb "#d62728" title "paper: 1"

  # ---- panel 7: α(D = 1 cm) / α(D = 2 cm) (bench at 28 and dg10 at 100 cm/s)   (paper: 1)
  reset
  set encoding utf8
  set origin 0,0.1856237624
  set size 0.5,0.1856237624
  set title "α(D = 1 cm) / α(D = 2 cm) (bench at 28 and dg10 at 100 cm/s)   (paper: 1)"
  set xlabel "box width (cm)"
  set ylabel "value"
  set grid lc rgb "#d0d0d0"
  set xrange [7:21]
  set yrange [0.93272:1.90828]
  unset key
  set arrow 1 from first 20, graph 0 to first 20, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "paper" at first 20, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 11 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "bench grains at D/d_g = 5", \
       data index 12 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#2ca02c" pt 5 ps 1.2 title "dg10 grains at D/d_g = 10", \
       1 with lines lw 1.5 dt 2 lc rgb "#d62728" title "paper: 1"

  # ---- panel 8: α(3 cm) / α(2 cm) (bench at 28 and dg10 at 100 cm/s)   (paper: 1)
  reset
  set encoding utf8
  set origin 0.5,0.1856237624
  set size 0.5,0.1856237624
  set title "α(3 cm) / α(2 cm) (bench at 28 and dg10 at 100 cm/s)   (paper: 1)"
  set xlabel "box width (cm)"
  set ylabel "value"
  set grid lc rgb "#d0d0d0"
  set xrange [7:21]
  set yrange [0.783656:1.081544]
  unset key
  set arrow 1 from first 20, graph 0 to first 20, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "paper" at first 20, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 13 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "bench grains at D/d_g = 5", \
       1 with lines lw 1.5 dt 2 lc rgb "#d62728" title "paper: 1"

  # ---- panel 9: α(D = 1 cm) / α(D = 2 cm) with the shaft frictionless   (paper: 1)
  reset
  set encoding utf8
  set origin 0,0
  set size 0.5,0.1856237624
  set title "α(D = 1 cm) / α(D = 2 cm) with the shaft frictionless   (paper: 1)"
  set xlabel "box width (cm)"
  set ylabel "value"
  set grid lc rgb "#d0d0d0"
  set xrange [7:21]
  set yrange [0.94512:1.74088]
  unset key
  set arrow 1 from first 20, graph 0 to first 20, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "paper" at first 20, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 14 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "bench grains at D/d_g = 5", \
       1 with lines lw 1.5 dt 2 lc rgb "#d62728" title "paper: 1"
  unset multiplot
  unset multiplot
  set output
}
