# Luding (1998) Fig. 7: S(k) against k = l/lambda at the snapshot times, (a) ED, (b) DSMC (first
# seed). Dashed: S(0) of the elastic hard-disk gas at this density (Henderson's equation of state),
# the level an equilibrated start would have at small k; the t = 0 curve lies below it where the
# long waves still remember the lattice start. The x axis ends with the data (the largest k in
# the table, 256 at paper scale); the key, in two columns, sits at the bottom right: at k > 10
# S(k) stays near or above S(0) = 0.33 there. Variables set by granrepro: datadir, outbase, tables, has().
set datafile separator "\t"
ed = datadir.'/sk_ed.tsv'
ds = datadir.'/sk_dsmc.tsv'
stats ed skip 1 nooutput
ncol = STATS_columns - 1  # the last column is S_equilibrium
have_dsmc = has('sk_dsmc')
stats ed using 1 skip 1 nooutput
kmin = STATS_min
kmax = STATS_max
colors = "#000000 #0072B2 #D55E00 #009E73 #CC79A7 #E69F00 #56B4E9 #999999"
points = "1 2 4 6 8 10 12 3"
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 1200,520 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 9in,3.9in enhanced font "Sans,9" }
  set output outbase.'.'.fmt
  set multiplot layout 1,2
  set logscale xy
  set xrange [kmin:kmax]
  set xlabel "k = l/λ"
  set ylabel "S(k)"
  set grid lc rgb "#dddddd"
  set key bottom right box opaque maxrows 5 samplen 2 font ",9"
  set title "(a) ED"
  plot for [c=2:ncol] ed using 1:c with linespoints lw 1 pt int(word(points,(c-2)%8+1)) ps 0.5 \
       lc rgb word(colors,(c-2)%8+1) title sprintf("t = %s s", substr(columnhead(c), 4, 20)), \
       ed using 1:(column(ncol+1)) skip 1 with lines lw 1.5 dt 2 lc rgb "black" title "S(0), elastic"
  set title "(b) DSMC"
  if (have_dsmc) {
    plot for [c=2:ncol] ds using 1:c with linespoints lw 1 pt int(word(points,(c-2)%8+1)) ps 0.5 \
         lc rgb word(colors,(c-2)%8+1) title sprintf("t = %s s", substr(columnhead(c), 4, 20)), \
         ds using 1:(column(ncol+1)) skip 1 with lines lw 1.5 dt 2 lc rgb "black" title "S(0), elastic"
  }
  unset multiplot
  unset output
}
