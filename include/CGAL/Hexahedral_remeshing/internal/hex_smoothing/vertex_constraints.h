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
};

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
