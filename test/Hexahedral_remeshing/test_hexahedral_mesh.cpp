// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#include "hex_mesh_generators.h"

#include <CGAL/Hexahedral_remeshing/IO/read_hexahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/IO/write_hexahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK_integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/IO/read_VTK.h>
#include <CGAL/Hexahedral_remeshing/Tetrahedral_soup_3.h>
#include <CGAL/Hexahedral_remeshing/build_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_boundary_groups.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_orientation.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_to_lcc.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_validation.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_mesh/close_boundary_cracks.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_mesh/hexahedron_topology.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <array>
#include <map>
#include <random>
#include <set>
#include <vector>

namespace HR = CGAL::Hexahedral_remeshing;
namespace T = CGAL::Hexahedral_remeshing::test;
namespace HRI = CGAL::Hexahedral_remeshing::internal;

namespace {

std::array<HR::Hexahedral_mesh_3::Point_3, 8> corners(const HR::Hexahedral_mesh_3& m, std::size_t h)
{
  std::array<HR::Hexahedral_mesh_3::Point_3, 8> p;
  for(int i = 0; i < 8; ++i)
    p[i] = m.points[m.hexahedra[h][i]];
  return p;
}

} // namespace

// The generators: every corner positively oriented, every quad used once (boundary) or twice, counts as
// computed by hand.
TEST(HexMeshGenerators, ValidAndCountsAsDesigned)
{
  for(const auto& g : T::all_generated_hex_meshes()) {
    SCOPED_TRACE(g.name);
    const auto& m = g.mesh;
    EXPECT_EQ(m.hexahedra.size(), g.expected.hexahedra);
    EXPECT_EQ(m.points.size(), g.expected.vertices);
    for(std::size_t h = 0; h < m.hexahedra.size(); ++h) {
      const auto p = corners(m, h);
      for(int c = 0; c < 8; ++c)
        EXPECT_GT(HR::internal::hex_corner_scaled_jacobian(p, c), 0.2) << "hex " << h << " corner " << c;
      EXPECT_GT(HR::internal::hex_signed_volume(p), 0.);
    }
    std::map<std::array<HR::Hexahedral_mesh_3::Index, 4>, int> uses;
    for(const auto& h : m.hexahedra)
      for(const auto& f : HR::internal::hex_faces()) {
        std::array<HR::Hexahedral_mesh_3::Index, 4> key{ {h[f[0]], h[f[1]], h[f[2]], h[f[3]]} };
        std::sort(key.begin(), key.end());
        ++uses[key];
      }
    std::size_t boundary = 0;
    for(const auto& u : uses) {
      EXPECT_LE(u.second, 2);
      boundary += (u.second == 1);
    }
    EXPECT_EQ(boundary, g.expected.boundary_quads);
  }
}

// The map: 24 tets per hex, positive in parameter space and in space, conforming (every tet face in at
// most two tets), transitions on all interior faces, and the integer points of the parameter domain at
// the hex corners scaled by k.
TEST(HexMeshGenerators, MapFromHexMesh)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  for(int k = 1; k <= 3; ++k)
    for(const auto& g : T::all_generated_hex_meshes()) {
      SCOPED_TRACE(g.name + " k=" + std::to_string(k));
      const HR::Integer_grid_map map = T::map_from_hex_mesh(g.mesh, k, 17u + k);
      ASSERT_EQ(map.tetrahedra.size(), 24 * g.mesh.hexahedra.size());
      ASSERT_EQ(map.parameters.size(), map.tetrahedra.size());
      std::map<std::array<std::uint32_t, 3>, int> face_uses;
      for(std::size_t t = 0; t < map.tetrahedra.size(); ++t) {
        const auto& tet = map.tetrahedra[t];
        EXPECT_EQ(CGAL::orientation(map.points[tet[0]], map.points[tet[1]], map.points[tet[2]], map.points[tet[3]]),
                  CGAL::POSITIVE);
        const auto& u = map.parameters[t];
        const K::Point_3 q[4] = {K::Point_3(u[0][0], u[0][1], u[0][2]), K::Point_3(u[1][0], u[1][1], u[1][2]),
                                 K::Point_3(u[2][0], u[2][1], u[2][2]), K::Point_3(u[3][0], u[3][1], u[3][2])};
        EXPECT_EQ(CGAL::orientation(q[0], q[1], q[2], q[3]), CGAL::POSITIVE);
        // the two hex corners of the tet sit at integer points, one hex edge = k apart
        EXPECT_DOUBLE_EQ((u[0] - u[1]).norm(), double(k));
        EXPECT_TRUE((u[0].array() == u[0].array().round()).all());
        for(int o = 0; o < 4; ++o) {
          std::array<std::uint32_t, 3> key;
          for(int j = 0, n = 0; j < 4; ++j)
            if(j != o)
              key[n++] = tet[j];
          std::sort(key.begin(), key.end());
          ++face_uses[key];
        }
      }
      std::size_t interior = 0, boundary = 0;
      for(const auto& f : face_uses) {
        EXPECT_LE(f.second, 2);
        (f.second == 2 ? interior : boundary) += 1;
      }
      EXPECT_EQ(boundary, 4 * g.expected.boundary_quads);
      EXPECT_EQ(map.transitions.size(), interior);
      std::size_t non_identity = 0;
      for(const auto& tr : map.transitions)
        non_identity += (tr.rotation != 0 || !tr.translation.isZero());
      // the faces between hexes (4 tet faces per quad) carry the random transitions
      const std::size_t inner_quads = (6 * g.mesh.hexahedra.size() - g.expected.boundary_quads) / 2;
      EXPECT_LE(non_identity, 4 * inner_quads);
      if(inner_quads > 0) {
        EXPECT_GT(non_identity, 0u);
      }
    }
}

// The checker on the generated meshes: valid, and the counts and irregular edges counted by hand.
TEST(CheckHexahedralMesh, GeneratedMeshesMatchTheirOracles)
{
  for(const auto& g : T::all_generated_hex_meshes()) {
    SCOPED_TRACE(g.name);
    const HR::Hexahedral_mesh_check c = HR::check_hexahedral_mesh(g.mesh);
    EXPECT_TRUE(c.valid);
    EXPECT_TRUE(c.conforming);
    EXPECT_TRUE(c.manifold_boundary);
    EXPECT_EQ(c.hexahedra, g.expected.hexahedra);
    EXPECT_EQ(c.vertices, g.expected.vertices);
    EXPECT_EQ(c.unused_vertices, 0u);
    EXPECT_EQ(c.boundary_quads, g.expected.boundary_quads);
    EXPECT_EQ(c.interior_quads, (6 * g.expected.hexahedra - g.expected.boundary_quads) / 2);
    EXPECT_EQ(c.boundary_euler_characteristic, g.expected.boundary_euler_characteristic);
    EXPECT_EQ(c.boundary_components, 1u);
    EXPECT_EQ(c.duplicate_vertices, 0u);
    EXPECT_EQ(c.duplicate_hexahedra, 0u);
    EXPECT_EQ(c.inverted_hexahedra, 0u);
    EXPECT_GT(c.min_scaled_jacobian, 0.2);
    EXPECT_EQ(c.irregular_interior_edges, g.expected.interior_irregular_edges);
    EXPECT_EQ(c.irregular_boundary_edges, g.expected.boundary_irregular_edges);
    EXPECT_EQ(c.irregular_interior_chains, g.expected.interior_irregular_chains);
    // a closed surface of quads: 2 E = 4 F
    EXPECT_EQ(2 * c.boundary_edges, 4 * c.boundary_quads);
  }
}

