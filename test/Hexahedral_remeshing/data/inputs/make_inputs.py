#!/usr/bin/env python3
# Copyright (c) 2026 The Hexahedral_remeshing project.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Writes the input fixtures of test_inputs and of the CLI checks (issue 13): everyday variants of
# the mesh formats and flawed surfaces, each small and built from unit cubes so that the expected
# outcome (volume, components) is known exactly. The gmsh files (.msh, .step) need gmsh's Python
# module (Debian python3-gmsh; run with /usr/bin/python3). Binary variants are made at test time.
#
#   /usr/bin/python3 make_inputs.py [OUTPUT_DIR]    (default: the directory of this script)
import os
import sys

out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))


def path(name):
    return os.path.join(out, name)


# Unit cube: vertex i = (x, y, z) with i = x + 2 y + 4 z; quads outward.
CUBE_QUADS = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
# Six tetrahedra around the diagonal 0-7 (Kuhn split), each of volume 1/6.
CUBE_TETS = [(0, 1, 3, 7), (0, 1, 5, 7), (0, 2, 3, 7), (0, 2, 6, 7), (0, 4, 5, 7), (0, 4, 6, 7)]


def cube_points(origin=(0, 0, 0), size=1.0):
    ox, oy, oz = origin
    return [(ox + size * (i & 1), oy + size * ((i >> 1) & 1), oz + size * ((i >> 2) & 1)) for i in range(8)]


def cube_triangles(offset=0, flip=False):
    tris = []
    for a, b, c, d in CUBE_QUADS:
        for t in ((a, b, c), (a, c, d)):
            tris.append(tuple(offset + v for v in (t[::-1] if flip else t)))
    return tris


