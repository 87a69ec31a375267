#!/usr/bin/env python3
"""Lays a kiosk run's snapshots side by side: the turn of the stone as one picture.

  turn_strip.py OUT.png FRAME.png [FRAME.png ...]

Frames identical to the one before are left out; of the rest, at most six evenly spaced ones
(the first and the last among them) are scaled to 480 px wide and joined left to right.
"""
import sys

from PIL import Image, ImageChops

MAX_FRAMES = 6
WIDTH = 480


def main(argv):
    if len(argv) < 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    out, paths = argv[1], argv[2:]
    frames = []
    for path in paths:
        image = Image.open(path).convert("RGB")
        if frames and ImageChops.difference(image, frames[-1][1]).getbbox() is None:
            continue
        frames.append((path, image))
    if len(frames) > MAX_FRAMES:
        step = (len(frames) - 1) / (MAX_FRAMES - 1)
        frames = [frames[round(i * step)] for i in range(MAX_FRAMES)]
    height = round(frames[0][1].height * WIDTH / frames[0][1].width)
    strip = Image.new("RGB", (WIDTH * len(frames), height))
    for i, (_, image) in enumerate(frames):
        strip.paste(image.resize((WIDTH, height), Image.LANCZOS), (i * WIDTH, 0))
    strip.save(out)
    names = ", ".join(path.rsplit("/", 1)[-1] for path, _ in frames)
    print(f"turn_strip: {out}: {len(frames)} different frames ({names})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
