// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_MESH_VALIDATION_H
#define CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_MESH_VALIDATION_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_mesh/hexahedron_topology.h>
#include <CGAL/Hexahedral_remeshing/internal/union_find.h>
#include <CGAL/Hexahedral_remeshing/parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

namespace internal_np {
enum duplicate_vertex_tolerance_t { duplicate_vertex_tolerance };
enum low_scaled_jacobian_threshold_t { low_scaled_jacobian_threshold };
enum flat_scaled_jacobian_threshold_t { flat_scaled_jacobian_threshold };
} // namespace internal_np

namespace parameters {
#ifdef DOXYGEN_RUNNING
/// Hexahedral mesh check: two vertices closer than this fraction of the bounding-box diagonal are
/// duplicates (`double`, default `1e-9`).
template <class T> unspecified_type duplicate_vertex_tolerance(const T& value);
/// Hexahedral mesh check: hexahedra whose scaled Jacobian is below this value are counted as low
/// quality (`double`, default `0.3`).
template <class T> unspecified_type low_scaled_jacobian_threshold(const T& value);
/// Hexahedral mesh check: hexahedra whose scaled Jacobian is positive but below this value are flat
/// and make the mesh invalid (`double`, default `1e-6`).
template <class T> unspecified_type flat_scaled_jacobian_threshold(const T& value);
#else
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(duplicate_vertex_tolerance)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(low_scaled_jacobian_threshold)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(flat_scaled_jacobian_threshold)
#endif
} // namespace parameters

/// \ingroup PkgHexahedralRemeshingRef
/// Report of `check_hexahedral_mesh()`: conformity, boundary manifoldness, duplicates, quality
/// (scaled Jacobian) and irregular edges of a `Hexahedral_mesh_3` (algorithms.md §6).
///
/// A quad is keyed by its sorted vertex ids. An edge's valence is the number of hexahedra containing
/// it; an edge is a boundary edge when it lies on a boundary quad. A regular interior edge has valence
/// 4, a regular boundary edge valence 2 (a flat boundary); a convex feature edge has boundary valence 1,
/// a concave one 3. Hexahedra with an index out of range or a repeated vertex are counted in
/// `invalid_hexahedra` and left out of every other count.
struct Hexahedral_mesh_check
{
  /// Number of vertices of the mesh.
  std::size_t vertices = 0;
  /// Number of vertices used by no (valid) hexahedron.
  std::size_t unused_vertices = 0;
  /// Number of hexahedra of the mesh.
  std::size_t hexahedra = 0;
  /// Hexahedra with a vertex index out of range or twice the same vertex.
  std::size_t invalid_hexahedra = 0;

  /// Number of distinct quads (faces of hexahedra).
  std::size_t quads = 0;
  /// Quads in exactly one hexahedron.
  std::size_t boundary_quads = 0;
  /// Quads in exactly two hexahedra with opposite orientations (conforming interior quads).
  std::size_t interior_quads = 0;
  /// Quads in two hexahedra with the same orientation (one of the two hexahedra is flipped).
  std::size_t same_orientation_quads = 0;
  /// Quads in two hexahedra whose cycles differ (same vertices, other order).
  std::size_t mismatched_quads = 0;
  /// Quads in more than two hexahedra.
  std::size_t overused_quads = 0;
  /// Total of the non-conforming quads (`same_orientation_quads + mismatched_quads + overused_quads`).
  std::size_t non_conforming_quads = 0;
  /// No non-conforming quad.
  bool conforming = false;

  /// Vertices of the boundary quads.
  std::size_t boundary_vertices = 0;
  /// Edges of the boundary quads.
  std::size_t boundary_edges = 0;
  /// Boundary edges not in exactly two boundary quads.
  std::size_t non_manifold_boundary_edges = 0;
  /// Boundary vertices whose link (the opposite edges of the incident boundary quads) is not one cycle.
  std::size_t non_manifold_boundary_vertices = 0;
  /// The boundary is a closed 2-manifold (both counts above are 0).
  bool manifold_boundary = false;
  /// Connected components of the boundary surface (through edges).
  std::size_t boundary_components = 0;
  /// Euler characteristic `V - E + F` of the boundary surface (2 per sphere).
  long boundary_euler_characteristic = 0;

