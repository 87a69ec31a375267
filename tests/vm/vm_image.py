"""Pictures for the VM test: QEMU's screenshots (binary PPM, netpbm's P6), the kiosk's own
snapshots (PNG, 8-bit RGB or RGBA, ISO/IEC 15948), PNG output for looking at them, and the
PSNR of two pictures' 8-bit values. Standard library only: the test runs on a bare machine."""

import math
import struct
import zlib


class Picture:
    def __init__(self, width, height, rgb):
        self.width = width
        self.height = height
        self.rgb = bytes(rgb)  # rows top to bottom, 3 bytes a pixel

    def size(self):
        return (self.width, self.height)


def read_ppm(path):
    with open(path, "rb") as f:
        data = f.read()
    # The header: "P6", width, height, maximum value, each after white space; then one
    # white-space byte and the samples.
    fields = []
    position = 0
    while len(fields) < 4:
        while data[position:position + 1].isspace():
            position += 1
        if data[position:position + 1] == b"#":
            position = data.index(b"\n", position) + 1
            continue
        end = position
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[position:end])
        position = end
    if fields[0] != b"P6" or int(fields[3]) != 255:
        raise ValueError(f"{path}: not an 8-bit binary PPM")
    width, height = int(fields[1]), int(fields[2])
    rgb = data[position + 1:position + 1 + width * height * 3]
    if len(rgb) != width * height * 3:
        raise ValueError(f"{path}: truncated")
    return Picture(width, height, rgb)


def _paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def read_png(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG")
    position, idat = 8, b""
    width = height = channels = None
    while position < len(data):
        length, kind = struct.unpack(">I4s", data[position:position + 8])
        body = data[position + 8:position + 8 + length]
        position += 12 + length
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            channels = {2: 3, 6: 4}.get(colour)
            if depth != 8 or channels is None or interlace != 0:
                raise ValueError(f"{path}: only 8-bit RGB/RGBA without interlacing is read")
        elif kind == b"IDAT":
            idat += body
        elif kind == b"IEND":
            break
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        # The five filters of the PNG specification, section 9.2.
        if kind == 1:
            for i in range(channels, stride):
                line[i] = (line[i] + line[i - channels]) & 255
        elif kind == 2:
            line = bytearray((a + b) & 255 for a, b in zip(line, previous))
        elif kind == 3:
            for i in range(stride):
                left = line[i - channels] if i >= channels else 0
                line[i] = (line[i] + ((left + previous[i]) >> 1)) & 255
        elif kind == 4:
            for i in range(stride):
                left = line[i - channels] if i >= channels else 0
                corner = previous[i - channels] if i >= channels else 0
                line[i] = (line[i] + _paeth(left, previous[i], corner)) & 255
        rows.append(line)
        previous = line
    rgb = bytearray()
    for line in rows:
        if channels == 3:
            rgb += line
        else:
            for i in range(0, stride, 4):
                rgb += line[i:i + 3]
    return Picture(width, height, rgb)


def write_png(picture, path):
    def chunk(kind, body):
        return (struct.pack(">I", len(body)) + kind + body +
                struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF))

    stride = picture.width * 3
    raw = b"".join(b"\x00" + picture.rgb[y * stride:(y + 1) * stride]
                   for y in range(picture.height))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", picture.width, picture.height, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw, 6)))
        f.write(chunk(b"IEND", b""))


def psnr(a, b):
    """PSNR of the 8-bit values, dB; infinity for equal pictures."""
    if a.size() != b.size():
        raise ValueError(f"pictures of different sizes: {a.size()} and {b.size()}")
    squared = sum((x - y) * (x - y) for x, y in zip(a.rgb, b.rgb))
    if squared == 0:
        return math.inf
    return 10.0 * math.log10(255.0 * 255.0 * len(a.rgb) / squared)


def side_by_side(pictures):
    """One picture of several of the same height, left to right, for looking at."""
    height = pictures[0].height
    width = sum(p.width for p in pictures)
    rgb = bytearray()
    for y in range(height):
        for p in pictures:
            rgb += p.rgb[y * p.width * 3:(y + 1) * p.width * 3]
    return Picture(width, height, rgb)
