#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine, builds gemkiosk and runs its main job: render the default
# stone (a Tolkowsky round brilliant in diamond) with the exact CPU tracer to a PNG.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release -DGEM_BUILD_TESTS=OFF >/dev/null
cmake --build build/release --target gemrender
mkdir -p out
./build/release/render/gemrender --out out/gemrender-default.png "$@"
echo "main: the default stone is rendered at $(pwd)/out/gemrender-default.png"
