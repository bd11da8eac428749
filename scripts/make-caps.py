#!/usr/bin/python3
"""Writes rules/fill/*.cap, the caps of the constructive fill (docs/fill.md).

A cap is the region between one surface quad a b c d (a, c black; b, d white)
and the inner surface under it. Its boundary: the quad on top; the inner quad
split by a diagonal into two triangles of three quads each at the bottom; four
walls, one per edge, each a hexagon (top edge, the black corner's vertical edge,
the bottom edge's two halves, the white corner's two-segment vertical edge):
the even wall in two quads (chord from the black top to the white bottom), the
three odd walls in three quads round a centre. The inner diagonal joins the
black corners a and c (surface validation refuses two quads sharing a diagonal,
so any fixed choice is safe). This script writes that boundary for the even
wall on cd, meshes it with build/loom (the weave and the closure's search,
which finds it in the database; the boundary layer loom adds for placement is
peeled off again), and writes four caps: that one and its images under the
symmetries of the square that keep the colours (a half turn, the two diagonal
mirrors). Usage: scripts/make-caps.py [WORKDIR]  (run from the source tree)
"""
import os, subprocess, sys

CORNERS = {'a': (0, 0), 'b': (1, 0), 'c': (1, 1), 'd': (0, 1)}
WHITE = {'b', 'd'}
EDGES = ['ab', 'bc', 'cd', 'da']
INSET = 0.25  # the inner square, in cap coordinates, at z = 0


def bottom(x, y):
    return (INSET + (1 - 2 * INSET) * x, INSET + (1 - 2 * INSET) * y, 0.0)


def boundary(odd, diagonal):
    """Role -> cap coordinates, and the boundary quads oriented outward."""
    pos, faces = {}, [['a_t', 'b_t', 'c_t', 'd_t']]
    def node(name, p):
        pos.setdefault(name, p)
        return name
    for k, (x, y) in CORNERS.items():
        node(k + '_t', (x, y, 1.0)); node(k + '_b', bottom(x, y))
        if k in WHITE: node(k + '_m', (x, y, 0.5))
    for i, e in enumerate(EDGES):
        x, y = e
        (px, py), (qx, qy) = CORNERS[x], CORNERS[y]
        mid = node('M' + e, bottom((px + qx) / 2, (py + qy) / 2))
        b, w = (y, x) if x in WHITE else (x, y)
        hexagon = [b + '_t', w + '_t', w + '_m', w + '_b', mid, b + '_b']
        if i in odd:
            c = node('W' + e, tuple(sum(pos[n][t] for n in hexagon) / 6 for t in range(3)))
            faces += [[c] + [hexagon[(2 * r + s) % 6] for s in range(3)] for r in range(3)]
        else:
            faces += [hexagon[0:4], hexagon[3:6] + hexagon[0:1]]
    p, q = diagonal
    mid = node('Mdiag', bottom((CORNERS[p][0] + CORNERS[q][0]) / 2, (CORNERS[p][1] + CORNERS[q][1]) / 2))
    def edge_mid(u, v):
        return mid if {u, v} == {p, q} else ('M' + u + v if u + v in EDGES else 'M' + v + u)
    for i, apex in enumerate(k for k in 'abcd' if k not in diagonal):
        tri = [apex, p, q]
        g = node('Gd%d' % i, bottom(sum(CORNERS[t][0] for t in tri) / 3, sum(CORNERS[t][1] for t in tri) / 3))
        for t in range(3):
            u, v, w = tri[t], tri[(t + 1) % 3], tri[(t + 2) % 3]
            faces.append([u + '_b', edge_mid(u, v), g, edge_mid(u, w)])
    oriented = []
    for f in faces:  # Newell normal against the direction from the cap's centre
        P = [pos[n] for n in f]
        n = [0.0, 0.0, 0.0]
        for i in range(4):
            a, b = P[i], P[(i + 1) % 4]
            n[0] += (a[1] - b[1]) * (a[2] + b[2]); n[1] += (a[2] - b[2]) * (a[0] + b[0]); n[2] += (a[0] - b[0]) * (a[1] + b[1])
        out = sum(n[t] * (sum(p[t] for p in P) / 4 - 0.5) for t in range(3))
        oriented.append(f if out > 0 else f[::-1])
    return pos, oriented


def write_obj(path, pos, faces):
    names = list(pos)
    index = {n: i + 1 for i, n in enumerate(names)}
    with open(path, 'w') as o:
        for n in names: o.write('v %g %g %g\n' % pos[n])
        for f in faces: o.write('f ' + ' '.join(str(index[n]) for n in f) + '\n')


PILLOW = 4  # the cell field `source` of a pillow hex (docs/formats.md)


def read_vtk(path):
    """Points, hexes, and each hex's `source` cell field."""
    words = open(path).read().split('\n')
    i = next(k for k, l in enumerate(words) if l.startswith('POINTS'))
    points = [tuple(map(float, words[i + 1 + k].split())) for k in range(int(words[i].split()[1]))]
    i = next(k for k, l in enumerate(words) if l.startswith('CELLS'))
    hexes = [list(map(int, words[i + 1 + k].split()[1:])) for k in range(int(words[i].split()[1]))]
    i = next(k for k, l in enumerate(words) if l.startswith('SCALARS source'))
    source = [int(words[i + 2 + k]) for k in range(len(hexes))]
    return points, hexes, source


