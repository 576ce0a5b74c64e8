# Schäfer & Wolf (1995) Fig. 4: mean Δv_y against v_y^i for impacts on a row of wall grains,
# v_x^i = 0.1 (solid), 0.3 (dashed), 0.5 m/s (dot-dashed), as in the paper, on touching wall grains
# (thick lines). Thin lines: the same on the bistable pipe's wall (grains 1 mm apart), whose curves
# Fig. 6's construction uses. Error bars (standard error over the 10 start positions) are drawn at
# every 8th point so that the line styles stay visible. Variables set by granrepro: datadir, outbase.
set datafile separator "\t"
set key autotitle columnhead
vxs = "0.1 0.3 0.5"
colors = "#0072B2 #D55E00 #009E73"
dashes = "1 2 4"
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 800,560 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 5.5in,3.9in enhanced font "Sans,10" }
  set output outbase.'.'.fmt
  set logscale x
  set format x "10^{%L}"
  set xlabel "v_y^i  [m/s]"
  set ylabel "mean Δv_y  [m/s]"
  set title "row of wall grains, k_N = 2000 N/m, e_N = 0.70, μ = 0.5"
  set grid lc rgb "#dddddd"
  set key below box
  plot for [i=1:3] datadir.'/impacts_vx'.word(vxs, i).'.tsv' using "vy_i":"dvy" with lines lw 2.5 dt int(word(dashes, i)) \
         lc rgb word(colors, i) title "v_x^i = ".word(vxs, i)." m/s", \
       for [i=1:3] datadir.'/impacts_vx'.word(vxs, i).'.tsv' using "vy_i":"dvy":"dvy_sem" every 8::(i) with yerrorbars \
         pt 7 ps 0.4 lc rgb word(colors, i) notitle, \
       for [i=1:3] datadir.'/impacts_pipe_vx'.word(vxs, i).'.tsv' using "vy_i":"dvy" with lines lw 1 dt int(word(dashes, i)) \
         lc rgb word(colors, i) title (i == 1 ? "pipe's wall (1 mm spacing), thin" : "")
  unset output
}
