// Tests of the foldover-free minimizer (Garanzha et al. 2021) and of the hexahedral mesh smoothing.
#include "data_paths.h"
#include <CGAL/Hexahedral_remeshing/IO/read_HexEx.h>
#include <CGAL/Hexahedral_remeshing/build_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_extraction.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_smoothing.h>
#include <CGAL/Hexahedral_remeshing/internal/untangling/foldover_free_map.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <functional>
#include <random>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace HR = CGAL::Hexahedral_remeshing;
namespace HRI = CGAL::Hexahedral_remeshing::internal;
typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Point;

namespace {

// ---------------------------------------------------------------------------------------------
// A cube [0,1]^3 of N^3 voxels, 6 Kuhn tets per voxel, every tet positively oriented.
struct Tet_grid
{
  int N = 0;
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 4> > tets;
  std::vector<bool> boundary;

  explicit Tet_grid(int n) : N(n)
  {
    auto id = [n](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
    for(int k = 0; k <= n; ++k)
      for(int j = 0; j <= n; ++j)
        for(int i = 0; i <= n; ++i) {
          points.emplace_back(double(i) / n, double(j) / n, double(k) / n);
          boundary.push_back(i == 0 || j == 0 || k == 0 || i == n || j == n || k == n);
        }
    const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for(int k = 0; k < n; ++k)
      for(int j = 0; j < n; ++j)
        for(int i = 0; i < n; ++i)
          for(const auto& p : perms) {
            std::array<int, 3> c{ {i, j, k} };
            std::array<int, 4> t;
            t[0] = id(c[0], c[1], c[2]);
            for(int s = 0; s < 3; ++s) {
              ++c[p[s]];
              t[s + 1] = id(c[0], c[1], c[2]);
            }
            if(edge_matrix(t).determinant() < 0) std::swap(t[2], t[3]);
            tets.push_back(t);
          }
  }

  Eigen::Matrix3d edge_matrix(const std::array<int, 4>& t) const
  {
    Eigen::Matrix3d R;
    for(int c = 0; c < 3; ++c) R.col(c) = points[t[c + 1]] - points[t[0]];
    return R;
  }
};

// Independent check: number of elements whose corner values are not positively oriented (exact).
std::size_t exact_non_positive(const HRI::Foldover_free_problem& p, const Eigen::VectorXd& y)
{
  const Eigen::VectorXd x = p.P * y + p.x0;
  std::size_t count = 0;
  for(std::size_t e = 0; e < p.M.size(); ++e) {
    const double* c = x.data() + 12 * e;
    const Point a(c[0], c[1], c[2]), b(c[3], c[4], c[5]), d(c[6], c[7], c[8]), f(c[9], c[10], c[11]);
    if(CGAL::orientation(a, b, d, f) != CGAL::POSITIVE) ++count;
  }
  return count;
}

// Single chart: u = identity on the boundary (folded into x0), one unknown 3-vector per interior vertex.
struct Single_chart
{
  HRI::Foldover_free_problem problem;
  std::vector<int> unknown; // per vertex: index of its 3-block in y, -1 if fixed
  int n = 0;

  explicit Single_chart(const Tet_grid& g)
  {
    unknown.assign(g.points.size(), -1);
    for(std::size_t v = 0; v < g.points.size(); ++v)
      if(!g.boundary[v]) unknown[v] = n++;
    const std::size_t E = g.tets.size();
    problem.x0 = Eigen::VectorXd::Zero(Eigen::Index(12 * E));
    std::vector<Eigen::Triplet<double> > triplets;
    for(std::size_t e = 0; e < E; ++e) {
      for(int c = 0; c < 4; ++c) {
        const int v = g.tets[e][c];
        for(int r = 0; r < 3; ++r) {
          const Eigen::Index row = Eigen::Index(12 * e + 3 * c + r);
          if(unknown[v] >= 0) triplets.emplace_back(int(row), 3 * unknown[v] + r, 1.);
          else problem.x0[row] = g.points[v][r];
        }
      }
      const Eigen::Matrix3d R = g.edge_matrix(g.tets[e]);
      problem.M.push_back(R.inverse());
      problem.w.push_back(R.determinant() / 6.);
    }
    problem.P.resize(Eigen::Index(12 * E), 3 * n);
    problem.P.setFromTriplets(triplets.begin(), triplets.end());
  }

  Eigen::VectorXd identity(const Tet_grid& g) const
  {
    Eigen::VectorXd y(3 * n);
    for(std::size_t v = 0; v < g.points.size(); ++v)
      if(unknown[v] >= 0) y.segment<3>(3 * unknown[v]) = g.points[v];
    return y;
  }
};

} // namespace

// ---------------------------------------------------------------------------------------------
// Energy of one element

TEST(FoldoverFreeEnergy, ChiIsStableAndPositive)
{
  for(double eps : {1., 1e-3, 1e-10})
    for(double D : {-1e6, -3., -1e-3, 0., 1e-3, 2., 1e6}) {
      const double chi = HRI::foldover_free_chi(D, eps);
      EXPECT_GT(chi, 0.);
      // chi is the positive root of c^2 - D c - eps^2/4: c = eps^2 / (4 (c - D)) (no cancellation for D <= 0)
      if(D <= 0) EXPECT_NEAR(chi, eps * eps / (4. * (chi - D)), 1e-12 * chi);
      // asymptotics: chi ~ D + eps^2 / (4 D) for D >> eps, chi ~ eps^2 / (4 |D|) for D << -eps
      if(D > 1e3 * eps) EXPECT_NEAR(chi, D + eps * eps / (4. * D), 1e-12 * D);
      if(D < -1e3 * eps) EXPECT_NEAR(chi, eps * eps / (-4. * D), 1e-5 * chi);
    }
  EXPECT_DOUBLE_EQ(HRI::foldover_free_chi(0., 2.), 1.);
  EXPECT_DOUBLE_EQ(HRI::foldover_free_chi(2., 0.), 2.);
}

TEST(FoldoverFreeEnergy, GradientMatchesFiniteDifferences)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1., 1.);
  for(double eps : {1., 0.1, 1e-3})
    for(int trial = 0; trial < 20; ++trial) {
      Eigen::Matrix3d K;
      for(int i = 0; i < 9; ++i) K.data()[i] = u(rng) + (i % 4 == 0 ? 0.5 : 0.);
      Eigen::Matrix3d G;
      HRI::foldover_free_element_energy(K, eps, 0.5, &G);
      for(int i = 0; i < 9; ++i) {
        const double h = 1e-6;
        Eigen::Matrix3d Kp = K, Km = K;
        Kp.data()[i] += h;
        Km.data()[i] -= h;
        const double fd = (HRI::foldover_free_element_energy(Kp, eps, 0.5) -
                           HRI::foldover_free_element_energy(Km, eps, 0.5)) / (2 * h);
        EXPECT_NEAR(G.data()[i], fd, 1e-5 * std::max(1., std::abs(fd)));
      }
    }
}

