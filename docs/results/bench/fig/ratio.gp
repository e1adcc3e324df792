# ratio.gp, written by granpen. The data are in ratio.dat beside it.
# granpen plot ratio: the binned F/F_z curves of granpen collapse (bins of t~ of width 0.25, z >= 0.2 cm), against z (bin centre t~ converted back to z)
# and against t~; the band 1 +- 0.2; k_z from alpha = 34.21.
# Run in this folder: `gnuplot ratio.gp` makes ratio.png and ratio.svg;
# `gnuplot -e "formats='png'" ratio.gp` makes only the PNG.
if (!exists("formats")) formats = "png svg"
data = "ratio.dat"
do for [fmt in formats] {
  if (fmt eq "png") {
    set terminal pngcairo enhanced size 1450,620 font "sans,12" background rgb "white"
  } else {
    if (fmt ne "svg") { print "unknown format ", fmt, " (png or svg)"; exit status 1 }
    set terminal svg enhanced size 1450,620 font "sans,12" background rgb "white"
  }
  set output "ratio." . fmt
  reset
  set encoding utf8
  set multiplot title "F over its depth term F_z: t̃* = 1.79 ± 1.1 (7 of 60 traces; their mean: not reached), spread 1.149 against z, 0.350 against t̃" font ",14"

  # ---- panel 1: (a) against depth
  set origin 0,0
  set size 0.38,0.94
  set title "(a) against depth"
  set xlabel "rod tip depth z (cm)"
  set ylabel "F / F_z   (F_z = α μ ρ_g g D² z)"
  set grid lc rgb "#d0d0d0"
  set logscale y
  set yrange [0.3724629164:86.41402287]
  unset key
  set object 10 rectangle from graph 0, first 0.8 to graph 1, first 1.2 behind fillcolor rgb "#808080" fillstyle transparent solid 0.18 noborder
  set ytics ("0.5" 0.5, "1" 1, "2" 2, "5" 5, "10" 10, "20" 20, "50" 50)
  set mytics 10
  set autoscale xfix
  set samples 400
  plot data index 0 using 1:2 with lines lw 1.8 dt 1 lc rgb "#144d75" notitle, \
       data index 1 using 1:2 with lines lw 1.8 dt 1 lc rgb "#165682" notitle, \
       data index 2 using 1:2 with lines lw 1.8 dt 1 lc rgb "#195f8f" notitle, \
       data index 3 using 1:2 with lines lw 1.8 dt 1 lc rgb "#1b679c" notitle, \
       data index 4 using 1:2 with lines lw 1.8 dt 1 lc rgb "#1d70a9" notitle, \
       data index 5 using 1:2 with lines lw 1.8 dt 1 lc rgb "#2279b5" notitle, \
       data index 6 using 1:2 with lines lw 1.8 dt 1 lc rgb "#3283ba" notitle, \
       data index 7 using 1:2 with lines lw 1.8 dt 1 lc rgb "#438dc0" notitle, \
       data index 8 using 1:2 with lines lw 1.8 dt 1 lc rgb "#5397c5" notitle, \
       data index 9 using 1:2 with lines lw 1.8 dt 1 lc rgb "#63a0cb" notitle, \
       data index 10 using 1:2 with lines lw 1.8 dt 1 lc rgb "#74aad0" notitle, \
       data index 11 using 1:2 with lines lw 1.8 dt 1 lc rgb "#84b4d6" notitle, \
       data index 12 using 1:2 with lines lw 1.8 dt 1 lc rgb "#8b191a" notitle, \
       data index 13 using 1:2 with lines lw 1.8 dt 1 lc rgb "#9b1c1d" notitle, \
       data index 14 using 1:2 with lines lw 1.8 dt 1 lc rgb "#aa1f20" notitle, \
       data index 15 using 1:2 with lines lw 1.8 dt 1 lc rgb "#ba2223" notitle, \
       data index 16 using 1:2 with lines lw 1.8 dt 1 lc rgb "#c92526" notitle, \
       data index 17 using 1:2 with lines lw 1.8 dt 1 lc rgb "#d72a2b" notitle, \
       data index 18 using 1:2 with lines lw 1.8 dt 1 lc rgb "#da3a3b" notitle, \
       data index 19 using 1:2 with lines lw 1.8 dt 1 lc rgb "#dd494a" notitle, \
       data index 20 using 1:2 with lines lw 1.8 dt 1 lc rgb "#e0595a" notitle, \
       data index 21 using 1:2 with lines lw 1.8 dt 1 lc rgb "#e26969" notitle, \
       data index 22 using 1:2 with lines lw 1.8 dt 1 lc rgb "#e57879" notitle, \
       data index 23 using 1:2 with lines lw 1.8 dt 1 lc rgb "#e88889" notitle, \
       data index 24 using 1:2 with lines lw 1.8 dt 1 lc rgb "#1d681d" notitle, \
       data index 25 using 1:2 with lines lw 1.8 dt 1 lc rgb "#207420" notitle, \
       data index 26 using 1:2 with lines lw 1.8 dt 1 lc rgb "#237f23" notitle, \
       data index 27 using 1:2 with lines lw 1.8 dt 1 lc rgb "#268b26" notitle, \
       data index 28 using 1:2 with lines lw 1.8 dt 1 lc rgb "#299729" notitle, \
       data index 29 using 1:2 with lines lw 1.8 dt 1 lc rgb "#2fa12f" notitle, \
       data index 30 using 1:2 with lines lw 1.8 dt 1 lc rgb "#3ea83e" notitle, \
       data index 31 using 1:2 with lines lw 1.8 dt 1 lc rgb "#4eaf4e" notitle, \
       data index 32 using 1:2 with lines lw 1.8 dt 1 lc rgb "#5db65d" notitle, \
       data index 33 using 1:2 with lines lw 1.8 dt 1 lc rgb "#6cbd6c" notitle, \
       data index 34 using 1:2 with lines lw 1.8 dt 1 lc rgb "#7cc47c" notitle, \
       data index 35 using 1:2 with lines lw 1.8 dt 1 lc rgb "#8bcb8b" notitle, \
       data index 36 using 1:2 with lines lw 1.8 dt 1 lc rgb "#a65309" notitle, \
       data index 37 using 1:2 with lines lw 1.8 dt 1 lc rgb "#b85c0a" notitle, \
       data index 38 using 1:2 with lines lw 1.8 dt 1 lc rgb "#cb650b" notitle, \
       data index 39 using 1:2 with lines lw 1.8 dt 1 lc rgb "#dd6e0c" notitle, \
       data index 40 using 1:2 with lines lw 1.8 dt 1 lc rgb "#f0770d" notitle, \
       data index 41 using 1:2 with lines lw 1.8 dt 1 lc rgb "#ff8111" notitle, \
       data index 42 using 1:2 with lines lw 1.8 dt 1 lc rgb "#ff8a23" notitle, \
       data index 43 using 1:2 with lines lw 1.8 dt 1 lc rgb "#ff9334" notitle, \
       data index 44 using 1:2 with lines lw 1.8 dt 1 lc rgb "#ff9d46" notitle, \
       data index 45 using 1:2 with lines lw 1.8 dt 1 lc rgb "#ffa657" notitle, \
       data index 46 using 1:2 with lines lw 1.8 dt 1 lc rgb "#ffaf69" notitle, \
       data index 47 using 1:2 with lines lw 1.8 dt 1 lc rgb "#ffb97a" notitle, \
       data index 48 using 1:2 with lines lw 1.8 dt 1 lc rgb "#60437b" notitle, \
       data index 49 using 1:2 with lines lw 1.8 dt 1 lc rgb "#6b4a89" notitle, \
       data index 50 using 1:2 with lines lw 1.8 dt 1 lc rgb "#765296" notitle, \
       data index 51 using 1:2 with lines lw 1.8 dt 1 lc rgb "#8059a4" notitle, \
       data index 52 using 1:2 with lines lw 1.8 dt 1 lc rgb "#8b61b2" notitle, \
       data index 53 using 1:2 with lines lw 1.8 dt 1 lc rgb "#9569be" notitle, \
       data index 54 using 1:2 with lines lw 1.8 dt 1 lc rgb "#9d74c3" notitle, \
       data index 55 using 1:2 with lines lw 1.8 dt 1 lc rgb "#a57fc8" notitle, \
       data index 56 using 1:2 with lines lw 1.8 dt 1 lc rgb "#ad8acc" notitle, \
       data index 57 using 1:2 with lines lw 1.8 dt 1 lc rgb "#b595d1" notitle, \
       data index 58 using 1:2 with lines lw 1.8 dt 1 lc rgb "#bca0d6" notitle, \
       data index 59 using 1:2 with lines lw 1.8 dt 1 lc rgb "#c4abdb" notitle

  # ---- panel 2: (b) against rescaled time
  reset
  set encoding utf8
  set origin 0.38,0
  set size 0.38,0.94
  set title "(b) against rescaled time"
  set xlabel "t̃ = (z / v_0) √(g / D)"
  set ylabel "F / F_z   (F_z = α μ ρ_g g D² z)"
  set grid lc rgb "#d0d0d0"
  set logscale y
  set yrange [0.3724629164:86.41402287]
  set key at screen 0.77, screen 0.9 left top Left reverse
  set key spacing 1.25
  set object 10 rectangle from graph 0, first 0.8 to graph 1, first 1.2 behind fillcolor rgb "#808080" fillstyle transparent solid 0.18 noborder
  set arrow 1 from first 1, graph 0 to first 1, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "t̃ = 1 (paper)" at first 1, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set ytics ("0.5" 0.5, "1" 1, "2" 2, "5" 5, "10" 10, "20" 20, "50" 50)
  set mytics 10
  set samples 400
  plot data index 120 using 1:3:4 with filledcurves fillcolor rgb "#000000" fillstyle transparent solid 0.22 noborder notitle, \
       keyentry with filledcurves fillcolor rgb "#808080" fillstyle transparent solid 0.36 noborder title "1 ± 0.2", \
       data index 60 using 1:2 with lines lw 1.8 dt 1 lc rgb "#144d75" title "v_0 = 28 cm/s (12 runs)", \
       data index 61 using 1:2 with lines lw 1.8 dt 1 lc rgb "#165682" notitle, \
       data index 62 using 1:2 with lines lw 1.8 dt 1 lc rgb "#195f8f" notitle, \
       data index 63 using 1:2 with lines lw 1.8 dt 1 lc rgb "#1b679c" notitle, \
       data index 64 using 1:2 with lines lw 1.8 dt 1 lc rgb "#1d70a9" notitle, \
       data index 65 using 1:2 with lines lw 1.8 dt 1 lc rgb "#2279b5" notitle, \
       data index 66 using 1:2 with lines lw 1.8 dt 1 lc rgb "#3283ba" notitle, \
       data index 67 using 1:2 with lines lw 1.8 dt 1 lc rgb "#438dc0" notitle, \
       data index 68 using 1:2 with lines lw 1.8 dt 1 lc rgb "#5397c5" notitle, \
       data index 69 using 1:2 with lines lw 1.8 dt 1 lc rgb "#63a0cb" notitle, \
       data index 70 using 1:2 with lines lw 1.8 dt 1 lc rgb "#74aad0" notitle, \
       data index 71 using 1:2 with lines lw 1.8 dt 1 lc rgb "#84b4d6" notitle, \
       data index 72 using 1:2 with lines lw 1.8 dt 1 lc rgb "#8b191a" title "v_0 = 50 cm/s (12 runs)", \
       data index 73 using 1:2 with lines lw 1.8 dt 1 lc rgb "#9b1c1d" notitle, \
       data index 74 using 1:2 with lines lw 1.8 dt 1 lc rgb "#aa1f20" notitle, \
       data index 75 using 1:2 with lines lw 1.8 dt 1 lc rgb "#ba2223" notitle, \
       data index 76 using 1:2 with lines lw 1.8 dt 1 lc rgb "#c92526" notitle, \
       data index 77 using 1:2 with lines lw 1.8 dt 1 lc rgb "#d72a2b" notitle, \
       data index 78 using 1:2 with lines lw 1.8 dt 1 lc rgb "#da3a3b" notitle, \
       data index 79 using 1:2 with lines lw 1.8 dt 1 lc rgb "#dd494a" notitle, \
       data index 80 using 1:2 with lines lw 1.8 dt 1 lc rgb "#e0595a" notitle, \
       data index 81 using 1:2 with lines lw 1.8 dt 1 lc rgb "#e26969" notitle, \
       data index 82 using 1:2 with lines lw 1.8 dt 1 lc rgb "#e57879" notitle, \
       data index 83 using 1:2 with lines lw 1.8 dt 1 lc rgb "#e88889" notitle, \
       data index 84 using 1:2 with lines lw 1.8 dt 1 lc rgb "#1d681d" title "v_0 = 100 cm/s (12 runs)", \
       data index 85 using 1:2 with lines lw 1.8 dt 1 lc rgb "#207420" notitle, \
       data index 86 using 1:2 with lines lw 1.8 dt 1 lc rgb "#237f23" notitle, \
       data index 87 using 1:2 with lines lw 1.8 dt 1 lc rgb "#268b26" notitle, \
       data index 88 using 1:2 with lines lw 1.8 dt 1 lc rgb "#299729" notitle, \
       data index 89 using 1:2 with lines lw 1.8 dt 1 lc rgb "#2fa12f" notitle, \
       data index 90 using 1:2 with lines lw 1.8 dt 1 lc rgb "#3ea83e" notitle, \
       data index 91 using 1:2 with lines lw 1.8 dt 1 lc rgb "#4eaf4e" notitle, \
       data index 92 using 1:2 with lines lw 1.8 dt 1 lc rgb "#5db65d" notitle, \
       data index 93 using 1:2 with lines lw 1.8 dt 1 lc rgb "#6cbd6c" notitle, \
       data index 94 using 1:2 with lines lw 1.8 dt 1 lc rgb "#7cc47c" notitle, \
       data index 95 using 1:2 with lines lw 1.8 dt 1 lc rgb "#8bcb8b" notitle, \
       data index 96 using 1:2 with lines lw 1.8 dt 1 lc rgb "#a65309" title "v_0 = 200 cm/s (12 runs)", \
       data index 97 using 1:2 with lines lw 1.8 dt 1 lc rgb "#b85c0a" notitle, \
       data index 98 using 1:2 with lines lw 1.8 dt 1 lc rgb "#cb650b" notitle, \
       data index 99 using 1:2 with lines lw 1.8 dt 1 lc rgb "#dd6e0c" notitle, \
       data index 100 using 1:2 with lines lw 1.8 dt 1 lc rgb "#f0770d" notitle, \
       data index 101 using 1:2 with lines lw 1.8 dt 1 lc rgb "#ff8111" notitle, \
       data index 102 using 1:2 with lines lw 1.8 dt 1 lc rgb "#ff8a23" notitle, \
       data index 103 using 1:2 with lines lw 1.8 dt 1 lc rgb "#ff9334" notitle, \
       data index 104 using 1:2 with lines lw 1.8 dt 1 lc rgb "#ff9d46" notitle, \
       data index 105 using 1:2 with lines lw 1.8 dt 1 lc rgb "#ffa657" notitle, \
       data index 106 using 1:2 with lines lw 1.8 dt 1 lc rgb "#ffaf69" notitle, \
       data index 107 using 1:2 with lines lw 1.8 dt 1 lc rgb "#ffb97a" notitle, \
       data index 108 using 1:2 with lines lw 1.8 dt 1 lc rgb "#60437b" title "v_0 = 280 cm/s (12 runs)", \
       data index 109 using 1:2 with lines lw 1.8 dt 1 lc rgb "#6b4a89" notitle, \
       data index 110 using 1:2 with lines lw 1.8 dt 1 lc rgb "#765296" notitle, \
       data index 111 using 1:2 with lines lw 1.8 dt 1 lc rgb "#8059a4" notitle, \
       data index 112 using 1:2 with lines lw 1.8 dt 1 lc rgb "#8b61b2" notitle, \
       data index 113 using 1:2 with lines lw 1.8 dt 1 lc rgb "#9569be" notitle, \
       data index 114 using 1:2 with lines lw 1.8 dt 1 lc rgb "#9d74c3" notitle, \
       data index 115 using 1:2 with lines lw 1.8 dt 1 lc rgb "#a57fc8" notitle, \
       data index 116 using 1:2 with lines lw 1.8 dt 1 lc rgb "#ad8acc" notitle, \
       data index 117 using 1:2 with lines lw 1.8 dt 1 lc rgb "#b595d1" notitle, \
       data index 118 using 1:2 with lines lw 1.8 dt 1 lc rgb "#bca0d6" notitle, \
       data index 119 using 1:2 with lines lw 1.8 dt 1 lc rgb "#c4abdb" notitle, \
       data index 120 using 1:2 with lines lw 3 dt 1 lc rgb "#000000" title "mean of the runs ± se"
  unset multiplot
  unset multiplot
  set output
}
