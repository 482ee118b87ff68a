// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// Test-only generators of valid hexahedral meshes with known irregular edges, and the integer-grid maps
// built from them (issue 10, algorithms.md §7): every hex is split into 24 tets whose parameters are the
// unit cube in that hex's own chart, scaled by k and moved by a random rotation of the 24-group and a
// random integer shift, so every face between two hexes carries a non-trivial transition. Extracting the
// map must give back k^3 hexes per hex and the irregular edges of the hex mesh, each split into k.
#ifndef CGAL_HEXAHEDRAL_REMESHING_TEST_HEX_MESH_GENERATORS_H
#define CGAL_HEXAHEDRAL_REMESHING_TEST_HEX_MESH_GENERATORS_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/Integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_mesh/hexahedron_topology.h>
#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>

#include <Eigen/Core>
#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace test {

// What a generated mesh must give, counted by hand from its construction (not by the checker).
struct Hex_mesh_oracle
{
  std::size_t hexahedra = 0;
  std::size_t vertices = 0;        // 0 when not known (maps at k > 1)
  std::size_t boundary_quads = 0;
  int boundary_euler_characteristic = 2;
  // valence -> number of interior edges with that valence != 4
  std::map<int, std::size_t> interior_irregular_edges;
  // valence -> number of boundary edges with that valence != 2
  std::map<int, std::size_t> boundary_irregular_edges;
  // valence -> number of chains of interior irregular edges (unchanged by the scaling)
  std::map<int, std::size_t> interior_irregular_chains;
};

struct Generated_hex_mesh
{
  std::string name;
  Hexahedral_mesh_3 mesh;
  Hex_mesh_oracle expected;
};

// The oracle of the mesh extracted from map_from_hex_mesh(mesh, k, .): every hex becomes k^3 hexes,
// every boundary quad k^2 quads, every irregular edge a chain of k edges with the same valence; the new
// edges inside old hexes or old faces are regular.
inline Hex_mesh_oracle scaled_oracle(const Hex_mesh_oracle& o, int k)
{
  Hex_mesh_oracle s = o;
  const std::size_t K = static_cast<std::size_t>(k);
  s.hexahedra = o.hexahedra * K * K * K;
  s.vertices = (k == 1) ? o.vertices : 0;
  s.boundary_quads = o.boundary_quads * K * K;
  for(auto& e : s.interior_irregular_edges) e.second *= K;
  for(auto& e : s.boundary_irregular_edges) e.second *= K;
  return s;
}

namespace generators_internal {

typedef Hexahedral_mesh_3::Point_3 Point_3;
typedef Hexahedral_mesh_3::Index Index;

inline std::array<Point_3, 8> hex_points(const Hexahedral_mesh_3& m, std::size_t h)
{
  std::array<Point_3, 8> p;
  for(int i = 0; i < 8; ++i)
    p[i] = m.points[m.hexahedra[h][i]];
  return p;
}

// Flips hexes built with a left-handed bottom quad (swap 1<->3 and 5<->7: the mirror in VTK order).
inline void orient_positively(Hexahedral_mesh_3& m)
{
  for(std::size_t h = 0; h < m.hexahedra.size(); ++h) {
    if(internal::hex_signed_volume(hex_points(m, h)) < 0.) {
      std::swap(m.hexahedra[h][1], m.hexahedra[h][3]);
      std::swap(m.hexahedra[h][5], m.hexahedra[h][7]);
    }
  }
}

// Drops unused vertices (the L-block removes cells from a grid).
inline void compact(Hexahedral_mesh_3& m)
{
  std::vector<Index> new_id(m.points.size(), Index(-1));
  std::vector<Point_3> points;
  for(auto& h : m.hexahedra)
    for(auto& v : h) {
      if(new_id[v] == Index(-1)) {
        new_id[v] = static_cast<Index>(points.size());
        points.push_back(m.points[v]);
      }
      v = new_id[v];
    }
  m.points.swap(points);
}

} // namespace generators_internal

