#!/usr/bin/env python3
"""Independent check of an integer-grid map in libHexEx's .hexex format, from its parameters alone.

    check_hexex.py MAP.hexex [--json OUT] [--expect-valid] [--edge-valence X0,Y0,Z0,X1,Y1,Z1,K ...]

Reads the vertices and, per tetrahedron, the parameters of its 4 corners in its own chart, and derives
(numpy; exact rational arithmetic where a floating-point sign is not certain):
  - inverted / degenerate tetrahedra: sign of the parameter-space volume against the space volume;
  - transitions: on every interior face the 3 shared corners satisfy u_a = g u_b + t with g one of the
    24 rotations of the cube and t integer (exactly, as sanitized maps are dyadic);
  - boundary faces: the 3 corners share one integer coordinate;
  - edge valences: (sum of the parameter-space dihedral angles of the tets around an edge) / (pi/2),
    as a histogram for boundary and interior edges, and for the edges lying on given segments
    (--edge-valence: every mesh edge with both ends on the segment must have valence K);
  - branched edges: interior edges whose tetrahedra are all positive but whose valence is 1 or less
    (the map is not locally injective there although no tetrahedron is inverted), and, reported only,
    the interior edges of valence other than 3, 4 or 5 (unusual_interior_edges);
  - wrapped boundary vertices, reported only: boundary vertices whose boundary triangles' parameter
    angles (negative on inverted tetrahedra) sum to 0 or fewer quarter turns, or, where the surface is
    smooth (space angles within 10 degrees of 2 pi), to other than 3, 4 or 5.
--expect-valid makes the exit status 1 unless every check above passes (flat tetrahedra, where a
singular curve's jog collapses, are counted but tolerated, as by the extraction). Writes a JSON summary.
Needs python3 with numpy (Debian python3-numpy). Written for the tests, apart from the package code.
"""
import argparse
import json
import math
import sys
from fractions import Fraction

import numpy as np


def read_hexex(path):
    tok = open(path).read().split()
    n = int(tok[0])
    pts = np.array(tok[1:1 + 3 * n], dtype=float).reshape(n, 3)
    k = 1 + 3 * n
    m = int(tok[k])
    rows = np.array(tok[k + 1:k + 1 + 16 * m], dtype=float).reshape(m, 16)
    tets = rows[:, :4].astype(np.int64)
    params = rows[:, 4:].reshape(m, 4, 3)
    if tets.min() < 0 or tets.max() >= n:
        raise SystemExit('%s: vertex index out of range' % path)
    return pts, tets, params


def orientation_signs(corners):
    """Sign of det[c1-c0, c2-c0, c3-c0] for an (m, 4, 3) array; exact where the float sign is unsure."""
    d = corners[:, 1:, :] - corners[:, :1, :]
    det = np.linalg.det(d)
    scale = np.prod(np.linalg.norm(d, axis=2), axis=1)
    sign = np.sign(det).astype(int)
    unsure = np.nonzero(np.abs(det) <= 1e-10 * scale)[0]
    for i in unsure:
        c = [[Fraction(float(x)) for x in corners[i, j]] for j in range(4)]
        a = [[c[j][r] - c[0][r] for r in range(3)] for j in (1, 2, 3)]
        e = (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
             a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))
        sign[i] = (e > 0) - (e < 0)
    return sign


def cube_rotations():
    out = []
    for perm in ((0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)):
        for s in range(8):
            R = np.zeros((3, 3))
            for r in range(3):
                R[r, perm[r]] = -1.0 if (s >> r) & 1 else 1.0
            if np.linalg.det(R) > 0:
                out.append(R)
    return out


