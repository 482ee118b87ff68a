#!/usr/bin/env python3
"""Independent measure of how well a hex mesh follows the sharp CAD curves of a part, compared with the
`features.coverage` of hexmesh's JSON report:
  check_feature_coverage.py HEX.mesh PART.step REPORT.json [--tolerance 0.05] [--min-coverage C]
The sharp curves are the CAD curves (gmsh's OpenCASCADE import) whose two faces' normals differ by more
than 30 degrees at the curve's middle (seams and curves between tangent faces are not sharp). A boundary
hex edge (on a quad of one hexahedron) follows a sharp curve if both its endpoints are within 5% of its
length of the curve (sampled at 400 points) and its midpoint within 10% (a chord of an arc); a sample of
the curve is covered if it lies within 10% of the length of such an edge from it. The coverage (covered
samples, weighted by the curve length) must equal the report's within the tolerance (absolute), and be
at least C if given. Prints one line; exit 1 on failure."""
import json
import math
import sys
from collections import Counter

import gmsh


def fail(msg):
    print('check_feature_coverage: ' + msg)
    sys.exit(1)


def segment_distance(p, a, b):
    ab = [b[d] - a[d] for d in range(3)]
    ap = [p[d] - a[d] for d in range(3)]
    l2 = sum(x * x for x in ab)
    t = 0.0 if l2 == 0 else max(0.0, min(1.0, sum(ab[d] * ap[d] for d in range(3)) / l2))
    return math.dist(p, [a[d] + t * ab[d] for d in range(3)])


def polyline_distance(p, pts):
    return min(segment_distance(p, pts[i], pts[i + 1]) for i in range(len(pts) - 1))


def main():
    mesh, step, report = sys.argv[1:4]
    tolerance = float(sys.argv[sys.argv.index('--tolerance') + 1]) if '--tolerance' in sys.argv else 0.05
    minimum = float(sys.argv[sys.argv.index('--min-coverage') + 1]) if '--min-coverage' in sys.argv else None
    tok = open(mesh).read().split()
    i = tok.index('Vertices'); n = int(tok[i + 1])
    P = [tuple(float(x) for x in tok[i + 2 + 4 * k:i + 5 + 4 * k]) for k in range(n)]
    j = tok.index('Hexahedra'); m = int(tok[j + 1])
    H = [[int(x) - 1 for x in tok[j + 2 + 9 * k:j + 10 + 9 * k]] for k in range(m)]
    faces = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    count, cycle = Counter(), {}
    for h in H:
        for f in faces:
            key = tuple(sorted(h[x] for x in f))
            count[key] += 1
            cycle[key] = [h[x] for x in f]
    edges = set()
    for key, c in count.items():
        if c == 1:
            q = cycle[key]
            for a in range(4): edges.add(tuple(sorted((q[a], q[(a + 1) % 4]))))
    gmsh.initialize()
    gmsh.option.setNumber('General.Terminal', 0)
    gmsh.model.occ.importShapes(step)
    gmsh.model.occ.synchronize()
    covered_length = total_length = 0.0
    sharp = 0
    for _, tag in gmsh.model.getEntities(1):
        up, _ = gmsh.model.getAdjacencies(1, tag)
        if len(up) != 2: continue
        lo, hi = gmsh.model.getParametrizationBounds(1, tag)
        N = 400
        pts = [tuple(gmsh.model.getValue(1, tag, [lo[0] + (hi[0] - lo[0]) * k / N])) for k in range(N + 1)]
        mid = pts[N // 2]
        normals = [gmsh.model.getNormal(f, gmsh.model.getParametrization(2, f, list(mid))) for f in up]
        cos = sum(a * b for a, b in zip(*normals)) / math.sqrt(sum(a * a for a in normals[0]) * sum(b * b for b in normals[1]))
        if math.degrees(math.acos(max(-1.0, min(1.0, cos)))) <= 30: continue
        sharp += 1
        length = sum(math.dist(pts[k], pts[k + 1]) for k in range(N))
        lo_box = [min(p[d] for p in pts) for d in range(3)]
        hi_box = [max(p[d] for p in pts) for d in range(3)]
        along = []
        for a, b in edges:
            L = math.dist(P[a], P[b])
            if any(P[v][d] < lo_box[d] - 0.05 * L or P[v][d] > hi_box[d] + 0.05 * L for v in (a, b) for d in range(3)): continue
            mid_ab = [(P[a][d] + P[b][d]) / 2 for d in range(3)]
            if polyline_distance(P[a], pts) <= 0.05 * L and polyline_distance(P[b], pts) <= 0.05 * L and \
               polyline_distance(mid_ab, pts) <= 0.1 * L:
                along.append((P[a], P[b], L))
        covered = sum(1 for p in pts[:-1] if any(segment_distance(p, a, b) <= 0.1 * L for a, b, L in along))
        covered_length += length * covered / N
        total_length += length
    gmsh.finalize()
    measured = covered_length / total_length if total_length > 0 else 1.0
    reported = json.load(open(report))['features']['coverage']
    print('%s: %d sharp CAD curves, coverage measured %.3f, reported %.3f' % (mesh, sharp, measured, reported))
    if abs(measured - reported) > tolerance: fail('coverage differs by more than %g' % tolerance)
    if minimum is not None and measured < minimum: fail('coverage below %g' % minimum)


if __name__ == '__main__':
    main()
