// Tests of the frame field, the matchings, the singularity graph and the achieved boundary
// valences, on the oracles of the design guide (section 7).
#include "data_paths.h"
#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/boundary_dihedral_angles.h>
#include <CGAL/Hexahedral_remeshing/frame_field.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/aggregation_multigrid.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/conjugate_gradients.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/parallel_vector_operations.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/preconditioned_lbfgs.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/smoothing.h>
#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>

#include <Eigen/Sparse>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <cmath>
#include <iostream>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace HR = CGAL::Hexahedral_remeshing;
typedef HR::Tetrahedral_mesh_3<> Mesh;
typedef Mesh::Index Index;
typedef Mesh::Point_3 Point;

namespace {

const std::string example_data = HEXREM_EXAMPLE_DATA_DIR;
const std::string shared_data = HEXREM_SHARED_DATA_DIR;

Mesh load(const std::string& file, double max_volume = 0)
{
  Mesh m;
  HR::IO::read_tetrahedral_mesh(file, m, HR::parameters::maximum_tetrahedron_volume(max_volume));
  return m;
}

Mesh from_soup(const std::vector<Point>& points, const std::vector<std::array<std::size_t, 4> >& tets, bool split = true)
{
  HR::Tetrahedral_soup_3<Point> soup;
  soup.points = points;
  soup.tetrahedra = tets;
  Mesh m;
  HR::build_tetrahedral_mesh(soup, m, HR::parameters::split_multi_boundary_tetrahedra(split));
  return m;
}

Eigen::Vector3d to_eigen(const Mesh::Vector_3& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); }

Eigen::Vector3d centroid(const Mesh& m, Index t)
{
  const auto& v = m.tetrahedron_vertices(t);
  return to_eigen(CGAL::centroid(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])) - CGAL::ORIGIN);
}

struct Field
{
  std::vector<Eigen::Vector3d> directions;
  std::vector<Eigen::Matrix3d> frames;
  HR::Frame_field_result result;
  HR::Matchings matchings;
  HR::Singularity_graph graph;
  HR::Boundary_valences valences;
};

// The classic normal-aligned field with its analysis; the prescribed valences are the geometric classes.
Field normal_aligned_field(const Mesh& m)
{
  Field f;
  f.directions = HR::boundary_triangle_unit_normals(m);
  f.result = HR::compute_frame_field(m, f.directions, f.frames);
  f.matchings = HR::compute_matchings(m, f.frames);
  f.graph = HR::compute_singularity_graph(m, f.frames, f.matchings);
  std::vector<int> geometric(m.number_of_edges(), -1);
  for(Index e : m.boundary_edges()) geometric[e] = HR::boundary_edge_dihedral_class(m, e);
  f.valences = HR::compute_achieved_boundary_valences(m, f.frames, f.matchings, f.directions, geometric);
  return f;
}

// The tets around the edge (0,0,0)-(0,0,1): a wheel of n tets.
Mesh wheel(int n)
{
  std::vector<Point> p = {Point(0, 0, 0), Point(0, 0, 1)};
  std::vector<std::array<std::size_t, 4> > tets;
  for(int k = 0; k < n; ++k) p.push_back(Point(std::cos(2 * CGAL_PI * k / n), std::sin(2 * CGAL_PI * k / n), 0.5));
  for(int k = 0; k < n; ++k) tets.push_back({0, 1, std::size_t(2 + k), std::size_t(2 + (k + 1) % n)});
  return from_soup(p, tets, false);
}

} // namespace

