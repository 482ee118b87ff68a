#!/usr/bin/env bash
# A map whose tetrahedra are all positive can still fail to be locally injective: around an interior edge
# the parameter angles must sum to the field's valence (3 or 5 quarter turns on a singular edge, 4
# elsewhere). On the flange of make_parts.py (flange.brep, a 10-thick disk with a hub and 4 bolt holes;
# gmsh's default size, 52,079 tetrahedra) the repair of the folds (the untangling of the re-embedded
# complex's lengths) leaves valence-5 curves across the disk at valence 1, each beside a regular edge at
# valence 8: 21 branched edges, and a non-conforming hex mesh. The continuation from the injective seamless
# map to the same integer values, on which no tetrahedron folds, must replace that map
# (integer_grid_map.continuation: ran, kept, branched edges before > 0, none after). Measured independently:
# check_hexex.py on the written map (no inverted or flat tetrahedron, no interior edge whose valence is not
# 3, 4 or 5, transitions, planes; the package's count of branched edges must equal the checker's), and
# check_hex_mesh.py on the hex mesh (corner orientations, conformity, closed boundary). About 2 minutes.
#   test_map_continuation.sh HEXMESH SOURCE_DIR
set -uo pipefail
hexmesh="$1"; root="$2"
model="$root/test/Hexahedral_remeshing/data/flange.brep"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
export OMP_WAIT_POLICY=PASSIVE
"$hexmesh" remesh "$model" --threads 1 --quiet --out "$tmp/hex.mesh" \
  --hexex "$tmp/map.hexex" --json "$tmp/map.json" > "$tmp/out" 2> "$tmp/err"
rc=$?
if [ "$rc" -ne 0 ]; then echo "FAIL: hexmesh remesh exit $rc: $(tail -1 "$tmp/err")"; exit 1; fi
py=/usr/bin/python3; [ -x "$py" ] || py=python3
"$py" "$root/test/Hexahedral_remeshing/check_hexex.py" "$tmp/map.hexex" > "$tmp/check.json"
"$py" - "$tmp/map.json" "$tmp/check.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))['integer_grid_map']
c = json.load(open(sys.argv[2]))
k = m['continuation']
print('package: status %s, %d inverted, %d flat, %d branched edges; continuation ran %s, kept %s, %d steps, '
      'branched edges %d -> %d; check_hexex.py: %d inverted, %d flat, interior valences %s, %d unusual interior '
      'edges, valid %s' %
      (m['status'], m['inverted_tetrahedra'], m['degenerate_tetrahedra'], m['branched_edges'], k['ran'], k['kept'],
       k['steps'], k['branched_before'], k['branched_after'], c['inverted_tetrahedra'], c['degenerate_tetrahedra'],
       c['interior_edge_valences'], c['unusual_interior_edges'], c['valid']))
failures = []
if m['branched_edges'] != c['unusual_interior_edges']:
    failures.append('the package reports %d branched edges, check_hexex.py finds %d' % (m['branched_edges'], c['unusual_interior_edges']))
if not k['ran'] or k['branched_before'] == 0:
    failures.append('the repaired map did not branch: the case no longer exercises the continuation')
if not k['kept']:
    failures.append('the continuation was not kept')
if not c['valid'] or c['unusual_interior_edges'] or c['inverted_tetrahedra'] or c['degenerate_tetrahedra']:
    failures.append('the written map is not a locally injective integer-grid map')
if m['status'] != 'OK':
    failures.append('status %s' % m['status'])
for f in failures:
    print('FAIL: ' + f)
sys.exit(1 if failures else 0)
PY
[ $? -eq 0 ] || exit 1
"$py" "$root/test/Hexahedral_remeshing/check_hex_mesh.py" "$tmp/hex.mesh" || exit 1
