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
set multiplot layout 2,2 title "jostle, Box2D 2.4.1 and Chipmunk 7, single thread (docs/benchmarks.md)"
# Column 2: family, 4: engine, 5: bodies, 8: ms per step. Other rows plot nothing.
pick(family, engine) = (strcol(2) eq family && strcol(4) eq engine) ? $8 : NaN
do for [family in "pyramid rain gas tilemap"] {
  set title family
  plot csv using 5:(pick(family, "jostle")) skip 1 with linespoints lw 2 pt 7 title "jostle", \
       csv using 5:(pick(family, "box2d")) skip 1 with linespoints lw 2 pt 5 title "Box2D", \
       csv using 5:(pick(family, "chipmunk")) skip 1 with linespoints lw 2 pt 9 title "Chipmunk"
}
unset multiplot
