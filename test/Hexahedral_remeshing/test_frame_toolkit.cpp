// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers

// Frame toolkit: octahedral group, L4 spherical harmonics, projection onto frames (design 0, 1, 2.2).
// Every identity is checked against an independent computation (3x3 rotations, Eigen's unsupported
// matrix exponential, brute force over the group), never against stored numbers.

#include <CGAL/Hexahedral_remeshing/internal/frame_projection.h>
#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>
#include <CGAL/Hexahedral_remeshing/internal/spherical_harmonics.h>

#include <Eigen/Geometry>
#include <unsupported/Eigen/MatrixFunctions>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <vector>

namespace HR = CGAL::Hexahedral_remeshing::internal;
using HR::Matrix9;
using HR::Vector9;

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double identity_tol = 1e-12; // closed-form identities
constexpr double iterative_tol = 1e-9; // results of iterations

Eigen::Matrix3d rot(double t, const Eigen::Vector3d& axis)
{
  return Eigen::AngleAxisd(t, axis.normalized()).toRotationMatrix();
}

// Uniform random rotation (normalized Gaussian quaternion), fixed seed for reproducibility.
Eigen::Matrix3d random_rotation(std::mt19937& rng)
{
  std::normal_distribution<double> n(0., 1.);
  Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  q.normalize();
  return q.toRotationMatrix();
}

Eigen::Vector3d random_unit_vector(std::mt19937& rng)
{
  std::normal_distribution<double> n(0., 1.);
  return Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
}

double max_abs(const Eigen::MatrixXd& M) { return M.cwiseAbs().maxCoeff(); }

// Rotations where the ZYZ decomposition degenerates (sin beta = 0 or ~0), plus group elements.
std::vector<Eigen::Matrix3d> special_rotations()
{
  std::vector<Eigen::Matrix3d> R;
  R.push_back(Eigen::Matrix3d::Identity());
  R.push_back(rot(0.7, Eigen::Vector3d::UnitZ()));
  R.push_back(rot(pi, Eigen::Vector3d::UnitX()));
  R.push_back(rot(pi, Eigen::Vector3d::UnitY()) * rot(-1.3, Eigen::Vector3d::UnitZ()));
  R.push_back(rot(1e-9, Eigen::Vector3d::UnitY()) * rot(0.4, Eigen::Vector3d::UnitZ()));
  R.push_back(rot(pi - 1e-9, Eigen::Vector3d(1., 2., 0.)));
  R.push_back(rot(1e-13, Eigen::Vector3d(3., -1., 0.)));
  for(int g = 0; g < 24; ++g)
    R.push_back(HR::octahedral_group().matrix(g));
  return R;
}

Eigen::Matrix3d generator_3d(int axis)
{
  Eigen::Matrix3d K = Eigen::Matrix3d::Zero();
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  K(j, i) = 1.;
  K(i, j) = -1.;
  return K;
}

const Matrix9& sh_generator(int axis)
{
  return axis == 0 ? HR::sh_generator_x() : axis == 1 ? HR::sh_generator_y() : HR::sh_generator_z();
}

} // namespace

// ---------------------------------------------------------------- octahedral group

TEST(OctahedralGroup, ElementsAreTheTwentyFourRotationsOfTheCube)
{
  const HR::Octahedral_group& G = HR::octahedral_group();
  EXPECT_TRUE(G.matrix(0).isIdentity(0.));
  for(int g = 0; g < 24; ++g) {
    const Eigen::Matrix3d& M = G.matrix(g);
    EXPECT_EQ(M.determinant(), 1.) << g;
    EXPECT_TRUE((M.transpose() * M).isIdentity(0.)) << g;
    for(int c = 0; c < 3; ++c)
      EXPECT_EQ(M.col(c).cwiseAbs().sum(), 1.) << g; // one +-1 per column: a signed permutation
    for(int h = 0; h < g; ++h)
      EXPECT_FALSE(M == G.matrix(h)) << g << " duplicates " << h;
  }
  // Completeness: of the 48 signed permutation matrices, exactly the det +1 ones are found.
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  int found = 0;
  for(const auto& p : perms)
    for(int s = 0; s < 8; ++s) {
      Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
      for(int r = 0; r < 3; ++r)
        M(r, p[r]) = (s >> r & 1) ? -1. : 1.;
      const int g = G.index_of(M);
      if(M.determinant() > 0) {
        ASSERT_GE(g, 0);
        EXPECT_TRUE(G.matrix(g) == M);
        ++found;
      } else {
        EXPECT_EQ(g, -1) << "reflection accepted";
      }
    }
  EXPECT_EQ(found, 24);
}

