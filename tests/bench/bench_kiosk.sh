#!/usr/bin/env bash
# The kiosk's own figures, headless on this machine: frames per second and frame-time
# percentiles while a recorded drag is replayed again and again, the time from an input event
# to the frame that shows it, the time from process start to the first frame, and resident
# memory (the kiosk logs a status line with it every minute).
#
# Usage: tests/bench/bench_kiosk.sh BUILD_DIR CATALOGUE_DIR [SECONDS] [WIDTHxHEIGHT]
#   e.g. tests/bench/bench_kiosk.sh build/release build/release/catalogue 60 1920x1080
# Prints the kiosk's log lines that carry figures; the frame CSV goes to $BUILD_DIR/bench-kiosk.
set -euo pipefail
build=$1
catalogue=$2
seconds=${3:-60}
size=${4:-1920x1080}
here=$(cd "$(dirname "$0")/../.." && pwd)
out=$build/bench-kiosk
rm -rf "$out" && mkdir -p "$out"
"$build/kiosk/gemkiosk" --config "$here/config/gemkiosk.toml" --backend headless \
  --width "${size%x*}" --height "${size#*x}" --catalogue "$catalogue" --state-dir "$out/state" \
  --replay "$here/tests/fixtures/kiosk/atmel-drag-right.events" --replay-loop \
  --seconds "$seconds" --stats "$out/frames.csv" 2>&1 |
  grep -E "display:|first frame|status:|frames:|resident|last view"
