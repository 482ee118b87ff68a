// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_LOCAL_MESHABILITY_H
#define CGAL_HEXAHEDRAL_REMESHING_LOCAL_MESHABILITY_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/edge_holonomy.h>

#include <Eigen/Dense>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// Why a location of a frame field is not locally hex-meshable (design notes `robust_pipeline.md` §1;
/// Liu, Bommes et al., "Locally Meshable Frame Fields", 2023).
enum class Meshability_reason {
  /// An interior edge whose holonomy is neither the identity nor a quarter turn (a compound edge).
  IMPROPER_EDGE,
  /// A singular edge (quarter-turn holonomy) more than 45 degrees off its holonomy axis.
  JOG,
  /// An interior vertex where exactly one singular edge ends.
  DANGLING_END,
  /// An interior vertex where a valence-3 curve turns into a valence-5 one.
  ZIPPER,
  /// An interior vertex where three or more singular edges meet in a configuration that no hex-mesh
  /// vertex has: the link of a hex-mesh vertex is a triangulated sphere, so the valences `k` of the
  /// hex edges at the vertex satisfy `sum (6 - k) = 12` (with `k >= 3`); with `n3` valence-3 and
  /// `n5` valence-5 edges, `12 - 3 n3 - n5` must be even and non-negative (the regular edges make up
  /// the rest, 2 each). A necessary condition, not the full local parametrization test. At a boundary
  /// vertex (checked when the boundary valences are given), the link is a triangulated disk, whose
  /// Euler formula gives the number of hexahedra at the vertex, `F = 4 + sum (k - 2)` over its feature
  /// edges `+ sum (k - 4)` over its singular edges: `F >= 1`, and `F <= 7` without a singular edge
  /// (the apex of a square pyramid, four convex edges of valence 1, has `F = 0`: a curve must end there).
  INVALID_NODE,
  /// A boundary vertex where a singular curve touches the boundary and goes on (two singular edges of
  /// the same valence, nothing ends there).
  BOUNDARY_CONTACT,
  /// A boundary edge whose valence, as the frames make it, differs from the prescribed one (the sectors
  /// of the feature do not fit its valence).
  FEATURE_SECTOR,
  /// An interior face where the closest matching of the frames differs from the kept matching.
  DISAGREEING_FACE,
  /// A boundary vertex where a singular curve ends (or touches the boundary) on a boundary triangle
  /// that runs alongside the curve: the frame axis closest to the triangle's normal is not the curve's
  /// holonomy axis. The map puts the triangle on an integer plane and the curve on an integer line
  /// sharing that coordinate, so the whole curve lies in the patch's plane and every tetrahedron
  /// between them is flat in every map. A curve ends on faces it crosses (a curve ending on a feature
  /// curve next to a patch parallel to it, or bending into the boundary with a jog).
  END_IN_BOUNDARY_PLANE,
  /// An interior face a-v-c whose edges v-a and v-c are two consecutive edges of one singular curve
  /// (valence 3 or 5 both) and whose third edge a-c is the chord of the bend: the map puts a, v and c on
  /// the curve's parameter line, so the face is degenerate and both tetrahedra on it are flat in every
  /// map. The singular edges may be within 45 degrees of their axis (not jogs); reported at v.
  ZIGZAG_FACE
};

/// \ingroup PkgHexahedralRemeshingRef
/// Number of values of `Meshability_reason`.
constexpr std::size_t number_of_meshability_reasons = 10;

/// \ingroup PkgHexahedralRemeshingRef
/// The name of a reason in reports (`"improper_edge"`, `"jog"`, `"dangling_end"`, `"zipper"`,
/// `"invalid_node"`, `"boundary_contact"`, `"feature_sector"`, `"disagreeing_face"`,
/// `"end_in_boundary_plane"`, `"zigzag_face"`).
inline const char* meshability_reason_name(Meshability_reason reason)
{
  static const char* names[number_of_meshability_reasons] = {"improper_edge", "jog", "dangling_end", "zipper",
                                                              "invalid_node", "boundary_contact", "feature_sector",
                                                              "disagreeing_face", "end_in_boundary_plane", "zigzag_face"};
  return names[std::size_t(reason)];
}

