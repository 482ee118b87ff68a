// Issue 27 step 2: the motorcycle complex of built seamless maps whose complexes are counted by hand
// (blocks, patches, arcs, nodes), traced exactly through the tetrahedra the walls cross.
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/motorcycle_complex.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <vector>

namespace MC = CGAL::Hexahedral_remeshing::internal::motorcycle;

namespace {

// A tetrahedral mesh with a map: positions, tetrahedra, the map at their corners.
struct Built_map
{
  std::vector<std::array<double, 3> > points;
  std::vector<std::array<std::uint32_t, 4> > tets;
  std::vector<std::array<Eigen::Vector3d, 4> > parameters;

  // adds a tetrahedron, reoriented so that its parameters are positively oriented
  void add(std::array<std::uint32_t, 4> v, std::array<Eigen::Vector3d, 4> p)
  {
    if((p[1] - p[0]).cross(p[2] - p[0]).dot(p[3] - p[0]) < 0) {
      std::swap(v[2], v[3]);
      std::swap(p[2], p[3]);
    }
    tets.push_back(v);
    parameters.push_back(p);
  }
};

// Unit cells (i, j, k) of a grid of step h, each split into the 6 Kuhn tetrahedra along its
// diagonal; the map is the position, moved by `offset` at the vertices off the boundary.
Built_map kuhn_cells(const std::set<std::array<int, 3> >& cells, double h,
                     const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& offset = nullptr)
{
  Built_map m;
  std::map<std::array<int, 3>, std::uint32_t> id;
  auto vertex = [&](const std::array<int, 3>& g) {
    auto it = id.emplace(g, std::uint32_t(m.points.size()));
    if(it.second) m.points.push_back({{h * g[0], h * g[1], h * g[2]}});
    return it.first->second;
  };
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for(const auto& c : cells)
    for(const auto& perm : perms) {
      std::array<int, 3> g = c;
      std::array<std::uint32_t, 4> v;
      v[0] = vertex(g);
      for(int s = 0; s < 3; ++s) {
        ++g[std::size_t(perm[s])];
        v[std::size_t(s + 1)] = vertex(g);
      }
      m.tets.push_back(v);
    }
  // boundary vertices: on a face of a single tetrahedron
  std::map<std::array<std::uint32_t, 3>, int> faces;
  for(const auto& t : m.tets)
    for(int f = 0; f < 4; ++f) {
      std::array<std::uint32_t, 3> k;
      for(int i = 0, j = 0; i < 4; ++i)
        if(i != f) k[std::size_t(j++)] = t[std::size_t(i)];
      std::sort(k.begin(), k.end());
      ++faces[k];
    }
  std::vector<char> boundary(m.points.size(), 0);
  for(const auto& f : faces)
    if(f.second == 1)
      for(std::uint32_t v : f.first) boundary[v] = 1;
  const std::vector<std::array<std::uint32_t, 4> > tets = m.tets;
  m.tets.clear();
  for(const auto& t : tets) {
    std::array<Eigen::Vector3d, 4> p;
    for(std::size_t c = 0; c < 4; ++c) {
      const Eigen::Vector3d x(m.points[t[c]][0], m.points[t[c]][1], m.points[t[c]][2]);
      p[c] = x + (offset && !boundary[t[c]] ? offset(x) : Eigen::Vector3d::Zero());
    }
    m.add(t, p);
  }
  return m;
}

// Triangles (corners counterclockwise) each split into three kites (centre, midpoint of a side,
// corner, midpoint of the next side), every kite the unit square of its own chart, extruded by
// `layers`: a valence-3 axis through the centre of every triangle (three quarter turns around it).
Built_map kite_prism(const std::vector<Eigen::Vector2d>& corners, const std::vector<std::array<int, 3> >& triangles, int layers)
{
  Built_map m;
  std::vector<Eigen::Vector2d> plane = corners;
  std::map<std::pair<int, int>, std::uint32_t> midpoint;
  auto mid = [&](int a, int b) {
    const auto key = std::make_pair(std::min(a, b), std::max(a, b));
    auto it = midpoint.emplace(key, std::uint32_t(plane.size()));
    if(it.second) plane.push_back((corners[std::size_t(a)] + corners[std::size_t(b)]) / 2);
    return it.first->second;
  };
  std::vector<std::array<std::uint32_t, 4> > kites;
  for(const auto& t : triangles) {
    const std::uint32_t C = std::uint32_t(plane.size());
    plane.push_back((corners[std::size_t(t[0])] + corners[std::size_t(t[1])] + corners[std::size_t(t[2])]) / 3);
    for(int i = 0; i < 3; ++i)
      kites.push_back({{C, mid(t[std::size_t((i + 2) % 3)], t[std::size_t(i)]), std::uint32_t(t[std::size_t(i)]),
                        mid(t[std::size_t(i)], t[std::size_t((i + 1) % 3)])}});
  }
  for(int z = 0; z <= layers; ++z)
    for(const auto& q : plane) m.points.push_back({{q[0], q[1], double(z)}});
  const std::uint32_t per_level = std::uint32_t(plane.size());
  const std::array<Eigen::Vector2d, 4> square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  for(const auto& k : kites)
    for(const std::array<int, 3>& tri : {std::array<int, 3>{{0, 1, 2}}, std::array<int, 3>{{0, 2, 3}}})
      for(int z = 0; z < layers; ++z) {
        std::array<int, 3> s = tri; // kite corners sorted by vertex number: conforming diagonals
        std::sort(s.begin(), s.end(), [&](int a, int b) { return k[std::size_t(a)] < k[std::size_t(b)]; });
        const std::array<std::array<std::pair<int, int>, 4>, 3> split{{
          {{{s[0], z}, {s[1], z}, {s[2], z}, {s[0], z + 1}}},
          {{{s[1], z}, {s[2], z}, {s[0], z + 1}, {s[1], z + 1}}},
          {{{s[2], z}, {s[0], z + 1}, {s[1], z + 1}, {s[2], z + 1}}}}};
        for(const auto& tet : split) {
          std::array<std::uint32_t, 4> v;
          std::array<Eigen::Vector3d, 4> p;
          for(std::size_t c = 0; c < 4; ++c) {
            v[c] = k[std::size_t(tet[c].first)] + std::uint32_t(tet[c].second) * per_level;
            const Eigen::Vector2d& q = square[std::size_t(tet[c].first)];
            p[c] = Eigen::Vector3d(q[0], q[1], double(tet[c].second));
          }
          m.add(v, p);
        }
      }
  return m;
}

// The equilateral triangle: one valence-3 axis.
Built_map valence_three_prism(int layers)
{
  const double pi = std::acos(-1.0);
  std::vector<Eigen::Vector2d> P;
  for(int i = 0; i < 3; ++i) P.emplace_back(std::cos(pi / 2 + 2 * pi * i / 3), std::sin(pi / 2 + 2 * pi * i / 3));
  return kite_prism(P, {{{0, 1, 2}}}, layers);
}

MC::Motorcycle_complex trace(const Built_map& m) { return MC::trace_motorcycle_complex(m.points, m.tets, m.parameters); }

// The traced mesh is the same map: every tetrahedron positive, the same parameter volume.
MC::Rational parameter_volume(const MC::Exact_map_mesh& mesh, std::size_t& not_positive)
{
  MC::Rational v = 0;
  not_positive = 0;
  for(const MC::Map_tetrahedron& T : mesh.tetrahedra) {
    not_positive += MC::parameter_orientation(T) != CGAL::POSITIVE;
    std::array<std::array<MC::Rational, 3>, 3> d;
    for(std::size_t i = 0; i < 3; ++i)
      for(std::size_t k = 0; k < 3; ++k) d[i][k] = T.parameter[i + 1][k] - T.parameter[0][k];
    v += d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) - d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
         d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
  }
  return v / 6;
}

