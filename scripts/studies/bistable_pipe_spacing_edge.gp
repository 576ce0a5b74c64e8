# The wall-spacing study of issue 26 as a figure: the slow branch's edge and the fast branch's top
# against the spacing of the wall grains (k_N = 2000 N/m). Between the two lines the pipe is
# bistable; the paper has the edge at e_N ≈ 0.85 (grey line) and bistability for every e_N above.
# Run: gnuplot scripts/studies/bistable_pipe_spacing_edge.gp (from the repository root);
# writes scripts/studies/bistable_pipe_spacing_edge.png.
set terminal pngcairo size 760,520 enhanced font "Sans,11"
set output "scripts/studies/bistable_pipe_spacing_edge.png"
set datafile separator "\t"
set datafile missing "NaN"
set key bottom right opaque box
set xlabel "wall spacing [mm]"
set ylabel "e_N"
set xrange [0.95:1.55]
set yrange [0.72:0.97]
set grid
set arrow 1 from 0.95, 0.85 to 1.55, 0.85 nohead dt 2 lw 2 lc rgb "#999999"
set label 1 "paper: slow branch unstable at e_N ≈ 0.85" at 0.97, 0.843 textcolor rgb "#777777"
set arrow 2 from 1.3, 0.72 to 1.3, 0.97 nohead dt 3 lc rgb "#000000"
set label 2 "chosen 1.3 mm" at 1.305, 0.96
f = "scripts/studies/bistable_pipe_spacing_edge.tsv"
plot f using 1:2 skip 4 with linespoints pt 7 ps 1.4 lw 2 lc rgb "#0072B2" title "slow-branch edge, quick pipe", \
     f using 1:4 skip 4 with linespoints pt 5 ps 1.4 lw 2 lc rgb "#D55E00" title "slow-branch edge, paper pipe", \
     f using 1:3 skip 4 with linespoints pt 6 ps 1.4 lw 1.5 dt 2 lc rgb "#0072B2" title "fast-branch top, quick pipe", \
     f using 1:5 skip 4 with linespoints pt 4 ps 1.4 lw 1.5 dt 2 lc rgb "#D55E00" title "fast-branch top, paper pipe"