TEST(OctahedralGroup, TablesMatchMatrixProducts)
{
  const HR::Octahedral_group& G = HR::octahedral_group();
  for(int a = 0; a < 24; ++a) {
    EXPECT_EQ(G.index_of(G.matrix(a)), a);
    const int ia = G.inverse(a);
    EXPECT_TRUE(G.matrix(ia) == G.matrix(a).transpose()) << a;
    EXPECT_EQ(G.multiply(a, ia), 0);
    EXPECT_EQ(G.multiply(ia, a), 0);
    EXPECT_EQ(G.multiply(a, 0), a);
    EXPECT_EQ(G.multiply(0, a), a);
    std::set<int> row;
    for(int b = 0; b < 24; ++b) {
      EXPECT_TRUE(G.matrix(G.multiply(a, b)) == G.matrix(a) * G.matrix(b)) << a << " " << b;
      row.insert(G.multiply(a, b));
      for(int c = 0; c < 24; ++c)
        EXPECT_EQ(G.multiply(G.multiply(a, b), c), G.multiply(a, G.multiply(b, c)));
    }
    EXPECT_EQ(row.size(), 24u) << "row " << a << " of the table is not a permutation";
  }
}

TEST(OctahedralGroup, IndexOfToleratesNoiseAndRejectsOtherMatrices)
{
  const HR::Octahedral_group& G = HR::octahedral_group();
  std::mt19937 rng(7);
  for(int g = 0; g < 24; ++g) {
    const Eigen::Matrix3d noisy = rot(1e-8, random_unit_vector(rng)) * G.matrix(g);
    EXPECT_EQ(G.index_of(noisy), g);
    EXPECT_EQ(G.index_of(rot(0.3, random_unit_vector(rng)) * G.matrix(g)), -1);
  }
}

TEST(OctahedralGroup, AngleAxisClassification)
{
  const HR::Octahedral_group& G = HR::octahedral_group();
  int count[4] = {0, 0, 0, 0};
  for(int g = 0; g < 24; ++g) {
    const double angle = G.angle(g);
    const Eigen::Vector3d& axis = G.axis(g);
    const HR::Octahedral_rotation_class cls = G.rotation_class(g);
    ++count[static_cast<int>(cls)];
    if(cls == HR::Octahedral_rotation_class::IDENTITY) {
      EXPECT_EQ(g, 0);
      EXPECT_EQ(angle, 0.);
      continue;
    }
    EXPECT_NEAR(axis.norm(), 1., identity_tol);
    EXPECT_LT(max_abs(rot(angle, axis) - G.matrix(g)), identity_tol) << g;
    // Angle and class agree, and axes are of the expected kind (coordinate axis / diagonals).
    const Eigen::Vector3d a = axis.cwiseAbs();
    const int nonzero = (a.array() > 0.5 / std::sqrt(3.)).count();
    switch(cls) {
    case HR::Octahedral_rotation_class::QUARTER_TURN:
      EXPECT_NEAR(angle, pi / 2, identity_tol);
      EXPECT_EQ(nonzero, 1);
      break;
    case HR::Octahedral_rotation_class::THIRD_TURN:
      EXPECT_NEAR(angle, 2 * pi / 3, identity_tol);
      EXPECT_EQ(nonzero, 3);
      break;
    case HR::Octahedral_rotation_class::HALF_TURN:
      EXPECT_NEAR(angle, pi, identity_tol);
      EXPECT_TRUE(nonzero == 1 || nonzero == 2);
      // Canonical sign of a half-turn axis: first non-zero coordinate positive.
      EXPECT_GT(axis[0] != 0. ? axis[0] : axis[1] != 0. ? axis[1] : axis[2], 0.);
      break;
    default:
      break;
    }
  }
  EXPECT_EQ(count[0], 1); // identity
  EXPECT_EQ(count[1], 6); // +-90 about 3 axes
  EXPECT_EQ(count[2], 9); // 180 about 3 axes + 6 face diagonals
  EXPECT_EQ(count[3], 8); // +-120 about 4 cube diagonals
}

