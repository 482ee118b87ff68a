#!/usr/bin/env bash
# One row per model: the singular graph of the repaired, realigned field of `hexmesh frames` read from its
# frames alone (frames_alone_graph.py: closest matchings, holonomies; none of the package's code), next to
# the package's own check with the kept matchings: singular edges along their axis, jogs, improper edges,
# their sum (the edges that are not a quarter turn along the edge), dangling ends; the check's jogs and
# disagreeing faces; the realignment's broken ties.
#   benchmark/Hexahedral_remeshing/frames_alone_table.sh [--timeout S] [FILE...]
# Needs a build (scripts/build) and python3 with numpy; writes the frames under build/frames_alone_table/.
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/table_inputs.sh"
out="$build/frames_alone_table"
mkdir -p "$out"
printf '%-28s %7s %6s %5s %8s %17s %8s %11s %11s %11s\n' model tets along jogs improper not_quarter_along dangling check_jogs disagreeing broken_ties
for f in "${files[@]}"; do
  name=$(basename "$f"); name="${name%.*}"
  rm -f "$out/$name.vtk" "$out/$name.json"
  if ! timeout "$limit" "$hexmesh" frames "$f" --quiet --frames "$out/$name.vtk" --json "$out/$name.json" > /dev/null 2> "$out/$name.err"; then
    printf '%-28s failed: %s\n' "$name" "$(tail -1 "$out/$name.err")"
    continue
  fi
  python3 - "$out/$name.vtk" "$out/$name.json" "$name" "$(dirname "${BASH_SOURCE[0]}")" <<'PY'
import json, sys
vtk, report, name, here = sys.argv[1:]
sys.path.insert(0, here)
from frames_alone_graph import analyze
c, dangling = analyze(vtk)
r = json.load(open(report))
after = r.get('meshability', {}).get('final', {}) or {}
print('%-28s %7d %6d %5d %8d %17d %8d %11s %11s %11s' % (name, r['mesh']['tetrahedra'], c['along'], c['jog'], c['improper'],
      c['jog'] + c['improper'], dangling, after.get('jog', '-'), after.get('disagreeing_face', '-'),
      r['realignment'].get('broken_ties', '-')))
PY
done
