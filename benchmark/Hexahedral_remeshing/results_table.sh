#!/usr/bin/env bash
# The results table of the user manual, generated: `hexmesh remesh MODEL` with the default options on a list of
# models, one row per model (model, tetrahedra, status, hexahedra, min and mean scaled Jacobian, failed stage),
# written as a doxygen (1.9) markdown table.
#
#   benchmark/Hexahedral_remeshing/results_table.sh [--timeout S] [--table FILE] [--manual FILE] [--no-manual]
#                                                   [--keep DIR] [FILE...]
#
# Without FILE: the shipped models (examples/Hexahedral_remeshing/data: cube.off, cylinder.off,
# n13c_acute_wedge.brep), the HexMe "s" models and a few "n" ones of ../shared/data/hexme (those present);
# the table goes into doc/Hexahedral_remeshing/fig/results_table.md and, between the lines
# <!-- results-table-begin --> and <!-- results-table-end --> of the user manual
# (doc/Hexahedral_remeshing/Hexahedral_remeshing.txt), in place of what was there (section HexRemResults).
# With FILE...: those models; the table is printed on stdout, and written only where --table / --manual say.
#
#   --timeout S    seconds per model (default 300); a model that takes longer gets the row "timeout"
#   --table FILE   write the table (markdown) into FILE
#   --manual FILE  replace the lines between the two markers of FILE with the table
#   --no-manual    leave the user manual alone (default list only)
#   --keep DIR     keep the JSON reports, hex meshes and error output of every run in DIR (default: a
#                  temporary directory, removed at the end)
#   HEXMESH=PATH   the hexmesh program (default: build/examples/Hexahedral_remeshing/hexmesh, made by scripts/build)
#   PYTHON=PATH    a Python 3 (default: python3); only its standard library is used
#
# Progress goes to stderr, one line per model. A model whose remeshing fails is a row of the table, not an
# error. Exit status: 0 table written, 2 missing tool, unknown option or missing model file, 3 the manual has
# no markers (the table file is written all the same).
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
hexmesh="${HEXMESH:-$root/build/examples/Hexahedral_remeshing/hexmesh}"
python="${PYTHON:-python3}"
data="$root/examples/Hexahedral_remeshing/data"
hexme="$root/../shared/data/hexme"
limit=300; table=""; manual=""; no_manual=0; keep=""; files=()
while [ $# -gt 0 ]; do
  case "$1" in
    --timeout) limit="${2:-}"; shift ;;
    --table) table="${2:-}"; shift ;;
    --manual) manual="${2:-}"; shift ;;
    --no-manual) no_manual=1 ;;
    --keep) keep="${2:-}"; shift ;;
    -*) echo "results_table.sh: unknown option $1" >&2; exit 2 ;;
    *) files+=("$1") ;;
  esac
  shift
done
case "$limit" in ''|*[!0-9]*|0) echo "results_table.sh: --timeout needs a positive number of seconds" >&2; exit 2 ;; esac
if [ ! -x "$hexmesh" ]; then
  echo "results_table.sh: $hexmesh not found: build it with scripts/build (or set HEXMESH)" >&2
  exit 2
fi
if ! command -v "$python" > /dev/null 2>&1; then
  echo "results_table.sh: needs python3 (or set PYTHON)" >&2
  exit 2
fi
if ! command -v timeout > /dev/null 2>&1; then
  echo "results_table.sh: needs timeout (GNU coreutils)" >&2
  exit 2
fi

