# Luding (1998) Fig. 10: the TCED run of Section 4.2 (r = 0.8, t_c = 1e-5 s, rho = 0.25).
# (a) K/K0 against t; solid: slope -2, the t >> t0 asymptote (t/t0)^-2 of Eq. (18) (t0 from
# kinetic theory); dotted: Eq. (18) itself; dashed: slope -1, drawn a factor 5 above the late
# samples (through them it would hide under the data it describes) and last, on top.
# (b) C/N (circles) and TC-elastic collisions per particle (squares) against t.
# Variables set by granrepro: datadir, outbase.
set datafile separator "\t"
set datafile missing "NaN"
set key autotitle columnhead
f = datadir.'/energy.tsv'
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 1400,560 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 10in,4in enhanced font "Sans,9" }
  set output outbase.'.'.fmt
  set multiplot layout 1,2
  set grid lc rgb "#dddddd"
  set logscale xy
  set format x "10^{%L}"
  set format y "10^{%L}"
  set xlabel "t [s]"
  set xrange [1e-3:*]
  set ylabel "K/K_0"
  set yrange [*:2]
  set key bottom left box opaque
  set title "(a) K(t), r = 0.8, t_c = 10^{-5} s"
  plot f using "t":"K_over_K0" with linespoints lw 2 pt 7 ps 0.5 lc rgb "#0072B2" title "TCED", \
       f using "t":"eq18" with lines lw 1.2 dt 3 lc rgb "black" title "Eq. (18)", \
       f using "t":"slope_minus2" with lines lw 1.5 lc rgb "#D55E00" title "slope -2", \
       f using "t":(column("slope_minus1")*5) with lines lw 2 dt 2 lc rgb "#009E73" title "slope -1 (×5)"
  set ylabel "collisions per particle"
  set yrange [*:*]
  set key top left box opaque
  set title "(b) C/N (circles) and elastic collisions per particle (squares)"
  plot f using "t":"C_over_N" with points pt 6 ps 0.8 lc rgb "#0072B2" title "C/N", \
       f using "t":"elastic_C_over_N" with points pt 4 ps 0.8 lc rgb "#D55E00" title "elastic (TC) C/N"
  unset multiplot
  unset output
}
