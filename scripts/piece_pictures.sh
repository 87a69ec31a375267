#!/usr/bin/env bash
# The pictures of docs/pieces.md and the README: each default setting as the kiosk shows it at
# its start view (1920×1080, the still view refined), in the studio and the white look, joined
# into one sheet; the solitaire in all four looks; and a close-up of a claw on the crown drawn
# by the GPU trace beside the CPU reference.
#
#   scripts/piece_pictures.sh BUILD_DIR OUT_DIR
#   e.g. scripts/piece_pictures.sh build/test out/pieces
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:?build directory}
out=${2:?output directory}
rm -rf "$out" && mkdir -p "$out"

# One catalogue per piece and look: the kiosk opens on its first entry at the start view. Each
# background comes with the lighting of the same place in the config, as the kiosk pairs them.
looks=("studio:spotlight" "velvet:two softboxes" "white:light tent" "counter:ambient")
for piece in solitaire halo three-stone eternity-band; do
  for look in "${looks[@]}"; do
    if [[ $piece != solitaire && $look != studio:* && $look != white:* ]]; then continue; fi
    background=${look%%:*}
    lighting=${look#*:}
    dir="$out/$piece-$background"
    mkdir -p "$dir/catalogue/pieces" "$dir/catalogue/stones"
    cp config/pieces/$piece.toml "$dir/catalogue/pieces/"
    cp config/stones/*.toml "$dir/catalogue/stones/"
    cat >"$dir/catalogue/catalogue.toml" <<EOF
[catalogue]
name = "$piece"

[[stone]]
name = "$piece"
piece = "pieces/$piece.toml"
background = "$background"
lighting = "$lighting"
EOF
    "$build/kiosk/gemkiosk" --config config/gemkiosk.toml --backend headless \
      --catalogue "$dir/catalogue" --state-dir "$dir/state" --snapshot-dir "$dir" \
      --snapshot-last --frames 20 >"$dir/kiosk.log" 2>&1
    cp "$dir/last.png" "$out/$piece-$background.png"
  done
done

# The claw at the front of the solitaire, close: the GPU trace (4× MSAA, 16 still frames) and
# the exact CPU reference (16 samples a pixel) of the same camera.
close=(--piece config/pieces/solitaire.toml --size 384 --elevation 30 --azimuth 45 --zoom 9)
"$build/render/gemrender" "${close[@]}" --method trace --msaa 4 --still-frames 16 \
  --out "$out/claw-trace.png" >/dev/null
"$build/render/gemrender" "${close[@]}" --method reference --spp 16 \
  --out "$out/claw-reference.png" >/dev/null

/usr/bin/python3 - "$out" <<'EOF'
import sys
from PIL import Image

out = sys.argv[1]
pieces = ["solitaire", "halo", "three-stone", "eternity-band"]
tile = (640, 360)
sheet = Image.new("RGB", (2 * tile[0], len(pieces) * tile[1]))
for row, piece in enumerate(pieces):
    for column, look in enumerate(["studio", "white"]):
        image = Image.open(f"{out}/{piece}-{look}.png").convert("RGB").resize(tile, Image.LANCZOS)
        sheet.paste(image, (column * tile[0], row * tile[1]))
sheet.save(f"{out}/kiosk-pieces.png")
looks = Image.new("RGB", (2 * tile[0], 2 * tile[1]))
for i, look in enumerate(["studio", "velvet", "white", "counter"]):
    image = Image.open(f"{out}/solitaire-{look}.png").convert("RGB").resize(tile, Image.LANCZOS)
    looks.paste(image, ((i % 2) * tile[0], (i // 2) * tile[1]))
looks.save(f"{out}/kiosk-looks.png")
pair = [Image.open(f"{out}/claw-{m}.png").convert("RGB") for m in ("trace", "reference")]
joined = Image.new("RGB", (pair[0].width * 2, pair[0].height))
joined.paste(pair[0], (0, 0))
joined.paste(pair[1], (pair[0].width, 0))
joined.save(f"{out}/claw-trace-reference.png")
EOF
echo "piece_pictures: $out/kiosk-pieces.png, $out/kiosk-looks.png, $out/claw-trace-reference.png"