void expect_complex(const Built_map& m, std::size_t blocks, std::size_t patches, std::size_t arcs, std::size_t nodes,
                    MC::Motorcycle_complex* out = nullptr)
{
  MC::Motorcycle_complex mc = trace(m);
  const MC::Motorcycle_complex_report& r = mc.report;
  ASSERT_TRUE(r.success) << r.reason;
  EXPECT_EQ(r.blocks, blocks);
  EXPECT_EQ(r.patches, patches);
  EXPECT_EQ(r.arcs, arcs);
  EXPECT_EQ(r.nodes, nodes);
  // the same map: the split points are rounded to 2^-40 off the walls' planes
  std::size_t not_positive = 0;
  const MC::Rational after = parameter_volume(*mc.mesh, not_positive);
  EXPECT_EQ(not_positive, 0u);
  MC::Exact_map_mesh input(m.points, m.tets, m.parameters);
  std::size_t unused = 0;
  const MC::Rational before = parameter_volume(input, unused);
  if(r.split_edges == 0) EXPECT_EQ(after, before);
  EXPECT_NEAR(CGAL::to_double(after), CGAL::to_double(before), 1e-9);
  if(out) *out = std::move(mc);
}

std::set<std::array<int, 3> > box_cells(int a, int b, int c, const std::function<bool(int, int, int)>& keep = nullptr)
{
  std::set<std::array<int, 3> > s;
  for(int i = 0; i < a; ++i)
    for(int j = 0; j < b; ++j)
      for(int k = 0; k < c; ++k)
        if(!keep || keep(i, j, k)) s.insert({{i, j, k}});
  return s;
}

