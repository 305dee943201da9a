#!/usr/bin/env python3
"""Decimates a binary little-endian PLY triangle mesh by vertex clustering: vertices are merged
per cell of a uniform grid (CELLS cells along the longest side, each cluster at its members'
mean), faces that collapse are dropped. Used for presets/meshes/dragon_100k.ply, which is

    scripts/decimate_ply.py ../shared/data/meshes/dragon_200k.ply presets/meshes/dragon_100k.ply 160

(the Stanford dragon's 202,520 triangles brought to 97,326, under 2 MiB). A vertex moves by at
most half a cell (0.3% of the dragon's length, about half a voxel of the presets' 192 grid), which
no render of the filled volume shows; finer scales are the 200k original's, in ../shared."""
import struct
import sys


def read_ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    if "format binary_little_endian 1.0" not in header:
        raise SystemExit(f"{path}: only binary little-endian PLY is supported")
    vertices = int(next(l for l in header if l.startswith("element vertex")).split()[2])
    faces = int(next(l for l in header if l.startswith("element face")).split()[2])
    offset = end
    points = list(struct.iter_unpack("<3f", data[offset:offset + 12 * vertices]))
    offset += 12 * vertices
    triangles = []
    for _ in range(faces):
        count = data[offset]
        if count != 3:
            raise SystemExit(f"{path}: only triangles are supported")
        triangles.append(struct.unpack_from("<3i", data, offset + 1))
        offset += 13
    comments = [l for l in header if l.startswith("comment")]
    return points, triangles, comments


def main():
    source, target, cells = sys.argv[1], sys.argv[2], int(sys.argv[3])
    points, triangles, comments = read_ply(source)
    low = [min(p[a] for p in points) for a in range(3)]
    high = [max(p[a] for p in points) for a in range(3)]
    size = max(high[a] - low[a] for a in range(3)) / cells
    cluster_of, sums = {}, []
    remap = []
    for p in points:
        key = tuple(int((p[a] - low[a]) / size) for a in range(3))
        index = cluster_of.get(key)
        if index is None:
            index = cluster_of[key] = len(sums)
            sums.append([0.0, 0.0, 0.0, 0])
        s = sums[index]
        s[0] += p[0]; s[1] += p[1]; s[2] += p[2]; s[3] += 1
        remap.append(index)
    kept, seen = [], set()
    for a, b, c in triangles:
        a, b, c = remap[a], remap[b], remap[c]
        if a == b or b == c or a == c:
            continue
        key = tuple(sorted((a, b, c)))
        if key in seen:
            continue
        seen.add(key)
        kept.append((a, b, c))
    with open(target, "wb") as out:
        header = ["ply", "format binary_little_endian 1.0", *comments,
                  f"comment decimated by scripts/decimate_ply.py, {cells} cells along the longest side",
                  f"element vertex {len(sums)}", "property float x", "property float y", "property float z",
                  f"element face {len(kept)}", "property list uchar int vertex_indices", "end_header"]
        out.write(("\n".join(header) + "\n").encode("ascii"))
        for s in sums:
            out.write(struct.pack("<3f", s[0] / s[3], s[1] / s[3], s[2] / s[3]))
        for t in kept:
            out.write(struct.pack("<B3i", 3, *t))
    print(f"{target}: {len(sums)} vertices, {len(kept)} triangles (from {len(points)} and {len(triangles)})")


if __name__ == "__main__":
    main()
