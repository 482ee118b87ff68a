// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_SINGULARITY_GRAPH_H
#define CGAL_HEXAHEDRAL_REMESHING_SINGULARITY_GRAPH_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// A quarter-turn edge whose |cos| to its holonomy axis exceeds this reads as valence 3 or 5 by the sign
// in compute_singularity_graph() (up to about 75.5 degrees off the axis); nearer perpendicular, it is a
// jog that takes a neighbour's valence.
constexpr double lenient_axis_cosine = 0.25;

} // namespace internal

/// \ingroup PkgHexahedralRemeshingRef
/// Matchings of a frame field: for each interior face `f` with tetrahedra `(t0, t1) =
/// mesh.face_tetrahedra(f)`, the element `g_f` of the octahedral group (index 0..23 of
/// `internal::Octahedral_group`) such that `E_t0 ~ E_t1 g_f` (Eq. 2 of the paper).
struct Matchings
{
  /// Per face: the group element, -1 on the boundary.
  std::vector<int> face_matching;
  /// Per face: the rotation angle (radians) between `E_t0` and `E_t1 g_f`, 0 on the boundary.
  std::vector<double> face_angle;
  /// Number of interior faces whose frames differ by more than 45 degrees after matching
  /// (the field is under-resolved there and the matching is ambiguous).
  std::size_t under_resolved_faces = 0;

  /// The group element `g` with `E_from ~ E_to g` for a step from tetrahedron `from` to its
  /// neighbour across face `f`.
  template <class Mesh>
  int step(const Mesh& mesh, typename Mesh::Index f, typename Mesh::Index from) const
  {
    const int g = face_matching[f];
    return mesh.face_tetrahedra(f)[0] == from ? g : internal::octahedral_group().inverse(g);
  }
};

/// \ingroup PkgHexahedralRemeshingRef
/// Computes the matchings `g_ij = argmin_g |E_i - E_j g|_F` over the 24 rotations of the cube.
template <class Traits>
Matchings compute_matchings(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames)
{
  if(frames.size() != mesh.number_of_tetrahedra()) throw Error("compute_matchings: one frame per tetrahedron expected");
  Matchings m;
  m.face_matching.assign(mesh.number_of_faces(), -1);
  m.face_angle.assign(mesh.number_of_faces(), 0.);
  const std::ptrdiff_t nf = std::ptrdiff_t(mesh.number_of_faces());
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
  for(std::ptrdiff_t f = 0; f < nf; ++f) {
    const auto& ft = mesh.face_tetrahedra(typename Tetrahedral_mesh_3<Traits>::Index(f));
    if(ft[1] == Tetrahedral_mesh_3<Traits>::null_index) continue;
    const internal::Octahedral_matching r = internal::closest_matching(frames[ft[0]], frames[ft[1]]);
    m.face_matching[f] = r.index;
    // trace = 1 + 2 cos(angle)
    m.face_angle[f] = std::acos(std::clamp((r.trace - 1.0) / 2.0, -1.0, 1.0));
  }
  for(double a : m.face_angle) m.under_resolved_faces += (a > CGAL_PI / 4);
  return m;
}

/// \ingroup PkgHexahedralRemeshingRef
/// A chain of singular interior edges of one type.
struct Singular_curve
{
  /// Valence of its edges: 3 or 5, or 0 for improper edges.
  int valence = 0;
  /// Its edges, in order.
  std::vector<std::uint32_t> edges;
  /// Its vertices, in order (one more than the edges, first == last if closed).
  std::vector<std::uint32_t> vertices;
  /// True if the curve is a closed loop.
  bool closed = false;
};

/// \ingroup PkgHexahedralRemeshingRef
/// Singularity graph of a frame field: the type of every interior edge from the holonomy of the
/// matchings around it (guide 2.3), the singular curves, and cheap meshability flags.
struct Singularity_graph
{
  /// Per edge: 4 for a regular interior edge, 3 or 5 for a singular one, 0 for an improper one
  /// (any other holonomy: half turn, third turn, or a quarter turn about an axis more than 75.5
  /// degrees away from the edge that is not the jog of a neighbouring singular curve with the same
  /// axis), -1 for a boundary edge.
  std::vector<signed char> edge_valence;
  /// Per edge: the holonomy (group element) around an interior edge, -1 on the boundary.
  std::vector<int> edge_holonomy;
  /// The singular curves.
  std::vector<Singular_curve> curves;
  /// Numbers of edges by type.
  std::size_t valence3_edges = 0;
  /// Number of valence-5 edges.
  std::size_t valence5_edges = 0;
  /// Number of improper edges.
  std::size_t improper_edges = 0;
  /// Interior vertices where exactly one singular edge ends (a dangling curve end: not meshable).
  std::vector<std::uint32_t> dangling_vertices;
  /// Interior vertices where a valence-3 curve turns into a valence-5 one (a zipper: not meshable).
  std::vector<std::uint32_t> zipper_vertices;

