// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// The hex-scale simplification of the singularity graph (robust_pipeline.md §1): an integer-grid map
// at hex edge h puts singular curves on integer lines, so two curves closer than h (a valence-3 curve
// beside a valence-5 one), a closed curve or a curve from boundary to boundary shorter than h have no
// room in it: the map collapses or folds there, whatever the quantization. Such a cluster of curves is
// removed by making the field flat (every holonomy the identity) in a region R around it. The tetrahedra
// around R (its collar) keep their matchings and carry a gauge A_t (one rotation per tetrahedron,
// transported across the collar's faces); every face with a tetrahedron in R gets the matching
// A_t1 A_t0^-1 of that gauge, so every edge whose ring lies in R and its collar has the identity as
// holonomy. This is possible only if the collar is flat itself (its faces agree with the gauge: no other
// curve crosses it; around a 3-5 pair the two holonomies cancel, around two curves of one valence they
// do not); the valence every boundary edge achieves (Eq. 3) must stay the same, and the cost of the
// repair must go down. Frames are not touched: the realignment's solver re-optimizes them afterwards.
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_SIMPLIFY_AT_HEX_SCALE_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_SIMPLIFY_AT_HEX_SCALE_H

#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/repair_state.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <deque>
#include <functional>
#include <numeric>
#include <queue>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// What became of a cluster: removed, or why it stays.
enum class Flattening { REMOVED, TOO_LARGE, COLLAR_NOT_FLAT, NOT_EDITABLE, BOUNDARY_VALENCE, NOT_CHEAPER };

// The clusters with no room at the hex scale, and what became of them.
struct Hex_scale_simplification
{
  std::size_t clusters = 0, removed = 0;
  // why the others stay: region over the size limit, another curve crossing the collar (or holonomies
  // that do not cancel), a face that may not change, a boundary valence that would change, no gain
  std::size_t too_large = 0, collar_not_flat = 0, not_editable = 0, boundary_valence = 0, not_cheaper = 0;
  void count(Flattening f)
  {
    ++clusters;
    switch(f) {
      case Flattening::REMOVED: ++removed; break;
      case Flattening::TOO_LARGE: ++too_large; break;
      case Flattening::COLLAR_NOT_FLAT: ++collar_not_flat; break;
      case Flattening::NOT_EDITABLE: ++not_editable; break;
      case Flattening::BOUNDARY_VALENCE: ++boundary_valence; break;
      case Flattening::NOT_CHEAPER: ++not_cheaper; break;
    }
  }
};

// A connected set of singular edges (curves joined at their nodes), with its bounding box.
struct Singular_component
{
  std::vector<std::size_t> edges;
  std::vector<std::size_t> vertices;
  Eigen::AlignedBox3d box;
};

template <class Mesh>
std::vector<Singular_component> singular_components(const Singularity_repair_state<Mesh>& state)
{
  const Mesh& mesh = state.mesh();
  std::vector<std::size_t> parent(mesh.number_of_vertices());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&](std::size_t v) {
    while(parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  std::vector<std::size_t> singular;
  for(std::size_t e = 0; e < mesh.number_of_edges(); ++e) {
    if(!is_singular_class(state.edge_class(e))) continue;
    singular.push_back(e);
    const auto& ev = mesh.edge_vertices(e);
    parent[find(ev[0])] = find(ev[1]);
  }
  std::unordered_map<std::size_t, std::size_t> index_of_root;
  std::vector<Singular_component> out;
  for(std::size_t e : singular) {
    const std::size_t root = find(mesh.edge_vertices(e)[0]);
    auto it = index_of_root.emplace(root, out.size()).first;
    if(it->second == out.size()) out.emplace_back();
    Singular_component& c = out[it->second];
    c.edges.push_back(e);
    for(auto v : mesh.edge_vertices(e)) {
      c.vertices.push_back(v);
      c.box.extend(to_eigen_point(mesh.point(v)));
    }
  }
  for(Singular_component& c : out) {
    std::sort(c.vertices.begin(), c.vertices.end());
    c.vertices.erase(std::unique(c.vertices.begin(), c.vertices.end()), c.vertices.end());
  }
  return out;
}

inline double segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  const Eigen::Vector3d d = b - a;
  const double l = d.squaredNorm();
  const double s = l > 0 ? std::clamp((p - a).dot(d) / l, 0., 1.) : 0.;
  return (a + s * d - p).norm();
}

