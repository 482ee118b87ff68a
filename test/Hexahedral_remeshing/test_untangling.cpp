// Tests of the foldover-free minimizer (Garanzha et al. 2021) and of the hexahedral mesh smoothing.
#include <CGAL/Hexahedral_remeshing/internal/untangling/foldover_free_map.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
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
