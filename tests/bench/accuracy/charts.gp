# Charts of the accuracy benchmark (docs/accuracy.md) from its CSV:
#   gnuplot -e "csv='accuracy.csv'; out='charts'" charts.gp
# Error is the mean CIEDE2000 over the stone's pixels against the CPU reference (deep,
# spectral, same camera); see engine/render/image_error.hpp.
# Columns: 1 study 2 scene 3 view 4 offset_deg 5 method 6 level 7 spacing_deg 8 blend
# 9 blend_weight 10 depth 11 threshold 12 dispersion 13 samples 14 compared_with 15 frame_ms
# 16 db_bytes 17 build_s 18 psnr_db 19 de_mean 20 de_p99 21 de_max 22 share_visible
# 23 pixels 24 nd_psnr_db 25 nd_de_mean 26 nd_de_p99 27 nd_share_visible
if (!exists("csv")) csv = 'accuracy.csv'
if (!exists("out")) out = '.'
# The scene whose table sweep chart 2 shows, and the scenes with a path (chart 3); a --quick
# run has only the face-up diamond.
if (!exists("sweep_scene")) sweep_scene = 'diamond-tilted'
if (!exists("path_scenes")) path_scenes = 'diamond-tilted oval-sapphire'
set datafile separator ','
set terminal pngcairo size 1100,460 font 'DejaVu Sans,11' linewidth 1.5
set grid lc rgb '#dddddd'
set logscale y
set format y '%g'
set ytics (0.5, 1, 2, 5, 10, 20, 50)
set yrange [0.3:60]

is(c, s) = strcol(c) eq s
vsref = 'is(14, "reference")'
sel(cond, v) = cond ? v : NaN

# 1. Error against frame time: every method and setting, filled on stored directions, open
# between them.
set output out.'/error-vs-frame-time.png'
set terminal pngcairo size 1000,520 font 'DejaVu Sans,11' linewidth 1.5
set key outside right center vertical font ',10'
set title 'Error against frame time (every scene, method and setting)'
set logscale x
set xrange [1:5000]
set format x '%g'
set xlabel 'time per frame, ms (log)'
set ylabel 'mean ΔE00 on the stone (log)'
set arrow 1 from graph 0, first 2 to graph 1, first 2 nohead dt 2 lc rgb '#888888'
set label 1 'visible (ΔE00 = 2)' at graph 0.02, first 2.3 font ',9' tc rgb '#666666'
m(meth, b, v) = is(5, meth) && (b < 0 || strcol(8) eq sprintf('%d', b)) && is(3, v) && (is(14, 'reference'))
plot for [v in "on between"] csv every ::1 using (sel(m('table', 0, v), $15)):19 \
       with points pt (v eq 'on' ? 7 : 6) ps 1.0 lc rgb '#1f77b4' title 'table, nearest view, '.v, \
     for [v in "on between"] '' every ::1 using (sel(m('table', 1, v), $15)):19 \
       with points pt (v eq 'on' ? 9 : 8) ps 1.2 lc rgb '#17becf' title 'table, blend, '.v, \
     for [v in "on between"] '' every ::1 using (sel(m('trace', -1, v), $15)):19 \
       with points pt (v eq 'on' ? 5 : 4) ps 1.0 lc rgb '#d62728' title 'trace (GLSL), '.v, \
     for [v in "on between"] '' every ::1 using (sel(m('phong', -1, v), $15)):19 \
       with points pt (v eq 'on' ? 11 : 10) ps 1.2 lc rgb '#555555' title 'phong, '.v, \
     '' every ::1 using (sel(m('reference', -1, 'on'), $15)):19 \
       with points pt 13 ps 1.2 lc rgb '#2ca02c' title 'CPU reference, cheaper'
unset arrow 1
unset label 1
unset logscale x
unset xrange

# 2. Error against database size: the table settings, one at a time, on the tilted diamond.
set output out.'/error-vs-database-size.png'
set terminal pngcairo size 1100,480 font 'DejaVu Sans,11' linewidth 1.5
set logscale x
set autoscale x
set key inside top right vertical font ',9' box opaque
set multiplot layout 1,2 title 'Error against database size: table settings varied one at a time ('.sweep_scene.'; filled: vs spectral reference, open: vs reference at n(D))'
set xlabel 'database size, MB (log)'
set arrow 1 from graph 0, first 2 to graph 1, first 2 nohead dt 2 lc rgb '#888888'
col(s) = s eq 'base' ? '#000000' : s eq 'level' ? '#009e73' : s eq 'spacing' ? '#56b4e9' : \
         s eq 'depth' ? '#e69f00' : s eq 'threshold' ? '#cc79a7' : '#0072b2'
label(s) = is(1,'level') ? sprintf('%d px', $6) : is(1,'spacing') ? sprintf('%g°', $7) : \
           is(1,'depth') ? sprintf('d%d', $10) : is(1,'threshold') ? sprintf('thr %g', $11) : \
           is(1,'dispersion') ? 'disp' : ''
