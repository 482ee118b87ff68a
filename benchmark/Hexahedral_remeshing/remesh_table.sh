#!/usr/bin/env bash
# One row per model: hexmesh remesh (prescribed valences with the default repair of the field, and --baseline,
# and --no-repair) on every model of
# ../shared/data (or the files given), with the outcome, the stage a failed run failed at, the defects of the
# field's local meshability check before and after the repair and what became of the repair (with the clusters of
# curves removed / found at the hex scale), hex count, scaled Jacobian, Hausdorff distance,
# feature coverage, hex edges on sharp edges with the prescribed valence, seconds per stage and peak memory;
# cells: those the extraction left out / completed from their neighbours (resolve_conflicting_cells); refine: the
# second run on the refined tetrahedra of a coarse mesh that failed as given (used / tried, rounds); +prop / +prop?: the
# whole run again from the boundary propagation (field_restart) kept / tried; total_s: every run.
#   benchmark/Hexahedral_remeshing/remesh_table.sh [--baseline-too] [--no-repair-too] [--timeout S] [FILE or FOLDER...]
# Needs a build (scripts/build) and python3; writes the JSON reports under build/remesh_table/.
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/table_inputs.sh"
out="$build/remesh_table"
mkdir -p "$out"
modes=(prescribed); [ "$baseline" -eq 1 ] && modes+=(baseline); [ "$norepair" -eq 1 ] && modes+=(no_repair)
printf '%-28s %-10s %8s %7s %-17s %-12s %9s %-13s %7s %6s %6s %9s %6s %9s %8s %8s %8s %8s %8s %7s %-8s %8s\n' model mode tets hexes status failed_at defects repair cells minSJ meanSJ \
  hausdorff cover valences field_s repair_s map_s extr_s smooth_s peakMB refine total_s
for f in "${files[@]}"; do
  name=$(basename "$f"); name="${name%.*}"
  for mode in "${modes[@]}"; do
    flag=(); [ "$mode" = baseline ] && flag=(--baseline); [ "$mode" = no_repair ] && flag=(--no-repair)
    json="$out/$name.$mode.json"; rm -f "$json"
    /usr/bin/time -f '%M' -o "$out/$name.$mode.mem" timeout "$limit" "$hexmesh" remesh "$f" "${flag[@]}" --quiet \
      --keep-partial --out "$out/$name.$mode.mesh" --json "$json" > /dev/null 2> "$out/$name.$mode.err"
    rc=$?
    python3 - "$json" "$out/$name.$mode.mem" "$name" "$mode" "$rc" "$out/$name.$mode.err" <<'PY'
import json, os, sys
path, mem, name, mode, rc, err = sys.argv[1:]
try: peak = int(open(mem).read().split()[-1]) / 1024
except Exception: peak = float('nan')
if not os.path.exists(path):
    msg = open(err).read().strip().splitlines()
    print('%-28s %-10s %s' % (name, mode, 'exit %s: %s' % (rc, msg[-1][:110] if msg else 'timeout')))
    sys.exit(0)
r = json.load(open(path))
h, f, s = r['hex_mesh'], r['features'], r['seconds']
m = r.get('meshability', {})
graph = lambda c: sum(v for k, v in c.items() if k not in ('feature_sector', 'disagreeing_face'))
defects = '%d>%d' % (graph(m['before_repair']), graph(m['final'])) if m else '-'
repair_s = m.get('repair', {}).get('seconds', 0.) if m else 0.
rep = m.get('repair', {}) if m else {}
# kept / not kept (changed, no better) / no change / off; fallback: the mesh is the unrepaired field's
repair = ('fallback' if r.get('repair_fallback') else 'no sweeps' if r.get('sweep_fallback') else 'kept' if rep.get('accepted') else
          'no change' if rep.get('performed') and rep.get('changed_faces', 0) == 0 else 'not kept' if rep.get('performed') else 'off')
# hex-scale simplification: clusters of curves with no room at the hex size, removed/found
hs = rep.get('hex_scale', {})
if hs.get('clusters'): repair += ' %d/%d' % (hs.get('removed', 0), hs['clusters'])
hd = f['relative_hausdorff_distance']  # null without a smoothed mesh
ex = r['extraction']  # cells left out / completed from their neighbours
cells = '%d/%d' % (ex.get('incomplete_cells', 0), ex.get('resolved_cells', 0))
# a second run on the refined tetrahedra of a coarse mesh (tetrahedron_refinement): used or only tried
tr = r.get('tetrahedron_refinement', {})
refine = '-' if not tr.get('rounds') else '%s %d' % ('used' if tr.get('used') else 'tried', tr['rounds'])
# the whole run again from the boundary propagation (field_restart): "+prop" if its mesh was kept, "+prop?" if tried
fr = r.get('field_restart', {})
refine += ' +prop' if fr.get('used') else ' +prop?' if fr.get('tried') else ''
print('%-28s %-10s %8d %7d %-17s %-12s %9s %-13s %7s %6.3f %6.3f %9s %6.3f %9s %8.2f %8.3f %8.2f %8.2f %8.2f %7.0f %-8s %8.2f' % (
    name, mode, r['tetrahedra'], h['hexahedra'], r['status'], r.get('failed_stage') or '-', defects, repair, cells,
    h['min_scaled_jacobian'], h['mean_scaled_jacobian'],
    '-' if hd is None else '%.2e' % hd, f['coverage'],
    '%d/%d' % (f['hex_feature_edges_with_prescribed_valence'], f['hex_feature_edges']),
    s['frame_field'], repair_s, s['map'], s['extraction'], s['smoothing'], peak, refine, s['total']))
PY
  done
done
