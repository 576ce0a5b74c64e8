# Luding (1998) Fig. 6: g(r/d) from ED (solid) and DSMC (dashed) at the snapshot times, shifted
# vertically by 2 per time as in the paper; one colour per time for both methods.
# Variables set by granrepro: datadir, outbase, tables, has().
set datafile separator "\t"
ed = datadir.'/gr_ed.tsv'
ds = datadir.'/gr_dsmc.tsv'
stats ed skip 1 nooutput
ncol = STATS_columns
have_dsmc = has('gr_dsmc')
colors = "#000000 #0072B2 #D55E00 #009E73 #CC79A7 #E69F00 #56B4E9 #999999"
col(c) = word(colors, (c-2)%8+1)
# The time is in the column's name (g_t<time>); columnhead() reads it where the plot reads the header.
tlabel(c) = sprintf("t = %s s (+%d)", substr(columnhead(c), 4, 20), 2*(c-2))
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 800,1000 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 5.5in,6.9in enhanced font "Sans,10" }
  set output outbase.'.'.fmt
  set xlabel "r/d"
  set ylabel "g(r/d) + 2 (i - 1)"
  set xrange [0:6.8]
  set xtics 0,1,5
  set yrange [0:*]
  set grid lc rgb "#dddddd"
  set key top right box opaque font ",9" spacing 1.1
  set title "pair correlation, ED (solid) and DSMC (dashed)"
  if (have_dsmc) {
    plot for [c=2:ncol] ed using 1:(column(c) + 2*(c-2)) with lines lw 1.5 lc rgb col(c) title tlabel(c), \
         for [c=2:ncol] ds using 1:(column(c) + 2*(c-2)) skip 1 with lines lw 1.5 dt 2 lc rgb col(c) notitle, \
         NaN with lines lw 1.5 lc rgb "black" title "ED", \
         NaN with lines lw 1.5 dt 2 lc rgb "black" title "DSMC"
  } else {
    plot for [c=2:ncol] ed using 1:(column(c) + 2*(c-2)) with lines lw 1.5 lc rgb col(c) title tlabel(c)
  }
  unset output
}
