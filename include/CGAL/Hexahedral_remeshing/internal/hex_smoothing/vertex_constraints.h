// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEX_SMOOTHING_VERTEX_CONSTRAINTS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEX_SMOOTHING_VERTEX_CONSTRAINTS_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/internal/hex_smoothing/reference_projector.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_mesh/hexahedron_topology.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// What a hex vertex may do during the smoothing.
enum class Hex_vertex_kind : std::uint8_t {
  INTERIOR, // moves freely
  SURFACE,  // slides on the reference surface
  CURVE,    // slides on one feature polyline
  FIXED     // does not move (corners, user-fixed vertices)
};

struct Hex_vertex_constraint
{
  Hex_vertex_kind kind = Hex_vertex_kind::INTERIOR;
  std::size_t polyline = 0; // for CURVE
  int patch = -1;           // for SURFACE: the reference patch it stays on (-1: the whole surface)
  bool on_boundary = false; // topologically on the hex boundary or tagged BOUNDARY
  // for FIXED: the reference corner the vertex is put on first (a corner found from the patches of
  // its quads, which may lie off it), or none
  std::size_t corner = (std::numeric_limits<std::size_t>::max)();
};

// The reference patches meeting at each vertex of the hex boundary: each boundary quad takes the patch
// most of five points inside it (its centre, and halfway from the centre to each corner) are closest
// to. Inside the quads, the vote holds when the vertices lie off the sharp edges (a noisy mesh): one
// patch at a vertex means the surface, two a feature curve, three or more a corner.
inline std::vector<std::vector<int> > vertex_patches_from_quads(const Hexahedral_mesh_3& mesh,
                                                                const std::vector<std::array<std::uint32_t, 4> >& quads,
                                                                const Reference_projector& reference)
{
  std::vector<std::vector<int> > patches(mesh.number_of_vertices());
  for(const auto& q : quads) {
    double c[3] = {0, 0, 0};
    for(auto v : q)
      for(int d = 0; d < 3; ++d) c[d] += mesh.points[v][d] / 4;
    const Hexahedral_mesh_3::Point_3 centre(c[0], c[1], c[2]);
    std::vector<int> votes{ reference.patch_of(centre) };
    for(auto v : q) votes.push_back(reference.patch_of(CGAL::midpoint(centre, mesh.points[v])));
    int best = votes[0], best_count = 0;
    for(int p : votes) {
      const int k = int(std::count(votes.begin(), votes.end(), p));
      if(k > best_count) { best = p; best_count = k; }
    }
    for(auto v : q)
      if(std::find(patches[v].begin(), patches[v].end(), best) == patches[v].end()) patches[v].push_back(best);
  }
  return patches;
}

