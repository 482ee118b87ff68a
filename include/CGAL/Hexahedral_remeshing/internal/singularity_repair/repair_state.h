// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// The state of the singularity-graph repair: the kept matchings being edited, the holonomy and class
// of every interior edge, and the local cost that every operation must lower. A change of the
// matching of one face changes the holonomy of its three edges only (Li et al. 2012: moving a
// singular edge across a triangle), so a change is evaluated on those edges and their vertices.
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_REPAIR_STATE_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_REPAIR_STATE_H

#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/edge_holonomy.h>
#include <CGAL/Hexahedral_remeshing/local_meshability.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>

#include <Eigen/Dense>

#include <array>
#include <cstdint>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// A proposed change: face `face` gets matching `matching`, then (if `second_face` is not -1)
// `second_face` gets `second_matching`, then each face of `more` its matching, in order; `delta` the
// change of the cost.
struct Face_change
{
  std::uint32_t face = 0;
  int matching = -1;
  double delta = 0;
  std::int64_t second_face = -1;
  int second_matching = -1;
  std::vector<std::pair<std::uint32_t, int> > more;
};

template <class Mesh>
class Singularity_repair_state
{
public:
  typedef typename Mesh::Index Index;

  // `directions` (per boundary triangle, the directions the frames follow; may be null): with them,
  // faces with a boundary edge may change too, as long as the valence every boundary edge gets
  // (Eq. 3) stays the same; without them, such faces are never changed.
  Singularity_repair_state(const Mesh& mesh, const std::vector<Eigen::Matrix3d>& frames, std::vector<int>& face_matching,
                           const std::vector<Eigen::Vector3d>* directions = nullptr)
    : m_mesh(mesh), m_frames(frames), m_matching(face_matching), m_directions(directions)
  {
    const std::size_t ne = mesh.number_of_edges();
    m_holonomy.assign(ne, -1);
    m_class.assign(ne, -1);
    m_lean.assign(ne, 0);
    double total = 0;
    for(Index e = 0; e < ne; ++e) {
      const auto& ev = mesh.edge_vertices(e);
      total += (to_eigen_point(mesh.point(ev[1])) - to_eigen_point(mesh.point(ev[0]))).norm();
      if(mesh.is_boundary_edge(e)) continue;
      m_holonomy[e] = edge_holonomy(mesh, m_matching, e);
      m_class[e] = classify(e, m_holonomy[e]);
      m_lean[e] = lean(e, m_holonomy[e], m_class[e]);
    }
    m_mean_length = ne > 0 ? total / double(ne) : 1.0;
    // every change keeps them (evaluate()): the hexahedra at a boundary vertex are counted from them
    if(m_directions != nullptr) {
      m_achieved.assign(ne, -1);
      for(Index e : mesh.boundary_edges()) m_achieved[e] = boundary_valence(e);
    }
  }

  const Mesh& mesh() const { return m_mesh; }
  const std::vector<signed char>& edge_classes() const { return m_class; }
  signed char edge_class(Index e) const { return m_class[e]; }
  int matching(Index f) const { return m_matching[f]; }

  // The edges of face f (found once per face asked).
  std::array<Index, 3> face_edges(Index f) const
  {
    const auto& fv = m_mesh.face_vertices(f);
    return {{m_mesh.find_edge(fv[0], fv[1]), m_mesh.find_edge(fv[1], fv[2]), m_mesh.find_edge(fv[2], fv[0])}};
  }

  // Interior faces; those with a boundary edge only if the directions are known, so that every change
  // can be checked to keep the boundary valences the paper guarantees.
  bool is_editable(Index f) const
  {
    if(m_mesh.is_boundary_face(f)) return false;
    if(m_directions != nullptr) return true;
    for(Index e : face_edges(f)) if(m_mesh.is_boundary_edge(e)) return false;
    return true;
  }

