#!/usr/bin/env bash
# End-to-end tests of the hexmesh command-line tool: exit codes, one-line errors, JSON reports.
#   test_hexmesh_cli.sh HEXMESH REPO_ROOT
set -u
hexmesh="$1"; root="$2"
data="$root/examples/Hexahedral_remeshing/data"
broken="$root/test/Hexahedral_remeshing/data/broken"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# expect_error CODE PATTERN ARGS...: exit code CODE and one stderr line containing PATTERN
expect_error() {
  local code="$1" pattern="$2"; shift 2
  "$hexmesh" "$@" > "$tmp/out" 2> "$tmp/err"; local rc=$?
  [ "$rc" -eq "$code" ] || fail "hexmesh $*: exit $rc, expected $code"
  [ "$(wc -l < "$tmp/err")" -eq 1 ] || fail "hexmesh $*: expected a one-line message, got: $(cat "$tmp/err")"
  grep -q -- "$pattern" "$tmp/err" || fail "hexmesh $*: message lacks '$pattern': $(cat "$tmp/err")"
}

# info on the shipped model: exit 0, JSON with the documented keys and the exact histogram
"$hexmesh" info "$data/n13c_acute_line.vtk" --json "$tmp/info.json" > "$tmp/out" 2> "$tmp/err" || fail "info exit code $?"
grep -q '"dihedral_class_histogram": \[8, 52, 615, 0, 0\]' "$tmp/info.json" || fail "info JSON histogram: $(cat "$tmp/info.json")"
for key in vertices tetrahedra boundary_triangles boundary_edges components boundary_euler_characteristic \
           feature_edges min_dihedral_angle_degrees max_dihedral_angle_degrees; do
  grep -q "\"$key\"" "$tmp/info.json" || fail "info JSON lacks $key"
done
python3 -c "import json,sys; json.load(open(sys.argv[1]))" "$tmp/info.json" 2>/dev/null || \
  { command -v python3 >/dev/null && fail "info JSON is not valid JSON"; }
grep -q "k = 0 (phi < 45, not meshable): 8" "$tmp/out" || fail "info output lacks the class-0 count"
"$hexmesh" info "$data/cube.off" > /dev/null 2>&1 || fail "info on a surface (TetGen) failed"
"$hexmesh" --help | grep -q "usage: hexmesh" || fail "--help"

expect_error 3 "does_not_exist.vtk: cannot open file" info "$tmp/does_not_exist.vtk"
expect_error 3 "malformed_number.vtk:7: malformed number" info "$broken/malformed_number.vtk"
expect_error 3 "degenerate (zero volume)" info "$broken/degenerate_tetrahedron.vtk"
expect_error 3 "binary VTK files are not supported" info "$broken/binary.vtk"
expect_error 2 "unknown command" frobnicate
expect_error 2 "unknown option --nope" info "$data/n13c_acute_line.vtk" --nope
expect_error 2 "expects a number" info "$data/cube.off" --max-volume abc
expect_error 5 "cannot open file for writing" info "$data/n13c_acute_line.vtk" --json "$tmp/no/such/dir/x.json"
[ ! -e "$tmp/no/such/dir/x.json.tmp" ] || fail "partial output left behind"

[ "$failures" -eq 0 ] && echo "all hexmesh CLI checks passed"
exit "$failures"
