# Sourced by remesh_table.sh and map_table.sh: the build's hexmesh, and the arguments
# [--timeout S] [--baseline-too] [--no-repair-too] [FILE or FOLDER...] parsed into limit, baseline, norepair and files (default: every model of
# ../shared/data). Sets root, build, hexmesh, limit, baseline, files.
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${BUILD_DIR:-$root/build}"
hexmesh="$build/examples/Hexahedral_remeshing/hexmesh"
baseline=0; norepair=0; limit=600; files=()
while [ $# -gt 0 ]; do
  case "$1" in
    --baseline-too) baseline=1 ;;
    --no-repair-too) norepair=1 ;;
    --timeout) limit="$2"; shift ;;
    *) if [ -d "$1" ]; then  # a folder: its meshes and CAD parts
         for f in "$1"/*.vtk "$1"/*.msh "$1"/*.mesh "$1"/*.step "$1"/*.stp "$1"/*.brep "$1"/*.off "$1"/*.stl; do
           [ -e "$f" ] && files+=("$f")
         done
       else
         files+=("$1")
       fi ;;
  esac
  shift
done
if [ ${#files[@]} -eq 0 ]; then
  for f in "$root"/../shared/data/hexme/*.vtk "$root"/../shared/data/mambo/*.vtk; do [ -e "$f" ] && files+=("$f"); done
fi
export OMP_WAIT_POLICY="${OMP_WAIT_POLICY:-PASSIVE}"
