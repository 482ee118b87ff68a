#!/usr/bin/python3
"""Industrial-style CAD parts (OpenCASCADE .brep) for judging the hex-remeshing pipeline.

The models of ../shared/data are mostly smooth or academic shapes; these thirteen parts are the
kind a mechanical engineer sends: brackets with holes, bosses with blind holes, ribs, thin
walls, fillets, chamfers and an acute (30 degree) edge. Each is a single closed solid of
modest size (tens of mm), so that hexmesh's default target (~2,000 hexahedra) is reasonable.

  bracket_l_hole   L-bracket (two plates at 90 deg, thickness 1/8 of the length), a through hole in each leg
  plate_boss       plate with a fused cylindrical boss and a coaxial blind hole
  ribbed_plate     base plate with three thin parallel ribs fused on top
  thin_channel     U-channel, wall thickness 1/15 of the width
  filleted_block   box with a step, the step's two edges (concave and convex) filleted
  flange           disk with a central hub (bored through) and 4 bolt holes
  chamfer_wedge    box with one chamfered edge and a wedge cut leaving a 30 degree edge
  pillow_block     base with two bolt holes, a web and a bored bearing housing across it
  pipe_tee         two tubes fused at right angles (saddle-shaped intersection curves)
  gusset_bracket   L-bracket stiffened by a triangular gusset
  stepped_shaft    three coaxial cylinders with a groove
  clevis           block with a slot and a pin hole through both cheeks
  pocket_housing   box with a rectangular pocket and a round boss on the pocket's floor

Needs gmsh's Python module with OpenCASCADE (Debian's python3-gmsh: run with /usr/bin/python3).

  /usr/bin/python3 benchmark/Hexahedral_remeshing/make_parts.py [OUT_DIR]     # default: build/parts
  benchmark/Hexahedral_remeshing/remesh_table.sh --timeout 900 build/parts    # every .brep of the folder
  benchmark/Hexahedral_remeshing/remesh_table.sh --timeout 900 build/parts/flange.brep   # one part

(OUT_DIR relative to the current directory; the default is the repository's build/parts, or
$BUILD_DIR/parts.) Prints one line per part: name, volume, bounding box. Exits non-zero if a
part is not exactly one volume.
"""
import math
import os
import sys

import gmsh

occ = None  # gmsh.model.occ, set in main()


def volumes():
    occ.synchronize()
    return [t for _, t in gmsh.model.getEntities(3)]


def curves_in(xmin, ymin, zmin, xmax, ymax, zmax):
    occ.synchronize()
    return [t for _, t in gmsh.model.getEntitiesInBoundingBox(xmin, ymin, zmin, xmax, ymax, zmax, 1)]


def surfaces_in(xmin, ymin, zmin, xmax, ymax, zmax):
    occ.synchronize()
    return [t for _, t in gmsh.model.getEntitiesInBoundingBox(xmin, ymin, zmin, xmax, ymax, zmax, 2)]


def fuse(*tags):
    out, _ = occ.fuse([(3, tags[0])], [(3, t) for t in tags[1:]])
    return [t for d, t in out if d == 3]


def cut(tag, *tools):
    out, _ = occ.cut([(3, tag)], [(3, t) for t in tools])
    return [t for d, t in out if d == 3]


def bracket_l_hole():
    # length 80, width 40, thickness 10 (1/8 of the length)
    L, W, T, r = 80., 40., 10., 6.
    base = occ.addBox(0, 0, 0, L, W, T)
    leg = occ.addBox(0, 0, 0, T, W, L)
    (v,) = fuse(base, leg)
    h1 = occ.addCylinder(50, W / 2, -1, 0, 0, T + 2, r)   # through the horizontal leg
    h2 = occ.addCylinder(-1, W / 2, 50, T + 2, 0, 0, r)   # through the vertical leg
    cut(v, h1, h2)


def plate_boss():
    plate = occ.addBox(0, 0, 0, 80, 60, 8)
    boss = occ.addCylinder(40, 30, 8, 0, 0, 20, 12)        # boss top at z = 28
    (v,) = fuse(plate, boss)
    hole = occ.addCylinder(40, 30, 14, 0, 0, 15, 6)        # blind: bottom at z = 14, above the plate
    cut(v, hole)


