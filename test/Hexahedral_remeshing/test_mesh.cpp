// Tests of the foundation: readers, input validation, topology of Tetrahedral_mesh_3, exact
// dihedral classes, TetGen inputs.
#include "data_paths.h"
#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK.h>
#include <CGAL/Hexahedral_remeshing/boundary_dihedral_angles.h>
#include <CGAL/Hexahedral_remeshing/mesh_statistics.h>
#include <CGAL/Hexahedral_remeshing/refine_tetrahedral_mesh.h>

#include <gtest/gtest.h>

#include "shared_models.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace HR = CGAL::Hexahedral_remeshing;
typedef HR::Tetrahedral_mesh_3<> Mesh;
typedef Mesh::Index Index;
typedef Mesh::Point_3 Point;
typedef Mesh::Vector_3 Vector;
namespace fs = std::filesystem;

namespace {

const std::string test_data = HEXREM_TEST_DATA_DIR;
const std::string example_data = HEXREM_EXAMPLE_DATA_DIR;
const std::string shared_data = HEXREM_SHARED_DATA_DIR;


// Independent count of the points and of the type-10 cells of a VTK file (oracle for the reader).
std::pair<std::size_t, std::size_t> count_vtk(const std::string& filename)
{
  std::ifstream in(filename);
  std::string word;
  std::size_t points = 0, tets = 0;
  while(in >> word) {
    if(word == "POINTS") in >> points;
    if(word == "CELL_TYPES") {
      std::size_t n;
      in >> n;
      for(std::size_t i = 0; i < n; ++i) { int t; in >> t; tets += (t == 10); }
    }
  }
  return {points, tets};
}

double tet_volume(const Mesh& m, Index t)
{
  const auto& v = m.tetrahedron_vertices(t);
  return CGAL::to_double(CGAL::volume(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])));
}

Point centroid(const Mesh& m, Index t)
{
  const auto& v = m.tetrahedron_vertices(t);
  return CGAL::centroid(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]));
}