// The evaluator's fused element (corner values in, w f and its 12 corner derivatives out) against the
// textbook composition with Eigen's products, K = D M and d/dD = w G M^T, on valid, flat and inverted
// elements, and against finite differences in the corners. With Eigen's SSE2 products (the default
// x86-64 build) the two are the same bits, which keeps every map as it was before the fusion.
TEST(FoldoverFreeEnergy, FusedElementIsTheEigenComposition)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1., 1.);
  std::size_t bitwise = 0, total = 0;
  for(double eps : {1., 0.1, 1e-3, 1e-10})
    for(int trial = 0; trial < 500; ++trial) {
      double c[12];
      for(int i = 0; i < 12; ++i) c[i] = 3. * u(rng);
      Eigen::Matrix3d M;
      for(int i = 0; i < 9; ++i) M.data()[i] = u(rng) + (i % 4 == 0 ? 1. : 0.);
      const double w = 0.5 + u(rng) * u(rng);
      Eigen::Matrix3d D;
      for(int k = 0; k < 3; ++k)
        for(int r = 0; r < 3; ++r) D(r, k) = c[3 * (k + 1) + r] - c[r];
      Eigen::Matrix3d G;
      const double f = w * HRI::foldover_free_element_energy(D * M, eps, 0.5, &G);
      const Eigen::Matrix3d dD = w * G * M.transpose();
      double g[12];
      const double fused = HRI::foldover_free_fused_element(c, M, w, eps, 0.5, g);
      bool same = (fused == f);
      EXPECT_NEAR(fused, f, 1e-13 * std::abs(f));
      for(int r = 0; r < 3; ++r) {
        const double g0 = -(dD(r, 0) + dD(r, 1) + dD(r, 2));
        EXPECT_NEAR(g[r], g0, 1e-12 * (1. + std::abs(g0)));
        same = same && g[r] == g0;
        for(int k = 0; k < 3; ++k) {
          EXPECT_NEAR(g[3 * (k + 1) + r], dD(r, k), 1e-12 * (1. + std::abs(dD(r, k))));
          same = same && g[3 * (k + 1) + r] == dD(r, k);
        }
      }
      bitwise += same;
      ++total;
      if(trial % 50 != 0 || eps < 1e-3) continue; // finite differences where the barrier is smooth enough
      for(int i = 0; i < 12; ++i) {
        const double h = 1e-6;
        double cp[12], cm[12], unused[12];
        std::copy(c, c + 12, cp);
        std::copy(c, c + 12, cm);
        cp[i] += h;
        cm[i] -= h;
        const double fd = (HRI::foldover_free_fused_element(cp, M, w, eps, 0.5, unused) -
                           HRI::foldover_free_fused_element(cm, M, w, eps, 0.5, unused)) / (2 * h);
        EXPECT_NEAR(g[i], fd, 1e-5 * std::max(1., std::abs(fd)));
      }
    }
#if defined(EIGEN_VECTORIZE_SSE2) && !defined(EIGEN_VECTORIZE_AVX)
  EXPECT_EQ(bitwise, total);
#endif
}

TEST(FoldoverFreeEnergy, IdentityIsTheMinimumWithTheBarrier)
{
  Eigen::Matrix3d G;
  const double f = HRI::foldover_free_element_energy(Eigen::Matrix3d::Identity(), 1e-10, 0.5, &G);
  EXPECT_NEAR(f, 2.5, 1e-14);
  EXPECT_LT(G.norm(), 1e-12);
  // rotations have the same energy; a scaled or sheared element a higher one
  const Eigen::Matrix3d Rz = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  EXPECT_NEAR(HRI::foldover_free_element_energy(Rz, 1e-10, 0.5), 2.5, 1e-12);
  EXPECT_GT(HRI::foldover_free_element_energy(1.1 * Eigen::Matrix3d::Identity(), 1e-10, 0.5), 2.5);
  Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
  S(0, 1) = 0.2;
  EXPECT_GT(HRI::foldover_free_element_energy(S, 1e-10, 0.5), 2.5);
}

// ---------------------------------------------------------------------------------------------
// The minimizer on a tet grid of the unit cube (u = identity on the boundary)

TEST(FoldoverFreeMap, GridProblemIsWellFormed)
{
  const Tet_grid g(4);
  ASSERT_EQ(g.tets.size(), 6u * 64u);
  const Single_chart s(g);
  EXPECT_EQ(s.n, 27);
  EXPECT_EQ(exact_non_positive(s.problem, s.identity(g)), 0u);
  double volume = 0;
  for(double w : s.problem.w) volume += w;
  EXPECT_NEAR(volume, 1., 1e-12);
}

TEST(FoldoverFreeMap, IdentityStaysTheIdentity)
{
  const Tet_grid g(4);
  const Single_chart s(g);
  const Eigen::VectorXd y0 = s.identity(g);
  Eigen::VectorXd y = y0;
  const HRI::Foldover_free_result r = HRI::minimize_foldover_free(s.problem, y);
  EXPECT_TRUE(r.success);
  EXPECT_EQ(r.inverted_before, 0u);
  EXPECT_EQ(r.inverted_after, 0u);
  EXPECT_LT((y - y0).lpNorm<Eigen::Infinity>(), 1e-9);
  EXPECT_NEAR(r.energy, 2.5, 1e-9); // 2.5 per unit volume, total volume 1
  EXPECT_NEAR(r.min_det_after, 1., 1e-9);
}

TEST(FoldoverFreeMap, RandomInteriorIsUntangled)
{
  const Tet_grid g(4);
  const Single_chart s(g);
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-0.4, 0.4); // +-1.6 cells
  Eigen::VectorXd y = s.identity(g);
  for(Eigen::Index i = 0; i < y.size(); ++i) y[i] += u(rng);
  const std::size_t before = exact_non_positive(s.problem, y);
  EXPECT_GE(before, 20u);
  const HRI::Foldover_free_result r = HRI::minimize_foldover_free(s.problem, y);
  EXPECT_EQ(r.inverted_before, before);
  EXPECT_TRUE(r.success);
  EXPECT_EQ(r.inverted_after, 0u);
  EXPECT_EQ(exact_non_positive(s.problem, y), 0u);
  EXPECT_GT(r.min_det_after, 0.);
  EXPECT_LT(r.min_det_before, 0.);
}

