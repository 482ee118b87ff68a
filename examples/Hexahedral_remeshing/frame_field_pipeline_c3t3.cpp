// The whole frame-field pipeline on a mesh made by CGAL's Mesh_3: a cube with its 12 sharp edges
// protected as features, converted to the package's mesh model, then valences, constraints, frame
// field, singularity graph and realignment in one call. (The only Mesh_3 example: it compiles slowly.)
#include <CGAL/Hexahedral_remeshing/build_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/frame_field_pipeline.h>
#include <CGAL/Hexahedral_remeshing/tetrahedral_soup_from_c3t3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/make_mesh_3.h>

#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface> Domain;
typedef CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index> C3t3;
namespace HR = CGAL::Hexahedral_remeshing;
namespace p = CGAL::parameters;

int main(int argc, char** argv)
{
  Surface surface;
  if(!CGAL::IO::read_polygon_mesh(argc > 1 ? argv[1] : "data/cube.off", surface)) return 1;
  Domain domain(surface);
  domain.detect_features(); // the 12 edges of the cube become protected feature curves
  const CGAL::Mesh_criteria_3<Tr> criteria(p::edge_size = 0.2, p::facet_angle = 25, p::facet_size = 0.2,
                                           p::facet_distance = 0.05, p::cell_radius_edge_ratio = 3, p::cell_size = 0.2);
  const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, p::no_perturb(), p::no_exude());

  HR::Tetrahedral_soup_3<K::Point_3> soup; // cells, surface patches, feature curves and corners
  HR::tetrahedral_soup_from_c3t3(c3t3, soup);
  HR::Tetrahedral_mesh_3<> mesh;
  HR::build_tetrahedral_mesh(soup, mesh, HR::parameters::split_boundary_chords(true));

  const HR::Frame_field_pipeline_result r = HR::compute_frame_field_pipeline(mesh);
  std::cout << mesh.number_of_tetrahedra() << " tetrahedra, E(n) = " << r.constraints.initial_energy << " -> E(v) = "
            << r.constraints.final_energy << ", field energy " << r.frame_field.energy << ", "
            << r.singularities.curves.size() << " singular curves, boundary valences " << r.boundary_valences.matched
            << "/" << r.boundary_valences.total << ", alignment error " << r.realignment.alignment_error << ", "
            << r.seconds << " s\n";
  // A cube needs no singularity: every boundary edge gets its valence (1 on the cube edges, 2 elsewhere).
  return (r.boundary_valences.mismatched == 0 && r.singularities.curves.empty() &&
          r.realignment.alignment_error < 1e-9) ? 0 : 1;
}