// Checks every topological invariant the later stages rely on; returns the boundary Euler characteristic.
void check_topology(const Mesh& m)
{
  // tetrahedra positively oriented; faces consistent
  for(Index t = 0; t < m.number_of_tetrahedra(); ++t) {
    const auto& v = m.tetrahedron_vertices(t);
    ASSERT_EQ(CGAL::orientation(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])), CGAL::POSITIVE);
    for(int i = 0; i < 4; ++i) {
      const Index f = m.tetrahedron_face(t, i);
      const auto& ft = m.face_tetrahedra(f);
      ASSERT_TRUE(ft[0] == t || ft[1] == t);
      for(Index fv : m.face_vertices(f)) ASSERT_NE(fv, v[i]); // face i is opposite vertex i
    }
  }
  // interior faces have two tetrahedra on opposite sides; face_vertices outward from the first
  for(Index f = 0; f < m.number_of_faces(); ++f) {
    const auto& fv = m.face_vertices(f);
    const auto& ft = m.face_tetrahedra(f);
    ASSERT_NE(ft[0], Mesh::null_index);
    ASSERT_EQ(CGAL::orientation(m.point(fv[0]), m.point(fv[1]), m.point(fv[2]), centroid(m, ft[0])), CGAL::NEGATIVE);
    if(ft[1] != Mesh::null_index) {
      ASSERT_EQ(CGAL::orientation(m.point(fv[0]), m.point(fv[1]), m.point(fv[2]), centroid(m, ft[1])), CGAL::POSITIVE);
      ASSERT_EQ(m.face_boundary_triangle(f), Mesh::null_index);
    } else {
      ASSERT_EQ(m.boundary_triangle_face(m.face_boundary_triangle(f)), f);
    }
  }
  // each tetrahedron carries at most one boundary face after the default preprocessing
  for(Index t = 0; t < m.number_of_tetrahedra(); ++t) {
    int nb = 0;
    for(int i = 0; i < 4; ++i) nb += m.is_boundary_face(m.tetrahedron_face(t, i));
    ASSERT_LE(nb, 1);
  }
  // boundary edges: exactly two boundary triangles, consistent opposite orientations
  std::size_t boundary_edges = 0;
  for(Index e = 0; e < m.number_of_edges(); ++e) {
    const auto& ev = m.edge_vertices(e);
    const auto ring = m.edge_ring(e);
    const auto faces = m.edge_ring_faces(e);
    ASSERT_GE(ring.size(), 1u);
    const Vector d = m.point(ev[1]) - m.point(ev[0]);
    for(std::size_t k = 0; k < ring.size(); ++k) {
      const auto& tv = m.tetrahedron_vertices(ring[k]);
      ASSERT_TRUE(std::count(tv.begin(), tv.end(), ev[0]) == 1 && std::count(tv.begin(), tv.end(), ev[1]) == 1);
    }
    if(m.is_boundary_edge(e)) {
      ++boundary_edges;
      ASSERT_EQ(faces.size(), ring.size() + 1);
      const auto& bt = m.edge_boundary_triangles(e);
      ASSERT_EQ(m.boundary_triangle_face(bt[0]), faces.front());
      ASSERT_EQ(m.boundary_triangle_face(bt[1]), faces.back());
      ASSERT_EQ(m.boundary_triangle_tetrahedron(bt[0]), ring.front());
      ASSERT_EQ(m.boundary_triangle_tetrahedron(bt[1]), ring.back());
      // the first triangle holds the half-edge v1 -> v0, the second v0 -> v1
      auto has_half_edge = [&](Index b, Index from, Index to) {
        const auto& v = m.boundary_triangle_vertices(b);
        for(int i = 0; i < 3; ++i) if(v[i] == from && v[(i + 1) % 3] == to) return true;
        return false;
      };
      ASSERT_TRUE(has_half_edge(bt[0], ev[1], ev[0]));
      ASSERT_TRUE(has_half_edge(bt[1], ev[0], ev[1]));
    } else {
      ASSERT_EQ(faces.size(), ring.size()); // closed ring
    }
    // face k separates ring tetrahedra k and k+1 (cyclically for interior edges)
    const std::size_t m_faces = m.is_boundary_edge(e) ? ring.size() - 1 : ring.size();
    const std::size_t shift = m.is_boundary_edge(e) ? 1 : 0;
    for(std::size_t k = 0; k < m_faces; ++k) {
      const auto& ft = m.face_tetrahedra(faces[k + shift]);
      const Index a = ring[k], b = ring[(k + 1) % ring.size()];
      ASSERT_TRUE((ft[0] == a && ft[1] == b) || (ft[0] == b && ft[1] == a));
      // counter-clockwise about d: rotating from tet k to tet k+1 is a positive turn about d
      // (checked on the two third vertices of the separating face and the next tetrahedron)
    }
    // counter-clockwise about d, checked geometrically: each ring tetrahedron spans the wedge from
    // the third vertex of its entry face to the third vertex of its exit face, which must be a
    // positive turn about d (exact orientation), and the wedges of a closed ring add up to 2 pi.
    auto third = [&](Index f) {
      for(Index v : m.face_vertices(f)) if(v != ev[0] && v != ev[1]) return v;
      return Mesh::null_index;
    };
    const Vector dn = d / std::sqrt(CGAL::to_double(d.squared_length()));
    double total = 0;
    for(std::size_t k = 0; k < ring.size(); ++k) {
      const Index entry = m.is_boundary_edge(e) ? faces[k] : faces[(k + ring.size() - 1) % ring.size()];
      const Index exit = m.is_boundary_edge(e) ? faces[k + 1] : faces[k];
      const Point& a = m.point(third(entry));
      const Point& b = m.point(third(exit));
      ASSERT_EQ(CGAL::orientation(m.point(ev[0]), m.point(ev[1]), a, b), CGAL::POSITIVE) << "edge " << e << " step " << k;
      const Vector ap = (a - m.point(ev[0])) - ((a - m.point(ev[0])) * dn) * dn;
      const Vector bp = (b - m.point(ev[0])) - ((b - m.point(ev[0])) * dn) * dn;
      total += std::atan2(CGAL::to_double(CGAL::cross_product(ap, bp) * dn), CGAL::to_double(ap * bp));
    }
    if(!m.is_boundary_edge(e)) ASSERT_NEAR(total, 2 * CGAL_PI, 1e-6) << "edge " << e;
    else ASSERT_NEAR(total, HR::boundary_edge_dihedral_angle(m, e), 1e-6) << "edge " << e;
  }
  ASSERT_EQ(boundary_edges, m.boundary_edges().size());
  // boundary triangles: edges and neighbours consistent
  for(Index b = 0; b < m.number_of_boundary_triangles(); ++b)
    for(int i = 0; i < 3; ++i) {
      const Index e = m.boundary_triangle_edge(b, i);
      const auto& v = m.boundary_triangle_vertices(b);
      const auto& ev = m.edge_vertices(e);
      ASSERT_TRUE(std::count(ev.begin(), ev.end(), v[(i + 1) % 3]) == 1 && std::count(ev.begin(), ev.end(), v[(i + 2) % 3]) == 1);
      const Index n = m.boundary_triangle_neighbor(b, i);
      ASSERT_NE(n, b);
      ASSERT_NE(n, Mesh::null_index);
    }
  // 3 F = 2 E on a closed surface
  ASSERT_EQ(3 * m.number_of_boundary_triangles(), 2 * m.boundary_edges().size());
  // outward orientation: the volume enclosed by the boundary triangles equals the tet volume
  double boundary_volume = 0, volume = 0;
  for(Index b = 0; b < m.number_of_boundary_triangles(); ++b) {
    const auto& v = m.boundary_triangle_vertices(b);
    const Vector p0 = m.point(v[0]) - CGAL::ORIGIN, p1 = m.point(v[1]) - CGAL::ORIGIN, p2 = m.point(v[2]) - CGAL::ORIGIN;
    boundary_volume += CGAL::to_double(p0 * CGAL::cross_product(p1, p2)) / 6.0;
  }
  for(Index t = 0; t < m.number_of_tetrahedra(); ++t) volume += tet_volume(m, t);
  ASSERT_GT(volume, 0);
  ASSERT_NEAR(boundary_volume, volume, 1e-9 * volume);
}