// Structured grid of a x b x c unit cubes (edge length h) on [0, a h] x [0, b h] x [0, c h].
// Only the 12 box edges are irregular: boundary valence 1, 4 (a + b + c) edges.
inline Generated_hex_mesh make_grid(int a, int b, int c, double h = 1.)
{
  typedef generators_internal::Index Index;
  Generated_hex_mesh g;
  g.name = "grid_" + std::to_string(a) + "x" + std::to_string(b) + "x" + std::to_string(c);
  auto id = [&](int i, int j, int l) { return static_cast<Index>(i + (a + 1) * (j + (b + 1) * l)); };
  for(int l = 0; l <= c; ++l)
    for(int j = 0; j <= b; ++j)
      for(int i = 0; i <= a; ++i)
        g.mesh.points.emplace_back(i * h, j * h, l * h);
  const auto& uc = internal::hex_unit_corners();
  for(int l = 0; l < c; ++l)
    for(int j = 0; j < b; ++j)
      for(int i = 0; i < a; ++i) {
        std::array<Index, 8> hex;
        for(int v = 0; v < 8; ++v)
          hex[v] = id(i + uc[v][0], j + uc[v][1], l + uc[v][2]);
        g.mesh.hexahedra.push_back(hex);
      }
  const std::size_t A = a, B = b, C = c;
  g.expected.hexahedra = A * B * C;
  g.expected.vertices = (A + 1) * (B + 1) * (C + 1);
  g.expected.boundary_quads = 2 * (A * B + B * C + C * A);
  g.expected.boundary_irregular_edges[1] = 4 * (A + B + C);
  return g;
}

// L-block: the 2n x 2n grid of the xy-plane without its quadrant [n, 2n) x [n, 2n), extruded over m
// layers (unit cubes). The concave vertical edge at (n, n) is a chain of m boundary edges of valence 3;
// the 5 convex vertical edges (5 m) and the top and bottom outlines (2 x 8 n) have valence 1.
inline Generated_hex_mesh make_L_block(int n, int m)
{
  Generated_hex_mesh g = make_grid(2 * n, 2 * n, m);
  g.name = "L_block_" + std::to_string(n) + "_" + std::to_string(m);
  std::vector<std::array<generators_internal::Index, 8> > kept;
  std::size_t h = 0;
  for(int l = 0; l < m; ++l)
    for(int j = 0; j < 2 * n; ++j)
      for(int i = 0; i < 2 * n; ++i, ++h)
        if(!(i >= n && j >= n))
          kept.push_back(g.mesh.hexahedra[h]);
  g.mesh.hexahedra.swap(kept);
  generators_internal::compact(g.mesh);
  const std::size_t N = n, M = m;
  g.expected = Hex_mesh_oracle();
  g.expected.hexahedra = 3 * N * N * M;
  g.expected.vertices = (M + 1) * ((2 * N + 1) * (2 * N + 1) - N * N);
  g.expected.boundary_quads = 2 * 3 * N * N + 8 * N * M;
  g.expected.boundary_irregular_edges[1] = 5 * M + 16 * N;
  g.expected.boundary_irregular_edges[3] = M;
  return g;
}

// Prism over a regular n-gon (circumradius 1) split into n quads around its centre (centre, edge
// midpoint, corner, next edge midpoint), extruded over `layers` layers of height `height`. The axis is
// one chain of `layers` interior edges of valence n; the n vertical corner edges (n x layers) and the
// 2 x 2n cap rim edges have boundary valence 1; every other edge is regular.
inline Generated_hex_mesh make_polygon_prism(int n, int layers, double height = 0.5)
{
  typedef generators_internal::Index Index;
  Generated_hex_mesh g;
  g.name = "prism_" + std::to_string(n) + "_" + std::to_string(layers);
  const double pi = 3.14159265358979323846;
  // per layer: 0 = centre, 1 + i = corner i, 1 + n + i = midpoint of corners i, i + 1
  const int per_layer = 1 + 2 * n;
  for(int l = 0; l <= layers; ++l) {
    const double z = l * height;
    g.mesh.points.emplace_back(0., 0., z);
    for(int i = 0; i < n; ++i)
      g.mesh.points.emplace_back(std::cos(2 * pi * i / n), std::sin(2 * pi * i / n), z);
    for(int i = 0; i < n; ++i) {
      const int j = (i + 1) % n;
      g.mesh.points.emplace_back(0.5 * (std::cos(2 * pi * i / n) + std::cos(2 * pi * j / n)),
                                 0.5 * (std::sin(2 * pi * i / n) + std::sin(2 * pi * j / n)), z);
    }
  }
  for(int l = 0; l < layers; ++l)
    for(int i = 0; i < n; ++i) {
      // counter-clockwise seen from +z: centre, midpoint before corner i, corner i, midpoint after
      const int q[4] = {0, 1 + n + (i + n - 1) % n, 1 + i, 1 + n + i};
      std::array<Index, 8> hex;
      for(int v = 0; v < 4; ++v) {
        hex[v] = static_cast<Index>(l * per_layer + q[v]);
        hex[v + 4] = static_cast<Index>((l + 1) * per_layer + q[v]);
      }
      g.mesh.hexahedra.push_back(hex);
    }
  generators_internal::orient_positively(g.mesh);
  const std::size_t N = n, L = layers;
  g.expected.hexahedra = N * L;
  g.expected.vertices = (L + 1) * (2 * N + 1);
  g.expected.boundary_quads = 2 * N + 2 * N * L;
  if(n != 4) {
    g.expected.interior_irregular_edges[n] = L;
    g.expected.interior_irregular_chains[n] = 1;
  }
  g.expected.boundary_irregular_edges[1] = N * L + 4 * N;
  return g;
}

