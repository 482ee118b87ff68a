#!/usr/bin/env python3
"""Writes the 10-degree wedge (the geometry of HexMe's n13 "acute line") as a CAD part,
n13c_acute_wedge.brep (OpenCASCADE BRep: the main job of scripts/run, which hexmesh tetrahedralizes
with gmsh, graded towards the acute edge by itself), and a graded tetrahedral mesh of it made here,
n13c_acute_wedge_graded.msh.

The part: the triangle (y, z) = (0, 0), (0, 1), (-sin 10deg, cos 10deg) extruded along x over [0, 1]
(the 10-degree edge is the x axis). The tetrahedra are 0.003 on the 10-degree edge, growing linearly
to 0.04 at 0.2 from it: the band of fixed frames of the hex pipeline (twice the hex edge length, 0.07
at the default 2000 hexahedra) holds the cross-section's valence-3 curve off the edge, and the wedge
is only 0.012 thick there, so the curve needs tetrahedra smaller than that to lie inside the wedge
rather than on its faces (at 0.004 on the edge it still touches them and the map folds). Needs Debian's python3-gmsh (installed by scripts/setup).
    python3 make_acute_wedge.py [OUT.msh [OUT.brep]]
"""
import math
import sys

import gmsh

out = sys.argv[1] if len(sys.argv) > 1 else "n13c_acute_wedge_graded.msh"
out_cad = sys.argv[2] if len(sys.argv) > 2 else "n13c_acute_wedge.brep"
gmsh.initialize()
gmsh.option.setNumber("General.Verbosity", 1)
gmsh.model.add("acute_wedge")
occ = gmsh.model.occ
s, c = math.sin(math.radians(10)), math.cos(math.radians(10))
points = [occ.addPoint(0, 0, 0), occ.addPoint(0, 0, 1), occ.addPoint(0, -s, c)]
lines = [occ.addLine(points[0], points[1]), occ.addLine(points[1], points[2]), occ.addLine(points[2], points[0])]
section = occ.addPlaneSurface([occ.addCurveLoop(lines)])
occ.extrude([(2, section)], 1, 0, 0)
occ.synchronize()
gmsh.write(out_cad)


def on_x_axis(curve):
    b = gmsh.model.getBoundingBox(1, curve)
    return all(abs(v) < 1e-5 for v in (b[1], b[2], b[4], b[5]))


acute = [t for d, t in gmsh.model.getEntities(1) if on_x_axis(t)]
if len(acute) != 1:
    sys.exit("make_acute_wedge.py: expected one curve on the x axis, found %d" % len(acute))
field = gmsh.model.mesh.field
field.add("Distance", 1)
field.setNumbers(1, "CurvesList", acute)
field.setNumber(1, "NumPointsPerCurve", 200)
field.add("Threshold", 2)
field.setNumber(2, "InField", 1)
field.setNumber(2, "SizeMin", 0.003)
field.setNumber(2, "SizeMax", 0.04)
field.setNumber(2, "DistMin", 0.0)
field.setNumber(2, "DistMax", 0.2)
field.setAsBackgroundMesh(2)
gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
gmsh.model.mesh.generate(3)
gmsh.write(out)
gmsh.finalize()
