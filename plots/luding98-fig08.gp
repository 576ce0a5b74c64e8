# Luding (1998) Fig. 8: N = 784, L = 50, t_c = fig8_t_c (1e-6 s), r as in the key. Single runs (seed 0), as
# the paper shows them. (a) K/K0 against C/N = 2 (pair collisions)/N, with the line
# exp(-(1-r^2) C/N / 2) that Eq. (18) implies (dashed, same colour; see parameter_study.cpp).
# (b) (K_x - K_y)/K against C/N: ~0 while homogeneous, near +-1 in the shearing mode.
# One key for both panels (same colours), below panel (a), off the curves; both panels keep the
# same bottom margin so that their axes line up.
# Variables set by granrepro: datadir, outbase.
# Parameters set by granrepro: fig8_r, fig8_t_c
set datafile separator "\t"
set datafile missing "NaN"
rlist = fig8_r
n = words(rlist)
# Okabe-Ito: colour-blind safe
colors = "#0072B2 #D55E00 #009E73 #CC79A7 #E69F00 #56B4E9 #000000"
f(k) = datadir.'/run_r'.word(rlist, k).'_tc'.fig8_t_c.'.tsv'
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 1400,560 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 10in,4in enhanced font "Sans,9" }
  set output outbase.'.'.fmt
  set multiplot layout 1,2
  set bmargin 6
  set grid lc rgb "#dddddd"
  set logscale y
  set format y "10^{%L}"
  set xlabel "C/N"
  set ylabel "K/K_0"
  set yrange [1e-12:1.5]
  set xrange [0:*]
  set key below horizontal maxrows 2 box
  set title "(a) t_c = ".fig8_t_c." s, single runs; dashed: exp(-(1-r^2) C/N / 2)"
  plot for [k=1:n] f(k) using "C_over_N":"K_over_K0" with lines lw 2 lc rgb word(colors, (k-1)%7+1) title "r = ".word(rlist, k), \
       for [k=1:n] f(k) using "C_over_N":"exp_line" with lines lw 1 dt 2 lc rgb word(colors, (k-1)%7+1) notitle
  unset logscale y
  set format y "% h"
  set logscale x
  set format x "10^{%L}"
  set xrange [0.1:*]
  set yrange [-1.05:1.05]
  set ylabel "(K_x - K_y)/K"
  unset key
  set title "(b) anisotropy, colours as in (a); ±1 is the shearing mode"
  plot for [k=1:n] f(k) using "C_over_N":"anisotropy" with lines lw 1.5 lc rgb word(colors, (k-1)%7+1) notitle
  unset logscale x
  set format x "% h"
  unset multiplot
  set bmargin
  unset output
}
