// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_MESH_ORIENTATION_H
#define CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_MESH_ORIENTATION_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_mesh/hexahedron_topology.h>

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// What `orient_hexahedral_mesh()` changed.
struct Hexahedral_orientation_result
{
  /// Hexahedra whose vertex order was mirrored (top and bottom quads swapped).
  std::size_t reoriented = 0;
  /// Connected components (hexahedra joined by shared quads).
  std::size_t components = 0;
  /// Components whose hexahedra were all mirrored (a mesh written in the other vertex order).
  std::size_t mirrored_components = 0;
};

namespace internal {

// Mirrors a hexahedron: its top and bottom quads swap, which reverses every face cycle.
inline void mirror_hexahedron(std::array<std::uint32_t, 8>& h)
{
  std::array<std::uint32_t, 8> m{ {h[4], h[5], h[6], h[7], h[0], h[1], h[2], h[3]} };
  h = m;
}

// Six times the signed volume of a hexahedron, from its faces split about their centres (divergence
// theorem): positive for a hexahedron in VTK order, whatever its shape as long as it is not folded.
inline double hexahedron_signed_volume6(const Hexahedral_mesh_3& mesh, const std::array<std::uint32_t, 8>& h)
{
  double v = 0;
  for(const auto& f : hex_faces()) {
    double c[3] = {0, 0, 0};
    for(int i = 0; i < 4; ++i)
      for(int d = 0; d < 3; ++d) c[d] += mesh.points[h[f[i]]][d] / 4;
    for(int i = 0; i < 4; ++i) {
      const auto& a = mesh.points[h[f[i]]];
      const auto& b = mesh.points[h[f[(i + 1) % 4]]];
      v += c[0] * (a[1] * b[2] - a[2] * b[1]) - c[1] * (a[0] * b[2] - a[2] * b[0]) + c[2] * (a[0] * b[1] - a[1] * b[0]);
    }
  }
  return v;
}

} // namespace internal

/// \ingroup PkgHexahedralRemeshingRef
/// Orients the hexahedra of `mesh` consistently and positively, for a mesh read from a file written
/// by another tool: every quad shared by two hexahedra must be seen in opposite directions by them
/// (their faces pair up), which decides, hexahedron by hexahedron, which ones to mirror; each
/// connected component is then mirrored as a whole if its signed volume is negative (a mesh written
/// in the mirrored vertex order). Positions are not changed.
/// \returns how many hexahedra were mirrored, the components, and those mirrored entirely.
/// \throws Input_error naming the hexahedron for a hexahedron that lists a vertex twice (degenerate) or
///         a vertex out of range, and for faces that cannot pair up: a quad shared by more than two
///         hexahedra, or hexahedra whose orientations contradict each other around a cycle.
inline Hexahedral_orientation_result orient_hexahedral_mesh(Hexahedral_mesh_3& mesh, const std::string& source = "<memory>")
{
  typedef std::uint32_t Id;
  const std::size_t H = mesh.hexahedra.size();
  for(std::size_t h = 0; h < H; ++h) {
    std::array<Id, 8> s = mesh.hexahedra[h];
    for(Id v : s)
      if(v >= mesh.points.size())
        throw Input_error(source, 0, "hexahedron " + std::to_string(h) + ": vertex index " + std::to_string(v) + " out of range");
    std::sort(s.begin(), s.end());
    const auto twice = std::adjacent_find(s.begin(), s.end());
    if(twice != s.end())
      throw Input_error(source, 0, "hexahedron " + std::to_string(h) + " lists vertex " + std::to_string(*twice) +
                        " twice (a degenerate hexahedron): remove it or give it eight distinct vertices");
  }
  // the face cycles of every quad, by sorted key: (hexahedron, first vertex position in the cycle)
  std::map<std::array<Id, 4>, std::vector<std::pair<std::size_t, std::array<Id, 4> > > > quads;
  for(std::size_t h = 0; h < H; ++h)
    for(const auto& f : internal::hex_faces()) {
      std::array<Id, 4> cycle{ {mesh.hexahedra[h][f[0]], mesh.hexahedra[h][f[1]], mesh.hexahedra[h][f[2]], mesh.hexahedra[h][f[3]]} };
      std::array<Id, 4> key = cycle;
      std::sort(key.begin(), key.end());
      quads[key].emplace_back(h, cycle);
    }
  // flip[h] xor flip[k] must be `differ` for hexahedra h and k sharing a quad
  std::vector<std::vector<std::pair<std::size_t, bool> > > adjacent(H);
  for(const auto& q : quads) {
    if(q.second.size() > 2)
      throw Input_error(source, 0, "a quad is shared by " + std::to_string(q.second.size()) + " hexahedra (" +
                        std::to_string(q.second[0].first) + ", " + std::to_string(q.second[1].first) + ", " +
                        std::to_string(q.second[2].first) + "): the faces cannot pair up");
    if(q.second.size() < 2) continue;
    const auto& a = q.second[0].second;
    const auto& b = q.second[1].second;
    // opposite directions: b is a reversed rotation of a
    bool opposite = false;
    for(int s = 0; s < 4 && !opposite; ++s) {
      bool all = true;
      for(int k = 0; k < 4; ++k) all = all && a[std::size_t(k)] == b[std::size_t((s - k + 4) % 4)];
      opposite = all;
    }
    adjacent[q.second[0].first].emplace_back(q.second[1].first, !opposite);
    adjacent[q.second[1].first].emplace_back(q.second[0].first, !opposite);
  }
  Hexahedral_orientation_result r;
  std::vector<int> flip(H, -1);
  for(std::size_t start = 0; start < H; ++start) {
    if(flip[start] >= 0) continue;
    ++r.components;
    std::vector<std::size_t> component{ start }, stack{ start };
    flip[start] = 0;
    while(!stack.empty()) {
      const std::size_t h = stack.back();
      stack.pop_back();
      for(const auto& nb : adjacent[h]) {
        const int want = flip[h] ^ int(nb.second);
        if(flip[nb.first] < 0) {
          flip[nb.first] = want;
          component.push_back(nb.first);
          stack.push_back(nb.first);
        } else if(flip[nb.first] != want) {
          throw Input_error(source, 0, "hexahedra " + std::to_string(h) + " and " + std::to_string(nb.first) +
                            " cannot be oriented consistently with their neighbours (their faces do not pair up "
                            "around a cycle of hexahedra): the mesh is not orientable or its connectivity is broken");
        }
      }
    }
    double volume = 0;
    for(std::size_t h : component) {
      std::array<Id, 8> cell = mesh.hexahedra[h];
      if(flip[h]) internal::mirror_hexahedron(cell);
      volume += internal::hexahedron_signed_volume6(mesh, cell);
    }
    const int all = volume < 0 ? 1 : 0;
    std::size_t mirrored = 0;
    for(std::size_t h : component)
      if(flip[h] ^ all) {
        internal::mirror_hexahedron(mesh.hexahedra[h]);
        ++mirrored;
      }
    r.reoriented += mirrored;
    if(mirrored == component.size()) ++r.mirrored_components;
  }
  return r;
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_MESH_ORIENTATION_H
