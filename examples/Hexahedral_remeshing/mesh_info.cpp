// Reads a tetrahedral mesh, builds its exact topology and prints the boundary edges by exact
// dihedral class: an acute edge (class 0) breaks any normal-aligned frame field.
#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/boundary_dihedral_angles.h>

#include <array>
#include <iostream>

namespace HR = CGAL::Hexahedral_remeshing;

int main(int argc, char** argv)
{
  const std::string filename = argc > 1 ? argv[1] : "data/n13c_acute_line.vtk";
  HR::Tetrahedral_mesh_3<> mesh;
  try {
    HR::IO::read_tetrahedral_mesh(filename, mesh);
  } catch(const HR::Input_error& e) {
    std::cerr << e.what() << std::endl;
    return 1;
  }
  std::array<int, 5> histogram{{0, 0, 0, 0, 0}};
  for(auto e : mesh.boundary_edges()) ++histogram[HR::boundary_edge_dihedral_class(mesh, e)];

  std::cout << mesh.number_of_tetrahedra() << " tetrahedra, " << mesh.number_of_boundary_triangles()
            << " boundary triangles, " << mesh.boundary_edges().size() << " boundary edges\n";
  for(int k = 0; k < 5; ++k) std::cout << "class " << k << ": " << histogram[k] << " edges\n";
  return histogram[0] > 0 && filename.find("acute") == std::string::npos ? 1 : 0;
}
