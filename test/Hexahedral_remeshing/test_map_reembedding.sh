#!/usr/bin/env bash
# Issue 27, step 4 (the re-embedding of the motorcycle complex's lengths), end to end on a CAD part:
# filleted_block.brep (a box with a step whose concave and convex edges are filleted, radius 5; made by
# benchmark/Hexahedral_remeshing/make_parts.py), tetrahedralized by gmsh at --mesh-size 2.5 (24,753
# tetrahedra). Its seamless map is injective and its motorcycle complex traced (7 blocks), but the greedy
# rounding folds 63 tetrahedra and the complex's lengths, held in the linear solve, fold too, so the
# rounded map is repaired first: 51 tetrahedra stay folded. The complex's lengths, held and repaired the
# same way (the untangling re-embeds them), fold none: that map must be the one kept.
# What the map is, is measured by check_hexex.py from the written parameters alone (independently of
# the package): no inverted and no flat tetrahedron, every transition a cube rotation with an integer
# shift, every boundary face on an integer plane. The report must say which path made the map, and
# that the rounded map would have kept folds (so the test fails if the case stops exercising the path).
# The hex mesh extracted from that map is checked by check_hex_mesh.py (corner orientations, conformity,
# closed boundary). The continuation from the seamless map, which runs before this repair and reaches the
# complex's lengths on this part, is turned off (--no-continuation): this is the fallback when it fails.
#   test_map_reembedding.sh HEXMESH SOURCE_DIR
set -uo pipefail
hexmesh="$1"; root="$2"
model="$root/test/Hexahedral_remeshing/data/filleted_block.brep"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
export OMP_WAIT_POLICY=PASSIVE
"$hexmesh" remesh "$model" --mesh-size 2.5 --threads 1 --quiet --no-continuation --out "$tmp/hex.mesh" \
  --hexex "$tmp/map.hexex" --json "$tmp/map.json" > "$tmp/out" 2> "$tmp/err"
rc=$?
if [ "$rc" -ne 0 ]; then echo "FAIL: hexmesh remesh exit $rc: $(tail -1 "$tmp/err")"; exit 1; fi
# numpy: Debian's python3 (scripts/setup installs python3-numpy)
py=/usr/bin/python3; [ -x "$py" ] || py=python3
"$py" "$root/test/Hexahedral_remeshing/check_hexex.py" "$tmp/map.hexex" --expect-valid > "$tmp/check.json" \
  || { cat "$tmp/check.json"; echo "FAIL: the map is not a valid integer-grid map"; exit 1; }
"$py" - "$tmp/map.json" "$tmp/check.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))['integer_grid_map']
c = json.load(open(sys.argv[2]))
q = r['quantization']
mc = q['motorcycle_complex']
print('map (check_hexex.py): %d tetrahedra, %d inverted, %d flat, %d bad transitions, %d boundary faces off '
      'their plane' % (c['tetrahedra'], c['inverted_tetrahedra'], c['degenerate_tetrahedra'], c['bad_transitions'],
                       c['boundary_faces_off_plane']))
print('report: path %s (%s); complex %d blocks; seamless map injective %s; once repaired: rounded map %d folds, '
      'the complex\'s lengths %d' % (q['path'], q['reason'], mc['blocks'], r['seamless_map']['injective'],
                                     mc['folds_after_repair_quantized'], mc['folds_after_repair_program']))
failures = []
if c['inverted_tetrahedra'] or c['degenerate_tetrahedra']:
    failures.append('the map has inverted or flat tetrahedra')
if not r['seamless_map']['injective'] or not mc['traced']:
    failures.append('no injective seamless map or no complex: the case no longer reaches the re-embedding')
if mc['folds_after_repair_quantized'] == 0:
    failures.append('the rounded map repairs cleanly: the case no longer needs the re-embedding')
if q['path'] != 'motorcycle_complex' or not mc['reembedded'] or mc['folds_after_repair_program'] != 0:
    failures.append('the complex\'s re-embedded lengths were not kept')
for f in failures:
    print('FAIL: ' + f)
sys.exit(1 if failures else 0)
PY
[ $? -eq 0 ] || exit 1
python3 "$root/test/Hexahedral_remeshing/check_hex_mesh.py" "$tmp/hex.mesh" || exit 1