TEST(CheckHexahedralMesh, GridCountsAndVolumes)
{
  const int a = 2, b = 3, cc = 4;
  const auto g = T::make_grid(a, b, cc, 0.5);
  const auto c = HR::check_hexahedral_mesh(g.mesh);
  EXPECT_EQ(c.interior_edges, std::size_t(a * (b - 1) * (cc - 1) + (a - 1) * b * (cc - 1) + (a - 1) * (b - 1) * cc));
  EXPECT_EQ(c.interior_edge_valences.size(), 1u);
  EXPECT_EQ(c.boundary_vertices, std::size_t((a + 1) * (b + 1) * (cc + 1) - (a - 1) * (b - 1) * (cc - 1)));
  EXPECT_NEAR(c.min_scaled_jacobian, 1., 1e-12);
  EXPECT_NEAR(c.mean_scaled_jacobian, 1., 1e-12);
  EXPECT_EQ(c.low_quality_share, 0.);
  EXPECT_NEAR(c.total_volume, a * b * cc * 0.125, 1e-12);

  const auto L = T::make_L_block(2, 3);
  EXPECT_NEAR(HR::check_hexahedral_mesh(L.mesh).total_volume, 3 * 4 * 3, 1e-10);
  const double pi = 3.14159265358979323846;
  for(int n : {3, 5, 6}) {
    const auto p = T::make_polygon_prism(n, 4, 0.5);
    // planar faces: the 24-tet volume is exact, area of the n-gon x height
    EXPECT_NEAR(HR::check_hexahedral_mesh(p.mesh).total_volume, 0.5 * n * std::sin(2 * pi / n) * 2., 1e-12);
  }
  // the twist preserves volume; the bilinear faces only approximately
  EXPECT_NEAR(HR::check_hexahedral_mesh(T::make_twisted_grid(3, 3, 4).mesh).total_volume, 36., 0.36);
  const double ball = HR::check_hexahedral_mesh(T::make_cubed_ball(3, 2).mesh).total_volume;
  EXPECT_LT(ball, 4. / 3. * pi);
  EXPECT_GT(ball, 0.85 * 4. / 3. * pi);
}

TEST(CheckHexahedralMesh, PrismAxisIsOneChainOfValenceN)
{
  for(int n : {3, 5, 6})
    for(int layers : {1, 3}) {
      const auto c = HR::check_hexahedral_mesh(T::make_polygon_prism(n, layers).mesh);
      const std::map<int, std::size_t> axis{ {n, std::size_t(layers)} };
      EXPECT_EQ(c.irregular_interior_edges, axis) << n << " " << layers;
      EXPECT_EQ(c.irregular_interior_chains, (std::map<int, std::size_t>{ {n, 1u} })) << n << " " << layers;
    }
  // n = 4: a plain 2 x 2 grid in disguise
  EXPECT_TRUE(HR::check_hexahedral_mesh(T::make_polygon_prism(4, 2).mesh).irregular_interior_edges.empty());
}

TEST(CheckHexahedralMesh, FlatHexahedraAreNotValid)
{
  // a unit cube sheared flat: the top face at height h moved by one edge length along x; every corner
  // has its third edge at an angle ~h off the bottom plane, so the scaled Jacobian is ~h > 0
  for(double h : {1e-8, 1e-1}) {
    auto g = T::make_grid(1, 1, 1);
    for(auto& p : g.mesh.points)
      if(p.z() > 0.5) p = HR::Hexahedral_mesh_3::Point_3(p.x() + 1., p.y(), h);
    const auto c = HR::check_hexahedral_mesh(g.mesh);
    const double expected = h / std::sqrt(1. + h * h);  // det of (1,0,0), (0,1,0), (1,0,h)/|.|
    EXPECT_NEAR(c.min_scaled_jacobian, expected, 1e-3 * expected) << h;
    EXPECT_TRUE(c.conforming);
    EXPECT_TRUE(c.manifold_boundary);
    EXPECT_EQ(c.inverted_hexahedra, 0u);
    EXPECT_EQ(c.flat_hexahedra, h < 1e-6 ? 1u : 0u) << h;
    EXPECT_EQ(c.valid, h > 1e-6) << h;
    // a threshold of 0 accepts any positive corner
    EXPECT_TRUE(HR::check_hexahedral_mesh(g.mesh, HR::parameters::flat_scaled_jacobian_threshold(0.)).valid) << h;
  }
  EXPECT_THROW(HR::check_hexahedral_mesh(T::make_grid(1, 1, 1).mesh, HR::parameters::flat_scaled_jacobian_threshold(1.)),
               HR::Error);
}

TEST(CheckHexahedralMesh, InvertedHexahedra)
{
  // geometrically inverted corner, combinatorially fine
  auto g = T::make_grid(1, 1, 1);
  g.mesh.points[6] = HR::Hexahedral_mesh_3::Point_3(0.2, 0.2, 0.2);
  auto c = HR::check_hexahedral_mesh(g.mesh);
  EXPECT_TRUE(c.conforming);
  EXPECT_EQ(c.inverted_hexahedra, 1u);
  EXPECT_LT(c.min_scaled_jacobian, 0.);
  EXPECT_FALSE(c.valid);

  // mirrored vertex order of a corner hex of a 2x2x2 grid: negative and its 3 inner faces same-oriented
  g = T::make_grid(2, 2, 2);
  std::swap(g.mesh.hexahedra[0][1], g.mesh.hexahedra[0][3]);
  std::swap(g.mesh.hexahedra[0][5], g.mesh.hexahedra[0][7]);
  c = HR::check_hexahedral_mesh(g.mesh);
  EXPECT_EQ(c.inverted_hexahedra, 1u);
  EXPECT_NEAR(c.min_scaled_jacobian, -1., 1e-12);
  EXPECT_EQ(c.same_orientation_quads, 3u);
  EXPECT_EQ(c.non_conforming_quads, 3u);
  EXPECT_FALSE(c.conforming);
  EXPECT_FALSE(c.valid);
  EXPECT_NEAR(c.total_volume, 6., 1e-12);
}

TEST(CheckHexahedralMesh, DuplicatedHexahedronAndVertex)
{
  auto g = T::make_grid(2, 2, 2);
  g.mesh.hexahedra.push_back(g.mesh.hexahedra[0]);
  auto c = HR::check_hexahedral_mesh(g.mesh);
  EXPECT_EQ(c.duplicate_hexahedra, 1u);
  EXPECT_EQ(c.same_orientation_quads, 3u);  // its 3 boundary faces, now in 2 hexes the same way
  EXPECT_EQ(c.overused_quads, 3u);          // its 3 inner faces, now in 3 hexes
  EXPECT_FALSE(c.valid);

  // a vertex split in two coincident copies: a crack between the hexes
  g = T::make_grid(2, 1, 1);
  const auto copy = static_cast<HR::Hexahedral_mesh_3::Index>(g.mesh.points.size());
  g.mesh.points.push_back(g.mesh.points[1]);
  g.mesh.hexahedra[1][0] = copy;  // vertex 1 is corner 0 of the second hex
  c = HR::check_hexahedral_mesh(g.mesh);
  EXPECT_EQ(c.duplicate_vertices, 1u);
  EXPECT_FALSE(c.valid);
  // an unused vertex is counted, not a defect
  g = T::make_grid(1, 1, 1);
  g.mesh.points.emplace_back(5., 5., 5.);
  c = HR::check_hexahedral_mesh(g.mesh);
  EXPECT_EQ(c.unused_vertices, 1u);
  EXPECT_TRUE(c.valid);
}