// Cubed ball of radius `radius`: an inner cube [-s, s]^3 of n^3 hexes (s = inner_ratio x radius / sqrt 3)
// inside 6 frusta, one per cube face, of n x n x `shells` hexes whose outer layer is projected on the
// sphere. Interior valence-3 edges: the 12 inner cube edges (12 n) and the 8 radial lines from the
// cube corners to the sphere (8 shells); they meet at the 8 cube corners (20 chains). The boundary (a cubed sphere)
// has no irregular edge.
inline Generated_hex_mesh make_cubed_ball(int n = 3, int shells = 1, double radius = 1., double inner_ratio = 0.6)
{
  typedef generators_internal::Index Index;
  Generated_hex_mesh g;
  g.name = "cubed_ball_" + std::to_string(n) + "_" + std::to_string(shells);
  const double s = inner_ratio * radius / std::sqrt(3.);
  std::map<std::array<int, 4>, Index> ids;  // (i, j, l) lattice point of the inner cube, shell layer
  auto vertex = [&](int i, int j, int l, int layer) -> Index {
    const std::array<int, 4> key{ {i, j, l, layer} };
    auto it = ids.find(key);
    if(it != ids.end())
      return it->second;
    const double p[3] = {-s + 2 * s * i / n, -s + 2 * s * j / n, -s + 2 * s * l / n};
    // layer 0 is the inner cube itself (its centre may be the origin, which has no projection)
    double q[3] = {p[0], p[1], p[2]};
    if(layer > 0) {
      const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      const double t = double(layer) / shells;
      for(int d = 0; d < 3; ++d)
        q[d] = (1 - t) * p[d] + t * radius * p[d] / len;
    }
    const Index v = static_cast<Index>(g.mesh.points.size());
    g.mesh.points.emplace_back(q[0], q[1], q[2]);
    ids.emplace(key, v);
    return v;
  };
  const auto& uc = internal::hex_unit_corners();
  for(int l = 0; l < n; ++l)
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i) {
        std::array<Index, 8> hex;
        for(int v = 0; v < 8; ++v)
          hex[v] = vertex(i + uc[v][0], j + uc[v][1], l + uc[v][2], 0);
        g.mesh.hexahedra.push_back(hex);
      }
  // per cube face (axis d, side 0 or n): cells (a, b) of the face, extruded outwards layer by layer
  for(int d = 0; d < 3; ++d)
    for(int side = 0; side <= n; side += n) {
      const int d1 = (d + 1) % 3, d2 = (d + 2) % 3;
      for(int b = 0; b < n; ++b)
        for(int a = 0; a < n; ++a) {
          const int corners[4][2] = {{a, b}, {a + 1, b}, {a + 1, b + 1}, {a, b + 1}};
          for(int layer = 0; layer < shells; ++layer) {
            std::array<Index, 8> hex;
            for(int v = 0; v < 4; ++v) {
              int c[3];
              c[d] = side; c[d1] = corners[v][0]; c[d2] = corners[v][1];
              hex[v] = vertex(c[0], c[1], c[2], layer);
              hex[v + 4] = vertex(c[0], c[1], c[2], layer + 1);
            }
            g.mesh.hexahedra.push_back(hex);
          }
        }
    }
  generators_internal::orient_positively(g.mesh);
  const std::size_t N = n, S = shells;
  g.expected.hexahedra = N * N * N + 6 * N * N * S;
  g.expected.vertices = (N + 1) * (N + 1) * (N + 1) + S * (6 * N * N + 2);
  g.expected.boundary_quads = 6 * N * N;
  g.expected.interior_irregular_edges[3] = 12 * N + 8 * S;
  // the 12 cube edges and the 8 radial lines, split at the cube corners (4 lines meet there)
  g.expected.interior_irregular_chains[3] = 20;
  return g;
}

