# Issue 43 §1 (Luding 1998 Sec. 5, Fig. 13): the crack study's table as a figure. Per config (side-wall
# jitter, lattice registration, relaxation without gravity, and the interparticle rows of
# pipe_arching_crack.sh, rerun here as frame runs), from the frame runs of each: the share of seeds whose local opening at the
# initiating disk (over its own width, within 10 ms after the arch) exceeds 0.3 d and 0.5 d, the same
# over 3 d of the wall, the widest wall-to-wall gap within 10 ms after the arch (largest seed, in d),
# and the median share of the first arch still white 4 ms later (the paper: "almost disappeared",
# read as <= 0.25, grey line). A crack of Fig. 13 would put the wall-to-wall gap at 0.5 d (grey line).
# Run: gnuplot scripts/studies/pipe_arching_walls.gp (from the repository root);
# writes scripts/studies/pipe_arching_walls.png. Data: scripts/studies/pipe_arching_walls.tsv.
set terminal pngcairo size 1000,560 enhanced font "Sans,11"
set output "scripts/studies/pipe_arching_walls.png"
set datafile separator "\t"
set datafile missing "nan"
set key outside right top box
set ylabel "share of seeds, opening [d], share of the arch"
set yrange [0:1.05]
set xrange [-0.6:10.6]
set xtics rotate by -35 font ",10"
set grid ytics
set arrow 1 from -0.6, 0.5 to 10.6, 0.5 nohead dt 2 lw 1.5 lc rgb "#999999"
set arrow 2 from -0.6, 0.25 to 10.6, 0.25 nohead dt 3 lw 1.5 lc rgb "#999999"
set label 1 "0.5 d: a visible crack" at -0.5, 0.53 textcolor rgb "#777777"
set label 2 "0.25: almost disappeared" at -0.5, 0.22 textcolor rgb "#777777"
f = "scripts/studies/pipe_arching_walls.tsv"
plot f using 1:7:xtic(2) with points pt 7 ps 1.6 lc rgb "#0072B2" title "local, own width: share > 0.3 d", \
     f using 1:8 with points pt 5 ps 1.4 lc rgb "#56B4E9" title "local, own width: share > 0.5 d", \
     f using 1:9 with points pt 4 ps 1.4 lc rgb "#009E73" title "local, 3 d of wall: share > 0.3 d", \
     f using 1:11 with points pt 9 ps 1.6 lc rgb "#D55E00" title "wall-to-wall gap, largest seed [d]", \
     f using 1:12 with points pt 13 ps 1.6 lc rgb "#000000" title "arch still white after 4 ms, median"
