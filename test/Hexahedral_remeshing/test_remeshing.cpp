// Tests of the one call from tetrahedra to hexahedra, CGAL::hexahedral_remeshing(): inputs (our
// Tetrahedral_mesh_3, a closed Surface_mesh), outputs (Hexahedral_mesh_3, CGAL's LCC), sizes, the report,
// and bad parameters. The hex meshes are checked from their cells here (counts, orientation of every
// corner, conformity by quad keys, volume), not from the package's own flags.
#include "data_paths.h"
#include <CGAL/hexahedral_remeshing.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <gtest/gtest.h>

#include "hex_mesh_generators.h"
#include "synthetic_models.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace HR = CGAL::Hexahedral_remeshing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef HR::Tetrahedral_mesh_3<> Mesh;

namespace {

const std::string example_data = HEXREM_EXAMPLE_DATA_DIR;

Mesh load(const std::string& file, double max_volume = 0) { return load_tetrahedral_mesh<Mesh>(file, max_volume); }

// Independent checks of a hex mesh: every corner positively oriented (exact), every quad used once
// (boundary) or twice with opposite orientations (interior), the volume.
struct Cell_check
{
  std::size_t non_positive_corners = 0, boundary_quads = 0, interior_quads = 0, bad_quads = 0;
  double volume = 0;
};

Cell_check check_cells(const HR::Hexahedral_mesh_3& h)
{
  static const int corner[8][3] = { {1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7}, {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3} };
  static const int faces[6][4] = { {0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7} };
  Cell_check c;
  std::map<std::array<std::uint32_t, 4>, std::vector<std::array<std::uint32_t, 4> > > quads;
  for(const auto& hex : h.hexahedra) {
    for(int i = 0; i < 8; ++i)
      if(CGAL::orientation(h.points[hex[i]], h.points[hex[corner[i][0]]], h.points[hex[corner[i][1]]],
                           h.points[hex[corner[i][2]]]) != CGAL::POSITIVE)
        ++c.non_positive_corners;
    // volume: 5-tet split of the hexahedron
    static const int tets[5][4] = { {0, 1, 3, 4}, {1, 2, 3, 6}, {1, 4, 5, 6}, {3, 4, 6, 7}, {1, 3, 4, 6} };
    for(const auto& t : tets)
      c.volume += CGAL::volume(h.points[hex[t[0]]], h.points[hex[t[1]]], h.points[hex[t[2]]], h.points[hex[t[3]]]);
    for(const auto& f : faces) {
      std::array<std::uint32_t, 4> q{ {hex[f[0]], hex[f[1]], hex[f[2]], hex[f[3]]} }, k = q;
      std::sort(k.begin(), k.end());
      quads[k].push_back(q);
    }
  }
  for(const auto& kv : quads) {
    if(kv.second.size() == 1) { ++c.boundary_quads; continue; }
    if(kv.second.size() != 2) { ++c.bad_quads; continue; }
    // opposite orientation: the second cycle is the first one reversed (up to rotation)
    const auto& a = kv.second[0];
    const auto& b = kv.second[1];
    bool opposite = false;
    for(int s = 0; s < 4; ++s) {
      bool all = true;
      for(int i = 0; i < 4; ++i) all = all && a[i] == b[(s - i + 8) % 4];
      opposite = opposite || all;
    }
    if(opposite) ++c.interior_quads; else ++c.bad_quads;
  }
  return c;
}

// Vertices on the boundary of the hex mesh: those of the quads that only one hexahedron has.
std::vector<char> boundary_vertices(const HR::Hexahedral_mesh_3& hexes)
{
  static const int faces[6][4] = { {0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7} };
  std::map<std::array<std::uint32_t, 4>, int> quad_count;
  for(const auto& hex : hexes.hexahedra)
    for(const auto& f : faces) {
      std::array<std::uint32_t, 4> k{ {hex[f[0]], hex[f[1]], hex[f[2]], hex[f[3]]} };
      std::sort(k.begin(), k.end());
      ++quad_count[k];
    }
  std::vector<char> on_boundary(hexes.points.size(), 0);
  for(const auto& kv : quad_count)
    if(kv.second == 1) for(std::uint32_t v : kv.first) on_boundary[v] = 1;
  return on_boundary;
}

// Number of hexahedra around every hex edge (sorted vertex pair).
std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_valences(const HR::Hexahedral_mesh_3& hexes)
{
  static const int edges[12][2] = { {0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7} };
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> valence;
  for(const auto& hex : hexes.hexahedra)
    for(const auto& e : edges) ++valence[std::minmax(hex[e[0]], hex[e[1]])];
  return valence;
}

Mesh from_off(const std::string& name, const std::string& text, double max_volume)
{
  return tetrahedral_mesh_of_off<Mesh>(name, text, max_volume);
}

struct Counting_visitor : HR::Hexahedral_remeshing_visitor
{
  std::vector<std::string> stages;
  void start_stage(const std::string& s) { stages.push_back(s); }
};

} // namespace