// Distance from p to the edges of component c.
template <class Mesh>
double component_distance(const Mesh& mesh, const Singular_component& c, const Eigen::Vector3d& p)
{
  double d = std::numeric_limits<double>::infinity();
  for(std::size_t e : c.edges) {
    const auto& ev = mesh.edge_vertices(e);
    d = (std::min)(d, segment_distance(p, to_eigen_point(mesh.point(ev[0])), to_eigen_point(mesh.point(ev[1]))));
  }
  return d;
}

// Largest distance from a vertex or edge midpoint of a to the edges of b.
template <class Mesh>
double directed_hausdorff(const Mesh& mesh, const Singular_component& a, const Singular_component& b)
{
  double d = 0;
  for(std::size_t e : a.edges) {
    const auto& ev = mesh.edge_vertices(e);
    const Eigen::Vector3d p = to_eigen_point(mesh.point(ev[0])), q = to_eigen_point(mesh.point(ev[1]));
    d = (std::max)({d, component_distance(mesh, b, p), component_distance(mesh, b, q), component_distance(mesh, b, 0.5 * (p + q))});
  }
  return d;
}

template <class Mesh>
Eigen::Vector3d tetrahedron_centroid(const Mesh& mesh, typename Mesh::Index t)
{
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for(auto v : mesh.tetrahedron_vertices(t)) c += to_eigen_point(mesh.point(v));
  return c / 4;
}

// The tetrahedra at the vertices of the cluster's components and those reached from them through faces
// whose centroid is within `radius` of every component of the cluster (the strip between two curves,
// the disk of a loop); empty if more than `maximum_size`.
template <class Mesh>
std::vector<typename Mesh::Index> flattening_region(const Mesh& mesh, const std::vector<const Singular_component*>& cluster,
                                                    double radius, std::size_t maximum_size)
{
  typedef typename Mesh::Index Index;
  std::unordered_map<Index, char> seen;
  std::deque<Index> queue;
  std::vector<Index> region;
  for(const Singular_component* c : cluster)
    for(std::size_t v : c->vertices)
      for(Index e : mesh.vertex_edges(Index(v)))
        for(Index t : mesh.edge_ring(e))
          if(seen.emplace(t, 1).second) { queue.push_back(t); region.push_back(t); }
  auto within = [&](Index t) {
    const Eigen::Vector3d p = tetrahedron_centroid(mesh, t);
    for(const Singular_component* c : cluster)
      if(component_distance(mesh, *c, p) > radius) return false;
    return true;
  };
  while(!queue.empty() && region.size() <= maximum_size) {
    const Index t = queue.front();
    queue.pop_front();
    for(int i = 0; i < 4; ++i) {
      const Index n = mesh.tetrahedron_neighbor(t, i);
      if(n == Mesh::null_index || !seen.emplace(n, 1).second || !within(n)) continue;
      queue.push_back(n);
      region.push_back(n);
    }
  }
  if(region.size() > maximum_size) region.clear();
  return region;
}

// Applies the changes (face, matching before) to the matchings `target(face)` if no boundary valence
// changes and the cost of the repair goes down; restores them otherwise.
template <class Mesh, class Target>
Flattening apply_if_cheaper(Singularity_repair_state<Mesh>& state, const std::vector<std::pair<typename Mesh::Index, int> >& changes,
                      const Target& target)
{
  typedef typename Mesh::Index Index;
  const Mesh& mesh = state.mesh();
  if(changes.empty()) return Flattening::NOT_CHEAPER;
  std::vector<Index> edges, vertices, boundary_edges;
  for(const auto& c : changes) {
    for(Index e : state.face_edges(c.first)) (mesh.is_boundary_edge(e) ? boundary_edges : edges).push_back(e);
    for(Index v : mesh.face_vertices(c.first)) vertices.push_back(v);
  }
  for(std::vector<Index>* s : {&edges, &vertices, &boundary_edges}) {
    std::sort(s->begin(), s->end());
    s->erase(std::unique(s->begin(), s->end()), s->end());
  }
  std::vector<int> valences;
  for(Index e : boundary_edges) valences.push_back(state.achieved_valence(e));
  const double before = state.local_cost(edges, vertices);
  for(const auto& c : changes) state.apply(c.first, target(c.first));
  Flattening outcome = state.local_cost(edges, vertices) < before - 1e-9 ? Flattening::REMOVED : Flattening::NOT_CHEAPER;
  for(std::size_t k = 0; outcome == Flattening::REMOVED && k < boundary_edges.size(); ++k)
    if(state.achieved_valence(boundary_edges[k]) != valences[k]) outcome = Flattening::BOUNDARY_VALENCE;
  if(outcome != Flattening::REMOVED)
    for(const auto& c : changes) state.apply(c.first, c.second);
  return outcome;
}

