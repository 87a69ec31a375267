#!/usr/bin/env bash
# Pieces drawn at one close view two ways, the GPU as the kiosk refines a still view and the
# exact piece reference, and compared over the piece's 4×4-pixel blocks (compare_pictures, with
# a heat map of where they differ): the figures of docs/pieces.md, "On the GPU" (the shipped
# pieces, by default) and of docs/gltf.md (the glTF corpus, through scripts/gltf_corpus.sh).
# Run from the repository root after building build/test.
#   bash scripts/piece_accuracy.sh [OUT_DIR] [SPP] [PIECE ...]
#   (default out/piece-accuracy, 16 samples, config/pieces/*.toml)
# REFERENCE_FLAGS adds gemrender flags to the reference's command, e.g.
# REFERENCE_FLAGS=--metal-sees-environment (the reference's metal drawn as the GPU's is).
set -euo pipefail
reference_flags=(${REFERENCE_FLAGS:-})
cd "$(dirname "$0")/.."
out=${1:-out/piece-accuracy}
spp=${2:-16}
shift $(($# < 2 ? $# : 2))
pieces=("$@")
[ ${#pieces[@]} -gt 0 ] || pieces=(config/pieces/*.toml)
bin=build/test
mkdir -p "$out"
view=(--size 384 --elevation 40 --azimuth 20 --zoom 2.5)
for file in "${pieces[@]}"; do
  name=$(basename "${file%.*}")
  "$bin/render/gemrender" --piece "$file" --method trace --fire none --msaa 1 --still-frames 16 \
    --depth 8 "${view[@]}" --out "$out/$name-trace.png" > /dev/null
  "$bin/render/gemrender" --piece "$file" --method reference --spp "$spp" --depth 8 "${view[@]}" \
    "${reference_flags[@]}" --out "$out/$name-reference.png" --coverage "$out/$name-mask.png" \
    > /dev/null
  printf '%-20s %s\n' "$name" \
    "$("$bin/tests/bench/compare_pictures" "$out/$name-trace.png" "$out/$name-reference.png" \
      "$out/$name-mask.png" --heat "$out/$name-heat.png")"
done
