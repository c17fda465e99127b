#!/usr/bin/env -S gnuplot -c
# ms per step against body count, one panel per scene family, one line per engine.
# Usage: plot-bench.gp SERIES.csv OUT.png (the CSV from jostle-bench --series ... --csv).
csv = ARG1
set terminal pngcairo size 1400,1000 font ",11"
set output ARG2
set datafile separator ","
set key top left
set logscale xy
set grid
set xlabel "bodies"
set ylabel "ms per step (median)"
set multiplot layout 2,2 title "jostle on 1 and 2 threads, Box2D 2.4.1 and Chipmunk 7 on one (docs/benchmarks.md)"
# Column 2: family, 4: engine, 5: workers, 6: bodies, 9: ms per step. Other rows plot
# nothing.
pick(family, engine, workers) = \
  (strcol(2) eq family && strcol(4) eq engine && $5 == workers) ? $9 : NaN
do for [family in "pyramid rain gas tilemap"] {
  set title family
  plot csv using 6:(pick(family, "jostle", 1)) skip 1 with linespoints lw 2 pt 7 title "jostle", \
       csv using 6:(pick(family, "jostle", 2)) skip 1 with linespoints lw 2 pt 6 title "jostle, 2 threads", \
       csv using 6:(pick(family, "box2d", 1)) skip 1 with linespoints lw 2 pt 5 title "Box2D", \
       csv using 6:(pick(family, "chipmunk", 1)) skip 1 with linespoints lw 2 pt 9 title "Chipmunk"
}
unset multiplot