TEST(FoldoverFreeMap, ReflectedInteriorIsUntangled)
{
  // every interior vertex mirrored through the centre: a deliberately folded map
  const Tet_grid g(4);
  const Single_chart s(g);
  Eigen::VectorXd y = s.identity(g);
  for(Eigen::Index i = 0; i < y.size(); ++i) y[i] = 1. - y[i];
  const std::size_t before = exact_non_positive(s.problem, y);
  EXPECT_GE(before, 50u);
  const HRI::Foldover_free_result r = HRI::minimize_foldover_free(s.problem, y);
  EXPECT_TRUE(r.success);
  EXPECT_EQ(exact_non_positive(s.problem, y), 0u);
  // the unique minimizer with an identity boundary on a uniform grid is the identity
  EXPECT_LT((y - s.identity(g)).lpNorm<Eigen::Infinity>(), 1e-3);
}

TEST(FoldoverFreeMap, CollapsedInteriorOnLargerGridIsUntangled)
{
  // all interior vertices collapsed near one corner (plus jitter): many degenerate and inverted tets
  const Tet_grid g(6);
  const Single_chart s(g);
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(-0.01, 0.01);
  Eigen::VectorXd y(3 * s.n);
  for(Eigen::Index i = 0; i < y.size(); ++i) y[i] = 0.2 + u(rng);
  EXPECT_GE(exact_non_positive(s.problem, y), 100u);
  const HRI::Foldover_free_result r = HRI::minimize_foldover_free(s.problem, y);
  EXPECT_TRUE(r.success);
  EXPECT_EQ(exact_non_positive(s.problem, y), 0u);
}

TEST(FoldoverFreeMap, TwoChartsCoupledByATransition)
{
  // chart A: tets with centroid x < 1/2, u = identity; chart B: u' = R u + t (R = 90 degrees about z,
  // t integer). A vertex shared by both charts has one unknown (A coordinates); the corners of its
  // B tets are R y + t (the +-1 coupling); vertices only in B have unknowns in B coordinates.
  const Tet_grid g(4);
  Eigen::Matrix3d R;
  R << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  const Eigen::Vector3d t(3, -2, 1);
  const std::size_t E = g.tets.size();
  std::vector<int> chart(E);
  std::vector<bool> in_A(g.points.size(), false);
  for(std::size_t e = 0; e < E; ++e) {
    double cx = 0;
    for(int c = 0; c < 4; ++c) cx += g.points[g.tets[e][c]].x() / 4;
    chart[e] = cx < 0.5 ? 0 : 1;
    if(chart[e] == 0)
      for(int c = 0; c < 4; ++c) in_A[g.tets[e][c]] = true;
  }
  std::vector<int> unknown(g.points.size(), -1);
  int n = 0, seam = 0;
  for(std::size_t v = 0; v < g.points.size(); ++v)
    if(!g.boundary[v]) unknown[v] = n++;
  HRI::Foldover_free_problem p;
  p.x0 = Eigen::VectorXd::Zero(Eigen::Index(12 * E));
  std::vector<Eigen::Triplet<double> > triplets;
  std::vector<bool> coupled(g.points.size(), false);
  for(std::size_t e = 0; e < E; ++e) {
    for(int c = 0; c < 4; ++c) {
      const int v = g.tets[e][c];
      const Eigen::Index row = Eigen::Index(12 * e + 3 * c);
      if(chart[e] == 0 || unknown[v] < 0 || !in_A[v]) {
        // identity block: A tets, B-only unknowns (already in B coordinates), fixed boundary values
        for(int r = 0; r < 3; ++r) {
          if(unknown[v] >= 0) triplets.emplace_back(int(row + r), 3 * unknown[v] + r, 1.);
          else p.x0[row + r] = chart[e] == 0 ? g.points[v][r] : (R * g.points[v] + t)[r];
        }
      } else {
        coupled[v] = true;
        for(int r = 0; r < 3; ++r) {
          for(int s2 = 0; s2 < 3; ++s2)
            if(R(r, s2) != 0) triplets.emplace_back(int(row + r), 3 * unknown[v] + s2, R(r, s2));
          p.x0[row + r] = t[r];
        }
      }
    }
    const Eigen::Matrix3d Re = g.edge_matrix(g.tets[e]);
    p.M.push_back(chart[e] == 0 ? Eigen::Matrix3d(Re.inverse()) : Eigen::Matrix3d(Re.inverse() * R.transpose()));
    p.w.push_back(Re.determinant() / 6.);
  }
  for(bool b : coupled) seam += b ? 1 : 0;
  EXPECT_EQ(seam, 9); // the interior vertices of the plane x = 1/2
  p.P.resize(Eigen::Index(12 * E), 3 * n);
  p.P.setFromTriplets(triplets.begin(), triplets.end());

  // ideal values: identity in A coordinates, R p + t for B-only vertices
  Eigen::VectorXd ideal(3 * n);
  for(std::size_t v = 0; v < g.points.size(); ++v)
    if(unknown[v] >= 0)
      ideal.segment<3>(3 * unknown[v]) = in_A[v] ? Eigen::Vector3d(g.points[v]) : Eigen::Vector3d(R * g.points[v] + t);
  EXPECT_EQ(exact_non_positive(p, ideal), 0u);

  std::mt19937 rng(2021);
  std::uniform_real_distribution<double> u(-0.35, 0.35);
  Eigen::VectorXd y = ideal;
  for(Eigen::Index i = 0; i < y.size(); ++i) y[i] += u(rng);
  EXPECT_GE(exact_non_positive(p, y), 20u);
  const HRI::Foldover_free_result r = HRI::minimize_foldover_free(p, y);
  EXPECT_TRUE(r.success);
  EXPECT_EQ(exact_non_positive(p, y), 0u);
  EXPECT_LT((y - ideal).lpNorm<Eigen::Infinity>(), 1e-3);
}

