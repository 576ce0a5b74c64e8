# Schäfer & Wolf (1995) Fig. 6: steady-state mean velocity in a vertical pipe against e_N for each
# k_N, from slow starts (filled symbols, solid lines) and fast starts (filled symbols, dashed lines,
# shifted right by 0.006 in e_N so that coinciding states stay visible), at the run's time step
# (time_step; by default dt resolving the passage of a grain along the wall grains). Open symbols,
# dotted lines, shifted by 0.012: the fast starts at Eq. (5)'s step, t_col/50 throughout (the
# paper's stated Δt; columns *_fast_eq5), whose fast states lock to the step (issue 42). A run that
# reached no steady state is drawn as an arrow pointing up from its last speed (outcome 1: free
# fall, 2: still drifting or past v_abort).
# Lines join a start's states within one regime (normal or emergency brake) only.
# Dotted lines: v_crit of each k_N (Eq. 8: v_crit = v_crit_2000 sqrt(k_N / 2000 N/m)), the border
# between the normal regime and brake failure.
# The paper's numbers (text below Fig. 6, k_N = 2000 N/m), grey dashes named "paper: ..." in the
# key: the slow branch "gets unstable at e_N ≈ 0.85" (vertical line; the light band is half a grid
# step either side, the claim's tolerance), and the fast branch comes from "high initial mean
# velocities ≈ 5-10 m/s" (horizontal band between dashed lines: a start speed, not a steady one;
# ours start at fast_v0). A script reads no claim: the same numbers are in
# expected/bistable-pipe.toml, claims slow_branch_unstable_near_0.85 (paper = 0.85) and
# fast_branch_k2000 (its statement: fast starts 5-10 m/s; fast_v0 is calibrated on it).
# The speed axis is logarithmic: the slow and fast branches differ by up to a factor 100, and
# v_crit spans 1.3-40 m/s over the three k_N.
# Variables set by granrepro: datadir, outbase, tables.
# Parameters set by granrepro: v_crit_2000, fast_v0
paper_edge = 0.85
paper_fast_lo = 5.0
paper_fast_hi = 10.0
set datafile separator "\t"
set datafile missing "NaN"
# The steady_k<k_N> tables, k_N ascending (granrepro lists them in numeric order).
steady = ''
do for [i=1:words(tables)] { if (strstrt(word(tables, i), 'steady_k') == 1) { steady = steady.' '.word(tables, i) } }
kname(i) = word(steady, i)[9:]
file(i) = datadir.'/'.word(steady, i).'.tsv'
# A start's steady speed if its regime is em (0 normal, 1 emergency brake), else NaN.
# (The Eq. (5) runs have no impact count: their steady states are drawn as one series, em = 1.)
regime(s) = (s eq "fast_eq5") ? 1 : (column("impact_contacts_".s) >= 2 ? 1 : 0)
regv(s, em) = (column("v_".s) == column("v_".s) && regime(s) == em) ? column("v_".s) : NaN
colors = "#0072B2 #D55E00 #009E73"
filled = "7 5 9"
open = "6 4 8"
# A series with no row to draw (a column that is NaN throughout: NaN != NaN) is left out of the
# plot command, instead of drawing nothing with a warning. The command names each table as
# file(i), never by its path: a path with a quote in it would end the string and be run as code.
cmd = "plot '+' using (0.5):(1) every ::0::0 with dots lc rgb 'white' notitle"
do for [i=1:words(steady)] {
  f = file(i)
  do for [s in "slow fast fast_eq5"] {
    shift = (s eq "fast") ? "0.006" : ((s eq "fast_eq5") ? "0.012" : "0")
    style = sprintf("with linespoints pt %s ps %s lw 1.5 dt %s lc rgb '%s'", (s eq "fast_eq5") ? word(open, i) : word(filled, i), \
      (s eq "slow") ? "1.3" : "1.1", (s eq "slow") ? "1" : ((s eq "fast") ? "2" : "3"), word(colors, i))
    label = (s eq "fast_eq5") ? "fast start, Eq. (5) Δt" : s." start"
    # Every series has its legend entry, whether or not it has a steady state to draw; the Eq. (5)
    # fast starts only where they were run (time_step = wall; under eq5 the fast start is one).
    stats f using (column("outcome_".s) == column("outcome_".s) ? 1 : 0) nooutput
    if ((s ne "fast_eq5") + (STATS_sum > 0) > 0) {
      cmd = cmd.sprintf(", NaN %s title 'k_N = %s N/m, %s'", style, kname(i), label)
    }
    # The line joins states of one regime only (Fig. 5's criterion: fewer than two wall grains
    # per impact is the normal regime, two or more the emergency brake), so a start that lands on
    # the other branch at the next e_N is not drawn as a line through the gap between the branches.
    do for [em=0:1] {
      stats f using (regv(s, em) == regv(s, em) ? 1 : 0) nooutput
      if (STATS_sum > 0) {
        cmd = cmd.sprintf(", file(%d) using ($1 + %s):(regv('%s', %d)) %s notitle", i, shift, s, em, style)
      }
    }
    stats f using (column("outcome_".s) > 0 ? 1 : 0) nooutput
    if (STATS_sum > 0) {
      cmd = cmd.sprintf(", file(%d) using ($1 + %s):(column('outcome_%s') > 0 ? column('v_last_%s') : NaN):(0):(column('v_last_%s') * 0.6) with vectors head %s size screen 0.008,20 lw 1.5 lc rgb '%s' notitle", \
        i, shift, s, s, s, (s eq "fast_eq5") ? "empty" : "filled", word(colors, i))
    }
  }
}
cmd = cmd.", NaN with vectors head filled lw 1.5 lc rgb 'black' title 'no steady state: arrow up from its last speed'"
cmd = cmd.sprintf(", NaN with lines dt 2 lw 2 lc rgb '#999999' title 'paper: slow branch (k_N = 2000 N/m) unstable at e_N ≈ %g (band: ± half a grid step)'", paper_edge)
cmd = cmd.sprintf(", %g with lines dt 2 lw 2 lc rgb '#999999' title 'paper: fast starts at ≈ %g-%g m/s (initial speed; ours %s m/s)', %g with lines dt 2 lw 2 lc rgb '#999999' notitle", \
  paper_fast_lo, paper_fast_lo, paper_fast_hi, fast_v0, paper_fast_hi)
