# Luding (1998) Fig. 5: N = 240, rho = 0.7495, r = 0.80 (left), 0.90 (middle), 0.95 (right).
# Top: the disks at t = 1 s with velocity arrows (a disk at its panel's rms speed gets an arrow
# of 0.8 d; the factor is printed in the title, standing in for the paper's factors 1, 3, 7).
# Bottom: principal stresses of Eq. (9) per cell, averaged over 0.5 s <= t < 1 s (all
# collisions in the cell plus the kinetic term); arm lengths are |sigma| scaled so that the
# panel's sigma_max spans 0.9 cell widths, as the paper scales each panel to its sigma_max.
# Blue arm: larger compression; orange: smaller. Variables set by granrepro: datadir, outbase.
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
  set multiplot layout 2,3 margins 0.06,0.98,0.06,0.88 spacing 0.06,0.1 title \
    "Top: disks at t = 1 s with velocity arrows v × τ, τ chosen per panel so that a disk moving at the panel's v_{rms} gets an arrow of 0.8 d\n(the paper scales its panels by 1, 3, 7 in unstated units; we print τ instead, the velocity ordering they imply is checked as a claim).\nBottom: principal stresses of Eq. (9) per cell (0.5–1 s): each cell's two arms lie along the principal axes, length ∝ |σ|, the panel's σ_{max} spanning 0.9 cell;\nblue arm: the larger compression, orange: the smaller (as the paper, each panel is scaled to its own σ_{max})" font ",10"
  set size ratio -1
  set xrange [0:L]
  set yrange [0:L]
  set xlabel "x / d"
  set ylabel "y / d"
  unset key
  do for [k=1:3] {
    r = word(rl, k)
    stats meta using "arrow_tau" every ::(k-1)::(k-1) nooutput
    tau = STATS_max
    stats meta using "v_rms" every ::(k-1)::(k-1) nooutput
    vr = STATS_max
    set title sprintf("r = %s, t = 1 s: v_{rms} = %.2g m/s, arrow = v × %.2g s", r, vr, tau)
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