// The evaluator's gradient on a P that mixes the rows of a map: +-1 (a variable or its opposite),
// general (a transition's combination of two variables) and empty (a value fixed in x0). Against the
// chain rule written out (P^T times the per-element derivatives, the same bits) and against central
// differences of the energy.
TEST(FoldoverFreeMap, EvaluatorGradientIsTheChainRule)
{
  const Tet_grid g(3);
  const std::size_t E = g.tets.size();
  const int n = 3 * int(g.points.size());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1., 1.);
  std::uniform_int_distribution<int> kind(0, 9);
  HRI::Foldover_free_problem p;
  p.x0 = Eigen::VectorXd::Zero(Eigen::Index(12 * E));
  std::vector<Eigen::Triplet<double> > triplets;
  std::size_t unit = 0, general = 0, empty = 0;
  for(std::size_t e = 0; e < E; ++e) {
    for(int c = 0; c < 4; ++c)
      for(int r = 0; r < 3; ++r) {
        // x0 chosen so that every corner is at its vertex when y is the identity: elements near their
        // ideal shape, where central differences are accurate
        const int row = int(12 * e + 3 * c + r), v = 3 * g.tets[e][c] + r, w = (v + 7) % n, k = kind(rng);
        const double pv = g.points[std::size_t(v / 3)][v % 3], pw = g.points[std::size_t(w / 3)][w % 3];
        if(k < 4) { triplets.emplace_back(row, v, 1.); ++unit; }
        else if(k < 6) { triplets.emplace_back(row, v, -1.); p.x0[row] = 2 * pv; ++unit; }
        else if(k < 9) { triplets.emplace_back(row, v, 0.75); triplets.emplace_back(row, w, -0.5); p.x0[row] = 0.25 * pv + 0.5 * pw; ++general; }
        else { p.x0[row] = pv; ++empty; }
      }
    const Eigen::Matrix3d R = g.edge_matrix(g.tets[e]);
    p.M.push_back(R.inverse());
    p.w.push_back(R.determinant() / 6.);
  }
  p.P.resize(Eigen::Index(12 * E), n);
  p.P.setFromTriplets(triplets.begin(), triplets.end());
  ASSERT_GT(unit, 0u);
  ASSERT_GT(general, 0u);
  ASSERT_GT(empty, 0u);
  Eigen::VectorXd y(n);
  for(int i = 0; i < n; ++i) y[i] = g.points[std::size_t(i / 3)][i % 3] + 0.05 * u(rng);
  HRI::Foldover_free_evaluator ev(p, 0.5);
  ev.epsilon = 0.1;
  Eigen::VectorXd grad;
  const double F = ev(y, grad);
  // the chain rule with Eigen: x = P y + x0, per element w_e f_e / sum w and its corner derivatives
  const Eigen::VectorXd x = p.P * y + p.x0;
  double total = 0;
  for(double w : p.w) total += w;
  Eigen::VectorXd gx(12 * E);
  for(std::size_t e = 0; e < E; ++e)
    HRI::foldover_free_fused_element(x.data() + 12 * e, p.M[e], p.w[e] / total, 0.1, 0.5, gx.data() + 12 * e);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> Pt = p.P.transpose();
  const Eigen::VectorXd expected = Pt * gx;
  ASSERT_EQ(grad.size(), expected.size());
  for(int i = 0; i < n; ++i) EXPECT_EQ(grad[i], expected[i]) << i;
  for(int i = 0; i < n; i += 5) {
    const double h = 1e-6;
    Eigen::VectorXd yp = y, ym = y;
    yp[i] += h;
    ym[i] -= h;
    const double fd = (ev.value(yp) - ev.value(ym)) / (2 * h);
    EXPECT_NEAR(grad[i], fd, 1e-6 * std::max(1., std::abs(fd))) << i;
  }
  EXPECT_TRUE(std::isfinite(F));
}

TEST(FoldoverFreeMap, SameResultWithOneOrTwoThreads)
{
#ifdef _OPENMP
  const Tet_grid g(5);
  const Single_chart s(g);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  Eigen::VectorXd y0 = s.identity(g);
  for(Eigen::Index i = 0; i < y0.size(); ++i) y0[i] += u(rng);
  const int threads = omp_get_max_threads();
  Eigen::VectorXd y1 = y0, y2 = y0;
  omp_set_num_threads(1);
  const HRI::Foldover_free_result r1 = HRI::minimize_foldover_free(s.problem, y1);
  omp_set_num_threads(2);
  const HRI::Foldover_free_result r2 = HRI::minimize_foldover_free(s.problem, y2);
  omp_set_num_threads(threads);
  EXPECT_TRUE(r1.success);
  EXPECT_EQ(r1.outer_iterations, r2.outer_iterations);
  EXPECT_EQ(r1.inner_iterations, r2.inner_iterations);
  EXPECT_EQ(r1.energy, r2.energy);
  EXPECT_TRUE(y1 == y2);
#else
  GTEST_SKIP() << "built without OpenMP";
#endif
}

TEST(FoldoverFreeMap, InconsistentSizesThrow)
{
  const Tet_grid g(2);
  Single_chart s(g);
  Eigen::VectorXd y(3 * s.n + 1);
  EXPECT_THROW(HRI::minimize_foldover_free(s.problem, y), HR::Error);
}

TEST(FoldoverFreeMap, HeavilyTangledLargerGrid)
{
  // 10^3 voxels (6000 tets), interior vertices shuffled by up to +-3 cells
  const Tet_grid g(10);
  const Single_chart s(g);
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  Eigen::VectorXd y = s.identity(g);
  for(Eigen::Index i = 0; i < y.size(); ++i) y[i] += u(rng);
  const std::size_t before = exact_non_positive(s.problem, y);
  EXPECT_GE(before, 1000u);
  const HRI::Foldover_free_result r = HRI::minimize_foldover_free(s.problem, y);
  EXPECT_EQ(r.inverted_before, before);
  EXPECT_TRUE(r.success);
  EXPECT_EQ(exact_non_positive(s.problem, y), 0u);
  EXPECT_LT((y - s.identity(g)).lpNorm<Eigen::Infinity>(), 1e-3);
}

// ---------------------------------------------------------------------------------------------
// Hexahedral mesh smoothing