Mesh load(const std::string& file)
{
  Mesh m;
  HR::IO::read_tetrahedral_mesh(file, m);
  return m;
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Readers on valid inputs

TEST(Readers, SharedModelsMatchFileCounts)
{
  const auto files = shared_models();
  if(files.empty()) GTEST_SKIP() << "../shared/data not present";
  for(const std::string& f : files) {
    SCOPED_TRACE(f);
    HR::Tetrahedral_soup_3<Point> soup;
    HR::IO::read_tetrahedral_soup(f, soup);
    const auto counts = count_vtk(f);
    EXPECT_EQ(soup.points.size(), counts.first);
    EXPECT_EQ(soup.tetrahedra.size(), counts.second);
    Mesh m;
    HR::build_tetrahedral_mesh(soup, m, HR::parameters::split_multi_boundary_tetrahedra(false));
    EXPECT_EQ(m.number_of_tetrahedra(), counts.second);
    EXPECT_EQ(m.number_of_vertices(), counts.first);
  }
}

TEST(Readers, TwoTetsVtkMeditAndWindowsLineEnds)
{
  for(const std::string f : {"two_tets.vtk", "two_tets_crlf.vtk", "two_tets.mesh", "two_tets_crlf.mesh"}) {
    SCOPED_TRACE(f);
    const Mesh m = load(test_data + "/" + f);
    EXPECT_EQ(m.number_of_input_vertices(), 5u);
    // both tets have three boundary faces: each is split 1-to-4, 8 tets, 2 new vertices
    EXPECT_EQ(m.number_of_split_tetrahedra(), 2u);
    EXPECT_EQ(m.number_of_tetrahedra(), 8u);
    EXPECT_EQ(m.number_of_vertices(), 7u);
    EXPECT_EQ(m.number_of_boundary_triangles(), 6u);
    EXPECT_EQ(m.boundary_edges().size(), 9u);
    EXPECT_EQ(m.boundary_euler_characteristic(), 2);
    check_topology(m);
  }
  const Mesh medit = load(test_data + "/two_tets.mesh");
  EXPECT_EQ(medit.number_of_surface_patches(), 1u);
  EXPECT_EQ(medit.number_of_feature_curves(), 1u);
  EXPECT_EQ(medit.number_of_feature_edges(), 1u);
  ASSERT_EQ(medit.corners().size(), 1u);
  EXPECT_EQ(medit.corners()[0], 0u);
  EXPECT_EQ(medit.edge_curve(medit.find_edge(0, 1)), 5);
}

TEST(Readers, InvertedTetrahedraAreReoriented)
{
  const Mesh m = load(test_data + "/inverted.vtk");
  EXPECT_EQ(m.number_of_reoriented_tetrahedra(), 1u);
  check_topology(m);
}

TEST(Readers, SeveralComponentsAreAccepted)
{
  const Mesh m = load(test_data + "/two_components.vtk");
  EXPECT_EQ(m.number_of_components(), 2u);
  EXPECT_EQ(m.number_of_boundary_components(), 2u);
  EXPECT_EQ(m.boundary_euler_characteristic(), 4);
  check_topology(m);
}

TEST(Readers, NoSplitKeepsInputTetrahedra)
{
  Mesh m;
  HR::IO::read_tetrahedral_mesh(test_data + "/two_tets.vtk", m, HR::parameters::split_multi_boundary_tetrahedra(false));
  EXPECT_EQ(m.number_of_tetrahedra(), 2u);
  EXPECT_EQ(m.number_of_vertices(), 5u);
}

// ---------------------------------------------------------------------------------------------
// Red refinement (refine_tetrahedral_soup): the same solid, boundary and features on more tetrahedra

namespace {

// Volume (from the points, floating point) and exact orientation counts of a soup's tetrahedra.
struct Soup_volume { double volume = 0; std::size_t positive = 0, negative = 0; };
Soup_volume soup_volume(const HR::Tetrahedral_soup_3<Point>& soup)
{
  Soup_volume r;
  for(const auto& t : soup.tetrahedra) {
    const Point& a = soup.points[t[0]];
    const CGAL::Orientation o = CGAL::orientation(a, soup.points[t[1]], soup.points[t[2]], soup.points[t[3]]);
    (o == CGAL::POSITIVE ? r.positive : r.negative) += (o != CGAL::COPLANAR);
    r.volume += std::abs(CGAL::to_double(CGAL::determinant(soup.points[t[1]] - a, soup.points[t[2]] - a, soup.points[t[3]] - a))) / 6;
  }
  return r;
}

// Boundary area and the number of boundary edges of each exact dihedral class.
std::pair<double, std::map<int, std::size_t> > boundary_summary(const Mesh& m)
{
  double area = 0;
  for(Index b = 0; b < m.number_of_boundary_triangles(); ++b) {
    const auto& v = m.boundary_triangle_vertices(b);
    area += std::sqrt(CGAL::to_double(CGAL::cross_product(m.point(v[1]) - m.point(v[0]), m.point(v[2]) - m.point(v[0])).squared_length())) / 2;
  }
  std::map<int, std::size_t> classes;
  for(Index e : m.boundary_edges()) ++classes[HR::boundary_edge_dihedral_class(m, e)];
  return {area, classes};
}

} // namespace

TEST(Refinement, RedRefinementKeepsTheSolidItsBoundaryAndFeatures)
{
  // the shipped HexMe 10-degree wedge (0.3 tetrahedra per hexahedron at the default size)
  HR::Tetrahedral_soup_3<Point> input;
  HR::IO::read_tetrahedral_soup(example_data + "/n13c_acute_line.vtk", input);
  Mesh coarse;
  HR::build_tetrahedral_mesh(input, coarse, HR::parameters::split_multi_boundary_tetrahedra(false));
  ASSERT_GT(input.triangles.size(), 0u);
  const Soup_volume v0 = soup_volume(input);
  const auto b0 = boundary_summary(coarse);
  for(int rounds : {1, 2}) {
    HR::Tetrahedral_soup_3<Point> fine;
    HR::refine_tetrahedral_soup(input, fine, rounds);
    const std::size_t k = std::size_t(1) << (3 * rounds);  // 8^rounds
    EXPECT_EQ(fine.tetrahedra.size(), k * input.tetrahedra.size());
    EXPECT_EQ(fine.tetrahedron_lines.size(), fine.tetrahedra.size());
    EXPECT_EQ(fine.triangles.size(), (std::size_t(1) << (2 * rounds)) * input.triangles.size());
    EXPECT_EQ(fine.feature_edges.size(), (std::size_t(1) << rounds) * input.feature_edges.size());
    EXPECT_EQ(fine.corners, input.corners);
    for(std::size_t i = 0; i < input.points.size(); ++i) ASSERT_EQ(fine.points[i], input.points[i]) << i;
    // every child has the orientation of the input's tetrahedra (all positive in this file), the
    // volume is the same
    const Soup_volume v = soup_volume(fine);
    EXPECT_EQ(v.negative, k * v0.negative) << rounds;
    EXPECT_EQ(v.positive, k * v0.positive) << rounds;
    EXPECT_NEAR(v.volume, v0.volume, 1e-12 * v0.volume) << rounds;
    // a conforming mesh (the build throws on a face of three tetrahedra or overlapping ones) with
    // the boundary triangles split 1-to-4, the same boundary topology and area, and each feature
    // edge in 2^rounds edges of the same exact dihedral class (flat ones: more, inside the faces)
    Mesh m;
    ASSERT_NO_THROW(HR::build_tetrahedral_mesh(fine, m, HR::parameters::split_multi_boundary_tetrahedra(false)));
    EXPECT_EQ(m.number_of_tetrahedra(), fine.tetrahedra.size());
    EXPECT_EQ(m.number_of_boundary_triangles(), (std::size_t(1) << (2 * rounds)) * coarse.number_of_boundary_triangles());
    EXPECT_EQ(m.number_of_boundary_components(), coarse.number_of_boundary_components());
    EXPECT_EQ(m.boundary_euler_characteristic(), coarse.boundary_euler_characteristic());
    EXPECT_EQ(m.number_of_feature_curves(), coarse.number_of_feature_curves());
    EXPECT_EQ(m.number_of_surface_patches(), coarse.number_of_surface_patches());
    const auto b = boundary_summary(m);
    EXPECT_NEAR(b.first, b0.first, 1e-12 * b0.first);
    for(const auto& c : b0.second)
      if(c.first != 2) EXPECT_EQ(b.second.at(c.first), (std::size_t(1) << rounds) * c.second) << "class " << c.first;
  }
  HR::Tetrahedral_soup_3<Point> same;
  HR::refine_tetrahedral_soup(input, same, 0);
  EXPECT_EQ(same.tetrahedra, input.tetrahedra);
  EXPECT_THROW(HR::refine_tetrahedral_soup(input, same, 5), HR::Error);
  EXPECT_THROW(HR::refine_tetrahedral_soup(input, same, -1), HR::Error);
}

TEST(Refinement, SoupOfAMeshBuildsTheSameMesh)
{
  const Mesh m = load(example_data + "/n13c_acute_line.vtk");
  HR::Tetrahedral_soup_3<Point> soup;
  HR::tetrahedral_soup_from_mesh(m, soup);
  Mesh again;
  HR::build_tetrahedral_mesh(soup, again);
  EXPECT_EQ(again.number_of_tetrahedra(), m.number_of_tetrahedra());
  EXPECT_EQ(again.number_of_vertices(), m.number_of_vertices());
  EXPECT_EQ(again.number_of_boundary_triangles(), m.number_of_boundary_triangles());
  EXPECT_EQ(again.number_of_feature_edges(), m.number_of_feature_edges());
  EXPECT_EQ(again.number_of_feature_curves(), m.number_of_feature_curves());
  EXPECT_EQ(again.corners(), m.corners());
  for(Index t = 0; t < m.number_of_tetrahedra(); ++t) ASSERT_EQ(again.tetrahedron_vertices(t), m.tetrahedron_vertices(t));
}

TEST(Refinement, RoundsBringTheMeshToSixTetrahedraPerHexahedron)
{
  // 1000 tetrahedra in a unit volume: 1 per hexahedron of edge 0.1 -> 8 after one round
  EXPECT_EQ(HR::tetrahedron_refinement_rounds(1000, 1., 0.1), 1);
  EXPECT_EQ(HR::tetrahedron_refinement_rounds(8000, 1., 0.1), 1);     // below 12: one round
  EXPECT_EQ(HR::tetrahedron_refinement_rounds(12000, 1., 0.1), 0);    // 12 per hexahedron: none
  EXPECT_EQ(HR::tetrahedron_refinement_rounds(700, 1., 0.1), 2);      // 0.7 -> 5.6 -> 44.8
  EXPECT_EQ(HR::tetrahedron_refinement_rounds(10, 1., 0.1), 2);       // at most two rounds
  EXPECT_EQ(HR::tetrahedron_refinement_rounds(10, 1., 0.1, 6, 12, 4), 4);
  EXPECT_EQ(HR::tetrahedron_refinement_rounds(1000, 1., 0.), 0);      // no size
  EXPECT_EQ(HR::tetrahedron_refinement_rounds(1000, 0., 0.1), 0);     // no volume
}

// ---------------------------------------------------------------------------------------------
// Broken inputs: each defect gives an Input_error naming the file, the place and the problem.

struct Broken_case { const char* file; const char* problem; std::size_t line; bool unsupported; };

TEST(Validation, BrokenFilesGiveClearErrors)
{
  const Broken_case cases[] = {
    {"truncated.vtk", "unexpected end of file while reading POINTS", 10, false},
    {"malformed_number.vtk", "malformed number '0x'", 7, false},
    {"index_out_of_range.vtk", "vertex index 9 out of range", 13, false},
    {"no_tetrahedra.vtk", "no tetrahedra", 0, false},
    {"nan_coordinate.vtk", "vertex 2: coordinate is not a finite number", 0, false},
    {"inf_coordinate.vtk", "vertex 3: coordinate is not a finite number", 0, false},
    {"degenerate_tetrahedron.vtk", "tetrahedron 1: degenerate (zero volume)", 14, false},
    {"face_three_tetrahedra.vtk", "is shared by 3 tetrahedra", 0, false},
    {"nonmanifold_edge.vtk", "non-manifold boundary", 0, false},
    {"nonmanifold_vertex.vtk", "vertex 0: non-manifold boundary", 0, false},
    {"duplicate_tetrahedron.vtk", "duplicate of tetrahedron", 0, false},
    // binary VTK is read since issue 13: this one says BINARY but holds text, too short for the data
    {"binary.vtk", "POINTS: the binary block of 15 values of type double is truncated", 5, false},
    {"not_vtk.vtk", "not a VTK legacy file", 1, false},
    {"wrong_cell_size.vtk", "has 4 vertices instead of 3", 0, false},
    {"empty.vtk", "unexpected end of file", 0, false},
    {"medit_zero_index.mesh", "invalid index 0", 0, false},
    {"medit_malformed.mesh", "malformed integer 'five'", 4, false},
    {"medit_truncated.mesh", "exceeds what the file holds (truncated file?)", 4, false},
    {"medit_unknown_keyword.mesh", "unsupported MEDIT keyword 'Tetrahedrons'", 0, true},
    {"does_not_exist.vtk", "cannot open file", 0, false},
    {"does_not_exist.off", "cannot open file", 0, false},
    {"unknown.xyz", "unknown file extension", 0, true},
    // hostile inputs: a huge declared count in a tiny file is rejected before any allocation
    {"huge_count_points.vtk", "count 4000000000 in POINTS exceeds what the file holds", 5, false},
    {"huge_count_cells.vtk", "count 1000000000000 in CELLS exceeds what the file holds", 10, false},
    {"medit_huge_count.mesh", "integer '99999999999999999999' out of range in Vertices", 4, false},
    // found by scripts/fuzz: a second CELLS section after the CellEntityIds of the first one
    // made the reader read past the ids
    {"duplicate_cells.vtk", "duplicate CELLS section", 17, false},
  };
  for(const Broken_case& c : cases) {
    SCOPED_TRACE(c.file);
    const std::string path = test_data + "/broken/" + c.file;
    try {
      Mesh m;
      HR::IO::read_tetrahedral_mesh(path, m);
      ADD_FAILURE() << "no error for " << c.file;
    } catch(const HR::Input_error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(path), std::string::npos) << what;           // names the file
      EXPECT_NE(what.find(c.problem), std::string::npos) << what;      // names the problem
      if(c.line > 0) EXPECT_EQ(e.line(), c.line) << what;              // names the line
      EXPECT_EQ(dynamic_cast<const HR::Unsupported_input*>(&e) != nullptr, c.unsupported) << what;
    }
  }
}

