// C3t3 input: mesh the shipped cube with CGAL Mesh_3 with sharp features, convert the complex with
// tetrahedral_soup_from_c3t3() and build the Tetrahedral_mesh_3 from it.
// This is the only Mesh_3 translation unit of the tests (it compiles slowly): keep it that way.
#include "data_paths.h"
#include <CGAL/Hexahedral_remeshing/boundary_dihedral_angles.h>
#include <CGAL/Hexahedral_remeshing/build_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/tetrahedral_soup_from_c3t3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/make_mesh_3.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <set>
#include <string>

namespace HR = CGAL::Hexahedral_remeshing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface> Domain;
typedef CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index> C3t3;
typedef CGAL::Mesh_criteria_3<Tr> Criteria;
typedef HR::Tetrahedral_mesh_3<> Mesh;
typedef Mesh::Index Index;
typedef Mesh::Point_3 Point;

namespace {

// Meshes the unit cube once (sequential, no perturbation or exudation: deterministic and fast).
const C3t3& cube_c3t3()
{
  static const C3t3 c3t3 = [] {
    Surface surface;
    const std::string file = std::string(HEXREM_EXAMPLE_DATA_DIR) + "/cube.off";
    if(!CGAL::IO::read_polygon_mesh(file, surface) || surface.is_empty())
      throw std::runtime_error("cannot read " + file);
    Domain domain(surface);
    domain.detect_features(); // sharp edges at 60 degrees: the 12 edges of the cube
    namespace p = CGAL::parameters;
    const Criteria criteria(p::edge_size = 0.35, p::facet_angle = 25, p::facet_size = 0.35,
                            p::facet_distance = 0.05, p::cell_radius_edge_ratio = 3, p::cell_size = 0.35);
    return CGAL::make_mesh_3<C3t3>(domain, criteria, p::no_perturb(), p::no_exude());
  }();
  return c3t3;
}

Mesh cube_mesh(bool split)
{
  HR::Tetrahedral_soup_3<Point> soup;
  HR::tetrahedral_soup_from_c3t3(cube_c3t3(), soup);
  Mesh mesh;
  HR::build_tetrahedral_mesh(soup, mesh, HR::parameters::split_multi_boundary_tetrahedra(split));
  return mesh;
}

double volume(const Mesh& m)
{
  double v = 0;
  for(Index t = 0; t < m.number_of_tetrahedra(); ++t) {
    const auto& tv = m.tetrahedron_vertices(t);
    v += CGAL::to_double(CGAL::volume(m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3])));
  }
  return v;
}

} // namespace

TEST(C3t3, SoupCarriesCellsPatchesCurvesCorners)
{
  const C3t3& c3t3 = cube_c3t3();
  ASSERT_GT(c3t3.number_of_cells_in_complex(), 0u);
  std::cout << "cube C3t3: " << c3t3.triangulation().number_of_vertices() << " vertices, "
            << c3t3.number_of_cells_in_complex() << " cells, " << c3t3.number_of_facets_in_complex()
            << " facets, " << c3t3.number_of_edges_in_complex() << " feature edges, "
            << c3t3.number_of_vertices_in_complex() << " corners\n";
  HR::Tetrahedral_soup_3<Point> soup;
  HR::tetrahedral_soup_from_c3t3(c3t3, soup);
  EXPECT_EQ(soup.source, "<C3t3>");
  EXPECT_EQ(soup.tetrahedra.size(), c3t3.number_of_cells_in_complex());
  EXPECT_EQ(soup.triangles.size(), c3t3.number_of_facets_in_complex());
  EXPECT_EQ(soup.triangle_patches.size(), soup.triangles.size());
  EXPECT_EQ(soup.feature_edges.size(), c3t3.number_of_edges_in_complex());
  EXPECT_EQ(soup.feature_edge_curves.size(), soup.feature_edges.size());
  EXPECT_EQ(soup.corners.size(), 8u);
  EXPECT_EQ(std::set<int>(soup.triangle_patches.begin(), soup.triangle_patches.end()).size(), 6u);
  EXPECT_EQ(std::set<int>(soup.feature_edge_curves.begin(), soup.feature_edge_curves.end()).size(), 12u);
  // every vertex of the soup is a vertex of a tetrahedron (the hints add no isolated vertex)
  std::set<std::size_t> used;
  for(const auto& t : soup.tetrahedra) used.insert(t.begin(), t.end());
  EXPECT_EQ(used.size(), soup.points.size());
  // the corners are the 8 corners of the cube
  for(std::size_t c : soup.corners) {
    const Point& p = soup.points[c];
    for(int i = 0; i < 3; ++i) EXPECT_TRUE(p[i] == 0 || p[i] == 1) << p;
  }
  // an explicit source name is kept
  HR::Tetrahedral_soup_3<Point> named;
  named.source = "cube complex";
  HR::tetrahedral_soup_from_c3t3(c3t3, named);
  EXPECT_EQ(named.source, "cube complex");
  EXPECT_EQ(named.points.size(), soup.points.size());
}