do for [v in "on between"] {
  set title (v eq 'on' ? 'views ON stored directions' : 'views BETWEEN stored directions')
  if (v eq 'between') { unset key }
  keep(s) = is(2,sweep_scene) && is(5,'table') && is(8,'0') && is(14,'reference') && is(3,v) && is(1,s)
  # Filled: against the spectral reference; open: against the same reference traced at n(D).
  # Thresholds 1e-3 and 1e-5 land on the base point (depth 8 ends the rays first).
  plot for [s in "base level spacing depth threshold dispersion"] csv every ::1 \
         using (sel(keep(s), $16/1e6)):19 with points pt 7 ps 1.1 lc rgb col(s) title s, \
       for [s in "base level spacing depth threshold dispersion"] csv every ::1 \
         using (sel(keep(s), $16/1e6)):25 with points pt 6 ps 1.1 lc rgb col(s) notitle, \
       csv every ::1 using (sel(is(2,sweep_scene) && is(5,'table') && is(8,'0') && is(14,'reference') && is(3,v) && !is(1,'path') && !is(1,'quantise') && !(is(1,'threshold') && $11 < 0.005) && !is(1,'blend'), $16/1e6)):19:(label(0)) \
         with labels offset 0,0.8 font ',8' notitle, \
       csv every ::1 using (sel(keep('base'), $16/1e6)):19:('base (= thr 1e-3, 1e-5)') \
         with labels offset 0,-0.9 font ',8' notitle
}
unset multiplot
unset arrow 1

# 3. Error against the angle to the nearest stored view, along a path across the gap.
set output out.'/error-vs-angular-offset.png'
set terminal pngcairo size 1100,460 font 'DejaVu Sans,11' linewidth 1.5
unset logscale x
set autoscale x
set key inside bottom right vertical font ',9' box opaque
set format x '%g'
set multiplot layout 1,2 title 'Error against the angle to the nearest stored view (views every 6°, a path from one stored view past the midpoint)'
set xlabel 'angle between the view and the nearest stored direction, degrees'
set arrow 1 from graph 0, first 2 to graph 1, first 2 nohead dt 2 lc rgb '#888888'
do for [sc in path_scenes] {
  set title sc
  plot csv every ::1 using (sel(is(1,'path') && is(2,sc) && is(8,'0'), $4)):19 \
         with points pt 7 ps 1.1 lc rgb '#1f77b4' title 'nearest view', \
       '' every ::1 using (sel(is(1,'path') && is(2,sc) && is(8,'1'), $4)):19 \
         with points pt 9 ps 1.3 lc rgb '#17becf' title 'blend of two views', \
       '' every ::1 using (sel(is(1,'path') && is(2,sc) && is(8,'0'), $4)):25 \
         with points pt 6 ps 1.1 lc rgb '#1f77b4' title 'nearest, vs reference at n(D)', \
       '' every ::1 using (sel(is(1,'path') && is(2,sc) && is(8,'1'), $4)):25 \
         with points pt 8 ps 1.3 lc rgb '#17becf' title 'blend, vs reference at n(D)'
}
unset multiplot

# 4. The still picture: error against the time to the settled picture (the summed time of its
# frames), against the reference averaged over the pixel (16 samples). Per scene: the moving
# frame, 16 still frames with exact fire, and 16 with spectral fire at still depths 8, 16, 32.
if (!exists("still_scenes")) still_scenes = 'diamond-faceup diamond-tilted oval-sapphire heart-ruby'
set output out.'/still-picture.png'
set terminal pngcairo size 1150,520 font 'DejaVu Sans,11' linewidth 1.5
set title 'The still picture against a 16-sample reference'
set key outside right center vertical font ',10'
set logscale x
set autoscale x
set format x '%g'
set xlabel 'summed time of the frames, ms (log)'
set ylabel 'mean ΔE00 on the stone (log)'
set arrow 1 from graph 0, first 2 to graph 1, first 2 nohead dt 2 lc rgb '#888888'
scol(sc) = sc eq 'diamond-faceup' ? '#ff7f0e' : sc eq 'diamond-tilted' ? '#d62728' : \
           sc eq 'oval-sapphire' ? '#0072b2' : '#cc79a7'
still(sc, frames, disp) = is(1,'still') && is(2,sc) && $13 == frames && $12 == disp
plot for [sc in still_scenes] csv every ::1 using (sel(still(sc, 1, 0), $15)):19 \
       with points pt 4 ps 1.2 lc rgb scol(sc) title sc.': moving (1 frame)', \
     for [sc in still_scenes] '' every ::1 using (sel(still(sc, 16, 0), $15)):19 \
       with points pt 5 ps 1.2 lc rgb scol(sc) title sc.': 16 frames, exact fire', \
     for [sc in still_scenes] '' every ::1 using (sel(still(sc, 16, 1), $15)):19 \
       with linespoints pt 7 ps 1.2 lc rgb scol(sc) title sc.': 16 frames, spectral, depth 8–32', \
     for [sc in still_scenes] '' every ::1 using (sel(still(sc, 16, 1), $15)):19:(sprintf('d%d', $10)) \
       with labels offset 0,0.8 font ',8' notitle
unset arrow 1
