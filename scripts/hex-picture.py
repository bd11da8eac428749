#!/usr/bin/python3
"""Cut-away picture of a Loom hex mesh as SVG, hexes coloured by their source or quality.

    /usr/bin/python3 scripts/hex-picture.py MESH.vtk PICTURE.svg|PICTURE.png [--axis x|y|z] [--keep 0.5]
        [--colour source|quality]

Reads the legacy ASCII .vtk that `loom weave` writes: its `source` cell field
(0 woven, 1 searched, 2 database, 3 filled, 4 pillow) or, with --colour quality,
its `scaled_jacobian` field in five bands (<= 0, below 0.2, 0.5, 0.8, and above). It keeps the hexes whose
centre lies in the given fraction of the hex centres' extent along the axis, on the
side away from the viewer, and draws the faces that bound that set, farthest
first, seen from a fixed oblique direction (from low x and y, from above). Plain Python, no modules beyond the standard library, so that it
runs on a bare Debian.
"""
import argparse
import math
import os
import struct
import sys
import zlib

COLOURS = {0: (70, 130, 180), 1: (230, 150, 40), 2: (90, 170, 90), 3: (200, 60, 60), 4: (170, 170, 170)}
NAMES = {0: "woven", 1: "searched", 2: "database", 3: "filled", 4: "pillow"}
QUALITY_COLOURS = {0: (200, 40, 40), 1: (240, 150, 40), 2: (230, 210, 80), 3: (140, 190, 110), 4: (70, 130, 180)}
QUALITY_NAMES = {0: "SJ <= 0", 1: "0 - 0.2", 2: "0.2 - 0.5", 3: "0.5 - 0.8", 4: ">= 0.8"}
FACES = ((0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7))


def quality_band(sj):
    return 0 if sj <= 0 else 1 if sj < 0.2 else 2 if sj < 0.5 else 3 if sj < 0.8 else 4


def fail(message):
    print(f"hex-picture: {message}", file=sys.stderr)
    sys.exit(2)


def read_vtk(path, field):
    try:
        tokens = open(path).read().split()
    except OSError as e:
        fail(f"{path}: {e.strerror}; give a .vtk that loom weave wrote")
    def section(name):
        try:
            return tokens.index(name)
        except ValueError:
            fail(f"{path}: no {name} section; give a legacy ASCII .vtk that loom weave wrote")
    p = section("POINTS")
    n = int(tokens[p + 1])
    if not 0 <= n <= (len(tokens) - p) // 3:
        fail(f"{path}: POINTS says {n} nodes, more than the file holds; the file is damaged")
    points = [tuple(float(t) for t in tokens[p + 3 + 3 * i: p + 6 + 3 * i]) for i in range(n)]
    c = section("CELLS")
    cells, at = [], c + 3
    count = int(tokens[c + 1])
    if not 0 <= count <= (len(tokens) - c) // 9:
        fail(f"{path}: CELLS says {count} cells, more than the file holds; the file is damaged")
    for _ in range(count):
        k = int(tokens[at])
        if k != 8:
            fail(f"{path}: a cell with {k} nodes; this draws hex meshes only")
        cell = tuple(int(t) for t in tokens[at + 1: at + 9])
        if len(cell) != 8 or any(not 0 <= v < n for v in cell):
            fail(f"{path}: cell {len(cells)} names a node that is not in POINTS; the file is damaged")
        cells.append(cell)
        at += 9
    if not cells:
        fail(f"{path}: no hexes to draw")
    if field == "source" and "source" not in tokens:
        return points, cells, [0] * len(cells)
    if field not in tokens:
        fail(f"{path}: no {field} cell field; give a .vtk that loom weave or loom mesh wrote")
    s = tokens.index(field) + 5  # NAME TYPE 1 LOOKUP_TABLE default
    values = tokens[s: s + len(cells)]
    if len(values) != len(cells):
        fail(f"{path}: the {field} field has {len(values)} values for {len(cells)} hexes; the file is damaged")
    if field == "source":
        return points, cells, [int(t) for t in values]
    return points, cells, [quality_band(float(t)) for t in values]


