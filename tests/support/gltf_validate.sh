#!/usr/bin/env bash
# Runs the Khronos glTF Validator (npm's gltf-validator) over .glb files: exits 0 when none has
# an error, 1 when one has, and 77 (a skip) when node, npm or the registry cannot be reached.
# Usage: gltf_validate.sh NPM_DIR FILE...
set -u
dir=$1
shift
here=$(cd "$(dirname "$0")" && pwd)
version=2.0.0-dev.3.10
for tool in node npm; do
  command -v "$tool" >/dev/null || { echo "skipped: $tool is not installed"; exit 77; }
done
if [ ! -f "$dir/node_modules/gltf-validator/package.json" ]; then
  mkdir -p "$dir"
  if ! timeout 120 npm install --prefix "$dir" --no-audit --no-fund --no-save \
    "gltf-validator@$version" >"$dir/npm.log" 2>&1; then
    echo "skipped: npm could not fetch gltf-validator@$version:"
    tail -n 3 "$dir/npm.log"
    exit 77
  fi
fi
NODE_PATH="$dir/node_modules" node "$here/gltf_validate.js" "$@"
