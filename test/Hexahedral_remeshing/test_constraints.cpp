// Tests of the boundary edge valences (Desobry et al., Sec. 5) and of the boundary direction
// constraints (Sec. 4 and 6.2): heuristics with exact thresholds, prescriptions and their errors,
// the a-b-k file format, orientation conventions, Algorithms 1 and 2, the acute model, double
// slopes with valences 4 and 5, every model of ../shared/data, determinism.
#include "data_paths.h"
#include <CGAL/Hexahedral_remeshing/IO/edge_valences.h>
#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK_boundary.h>
#include <CGAL/Hexahedral_remeshing/boundary_dihedral_angles.h>
#include <CGAL/Hexahedral_remeshing/boundary_direction_constraints.h>
#include <CGAL/Hexahedral_remeshing/boundary_edge_valences.h>
#include <CGAL/Hexahedral_remeshing/build_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/tetrahedralize_surface.h>
#include <CGAL/Hexahedral_remeshing/internal/ambiguous_dihedral_class.h>
#include <CGAL/Hexahedral_remeshing/internal/direction_constraints_energy.h>

#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include "shared_models.h"
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <random>
#include <set>
#include <sstream>

namespace HR = CGAL::Hexahedral_remeshing;
namespace HP = CGAL::Hexahedral_remeshing::parameters;
typedef HR::Tetrahedral_mesh_3<> Mesh;
typedef Mesh::Index Index;
typedef Mesh::Point_3 Point;
typedef HR::internal::Boundary_direction_energy Energy;
typedef Eigen::Vector3d Vec;
namespace fs = std::filesystem;