TEST(OctahedralGroup, ClosestMatchingRecoversKnownElement)
{
  const HR::Octahedral_group& G = HR::octahedral_group();
  std::mt19937 rng(11);
  for(int trial = 0; trial < 20; ++trial) {
    const Eigen::Matrix3d Ei = random_rotation(rng);
    for(int g = 0; g < 24; ++g) {
      // E_i = E_j g exactly: trace 3.
      const Eigen::Matrix3d Ej = Ei * G.matrix(g).transpose();
      const HR::Octahedral_matching exact = HR::closest_matching(Ei, Ej);
      EXPECT_EQ(exact.index, g);
      EXPECT_NEAR(exact.trace, 3., identity_tol);
      // Perturbed by up to 30 degrees (< 45: the coset is still unambiguous).
      const double angle = std::uniform_real_distribution<double>(0.01, 0.52)(rng);
      const Eigen::Matrix3d Ej_noisy = rot(angle, random_unit_vector(rng)) * Ej;
      const HR::Octahedral_matching m = HR::closest_matching(Ei, Ej_noisy);
      EXPECT_EQ(m.index, g);
      EXPECT_NEAR(m.trace, 1. + 2. * std::cos(angle), identity_tol);
      // g_ji = g_ij^{-1}.
      EXPECT_EQ(HR::closest_matching(Ej_noisy, Ei).index, G.inverse(g));
    }
  }
}

TEST(OctahedralGroup, ClosestMatchingIsTheBruteForceArgmax)
{
  const HR::Octahedral_group& G = HR::octahedral_group();
  std::mt19937 rng(13);
  for(int trial = 0; trial < 200; ++trial) {
    const Eigen::Matrix3d Ei = random_rotation(rng), Ej = random_rotation(rng);
    const HR::Octahedral_matching m = HR::closest_matching(Ei, Ej);
    double best = std::numeric_limits<double>::infinity();
    for(int g = 0; g < 24; ++g)
      best = std::min(best, (Ei - Ej * G.matrix(g)).squaredNorm());
    EXPECT_NEAR((Ei - Ej * G.matrix(m.index)).squaredNorm(), best, identity_tol);
    EXPECT_NEAR(m.trace, 3. - 0.5 * (Ei - Ej * G.matrix(m.index)).squaredNorm(), identity_tol);
  }
}

// ---------------------------------------------------------------- spherical harmonics

TEST(SphericalHarmonics, IdentityFrameIsReference)
{
  const Vector9 q_ref = HR::reference_sh_frame();
  EXPECT_NEAR(q_ref.norm(), 1., identity_tol);
  EXPECT_NEAR(q_ref[4], std::sqrt(7. / 12.), identity_tol);
  EXPECT_NEAR(q_ref[8], std::sqrt(5. / 12.), identity_tol);
  EXPECT_LT(max_abs(HR::frame_to_sh(Eigen::Matrix3d::Identity()) - q_ref), identity_tol);
}

TEST(SphericalHarmonics, UnnormalizedSumHasConstantNorm)
{
  // |q(E)| = 1 is enforced by the normalization; the real content is that |sum_i Y(E e_i)| does not depend
  // on E (a rotation acts orthogonally on band 4), so the normalization never distorts the field.
  auto raw = [](const Eigen::Matrix3d& E) {
    return Vector9(HR::sh_basis(E.col(0)) + HR::sh_basis(E.col(1)) + HR::sh_basis(E.col(2)));
  };
  const double n0 = raw(Eigen::Matrix3d::Identity()).norm();
  std::mt19937 rng(17);
  for(int i = 0; i < 200; ++i) {
    const Eigen::Matrix3d E = random_rotation(rng);
    EXPECT_NEAR(raw(E).norm(), n0, identity_tol);
    EXPECT_NEAR(HR::frame_to_sh(E).norm(), 1., identity_tol);
  }
}