TEST(HexahedralRemeshing, CubeFromTetrahedraGivesNCubedHexahedra)
{
  const Mesh m = load(example_data + "/cube.off", 0.002);
  for(int N : {2, 4}) {
    SCOPED_TRACE(N);
    HR::Hexahedral_mesh_3 hexes;
    Counting_visitor visitor;
    const HR::Hexahedral_remeshing_result r =
      CGAL::hexahedral_remeshing(m, hexes, HR::parameters::target_edge_length(1.0 / N).visitor(std::ref(visitor)));
    EXPECT_EQ(r.status, HR::Hexahedral_remeshing_status::OK) << r.message;
    ASSERT_EQ(hexes.number_of_hexahedra(), std::size_t(N * N * N));
    EXPECT_EQ(hexes.number_of_vertices(), std::size_t((N + 1) * (N + 1) * (N + 1)));
    const Cell_check c = check_cells(hexes);
    EXPECT_EQ(c.non_positive_corners, 0u);
    EXPECT_EQ(c.bad_quads, 0u);
    EXPECT_EQ(c.boundary_quads, std::size_t(6 * N * N));
    // the frames are the identity only to the smoothing tolerance, and boundary vertices are projected
    EXPECT_NEAR(c.volume, 1.0, 1e-6);
    EXPECT_EQ(r.check.hexahedra, std::size_t(N * N * N));
    EXPECT_GT(r.check.min_scaled_jacobian, 0.999);
    EXPECT_EQ(r.map.target_edge_length, 1.0 / N);
    // the 12 edges of the cube: every boundary hex edge on them has 1 hexahedron (prescribed k = 1)
    EXPECT_EQ(r.hex_feature_edges, std::size_t(12 * N));
    EXPECT_EQ(r.hex_feature_edges_with_prescribed_valence, r.hex_feature_edges);
    EXPECT_NEAR(r.feature_coverage, 1.0, 1e-9);
    EXPECT_NEAR(r.volume_ratio, 1.0, 1e-6);
    EXPECT_TRUE(r.smoothed);
    EXPECT_GE(r.relative_hausdorff_distance, 0.0);
    EXPECT_LT(r.relative_hausdorff_distance, 1e-6);
    for(const char* stage : {"valences", "constraints", "rounding", "cells", "hex smoothing", "check"})
      EXPECT_NE(std::find(visitor.stages.begin(), visitor.stages.end(), stage), visitor.stages.end()) << stage;
  }
}

// A mesh that the check finds valid but with a hexahedron whose scaled Jacobian is positive only by
// rounding (n03c after the untangling: 4.6e-15) is not OK: a solver's element matrix is singular there.
TEST(HexahedralRemeshing, FlatHexahedronIsNotOK)
{
  const Mesh m = load(example_data + "/cube.off", 0.002);
  HR::Hexahedral_mesh_3 hexes;
  HR::Hexahedral_remeshing_result r = CGAL::hexahedral_remeshing(m, hexes, HR::parameters::target_edge_length(0.5));
  ASSERT_EQ(r.status, HR::Hexahedral_remeshing_status::OK) << r.message;
  ASSERT_TRUE(r.check.valid);
  EXPECT_EQ(r.check.flat_hexahedra, 0u);
  EXPECT_EQ(r.check.flat_scaled_jacobian_threshold, HR::internal::minimum_scaled_jacobian);
  // what the check reports of a mesh with one hexahedron at 4.6e-15 (n03c after the untangling)
  const HR::Hexahedral_mesh_check sound = r.check;
  r.check.min_scaled_jacobian = 4.6e-15;
  r.check.flat_hexahedra = 1;
  r.check.valid = false;
  HR::internal::decide_remeshing_status(m, r);
  EXPECT_EQ(r.status, HR::Hexahedral_remeshing_status::INVALID_HEX_MESH);
  EXPECT_NE(r.message.find("1 hexahedra are flat"), std::string::npos) << r.message;
  r.check = sound;
  HR::internal::decide_remeshing_status(m, r);
  EXPECT_EQ(r.status, HR::Hexahedral_remeshing_status::OK) << r.message;
}