TEST(Singularities, AnalyticFieldsAroundAnEdgeGiveValence3And5)
{
  for(int n : {8, 13}) {
    const Mesh m = wheel(n);
    const Index axis = m.find_edge(0, 1);
    ASSERT_FALSE(m.is_boundary_edge(axis));
    for(int sign : {+1, -1}) {
      std::vector<Eigen::Matrix3d> frames(m.number_of_tetrahedra());
      for(Index t = 0; t < m.number_of_tetrahedra(); ++t) {
        const Eigen::Vector3d c = centroid(m, t);
        double theta = std::atan2(c.y(), c.x());
        if(theta < 0) theta += 2 * CGAL_PI;
        frames[t] = Eigen::AngleAxisd(sign * theta / 4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
      }
      const HR::Matchings mt = HR::compute_matchings(m, frames);
      const HR::Singularity_graph g = HR::compute_singularity_graph(m, frames, mt);
      EXPECT_EQ(g.edge_valence[axis], sign > 0 ? 3 : 5) << n << " tets, sign " << sign;
      EXPECT_EQ(sign > 0 ? g.valence3_edges : g.valence5_edges, 1u);
      EXPECT_EQ(g.improper_edges, 0u);
      ASSERT_EQ(g.curves.size(), 1u);
      EXPECT_EQ(g.curves[0].edges, std::vector<std::uint32_t>{axis});
      // a constant field is regular
      std::vector<Eigen::Matrix3d> constant(m.number_of_tetrahedra(), Eigen::Matrix3d::Identity());
      const HR::Matchings mc = HR::compute_matchings(m, constant);
      EXPECT_EQ(HR::compute_singularity_graph(m, constant, mc).edge_valence[axis], 4);
    }
  }
}

TEST(FrameField, CubeIsPerfectlySmoothAndRegular)
{
  const Mesh m = load(example_data + "/cube.off", 0.002);
  ASSERT_GT(m.number_of_tetrahedra(), 500u);
  const Field f = normal_aligned_field(m);
  EXPECT_LT(f.result.energy, 1e-10);
  EXPECT_EQ(f.graph.valence3_edges + f.graph.valence5_edges + f.graph.improper_edges, 0u);
  // k = 1 on the edges of the 12 cube edges, 2 elsewhere: exactly the geometric classes
  EXPECT_EQ(f.valences.mismatched, 0u);
  EXPECT_EQ(f.valences.matched, m.boundary_edges().size());
  EXPECT_GE(f.valences.histogram[1], 12u);
  EXPECT_EQ(f.valences.histogram[1] + f.valences.histogram[2], m.boundary_edges().size());
  EXPECT_LT(f.valences.max_deviation, 1e-9);
  // every constrained tet keeps an axis exactly on its direction
  for(Index b = 0; b < m.number_of_boundary_triangles(); ++b) {
    const Eigen::Vector3d c = f.frames[m.boundary_triangle_tetrahedron(b)].transpose() * f.directions[b];
    EXPECT_NEAR(c.cwiseAbs().maxCoeff(), 1.0, 1e-12);
  }
}

TEST(FrameField, CylinderHasFourValence3CurvesAlongTheAxis)
{
  const Mesh m = load(example_data + "/cylinder.off", 0.004);
  const Field f = normal_aligned_field(m);
  EXPECT_EQ(f.valences.mismatched, 0u); // rims k = 1, elsewhere 2
  EXPECT_EQ(f.graph.valence5_edges, 0u);
  EXPECT_EQ(f.graph.improper_edges, 0u);
  EXPECT_EQ(f.graph.number_of_curves(3), 4u);
  // each curve goes from cap to cap, roughly parallel to the axis
  for(const HR::Singular_curve& c : f.graph.curves) {
    ASSERT_EQ(c.valence, 3);
    const double z0 = m.point(c.vertices.front()).z(), z1 = m.point(c.vertices.back()).z();
    EXPECT_NEAR(std::min(z0, z1), 0.0, 1e-12);
    EXPECT_NEAR(std::max(z0, z1), 2.0, 1e-12);
  }
  EXPECT_TRUE(f.graph.dangling_vertices.empty());
  EXPECT_TRUE(f.graph.zipper_vertices.empty());
}

TEST(FrameField, AcuteEdgeBreaksTheNormalAlignedField)
{
  const Mesh m = load(example_data + "/n13c_acute_line.vtk");
  const Field f = normal_aligned_field(m);
  std::size_t zero = 0;
  for(Index e : m.boundary_edges())
    if(HR::boundary_edge_dihedral_class(m, e) == 0) {
      EXPECT_EQ(f.valences.achieved[e], 0); // the failure the paper fixes
      ++zero;
    }
  EXPECT_EQ(zero, 8u);
  EXPECT_EQ(f.valences.histogram[0], 8u);
}

TEST(FrameField, SmoothingNeverIncreasesTheEnergy)
{
  struct Recorder : HR::Frame_field_visitor
  {
    std::vector<double> energies;
    std::vector<std::string> stages;
    void start_stage(const std::string& s) { stages.push_back(s); }
    void smoothing_progress(double e, int) { energies.push_back(e); }
  } recorder;
  const Mesh m = load(example_data + "/cylinder.off", 0.004);
  std::vector<Eigen::Matrix3d> frames;
  const HR::Frame_field_result r = HR::compute_frame_field(m, HR::boundary_triangle_unit_normals(m), frames,
                                                           CGAL::parameters::visitor(std::ref(recorder)));
  EXPECT_EQ(recorder.stages, (std::vector<std::string>{"setup", "initialization", "smoothing"}));
  ASSERT_FALSE(recorder.energies.empty());
  double previous = r.initial_energy;
  for(double e : recorder.energies) {
    EXPECT_LE(e, previous);
    previous = e;
  }
  EXPECT_LT(r.energy, r.initial_energy);
  EXPECT_DOUBLE_EQ(r.energy, recorder.energies.back());
  // the reported energy is the energy of the returned frames
  HR::Tetrahedral_mesh_3<> copy = m;
  auto p = HR::internal::make_frame_field_problem(copy, HR::boundary_triangle_unit_normals(m), HR::internal::Face_weighting::AREA_OVER_DISTANCE);
  EXPECT_NEAR(HR::internal::frame_field_energy(p, frames), r.energy, 1e-9 * r.energy);
}

TEST(FrameField, BadInputsAreRejected)
{
  const Mesh m = load(example_data + "/cube.off");
  std::vector<Eigen::Matrix3d> frames;
  std::vector<Eigen::Vector3d> too_few(3, Eigen::Vector3d::UnitX());
  EXPECT_THROW(HR::compute_frame_field(m, too_few, frames), HR::Error);
  std::vector<Eigen::Vector3d> zero(m.number_of_boundary_triangles(), Eigen::Vector3d::Zero());
  EXPECT_THROW(HR::compute_frame_field(m, zero, frames), HR::Error);
  Mesh unsplit;
  HR::IO::read_tetrahedral_mesh(example_data + "/cube.off", unsplit, HR::parameters::split_multi_boundary_tetrahedra(false));
  if(unsplit.number_of_split_tetrahedra() == 0 && unsplit.number_of_tetrahedra() == m.number_of_tetrahedra()) return;
  EXPECT_THROW(HR::compute_frame_field(unsplit, HR::boundary_triangle_unit_normals(unsplit), frames), HR::Error);
}

// fixed_frames: the given tetrahedra keep their frames exactly, the constrained ones stay on their
// directions, the reported energy is that of the returned field, and bad frames are refused.
TEST(FrameField, FixedFramesAreKept)
{
  const Mesh m = load(example_data + "/cylinder.off", 0.004);
  const auto normals = HR::boundary_triangle_unit_normals(m);
  std::vector<bool> on_boundary(m.number_of_tetrahedra(), false);
  for(Index b = 0; b < m.number_of_boundary_triangles(); ++b) on_boundary[m.boundary_triangle_tetrahedron(b)] = true;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.35, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  std::vector<std::pair<std::size_t, Eigen::Matrix3d> > fixed;
  for(Index t = 0; t < m.number_of_tetrahedra(); ++t) {
    const auto& tv = m.tetrahedron_vertices(t);
    if(!on_boundary[t] && CGAL::to_double(m.point(tv[0]).z()) > 1.2) fixed.emplace_back(t, R);
  }
  ASSERT_GT(fixed.size(), 20u);
  std::vector<Eigen::Matrix3d> free_frames, frames;
  const HR::Frame_field_result free_field = HR::compute_frame_field(m, normals, free_frames);
  const HR::Frame_field_result r = HR::compute_frame_field(m, normals, frames, HR::parameters::fixed_frames(fixed));
  for(const auto& f : fixed) ASSERT_TRUE(frames[f.first] == f.second) << "tetrahedron " << f.first;
  for(Index b = 0; b < m.number_of_boundary_triangles(); ++b)
    ASSERT_NEAR((frames[m.boundary_triangle_tetrahedron(b)].transpose() * normals[b]).cwiseAbs().maxCoeff(), 1.0, 1e-9);
  // a field forced away from its optimum costs energy
  EXPECT_GT(r.energy, free_field.energy);
  auto p = HR::internal::make_frame_field_problem(m, normals, HR::internal::Face_weighting::AREA_OVER_DISTANCE, fixed);
  EXPECT_NEAR(HR::internal::frame_field_energy(p, frames), r.energy, 1e-9 * r.energy);

  auto bad = fixed;
  bad.front().second(0, 0) += 0.1; // not a rotation
  EXPECT_THROW(HR::compute_frame_field(m, normals, frames, HR::parameters::fixed_frames(bad)), HR::Error);
  bad = fixed;
  bad.emplace_back(m.number_of_tetrahedra(), R); // no such tetrahedron
  EXPECT_THROW(HR::compute_frame_field(m, normals, frames, HR::parameters::fixed_frames(bad)), HR::Error);
  bad = fixed;
  const Index b0 = 0;
  const Eigen::Matrix3d off = Eigen::AngleAxisd(0.3, normals[b0].unitOrthogonal()).toRotationMatrix() *
                              HR::internal::minimal_rotation_to(normals[b0]);
  bad.emplace_back(m.boundary_triangle_tetrahedron(b0), off); // leaves its boundary direction
  EXPECT_THROW(HR::compute_frame_field(m, normals, frames, HR::parameters::fixed_frames(bad)), HR::Error);
}

namespace {

// sum_f w_f |q_s - M_f q_t|^2 + mu |q|^2 in the reduced unknowns, written out here face by face
// (scatter) independently of the solvers' per-tet gathers.
Eigen::VectorXd apply_reference(const HR::internal::Multigrid_fine_system& s, const Eigen::VectorXd& x)
{
  typedef Eigen::Matrix<double, 9, 1> V9;
  std::vector<V9> q(s.number_of_tets, V9::Zero());
  auto d = [&](std::size_t t) { return Eigen::Index(s.offset[t + 1] - s.offset[t]); };
  for(std::size_t t = 0; t < s.number_of_tets; ++t)
    q[t] = d(t) == 9 ? V9(x.segment<9>(Eigen::Index(s.offset[t]))) : d(t) == 0 ? V9::Zero() : V9(s.Q(t) * x.segment(Eigen::Index(s.offset[t]), d(t)));
  std::vector<V9> g(s.number_of_tets, V9::Zero());
  for(std::size_t t = 0; t < s.number_of_tets; ++t) g[t] = s.mu * q[t];
  for(std::size_t f = 0; f < s.face_tets->size(); ++f) {
    const auto st = (*s.face_tets)[f];
    const Eigen::Matrix<double, 9, 9> M = s.face_rotation.empty() ? Eigen::Matrix<double, 9, 9>::Identity() : s.face_rotation[f].matrix();
    const V9 r = (*s.face_weight)[f] * (q[st[0]] - M * q[st[1]]);
    g[st[0]] += r;
    g[st[1]] -= M.transpose() * r;
  }
  Eigen::VectorXd y(x.size());
  for(std::size_t t = 0; t < s.number_of_tets; ++t) {
    if(d(t) == 9) y.segment<9>(Eigen::Index(s.offset[t])) = g[t];
    else if(d(t) > 0) y.segment(Eigen::Index(s.offset[t]), d(t)) = s.Q(t).transpose() * g[t];
  }
  return y;
}

} // namespace

// The multigrid preconditioner of both frame-field solves, on a system with the realignment's
// structure (random matchings on the faces, 6 unknowns on boundary tets, a few tets without any):
// symmetric, positive definite, and the conjugate gradients it preconditions reach the residual
// measured by an independent operator.
TEST(FrameFieldSolvers, MultigridIsSymmetricPositiveDefiniteAndConverges)
{
  const Mesh m = load(example_data + "/cylinder.off", 0.002);
  const auto p = HR::internal::make_frame_field_problem(m, HR::boundary_triangle_unit_normals(m), HR::internal::Face_weighting::AREA_OVER_DISTANCE);
  const HR::internal::Octahedral_group& group = HR::internal::octahedral_group();
  std::srand(7);
  HR::internal::Multigrid_fine_system s;
  s.number_of_tets = p.number_of_tets;
  s.face_tets = &p.face_tets;
  s.face_weight = &p.face_weight;
  s.tet_faces = &p.tet_faces;
  for(std::size_t f = 0; f < p.face_tets.size(); ++f) s.face_rotation.push_back(HR::internal::right_multiplication(group.matrix(std::rand() % 24)));
  s.offset.assign(p.number_of_tets + 1, 0);
  s.embedding.assign(p.number_of_tets, 0);
  std::size_t without = 0, constrained = 0;
  for(std::size_t t = 0; t < p.number_of_tets; ++t) {
    int d = 9;
    if(t % 97 == 5) { d = 0; ++without; }
    else if(p.is_constrained(Index(t))) {
      d = 6;
      ++constrained;
      const Eigen::Matrix<double, 9, 6> Q = Eigen::HouseholderQR<Eigen::Matrix<double, 9, 6> >(Eigen::Matrix<double, 9, 6>::Random()).householderQ() * Eigen::Matrix<double, 9, 6>::Identity();
      s.embedding[t] = s.embeddings.size();
      s.embeddings.insert(s.embeddings.end(), Q.data(), Q.data() + 54);
    }
    s.offset[t + 1] = s.offset[t] + std::size_t(d);
  }
  ASSERT_GT(without, 10u);
  ASSERT_GT(constrained, 100u);
  s.mu = 1e-6;
  const HR::internal::Multigrid_fine_system reference = s;
  s.apply = [&](const Eigen::VectorXd& x, Eigen::VectorXd& y) { y = apply_reference(reference, x); };
  const HR::internal::Aggregation_multigrid M(s, HR::internal::Multigrid_cycle::V);
  EXPECT_GE(M.number_of_levels(), 2u);
  const Eigen::Index n = Eigen::Index(s.offset.back());
  for(int k = 0; k < 5; ++k) {
    const Eigen::VectorXd u = Eigen::VectorXd::Random(n), v = Eigen::VectorXd::Random(n);
    Eigen::VectorXd Mu, Mv;
    M(u, Mu);
    M(v, Mv);
    EXPECT_NEAR(u.dot(Mv), v.dot(Mu), 1e-9 * u.norm() * Mv.norm());
    EXPECT_GT(u.dot(Mu), 0.);
  }
#ifdef _OPENMP
  for(const HR::internal::Multigrid_cycle cycle : {HR::internal::Multigrid_cycle::V, HR::internal::Multigrid_cycle::K}) {
    // parallel loops gather per row: the preconditioner is bitwise the same whatever the thread count
    const Eigen::VectorXd u = Eigen::VectorXd::Random(n);
    const int saved = omp_get_max_threads();
    Eigen::VectorXd one, two;
    omp_set_num_threads(1);
    const HR::internal::Aggregation_multigrid M1(s, cycle);
    M1(u, one);
    omp_set_num_threads(2);
    const HR::internal::Aggregation_multigrid M2(s, cycle);
    M2(u, two);
    omp_set_num_threads(saved);
    EXPECT_TRUE(one == two);
  }
#endif
  const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  int iterations = 0;
  double residual = 1;
  HR::internal::preconditioned_conjugate_gradients(s.apply, M, b, x, 1e-9, 500, iterations, residual);
  EXPECT_LT((b - apply_reference(reference, x)).norm(), 2e-9 * b.norm());
  EXPECT_LT(iterations, 60);
}

// The relaxation preconditioned by the multigrid solves the same system as with Jacobi, and its
// number of iterations hardly grows when the mesh is refined 8 times, where Jacobi's doubles.
TEST(FrameFieldSolvers, MultigridIterationsHardlyGrowWithTheMesh)
{
  std::vector<int> multigrid, jacobi;
  for(double volume : {0.004, 0.0005}) {
    const Mesh m = load(example_data + "/cylinder.off", volume);
    const auto p = HR::internal::make_frame_field_problem(m, HR::boundary_triangle_unit_normals(m), HR::internal::Face_weighting::AREA_OVER_DISTANCE);
    const HR::internal::Frame_field_relaxation relaxation(p);
    int it_mg = 0, it_jacobi = 0;
    double res_mg = 1, res_jacobi = 1;
    const auto q_mg = relaxation.solve(1e-10, 20000, it_mg, res_mg, HR::internal::Frame_field_preconditioner::MULTIGRID);
    const auto q_jacobi = relaxation.solve(1e-10, 20000, it_jacobi, res_jacobi, HR::internal::Frame_field_preconditioner::JACOBI);
    ASSERT_LT(res_mg, 1e-10);
    ASSERT_LT(res_jacobi, 1e-10);
    double diff = 0, norm = 0;
    for(std::size_t t = 0; t < q_mg.size(); ++t) { diff = (std::max)(diff, (q_mg[t] - q_jacobi[t]).norm()); norm = (std::max)(norm, q_jacobi[t].norm()); }
    EXPECT_LT(diff, 1e-6 * norm) << m.number_of_tetrahedra() << " tets";
    multigrid.push_back(it_mg);
    jacobi.push_back(it_jacobi);
  }
  EXPECT_GT(jacobi[1], 3 * jacobi[0] / 2);
  EXPECT_LT(multigrid[1], 3 * jacobi[1] / 10);
  EXPECT_LE(multigrid[1], multigrid[0] + multigrid[0] / 3 + 2);
}

// The relaxation's default K-cycle (with flexible conjugate gradients around it: it is not a fixed
// linear map) solves the same system as the V-cycle in fewer iterations once the multigrid has two
// coarse levels (on a single one both are the same).
TEST(FrameFieldSolvers, KCycleNeedsFewerIterationsThanTheVCycle)
{
  const Mesh m = load(example_data + "/cylinder.off", 0.0005);
  const auto p = HR::internal::make_frame_field_problem(m, HR::boundary_triangle_unit_normals(m), HR::internal::Face_weighting::AREA_OVER_DISTANCE);
  const HR::internal::Frame_field_relaxation relaxation(p);
  int it_v = 0, it_k = 0;
  double res_v = 1, res_k = 1;
  const auto q_v = relaxation.solve(1e-10, 20000, it_v, res_v, HR::internal::Frame_field_preconditioner::MULTIGRID,
                                    HR::internal::Multigrid_cycle::V);
  const auto q_k = relaxation.solve(1e-10, 20000, it_k, res_k, HR::internal::Frame_field_preconditioner::MULTIGRID,
                                    HR::internal::Multigrid_cycle::K);
  ASSERT_LT(res_v, 1e-10);
  ASSERT_LT(res_k, 1e-10);
  double diff = 0, norm = 0;
  for(std::size_t t = 0; t < q_v.size(); ++t) { diff = (std::max)(diff, (q_k[t] - q_v[t]).norm()); norm = (std::max)(norm, q_v[t].norm()); }
  EXPECT_LT(diff, 1e-6 * norm);
  // measured: 44 -> 35 here (about 27k tets); the gain grows with the number of levels (B0, 91k
  // tets: 32 -> 18; a 502k-tet cylinder: 41 -> 20, at the pipeline's tolerance)
  EXPECT_LT(it_k, 9 * it_v / 10) << "V-cycle " << it_v << ", K-cycle " << it_k << " iterations";
}

namespace {

// f(x) = 1/2 x^T A x - b^T x + c sum_i log cosh(x_i - i/n), A = I/100 + a path Laplacian: smooth,
// strictly convex, ill-conditioned, not quadratic unless c = 0.
struct Convex_test_function
{
  Eigen::SparseMatrix<double> A;
  Eigen::VectorXd b;
  double c;
  Convex_test_function(int n, double c_) : A(n, n), b(n), c(c_)
  {
    std::vector<Eigen::Triplet<double> > t;
    for(int i = 0; i < n; ++i) {
      t.emplace_back(i, i, 0.01 + (i > 0) + (i + 1 < n));
      if(i > 0) { t.emplace_back(i, i - 1, -1.0); t.emplace_back(i - 1, i, -1.0); }
      b[i] = std::sin(0.3 * i);
    }
    A.setFromTriplets(t.begin(), t.end());
  }
  double operator()(const Eigen::VectorXd& x, Eigen::VectorXd& g) const
  {
    g = A * x - b;
    double f = 0.5 * x.dot(A * x) - b.dot(x);
    for(Eigen::Index i = 0; i < x.size(); ++i) {
      const double d = x[i] - double(i) / double(x.size());
      f += c * std::log(std::cosh(d));
      g[i] += c * std::tanh(d);
    }
    return f;
  }
};

LBFGSpp::LBFGSParam<double> test_lbfgs_parameters(double epsilon)
{
  LBFGSpp::LBFGSParam<double> param;
  param.m = 7;
  param.epsilon = epsilon;
  param.epsilon_rel = 0;
  param.past = 0;
  param.max_iterations = 2000;
  param.linesearch = LBFGSpp::LBFGS_LINESEARCH_BACKTRACKING_STRONG_WOLFE;
  return param;
}

} // namespace

// With P = I, the recursion is LBFGS++'s own: same iterates up to round-off.
TEST(FrameFieldSolvers, PreconditionedLbfgsWithTheIdentityIsLbfgspp)
{
  Convex_test_function f(300, 1.0);
  // LBFGS++'s line search fails at the limit of the precision, which a smaller epsilon reaches here
  const auto param = test_lbfgs_parameters(1e-6);
  Eigen::VectorXd x_ref = Eigen::VectorXd::Zero(300);
  x_ref[0] = 3;
  Eigen::VectorXd x = x_ref;
  double f_ref = 0, fx = 0;
  LBFGSpp::LBFGSSolver<double, LBFGSpp::LineSearchNocedalWright> solver(param);
  const int it_ref = solver.minimize(f, x_ref, f_ref);
  const int it = HR::internal::preconditioned_lbfgs(f, [](const Eigen::VectorXd& v, Eigen::VectorXd& Pv) { Pv = v; },
                                                    x, fx, param);
  EXPECT_GT(it_ref, 20);
  EXPECT_EQ(it, it_ref);
  EXPECT_LT((x - x_ref).norm(), 1e-8 * x_ref.norm());
  Eigen::VectorXd g;
  f(x, g);
  EXPECT_LT(g.norm(), 1e-6);
}

// With P = A^-1 on a quadratic, the first direction is Newton's: converged in a couple of steps, to
// the solution of A x = b computed by a direct factorization.
TEST(FrameFieldSolvers, PreconditionedLbfgsWithTheInverseHessianTakesNewtonSteps)
{
  Convex_test_function f(400, 0.0);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > ldlt(f.A);
  const Eigen::VectorXd exact = ldlt.solve(f.b);
  const auto param = test_lbfgs_parameters(1e-6);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(400), x_plain = x;
  double fx = 0, f_plain = 0;
  const int it = HR::internal::preconditioned_lbfgs(f, [&](const Eigen::VectorXd& v, Eigen::VectorXd& Pv) { Pv = ldlt.solve(v); },
                                                    x, fx, param);
  LBFGSpp::LBFGSSolver<double, LBFGSpp::LineSearchNocedalWright> solver(param);
  const int it_plain = solver.minimize(f, x_plain, f_plain);
  EXPECT_LE(it, 3);
  EXPECT_GT(it_plain, 10 * it);
  EXPECT_LT((x - exact).norm(), 1e-8 * exact.norm());
}

// Near a smooth field the smoothing energy's Hessian in the smoother's angles is (40/3) times the
// rotation Laplacian that its preconditioner inverts: checked by central differences of the
// gradient on the cube, whose normal-aligned field is constant (energy 0), with constrained and
// free tets.
TEST(FrameFieldSolvers, RotationLaplacianIsTheSmoothingHessianAtASmoothField)
{
  const Mesh m = load(example_data + "/cube.off", 0.01);
  const auto directions = HR::boundary_triangle_unit_normals(m);
  const auto p = HR::internal::make_frame_field_problem(m, directions, HR::internal::Face_weighting::AREA_OVER_DISTANCE);
  std::vector<Eigen::Matrix3d> frames(m.number_of_tetrahedra(), Eigen::Matrix3d::Identity());
  ASSERT_LT(HR::internal::frame_field_energy(p, frames), 1e-20);
  HR::internal::Frame_field_smoother smoother(p, frames);
  const Eigen::Index n = Eigen::Index(smoother.number_of_unknowns());
  std::size_t constrained = 0;
  for(std::size_t t = 0; t < p.number_of_tets; ++t) constrained += p.is_constrained(HR::internal::Frame_field_problem::Index(t));
  ASSERT_GT(constrained, 50u);
  ASSERT_GT(std::size_t(n), constrained + 300);
  Eigen::VectorXd v(n);
  for(Eigen::Index i = 0; i < n; ++i) v[i] = std::sin(0.7 * double(i)) + 0.5 * std::cos(0.05 * double(i));
  const double h = 1e-5;
  Eigen::VectorXd g_plus, g_minus, Lv;
  smoother(h * v, g_plus);
  smoother(-h * v, g_minus);
  const Eigen::VectorXd Hv = (g_plus - g_minus) / (2 * h);
  smoother.apply_rotation_laplacian(v, Lv);
  // Lv includes mu v, mu = 1e-8: far below the differences' error
  EXPECT_LT((Hv - (40.0 / 3.0) * Lv).norm(), 1e-5 * Hv.norm());
}

// The solvers' vector operations: Eigen's own below parallel_vector_minimum entries (small meshes
// keep their results), above it sums of fixed blocks in block order, so bitwise the same with 1 and
// 2 threads, and within rounding of the sequential sums (a compensated sum is the reference).
TEST(FrameFieldSolvers, ParallelVectorOperationsAreDeterministic)
{
  namespace I = HR::internal;
  auto reference_dot = [](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    long double s = 0;
    for(Eigen::Index i = 0; i < a.size(); ++i) s += (long double)a[i] * (long double)b[i];
    return double(s);
  };
  for(const Eigen::Index n : {Eigen::Index(1000), I::parallel_vector_minimum - 1, I::parallel_vector_minimum,
                              2 * I::parallel_vector_minimum + 12345}) {
    const Eigen::VectorXd u = Eigen::VectorXd::Random(n), v = Eigen::VectorXd::Random(n), w = Eigen::VectorXd::Random(n);
    std::vector<double> one, two;
    double sum_one = 0, sum_two = 0;
    Eigen::VectorXd x_one = u, x_two = u;
    for(int threads : {1, 2}) {
#ifdef _OPENMP
      const int saved = omp_get_max_threads();
      omp_set_num_threads(threads);
#endif
      std::vector<double>& d = threads == 1 ? one : two;
      I::parallel_dots(u, {&v, &w, &u}, d);
      Eigen::VectorXd& x = threads == 1 ? x_one : x_two;
      (threads == 1 ? sum_one : sum_two) = I::parallel_segment_sum(n, [&](Eigen::Index b, Eigen::Index size) {
        x.segment(b, size) += 0.5 * v.segment(b, size);
        return x.segment(b, size).squaredNorm();
      });
#ifdef _OPENMP
      omp_set_num_threads(saved);
#endif
    }
    ASSERT_EQ(one.size(), 3u);
    EXPECT_TRUE(one == two) << n;
    EXPECT_EQ(sum_one, sum_two) << n;
    EXPECT_TRUE(x_one == x_two) << n;
    const Eigen::VectorXd x = u + 0.5 * v;
    EXPECT_TRUE(x_one == x) << n; // an elementwise update is the same however it is split
    EXPECT_NEAR(one[0], reference_dot(u, v), 1e-12 * double(n));
    EXPECT_NEAR(one[1], reference_dot(u, w), 1e-12 * double(n));
    EXPECT_NEAR(one[2], reference_dot(u, u), 1e-12 * double(n));
    EXPECT_NEAR(sum_one, reference_dot(x, x), 1e-12 * double(n));
    if(!I::use_parallel_vector_operations(n)) {
      EXPECT_EQ(one[0], u.dot(v)) << n; // Eigen's own
      EXPECT_EQ(sum_one, x.squaredNorm()) << n;
    }
  }
}

// The smoothing preconditioned by the multigrid reaches a field as smooth as plain L-BFGS (both are
// local minima of a non-convex energy) in fewer iterations, bitwise the same with 1 and 2 threads.
TEST(FrameFieldSolvers, PreconditionedSmoothingNeedsFewerIterations)
{
  const Mesh m = load(example_data + "/cylinder.off", 0.0005);
  const auto directions = HR::boundary_triangle_unit_normals(m);
  const auto p = HR::internal::make_frame_field_problem(m, directions, HR::internal::Face_weighting::AREA_OVER_DISTANCE);
  int it0 = 0;
  double res0 = 0;
  const HR::internal::Frame_field_relaxation relaxation(p);
  const std::vector<Eigen::Matrix3d> initial = relaxation.project(relaxation.solve(1e-6, 20000, it0, res0));
  const double initial_energy = HR::internal::frame_field_energy(p, initial);
  auto smooth = [&](HR::internal::Frame_field_preconditioner pre, int threads, int& iterations, std::vector<Eigen::Matrix3d>& frames) {
#ifdef _OPENMP
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
#else
    (void)threads;
#endif
    frames = initial;
    HR::internal::Frame_field_smoother smoother(p, frames);
    const double e = smoother.minimize(2000, 1e-7, nullptr, iterations, pre);
#ifdef _OPENMP
    omp_set_num_threads(saved);
#endif
    return e;
  };
  std::vector<Eigen::Matrix3d> plain, preconditioned, preconditioned_1;
  int it_plain = 0, it_pre = 0, it_pre_1 = 0;
  const double e_plain = smooth(HR::internal::Frame_field_preconditioner::JACOBI, 2, it_plain, plain);
  const double e_pre = smooth(HR::internal::Frame_field_preconditioner::MULTIGRID, 2, it_pre, preconditioned);
  const double e_pre_1 = smooth(HR::internal::Frame_field_preconditioner::MULTIGRID, 1, it_pre_1, preconditioned_1);
  std::cout << m.number_of_tetrahedra() << " tets: energy " << initial_energy << " -> plain " << e_plain << " ("
            << it_plain << " iterations), preconditioned " << e_pre << " (" << it_pre << ")\n";
  // the energies are those of the returned frames
  EXPECT_NEAR(HR::internal::frame_field_energy(p, preconditioned), e_pre, 1e-9 * e_pre);
  EXPECT_LT(e_pre, 0.7 * initial_energy);
  EXPECT_LT(e_pre, 1.002 * e_plain);
  // 221 -> 120 measured; the gain grows with the mesh (B0, 91k tets: 101 -> 55; 502k: 226 -> 75)
  EXPECT_LT(3 * it_pre, 2 * it_plain);
  EXPECT_EQ(it_pre_1, it_pre);
  EXPECT_EQ(e_pre_1, e_pre);
  for(std::size_t t = 0; t < preconditioned.size(); ++t) ASSERT_EQ(preconditioned[t], preconditioned_1[t]) << t;
}

// The Hilbert order of the tets is a permutation that brings the face neighbours closer in memory,
// and a problem in that order is the same problem: same energy for the same frames, same solution.
TEST(FrameFieldSolvers, LocalOrderIsTheSameProblem)
{
  const Mesh m = load(example_data + "/cylinder.off", 0.004);
  const auto directions = HR::boundary_triangle_unit_normals(m);
  const std::vector<std::uint32_t> order = HR::internal::hilbert_order(m);
  ASSERT_EQ(order.size(), m.number_of_tetrahedra());
  std::vector<std::uint32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for(std::size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);
  const auto p = HR::internal::make_frame_field_problem(m, directions, HR::internal::Face_weighting::AREA_OVER_DISTANCE);
  const auto q = HR::internal::make_frame_field_problem(m, directions, HR::internal::Face_weighting::AREA_OVER_DISTANCE, {}, order);
  ASSERT_EQ(q.mesh_tet, order);
  ASSERT_EQ(p.face_tets.size(), q.face_tets.size());
  auto mean_gap = [](const HR::internal::Frame_field_problem& r) {
    double sum = 0;
    for(const auto& ft : r.face_tets) sum += std::abs(double(ft[0]) - double(ft[1]));
    return sum / double(r.face_tets.size());
  };
  std::cout << "mean index gap of face neighbours: mesh order " << mean_gap(p) << ", Hilbert order " << mean_gap(q) << "\n";
  EXPECT_LT(mean_gap(q), mean_gap(p) / 2);
  // the same frames, permuted, have the same energy
  std::vector<Eigen::Matrix3d> frames(m.number_of_tetrahedra()), permuted(m.number_of_tetrahedra());
  for(std::size_t t = 0; t < frames.size(); ++t)
    frames[t] = Eigen::AngleAxisd(0.001 * double(t % 997), Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  for(std::size_t i = 0; i < frames.size(); ++i) permuted[i] = frames[order[i]];
  const double e = HR::internal::frame_field_energy(p, frames);
  EXPECT_GT(e, 1.0);
  EXPECT_NEAR(HR::internal::frame_field_energy(q, permuted), e, 1e-12 * e);
  // constraints follow their tets
  for(std::size_t i = 0; i < frames.size(); ++i) {
    ASSERT_EQ(q.is_constrained(std::uint32_t(i)), p.is_constrained(order[i]));
    if(q.is_constrained(std::uint32_t(i))) ASSERT_EQ(q.direction(std::uint32_t(i)), p.direction(order[i]));
  }
  // the relaxation solves the same system
  int it_p = 0, it_q = 0;
  double res_p = 1, res_q = 1;
  const auto x_p = HR::internal::Frame_field_relaxation(p).solve(1e-10, 20000, it_p, res_p);
  const auto x_q = HR::internal::Frame_field_relaxation(q).solve(1e-10, 20000, it_q, res_q);
  double diff = 0, norm = 0;
  for(std::size_t i = 0; i < x_q.size(); ++i) {
    diff = (std::max)(diff, (x_q[i] - x_p[order[i]]).norm());
    norm = (std::max)(norm, x_p[order[i]].norm());
  }
  EXPECT_LT(diff, 1e-6 * norm);
  // fixed frames follow their tets
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.3, Eigen::Vector3d(0, 1, 1).normalized()).toRotationMatrix();
  std::size_t interior = 0;
  while(p.is_constrained(std::uint32_t(interior))) ++interior;
  const auto f = HR::internal::make_frame_field_problem(m, directions, HR::internal::Face_weighting::AREA_OVER_DISTANCE,
                                                        {{interior, R}}, order);
  for(std::size_t i = 0; i < order.size(); ++i) {
    ASSERT_EQ(f.is_fixed(std::uint32_t(i)), order[i] == interior);
    if(order[i] == interior) EXPECT_EQ(f.frame(std::uint32_t(i)), R);
  }
  // bad orders
  std::vector<std::uint32_t> bad = order;
  bad[0] = bad[1];
  EXPECT_THROW(HR::internal::make_frame_field_problem(m, directions, HR::internal::Face_weighting::AREA_OVER_DISTANCE, {}, bad), HR::Error);
  bad.pop_back();
  EXPECT_THROW(HR::internal::make_frame_field_problem(m, directions, HR::internal::Face_weighting::AREA_OVER_DISTANCE, {}, bad), HR::Error);
}

// Above 30,000 tets compute_frame_field() solves in the Hilbert order and returns the frames in the
// mesh's: every boundary tet keeps an axis on its own direction, and the reported energy is that of
// the returned frames, evaluated on the mesh's order.
TEST(FrameField, FramesComeBackInTheMeshOrder)
{
  const Mesh m = load(example_data + "/cylinder.off", 0.0004);
  ASSERT_GE(m.number_of_tetrahedra(), HR::internal::multigrid_minimum_tets);
  const auto directions = HR::boundary_triangle_unit_normals(m);
  std::vector<Eigen::Matrix3d> frames;
  const HR::Frame_field_result r = HR::compute_frame_field(m, directions, frames);
  ASSERT_EQ(frames.size(), m.number_of_tetrahedra());
  for(Index b = 0; b < m.number_of_boundary_triangles(); ++b) {
    const Eigen::Vector3d c = frames[m.boundary_triangle_tetrahedron(b)].transpose() * directions[b];
    ASSERT_NEAR(c.cwiseAbs().maxCoeff(), 1.0, 1e-9) << b;
  }
  const auto p = HR::internal::make_frame_field_problem(m, directions, HR::internal::Face_weighting::AREA_OVER_DISTANCE);
  EXPECT_NEAR(HR::internal::frame_field_energy(p, frames), r.energy, 1e-9 * r.energy);
  EXPECT_LT(r.energy, r.initial_energy);
}

// The boundary propagation (frame_field_initialization): the boundary tets keep the relaxation's frames
// exactly, and every other tet gets a copy of the frame of a nearby boundary tet. On the cylinder (radius 1, height
// 2), every tet nearer the side than the caps (and not near the axis) gets a frame with an axis within 20
// degrees of its radial direction (the side has 32 facets, 11.25 degrees apart): checked
// from the geometry of the cylinder, not from the propagation's own distances.
TEST(FrameField, BoundaryPropagationCarriesTheNearestBoundaryFrameInwards)
{
  namespace HP = HR::parameters;
  const Mesh m = load(example_data + "/cylinder.off", 0.004);
  const auto normals = HR::boundary_triangle_unit_normals(m);
  std::vector<Eigen::Matrix3d> relaxed, propagated;
  const HR::Frame_field_result rr = HR::compute_frame_field(
    m, normals, relaxed, HP::frame_field_initialization(HR::Frame_field_initialization::RELAXATION, HP::smoothing(false)));
  const HR::Frame_field_result rp = HR::compute_frame_field(
    m, normals, propagated, HP::frame_field_initialization(HR::Frame_field_initialization::BOUNDARY_PROPAGATION, HP::smoothing(false)));
  EXPECT_EQ(rr.initialization, HR::Frame_field_initialization::RELAXATION);
  EXPECT_EQ(rp.initialization, HR::Frame_field_initialization::BOUNDARY_PROPAGATION);
  std::vector<bool> on_boundary(m.number_of_tetrahedra(), false);
  for(Index b = 0; b < m.number_of_boundary_triangles(); ++b) on_boundary[m.boundary_triangle_tetrahedron(b)] = true;
  std::set<std::array<double, 9> > boundary_frames;
  auto key = [](const Eigen::Matrix3d& f) {
    std::array<double, 9> k;
    std::copy(f.data(), f.data() + 9, k.begin());
    return k;
  };
  for(Index t = 0; t < m.number_of_tetrahedra(); ++t)
    if(on_boundary[t]) boundary_frames.insert(key(relaxed[t]));
  std::size_t side = 0, radial = 0;
  for(Index t = 0; t < m.number_of_tetrahedra(); ++t) {
    if(on_boundary[t]) {
      ASSERT_TRUE(propagated[t] == relaxed[t]) << "boundary tetrahedron " << t;
      continue;
    }
    // a copy of a boundary tet's frame
    ASSERT_EQ(boundary_frames.count(key(propagated[t])), 1u) << "tetrahedron " << t;
    const Eigen::Vector3d c = centroid(m, t);
    const double rho = std::hypot(c.x(), c.y());
    // near the axis the paths along the adjacency from sides 30 degrees apart differ too little
    if(rho < 0.5 || 1 - rho > std::min(c.z(), 2 - c.z()) - 0.25) continue;
    ++side;
    const Eigen::Vector3d r(c.x() / rho, c.y() / rho, 0);
    if((propagated[t].transpose() * r).cwiseAbs().maxCoeff() > std::cos(CGAL_PI / 9)) ++radial;
  }
  ASSERT_GT(side, 50u);
  EXPECT_EQ(radial, side);
  // the smoothing starts from it and lowers its energy
  std::vector<Eigen::Matrix3d> smoothed;
  const HR::Frame_field_result rs = HR::compute_frame_field(
    m, normals, smoothed, HP::frame_field_initialization(HR::Frame_field_initialization::BOUNDARY_PROPAGATION));
  EXPECT_DOUBLE_EQ(rs.initial_energy, rp.initial_energy);
  EXPECT_LT(rs.energy, rs.initial_energy);
  for(Index b = 0; b < m.number_of_boundary_triangles(); ++b)
    ASSERT_NEAR((smoothed[m.boundary_triangle_tetrahedron(b)].transpose() * normals[b]).cwiseAbs().maxCoeff(), 1.0, 1e-9);
}