TEST(SphericalHarmonics, GeneratorsAreTheLieAlgebraOfTheRotationAction)
{
  // Antisymmetric, same commutators as so(3) ([Lx, Ly] = Lz, ...), and exp(t L_axis) q(E) = q(Rot_axis(t) E).
  for(int a = 0; a < 3; ++a) {
    const Matrix9& L = sh_generator(a);
    EXPECT_LT(max_abs(L + L.transpose()), identity_tol);
    const Matrix9 commutator = sh_generator(a) * sh_generator((a + 1) % 3) - sh_generator((a + 1) % 3) * sh_generator(a);
    EXPECT_LT(max_abs(commutator - sh_generator((a + 2) % 3)), identity_tol) << a;
    // Same bracket for the 3x3 generators, to make sure the conventions agree.
    const Eigen::Matrix3d c3 = generator_3d(a) * generator_3d((a + 1) % 3) - generator_3d((a + 1) % 3) * generator_3d(a);
    EXPECT_LT(max_abs(c3 - generator_3d((a + 2) % 3)), identity_tol);
  }
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> angle(-pi, pi);
  for(int i = 0; i < 50; ++i) {
    const Eigen::Matrix3d E = random_rotation(rng);
    for(int a = 0; a < 3; ++a) {
      const double t = angle(rng);
      const Matrix9 D = (t * sh_generator(a)).exp();
      const Eigen::Matrix3d R = rot(t, Eigen::Vector3d::Unit(a));
      EXPECT_LT(max_abs(D * HR::frame_to_sh(E) - HR::frame_to_sh(R * E)), identity_tol) << "axis " << a;
    }
  }
}

TEST(SphericalHarmonics, TangentGramMatrixIsConstant)
{
  // The projection's Gauss-Newton step relies on J^T J = (20/3) I, J = [Lx a, Ly a, Lz a], a = q(E), for
  // every frame E.  Also |q(R) - q(S)|^2 ~ (20/3) angle^2 for nearby frames (consistent with 1.3).
  std::mt19937 rng(61);
  for(int i = 0; i < 100; ++i) {
    const Vector9 a = HR::frame_to_sh(random_rotation(rng));
    Eigen::Matrix<double, 9, 3> J;
    for(int k = 0; k < 3; ++k)
      J.col(k) = sh_generator(k) * a;
    EXPECT_LT(max_abs(J.transpose() * J - (20. / 3.) * Eigen::Matrix3d::Identity()), identity_tol) << i;
  }
}

TEST(SphericalHarmonics, ClosedFormDzIsExpOfLz)
{
  for(double t : {0., 0.1, -0.7, 1.3, pi / 4, pi / 2, 2.9, -5.5, 17.}) {
    const Matrix9 reference = (t * HR::sh_generator_z()).exp();
    EXPECT_LT(max_abs(HR::sh_rotation_z(t) - reference), identity_tol) << t;
  }
}

TEST(SphericalHarmonics, DxHalfPiMatchesExponentialAndRotation)
{
  const Matrix9 reference = ((pi / 2) * HR::sh_generator_x()).exp();
  EXPECT_LT(max_abs(HR::sh_rotation_x_half_pi() - reference), identity_tol);
  std::mt19937 rng(23);
  for(int i = 0; i < 50; ++i) {
    const Eigen::Matrix3d E = random_rotation(rng);
    const Eigen::Matrix3d Rx = rot(pi / 2, Eigen::Vector3d::UnitX());
    EXPECT_LT(max_abs(HR::sh_rotation_x_half_pi() * HR::frame_to_sh(E) - HR::frame_to_sh(Rx * E)), identity_tol);
  }
}

