# The still view against its seconds of stillness (docs/accuracy.md, "The still view by time"):
#   gnuplot -e "out='docs/images/accuracy'" tests/bench/still_by_time.gp
# Each point is a count of still frames: its ΔE00 (y) measured by
#   bench_still_picture --size 192 --only diamond-40 --reference-spp 64 --reference-wavelengths 48
#     --still-depth 16 --still-depth-max D --checkpoints N,...          (the diamond, over the stone)
#   gemrender --piece config/pieces/halo.toml --method trace --fire spectral --still-frames N
#     --depth 8 --still-depth 16 --still-depth-max D --size 256 --elevation 40 --azimuth 20
#     --zoom 2.5, then compare_pictures against the reference (64 spp, depth 64, spectral)
#     (the halo, 4×4 blocks of the piece)
# and the second (x) at which the kiosk had drawn that many, at 1920×1080 on the 2-core build
# machine (llvmpipe): its line "still view refined: N frames in T s, to depth D" with
# picture.still_seconds 2, 5, 10 and 20 (the shipped config, render.method "trace", a catalogue
# of the one piece). "Whole frames": the same kiosk when a still frame had to be drawn whole
# within picture.still_frame_ms, so that on this machine it stayed at depth 16 (88 ms the
# diamond's frame, 132 ms the halo's): the frame counts from its --stats CSV. "A GPU ten times
# faster": those frame costs a tenth, each deeper frame dearer in proportion to its depth,
# every frame within 100 ms, so the still frames deepen as gpu/still_schedule.hpp says (16, 32,
# then 64). Measured 2026-12-05.
if (!exists("out")) out = 'docs/images/accuracy'
$diamond_here << EOD
2.1 6.70
5.1 4.87
10.2 3.40
20.0 2.49
EOD
$diamond_whole << EOD
2.0 7.43
3.4 6.38
6.2 5.90
11.8 5.52
20.1 5.33
EOD
$diamond_fast << EOD
0.14 7.43
0.42 5.12
1.55 3.29
3.80 2.20
8.3 1.65
17.3 1.36
20.0 1.31
EOD
$halo_here << EOD
2.1 6.46
5.0 6.17
10.2 6.07
20.2 5.93
EOD
$halo_whole << EOD
2.3 6.41
8.6 6.25
20.1 6.16
EOD
$halo_fast << EOD
0.21 6.41
2.31 6.00
12.4 5.84
20.0 5.83
EOD
set terminal pngcairo size 900,460 font 'DejaVu Sans,11' linewidth 1.5
set output out.'/still-view-by-time.png'
set grid lc rgb '#dddddd'
set logscale xy
set format y '%g'
set ytics (1, 1.5, 2, 3, 5, 7, 10)
set yrange [1:10]
set xrange [0.1:25]
set xlabel 'seconds of stillness (the kiosk at 1920×1080)'
set ylabel 'mean ΔE00 against the spectral reference'
set key outside right top
plot $diamond_here w lp pt 7 lc rgb '#1f77b4' t 'diamond, this machine', \
     $diamond_whole w lp pt 7 dt 3 lc rgb '#9ecae1' t 'diamond, this machine, whole frames', \
     $diamond_fast w lp pt 6 dt 2 lc rgb '#1f77b4' t 'diamond, a GPU 10× faster', \
     $halo_here w lp pt 5 lc rgb '#d62728' t 'halo, this machine', \
     $halo_whole w lp pt 5 dt 3 lc rgb '#fc9272' t 'halo, this machine, whole frames', \
     $halo_fast w lp pt 4 dt 2 lc rgb '#d62728' t 'halo, a GPU 10× faster'
