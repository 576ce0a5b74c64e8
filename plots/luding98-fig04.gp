# Luding (1998) Fig. 4: P(b/d) for N = 240 hard disks. (a) rho = 0.7495 and r = 0.80, 0.90,
# 0.95, over the whole run 0-1 s (symbols with Poisson error bars) and over 0.5-1 s (dashed lines,
# both explained in the key);
# (b) the elastic check of Sec. 3.2, r = 1 from dilute to dense; (c) the same in 3D (smooth
# hard spheres), where molecular chaos gives P(b/d) = 2 b/d. Curves are shifted sideways by
# a few thousandths of b/d so that the error bars stay apart. Variables set by granrepro:
# datadir, outbase.
set datafile separator "\t"
set datafile missing "NaN"
set key autotitle columnhead
fi = datadir.'/fig4_inelastic.tsv'
fe = datadir.'/fig4_elastic.tsv'
f3 = datadir.'/fig4_elastic_3d.tsv'

do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 1700,520 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 12.7in,3.9in enhanced font "Sans,9" }
  set output outbase.'.'.fmt
  set multiplot layout 1,3
  set xlabel "b/d"
  set ylabel "P(b/d)"
  set xrange [0:1]
  set grid lc rgb "#dddddd"
  set arrow 1 from 0, first 1 to 1, first 1 nohead dt 3 lc rgb "black"

  set title "(a) ρ = 0.7495, N = 240: symbols 0–1 s, lines 0.5–1 s"
  set yrange [0.5:2.2]
  set key top left box opaque
  # Error bars without a key entry, then the symbols with one, so that each key glyph is the
  # symbol drawn in the panel (a yerrorbars key entry draws a horizontal bar the data never show).
  plot fi using ($1-0.006):"P_r0.80":"err_r0.80" with yerrorbars pt -1 lc rgb "#D55E00" notitle, \
       fi using ($1-0.006):"P_r0.80" with points pt 7 ps 0.7 lc rgb "#D55E00" title "r = 0.80", \
       fi using 1:"P_late_r0.80" with lines lw 1.5 dt 2 lc rgb "#D55E00" notitle, \
       fi using 1:"P_r0.90":"err_r0.90" with yerrorbars pt -1 lc rgb "#0072B2" notitle, \
       fi using 1:"P_r0.90" with points pt 5 ps 0.6 lc rgb "#0072B2" title "r = 0.90", \
       fi using 1:"P_late_r0.90" with lines lw 1.5 dt 2 lc rgb "#0072B2" notitle, \
       fi using ($1+0.006):"P_r0.95":"err_r0.95" with yerrorbars pt -1 lc rgb "#009E73" notitle, \
       fi using ($1+0.006):"P_r0.95" with points pt 9 ps 0.7 lc rgb "#009E73" title "r = 0.95", \
       fi using 1:"P_late_r0.95" with lines lw 1.5 dt 2 lc rgb "#009E73" notitle, \
       keyentry with points pt 7 ps 0.7 lc rgb "black" title "symbols: 0–1 s", \
       keyentry with lines lw 1.5 dt 2 lc rgb "black" title "dashed: 0.5–1 s"

  set title "(b) elastic, r = 1, N = 240: P(b/d) = 1 at every density"
  set yrange [0.85:1.15]
  set key bottom center box opaque horizontal
  plot fe using ($1-0.009):"P_rho0.05":"err_rho0.05" with yerrorbars pt 7 ps 0.6 lc rgb "#E69F00" title "ρ = 0.05", \
       fe using ($1-0.003):"P_rho0.25":"err_rho0.25" with yerrorbars pt 5 ps 0.6 lc rgb "#56B4E9" title "ρ = 0.25", \
       fe using ($1+0.003):"P_rho0.5":"err_rho0.5" with yerrorbars pt 9 ps 0.7 lc rgb "#CC79A7" title "ρ = 0.5", \
       fe using ($1+0.009):"P_rho0.7495":"err_rho0.7495" with yerrorbars pt 11 ps 0.7 lc rgb "#000000" title "ρ = 0.7495"
  unset arrow 1

  set title "(c) elastic spheres in 3D (N = 125): P(b/d) = 2b/d"
  set yrange [0:2.2]
  set key top left box opaque
  plot f3 using 1:"P_2bd" with lines lw 1.5 dt 3 lc rgb "black" title "2b/d", \
       f3 using ($1-0.004):"P_eta0.05":"err_eta0.05" with yerrorbars pt 7 ps 0.6 lc rgb "#E69F00" title "η = 0.05", \
       f3 using ($1+0.004):"P_eta0.3":"err_eta0.3" with yerrorbars pt 5 ps 0.6 lc rgb "#0072B2" title "η = 0.3"
  unset multiplot
  unset output
}
