// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_REALIGNMENT_SOLVE_REALIGNMENT_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_REALIGNMENT_SOLVE_REALIGNMENT_H

#include <CGAL/Hexahedral_remeshing/internal/realignment/realignment_system.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/aggregation_multigrid.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/conjugate_gradients.h>
#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>

#include <Eigen/Dense>

#include <array>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// The aggregation multigrid of the realignment's system on the dual graph, its coarse unknowns
// following the matchings (aggregation_multigrid.h). `face_tets` must outlive the multigrid.
template <class Traits, class Apply>
std::unique_ptr<Aggregation_multigrid> realignment_multigrid(const Realignment_system<Traits>& system,
                                                             std::vector<std::array<typename Realignment_system<Traits>::Index, 2> >& face_tets,
                                                             Apply apply_reduced)
{
  const Octahedral_group& group = octahedral_group();
  face_tets.resize(system.faces.size());
  for(std::size_t fi = 0; fi < system.faces.size(); ++fi) face_tets[fi] = {system.faces[fi].a, system.faces[fi].b};
  Multigrid_fine_system fine;
  fine.number_of_tets = system.nt;
  fine.face_tets = &face_tets;
  fine.face_weight = &system.weights;
  fine.tet_faces = &system.tet_faces;
  fine.face_rotation.reserve(system.faces.size());
  for(const auto& f : system.faces) fine.face_rotation.push_back(right_multiplication(group.matrix(f.matching)));
  fine.offset = system.offset;
  fine.embedding.assign(system.nt, 0);
  for(std::size_t t = 0; t < system.nt; ++t) {
    if(!system.is_constrained(t)) continue;
    // vec(T Y) = (I3 x T) vec(Y), Y 2 x 3 column-major
    Eigen::Matrix<double, 9, 6> Q = Eigen::Matrix<double, 9, 6>::Zero();
    for(int c = 0; c < 3; ++c) Q.template block<3, 2>(3 * c, 2 * c) = system.T[t];
    fine.embedding[t] = fine.embeddings.size();
    fine.embeddings.insert(fine.embeddings.end(), Q.data(), Q.data() + 54);
  }
  fine.mu = system.mu;
  fine.apply = apply_reduced;
  return std::unique_ptr<Aggregation_multigrid>(new Aggregation_multigrid(std::move(fine), Multigrid_cycle::K));
}

// Solves the realignment's system from the old frames (projected) by conjugate gradients,
// preconditioned by Jacobi on small meshes, else (flexible) by the aggregation multigrid's K-cycle,
// built at the first iteration only (a field that needs no realignment needs no multigrid either).
// Returns E' = X0 + P y per solver tet.
template <class Traits>
std::vector<Eigen::Matrix3d> solve_realignment(const Realignment_system<Traits>& system,
                                               const std::vector<Eigen::Matrix3d>& frames, double tolerance,
                                               int& iterations, double& residual)
{
  typedef typename Realignment_system<Traits>::Index Index;
  Eigen::VectorXd b, x;
  system.right_hand_side(frames, b, x);
  std::vector<Eigen::Matrix3d> Ev; // reused: a fresh one per product costs its page faults every time
  auto apply_reduced = [&](const Eigen::VectorXd& v, Eigen::VectorXd& Av) {
    system.expand(v, Ev, false);
    system.apply(Ev, Av);
  };
  std::vector<std::array<Index, 2> > face_tets;
  std::unique_ptr<Aggregation_multigrid> multigrid;
  Eigen::VectorXd inv_diag;
  const bool use_mg = use_multigrid(Frame_field_preconditioner::AUTOMATIC, system.nt);
  if(!use_mg) {
    inv_diag.resize(system.n);
    for(std::size_t t = 0; t < system.nt; ++t)
      for(std::size_t k = system.offset[t]; k < system.offset[t + 1]; ++k)
        inv_diag[Eigen::Index(k)] = 1.0 / (system.degree[t] + system.mu);
  }
  preconditioned_conjugate_gradients(
    apply_reduced,
    [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) {
      if(!use_mg) { z = inv_diag.cwiseProduct(r); return; }
      if(!multigrid) multigrid = realignment_multigrid(system, face_tets, apply_reduced);
      (*multigrid)(r, z);
    },
    std::move(b), x, tolerance, 20000, iterations, residual, use_mg);
  std::vector<Eigen::Matrix3d> E;
  system.expand(x, E, true);
  return E;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_REALIGNMENT_SOLVE_REALIGNMENT_H