  /// Used vertices at distance below `duplicate_vertex_tolerance` x bounding-box diagonal of a used
  /// vertex of smaller index (n coincident vertices count n - 1).
  std::size_t duplicate_vertices = 0;
  /// Hexahedra with the same vertex set as a hexahedron of smaller index.
  std::size_t duplicate_hexahedra = 0;

  /// Smallest scaled Jacobian of a hexahedron (see `hexahedron_scaled_jacobian()`); 0 without hexahedra.
  double min_scaled_jacobian = 0;
  /// Mean over the hexahedra of their scaled Jacobian.
  double mean_scaled_jacobian = 0;
  /// The threshold of `low_quality_share`.
  double low_scaled_jacobian_threshold = 0.3;
  /// Share (0..1) of hexahedra whose scaled Jacobian is below `low_scaled_jacobian_threshold`.
  double low_quality_share = 0;
  /// Hexahedra whose scaled Jacobian is <= 0 (inverted or degenerate).
  std::size_t inverted_hexahedra = 0;
  /// The threshold of `flat_hexahedra`.
  double flat_scaled_jacobian_threshold = 1e-6;
  /// Hexahedra whose scaled Jacobian is in (0, `flat_scaled_jacobian_threshold`): positive in floating
  /// point, but a corner is flat to within rounding, which no solver accepts as an element.
  std::size_t flat_hexahedra = 0;
  /// Sum of the signed volumes of the hexahedra (each split into 24 tetrahedra through its face and
  /// cell centroids), in model units cubed.
  double total_volume = 0;

  /// Number of interior edges.
  std::size_t interior_edges = 0;
  /// Histogram valence -> number of interior edges.
  std::map<int, std::size_t> interior_edge_valences;
  /// Histogram valence -> number of boundary edges.
  std::map<int, std::size_t> boundary_edge_valences;
  /// Histogram valence -> number of interior edges of valence != 4.
  std::map<int, std::size_t> irregular_interior_edges;
  /// Histogram valence -> number of boundary edges of valence != 2.
  std::map<int, std::size_t> irregular_boundary_edges;
  /// Histogram valence -> number of chains of irregular interior edges: maximal paths of edges of one
  /// valence through vertices where exactly two irregular interior edges meet, both of that valence
  /// (a closed loop is one chain). They compare with the curves of the frame field's singular graph.
  std::map<int, std::size_t> irregular_interior_chains;

  /// At least one hexahedron, none invalid, conforming, manifold boundary, no duplicate vertex or
  /// hexahedron, and `min_scaled_jacobian >= flat_scaled_jacobian_threshold` (none inverted or flat).
  bool valid = false;
};

/// \ingroup PkgHexahedralRemeshingRef
/// Scaled Jacobian of a hexahedron given by its 8 corners in VTK order: the minimum over the corners of
/// `det[e_a, e_b, e_c]` of the unit vectors along the three edges leaving the corner, with neighbours
/// 0:(1,3,4) 1:(2,0,5) 2:(3,1,6) 3:(0,2,7) 4:(7,5,0) 5:(4,6,1) 6:(5,7,2) 7:(6,4,3). In [-1, 1]: 1 for a
/// parallelepiped with right angles (a cube, a box), <= 0 for an inverted or degenerate corner (a
/// zero-length edge gives 0). Reference: Knupp, "Achieving finite element mesh quality via
/// optimization of the Jacobian matrix norm and associated quantities", 2000.
inline double hexahedron_scaled_jacobian(const std::array<Hexahedral_mesh_3::Point_3, 8>& corners)
{
  double sj = (std::numeric_limits<double>::max)();
  for(int c = 0; c < 8; ++c)
    sj = (std::min)(sj, internal::hex_corner_scaled_jacobian(corners, c));
  return sj;
}

/// \ingroup PkgHexahedralRemeshingRef
/// Scaled Jacobian (see the overload on corners) of the hexahedron `h` of `mesh`.
/// \pre `h < mesh.number_of_hexahedra()` and its vertex indices are valid.
inline double hexahedron_scaled_jacobian(const Hexahedral_mesh_3& mesh, std::size_t h)
{
  std::array<Hexahedral_mesh_3::Point_3, 8> p;
  for(int i = 0; i < 8; ++i)
    p[i] = mesh.points[mesh.hexahedra[h][i]];
  return hexahedron_scaled_jacobian(p);
}