def write_off(name, points, faces):
    with open(path(name), "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(points), len(faces)))
        for p in points:
            f.write("%.17g %.17g %.17g\n" % p)
        for t in faces:
            f.write("%d %s\n" % (len(t), " ".join(str(v) for v in t)))


def write_stl(name, points, faces):
    with open(path(name), "w") as f:
        f.write("solid %s\n" % name)
        for t in faces:
            f.write(" facet normal 0 0 0\n  outer loop\n")
            for v in t:
                f.write("   vertex %.17g %.17g %.17g\n" % points[v])
            f.write("  endloop\n endfacet\n")
        f.write("endsolid %s\n" % name)


def surfaces():
    # a cube whose facets are not all oriented alike (STL exporters do this)
    tris = cube_triangles()
    for k in (1, 4, 9):
        tris[k] = tris[k][::-1]
    write_stl("flipped_facets.stl", cube_points(), tris)
    # triangle soups: every triangle has its own three vertices
    pts, faces = [], []
    for t in cube_triangles():
        faces.append(tuple(range(len(pts), len(pts) + 3)))
        pts += [cube_points()[v] for v in t]
    write_off("soup_duplicated_vertices.off", pts, faces)
    with open(path("soup_duplicated_vertices.obj"), "w") as f:
        for p in pts:
            f.write("v %.17g %.17g %.17g\n" % p)
        for t in faces:
            f.write("f %d %d %d\n" % tuple(v + 1 for v in t))
    # a cube with an inner cube: a cavity (volume 27 - 1 = 26)
    write_off("cavity.off", cube_points((0, 0, 0), 3) + cube_points((1, 1, 1), 1),
              cube_triangles() + cube_triangles(8))
    # a body inside the cavity of another (volume 125 - 27 + 1 = 99, two bodies)
    write_off("body_in_cavity.off", cube_points((0, 0, 0), 5) + cube_points((1, 1, 1), 3) + cube_points((2, 2, 2), 1),
              cube_triangles() + cube_triangles(8) + cube_triangles(16))
    # two disjoint cubes: two bodies (volume 2)
    write_off("two_bodies.off", cube_points() + cube_points((2, 0, 0)), cube_triangles() + cube_triangles(8))
    # an assembly of two cubes whose faces touch (coplanar overlapping facets, separate vertices)
    write_stl("touching_bodies.stl", cube_points() + cube_points((1, 0.5, 0)), cube_triangles() + cube_triangles(8))
    # a closed cube surface that intersects itself: corner 7 pushed down through the bottom face
    pts = cube_points()
    pts[7] = (0.2, 0.2, -1.0)
    write_off("self_intersecting.off", pts, cube_triangles())
    # a cube with a missing face (2 triangles): not closed
    write_off("open_surface.off", cube_points(), cube_triangles()[2:])
    # two cubes sharing an edge (non-manifold)
    pts = cube_points() + [p for i, p in enumerate(cube_points((1, 1, 0))) if i not in (0, 4)]
    remap = {0: 3, 4: 7}
    tris = cube_triangles()
    for t in cube_triangles(8):
        tris.append(tuple(remap[v - 8] if v - 8 in remap else 8 + [i for i in range(8) if i not in (0, 4)].index(v - 8)
                          for v in t))
    write_off("shared_edge.off", pts, tris)
    # a cube with corner 7 pulled out 2000 units (a thin spike): TetGen's quality refinement does not end near its tip
    pts = cube_points()
    pts[7] = (1.2, 2001.0, 0.2)
    write_off("spike.off", pts, cube_triangles())


def vtk_cells(cells, types):
    return cells, types


def write_vtk_classic(name, points, cells, types, extra=""):
    with open(path(name), "w") as f:
        f.write("# vtk DataFile Version 4.2\n%s\nASCII\nDATASET UNSTRUCTURED_GRID\n" % name)
        f.write("POINTS %d double\n" % len(points))
        for p in points:
            f.write("%.17g %.17g %.17g\n" % p)
        f.write("CELLS %d %d\n" % (len(cells), sum(len(c) + 1 for c in cells)))
        for c in cells:
            f.write("%d %s\n" % (len(c), " ".join(str(v) for v in c)))
        f.write("CELL_TYPES %d\n" % len(cells))
        for t in types:
            f.write("%d\n" % t)
        f.write(extra)


def volumes():
    pts = cube_points()
    # VTK 5.1 (meshio / ParaView legacy export): OFFSETS / CONNECTIVITY, METADATA blocks, FIELD cell data
    with open(path("cube_v51.vtk"), "w") as f:
        f.write("# vtk DataFile Version 5.1\nvtk output\nASCII\nDATASET UNSTRUCTURED_GRID\n")
        f.write("POINTS 8 float\n")
        for p in pts:
            f.write("%g %g %g\n" % p)
        f.write("\nMETADATA\nINFORMATION 2\nNAME L2_NORM_RANGE LOCATION vtkDataArray\nDATA 2 0 1.73205\n"
                "NAME L2_NORM_FINITE_RANGE LOCATION vtkDataArray\nDATA 2 0 1.73205\n\n")
        cells = CUBE_TETS + [(0, 1, 3), (0, 3, 2), (0, 1)]
        f.write("CELLS %d %d\nOFFSETS vtktypeint64\n" % (len(cells) + 1, sum(len(c) for c in cells)))
        off = [0]
        for c in cells:
            off.append(off[-1] + len(c))
        f.write(" ".join(str(o) for o in off) + "\nCONNECTIVITY vtktypeint64\n")
        f.write(" ".join(str(v) for c in cells for v in c) + "\n")
        f.write("CELL_TYPES %d\n%s\n" % (len(cells), "\n".join(["10"] * 6 + ["5", "5", "3"])))
        f.write("CELL_DATA %d\nFIELD FieldData 1\ngmsh:geometrical 1 %d int\n%s\n" %
                (len(cells), len(cells), " ".join(["1"] * 6 + ["7", "7", "3"])))
        f.write("METADATA\nINFORMATION 0\n\n")
    # the same, but each METADATA block followed directly by the next section (no empty line), as
    # some writers do
    text = open(path("cube_v51.vtk")).read()
    text = text.replace("DATA 2 0 1.73205\n\nCELLS", "DATA 2 0 1.73205\nCELLS").replace("INFORMATION 0\n\n", "INFORMATION 0\n")
    with open(path("cube_v51_metadata_no_blank_line.vtk"), "w") as f:
        f.write(text)
    # second-order tetrahedra (VTK type 24): corners then edge midpoints
    qp = list(pts)
    mid = {}
    cells = []
    for t in CUBE_TETS:
        c = list(t)
        for a, b in ((0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3)):
            key = tuple(sorted((t[a], t[b])))
            if key not in mid:
                mid[key] = len(qp)
                qp.append(tuple((pts[t[a]][i] + pts[t[b]][i]) / 2 for i in range(3)))
            c.append(mid[key])
        cells.append(c)
    write_vtk_classic("cube_quadratic_tets.vtk", qp, cells, [24] * 6)
    # a hexahedron next to six tetrahedra: volume cells other than tetrahedra
    hp = pts + [p for p in cube_points((1, 0, 0))][1::2]  # x = 2 face: 8 + (1,3,5,7) -> 8..11
    hex_cell = (1, 8, 9, 3, 5, 10, 11, 7)  # VTK order: bottom quad then top quad
    write_vtk_classic("tets_and_hexahedron.vtk", hp, CUBE_TETS + [hex_cell], [10] * 6 + [12])
    # a crack: two unit cubes side by side, the second with its own nodes on the interface x = 1
    cp = pts + cube_points((1, 0, 0))
    write_vtk_classic("cracked_interface.vtk", cp, CUBE_TETS + [tuple(v + 8 for v in t) for t in CUBE_TETS], [10] * 12)
    # MEDIT with the blocks the manual says to skip
    with open(path("cube_extra_blocks.mesh"), "w") as f:
        f.write("MeshVersionFormatted 2\nDimension 3\nIdentifier\n\"cube with extra blocks\"\nGeometry\n\"cube.stl\"\n")
        f.write("Vertices\n8\n" + "".join("%g %g %g 0\n" % p for p in pts))
        f.write("Tetrahedra\n6\n" + "".join("%d %d %d %d 1\n" % tuple(v + 1 for v in t) for t in CUBE_TETS))
        f.write("Triangles\n2\n1 2 4 3\n1 4 3 3\nRequiredTriangles\n1\n1\n")
        f.write("Normals\n2\n0 0 -1\n0 0 -1\nNormalAtVertices\n2\n1 1\n2 2\n")
        f.write("Tangents\n1\n1 0 0\nTangentAtVertices\n1\n1 1\nEdges\n1\n1 2 5\nRidges\n1\n1\nCorners\n1\n1\nEnd\n")
    with open(path("tets_and_prism.mesh"), "w") as f:
        f.write("MeshVersionFormatted 2\nDimension 3\nVertices\n9\n" + "".join("%g %g %g 0\n" % p for p in pts))
        f.write("2 0 0 0\nTetrahedra\n6\n" + "".join("%d %d %d %d 1\n" % tuple(v + 1 for v in t) for t in CUBE_TETS))
        f.write("Prisms\n1\n2 9 4 6 9 8 2\nEnd\n")


def gmsh_files():
    try:
        import gmsh
    except ImportError:
        print("make_inputs.py: gmsh's Python module not found (python3-gmsh): .msh and .step skipped")
        return
    gmsh.initialize(readConfigFiles=False)
    gmsh.option.setNumber("General.Terminal", 0)
    # a box with a box-shaped cavity: volume 8 - 1 = 7, 12 faces, 24 edges, 16 corners
    gmsh.model.add("box_with_cavity")
    gmsh.model.occ.addBox(0, 0, 0, 2, 2, 2, 1)
    gmsh.model.occ.addBox(0.5, 0.5, 0.5, 1, 1, 1, 2)
    gmsh.model.occ.cut([(3, 1)], [(3, 2)])
    gmsh.model.occ.synchronize()
    gmsh.write(path("box_with_cavity.step"))
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.5)
    gmsh.model.mesh.generate(3)
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    gmsh.write(path("box_with_cavity_v41.msh"))
    gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
    gmsh.write(path("box_with_cavity_v22.msh"))
    sphere_tangent_to_a_face(gmsh)
    gmsh.finalize()