// Box of a x b x c unit cubes whose horizontal layers are rotated about the vertical axis through the
// box centre, by `total_twist` radians at the top (linearly in z). Same irregular edges as the grid.
inline Generated_hex_mesh make_twisted_grid(int a, int b, int c, double total_twist = 0.6)
{
  Generated_hex_mesh g = make_grid(a, b, c);
  g.name = "twisted_" + std::to_string(a) + "x" + std::to_string(b) + "x" + std::to_string(c);
  for(auto& p : g.mesh.points) {
    const double angle = total_twist * p.z() / c;
    const double x = p.x() - 0.5 * a, y = p.y() - 0.5 * b;
    p = Hexahedral_mesh_3::Point_3(0.5 * a + std::cos(angle) * x - std::sin(angle) * y,
                                   0.5 * b + std::sin(angle) * x + std::cos(angle) * y, p.z());
  }
  return g;
}

// All the generated meshes the tests run on.
inline std::vector<Generated_hex_mesh> all_generated_hex_meshes()
{
  std::vector<Generated_hex_mesh> v;
  v.push_back(make_grid(2, 3, 4));
  v.push_back(make_L_block(1, 2));
  v.push_back(make_L_block(2, 1));
  v.push_back(make_polygon_prism(3, 3));
  v.push_back(make_polygon_prism(5, 2));
  v.push_back(make_polygon_prism(6, 2));
  v.push_back(make_cubed_ball(3, 1));
  v.push_back(make_cubed_ball(2, 2));
  v.push_back(make_twisted_grid(3, 3, 4));
  return v;
}