namespace {

typedef HR::Hexahedral_mesh_3 Hex_mesh;
typedef HR::Hexahedral_smoothing_reference Reference;

// Independent scaled Jacobian (algorithms.md §6), min over the 8 corners.
double hex_sj(const Hex_mesh& m, std::size_t h)
{
  static const int nb[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7}, {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
  double sj = 2;
  for(int i = 0; i < 8; ++i) {
    const Point& p = m.points[m.hexahedra[h][i]];
    Eigen::Matrix3d E;
    for(int k = 0; k < 3; ++k) {
      const Point& q = m.points[m.hexahedra[h][nb[i][k]]];
      Eigen::Vector3d e(q.x() - p.x(), q.y() - p.y(), q.z() - p.z());
      if(e.norm() == 0) return 0;
      E.col(k) = e.normalized();
    }
    sj = std::min(sj, E.determinant());
  }
  return sj;
}

std::pair<double, double> min_mean_sj(const Hex_mesh& m)
{
  double mn = 2, sum = 0;
  for(std::size_t h = 0; h < m.hexahedra.size(); ++h) {
    const double s = hex_sj(m, h);
    mn = std::min(mn, s);
    sum += s;
  }
  return std::make_pair(mn, sum / double(m.hexahedra.size()));
}

// Brute-force distances to the reference (independent of the AABB tree of the library).
double distance_to_triangles(const Reference& ref, const Point& p)
{
  double d = std::numeric_limits<double>::max();
  for(const auto& t : ref.triangles) {
    const CGAL::Exact_predicates_inexact_constructions_kernel::Triangle_3 tri(ref.points[t[0]], ref.points[t[1]], ref.points[t[2]]);
    d = std::min(d, CGAL::squared_distance(p, tri));
  }
  return std::sqrt(d);
}

double distance_to_polyline(const std::vector<Point>& pl, const Point& p)
{
  double d = std::numeric_limits<double>::max();
  for(std::size_t i = 0; i + 1 < pl.size(); ++i)
    d = std::min(d, CGAL::squared_distance(p, CGAL::Exact_predicates_inexact_constructions_kernel::Segment_3(pl[i], pl[i + 1])));
  return std::sqrt(d);
}

// A grid of N^3 unit cubes scaled to [0,1]^3, VTK order, tags set, and its exact reference (the
// cube's 12 triangles, 12 edges, 8 corners).
struct Hex_cube
{
  Hex_mesh mesh;
  Reference ref;
  std::vector<int> edge_of; // per vertex: index of its cube edge polyline, -1 if none
  int N;

  explicit Hex_cube(int n) : N(n)
  {
    auto id = [n](int i, int j, int k) { return std::uint32_t((k * (n + 1) + j) * (n + 1) + i); };
    for(int k = 0; k <= n; ++k)
      for(int j = 0; j <= n; ++j)
        for(int i = 0; i <= n; ++i) {
          mesh.points.emplace_back(double(i) / n, double(j) / n, double(k) / n);
          const int on = int(i == 0 || i == n) + int(j == 0 || j == n) + int(k == 0 || k == n);
          std::uint8_t tag = 0;
          if(on >= 1) tag |= Hex_mesh::BOUNDARY;
          if(on >= 2) tag |= Hex_mesh::FEATURE_CURVE;
          if(on == 3) tag |= Hex_mesh::CORNER;
          mesh.vertex_tags.push_back(tag);
        }
    for(int k = 0; k < n; ++k)
      for(int j = 0; j < n; ++j)
        for(int i = 0; i < n; ++i)
          mesh.hexahedra.push_back({ {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                                      id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)} });
    for(int c = 0; c < 8; ++c) ref.points.emplace_back(c & 1, (c >> 1) & 1, (c >> 2) & 1);
    const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for(const auto& q : quads) {
      ref.triangles.push_back({ {q[0], q[1], q[2]} });
      ref.triangles.push_back({ {q[0], q[2], q[3]} });
    }
    for(int a = 0; a < 8; ++a)
      for(int b = a + 1; b < 8; ++b)
        if(__builtin_popcount(unsigned(a ^ b)) == 1) ref.feature_polylines.push_back({ref.points[a], ref.points[b]});
    ref.corners = ref.points;
    edge_of.assign(mesh.points.size(), -1);
    for(std::size_t v = 0; v < mesh.points.size(); ++v)
      if((mesh.vertex_tags[v] & Hex_mesh::FEATURE_CURVE) && !(mesh.vertex_tags[v] & Hex_mesh::CORNER))
        for(std::size_t c = 0; c < ref.feature_polylines.size(); ++c)
          if(distance_to_polyline(ref.feature_polylines[c], mesh.points[v]) == 0) edge_of[v] = int(c);
  }
};

// A hex mesh of the cylinder r = 1, -1 <= z <= 1: an O-grid (inner n x n square of half-side 1/2,
// m ring layers blended linearly to the circle) extruded in nz layers; the reference is the
// cylinder triangulated with K segments (caps as fans), its two rims as closed polylines.
struct Hex_cylinder
{
  Hex_mesh mesh;
  Reference ref;
  std::vector<bool> rim;