// The HexMe tetrahedra of the 10-degree wedge are coarser than the hexahedra (2,573 after the splits, 1.3
// per hexahedron): the map collapses and gives no hexahedron. The second run on their red refinement
// gives a valid mesh, checked here from its cells; without the refinement the call fails as before.
TEST(HexahedralRemeshing, CoarseMeshThatFailsIsRefinedAndRemeshed)
{
  const Mesh m = load(example_data + "/n13c_acute_line.vtk");
  Mesh fine;
  HR::Hexahedral_mesh_3 hexes;
  const HR::Hexahedral_remeshing_result r =
    CGAL::hexahedral_remeshing(m, hexes, HR::parameters::refined_mesh_output(std::ref(fine)));
  ASSERT_EQ(r.status, HR::Hexahedral_remeshing_status::OK) << r.message;
  EXPECT_TRUE(r.refinement.used);
  EXPECT_EQ(r.refinement.rounds, 1);
  EXPECT_EQ(r.refinement.other_outcome.rfind("NO_HEXAHEDRA", 0), 0u) << r.refinement.other_outcome;
  EXPECT_EQ(fine.number_of_tetrahedra(), r.refinement.tetrahedra);
  EXPECT_EQ(r.tetrahedra, r.refinement.tetrahedra);
  EXPECT_GE(fine.number_of_tetrahedra(), 8 * m.number_of_tetrahedra());
  for(Mesh::Index v = 0; v < m.number_of_vertices(); ++v) ASSERT_EQ(fine.point(v), m.point(v)) << v;
  EXPECT_EQ(r.frame_field.valences.size(), fine.number_of_edges());  // the reports describe the refined mesh
  const Cell_check c = check_cells(hexes);
  EXPECT_GT(hexes.hexahedra.size(), 1000u);
  EXPECT_EQ(c.non_positive_corners, 0u);
  EXPECT_EQ(c.bad_quads, 0u);
  double solid = 0;
  for(Mesh::Index t = 0; t < m.number_of_tetrahedra(); ++t) {
    const auto& tv = m.tetrahedron_vertices(t);
    solid += CGAL::volume(m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3]));
  }
  EXPECT_NEAR(c.volume, solid, 0.01 * solid);

  HR::Hexahedral_mesh_3 coarse_hexes;
  const HR::Hexahedral_remeshing_result off =
    CGAL::hexahedral_remeshing(m, coarse_hexes, HR::parameters::tetrahedron_refinement(false));
  EXPECT_NE(off.status, HR::Hexahedral_remeshing_status::OK);
  EXPECT_EQ(off.refinement.rounds, 0);
  EXPECT_FALSE(off.refinement.used);
  EXPECT_EQ(off.tetrahedra, m.number_of_tetrahedra());
}

TEST(HexahedralRemeshing, SurfaceMeshInLinearCellComplexOut)
{
  CGAL::Surface_mesh<K::Point_3> surface;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(example_data + "/cube.off", surface));
  CGAL::Linear_cell_complex_for_combinatorial_map<3> lcc;
  const HR::Hexahedral_remeshing_result r = CGAL::hexahedral_remeshing(
    surface, lcc, HR::parameters::number_of_hexahedra(std::size_t(27), HR::parameters::maximum_tetrahedron_volume(0.002)));
  EXPECT_EQ(r.status, HR::Hexahedral_remeshing_status::OK) << r.message;
  EXPECT_NEAR(r.map.target_edge_length, 1.0 / 3.0, 1e-9);
  EXPECT_EQ(lcc.one_dart_per_cell<3>().size(), 27u);
  EXPECT_EQ(lcc.one_dart_per_cell<0>().size(), 64u);
  EXPECT_TRUE(lcc.is_valid());
}