// The L of the unit squares (0,0), (1,0), (0,1), one unit high, in cells of 1/2.
std::set<std::array<int, 3> > l_cells()
{
  return box_cells(4, 4, 2, [](int i, int j, int) { return i < 2 || j < 2; });
}

} // namespace

// A cube: no wall leaves the boundary; one block, its 6 faces, 12 edges, 8 corners.
TEST(MotorcycleComplex, CubeIsOneBlock)
{
  const Built_map m = kuhn_cells(box_cells(3, 3, 3), 1.0 / 3);
  MC::Motorcycle_complex mc;
  expect_complex(m, 1, 6, 12, 8, &mc);
  EXPECT_EQ(mc.report.singular_edges, 0u);
  EXPECT_EQ(mc.report.feature_edges, 12u * 3u);
  EXPECT_EQ(mc.report.split_edges, 0u);
}

// The L-prism: the two walls of the concave edge cut it into 3 blocks. By hand, in the cross-section:
// 8 points (the 6 corners of the L, the 2 ends of the walls), 10 segments (6 sides, 2 of them cut in
// two, and the 2 walls), 3 rectangles; extruded: 16 nodes, 10 x 2 + 8 = 28 arcs, 3 x 2 + 10 = 16
// patches, 3 blocks (16 - 28 + 16 - 3 = 1, a ball).
TEST(MotorcycleComplex, LPrismIsThreeBlocks)
{
  expect_complex(kuhn_cells(l_cells(), 0.5), 3, 16, 28, 16);
}

// The same L with the map moved off the grid inside (boundary kept on its planes): the walls now
// cross tetrahedra and are traced through exact splits; same complex.
TEST(MotorcycleComplex, LPrismWithWallsThroughTetrahedra)
{
  const Built_map m = kuhn_cells(l_cells(), 0.5, [](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(0.05 * std::sin(7 * x[0] + 3 * x[1] + 11 * x[2]), 0.05 * std::cos(5 * x[0] + 13 * x[1] + 2 * x[2]),
                           0.05 * std::sin(3 * x[0] + 17 * x[1] + 5 * x[2]));
  });
  MC::Motorcycle_complex mc;
  expect_complex(m, 3, 16, 28, 16, &mc);
  EXPECT_GT(mc.report.split_edges, 0u);
}

