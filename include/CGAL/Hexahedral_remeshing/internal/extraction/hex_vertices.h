// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_HEX_VERTICES_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_HEX_VERTICES_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/Integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/lattice_points.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/map_topology.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/sanitize.h>
#include <CGAL/Hexahedral_remeshing/internal/union_find.h>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {
namespace extraction {

// A lattice point on a simplex, seen from one tetrahedron of the simplex's star: its id and its
// coordinates in that tetrahedron's chart.
struct Chart_point
{
  std::uint32_t tetrahedron;
  std::uint32_t id;
  Eigen::Vector3d x;
};

// Hex vertices (h = 0) with their positions, provenance and tags, and the copies of each in the chart of
// every tetrahedron of its simplex's star; hex cell centres (h = 1/2) only in their owner's chart.
// The identity of a point is the simplex it lies on plus its coordinates in that simplex's owner chart
// (HexEx's canonical key): one owner per simplex, so no point is found twice.
struct Lattice_points
{
  std::vector<Hexahedral_mesh_3::Point_3> positions;
  std::vector<Hexahedral_vertex_location> locations;
  std::vector<std::uint8_t> tags;
  std::vector<std::uint32_t> per_tetrahedron_begin; // CSR over tetrahedra into `copies`
  std::vector<Chart_point> copies;
  std::vector<Chart_point> centres;                 // id unused
  std::size_t skipped_inverted_tetrahedra = 0;
  std::size_t merged_vertices = 0;
};

inline void extract_lattice_points(const Integer_grid_map& map, const Map_topology& topo, const Sanitized_map& sm,
                                   const Face_transitions& tr, Lattice_points& out)
{
  const std::size_t nt = map.tetrahedra.size();
  const auto& S = sm.parameters;
  out = Lattice_points();
  std::vector<Chart_point> copies;

  auto local_index = [&](std::uint32_t t, std::uint32_t v) {
    int k = 0;
    while(map.tetrahedra[t][k] != v) ++k;
    return k;
  };
  // A new hex vertex on the simplex of tetrahedron t given by local vertices lv[0..dim].
  auto new_vertex = [&](std::uint32_t t, int dim, const std::array<int, 4>& lv, const std::array<double, 4>& lambda,
                        bool boundary) {
    const std::uint32_t id = std::uint32_t(out.positions.size());
    double x = 0., y = 0., z = 0.;
    Hexahedral_vertex_location loc;
    loc.tetrahedron = t;
    loc.dimension = dim;
    for(int i = 0; i <= dim; ++i) {
      const auto& p = map.points[map.tetrahedra[t][lv[i]]];
      x += lambda[i] * p.x(); y += lambda[i] * p.y(); z += lambda[i] * p.z();
      loc.local_vertices[i] = std::uint8_t(lv[i]);
    }
    out.positions.emplace_back(x, y, z);
    out.locations.push_back(loc);
    out.tags.push_back(boundary ? Hexahedral_mesh_3::BOUNDARY : 0);
    return id;
  };

  for(int lattice = 0; lattice < 2; ++lattice) {
    const double h = lattice == 0 ? 0. : 0.5;
    const bool centres = lattice == 1;
    // vertices: one reference value per vertex (per connected part of its star)
    for(std::size_t ref = 0; ref < sm.reference_value.size(); ++ref) {
      const std::uint32_t root = sm.reference_root[ref];
      const int rk = sm.reference_root_corner[ref];
      const Eigen::Vector3d& x = S[root][rk];
      if(!on_lattice(x, h)) continue;
      if(centres) { out.centres.push_back({root, 0, x}); continue; }
      const std::uint32_t v = sm.reference_vertex[ref];
      const std::uint32_t id = new_vertex(root, 0, {{rk, 0, 0, 0}}, {{1., 0., 0., 0.}}, topo.vertex_on_boundary[v] != 0);
      for(std::uint32_t i = topo.vertex_star_begin[v]; i < topo.vertex_star_begin[v + 1]; ++i) {
        const std::uint32_t t = topo.vertex_star[i];
        const int k = local_index(t, v);
        if(sm.corner_reference[t][k] == ref) copies.push_back({t, id, S[t][k]});
      }
    }
    // edges
    for(std::size_t e = 0; e < topo.edges.size(); ++e) {
      const std::uint32_t o = topo.edge_owner[e];
      const int la = local_index(o, topo.edges[e][0]), lb = local_index(o, topo.edges[e][1]);
      lattice_points_on_edge(S[o][la], S[o][lb], h, [&](const Eigen::Vector3d& q, const std::array<double, 4>& l) {
        if(centres) { out.centres.push_back({o, 0, q}); return; }
        const std::uint32_t id = new_vertex(o, 1, {{la, lb, 0, 0}}, l, topo.edge_on_boundary[e] != 0);
        for(std::uint32_t i = topo.edge_star_begin[e]; i < topo.edge_star_begin[e + 1]; ++i) {
          const std::uint32_t t = topo.edge_star[i];
          if(t == o) { copies.push_back({t, id, q}); continue; }
          const int ta = local_index(t, topo.edges[e][0]), tb = local_index(t, topo.edges[e][1]);
          Eigen::Vector3d qt = l[0] * S[t][ta] + l[1] * S[t][tb];
          for(int c = 0; c < 3; ++c) qt[c] = to_lattice(qt[c], h);
          copies.push_back({t, id, qt});
        }
      });
    }
    // faces, in the chart of the smaller tetrahedron
    for(std::uint32_t t = 0; t < nt; ++t)
      for(int f = 0; f < 4; ++f) {
        const std::uint32_t n = topo.neighbor[t][f];
        if(n != no_tetrahedron && n < t) continue;
        const std::array<int, 4> lv = {{face_vertices[f][0], face_vertices[f][1], face_vertices[f][2], 0}};
        lattice_points_in_triangle(S[t][lv[0]], S[t][lv[1]], S[t][lv[2]], h,
                                   [&](const Eigen::Vector3d& q, const std::array<double, 4>& l) {
          if(centres) { out.centres.push_back({t, 0, q}); return; }
          const std::uint32_t id = new_vertex(t, 2, lv, l, n == no_tetrahedron);
          copies.push_back({t, id, q});
          if(n != no_tetrahedron) copies.push_back({n, id, apply(tr.to_this[n][topo.neighbor_face[t][f]], q)});
        });
      }
    // interiors
    for(std::uint32_t t = 0; t < nt; ++t) {
      const CGAL::Orientation o = parameter_orientation(S[t]);
      if(o != CGAL::POSITIVE) {
        if(o == CGAL::NEGATIVE && !centres) ++out.skipped_inverted_tetrahedra;
        continue;
      }
      lattice_points_in_tetrahedron(S[t], h, [&](const Eigen::Vector3d& q, const std::array<double, 4>& l) {
        if(centres) { out.centres.push_back({t, 0, q}); return; }
        const std::uint32_t id = new_vertex(t, 3, {{0, 1, 2, 3}}, l, false);
        copies.push_back({t, id, q});
      });
    }
  }

  // A zero-volume tetrahedron covers no volume but its faces overlap in parameter space: the same
  // point is found on two of its simplices. Such copies are one hex vertex (HexEx merges them too).
  {
    Union_find uf(out.positions.size());
    std::vector<std::vector<const Chart_point*> > in_tet(nt);
    bool any = false;
    for(std::uint32_t t = 0; t < nt; ++t) any = any || parameter_orientation(S[t]) == CGAL::COPLANAR;
    if(any) {
      for(const Chart_point& c : copies)
        if(parameter_orientation(S[c.tetrahedron]) == CGAL::COPLANAR) in_tet[c.tetrahedron].push_back(&c);
      for(std::uint32_t t = 0; t < nt; ++t)
        for(std::size_t i = 0; i < in_tet[t].size(); ++i)
          for(std::size_t j = i + 1; j < in_tet[t].size(); ++j)
            if(in_tet[t][i]->x == in_tet[t][j]->x) uf.unite(in_tet[t][i]->id, in_tet[t][j]->id);
      std::size_t n = 0;
      const std::vector<std::uint32_t> label = uf.labels(n);
      if(n < out.positions.size()) {
        out.merged_vertices = out.positions.size() - n;
        std::vector<Hexahedral_mesh_3::Point_3> positions(n);
        std::vector<Hexahedral_vertex_location> locations(n);
        std::vector<std::uint8_t> tags(n, 0);
        std::vector<char> done(n, 0);
        for(std::size_t v = 0; v < out.positions.size(); ++v) {
          const std::uint32_t l = label[v];
          tags[l] |= out.tags[v];
          if(done[l]) continue;
          done[l] = 1;
          positions[l] = out.positions[v];
          locations[l] = out.locations[v];
        }
        out.positions.swap(positions);
        out.locations.swap(locations);
        out.tags.swap(tags);
        for(Chart_point& c : copies) c.id = label[c.id];
        // a tetrahedron may now hold the same vertex twice at the same point: harmless for the cells
      }
    }
  }

  // CSR by tetrahedron
  out.per_tetrahedron_begin.assign(nt + 1, 0);
  for(const Chart_point& c : copies) ++out.per_tetrahedron_begin[c.tetrahedron + 1];
  for(std::size_t t = 0; t < nt; ++t) out.per_tetrahedron_begin[t + 1] += out.per_tetrahedron_begin[t];
  out.copies.resize(copies.size());
  std::vector<std::uint32_t> fill(out.per_tetrahedron_begin.begin(), out.per_tetrahedron_begin.end() - 1);
  for(const Chart_point& c : copies) out.copies[fill[c.tetrahedron]++] = c;
}

} // namespace extraction
} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_HEX_VERTICES_H
