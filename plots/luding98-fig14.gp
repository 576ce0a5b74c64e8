# Luding (1998) Fig. 14: P(N_c) over the last 5 ms of run 0. (a) before arches, semi-log, with the
# exponential Eq. (21); (b) after, log-log, with the power law Eq. (22). A and B are the maximum-
# likelihood fits pooled over the four times (table fits).
# Variables set by granrepro: datadir, outbase.
set datafile separator "\t"
files = system("ls ".datadir."/pnc_t*.tsv")
n = words(files)
fits = datadir.'/fits.tsv'
A = real(system("awk -F'\\t' 'NR==2{print $1}' ".fits))
dA = real(system("awk -F'\\t' 'NR==2{print $2}' ".fits))
B = real(system("awk -F'\\t' 'NR==2{print $3}' ".fits))
dB = real(system("awk -F'\\t' 'NR==2{print $4}' ".fits))
colors = "#0072B2 #D55E00 #009E73 #CC79A7"
points = "7 5 9 11"
Pe(x) = exp(-x/A)/A
Pp(x) = B/(B+x)**2
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 1200,520 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 9in,3.9in enhanced font "Sans,9" }
  set output outbase.'.'.fmt
  set multiplot layout 1,2
  set grid lc rgb "#dddddd"
  set key top right box opaque
  set xlabel "N_c [1/s]"
  set ylabel "P(N_c) [s]"
  unset logscale x
  set format x "%g"
  set logscale y
  set format y "10^{%L}"
  set xrange [0:8000]
  set yrange [1e-8:1e-2]
  set title "(a) before arches (semi-log)"
  plot for [k=1:4] word(files,k) using 1:($2>0?$2:1/0):3 skip 1 with yerrorbars pt int(word(points,k)) ps 0.8 \
         lc rgb word(colors,k) title sprintf("t = %s s", substr(word(files,k), strstrt(word(files,k),"pnc_t")+5, strstrt(word(files,k),".tsv")-1)), \
       Pe(x) with lines lw 2 lc rgb "black" title sprintf("Eq. (21), A = %.0f ± %.0f s^{-1}", A, dA)
  set logscale xy
  set format x "10^{%L}"
  set xrange [100:1e6]
  set yrange [1e-10:1e-2]
  set title "(b) after arches (log-log)"
  plot for [k=5:n] word(files,k) using 1:($2>0?$2:1/0):3 skip 1 with yerrorbars pt int(word(points,k-4)) ps 0.8 \
         lc rgb word(colors,k-4) title sprintf("t = %s s", substr(word(files,k), strstrt(word(files,k),"pnc_t")+5, strstrt(word(files,k),".tsv")-1)), \
       Pp(x) with lines lw 2 lc rgb "black" title sprintf("Eq. (22), B = %.0f ± %.0f s^{-1}", B, dB)
  unset multiplot
  unset output
}
