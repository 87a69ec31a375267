#!/usr/bin/env bash
# Each shipped piece (config/pieces/) drawn at one close view two ways, the GPU as the kiosk
# refines a still view and the exact piece reference, and compared over the piece's 4×4-pixel
# blocks (compare_pictures): the figures of docs/pieces.md, "On the GPU". Run from the
# repository root after building build/test.
#   bash scripts/piece_accuracy.sh [OUT_DIR] [SPP]     (default out/piece-accuracy, 16)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/piece-accuracy}
spp=${2:-16}
bin=build/test
mkdir -p "$out"
view=(--size 384 --elevation 40 --azimuth 20 --zoom 2.5)
for file in config/pieces/*.toml; do
  name=$(basename "$file" .toml)
  "$bin/render/gemrender" --piece "$file" --method trace --fire none --msaa 1 --still-frames 16 \
    --depth 8 "${view[@]}" --out "$out/$name-trace.png" > /dev/null
  "$bin/render/gemrender" --piece "$file" --method reference --spp "$spp" --depth 8 "${view[@]}" \
    --out "$out/$name-reference.png" --coverage "$out/$name-mask.png" > /dev/null
  printf '%-16s %s\n' "$name" \
    "$("$bin/tests/bench/compare_pictures" "$out/$name-trace.png" "$out/$name-reference.png" \
      "$out/$name-mask.png" --heat "$out/$name-heat.png")"
done