if [ ${#files[@]} -eq 0 ]; then
  for f in "$data/cube.off" "$data/cylinder.off" "$data/n13c_acute_wedge.brep"; do
    [ -e "$f" ] && files+=("$f")
  done
  for f in "$hexme"/s[0-9][0-9]c_*.vtk "$hexme"/n01c_*.vtk "$hexme"/n04c_*.vtk "$hexme"/n09c_*.vtk \
           "$hexme"/n13c_*.vtk "$hexme"/n14c_*.vtk; do
    [ -e "$f" ] && files+=("$f")
  done
  [ -n "$table" ] || table="$root/doc/Hexahedral_remeshing/fig/results_table.md"
  [ -n "$manual" ] || [ "$no_manual" -eq 1 ] || manual="$root/doc/Hexahedral_remeshing/Hexahedral_remeshing.txt"
fi
for f in "${files[@]}"; do
  if [ ! -f "$f" ]; then echo "results_table.sh: no model file $f" >&2; exit 2; fi
done
if [ -n "$manual" ] && [ ! -f "$manual" ]; then echo "results_table.sh: no manual $manual" >&2; exit 2; fi

if [ -n "$keep" ]; then
  work="$keep"
  mkdir -p "$work"
else
  work="$(mktemp -d)"
  trap 'rm -rf "$work"' EXIT
fi
# OpenMP threads spinning while they wait make a busy 2-core machine crawl (see scripts/run).
export OMP_WAIT_POLICY="${OMP_WAIT_POLICY:-PASSIVE}"

# One run per model: its JSON report (if any), exit code and error output; the list of runs for the table.
list="$work/runs.txt"
: > "$list"
for f in "${files[@]}"; do
  name="$(basename "$f")"
  stem="$work/${name%.*}"
  rm -f "$stem.json" "$stem.mesh"
  start=$SECONDS
  timeout --kill-after=10 "$limit" "$hexmesh" remesh "$f" --out "$stem.mesh" --json "$stem.json" --quiet \
    > /dev/null 2> "$stem.err"
  rc=$?
  echo "results_table.sh: $name: exit $rc, $((SECONDS - start)) s" >&2
  printf '%s\t%s\t%s\n' "$name" "$stem" "$rc" >> "$list"
done

"$python" - "$list" "$limit" "${table:--}" "${manual:-}" << 'PYTHON'
import json, math, os, shutil, sys, textwrap
runs, limit, table_file, manual = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]

def cell(text):
    return str(text).replace("|", "\\|").replace("\n", " ")

def number(x, digits=3):
    return "%.*f" % (digits, x) if isinstance(x, (int, float)) and math.isfinite(x) else "-"

rows = []
for line in open(runs):
    name, stem, rc = line.rstrip("\n").split("\t")
    rc = int(rc)
    row = ["`%s`" % name, "-", "-", "-", "-", "-", "-"]
    if os.path.exists(stem + ".json"):
        r = json.load(open(stem + ".json"))
        hm = r.get("hex_mesh", {})
        hexes = hm.get("hexahedra", 0) or 0
        row[1] = str(r.get("tetrahedra", "-"))
        row[2] = "`%s`" % r.get("status", "?")
        row[3] = str(hexes)
        if hexes > 0:
            row[4], row[5] = number(hm.get("min_scaled_jacobian")), number(hm.get("mean_scaled_jacobian"))
        row[6] = cell(r.get("failed_stage") or "-")
    elif rc in (124, 137):
        row[2] = "timeout (%s s)" % limit
    else:
        err = [l.strip() for l in open(stem + ".err") if l.strip()] if os.path.exists(stem + ".err") else []
        row[2] = "exit %d" % rc
        row[6] = cell(err[-1][:90] if err else "no report")
    rows.append(row)

intro = ("Generated by `benchmark/Hexahedral_remeshing/results_table.sh`: `hexmesh remesh MODEL` with the default "
         "options (about 2000 hexahedra, smoothing on), at most %s seconds per model. The tetrahedra are those the "
         "pipeline works on (a surface or CAD part tetrahedralized at the hex size, boundary chords split); the scaled "
         "Jacobians are those of the hex mesh produced, valid or not; the failed stage is the JSON report's "
         "`failed_stage` (\\ref\0HexRemOneCallStatus)." % limit)  # \0: no line break between \ref and its name
lines = [l.replace("\0", " ") for l in textwrap.wrap(intro, 115, break_on_hyphens=False, break_long_words=False)] + [
         "",
         "| model | tetrahedra | status | hexahedra | min scaled Jacobian | mean scaled Jacobian | failed stage |",
         "|---|--:|---|--:|--:|--:|---|"]
lines += ["| " + " | ".join(row) + " |" for row in rows]
text = "\n".join(lines) + "\n"

if table_file == "-":
    sys.stdout.write(text)
else:
    os.makedirs(os.path.dirname(os.path.abspath(table_file)), exist_ok=True)
    with open(table_file + ".tmp", "w") as out:
        out.write(text)
    os.replace(table_file + ".tmp", table_file)
    print("results_table.sh: table written to %s" % table_file, file=sys.stderr)

if manual:
    BEGIN, END = "<!-- results-table-begin -->", "<!-- results-table-end -->"
    old = open(manual).read().split("\n")
    starts = [i for i, l in enumerate(old) if l.strip() == BEGIN]
    ends = [i for i, l in enumerate(old) if l.strip() == END]
    if len(starts) != 1 or len(ends) != 1 or ends[0] < starts[0]:
        print("results_table.sh: %s: expected one line %s followed by one line %s: the manual is left as it is"
              % (manual, BEGIN, END), file=sys.stderr)
        sys.exit(3)
    new = old[:starts[0] + 1] + text.rstrip("\n").split("\n") + old[ends[0]:]
    with open(manual + ".tmp", "w") as out:
        out.write("\n".join(new))
    shutil.copymode(manual, manual + ".tmp")
    os.replace(manual + ".tmp", manual)
    print("results_table.sh: table put into %s" % manual, file=sys.stderr)
PYTHON