// A prism around a valence-3 axis: three spokes from the axis to the midpoints of the sides, 3 blocks.
// Cross-section: 7 points (centre, 3 corners, 3 midpoints), 9 segments (6 half sides, 3 spokes), 3
// quadrilaterals; extruded by 2 layers: 14 nodes, 9 x 2 + 7 = 25 arcs, 3 x 2 + 9 = 15 patches.
TEST(MotorcycleComplex, ValenceThreePrismIsThreeBlocks)
{
  const Built_map m = valence_three_prism(2);
  MC::Motorcycle_complex mc;
  expect_complex(m, 3, 15, 25, 14, &mc);
  EXPECT_EQ(mc.report.singular_edges, 2u);
}

// A folded map has no complex, and says why.
TEST(MotorcycleComplex, FoldedMapIsRefused)
{
  Built_map m = kuhn_cells(box_cells(2, 2, 2), 0.5);
  m.parameters[0][0] += Eigen::Vector3d(0.7, 0.7, 0.7);
  const MC::Motorcycle_complex mc = trace(m);
  EXPECT_FALSE(mc.report.success);
  EXPECT_GT(mc.report.inverted_tetrahedra, 0u);
  EXPECT_EQ(mc.report.reason, "the map is not locally injective");
}

// The plus: five unit squares, four concave edges whose walls meet two by two on one plane (the
// sides of the middle square). Cross-section: 12 corners, 12 sides and 4 walls, 5 squares;
// extruded: 24 nodes, 16 x 2 + 12 = 44 arcs, 5 x 2 + 16 = 26 patches, 5 blocks.
TEST(MotorcycleComplex, PlusPrismIsFiveBlocks)
{
  expect_complex(kuhn_cells(box_cells(6, 6, 2, [](int i, int j, int) { return (i >= 2 && i < 4) || (j >= 2 && j < 4); }), 0.5),
                 5, 26, 44, 24);
}

namespace {

// Wall faces (not boundary) of the identity map on the plane x[axis] = value whose centroid has
// coordinate `along` in (lo, hi).
std::size_t wall_faces_on(const MC::Exact_map_mesh& mesh, int axis, double value, int along, double lo, double hi)
{
  std::set<std::array<std::uint32_t, 3> > seen;
  for(const MC::Map_tetrahedron& T : mesh.tetrahedra)
    for(int f = 0; f < 4; ++f) {
      if(T.wall[std::size_t(f)] < 0) continue;
      bool on = true;
      double c = 0;
      for(int i = 0; i < 4; ++i)
        if(i != f) {
          on = on && T.parameter[std::size_t(i)][std::size_t(axis)] == MC::Rational(value);
          c += CGAL::to_double(T.parameter[std::size_t(i)][std::size_t(along)]) / 3;
        }
      if(on && c > lo && c < hi) seen.insert(MC::Exact_map_mesh::face_key(T, f));
    }
  return seen.size();
}

} // namespace

// Walls that cross: the square [0,4]^2 without [0,1]^2 (concave corner A = (1,1)) and without
// [3,4] x [2,4] (concave corner B = (3,2)). A's wall x = 1 reaches y = 2 at distance 1, B's wall
// y = 2 reaches x = 1 at distance 2: A's goes on to the top, B's stops on it; B's wall x = 3 reaches
// y = 1 at distance 1, before A's wall y = 1 (distance 2), which stops on it. By hand: 12 points (8
// corners, 2 wall ends on the boundary, 2 T-junctions), 16 segments, 5 rectangles; extruded: 24
// nodes, 44 arcs, 26 patches, 5 blocks.
TEST(MotorcycleComplex, CrossingWallsStopInOrderOfDistance)
{
  const Built_map m = kuhn_cells(box_cells(8, 8, 2, [](int i, int j, int) { return !(i < 2 && j < 2) && !(i >= 6 && j >= 4); }), 0.5);
  MC::Motorcycle_complex mc;
  expect_complex(m, 5, 26, 44, 24, &mc);
  EXPECT_GT(wall_faces_on(*mc.mesh, 0, 1.0, 1, 2.5, 4.0), 0u);  // A's x = 1 above B's y = 2
  EXPECT_EQ(wall_faces_on(*mc.mesh, 1, 2.0, 0, 0.0, 1.0), 0u);  // B's y = 2 stopped at x = 1
  EXPECT_GT(wall_faces_on(*mc.mesh, 0, 3.0, 1, 0.0, 1.0), 0u);  // B's x = 3 below A's y = 1
  EXPECT_EQ(wall_faces_on(*mc.mesh, 1, 1.0, 0, 3.0, 4.0), 0u);  // A's y = 1 stopped at x = 3
}

