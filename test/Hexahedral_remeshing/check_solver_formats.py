#!/usr/bin/env python3
"""Independent check of the solver files of one hex mesh, without the package:
  check_solver_formats.py --inp F.inp [--msh F.msh] [--vtu F.vtu] [--step PART.step] [--planar]
                          [--min-surfaces N]
.inp: parsed here (*NODE, *ELEMENT TYPE=C3D8, *NSET, *SURFACE TYPE=ELEMENT): every element has a positive
volume in the C3D8 node order (every corner's triple product positive), the element faces S1..S6 of the
surfaces (Abaqus' face definitions) are boundary faces of the mesh (used by one element) and cover the
boundary exactly once, each *NSET of a surface holds exactly the nodes of its faces.
.msh: read by gmsh's Python module: the same nodes (coordinates), the same hexahedra, one physical surface
per .inp surface with the same name and the same quads.
.vtu: parsed as XML: the same hexahedra (type 12), the boundary quads (type 9) with a `patch` per quad, and
as many distinct patches as .inp surfaces.
--step: the CAD faces of the part (gmsh's OpenCASCADE import): one surface per CAD face, `patch_<tag>`,
whose area equals the face's (within 1e-6 relative with --planar, where every surface must also be flat,
else 2%).
Prints one line per file; exit 1 with the reason when a check fails."""
import sys
import xml.etree.ElementTree as ET
from collections import defaultdict

FACES = {1: (0, 1, 2, 3), 2: (4, 7, 6, 5), 3: (0, 4, 5, 1), 4: (1, 5, 6, 2), 5: (2, 6, 7, 3), 6: (3, 7, 4, 0)}
CORNERS = [(1, 3, 4), (2, 0, 5), (3, 1, 6), (0, 2, 7), (7, 5, 0), (4, 6, 1), (5, 7, 2), (6, 4, 3)]


def fail(msg):
    print('check_solver_formats: ' + msg)
    sys.exit(1)


def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def parse_inp(path):
    nodes, elements, nsets, surfaces = {}, {}, defaultdict(set), defaultdict(list)
    mode, name = None, None
    for raw in open(path):
        line = raw.strip()
        if not line or line.startswith('**'): continue
        if line.startswith('*'):
            words = [w.strip() for w in line.split(',')]
            key = words[0].upper()
            opts = {w.split('=')[0].strip().upper(): w.split('=')[1].strip() for w in words[1:] if '=' in w}
            mode, name = None, None
            if key == '*NODE': mode = 'node'
            elif key == '*ELEMENT':
                if opts.get('TYPE', '').upper() != 'C3D8': fail('%s: element type %s' % (path, opts.get('TYPE')))
                mode = 'element'
            elif key == '*NSET': mode, name = 'nset', opts['NSET']
            elif key == '*SURFACE':
                if opts.get('TYPE', '').upper() != 'ELEMENT': fail('%s: surface type %s' % (path, opts.get('TYPE')))
                mode, name = 'surface', opts['NAME']
            continue
        values = [v.strip() for v in line.split(',') if v.strip()]
        if mode == 'node': nodes[int(values[0])] = tuple(float(v) for v in values[1:4])
        elif mode == 'element':
            if len(values) != 9: fail('%s: element line with %d values' % (path, len(values)))
            elements[int(values[0])] = [int(v) for v in values[1:]]
        elif mode == 'nset': nsets[name].update(int(v) for v in values)
        elif mode == 'surface':
            if not values[1].upper().startswith('S'): fail('%s: face %s' % (path, values[1]))
            surfaces[name].append((int(values[0]), int(values[1][1:])))
    return nodes, elements, nsets, surfaces