def sphere_tangent_to_a_face(gmsh):
    # a unit cube minus a sphere of radius 0.3 tangent to its top face at (0.5, 0.5, 1): a solid that
    # touches itself at one point, which gmsh's 3D mesher refuses with a PLC error naming no point
    gmsh.model.add("sphere_tangent")
    gmsh.model.occ.addBox(0, 0, 0, 1, 1, 1, 1)
    gmsh.model.occ.addSphere(0.5, 0.5, 0.7, 0.3, 2)
    gmsh.model.occ.cut([(3, 1)], [(3, 2)])
    gmsh.model.occ.synchronize()
    gmsh.write(path("sphere_tangent.step"))


def cad_parts():
    # CAD parts of the solver-format, thin-wall and feature-coverage tests (gmsh's OpenCASCADE kernel)
    import gmsh
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    # a 1 x 2 x 3 box: six planar CAD faces, the boundary groups of a hex mesh of it
    gmsh.model.add("box")
    gmsh.model.occ.addBox(0, 0, 0, 1, 2, 3)
    gmsh.model.occ.synchronize()
    gmsh.write(path("box_1x2x3.step"))
    # a 2 x 2 x 0.03 plate: with 400 hexahedra (edge 0.067) no layer fits in its thickness; at edge 0.03
    # one layer of about 4400 hexahedra
    gmsh.model.add("thin_plate")
    gmsh.model.occ.addBox(0, 0, 0, 2, 2, 0.03)
    gmsh.model.occ.synchronize()
    gmsh.write(path("thin_plate.step"))
    # the plate of the field report, 20 x 20 x 0.02: gmsh takes some 10 s at mesh size 0.15 (the time
    # limit test) and minutes at its default size
    gmsh.model.add("large_thin_plate")
    gmsh.model.occ.addBox(0, 0, 0, 20, 20, 0.02)
    gmsh.model.occ.synchronize()
    gmsh.write(path("thin_plate_20x20.step"))
    # a cylinder with a rounded top (a fillet of radius 0.2 on its top circle): one curved sharp edge,
    # the bottom circle
    gmsh.model.add("rounded_cylinder")
    gmsh.model.occ.addCylinder(0, 0, 0, 0, 0, 1, 0.5, 1)
    gmsh.model.occ.synchronize()
    top = [c for _, c in gmsh.model.getEntities(1)
           if abs(gmsh.model.occ.getCenterOfMass(1, c)[2] - 1) < 1e-9]
    gmsh.model.occ.fillet([1], top, [0.2])
    gmsh.model.occ.synchronize()
    gmsh.write(path("rounded_cylinder.step"))
    # a stepped shaft with a keyway: two coaxial cylinders and a slot cut along the thick one
    gmsh.model.add("stepped_shaft")
    gmsh.model.occ.addCylinder(0, 0, 0, 0, 0, 1.2, 0.5, 1)
    gmsh.model.occ.addCylinder(0, 0, 1.2, 0, 0, 0.8, 0.3, 2)
    gmsh.model.occ.fuse([(3, 1)], [(3, 2)], 3)
    gmsh.model.occ.addBox(-0.1, 0.35, 0.2, 0.2, 0.3, 0.8, 4)
    gmsh.model.occ.cut([(3, 3)], [(3, 4)], 5)
    gmsh.model.occ.synchronize()
    gmsh.write(path("stepped_shaft.step"))
    # a 4 x 2 x 1 block with a fin 0.1 thick and 1 tall on top, and a 4 x 2 x 2 block with a slot 0.1
    # wide and 1 deep: at hex edge 0.3 the greedy rounding collapses the fin (its two faces on one
    # integer plane) and the slot; the separation program keeps one layer (issue 27)
    gmsh.model.add("fin")
    gmsh.model.occ.addBox(0, 0, 0, 4, 2, 1, 1)
    gmsh.model.occ.addBox(1.95, 0, 1, 0.1, 2, 1, 2)
    gmsh.model.occ.fuse([(3, 1)], [(3, 2)])
    gmsh.model.occ.synchronize()
    gmsh.write(path("fin_block.step"))
    gmsh.model.add("slot")
    gmsh.model.occ.addBox(0, 0, 0, 4, 2, 2, 1)
    gmsh.model.occ.addBox(1.95, -1, 1, 0.1, 4, 2, 2)
    gmsh.model.occ.cut([(3, 1)], [(3, 2)])
    gmsh.model.occ.synchronize()
    gmsh.write(path("slotted_block.step"))
    gmsh.finalize()


if __name__ == "__main__":
    surfaces()
    volumes()
    gmsh_files()
    cad_parts()