TEST(C3t3, CubeFeaturesAndTopology)
{
  for(bool split : {true, false}) {
    SCOPED_TRACE(split ? "split" : "no split");
    const Mesh m = cube_mesh(split);
    EXPECT_EQ(m.number_of_feature_curves(), 12u);
    EXPECT_EQ(m.corners().size(), 8u);
    EXPECT_EQ(m.number_of_surface_patches(), 6u);
    EXPECT_EQ(m.number_of_components(), 1u);
    EXPECT_EQ(m.number_of_boundary_components(), 1u);
    EXPECT_EQ(m.boundary_euler_characteristic(), 2);
    EXPECT_NEAR(volume(m), 1.0, 1e-9);
    EXPECT_EQ(3 * m.number_of_boundary_triangles(), 2 * m.boundary_edges().size());
    // every boundary triangle lies on a face of the cube and carries a patch
    for(Index b = 0; b < m.number_of_boundary_triangles(); ++b) EXPECT_GE(m.boundary_triangle_patch(b), 0);

    // feature edges are exactly the boundary edges of exact dihedral class 1 (the cube's edges,
    // 90 degrees); every other boundary edge is flat (class 2)
    std::size_t feature = 0, class1 = 0;
    for(Index e = 0; e < m.number_of_edges(); ++e) {
      if(m.edge_curve(e) >= 0) {
        ++feature;
        ASSERT_TRUE(m.is_boundary_edge(e)) << "feature edge " << e << " is interior";
      }
      if(!m.is_boundary_edge(e)) continue;
      const int k = HR::boundary_edge_dihedral_class(m, e);
      EXPECT_TRUE(k == 1 || k == 2) << "edge " << e << " class " << k;
      class1 += (k == 1);
      EXPECT_EQ(k == 1, m.edge_curve(e) >= 0) << "edge " << e << " class " << k << " curve " << m.edge_curve(e);
    }
    EXPECT_EQ(feature, m.number_of_feature_edges());
    EXPECT_EQ(feature, class1);
    EXPECT_GE(feature, 12u);
    // the corners are boundary vertices where three feature curves meet
    for(Index c : m.corners()) {
      ASSERT_TRUE(m.is_boundary_vertex(c));
      std::set<int> curves;
      for(Index e : m.vertex_edges(c)) if(m.edge_curve(e) >= 0) curves.insert(m.edge_curve(e));
      EXPECT_EQ(curves.size(), 3u) << "corner " << c;
    }
  }
}

TEST(C3t3, EmptyComplexIsAnInputError)
{
  const C3t3 empty;
  HR::Tetrahedral_soup_3<Point> soup;
  try {
    HR::tetrahedral_soup_from_c3t3(empty, soup);
    ADD_FAILURE() << "no error";
  } catch(const HR::Input_error& e) {
    EXPECT_EQ(std::string(e.what()), "<C3t3>: the complex has no cells");
  }
}
