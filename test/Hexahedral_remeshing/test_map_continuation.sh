#!/usr/bin/env bash
# A map whose tetrahedra are all positive can still fail to be locally injective: around an interior edge
# the parameter angles must sum to the field's valence (3 or 5 quarter turns on a singular edge, 4
# elsewhere). On the flange of make_parts.py (flange.brep, a 10-thick disk with a hub and 4 bolt holes;
# gmsh's default size, 52,079 tetrahedra) the repair of the folds of the quantized map (the untangling, here
# of the re-embedded complex's lengths) leaves valence-5 curves across the disk at valence 1, each beside a
# regular edge at valence 8: branched edges, and a non-conforming hex mesh.
# 1. With that repair alone (--no-continuation), `hexmesh parametrize` must report every branched edge
#    (integer_grid_map.branched_edges, status BRANCHED_EDGES, a warning, exit 0) as check_hexex.py finds
#    them from the written parameters alone (interior edges away from inverted and flat tetrahedra whose
#    valence is not 3, 4 or 5).
# 2. By default, the continuation from the injective seamless map to the integer values, on which no
#    tetrahedron folds, must make the map instead (integer_grid_map.continuation: ran on a folded quantized
#    map, kept): check_hexex.py finds no inverted or flat tetrahedron and no branched edge, and
#    check_hex_mesh.py finds the hex mesh of `hexmesh remesh` valid (corner orientations, conformity, closed
#    boundary). About 2 minutes.
#   test_map_continuation.sh HEXMESH SOURCE_DIR
set -uo pipefail
hexmesh="$1"; root="$2"
model="$root/test/Hexahedral_remeshing/data/flange.brep"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
export OMP_WAIT_POLICY=PASSIVE
py=/usr/bin/python3; [ -x "$py" ] || py=python3
"$hexmesh" parametrize "$model" --threads 1 --quiet --keep-partial --no-continuation \
  --hexex "$tmp/branched.hexex" --json "$tmp/branched.json" > "$tmp/out1" 2> "$tmp/err1"
rc1=$?
if [ "$rc1" -ne 0 ] && [ "$rc1" -ne 4 ]; then echo "FAIL: hexmesh parametrize exit $rc1: $(tail -1 "$tmp/err1")"; exit 1; fi
"$py" "$root/test/Hexahedral_remeshing/check_hexex.py" "$tmp/branched.hexex" > "$tmp/branched_check.json"
"$hexmesh" remesh "$model" --threads 1 --quiet --out "$tmp/hex.mesh" \
  --hexex "$tmp/map.hexex" --json "$tmp/map.json" > "$tmp/out2" 2> "$tmp/err2"
rc2=$?
if [ "$rc2" -ne 0 ]; then echo "FAIL: hexmesh remesh exit $rc2: $(tail -1 "$tmp/err2")"; exit 1; fi
"$py" "$root/test/Hexahedral_remeshing/check_hexex.py" "$tmp/map.hexex" > "$tmp/check.json"
"$py" - "$tmp/branched.json" "$tmp/branched_check.json" "$rc1" "$tmp/err1" "$tmp/map.json" "$tmp/check.json" <<'PY'
import json, sys
failures = []
# 1. the repair alone: branched edges, reported as the checker finds them
b = json.load(open(sys.argv[1]))['integer_grid_map']
bc = json.load(open(sys.argv[2]))
rc, err = int(sys.argv[3]), open(sys.argv[4]).read()
print('--no-continuation: status %s, %d inverted, %d flat, %d branched edges; check_hexex.py: %d inverted, %d flat, '
      'interior valences %s, %d unusual interior edges; exit %d' %
      (b['status'], b['inverted_tetrahedra'], b['degenerate_tetrahedra'], b['branched_edges'], bc['inverted_tetrahedra'],
       bc['degenerate_tetrahedra'], bc['interior_edge_valences'], bc['unusual_interior_edges'], rc))
if b['branched_edges'] != bc['unusual_interior_edges']:
    failures.append('the package reports %d branched edges, check_hexex.py finds %d' % (b['branched_edges'], bc['unusual_interior_edges']))
if b['continuation']['ran']:
    failures.append('the continuation ran with --no-continuation')
if bc['unusual_interior_edges'] == 0:
    failures.append('the repaired map does not branch: the case no longer shows what the continuation is for')
if b['branched_edges'] > 0 and b['status'] in ('OK', 'DEGENERATE_TETRAHEDRA'):
    failures.append('a branched map has status %s' % b['status'])
if b['status'] == 'BRANCHED_EDGES' and (rc != 0 or 'branched edges' not in err):
    failures.append('parametrize exits %d on a branched map without folds, with no warning naming the branched edges' % rc)
# 2. the continuation
m = json.load(open(sys.argv[5]))['integer_grid_map']
c = json.load(open(sys.argv[6]))
k = m['continuation']
print('default: status %s, %d inverted, %d flat, %d branched edges; continuation ran %s, kept %s, program lengths %s, '
      '%d steps, folds %d -> %d; check_hexex.py: %d inverted, %d flat, interior valences %s, %d unusual interior '
      'edges, valid %s' %
      (m['status'], m['inverted_tetrahedra'], m['degenerate_tetrahedra'], m['branched_edges'], k['ran'], k['kept'],
       k['program_lengths'], k['steps'], k['folds_before'], k['folds_after'], c['inverted_tetrahedra'],
       c['degenerate_tetrahedra'], c['interior_edge_valences'], c['unusual_interior_edges'], c['valid']))
if m['branched_edges'] != c['unusual_interior_edges']:
    failures.append('the package reports %d branched edges, check_hexex.py finds %d' % (m['branched_edges'], c['unusual_interior_edges']))
if not k['ran'] or k['folds_before'] == 0:
    failures.append('the quantized map did not fold: the case no longer exercises the continuation')
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
