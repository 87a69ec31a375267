"""Pictures for the VM test, through Pillow (Debian's python3-pil): QEMU's screenshots (PPM),
the kiosk's own snapshots (PNG), PNGs to look at, and the PSNR of two pictures' 8-bit values."""

import math

from PIL import Image, ImageChops, ImageStat


def read(path):
    """A PPM or PNG file as 8-bit RGB, read in full (the file may go right after)."""
    with Image.open(path) as picture:
        return picture.convert("RGB")


def psnr(a, b):
    """PSNR of the 8-bit values over all three channels, dB; infinity for equal pictures."""
    if a.size != b.size:
        raise ValueError(f"pictures of different sizes: {a.size} and {b.size}")
    squares = sum(ImageStat.Stat(ImageChops.difference(a, b)).sum2)
    if squares == 0:
        return math.inf
    return 10.0 * math.log10(255.0 * 255.0 * 3 * a.width * a.height / squares)


def side_by_side(pictures):
    """One picture of several, left to right, for looking at."""
    canvas = Image.new("RGB", (sum(p.width for p in pictures), max(p.height for p in pictures)))
    x = 0
    for picture in pictures:
        canvas.paste(picture, (x, 0))
        x += picture.width
    return canvas