def ribbed_plate():
    plate = occ.addBox(0, 0, 0, 80, 60, 8)
    ribs = [occ.addBox(5, y, 8, 70, 3, 15) for y in (12., 28.5, 45.)]   # 3 thick, 15 high
    fuse(plate, *ribs)


def thin_channel():
    # width 60, height 40, length 100, walls 4 (1/15 of the width)
    W, H, L, t = 60., 40., 100., 4.
    outer = occ.addBox(0, 0, 0, L, W, H)
    inner = occ.addBox(-1, t, t, L + 2, W - 2 * t, H)
    cut(outer, inner)


def filleted_block():
    base = occ.addBox(0, 0, 0, 60, 40, 20)
    step = occ.addBox(0, 0, 20, 30, 40, 20)
    (v,) = fuse(base, step)
    occ.synchronize()
    e = 1e-3
    # the step's edges: along y at x = 30, convex at z = 40 and concave at z = 20
    edges = curves_in(30 - e, -e, 20 - e, 30 + e, 40 + e, 40 + e)
    edges = [c for c in edges if abs(occ.getBoundingBox(1, c)[4] - occ.getBoundingBox(1, c)[1] - 40) < 1e-6]
    if len(edges) != 2:
        raise RuntimeError('filleted_block: %d step edges found, expected 2' % len(edges))
    occ.fillet([v], edges, [5.], removeVolume=True)


def flange():
    disk = occ.addCylinder(0, 0, 0, 0, 0, 10, 50)
    hub = occ.addCylinder(0, 0, 10, 0, 0, 25, 20)
    (v,) = fuse(disk, hub)
    bore = occ.addCylinder(0, 0, -1, 0, 0, 37, 10)
    holes = [occ.addCylinder(35 * math.cos(a), 35 * math.sin(a), -1, 0, 0, 12, 5)
             for a in (math.pi / 4 + k * math.pi / 2 for k in range(4))]
    cut(v, bore, *holes)


def chamfer_wedge():
    L, W, H = 90., 40., 30.
    box = occ.addBox(0, 0, 0, L, W, H)
    occ.synchronize()
    e = 1e-3
    # chamfer the top edge along y at x = 0 (distance 6)
    edge = [c for c in curves_in(-e, -e, H - e, e, W + e, H + e)]
    face = surfaces_in(-e, -e, H - e, L + e, W + e, H + e)   # the top face
    if len(edge) != 1 or len(face) != 1:
        raise RuntimeError('chamfer_wedge: edge %s face %s' % (edge, face))
    out = occ.chamfer([box], edge, face, [6.], removeVolume=True)
    (v,) = [t for d, t in out if d == 3]
    # wedge cut: a plane through (85, 0) on the bottom face rising at 30 degrees towards -x,
    # leaving a 30 degree edge between the bottom face and the cut
    c, s = math.cos(math.pi / 6), math.sin(math.pi / 6)
    # the tool (xz profile extruded along y): two points on the plane (z = -5 and z = 60), two beyond x = L
    pts = [(85 + 10 * c, -10 * s), (100, -10 * s), (100, 60), (85 - 60 * c / s, 60)]
    p = [occ.addPoint(x, -1, z) for x, z in pts]
    lines = [occ.addLine(p[i], p[(i + 1) % 4]) for i in range(4)]
    surf = occ.addPlaneSurface([occ.addCurveLoop(lines)])
    tool = [t for d, t in occ.extrude([(2, surf)], 0, W + 2, 0) if d == 3]
    cut(v, *tool)


def pillow_block():
    # base 80 x 30 x 10 with two bolt holes, a bearing housing (outer radius 18) bored (radius 10) along y
    base = occ.addBox(0, 0, 0, 80, 30, 10)
    housing = occ.addCylinder(40, 0, 22, 0, 30, 0, 18)
    web = occ.addBox(22, 0, 10, 36, 30, 12)
    (v,) = fuse(base, housing, web)
    bore = occ.addCylinder(40, -1, 22, 0, 32, 0, 10)
    holes = [occ.addCylinder(x, 15, -1, 0, 0, 12, 4) for x in (10., 70.)]
    cut(v, bore, *holes)


def pipe_tee():
    # two tubes (outer radius 12, wall 3) fused at right angles: saddle-shaped intersection curves
    run = occ.addCylinder(-40, 0, 0, 80, 0, 0, 12)
    branch = occ.addCylinder(0, 0, 0, 0, 0, 35, 12)
    (v,) = fuse(run, branch)
    run_bore = occ.addCylinder(-41, 0, 0, 82, 0, 0, 9)
    branch_bore = occ.addCylinder(0, 0, 0, 0, 0, 36, 9)
    cut(v, run_bore, branch_bore)


