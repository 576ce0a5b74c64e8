# Luding (1998) Fig. 6: g(r/d) from ED (solid) and DSMC (dashed) at the snapshot times, shifted
# vertically by 2 per time as in the paper; one colour per time for both methods.
# The late ED contact peaks (tens, at r/d just above 1) would squash everything else, so the
# y axis ends just above the highest curve beyond r/d = 1.2 and each ED contact peak (the
# largest g for 1 <= r/d < 1.2, i.e. the first bins) is written in its colour beside its curve's
# baseline at 0 < r/d < 1. The x axis ends with the data (the table's last r/d, rounded up).
# Variables set by granrepro: datadir, outbase, tables, has().
set datafile separator "\t"
ed = datadir.'/gr_ed.tsv'
ds = datadir.'/gr_dsmc.tsv'
stats ed skip 1 nooutput
ncol = STATS_columns
have_dsmc = has('gr_dsmc')
colors = "#000000 #0072B2 #D55E00 #009E73 #CC79A7 #E69F00 #56B4E9 #999999"
col(c) = word(colors, (c-2)%8+1)
shift(c) = 2*(c-2)
# The time is in the column's name (g_t<time>); columnhead() reads it where the plot reads the header.
tlabel(c) = sprintf("t = %s s (+%d)", substr(columnhead(c), 4, 20), shift(c))
stats ed using 1 skip 1 nooutput
rmax = STATS_max
# Top of the y axis: the highest shifted curve (ED or DSMC) beyond the contact region; peak[c]:
# the ED contact peak. (Accumulated inside `using (..., 0)`, so a NaN column is no error.)
ytop = 0
array peak[ncol]
do for [c=2:ncol] {
  peak[c] = 0
  stats ed using (g = column(c), \
                  ytop = ($1 >= 1.2 && g + shift(c) > ytop ? g + shift(c) : ytop), \
                  peak[c] = ($1 >= 1 && $1 < 1.2 && g > peak[c] ? g : peak[c]), 0) skip 1 nooutput
  if (have_dsmc) {
    stats ds using (g = column(c), ytop = ($1 >= 1.2 && g + shift(c) > ytop ? g + shift(c) : ytop), 0) skip 1 nooutput
  }
}
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 900,1000 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 6.2in,6.9in enhanced font "Sans,10" }
  set output outbase.'.'.fmt
  set xlabel "r/d"
  set ylabel "g(r/d) + 2 (i - 1)"
  set xrange [0:ceil(rmax)]
  set xtics 0,1
  set yrange [0:ceil(ytop + 1)]
  set grid lc rgb "#dddddd"
  set key outside right top box opaque font ",9" spacing 1.1
  set title "pair correlation, ED (solid) and DSMC (dashed); ED contact peaks written at left"
  do for [c=2:ncol] {
    set label c sprintf("peak %.3g", peak[c]) at first 0.06, first shift(c) + 0.45 left font ",9" tc rgb col(c) front
  }
  if (have_dsmc) {
    plot for [c=2:ncol] ed using 1:(column(c) + shift(c)) with lines lw 1.5 lc rgb col(c) title tlabel(c), \
         for [c=2:ncol] ds using 1:(column(c) + shift(c)) skip 1 with lines lw 1.5 dt 2 lc rgb col(c) notitle, \
         NaN with lines lw 1.5 lc rgb "black" title "ED", \
         NaN with lines lw 1.5 dt 2 lc rgb "black" title "DSMC"
  } else {
    plot for [c=2:ncol] ed using 1:(column(c) + shift(c)) with lines lw 1.5 lc rgb col(c) title tlabel(c)
  }
  unset label
  unset output
}