/// \ingroup PkgHexahedralRemeshingRef
/// One location that fails the local meshability check.
struct Meshability_violation
{
  /// Why.
  Meshability_reason reason = Meshability_reason::IMPROPER_EDGE;
  /// Index of the edge (improper edge, jog, feature sector), vertex (dangling end, zipper, node,
  /// boundary contact, the bend of a zigzag face) or face (disagreeing face) in the tetrahedral mesh.
  std::uint32_t index = 0;
  /// Position in model units: the vertex, or the midpoint of the edge, or the centroid of the face.
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

namespace internal {

// Violations of the singularity graph itself: every reason but the feature sectors and the disagreeing
// faces, which the frames and the constraints decide.
inline std::size_t graph_defect_count(const std::array<std::size_t, number_of_meshability_reasons>& c)
{
  return c[std::size_t(Meshability_reason::IMPROPER_EDGE)] + c[std::size_t(Meshability_reason::JOG)] +
         c[std::size_t(Meshability_reason::DANGLING_END)] + c[std::size_t(Meshability_reason::ZIPPER)] +
         c[std::size_t(Meshability_reason::INVALID_NODE)] + c[std::size_t(Meshability_reason::BOUNDARY_CONTACT)] +
         c[std::size_t(Meshability_reason::END_IN_BOUNDARY_PLANE)] + c[std::size_t(Meshability_reason::ZIGZAG_FACE)];
}

} // namespace internal

/// \ingroup PkgHexahedralRemeshingRef
/// Result of `check_local_meshability()`.
struct Local_meshability_report
{
  /// Every violation, edges first (by index), then vertices, then faces.
  std::vector<Meshability_violation> violations;
  /// Number of violations per reason (indexed by `Meshability_reason`).
  std::array<std::size_t, number_of_meshability_reasons> counts{};
  /// Per interior edge, its class in the check (`-1` boundary, 4 regular, 3 or 5 singular along its
  /// axis, 0 improper, `1` a jog).
  std::vector<signed char> edge_class;

  /// Number of violations of one reason.
  std::size_t count(Meshability_reason reason) const { return counts[std::size_t(reason)]; }
  /// Number of violations of every reason.
  std::size_t total() const
  {
    std::size_t n = 0;
    for(std::size_t c : counts) n += c;
    return n;
  }
  /// Number of violations of the singularity graph itself (every reason but the disagreeing faces and
  /// the feature sectors, which the frames and the constraints decide).
  std::size_t graph_defects() const { return internal::graph_defect_count(counts); }
};

namespace internal {

// Whether the hexahedra around boundary vertex v can be counted (design notes §1): the link of v in a
// hex mesh is a triangulated disk (one triangle per hexahedron at v, one vertex per hex edge at v,
// with as many triangles around it as the edge's valence k). Euler's formula for the disk,
// sum over interior link vertices of (6 - k) + sum over boundary ones of (3 - k) = 6, gives the
// number of hexahedra at v, F = 4 + sum over feature edges (k - 2) + sum over singular edges (k - 4),
// the boundary edges of valence 2 and the regular interior edges (4) being free in number but not
// negative: sum (3 - k) + sum (6 - k) <= 6 over feature and singular edges. Without a singular edge at
// v, its hexahedra are octants of one chart, distinct and fewer than the 8 of an interior vertex:
// 1 <= F <= 7. A square pyramid's apex (four convex edges of valence 1: F = 0) or the apex of a
// pyramid-shaped cavity (four concave edges of valence 3: F = 8) fails: it needs a singular curve
// ending there. `edge_class`: the classes of the interior edges (a vertex with a jog or an improper
// edge is reported as such and passes here); `valence`: per boundary edge, its valence.
template <class Mesh>
bool is_meshable_boundary_corner(const Mesh& mesh, const std::vector<signed char>& edge_class, const std::vector<int>& valence,
                                 typename Mesh::Index v)
{
  int hexahedra = 4, fixed = 0, singular = 0;
  for(auto e : mesh.vertex_edges(v)) {
    if(mesh.is_boundary_edge(e)) {
      const int k = valence[e];
      if(k == 2) continue;
      hexahedra += k - 2;
      fixed += 3 - k;
    } else if(is_singular_class(edge_class[e])) {
      if(edge_class[e] != 3 && edge_class[e] != 5) return true;
      ++singular;
      hexahedra += edge_class[e] - 4;
      fixed += 6 - edge_class[e];
    }
  }
  return hexahedra >= 1 && fixed <= 6 && (singular > 0 || hexahedra <= 7);
}

// The check of check_local_meshability(), with the achieved boundary valences given (`achieved`,
// per edge, or null: no feature check) and the faces' check optional (`faces`: false when the
// matchings are the frames' closest ones, where no face can disagree).
template <class Traits>
Local_meshability_report local_meshability(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames,
                                           const Matchings& matchings, const std::vector<int>* achieved,
                                           const std::vector<int>& prescribed, bool faces)
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  Local_meshability_report r;
  auto point = [&](Index v) { return to_eigen_point(mesh.point(v)); };
  auto add = [&](Meshability_reason reason, Index index, const Eigen::Vector3d& p) {
    r.violations.push_back({reason, std::uint32_t(index), p});
    ++r.counts[std::size_t(reason)];
  };
  const std::size_t ne = mesh.number_of_edges();
  r.edge_class.assign(ne, -1);
  std::vector<int> holonomy(ne, Octahedral_group::identity_index);
  for(Index e = 0; e < ne; ++e) {
    if(mesh.is_boundary_edge(e)) continue;
    holonomy[e] = edge_holonomy(mesh, matchings.face_matching, e);
    r.edge_class[e] = classify_edge(mesh, frames, e, holonomy[e]);
    const auto& ev = mesh.edge_vertices(e);
    if(r.edge_class[e] == IMPROPER_CLASS) add(Meshability_reason::IMPROPER_EDGE, e, 0.5 * (point(ev[0]) + point(ev[1])));
    else if(r.edge_class[e] == JOG_CLASS) add(Meshability_reason::JOG, e, 0.5 * (point(ev[0]) + point(ev[1])));
  }
  if(achieved != nullptr)
    for(Index e : mesh.boundary_edges())
      if(!achieves_valence((*achieved)[e], prescribed[e])) {
        const auto& ev = mesh.edge_vertices(e);
        add(Meshability_reason::FEATURE_SECTOR, e, 0.5 * (point(ev[0]) + point(ev[1])));
      }
  for(Index v = 0; v < mesh.number_of_vertices(); ++v) {
    const Vertex_singularity s = vertex_singularity(mesh, r.edge_class, v);
    if(s.kind != Vertex_singularity::NONE) add(Meshability_reason(int(s.kind)), v, point(v));
    else if(achieved != nullptr && mesh.is_boundary_vertex(v) && !is_meshable_boundary_corner(mesh, r.edge_class, *achieved, v))
      add(Meshability_reason::INVALID_NODE, v, point(v));
    else if(ends_in_boundary_plane(mesh, frames, r.edge_class, holonomy, v))
      add(Meshability_reason::END_IN_BOUNDARY_PLANE, v, point(v));
    else if(s.kind == Vertex_singularity::NONE && zigzag_face(mesh, r.edge_class, v) != Tetrahedral_mesh_3<Traits>::null_index)
      add(Meshability_reason::ZIGZAG_FACE, v, point(v));
  }
  for(Index f = 0; faces && f < mesh.number_of_faces(); ++f) {
    if(mesh.is_boundary_face(f)) continue;
    const auto& ft = mesh.face_tetrahedra(f);
    if(closest_matching(frames[ft[0]], frames[ft[1]]).index == matchings.face_matching[f]) continue;
    const auto& fv = mesh.face_vertices(f);
    add(Meshability_reason::DISAGREEING_FACE, f, (point(fv[0]) + point(fv[1]) + point(fv[2])) / 3.0);
  }
  return r;
}

} // namespace internal