TEST(HexahedralRemeshing, CylinderSurfaceAtTheHexSizeHasFourValenceThreeChains)
{
  // The shipped cylinder (radius 1, axis z from 0 to 2) from its surface alone: the call
  // tetrahedralizes it at the hex size. A hex mesh of a cylinder from a smooth field has four
  // valence-3 chains parallel to the axis (the square core of an O-grid has four corners).
  CGAL::Surface_mesh<K::Point_3> surface;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(example_data + "/cylinder.off", surface));
  HR::Hexahedral_mesh_3 hexes;
  const HR::Hexahedral_remeshing_result r =
    CGAL::hexahedral_remeshing(surface, hexes, HR::parameters::number_of_hexahedra(std::size_t(500)));
  ASSERT_EQ(r.status, HR::Hexahedral_remeshing_status::OK) << r.message;
  EXPECT_GT(r.tetrahedra, 5000u); // at the hex size, not the 854 tetrahedra of the surface alone
  EXPECT_EQ(r.frame_field.singularities.number_of_curves(3), 4u);
  EXPECT_EQ(r.frame_field.singularities.number_of_curves(5), 0u);

  const Cell_check c = check_cells(hexes);
  EXPECT_EQ(c.non_positive_corners, 0u);
  EXPECT_EQ(c.bad_quads, 0u);
  EXPECT_GT(hexes.number_of_hexahedra(), 250u); // about 500: the size is cbrt(volume / 500), the count follows the rounding
  EXPECT_LT(hexes.number_of_hexahedra(), 700u);
  EXPECT_NEAR(c.volume, 2 * CGAL_PI, 0.06 * 2 * CGAL_PI);

  // boundary vertices on the cylinder; interior edges by valence, counted from the cells
  const std::vector<char> on_boundary = boundary_vertices(hexes);
  double worst = 0;
  for(std::size_t v = 0; v < hexes.points.size(); ++v) {
    if(!on_boundary[v]) continue;
    const auto& p = hexes.points[v];
    const double d = (std::min)({std::abs(std::hypot(p.x(), p.y()) - 1.0), std::abs(p.z()), std::abs(p.z() - 2.0)});
    worst = (std::max)(worst, d);
  }
  EXPECT_LT(worst, 1 - std::cos(CGAL_PI / 32) + 1e-6); // on the 32-gon prism of the file (its sag off the true cylinder)
  std::size_t valence3 = 0, other = 0;
  for(const auto& kv : edge_valences(hexes)) {
    if(on_boundary[kv.first.first] && on_boundary[kv.first.second]) continue; // boundary (or chord) edges
    if(kv.second == 4) continue;
    if(kv.second != 3) { ++other; continue; }
    ++valence3;
    const auto d = hexes.points[kv.first.second] - hexes.points[kv.first.first];
    EXPECT_GT(std::abs(d.z()), 0.9 * std::sqrt(d.squared_length())) << "a valence-3 edge across the axis";
  }
  EXPECT_EQ(other, 0u);
  EXPECT_GT(valence3, 0u);
  EXPECT_EQ(valence3 % 4, 0u) << valence3 << " valence-3 edges: not four chains through every layer";
}

TEST(HexahedralRemeshing, WithoutSmoothingTheHexahedraAreTheIntegerCells)
{
  const Mesh m = load(example_data + "/cube.off", 0.002);
  HR::Hexahedral_mesh_3 hexes;
  const HR::Hexahedral_remeshing_result r = CGAL::hexahedral_remeshing(
    m, hexes, HR::parameters::target_edge_length(0.5, HR::parameters::hexahedral_smoothing(false)));
  EXPECT_EQ(r.status, HR::Hexahedral_remeshing_status::OK) << r.message;
  EXPECT_FALSE(r.smoothed);
  EXPECT_EQ(r.relative_hausdorff_distance, -1.0);
  ASSERT_EQ(hexes.number_of_hexahedra(), 8u);
  // the vertices of the extracted cube grid are the multiples of 1/2 (up to the accuracy of the frames)
  for(const auto& p : hexes.points)
    for(int i = 0; i < 3; ++i) EXPECT_NEAR(2 * p[i], std::round(2 * p[i]), 1e-6);
}