FACES = ((1, 2, 3), (0, 2, 3), (0, 1, 3), (0, 1, 2))  # face f: the corners other than f
EDGES = ((0, 1, 2, 3), (0, 2, 1, 3), (0, 3, 1, 2), (1, 2, 0, 3), (1, 3, 0, 2), (2, 3, 0, 1))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('hexex')
    ap.add_argument('--json')
    ap.add_argument('--expect-valid', action='store_true')
    ap.add_argument('--edge-valence', action='append', default=[],
                    help='X0,Y0,Z0,X1,Y1,Z1,K: mesh edges on this segment must have valence K')
    ap.add_argument('--tolerance', type=float, default=1e-9, help='distance to a segment, in model units')
    a = ap.parse_args()

    pts, tets, params = read_hexex(a.hexex)
    m = len(tets)
    space = orientation_signs(pts[tets])
    par = orientation_signs(params)
    inverted = int(np.sum(par * space < 0))
    degenerate = int(np.sum(par == 0))
    flat_in_space = int(np.sum(space == 0))

    # faces: key = sorted vertex triple
    fv = np.sort(tets[:, FACES], axis=2).reshape(-1, 3)           # (4m, 3)
    owner = np.repeat(np.arange(m), 4)
    order = np.lexsort((fv[:, 2], fv[:, 1], fv[:, 0]))
    fs = fv[order]
    same = np.all(fs[1:] == fs[:-1], axis=1)
    first = np.nonzero(same)[0]                                  # pairs (first, first + 1) are interior faces
    counts = np.ones(len(fs), dtype=int)
    # a face seen more than twice is non-manifold
    triple = int(np.sum(same[1:] & same[:-1])) if len(same) > 1 else 0
    is_interior = np.zeros(len(fs), dtype=bool)
    is_interior[first] = True
    is_interior[first + 1] = True
    boundary_idx = order[~is_interior]

    def corner_params(t, verts):
        # parameters of the corners of tets t at vertices verts (k, 3) -> (k, 3, 3)
        local = np.argmax(tets[t][:, None, :] == verts[:, :, None], axis=2)  # (k, 3)
        return params[t[:, None], local]

    # interior transitions
    ia, ib = order[first], order[first + 1]
    ta, tb = owner[ia], owner[ib]
    verts = fs[first]
    pa = corner_params(ta, verts)
    pb = corner_params(tb, verts)
    ea = pa[:, 1:] - pa[:, :1]
    eb = pb[:, 1:] - pb[:, :1]
    ok = np.zeros(len(first), dtype=bool)
    for R in cube_rotations():
        rb = eb @ R.T
        match = np.all(rb == ea, axis=(1, 2))
        t = pa[:, 0] - pb[:, 0] @ R.T
        match &= np.all(t == np.round(t), axis=1)
        ok |= match
    bad_transitions = int(np.sum(~ok))

    # boundary faces on integer planes
    bt, bverts = owner[boundary_idx], fv[boundary_idx]
    bp = corner_params(bt, bverts)
    on_plane = np.zeros(len(boundary_idx), dtype=bool)
    for k in range(3):
        c = bp[:, :, k]
        on_plane |= (c[:, 0] == c[:, 1]) & (c[:, 1] == c[:, 2]) & (c[:, 0] == np.round(c[:, 0]))
    off_plane = int(np.sum(~on_plane))

    # dihedral angles in parameter space, summed per edge
    ev = tets[:, [e[:2] for e in EDGES]]                          # (m, 6, 2)
    P = params
    A = np.stack([P[:, e[0]] for e in EDGES], axis=1)
    B = np.stack([P[:, e[1]] for e in EDGES], axis=1)
    C = np.stack([P[:, e[2]] for e in EDGES], axis=1)
    D = np.stack([P[:, e[3]] for e in EDGES], axis=1)
    u = B - A
    un = np.linalg.norm(u, axis=2, keepdims=True)
    u = np.divide(u, un, out=np.zeros_like(u), where=un > 0)
    pc = (C - A) - np.sum((C - A) * u, axis=2, keepdims=True) * u
    pd = (D - A) - np.sum((D - A) * u, axis=2, keepdims=True) * u
    angle = np.arctan2(np.linalg.norm(np.cross(pc, pd), axis=2), np.sum(pc * pd, axis=2))
    # an inverted tetrahedron turns back: its angles count negatively (a fold shows as valence 0 or less)
    angle = angle * (par * space)[:, None]
    ek = np.sort(ev, axis=2).reshape(-1, 2)
    n = len(pts)
    keys = ek[:, 0] * n + ek[:, 1]
    uniq, inv = np.unique(keys, return_inverse=True)
    sums = np.bincount(inv, weights=angle.reshape(-1))
    valence = sums / (math.pi / 2)
    bkeys = set()
    for f in bverts:
        for i, j in ((0, 1), (1, 2), (0, 2)):
            bkeys.add(int(f[i]) * n + int(f[j]))
    is_boundary_edge = np.array([int(k) in bkeys for k in uniq])
    # edges whose tetrahedra are all positive: their angle sum is the map's turn around them
    not_positive = np.repeat((par * space <= 0)[:, None], 6, axis=1).reshape(-1)
    clean = np.bincount(inv, weights=not_positive.astype(float)) == 0
    rounded = np.round(valence)
    unusual = ~is_boundary_edge & clean & ((rounded < 3) | (rounded > 5))
    branched = ~is_boundary_edge & clean & (rounded <= 1)

    # boundary vertices around which the map wraps the surface: the parameter angles of a vertex's boundary
    # triangles (negative where the tetrahedron is inverted) sum to a positive number of quarter turns at a
    # hex mesh's boundary vertex, 3, 4 or 5 where the surface is smooth (space angles summing to 2 pi)
    bpts = pts[bverts]

    def corner_angles(q):
        out = []
        for c in range(3):
            a_, b_ = q[:, (c + 1) % 3] - q[:, c], q[:, (c + 2) % 3] - q[:, c]
            na, nb = np.linalg.norm(a_, axis=1), np.linalg.norm(b_, axis=1)
            cosv = np.sum(a_ * b_, axis=1) / np.where(na * nb > 0, na * nb, 1)
            out.append(np.where(na * nb > 0, np.arccos(np.clip(cosv, -1, 1)), 0))
        return np.stack(out, axis=1)
    pang = corner_angles(bp) * (par * space)[bt][:, None]
    sang = corner_angles(bpts)
    psum = np.bincount(bverts.reshape(-1), weights=pang.reshape(-1), minlength=len(pts))
    ssum = np.bincount(bverts.reshape(-1), weights=sang.reshape(-1), minlength=len(pts))
    on_boundary = np.bincount(bverts.reshape(-1), minlength=len(pts)) > 0
    q = psum / (math.pi / 2)
    turns = np.round(q)
    certain = on_boundary & (np.abs(q - turns) <= 0.1)
    smooth = np.abs(ssum - 2 * math.pi) < math.pi / 18
    wrapped_vertices = np.nonzero(certain & ((turns <= 0) | (smooth & ((turns < 3) | (turns > 5)))))[0]

    def histogram(vals):
        h = {}
        for v in vals:
            r = int(round(v))
            key = str(r) if abs(v - r) < 1e-6 else 'non-integer'
            h[key] = h.get(key, 0) + 1
        return dict(sorted(h.items()))

    segments = []
    for spec in a.edge_valence:
        x = [float(s) for s in spec.split(',')]
        p0, p1, K = np.array(x[0:3]), np.array(x[3:6]), int(x[6])
        d = p1 - p0
        L2 = d.dot(d)

        def on_segment(q):
            s = np.clip((q - p0) @ d / L2, 0, 1)
            return np.linalg.norm(q - (p0 + s[:, None] * d[None, :]), axis=1) <= a.tolerance
        va, vb = uniq // n, uniq % n
        sel = on_segment(pts[va]) & on_segment(pts[vb])
        vals = valence[sel]
        length = float(np.sum(np.linalg.norm(pts[va[sel]] - pts[vb[sel]], axis=1)))
        wrong = int(np.sum(np.abs(vals - K) > 1e-6))
        segments.append({'segment': spec, 'expected_valence': K, 'edges': int(np.sum(sel)), 'length': length,
                         'wrong': wrong, 'valences': histogram(vals)})

    report = {
        'tetrahedra': m, 'vertices': int(n),
        'inverted_tetrahedra': inverted, 'degenerate_tetrahedra': degenerate, 'flat_in_space': flat_in_space,
        'interior_faces': int(len(first)), 'bad_transitions': bad_transitions, 'non_manifold_faces': triple,
        'boundary_faces': int(len(boundary_idx)), 'boundary_faces_off_plane': off_plane,
        'boundary_edge_valences': histogram(valence[is_boundary_edge]),
        'interior_edge_valences': histogram(valence[~is_boundary_edge]),
        'unusual_interior_edges': int(np.sum(unusual)), 'branched_edges': int(np.sum(branched)),
        'wrapped_boundary_vertices': int(len(wrapped_vertices)),
        'segments': segments,
    }
    # flat tetrahedra are tolerated (collapsed jogs of singular curves; the extraction skips them)
    # an interior edge with every tetrahedron positive and at most a quarter turn around it is never
    # meshable (no hexahedra surround an edge with one quarter turn): the map is branched there
    valid = (inverted == 0 and bad_transitions == 0 and triple == 0 and off_plane == 0 and report['branched_edges'] == 0 and
             all(s['wrong'] == 0 and s['edges'] > 0 for s in segments))
    report['valid'] = valid
    text = json.dumps(report, indent=1)
    if a.json:
        open(a.json, 'w').write(text + '\n')
    print(text)
    if a.expect_valid and not valid:
        print('check_hexex: %s is not a valid integer-grid map (see above)' % a.hexex, file=sys.stderr)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