  /// Number of curves of the given valence (0 for improper).
  std::size_t number_of_curves(int valence) const
  {
    return std::size_t(std::count_if(curves.begin(), curves.end(), [&](const Singular_curve& c) { return c.valence == valence; }));
  }
};

/// \ingroup PkgHexahedralRemeshingRef
/// Computes the singularity graph of `frames` with matchings `matchings`.
template <class Traits>
Singularity_graph compute_singularity_graph(const Tetrahedral_mesh_3<Traits>& mesh,
                                            const std::vector<Eigen::Matrix3d>& frames,
                                            const Matchings& matchings)
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  const internal::Octahedral_group& group = internal::octahedral_group();
  Singularity_graph g;
  const std::size_t ne = mesh.number_of_edges();
  g.edge_valence.assign(ne, -1);
  g.edge_holonomy.assign(ne, -1);
  auto direction = [&](Index e) {
    const auto& ev = mesh.edge_vertices(e);
    const auto dv = mesh.point(ev[1]) - mesh.point(ev[0]);
    return Eigen::Vector3d(CGAL::to_double(dv.x()), CGAL::to_double(dv.y()), CGAL::to_double(dv.z())).normalized();
  };
  auto world_axis = [&](Index e) -> Eigen::Vector3d { return frames[mesh.edge_ring(e)[0]] * group.axis(g.edge_holonomy[e]); };
  std::vector<Index> jogs;
  for(Index e = 0; e < ne; ++e) {
    if(mesh.is_boundary_edge(e)) continue;
    const auto ring = mesh.edge_ring(e);
    const auto faces = mesh.edge_ring_faces(e);
    // G = g_{t(m-1) t0} ... g_{t1 t2} g_{t0 t1}: E_t0 ~ E_t0 G after a counter-clockwise turn
    int G = internal::Octahedral_group::identity_index;
    for(std::size_t k = 0; k < ring.size(); ++k) G = group.multiply(matchings.step(mesh, faces[k], ring[k]), G);
    g.edge_holonomy[e] = G;
    signed char valence = 0;
    if(G == internal::Octahedral_group::identity_index) {
      valence = 4;
    } else if(group.rotation_class(G) == internal::Octahedral_rotation_class::QUARTER_TURN) {
      const double c = world_axis(e).dot(direction(e));
      // a quarter turn about an axis along the edge: valence 4 - phi/(pi/2). Singular curves of a
      // tet mesh zigzag along their true direction, so edges up to ~70 degrees off the holonomy
      // axis occur on perfectly valid curves (measured on TetGen cylinders); an edge nearly
      // perpendicular to the axis (more than ~75.5 degrees, |cos| < 1/4) is a jog of a curve whose
      // valence is decided below from its neighbours.
      if(std::abs(c) > internal::lenient_axis_cosine) valence = c > 0 ? 3 : 5;
      else jogs.push_back(e);
    }
    g.edge_valence[e] = valence;
  }
  // A jog inherits the valence of a classified singular edge that shares one of its vertices and
  // whose holonomy axis is parallel to its own (the same curve); jogs with no such neighbour stay
  // improper.
  for(bool changed = true; changed;) {
    changed = false;
    for(Index e : jogs) {
      if(g.edge_valence[e] != 0) continue;
      const Eigen::Vector3d A = world_axis(e);
      for(Index v : mesh.edge_vertices(e))
        for(Index n : mesh.vertex_edges(v)) {
          if(n == e || (g.edge_valence[n] != 3 && g.edge_valence[n] != 5)) continue;
          if(std::abs(world_axis(n).dot(A)) < std::sqrt(0.5)) continue;
          g.edge_valence[e] = g.edge_valence[n];
          changed = true;
          break;
        }
    }
  }
  for(Index e = 0; e < ne; ++e) {
    if(g.edge_valence[e] == 3) ++g.valence3_edges;
    else if(g.edge_valence[e] == 5) ++g.valence5_edges;
    else if(g.edge_valence[e] == 0) ++g.improper_edges;
  }

  // Singular curves: maximal chains of singular edges of one valence through vertices of
  // singular degree 2 (deterministic: edges visited in increasing index).
  std::vector<std::uint32_t> degree(mesh.number_of_vertices(), 0);
  auto singular = [&](Index e) { return g.edge_valence[e] >= 0 && g.edge_valence[e] != 4; };
  for(Index e = 0; e < ne; ++e)
    if(singular(e)) for(Index v : mesh.edge_vertices(e)) ++degree[v];
  auto singular_edges_at = [&](Index v) {
    std::vector<Index> out;
    for(Index e : mesh.vertex_edges(v)) if(singular(e)) out.push_back(e);
    return out;
  };
  for(Index v = 0; v < mesh.number_of_vertices(); ++v) {
    if(mesh.is_boundary_vertex(v)) continue;
    if(degree[v] == 1) g.dangling_vertices.push_back(v);
    if(degree[v] == 2) {
      const auto es = singular_edges_at(v);
      if(g.edge_valence[es[0]] != g.edge_valence[es[1]]) g.zipper_vertices.push_back(v);
    }
  }
  std::vector<char> used(ne, 0);
  auto pass_through = [&](Index v, Index from) -> Index {
    // continue a curve through v if v is interior-or-boundary of degree 2 with the same valence
    if(degree[v] != 2) return Tetrahedral_mesh_3<Traits>::null_index;
    for(Index e : singular_edges_at(v))
      if(e != from && g.edge_valence[e] == g.edge_valence[from]) return e;
    return Tetrahedral_mesh_3<Traits>::null_index;
  };
  for(Index e0 = 0; e0 < ne; ++e0) {
    if(!singular(e0) || used[e0]) continue;
    // walk backwards to the start of the chain (or around a loop)
    Index start = e0, start_vertex = mesh.edge_vertices(e0)[0];
    bool closed = false;
    for(;;) {
      const Index prev = pass_through(start_vertex, start);
      if(prev == Tetrahedral_mesh_3<Traits>::null_index) break;
      if(prev == e0) { closed = true; break; }
      const auto& pv = mesh.edge_vertices(prev);
      start_vertex = pv[0] == start_vertex ? pv[1] : pv[0];
      start = prev;
    }
    if(closed) { start = e0; start_vertex = mesh.edge_vertices(e0)[0]; }
    Singular_curve c;
    c.valence = g.edge_valence[e0];
    c.closed = closed;
    c.vertices.push_back(start_vertex);
    Index e = start, v = start_vertex;
    while(e != Tetrahedral_mesh_3<Traits>::null_index && !used[e]) {
      used[e] = 1;
      c.edges.push_back(e);
      const auto& ev = mesh.edge_vertices(e);
      v = ev[0] == v ? ev[1] : ev[0];
      c.vertices.push_back(v);
      e = pass_through(v, e);
    }
    g.curves.push_back(c);
  }
  return g;
}