TEST(Validation, SoupErrorsNameTheElement)
{
  HR::Tetrahedral_soup_3<Point> soup;
  Mesh m;
  EXPECT_THROW(HR::build_tetrahedral_mesh(soup, m), HR::Input_error); // empty
  soup.points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)};
  soup.tetrahedra = {{0, 1, 2, 2}};
  try {
    HR::build_tetrahedral_mesh(soup, m);
    ADD_FAILURE();
  } catch(const HR::Input_error& e) {
    EXPECT_EQ(std::string(e.what()), "<memory>: tetrahedron 0: degenerate (zero volume)");
  }
}

// ---------------------------------------------------------------------------------------------
// Hostile inputs (issue 6): each gives a correct result or a clear Input_error, never a crash.

namespace {
// The unit cube of 5 tetrahedra of cube_1e30.vtk / cube_1e-30.vtk with coordinates 0 and s.
Mesh scaled_cube(double s)
{
  HR::Tetrahedral_soup_3<Point> soup;
  for(int z = 0; z < 2; ++z)
    for(int y = 0; y < 2; ++y)
      for(int x = 0; x < 2; ++x) soup.points.push_back(Point(x * s, y * s, z * s));
  soup.tetrahedra = {{0, 1, 2, 4}, {3, 1, 2, 7}, {5, 1, 4, 7}, {6, 2, 4, 7}, {1, 2, 4, 7}};
  Mesh m;
  HR::build_tetrahedral_mesh(soup, m);
  return m;
}
} // namespace

