// User-prescribed valences on a feature curve (Desobry et al., Sec. 5.3): on the part with a
// 10-degree edge, prescribe valence 1 on the feature curve of that edge and let the geometric
// heuristic decide everywhere else; run the whole frame-field pipeline and check the result.
#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/boundary_dihedral_angles.h>
#include <CGAL/Hexahedral_remeshing/frame_field_pipeline.h>

#include <iostream>
#include <map>

namespace HR = CGAL::Hexahedral_remeshing;
namespace HP = CGAL::Hexahedral_remeshing::parameters;

int main(int argc, char** argv)
{
  HR::Tetrahedral_mesh_3<> mesh; // split the interior edges joining two boundary vertices: acute wedges need it
  HR::IO::read_tetrahedral_mesh(argc > 1 ? argv[1] : "data/n13c_acute_line.vtk", mesh, HP::split_boundary_chords(true));

  int acute_curve = -1; // the feature curve (gmsh line entity) of the edges below 45 degrees
  for(auto e : mesh.boundary_edges())
    if(HR::boundary_edge_dihedral_class(mesh, e) == 0) acute_curve = mesh.edge_curve(e);
  if(acute_curve < 0) { std::cerr << "no feature curve below 45 degrees\n"; return 1; }

  const std::map<int, int> curve_valences{{acute_curve, 1}}; // curve id -> k
  const HR::Frame_field_pipeline_result r = HR::compute_frame_field_pipeline(
    mesh, HP::valence_heuristic(HR::Valence_heuristic::GEOMETRIC, HP::prescribed_curve_valences(curve_valences)));

  bool ok = r.valence_statistics.prescribed_edges > 0 && r.boundary_valences.mismatched == 0;
  for(auto e : mesh.boundary_edges())
    if(mesh.edge_curve(e) == acute_curve) {
      std::cout << "edge " << mesh.edge_vertices(e)[0] << "-" << mesh.edge_vertices(e)[1] << " of curve " << acute_curve
                << ": prescribed " << r.valences[e] << ", achieved " << r.boundary_valences.achieved[e] << "\n";
      ok = ok && r.boundary_valences.achieved[e] == 1;
    }
  std::cout << r.boundary_valences.matched << "/" << r.boundary_valences.total << " boundary edges as prescribed, E(v) = "
            << r.constraints.final_energy << " rad\n";
  return ok ? 0 : 1;
}
