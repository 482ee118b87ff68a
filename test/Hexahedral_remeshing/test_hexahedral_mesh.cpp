// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#include "hex_mesh_generators.h"

#include <CGAL/Hexahedral_remeshing/internal/hexahedral_mesh/hexahedron_topology.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <vector>

namespace HR = CGAL::Hexahedral_remeshing;
namespace T = CGAL::Hexahedral_remeshing::test;

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
      if(inner_quads > 0)
        EXPECT_GT(non_identity, 0u);
    }
}
