#!/usr/bin/env python3
# Checks the output files of `hexmesh frames` (used by test_hexmesh_cli.sh):
#   check_frames_outputs.py report JSON [baseline]      documented keys, consistency, expected valences
#   check_frames_outputs.py frames VTK JSON             VECTORS frame_u/v/w: one unit right-handed frame per tet
#   check_frames_outputs.py singularities VTK JSON      POLYDATA lines, one per singular edge: valence, curve, reason
#   check_frames_outputs.py cubecover PREFIX JSON       .mesh/.fra/.perm as CubeCover reads them; the
#                                                       permutations are CubeCover's own best fit of the frames
#                                                       except on the faces whose matching the realignment changed
# Exits 1 with a message on the first failed check.
import itertools
import json
import math
import sys


def fail(message):
    print('check_frames_outputs: ' + message)
    sys.exit(1)


def check(condition, message):
    if not condition:
        fail(message)


def lookup(report, dotted):
    node = report
    for part in dotted.split('.'):
        check(isinstance(node, dict) and part in node, 'JSON lacks ' + dotted)
        node = node[part]
    return node


def report(path, mode):
    r = json.load(open(path))
    for key in ['frame_field.energy', 'frame_field.seconds', 'singularities.valence3_edges',
                'singularities.valence5_edges', 'singularities.improper_edges', 'singularities.curves',
                'boundary_valences.total', 'boundary_valences.matched', 'boundary_valences.mismatched',
                'boundary_valences.histogram', 'boundary_valences.by_dihedral_class',
                'seconds.valences', 'seconds.constraints', 'seconds.setup', 'seconds.initialization',
                'seconds.smoothing', 'seconds.matchings', 'seconds.realignment', 'seconds.total',
                'constraints.E_initial', 'constraints.E_final', 'realignment.alignment_error',
                'realignment.changed_matchings', 'realignment.changed_edges',
                'mesh.vertices', 'mesh.tetrahedra', 'mesh.boundary_triangles', 'mesh.boundary_edges',
                'mesh.dihedral_class_histogram', 'mesh.min_dihedral_angle_degrees', 'valences.histogram']:
        lookup(r, key)
    for key in ['valences', 'constraints', 'setup', 'initialization', 'smoothing', 'matchings', 'realignment', 'total']:
        check(r['seconds'][key] >= 0, 'negative seconds.' + key)
    bv = r['boundary_valences']
    check(bv['total'] == r['mesh']['boundary_edges'], 'boundary_valences.total != mesh.boundary_edges')
    check(bv['matched'] + bv['mismatched'] == bv['total'], 'matched + mismatched != total')
    check(bv['mismatched'] == 0, 'boundary_valences.mismatched = %d' % bv['mismatched'])
    check(sum(bv['histogram']) == bv['total'], 'achieved histogram does not sum to total')
    check(math.isfinite(r['frame_field'].get('energy') or float('nan')), 'frame_field.energy is not a number')
    acute = r['mesh']['dihedral_class_histogram'][0]
    check(acute > 0, 'the model has no edge below 45 degrees')
    row0 = bv['by_dihedral_class'][0]
    if mode == 'baseline':
        check(r['baseline'] is True and r['realigned'] is False, 'baseline flags')
        check(bv['histogram'][0] == acute and row0[0] == acute, 'baseline: %d edges below 45 degrees, achieved by class '
              'row %s, histogram %s' % (acute, row0, bv['histogram']))
        check(r['constraints']['E_initial'] == r['constraints']['E_final'], 'baseline: E(v) != E(n)')
    else:
        check(r['baseline'] is False, 'baseline flag')
        check(row0[1] == acute and sum(row0) == acute, 'edges below 45 degrees did not all get valence 1: %s' % row0)
        check(bv['histogram'][0] == 0, 'valence-0 boundary edges remain')
        check(r['constraints']['E_initial'] > math.pi / 4 > r['constraints']['E_final'], 'E(n) > pi/4 > E(v) violated')
        if r['realigned']:
            check(r['realignment']['alignment_error'] < 1e-9, 'alignment error %g' % r['realignment']['alignment_error'])


def vtk_sections(path):
    with open(path) as f:
        lines = f.read().split('\n')
    check(lines[0].startswith('# vtk DataFile Version'), path + ': not a VTK legacy file')
    check(lines[2].strip() == 'ASCII', path + ': not ASCII')
    return lines