/// \ingroup PkgHexahedralRemeshingRef
/// Scaled Jacobian of every hexahedron of `mesh`, in hexahedron order.
/// \pre every vertex index of `mesh.hexahedra` is valid.
inline std::vector<double> hexahedra_scaled_jacobians(const Hexahedral_mesh_3& mesh)
{
  std::vector<double> sj(mesh.number_of_hexahedra());
  for(std::size_t h = 0; h < sj.size(); ++h)
    sj[h] = hexahedron_scaled_jacobian(mesh, h);
  return sj;
}

namespace internal {

inline std::uint64_t hex_edge_key(std::uint32_t a, std::uint32_t b)
{
  if(a > b)
    std::swap(a, b);
  return (std::uint64_t(a) << 32) | b;
}

// 0: same cycle reversed (conforming), 1: same cycle same direction, 2: other cycle.
inline int compare_quad_cycles(const std::array<std::uint32_t, 4>& a, const std::array<std::uint32_t, 4>& b)
{
  int s = 0;
  while(s < 4 && b[s] != a[0])
    ++s;
  if(s == 4)
    return 2;
  bool reversed = true, same = true;
  for(int j = 0; j < 4; ++j) {
    reversed = reversed && (b[(s + 4 - j) % 4] == a[j]);
    same = same && (b[(s + j) % 4] == a[j]);
  }
  return reversed ? 0 : (same ? 1 : 2);
}

// Number of used vertices within `tolerance` of a used vertex of smaller index, by hashing the points
// on a grid of cell size 2 x `tolerance`: a point's partners then lie in its cell or in the neighbouring
// cells on the side of its nearest cell faces, 2 x 2 x 2 cells in all. The vertices of a cell are chained
// through `next` rather than stored in per-cell vectors (one allocation per vertex is what dominated).
inline std::size_t count_duplicate_vertices(const std::vector<Hexahedral_mesh_3::Point_3>& points,
                                            const std::vector<bool>& used, double tolerance)
{
  std::size_t duplicates = 0;
  if(!(tolerance > 0.)) {
    // a zero-size bounding box: all used points coincide
    std::size_t n = 0;
    for(bool u : used) n += u;
    return n > 0 ? n - 1 : 0;
  }
  struct Key_hash {
    std::size_t operator()(const std::array<std::int64_t, 3>& k) const
    {
      // splitmix64 finalizer on a combination of the three cell coordinates
      std::uint64_t h = std::uint64_t(k[0]) * 0x9E3779B97F4A7C15ull ^ std::uint64_t(k[1]) * 0xC2B2AE3D27D4EB4Full ^
                        std::uint64_t(k[2]) * 0x165667B19E3779F9ull;
      h ^= h >> 30; h *= 0xBF58476D1CE4E5B9ull;
      h ^= h >> 27; h *= 0x94D049BB133111EBull;
      h ^= h >> 31;
      return std::size_t(h);
    }
  };
  const std::uint32_t none = (std::numeric_limits<std::uint32_t>::max)();
  std::unordered_map<std::array<std::int64_t, 3>, std::uint32_t, Key_hash> first;
  first.reserve(points.size());
  std::vector<std::uint32_t> next(points.size(), none);
  const double t2 = tolerance * tolerance;
  for(std::uint32_t v = 0; v < points.size(); ++v) {
    if(!used[v])
      continue;
    const auto& p = points[v];
    std::array<std::int64_t, 3> k;
    int side[3];
    for(int d = 0; d < 3; ++d) {
      const double f = p[d] / (2. * tolerance);
      const double c = std::floor(f);
      k[d] = std::int64_t(c);
      side[d] = (f - c < 0.5) ? -1 : 1;
    }
    bool duplicate = false;
    for(int m = 0; m < 8 && !duplicate; ++m) {
      const std::array<std::int64_t, 3> n{ {k[0] + ((m & 1) ? side[0] : 0), k[1] + ((m & 2) ? side[1] : 0),
                                            k[2] + ((m & 4) ? side[2] : 0)} };
      auto it = first.find(n);
      if(it == first.end())
        continue;
      for(std::uint32_t w = it->second; w != none && !duplicate; w = next[w])
        duplicate = CGAL::squared_distance(p, points[w]) < t2;
    }
    duplicates += duplicate;
    auto inserted = first.emplace(k, v);
    if(!inserted.second) {
      next[v] = inserted.first->second;
      inserted.first->second = v;
    }
  }
  return duplicates;
}

} // namespace internal