// The gauge of the tetrahedron across face f from tetrahedron t, whose gauge is a.
template <class Mesh>
int carried_gauge(const Mesh& mesh, const Singularity_repair_state<Mesh>& state, typename Mesh::Index t, typename Mesh::Index f, int a)
{
  const Octahedral_group& group = octahedral_group();
  const int g = state.matching(f);
  return mesh.face_tetrahedra(f)[0] == t ? group.multiply(g, a) : group.multiply(group.inverse(g), a);
}

// Carries the gauge from `sources` into the tetrahedra `is(t, 1)` of the region, nearest first, the
// length of a step being how far the frames are from their matching across its face (3 - trace, in
// [0, 6]) plus a small constant.
template <class Mesh, class Role>
void spread_gauge_into_region(const Singularity_repair_state<Mesh>& state, const std::vector<typename Mesh::Index>& sources,
                              const Role& is, std::unordered_map<typename Mesh::Index, int>& gauge)
{
  typedef typename Mesh::Index Index;
  const Mesh& mesh = state.mesh();
  const Octahedral_group& group = octahedral_group();
  typedef std::pair<double, Index> Entry;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;
  std::unordered_map<Index, std::pair<double, Index> > best; // distance, face it is reached through
  for(Index t : sources) queue.push({0., t});
  while(!queue.empty()) {
    const Entry top = queue.top();
    queue.pop();
    const Index t = top.second;
    auto it = best.find(t);
    if(!gauge.count(t)) {
      if(it == best.end() || top.first > it->second.first) continue;
      const Index f = it->second.second;
      const auto& ft = mesh.face_tetrahedra(f);
      const Index from = ft[0] == t ? ft[1] : ft[0];
      gauge[t] = carried_gauge(mesh, state, from, f, gauge[from]);
    }
    for(int i = 0; i < 4; ++i) {
      const Index n = mesh.tetrahedron_neighbor(t, i);
      if(n == Mesh::null_index || gauge.count(n) || !is(n, 1)) continue;
      const Index f = mesh.tetrahedron_face(t, i);
      const auto& ft = mesh.face_tetrahedra(f);
      const Eigen::Matrix3d P = state.frames()[ft[1]].transpose() * state.frames()[ft[0]];
      double trace = 0;
      for(int c = 0; c < 3; ++c) trace += group.sign_of_column(state.matching(f), c) * P(group.row_of_column(state.matching(f), c), c);
      const double d = top.first + (3 - trace) + 1e-3;
      auto b = best.find(n);
      if(b != best.end() && b->second.first <= d) continue;
      best[n] = {d, f};
      queue.push({d, n});
    }
  }
}