TEST(Hostile, CoordinatesOf1e30And1eMinus30GiveTheResultOfTheUnitCube)
{
  const Mesh unit = scaled_cube(1);
  const auto ref = HR::compute_mesh_statistics(unit);
  EXPECT_EQ(ref.dihedral_class_histogram, (std::array<std::size_t, 5>{{0, 12, 6, 0, 0}}));
  for(const char* f : {"cube_1e30.vtk", "cube_1e-30.vtk"}) {
    SCOPED_TRACE(f);
    const Mesh m = load(test_data + "/" + f);
    check_topology(m); // exact orientations, outward boundary, rings, volume (relative tolerance)
    ASSERT_EQ(m.number_of_tetrahedra(), unit.number_of_tetrahedra());
    ASSERT_EQ(m.number_of_vertices(), unit.number_of_vertices());
    for(Index t = 0; t < m.number_of_tetrahedra(); ++t)
      EXPECT_EQ(m.tetrahedron_vertices(t), unit.tetrahedron_vertices(t)); // same split, same orientation
    const auto s = HR::compute_mesh_statistics(m);
    EXPECT_EQ(s.dihedral_class_histogram, ref.dihedral_class_histogram);
    EXPECT_NEAR(s.min_dihedral_angle_degrees, 90.0, 1e-9);
    EXPECT_NEAR(s.max_dihedral_angle_degrees, 180.0, 1e-9);
    for(Index e : m.boundary_edges())
      EXPECT_NEAR(HR::boundary_edge_dihedral_angle(m, e), HR::boundary_edge_dihedral_angle(unit, e), 1e-12);
  }
  // the barycentres of the split are exact multiples of the scale: same result for any power of two
  for(double s : {std::ldexp(1.0, 100), std::ldexp(1.0, -100), std::ldexp(1.0, 1000), std::ldexp(1.0, -1000)}) {
    const Mesh m = scaled_cube(s);
    EXPECT_EQ(HR::compute_mesh_statistics(m).dihedral_class_histogram, ref.dihedral_class_histogram) << s;
  }
}

