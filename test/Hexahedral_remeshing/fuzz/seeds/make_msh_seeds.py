#!/usr/bin/env python3
# Writes the .msh seeds of the msh fuzz target (a unit cube of 6 tetrahedra in formats 4.1 ASCII,
# 2.2 ASCII and 4.1 binary): /usr/bin/python3 make_msh_seeds.py seeds/msh  (needs python3-gmsh)
import gmsh, sys
gmsh.initialize(readConfigFiles=False)
gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.add("cube")
v = gmsh.model.addDiscreteEntity(3)
pts = [(i & 1, (i >> 1) & 1, (i >> 2) & 1) for i in range(8)]
gmsh.model.mesh.addNodes(3, v, list(range(1, 9)), [c for p in pts for c in p])
tets = [(0, 1, 3, 7), (0, 1, 5, 7), (0, 2, 3, 7), (0, 2, 6, 7), (0, 4, 5, 7), (0, 4, 6, 7)]
gmsh.model.mesh.addElementsByType(v, 4, [], [i + 1 for t in tets for i in t])
for version, binary, name in ((4.1, 0, "cube_v41.msh"), (2.2, 0, "cube_v22.msh"), (4.1, 1, "cube_v41_binary.msh")):
    gmsh.option.setNumber("Mesh.MshFileVersion", version)
    gmsh.option.setNumber("Mesh.Binary", binary)
    gmsh.write(sys.argv[1] + "/" + name)
gmsh.finalize()
