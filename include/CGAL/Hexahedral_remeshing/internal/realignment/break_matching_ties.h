// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// Ties between two matchings in the realigned frames, broken towards the kept matching. Two tetrahedra
// whose boundary faces meet at a CAD chamfer (135 or 225 degrees) with nothing between them (the edge's
// ring holds only these two) each have an axis exactly on their own normal after the realignment: their
// frames differ by 45 degrees about the edge, half way between the kept matching and its neighbour in
// the group, and the mesh's coordinates decide which of the two a reader of the frames alone takes
// (measured on MAMBO B41: 24 such faces at its chamfers, the closest matching ahead of the kept one by
// 4e-9 to 4e-7 in the trace; an independent count of the singular graph from the frames alone found 35
// edges that are not a quarter turn along the edge where the kept matchings have 3 jogs). No rotation
// about the normals can break such a tie, so one frame is turned by 1e-5 radian about the axis of its
// residual rotation towards the kept matching: its axis leaves the normal by 1e-5 radian at most (an
// alignment error of 5e-11), and the kept matching gains about 2.8e-5 in the trace on its rival. Only
// faces whose closest matching is ahead by less than 1e-5 are turned, and a turn that would make another
// face of the tetrahedron disagree is undone. After it, B41's frames alone give its 3 jogs.
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_REALIGNMENT_BREAK_MATCHING_TIES_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_REALIGNMENT_BREAK_MATCHING_TIES_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// tr(g^T E_j^T E_i) of matching g across face f (E_i ~ E_j g, i and j the face's two tetrahedra)
template <class Traits>
double matching_trace(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames, std::size_t f, int g)
{
  const auto& ft = mesh.face_tetrahedra(typename Tetrahedral_mesh_3<Traits>::Index(f));
  return (octahedral_group().matrix(g).transpose() * frames[ft[1]].transpose() * frames[ft[0]]).trace();
}

// True if the closest matching of face f is its kept one (a tie counts as agreement only if the
// enumeration's lowest index is the kept one, as compute_matchings() decides it).
template <class Traits>
bool face_agrees(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames,
                 const Matchings& matchings, std::size_t f)
{
  const auto& ft = mesh.face_tetrahedra(typename Tetrahedral_mesh_3<Traits>::Index(f));
  if(ft[1] == Tetrahedral_mesh_3<Traits>::null_index) return true;
  return closest_matching(frames[ft[0]], frames[ft[1]]).index == matchings.face_matching[f];
}

// Turns frame `t` (one of the two of face f) by `angle` towards its image under the kept matching;
// returns false (frame unchanged) if another face of t agreed before and not after.
template <class Traits>
bool turn_towards_kept(const Tetrahedral_mesh_3<Traits>& mesh, std::vector<Eigen::Matrix3d>& frames,
                       const Matchings& matchings, std::size_t f, int side, double angle)
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  const auto& ft = mesh.face_tetrahedra(Index(f));
  const Eigen::Matrix3d& g = octahedral_group().matrix(matchings.face_matching[f]);
  // the image of the frame under the kept matching: E_i ~ E_j g, E_j ~ E_i g^T
  const Eigen::Matrix3d target = side == 0 ? Eigen::Matrix3d(frames[ft[1]] * g) : Eigen::Matrix3d(frames[ft[0]] * g.transpose());
  Eigen::Matrix3d& E = frames[ft[side]];
  const Eigen::AngleAxisd residual(Eigen::Matrix3d(E * target.transpose()));
  if(!(residual.angle() > angle)) return false;
  const Index t = ft[side];
  std::vector<char> agreed(4);
  for(int k = 0; k < 4; ++k) agreed[k] = face_agrees(mesh, frames, matchings, mesh.tetrahedron_face(t, k));
  const Eigen::Matrix3d before = E;
  E = Eigen::AngleAxisd(-angle, residual.axis()).toRotationMatrix() * E;
  for(int k = 0; k < 4; ++k)
    if(agreed[k] && !face_agrees(mesh, frames, matchings, mesh.tetrahedron_face(t, k))) {
      E = before;
      return false;
    }
  return true;
}

// Of the `disagreeing` faces (increasing; their closest matching is not the kept one), those whose
// closest matching is within `tie` (in the trace) of the kept one: one of their two frames turned by
// `angle` towards the kept matching (see the file's comment). A face that agrees with the kept
// matchings never comes to disagree, since such a turn is undone. Returns the tetrahedra turned.
template <class Traits>
std::vector<std::size_t> break_matching_ties(const Tetrahedral_mesh_3<Traits>& mesh, std::vector<Eigen::Matrix3d>& frames,
                                             const Matchings& matchings, const std::vector<std::size_t>& disagreeing,
                                             double tie = 1e-5, double angle = 1e-5)
{
  std::vector<std::size_t> turned;
  for(std::size_t f : disagreeing) {
    const auto& ft = mesh.face_tetrahedra(typename Tetrahedral_mesh_3<Traits>::Index(f));
    if(ft[1] == Tetrahedral_mesh_3<Traits>::null_index || face_agrees(mesh, frames, matchings, f)) continue;
    const Octahedral_matching closest = closest_matching(frames[ft[0]], frames[ft[1]]);
    if(closest.trace - matching_trace(mesh, frames, f, matchings.face_matching[f]) > tie) continue;
    for(int side : {1, 0})
      if(turn_towards_kept(mesh, frames, matchings, f, side, angle)) {
        turned.push_back(std::size_t(ft[side]));
        break;
      }
  }
  return turned;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_REALIGNMENT_BREAK_MATCHING_TIES_H
