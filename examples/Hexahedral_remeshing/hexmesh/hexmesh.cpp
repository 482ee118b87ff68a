// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// hexmesh: command-line front end of the Hexahedral_remeshing package.
#include "cli_common.h"
#include "command_info.h"
#include "command_constraints.h"
#include "command_frames.h"
#include "command_extract.h"
#include "command_parametrize.h"
#include "command_remesh.h"
#include "command_smooth.h"

#include <CGAL/Hexahedral_remeshing/exceptions.h>

#include <iostream>
#include <string>

namespace {

const char* usage =
  "usage: hexmesh COMMAND [OPTIONS]\n"
  "\n"
  "Commands:\n"
  "  info IN [--json FILE]     mesh statistics, boundary edges by exact dihedral class\n"
  "  constraints IN [--heuristic NAME] [--valences FILE] [--json FILE] [--vtk FILE]\n"
  "              [--refinements N] [--save-valences FILE]\n"
  "                            boundary edge valences and boundary direction constraints:\n"
  "                            NAME is low_angle (default), geometric, ambiguous or cap_two;\n"
  "                            FILE for --valences has lines 'a b k' (0-based input vertices of a\n"
  "                            boundary edge, prescribed valence 1..6), overriding the heuristic;\n"
  "                            --vtk writes the boundary triangles with n, v, E_i as cell data;\n"
  "                            --save-valences writes the chosen valences in the 'a b k' format.\n"
  "                            Warnings (one line per kind) for valence-0 edges and E_i >= pi/4.\n"
  "  frames IN [--heuristic NAME] [--valences FILE] [--baseline] [--no-realign] [--no-repair]\n"
  "         [--frames OUT.vtk] [--singularities OUT.vtk] [--json FILE] [--valences-out FILE]\n"
  "         [--cubecover PREFIX] [--no-chord-split] [--acute-edge-band R] [--field-initialization S]\n"
  "         [--threads N] [--quiet]\n"
  "                            the whole frame-field pipeline: valences (as for constraints),\n"
  "                            direction constraints, smooth frame field, matchings, singular\n"
  "                            curves, achieved boundary valences, realignment with the normals;\n"
  "                            prints a summary (stdout), progress of stages over 1 s (stderr).\n"
  "                            --baseline: field aligned with the normals, no valences/constraints;\n"
  "                            --no-realign: keep the field aligned with the constraints;\n"
  "                            the singularity graph is repaired by matching surgery (jogs,\n"
  "                            zigzags, improper edges, zippers, bad nodes), kept only if no worse;\n"
  "                            --no-repair: the field as the realignment leaves it (--repair: the\n"
  "                            repair on the baseline too); the local meshability check by reason\n"
  "                            is printed before and after, and in the JSON under meshability;\n"
  "                            --frames: tet mesh (VTK) with cell vectors frame_u, frame_v, frame_w;\n"
  "                            --singularities: singular edges as VTK lines (valence, curve, and\n"
  "                            the reason of the check: 0 improper, 1 jog; failing vertices too);\n"
  "                            --json: report (schema in the user manual);\n"
  "                            --valences-out: prescribed valences as 'a b k' (vertex indices of\n"
  "                            the --frames file, whose first vertices are the input's);\n"
  "                            --cubecover: PREFIX.mesh, PREFIX.fra, PREFIX.perm for CubeCover;\n"
  "                            --no-chord-split: keep interior edges joining two boundary vertices\n"
  "                            (split by default: acute features need it); --threads N: OpenMP\n"
  "                            threads; --quiet: no summary nor progress (warnings remain).\n"
  "                            --acute-edge-band R: frames fixed within R (model units) of the\n"
  "                            edges under 45 degrees of valence 1, which keeps singular curves\n"
  "                            off them (default 0 here; 0 disables it).\n"
  "                            --field-initialization S: the field the smoothing starts from,\n"
  "                            relaxation (default here) or propagation (each tetrahedron takes the\n"
  "                            frame of the nearest boundary one: untwists a torus's field).\n"
  "                            On a busy machine, OMP_WAIT_POLICY=PASSIVE (environment) avoids\n"
  "                            OpenMP threads spinning while they wait.\n"
  "  remesh IN --out OUT.{mesh,vtk,vtu,inp,msh} [--target-edge-length H | --hexahedra N]\n"
  "         [--heuristic NAME] [--valences FILE] [--baseline] [--no-repair] [--no-smoothing] [--frames F]\n"
  "         [--singularities F] [--json FILE] [--valences-out FILE] [--keep-partial] [--no-chord-split]\n"
  "         [--hexex F] [--no-tet-refinement] [--acute-edge-band R] [--greedy-rounding] [--relocate-singular-vertices]\n"
  "         [--no-continuation] [--field-initialization S] [--threads N] [--quiet]\n"
  "                            tetrahedra to hexahedra in one call: the frame-field pipeline (as\n"
  "                            for frames), the integer-grid map, the extraction, untangling and\n"
  "                            smoothing (unless --no-smoothing), the check. H: hex edge length in\n"
  "                            model units; N: approximate number of hexahedra. Prints hexahedra,\n"
  "                            scaled Jacobian, irregular edges, hex edges on sharp edges with the\n"
  "                            prescribed valence, feature coverage, Hausdorff distance, seconds.\n"
  "                            --baseline: the classic normal-aligned field (the paper's\n"
  "                            comparison). --valences-out: the prescribed valences as 'a b k' (edit\n"
  "                            and give back with --valences). --hexex: the integer-grid map the\n"
  "                            hexahedra come from (as parametrize writes it). --acute-edge-band:\n"
  "                            as for frames, default two hex edge lengths. Where the greedy\n"
  "                            rounding of the map folds, an integer program (COIN-OR Cbc) keeps\n"
  "                            apart the planes and lines it collapsed (a thin wall, two close\n"
  "                            curves); --greedy-rounding: the rounding alone.\n"
  "                            --relocate-singular-vertices: the map on tetrahedra whose singular\n"
  "                            curves' interior vertices moved towards their axes (experimental).\n"
  "                            Where the rounded map folds and the seamless map does not, the\n"
  "                            seamless map is moved to the integer values without ever folding\n"
  "                            (the untangling of folds can wrap the map around an edge);\n"
  "                            --no-continuation: the untangling of the folds only.\n"
  "                            If the hex mesh is not valid (or empty) the command\n"
  "                            exits 4 with the stage it failed at (frame_field: not meshable;\n"
  "                            seamless_map; rounding; extraction; smoothing; check) and the\n"
  "                            reason, and writes no hex mesh, unless --keep-partial.\n"
  "                            A surface or CAD input is tetrahedralized at the hex size unless\n"
  "                            --max-volume or --mesh-size is given. A tet mesh with fewer than 12\n"
  "                            tetrahedra per hexahedron that gives no valid hex mesh is refined\n"
  "                            1-to-8 (once or twice, the boundary kept) and remeshed again; that\n"
  "                            mesh is kept if valid (not with --no-tet-refinement or --valences).\n"
  "                            If still not valid, all this runs again with the field smoothed\n"
  "                            from the propagation, kept if valid (not with --field-initialization).\n"  "                            A part whose walls are thinner than half the hex edge (over half of\n"
  "                            its surface) is refused (exit 3) with the thickness and a size that fits.\n"
  "  parametrize IN --hexex OUT.hexex [--vtk OUT.vtk] [--json FILE] [--valences-out FILE]\n"
  "         [--target-edge-length H] [--heuristic NAME] [--valences FILE] [--baseline] [--no-repair]\n"
  "         [--no-chord-split] [--acute-edge-band R] [--greedy-rounding] [--relocate-singular-vertices]\n"
  "         [--no-continuation] [--field-initialization S] [--keep-partial] [--seamless-hexex F]\n"
  "         [--threads N] [--quiet]\n"
  "                            the frame-field pipeline (as for remesh, with its band along\n"
  "                            acute edges: the map is the one remesh extracts), then the seamless\n"
  "                            integer-grid map (cut, integer constraints, greedy rounding and the\n"
  "                            separation program where it folds, untangling): --hexex writes it in libHexEx's format (input of\n"
  "                            extract), --vtk as exploded tetrahedra with point data uvw;\n"
  "                            --seamless-hexex: the seamless map before any rounding, in the same\n"
  "                            format on the same mesh (not integer: for inspection and checks);\n"
  "                            H is the hex edge length in model units (default: about 2000\n"
  "                            hexahedra). Prints the map status, inverted/degenerate\n"
  "                            tetrahedra, edge valences of the map and seconds per step. A map\n"
  "                            with inverted tetrahedra exits 4 and is written only with\n"
  "                            --keep-partial (flat tetrahedra of collapsed jogs are accepted, and\n"
  "                            branched edges, every tetrahedron positive but angle sums not 3, 4\n"
  "                            or 5 quarter turns, with a warning).\n"
  "  extract IN.hexex --out OUT.{mesh,vtk,vtu,inp,msh} [--json FILE] [--quiet]\n"
  "                            hexahedra of an integer-grid map (libHexEx's .hexex: vertices, then\n"
  "                            tets with the parameters of their corners in their own chart): reads,\n"
  "                            extracts (HexEx-style), checks (conformity, scaled Jacobian, irregular\n"
  "                            edges) and writes the hex mesh (.mesh for HexaLab/gmsh, .vtk for\n"
  "                            ParaView). A map that is not integer-grid (jumps not in the 24\n"
  "                            rotations with integer shifts, boundary off the integer planes) is\n"
  "                            refused (exit 3); cells a broken map cannot complete are left out.\n"
  "  smooth IN_HEX --reference TETS_OR_SURFACE --out OUT.{mesh,vtk,vtu,inp,msh} [--json FILE]\n"
  "         [--iterations N] [--quiet]\n"
  "                            untangles and smooths a hex mesh (.mesh or .vtk) against the boundary\n"
  "                            of a tet mesh or a closed surface: boundary vertices stay on it,\n"
  "                            feature vertices on their curve (sharp edges found by dihedral angle\n"
  "                            when the reference has none), corners fixed; the minimum scaled\n"
  "                            Jacobian never decreases. N: maximum number of sweeps (default 10).\n"
  "                            Prints the quality before/after (min, mean SJ, share below 0.3,\n"
  "                            SJ <= 0, Hausdorff distance) and the seconds.\n"
  "\n"
  "Inputs: .vtk (VTK legacy unstructured grid, ASCII or binary, 5.1 too), .mesh (MEDIT),\n"
  "        .msh (gmsh 4.1 / 2.2), .step .stp .brep .iges .igs (CAD parts, meshed with gmsh),\n"
  "        .off .obj .stl .ply (closed surfaces, repaired and checked, tetrahedralized with TetGen).\n"
  "Options of every command reading a tetrahedral mesh or a surface:\n"
  "  --max-volume V            surfaces: TetGen bound on the tetrahedron volume (> 0)\n"
  "  --radius-edge R           surfaces: TetGen quality bound (default 2, at least 1; 0 disables)\n"
  "  --mesh-size H             CAD parts: gmsh element size (default from the part's size)\n"
  "  --no-tet-refinement       tet meshes (remesh): no second run on the 1-to-8 refinement of a\n"
  "                            mesh coarser than the hexahedra that gave no valid hex mesh\n"
  "  --no-acute-grading        CAD parts (frames, parametrize, remesh): no grading of the\n"
  "                            tetrahedra towards edges under 45 degrees (graded by default:\n"
  "                            mesh size / 7 on them, growing as tan(angle) x distance)\n"
  "  --coincident-vertices P   refuse (default), merge or keep distinct vertices at one position\n"
  "  --time-limit S            stop gmsh or TetGen after S seconds with an error (default 900; 0: none)\n"
  "\n"
  "Hex mesh outputs, by extension: .mesh (MEDIT: HexaLab, gmsh), .vtk and .vtu (ParaView),\n"
  "        .inp (Abaqus, CalculiX: C3D8, one *SURFACE and *NSET per boundary patch), .msh (gmsh 4.1:\n"
  "        one physical surface per boundary patch, feature curves as lines). Boundary patches are the\n"
  "        CAD faces (or the input's patches, else the regions between sharp edges). --out may be\n"
  "        repeated to write the same hex mesh in several formats.\n"
  "\n"
  "Exit codes: 0 success, 2 usage error, 3 invalid or unreadable input,\n"
  "            4 a stage failed, 5 an output file cannot be written.\n";

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2) { std::cerr << usage; return hexmesh::EXIT_USAGE; }
  const std::string command = argv[1];
  if(command == "--help" || command == "-h" || command == "help") { std::cout << usage; return hexmesh::EXIT_OK; }
  try {
    if(command == "info") {
      std::vector<std::string> options = hexmesh::input_options();
      options.push_back("json");
      return hexmesh::command_info(hexmesh::Arguments(argc, argv, 2, options, {}));
    }
    if(command == "constraints")
      return hexmesh::command_constraints(hexmesh::Arguments(argc, argv, 2, hexmesh::constraints_options(), {}));
    if(command == "frames")
      return hexmesh::command_frames(
        hexmesh::Arguments(argc, argv, 2, hexmesh::frames_options(), hexmesh::frames_flags()));
    if(command == "remesh")
      return hexmesh::command_remesh(hexmesh::Arguments(argc, argv, 2, hexmesh::remesh_options(), hexmesh::remesh_flags()));
    if(command == "parametrize")
      return hexmesh::command_parametrize(
        hexmesh::Arguments(argc, argv, 2, hexmesh::parametrize_options(), hexmesh::parametrize_flags()));
    if(command == "extract")
      return hexmesh::command_extract(
        hexmesh::Arguments(argc, argv, 2, hexmesh::extract_options(), hexmesh::extract_flags()));
    if(command == "smooth")
      return hexmesh::command_smooth(hexmesh::Arguments(argc, argv, 2, hexmesh::smooth_options(), hexmesh::smooth_flags()));
    throw hexmesh::Usage_error("unknown command '" + command + "'");
  } catch(const hexmesh::Usage_error& e) {
    std::cerr << "hexmesh: " << e.what() << " (see hexmesh --help)\n";
    return hexmesh::EXIT_USAGE;
  } catch(const hexmesh::Stage_error& e) {
    std::cerr << "hexmesh: " << e.what() << "\n";
    return hexmesh::EXIT_FAILURE_STAGE;
  } catch(const CGAL::Hexahedral_remeshing::Input_error& e) {
    std::cerr << "hexmesh: " << e.what() << "\n";
    return hexmesh::EXIT_INPUT;
  } catch(const CGAL::Hexahedral_remeshing::Error& e) {
    std::cerr << "hexmesh: " << e.what() << "\n";
    return hexmesh::EXIT_OUTPUT;
  } catch(const std::exception& e) {
    std::cerr << "hexmesh: " << command << " failed: " << e.what() << "\n";
    return hexmesh::EXIT_FAILURE_STAGE;
  }
}