// The integer-grid map of a hex mesh: every hex is split into 24 tets (edge, face centre, cell centre),
// the tets of a hex get the unit-cube parameters of its own chart (corner i of the VTK order its
// unit-cube corner, a face centre the face centre, the cell centre (1/2, 1/2, 1/2)), scaled by k, then
// moved by a random rotation of the 24-group and a random integer shift in [-10, 10]^3, per hex.
// Hex corners and face centres shared by hexes are shared vertices, so the tet mesh is conforming.
// Vertex ids: the hex mesh's vertices first, then one per distinct quad (face centres), then one per hex
// (cell centres). Tets are positively oriented in parameter space (and in space for a valid hex mesh
// with convex-enough hexes). With `with_transitions`, the transitions of all interior tet faces are
// filled (identity inside a hex); otherwise they are left to be recovered from the parameters.
inline Integer_grid_map map_from_hex_mesh(const Hexahedral_mesh_3& hexes, int k, unsigned seed,
                                          bool with_transitions = true)
{
  typedef Hexahedral_mesh_3::Index Index;
  typedef Integer_grid_map::Point_3 Point_3;
  const auto& group = internal::Octahedral_group::instance();
  const auto& uc = internal::hex_unit_corners();
  const auto& faces = internal::hex_faces();
  std::mt19937 rng(seed);

  Integer_grid_map map;
  map.points = hexes.points;
  std::map<std::array<Index, 4>, std::uint32_t> face_centre;
  auto face_key = [&](const std::array<Index, 8>& h, int f) {
    std::array<Index, 4> key{ {h[faces[f][0]], h[faces[f][1]], h[faces[f][2]], h[faces[f][3]]} };
    std::sort(key.begin(), key.end());
    return key;
  };
  for(const auto& h : hexes.hexahedra)
    for(int f = 0; f < 6; ++f) {
      const auto key = face_key(h, f);
      if(face_centre.count(key))
        continue;
      double c[3] = {0., 0., 0.};
      for(int j = 0; j < 4; ++j) {
        const Point_3& p = hexes.points[h[faces[f][j]]];
        c[0] += p.x() / 4; c[1] += p.y() / 4; c[2] += p.z() / 4;
      }
      face_centre.emplace(key, static_cast<std::uint32_t>(map.points.size()));
      map.points.emplace_back(c[0], c[1], c[2]);
    }

  for(const auto& h : hexes.hexahedra) {
    double c[3] = {0., 0., 0.};
    for(int v = 0; v < 8; ++v) {
      const Point_3& p = hexes.points[h[v]];
      c[0] += p.x() / 8; c[1] += p.y() / 8; c[2] += p.z() / 8;
    }
    const std::uint32_t cell = static_cast<std::uint32_t>(map.points.size());
    map.points.emplace_back(c[0], c[1], c[2]);

    const int g = static_cast<int>(rng() % 24);
    Eigen::Vector3d shift;
    for(int d = 0; d < 3; ++d)
      shift[d] = static_cast<double>(static_cast<int>(rng() % 21) - 10);
    const Eigen::Matrix3d& R = group.matrix(g);
    auto param = [&](const Eigen::Vector3d& unit) -> Eigen::Vector3d { return R * (double(k) * unit) + shift; };

    for(int f = 0; f < 6; ++f) {
      Eigen::Vector3d fc = Eigen::Vector3d::Zero();
      for(int j = 0; j < 4; ++j)
        fc += 0.25 * Eigen::Vector3d(uc[faces[f][j]][0], uc[faces[f][j]][1], uc[faces[f][j]][2]);
      const std::uint32_t F = face_centre.at(face_key(h, f));
      for(int j = 0; j < 4; ++j) {
        const int a = faces[f][j], b = faces[f][(j + 1) % 4];
        std::array<std::uint32_t, 4> tet{ {h[b], h[a], F, cell} };
        std::array<Eigen::Vector3d, 4> u{ {
          param(Eigen::Vector3d(uc[b][0], uc[b][1], uc[b][2])),
          param(Eigen::Vector3d(uc[a][0], uc[a][1], uc[a][2])),
          param(fc), param(Eigen::Vector3d(0.5, 0.5, 0.5)) } };
        Eigen::Matrix3d J;
        J << u[1] - u[0], u[2] - u[0], u[3] - u[0];
        if(J.determinant() < 0) {
          std::swap(tet[0], tet[1]);
          std::swap(u[0], u[1]);
        }
        map.tetrahedra.push_back(tet);
        map.parameters.push_back(u);
      }
    }
  }

  if(with_transitions) {
    // face (sorted global ids) -> (tet, local indices of the three vertices in that order)
    std::map<std::array<std::uint32_t, 3>, std::pair<std::uint32_t, std::array<int, 3> > > open_faces;
    for(std::uint32_t t = 0; t < map.tetrahedra.size(); ++t)
      for(int o = 0; o < 4; ++o) {
        std::array<std::pair<std::uint32_t, int>, 3> vs;
        for(int j = 0, n = 0; j < 4; ++j)
          if(j != o)
            vs[n++] = std::make_pair(map.tetrahedra[t][j], j);
        std::sort(vs.begin(), vs.end());
        const std::array<std::uint32_t, 3> key{ {vs[0].first, vs[1].first, vs[2].first} };
        const std::array<int, 3> local{ {vs[0].second, vs[1].second, vs[2].second} };
        auto it = open_faces.find(key);
        if(it == open_faces.end()) {
          open_faces.emplace(key, std::make_pair(t, local));
          continue;
        }
        const std::uint32_t t0 = it->second.first;
        const auto& l0 = it->second.second;
        // u_t0 = R u_t1 + translation on the face: the three vertices fix R in the 24-group
        Integer_grid_map_transition tr;
        tr.tetrahedra = {{t0, t}};
        tr.rotation = -1;
        for(int r = 0; r < 24 && tr.rotation < 0; ++r) {
          const Eigen::Matrix3d& M = group.matrix(r);
          const Eigen::Vector3d d = map.parameters[t0][l0[0]] - M * map.parameters[t][local[0]];
          bool ok = (d.array() == d.array().round()).all();
          for(int j = 1; j < 3 && ok; ++j)
            ok = (map.parameters[t0][l0[j]] - M * map.parameters[t][local[j]] - d).isZero(0.);
          if(ok) {
            tr.rotation = r;
            tr.translation = d.cast<int>();
          }
        }
        if(tr.rotation < 0)
          throw std::logic_error("map_from_hex_mesh: no transition (hex mesh not positively oriented?)");
        map.transitions.push_back(tr);
        open_faces.erase(it);
      }
  }
  map.source = "map_from_hex_mesh";
  return map;
}

} // namespace test
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_TEST_HEX_MESH_GENERATORS_H
