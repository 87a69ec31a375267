#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine, builds gemkiosk and its default catalogue (ray-table
# databases traced from config/stones/), and runs the kiosk's main job headless: the shipped
# config on an off-screen 1920×1080 display, a recorded one-finger drag replayed as if from a
# touchscreen, every 3rd frame and the last one written as PNG, frame times as CSV, and the turn
# as one strip of its different frames (out/kiosk/strip.png).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release -DGEM_BUILD_TESTS=OFF >/dev/null
cmake --build build/release --target gemkiosk gemtables default_catalogue
rm -rf out/kiosk && mkdir -p out/kiosk
./build/release/kiosk/gemkiosk --config config/gemkiosk.toml --backend headless \
  --catalogue build/release/catalogue --state-dir out/kiosk/state \
  --snapshot-dir out/kiosk --snapshot-every 3 --snapshot-last \
  --replay tests/fixtures/kiosk/atmel-drag-right.events --exit-after-replay \
  --stats out/kiosk/frames.csv "$@" 2>&1 | tee out/kiosk/kiosk.log
/usr/bin/python3 scripts/turn_strip.py out/kiosk/strip.png out/kiosk/frame-*.png out/kiosk/last.png
echo "main: the kiosk's frames are in $(pwd)/out/kiosk (last.png is the last one, strip.png the turn)"
echo "main: $(sed -n 's/.*gemkiosk: frames: //p' out/kiosk/kiosk.log | tail -n 1)"