// Which vertex lies on what. With `mesh.vertex_tags` (full size, not all 0): CORNER -> FIXED, FEATURE_CURVE ->
// CURVE on the nearest polyline, BOUNDARY -> SURFACE (or CURVE / FIXED if it lies on a polyline /
// corner, by distance as below), untagged -> INTERIOR even on a boundary quad (hole of a partial mesh). Without: the vertices of the boundary quads,
// then by distance, below 1e-3 of their shortest hex edge: to a reference corner -> FIXED, to a
// polyline -> CURVE, else SURFACE. Then `keep`: 1 also fixes the CURVE vertices, 2 every boundary
// vertex; `user_fixed[v]` fixes v. A constraint that the reference cannot honour (no surface, no
// polyline) fixes the vertex.
inline std::vector<Hex_vertex_constraint>
classify_hex_vertices(const Hexahedral_mesh_3& mesh, const std::vector<std::array<std::uint32_t, 4> >& boundary_quads,
                      const Reference_projector& reference, int keep, const std::vector<bool>& user_fixed)
{
  const std::size_t n = mesh.number_of_vertices();
  std::vector<Hex_vertex_constraint> c(n);
  for(const auto& q : boundary_quads)
    for(std::uint32_t v : q) c[v].on_boundary = true;
  // all-zero tags carry no information (a MEDIT file whose vertex references are all 0)
  const bool tagged = mesh.vertex_tags.size() == n &&
                      std::any_of(mesh.vertex_tags.begin(), mesh.vertex_tags.end(), [](std::uint8_t t) { return t != 0; });
  std::vector<double> shortest(n, (std::numeric_limits<double>::max)());
  for(const auto& h : mesh.hexahedra)
      for(const auto& e : hex_edges()) {
        const double l = std::sqrt(CGAL::squared_distance(mesh.points[h[e[0]]], mesh.points[h[e[1]]]));
        shortest[h[e[0]]] = (std::min)(shortest[h[e[0]]], l);
        shortest[h[e[1]]] = (std::min)(shortest[h[e[1]]], l);
      }
  std::vector<double> mean_edge(n, 0.);
  std::vector<int> edge_count(n, 0);
  for(const auto& h : mesh.hexahedra)
    for(const auto& e : hex_edges()) {
      const double l = std::sqrt(CGAL::squared_distance(mesh.points[h[e[0]]], mesh.points[h[e[1]]]));
      for(int i = 0; i < 2; ++i) { mean_edge[h[e[i]]] += l; ++edge_count[h[e[i]]]; }
    }
  for(std::size_t v = 0; v < n; ++v) if(edge_count[v] > 0) mean_edge[v] /= edge_count[v];
  const std::vector<std::vector<int> > by_patches =
    !tagged && reference.number_of_patches() > 1 ? vertex_patches_from_quads(mesh, boundary_quads, reference)
                                                 : std::vector<std::vector<int> >();
  for(std::size_t v = 0; v < n; ++v) {
    Hex_vertex_constraint& cv = c[v];
    const auto& p = mesh.points[v];
    bool corner = false, curve = false;
    if(tagged) {
      const std::uint8_t t = mesh.vertex_tags[v];
      // the tags say what lies on the input boundary: a boundary quad with untagged vertices bounds a
      // hole of a partial mesh (cells the extraction left out), which must not be pulled onto the
      // surface; its vertices move freely
      cv.on_boundary = (t & (Hexahedral_mesh_3::BOUNDARY | Hexahedral_mesh_3::FEATURE_CURVE | Hexahedral_mesh_3::CORNER)) != 0;
      corner = (t & Hexahedral_mesh_3::CORNER) != 0;
      curve = (t & Hexahedral_mesh_3::FEATURE_CURVE) != 0;
    }
    // a vertex tagged as a plain boundary vertex may still lie on a feature the tags did not know
    // (features detected on the reference by dihedral angle)
    if(cv.on_boundary && !corner && !curve && (!tagged || reference.number_of_polylines() > 0 || !reference.corners().empty())) {
      const double tol = 1e-3 * shortest[v];
      corner = reference.distance_to_corners(p) <= tol;
      if(!corner && reference.number_of_polylines() > 0) {
        double d;
        reference.nearest_polyline(p, &d);
        curve = d <= tol;
      }
    }
    // untagged vertices off the features (a noisy mesh): the patches of their quads decide, within
    // half an incident edge of the curve or corner
    if(!tagged && cv.on_boundary && !corner && !curve && !by_patches.empty()) {
      const std::size_t k = by_patches[v].size();
      double d = 0;
      if(k >= 3 && reference.nearest_corner(p, &d) < reference.corners().size() && d <= 0.5 * mean_edge[v]) {
        corner = true;
        cv.corner = reference.nearest_corner(p);
      } else if(k == 2 && reference.number_of_polylines() > 0) {
        reference.nearest_polyline(p, &d);
        curve = d <= 0.5 * mean_edge[v];
      }
    }
    if(!cv.on_boundary) cv.kind = Hex_vertex_kind::INTERIOR;
    else if(corner) cv.kind = Hex_vertex_kind::FIXED;
    else if(curve && reference.number_of_polylines() > 0) {
      cv.kind = Hex_vertex_kind::CURVE;
      cv.polyline = reference.nearest_polyline(p);
    } else cv.kind = reference.has_surface() ? Hex_vertex_kind::SURFACE : Hex_vertex_kind::FIXED;
    if(cv.kind == Hex_vertex_kind::SURFACE) cv.patch = reference.number_of_patches() > 0 ? reference.patch_of(p) : -1;
    if(cv.kind == Hex_vertex_kind::CURVE && keep >= 1) cv.kind = Hex_vertex_kind::FIXED;
    if(cv.on_boundary && keep >= 2) cv.kind = Hex_vertex_kind::FIXED;
    if(v < user_fixed.size() && user_fixed[v]) cv.kind = Hex_vertex_kind::FIXED;
  }
  return c;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEX_SMOOTHING_VERTEX_CONSTRAINTS_H