namespace {

// The map's coordinates as their own variables: coordinate k of vertex v is variable 3 v + k.
struct Vertex_forms : MC::Map_forms
{
  CGAL::Hexahedral_remeshing::internal::Linear_form corner(std::uint32_t, std::uint32_t v, int axis) const override
  {
    CGAL::Hexahedral_remeshing::internal::Linear_form f;
    f.terms.emplace_back(Eigen::Index(3 * v + std::uint32_t(axis)), 1.0);
    return f;
  }
};

} // namespace

// The blocks of the L-prism as boxes: 3 blocks x 3 axes, every extent 1 (a unit cube each), as a
// function of the map's coordinates that gives the map's extent; kept apart (>= 1) where both sides
// are boundary: the 3 heights and the two arms across their width, not the walls' sides.
TEST(MotorcycleComplex, BlockExtentsOfTheLPrism)
{
  const Built_map m = kuhn_cells(l_cells(), 0.5);
  const Vertex_forms forms;
  const MC::Motorcycle_complex mc = MC::trace_motorcycle_complex(m.points, m.tets, m.parameters, 50, &forms);
  ASSERT_TRUE(mc.report.success) << mc.report.reason;
  EXPECT_EQ(mc.extents.extents.size(), 9u);
  EXPECT_EQ(mc.extents.sides_without_form, 0u);
  EXPECT_EQ(mc.extents.not_boxes, 0u);
  Eigen::VectorXd y(Eigen::Index(3 * m.points.size()));
  for(std::size_t v = 0; v < m.points.size(); ++v)
    for(int k = 0; k < 3; ++k) y[Eigen::Index(3 * v + std::size_t(k))] = m.points[v][std::size_t(k)];
  std::size_t separate = 0;
  for(const MC::Block_extent& e : mc.extents.extents) {
    EXPECT_EQ(e.seamless, MC::Rational(1));
    EXPECT_DOUBLE_EQ(e.form(y), 1.0);
    ASSERT_EQ(e.form.terms.size(), 2u);
    separate += e.separate;
  }
  EXPECT_EQ(separate, 5u);
}

