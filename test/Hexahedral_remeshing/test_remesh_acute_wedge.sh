#!/usr/bin/env bash
# End to end on the shipped 10-degree wedge (issue 11): `hexmesh remesh` must give a valid hex mesh
# (exit 0), which check_hex_mesh.py checks again independently of the package
# (corner orientations, conformity, closed boundary), and the 10-degree edge (the x axis) must be covered
# by hex edges of valence 1, counted here from the output's hexahedra. The integer-grid map the
# hexahedra come from (--hexex) is checked from its parameters by check_hexex.py: no inverted
# tetrahedron, every transition a cube rotation with an integer shift, every boundary face on an integer
# plane, and the parameter angle sum of every tetrahedron edge on the 10-degree edge equal to pi/2.
# vtk: the HexMe tetrahedra n13c_acute_line.vtk as they are (592, 0.3 per hexahedron: the map collapses),
# which remesh refines after the first run fails (tetrahedron_refinement): valid, the 10-degree
# edge (the z axis there) at valence 1, and the JSON says the refined mesh was used.
#   test_remesh_acute_wedge.sh HEXMESH SOURCE_DIR [msh|brep|vtk]
# msh (default): the hand-graded tetrahedra n13c_acute_wedge_graded.msh, hex mesh and map checked;
# brep: the CAD part n13c_acute_wedge.brep, the main job of scripts/run, tetrahedralized by gmsh and
# graded towards the acute edge by read_CAD(); its hex mesh is checked (its map folds on 12 tetrahedra
# 0.005 from the acute edge where it meets the end face, which the extraction and smoothing repair).
set -uo pipefail
hexmesh="$1"; root="$2"; mode="${3:-msh}"
case "$mode" in
  msh) model="$root/examples/Hexahedral_remeshing/data/n13c_acute_wedge_graded.msh" ;;
  brep) model="$root/examples/Hexahedral_remeshing/data/n13c_acute_wedge.brep" ;;
  vtk) model="$root/examples/Hexahedral_remeshing/data/n13c_acute_line.vtk" ;;
  *) echo "FAIL: unknown mode $mode"; exit 1 ;;
esac
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
export OMP_WAIT_POLICY=PASSIVE
"$hexmesh" remesh "$model" --quiet \
  --out "$tmp/wedge.mesh" --hexex "$tmp/wedge.hexex" --json "$tmp/wedge.json" > "$tmp/out" 2> "$tmp/err"
rc=$?
if [ "$rc" -ne 0 ]; then echo "FAIL: hexmesh remesh exit $rc: $(tail -1 "$tmp/err")"; exit 1; fi
# numpy: Debian's python3 (scripts/setup installs python3-numpy)
py=/usr/bin/python3; [ -x "$py" ] || py=python3
if [ "$mode" = vtk ]; then
  "$py" -c 'import json, sys; r = json.load(open(sys.argv[1]))["tetrahedron_refinement"]
print("refinement: %d rounds, %d tetrahedra, used %s; the mesh as given: %s" % (r["rounds"], r["tetrahedra"], r["used"], r["other_outcome"][:100]))
sys.exit(0 if r["used"] and r["rounds"] >= 1 and not r["other_outcome"].startswith("OK") else 1)' "$tmp/wedge.json" \
    || { echo "FAIL: the hex mesh of the coarse wedge does not come from its refinement"; exit 1; }
fi
if [ "$mode" = msh ]; then
"$py" "$root/test/Hexahedral_remeshing/check_hexex.py" "$tmp/wedge.hexex" --expect-valid --edge-valence 0,0,0,1,0,0,1 \
  > "$tmp/map.json" || { cat "$tmp/map.json"; echo "FAIL: the map of the wedge"; exit 1; }
"$py" - "$tmp/map.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
s = r['segments'][0]
print('map: %d tetrahedra, %d inverted, %d flat, %d bad transitions, %d boundary faces off their plane; '
      '%d tetrahedron edges on the 10-degree edge (length %.6f) of valences %s' %
      (r['tetrahedra'], r['inverted_tetrahedra'], r['degenerate_tetrahedra'], r['bad_transitions'],
       r['boundary_faces_off_plane'], s['edges'], s['length'], s['valences']))
if abs(s['length'] - 1.0) > 1e-6:
    print('FAIL: the tetrahedron edges found do not cover the 10-degree edge')
    sys.exit(1)
PY
[ $? -eq 0 ] || exit 1
fi
python3 "$root/test/Hexahedral_remeshing/check_hex_mesh.py" "$tmp/wedge.mesh" || exit 1
axis=0; [ "$mode" = vtk ] && axis=2  # the 10-degree edge: the x axis of the made wedge, the z axis of HexMe's
python3 - "$tmp/wedge.mesh" "$axis" <<'PY'
import sys
axis = int(sys.argv[2])
tokens = open(sys.argv[1]).read().split()
i = tokens.index("Vertices")
n = int(tokens[i + 1])
points = [tuple(float(t) for t in tokens[i + 2 + 4 * k:i + 5 + 4 * k]) for k in range(n)]
j = tokens.index("Hexahedra")
m = int(tokens[j + 1])
hexes = [[int(t) - 1 for t in tokens[j + 2 + 9 * k:j + 10 + 9 * k]] for k in range(m)]
# the 12 edges of a hexahedron in the Medit (and VTK) vertex order
edges = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7)]
on_axis = lambda v: all(abs(points[v][d]) < 1e-9 for d in range(3) if d != axis)
valence = {}
for h in hexes:
    for a, b in edges:
        u, v = h[a], h[b]
        if on_axis(u) and on_axis(v):
            key = (min(u, v), max(u, v))
            valence[key] = valence.get(key, 0) + 1
length = sum(abs(points[u][axis] - points[v][axis]) for u, v in valence)
bad = [k for k, c in valence.items() if c != 1]
print("%d hexahedra; %d hex edges on the 10-degree edge, total length %.6f, valences %s" %
      (m, len(valence), length, sorted(set(valence.values()))))
if not valence or bad or abs(length - 1.0) > 1e-6:
    print("FAIL: the 10-degree edge is not covered by hex edges of valence 1")
    sys.exit(1)
PY
