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
# of the one piece: the diamond in its parametric platinum ring, or the halo). A still frame
# there traces its stones and, from the second on, its metal's reflections and its stones'
# exits through the piece (metal_sight.glsl, stone_sight.glsl). "A GPU ten times faster": the
# kiosk's whole still frames' costs a tenth (the diamond's about 285 ms at depth 16, of which
# the rays through its ring about 197; the halo's about 1,173 ms, of which 938: bench_pieces'
# still frames' metal and stone passes added to the frames before the stones' rays), each
# deeper frame's stones dearer in proportion to the depth, so the still frames deepen as
# gpu/still_schedule.hpp says (16, 32, then 64). Measured 2026-12-06; the halo on this machine
# again that day with its still frames' metal drawn depth first and its stones shaded through
# the visibility pass (4, 6, 11 and 20 frames where there were 3, 5, 9 and 16; the same
# reference and gemrender give the earlier counts' figures to the hundredth).
if (!exists("out")) out = 'docs/images/accuracy'
$diamond_here << EOD
2.3 9.15
5.2 7.22
10.2 5.18
20.0 3.48
EOD
$diamond_fast << EOD
2.0 3.77
5.0 2.49
9.9 1.82
20.0 1.45
EOD
$halo_here << EOD
2.9 5.75
5.8 5.15
10.7 4.34
20.4 3.63
EOD
$halo_fast << EOD
1.9 3.90
4.9 3.18
10.0 2.93
19.9 2.70
EOD
set terminal pngcairo size 900,460 font 'DejaVu Sans,11' linewidth 1.5
set output out.'/still-view-by-time.png'
set grid lc rgb '#dddddd'
set logscale xy
set format y '%g'
set ytics (1, 1.5, 2, 3, 5, 7, 10)
set yrange [1:10]
set xrange [1:25]
set xlabel 'seconds of stillness (the kiosk at 1920×1080)'
set ylabel 'mean ΔE00 against the spectral reference'
set key outside right top
plot $diamond_here w lp pt 7 lc rgb '#1f77b4' t 'diamond, this machine', \
     $diamond_fast w lp pt 6 dt 2 lc rgb '#1f77b4' t 'diamond, a GPU 10× faster', \
     $halo_here w lp pt 5 lc rgb '#d62728' t 'halo, this machine', \
     $halo_fast w lp pt 4 dt 2 lc rgb '#d62728' t 'halo, a GPU 10× faster'