TEST(HexahedralRemeshing, BadParameters)
{
  const Mesh m = load(example_data + "/cube.off", 0.01);
  HR::Hexahedral_mesh_3 hexes;
  EXPECT_THROW(CGAL::hexahedral_remeshing(m, hexes, HR::parameters::target_edge_length(-1.0)), HR::Input_error);
  EXPECT_THROW(CGAL::hexahedral_remeshing(m, hexes, HR::parameters::target_edge_length(std::numeric_limits<double>::quiet_NaN())),
               HR::Input_error);
}

TEST(HexahedralRemeshing, LPrismConcaveEdgeGetsThreeHexahedra)
{
  const Mesh m = from_off("hexrem_remesh_l_prism", l_prism_off(), 0.005);
  HR::Hexahedral_mesh_3 hexes;
  const HR::Hexahedral_remeshing_result r = CGAL::hexahedral_remeshing(m, hexes, HR::parameters::target_edge_length(0.25));
  EXPECT_EQ(r.status, HR::Hexahedral_remeshing_status::OK) << r.message;
  ASSERT_EQ(hexes.number_of_hexahedra(), 3u * 4 * 4 * 4);
  EXPECT_EQ(hexes.number_of_vertices(), std::size_t(3 * 5 * 5 * 5 - 2 * 5 * 5));
  const Cell_check c = check_cells(hexes);
  EXPECT_EQ(c.non_positive_corners, 0u);
  EXPECT_EQ(c.bad_quads, 0u);
  EXPECT_NEAR(c.volume, 3.0, 1e-6);
  // hex edges counted from the output: the concave vertical edge (x = y = 1) has 3 hexahedra around it,
  // the 17 other feature edges 1
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_hexes;
  static const int E[12][2] = { {0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7} };
  for(const auto& h : hexes.hexahedra)
    for(const auto& e : E) ++edge_hexes[std::minmax(h[e[0]], h[e[1]])];
  std::size_t concave = 0;
  for(const auto& kv : edge_hexes) {
    const auto& a = hexes.points[kv.first.first];
    const auto& b = hexes.points[kv.first.second];
    if(std::abs(a.x() - 1) < 1e-6 && std::abs(a.y() - 1) < 1e-6 && std::abs(b.x() - 1) < 1e-6 && std::abs(b.y() - 1) < 1e-6) {
      EXPECT_EQ(kv.second, 3);
      ++concave;
    }
  }
  EXPECT_EQ(concave, 4u);
  EXPECT_EQ(r.hex_feature_edges, std::size_t(2 * 32 + 6 * 4)); // 2 L outlines of length 8, 6 vertical edges of length 1
  EXPECT_EQ(r.hex_feature_edges_with_prescribed_valence, r.hex_feature_edges);
}