TEST(SphericalHarmonics, RotationMatrixIsOrthogonalHomomorphismAndActsOnFrames)
{
  std::mt19937 rng(29);
  std::vector<Eigen::Matrix3d> rotations = special_rotations();
  for(int i = 0; i < 100; ++i)
    rotations.push_back(random_rotation(rng));

  for(std::size_t i = 0; i < rotations.size(); ++i) {
    const Eigen::Matrix3d& R1 = rotations[i];
    const Eigen::Matrix3d& R2 = rotations[(i * 7 + 3) % rotations.size()];
    const Matrix9 D1 = HR::sh_rotation(R1);
    EXPECT_LT(max_abs(D1.transpose() * D1 - Matrix9::Identity()), identity_tol) << i;
    EXPECT_LT(max_abs(HR::sh_rotation(R1 * R2) - D1 * HR::sh_rotation(R2)), identity_tol) << i;
    const Eigen::Matrix3d E = random_rotation(rng);
    EXPECT_LT(max_abs(D1 * HR::frame_to_sh(E) - HR::frame_to_sh(R1 * E)), identity_tol) << i;
  }
  // Consistent with the generators: D(Rot_axis(t)) = exp(t L_axis).
  for(int a = 0; a < 3; ++a)
    for(double t : {0.3, -2.1}) {
      const Matrix9 reference = (t * sh_generator(a)).exp();
      EXPECT_LT(max_abs(HR::sh_rotation(rot(t, Eigen::Vector3d::Unit(a))) - reference), identity_tol);
    }
}

TEST(SphericalHarmonics, EnergyIdentity)
{
  // <q(R), q(S)> = (5 sigma - 9) / 6 with sigma = sum P_ab^4, P = R^T S.
  std::mt19937 rng(31);
  for(int i = 0; i < 500; ++i) {
    const Eigen::Matrix3d R = random_rotation(rng);
    // Mix far pairs and close pairs (the regime of a smooth field).
    const Eigen::Matrix3d S = (i % 2 == 0) ? random_rotation(rng) : Eigen::Matrix3d(rot(0.05 * i / 500., random_unit_vector(rng)) * R);
    const Eigen::Matrix3d P = R.transpose() * S;
    const double sigma = P.array().pow(4).sum();
    const Vector9 qR = HR::frame_to_sh(R), qS = HR::frame_to_sh(S);
    EXPECT_NEAR(qR.dot(qS), (5. * sigma - 9.) / 6., identity_tol);
    EXPECT_NEAR((qR - qS).squaredNorm(), (5. / 3.) * (3. - sigma), identity_tol);
  }
}

TEST(SphericalHarmonics, InvariantUnderTheOctahedralGroup)
{
  const HR::Octahedral_group& G = HR::octahedral_group();
  std::mt19937 rng(37);
  for(int i = 0; i < 20; ++i) {
    const Eigen::Matrix3d E = random_rotation(rng);
    const Vector9 q = HR::frame_to_sh(E);
    for(int g = 0; g < 24; ++g)
      EXPECT_LT(max_abs(HR::frame_to_sh(E * G.matrix(g)) - q), identity_tol) << g;
  }
  // D(g) fixes q_ref (the same statement through the 9x9 action).
  for(int g = 0; g < 24; ++g)
    EXPECT_LT(max_abs(HR::sh_rotation(G.matrix(g)) * HR::reference_sh_frame() - HR::reference_sh_frame()), identity_tol);
  // ... and a generic rotation does not (so the check above is not vacuous).
  EXPECT_GT(max_abs(HR::frame_to_sh(rot(0.2, Eigen::Vector3d(1., 2., 3.))) - HR::reference_sh_frame()), 0.1);
}

// ---------------------------------------------------------------- frames with an axis along v

