#!/usr/bin/env bash
# The seamless map is locally injective only if, besides every tetrahedron being positive, the parameter
# angles around every interior edge sum to 3, 4 or 5 quarter turns: its untangling can wrap the map around
# an edge with every tetrahedron positive. The flange of make_parts.py meshed by gmsh at --mesh-size 1.8
# (87,415 tetrahedra; 91 folds in the energy's minimizer) is such a case: its local untangling leaves 3
# branched edges beside a bolt hole, and the package must then untangle it again with every variable free
# (integer_grid_map.seamless_map.unbranching_ran) and keep a map that is locally injective: the seamless map
# it writes (--seamless-hexex) must have, by check_hexex.py (from the parameters alone, apart from the
# package), no inverted or flat tetrahedron and no interior edge whose angle sum is not 3, 4 or 5 quarter
# turns, and the report must say injective with the same count (0). Without the second untangling the
# checker finds the 3 edges. About 3 minutes.
#   test_seamless_branched.sh HEXMESH SOURCE_DIR
set -uo pipefail
hexmesh="$1"; root="$2"
model="$root/test/Hexahedral_remeshing/data/flange.brep"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
export OMP_WAIT_POLICY=PASSIVE
py=/usr/bin/python3; [ -x "$py" ] || py=python3
"$hexmesh" parametrize "$model" --mesh-size 1.8 --threads 1 --quiet --keep-partial \
  --hexex "$tmp/map.hexex" --seamless-hexex "$tmp/seamless.hexex" --json "$tmp/map.json" > "$tmp/out" 2> "$tmp/err"
rc=$?
if [ "$rc" -ne 0 ] && [ "$rc" -ne 4 ]; then echo "FAIL: hexmesh parametrize exit $rc: $(tail -1 "$tmp/err")"; exit 1; fi
[ -s "$tmp/seamless.hexex" ] || { echo "FAIL: no seamless map written"; exit 1; }
"$py" "$root/test/Hexahedral_remeshing/check_hexex.py" "$tmp/seamless.hexex" > "$tmp/check.json"
"$py" - "$tmp/map.json" "$tmp/check.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))['integer_grid_map']['seamless_map']
c = json.load(open(sys.argv[2]))
print('seamless map: report injective %s, %d inverted, %d flat, %d branched edges; check_hexex.py: %d inverted, %d degenerate, %d unusual interior edges'
      % (s['injective'], s['inverted_tetrahedra'], s['degenerate_tetrahedra'], s['branched_edges'], c['inverted_tetrahedra'], c['degenerate_tetrahedra'],
         c['unusual_interior_edges']))
failures = []
if not s['unbranching_ran']:
    failures.append('the local untangling no longer branches: the case no longer exercises the second untangling')
if c['inverted_tetrahedra'] + c['degenerate_tetrahedra'] != 0 or s['inverted_tetrahedra'] + s['degenerate_tetrahedra'] != 0:
    failures.append('the seamless map folds')
if c['unusual_interior_edges'] != 0:
    failures.append('the checker finds %d branched edges in the seamless map' % c['unusual_interior_edges'])
if s['branched_edges'] != c['unusual_interior_edges']:
    failures.append('branched edges: report %d, checker %d' % (s['branched_edges'], c['unusual_interior_edges']))
if not s['injective']:
    failures.append('reported not injective')
for f in failures: print('FAIL: ' + f)
sys.exit(1 if failures else 0)
PY