// QGP3D's separation through stacked blocks: in the L-prism, the corner block and each arm are stacked
// along the arm, between two boundary sheets (the corner's outer face and the arm's end), through the
// wall between them, which is no entity. Neither block alone has two critical sides, but their two
// extents zero would merge the sheets: with every extent zero, exactly these two chains (corner x + arm
// x, corner y + other arm y), each 2 long in the map; with the arms' extents 1, none.
TEST(MotorcycleComplex, ZeroLengthPathsOfTheLPrism)
{
  const Built_map m = kuhn_cells(l_cells(), 0.5);
  const Vertex_forms forms;
  const MC::Motorcycle_complex mc = MC::trace_motorcycle_complex(m.points, m.tets, m.parameters, 50, &forms);
  ASSERT_TRUE(mc.report.success) << mc.report.reason;
  const std::vector<MC::Block_extent>& extents = mc.extents.extents;
  ASSERT_EQ(extents.size(), 9u);
  Eigen::VectorXd y(Eigen::Index(3 * m.points.size()));
  for(std::size_t v = 0; v < m.points.size(); ++v)
    for(int k = 0; k < 3; ++k) y[Eigen::Index(3 * v + std::size_t(k))] = m.points[v][std::size_t(k)];
  const std::vector<std::vector<std::uint32_t> > paths = MC::zero_length_paths(mc.extents, std::vector<double>(extents.size(), 0.0));
  ASSERT_EQ(paths.size(), 2u);
  std::set<std::uint32_t> arms;
  for(const auto& path : paths) {
    ASSERT_EQ(path.size(), 2u);
    EXPECT_NE(extents[path[0]].block, extents[path[1]].block);
    double length = 0;
    for(std::uint32_t i : path) {
      length += extents[i].form(y);
      EXPECT_FALSE(extents[i].separate);
    }
    EXPECT_DOUBLE_EQ(length, 2.0);
    // one end of each chain is the outer face of the corner block, the other the end of an arm
    EXPECT_TRUE(extents[path[0]].critical[0] || extents[path[0]].critical[1]);
    EXPECT_TRUE(extents[path[1]].critical[0] || extents[path[1]].critical[1]);
    for(std::uint32_t i : path) arms.insert(i);
  }
  EXPECT_EQ(arms.size(), 4u); // the corner's two extents and one of each arm
  // the corner block is in both chains; with the arms' extents 1 (or the corner's), no chain is left
  const std::uint32_t corner = extents[paths[0][0]].block == extents[paths[1][0]].block ||
                                   extents[paths[0][0]].block == extents[paths[1][1]].block
                                 ? extents[paths[0][0]].block
                                 : extents[paths[0][1]].block;
  for(bool arm : {true, false}) {
    std::vector<double> values(extents.size(), 0.0);
    std::size_t ones = 0;
    for(std::uint32_t i : arms)
      if((extents[i].block != corner) == arm) { values[i] = 1.0; ++ones; }
    EXPECT_EQ(ones, 2u);
    EXPECT_TRUE(MC::zero_length_paths(mc.extents, values).empty());
  }
  // one arm 1, the other 0: one chain left
  std::vector<double> values(extents.size(), 0.0);
  values[extents[paths[0][0]].block == corner ? paths[0][1] : paths[0][0]] = 1.0;
  EXPECT_EQ(MC::zero_length_paths(mc.extents, values).size(), 1u);
}

// Two valence-3 axes: the rhombus of two triangles, each in three kites. The spoke of each axis
// towards the shared side goes on straight through the side's midpoint (four kites there) to the other
// axis: one wall joins the two curves. The kites on either side of the shared side make one block
// each (that side is no wall), a box whose two ends are on the two curves. By hand, in the cross-
// section: 8 nodes (the 2 axes, the 4 ends of the other spokes, the 2 far corners; the near corners are
// flat in the map, 90 + 90 degrees), 11 arcs (5 walls, 6 boundary pieces), 4 blocks; one layer
// extruded: 16 nodes, 11 x 2 + 8 = 30 arcs, 4 x 2 + 11 = 19 patches. Every extent has a curve or
// the whole boundary on both sides: all 12 kept >= 1 (the two curves are 2 apart along their wall).
TEST(MotorcycleComplex, TwoValenceThreeAxesAreKeptApart)
{
  const std::vector<Eigen::Vector2d> P{{0, 0}, {1, -0.6}, {1, 0.6}, {2, 0}};
  const Built_map m = kite_prism(P, {{{0, 1, 2}}, {{1, 3, 2}}}, 1);
  const Vertex_forms forms;
  const MC::Motorcycle_complex mc = MC::trace_motorcycle_complex(m.points, m.tets, m.parameters, 50, &forms);
  ASSERT_TRUE(mc.report.success) << mc.report.reason;
  EXPECT_EQ(mc.report.singular_edges, 2u);
  EXPECT_EQ(mc.report.blocks, 4u);
  EXPECT_EQ(mc.report.patches, 19u);
  EXPECT_EQ(mc.report.arcs, 30u);
  EXPECT_EQ(mc.report.nodes, 16u);
  EXPECT_EQ(mc.extents.extents.size(), 12u);
  std::size_t separate = 0, two = 0;
  for(const MC::Block_extent& e : mc.extents.extents) {
    separate += e.separate;
    two += e.seamless == MC::Rational(2);
  }
  EXPECT_EQ(separate, 12u);
  EXPECT_EQ(two, 2u); // the two merged blocks, from one axis to the other
}

