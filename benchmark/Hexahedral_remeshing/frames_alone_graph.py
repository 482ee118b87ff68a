#!/usr/bin/env python3
# The singular graph of a frame field from its frames alone, as an outside reader of `hexmesh frames
# --frames F.vtk` sees it: every face's matching is the closest of the 24 rotations of the cube between the
# two frames, an interior edge's holonomy is the product around its ring, and the edge is
#   regular      the identity,
#   along        a quarter turn whose axis (read in the first tetrahedron's frame) is within 45 degrees
#                of the edge (a valence 3 or 5 edge a hex mesh can follow),
#   jog          a quarter turn about an axis more than 45 degrees off the edge,
#   improper     any other rotation;
# a dangling end is an interior vertex with exactly one singular edge. None of the package's code is used.
#   frames_alone_graph.py F.vtk [F2.vtk ...]   one line per file: along, jog, improper, not_quarter_along, dangling
import collections
import itertools
import sys

import numpy as np


def read_frames(path):
    tokens = open(path).read().split('\n')
    i = 0
    while not tokens[i].startswith('POINTS'):
        i += 1
    n = int(tokens[i].split()[1])
    values = []
    i += 1
    while len(values) < 3 * n:
        values += tokens[i].split()
        i += 1
    points = np.array(values, float).reshape(n, 3)
    while not tokens[i].startswith('CELLS'):
        i += 1
    m = int(tokens[i].split()[1])
    tets = np.array([list(map(int, tokens[i + 1 + k].split()))[1:] for k in range(m)])
    i += m + 1
    columns = []
    for name in ['frame_u', 'frame_v', 'frame_w']:
        while not tokens[i].startswith('VECTORS ' + name):
            i += 1
        i += 1
        values = []
        while len(values) < 3 * m:
            values += tokens[i].split()
            i += 1
        columns.append(np.array(values, float).reshape(m, 3))
    return points, tets, np.stack(columns, axis=2)


def cube_rotations():
    group = []
    for perm in itertools.permutations(range(3)):
        for signs in itertools.product([1, -1], repeat=3):
            R = np.zeros((3, 3))
            for c in range(3):
                R[perm[c], c] = signs[c]
            if np.linalg.det(R) > 0:
                group.append(R)
    return np.array(group)


def analyze(path):
    points, tets, frames = read_frames(path)
    group = cube_rotations()
    faces = collections.defaultdict(list)
    for t, tv in enumerate(tets):
        for k in range(4):
            faces[tuple(sorted(np.delete(tv, k)))].append(t)
    interior = [ts for ts in faces.values() if len(ts) == 2]
    a = np.array([ts[0] for ts in interior])
    b = np.array([ts[1] for ts in interior])
    # the step from a to b: g closest to E_a^T E_b (maximizing tr(g^T E_a^T E_b)), so that the product
    # of the steps around a ring telescopes to the identity where the frames turn smoothly
    scores = np.einsum('nik,gik->ng', np.einsum('nji,njk->nik', frames[a], frames[b]), group)
    best = np.argmax(scores, axis=1)
    step = {}
    for k in range(len(interior)):
        g = group[best[k]]
        step[(a[k], b[k])] = g
        step[(b[k], a[k])] = g.T
    boundary_vertices = {v for f, ts in faces.items() if len(ts) == 1 for v in f}
    boundary_faces = {f for f, ts in faces.items() if len(ts) == 1}
    edge_tets = collections.defaultdict(list)
    for t, tv in enumerate(tets):
        for u, v in itertools.combinations(sorted(tv), 2):
            edge_tets[(u, v)].append(t)
    counts = collections.Counter()
    singular_degree = collections.Counter()
    for (u, v), ring in edge_tets.items():
        around = [f for t in ring for f in (tuple(sorted(np.delete(tets[t], k))) for k in range(4)) if u in f and v in f]
        if any(f in boundary_faces for f in around):
            continue
        order, previous, current, members = [ring[0]], None, ring[0], set(ring)
        while True:
            following = None
            for f in (tuple(sorted(np.delete(tets[current], k))) for k in range(4)):
                if u in f and v in f:
                    other = [x for x in faces[f] if x != current][0]
                    if other != previous and other in members:
                        following = other
                        break
            if following is None or following == ring[0]:
                break
            order.append(following)
            previous, current = current, following
        H = np.eye(3)
        for k in range(len(order)):
            H = H @ step[(order[k], order[(k + 1) % len(order)])]
        trace = np.trace(H)
        if abs(trace - 3) < 1e-6:
            continue
        singular_degree[u] += 1
        singular_degree[v] += 1
        if abs(trace - 1) < 1e-6:
            w = np.array([H[2, 1] - H[1, 2], H[0, 2] - H[2, 0], H[1, 0] - H[0, 1]])
            axis = frames[order[0]][:, int(np.argmax(np.abs(w)))]
            d = points[v] - points[u]
            along = abs(np.dot(axis, d)) >= np.cos(np.pi / 4) * np.linalg.norm(d)
            counts['along' if along else 'jog'] += 1
        else:
            counts['improper'] += 1
    dangling = sum(1 for x, k in singular_degree.items() if k == 1 and x not in boundary_vertices)
    return counts, dangling


if __name__ == '__main__':
    for path in sys.argv[1:]:
        c, dangling = analyze(path)
        print('%s along %d jog %d improper %d not_quarter_along %d dangling %d'
              % (path, c['along'], c['jog'], c['improper'], c['jog'] + c['improper'], dangling))
