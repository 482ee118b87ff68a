// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_REALIGN_FRAME_FIELD_H
#define CGAL_HEXAHEDRAL_REMESHING_REALIGN_FRAME_FIELD_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/boundary_triangle_normals.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/parameters.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/frame_field.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/problem.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/aggregation_multigrid.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/conjugate_gradients.h>
#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>

#include <Eigen/Dense>
#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <chrono>
#include <memory>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// Outcome of `realign_frame_field()`.
struct Realignment_result
{
  /// Largest `|1 - |E_t^T n_i|_inf|` over the constrained tetrahedra after realignment
  /// (0 when every constrained frame has an axis exactly on its normal).
  double alignment_error = 0;
  /// Largest violation of the linear constraints `n_i^T E_t = v_i^T E_t^old` before projection.
  double constraint_error = 0;
  /// Conjugate-gradient iterations and final relative residual of the linear solve.
  int solver_iterations = 0;
  /// Final relative residual of the linear solve.
  double solver_residual = 0;
  /// Interior faces whose recomputed matching differs from the fixed one (0 expected).
  std::size_t changed_matchings = 0;
  /// Interior edges whose type (regular, valence 3, 5, improper) changed (0 expected).
  std::size_t changed_edges = 0;
  /// Seconds.
  double seconds = 0;
};

namespace internal {

// Axial index of the local axis of E aligned with direction d and its sign: E^T d ~ sign e_k.
inline int aligned_axis(const Eigen::Matrix3d& E, const Eigen::Vector3d& d, double& sign)
{
  const Eigen::Vector3d c = E.transpose() * d;
  int k = 0;
  c.cwiseAbs().maxCoeff(&k);
  sign = c[k] >= 0 ? 1.0 : -1.0;
  return k;
}

// Orthonormal basis (columns) of the plane orthogonal to the unit vector n.
inline Eigen::Matrix<double, 3, 2> tangent_basis(const Eigen::Vector3d& n)
{
  const Eigen::Vector3d a = std::abs(n.x()) < 0.6 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d t1 = (a - a.dot(n) * n).normalized();
  Eigen::Matrix<double, 3, 2> T;
  T.col(0) = t1;
  T.col(1) = n.cross(t1);
  return T;
}

} // namespace internal