// The corner values of a map with jumps as functions of y = the vertices' coordinates in the model: a
// corner's value is its vertex's variable plus the jump of its tetrahedron's chart there (a constant),
// so the translations between charts are those constants.
struct Chart_forms : MC::Map_forms
{
  const Built_map& map;
  explicit Chart_forms(const Built_map& m) : map(m) {}
  CGAL::Hexahedral_remeshing::internal::Linear_form corner(std::uint32_t t, std::uint32_t v, int axis) const override
  {
    CGAL::Hexahedral_remeshing::internal::Linear_form f;
    f.terms.emplace_back(Eigen::Index(3 * v + std::uint32_t(axis)), 1.0);
    for(std::size_t c = 0; c < 4; ++c)
      if(map.tets[t][c] == v) f.constant = map.parameters[t][c][std::size_t(axis)] - map.points[v][std::size_t(axis)];
    return f;
  }
};

// A toroidal block: the box [0,4] x [0,1] x [0,1] with its ends x = 0 and x = 4 glued (the map jumps by
// 4 there: a translation, no rotation, so no singular edge). The feature edges run around the ring in
// the boundary planes: no wall enters the part, which stays one block whose four faces are annuli
// bounded by four closed arcs without a node. Its extents across the ring (y, z) are 1, between
// boundary sides, kept apart; the one around it (x) is the ring's period, 4 (the jump), kept >= 1:
// it is what a wall cutting the ring would give between its two sides.
TEST(MotorcycleComplex, ToroidalBlockIsOneBlockWithClosedArcs)
{
  Built_map m = kuhn_cells(box_cells(4, 1, 1), 1.0);
  std::map<std::array<double, 3>, std::uint32_t> at;
  for(std::uint32_t v = 0; v < m.points.size(); ++v) at.emplace(m.points[v], v);
  for(auto& t : m.tets)
    for(auto& v : t)
      if(m.points[v][0] == 4.0) v = at.at({{0.0, m.points[v][1], m.points[v][2]}});
  const Chart_forms forms(m);
  const MC::Motorcycle_complex mc = MC::trace_motorcycle_complex(m.points, m.tets, m.parameters, 50, &forms);
  ASSERT_TRUE(mc.report.success) << mc.report.reason;
  EXPECT_EQ(mc.report.singular_edges, 0u);
  EXPECT_EQ(mc.report.feature_edges, 16u);
  EXPECT_EQ(mc.report.split_edges, 0u);
  EXPECT_EQ(mc.report.blocks, 1u);
  EXPECT_EQ(mc.report.patches, 4u);
  EXPECT_EQ(mc.report.arcs, 4u);
  EXPECT_EQ(mc.report.nodes, 0u);
  ASSERT_EQ(mc.extents.extents.size(), 3u);
  EXPECT_EQ(mc.extents.sides_without_form, 0u);
  EXPECT_EQ(mc.extents.not_boxes, 0u);
  EXPECT_EQ(mc.extents.rings, 1u);
  Eigen::VectorXd y(Eigen::Index(3 * m.points.size()));
  for(std::size_t v = 0; v < m.points.size(); ++v)
    for(int k = 0; k < 3; ++k) y[Eigen::Index(3 * v + std::size_t(k))] = m.points[v][std::size_t(k)];
  std::array<double, 3> extent{{0, 0, 0}};
  for(const MC::Block_extent& e : mc.extents.extents) {
    EXPECT_TRUE(e.separate);
    extent[std::size_t(e.axis)] = e.form(y);
    EXPECT_EQ(MC::Rational(e.form(y)), e.seamless);
    // around the ring: the jump alone, whatever the vertices' positions
    if(e.axis == 0) for(const auto& term : e.form.terms) EXPECT_EQ(term.second, 0.0);
  }
  EXPECT_EQ(extent[0], 4.0);
  EXPECT_EQ(extent[1], 1.0);
  EXPECT_EQ(extent[2], 1.0);
}