/// \ingroup PkgHexahedralRemeshingRef
/// Checks that a frame field with its kept matchings is locally hex-meshable: every interior edge's
/// holonomy (the product of the kept matchings around it) is the identity or a quarter turn about an
/// axis within 45 degrees of the edge; no singular curve ends inside the volume, turns from valence 3
/// into valence 5, touches the boundary without ending there, or ends on a boundary triangle that runs
/// alongside it (`Meshability_reason::END_IN_BOUNDARY_PLANE`), or bends back across one face
/// (`Meshability_reason::ZIGZAG_FACE`); nodes pass the link condition of
/// `Meshability_reason::INVALID_NODE`; boundary edges get their prescribed valence; frames agree
/// with the kept matchings. The check reads the matchings, not `compute_singularity_graph()`'s
/// flags (which tolerate edges up to 75.5 degrees off their axis).
///
/// \param mesh the tetrahedral mesh
/// \param frames one frame (columns = axes) per tetrahedron
/// \param matchings the kept matchings
/// \param prescribed per edge, the prescribed valence of boundary edges (empty: no feature check)
/// \param directions per boundary triangle, the directions the frames are aligned with (the normals
///        after the realignment; empty: no feature check)
/// \returns every violation with its reason and position, and the counts by reason
/// \throws Error if `frames` or `matchings` are not sized for `mesh`.
template <class Traits>
Local_meshability_report check_local_meshability(const Tetrahedral_mesh_3<Traits>& mesh,
                                                 const std::vector<Eigen::Matrix3d>& frames,
                                                 const Matchings& matchings,
                                                 const std::vector<int>& prescribed = std::vector<int>(),
                                                 const std::vector<Eigen::Vector3d>& directions = std::vector<Eigen::Vector3d>())
{
  if(frames.size() != mesh.number_of_tetrahedra() || matchings.face_matching.size() != mesh.number_of_faces())
    throw Error("check_local_meshability: frames or matchings of another mesh");
  if(prescribed.empty() || directions.empty()) return internal::local_meshability(mesh, frames, matchings, nullptr, prescribed, true);
  const Boundary_valences b = compute_achieved_boundary_valences(mesh, frames, matchings, directions, prescribed);
  return internal::local_meshability(mesh, frames, matchings, &b.achieved, prescribed, true);
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_LOCAL_MESHABILITY_H
