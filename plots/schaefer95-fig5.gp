# Schäfer & Wolf (1995) Fig. 5: mean number of wall grains touched per impact against v_y^i,
# v_x^i = 0.1 (solid), 0.3 (dashed), 0.5 m/s (dot-dashed). The line at 2 marks the onset of the
# multiple-contact regime. Variables set by granrepro: datadir, outbase.
# Parameters set by granrepro: vx_list
set datafile separator "\t"
set key autotitle columnhead
colors = "#0072B2 #D55E00 #009E73 #CC79A7 #E69F00 #56B4E9"
dashes = "1 2 4 5 3 6"
points = "7 5 9 11 13 15"
sizes = "0.5 0.5 0.6 0.6 0.6 0.6"
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
  plot for [i=1:words(vx_list)] datadir.'/impacts_vx'.word(vx_list, i).'.tsv' using "vy_i":"contacts" with linespoints \
         lw 2 dt int(word(dashes, (i-1)%6+1)) pt int(word(points, (i-1)%6+1)) ps real(word(sizes, (i-1)%6+1)) lc rgb word(colors, (i-1)%6+1) \
         title "v_x^i = ".word(vx_list, i)." m/s"
  unset arrow
  unset output
}