namespace {

// The sign of det[p1 - p0, p2 - p0, p3 - p0], by rational arithmetic in the test.
CGAL::Sign exact_orientation(const std::array<MC::Parameter, 4>& p)
{
  MC::Rational d[3][3];
  for(int i = 0; i < 3; ++i)
    for(int k = 0; k < 3; ++k) d[i][k] = p[std::size_t(i + 1)][std::size_t(k)] - p[0][std::size_t(k)];
  const MC::Rational det = d[0][0] * d[1][1] * d[2][2] + d[0][1] * d[1][2] * d[2][0] + d[0][2] * d[1][0] * d[2][1] -
                           d[0][2] * d[1][1] * d[2][0] - d[0][0] * d[1][2] * d[2][1] - d[0][1] * d[1][0] * d[2][2];
  return CGAL::sign(det);
}

MC::Map_tetrahedron tetrahedron(const std::array<MC::Parameter, 4>& p)
{
  MC::Map_tetrahedron T;
  T.vertex = {{0, 1, 2, 3}};
  T.parameter = p;
  return T;
}

} // namespace

// The orientation of a tetrahedron in parameter space is filtered by interval arithmetic: where the
// intervals cannot tell (a determinant of -2^-104 from entries near 1, whose products round), where a
// coordinate is not a double (1/3), and on a flat tetrahedron, it must still be the exact sign.
TEST(MotorcycleComplex, OrientationIsExactWhereIntervalsCannotTell)
{
  const double u = std::ldexp(1.0, -52);
  const MC::Parameter o = MC::exact_parameter(0, 0, 0);
  // rows (1 + u, 1, 0), (1, 1 - u, 0), (0, 0, 1): det = (1 + u)(1 - u) - 1 = -u^2
  const std::array<MC::Parameter, 4> close{{o, MC::exact_parameter(1 + u, 1, 0), MC::exact_parameter(1, 1 - u, 0), MC::exact_parameter(0, 0, 1)}};
  EXPECT_EQ(exact_orientation(close), CGAL::NEGATIVE);
  EXPECT_EQ(MC::parameter_orientation(tetrahedron(close)), CGAL::NEGATIVE);
  std::array<MC::Parameter, 4> swapped = close;
  std::swap(swapped[1], swapped[2]);
  EXPECT_EQ(MC::parameter_orientation(tetrahedron(swapped)), CGAL::POSITIVE);
  // a third, and a point on the plane of the other three (flat)
  const MC::Rational third(1, 3);
  std::array<MC::Parameter, 4> thirds{{o, MC::Parameter{{third, 0, 0}}, MC::Parameter{{0, third, 0}}, MC::Parameter{{0, 0, third}}}};
  EXPECT_EQ(exact_orientation(thirds), CGAL::POSITIVE);
  EXPECT_EQ(MC::parameter_orientation(tetrahedron(thirds)), CGAL::POSITIVE);
  thirds[3] = MC::Parameter{{third, third, 0}};
  EXPECT_EQ(exact_orientation(thirds), CGAL::ZERO);
  EXPECT_EQ(MC::parameter_orientation(tetrahedron(thirds)), CGAL::ZERO);
  // 2^-200 above that plane: positive
  MC::Rational epsilon(1);
  for(int i = 0; i < 200; ++i) epsilon = epsilon / 2;
  thirds[3][2] = epsilon;
  EXPECT_EQ(exact_orientation(thirds), CGAL::POSITIVE);
  EXPECT_EQ(MC::parameter_orientation(tetrahedron(thirds)), CGAL::POSITIVE);
}