// The integer-grid map of a field whose singular curve is known exactly: frames taken from the charts
// of a hex mesh with one valence-3 (or 5) axis, split into 24 tetrahedra per hexahedron. The map, then
// the extraction, must give back a valid hex mesh with the irregular axis (independent of the frame field).
TEST(HexahedralRemeshing, MapOfExactFramesAroundASingularAxis)
{
  namespace T = CGAL::Hexahedral_remeshing::test;
  for(int n : {3, 5}) {
    SCOPED_TRACE(n);
    const T::Generated_hex_mesh g = T::make_polygon_prism(n, 2);
    const HR::Integer_grid_map source = T::map_from_hex_mesh(g.mesh, 1, 7u + unsigned(n));
    HR::Tetrahedral_soup_3<Mesh::Point_3> soup;
    soup.points = source.points;
    for(const auto& t : source.tetrahedra) soup.tetrahedra.push_back({t[0], t[1], t[2], t[3]});
    Mesh mesh;
    HR::build_tetrahedral_mesh(soup, mesh, HR::parameters::split_multi_boundary_tetrahedra(false));
    ASSERT_EQ(mesh.number_of_tetrahedra(), source.number_of_tetrahedra());
    // frame of a tetrahedron: the rotation closest to the transposed Jacobian of its chart
    std::vector<Eigen::Matrix3d> frames(mesh.number_of_tetrahedra());
    for(std::size_t t = 0; t < frames.size(); ++t) {
      const std::size_t i = mesh.tetrahedron_input_index(Mesh::Index(t));
      Eigen::Matrix3d U, D;
      for(int k = 1; k < 4; ++k) {
        const auto& p = source.points[source.tetrahedra[i][k]];
        const auto& p0 = source.points[source.tetrahedra[i][0]];
        D.col(k - 1) = Eigen::Vector3d(p.x() - p0.x(), p.y() - p0.y(), p.z() - p0.z());
        U.col(k - 1) = source.parameters[i][k] - source.parameters[i][0];
      }
      const Eigen::Matrix3d J = U * D.inverse();
      Eigen::JacobiSVD<Eigen::Matrix3d> svd(J.transpose(), Eigen::ComputeFullU | Eigen::ComputeFullV);
      frames[t] = svd.matrixU() * svd.matrixV().transpose();
      ASSERT_GT(frames[t].determinant(), 0);
    }
    const HR::Matchings matchings = HR::compute_matchings(mesh, frames);
    const HR::Singularity_graph singularities = HR::compute_singularity_graph(mesh, frames, matchings);
    ASSERT_EQ(singularities.number_of_curves(n == 3 ? 3 : 5), 1u);
    HR::Integer_grid_map map;
    const HR::Integer_grid_map_result r = HR::compute_integer_grid_map(mesh, frames, matchings, singularities, map,
                                                                       HR::parameters::target_edge_length(0.5));
    const HR::Integer_grid_map_check check = HR::check_integer_grid_map(map);
    EXPECT_EQ(check.inverted_tetrahedra, 0u);
    EXPECT_TRUE(check.is_integer_grid());
    EXPECT_EQ(check.interior_edge_valences.count(n == 3 ? 3 : 5), 1u);
    HR::Hexahedral_mesh_3 hexes;
    HR::extract_hexahedra(map, hexes);
    const Cell_check c = check_cells(hexes);
    EXPECT_GT(hexes.number_of_hexahedra(), 0u);
    EXPECT_EQ(c.non_positive_corners, 0u);
    EXPECT_EQ(c.bad_quads, 0u);
    const HR::Hexahedral_mesh_check hc = HR::check_hexahedral_mesh(hexes);
    EXPECT_EQ(hc.irregular_interior_edges.count(n), 1u);
    EXPECT_EQ(r.status, HR::Integer_grid_map_status::OK);
  }
}