/// \ingroup PkgHexahedralRemeshingRef
/// Checks a hexahedral mesh (algorithms.md §6): conformity (each quad, keyed by its sorted vertex ids,
/// used once on the boundary or twice inside with opposite orientations), closed 2-manifold boundary
/// (every boundary edge in exactly two boundary quads, every boundary vertex link one cycle), no
/// coincident vertices or duplicate hexahedra, Euler characteristic and components of the boundary,
/// scaled Jacobian (min, mean, share below a threshold, count <= 0), total volume, and the interior and
/// boundary edges by valence. Never throws on a defective mesh: defects are counted.
/// Cost: O(n log n) in the number of hexahedra.
///
/// \param mesh the mesh; optional arrays are ignored.
/// \param np optional named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{duplicate_vertex_tolerance}
///     \cgalParamDescription{distance below which two used vertices are duplicates, relative to the
///       bounding-box diagonal of the used vertices}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`1e-9`}
///   \cgalParamNEnd
///   \cgalParamNBegin{low_scaled_jacobian_threshold}
///     \cgalParamDescription{scaled Jacobian below which a hexahedron counts in `low_quality_share`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`0.3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{flat_scaled_jacobian_threshold}
///     \cgalParamDescription{positive scaled Jacobian below which a hexahedron is flat (`flat_hexahedra`),
///       which makes the mesh invalid; must be in [0, 1)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`1e-6`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
Hexahedral_mesh_check check_hexahedral_mesh(const Hexahedral_mesh_3& mesh,
                                            const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef std::uint32_t Id;
  const double relative_tolerance = choose_parameter(get_parameter(np, internal_np::duplicate_vertex_tolerance), 1e-9);
  const double sj_threshold = choose_parameter(get_parameter(np, internal_np::low_scaled_jacobian_threshold), 0.3);
  const double flat_threshold = choose_parameter(get_parameter(np, internal_np::flat_scaled_jacobian_threshold), 1e-6);
  if(!(flat_threshold >= 0. && flat_threshold < 1.))
    throw Error("hexahedral mesh check: flat_scaled_jacobian_threshold must be in [0, 1), got " +
                std::to_string(flat_threshold));
  const auto& faces = internal::hex_faces();
  const auto& edges = internal::hex_edges();

  Hexahedral_mesh_check r;
  r.vertices = mesh.points.size();
  r.hexahedra = mesh.hexahedra.size();
  r.low_scaled_jacobian_threshold = sj_threshold;
  r.flat_scaled_jacobian_threshold = flat_threshold;

  // valid hexahedra only from here on
  std::vector<std::size_t> hexes;
  std::vector<bool> used(mesh.points.size(), false);
  for(std::size_t h = 0; h < mesh.hexahedra.size(); ++h) {
    auto ids = mesh.hexahedra[h];
    bool ok = true;
    for(Id v : ids)
      ok = ok && v < mesh.points.size();
    std::sort(ids.begin(), ids.end());
    ok = ok && std::adjacent_find(ids.begin(), ids.end()) == ids.end();
    if(!ok) {
      ++r.invalid_hexahedra;
      continue;
    }
    hexes.push_back(h);
    for(Id v : ids)
      used[v] = true;
  }
  for(bool u : used)
    r.unused_vertices += !u;

  // duplicate hexahedra
  {
    std::vector<std::pair<std::array<Id, 8>, std::size_t> > keys;
    keys.reserve(hexes.size());
    for(std::size_t h : hexes) {
      auto k = mesh.hexahedra[h];
      std::sort(k.begin(), k.end());
      keys.emplace_back(k, h);
    }
    std::sort(keys.begin(), keys.end());
    for(std::size_t i = 1; i < keys.size(); ++i)
      r.duplicate_hexahedra += (keys[i].first == keys[i - 1].first);
  }

  // duplicate vertices
  {
    double lo[3] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
    double hi[3] = {-lo[0], -lo[1], -lo[2]};
    bool any = false;
    for(std::size_t v = 0; v < mesh.points.size(); ++v) {
      if(!used[v])
        continue;
      any = true;
      for(int d = 0; d < 3; ++d) {
        lo[d] = (std::min)(lo[d], mesh.points[v][d]);
        hi[d] = (std::max)(hi[d], mesh.points[v][d]);
      }
    }
    if(any) {
      const double diagonal = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                        (hi[2] - lo[2]) * (hi[2] - lo[2]));
      r.duplicate_vertices = internal::count_duplicate_vertices(mesh.points, used, relative_tolerance * diagonal);
    }
  }

  // quads: (sorted key, oriented cycle)
  struct Quad_record {
    std::array<Id, 4> key;
    std::array<Id, 4> cycle;
    bool operator<(const Quad_record& o) const { return key < o.key; }
  };
  std::vector<Quad_record> quads;
  quads.reserve(6 * hexes.size());
  for(std::size_t h : hexes)
    for(const auto& f : faces) {
      Quad_record q;
      for(int j = 0; j < 4; ++j)
        q.cycle[j] = mesh.hexahedra[h][f[j]];
      q.key = q.cycle;
      std::sort(q.key.begin(), q.key.end());
      quads.push_back(q);
    }
  std::sort(quads.begin(), quads.end());
  std::vector<std::array<Id, 4> > boundary;
  for(std::size_t i = 0; i < quads.size();) {
    std::size_t j = i + 1;
    while(j < quads.size() && quads[j].key == quads[i].key)
      ++j;
    ++r.quads;
    if(j - i == 1) {
      ++r.boundary_quads;
      boundary.push_back(quads[i].cycle);
    } else if(j - i == 2) {
      switch(internal::compare_quad_cycles(quads[i].cycle, quads[i + 1].cycle)) {
      case 0: ++r.interior_quads; break;
      case 1: ++r.same_orientation_quads; break;
      default: ++r.mismatched_quads; break;
      }
    } else {
      ++r.overused_quads;
    }
    i = j;
  }
  r.non_conforming_quads = r.same_orientation_quads + r.mismatched_quads + r.overused_quads;
  r.conforming = (r.non_conforming_quads == 0);

  // boundary surface: edges, manifoldness, vertex links, components, Euler characteristic
  std::vector<std::uint64_t> boundary_edge_keys;
  {
    std::vector<std::uint64_t> keys;
    keys.reserve(4 * boundary.size());
    // per boundary vertex, its link edges (previous, next) in the incident quads
    std::vector<std::pair<Id, std::pair<Id, Id> > > links;
    links.reserve(4 * boundary.size());
    for(const auto& q : boundary)
      for(int j = 0; j < 4; ++j) {
        keys.push_back(internal::hex_edge_key(q[j], q[(j + 1) % 4]));
        links.emplace_back(q[j], std::make_pair(q[(j + 3) % 4], q[(j + 2) % 4]));
        links.emplace_back(q[j], std::make_pair(q[(j + 2) % 4], q[(j + 1) % 4]));
      }
    std::sort(keys.begin(), keys.end());
    internal::Union_find components(mesh.points.size());
    for(std::size_t i = 0; i < keys.size();) {
      std::size_t j = i + 1;
      while(j < keys.size() && keys[j] == keys[i])
        ++j;
      boundary_edge_keys.push_back(keys[i]);
      r.non_manifold_boundary_edges += (j - i != 2);
      components.unite(Id(keys[i] >> 32), Id(keys[i] & 0xffffffffu));
      i = j;
    }
    r.boundary_edges = boundary_edge_keys.size();

    std::sort(links.begin(), links.end());
    for(std::size_t i = 0; i < links.size();) {
      std::size_t j = i + 1;
      while(j < links.size() && links[j].first == links[i].first)
        ++j;
      ++r.boundary_vertices;
      // the link is one cycle iff every link vertex has degree 2 and a walk visits all link edges
      std::map<Id, std::vector<Id> > adjacency;
      for(std::size_t e = i; e < j; ++e) {
        adjacency[links[e].second.first].push_back(links[e].second.second);
        adjacency[links[e].second.second].push_back(links[e].second.first);
      }
      bool cycle = true;
      for(const auto& a : adjacency)
        cycle = cycle && a.second.size() == 2;
      if(cycle) {
        const Id start = adjacency.begin()->first;
        Id previous = start, current = adjacency.begin()->second[0];
        std::size_t steps = 1;
        while(current != start && steps <= adjacency.size()) {
          const auto& n = adjacency[current];
          const Id next = (n[0] == previous) ? n[1] : n[0];
          previous = current;
          current = next;
          ++steps;
        }
        cycle = (current == start && steps == adjacency.size());
      }
      r.non_manifold_boundary_vertices += !cycle;
      i = j;
    }
    r.manifold_boundary = (r.non_manifold_boundary_edges == 0 && r.non_manifold_boundary_vertices == 0);
    r.boundary_euler_characteristic =
      long(r.boundary_vertices) - long(r.boundary_edges) + long(r.boundary_quads);
    std::vector<bool> root_seen(mesh.points.size(), false);
    for(std::size_t i = 0; i < links.size(); ++i) {
      const Id root = components.find(links[i].first);
      if(!root_seen[root]) {
        root_seen[root] = true;
        ++r.boundary_components;
      }
    }
  }

  // edge valences
  {
    std::vector<std::uint64_t> keys;
    keys.reserve(12 * hexes.size());
    for(std::size_t h : hexes)
      for(const auto& e : edges)
        keys.push_back(internal::hex_edge_key(mesh.hexahedra[h][e[0]], mesh.hexahedra[h][e[1]]));
    std::sort(keys.begin(), keys.end());
    // irregular interior edges (key, valence), for the chains
    std::vector<std::pair<std::uint64_t, int> > irregular;
    for(std::size_t i = 0; i < keys.size();) {
      std::size_t j = i + 1;
      while(j < keys.size() && keys[j] == keys[i])
        ++j;
      const int valence = int(j - i);
      if(std::binary_search(boundary_edge_keys.begin(), boundary_edge_keys.end(), keys[i])) {
        ++r.boundary_edge_valences[valence];
        if(valence != 2)
          ++r.irregular_boundary_edges[valence];
      } else {
        ++r.interior_edges;
        ++r.interior_edge_valences[valence];
        if(valence != 4) {
          ++r.irregular_interior_edges[valence];
          irregular.emplace_back(keys[i], valence);
        }
      }
      i = j;
    }

    // chains: join the two edges at every vertex of irregular degree 2 when their valences agree
    std::vector<std::pair<Id, std::uint32_t> > ends;  // (vertex, irregular edge)
    for(std::uint32_t e = 0; e < irregular.size(); ++e) {
      ends.emplace_back(Id(irregular[e].first >> 32), e);
      ends.emplace_back(Id(irregular[e].first & 0xffffffffu), e);
    }
    std::sort(ends.begin(), ends.end());
    internal::Union_find chains(irregular.size());
    for(std::size_t i = 0; i < ends.size();) {
      std::size_t j = i + 1;
      while(j < ends.size() && ends[j].first == ends[i].first)
        ++j;
      if(j - i == 2 && irregular[ends[i].second].second == irregular[ends[i + 1].second].second)
        chains.unite(ends[i].second, ends[i + 1].second);
      i = j;
    }
    for(std::uint32_t e = 0; e < irregular.size(); ++e)
      if(chains.find(e) == e)
        ++r.irregular_interior_chains[irregular[e].second];
  }

  // quality and volume
  if(!hexes.empty()) {
    double sum = 0.;
    std::size_t low = 0;
    r.min_scaled_jacobian = (std::numeric_limits<double>::max)();
    for(std::size_t h : hexes) {
      std::array<Hexahedral_mesh_3::Point_3, 8> p;
      for(int i = 0; i < 8; ++i)
        p[i] = mesh.points[mesh.hexahedra[h][i]];
      const double sj = hexahedron_scaled_jacobian(p);
      r.min_scaled_jacobian = (std::min)(r.min_scaled_jacobian, sj);
      sum += sj;
      low += (sj < sj_threshold);
      r.inverted_hexahedra += !(sj > 0.);  // NaN: a corner with a zero-length edge
      r.flat_hexahedra += (sj > 0. && sj < flat_threshold);
      r.total_volume += internal::hex_signed_volume(p);
    }
    r.mean_scaled_jacobian = sum / double(hexes.size());
    r.low_quality_share = double(low) / double(hexes.size());
  }

  r.valid = !mesh.hexahedra.empty() && r.invalid_hexahedra == 0 && r.conforming && r.manifold_boundary &&
            r.duplicate_vertices == 0 && r.duplicate_hexahedra == 0 && r.inverted_hexahedra == 0 &&
            r.flat_hexahedra == 0;
  return r;
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_MESH_VALIDATION_H