  double edge_cost(Index e, signed char c, int G) const
  {
    if(c == 4 || c < 0) return 0;
    if(c == IMPROPER_CLASS) return 20;
    const auto& ev = m_mesh.edge_vertices(e);
    const double length = (to_eigen_point(m_mesh.point(ev[1])) - to_eigen_point(m_mesh.point(ev[0]))).norm() / m_mean_length;
    const double a = std::abs(holonomy_axis_cosine(m_mesh, m_frames, e, G));
    // a jog costs more the further it is off its axis, so that a jog can be walked off in steps
    if(c == JOG_CLASS) return 4 + 4 * (std::sqrt(0.5) - a) / std::sqrt(0.5) + 0.05 * length;
    return 0.05 * length * (2 - a);
  }

  static double vertex_cost(const Vertex_singularity& s)
  {
    switch(s.kind) {
      case Vertex_singularity::NONE: return 0;
      case Vertex_singularity::BOUNDARY_CONTACT: return 5;
      default: return 10;
    }
  }

  // A boundary vertex whose hexahedra cannot be counted (is_meshable_boundary_corner(): a curve ending
  // at a box corner, four concave edges of valence 3 with no curve ending there); known only with the
  // directions, which give the boundary valences.
  bool is_invalid_boundary_corner(Index v) const
  {
    return m_directions != nullptr && m_mesh.is_boundary_vertex(v) && !is_meshable_boundary_corner(m_mesh, m_class, m_achieved, v);
  }

  // A vertex where a curve turns from one lean to the other (is_leaning_zipper()).
  bool turns_lean(Index v) const { return is_leaning_zipper(m_mesh, m_class, m_lean, v); }

  // A curve ending in a boundary plane (ends_in_boundary_plane()): its whole curve is flat against a
  // patch in every map.
  bool ends_in_boundary_plane(Index v) const
  {
    return internal::ends_in_boundary_plane(m_mesh, m_frames, m_class, m_holonomy, v);
  }
  // A vertex where the curve turns from one lean to the other costs as a zipper: the map reports it
  // as one (see edge_lean()); an invalid boundary corner as an invalid node; a curve ending in a
  // boundary plane or a zigzag as a boundary contact.
  double vertex_cost(Index v) const
  {
    const double c = vertex_cost(vertex_singularity(m_mesh, m_class, v));
    if(c != 0) return c;
    if(is_leaning_zipper(m_mesh, m_class, m_lean, v) || is_invalid_boundary_corner(v)) return 10;
    return ends_in_boundary_plane(v) || is_zigzag(v) ? 5 : 0;
  }

  // An interior curve vertex whose two singular edges bound a face (zigzag_face()): that face is flat in
  // every map.
  bool is_zigzag(Index v) const { return zigzag_face(m_mesh, m_class, v) != Mesh::null_index; }

  // The change of the cost if face f had matching g (infinite if a boundary edge's valence changes).
  double evaluate(Index f, int g)
  {
    const std::array<Index, 3> edges = face_edges(f);
    const auto& fv = m_mesh.face_vertices(f);
    double before = 0, after = 0;
    for(Index v : fv) before += vertex_cost(v);
    std::array<int, 3> G;
    std::array<signed char, 3> c;
    std::array<int, 3> valence{{-1, -1, -1}};
    for(int i = 0; i < 3; ++i) {
      before += edge_cost(edges[i], m_class[edges[i]], m_holonomy[edges[i]]);
      if(m_mesh.is_boundary_edge(edges[i])) valence[i] = boundary_valence(edges[i]);
    }
    const int old = m_matching[f];
    m_matching[f] = g;
    bool keeps_valences = true;
    for(int i = 0; i < 3; ++i) {
      if(m_mesh.is_boundary_edge(edges[i])) {
        keeps_valences = keeps_valences && boundary_valence(edges[i]) == valence[i];
        G[i] = -1;
        c[i] = -1;
        continue;
      }
      G[i] = edge_holonomy(m_mesh, m_matching, edges[i]);
      c[i] = classify(edges[i], G[i]);
      after += edge_cost(edges[i], c[i], G[i]);
    }
    std::array<signed char, 3> saved, saved_lean;
    std::array<int, 3> saved_holonomy;
    for(int i = 0; i < 3; ++i) {
      saved[i] = m_class[edges[i]];
      saved_lean[i] = m_lean[edges[i]];
      saved_holonomy[i] = m_holonomy[edges[i]];
      m_class[edges[i]] = c[i];
      m_lean[edges[i]] = c[i] < 0 ? 0 : lean(edges[i], G[i], c[i]);
      if(c[i] >= 0) m_holonomy[edges[i]] = G[i];
    }
    for(Index v : fv) after += vertex_cost(v);
    for(int i = 0; i < 3; ++i) {
      m_class[edges[i]] = saved[i];
      m_lean[edges[i]] = saved_lean[i];
      m_holonomy[edges[i]] = saved_holonomy[i];
    }
    m_matching[f] = old;
    return keeps_valences ? after - before : std::numeric_limits<double>::infinity();
  }