namespace internal {

// Whether achieved valence k is the prescribed p (modulo 4 for p >= 5: a frame field cannot tell k
// from k + 4, paper Sec. 6.2).
inline bool achieves_valence(int k, int p) { return p >= 5 ? ((k - p) % 4 + 4) % 4 == 0 : k == p; }

// The valence boundary edge e gets from the frames and the matchings `face_matching` (Eq. 3 of the
// paper, see compute_achieved_boundary_valences()); `k_real`, if given, receives the real value of Eq. 3.
template <class Traits>
int achieved_boundary_valence(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames,
                              const std::vector<int>& face_matching, const std::vector<Eigen::Vector3d>& directions,
                              typename Tetrahedral_mesh_3<Traits>::Index e, double* k_real = nullptr)
{
  const Octahedral_group& group = octahedral_group();
  auto to_eigen = [](const typename Traits::Vector_3& v) {
    return Eigen::Vector3d(CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z()));
  };
  const auto ring = mesh.edge_ring(e);
  const auto faces = mesh.edge_ring_faces(e);
  const auto& bt = mesh.edge_boundary_triangles(e);
  // H = g_{t(m-1) tm} ... g_{t1 t2}, so that E_t1 ~ E_tm H
  int H = Octahedral_group::identity_index;
  for(std::size_t k = 0; k + 1 < ring.size(); ++k) {
    const int g = face_matching[faces[k + 1]];
    H = group.multiply(mesh.face_tetrahedra(faces[k + 1])[0] == ring[k] ? g : group.inverse(g), H);
  }
  const Eigen::Matrix3d R = frames[ring.front()] * group.matrix(H).transpose() * frames[ring.back()].transpose();
  const auto& ev = mesh.edge_vertices(e);
  const Eigen::Vector3d half_edge = to_eigen(mesh.point(ev[0]) - mesh.point(ev[1])).normalized(); // e_ij of triangle i
  const Eigen::Vector3d di = directions[bt[0]].normalized(), dj = directions[bt[1]].normalized();
  const Eigen::Vector3d Rdj = R * dj;
  const double real = 2.0 - (2.0 / CGAL_PI) * std::atan2(di.cross(Rdj).dot(half_edge), di.dot(Rdj));
  if(k_real != nullptr) *k_real = real;
  const int k_mod = ((int(std::round(real)) % 4) + 4) % 4;
  const double phi = CGAL_PI - std::atan2(di.cross(dj).dot(half_edge), di.dot(dj)); // [0, 2 pi]
  const double target = 2.0 * phi / CGAL_PI;
  int k = k_mod;
  while(std::abs(k + 4 - target) < std::abs(k - target)) k += 4;
  return k;
}

} // namespace internal