def check_inp(path):
    nodes, elements, nsets, surfaces = parse_inp(path)
    if not elements: fail(path + ': no element')
    volume = 0.0
    for e, n in elements.items():
        if any(v not in nodes for v in n): fail('%s: element %d refers to a missing node' % (path, e))
        p = [nodes[v] for v in n]
        for c, (a, b, d) in enumerate(CORNERS):
            if dot(cross(sub(p[a], p[c]), sub(p[b], p[c])), sub(p[d], p[c])) <= 0:
                fail('%s: element %d is not positively oriented at its node %d' % (path, e, c + 1))
        # volume by the divergence theorem over its faces, each split about its centre
        for f in FACES.values():
            q = [p[k] for k in f]
            m = tuple(sum(x[i] for x in q) / 4 for i in range(3))
            for k in range(4):
                # Abaqus' faces run clockwise seen from outside: reverse for the outward normal
                volume -= dot(m, cross(q[k], q[(k + 1) % 4])) / 6
    face_count = defaultdict(int)
    for n in elements.values():
        for f in FACES.values(): face_count[frozenset(n[k] for k in f)] += 1
    boundary = {k for k, c in face_count.items() if c == 1}
    covered = defaultdict(int)
    for name, faces in surfaces.items():
        face_nodes = set()
        for e, s in faces:
            if e not in elements or s not in FACES: fail('%s: surface %s names face S%d of element %d' % (path, name, s, e))
            key = frozenset(elements[e][k] for k in FACES[s])
            if key not in boundary: fail('%s: surface %s: face S%d of element %d is not on the boundary' % (path, name, s, e))
            covered[key] += 1
            face_nodes |= key
        if nsets.get(name) != face_nodes: fail('%s: *NSET %s differs from the nodes of its surface' % (path, name))
    if any(c != 1 for c in covered.values()): fail('%s: a boundary face is in several surfaces' % path)
    if len(covered) != len(boundary): fail('%s: %d of %d boundary faces in no surface' % (path, len(boundary) - len(covered), len(boundary)))
    print('%s: %d nodes, %d C3D8 elements, all positive, volume %.6g, %d surfaces covering the %d boundary faces once'
          % (path, len(nodes), len(elements), volume, len(surfaces), len(boundary)))
    return nodes, elements, surfaces


def check_msh(path, nodes, elements, surfaces):
    import gmsh
    gmsh.initialize()
    gmsh.option.setNumber('General.Terminal', 0)
    gmsh.open(path)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    if len(tags) != len(nodes): fail('%s: %d nodes, the .inp %d' % (path, len(tags), len(nodes)))
    for i, t in enumerate(tags):
        if max(abs(coords[3 * i + d] - nodes[int(t)][d]) for d in range(3)) > 1e-9 * (1 + max(map(abs, nodes[int(t)]))):
            fail('%s: node %d moved' % (path, t))
    hexes = set()
    for dim, tag in gmsh.model.getEntities(3):
        types, etags, enodes = gmsh.model.mesh.getElements(3, tag)
        for ty, et, en in zip(types, etags, enodes):
            if ty != 5: fail('%s: volume element type %d' % (path, ty))
            for k in range(len(et)): hexes.add(tuple(int(x) for x in en[8 * k:8 * k + 8]))
    if hexes != {tuple(n) for n in elements.values()}: fail('%s: the hexahedra differ from the .inp' % path)
    groups = {}
    for dim, ptag in gmsh.model.getPhysicalGroups(2):
        name = gmsh.model.getPhysicalName(dim, ptag)
        quads = set()
        for ent in gmsh.model.getEntitiesForPhysicalGroup(dim, ptag):
            types, etags, enodes = gmsh.model.mesh.getElements(2, ent)
            for ty, et, en in zip(types, etags, enodes):
                if ty != 3: fail('%s: surface element type %d' % (path, ty))
                for k in range(len(et)): quads.add(frozenset(int(x) for x in en[4 * k:4 * k + 4]))
        groups[name] = quads
    expected = {name: {frozenset(elements[e][k] for k in FACES[s]) for e, s in faces} for name, faces in surfaces.items()}
    if groups != expected: fail('%s: physical surfaces %s differ from the .inp surfaces %s' % (path, sorted(groups), sorted(expected)))
    curves = len(gmsh.model.getPhysicalGroups(1))
    gmsh.finalize()
    print('%s: read by gmsh: same %d nodes and %d hexahedra, %d physical surfaces as the .inp, %d physical curves'
          % (path, len(tags), len(hexes), len(groups), curves))


