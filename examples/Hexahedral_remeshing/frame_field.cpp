// A smooth frame field aligned with the normals of a cylinder (tetrahedralized with TetGen), its
// matchings and its singularity graph: four valence-3 curves run along the axis.
#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/boundary_triangle_normals.h>
#include <CGAL/Hexahedral_remeshing/frame_field.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>

#include <iostream>

namespace HR = CGAL::Hexahedral_remeshing;

int main(int argc, char** argv)
{
  HR::Tetrahedral_mesh_3<> mesh;
  HR::IO::read_tetrahedral_mesh(argc > 1 ? argv[1] : "data/cylinder.off", mesh,
                                HR::parameters::maximum_tetrahedron_volume(0.004)); // TetGen size bound

  std::vector<Eigen::Matrix3d> frames; // one per tetrahedron, columns = the three axes
  const HR::Frame_field_result field =
    HR::compute_frame_field(mesh, HR::boundary_triangle_unit_normals(mesh), frames);
  std::cout << mesh.number_of_tetrahedra() << " tetrahedra, smoothness energy " << field.energy << " after "
            << field.smoothing_iterations << " L-BFGS iterations (" << field.seconds << " s)\n";

  const HR::Matchings matchings = HR::compute_matchings(mesh, frames);
  const HR::Singularity_graph graph = HR::compute_singularity_graph(mesh, frames, matchings);
  for(const HR::Singular_curve& c : graph.curves)
    std::cout << "valence-" << c.valence << " curve of " << c.edges.size() << " edges from z = "
              << mesh.point(c.vertices.front()).z() << " to z = " << mesh.point(c.vertices.back()).z() << "\n";

  return (graph.number_of_curves(3) == 4 && graph.valence5_edges == 0 && graph.improper_edges == 0) ? 0 : 1;
}