  Hex_cylinder(int n, int m, int nz, int K)
  {
    // 2D points and quads
    std::vector<Eigen::Vector2d> p2;
    std::vector<std::array<int, 4> > q2;
    std::vector<int> boundary2; // 1 on the circle
    auto sq = [&](int i, int j) { return j * (n + 1) + i; };
    for(int j = 0; j <= n; ++j)
      for(int i = 0; i <= n; ++i) {
        p2.emplace_back(-0.5 + double(i) / n, -0.5 + double(j) / n);
        boundary2.push_back(0);
      }
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i) q2.push_back({ {sq(i, j), sq(i + 1, j), sq(i + 1, j + 1), sq(i, j + 1)} });
    // perimeter of the square, counter-clockwise, 4n points
    std::vector<int> perimeter;
    for(int i = 0; i < n; ++i) perimeter.push_back(sq(i, 0));
    for(int j = 0; j < n; ++j) perimeter.push_back(sq(n, j));
    for(int i = n; i > 0; --i) perimeter.push_back(sq(i, n));
    for(int j = n; j > 0; --j) perimeter.push_back(sq(0, j));
    const int P = int(perimeter.size());
    std::vector<std::vector<int> > layer(m + 1);
    layer[0] = perimeter;
    for(int k = 1; k <= m; ++k)
      for(int s = 0; s < P; ++s) {
        const Eigen::Vector2d a = p2[perimeter[s]];
        const double t = double(k) / m;
        p2.push_back((1 - t) * a + t * a.normalized());
        boundary2.push_back(k == m ? 1 : 0);
        layer[k].push_back(int(p2.size()) - 1);
      }
    for(int k = 0; k < m; ++k)
      for(int s = 0; s < P; ++s)
        q2.push_back({ {layer[k][s], layer[k + 1][s], layer[k + 1][(s + 1) % P], layer[k][(s + 1) % P]} });
    for(auto& q : q2) {
      double area = 0;
      for(int c = 0; c < 4; ++c) {
        const Eigen::Vector2d& a = p2[q[c]];
        const Eigen::Vector2d& b = p2[q[(c + 1) % 4]];
        area += a.x() * b.y() - a.y() * b.x();
      }
      if(area < 0) std::swap(q[1], q[3]);
    }
    const std::uint32_t L = std::uint32_t(p2.size());
    for(int z = 0; z <= nz; ++z)
      for(std::size_t v = 0; v < p2.size(); ++v) {
        mesh.points.emplace_back(p2[v].x(), p2[v].y(), -1. + 2. * z / nz);
        const bool cap = z == 0 || z == nz;
        std::uint8_t tag = 0;
        if(cap || boundary2[v]) tag |= Hex_mesh::BOUNDARY;
        if(cap && boundary2[v]) tag |= Hex_mesh::FEATURE_CURVE;
        mesh.vertex_tags.push_back(tag);
        rim.push_back(cap && boundary2[v]);
      }
    for(int z = 0; z < nz; ++z)
      for(const auto& q : q2) {
        std::array<std::uint32_t, 8> h;
        for(int c = 0; c < 4; ++c) {
          h[c] = std::uint32_t(z) * L + std::uint32_t(q[c]);
          h[c + 4] = std::uint32_t(z + 1) * L + std::uint32_t(q[c]);
        }
        mesh.hexahedra.push_back(h);
      }
    // reference
    for(int z = 0; z < 2; ++z)
      for(int k = 0; k < K; ++k) {
        const double a = 2 * M_PI * k / K;
        ref.points.emplace_back(std::cos(a), std::sin(a), z == 0 ? -1. : 1.);
      }
    ref.points.emplace_back(0, 0, -1);
    ref.points.emplace_back(0, 0, 1);
    const std::uint32_t c0 = std::uint32_t(2 * K), c1 = c0 + 1;
    for(int k = 0; k < K; ++k) {
      const std::uint32_t a = std::uint32_t(k), b = std::uint32_t((k + 1) % K);
      ref.triangles.push_back({ {a, b, b + std::uint32_t(K)} });
      ref.triangles.push_back({ {a, b + std::uint32_t(K), a + std::uint32_t(K)} });
      ref.triangles.push_back({ {c0, b, a} });
      ref.triangles.push_back({ {c1, a + std::uint32_t(K), b + std::uint32_t(K)} });
    }
    for(int z = 0; z < 2; ++z) {
      std::vector<Point> pl;
      for(int k = 0; k <= K; ++k) pl.push_back(ref.points[std::size_t(z * K + k % K)]);
      ref.feature_polylines.push_back(pl);
    }
  }
};

struct Recording_visitor
{
  int untangled = 0, rounds = 0;
  void after_untangling(const HR::Hexahedral_mesh_quality&) { ++untangled; }
  void after_round(int, const HR::Hexahedral_mesh_quality&, bool) { ++rounds; }
};

} // namespace

TEST(HexSmoothing, TangledCubeGridIsUntangledAndKeepsItsBoundary)
{
  Hex_cube cube(5);
  const Hex_mesh input = cube.mesh;
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-0.16, 0.16); // +-0.8 cell
  for(std::size_t v = 0; v < cube.mesh.points.size(); ++v)
    if(cube.mesh.vertex_tags[v] == 0) {
      const Point& p = cube.mesh.points[v];
      cube.mesh.points[v] = Point(p.x() + u(rng), p.y() + u(rng), p.z() + u(rng));
    }
  const std::pair<double, double> before = min_mean_sj(cube.mesh);
  std::size_t inverted = 0;
  for(std::size_t h = 0; h < cube.mesh.hexahedra.size(); ++h) inverted += hex_sj(cube.mesh, h) <= 0 ? 1 : 0;
  EXPECT_GE(inverted, 5u);
  const Hex_mesh tangled = cube.mesh;
  Recording_visitor visitor;
  const HR::Hexahedral_smoothing_report r =
    HR::smooth_hexahedral_mesh(cube.mesh, cube.ref, CGAL::parameters::visitor(std::ref(visitor)));
  const std::pair<double, double> after = min_mean_sj(cube.mesh);
  EXPECT_TRUE(r.untangling_run);
  EXPECT_EQ(visitor.untangled, 1);
  EXPECT_EQ(visitor.rounds, r.rounds);
  EXPECT_GT(after.first, 0.);
  EXPECT_GT(after.second, before.second);
  EXPECT_NEAR(r.after.min_scaled_jacobian, after.first, 1e-12);
  EXPECT_NEAR(r.before.min_scaled_jacobian, before.first, 1e-12);
  EXPECT_EQ(r.before.non_positive, inverted);
  EXPECT_EQ(r.after.non_positive, 0u);
  EXPECT_EQ(r.fixed_vertices, 8u);
  EXPECT_EQ(r.curve_vertices, 12u * 4u);
  EXPECT_EQ(r.surface_vertices, 6u * 16u);
  EXPECT_EQ(r.interior_vertices, 64u);
  // corners did not move, feature vertices are on their edge, boundary vertices on the cube
  for(std::size_t v = 0; v < input.points.size(); ++v) {
    const std::uint8_t t = input.vertex_tags[v];
    if(t & Hex_mesh::CORNER) EXPECT_EQ(cube.mesh.points[v], input.points[v]);
    else if(t & Hex_mesh::FEATURE_CURVE)
      EXPECT_LT(distance_to_polyline(cube.ref.feature_polylines[std::size_t(cube.edge_of[v])], cube.mesh.points[v]), 1e-12);
    else if(t & Hex_mesh::BOUNDARY) EXPECT_LT(distance_to_triangles(cube.ref, cube.mesh.points[v]), 1e-12);
  }
  EXPECT_LT(r.after.hausdorff_distance, 1e-12);
}

TEST(HexSmoothing, UntaggedMeshIsClassifiedByDistance)
{
  // same as above without vertex_tags: the roles are recomputed from the boundary quads and distances
  Hex_cube cube(4);
  const Hex_mesh input = cube.mesh;
  cube.mesh.vertex_tags.clear();
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  for(std::size_t v = 0; v < cube.mesh.points.size(); ++v)
    if(input.vertex_tags[v] == 0) {
      const Point& p = cube.mesh.points[v];
      cube.mesh.points[v] = Point(p.x() + u(rng), p.y() + u(rng), p.z() + u(rng));
    }
  EXPECT_LE(min_mean_sj(cube.mesh).first, 0.);
  const HR::Hexahedral_smoothing_report r = HR::smooth_hexahedral_mesh(cube.mesh, cube.ref);
  EXPECT_EQ(r.fixed_vertices, 8u);
  EXPECT_EQ(r.curve_vertices, 12u * 3u);
  EXPECT_EQ(r.surface_vertices, 6u * 9u);
  EXPECT_EQ(r.interior_vertices, 27u);
  EXPECT_GT(min_mean_sj(cube.mesh).first, 0.);
  for(std::size_t v = 0; v < input.points.size(); ++v)
    if(input.vertex_tags[v] & Hex_mesh::CORNER) EXPECT_EQ(cube.mesh.points[v], input.points[v]);
    else if(input.vertex_tags[v] & Hex_mesh::FEATURE_CURVE)
      EXPECT_LT(distance_to_polyline(cube.ref.feature_polylines[std::size_t(cube.edge_of[v])], cube.mesh.points[v]), 1e-12);
}