TEST(Hostile, CoordinatesNearTheLargestDouble)
{
  // found by scripts/fuzz: the barycentre of the split overflowed to inf, and the exact predicates
  // then failed on a non-finite coordinate; now it is computed without overflow
  const Mesh m = load(test_data + "/overflow_barycentre.vtk");
  EXPECT_EQ(m.number_of_split_tetrahedra(), 1u);
  EXPECT_EQ(m.number_of_tetrahedra(), 4u);
  for(Index t = 0; t < m.number_of_tetrahedra(); ++t) {
    const auto& v = m.tetrahedron_vertices(t);
    EXPECT_EQ(CGAL::orientation(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])), CGAL::POSITIVE);
  }
  for(Index v = 0; v < m.number_of_vertices(); ++v)
    for(int c = 0; c < 3; ++c) EXPECT_TRUE(std::isfinite(m.point(v)[c]));
  // the exact classes do not depend on the scale (all coordinates are 0 or 1.7e308)
  HR::Tetrahedral_soup_3<Point> unit;
  unit.points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 1)};
  unit.tetrahedra = {{0, 1, 2, 3}};
  Mesh u;
  HR::build_tetrahedral_mesh(unit, u);
  EXPECT_EQ(HR::compute_mesh_statistics(m).dihedral_class_histogram, HR::compute_mesh_statistics(u).dihedral_class_histogram);
}

TEST(Hostile, SliversAndBowTies)
{
  // four coplanar, distinct points: exact zero volume (degenerate_tetrahedron.vtk, in the table
  // above); a tetrahedron of height 1e-17 has a positive volume, exactly, and is accepted
  const Mesh sliver = load(test_data + "/near_sliver.vtk");
  EXPECT_EQ(sliver.number_of_tetrahedra(), 4u);
  check_topology(sliver);
  // a sliver whose coplanarity is exact but not visible in floating point: points on the plane
  // x + y + z = 3 * 2^-3, each coordinate a multiple of 2^-3
  HR::Tetrahedral_soup_3<Point> soup;
  soup.points = {Point(0.375, 0, 0), Point(0, 0.375, 0), Point(0, 0, 0.375), Point(0.125, 0.125, 0.125),
                 Point(1, 1, 1)};
  soup.tetrahedra = {{0, 1, 2, 4}, {0, 1, 2, 3}};
  Mesh m;
  try {
    HR::build_tetrahedral_mesh(soup, m);
    ADD_FAILURE() << "coplanar tetrahedron accepted";
  } catch(const HR::Input_error& e) {
    EXPECT_EQ(e.problem(), "tetrahedron 1: degenerate (zero volume)");
  }
  // bow-tie: two tetrahedra sharing only a vertex, or only an edge
  for(const char* f : {"nonmanifold_vertex.vtk", "nonmanifold_edge.vtk"}) {
    SCOPED_TRACE(f);
    EXPECT_THROW(load(test_data + "/broken/" + f), HR::Input_error);
  }
}

// ---------------------------------------------------------------------------------------------
// Topology on every shared model

TEST(Topology, InvariantsOnSharedModels)
{
  const auto files = shared_models();
  if(files.empty()) GTEST_SKIP() << "../shared/data not present";
  // Genus of each model's boundary surface (sum over components), from its shape: through-holes
  // of the parts; every other model is a topological ball.
  const std::map<std::string, long> genus = {
    {"s16c_torus", 1}, {"n05c_box_min_pcyls", 1}, {"n10c_qtorus_cyl", 1}, {"n11c_limit_cycle", 1},
    {"B1_tet", 1}, {"i11c_s1", 3}, {"i01c_m1", 9}};
  for(const std::string& f : files) {
    SCOPED_TRACE(f);
    const Mesh m = load(f);
    check_topology(m);
    const std::string name = fs::path(f).stem().string();
    const long g = genus.count(name) ? genus.at(name) : 0;
    EXPECT_EQ(m.boundary_euler_characteristic(), 2 * long(m.number_of_boundary_components()) - 2 * g);
    EXPECT_EQ(m.number_of_components(), 1u);
  }
}

