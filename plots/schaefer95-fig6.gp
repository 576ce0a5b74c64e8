# Schäfer & Wolf (1995) Fig. 6: steady-state mean velocity in a vertical pipe against e_N, one
# symbol per k_N; filled symbols: slow starts, open symbols: fast starts. Runs that reached no
# steady state are not plotted (their final speeds are in the tables, columns *_final).
# Variables set by granrepro: datadir, outbase.
set datafile separator "\t"
set datafile missing "NaN"
set key autotitle columnhead
files = system("ls ".datadir."/steady_k*.tsv 2>/dev/null")
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 800,560 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 5.5in,3.9in enhanced font "Sans,10" }
  set output outbase.'.'.fmt
  set xlabel "e_N"
  set ylabel "steady-state mean velocity  [m/s]"
  set title "vertical pipe, width 2 cm, φ = 0.55, μ = 0.5"
  set grid lc rgb "#dddddd"
  set key top right box opaque
  set xrange [0.45:1.02]
  set yrange [0:*]
  colors = "#0072B2 #D55E00 #009E73"
  # The invisible point keeps gnuplot from aborting when no run reached a steady state.
  plot '+' using (0.5):(0) every ::0::0 with dots lc rgb "white" notitle, \
       for [i=1:words(files)] word(files, i) using "e_N":"v_slow" with linespoints pt 7 ps 1.2 lw 1.5 lc rgb word(colors, i) \
         title sprintf("k_N = %s N/m, slow start", system("basename ".word(files, i)." .tsv | sed 's/steady_k//'")), \
       for [i=1:words(files)] word(files, i) using "e_N":"v_fast" with linespoints pt 6 ps 1.4 lw 1.5 dt 2 lc rgb word(colors, i) \
         title sprintf("k_N = %s N/m, fast start", system("basename ".word(files, i)." .tsv | sed 's/steady_k//'"))
  unset output
}
