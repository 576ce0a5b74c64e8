# Schäfer & Wolf (1995) Fig. 4: mean Δv_y against v_y^i for impacts on a row of wall grains,
# v_x^i = 0.1 (solid), 0.3 (dashed), 0.5 m/s (dot-dashed), as in the paper, on touching wall grains
# (thick lines). Thin lines: the same on the bistable pipe's wall (grains pipe_wall_spacing apart, 1.3 mm), whose curves
# Fig. 6's construction uses. Error bars (standard error over the 10 start positions) are drawn at
# every 8th point so that the line styles stay visible. Variables set by granrepro: datadir, outbase.
# Parameters set by granrepro: vx_list, wall_spacing, pipe_wall_spacing
set datafile separator "\t"
set key autotitle columnhead
vxs = vx_list
n = words(vxs)
# The pipe's tables exist only where its wall spacing differs from the row's.
np = pipe_wall_spacing ne wall_spacing ? n : 0
colors = "#0072B2 #D55E00 #009E73 #CC79A7 #E69F00 #56B4E9"
dashes = "1 2 4 5 3 6"
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
  # gnuplot 5.4 runs an empty "for [i=1:0]" clause once, so the pipe's clause is left out instead.
  if (np > 0) {
    plot for [i=1:n] datadir.'/impacts_vx'.word(vxs, i).'.tsv' using "vy_i":"dvy" with lines lw 2.5 \
           dt int(word(dashes, (i-1)%6+1)) lc rgb word(colors, (i-1)%6+1) title "v_x^i = ".word(vxs, i)." m/s", \
         for [i=1:n] datadir.'/impacts_vx'.word(vxs, i).'.tsv' using "vy_i":"dvy":"dvy_sem" every 8::(i) with yerrorbars \
           pt 7 ps 0.4 lc rgb word(colors, (i-1)%6+1) notitle, \
         for [i=1:np] datadir.'/impacts_pipe_vx'.word(vxs, i).'.tsv' using "vy_i":"dvy" with lines lw 1 \
           dt int(word(dashes, (i-1)%6+1)) lc rgb word(colors, (i-1)%6+1) \
           title (i == 1 ? sprintf("pipe's wall (%g mm spacing), thin", real(pipe_wall_spacing)*1e3) : "")
  } else {
    plot for [i=1:n] datadir.'/impacts_vx'.word(vxs, i).'.tsv' using "vy_i":"dvy" with lines lw 2.5 \
           dt int(word(dashes, (i-1)%6+1)) lc rgb word(colors, (i-1)%6+1) title "v_x^i = ".word(vxs, i)." m/s", \
         for [i=1:n] datadir.'/impacts_vx'.word(vxs, i).'.tsv' using "vy_i":"dvy":"dvy_sem" every 8::(i) with yerrorbars \
           pt 7 ps 0.4 lc rgb word(colors, (i-1)%6+1) notitle
  }
  unset output
}