TEST(CheckHexahedralMesh, MissingHexahedra)
{
  // the centre of a 3x3x3 grid removed: an inner spherical boundary with 12 concave edges
  auto g = T::make_grid(3, 3, 3);
  g.mesh.hexahedra.erase(g.mesh.hexahedra.begin() + 13);
  auto c = HR::check_hexahedral_mesh(g.mesh);
  EXPECT_TRUE(c.valid);
  EXPECT_EQ(c.boundary_quads, 54u + 6u);
  EXPECT_EQ(c.boundary_components, 2u);
  EXPECT_EQ(c.boundary_euler_characteristic, 4);
  const std::map<int, std::size_t> boundary{ {1, 36u}, {3, 12u} };
  EXPECT_EQ(c.irregular_boundary_edges, boundary);
  EXPECT_TRUE(c.irregular_interior_edges.empty());
  EXPECT_NEAR(c.total_volume, 26., 1e-12);

  // 2x2x1 without two opposite hexes: the two left touch along one edge only
  g = T::make_grid(2, 2, 1);
  g.mesh.hexahedra = {g.mesh.hexahedra[0], g.mesh.hexahedra[3]};
  c = HR::check_hexahedral_mesh(g.mesh);
  EXPECT_TRUE(c.conforming);
  EXPECT_EQ(c.non_manifold_boundary_edges, 1u);    // the shared vertical edge, in 4 boundary quads
  EXPECT_EQ(c.non_manifold_boundary_vertices, 2u); // its ends: links of two cycles
  EXPECT_FALSE(c.manifold_boundary);
  EXPECT_FALSE(c.valid);
  EXPECT_EQ(c.boundary_components, 1u);

  // a hex with a repeated vertex and one with an index out of range are left out and counted
  g = T::make_grid(2, 1, 1);
  g.mesh.hexahedra.push_back(g.mesh.hexahedra[0]);
  g.mesh.hexahedra.back()[7] = g.mesh.hexahedra.back()[0];
  g.mesh.hexahedra.push_back(g.mesh.hexahedra[0]);
  g.mesh.hexahedra.back()[3] = 1000;
  c = HR::check_hexahedral_mesh(g.mesh);
  EXPECT_EQ(c.invalid_hexahedra, 2u);
  EXPECT_EQ(c.boundary_quads, 10u);
  EXPECT_FALSE(c.valid);

  EXPECT_FALSE(HR::check_hexahedral_mesh(HR::Hexahedral_mesh_3()).valid);
}

// The grid hashing of the duplicate search against the brute-force count on clustered random points.
TEST(CheckHexahedralMesh, DuplicateVerticesAgainstBruteForce)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0., 1.), jitter(-0.009, 0.009);
  typedef HR::Hexahedral_mesh_3::Point_3 P;
  for(double tolerance : {0.01, 0.02, 0.05}) {
    std::vector<P> points;
    for(int i = 0; i < 600; ++i) {
      if(i > 0 && i % 3 == 0) {
        const P& q = points[rng() % points.size()];
        points.emplace_back(q.x() + jitter(rng), q.y() + jitter(rng), q.z() + jitter(rng));
      } else {
        points.emplace_back(unit(rng), unit(rng), unit(rng));
      }
    }
    std::vector<bool> used(points.size(), true);
    used[7] = false;
    std::size_t brute = 0;
    for(std::size_t v = 0; v < points.size(); ++v) {
      if(!used[v]) continue;
      bool d = false;
      for(std::size_t w = 0; w < v && !d; ++w)
        d = used[w] && CGAL::squared_distance(points[v], points[w]) < tolerance * tolerance;
      brute += d;
    }
    EXPECT_GT(brute, 50u);
    EXPECT_EQ(HR::internal::count_duplicate_vertices(points, used, tolerance), brute) << tolerance;
  }
}

TEST(CheckHexahedralMesh, OverlappingHexesSharingAFaceTheSameWay)
{
  // B = [0.5, 1] x [0, 1]^2 shares A's face x = 1 but lies on A's side: both positive, not conforming
  auto g = T::make_grid(1, 1, 1);
  typedef HR::Hexahedral_mesh_3::Point_3 P;
  const auto& A = g.mesh.hexahedra[0];
  const auto n = static_cast<HR::Hexahedral_mesh_3::Index>(g.mesh.points.size());
  g.mesh.points.push_back(P(0.5, 0, 0));
  g.mesh.points.push_back(P(0.5, 1, 0));
  g.mesh.points.push_back(P(0.5, 1, 1));
  g.mesh.points.push_back(P(0.5, 0, 1));
  const std::array<HR::Hexahedral_mesh_3::Index, 8> B{ {n, A[1], A[2], n + 1, n + 3, A[5], A[6], n + 2} };
  g.mesh.hexahedra.push_back(B);
  const auto c = HR::check_hexahedral_mesh(g.mesh);
  EXPECT_GT(c.min_scaled_jacobian, 0.99);
  EXPECT_EQ(c.same_orientation_quads, 1u);
  EXPECT_FALSE(c.conforming);
  EXPECT_FALSE(c.valid);
}

TEST(CheckHexahedralMesh, NamedParameters)
{
  auto g = T::make_twisted_grid(3, 3, 4, 1.2);
  const auto sj = HR::hexahedra_scaled_jacobians(g.mesh);
  const double mid = 0.5 * (*std::min_element(sj.begin(), sj.end()) + *std::max_element(sj.begin(), sj.end()));
  std::size_t below = 0;
  for(double s : sj) below += (s < mid);
  const auto c = HR::check_hexahedral_mesh(g.mesh, HR::parameters::low_scaled_jacobian_threshold(mid));
  EXPECT_DOUBLE_EQ(c.low_quality_share, double(below) / double(sj.size()));
  EXPECT_DOUBLE_EQ(c.min_scaled_jacobian, *std::min_element(sj.begin(), sj.end()));
  // vertices 0.01 apart in a box of diagonal ~2.4: duplicates at a relative tolerance of 1e-2, not at 1e-9
  g = T::make_grid(2, 1, 1);
  const auto copy = static_cast<HR::Hexahedral_mesh_3::Index>(g.mesh.points.size());
  g.mesh.points.push_back(HR::Hexahedral_mesh_3::Point_3(1.01, 0., 0.));
  g.mesh.hexahedra[1][0] = copy;
  EXPECT_EQ(HR::check_hexahedral_mesh(g.mesh).duplicate_vertices, 0u);
  EXPECT_EQ(HR::check_hexahedral_mesh(g.mesh, HR::parameters::duplicate_vertex_tolerance(1e-2)).duplicate_vertices, 1u);
}

