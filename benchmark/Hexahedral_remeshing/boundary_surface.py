#!/usr/bin/env python3
# Copyright (c) 2026 The Hexahedral_remeshing project.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Writes the boundary surface of a tetrahedral mesh (legacy ASCII .vtk, tetrahedra of type 10) as an OFF
# file: the triangles that belong to one tetrahedron only (the surface reader orients them). With `bench_frame_field --max-volume V`
# (or `hexmesh frames --max-volume V`) TetGen refills it at any size: the issue-14 part of 768k tets is
#   python3 boundary_surface.py ../shared/data/mambo/B0.vtk B0.off
#   bench_frame_field --runs 1 --max-volume 0.00052 B0.off
import sys


def read_vtk_tets(path):
    tokens = open(path).read().split()
    i = tokens.index("POINTS")
    n = int(tokens[i + 1])
    points = [tuple(float(x) for x in tokens[i + 3 + 3 * k:i + 6 + 3 * k]) for k in range(n)]
    j = tokens.index("CELLS")
    m = int(tokens[j + 1])
    k = j + 3
    cells = []
    for _ in range(m):
        c = int(tokens[k])
        cells.append([int(x) for x in tokens[k + 1:k + 1 + c]])
        k += 1 + c
    t = tokens.index("CELL_TYPES")
    types = [int(x) for x in tokens[t + 2:t + 2 + m]]
    return points, [c for c, ty in zip(cells, types) if ty == 10]


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: boundary_surface.py MESH.vtk OUT.off")
    points, tets = read_vtk_tets(sys.argv[1])
    count, oriented = {}, {}
    for a, b, c, d in tets:
        for f in ((b, c, d), (a, d, c), (a, b, d), (a, c, b)):
            key = tuple(sorted(f))
            count[key] = count.get(key, 0) + 1
            oriented[key] = f
    boundary = [oriented[k] for k, c in count.items() if c == 1]
    used = sorted({v for f in boundary for v in f})
    index = {v: i for i, v in enumerate(used)}
    with open(sys.argv[2], "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(used), len(boundary)))
        for v in used:
            out.write("%.17g %.17g %.17g\n" % points[v])
        for f in boundary:
            out.write("3 %d %d %d\n" % tuple(index[v] for v in f))
    print("%s: %d vertices, %d triangles" % (sys.argv[2], len(used), len(boundary)))


if __name__ == "__main__":
    main()
