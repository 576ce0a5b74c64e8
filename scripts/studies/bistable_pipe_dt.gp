# Issue 42: the fast starts' speed against the steps a grain takes to pass one wall grain at that
# speed, wall_spacing / (v dt), for every run of scripts/studies/bistable_pipe_dt.sh (its table
# bistable_pipe_dt.tsv). Filled: steady states at a fixed step t_col/N (Eq. 5 is N = 50); open:
# no steady state (last speed); crosses: the wall rule (dt <= wall_spacing / (32 v_max)).
# Vertical lines: whole numbers of steps per wall grain, where the fixed-step states lock.
#   gnuplot -e "tsv='scripts/studies/bistable_pipe_dt.tsv'; out='scripts/studies/bistable_pipe_dt.png'" scripts/studies/bistable_pipe_dt.gp
set datafile separator "\t"
set terminal pngcairo size 900,640 enhanced font "Sans,11"
set output out
set logscale xy
set xrange [1:200]
set yrange [10:1000]
set xlabel "steps while the plug passes one wall grain, wall spacing / (v dt)"
set ylabel "fast start: speed [m/s] (steady, or last if not steady)"
set title "Fig. 6 fast starts (paper pipe, 10 m/s starts): the speed follows the time step"
set grid lc rgb "#dddddd"
do for [n=2:40] { set arrow from n, graph 0 to n, graph 1 nohead lc rgb (n % 5 == 0 ? "#bbbbbb" : "#eeeeee") back }
set key top right box
fixed(r) = strstrt(r, "t_col/") == 1 && strstrt(r, "beside") == 0
sel(k, e, steady) = (strcol(1) eq "paper" && column(2) == k && abs(column(3) - e) < 1e-9 && strcol(6) eq "fast" && fixed(strcol(5)) && ((strcol(9) eq "steady") == steady)) ? column(10) : NaN
wall(k) = (strcol(1) eq "paper" && column(2) == k && strcol(6) eq "fast" && strstrt(strcol(5), "wall") == 1) ? column(10) : NaN
plot for [ke in "2000:0.5 2000:0.7 2000:0.9 2000:0.95 200:0.7 200:0.95"] \
       tsv using 13:(sel(real(ke[1:strstrt(ke, ":") - 1]), real(ke[strstrt(ke, ":") + 1:]), 1)) with points pt 7 ps 1.4 \
       title sprintf("k_N = %s N/m, e_N = %s, fixed step", ke[1:strstrt(ke, ":") - 1], ke[strstrt(ke, ":") + 1:]), \
     for [ke in "2000:0.5 2000:0.7 2000:0.9 2000:0.95 200:0.7 200:0.95"] \
       tsv using 13:(sel(real(ke[1:strstrt(ke, ":") - 1]), real(ke[strstrt(ke, ":") + 1:]), 0)) with points pt 6 ps 1.4 notitle, \
     tsv using 13:(wall(2000)) with points pt 2 ps 1.6 lc rgb "black" title "k_N = 2000 N/m, wall rule (no steady state)", \
     tsv using 13:(wall(200)) with points pt 3 ps 1.6 lc rgb "#555555" title "k_N = 200 N/m, wall rule (no steady state)"
