# Luding (1998) Fig. 3: normalised P(b/d) of the ED run of Fig. 2 in successive time windows
# [t_begin, t_end) (impact_parameter_windows.tsv; columns P_t<begin> of impact_parameter_ed.tsv).
# Variables set by granrepro: datadir, outbase, tables.
set datafile separator "\t"
f = datadir.'/impact_parameter_ed.tsv'
w = datadir.'/impact_parameter_windows.tsv'
stats f skip 1 nooutput
ncol = STATS_columns
# The label of window k (row k of the windows table).
stats w using (0) skip 1 nooutput  # every row, whatever it holds
array wl[STATS_records]
do for [k=1:|wl|] {
  stats w using (wl[k] = sprintf("%g s ≤ t < %g s", column(1), column(2)), 0) skip 1 every ::(k-1)::(k-1) nooutput
}
wlabel(k) = wl[k]
colors = "#0072B2 #D55E00 #009E73 #CC79A7 #E69F00 #56B4E9 #000000"
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 800,600 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 5.5in,4.1in enhanced font "Sans,10" }
  set output outbase.'.'.fmt
  set xlabel "b/d"
  set ylabel "P(b/d)"
  set xrange [0:1]
  set grid lc rgb "#dddddd"
  set key top left box opaque
  set title "impact parameter, ED, ρ = 0.25, r = 0.8, collisions in the time windows given"
  plot for [c=2:ncol:2] f using 1:c:(column(c+1)) skip 1 with yerrorlines lw 1.5 pt 7 ps 0.5 \
       lc rgb word(colors, (c/2-1)%7+1) title wlabel(c/2)
  unset output
}