/// \ingroup PkgHexahedralRemeshingRef
/// Realigns a frame field with the surface normals while keeping its matchings, hence its
/// singularity graph (Desobry et al., Sec. 3.3, Eq. 4): solves
/// `min sum_f w_f |E'_i - E'_j g_ij|_F^2 + mu sum_t |E'_t - E_t|_F^2` subject to
/// `n_i^T E'_t = v_i^T E_t` for the tetrahedron `t` of each boundary triangle `i` (enforced exactly
/// by elimination: `E'_t = n_i c^T + T Y_t`, `c = E_t^T v_i`, `T` a basis of the plane orthogonal to
/// `n_i`), by matrix-free conjugate gradients (preconditioned by an aggregation multigrid on large meshes) from `E'` = `E`, then projects every matrix to the
/// closest rotation (the constrained column kept exactly on `+-n_i`, a 2D Procrustes for the others).
/// Afterwards the matchings are recomputed and compared with `matchings`, and the singularity graph
/// with the one of `frames`: any difference is reported in the result (never hidden).
///
/// \param mesh the mesh
/// \param frames in: the field of step 2, aligned with `directions`; out: the realigned field
/// \param matchings the matchings of the input field (kept)
/// \param directions the directions `v_i` the input field is aligned with, per boundary triangle
/// \param np an optional sequence of named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{face_weights}
///     \cgalParamDescription{weights of the interior faces, as in `compute_frame_field()`}
///     \cgalParamType{`Face_weights`}
///     \cgalParamDefault{`Face_weights::AREA_OVER_DISTANCE`}
///   \cgalParamNEnd
///   \cgalParamNBegin{relaxation_tolerance}
///     \cgalParamDescription{relative residual at which the conjugate gradients stop}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`1e-5`}
///   \cgalParamNEnd
///   \cgalParamNBegin{tetrahedron_order}
///     \cgalParamDescription{the order in which the solver numbers the tetrahedra (empty: the mesh's
///       own), as in `compute_frame_field()`; the frames come back in the mesh's order}
///     \cgalParamType{`std::vector<std::uint32_t>`, a permutation of the tetrahedra}
///     \cgalParamDefault{`solver_tetrahedron_order(mesh)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Error if the sizes do not match the mesh or the tetrahedron order is not a permutation.
template <class Traits, class NamedParameters = CGAL::parameters::Default_named_parameters>
Realignment_result realign_frame_field(const Tetrahedral_mesh_3<Traits>& mesh, std::vector<Eigen::Matrix3d>& frames,
                                       const Matchings& matchings, const std::vector<Eigen::Vector3d>& directions,
                                       const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  typedef Eigen::Matrix<double, 3, 2> Matrix32;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double tolerance = choose_parameter(get_parameter(np, internal_np::relaxation_tolerance), 1e-5);
  const bool uniform = choose_parameter(get_parameter(np, internal_np::face_weights), Face_weights::AREA_OVER_DISTANCE) ==
                       Face_weights::UNIFORM;
  const auto start = std::chrono::steady_clock::now();
  const std::size_t nt = mesh.number_of_tetrahedra();
  if(frames.size() != nt || directions.size() != mesh.number_of_boundary_triangles() ||
     matchings.face_matching.size() != mesh.number_of_faces())
    throw Error("realign_frame_field: frames, matchings or directions do not match the mesh");
  const internal::Octahedral_group& group = internal::octahedral_group();
  const std::vector<Eigen::Vector3d> normals = boundary_triangle_unit_normals(mesh);
  const Singularity_graph graph_before = compute_singularity_graph(mesh, frames, matchings);

  // The solver numbers the tets in the frame field's order (a Hilbert curve on the meshes where it is
  // memory-bound); mesh_tet(s) is the mesh's index of solver tet s.
  const std::vector<std::uint32_t> order = internal::solver_order(mesh, np);
  const std::vector<std::uint32_t> rank = internal::ranks_of_order(order, nt, "realign_frame_field");
  auto mesh_tet = [&](std::size_t s) { return order.empty() ? s : std::size_t(order[s]); };
  auto solver_tet = [&](std::size_t t) { return rank.empty() ? Index(t) : Index(rank[t]); };
  // Per tet: the boundary triangle constraining it, the eliminated part X0 and the basis T.
  std::vector<Index> constraint(nt, Tetrahedral_mesh_3<Traits>::null_index);
  std::vector<Eigen::Matrix3d> X0(nt, Eigen::Matrix3d::Zero());
  std::vector<Matrix32> T(nt);
  Realignment_result result;
  for(Index b = 0; b < mesh.number_of_boundary_triangles(); ++b) {
    const Index t = mesh.boundary_triangle_tetrahedron(b);
    const Index st = solver_tet(t);
    if(constraint[st] != Tetrahedral_mesh_3<Traits>::null_index)
      throw Error("realign_frame_field: tetrahedron " + std::to_string(t) + " has several boundary faces");
    constraint[st] = b;
    const Eigen::Vector3d c = frames[t].transpose() * directions[b].normalized();
    X0[st] = normals[b] * c.transpose();
    T[st] = internal::tangent_basis(normals[b]);
  }
  // Interior faces with their matching step in both directions (E_from ~ E_to g), stored as signed
  // permutations: column j of E g is sign[j] * column perm[j] of E (no 3x3 product in the solver).
  struct Signed_permutation
  {
    std::array<int, 3> perm;
    std::array<double, 3> sign;
    explicit Signed_permutation(const Eigen::Matrix3d& g)
    {
      for(int j = 0; j < 3; ++j)
        for(int i = 0; i < 3; ++i)
          if(g(i, j) != 0) { perm[j] = i; sign[j] = g(i, j); }
    }
    void add_product(const Eigen::Matrix3d& E, double w, Eigen::Matrix3d& out) const // out -= w E g
    {
      for(int j = 0; j < 3; ++j) out.col(j) -= (w * sign[j]) * E.col(perm[j]);
    }
  };
  // 24 bytes per face: the matching's steps both ways are looked up in tables of the 24 rotations
  struct Face { Index a, b; std::uint8_t matching; double w; };
  std::vector<Face> faces;
  std::vector<Signed_permutation> step_ab, step_ba;
  for(int m = 0; m < 24; ++m) {
    step_ab.emplace_back(group.matrix(m));
    step_ba.emplace_back(Eigen::Matrix3d(group.matrix(m).transpose()));
  }
  std::vector<std::array<Index, 4> > tet_faces(nt, {Tetrahedral_mesh_3<Traits>::null_index, Tetrahedral_mesh_3<Traits>::null_index,
                                                    Tetrahedral_mesh_3<Traits>::null_index, Tetrahedral_mesh_3<Traits>::null_index});
  std::vector<double> weights;
  std::vector<Index> interior_faces = internal::interior_faces_in_order(mesh, rank);
  for(const Index f : interior_faces) {
    const auto& ft = mesh.face_tetrahedra(f);
    faces.push_back({solver_tet(ft[0]), solver_tet(ft[1]), std::uint8_t(matchings.face_matching[f]), 1.0});
    weights.push_back(uniform ? 1.0 : internal::area_over_distance(mesh, f));
  }
  std::vector<Index>().swap(interior_faces);
  internal::normalize_mean(weights);
  for(std::size_t fi = 0; fi < faces.size(); ++fi) faces[fi].w = weights[fi];
  for(Index fi = 0; fi < faces.size(); ++fi)
    for(Index t : {faces[fi].a, faces[fi].b})
      for(int k = 0; k < 4; ++k)
        if(tet_faces[t][k] == Tetrahedral_mesh_3<Traits>::null_index) { tet_faces[t][k] = fi; break; }
  std::vector<double> degree(nt, 0.);
  for(const Face& f : faces) { degree[f.a] += f.w; degree[f.b] += f.w; }
  // only there to make the system definite (the face weights have mean 1)
  const double mu = 1e-6;

  // Unknowns: 9 per free tet (E' itself), 6 per constrained tet (Y_t, E' = X0 + T Y_t).
  std::vector<std::size_t> offset(nt + 1, 0);
  for(std::size_t t = 0; t < nt; ++t)
    offset[t + 1] = offset[t] + (constraint[t] == Tetrahedral_mesh_3<Traits>::null_index ? 9 : 6);
  const Eigen::Index n = Eigen::Index(offset[nt]);
  auto is_constrained = [&](std::size_t t) { return constraint[t] != Tetrahedral_mesh_3<Traits>::null_index; };
  auto expand = [&](const Eigen::VectorXd& y, std::vector<Eigen::Matrix3d>& E, bool with_offset) {
    E.resize(nt);
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for(std::ptrdiff_t ti = 0; ti < std::ptrdiff_t(nt); ++ti) {
      const std::size_t t = std::size_t(ti);
      if(is_constrained(t)) {
        E[t] = T[t] * Eigen::Map<const Eigen::Matrix<double, 2, 3> >(y.data() + offset[t]);
        if(with_offset) E[t] += X0[t];
      } else {
        E[t] = Eigen::Map<const Eigen::Matrix3d>(y.data() + offset[t]);
      }
    }
  };
  // y_out = P^T (L + mu I) E, per tet gather.
  auto apply = [&](const std::vector<Eigen::Matrix3d>& E, Eigen::VectorXd& out) {
    out.resize(n);
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for(std::ptrdiff_t ti = 0; ti < std::ptrdiff_t(nt); ++ti) {
      const std::size_t t = std::size_t(ti);
      Eigen::Matrix3d r = (mu + degree[t]) * E[t];
      for(Index fi : tet_faces[t]) {
        if(fi == Tetrahedral_mesh_3<Traits>::null_index) continue;
        const Face& f = faces[fi];
        if(f.a == t) step_ab[f.matching].add_product(E[f.b], f.w, r);
        else step_ba[f.matching].add_product(E[f.a], f.w, r);
      }
      if(is_constrained(t)) Eigen::Map<Eigen::Matrix<double, 2, 3> >(out.data() + offset[t]) = T[t].transpose() * r;
      else Eigen::Map<Eigen::Matrix3d>(out.data() + offset[t]) = r;
    }
  };
  // Right-hand side: P^T (mu E_old - (L + mu I) X0); initial guess: the old frames projected.
  Eigen::VectorXd b(n), x(n);
  {
    std::vector<Eigen::Matrix3d> E0;
    Eigen::VectorXd zero = Eigen::VectorXd::Zero(n), AX0;
    expand(zero, E0, true);
    apply(E0, AX0);
    for(std::size_t t = 0; t < nt; ++t) {
      const Eigen::Matrix3d& F = frames[mesh_tet(t)];
      if(is_constrained(t)) {
        Eigen::Map<Eigen::Matrix<double, 2, 3> >(b.data() + offset[t]) = T[t].transpose() * (mu * F);
        Eigen::Map<Eigen::Matrix<double, 2, 3> >(x.data() + offset[t]) = T[t].transpose() * F;
      } else {
        Eigen::Map<Eigen::Matrix3d>(b.data() + offset[t]) = mu * F;
        Eigen::Map<Eigen::Matrix3d>(x.data() + offset[t]) = F;
      }
    }
    b -= AX0;
  }
  // Conjugate gradients preconditioned by Jacobi on small meshes, else (flexible) by an aggregation
  // multigrid's K-cycle on the dual graph whose coarse unknowns follow the matchings
  // (aggregation_multigrid.h), built at the first iteration only (a field that needs no realignment
  // needs no multigrid either).
  std::vector<Eigen::Matrix3d> E;
  std::vector<Eigen::Matrix3d> Ev; // reused: a fresh one per product costs its page faults every time
  auto apply_reduced = [&](const Eigen::VectorXd& v, Eigen::VectorXd& Av) {
    expand(v, Ev, false);
    apply(Ev, Av);
  };
  std::vector<std::array<Index, 2> > face_tets;
  std::unique_ptr<internal::Aggregation_multigrid> multigrid;
  auto build_multigrid = [&]() {
    face_tets.resize(faces.size());
    for(std::size_t fi = 0; fi < faces.size(); ++fi) face_tets[fi] = {faces[fi].a, faces[fi].b};
    internal::Multigrid_fine_system fine;
    fine.number_of_tets = nt;
    fine.face_tets = &face_tets;
    fine.face_weight = &weights;
    fine.tet_faces = &tet_faces;
    fine.face_rotation.reserve(faces.size());
    for(const Face& f : faces) fine.face_rotation.push_back(internal::right_multiplication(group.matrix(f.matching)));
    fine.offset = offset;
    fine.embedding.assign(nt, 0);
    for(std::size_t t = 0; t < nt; ++t) {
      if(!is_constrained(t)) continue;
      // vec(T Y) = (I3 x T) vec(Y), Y 2 x 3 column-major
      Eigen::Matrix<double, 9, 6> Q = Eigen::Matrix<double, 9, 6>::Zero();
      for(int c = 0; c < 3; ++c) Q.block<3, 2>(3 * c, 2 * c) = T[t];
      fine.embedding[t] = fine.embeddings.size();
      fine.embeddings.insert(fine.embeddings.end(), Q.data(), Q.data() + 54);
    }
    fine.mu = mu;
    fine.apply = apply_reduced;
    multigrid.reset(new internal::Aggregation_multigrid(std::move(fine), internal::Multigrid_cycle::K));
  };
  Eigen::VectorXd inv_diag;
  const bool use_multigrid = internal::use_multigrid(internal::Frame_field_preconditioner::AUTOMATIC, nt);
  if(!use_multigrid) {
    inv_diag.resize(n);
    for(std::size_t t = 0; t < nt; ++t)
      for(std::size_t k = offset[t]; k < offset[t + 1]; ++k) inv_diag[Eigen::Index(k)] = 1.0 / (degree[t] + mu);
  }
  internal::preconditioned_conjugate_gradients(
    apply_reduced,
    [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) {
      if(!use_multigrid) { z = inv_diag.cwiseProduct(r); return; }
      if(!multigrid) build_multigrid();
      (*multigrid)(r, z);
    },
    std::move(b), x, tolerance, 20000, result.solver_iterations, result.solver_residual, use_multigrid);
  expand(x, E, true);

  // Projection to rotations (t: the solver's tet, frame: the mesh's), independent per tet; the
  // errors are maxima, the same in any order.
  double constraint_error = 0, alignment_error = 0;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) reduction(max : constraint_error, alignment_error)
