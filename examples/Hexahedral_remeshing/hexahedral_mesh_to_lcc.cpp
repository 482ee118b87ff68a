// Converts a hexahedral mesh into CGAL's own volume-mesh structure, a 3D linear cell complex, and
// prints its characteristics. Without argument, the mesh is an L-shaped block of 3 x 2 hexahedra
// built here; with one, it is read from a `.mesh` (MEDIT Hexahedra) or `.vtk` (cell type 12) file.
#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/IO/read_hexahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_to_lcc.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_validation.h>

#include <iostream>

namespace HR = CGAL::Hexahedral_remeshing;

int main(int argc, char** argv)
{
  HR::Hexahedral_mesh_3 hexes;
  if(argc > 1) {
    try {
      HR::IO::read_hexahedral_mesh(argv[1], hexes);
    } catch(const HR::Input_error& e) {
      std::cerr << e.what() << std::endl;
      return 1;
    }
  } else {
    // a 2 x 2 x 2 grid of unit cubes without the cells x >= 1, y >= 1: an L-block of 6 hexahedra
    auto id = [](int i, int j, int k) { return HR::Hexahedral_mesh_3::Index(i + 3 * (j + 3 * k)); };
    for(int k = 0; k <= 2; ++k)
      for(int j = 0; j <= 2; ++j)
        for(int i = 0; i <= 2; ++i)
          hexes.points.emplace_back(i, j, k);
    for(int k = 0; k < 2; ++k)
      for(int j = 0; j < 2; ++j)
        for(int i = 0; i < 2; ++i)
          if(i == 0 || j == 0)  // VTK order: bottom quad counter-clockwise seen from above, then the top
            hexes.hexahedra.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                                       id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
  }

  const HR::Hexahedral_mesh_check check = HR::check_hexahedral_mesh(hexes);
  std::cout << hexes.number_of_hexahedra() << " hexahedra, " << check.boundary_quads << " boundary quads, "
            << (check.valid ? "valid" : "NOT valid") << ", min scaled Jacobian " << check.min_scaled_jacobian << "\n";

  CGAL::Linear_cell_complex_for_combinatorial_map<3> lcc;
  HR::hexahedral_mesh_to_lcc(hexes, lcc);
  std::size_t free_facets = 0;
  for(auto d = lcc.one_dart_per_cell<2>().begin(); d != lcc.one_dart_per_cell<2>().end(); ++d)
    free_facets += lcc.is_free<3>(d);
  std::cout << "Linear cell complex: ";
  lcc.display_characteristics(std::cout);
  std::cout << ", valid=" << lcc.is_valid() << "\n3-free facets (boundary quads): " << free_facets << "\n";
  return lcc.is_valid() && lcc.one_dart_per_cell<3>().size() == hexes.number_of_hexahedra() &&
         free_facets == check.boundary_quads ? 0 : 1;
}
