// From CGAL's Mesh_3 to CGAL's Linear_cell_complex in one call: a cube meshed with tetrahedra (its
// 12 sharp edges protected), remeshed with hexahedra of edge 1/4 by CGAL::hexahedral_remeshing().
#include <CGAL/hexahedral_remeshing.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_mesh_3.h>

#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface> Domain;
typedef CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index> C3t3;
namespace p = CGAL::parameters;

int main(int argc, char** argv)
{
  Surface surface;
  if(!CGAL::IO::read_polygon_mesh(argc > 1 ? argv[1] : "data/cube.off", surface)) return 1;
  Domain domain(surface);
  domain.detect_features();
  const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, CGAL::Mesh_criteria_3<Tr>(p::edge_size = 0.15, p::facet_size = 0.15,
                                            p::facet_distance = 0.05, p::cell_radius_edge_ratio = 3, p::cell_size = 0.15),
                                            p::no_perturb(), p::no_exude());

  CGAL::Linear_cell_complex_for_combinatorial_map<3> lcc;
  const auto r = CGAL::hexahedral_remeshing(c3t3, lcc, CGAL::Hexahedral_remeshing::parameters::target_edge_length(0.25));
  std::cout << "status " << CGAL::Hexahedral_remeshing::status_name(r.status) << ", " << lcc.one_dart_per_cell<3>().size()
            << " hexahedra, min scaled Jacobian " << r.check.min_scaled_jacobian << ", " << r.seconds << " s\n";
  lcc.display_characteristics(std::cout) << ", valid=" << lcc.is_valid() << "\n";
  return r.status == CGAL::Hexahedral_remeshing::Hexahedral_remeshing_status::OK ? 0 : 1;
}