#endif
  for(std::ptrdiff_t ti = 0; ti < std::ptrdiff_t(nt); ++ti) {
    const std::size_t t = std::size_t(ti);
    Eigen::Matrix3d& frame = frames[mesh_tet(t)];
    if(!is_constrained(t)) {
      Eigen::JacobiSVD<Eigen::Matrix3d> svd(E[t], Eigen::ComputeFullU | Eigen::ComputeFullV);
      Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
      D(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1 : 1;
      frame = svd.matrixU() * D * svd.matrixV().transpose();
      continue;
    }
    const Index bt = constraint[t];
    const Eigen::Vector3d& nrm = normals[bt];
    double s = 1;
    const int k = internal::aligned_axis(frame, directions[bt].normalized(), s);
    constraint_error = (std::max)(constraint_error, (nrm.transpose() * E[t] - directions[bt].normalized().transpose() * frame).cwiseAbs().maxCoeff());
    const int a = (k + 1) % 3, c = (k + 2) % 3;
    // 2D Procrustes of columns a and c inside the tangent plane, keeping a right-handed frame
    const Matrix32& B = T[t];
    Eigen::Matrix2d M;
    M.col(0) = B.transpose() * E[t].col(a);
    M.col(1) = B.transpose() * E[t].col(c);
    Eigen::JacobiSVD<Eigen::Matrix2d> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix2d Q = svd.matrixU() * svd.matrixV().transpose();
    // columns (a, c, k) must be right-handed: col_a x col_c = col_k = s n, i.e. det(Q) = s
    // (B is right-handed about n: B.col(0) x B.col(1) = n)
    if(Q.determinant() * s < 0) {
      Eigen::Matrix2d Dm = Eigen::Matrix2d::Identity();
      Dm(1, 1) = -1;
      Q = svd.matrixU() * Dm * svd.matrixV().transpose();
    }
    Eigen::Matrix3d R;
    R.col(k) = s * nrm;
    R.col(a) = B * Q.col(0);
    R.col(c) = B * Q.col(1);
    frame = R;
    const Eigen::Vector3d check = R.transpose() * nrm;
    alignment_error = (std::max)(alignment_error, std::abs(1.0 - check.cwiseAbs().maxCoeff()));
  }
  result.constraint_error = (std::max)(result.constraint_error, constraint_error);
  result.alignment_error = (std::max)(result.alignment_error, alignment_error);

  // Post-checks: matchings and singular graph must be unchanged.
  const Matchings after = compute_matchings(mesh, frames);
  for(std::size_t f = 0; f < after.face_matching.size(); ++f)
    result.changed_matchings += after.face_matching[f] != matchings.face_matching[f];
  const Singularity_graph graph_after = compute_singularity_graph(mesh, frames, matchings);
  for(std::size_t e = 0; e < graph_after.edge_valence.size(); ++e)
    result.changed_edges += graph_after.edge_valence[e] != graph_before.edge_valence[e];
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_REALIGN_FRAME_FIELD_H
