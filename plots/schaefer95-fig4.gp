# Schäfer & Wolf (1995) Fig. 4: mean Δv_y against v_y^i for impacts on a row of wall grains,
# v_x^i = 0.1 (solid), 0.3 (dashed), 0.5 m/s (dot-dashed), as in the paper; error bars are the
# standard error over the start positions. Variables set by granrepro: datadir, outbase.
set datafile separator "\t"
set key autotitle columnhead
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
  set key top left box opaque
  plot datadir.'/impacts_vx0.1.tsv' using "vy_i":"dvy" with lines lw 2 dt 1 lc rgb "#0072B2" title "v_x^i = 0.1 m/s", \
       '' using "vy_i":"dvy":"dvy_sem" with yerrorbars pt 7 ps 0.4 lc rgb "#0072B2" notitle, \
       datadir.'/impacts_vx0.3.tsv' using "vy_i":"dvy" with lines lw 2 dt 2 lc rgb "#D55E00" title "v_x^i = 0.3 m/s", \
       '' using "vy_i":"dvy":"dvy_sem" with yerrorbars pt 7 ps 0.4 lc rgb "#D55E00" notitle, \
       datadir.'/impacts_vx0.5.tsv' using "vy_i":"dvy" with lines lw 2 dt 4 lc rgb "#009E73" title "v_x^i = 0.5 m/s", \
       '' using "vy_i":"dvy":"dvy_sem" with yerrorbars pt 7 ps 0.4 lc rgb "#009E73" notitle
  unset output
}