  // The change of the cost of a change of one face or more, evaluated one after the other.
  double evaluate(const Face_change& c)
  {
    if(c.second_face < 0 && c.more.empty()) return evaluate(c.face, c.matching);
    std::vector<std::pair<Index, int> > undo;
    double delta = 0;
    for_each_face(c, [&](Index f, int g) {
      delta += evaluate(f, g);
      undo.emplace_back(f, m_matching[f]);
      apply(f, g);
    });
    for(auto u = undo.rbegin(); u != undo.rend(); ++u) apply(u->first, u->second);
    return delta;
  }

  void apply(const Face_change& c)
  {
    for_each_face(c, [&](Index f, int g) { apply(f, g); });
  }

  // Calls fn(face, matching) for each face of c, in order.
  template <class Fn>
  static void for_each_face(const Face_change& c, const Fn& fn)
  {
    fn(Index(c.face), c.matching);
    if(c.second_face >= 0) fn(Index(c.second_face), c.second_matching);
    for(const auto& m : c.more) fn(Index(m.first), m.second);
  }

  void apply(Index f, int g)
  {
    m_matching[f] = g;
    for(Index e : face_edges(f)) {
      if(m_mesh.is_boundary_edge(e)) continue;
      m_holonomy[e] = edge_holonomy(m_mesh, m_matching, e);
      m_class[e] = classify(e, m_holonomy[e]);
      m_lean[e] = lean(e, m_holonomy[e], m_class[e]);
    }
  }

  int holonomy(Index e) const { return m_holonomy[e]; }
  const std::vector<int>& holonomies() const { return m_holonomy; }
  double mean_edge_length() const { return m_mean_length; }
  const std::vector<Eigen::Matrix3d>& frames() const { return m_frames; }

  // The cost of the given edges and vertices as the field stands.
  double local_cost(const std::vector<Index>& edges, const std::vector<Index>& vertices) const
  {
    double c = 0;
    for(Index e : edges) c += edge_cost(e, m_class[e], m_holonomy[e]);
    for(Index v : vertices) c += vertex_cost(v);
    return c;
  }

  // The valence boundary edge e achieves (Eq. 3) with the present matchings; -1 without directions.
  int achieved_valence(Index e) const { return m_directions == nullptr ? -1 : boundary_valence(e); }

private:
  signed char classify(Index e, int G) const { return classify_edge(m_mesh, m_frames, e, G); }
  signed char lean(Index e, int G, signed char c) const { return edge_lean(m_mesh, m_frames, e, G, c); }
  int boundary_valence(Index e) const { return achieved_boundary_valence(m_mesh, m_frames, m_matching, *m_directions, e); }

  const Mesh& m_mesh;
  const std::vector<Eigen::Matrix3d>& m_frames;
  std::vector<int>& m_matching;
  const std::vector<Eigen::Vector3d>* m_directions;
  std::vector<int> m_holonomy;
  std::vector<signed char> m_class;
  std::vector<signed char> m_lean; // edge_lean() per interior edge
  std::vector<int> m_achieved;      // per boundary edge, its valence (with the directions only)
  double m_mean_length = 1;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_REPAIR_STATE_H