/// \ingroup PkgHexahedralRemeshingRef
/// Valences of the boundary edges produced by a frame field (Eq. 3 of the paper).
struct Boundary_valences
{
  /// Per edge: the achieved valence of a boundary edge, -1 for an interior edge.
  std::vector<int> achieved;
  /// Largest distance of Eq. (3) to an integer over the boundary edges (0 for perfectly aligned frames).
  double max_deviation = 0;
  /// Number of boundary edges.
  std::size_t total = 0;
  /// Boundary edges whose achieved valence equals the prescribed one (modulo 4 for prescribed
  /// valences of 5 or more: a frame field cannot tell k from k + 4, paper Sec. 6.2).
  std::size_t matched = 0;
  /// Boundary edges whose achieved valence differs from the prescribed one.
  std::size_t mismatched = 0;
  /// Histogram of the achieved valences 0..4.
  std::array<std::size_t, 5> histogram{{0, 0, 0, 0, 0}};
};

/// \ingroup PkgHexahedralRemeshingRef
/// Valence of every boundary edge as the frame field makes it, from Eq. (3) of the paper with the
/// transport `R = E_t1 H^T E_tm^T` through the ring of tetrahedra (guide 2.4), evaluated with the
/// directions the frames are aligned with (`directions`, per boundary triangle: the constraints
/// `v` for the field of step 2, the normals after realignment). Eq. (3) gives the valence modulo 4;
/// the representative is the one closest to `2 phi(d_i, d_j) / pi`.
///
/// \param mesh the mesh the frames live on
/// \param frames one frame per tetrahedron
/// \param matchings the matchings of `frames` (`compute_matchings()`)
/// \param directions the directions the boundary frames are aligned with, one per boundary triangle
/// \param prescribed per edge, the prescribed valence (boundary edges), or empty to only measure
/// \returns the achieved valence of every boundary edge and, if `prescribed` is given, the counts of
///          matched and mismatched edges
/// \throws Error if `directions` does not have one entry per boundary triangle.
template <class Traits>
Boundary_valences compute_achieved_boundary_valences(const Tetrahedral_mesh_3<Traits>& mesh,
                                                     const std::vector<Eigen::Matrix3d>& frames,
                                                     const Matchings& matchings,
                                                     const std::vector<Eigen::Vector3d>& directions,
                                                     const std::vector<int>& prescribed = std::vector<int>())
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  if(directions.size() != mesh.number_of_boundary_triangles())
    throw Error("compute_achieved_boundary_valences: one direction per boundary triangle expected");
  Boundary_valences r;
  r.achieved.assign(mesh.number_of_edges(), -1);
  for(Index e : mesh.boundary_edges()) {
    double k_real = 0;
    const int k = internal::achieved_boundary_valence(mesh, frames, matchings.face_matching, directions, e, &k_real);
    r.max_deviation = (std::max)(r.max_deviation, std::abs(k_real - std::round(k_real)));
    r.achieved[e] = k;
    ++r.total;
    ++r.histogram[std::size_t((std::min)(k, 4))];
    if(!prescribed.empty()) internal::achieves_valence(k, prescribed[e]) ? ++r.matched : ++r.mismatched;
  }
  return r;
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_SINGULARITY_GRAPH_H