namespace {

const std::string test_data = HEXREM_TEST_DATA_DIR;
const std::string example_data = HEXREM_EXAMPLE_DATA_DIR;
const std::string shared_data = HEXREM_SHARED_DATA_DIR;
const double quarter_pi = CGAL_PI / 4;


Mesh load(const std::string& f)
{
  Mesh m;
  HR::IO::read_tetrahedral_mesh(f, m);
  return m;
}

std::string temporary_file(const std::string& name)
{
  return (fs::temp_directory_path() / ("hexrem_test_constraints_" + name)).string();
}

// ---------------------------------------------------------------------------------------------
// A fan of tetrahedra around the edge p = (0,0,1) -> q = (0,0,0): the fan points lie at z = 1/2,
// the first at angle 0 (on +x) and the last at `last`; between them, integer points every 90
// degrees (counter-clockwise about +z). The boundary edge pq then has the interior dihedral angle
// of `last` seen from the axis (the same construction as the DihedralClass tests of test_mesh).
struct Fan
{
  Mesh mesh;
  Index edge = Mesh::null_index;
};

Fan make_fan(const Point& last, double last_degrees)
{
  HR::Tetrahedral_soup_3<Point> soup;
  soup.points = {Point(0, 0, 1), Point(0, 0, 0), Point(1, 0, 0.5)};
  const Point axis_points[] = {Point(0, 1, 0.5), Point(-1, 0, 0.5), Point(0, -1, 0.5)};
  for(int q = 1; q <= 3; ++q)
    if(last_degrees > 90.0 * q + 1e-9) soup.points.push_back(axis_points[q - 1]);
  soup.points.push_back(last);
  for(std::size_t k = 2; k + 1 < soup.points.size(); ++k) soup.tetrahedra.push_back({0, 1, k, k + 1});
  Fan fan;
  HR::build_tetrahedral_mesh(soup, fan.mesh, HP::split_multi_boundary_tetrahedra(false));
  fan.edge = fan.mesh.find_edge(0, 1);
  return fan;
}

Point at_degrees(double deg)
{
  const double r = deg * CGAL_PI / 180;
  return Point(std::cos(r), std::sin(r), 0.5);
}

// ---------------------------------------------------------------------------------------------
// Double-slope solid: the block [0,2] x [0,1] x [0,H] with a V-shaped notch along y, centred at
// x = 1, of half-width w at the top, whose two planar slopes meet at the bottom of the notch with
// the interior dihedral angle `interior` (> pi). Closed surface -> TetGen -> Tetrahedral_mesh_3.
Mesh double_slope_solid(double interior, double w, double H, double max_volume)
{
  const double alpha = (interior - CGAL_PI) / 2; // slope of each face of the notch
  const double d = w * std::tan(alpha);
  const std::vector<std::pair<double, double> > polygon = {
    {0, 0}, {2, 0}, {2, H}, {1 + w, H}, {1, H - d}, {1 - w, H}, {0, H}}; // (x, z), counter-clockwise
  typedef CGAL::Surface_mesh<Point> Surface;
  Surface sm;
  std::vector<Surface::Vertex_index> front, back;
  for(const auto& p : polygon) {
    front.push_back(sm.add_vertex(Point(p.first, 0, p.second)));
    back.push_back(sm.add_vertex(Point(p.first, 1, p.second)));
  }
  // the polygon is counter-clockwise in (x, z), i.e. clockwise about +y: outward -y at y = 0
  sm.add_face(front);
  sm.add_face(std::vector<Surface::Vertex_index>(back.rbegin(), back.rend()));
  for(std::size_t i = 0; i < polygon.size(); ++i) {
    const std::size_t j = (i + 1) % polygon.size();
    sm.add_face(front[j], front[i], back[i], back[j]);
  }
  HR::Tetrahedral_soup_3<Point> soup;
  HR::tetrahedralize_surface(sm, soup, HP::maximum_tetrahedron_volume(max_volume));
  Mesh m;
  HR::build_tetrahedral_mesh(soup, m);
  return m;
}

// The boundary edges at the bottom of the notch: the only ones of exact class >= 3.
std::vector<Index> notch_edges(const Mesh& m)
{
  std::vector<Index> edges;
  for(Index e : m.boundary_edges())
    if(HR::boundary_edge_dihedral_class(m, e) >= 3) edges.push_back(e);
  return edges;
}

struct Constraint_run
{
  std::vector<int> valences;
  std::vector<Vec> directions;
  HR::Boundary_direction_constraints_result result;
};

template <class NP = CGAL::parameters::Default_named_parameters>
Constraint_run run_constraints(const Mesh& m, const NP& valence_np = CGAL::parameters::default_values())
{
  Constraint_run r;
  HR::compute_boundary_edge_valences(m, r.valences, valence_np);
  r.result = HR::compute_boundary_direction_constraints(m, r.valences, r.directions);
  return r;
}

// With E(v) < pi/4 every boundary edge has |phi(v_i, v_j) - k pi/2| < pi/4 (modulo 2 pi for
// k >= 5): the frame field rounds phi(v) to the prescribed valence. Checked through the public
// per-edge angle, so that the orientation conventions of the energy and of the mesh must agree.
void expect_valences_realized(const Mesh& m, const Constraint_run& r)
{
  std::size_t wrong = 0;
  for(Index e : m.boundary_edges()) {
    const double phi = HR::boundary_edge_direction_angle(m, e, r.directions);
    const int k = r.valences[e];
    double dev = std::abs(phi - k * CGAL_PI / 2);
    if(k >= 5) dev = std::min(std::fmod(dev, 2 * CGAL_PI), 2 * CGAL_PI - std::fmod(dev, 2 * CGAL_PI));
    if(!(dev < quarter_pi)) ++wrong;
  }
  EXPECT_EQ(wrong, 0u) << m.source();
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Heuristics

TEST(Valences, HeuristicsOnConstructedEdges)
{
  struct Case { const char* name; Point last; double degrees; int geometric, low_angle, ambiguous, cap_two; };
  const Case cases[] = {
    {"10", at_degrees(10), 10, 0, 1, 1, 0},
    {"44.9", at_degrees(44.9), 44.9, 0, 1, 1, 0},
    {"45 exact", Point(1, 1, 0.5), 45, 1, 1, 1, 1},          // tie at pi/4: rounds up
    {"90", Point(0, 1, 0.5), 90, 1, 1, 1, 1},
    {"135 exact", Point(-1, 1, 0.5), 135, 2, 2, 2, 2},       // tie at 3pi/4: rounds up
    {"180", Point(-1, 0, 0.5), 180, 2, 2, 2, 2},
    {"225 exact", Point(-1, -1, 0.5), 225, 3, 3, 3, 2},      // tie at 5pi/4: rounds up
    {"270", Point(0, -1, 0.5), 270, 3, 3, 3, 2},
    {"315 exact", Point(1, -1, 0.5), 315, 4, 4, 4, 2},       // tie at 7pi/4: rounds up
    {"350", at_degrees(350), 350, 4, 4, 4, 2},
    // the ambiguous heuristic differs from low_angle in [m 90 + 40.5, m 90 + 45)
    {"40.4", at_degrees(40.4), 40.4, 0, 1, 1, 0},
    {"40.6", at_degrees(40.6), 40.6, 0, 1, 1, 0},
    {"130.4", at_degrees(130.4), 130.4, 1, 1, 1, 1},
    {"130.6", at_degrees(130.6), 130.6, 1, 1, 2, 1},
    {"220.4", at_degrees(220.4), 220.4, 2, 2, 2, 2},
    {"220.6", at_degrees(220.6), 220.6, 2, 2, 3, 2},
    {"310.4", at_degrees(310.4), 310.4, 3, 3, 3, 2},
    {"310.6", at_degrees(310.6), 310.6, 3, 3, 4, 2},
    // within pi/8192 (0.022 degrees) below a tie: a tie for every heuristic but the geometric one
    {"134.99", at_degrees(134.99), 134.99, 1, 2, 2, 2},
    {"224.99", at_degrees(224.99), 224.99, 2, 3, 3, 2},
    {"314.99", at_degrees(314.99), 314.99, 3, 4, 4, 2},
    {"134.97", at_degrees(134.97), 134.97, 1, 1, 2, 1},   // 0.03 below: not a tie
    {"224.97", at_degrees(224.97), 224.97, 2, 2, 3, 2},
  };
  for(const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const Fan fan = make_fan(c.last, c.degrees);
    ASSERT_NE(fan.edge, Mesh::null_index);
    ASSERT_TRUE(fan.mesh.is_boundary_edge(fan.edge));
    EXPECT_NEAR(HR::boundary_edge_dihedral_angle(fan.mesh, fan.edge) * 180 / CGAL_PI, c.degrees, 1e-9);
    EXPECT_EQ(HR::boundary_edge_valence(fan.mesh, fan.edge, HR::Valence_heuristic::GEOMETRIC), c.geometric);
    EXPECT_EQ(HR::boundary_edge_valence(fan.mesh, fan.edge, HR::Valence_heuristic::LOW_ANGLE), c.low_angle);
    EXPECT_EQ(HR::boundary_edge_valence(fan.mesh, fan.edge, HR::Valence_heuristic::AMBIGUOUS), c.ambiguous);
    EXPECT_EQ(HR::boundary_edge_valence(fan.mesh, fan.edge, HR::Valence_heuristic::CAP_TWO), c.cap_two);
    // the whole-mesh function agrees with the per-edge one
    for(HR::Valence_heuristic h : {HR::Valence_heuristic::GEOMETRIC, HR::Valence_heuristic::LOW_ANGLE,
                                   HR::Valence_heuristic::AMBIGUOUS, HR::Valence_heuristic::CAP_TWO}) {
      std::vector<int> k;
      HR::compute_boundary_edge_valences(fan.mesh, k, HP::valence_heuristic(h));
      ASSERT_EQ(k.size(), fan.mesh.number_of_edges());
      EXPECT_EQ(k[fan.edge], HR::boundary_edge_valence(fan.mesh, fan.edge, h));
      for(Index e = 0; e < fan.mesh.number_of_edges(); ++e)
        EXPECT_EQ(k[e] == HR::interior_edge_valence, !fan.mesh.is_boundary_edge(e));
    }
  }
}

TEST(Valences, HeuristicNames)
{
  HR::Valence_heuristic h = HR::Valence_heuristic::GEOMETRIC;
  EXPECT_TRUE(HR::parse_valence_heuristic("low-angle", h));
  EXPECT_EQ(h, HR::Valence_heuristic::LOW_ANGLE);
  for(HR::Valence_heuristic c : {HR::Valence_heuristic::GEOMETRIC, HR::Valence_heuristic::LOW_ANGLE,
                                 HR::Valence_heuristic::AMBIGUOUS, HR::Valence_heuristic::CAP_TWO}) {
    EXPECT_TRUE(HR::parse_valence_heuristic(HR::valence_heuristic_name(c), h));
    EXPECT_EQ(h, c);
  }
  EXPECT_FALSE(HR::parse_valence_heuristic("round", h));
}

// floor(floor(mul phi / pi + add) / div) for phi = atan2(y, x) in [0, 2 pi), in 256-bit MPFR: the
// oracle of the biased class thresholds (integers only besides mul phi / pi).
int mpfr_biased_class(double x, double y, unsigned long mul, unsigned long add, long div)
{
  mpfr_t phi, t, pi;
  mpfr_inits2(256, phi, t, pi, (mpfr_ptr)0);
  mpfr_set_d(t, x, MPFR_RNDN);
  mpfr_set_d(phi, y, MPFR_RNDN);
  mpfr_atan2(phi, phi, t, MPFR_RNDN);
  mpfr_const_pi(pi, MPFR_RNDN);
  if(mpfr_sgn(phi) < 0) { mpfr_mul_ui(t, pi, 2, MPFR_RNDN); mpfr_add(phi, phi, t, MPFR_RNDN); }
  mpfr_mul_ui(phi, phi, mul, MPFR_RNDN);
  mpfr_div(phi, phi, pi, MPFR_RNDN);
  mpfr_add_ui(phi, phi, add, MPFR_RNDN);
  mpfr_floor(phi, phi);
  const long k = mpfr_get_si(phi, MPFR_RNDN);
  mpfr_clears(phi, t, pi, (mpfr_ptr)0);
  return int(k / div);
}

// The +0.05 bias of the ambiguous heuristic puts thresholds at (m + 0.45) pi/2, irrational angles.
// Points within a few ulps of them make the interval filter fail (8 of the 36 below, measured);
// the exact path must agree with
// an independent oracle: atan2 of the same doubles in 256-bit MPFR arithmetic.
TEST(Valences, AmbiguousThresholdIsExact)
{
  // round(2 phi/pi + 0.05) = floor(2 phi/pi + 0.55) = floor(floor(40 phi/pi + 11) / 20)
  auto oracle = [](double x, double y) { return mpfr_biased_class(x, y, 40, 11, 20); };
  int checked = 0;
  std::set<int> classes;
  for(double deg : {40.5, 130.5, 220.5, 310.5}) {
    const double r = deg * CGAL_PI / 180;
    const double x0 = std::cos(r), y0 = std::sin(r);
    for(int ulps = -4; ulps <= 4; ++ulps) {
      double y = y0;
      for(int u = 0; u < std::abs(ulps); ++u) y = std::nextafter(y, ulps > 0 ? 10.0 : -10.0);
      const std::array<double, 12> xyz = {0, 0, 1, 0, 0, 0, 1, 0, 0, x0, y, 0.5};
      const int expected = oracle(x0, y);
      EXPECT_EQ(HR::internal::ambiguous_dihedral_class_exact(xyz), expected) << deg << " " << ulps;
      classes.insert(expected);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 36);
  EXPECT_GE(classes.size(), 4u); // both sides of the thresholds are reached
  // away from the thresholds it is round(2 phi / pi + 0.05)
  for(double deg = 0.25; deg < 360; deg += 0.5) {
    const Point b = at_degrees(deg);
    const std::array<double, 12> xyz = {0, 0, 1, 0, 0, 0, 1, 0, 0, b.x(), b.y(), 0.5};
    EXPECT_EQ(HR::internal::ambiguous_dihedral_class_exact(xyz), int(std::floor(deg / 90 + 0.55))) << deg;
  }
}

// A CAD angle of 45, 135, 225 or 315 degrees whose points are rounded to doubles lands on either
// side of the exact tie: the exact classes differ edge by edge (both sides are reached below), and
// the class the heuristics use (near ties rounded up) is the tie's on every one of them.
TEST(Valences, RoundedTiesTakeTheTiesClass)
{
  for(int m = 0; m < 4; ++m) {
    SCOPED_TRACE(m);
    std::set<int> exact;
    for(int step = -20; step <= 20; ++step) {
      // the edge's second face turned about the edge by a tiny angle around the tie, then rounded
      const double r = (90.0 * m + 45.0) * CGAL_PI / 180 + step * 1e-15;
      const std::array<double, 12> xyz = {0, 0, 1, 0, 0, 0, 1, 0, 0, std::cos(r), std::sin(r), 0.5};
      exact.insert(HR::internal::dihedral_class_exact(xyz));
      EXPECT_EQ(HR::internal::near_tie_dihedral_class_exact(xyz), m + 1) << step;
    }
    EXPECT_EQ(exact, (std::set<int>{m, m + 1}));
  }
  // on a mesh: the public class of an edge 0.01 degrees below 135
  const Fan fan = make_fan(at_degrees(134.99), 134.99);
  EXPECT_EQ(HR::boundary_edge_dihedral_class(fan.mesh, fan.edge), 1);
  EXPECT_EQ(HR::boundary_edge_near_tie_class(fan.mesh, fan.edge), 2);
}

// The near-tie thresholds m pi/2 + 2047 pi/8192, decided exactly: against an MPFR oracle on points
// within a few ulps of them (where the interval filter fails) and on a grid of angles.
TEST(Valences, NearTieThresholdIsExact)
{
  // m + 1 from phi = m pi/2 + 2047 pi/8192 on: floor(2 phi/pi + 2049/4096) = floor(floor(8192 phi/pi + 2049) / 4096)
  auto oracle = [](double x, double y) { return mpfr_biased_class(x, y, 8192, 2049, 4096); };
  std::set<int> classes;
  for(int m = 0; m < 4; ++m) {
    const double r = m * CGAL_PI / 2 + 2047 * CGAL_PI / 8192;
    const double x0 = std::cos(r), y0 = std::sin(r);
    for(int ulps = -12; ulps <= 12; ++ulps) { // CGAL_PI and the sums round: a few ulps off the threshold
      double y = y0;
      for(int u = 0; u < std::abs(ulps); ++u) y = std::nextafter(y, ulps > 0 ? 10.0 : -10.0);
      const std::array<double, 12> xyz = {0, 0, 1, 0, 0, 0, 1, 0, 0, x0, y, 0.5};
      const int expected = oracle(x0, y);
      EXPECT_EQ(HR::internal::near_tie_dihedral_class_exact(xyz), expected) << m << " " << ulps;
      classes.insert(expected);
    }
  }
  EXPECT_EQ(classes.size(), 5u); // both sides of each threshold
  for(double deg = 0.25; deg < 360; deg += 0.5) {
    const Point b = at_degrees(deg);
    const std::array<double, 12> xyz = {0, 0, 1, 0, 0, 0, 1, 0, 0, b.x(), b.y(), 0.5};
    EXPECT_EQ(HR::internal::near_tie_dihedral_class_exact(xyz), int(std::floor(deg / 90 + 0.5))) << deg;
  }
}

// ---------------------------------------------------------------------------------------------
// Prescriptions

TEST(Valences, PrescriptionsOverrideTheHeuristic)
{
  const Mesh m = load(example_data + "/n13c_acute_line.vtk");
  std::vector<int> heuristic;
  const auto s0 = HR::compute_boundary_edge_valences(m, heuristic);
  EXPECT_EQ(s0.prescribed_edges, 0u);
  EXPECT_EQ(s0.histogram, (std::array<std::size_t, 7>{{0, 60, 615, 0, 0, 0, 0}}));
  EXPECT_EQ(s0.edges_differing_from_geometry, 8u);

  // the curve of the acute edge, prescribed as a whole
  int acute_curve = -1;
  std::size_t acute_curve_edges = 0;
  for(Index e : m.boundary_edges())
    if(HR::boundary_edge_dihedral_class(m, e) == 0) acute_curve = m.edge_curve(e);
  ASSERT_GE(acute_curve, 0);
  for(Index e : m.boundary_edges()) acute_curve_edges += (m.edge_curve(e) == acute_curve);
  std::vector<Index> off_curve;
  for(Index e : m.boundary_edges())
    if(m.edge_curve(e) != acute_curve) off_curve.push_back(e);
  ASSERT_GE(off_curve.size(), 21u);
  const Index e1 = off_curve[10], e2 = off_curve[20];
  const auto& v2 = m.edge_vertices(e2);
  std::map<Index, int> by_index = {{e1, 3}};
  std::vector<std::pair<std::array<Index, 2>, int> > by_pair = {{{{v2[1], v2[0]}}, 6}};
  std::vector<std::pair<int, int> > by_curve = {{acute_curve, 2}};

  std::vector<int> k;
  const auto s = HR::compute_boundary_edge_valences(
    m, k, HP::prescribed_curve_valences(by_curve, HP::prescribed_edge_valences(by_index)));
  EXPECT_EQ(k[e1], 3);
  EXPECT_EQ(s.prescribed_edges, acute_curve_edges + 1);
  for(Index e : m.boundary_edges()) {
    if(e == e1) continue;
    if(m.edge_curve(e) == acute_curve) { EXPECT_EQ(k[e], 2); }
    else { EXPECT_EQ(k[e], heuristic[e]); }
  }
  // per-edge prescriptions win over curve prescriptions; vertex pairs work in either order
  std::vector<int> k2;
  HR::compute_boundary_edge_valences(m, k2, HP::prescribed_edge_valences(by_pair, HP::valence_heuristic(HR::Valence_heuristic::GEOMETRIC)));
  EXPECT_EQ(k2[e2], 6);
  std::size_t zeros = 0;
  for(Index e : m.boundary_edges()) zeros += (k2[e] == 0);
  EXPECT_EQ(zeros, 8u);
}

TEST(Valences, ImpossiblePrescriptionsAreRejected)
{
  const Mesh m = load(example_data + "/n13c_acute_line.vtk");
  const Index b = m.boundary_edges().front();
  Index interior = Mesh::null_index;
  for(Index e = 0; e < m.number_of_edges() && interior == Mesh::null_index; ++e)
    if(!m.is_boundary_edge(e)) interior = e;
  ASSERT_NE(interior, Mesh::null_index);
  auto message = [&](auto np) {
    std::vector<int> k;
    try {
      HR::compute_boundary_edge_valences(m, k, np);
    } catch(const HR::Input_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  auto edge = [](Index e, int k) { return std::map<Index, int>{{e, k}}; };
  EXPECT_NE(message(HP::prescribed_edge_valences(edge(b, 0))).find("prescribed valence 0 is impossible"), std::string::npos);
  EXPECT_NE(message(HP::prescribed_edge_valences(edge(b, -2))).find("impossible"), std::string::npos);
  EXPECT_NE(message(HP::prescribed_edge_valences(edge(b, 7))).find("between 1 and 6"), std::string::npos);
  EXPECT_NE(message(HP::prescribed_edge_valences(edge(interior, 2))).find("not a boundary edge"), std::string::npos);
  EXPECT_NE(message(HP::prescribed_edge_valences(edge(Index(m.number_of_edges()), 2))).find("no such edge"),
            std::string::npos);
  const std::vector<std::pair<std::pair<int, int>, int> > not_an_edge = {{{0, 0}, 2}};
  EXPECT_NE(message(HP::prescribed_edge_valences(not_an_edge)).find("not an edge"), std::string::npos);
  const std::vector<std::pair<Index, int> > twice = {{b, 2}, {b, 3}};
  EXPECT_NE(message(HP::prescribed_edge_valences(twice)).find("prescribed twice"), std::string::npos);
  const std::vector<std::pair<int, int> > unknown_curve = {{12345, 2}};
  EXPECT_NE(message(HP::prescribed_curve_valences(unknown_curve)).find("curve 12345"), std::string::npos);
  const std::vector<std::pair<int, int> > bad_curve_valence = {{m.edge_curve(b) >= 0 ? m.edge_curve(b) : 0, 0}};
  EXPECT_NE(message(HP::prescribed_curve_valences(bad_curve_valence)).find("impossible"), std::string::npos);
}

TEST(Valences, FileReaderAndWriter)
{
  const Mesh m = load(example_data + "/n13c_acute_line.vtk");
  // round trip of every boundary valence
  std::vector<int> k;
  HR::compute_boundary_edge_valences(m, k, HP::valence_heuristic(HR::Valence_heuristic::AMBIGUOUS));
  const std::string f = temporary_file("valences.txt");
  HR::IO::write_edge_valences(f, m, k);
  const auto read = HR::IO::read_edge_valences(f, m);
  EXPECT_EQ(read.size(), m.boundary_edges().size());
  std::vector<int> k2;
  HR::compute_boundary_edge_valences(m, k2, HP::prescribed_edge_valences(read, HP::valence_heuristic(HR::Valence_heuristic::GEOMETRIC)));
  EXPECT_EQ(k, k2);

  const Index b = m.boundary_edges()[5];
  const auto& bv = m.edge_vertices(b);
  Index interior = Mesh::null_index;
  for(Index e = 0; e < m.number_of_edges() && interior == Mesh::null_index; ++e)
    if(!m.is_boundary_edge(e) && m.edge_vertices(e)[0] < m.number_of_input_vertices() &&
       m.edge_vertices(e)[1] < m.number_of_input_vertices())
      interior = e;
  ASSERT_NE(interior, Mesh::null_index);
  const auto& iv = m.edge_vertices(interior);
  const std::string pair = std::to_string(bv[0]) + " " + std::to_string(bv[1]);
  auto write = [&](const std::string& text) { std::ofstream(f) << text; };
  // comments, blank lines, Windows line ends, repeated identical lines are fine
  write("# header\n\n" + pair + " 4   # trailing comment\r\n" + std::to_string(bv[1]) + " " + std::to_string(bv[0]) + " 4\n");
  const auto ok = HR::IO::read_edge_valences(f, m);
  ASSERT_EQ(ok.size(), 1u);
  EXPECT_EQ(ok[0].first, b);
  EXPECT_EQ(ok[0].second, 4);

  struct Bad { std::string text; std::size_t line; std::string problem; };
  const Bad bad[] = {
    {"# c\n" + pair + " 2\n0 0 2\n", 3, "do not form an edge"},
    {pair + " 2\n\n" + std::to_string(iv[0]) + " " + std::to_string(iv[1]) + " 2\n", 3, "is not a boundary edge"},
    {pair + " 0\n", 1, "valence 0 of edge " + pair + " is impossible"},
    {pair + " 7\n", 1, "between 1 and 6"},
    {"\n" + pair + "\n", 2, "expected three integers"},
    {pair + " 2 9\n", 1, "expected three integers"},
    {pair + " two\n", 1, "malformed integer 'two'"},
    {"-1 4 2\n", 1, "vertex -1 does not exist"},
    {"99999 4 2\n", 1, "vertex 99999 does not exist"},
    {pair + " 2\n" + pair + " 3\n", 2, "was given valence 2 on line 1"},
  };
  for(const Bad& c : bad) {
    SCOPED_TRACE(c.text);
    write(c.text);
    try {
      HR::IO::read_edge_valences(f, m);
      ADD_FAILURE() << "no error";
    } catch(const HR::Input_error& e) {
      EXPECT_EQ(e.line(), c.line);
      EXPECT_EQ(e.source(), f);
      EXPECT_NE(std::string(e.what()).find(f + ":" + std::to_string(c.line) + ": "), std::string::npos) << e.what();
      EXPECT_NE(e.problem().find(c.problem), std::string::npos) << e.what();
    }
  }
  std::remove(f.c_str());
  EXPECT_THROW(HR::IO::read_edge_valences(f, m), HR::Input_error); // missing file
}

// ---------------------------------------------------------------------------------------------
// Energies and conventions

TEST(Constraints, IdealNormalsMatchThePaper)
{
  // nbar_ij = (n_i + R_ij n_j) / |n_i + R_ij n_j|, R_ij the rotation of angle pi - k pi/2 about
  // e_ji (right-handed about e_ij by k pi/2 - pi), on random configurations away from n_i = -R n_j.
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> angle(0, 2 * CGAL_PI);
  std::size_t compared = 0;
  for(int trial = 0; trial < 2000; ++trial) {
    const Vec e = Vec(std::cos(angle(gen)), std::sin(angle(gen)), std::cos(angle(gen))).normalized();
    const Vec ni = e.unitOrthogonal();
    const Vec nj = Energy::rotate(ni, e, angle(gen));
    for(int k = 0; k <= 6; ++k) {
      const Vec rnj = Energy::rotate(nj, e, k * CGAL_PI / 2 - CGAL_PI);
      const Vec sum = ni + rnj;
      const Vec nbar = Energy::ideal_half_edge_normal(ni, nj, e, k);
      const Vec nbar_ji = Energy::ideal_half_edge_normal(nj, ni, -e, k);
      // the pair satisfies the dihedral constraint modulo 2 pi
      const double phi = Energy::dihedral_angle(nbar, nbar_ji, e);
      EXPECT_LT(Energy::dihedral_deviation(phi, k * CGAL_PI / 2, true), 1e-9);
      EXPECT_NEAR(nbar.norm(), 1, 1e-12);
      if(sum.norm() < 1e-3) continue;
      EXPECT_LT((nbar - sum.normalized()).norm(), 1e-9);
      ++compared;
    }
  }
  EXPECT_GT(compared, 13000u);
  // the normals of an edge that already has its dihedral angle are their own ideal normals
  const Vec e(0, 0, -1), ni(0, -1, 0); // edge p -> q along -z, first face along +x: outward -y
  for(int k = 0; k <= 4; ++k) {
    // the second face at angle phi = k pi/2 about +z has outward normal rotated by pi - phi from ni about e
    const Vec nj = Energy::rotate(ni, e, CGAL_PI - k * CGAL_PI / 2);
    EXPECT_LT(Energy::dihedral_deviation(Energy::dihedral_angle(ni, nj, e), k * CGAL_PI / 2, true), 1e-12);
    EXPECT_LT((Energy::ideal_half_edge_normal(ni, nj, e, k) - ni).norm(), 1e-12) << k;
  }
  // modulo form: 5 pi/2 is pi/2 away from 2 pi and from pi; 3 pi/2 away from 0 plainly, pi/2 modulo
  EXPECT_NEAR(Energy::dihedral_deviation(0, 5 * CGAL_PI / 2, true), CGAL_PI / 2, 1e-12);
  EXPECT_NEAR(Energy::dihedral_deviation(0, 5 * CGAL_PI / 2, false), 5 * CGAL_PI / 2, 1e-12);
  EXPECT_NEAR(Energy::dihedral_deviation(0.3, 3 * CGAL_PI, true), CGAL_PI - 0.3, 1e-12);
}

TEST(Constraints, NormalsGiveTheInteriorDihedralAngles)
{
  // phi(n_i, n_j) of the direction-angle function equals the dihedral angle of the mesh: the
  // half-edge conventions of the energy and of Tetrahedral_mesh_3 agree.
  const Mesh m = load(example_data + "/n13c_acute_line.vtk");
  const std::vector<Vec> n = HR::boundary_triangle_unit_normals(m);
  for(Index e : m.boundary_edges())
    EXPECT_NEAR(HR::boundary_edge_direction_angle(m, e, n), HR::boundary_edge_dihedral_angle(m, e), 1e-9);
  // E(n) of the geometric valences is the largest rounding error |phi - round(2 phi/pi) pi/2|
  std::vector<int> k;
  HR::compute_boundary_edge_valences(m, k, HP::valence_heuristic(HR::Valence_heuristic::GEOMETRIC));
  std::vector<double> fe;
  const double en = HR::compute_boundary_direction_deviation(m, k, n, fe);
  EXPECT_NEAR(en, 10 * CGAL_PI / 180, 1e-9); // the 10 degree edge is 10 degrees from valence 0
  EXPECT_EQ(fe.size(), m.number_of_boundary_triangles());
}

TEST(Constraints, CubeNormalsAreOptimal)
{
  // planar faces and 90 degree edges: E(n) = 0 and no triangle is searched (early exit)
  const Mesh m = load(example_data + "/cube.off");
  const Constraint_run r = run_constraints(m);
  EXPECT_LT(r.result.initial_energy, 1e-12);
  EXPECT_LT(r.result.final_energy, 1e-12);
  EXPECT_EQ(r.result.searches, 0u);
  EXPECT_EQ(r.result.queue_pops, m.number_of_boundary_triangles());
  EXPECT_EQ(r.directions, HR::boundary_triangle_unit_normals(m));
}

TEST(Constraints, SearchGridOfAlgorithmTwo)
{
  // without refinement, a direction is a normal or one of the 26 directions of the cube of size 2
  const Mesh m = load(example_data + "/n13c_acute_line.vtk");
  std::vector<int> k;
  HR::compute_boundary_edge_valences(m, k);
  std::vector<Vec> v;
  const auto r0 = HR::compute_boundary_direction_constraints(m, k, v, HP::number_of_refinements(0));
  const std::vector<Vec> n = HR::boundary_triangle_unit_normals(m);
  std::size_t on_grid = 0;
  for(std::size_t i = 0; i < v.size(); ++i) {
    if(v[i] == n[i]) continue;
    bool found = false;
    for(int x = -1; x <= 1; ++x)
      for(int y = -1; y <= 1; ++y)
        for(int z = -1; z <= 1; ++z)
          if((x || y || z) && v[i] == Vec(x, y, z).normalized()) found = true;
    EXPECT_TRUE(found) << i;
    ++on_grid;
  }
  EXPECT_GT(on_grid, 0u);
  EXPECT_GT(r0.final_energy, 0.);
  // each refinement tests at most 8 neighbours: at most 26 + 8 r evaluations per search
  std::vector<Vec> v9;
  const auto r9 = HR::compute_boundary_direction_constraints(m, k, v9);
  EXPECT_LE(r9.energy_evaluations, r9.searches * (26 + 8 * 9));
  EXPECT_LE(r0.energy_evaluations, r0.searches * 26);
  EXPECT_LT(r9.final_energy, r0.final_energy);
  EXPECT_THROW(HR::compute_boundary_direction_constraints(m, k, v, HP::number_of_refinements(-1)), HR::Error);
}

TEST(Constraints, InvalidValenceVectorsAreRejected)
{
  const Mesh m = load(example_data + "/n13c_acute_line.vtk");
  std::vector<int> k;
  HR::compute_boundary_edge_valences(m, k);
  std::vector<Vec> v;
  std::vector<int> short_k(k.begin(), k.end() - 1);
  EXPECT_THROW(HR::compute_boundary_direction_constraints(m, short_k, v), HR::Error);
  std::vector<int> bad = k;
  bad[m.boundary_edges().front()] = 7;
  EXPECT_THROW(HR::compute_boundary_direction_constraints(m, bad, v), HR::Input_error);
  bad[m.boundary_edges().front()] = -1;
  EXPECT_THROW(HR::compute_boundary_direction_constraints(m, bad, v), HR::Input_error);
  std::vector<double> fe;
  std::vector<Vec> wrong_size(3, Vec(1, 0, 0));
  EXPECT_THROW(HR::compute_boundary_direction_deviation(m, k, wrong_size, fe), HR::Error);
}

// ---------------------------------------------------------------------------------------------
// The acute model (10 degree wedge edge)

TEST(Constraints, AcuteLineLowAngle)
{
  const Mesh m = load(example_data + "/n13c_acute_line.vtk");
  const Constraint_run r = run_constraints(m);
  EXPECT_GT(r.result.initial_energy, quarter_pi);
  EXPECT_NEAR(r.result.initial_energy, 80 * CGAL_PI / 180, 1e-9); // 10 degrees to make 90
  EXPECT_LT(r.result.final_energy, quarter_pi);
  EXPECT_TRUE(r.result.failed_faces.empty());
  EXPECT_TRUE(r.result.converged);
  std::size_t acute = 0;
  for(Index e : m.boundary_edges())
    if(HR::boundary_edge_dihedral_class(m, e) == 0) {
      ++acute;
      EXPECT_EQ(r.valences[e], 1);
      const double phi = HR::boundary_edge_direction_angle(m, e, r.directions);
      EXPECT_EQ(int(std::floor(2 * phi / CGAL_PI + 0.5)), 1) << "edge " << e << " phi(v) " << phi;
    }
  EXPECT_EQ(acute, 8u);
  expect_valences_realized(m, r);
  // the per-face energies are consistent with the public evaluation
  std::vector<double> fe;
  EXPECT_EQ(HR::compute_boundary_direction_deviation(m, r.valences, r.directions, fe), r.result.final_energy);
  EXPECT_EQ(fe, r.result.face_energies);
}

TEST(Constraints, AcuteLineGeometricGivesValenceZero)
{
  const Mesh m = load(example_data + "/n13c_acute_line.vtk");
  std::vector<int> k;
  const auto s = HR::compute_boundary_edge_valences(m, k, HP::valence_heuristic(HR::Valence_heuristic::GEOMETRIC));
  EXPECT_EQ(s.histogram[0], 8u);
  for(Index e : m.boundary_edges()) {
    if(HR::boundary_edge_dihedral_class(m, e) == 0) { EXPECT_EQ(k[e], 0); }
  }
  // the constraints then reproduce the normals' valences, 0 included: not meshable
  std::vector<Vec> v;
  const auto r = HR::compute_boundary_direction_constraints(m, k, v);
  EXPECT_LT(r.final_energy, quarter_pi);
  for(Index e : m.boundary_edges()) {
    if(k[e] == 0) { EXPECT_EQ(int(std::floor(2 * HR::boundary_edge_direction_angle(m, e, v) / CGAL_PI + 0.5)), 0); }
  }
}

// ---------------------------------------------------------------------------------------------
// Double slopes (paper Fig. 10 and 13)

// The notch edge has the interior angle 4.37 rad of Fig. 10 (left); prescribed k = 4 the frame
// field must turn it into a 2 pi "crack": E(n) = 2 pi - 4.37 = 1.913 (the paper's 1.91).
TEST(DoubleSlope, ValenceFourOnAConcaveEdge)
{
  const Mesh m = double_slope_solid(4.37, 0.8, 1.0, 0.002);
  const std::vector<Index> notch = notch_edges(m);
  ASSERT_GE(notch.size(), 2u);
  for(Index e : notch) {
    const double phi = HR::boundary_edge_dihedral_angle(m, e);
    EXPECT_NEAR(phi, 4.37, 1e-9);
    EXPECT_TRUE(phi >= CGAL_PI && phi <= 3 * CGAL_PI / 2);
  }
  std::map<Index, int> four;
  for(Index e : notch) four[e] = 4;
  const Constraint_run r = run_constraints(m, HP::prescribed_edge_valences(four));
  EXPECT_NEAR(r.result.initial_energy, 2 * CGAL_PI - 4.37, 1e-9);
  EXPECT_LT(r.result.final_energy, quarter_pi);
  EXPECT_TRUE(r.result.failed_faces.empty());
  for(Index e : notch) {
    const double phi = HR::boundary_edge_direction_angle(m, e, r.directions);
    EXPECT_GT(phi, 7 * CGAL_PI / 4); // rounds to 4
  }
  expect_valences_realized(m, r);
}

// Fig. 13: k = 5 on the edge of two slopes, initial deviation 2.2 (interior angle 5 pi/2 - 2.2,
// a steep V slot). phi(v) lies in [0, 2 pi): valence 5 is reached modulo 2 pi, phi(v) near pi/2.
TEST(DoubleSlope, ValenceFiveUsesTheModuloForm)
{
  const Mesh m = double_slope_solid(5 * CGAL_PI / 2 - 2.2, 0.3, 1.2, 0.002);
  const std::vector<Index> notch = notch_edges(m);
  ASSERT_GE(notch.size(), 2u);
  std::map<Index, int> five;
  for(Index e : notch) five[e] = 5;
  const Constraint_run r = run_constraints(m, HP::prescribed_edge_valences(five));
  EXPECT_NEAR(r.result.initial_energy, 2.2, 1e-9);
  EXPECT_LT(r.result.final_energy, quarter_pi);
  for(Index e : notch) {
    const double phi = HR::boundary_edge_direction_angle(m, e, r.directions);
    // |phi - 5 pi/2| >= pi/2 for every phi in [0, 2 pi): only the modulo form gets below pi/4
    EXPECT_GT(phi, CGAL_PI / 4);
    EXPECT_LT(phi, 3 * CGAL_PI / 4);
  }
  expect_valences_realized(m, r);
}

// Known infeasible: k = 5 on the 4.37 rad edge of the first double slope (interior angle in
// [pi, 3 pi/2]). Modulo 2 pi the target 5 pi/2 is pi/2, 2.80 rad below 4.37 (3.48 rad above it), so
// E(n) = 2.80. The triangles along the notch have coplanar neighbours, whose ideal normals are their
// own normals, so delta^n bounds the turn of each direction by E: with both sides turning by at
// most E < pi/4, the deviation stays above 2.80 - 2E > pi/4 (checked numerically by sampling pairs
// of directions in cones of half-angle E around the normals). Measured: E(v) = 0.949.
TEST(DoubleSlope, ValenceFiveOnTheShallowNotchIsOutOfReach)
{
  const Mesh m = double_slope_solid(4.37, 0.8, 1.0, 0.002);
  std::map<Index, int> five;
  for(Index e : notch_edges(m)) five[e] = 5;
  const Constraint_run r = run_constraints(m, HP::prescribed_edge_valences(five));
  EXPECT_NEAR(r.result.initial_energy, 2 * CGAL_PI - (5 * CGAL_PI / 2 - 4.37), 1e-9);
  EXPECT_GE(r.result.final_energy, quarter_pi);
  EXPECT_LT(r.result.final_energy, r.result.initial_energy);
  EXPECT_FALSE(r.result.failed_faces.empty());
}

// ---------------------------------------------------------------------------------------------
// Every model of ../shared/data with low_angle

TEST(Constraints, SharedModelsLowAngle)
{
  const auto files = shared_models();
  if(files.empty()) GTEST_SKIP() << "../shared/data not present";
  // Models on which E(v) stays >= pi/4, with the measured E(v). Currently none.
  const std::map<std::string, double> known_failures = {};
  std::ostringstream table;
  table << std::left << std::setw(30) << "model" << std::right << std::setw(8) << "tets" << std::setw(8) << "tris"
        << std::setw(9) << "E(n)" << std::setw(9) << "E(v)" << std::setw(7) << "fail" << std::setw(9) << "s\n";
  for(const std::string& f : files) {
    SCOPED_TRACE(f);
    const Mesh m = load(f);
    const Constraint_run r = run_constraints(m);
    const std::string name = fs::path(f).stem().string();
    table << std::left << std::setw(30) << name << std::right << std::setw(8) << m.number_of_tetrahedra() << std::setw(8)
          << m.number_of_boundary_triangles() << std::fixed << std::setprecision(4) << std::setw(9)
          << r.result.initial_energy << std::setw(9) << r.result.final_energy << std::setw(7)
          << r.result.failed_faces.size() << std::setw(9) << r.result.seconds << "\n";
    EXPECT_TRUE(r.result.converged);
    EXPECT_LE(r.result.final_energy, r.result.initial_energy);
    if(known_failures.count(name)) {
      EXPECT_GE(r.result.final_energy, quarter_pi) << "known failure now passes: update the list";
    } else {
      EXPECT_LT(r.result.final_energy, quarter_pi);
      EXPECT_TRUE(r.result.failed_faces.empty());
      expect_valences_realized(m, r);
    }
  }
  std::cout << table.str();
}

// ---------------------------------------------------------------------------------------------
// Determinism

TEST(Constraints, TwoRunsGiveBitwiseIdenticalDirections)
{
  std::vector<std::string> files = {example_data + "/n13c_acute_line.vtk"};
  if(fs::exists(shared_data + "/mambo/B41.vtk")) files.push_back(shared_data + "/mambo/B41.vtk");
  for(const std::string& f : files) {
    const Mesh m = load(f);
    const Constraint_run a = run_constraints(m);
    const Constraint_run b = run_constraints(m);
    ASSERT_EQ(a.directions.size(), b.directions.size());
    EXPECT_EQ(std::memcmp(a.directions.data(), b.directions.data(), a.directions.size() * sizeof(Vec)), 0) << f;
    EXPECT_EQ(a.result.queue_pops, b.result.queue_pops);
    EXPECT_EQ(a.result.iterations, b.result.iterations);
    EXPECT_EQ(a.result.face_energies, b.result.face_energies);
  }
}

// ---------------------------------------------------------------------------------------------
// VTK output of the boundary

TEST(Writer, BoundaryTrianglesWithCellData)
{
  const Mesh m = load(example_data + "/n13c_acute_line.vtk");
  const Constraint_run r = run_constraints(m);
  HR::IO::VTK_array ei;
  ei.name = "E_i";
  ei.values = r.result.face_energies;
  HR::IO::VTK_array v;
  v.name = "v";
  v.components = 3;
  for(const Vec& d : r.directions) v.values.insert(v.values.end(), {d[0], d[1], d[2]});
  const std::string f = temporary_file("boundary.vtk");
  HR::IO::write_VTK_boundary(f, m, {ei, v});
  std::ifstream in(f);
  std::string word;
  std::size_t cells = 0, triangles = 0, points = 0;
  bool has_ei = false, has_v = false;
  while(in >> word) {
    if(word == "POINTS") in >> points;
    if(word == "CELL_TYPES") {
      in >> cells;
      for(std::size_t i = 0; i < cells; ++i) { int t; in >> t; triangles += (t == 5); }
    }
    if(word == "E_i") has_ei = true;
    if(word == "v") has_v = true;
  }
  EXPECT_EQ(cells, m.number_of_boundary_triangles());
  EXPECT_EQ(triangles, cells);
  EXPECT_EQ(points, 227u);
  EXPECT_TRUE(has_ei && has_v);
  std::remove(f.c_str());
  ei.values.pop_back();
  EXPECT_THROW(HR::IO::write_VTK_boundary(f, m, {ei}), HR::Error);
  EXPECT_FALSE(fs::exists(f));
  EXPECT_FALSE(fs::exists(f + ".tmp"));
}
