# Luding (1998) Fig. 5: N = 240, rho = 0.7495, r = 0.80 (left), 0.90 (middle), 0.95 (right).
# Caption. Top: the disks at t = 1 s with velocity arrows v x tau; tau is chosen per panel so
# that a disk moving at its panel's rms speed gets an arrow of 0.8 d (arrow_rms_length), and each
# panel's title prints tau and tau relative to the left panel. Bottom: principal stresses of
# Eq. (9) per cell, averaged over 0.5 s <= t < 1 s (all collisions in the cell plus the kinetic
# term); each cell's two arms lie along the principal axes with length proportional to |sigma|,
# the panel's sigma_max spanning 0.9 cell widths, as the paper scales each panel to its own
# sigma_max. Blue arm: the larger compression; orange: the smaller.
# Why not the paper's arrow factors 1, 3, 7: their units are not stated, and they only make
# arrows of similar length if v(0.8) : v(0.9) : v(0.95) = 21 : 7 : 3. In our runs r = 0.9 is
# the slowest panel and r = 0.95 about as fast as r = 0.8 (paper scale, 32 seeds, geometric
# means: v(0.8)/v(0.9) = 2.4, v(0.8)/v(0.95) = 1.1; scripts/studies/fig5_scan.md), so with
# 1, 3, 7 the right panel's arrows would be ~6 times the left panel's: 0.8 d on the left would
# mean ~5 d, a third of the box, on the right. The order the factors imply is checked as a claim (velocity_order_arrow_factors,
# scripts/studies/fig5_scan.sh); the relative tau in the titles is our counterpart of 1, 3, 7.
# Variables set by granrepro: datadir, outbase.
set datafile separator "\t"
set key autotitle columnhead
meta = datadir.'/fig5_meta.tsv'
rl = "0.80 0.90 0.95"
stats meta using "box_over_d" nooutput
L = STATS_max
ncell = 5

do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 1350,1000 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 10in,7.4in enhanced font "Sans,9" }
  set output outbase.'.'.fmt
  set multiplot layout 2,3 margins 0.06,0.98,0.06,0.92 spacing 0.06,0.1 title \
    "Luding (1998) Fig. 5: N = 240, ρ = 0.7495; top: velocities at t = 1 s, bottom: Eq. (9) stresses 0.5–1 s" font ",12"
  set size ratio -1
  set xrange [0:L]
  set yrange [0:L]
  set xlabel "x / d"
  set ylabel "y / d"
  unset key
  stats meta using "arrow_tau" every ::0::0 nooutput
  tau1 = STATS_max
  do for [k=1:3] {
    r = word(rl, k)
    stats meta using "arrow_tau" every ::(k-1)::(k-1) nooutput
    tau = STATS_max
    stats meta using "v_rms" every ::(k-1)::(k-1) nooutput
    vr = STATS_max
    set title sprintf("r = %s: v_{rms} = %.2g m/s, arrow = v × %.2g s\n(%.2g × the left panel's; paper: %s)", r, vr, tau, tau/tau1, word("1 3 7", k))
    f = datadir.'/fig5_snapshot_r'.r.'.tsv'
    plot f using "x_over_d":"y_over_d":(0.5) with circles fs transparent solid 0.25 lc rgb "#999999", \
         f using "x_over_d":"y_over_d":"arrow_x_over_d":"arrow_y_over_d" with vectors head size 0.35,25 filled lw 1.2 lc rgb "#0072B2"
  }
  set grid front xtics ytics lc rgb "#888888" lw 1 dt 1
  set xtics 0, L/ncell, L format "%.1f"
  set ytics 0, L/ncell, L format "%.1f"
  do for [k=1:3] {
    r = word(rl, k)
    stats meta using "sigma_max" every ::(k-1)::(k-1) nooutput
    sm = STATS_max
    set title sprintf("r = %s, stress 0.5–1 s: σ_{max} = %.3g N/m", r, sm)
    f = datadir.'/fig5_stress_r'.r.'.tsv'
    plot f using ($1-column("axis1_x_over_d")):($2-column("axis1_y_over_d")):(2*column("axis1_x_over_d")):(2*column("axis1_y_over_d")) with vectors nohead lw 2.5 lc rgb "#0072B2", \
         f using ($1-column("axis2_x_over_d")):($2-column("axis2_y_over_d")):(2*column("axis2_x_over_d")):(2*column("axis2_y_over_d")) with vectors nohead lw 2.5 lc rgb "#E69F00"
  }
  unset grid
  set xtics autofreq format "% h"
  set ytics autofreq format "% h"
  unset multiplot
  unset output
}
