#!/usr/bin/env python3
"""Independent check of a hex mesh file (MEDIT .mesh, Hexahedra in VTK order), without the package:
every corner of every hexahedron positively oriented (the triple product of its three edges), every quad
used by one hexahedron (boundary) or by two with opposite orientations, the boundary a closed surface
(every boundary edge in exactly two boundary quads), and, if given, the number of boundary components.
  check_hex_mesh.py FILE.mesh [--components N]
Prints one line; exit 1 with the reason if a check fails."""
import sys
from collections import defaultdict

def main():
    path = sys.argv[1]
    want_components = int(sys.argv[sys.argv.index('--components') + 1]) if '--components' in sys.argv else None
    tok = open(path).read().split()
    i = tok.index('Vertices'); n = int(tok[i + 1])
    P = [tuple(float(x) for x in tok[i + 2 + 4 * k:i + 5 + 4 * k]) for k in range(n)]
    j = tok.index('Hexahedra'); m = int(tok[j + 1])
    H = [[int(x) - 1 for x in tok[j + 2 + 9 * k:j + 10 + 9 * k]] for k in range(m)]
    if m == 0: fail('no hexahedron')
    corner = [(1, 3, 4), (2, 0, 5), (3, 1, 6), (0, 2, 7), (7, 5, 0), (4, 6, 1), (5, 7, 2), (6, 4, 3)]
    faces = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
    def det(a, b, c):
        return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])
    bad_corners = 0
    quads = defaultdict(list)
    for h in H:
        if len(set(h)) != 8 or min(h) < 0 or max(h) >= n: fail('hexahedron with repeated or invalid vertices: %s' % h)
        for c, (a, b, d) in enumerate(corner):
            o = P[h[c]]
            if det(sub(P[h[a]], o), sub(P[h[b]], o), sub(P[h[d]], o)) <= 0: bad_corners += 1
        for f in faces:
            q = tuple(h[k] for k in f)
            quads[tuple(sorted(q))].append(q)
    if bad_corners: fail('%d hexahedron corners not positively oriented' % bad_corners)
    boundary = []
    for key, qs in quads.items():
        if len(qs) == 1: boundary.append(qs[0]); continue
        if len(qs) > 2: fail('quad %s in %d hexahedra' % (key, len(qs)))
        a, b = qs
        if not any(all(a[k] == b[(s - k) % 4] for k in range(4)) for s in range(4)): fail('quad %s twice with one orientation' % (key,))
    edge_quads = defaultdict(int)
    for q in boundary:
        for k in range(4): edge_quads[tuple(sorted((q[k], q[(k + 1) % 4])))] += 1
    if any(c != 2 for c in edge_quads.values()): fail('boundary edge not in two boundary quads')
    parent = {}
    def find(x):
        while parent.setdefault(x, x) != x:
            parent[x] = parent[parent[x]]; x = parent[x]
        return x
    for q in boundary:
        for k in range(1, 4): parent[find(q[k])] = find(q[0])
    components = len({find(v) for q in boundary for v in q})
    if want_components is not None and components != want_components:
        fail('%d boundary components, expected %d' % (components, want_components))
    print('%s: %d hexahedra, %d boundary quads, %d boundary components, every corner positive, conforming' % (path, m, len(boundary), components))

def fail(msg):
    print('%s: %s' % (sys.argv[1], msg))
    sys.exit(1)

main()