def write_png(path, width, height, polygons):
    """Scanline-fills the polygons (farthest first) with black outlines; rows of RGB."""
    pixels = [bytearray(b"\xff" * (3 * width)) for _ in range(height)]
    def plot(x, y, rgb):
        if 0 <= x < width and 0 <= y < height:
            pixels[y][3 * x: 3 * x + 3] = bytes(rgb)
    for corners, rgb in polygons:
        ys = [p[1] for p in corners]
        for y in range(max(0, int(min(ys))), min(height, int(max(ys)) + 1)):
            yc = y + 0.5
            xs = []
            for (x0, y0), (x1, y1) in zip(corners, corners[1:] + corners[:1]):
                if (y0 <= yc) != (y1 <= yc):
                    xs.append(x0 + (yc - y0) * (x1 - x0) / (y1 - y0))
            xs.sort()
            for a, b in zip(xs[0::2], xs[1::2]):
                for x in range(max(0, int(a + 0.5)), min(width, int(b + 0.5))):
                    pixels[y][3 * x: 3 * x + 3] = bytes(rgb)
        for (x0, y0), (x1, y1) in zip(corners, corners[1:] + corners[:1]):
            steps = int(max(abs(x1 - x0), abs(y1 - y0))) + 1
            for i in range(steps + 1):
                t = i / steps
                plot(int(x0 + t * (x1 - x0)), int(y0 + t * (y1 - y0)), (0, 0, 0))
    raw = b"".join(b"\x00" + bytes(row) for row in pixels)
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("mesh")
    ap.add_argument("picture", help="PICTURE.png or PICTURE.svg")
    ap.add_argument("--axis", choices="xyz", default="x")
    ap.add_argument("--keep", type=float, default=0.5, help="fraction of the extent kept (default 0.5)")
    ap.add_argument("--colour", choices=("source", "quality"), default="source")
    a = ap.parse_args()
    colours, names = (COLOURS, NAMES) if a.colour == "source" else (QUALITY_COLOURS, QUALITY_NAMES)
    try:
        points, cells, source = read_vtk(a.mesh, "source" if a.colour == "source" else "scaled_jacobian")
    except (ValueError, IndexError):
        fail(f"{a.mesh}: a number is missing or malformed; give a legacy ASCII .vtk that loom weave wrote")
    axis = "xyz".index(a.axis)
    centres = [sum(points[v][axis] for v in c) / 8 for c in cells]
    lo, hi = min(centres), max(centres)  # hex centres: a node placed far off does not stretch the cut
    # The view looks from low x and y and from high z: keep the far part, so the cut faces the viewer.
    def far_side(centre):
        return centre <= lo + a.keep * (hi - lo) if axis == 2 else centre >= hi - a.keep * (hi - lo)
    kept = [h for h in range(len(cells)) if far_side(centres[h])]

    faces = {}
    for h in kept:
        for f in FACES:
            quad = tuple(cells[h][i] for i in f)
            key = tuple(sorted(quad))
            faces[key] = None if key in faces else (quad, source[h])
    drawn = [v for v in faces.values() if v is not None]

    # An oblique view: turn about z, then tilt about x.
    yaw, pitch = math.radians(35), math.radians(-60)
    def view(p):
        x = p[0] * math.cos(yaw) - p[1] * math.sin(yaw)
        y = p[0] * math.sin(yaw) + p[1] * math.cos(yaw)
        return (x, y * math.cos(pitch) - p[2] * math.sin(pitch), y * math.sin(pitch) + p[2] * math.cos(pitch))
    projected = [view(p) for p in points]
    xs = [projected[v][0] for q, _ in drawn for v in q]
    ys = [projected[v][1] for q, _ in drawn for v in q]
    if not xs:
        fail("no hex kept; raise --keep")
    size, margin = 800.0, 20.0
    scale = (size - 2 * margin) / max(max(xs) - min(xs), max(ys) - min(ys))
    def screen(v):
        x, y, _ = projected[v]
        return margin + (x - min(xs)) * scale, margin + (max(ys) - y) * scale

    def shade_rgb(quad, rgb):
        a, b, c = (projected[quad[i]] for i in (0, 1, 2))
        u = [b[i] - a[i] for i in range(3)]
        w = [c[i] - a[i] for i in range(3)]
        n = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
        length = math.sqrt(sum(x * x for x in n)) or 1.0
        light = 0.45 + 0.55 * abs(n[2]) / length
        return tuple(int(x * light) for x in rgb)

    drawn.sort(key=lambda d: sum(projected[v][2] for v in d[0]))
    polygons = [([screen(v) for v in quad], shade_rgb(quad, colours.get(s, (0, 0, 0)))) for quad, s in drawn]
    tmp = a.picture + ".tmp"
    if a.picture.endswith(".png"):
        write_png(tmp, int(size), int(size), polygons)
    else:
        out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{size:.0f}" height="{size + 30:.0f}">',
               '<rect width="100%" height="100%" fill="white"/>']
        for corners, rgb in polygons:
            pts = " ".join(f"{x:.1f},{y:.1f}" for x, y in corners)
            fill = "#{:02x}{:02x}{:02x}".format(*rgb)
            out.append(f'<polygon points="{pts}" fill="{fill}" stroke="black" stroke-width="0.4"/>')
        x = margin
        for s, name in names.items():
            fill = "#{:02x}{:02x}{:02x}".format(*colours[s])
            out.append(f'<rect x="{x:.0f}" y="{size + 8:.0f}" width="14" height="14" fill="{fill}"/>')
            out.append(f'<text x="{x + 18:.0f}" y="{size + 20:.0f}" font-family="sans-serif" '
                       f'font-size="13">{name} {source.count(s)}</text>')
            x += 150
        out.append("</svg>")
        with open(tmp, "w") as f:
            f.write("\n".join(out) + "\n")
    os.replace(tmp, a.picture)
    print(f"wrote {a.picture}: {len(kept)} of {len(cells)} hexes, {len(drawn)} faces")


if __name__ == "__main__":
    main()
