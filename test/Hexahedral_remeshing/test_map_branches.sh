#!/usr/bin/env bash
# A map whose tetrahedra are all positive can still fail to be locally injective: around an interior edge
# the parameter angles must sum to the field's valence (3 or 5 quarter turns on a singular edge, 4
# elsewhere). On the flange of make_parts.py (flange.brep, a 10-thick disk with a hub and 4 bolt holes;
# gmsh's default size, 52,079 tetrahedra) the repair of the folds leaves valence-5 curves across the disk at
# valence 1, each beside a regular edge at valence 8. `hexmesh parametrize` must report every such edge
# (integer_grid_map.branched_edges, status BRANCHED_EDGES when nothing worse applies) as check_hexex.py
# finds them from the written parameters alone (unusual_interior_edges: interior edges away from inverted
# and flat tetrahedra whose valence is not 3, 4 or 5), and warn (exit 0: the extraction copes where the
# branch holds no integer point, as on MAMBO B1_tet). The counts must agree whatever they are, so the test
# holds once the branches are repaired.
#   test_map_branches.sh HEXMESH SOURCE_DIR
set -uo pipefail
hexmesh="$1"; root="$2"
model="$root/test/Hexahedral_remeshing/data/flange.brep"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
export OMP_WAIT_POLICY=PASSIVE
"$hexmesh" parametrize "$model" --threads 1 --quiet --keep-partial \
  --hexex "$tmp/map.hexex" --json "$tmp/map.json" > "$tmp/out" 2> "$tmp/err"
rc=$?
if [ "$rc" -ne 0 ] && [ "$rc" -ne 4 ]; then echo "FAIL: hexmesh parametrize exit $rc: $(tail -1 "$tmp/err")"; exit 1; fi
py=/usr/bin/python3; [ -x "$py" ] || py=python3
"$py" "$root/test/Hexahedral_remeshing/check_hexex.py" "$tmp/map.hexex" > "$tmp/check.json"
"$py" - "$tmp/map.json" "$tmp/check.json" "$rc" "$tmp/err" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))['integer_grid_map']
c = json.load(open(sys.argv[2]))
rc = int(sys.argv[3])
print('package: status %s, %d inverted, %d flat, %d branched edges; check_hexex.py: %d inverted, %d flat, interior '
      'valences %s, %d unusual interior edges (%d of valence 1 or less); exit %d' %
      (m['status'], m['inverted_tetrahedra'], m['degenerate_tetrahedra'], m['branched_edges'], c['inverted_tetrahedra'],
       c['degenerate_tetrahedra'], c['interior_edge_valences'], c['unusual_interior_edges'], c['branched_edges'], rc))
failures = []
if m['branched_edges'] != c['unusual_interior_edges']:
    failures.append('the package reports %d branched edges, check_hexex.py finds %d' % (m['branched_edges'], c['unusual_interior_edges']))
if m['branched_edges'] > 0 and m['status'] in ('OK', 'DEGENERATE_TETRAHEDRA'):
    failures.append('a branched map has status %s' % m['status'])
err = open(sys.argv[4]).read()
if m['status'] == 'BRANCHED_EDGES' and (rc != 0 or 'branched edges' not in err):
    failures.append('parametrize exits %d on a branched map without folds, with no warning naming the branched edges' % rc)
if m['branched_edges'] == 0 and m['status'] == 'BRANCHED_EDGES':
    failures.append('status BRANCHED_EDGES without a branched edge')
for f in failures:
    print('FAIL: ' + f)
sys.exit(1 if failures else 0)
PY
