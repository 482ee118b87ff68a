// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_SANITIZE_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_SANITIZE_H

#include <CGAL/Hexahedral_remeshing/Integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/map_topology.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/rigid_transform.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/transitions.h>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {
namespace extraction {

// Parameters on which every transition holds bit for bit (HexEx's truncatePrecision, HexHex's sanitize):
// each vertex gets one reference value in the chart of one incident tetrahedron, snapped to a common
// dyadic grid, and every corner of the vertex is the image of that value by the transition chain
// through the vertex star. Rotations by 90 degrees and integer shifts of grid values are exact in
// double, so afterwards exact predicates on parameters of different charts agree.
struct Sanitized_map
{
  // Per tetrahedron, the sanitized corner parameters (same layout as Integer_grid_map::parameters).
  std::vector<std::array<Eigen::Vector3d, 4> > parameters;
  // Per corner (t, k): the reference value it comes from, and the transition from its chart.
  std::vector<std::array<std::uint32_t, 4> > corner_reference;
  std::vector<std::array<Rigid_transform, 4> > corner_transform;
  std::vector<Eigen::Vector3d> reference_value;
  std::vector<std::uint32_t> reference_vertex, reference_root;  // vertex, tetrahedron of the chart
  std::vector<std::int8_t> reference_root_corner;               // local index of the vertex in the root
  // Largest move of a parameter, vertices snapped onto singular axes, holonomies without a fixed point
  // (a broken map), boundary vertices claimed by two different planes, faces whose transition still fails.
  double max_move = 0.;
  std::size_t singular_snaps = 0, broken_holonomies = 0, boundary_conflicts = 0, inexact_faces = 0;
};

// Rounds x to the grid 2^-k (exact: ldexp only changes the exponent).
inline double snap_to_grid(double x, int k) { return std::ldexp(std::round(std::ldexp(x, k)), -k); }

inline void sanitize_map(const Integer_grid_map& map, const Map_topology& topo, const Face_transitions& tr,
                         Sanitized_map& out)
{
  const std::size_t nt = map.tetrahedra.size();
  out = Sanitized_map();
  out.corner_reference.assign(nt, {});
  out.corner_transform.assign(nt, {});

  // Grid 2^-k such that every value of magnitude <= 4 * 2^e (2^e >= max |u| + 1) is exact.
  double max_abs = 0.;
  for(const auto& t : map.parameters)
    for(const auto& u : t) max_abs = (std::max)(max_abs, u.cwiseAbs().maxCoeff());
  int e;
  std::frexp(max_abs + 1., &e);
  const int k = 50 - e;

  // Reference charts by a walk through each vertex star across the faces containing the vertex.
  std::vector<std::uint32_t> stamp(nt, no_tetrahedron);
  std::vector<std::uint32_t> queue;
  std::vector<std::vector<Rigid_transform> > holonomies;
  const std::size_t nv = map.points.size();
  for(std::uint32_t v = 0; v < nv; ++v) {
    for(std::uint32_t i = topo.vertex_star_begin[v]; i < topo.vertex_star_begin[v + 1]; ++i) {
      const std::uint32_t root = topo.vertex_star[i];
      if(stamp[root] == v) continue;
      const std::uint32_t ref = std::uint32_t(out.reference_value.size());
      int rk = 0;
      while(map.tetrahedra[root][rk] != v) ++rk;
      out.reference_value.push_back(map.parameters[root][rk].unaryExpr([k](double x) { return snap_to_grid(x, k); }));
      out.reference_vertex.push_back(v);
      out.reference_root.push_back(root);
      out.reference_root_corner.push_back(std::int8_t(rk));
      holonomies.emplace_back();
      stamp[root] = v;
      out.corner_reference[root][rk] = ref;
      out.corner_transform[root][rk] = Rigid_transform();
      queue.assign(1, root);
      for(std::size_t q = 0; q < queue.size(); ++q) {
        const std::uint32_t t = queue[q];
        int lt = 0;
        while(map.tetrahedra[t][lt] != v) ++lt;
        const Rigid_transform Tt = out.corner_transform[t][lt];
        for(int f = 0; f < 4; ++f) {
          if(f == lt) continue; // the face opposite v does not contain it
          const std::uint32_t n = topo.neighbor[t][f];
          if(n == no_tetrahedron) continue;
          const Rigid_transform Tn = compose(tr.to_this[n][topo.neighbor_face[t][f]], Tt);
          int ln = 0;
          while(map.tetrahedra[n][ln] != v) ++ln;
          if(stamp[n] != v) {
            stamp[n] = v;
            out.corner_reference[n][ln] = ref;
            out.corner_transform[n][ln] = Tn;
            queue.push_back(n);
          } else if(out.corner_transform[n][ln] != Tn) {
            // a loop around an edge through v with a non-trivial holonomy (in the reference chart)
            const Rigid_transform H = compose(inverse(out.corner_transform[n][ln]), Tn);
            auto& hs = holonomies[ref];
            if(std::find(hs.begin(), hs.end(), H) == hs.end() && std::find(hs.begin(), hs.end(), inverse(H)) == hs.end())
              hs.push_back(H);
          }
        }
      }
    }
  }

  // Boundary faces onto their integer planes, written into the reference values.
  std::vector<std::array<double, 3> > fixed(out.reference_value.size(), {{NAN, NAN, NAN}});
  const Octahedral_group& g = octahedral_group();
  for(std::uint32_t t = 0; t < nt; ++t)
    for(int f = 0; f < 4; ++f) {
      if(topo.neighbor[t][f] != no_tetrahedron) continue;
      int axis;
      double value, deviation;
      boundary_plane(map, t, f, axis, value, deviation);
      for(int i = 0; i < 3; ++i) {
        const int lk = face_vertices[f][i];
        const std::uint32_t ref = out.corner_reference[t][lk];
        const Rigid_transform& T = out.corner_transform[t][lk];
        int j = 0;
        while(g.row_of_column(T.rotation, j) != axis) ++j;
        const double x = g.sign_of_column(T.rotation, j) * (value - T.translation[axis]);
        if(std::isnan(fixed[ref][j])) {
          fixed[ref][j] = x;
          out.reference_value[ref][j] = x;
        } else if(fixed[ref][j] != x) {
          ++out.boundary_conflicts;
        }
      }
    }

  // Vertices on singular edges onto the fixed axes of their holonomies.
  for(std::size_t ref = 0; ref < out.reference_value.size(); ++ref) {
    Eigen::Vector3d& x = out.reference_value[ref];
    bool snapped = false;
    for(const Rigid_transform& H : holonomies[ref]) {
      if(apply(H, x) == x) continue;
      for(int c = 0; c < 3; ++c)
        if(!(g.row_of_column(H.rotation, c) == c && g.sign_of_column(H.rotation, c) > 0)) x[c] = std::round(x[c]);
      snapped = true;
      if(apply(H, x) != x) {
        x = x.unaryExpr([](double y) { return std::round(y); });
        if(apply(H, x) != x) ++out.broken_holonomies;
      }
    }
    if(snapped) ++out.singular_snaps;
  }

  out.parameters.assign(nt, {});
  for(std::uint32_t t = 0; t < nt; ++t)
    for(int c = 0; c < 4; ++c) {
      out.parameters[t][c] = apply(out.corner_transform[t][c], out.reference_value[out.corner_reference[t][c]]);
      out.max_move = (std::max)(out.max_move, (out.parameters[t][c] - map.parameters[t][c]).cwiseAbs().maxCoeff());
    }
  for(std::uint32_t t = 0; t < nt; ++t)
    for(int f = 0; f < 4; ++f) {
      const std::uint32_t n = topo.neighbor[t][f];
      if(n == no_tetrahedron || n < t) continue;
      for(int i = 0; i < 3; ++i) {
        const int lt = face_vertices[f][i];
        int ln = 0;
        while(map.tetrahedra[n][ln] != map.tetrahedra[t][lt]) ++ln;
        if(apply(tr.to_this[t][f], out.parameters[n][ln]) != out.parameters[t][lt]) { ++out.inexact_faces; break; }
      }
    }
}

} // namespace extraction
} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_SANITIZE_H
