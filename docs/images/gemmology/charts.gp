# Written by tests/bench/bench_gemmology; run from the repository root.
set datafile separator ','
set terminal pngcairo size 720,480 font 'sans,10'
set grid
set key below
set output 'docs/images/gemmology/pavilion-sweep.png'
set title 'Round brilliant, crown 34.5°, table 53 %: light return against pavilion angle'
set xlabel 'pavilion angle (°)'
set ylabel 'share of light'
set y2label 'fire (° × share of light)'
set y2tics
set ytics nomirror
plot 'docs/gemmology/pavilion_sweep.csv' using 1:3 with linespoints title 'light return to the eye', '' using 1:14 with linespoints title 'return to the upper hemisphere', '' using 1:9 with linespoints title 'leakage (below girdle)', '' using 1:8 with linespoints title 'head (blue)', '' using 1:11 axes x1y2 with linespoints title 'fire (right axis)'
set output 'docs/images/gemmology/crown-sweep.png'
set title 'Round brilliant, pavilion 40.75°, table 53 %: against crown angle'
set xlabel 'crown angle (°)'
plot 'docs/gemmology/crown_sweep.csv' using 2:3 with linespoints title 'light return to the eye', '' using 2:14 with linespoints title 'return to the upper hemisphere', '' using 2:9 with linespoints title 'leakage', '' using 2:8 with linespoints title 'head (blue)', '' using 2:11 axes x1y2 with linespoints title 'fire (right axis)'
set output 'docs/images/gemmology/radial-profiles.png'
set title 'Face-up light return along the pavilion mains'' meridians (±4°)'
set xlabel 'radius / girdle radius'
set ylabel 'light return'
set y2label 'weight leaving through the girdle'
plot for [s in 'tolkowsky nailhead fisheye'] 'docs/gemmology/'.s.'-radial.csv' using 1:2 with lines lw 2 title s, 'docs/gemmology/fisheye-radial.csv' using 1:3 axes x1y2 with lines dt 2 lw 2 title 'fisheye: girdle exits (right axis)'
