# Schäfer & Wolf (1995) Fig. 5: mean number of wall grains touched per impact against v_y^i,
# v_x^i = 0.1 (solid), 0.3 (dashed), 0.5 m/s (dot-dashed). The line at 2 marks the onset of the
# multiple-contact regime. Variables set by granrepro: datadir, outbase.
set datafile separator "\t"
set key autotitle columnhead
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 800,560 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 5.5in,3.9in enhanced font "Sans,10" }
  set output outbase.'.'.fmt
  set logscale x
  set format x "10^{%L}"
  set xlabel "v_y^i  [m/s]"
  set ylabel "number of contacts"
  set title "wall grains touched per impact (mean over 10 start positions)"
  set grid lc rgb "#dddddd"
  set key top left box opaque
  set arrow from graph 0, first 2 to graph 1, first 2 nohead dt 3 lc rgb "black"
  plot datadir.'/impacts_vx0.1.tsv' using "vy_i":"contacts" with linespoints lw 2 dt 1 pt 7 ps 0.5 lc rgb "#0072B2" title "v_x^i = 0.1 m/s", \
       datadir.'/impacts_vx0.3.tsv' using "vy_i":"contacts" with linespoints lw 2 dt 2 pt 5 ps 0.5 lc rgb "#D55E00" title "v_x^i = 0.3 m/s", \
       datadir.'/impacts_vx0.5.tsv' using "vy_i":"contacts" with linespoints lw 2 dt 4 pt 9 ps 0.6 lc rgb "#009E73" title "v_x^i = 0.5 m/s"
  unset arrow
  unset output
}