TEST(HexahedralRemeshing, PrismThirtyDegreeEdgeGetsValenceOneAndOneValenceThreeChain)
{
  // The 30-60-90 prism (x, y cross-section, z from 0 to 1) from its surface. Its 30-degree edge is the
  // line x = 1, y = 0; the band of fixed frames keeps the cross-section's valence-3 curve off it (without
  // the band the curve ran in the 30-degree wedge against its faces and the map collapsed the wedge).
  CGAL::Surface_mesh<K::Point_3> surface;
  std::istringstream off(prism_30_60_90_off());
  ASSERT_TRUE(CGAL::IO::read_OFF(off, surface));
  HR::Hexahedral_mesh_3 hexes;
  const HR::Hexahedral_remeshing_result r =
    CGAL::hexahedral_remeshing(surface, hexes, HR::parameters::number_of_hexahedra(std::size_t(300)));
  ASSERT_EQ(r.status, HR::Hexahedral_remeshing_status::OK) << r.message;
  EXPECT_EQ(r.frame_field.singularities.number_of_curves(3), 1u);
  EXPECT_FALSE(r.frame_field.fixed_frames.empty());

  const Cell_check c = check_cells(hexes);
  EXPECT_EQ(c.non_positive_corners, 0u);
  EXPECT_EQ(c.bad_quads, 0u);
  const double volume = 0.5 / std::sqrt(3.0);
  EXPECT_NEAR(c.volume, volume, 0.03 * volume);

  // counted from the cells: the hex edges on the 30-degree edge have valence 1 and cover it; the
  // interior edges of valence 3 are parallel to z (one chain through every layer)
  const std::vector<char> on_boundary = boundary_vertices(hexes);
  auto on_acute_edge = [&](std::uint32_t v) {
    return std::abs(hexes.points[v].x() - 1) < 1e-6 && std::abs(hexes.points[v].y()) < 1e-6;
  };
  double acute_length = 0;
  std::size_t valence3 = 0, other = 0;
  for(const auto& kv : edge_valences(hexes)) {
    const std::uint32_t a = kv.first.first, b = kv.first.second;
    const auto d = hexes.points[b] - hexes.points[a];
    if(on_acute_edge(a) && on_acute_edge(b)) {
      EXPECT_EQ(kv.second, 1) << "a hex edge of the 30-degree edge with valence " << kv.second;
      acute_length += std::abs(d.z());
      continue;
    }
    if(on_boundary[a] && on_boundary[b]) continue;
    if(kv.second == 4) continue;
    if(kv.second != 3) { ++other; continue; }
    ++valence3;
    EXPECT_GT(std::abs(d.z()), 0.9 * std::sqrt(d.squared_length())) << "a valence-3 edge across the prism's axis";
  }
  EXPECT_NEAR(acute_length, 1.0, 1e-6);
  EXPECT_EQ(other, 0u);
  EXPECT_GT(valence3, 0u);
}

// The HexMe torus s16c (ring radius 20, tube radius 5): the field smoothed from the relaxation gives no
// valid hex mesh (its map folds), the run from the boundary propagation does, and the result says so.
// The hex mesh is checked from its cells and against the torus itself: every corner positive, every
// quad conforming, the boundary vertices on the torus, the volume of the inscribed hexahedra close to the
// solid's (a tube about 12 quads around: an inscribed 12-gon has 95% of the disk's area). Without the
// refinement retry, whose run on 54,600 tetrahedra (it fails too) would take minutes.
TEST(HexahedralRemeshing, TorusRestartsFromTheBoundaryPropagation)
{
  const std::string file = std::string(HEXREM_SHARED_DATA_DIR) + "/hexme/s16c_torus.vtk";
  if(!std::ifstream(file)) GTEST_SKIP() << "no shared data: " << file;
  const Mesh m = load(file);
  HR::Hexahedral_mesh_3 hexes;
  const HR::Hexahedral_remeshing_result r =
    CGAL::hexahedral_remeshing(m, hexes, HR::parameters::tetrahedron_refinement(false));
  ASSERT_EQ(r.status, HR::Hexahedral_remeshing_status::OK) << r.message;
  EXPECT_TRUE(r.field_restart.tried);
  EXPECT_TRUE(r.field_restart.used);
  EXPECT_EQ(r.field_restart.other_outcome.rfind("INVALID_HEX_MESH", 0), 0u) << r.field_restart.other_outcome;
  EXPECT_EQ(r.frame_field.frame_field.initialization, HR::Frame_field_initialization::BOUNDARY_PROPAGATION);
  EXPECT_GT(r.seconds, r.field_restart.other_seconds);
  const Cell_check c = check_cells(hexes);
  EXPECT_GT(hexes.hexahedra.size(), 500u);
  EXPECT_EQ(c.non_positive_corners, 0u);
  EXPECT_EQ(c.bad_quads, 0u);
  const std::vector<char> on_boundary = boundary_vertices(hexes);
  for(std::size_t v = 0; v < hexes.points.size(); ++v) {
    if(!on_boundary[v]) continue;
    const auto& p = hexes.points[v];
    const double tube = std::hypot(std::hypot(CGAL::to_double(p.x()), CGAL::to_double(p.y())) - 20, CGAL::to_double(p.z()));
    ASSERT_NEAR(tube, 5, 0.25) << "boundary vertex " << v;
  }
  const double torus = 2 * CGAL_PI * CGAL_PI * 20 * 25;
  EXPECT_GT(c.volume, 0.85 * torus);
  EXPECT_LT(c.volume, torus);
}
