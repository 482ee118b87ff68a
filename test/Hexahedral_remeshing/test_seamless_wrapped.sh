#!/usr/bin/env bash
# Where the seamless map folds at the boundary, the report counts the boundary vertices around which it
# wraps the boundary surface (integer_grid_map.seamless_map.wrapped_boundary_vertices): the parameter angles
# of a vertex's boundary triangles, negative on inverted tetrahedra, sum to 0 or fewer quarter turns, or,
# where the surface is smooth, to other than 3, 4 or 5 (no hex mesh has such a boundary vertex, and the
# untangling seldom unwinds it). check_hexex.py counts them again from the written seamless map
# (--seamless-hexex) alone, apart from the package. HexMe n11c (no singular curve; its 13 folds are where
# the map folds the boundary over itself), s11c (four valence-3 curves ending on a concave circle, which
# collapse the cylinder's wall onto them) and the cube (injective, none) must give the same count both ways,
# n11c and s11c at least one, and n11c every fold at such a vertex. Skipped when ../shared/data is absent.
#   test_seamless_wrapped.sh HEXMESH SOURCE_DIR SHARED_DATA_DIR
set -uo pipefail
hexmesh="$1"; root="$2"; data="$3"
if [ ! -d "$data/hexme" ]; then
  echo "no shared data at $data: skipped"
  exit 0
fi
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
export OMP_WAIT_POLICY=PASSIVE
py=/usr/bin/python3; [ -x "$py" ] || py=python3
failed=0
for m in n11c_limit_cycle s11c_cube_cyl s01c_cube; do
  "$hexmesh" parametrize "$data/hexme/$m.vtk" --threads 1 --quiet --keep-partial \
    --hexex "$tmp/$m.hexex" --seamless-hexex "$tmp/$m.seamless.hexex" --json "$tmp/$m.json" > "$tmp/out" 2> "$tmp/err"
  rc=$?
  if [ "$rc" -ne 0 ] && [ "$rc" -ne 4 ]; then echo "FAIL $m: hexmesh parametrize exit $rc: $(tail -1 "$tmp/err")"; failed=1; continue; fi
  "$py" "$root/test/Hexahedral_remeshing/check_hexex.py" "$tmp/$m.seamless.hexex" > "$tmp/$m.check.json" || { echo "FAIL $m: check_hexex.py"; failed=1; continue; }
  "$py" - "$m" "$tmp/$m.json" "$tmp/$m.check.json" <<'PY' || failed=1
import json, sys
m = sys.argv[1]
s = json.load(open(sys.argv[2]))['integer_grid_map']['seamless_map']
c = json.load(open(sys.argv[3]))
folds = s['inverted_tetrahedra'] + s['degenerate_tetrahedra']
print('%s: seamless map %d folds; wrapped boundary vertices: report %d (%d in the minimizer, %d folds there), check_hexex.py %d'
      % (m, folds, s['wrapped_boundary_vertices'], s['wrapped_before_untangling'], s['folds_at_wrapped_boundary'], c['wrapped_boundary_vertices']))
failures = []
if s['wrapped_boundary_vertices'] != c['wrapped_boundary_vertices']:
    failures.append('report and checker disagree')
if m == 's01c_cube' and (folds != 0 or c['wrapped_boundary_vertices'] != 0):
    failures.append('the cube\'s seamless map folds or wraps')
if m != 's01c_cube' and c['wrapped_boundary_vertices'] == 0:
    failures.append('no wrapped boundary vertex found: the case no longer exercises the count')
if m == 'n11c_limit_cycle' and s['folds_at_wrapped_boundary'] != folds:
    failures.append('%d of %d folds at wrapped vertices' % (s['folds_at_wrapped_boundary'], folds))
for f in failures: print('FAIL %s: %s' % (m, f))
sys.exit(1 if failures else 0)
PY
done
exit $failed
