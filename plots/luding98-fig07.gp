# Luding (1998) Fig. 7: S(k) against k = l/lambda at the snapshot times, (a) ED, (b) DSMC.
# Variables set by granrepro: datadir, outbase.
set datafile separator "\t"
ed = datadir.'/sk_ed.tsv'
ds = datadir.'/sk_dsmc.tsv'
header = system("head -1 ".ed)
ncol = words(header)
have_dsmc = system("test -f ".ds." && echo 1 || echo 0") + 0
colors = "#000000 #0072B2 #D55E00 #009E73 #CC79A7 #E69F00 #56B4E9"
points = "1 2 4 6 8 10 12"
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 1200,520 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 9in,3.9in enhanced font "Sans,9" }
  set output outbase.'.'.fmt
  set multiplot layout 1,2
  set logscale xy
  set xlabel "k = l/λ"
  set ylabel "S(k)"
  set grid lc rgb "#dddddd"
  set key top right box opaque
  set title "(a) ED"
  plot for [c=2:ncol] ed using 1:c skip 1 with linespoints lw 1 pt word(points,(c-2)%7+1) ps 0.5 \
       lc rgb word(colors,(c-2)%7+1) title sprintf("t = %s s", substr(word(header, c), 4, 20))
  set title "(b) DSMC"
  if (have_dsmc) {
    plot for [c=2:ncol] ds using 1:c skip 1 with linespoints lw 1 pt word(points,(c-2)%7+1) ps 0.5 \
         lc rgb word(colors,(c-2)%7+1) title sprintf("t = %s s", substr(word(header, c), 4, 20))
  }
  unset multiplot
  unset output
}