TEST(HexSmoothing, FeatureVerticesSlideOnTheirCurveAndCornersStay)
{
  // boundary vertices moved along the reference (features along their edge, surface vertices in their
  // face), interior vertices jittered: the result keeps every constraint and does not lower min SJ
  Hex_cube cube(5);
  const Hex_mesh input = cube.mesh;
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-0.04, 0.04);
  for(std::size_t v = 0; v < cube.mesh.points.size(); ++v) {
    const std::uint8_t t = input.vertex_tags[v];
    if(t & Hex_mesh::CORNER) continue;
    Eigen::Vector3d p(input.points[v].x(), input.points[v].y(), input.points[v].z());
    for(int d = 0; d < 3; ++d) {
      const bool on_side = p[d] == 0. || p[d] == 1.;
      if(!on_side) p[d] += u(rng);
    }
    cube.mesh.points[v] = Point(p[0], p[1], p[2]);
  }
  const std::pair<double, double> before = min_mean_sj(cube.mesh);
  EXPECT_GT(before.first, 0.);
  const HR::Hexahedral_smoothing_report r = HR::smooth_hexahedral_mesh(cube.mesh, cube.ref);
  const std::pair<double, double> after = min_mean_sj(cube.mesh);
  EXPECT_FALSE(r.untangling_run);
  EXPECT_GE(after.first, before.first);
  EXPECT_GT(after.second, before.second);
  EXPECT_GT(after.first, 0.95); // the regular grid is the optimum
  for(std::size_t v = 0; v < input.points.size(); ++v) {
    const std::uint8_t t = input.vertex_tags[v];
    if(t & Hex_mesh::CORNER) EXPECT_EQ(cube.mesh.points[v], input.points[v]);
    else if(t & Hex_mesh::FEATURE_CURVE)
      EXPECT_LT(distance_to_polyline(cube.ref.feature_polylines[std::size_t(cube.edge_of[v])], cube.mesh.points[v]), 1e-9 * std::sqrt(3.));
    else if(t & Hex_mesh::BOUNDARY) EXPECT_LT(distance_to_triangles(cube.ref, cube.mesh.points[v]), 1e-9);
  }
  // FIX_FEATURES keeps the feature vertices where they are
  Hex_mesh fixed = cube.mesh;
  for(std::size_t v = 0; v < input.points.size(); ++v)
    if(input.vertex_tags[v] == 0) {
      const Point& p = fixed.points[v];
      fixed.points[v] = Point(p.x() + u(rng), p.y() + u(rng), p.z() + u(rng));
    }
  const Hex_mesh jittered = fixed;
  HR::smooth_hexahedral_mesh(fixed, cube.ref, HR::parameters::smoothing_boundary(HR::Hexahedral_smoothing_boundary::FIX_FEATURES));
  for(std::size_t v = 0; v < input.points.size(); ++v)
    if(input.vertex_tags[v] & (Hex_mesh::FEATURE_CURVE | Hex_mesh::CORNER)) EXPECT_EQ(fixed.points[v], jittered.points[v]);
  // FIX_ALL and user-fixed vertices: nothing on the boundary moves, nor vertex 31 (interior)
  Hex_mesh all = jittered;
  std::vector<bool> user(all.points.size(), false);
  ASSERT_EQ(input.vertex_tags[43], 0);
  user[43] = true;
  HR::smooth_hexahedral_mesh(all, cube.ref, HR::parameters::smoothing_boundary(HR::Hexahedral_smoothing_boundary::FIX_ALL,
                                                                               HR::parameters::smoothing_fixed_vertices(user)));
  for(std::size_t v = 0; v < input.points.size(); ++v)
    if(input.vertex_tags[v] != 0 || v == 43) EXPECT_EQ(all.points[v], jittered.points[v]);
}

TEST(HexSmoothing, CylinderBoundaryIsProjectedBackAndQualityImproves)
{
  Hex_cylinder cyl(4, 3, 4, 96);
  const Hex_mesh clean = cyl.mesh;
  const double diag = std::sqrt(2. * 2. + 2. * 2. + 2. * 2.);
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(-0.03, 0.03);
  for(std::size_t v = 0; v < cyl.mesh.points.size(); ++v)
    if(cyl.mesh.vertex_tags[v] != 0) {
      const Point& p = cyl.mesh.points[v];
      cyl.mesh.points[v] = Point(p.x() + u(rng), p.y() + u(rng), p.z() + u(rng));
    }
  const Hex_mesh perturbed = cyl.mesh;
  const std::pair<double, double> before = min_mean_sj(cyl.mesh);
  double off_before = 0;
  for(std::size_t v = 0; v < cyl.mesh.points.size(); ++v)
    if(cyl.mesh.vertex_tags[v] != 0) off_before = std::max(off_before, distance_to_triangles(cyl.ref, cyl.mesh.points[v]));
  EXPECT_GT(off_before, 1e-2);
  const HR::Hexahedral_smoothing_report r = HR::smooth_hexahedral_mesh(cyl.mesh, cyl.ref);
  const std::pair<double, double> after = min_mean_sj(cyl.mesh);
  EXPECT_GE(after.first, before.first);
  EXPECT_GT(after.second, before.second);
  for(std::size_t v = 0; v < cyl.mesh.points.size(); ++v) {
    if(cyl.mesh.vertex_tags[v] != 0) EXPECT_LT(distance_to_triangles(cyl.ref, cyl.mesh.points[v]), 1e-6 * diag);
    if(cyl.rim[v])
      EXPECT_LT(std::min(distance_to_polyline(cyl.ref.feature_polylines[0], cyl.mesh.points[v]),
                         distance_to_polyline(cyl.ref.feature_polylines[1], cyl.mesh.points[v])), 1e-9 * diag);
  }
  EXPECT_LT(r.after.hausdorff_distance, r.before.hausdorff_distance);
  EXPECT_GE(r.accepted_state, 1);
  EXPECT_NEAR(r.after.mean_scaled_jacobian, after.second, 1e-12);
}

