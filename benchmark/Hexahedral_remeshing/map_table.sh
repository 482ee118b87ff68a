#!/usr/bin/env bash
# One row per model: `hexmesh parametrize` (prescribed valences, the map that `hexmesh remesh` extracts) on
# every model of ../shared/data (or the files given): tetrahedra, map status, singular curves, jogs, inverted
# and flat tetrahedra, boundary valences of the map as prescribed (parameter-space angle sums), integer
# variables, the seamless map before rounding (folds of its minimizer -> inverted/flat after its
# untangling, exact; "inj" if none), its folds by cause (flat in every map at the boundary / inside; at the
# field's defects, others at the boundary, others inside: Seamless_fold_causes), the boundary vertices around
# which its minimizer -> the untangled map wrap the boundary surface (folds there), the quantization path (greedy rounding or separation program, with the
# folds after the rounding -> after the program), seconds per step and peak memory (GNU time).
#   benchmark/Hexahedral_remeshing/map_table.sh [--timeout S] [FILE...]
# Needs a build (scripts/build) and python3; writes the JSON reports under build/map_table/.
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/table_inputs.sh"
out="$build/map_table"
mkdir -p "$out"
printf '%-28s %7s %-26s %5s %4s %9s %6s %6s %13s %4s %-18s %-18s %-14s %-20s %7s %7s %7s %7s %7s %7s %7s %6s\n' model tets status "v3/v5" impr \
  "jogs(deg)" inv flat "map valences" int seamless "fold causes" "wrapped" quantization field_s elim_s seaml_s round_s stiff_s untan_s map_s peakMB
for f in "${files[@]}"; do
  name=$(basename "$f" .vtk)
  json="$out/$name.json"; rm -f "$json"
  /usr/bin/time -f '%M' -o "$out/$name.mem" timeout "$limit" "$hexmesh" parametrize "$f" --quiet \
    --hexex "$out/$name.hexex" --json "$json" > /dev/null 2> "$out/$name.err"
  rc=$?
  python3 - "$json" "$out/$name.mem" "$name" "$rc" "$out/$name.err" <<'PY'
import json, os, sys
path, mem, name, rc, err = sys.argv[1:]
try: peak = int(open(mem).read().split()[-1]) / 1024
except Exception: peak = float('nan')
if not os.path.exists(path):
    msg = open(err).read().strip().splitlines()
    print('%-28s %s' % (name, 'exit %s: %s' % (rc, msg[-1][:110] if msg else 'timeout')))
    sys.exit(0)
r = json.load(open(path))
m, s, g = r['integer_grid_map'], r['seconds'], r['singularities']
c, sm, q = m['check'], m['seamless_map'], m['quantization']
seamless = '%d->%s' % (sm['inverted_before_untangling'], 'inj' if sm['injective'] else '%d/%d' % (sm['inverted_tetrahedra'], sm['degenerate_tetrahedra']))
fc = sm.get('folds_by_cause', {})
causes = '%d/%d;%d,%d,%d' % tuple(fc.get(k, 0) for k in ('structural_at_boundary', 'structural_inside', 'at_field_defects', 'at_boundary', 'inside'))
wrapped = '%d->%d(%d)' % (sm.get('wrapped_before_untangling', 0), sm.get('wrapped_boundary_vertices', 0), sm.get('folds_at_wrapped_boundary', 0))
quant = '%s %d->%d' % ('separation' if q['path'] == 'separation_program' else 'greedy', q['folds_after_rounding'], q['folds_after_separation'])
print('%-28s %7d %-26s %5s %4d %9s %6d %6d %13s %4d %-18s %-18s %-14s %-20s %7.2f %7.2f %7.2f %7.2f %7.2f %7.2f %7.2f %6.0f' % (
    name, r['tetrahedra'], m['status'], '%d/%d' % (g['valence3_curves'], g['valence5_curves']), g['improper_edges'],
    '%d(%d)' % (m['jogs'], m['degenerate_jogs']), c['inverted_tetrahedra'], c['degenerate_tetrahedra'],
    '%d/%d' % (c['boundary_valences_matched'], c['boundary_valences_total']), m['integer_variables'], seamless, causes, wrapped, quant,
    s['frame_field'], s['elimination'], s['seamless_map'], s['rounding'], s['stiffening'], s['untangling'], s['map'], peak))
PY
done