namespace {

std::string temp_file(const std::string& name)
{
  return (std::filesystem::temp_directory_path() / ("hexmesh3_" + std::to_string(::getpid()) + "_" + name)).string();
}

std::string file_text(const std::string& filename)
{
  std::ifstream in(filename);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void expect_same_mesh(const HR::Hexahedral_mesh_3& a, const HR::Hexahedral_mesh_3& b)
{
  ASSERT_EQ(a.points.size(), b.points.size());
  for(std::size_t v = 0; v < a.points.size(); ++v)
    EXPECT_EQ(a.points[v], b.points[v]) << v;  // 17 digits: exact round trip
  EXPECT_EQ(a.hexahedra, b.hexahedra);
  EXPECT_EQ(a.vertex_tags, b.vertex_tags);
}

} // namespace

TEST(HexahedralMeshIO, RoundTripMEDITAndVTK)
{
  auto g = T::make_cubed_ball(3, 1);
  auto& m = g.mesh;
  m.vertex_tags.resize(m.points.size());
  for(std::size_t v = 0; v < m.points.size(); ++v)
    m.vertex_tags[v] = std::uint8_t(v % 8);
  m.hexahedron_source_tetrahedra.resize(m.hexahedra.size());
  for(std::size_t h = 0; h < m.hexahedra.size(); ++h)
    m.hexahedron_source_tetrahedra[h] = HR::Hexahedral_mesh_3::Index(3 * h);
  m.hexahedron_source_tetrahedra[5] = (std::numeric_limits<HR::Hexahedral_mesh_3::Index>::max)();

  for(const std::string ext : {"mesh", "vtk", "VTK"}) {
    SCOPED_TRACE(ext);
    const std::string file = temp_file("round_trip." + ext);
    HR::IO::write_hexahedral_mesh(file, m);
    EXPECT_FALSE(std::filesystem::exists(file + ".tmp"));
    HR::Hexahedral_mesh_3 back;
    HR::IO::read_hexahedral_mesh(file, back);
    expect_same_mesh(m, back);
    if(ext != "mesh") {
      EXPECT_EQ(back.hexahedron_source_tetrahedra, m.hexahedron_source_tetrahedra);
      const std::string text = file_text(file);
      EXPECT_NE(text.find("CELL_TYPES 81\n12\n"), std::string::npos);
      EXPECT_NE(text.find("SCALARS scaled_jacobian double 1"), std::string::npos);
      EXPECT_NE(text.find("SCALARS tags double 1"), std::string::npos);
    } else {
      EXPECT_TRUE(back.hexahedron_source_tetrahedra.empty());  // MEDIT has no place for them
      EXPECT_NE(file_text(file).find("Hexahedra\n81\n"), std::string::npos);
    }
    EXPECT_TRUE(HR::check_hexahedral_mesh(back).valid);
    std::remove(file.c_str());
  }

  // without the optional arrays: MEDIT refs 0 read back as all-zero tags, VTK without arrays as none
  auto plain = T::make_grid(1, 2, 1).mesh;
  const std::string vtk = temp_file("plain.vtk"), medit = temp_file("plain.mesh");
  HR::IO::write_VTK(vtk, plain);
  HR::IO::write_MEDIT(medit, plain);
  HR::Hexahedral_mesh_3 back;
  HR::IO::read_hexahedral_mesh(vtk, back);
  EXPECT_TRUE(back.vertex_tags.empty());
  EXPECT_TRUE(back.hexahedron_source_tetrahedra.empty());
  EXPECT_EQ(back.hexahedra, plain.hexahedra);
  HR::IO::read_hexahedral_mesh(medit, back);
  EXPECT_EQ(back.vertex_tags, std::vector<std::uint8_t>(plain.points.size(), 0));
  EXPECT_EQ(back.hexahedra, plain.hexahedra);
  std::remove(vtk.c_str());
  std::remove(medit.c_str());
}

// Boundary groups of a 3 x 2 x 1 box from its own boundary, checked from the cells: each patch is one
// side of the box (every quad's vertices on that plane), the feature edges are the 12 box edges.
TEST(HexahedralBoundaryGroups, BoxFromItsOwnSharpEdges)
{
  auto m = T::make_grid(3, 2, 1).mesh;
  const HR::Hexahedral_boundary_groups_report r = HR::compute_hexahedral_boundary_groups(m);
  EXPECT_EQ(r.boundary_quadrilaterals, 2u * (6 + 2 + 3));
  EXPECT_EQ(r.patches, 6u);
  EXPECT_EQ(r.curves, 12u);
  EXPECT_EQ(r.feature_edges, 4u * (3 + 2 + 1));
  const double extent[3] = {3, 2, 1};
  std::map<int, std::set<std::pair<int, double> > > planes;  // patch -> the (axis, value) its quads share
  std::map<int, std::size_t> quads_per_patch;
  for(const auto& q : m.boundary_quadrilaterals) {
    ++quads_per_patch[q.patch];
    std::set<std::pair<int, double> > common;
    for(int d = 0; d < 3; ++d) {
      bool same = true;
      for(auto v : q.vertices) same = same && m.points[v][d] == m.points[q.vertices[0]][d];
      if(same) common.insert(std::make_pair(d, m.points[q.vertices[0]][d]));
    }
    ASSERT_EQ(common.size(), 1u);
    EXPECT_TRUE(common.begin()->second == 0 || common.begin()->second == extent[common.begin()->first]);
    planes[q.patch].insert(*common.begin());
    // outward: the normal points away from the box centre
    const auto& p = m.points;
    const auto n = CGAL::cross_product(p[q.vertices[1]] - p[q.vertices[0]], p[q.vertices[2]] - p[q.vertices[0]]);
    const HR::Hexahedral_mesh_3::Point_3 centre(1.5, 1, 0.5);
    EXPECT_GT(n * (p[q.vertices[0]] - centre), 0);
    // face numbering: the quad is face q.face of its hexahedron
    for(int i = 0; i < 4; ++i) EXPECT_EQ(q.vertices[i], m.hexahedra[q.hexahedron][HR::internal::hex_faces()[q.face][i]]);
  }
  for(const auto& kv : planes) EXPECT_EQ(kv.second.size(), 1u) << "patch " << kv.first << " spans several sides";
  std::multiset<std::size_t> sizes;
  for(const auto& kv : quads_per_patch) sizes.insert(kv.second);
  EXPECT_EQ(sizes, (std::multiset<std::size_t>{2, 2, 3, 3, 6, 6}));
  for(const auto& e : m.feature_edges) {
    int on_sides = 0;  // a box edge lies on two sides
    for(int d = 0; d < 3; ++d) {
      const double a = m.points[e.vertices[0]][d], b = m.points[e.vertices[1]][d];
      on_sides += a == b && (a == 0 || a == extent[d]);
    }
    EXPECT_EQ(on_sides, 2);
  }
}

// Boundary groups from a tet mesh of the same 3 x 2 x 1 box whose boundary triangles carry no tag (a
// single unnamed patch, as in the MAMBO VTK files): the six sides between the sharp edges, as from the
// hex mesh's own boundary; with the patch named, that one named group.
TEST(HexahedralBoundaryGroups, UntaggedTrianglesGiveTheSidesBetweenSharpEdges)
{
  // the box in 6 tetrahedra around the diagonal (0,0,0)-(3,2,1), its 12 boundary triangles untagged
  std::ostringstream vtk;
  vtk << "# vtk DataFile Version 2.0\nbox\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 8 double\n";
  for(int i = 0; i < 8; ++i) vtk << 3 * (i & 1) << ' ' << 2 * ((i >> 1) & 1) << ' ' << ((i >> 2) & 1) << '\n';
  const int tets[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};
  const int sides[12][3] = {{0, 1, 3}, {0, 2, 3}, {4, 5, 7}, {4, 6, 7}, {0, 1, 5}, {0, 4, 5},
                            {2, 3, 7}, {2, 6, 7}, {0, 2, 6}, {0, 4, 6}, {1, 3, 7}, {1, 5, 7}};
  // and its 12 edges as untagged lines (one curve id for all, as in the MAMBO files)
  std::vector<std::array<int, 2> > lines;
  for(int a = 0; a < 8; ++a)
    for(int d = 0; d < 3; ++d)
      if(!(a & (1 << d))) lines.push_back({ {a, a | (1 << d)} });
  vtk << "CELLS 30 " << 6 * 5 + 12 * 4 + 12 * 3 << '\n';
  for(const auto& t : tets) vtk << "4 " << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << t[3] << '\n';
  for(const auto& t : sides) vtk << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  for(const auto& l : lines) vtk << "2 " << l[0] << ' ' << l[1] << '\n';
  vtk << "CELL_TYPES 30\n";
  for(int i = 0; i < 30; ++i) vtk << (i < 6 ? 10 : i < 18 ? 5 : 3) << '\n';
  HR::Tetrahedral_soup_3<HR::Tetrahedral_mesh_3<>::Point_3> soup;
  HR::IO::read_VTK(vtk.str(), "box.vtk", soup);
  HR::Tetrahedral_mesh_3<> tets_mesh;
  HR::build_tetrahedral_mesh(soup, tets_mesh);
  ASSERT_EQ(tets_mesh.number_of_surface_patches(), 1u);
  ASSERT_EQ(tets_mesh.number_of_feature_curves(), 1u);

  auto m = T::make_grid(3, 2, 1).mesh;
  HR::Hexahedral_boundary_groups_report r = HR::compute_hexahedral_boundary_groups(m, tets_mesh);
  EXPECT_EQ(r.patches, 6u);
  EXPECT_EQ(r.curves, 12u);
  EXPECT_EQ(r.feature_edges, 4u * (3 + 2 + 1));
  for(const auto& q : m.boundary_quadrilaterals) {  // each patch on one side of the box
    int on_plane = 0;
    for(int d = 0; d < 3; ++d) {
      bool same = true;
      for(auto v : q.vertices) same = same && m.points[v][d] == m.points[q.vertices[0]][d];
      on_plane += same;
    }
    EXPECT_EQ(on_plane, 1);
  }
  std::map<int, std::set<std::array<double, 3> > > normals;
  for(const auto& q : m.boundary_quadrilaterals) {
    const auto n = CGAL::cross_product(m.points[q.vertices[1]] - m.points[q.vertices[0]], m.points[q.vertices[2]] - m.points[q.vertices[0]]);
    normals[q.patch].insert({ {n.x() > 0 ? 1. : n.x() < 0 ? -1. : 0., n.y() > 0 ? 1. : n.y() < 0 ? -1. : 0., n.z() > 0 ? 1. : n.z() < 0 ? -1. : 0.} });
  }
  EXPECT_EQ(normals.size(), 6u);
  for(const auto& kv : normals) EXPECT_EQ(kv.second.size(), 1u) << "patch " << kv.first << " spans several sides";

  soup.patch_names = {{0, "wall"}};
  HR::Tetrahedral_mesh_3<> named;
  HR::build_tetrahedral_mesh(soup, named);
  auto n = T::make_grid(3, 2, 1).mesh;
  r = HR::compute_hexahedral_boundary_groups(n, named);
  EXPECT_EQ(r.patches, 1u);
  EXPECT_EQ(r.feature_edges, 0u);
  ASSERT_EQ(n.patch_names.size(), 1u);
  EXPECT_EQ(n.patch_names[0].second, "wall");
}

// Every writer carries the groups: MEDIT's Quadrilaterals read back by the package's reader, the
// others checked by test_hexmesh_cli.sh with an independent parser and gmsh's Python module.
TEST(HexahedralMeshIO, SolverFormatsAreWrittenAtomically)
{
  auto m = T::make_grid(2, 1, 1).mesh;
  for(const std::string ext : {"inp", "msh", "vtu", "mesh"}) {
    SCOPED_TRACE(ext);
    const std::string file = temp_file("groups." + ext);
    HR::IO::write_hexahedral_mesh(file, m);
    EXPECT_TRUE(std::filesystem::exists(file));
    EXPECT_FALSE(std::filesystem::exists(file + ".tmp"));
    EXPECT_FALSE(std::filesystem::exists(file + ".tmp.msh"));
    const std::string text = file_text(file);
    if(ext == "inp") {
      EXPECT_NE(text.find("*ELEMENT, TYPE=C3D8, ELSET=PART\n1, 1, 2, 5, 4, 7, 8, 11, 10\n"), std::string::npos) << text.substr(0, 600);
      EXPECT_NE(text.find("*SURFACE, NAME=patch_"), std::string::npos);
    }
    if(ext == "mesh") {
      EXPECT_NE(text.find("Quadrilaterals\n10\n"), std::string::npos);
      HR::Hexahedral_mesh_3 back;
      HR::IO::read_hexahedral_mesh(file, back);
      EXPECT_EQ(back.hexahedra, m.hexahedra);
    }
    if(ext == "vtu") EXPECT_NE(text.find("Name=\"patch\""), std::string::npos);
    if(ext == "msh") EXPECT_NE(text.find("$PhysicalNames\n"), std::string::npos);
    std::remove(file.c_str());
  }
}

// Hex meshes from other tools: written in the mirrored vertex order, or mixing both orders; oriented
// back (every hexahedron positive, checked by check_hexahedral_mesh from the cells), the same vertices
// and cells; a degenerate hexahedron and a quad in three hexahedra refused.
TEST(HexahedralMeshOrientation, MirroredAndMixedMeshesAreOriented)
{
  const auto grid = T::make_grid(3, 2, 2).mesh;
  auto mirror = [](std::array<std::uint32_t, 8> h) {
    return std::array<std::uint32_t, 8>{ {h[0], h[3], h[2], h[1], h[4], h[7], h[6], h[5]} };
  };
  auto same_cells = [](const HR::Hexahedral_mesh_3& a, const HR::Hexahedral_mesh_3& b) {
    if(a.hexahedra.size() != b.hexahedra.size()) return false;
    for(std::size_t h = 0; h < a.hexahedra.size(); ++h) {
      auto x = a.hexahedra[h], y = b.hexahedra[h];
      std::sort(x.begin(), x.end());
      std::sort(y.begin(), y.end());
      if(x != y) return false;
    }
    return true;
  };
  for(int mode = 0; mode < 3; ++mode) {
    SCOPED_TRACE(mode);
    auto m = grid;
    for(std::size_t h = 0; h < m.hexahedra.size(); ++h)
      if(mode == 1 || (mode == 2 && h % 3 != 0)) m.hexahedra[h] = mirror(m.hexahedra[h]);
    const std::size_t expected = mode == 0 ? 0 : mode == 1 ? m.hexahedra.size() : m.hexahedra.size() - (m.hexahedra.size() + 2) / 3;
    if(mode > 0) EXPECT_FALSE(HR::check_hexahedral_mesh(m).valid);
    const HR::Hexahedral_orientation_result r = HR::orient_hexahedral_mesh(m);
    EXPECT_EQ(r.reoriented, expected);
    EXPECT_EQ(r.components, 1u);
    EXPECT_EQ(r.mirrored_components, mode == 1 ? 1u : 0u);
    const HR::Hexahedral_mesh_check c = HR::check_hexahedral_mesh(m);
    EXPECT_TRUE(c.valid);
    EXPECT_EQ(c.inverted_hexahedra, 0u);
    EXPECT_NEAR(c.min_scaled_jacobian, 1.0, 1e-12);
    EXPECT_EQ(m.points, grid.points);
    EXPECT_TRUE(same_cells(m, grid));
  }
  auto degenerate = grid;
  degenerate.hexahedra[4][6] = degenerate.hexahedra[4][2];
  try {
    HR::orient_hexahedral_mesh(degenerate, "d.mesh");
    ADD_FAILURE() << "a degenerate hexahedron was accepted";
  } catch(const HR::Input_error& e) {
    EXPECT_NE(std::string(e.what()).find("hexahedron 4 lists vertex"), std::string::npos) << e.what();
  }
  auto three = T::make_grid(1, 1, 2).mesh;
  three.hexahedra.push_back(three.hexahedra[0]); // the quad between the two cells, now in three
  three.hexahedra.back()[0] = three.hexahedra[1][4];
  EXPECT_THROW(HR::orient_hexahedral_mesh(three), HR::Input_error);
}

TEST(HexahedralMeshIO, WritersRejectBrokenMeshesAndLeaveNoFile)
{
  auto m = T::make_grid(1, 1, 1).mesh;
  m.hexahedra[0][3] = 99;
  for(const std::string ext : {"mesh", "vtk"}) {
    const std::string file = temp_file("broken." + ext);
    EXPECT_THROW(HR::IO::write_hexahedral_mesh(file, m), HR::Error);
    EXPECT_FALSE(std::filesystem::exists(file));
    EXPECT_FALSE(std::filesystem::exists(file + ".tmp"));
  }
  auto ok = T::make_grid(1, 1, 1).mesh;
  ok.vertex_tags.assign(3, 0);  // wrong size
  EXPECT_THROW(HR::IO::write_VTK(temp_file("tags.vtk"), ok), HR::Error);
  EXPECT_FALSE(std::filesystem::exists(temp_file("tags.vtk")));
  EXPECT_THROW(HR::IO::write_hexahedral_mesh(temp_file("x.obj"), T::make_grid(1, 1, 1).mesh), HR::Error);
  EXPECT_THROW(HR::IO::write_hexahedral_mesh("/nonexistent_dir_hexmesh3/x.vtk", T::make_grid(1, 1, 1).mesh), HR::Error);
}

TEST(HexahedralMeshIO, ReadersRejectDefectsClearly)
{
  const std::string medit_ok =
    "MeshVersionFormatted 1\nDimension 3\nVertices\n8\n"
    "0 0 0 0\n1 0 0 0\n1 1 0 0\n0 1 0 0\n0 0 1 0\n1 0 1 0\n1 1 1 0\n0 1 1 0\n"
    "Hexahedra\n1\n1 2 3 4 5 6 7 8 1\nEnd\n";
  HR::Hexahedral_mesh_3 m;
  HR::IO::read_hexahedral_mesh_MEDIT(medit_ok, "ok.mesh", m);
  EXPECT_EQ(m.hexahedra.size(), 1u);
  EXPECT_NEAR(HR::check_hexahedral_mesh(m).min_scaled_jacobian, 1., 1e-15);

  auto expect_error = [](const std::string& text, bool vtk, const std::string& words, std::size_t line) {
    HR::Hexahedral_mesh_3 out;
    try {
      if(vtk) HR::IO::read_hexahedral_mesh_VTK(text, "bad", out);
      else HR::IO::read_hexahedral_mesh_MEDIT(text, "bad", out);
      ADD_FAILURE() << "no error for: " << words;
    } catch(const HR::Input_error& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
      if(line > 0) {
        EXPECT_EQ(e.line(), line) << e.what();
      }
    }
  };
  auto replace = [](std::string s, const std::string& from, const std::string& to) {
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  expect_error(medit_ok.substr(0, medit_ok.size() - 12), false, "unexpected end of file", 0);
  expect_error(replace(medit_ok, "1 2 3 4 5 6 7 8 1", "1 2 3 4 5 6 7 9 1"), false, "out of range", 15);
  expect_error(replace(medit_ok, "1 2 3 4 5 6 7 8 1", "0 2 3 4 5 6 7 8 1"), false, "1-based", 15);
  expect_error(replace(medit_ok, "1 1 0 0\n0 1 0 0", "1 nan 0 0\n0 1 0 0"), false, "non-finite", 7);
  expect_error(replace(medit_ok, "Hexahedra\n1\n", "Hexahedra\n1000\n"), false, "exceeds", 0);
  expect_error(replace(medit_ok, "Hexahedra\n1\n1 2 3 4 5 6 7 8 1\n", ""), false, "no hexahedron", 0);
  expect_error("MeshVersionFormatted 1\nDimension 3\nEnd\n", false, "no Vertices", 0);
  EXPECT_THROW(HR::IO::read_hexahedral_mesh_MEDIT(replace(medit_ok, "Hexahedra", "Hexaedres"), "bad", m),
               HR::Unsupported_input);

  const std::string vtk_ok =
    "# vtk DataFile Version 2.0\nhex\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 8 double\n"
    "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "CELLS 2 13\n8 0 1 2 3 4 5 6 7\n3 0 1 2\nCELL_TYPES 2\n12\n5\n"
    "CELL_DATA 2\nSCALARS source_tetrahedron double 1\nLOOKUP_TABLE default\n7\n-1\n"
    "POINT_DATA 8\nSCALARS tags double 1\nLOOKUP_TABLE default\n1\n1\n1\n1\n3\n3\n7\n0\n";
  HR::IO::read_hexahedral_mesh_VTK(vtk_ok, "ok.vtk", m);
  ASSERT_EQ(m.hexahedra.size(), 1u);  // the triangle is ignored
  EXPECT_EQ(m.hexahedron_source_tetrahedra, std::vector<HR::Hexahedral_mesh_3::Index>{7});
  EXPECT_EQ(m.vertex_tags, (std::vector<std::uint8_t>{1, 1, 1, 1, 3, 3, 7, 0}));
  expect_error(replace(vtk_ok, "8 0 1 2 3 4 5 6 7", "7 0 1 2 3 4 5 6"), true, "instead of 8", 15);
  expect_error(replace(vtk_ok, "8 0 1 2 3 4 5 6 7", "8 0 1 2 3 4 5 6 8"), true, "out of range", 15);
  expect_error(replace(vtk_ok, "CELL_TYPES 2\n12\n5", "CELL_TYPES 2\n5\n5"), true, "no hexahedron", 0);
  expect_error(replace(vtk_ok, "CELL_TYPES 2", "CELL_TYPES 3"), true, "differs", 17);
  expect_error(replace(vtk_ok, "0 1 1\nCELLS", "0 1 inf\nCELLS"), true, "non-finite", 13);
  expect_error(replace(vtk_ok, "3\n3\n7\n0\n", "3\n3\n9\n0\n"), true, "not a tag", 0);
  expect_error(vtk_ok.substr(0, 150), true, "unexpected end of file", 0);
  EXPECT_THROW(HR::IO::read_hexahedral_mesh_VTK(replace(vtk_ok, "ASCII", "BINARY"), "bad", m), HR::Unsupported_input);
  EXPECT_THROW(HR::IO::read_hexahedral_mesh(temp_file("missing.vtk"), m), HR::Input_error);
  EXPECT_THROW(HR::IO::read_hexahedral_mesh("x.off", m), HR::Unsupported_input);
}

// The exploded map: 4 own points per tet, the corner parameters as `uvw`, the parameter volume per tet
// (k^3 / 24 for every tet of a hex scaled by k: the 24 tets split the k-cube evenly).
TEST(HexahedralMeshIO, IntegerGridMapVTK)
{
  const int k = 2;
  const auto g = T::make_L_block(1, 1);
  const HR::Integer_grid_map map = T::map_from_hex_mesh(g.mesh, k, 5u);
  const std::string file = temp_file("map.vtk");
  HR::IO::VTK_array ids;
  ids.name = "tet";
  for(std::size_t t = 0; t < map.tetrahedra.size(); ++t) ids.values.push_back(double(t));
  HR::IO::write_VTK_integer_grid_map(file, map, {ids});
  const std::string text = file_text(file);
  std::remove(file.c_str());

  // the geometry through the package's own tetrahedral reader
  HR::Tetrahedral_soup_3<HR::Hexahedral_mesh_3::Point_3> soup;
  HR::IO::read_VTK(text, file, soup);
  ASSERT_EQ(soup.points.size(), 4 * map.tetrahedra.size());
  ASSERT_EQ(soup.tetrahedra.size(), map.tetrahedra.size());
  for(std::size_t t = 0; t < map.tetrahedra.size(); ++t)
    for(int i = 0; i < 4; ++i) {
      EXPECT_EQ(soup.tetrahedra[t][i], 4 * t + i);
      EXPECT_EQ(soup.points[4 * t + i], map.points[map.tetrahedra[t][i]]);
    }
  // the arrays by hand
  std::istringstream in(text.substr(text.find("SCALARS parameter_volume double 1\nLOOKUP_TABLE default\n") + 56));
  for(std::size_t t = 0; t < map.tetrahedra.size(); ++t) {
    double v;
    in >> v;
    EXPECT_NEAR(v, k * k * k / 24., 1e-12) << t;
  }
  std::istringstream uvw(text.substr(text.find("VECTORS uvw double\n") + 19));
  for(std::size_t t = 0; t < map.tetrahedra.size(); ++t)
    for(int i = 0; i < 4; ++i)
      for(int d = 0; d < 3; ++d) {
        double u;
        uvw >> u;
        EXPECT_EQ(u, map.parameters[t][i][d]);
      }
  EXPECT_NE(text.find("SCALARS tet double 1"), std::string::npos);

  HR::Integer_grid_map broken = map;
  broken.parameters.pop_back();
  EXPECT_THROW(HR::IO::write_VTK_integer_grid_map(file, broken), HR::Error);
  EXPECT_FALSE(std::filesystem::exists(file));
}

// CGAL's linear cell complex of the generated meshes: one 3-cell per hex, one 0-cell per vertex, the
// 3-free facets are the boundary quads, the edges and faces are the mesh's, and the complex is valid.
TEST(HexahedralMeshToLCC, CellsAndBoundary)
{
  for(const auto& g : T::all_generated_hex_meshes()) {
    SCOPED_TRACE(g.name);
    typedef CGAL::Linear_cell_complex_for_combinatorial_map<3> LCC;
    LCC lcc;
    const auto darts = HR::hexahedral_mesh_to_lcc(g.mesh, lcc);
    ASSERT_EQ(darts.size(), g.mesh.hexahedra.size());
    EXPECT_TRUE(lcc.is_valid());
    EXPECT_EQ(lcc.number_of_darts(), 24 * g.mesh.hexahedra.size());
    EXPECT_EQ(lcc.one_dart_per_cell<3>().size(), g.expected.hexahedra);
    EXPECT_EQ(lcc.one_dart_per_cell<0>().size(), g.expected.vertices);
    EXPECT_EQ(lcc.number_of_vertex_attributes(), g.expected.vertices);
    std::size_t free_facets = 0, facets = 0;
    for(auto d = lcc.one_dart_per_cell<2>().begin(); d != lcc.one_dart_per_cell<2>().end(); ++d) {
      ++facets;
      free_facets += lcc.is_free<3>(d);
    }
    EXPECT_EQ(free_facets, g.expected.boundary_quads);
    EXPECT_EQ(facets, (6 * g.expected.hexahedra + g.expected.boundary_quads) / 2);
    const auto c = HR::check_hexahedral_mesh(g.mesh);
    EXPECT_EQ(lcc.one_dart_per_cell<1>().size(), c.interior_edges + c.boundary_edges);
    // the dart of each hex sits on its vertex 0
    for(std::size_t h = 0; h < darts.size(); ++h)
      EXPECT_EQ(lcc.point(darts[h]), g.mesh.points[g.mesh.hexahedra[h][0]]);
  }
  // a hole in the middle: two boundary components, 60 3-free facets
  auto g = T::make_grid(3, 3, 3);
  g.mesh.hexahedra.erase(g.mesh.hexahedra.begin() + 13);
  const auto lcc = HR::hexahedral_mesh_to_lcc(g.mesh);
  EXPECT_TRUE(lcc.is_valid());
  EXPECT_EQ(lcc.one_dart_per_cell<3>().size(), 26u);
  std::size_t free_facets = 0;
  for(auto d = lcc.one_dart_per_cell<2>().begin(); d != lcc.one_dart_per_cell<2>().end(); ++d)
    free_facets += lcc.is_free<3>(d);
  EXPECT_EQ(free_facets, 60u);
  auto broken = T::make_grid(1, 1, 1).mesh;
  broken.hexahedra[0][2] = 8;
  EXPECT_THROW(HR::hexahedral_mesh_to_lcc(broken), HR::Error);
}

// An LCC whose facets carry an int: the boundary facets get the patch of their quad (each side of a box
// is one patch: every facet of a patch lies on one side, and each side has the patch's quads).
struct Items_with_facet_patch
{
  template <class Refs>
  struct Dart_wrapper
  {
    typedef CGAL::Cell_attribute_with_point<Refs> Vertex_attribute;
    typedef CGAL::Cell_attribute<Refs, int> Facet_attribute;
    typedef std::tuple<Vertex_attribute, void, Facet_attribute> Attributes;
  };
};

TEST(HexahedralMeshToLCC, BoundaryFacetsCarryTheirPatch)
{
  typedef CGAL::Linear_cell_complex_for_combinatorial_map<3, 3, CGAL::Linear_cell_complex_traits<3>, Items_with_facet_patch> LCC;
  auto m = T::make_grid(3, 2, 1).mesh;
  HR::compute_hexahedral_boundary_groups(m);
  LCC lcc;
  HR::hexahedral_mesh_to_lcc(m, lcc);
  ASSERT_TRUE(lcc.is_valid());
  std::map<int, std::size_t> facets_per_patch;
  std::map<int, std::set<std::pair<int, double> > > sides;
  std::size_t free_facets = 0;
  for(auto d = lcc.one_dart_per_cell<2>().begin(); d != lcc.one_dart_per_cell<2>().end(); ++d) {
    if(!lcc.is_free<3>(d)) { EXPECT_TRUE(lcc.attribute<2>(d) == nullptr); continue; }
    ++free_facets;
    ASSERT_TRUE(lcc.attribute<2>(d) != nullptr);
    const int patch = lcc.info<2>(d);
    ++facets_per_patch[patch];
    for(int axis = 0; axis < 3; ++axis) {
      bool same = true;
      const LCC::Dart_handle start = d;
      LCC::Dart_handle e = start;
      do { same = same && lcc.point(e)[axis] == lcc.point(start)[axis]; e = lcc.beta(e, 1); } while(e != start);
      if(same) sides[patch].insert(std::make_pair(axis, lcc.point(d)[axis]));
    }
  }
  EXPECT_EQ(free_facets, m.boundary_quadrilaterals.size());
  EXPECT_EQ(facets_per_patch.size(), 6u);
  for(const auto& kv : sides) EXPECT_EQ(kv.second.size(), 1u) << "patch " << kv.first;
  std::multiset<std::size_t> sizes;
  for(const auto& kv : facets_per_patch) sizes.insert(kv.second);
  EXPECT_EQ(sizes, (std::multiset<std::size_t>{2, 2, 3, 3, 6, 6}));
}

// A crack: two cells that share a face, but one of them has its own copy of one corner of it (slightly
// off, as the extraction leaves it where the map is flat). Their two faces share three corners; the
// boundary is not a manifold at the shared corners. Closing the crack merges the copy with the corner
// (halfway, neither is on a feature): the two-cell grid again, valid. A mesh without a crack is left as
// it is.
TEST(CloseBoundaryCracks, GluesTwoFacesThatShareThreeCorners)
{
  const auto g = T::make_grid(2, 1, 1, 1.0);
  HR::Hexahedral_mesh_3 cracked = g.mesh;
  ASSERT_EQ(cracked.hexahedra.size(), 2u);
  // the corner (1, 1, 1) of both cells
  std::uint32_t corner = std::uint32_t(-1);
  for(std::uint32_t v = 0; v < cracked.points.size(); ++v)
    if(cracked.points[v] == HR::Hexahedral_mesh_3::Point_3(1, 1, 1)) corner = v;
  ASSERT_NE(corner, std::uint32_t(-1));
  const std::uint32_t copy = std::uint32_t(cracked.points.size());
  cracked.points.push_back(HR::Hexahedral_mesh_3::Point_3(1, 1, 1.05));
  if(!cracked.vertex_tags.empty()) cracked.vertex_tags.push_back(cracked.vertex_tags[corner]);
  if(!cracked.vertex_locations.empty()) cracked.vertex_locations.push_back(cracked.vertex_locations[corner]);
  const std::size_t second = std::count(cracked.hexahedra[0].begin(), cracked.hexahedra[0].end(), corner) ? 1 : 0;
  std::replace(cracked.hexahedra[second].begin(), cracked.hexahedra[second].end(), corner, copy);
  const HR::Hexahedral_mesh_check before = HR::check_hexahedral_mesh(cracked);
  EXPECT_FALSE(before.manifold_boundary);
  EXPECT_FALSE(before.valid);

  EXPECT_EQ(HRI::close_boundary_cracks(cracked), 1u);
  const HR::Hexahedral_mesh_check after = HR::check_hexahedral_mesh(cracked);
  EXPECT_TRUE(after.valid);
  EXPECT_TRUE(after.manifold_boundary);
  EXPECT_EQ(cracked.points.size(), g.mesh.points.size());
  EXPECT_EQ(after.interior_quads, 1u);
  std::size_t halfway = 0;
  for(const auto& p : cracked.points) halfway += p == HR::Hexahedral_mesh_3::Point_3(1, 1, 1.025);
  EXPECT_EQ(halfway, 1u);

  // a cell holding both fourth corners would collapse: the crack is left open
  HR::Hexahedral_mesh_3 held = g.mesh;
  held.points.push_back(HR::Hexahedral_mesh_3::Point_3(1, 1, 1.05));
  std::replace(held.hexahedra[second].begin(), held.hexahedra[second].end(), corner, copy);
  std::array<std::uint32_t, 8> third{{corner, copy, 0, 0, 0, 0, 0, 0}};
  for(int i = 2; i < 8; ++i) {
    third[std::size_t(i)] = std::uint32_t(held.points.size());
    held.points.push_back(HR::Hexahedral_mesh_3::Point_3(5 + i, 5, 5));
  }
  held.hexahedra.push_back(third);
  held.vertex_tags.clear();
  held.vertex_locations.clear();
  const HR::Hexahedral_mesh_3 held_before = held;
  EXPECT_EQ(HRI::crack_corners(held).size(), 1u);
  EXPECT_EQ(HRI::close_boundary_cracks(held), 0u);
  EXPECT_EQ(held.hexahedra, held_before.hexahedra);

  // two copies in one cell of a 2 x 2 grid: the face it shares with its x-neighbour keeps only a
  // diagonal, a crack only once the face shared with its y-neighbour (three corners) is closed
  const auto g4 = T::make_grid(2, 2, 1, 1.0);
  HR::Hexahedral_mesh_3 chained = g4.mesh;
  auto vertex_at = [&](double x, double y, double z) {
    for(std::uint32_t v = 0; v < chained.points.size(); ++v)
      if(chained.points[v] == HR::Hexahedral_mesh_3::Point_3(x, y, z)) return v;
    return std::uint32_t(-1);
  };
  const std::uint32_t p = vertex_at(1, 1, 0), q = vertex_at(1, 0, 1), far_corner = vertex_at(2, 0, 0);
  ASSERT_NE(p, std::uint32_t(-1));
  ASSERT_NE(q, std::uint32_t(-1));
  std::size_t cell = chained.hexahedra.size();
  for(std::size_t h = 0; h < chained.hexahedra.size(); ++h)
    if(std::count(chained.hexahedra[h].begin(), chained.hexahedra[h].end(), far_corner)) cell = h;
  ASSERT_LT(cell, chained.hexahedra.size());
  for(const std::uint32_t v : {p, q}) {
    const std::uint32_t c = std::uint32_t(chained.points.size());
    chained.points.push_back(HR::Hexahedral_mesh_3::Point_3(chained.points[v].x() + 0.2, chained.points[v].y(), chained.points[v].z()));
    if(!chained.vertex_tags.empty()) chained.vertex_tags.push_back(chained.vertex_tags[v]);
    if(!chained.vertex_locations.empty()) chained.vertex_locations.push_back(chained.vertex_locations[v]);
    std::replace(chained.hexahedra[cell].begin(), chained.hexahedra[cell].end(), v, c);
  }
  EXPECT_FALSE(HR::check_hexahedral_mesh(chained).valid);
  EXPECT_EQ(HRI::crack_corners(chained).size(), 1u); // the diagonal-only face is no crack yet
  // the merged corner would not be inside the input (two walls of a slot, corners 0.2 apart): left apart
  HR::Hexahedral_mesh_3 slot = chained;
  EXPECT_EQ(HRI::close_boundary_cracks(slot, [](const HR::Hexahedral_mesh_3::Point_3&) { return 0.; }), 0u);
  EXPECT_EQ(slot.hexahedra, chained.hexahedra);
  EXPECT_EQ(slot.points, chained.points);
  HR::Hexahedral_mesh_3 slab = chained;
  // inside the input (a tenth of an edge deep): closed
  EXPECT_EQ(HRI::close_boundary_cracks(chained, [](const HR::Hexahedral_mesh_3::Point_3&) { return 0.1; }), 2u);
  const HR::Hexahedral_mesh_check chained_after = HR::check_hexahedral_mesh(chained);
  EXPECT_TRUE(chained_after.valid);
  EXPECT_EQ(chained.points.size(), g4.mesh.points.size());
  EXPECT_EQ(chained_after.interior_quads, 4u);
  // the input a slab 0 < z < 1: the fourth corners of both cracks lie on its boundary (z = 0, then z = 1),
  // the glued faces across it (their centres half an edge deep): a face split in two, closed
  auto slab_depth = [](const HR::Hexahedral_mesh_3::Point_3& x) { return std::min(x.z(), 1 - x.z()); };
  // ... unless the two fourth corners lie on two feature curves that share none: merging them would
  // collapse the face between the curves (the floor of a thin slot)
  HR::Hexahedral_mesh_3 thin_face = slab;
  EXPECT_EQ(HRI::close_boundary_cracks(thin_face, slab_depth,
                                       [](const HR::Hexahedral_mesh_3::Point_3& x, double) {
                                         return std::vector<std::size_t>{x.x() < 1.1 ? std::size_t(0) : std::size_t(1)};
                                       }),
            0u);
  EXPECT_EQ(thin_face.hexahedra, slab.hexahedra);
  EXPECT_EQ(HRI::close_boundary_cracks(slab, slab_depth), 2u);
  const HR::Hexahedral_mesh_check slab_after = HR::check_hexahedral_mesh(slab);
  EXPECT_TRUE(slab_after.valid);
  EXPECT_EQ(slab_after.interior_quads, 4u);

  HR::Hexahedral_mesh_3 intact = g.mesh;
  EXPECT_EQ(HRI::close_boundary_cracks(intact), 0u);
  EXPECT_EQ(intact.points, g.mesh.points);
  EXPECT_EQ(intact.hexahedra, g.mesh.hexahedra);
}
