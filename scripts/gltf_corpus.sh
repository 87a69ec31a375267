#!/usr/bin/env bash
# The glTF corpus of files made as other tools make them (tests/support/cad_corpus.hpp): each
# file written and read as the kiosk reads it, with what the reader said and how long it took,
# then drawn at a close view two ways, the GPU as the kiosk refines a still view and the exact
# piece reference, and compared over the piece's 4×4-pixel blocks (compare_pictures): the
# figures of docs/gltf.md. Run from the repository root after building build/test.
#   bash scripts/gltf_corpus.sh [OUT_DIR]     (default out/gltf-corpus)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/gltf-corpus}
bin=build/test
mkdir -p "$out"
"$bin/tests/bench/bench_gltf_corpus" "$out/files" --runs 5 | tee "$out/load.txt"
view=(--size 384 --elevation 40 --azimuth 20 --zoom 2.5)
for file in "$out"/files/*.glb; do
  name=$(basename "$file" .glb)
  "$bin/render/gemrender" --piece "$file" --method trace --fire none --msaa 1 --still-frames 16 \
    --depth 8 "${view[@]}" --out "$out/$name-trace.png" > /dev/null
  "$bin/render/gemrender" --piece "$file" --method reference --spp 16 --depth 8 "${view[@]}" \
    --out "$out/$name-reference.png" --coverage "$out/$name-mask.png" > /dev/null
  echo "$name: GPU trace against the reference: $("$bin/tests/bench/compare_pictures" \
    "$out/$name-trace.png" "$out/$name-reference.png" "$out/$name-mask.png")"
done | tee "$out/accuracy.txt"