def check_vtu(path, elements, surfaces):
    root = ET.parse(path).getroot()
    piece = root.find('UnstructuredGrid/Piece')
    def array(parent, name):
        for a in piece.find(parent).findall('DataArray'):
            if a.get('Name') == name: return a.text.split()
        fail('%s: no array %s' % (path, name))
    conn = [int(x) for x in array('Cells', 'connectivity')]
    offsets = [int(x) for x in array('Cells', 'offsets')]
    types = [int(x) for x in array('Cells', 'types')]
    patch = [int(x) for x in array('CellData', 'patch')]
    if int(piece.get('NumberOfCells')) != len(types) or len(patch) != len(types): fail(path + ': array sizes differ')
    hexes, quads, start = set(), defaultdict(int), 0
    for c, (t, end) in enumerate(zip(types, offsets)):
        cell = tuple(v + 1 for v in conn[start:end]); start = end
        if t == 12: hexes.add(cell)
        elif t == 9: quads[patch[c]] += 1
        else: fail('%s: cell type %d' % (path, t))
    if hexes != {tuple(n) for n in elements.values()}: fail('%s: the hexahedra differ from the .inp' % path)
    if sorted(quads.values()) != sorted(len(f) for f in surfaces.values()):
        fail('%s: quads per patch %s, the .inp surfaces %s' % (path, sorted(quads.values()), sorted(len(f) for f in surfaces.values())))
    print('%s: same %d hexahedra, %d boundary quads in %d patches as the .inp' % (path, len(hexes), sum(quads.values()), len(quads)))


def check_step(step, nodes, elements, surfaces, planar):
    import gmsh
    gmsh.initialize()
    gmsh.option.setNumber('General.Terminal', 0)
    gmsh.model.occ.importShapes(step)
    gmsh.model.occ.synchronize()
    areas = {tag: gmsh.model.occ.getMass(2, tag) for _, tag in gmsh.model.getEntities(2)}
    gmsh.finalize()
    if sorted(surfaces) != sorted('patch_%d' % t for t in areas):
        fail('%s: surfaces %s, CAD faces %s' % (step, sorted(surfaces), sorted(areas)))
    for name, faces in surfaces.items():
        area, pts = 0.0, []
        for e, s in faces:
            q = [nodes[elements[e][k]] for k in FACES[s]]
            pts += q
            a = cross(sub(q[2], q[0]), sub(q[3], q[1]))
            area += dot(a, a) ** 0.5 / 2
        want = areas[int(name[len('patch_'):])]
        tol = 1e-6 if planar else 0.02
        if abs(area - want) > tol * want: fail('%s: surface %s area %.9g, CAD face %.9g' % (step, name, area, want))
        if planar:
            o = pts[0]
            n = max((cross(sub(a, o), sub(b, o)) for a in pts for b in pts[:8]), key=lambda v: dot(v, v))
            nn = dot(n, n) ** 0.5
            if any(abs(dot(sub(p, o), n)) / nn > 1e-9 * (1 + max(map(abs, o))) for p in pts):
                fail('%s: surface %s is not planar' % (step, name))
    print('%s: %d surfaces, one per CAD face, areas equal to the faces\'%s' % (step, len(surfaces), ', planar' if planar else ''))


def main():
    args = sys.argv[1:]
    def opt(name):
        return args[args.index(name) + 1] if name in args else None
    nodes, elements, surfaces = check_inp(opt('--inp'))
    if opt('--min-surfaces') and len(surfaces) < int(opt('--min-surfaces')):
        fail('%d surfaces, expected at least %s' % (len(surfaces), opt('--min-surfaces')))
    if opt('--msh'): check_msh(opt('--msh'), nodes, elements, surfaces)
    if opt('--vtu'): check_vtu(opt('--vtu'), elements, surfaces)
    if opt('--step'): check_step(opt('--step'), nodes, elements, surfaces, '--planar' in args)


if __name__ == '__main__':
    main()