def gusset_bracket():
    # L-bracket (thickness 8) stiffened by a triangular gusset (thickness 6) in its middle
    L, W, T, g = 60., 40., 8., 6.
    base = occ.addBox(0, 0, 0, L, W, T)
    leg = occ.addBox(0, 0, 0, T, W, L)
    pts = [(T, T), (L - 10, T), (T, L - 10)]
    p = [occ.addPoint(x, (W - g) / 2, z) for x, z in pts]
    lines = [occ.addLine(p[i], p[(i + 1) % 3]) for i in range(3)]
    surf = occ.addPlaneSurface([occ.addCurveLoop(lines)])
    gusset = [t for d, t in occ.extrude([(2, surf)], 0, g, 0) if d == 3]
    fuse(base, leg, *gusset)


def stepped_shaft():
    # three coaxial cylinders (radii 10, 15, 8), a groove (depth 1.5, width 3) on the thinnest
    a = occ.addCylinder(0, 0, 0, 30, 0, 0, 10)
    b = occ.addCylinder(30, 0, 0, 25, 0, 0, 15)
    c = occ.addCylinder(55, 0, 0, 35, 0, 0, 8)
    (v,) = fuse(a, b, c)
    groove = occ.addCylinder(70, 0, 0, 3, 0, 0, 9)
    inner = occ.addCylinder(69, 0, 0, 5, 0, 0, 6.5)
    (ring,) = cut(groove, inner)
    cut(v, ring)


def clevis():
    # block 40 x 30 x 30 with a slot 10 wide and 20 deep, and a cross pin hole through both cheeks
    block = occ.addBox(0, 0, 0, 40, 30, 30)
    slot = occ.addBox(-1, 10, 10, 42, 10, 21)
    pin = occ.addCylinder(25, -1, 20, 0, 32, 0, 4)
    cut(block, slot, pin)


def pocket_housing():
    # box 70 x 50 x 30 with a rectangular pocket (walls 5, floor 6) and a round boss on the floor
    box = occ.addBox(0, 0, 0, 70, 50, 30)
    pocket = occ.addBox(5, 5, 6, 60, 40, 25)
    (v,) = cut(box, pocket)
    boss = occ.addCylinder(35, 25, 6, 0, 0, 12, 7)
    fuse(v, boss)


PARTS = [bracket_l_hole, plate_boss, ribbed_plate, thin_channel, filleted_block, flange, chamfer_wedge,
         pillow_block, pipe_tee, gusset_bracket, stepped_shaft, clevis, pocket_housing]


def main():
    global occ
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    default = os.path.join(os.environ.get('BUILD_DIR', os.path.join(root, 'build')), 'parts')
    out_dir = sys.argv[1] if len(sys.argv) > 1 else default
    if len(sys.argv) > 2 or out_dir in ('-h', '--help'):
        print(__doc__)
        return 2
    os.makedirs(out_dir, exist_ok=True)
    gmsh.initialize()
    gmsh.option.setNumber('General.Terminal', 0)
    occ = gmsh.model.occ
    failed = 0
    try:
        for part in PARTS:
            name = part.__name__
            gmsh.clear()
            gmsh.model.add(name)
            part()
            vols = volumes()
            if len(vols) != 1:
                print('%-16s FAILED: %d volumes (expected exactly one)' % (name, len(vols)), file=sys.stderr)
                failed += 1
                continue
            # nothing but the solid and its boundary (no construction leftovers in the .brep)
            faces = {t for _, t in gmsh.model.getBoundary([(3, vols[0])], oriented=False)}
            loose = [t for _, t in gmsh.model.getEntities(2) if t not in faces]
            if loose:
                print('%-16s FAILED: surfaces %s outside the solid' % (name, loose), file=sys.stderr)
                failed += 1
                continue
            v = vols[0]
            path = os.path.join(out_dir, name + '.brep')
            gmsh.write(path)
            box = occ.getBoundingBox(3, v)
            print('%-16s volume %10.1f  bbox [%7.2f %7.2f %7.2f] - [%7.2f %7.2f %7.2f]  %s' % (
                name, occ.getMass(3, v), *box, path))
    finally:
        gmsh.finalize()
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