vcrit(i) = real(v_crit_2000) * sqrt(real(kname(i)) / 2000.0)
do for [i=1:words(steady)] {
  cmd = cmd.sprintf(", %.6g with lines dt 3 lw 1.5 lc rgb '%s' title 'v_{crit} = %.3g m/s (k_N = %s N/m)'", vcrit(i), word(colors, i), vcrit(i), kname(i))
}
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 900,760 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 6.3in,5.3in enhanced font "Sans,10" }
  set output outbase.'.'.fmt
  set xlabel "e_N (free grain on a wall grain)"
  set ylabel "mean velocity  [m/s]  (log scale)"
  set object 1 rect from paper_edge - 0.025, graph 0 to paper_edge + 0.025, graph 1 fillcolor rgb "#ededed" fillstyle solid noborder behind
  set object 2 rect from graph 0, first paper_fast_lo to graph 1, first paper_fast_hi fillcolor rgb "#ededed" fillstyle solid noborder behind
  set arrow 1 from paper_edge, graph 0 to paper_edge, graph 1 nohead dt 2 lw 2 lc rgb "#999999" back
  set title "vertical pipe, width 2 cm, φ = 0.55, μ = 0.5; filled: the run's time step, open: Eq. (5)'s where it differs"
  set grid lc rgb "#dddddd"
  set logscale y
  set format y "%g"
  set xrange [0.45:1.02]
  set yrange [0.3:800]
  set key below box Left reverse maxrows 6
  eval cmd
  unset output
}
