// Stages 1 and 2 of the method of Desobry et al. on a part with a 10-degree edge: choose the valence
// of every boundary edge (heuristic "low angle": edges below 45 degrees get valence 1 instead of 0),
// then compute the boundary direction constraints v that a frame field must follow to produce them.
#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/boundary_direction_constraints.h>
#include <CGAL/Hexahedral_remeshing/boundary_edge_valences.h>

#include <iostream>

namespace HR = CGAL::Hexahedral_remeshing;

int main(int argc, char** argv)
{
  HR::Tetrahedral_mesh_3<> mesh;
  HR::IO::read_tetrahedral_mesh(argc > 1 ? argv[1] : "data/n13c_acute_line.vtk", mesh);

  std::vector<int> valences; // per edge: k on the boundary, -1 inside
  const HR::Boundary_edge_valences_statistics stats = HR::compute_boundary_edge_valences(
    mesh, valences, HR::parameters::valence_heuristic(HR::Valence_heuristic::LOW_ANGLE));
  for(int k = 0; k <= HR::maximum_prescribed_valence; ++k)
    if(stats.histogram[k] > 0) std::cout << stats.histogram[k] << " boundary edges of valence " << k << "\n";

  std::vector<Eigen::Vector3d> directions; // per boundary triangle
  const HR::Boundary_direction_constraints_result r =
    HR::compute_boundary_direction_constraints(mesh, valences, directions);
  std::cout << "deviation from the valences: E(n) = " << r.initial_energy << " rad with the normals, E(v) = "
            << r.final_energy << " rad with the constraints, " << r.failed_faces.size() << " failed triangles\n";

  // A field aligned with v realizes the valences when E(v) < pi/4; with the normals it cannot (E(n) > pi/4).
  return (stats.histogram[0] == 0 && r.final_energy < CGAL_PI / 4 && r.initial_energy > CGAL_PI / 4) ? 0 : 1;
}