TEST(Topology, ShippedAcuteModel)
{
  const Mesh m = load(example_data + "/n13c_acute_line.vtk");
  check_topology(m);
  EXPECT_EQ(m.number_of_input_vertices(), 227u);
  EXPECT_EQ(m.number_of_feature_curves(), 9u);
  EXPECT_EQ(m.number_of_surface_patches(), 5u);
  EXPECT_EQ(m.corners().size(), 6u);
  // the 10 degree wedge edge: 8 boundary edges of class 0, measured angle 10 degrees
  std::size_t acute = 0;
  for(Index e : m.boundary_edges())
    if(HR::boundary_edge_dihedral_class(m, e) == 0) {
      ++acute;
      EXPECT_NEAR(HR::boundary_edge_dihedral_angle(m, e) * 180 / CGAL_PI, 10.0, 1e-6);
      EXPECT_GE(m.edge_curve(e), 0);
    }
  EXPECT_EQ(acute, 8u);
}

// ---------------------------------------------------------------------------------------------
// Exact dihedral classes

namespace {
// Edge p -> q along -z, first face along +x, second face at angle phi counter-clockwise about +z:
// the interior dihedral angle of the paper's formula is then phi.
int dihedral_class_of(const Point& b)
{
  HR::Hexahedral_remeshing_traits_3<> traits;
  return traits.dihedral_class_3_object()(Point(0, 0, 1), Point(0, 0, 0), Point(1, 0, 0), b);
}
Point at_degrees(double deg)
{
  const double r = deg * CGAL_PI / 180;
  return Point(std::cos(r), std::sin(r), 0.5);
}
} // namespace

TEST(DihedralClass, ConstructedEdges)
{
  EXPECT_EQ(dihedral_class_of(at_degrees(10)), 0);
  EXPECT_EQ(dihedral_class_of(at_degrees(44.9)), 0);
  EXPECT_EQ(dihedral_class_of(Point(1, 1, 0)), 1);    // exactly 45 degrees: tie rounds up
  EXPECT_EQ(dihedral_class_of(Point(7, 7, -3)), 1);   // exactly 45 degrees, off-plane point
  EXPECT_EQ(dihedral_class_of(at_degrees(90)), 1);
  EXPECT_EQ(dihedral_class_of(Point(0, 1, 0)), 1);
  EXPECT_EQ(dihedral_class_of(Point(-1, 1, 0)), 2);   // exactly 135: tie rounds up
  EXPECT_EQ(dihedral_class_of(Point(-1, 0, 0)), 2);   // exactly 180
  EXPECT_EQ(dihedral_class_of(Point(-1, -1, 0)), 3);  // exactly 225: tie rounds up
  EXPECT_EQ(dihedral_class_of(Point(0, -1, 2)), 3);   // exactly 270
  EXPECT_EQ(dihedral_class_of(Point(1, -1, 0)), 4);   // exactly 315: tie rounds up
  EXPECT_EQ(dihedral_class_of(at_degrees(350)), 4);
  // just below and above the exact 45 degree tie: the filter fails and the exact path decides
  EXPECT_EQ(dihedral_class_of(Point(1, std::nextafter(1.0, 0.0), 0)), 0);
  EXPECT_EQ(dihedral_class_of(Point(1, std::nextafter(1.0, 2.0), 0)), 1);
  EXPECT_EQ(dihedral_class_of(Point(-1, std::nextafter(1.0, 2.0), 0)), 1);  // just below 135
  EXPECT_EQ(dihedral_class_of(Point(-1, std::nextafter(1.0, 0.0), 0)), 2);  // just above 135
  // agrees with round(2 phi / pi) away from ties
  for(double deg = 0.5; deg < 360; deg += 1.0)
    EXPECT_EQ(dihedral_class_of(at_degrees(deg)), int(std::floor(deg / 90 + 0.5))) << deg;
}

TEST(DihedralClass, HistogramOfAcuteModelAndB41)
{
  const Mesh n13 = load(example_data + "/n13c_acute_line.vtk");
  const auto s = HR::compute_mesh_statistics(n13);
  EXPECT_EQ(s.dihedral_class_histogram, (std::array<std::size_t, 5>{{8, 52, 615, 0, 0}}));
  EXPECT_NEAR(s.min_dihedral_angle_degrees, 10.0, 1e-6);

  // B41 has 45 degree edges (the rounding tie): in exact arithmetic on its double coordinates,
  // 18 of them are slightly below 45 degrees (class 0), the others at or above (class 1).
  const std::string b41 = shared_data + "/mambo/B41.vtk";
  if(!fs::exists(b41)) GTEST_SKIP() << "../shared/data not present";
  const Mesh m = load(b41);
  const auto sb = HR::compute_mesh_statistics(m);
  EXPECT_EQ(sb.dihedral_class_histogram, (std::array<std::size_t, 5>{{18, 518, 8344, 234, 0}}));
  std::size_t ties = 0;
  for(Index e : m.boundary_edges()) {
    const double phi = HR::boundary_edge_dihedral_angle(m, e);
    if(HR::boundary_edge_dihedral_class(m, e) == 0) {
      EXPECT_NEAR(phi, CGAL_PI / 4, 1e-9); // a tie that floating point cannot decide
      ++ties;
    }
    if(std::abs(phi - CGAL_PI / 4) < 1e-9 && HR::boundary_edge_dihedral_class(m, e) == 1) ++ties;
  }
  EXPECT_GT(ties, 18u); // both sides of the tie occur
}

// ---------------------------------------------------------------------------------------------
// TetGen on shipped surfaces