def read_arrays(lines, start, n):
    """Arrays of a CELL_DATA / POINT_DATA section of n elements starting at line index start."""
    arrays = {}
    i = start
    while i < len(lines):
        words = lines[i].split()
        if not words:
            i += 1
            continue
        if words[0] in ('CELL_DATA', 'POINT_DATA'):
            break
        if words[0] == 'SCALARS':
            values = [float(lines[i + 2 + k]) for k in range(n)]
            arrays[words[1]] = (1, values)
            i += 2 + n
        elif words[0] == 'VECTORS':
            values = [list(map(float, lines[i + 1 + k].split())) for k in range(n)]
            check(all(len(v) == 3 for v in values), 'VECTORS %s: not three components' % words[1])
            arrays[words[1]] = (3, values)
            i += 1 + n
        else:
            fail('unexpected line in a data section: ' + lines[i])
    return arrays, i


def frames(path, json_path):
    r = json.load(open(json_path))
    lines = vtk_sections(path)
    check(lines[3].strip() == 'DATASET UNSTRUCTURED_GRID', path + ': not an unstructured grid')
    index = {l.split()[0]: i for i, l in enumerate(lines) if l and l.split()[0] in ('POINTS', 'CELLS', 'CELL_TYPES', 'CELL_DATA')}
    nv = int(lines[index['POINTS']].split()[1])
    nt = int(lines[index['CELLS']].split()[1])
    check(nv == r['mesh']['vertices'] and nt == r['mesh']['tetrahedra'], path + ': %d points, %d cells' % (nv, nt))
    check(int(lines[index['CELL_DATA']].split()[1]) == nt, path + ': CELL_DATA count')
    arrays, _ = read_arrays(lines, index['CELL_DATA'] + 1, nt)
    for name in ('frame_u', 'frame_v', 'frame_w'):
        check(name in arrays and arrays[name][0] == 3 and len(arrays[name][1]) == nt, path + ': VECTORS ' + name)
    u, v, w = (arrays[n][1] for n in ('frame_u', 'frame_v', 'frame_w'))
    dot = lambda a, b: sum(x * y for x, y in zip(a, b))
    cross = lambda a, b: [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    for t in range(nt):
        for a in (u[t], v[t], w[t]):
            check(abs(dot(a, a) - 1) < 1e-9, path + ': tet %d: axis not unit' % t)
        check(abs(dot(u[t], v[t])) < 1e-9 and abs(dot(u[t], w[t])) < 1e-9 and abs(dot(v[t], w[t])) < 1e-9,
              path + ': tet %d: axes not orthogonal' % t)
        check(dot(cross(u[t], v[t]), w[t]) > 0.999999, path + ': tet %d: axes not right-handed' % t)


def singularities(path, json_path):
    """One VTK line per singular edge, with its valence, its curve and the reason of the local check."""
    report = json.load(open(json_path))
    s, final = report['singularities'], report['meshability']['final']
    lines = vtk_sections(path)
    check(lines[3].strip() == 'DATASET POLYDATA', path + ': not POLYDATA')
    i = 4
    npoints = int(lines[i].split()[1]); i += 1 + npoints
    words = lines[i].split()
    check(words[0] == 'LINES', path + ': no LINES after the points')
    nlines, size = int(words[1]), int(words[2])
    singular = s['valence3_edges'] + s['valence5_edges'] + s['improper_edges']
    check(nlines == singular, path + ': %d lines for %d singular edges' % (nlines, singular))
    check(size == 3 * nlines, path + ': LINES size')
    cells = [list(map(int, lines[i + 1 + k].split())) for k in range(nlines)]
    for c in cells:
        check(c[0] == 2 and all(0 <= x < npoints for x in c[1:]) and c[1] != c[2], path + ': a line is not an edge')
    check(len(set(tuple(sorted(c[1:])) for c in cells)) == nlines, path + ': an edge written twice')
    if nlines == 0:
        return
    i += 1 + nlines
    check(lines[i].split() == ['CELL_DATA', str(nlines)], path + ': CELL_DATA')
    arrays, i = read_arrays(lines, i + 1, nlines)
    check(all(k in arrays for k in ('valence', 'curve', 'reason')), path + ': cell arrays valence, curve, reason')
    # the failing vertices, one reason each, as many as the final check counts
    check(lines[i].split() == ['POINT_DATA', str(npoints)], path + ': POINT_DATA')
    points, _ = read_arrays(lines, i + 1, npoints)
    check('reason' in points, path + ': point array reason')
    vertex_reasons = {2: 'dangling_end', 3: 'zipper', 4: 'invalid_node', 5: 'boundary_contact', 8: 'end_in_boundary_plane', 9: 'zigzag_face'}
    check(all(r == -1 or r in vertex_reasons for r in points['reason'][1]), path + ': vertex reason values')
    for k, key in vertex_reasons.items():
        n = sum(1 for r in points['reason'][1] if r == k)
        check(n == final[key], path + ': %d vertices with reason %d, the check counts %d %s' % (n, k, final[key], key))
    valence, curve, reason = arrays['valence'][1], arrays['curve'][1], arrays['reason'][1]
    check(all(x in (0, 3, 5) for x in valence), path + ': valence values')
    check(all(0 <= x < s['curves'] for x in curve) and len(set(curve)) == s['curves'], path + ': curve ids')
    for k, key in ((3, 'valence3_edges'), (5, 'valence5_edges'), (0, 'improper_edges')):
        check(sum(1 for v in valence if v == k) == s[key], path + ': edges of valence %d != %s' % (k, key))
    check(sum(1 for r in reason if r == 1) == final['jog'], path + ': jogs != meshability.final.jog')
    check(sum(1 for r in reason if r == 0) == final['improper_edge'], path + ': improper edges != meshability.final.improper_edge')
    check(all(r in (-1, 0, 1) for r in reason), path + ': reason values')


def tokens(path):
    with open(path) as f:
        return f.read().split()


def cubecover(prefix, json_path):
    changed = json.load(open(json_path))['realignment']['changed_matchings']
    # .mesh as CubeCover's readMESH reads it (1-based; Vertices, Triangles, Tetrahedra, End)
    t = tokens(prefix + '.mesh')
    check(t[:4] == ['MeshVersionFormatted', '1', 'Dimension', '3'], prefix + '.mesh: header')
    i, tets = 4, []
    while i < len(t):
        k = t[i]; i += 1
        if k in ('Vertices', 'Triangles'):
            n = int(t[i]); i += 1 + 4 * n
        elif k == 'Tetrahedra':
            n = int(t[i]); i += 1
            tets = [[int(x) - 1 for x in t[i + 5 * j:i + 5 * j + 4]] for j in range(n)]
            i += 5 * n
        elif k == 'End':
            break
        else:
            fail(prefix + '.mesh: section unknown to CubeCover: ' + k)
    fra = tokens(prefix + '.fra')
    check(fra[:2] == ['FRA', '1'], prefix + '.fra: header')
    nt, vpt = int(fra[2]), int(fra[3])
    check(nt == len(tets) and vpt == 3, prefix + '.fra: %d frames of %d vectors for %d tets' % (nt, vpt, len(tets)))
    values = list(map(float, fra[5:]))
    check(len(values) == 9 * nt, prefix + '.fra: size')
    F = [[values[9 * a + 3 * r:9 * a + 3 * r + 3] for r in range(3)] for a in range(nt)]
    perm = tokens(prefix + '.perm')
    check(perm[:2] == ['PERM', '1'] and int(perm[2]) == nt and int(perm[4]) == 3, prefix + '.perm: header')
    nf = int(perm[3])
    check(len(perm) == 5 + 5 * nf, prefix + '.perm: size')
    rows = [list(map(int, perm[5 + 5 * j:10 + 5 * j])) for j in range(nf)]
    faces = {}
    for a, tv in enumerate(tets):
        for c in itertools.combinations(sorted(tv), 3):
            faces.setdefault(c, []).append(a)
    pairs = {tuple(sorted(v)) for v in faces.values() if len(v) == 2}
    # CubeCover's localAssignment: the signed permutation minimizing sum_i |s_i v_i(a) - v_{p_i}(b)|^2
    elements = [(p, s) for p in itertools.permutations(range(3)) for s in itertools.product((1, -1), repeat=3)]
    def best(a, b):
        return min(elements, key=lambda e: sum((e[1][i] * F[a][i][c] - F[b][e[0][i]][c]) ** 2
                                               for i in range(3) for c in range(3)))
    listed, differing = set(), 0
    for r in rows:
        a, b = r[0], r[1]
        key = tuple(sorted((a, b)))
        check(key in pairs, prefix + '.perm: tets %d and %d are not face neighbours' % (a, b))
        check(key not in listed, prefix + '.perm: face %d %d listed twice' % key)
        check(sorted(abs(x) for x in r[2:]) == [1, 2, 3], prefix + '.perm: not a signed permutation: %s' % r)
        listed.add(key)
        expected = (tuple(abs(x) - 1 for x in r[2:]), tuple(1 if x > 0 else -1 for x in r[2:]))
        differing += best(a, b) != expected
        check(expected != ((0, 1, 2), (1, 1, 1)), prefix + '.perm: identity listed')
    identity = ((0, 1, 2), (1, 1, 1))
    differing += sum(1 for a, b in pairs - listed if best(a, b) != identity)
    check(differing == changed, prefix + '.perm: %d faces differ from the best fit of the frames, the realignment '
          'changed %d matchings' % (differing, changed))


if __name__ == '__main__':
    what = sys.argv[1]
    if what == 'report':
        report(sys.argv[2], sys.argv[3] if len(sys.argv) > 3 else '')
    elif what == 'frames':
        frames(sys.argv[2], sys.argv[3])
    elif what == 'singularities':
        singularities(sys.argv[2], sys.argv[3])
    elif what == 'cubecover':
        cubecover(sys.argv[2], sys.argv[3])
    else:
        fail('unknown check ' + what)
