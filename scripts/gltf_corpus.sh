#!/usr/bin/env bash
# The glTF corpus of files made as other tools make them (tests/support/cad_corpus.hpp): each
# file written and read as the kiosk reads it, with what the reader said and how long it took,
# then drawn at a close view two ways and compared (scripts/piece_accuracy.sh): the figures of
# docs/gltf.md. Run from the repository root after building build/test.
#   bash scripts/gltf_corpus.sh [OUT_DIR]     (default out/gltf-corpus)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/gltf-corpus}
bin=build/test
mkdir -p "$out"
"$bin/tests/bench/bench_gltf_corpus" "$out/files" --runs 5 | tee "$out/load.txt"
bash scripts/piece_accuracy.sh "$out" 16 "$out"/files/*.glb | tee "$out/accuracy.txt"
