// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_TRANSITIONS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_TRANSITIONS_H

#include <CGAL/Hexahedral_remeshing/Integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/map_topology.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/rigid_transform.h>

#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {
namespace extraction {

// Transitions of every interior face, stored on both sides: across local face f of t,
// x_t = apply(to_this[t][f], x_neighbor) on the shared face.
struct Face_transitions
{
  std::vector<std::array<Rigid_transform, 4> > to_this;
  // Largest misfit of the face edge vectors under the best rotation, and largest distance of the
  // translation to an integer vector (after the rotation), with the faces where they occur.
  double max_rotation_deviation = 0., max_jump_deviation = 0.;
  std::uint32_t worst_rotation_tet = no_tetrahedron, worst_jump_tet = no_tetrahedron;
  int worst_rotation_face = -1, worst_jump_face = -1;
  // Faces whose rotation is not determined by the face (collinear or coincident parameters).
  std::size_t ambiguous = 0;
};

// Recovers the transition of one face from the parameters of its three vertices in both charts
// (HexEx / MC3D convention: the rotation of the 24-group best mapping one chart's face edge vectors
// onto the other's, and the translation rounded from u_t - R u_n).
inline void recover_face_transition(const std::array<Eigen::Vector3d, 3>& ut, const std::array<Eigen::Vector3d, 3>& un,
                                    Rigid_transform& T, double& rotation_deviation, double& jump_deviation,
                                    bool& ambiguous)
{
  const Eigen::Vector3d et[2] = {ut[1] - ut[0], ut[2] - ut[0]};
  const Eigen::Vector3d en[2] = {un[1] - un[0], un[2] - un[0]};
  double best = std::numeric_limits<double>::infinity(), second = best;
  int best_r = 0;
  const double scale = (std::max)({1., et[0].cwiseAbs().maxCoeff(), et[1].cwiseAbs().maxCoeff()});
  for(int r = 0; r < Octahedral_group::size; ++r) {
    const double d = (std::max)((et[0] - rotate(r, en[0])).cwiseAbs().maxCoeff(),
                                (et[1] - rotate(r, en[1])).cwiseAbs().maxCoeff());
    // identity first: among equally good rotations (degenerate faces) the identity wins
    if(d < best) { second = best; best = d; best_r = r; }
    else if(d < second) second = d;
  }
  ambiguous = second <= best + 1e-9 * scale;
  T.rotation = best_r;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  Eigen::Vector3d d[3];
  for(int k = 0; k < 3; ++k) { d[k] = ut[k] - rotate(best_r, un[k]); mean += d[k]; }
  mean /= 3.;
  for(int c = 0; c < 3; ++c) T.translation[c] = std::round(mean[c]);
  jump_deviation = 0.;
  for(int k = 0; k < 3; ++k) jump_deviation = (std::max)(jump_deviation, (d[k] - T.translation).cwiseAbs().maxCoeff());
  rotation_deviation = best;
}

// Transitions from map.transitions when the producer gave them, else recovered from the parameters.
inline void compute_face_transitions(const Integer_grid_map& map, const Map_topology& topo, Face_transitions& out)
{
  const std::size_t nt = map.tetrahedra.size();
  out = Face_transitions();
  out.to_this.assign(nt, {});
  std::map<std::pair<std::uint32_t, std::uint32_t>, Rigid_transform> given; // (t0, t1) -> x_t0 = T x_t1
  for(const Integer_grid_map_transition& tr : map.transitions) {
    if(tr.rotation < 0 || tr.rotation >= Octahedral_group::size || tr.tetrahedra[0] >= nt || tr.tetrahedra[1] >= nt)
      throw Input_error(map.source, 0, "transition between tetrahedra " + std::to_string(tr.tetrahedra[0]) + " and " +
                                           std::to_string(tr.tetrahedra[1]) + " is out of range");
    Rigid_transform T;
    T.rotation = tr.rotation;
    T.translation = tr.translation.cast<double>();
    given[{tr.tetrahedra[0], tr.tetrahedra[1]}] = T;
    given[{tr.tetrahedra[1], tr.tetrahedra[0]}] = inverse(T);
  }
  for(std::uint32_t t = 0; t < nt; ++t)
    for(int f = 0; f < 4; ++f) {
      const std::uint32_t n = topo.neighbor[t][f];
      if(n == no_tetrahedron || n < t) continue;
      std::array<Eigen::Vector3d, 3> ut, un;
      for(int k = 0; k < 3; ++k) {
        const int lt = face_vertices[f][k];
        const std::uint32_t v = map.tetrahedra[t][lt];
        int ln = 0;
        while(map.tetrahedra[n][ln] != v) ++ln;
        ut[k] = map.parameters[t][lt];
        un[k] = map.parameters[n][ln];
      }
      Rigid_transform T;
      double rot_dev, jump_dev;
      bool amb;
      recover_face_transition(ut, un, T, rot_dev, jump_dev, amb);
      const auto it = given.find({t, n});
      if(it != given.end()) {
        T = it->second;
        jump_dev = 0.;
        for(int k = 0; k < 3; ++k) jump_dev = (std::max)(jump_dev, (ut[k] - apply(T, un[k])).cwiseAbs().maxCoeff());
        amb = false;
      } else if(amb) {
        ++out.ambiguous;
      }
      if(rot_dev > out.max_rotation_deviation) {
        out.max_rotation_deviation = rot_dev; out.worst_rotation_tet = t; out.worst_rotation_face = f;
      }
      if(jump_dev > out.max_jump_deviation) {
        out.max_jump_deviation = jump_dev; out.worst_jump_tet = t; out.worst_jump_face = f;
      }
      out.to_this[t][f] = T;
      out.to_this[n][topo.neighbor_face[t][f]] = inverse(T);
    }
}

// Boundary face of t (local face f) on an integer plane: the coordinate with the smallest spread, its
// nearest integer and the largest distance of the three vertices to it.
inline void boundary_plane(const Integer_grid_map& map, std::uint32_t t, int f, int& axis, double& value,
                           double& deviation)
{
  double best_spread = std::numeric_limits<double>::infinity();
  axis = 0;
  for(int c = 0; c < 3; ++c) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for(int k = 0; k < 3; ++k) {
      const double x = map.parameters[t][face_vertices[f][k]][c];
      lo = (std::min)(lo, x); hi = (std::max)(hi, x);
    }
    if(hi - lo < best_spread) { best_spread = hi - lo; axis = c; }
  }
  double mean = 0.;
  for(int k = 0; k < 3; ++k) mean += map.parameters[t][face_vertices[f][k]][axis];
  value = std::round(mean / 3.);
  deviation = 0.;
  for(int k = 0; k < 3; ++k)
    deviation = (std::max)(deviation, std::abs(map.parameters[t][face_vertices[f][k]][axis] - value));
}

} // namespace extraction
} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_TRANSITIONS_H