TEST(HexSmoothing, ReferenceFromATetrahedralMesh)
{
  // the Kuhn tet grid of the unit cube with its 12 edges as feature curves and its 8 corners
  const Tet_grid g(3);
  HR::Tetrahedral_soup_3<Point> soup;
  for(const auto& p : g.points) soup.points.emplace_back(p.x(), p.y(), p.z());
  for(const auto& t : g.tets) soup.tetrahedra.push_back({ {std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2]), std::size_t(t[3])} });
  auto id = [](int i, int j, int k) { return std::size_t((k * 4 + j) * 4 + i); };
  int curve = 0;
  for(int axis = 0; axis < 3; ++axis)
    for(int a = 0; a <= 3; a += 3)
      for(int b = 0; b <= 3; b += 3, ++curve)
        for(int s = 0; s < 3; ++s) {
          int c0[3], c1[3];
          c0[axis] = s; c1[axis] = s + 1;
          c0[(axis + 1) % 3] = c1[(axis + 1) % 3] = a;
          c0[(axis + 2) % 3] = c1[(axis + 2) % 3] = b;
          soup.feature_edges.push_back({ {id(c0[0], c0[1], c0[2]), id(c1[0], c1[1], c1[2])} });
          soup.feature_edge_curves.push_back(curve);
        }
  for(int c = 0; c < 8; ++c) soup.corners.push_back(id(3 * (c & 1), 3 * ((c >> 1) & 1), 3 * ((c >> 2) & 1)));
  HR::Tetrahedral_mesh_3<> tets;
  HR::build_tetrahedral_mesh(soup, tets, HR::parameters::split_multi_boundary_tetrahedra(false));
  const Reference ref = HR::make_hexahedral_smoothing_reference(tets);
  EXPECT_EQ(ref.triangles.size(), 6u * 9u * 2u);
  ASSERT_EQ(ref.feature_polylines.size(), 12u);
  for(const auto& pl : ref.feature_polylines) {
    ASSERT_EQ(pl.size(), 4u);
    EXPECT_NEAR(std::sqrt(CGAL::squared_distance(pl.front(), pl.back())), 1., 1e-15);
  }
  EXPECT_EQ(ref.corners.size(), 8u);

  // and it drives the smoothing of a tangled hex grid like the exact reference
  Hex_cube cube(3);
  const Hex_mesh input = cube.mesh;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.25, 0.25);
  for(std::size_t v = 0; v < cube.mesh.points.size(); ++v)
    if(input.vertex_tags[v] == 0) {
      const Point& p = cube.mesh.points[v];
      cube.mesh.points[v] = Point(p.x() + u(rng), p.y() + u(rng), p.z() + u(rng));
    }
  HR::smooth_hexahedral_mesh(cube.mesh, ref);
  EXPECT_GT(min_mean_sj(cube.mesh).first, 0.);
  for(std::size_t v = 0; v < input.points.size(); ++v)
    if(input.vertex_tags[v] & Hex_mesh::CORNER) EXPECT_EQ(cube.mesh.points[v], input.points[v]);
}

TEST(HexSmoothing, InvalidIndexThrowsAndEmptyMeshIsANoOp)
{
  Hex_cube cube(1);
  Hex_mesh bad = cube.mesh;
  bad.hexahedra[0][5] = 99;
  EXPECT_THROW(HR::smooth_hexahedral_mesh(bad, cube.ref), HR::Input_error);
  Hex_mesh empty;
  const HR::Hexahedral_smoothing_report r = HR::smooth_hexahedral_mesh(empty, cube.ref);
  EXPECT_EQ(r.rounds, 0);
}

// ---------------------------------------------------------------------------------------------
// Extracted hex meshes of the shared integer-grid maps, smoothed against their tet mesh's boundary

class HexSmoothingOnExtractedMeshes : public ::testing::TestWithParam<const char*> {};

TEST_P(HexSmoothingOnExtractedMeshes, QualityNeverLowerAndBoundaryOnTheSurface)
{
  const std::string file = std::string(HEXREM_SHARED_DATA_DIR) + "/igm/" + GetParam() + ".hexex";
  if(!std::filesystem::exists(file)) GTEST_SKIP() << file << " absent";
  HR::Integer_grid_map map;
  HR::IO::read_HexEx(file, map);
  Hex_mesh hexes;
  HR::extract_hexahedra(map, hexes);
  ASSERT_GT(hexes.number_of_hexahedra(), 0u);
  HR::Tetrahedral_soup_3<Point> soup;
  soup.points.assign(map.points.begin(), map.points.end());
  for(const auto& t : map.tetrahedra) soup.tetrahedra.push_back({ {t[0], t[1], t[2], t[3]} });
  HR::Tetrahedral_mesh_3<> tets;
  HR::build_tetrahedral_mesh(soup, tets, HR::parameters::split_multi_boundary_tetrahedra(false));
  const Reference ref = HR::make_hexahedral_smoothing_reference(tets);
  const Hex_mesh input = hexes;
  const std::pair<double, double> before = min_mean_sj(hexes);
  const HR::Hexahedral_smoothing_report r = HR::smooth_hexahedral_mesh(hexes, ref);
  const std::pair<double, double> after = min_mean_sj(hexes);
  EXPECT_GE(after.first, before.first);
  if(before.first > 0) EXPECT_GT(after.first, 0.);
  EXPECT_EQ(hexes.hexahedra, input.hexahedra);
  // the extraction tags the boundary vertices: they stay on the tet mesh's boundary surface
  double diag = 0;
  for(const auto& p : ref.points)
    diag = std::max(diag, std::sqrt(CGAL::squared_distance(p, ref.points.front())));
  double worst = 0;
  for(std::size_t v = 0; v < hexes.points.size(); ++v)
    if((hexes.vertex_tags[v] & Hex_mesh::BOUNDARY) && r.accepted_state >= 0)
      worst = std::max(worst, distance_to_triangles(ref, hexes.points[v]));
  EXPECT_LT(worst, 1e-9 * diag);
  RecordProperty("min_sj_before", std::to_string(before.first));
  RecordProperty("min_sj_after", std::to_string(after.first));
}

INSTANTIATE_TEST_SUITE_P(SharedMaps, HexSmoothingOnExtractedMeshes, ::testing::Values("hand_q", "fancy_ring_q"));