TEST(TetGen, CubeAndCylinder)
{
  const Mesh cube = load(example_data + "/cube.off");
  check_topology(cube);
  double v = 0;
  for(Index t = 0; t < cube.number_of_tetrahedra(); ++t) v += tet_volume(cube, t);
  EXPECT_NEAR(v, 1.0, 1e-12);
  // class 1 exactly on the 12 cube edges (two coordinates in {0, 1}), class 2 elsewhere
  auto on_cube_edge = [](const Point& p) {
    int extreme = 0;
    for(int c = 0; c < 3; ++c) extreme += (p[c] == 0 || p[c] == 1);
    return extreme >= 2;
  };
  std::size_t convex = 0;
  for(Index e : cube.boundary_edges()) {
    const auto& ev = cube.edge_vertices(e);
    const bool on_edge = on_cube_edge(cube.point(ev[0])) && on_cube_edge(cube.point(ev[1])) &&
                         on_cube_edge(CGAL::midpoint(cube.point(ev[0]), cube.point(ev[1])));
    EXPECT_EQ(HR::boundary_edge_dihedral_class(cube, e), on_edge ? 1 : 2);
    convex += on_edge;
  }
  EXPECT_GE(convex, 12u);

  Mesh strict;
  HR::IO::read_tetrahedral_mesh(example_data + "/cube.off", strict, HR::parameters::preserve_surface_triangles(true));
  EXPECT_EQ(strict.number_of_boundary_triangles(), 12u);
  check_topology(strict);

  Mesh cyl;
  HR::IO::read_tetrahedral_mesh(example_data + "/cylinder.off", cyl, HR::parameters::maximum_tetrahedron_volume(0.01));
  check_topology(cyl);
  double vc = 0;
  for(Index t = 0; t < cyl.number_of_tetrahedra(); ++t) vc += tet_volume(cyl, t);
  const double polygon_area = 16 * std::sin(2 * CGAL_PI / 32);
  EXPECT_NEAR(vc, 2 * polygon_area, 1e-9);
  EXPECT_GT(cyl.number_of_tetrahedra(), 2 * polygon_area / 0.01); // the volume bound refined it
  // the rims are the only edges of class 1, and they are all of class 1
  std::size_t rim = 0;
  for(Index e : cyl.boundary_edges()) {
    const auto& ev = cyl.edge_vertices(e);
    const double z0 = CGAL::to_double(cyl.point(ev[0]).z()), z1 = CGAL::to_double(cyl.point(ev[1]).z());
    const double r0 = std::hypot(CGAL::to_double(cyl.point(ev[0]).x()), CGAL::to_double(cyl.point(ev[0]).y()));
    const double r1 = std::hypot(CGAL::to_double(cyl.point(ev[1]).x()), CGAL::to_double(cyl.point(ev[1]).y()));
    const bool on_rim = z0 == z1 && (z0 == 0 || z0 == 2) && r0 > 0.99 && r1 > 0.99;
    EXPECT_EQ(HR::boundary_edge_dihedral_class(cyl, e), on_rim ? 1 : 2);
    rim += on_rim;
  }
  EXPECT_GE(rim, 64u);
}

// ---------------------------------------------------------------------------------------------
// Writer round trip

TEST(Writer, VtkRoundTripKeepsVerticesAndArrays)
{
  const Mesh m = load(example_data + "/n13c_acute_line.vtk");
  HR::IO::VTK_array volumes{"volume", 1, {}};
  for(Index t = 0; t < m.number_of_tetrahedra(); ++t) volumes.values.push_back(tet_volume(m, t));
  const std::string out = (fs::temp_directory_path() / "hexrem_roundtrip.vtk").string();
  HR::IO::write_VTK(out, m, {volumes});
  EXPECT_FALSE(fs::exists(out + ".tmp"));
  Mesh r;
  HR::IO::read_tetrahedral_mesh(out, r, HR::parameters::split_multi_boundary_tetrahedra(false));
  EXPECT_EQ(r.number_of_vertices(), m.number_of_vertices());
  EXPECT_EQ(r.number_of_tetrahedra(), m.number_of_tetrahedra());
  for(Index v = 0; v < m.number_of_vertices(); ++v) ASSERT_EQ(r.point(v), m.point(v));
  std::remove(out.c_str());
  EXPECT_THROW(HR::IO::write_VTK("/nonexistent_dir/x.vtk", m), HR::Error);
}

TEST(Writer, FailuresLeaveNoPartialFile)
{
  const Mesh m = load(test_data + "/two_tets.vtk");
  const fs::path dir = fs::temp_directory_path() / "hexrem_writer_failures";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string out = (dir / "out.vtk").string();
  // a failure in the middle of the writing (an array of the wrong size): no file, no temporary
  HR::IO::VTK_array bad{"bad", 1, {1.0}};
  EXPECT_THROW(HR::IO::write_VTK(out, m, {bad}), HR::Error);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out + ".tmp"));
  // an existing file is kept as it was
  { std::ofstream(out) << "previous content\n"; }
  EXPECT_THROW(HR::IO::write_VTK(out, m, {}, {bad}), HR::Error);
  std::ifstream in(out);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "previous content");
  EXPECT_FALSE(fs::exists(out + ".tmp"));
  // the target is a directory: the rename fails, the temporary file is removed
  const std::string sub = (dir / "sub").string();
  fs::create_directories(sub);
  EXPECT_THROW(HR::IO::write_VTK(sub, m), HR::Error);
  EXPECT_TRUE(fs::is_directory(sub));
  EXPECT_FALSE(fs::exists(sub + ".tmp"));
  fs::remove_all(dir);
}
