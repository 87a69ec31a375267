#!/usr/bin/env bash
# The kiosk's frames over one recorded drag, for one shipped piece at a time, the pieces in
# turn ROUNDS times: a moving view's draw time against the solitaire's is what a piece's small
# stones and metal cost while the ring turns (the still view, refined between the drag's
# strokes, is timed apart). The shipped config with render.method "trace", picture.msaa 1 (or
# $MSAA) and picture.glare 0, headless at WIDTHxHEIGHT, a catalogue of the one piece each.
#
# Usage: tests/bench/kiosk_pieces.sh BUILD_DIR [ROUNDS] [WIDTHxHEIGHT] [PIECE...]
#   e.g. tests/bench/kiosk_pieces.sh build/test 3 1920x1080 solitaire halo eternity-band
# Prints a line per run: the piece, its moving and still-view draw p50, and the ratio of its
# moving p50 to the solitaire's in the same round.
set -euo pipefail
build=$1
rounds=${2:-3}
size=${3:-1920x1080}
shift $(($# < 3 ? $# : 3))
pieces=("$@")
((${#pieces[@]})) || pieces=(solitaire halo eternity-band)
here=$(cd "$(dirname "$0")/../.." && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
sed -e 's/^method = .*/method = "trace"/' -e "s/^msaa = .*/msaa = ${MSAA:-1}/" \
  -e 's/^glare = .*/glare = 0.0/' "$here/config/gemkiosk.toml" >"$out/gemkiosk.toml"
for piece in "${pieces[@]}"; do
  mkdir -p "$out/$piece/pieces" "$out/$piece/stones"
  cp "$here/config/pieces/$piece.toml" "$out/$piece/pieces/"
  cp "$here"/config/stones/*.toml "$out/$piece/stones/"
  printf '[catalogue]\nname = "%s"\n[[stone]]\nname = "%s"\npiece = "pieces/%s.toml"\n' \
    "$piece" "$piece" "$piece" >"$out/$piece/catalogue.toml"
done
# The p50 of draw_ms over the CSV's moving frames (still = -1) and over its still view's.
p50() {
  /usr/bin/env python3 - "$1" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
moving = [float(r["draw_ms"]) for r in rows if r["still"] == "-1"]
still = [float(r["draw_ms"]) for r in rows if r["still"] != "-1"]
print("%.1f %.1f %d" % (statistics.median(moving), statistics.median(still), len(moving)))
PY
}
for ((round = 1; round <= rounds; round++)); do
  first=""
  for piece in "${pieces[@]}"; do
    rm -rf "$out/state"
    "$build/kiosk/gemkiosk" --config "$out/gemkiosk.toml" --backend headless \
      --width "${size%x*}" --height "${size#*x}" --catalogue "$out/$piece" --state-dir "$out/state" \
      --replay "$here/tests/data/evemu/Atmel_maXTouch_Touchscreen.1-finger-drag-up-down.events" \
      --replay-desc "$here/tests/data/evemu/Atmel_maXTouch_Touchscreen.desc" --exit-after-replay \
      --stats "$out/frames.csv" >/dev/null 2>&1
    read -r moving still count < <(p50 "$out/frames.csv")
    [[ -n $first ]] || first=$moving
    printf 'round %d %-14s moving p50 %7.1f ms (%d frames)  still view p50 %7.1f ms  ÷ %s: %.2f\n' \
      "$round" "$piece" "$moving" "$count" "$still" "${pieces[0]}" \
      "$(/usr/bin/env python3 -c "print($moving / $first)")"
  done
done