TEST(FrameFamily, MinimalRotationMapsEzToV)
{
  std::mt19937 rng(41);
  std::vector<Eigen::Vector3d> directions = {Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ(),
                                             Eigen::Vector3d(1e-12, 0., -1.), Eigen::Vector3d(0., 1e-9, -1.),
                                             Eigen::Vector3d::UnitX(), Eigen::Vector3d(0., std::sqrt(3.), -1.), // v.z = -1/2
                                             Eigen::Vector3d(2., -3., 0.5)};
  for(int i = 0; i < 100; ++i)
    directions.push_back(random_unit_vector(rng));
  for(const Eigen::Vector3d& v : directions) {
    const Eigen::Matrix3d R = HR::minimal_rotation_to(v);
    EXPECT_LT(max_abs(R.transpose() * R - Eigen::Matrix3d::Identity()), identity_tol);
    EXPECT_NEAR(R.determinant(), 1., identity_tol);
    EXPECT_LT(max_abs(R.col(2) - v.normalized()), identity_tol) << v.transpose();
    // Minimal rotation (axis e_z x v, no z component) whenever its formula is used: R - R^T = 2 sin(t) [axis]_x.
    if(v.normalized().z() >= -0.5) {
      EXPECT_LT(std::abs((R - R.transpose())(0, 1)), identity_tol);
    }
  }
}

TEST(FrameFamily, EveryPointOfTheCircleIsAFrameWithAnAxisOnV)
{
  std::mt19937 rng(43);
  std::vector<Eigen::Vector3d> directions = {Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ(),
                                             Eigen::Vector3d(1e-10, -2e-10, -1.), Eigen::Vector3d::UnitY()};
  for(int i = 0; i < 30; ++i)
    directions.push_back(random_unit_vector(rng));
  const HR::Octahedral_group& G = HR::octahedral_group();
  for(const Eigen::Vector3d& v : directions) {
    const HR::Sh_frame_family family = HR::sh_frame_family(v);
    // Orthonormal basis orthogonal to the offset (so (a, b) are plain coordinates on a disc).
    EXPECT_LT(max_abs(family.basis.transpose() * family.basis - Eigen::Matrix2d::Identity()), identity_tol);
    EXPECT_LT(max_abs(family.basis.transpose() * family.offset), identity_tol);
    EXPECT_NEAR(family.offset.norm(), std::sqrt(7. / 12.), identity_tol);
    for(int k = 0; k < 64; ++k) {
      const double phi = 2. * pi * (k + 0.37) / 64.;
      const double r = 0.3 + 0.1 * k; // the radius must not matter
      const double a = r * std::sin(phi), b = r * std::cos(phi);
      const Eigen::Matrix3d E = HR::frame_from_family(v, a, b);
      EXPECT_LT(max_abs(E.transpose() * E - Eigen::Matrix3d::Identity()), identity_tol);
      EXPECT_NEAR(E.determinant(), 1., identity_tol);
      EXPECT_NEAR((E.transpose() * v.normalized()).cwiseAbs().maxCoeff(), 1., identity_tol);
      // The frame's q is the family point on the circle of radius sqrt(5/12).
      const Vector9 expected = family.offset + std::sqrt(5. / 12.) * family.basis * Eigen::Vector2d(a, b) / r;
      EXPECT_LT(max_abs(HR::frame_to_sh(E) - expected), identity_tol) << k;
      // Round trip: the coordinates of q(E) give back E modulo the group.
      const Eigen::Vector2d ab = family.basis.transpose() * HR::frame_to_sh(E);
      const Eigen::Matrix3d E2 = HR::frame_from_family(v, ab[0], ab[1]);
      const HR::Octahedral_matching m = HR::closest_matching(E2, E);
      EXPECT_LT((E2 - E * G.matrix(m.index)).norm(), identity_tol);
    }
  }
}

// ---------------------------------------------------------------- projection

namespace {

// Distance from R to the coset E O.
double coset_residual(const Eigen::Matrix3d& R, const Eigen::Matrix3d& E)
{
  const HR::Octahedral_matching m = HR::closest_matching(R, E);
  return (R - E * HR::octahedral_group().matrix(m.index)).norm();
}

} // namespace

