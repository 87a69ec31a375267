#!/usr/bin/env bash
# A chain's catalogue made from the shipped one: the shipped databases (linked rather than
# copied), then N entries, pieces (copies of the shipped halo, three-stone and eternity-band
# files, each its own file) and designs in rings (copies of the shipped stone files) in turn.
# For the kiosk's start-up figures with a catalogue of hundreds of entries (docs/performance.md).
#
# Usage: tests/bench/large_catalogue.sh SHIPPED_CATALOGUE_DIR OUT_DIR [N]
#   e.g. tests/bench/large_catalogue.sh build/test/catalogue /tmp/catalogue-300 300
set -euo pipefail
shipped=$(cd "$1" && pwd)
out=$2
count=${3:-300}
rm -rf "$out" && mkdir -p "$out/pieces" "$out/stones"
cp "$shipped"/stones/*.toml "$out/stones/"
metals=(platinum white_gold yellow_gold)
{
  printf '[catalogue]\nname = "large catalogue of %d entries"\n' "$count"
  for db in "$shipped"/*.gemdb; do
    ln "$db" "$out/" 2>/dev/null || cp "$db" "$out/"
    printf '\n[[stone]]\nname = "%s"\ndatabase = "%s"\nring = "parametric"\nmetal = "platinum"\n' \
      "$(basename "$db" .gemdb)" "$(basename "$db")"
  done
  pieces=("$shipped"/pieces/*.toml)
  stones=("$shipped"/stones/*.toml)
  # Pieces and designs in turn, so that a few taps show both.
  for ((i = 0; i < count; i++)); do
    if ((i % 2 == 0)); then
      cp "${pieces[i / 2 % ${#pieces[@]}]}" "$out/pieces/piece-$i.toml"
      printf '\n[[stone]]\nname = "Piece %d"\npiece = "pieces/piece-%d.toml"\n' "$i" "$i"
    else
      cp "${stones[i / 2 % ${#stones[@]}]}" "$out/stones/design-$i.toml"
      printf '\n[[stone]]\nname = "Design %d"\ndesign = "stones/design-%d.toml"\nring = "parametric"\nmetal = "%s"\n' \
        "$i" "$i" "${metals[i % 3]}"
    fi
  done
} >"$out/catalogue.toml"
echo "wrote $out: $(grep -c '^\[\[stone\]\]' "$out/catalogue.toml") entries"
