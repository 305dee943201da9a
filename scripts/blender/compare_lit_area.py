#!/usr/bin/env python3
"""Checks that two renders of one preset are lit in the same place: voxflame's own PNG and
Blender's render of the exported volume (scripts/test_blender.sh). Plain Python, no packages.

A pixel is lit when its brightest channel is at least THRESHOLD (of 255) above the background's,
the colour of the image's corners. The lit area's box runs from the 0.5th to the 99.5th
percentile of the lit pixels' columns and rows, so a few stray bright samples (Cycles renders
without denoising) do not stretch it. The measure is the box intersection's area over the
smaller box's area: 1 when one box lies inside the other. It must reach --min-overlap (0.8), and
the boxes' areas must be within a factor of two of each other, so that a picture lit everywhere
(or a speck) cannot pass by containing (or hiding in) the other.

Boxes of two centred subjects of a size overlap whatever the subjects are, so the lit pixels
themselves are compared too: their intersection over union must reach --min-mask-iou (0.7). The
same preset rendered by both gave 0.89-0.90 in our runs; two different presets (bunny and heart)
0.55-0.56.

Usage: compare_lit_area.py VOXFLAME.png BLENDER.png [--min-overlap 0.8] [--min-mask-iou 0.7]
                           [--threshold 40]
Prints both boxes, the overlap, the boxes' and the lit pixels' intersection over union; exits 1
when the check fails.
"""

import argparse
import struct
import sys
import zlib


def read_png(path):
    """8-bit, non-interlaced grey, grey+alpha, RGB or RGBA PNG: rows of (r, g, b) tuples."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("%s is not a PNG" % path)
    position, compressed = 8, b""
    while position < len(data):
        (length,) = struct.unpack(">I", data[position:position + 4])
        kind = data[position + 4:position + 8]
        chunk = data[position + 8:position + 8 + length]
        position += 12 + length
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", chunk)
        elif kind == b"IDAT":
            compressed += chunk
    channels = {0: 1, 4: 2, 2: 3, 6: 4}.get(colour)
    if depth != 8 or channels is None or interlace:
        raise ValueError("%s: only 8-bit non-interlaced grey or RGB(A) PNGs are read here" % path)
    raw = zlib.decompress(compressed)
    stride = width * channels
    previous = bytearray(stride)
    rows = []
    offset = 0
    for _ in range(height):
        kind = raw[offset]
        line = bytearray(raw[offset + 1:offset + 1 + stride])
        offset += 1 + stride
        for x in range(stride):
            left = line[x - channels] if x >= channels else 0
            up = previous[x]
            up_left = previous[x - channels] if x >= channels else 0
            if kind == 1:
                line[x] = (line[x] + left) & 255
            elif kind == 2:
                line[x] = (line[x] + up) & 255
            elif kind == 3:
                line[x] = (line[x] + (left + up) // 2) & 255
            elif kind == 4:
                guess = left + up - up_left
                nearest = min((abs(guess - left), 0, left), (abs(guess - up), 1, up),
                              (abs(guess - up_left), 2, up_left))[2]
                line[x] = (line[x] + nearest) & 255
        if channels >= 3:
            rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        else:
            rows.append([(line[x * channels],) * 3 for x in range(width)])
        previous = line
    return rows


def lit_box(rows, threshold):
    height, width = len(rows), len(rows[0])
    corners = [rows[0][0], rows[0][-1], rows[-1][0], rows[-1][-1]]
    background = sorted(max(c) for c in corners)[1]  # a corner the picture reaches does not decide
    lit = {(x, y) for y, row in enumerate(rows) for x, pixel in enumerate(row)
           if max(pixel) >= background + threshold}
    if len(lit) < 16:
        return None, lit, width * height
    xs = sorted(x for x, _ in lit)
    ys = sorted(y for _, y in lit)
    low, high = int(0.005 * (len(xs) - 1)), int(0.995 * (len(xs) - 1))
    return (xs[low], ys[low], xs[high] + 1, ys[high] + 1), lit, width * height


def area(box):
    return max(0, box[2] - box[0]) * max(0, box[3] - box[1])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("voxflame")
    parser.add_argument("blender")
    parser.add_argument("--min-overlap", type=float, default=0.8)
    parser.add_argument("--min-mask-iou", type=float, default=0.7)
    parser.add_argument("--threshold", type=int, default=40)
    arguments = parser.parse_args()
    images = {name: read_png(path) for name, path in (("voxflame", arguments.voxflame),
                                                       ("blender", arguments.blender))}
    sizes = {name: (len(rows[0]), len(rows)) for name, rows in images.items()}
    if sizes["voxflame"] != sizes["blender"]:
        print("the images differ in size: %s" % sizes)
        return 1
    boxes, masks = {}, {}
    for name, rows in images.items():
        box, lit, pixels = lit_box(rows, arguments.threshold)
        if box is None:
            print("%s: nothing is lit (%d pixels)" % (name, len(lit)))
            return 1
        boxes[name], masks[name] = box, lit
        print("%-8s lit box x %d-%d, y %d-%d (%d of %d pixels lit)" % (name, box[0], box[2], box[1], box[3],
                                                                      len(lit), pixels))
    a, b = boxes["voxflame"], boxes["blender"]
    inter = area((max(a[0], b[0]), max(a[1], b[1]), min(a[2], b[2]), min(a[3], b[3])))
    overlap = inter / min(area(a), area(b))
    union = area(a) + area(b) - inter
    ratio = area(b) / area(a)
    mask_iou = len(masks["voxflame"] & masks["blender"]) / len(masks["voxflame"] | masks["blender"])
    print("overlap (box intersection over the smaller box) %.1f%%, boxes' intersection over union %.1f%%, "
          "area ratio blender/voxflame %.2f, lit pixels' intersection over union %.1f%%"
          % (100 * overlap, 100 * inter / union, ratio, 100 * mask_iou))
    if overlap < arguments.min_overlap or not 0.5 <= ratio <= 2.0 or mask_iou < arguments.min_mask_iou:
        print("FAIL: the renders are not lit in the same place (need %.0f%% box overlap, box areas within 2x "
              "and %.0f%% of lit pixels shared)" % (100 * arguments.min_overlap, 100 * arguments.min_mask_iou))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