def peel_layer(hexes, source, on_surface):
    """The mesh inside the boundary layer loom weave pillowed in (its pillow
    hexes, each a surface quad and its copy joined by the edges k, k+4), with
    each copied node put back on the surface node it copies."""
    back = {}
    for h, s in zip(hexes, source):
        if s != PILLOW: continue
        for k in range(4):
            outer, inner = (h[k], h[k + 4]) if on_surface(h[k]) else (h[k + 4], h[k])
            assert on_surface(outer) and not on_surface(inner), 'a pillow hex not on the surface'
            assert back.setdefault(inner, outer) == outer, 'a node copied twice'
    return [[back.get(v, v) for v in h] for h, s in zip(hexes, source) if s != PILLOW]


HEX_FACES = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]


def boundary_faces(hexes):
    uses = {}
    for h in hexes:
        for f in HEX_FACES:
            uses.setdefault(frozenset(h[t] for t in f), []).append([h[t] for t in f])
    return [v[0] for v in uses.values() if len(v) == 1]


# Symmetries of the square keeping the colours: corner map, mirror?, map of cap coordinates.
SYMMETRIES = {
    'itself': ('abcd', False, lambda x, y: (x, y)),
    'its half turn': ('cdab', False, lambda x, y: (1 - x, 1 - y)),
    'its mirror in bd': ('cbad', True, lambda x, y: (1 - y, 1 - x)),
    'its mirror in ac': ('adcb', True, lambda x, y: (y, x)),
}


def edge_name(u, v):
    return u + v if u + v in EDGES else v + u


def image(role, corner, diagonal):
    if role.startswith('i') or role == 'Mdiag': return role
    if role[1:2] == '_': return corner[role[0]] + role[1:]
    if role.startswith('Gd'):
        apexes = [k for k in 'abcd' if k not in diagonal]
        return 'Gd%d' % apexes.index(corner[apexes[int(role[2])]])
    return role[0] + edge_name(corner[role[1]], corner[role[2]])


def make(diagonal, even, work, out_dir, loom):
    odd = [i for i in range(4) if i != even]
    pos, faces = boundary(odd, diagonal)
    stem = os.path.join(work, 'cap_%s' % diagonal)
    write_obj(stem + '.obj', pos, faces)
    if os.path.exists(stem + '.vtk'): os.remove(stem + '.vtk')
    # The whole of loom weave, closure included: the search finds the cap's
    # boundary in the database (36 hexes). The whole-surface fill is off: it
    # would need these caps.
    status = subprocess.run([loom, 'weave', stem + '.obj', '-o', stem + '.vtk', '--closure', 'search', '-q']).returncode
    if status not in (0, 3):  # 3: geometry not achieved, which is fine: only the connectivity is kept
        sys.exit('make-caps: loom weave gave no cap (status %d)' % status)
    points, hexes, source = read_vtk(stem + '.vtk')
    by_position = {tuple(round(x, 6) for x in p): n for n, p in pos.items()}
    hexes = peel_layer(hexes, source, lambda v: tuple(round(x, 6) for x in points[v]) in by_position)
    used = sorted({v for h in hexes for v in h})
    renumber = {v: k for k, v in enumerate(used)}
    points = [points[v] for v in used]
    hexes = [[renumber[v] for v in h] for h in hexes]
    names, inside = [], {}
    for p in points:
        n = by_position.get(tuple(round(x, 6) for x in p))
        if n is None:
            n = 'i%d' % len(inside); inside[n] = p
        names.append(n)
    hexes = [[names[v] for v in h] for h in hexes]
    top = next(f for f in boundary_faces(hexes) if set(f) == {'a_t', 'b_t', 'c_t', 'd_t'})
    assert top[top.index('a_t'):] + top[:top.index('a_t')] == ['a_t', 'b_t', 'c_t', 'd_t'], 'hexes not positive'
    for what, (corners, mirror, place) in SYMMETRIES.items():
        corner = dict(zip('abcd', corners))
        e = edge_name(corner[EDGES[even][0]], corner[EDGES[even][1]])
        mapped = [[image(n, corner, diagonal) for n in h] for h in hexes]
        if mirror: mapped = [[h[0], h[3], h[2], h[1], h[4], h[7], h[6], h[5]] for h in mapped]
        _, expected = boundary([i for i in range(4) if EDGES[i] != e], diagonal)
        assert {frozenset(f) for f in boundary_faces(mapped)} == {frozenset(f) for f in expected}, what
        with open(os.path.join(out_dir, 'cap_even_%s.cap' % e), 'w') as o:
            o.write('# Cap over one quad: even wall %s, inner diagonal %s, %d hexes (docs/fill.md).\n' % (e, diagonal, len(mapped)))
            o.write('# Written by scripts/make-caps.py: %s of the cap with even wall %s meshed by loom weave.\n' % (what, EDGES[even]))
            o.write('even %s\n' % e)
            for n, p in inside.items():
                x, y = place(p[0], p[1])
                o.write('node %s %.4f %.4f %.4f\n' % (n, x, y, p[2]))
            for h in mapped: o.write('hex ' + ' '.join(h) + '\n')


if __name__ == '__main__':
    work = sys.argv[1] if len(sys.argv) > 1 else '/tmp/loom-caps'
    os.makedirs(work, exist_ok=True)
    make('ac', 2, work, 'rules/fill', 'build/loom')