TEST(FrameProjection, RecoversRotationModuloTheGroup)
{
  std::mt19937 rng(47);
  std::vector<Eigen::Matrix3d> frames = special_rotations();
  // Frames sitting exactly on the seeds, and half-way between seeds.
  frames.push_back(rot(pi / 4, Eigen::Vector3d::UnitZ()) * rot(pi / 4, Eigen::Vector3d::UnitX()));
  frames.push_back(rot(pi / 8, Eigen::Vector3d::UnitY()));
  frames.push_back(rot(2 * pi / 3 / 2, Eigen::Vector3d(1., 1., 1.)));
  for(int i = 0; i < 300; ++i)
    frames.push_back(random_rotation(rng));
  for(std::size_t i = 0; i < frames.size(); ++i) {
    const Eigen::Matrix3d& E = frames[i];
    const double scale = 0.01 + 3. * (i % 5); // projection must not depend on |q|
    const Eigen::Matrix3d R = HR::project_to_frame(scale * HR::frame_to_sh(E), nullptr);
    EXPECT_LT(max_abs(R.transpose() * R - Eigen::Matrix3d::Identity()), identity_tol);
    EXPECT_NEAR(R.determinant(), 1., identity_tol);
    EXPECT_LT(coset_residual(R, E), iterative_tol) << i;
    // A hint (here a wrong-by-40-degrees neighbour) must not spoil the result.
    const Eigen::Matrix3d hint = rot(0.7, random_unit_vector(rng)) * E;
    EXPECT_LT(coset_residual(HR::project_to_frame(HR::frame_to_sh(E), &hint), E), iterative_tol) << i;
  }
}

TEST(FrameProjection, NoisyTargetGivesTheClosestFrame)
{
  std::mt19937 rng(53);
  std::normal_distribution<double> n(0., 1.);
  const Matrix9& Lx = HR::sh_generator_x();
  const Matrix9& Ly = HR::sh_generator_y();
  const Matrix9& Lz = HR::sh_generator_z();
  for(int i = 0; i < 300; ++i) {
    const Eigen::Matrix3d E = random_rotation(rng);
    Vector9 noise;
    for(int k = 0; k < 9; ++k)
      noise[k] = n(rng);
    const Vector9 q = HR::frame_to_sh(E) + 0.05 * noise.normalized();
    const Vector9 qn = q.normalized();
    const Eigen::Matrix3d R = HR::project_to_frame(q, nullptr);
    const Vector9 a = HR::frame_to_sh(R);
    // Stationary: the residual is orthogonal to the tangent space of the frame manifold at R.
    const Eigen::Vector3d gradient((Lx * a).dot(qn - a), (Ly * a).dot(qn - a), (Lz * a).dot(qn - a));
    EXPECT_LT(gradient.norm(), iterative_tol) << i;
    // At least as close as the noise-free frame (projection = nearest point, not just a critical point).
    EXPECT_GE(qn.dot(a), qn.dot(HR::frame_to_sh(E)) - iterative_tol) << i;
    // Matches the truth modulo O: |dq| ~ sqrt(20/3) |d angle|, so noise 0.05 moves the frame < ~0.02 rad.
    const HR::Octahedral_matching m = HR::closest_matching(R, E);
    const double angle = std::acos(std::min(1., std::max(-1., 0.5 * (m.trace - 1.))));
    EXPECT_LT(angle, 0.05) << i;
  }
}

TEST(FrameProjection, DegenerateInputReturnsHintOrIdentity)
{
  Vector9 tiny = Vector9::Constant(1e-8);
  EXPECT_TRUE(HR::project_to_frame(tiny, nullptr).isIdentity(0.));
  const Eigen::Matrix3d hint = rot(0.4, Eigen::Vector3d(1., -2., 0.5));
  EXPECT_TRUE(HR::project_to_frame(tiny, &hint) == hint);
  EXPECT_TRUE(HR::project_to_frame(Vector9::Zero(), &hint) == hint);
}

TEST(FrameProjection, RefineFrameConvergesQuadratically)
{
  // From a start 0.2 rad away, a handful of Gauss-Newton steps reach machine precision.
  std::mt19937 rng(59);
  for(int i = 0; i < 50; ++i) {
    const Eigen::Matrix3d E = random_rotation(rng);
    Eigen::Matrix3d R = rot(0.2, random_unit_vector(rng)) * E;
    const double dot = HR::refine_frame(HR::frame_to_sh(E), R, 6);
    EXPECT_NEAR(dot, 1., identity_tol);
    EXPECT_LT(coset_residual(R, E), iterative_tol);
  }
}