// Makes the field flat in `region` (see the file's comment), or says why not (nothing changed then).
template <class Mesh>
Flattening flatten_region(Singularity_repair_state<Mesh>& state, const std::vector<typename Mesh::Index>& region)
{
  typedef typename Mesh::Index Index;
  const Mesh& mesh = state.mesh();
  const Octahedral_group& group = octahedral_group();
  enum Role : char { INSIDE = 1, COLLAR = 2 };
  std::unordered_map<Index, char> role;
  for(Index t : region) role[t] = INSIDE;
  std::vector<Index> collar;
  for(Index t : region) {
    const auto& tv = mesh.tetrahedron_vertices(t);
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
        for(Index n : mesh.edge_ring(mesh.find_edge(tv[i], tv[j])))
          if(role.emplace(n, COLLAR).second) collar.push_back(n);
  }
  auto is = [&](Index t, char r) { auto it = role.find(t); return it != role.end() && it->second == r; };
  // the gauge: across the collar first (one root per piece of it), then into the region from the whole
  // collar at once, along the faces where the frames agree best with the matchings (Dijkstra), so that
  // the old jumps inside (the sheets between the curves, where the frames turn) are crossed last
  std::unordered_map<Index, int> gauge;
  for(Index t : collar) {
    if(gauge.count(t)) continue;
    gauge[t] = Octahedral_group::identity_index;
    std::deque<Index> queue(1, t);
    while(!queue.empty()) {
      const Index u = queue.front();
      queue.pop_front();
      for(int i = 0; i < 4; ++i) {
        const Index n = mesh.tetrahedron_neighbor(u, i);
        if(n == Mesh::null_index || gauge.count(n) || !is(n, COLLAR)) continue;
        gauge[n] = carried_gauge(mesh, state, u, mesh.tetrahedron_face(u, i), gauge[u]);
        queue.push_back(n);
      }
    }
  }
  spread_gauge_into_region(state, collar, is, gauge);
  for(Index t : region)
    if(!gauge.count(t)) { gauge[t] = Octahedral_group::identity_index; spread_gauge_into_region(state, {t}, is, gauge); }
  auto gauge_matching = [&](Index f) {
    const auto& ft = mesh.face_tetrahedra(f);
    return group.multiply(gauge[ft[1]], group.inverse(gauge[ft[0]]));
  };
  for(Index t : collar)
    for(int i = 0; i < 4; ++i) {
      const Index n = mesh.tetrahedron_neighbor(t, i);
      if(n != Mesh::null_index && is(n, COLLAR) && state.matching(mesh.tetrahedron_face(t, i)) != gauge_matching(mesh.tetrahedron_face(t, i)))
        return Flattening::COLLAR_NOT_FLAT; // another curve crosses the collar, or the cluster's holonomies do not cancel
    }
  std::vector<std::pair<Index, int> > changes; // (face, matching before)
  std::unordered_map<Index, char> changed;
  for(Index t : region)
    for(int i = 0; i < 4; ++i) {
      const Index f = mesh.tetrahedron_face(t, i);
      if(mesh.tetrahedron_neighbor(t, i) == Mesh::null_index || !changed.emplace(f, 1).second) continue;
      if(state.matching(f) == gauge_matching(f)) continue;
      if(!state.is_editable(f)) return Flattening::NOT_EDITABLE;
      changes.emplace_back(f, state.matching(f));
    }
  return apply_if_cheaper(state, changes, gauge_matching);
}

// Removes the clusters of singular curves that have no room at hex edge `hex_edge_length`: a component
// whose bounding box is smaller than a hex edge (a small loop, a short stub between boundary points),
// and two components within a hex edge of each other everywhere (Hausdorff distance), such as a 3-5
// pair.
template <class Mesh>
Hex_scale_simplification simplify_at_hex_scale(Singularity_repair_state<Mesh>& state, double hex_edge_length)
{
  Hex_scale_simplification report;
  if(!(hex_edge_length > 0)) return report;
  const Mesh& mesh = state.mesh();
  const std::vector<Singular_component> components = singular_components(state);
  const double h = hex_edge_length, margin = state.mean_edge_length();
  const std::size_t maximum_size = (std::max)(std::size_t(100000), mesh.number_of_tetrahedra() / 4);
  struct Cluster { std::size_t a, b; double radius; };
  std::vector<Cluster> clusters;
  for(std::size_t i = 0; i < components.size(); ++i) {
    const double diagonal = components[i].box.diagonal().norm();
    if(diagonal < h) clusters.push_back({i, i, 0.5 * diagonal + margin});
  }
  for(std::size_t i = 0; i < components.size(); ++i)
    for(std::size_t j = i + 1; j < components.size(); ++j) {
      if(components[i].box.exteriorDistance(components[j].box) >= h) continue;
      const double d = (std::max)(directed_hausdorff(mesh, components[i], components[j]),
                                  directed_hausdorff(mesh, components[j], components[i]));
      if(d < h) clusters.push_back({i, j, d + margin});
    }
  for(const Cluster& c : clusters) {
    // a component already removed with another cluster
    if(!is_singular_class(state.edge_class(typename Mesh::Index(components[c.a].edges[0]))) ||
       !is_singular_class(state.edge_class(typename Mesh::Index(components[c.b].edges[0]))))
      continue;
    std::vector<const Singular_component*> cluster(1, &components[c.a]);
    if(c.b != c.a) cluster.push_back(&components[c.b]);
    const auto region = flattening_region(mesh, cluster, c.radius, maximum_size);
    report.count(region.empty() ? Flattening::TOO_LARGE : flatten_region(state, region));
  }
  return report;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_SIMPLIFY_AT_HEX_SCALE_H
