# Luding (1998) Fig. 6: g(r/d) from ED (solid) and DSMC (dashed) at the snapshot times, shifted
# vertically by 2 per time as in the paper. Variables set by granrepro: datadir, outbase.
set datafile separator "\t"
ed = datadir.'/gr_ed.tsv'
ds = datadir.'/gr_dsmc.tsv'
header = system("head -1 ".ed)
ncol = words(header)
have_dsmc = system("test -f ".ds." && echo 1 || echo 0") + 0
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 800,900 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 5.5in,6.2in enhanced font "Sans,10" }
  set output outbase.'.'.fmt
  set xlabel "r/d"
  set ylabel "g(r/d) + 2 (i - 1)"
  set xrange [0:5]
  set yrange [0:*]
  set grid lc rgb "#dddddd"
  set key top right box opaque
  set title "pair correlation, ED (solid) and DSMC (dashed)"
  if (have_dsmc) {
    plot for [c=2:ncol] ed using 1:(column(c) + 2*(c-2)) skip 1 with lines lw 1.5 lc rgb "#0072B2" \
           title sprintf("ED, %s s", substr(word(header, c), 4, 20)), \
         for [c=2:ncol] ds using 1:(column(c) + 2*(c-2)) skip 1 with lines lw 1.2 dt 2 lc rgb "#D55E00" notitle
  } else {
    plot for [c=2:ncol] ed using 1:(column(c) + 2*(c-2)) skip 1 with lines lw 1.5 lc rgb "#0072B2" \
           title sprintf("ED, %s s", substr(word(header, c), 4, 20))
  }
  unset output
}
