// Tests of the whole frame-field pipeline (valences -> constraints -> frame field -> matchings ->
// realignment): the prism and acute-edge oracles, every shared model, realignment invariants,
// determinism across thread counts, and the Surface_mesh entry.
#include "data_paths.h"
#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/boundary_dihedral_angles.h>
#include <CGAL/Hexahedral_remeshing/frame_field_pipeline.h>

#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include "shared_models.h"

#ifdef _OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

namespace HR = CGAL::Hexahedral_remeshing;
typedef HR::Tetrahedral_mesh_3<> Mesh;
typedef Mesh::Index Index;
typedef Mesh::Point_3 Point;
namespace fs = std::filesystem;

namespace {

const std::string example_data = HEXREM_EXAMPLE_DATA_DIR;

Mesh load(const std::string& file, double max_volume = 0)
{
  Mesh m;
  HR::IO::read_tetrahedral_mesh(file, m, HR::parameters::split_boundary_chords(true,
                                           HR::parameters::maximum_tetrahedron_volume(max_volume)));
  return m;
}

// A right triangular prism whose cross-section has angles 90 (at A), 30 (at B) and 60 degrees,
// extruded along z over [0, 1], tetrahedralized with TetGen.
Mesh prism_30_60_90()
{
  const double c = 1.0 / std::sqrt(3.0);
  const std::string off = (fs::temp_directory_path() / "hexrem_prism_30_60_90.off").string();
  {
    std::ofstream out(off);
    out.precision(17);
    out << "OFF\n6 8 0\n0 0 0\n1 0 0\n0 " << c << " 0\n0 0 1\n1 0 1\n0 " << c << " 1\n"
        << "3 0 2 1\n3 3 4 5\n3 0 1 4\n3 0 4 3\n3 1 2 5\n3 1 5 4\n3 2 0 3\n3 2 3 5\n";
  }
  Mesh m = load(off, 0.0005);
  std::remove(off.c_str());
  return m;
}

bool vertical(const Mesh& m, Index e)
{
  const auto& ev = m.edge_vertices(e);
  return m.point(ev[0]).x() == m.point(ev[1]).x() && m.point(ev[0]).y() == m.point(ev[1]).y();
}


void check_realignment(const Mesh& m, const HR::Frame_field_pipeline_result& r)
{
  ASSERT_TRUE(r.realigned);
  EXPECT_LT(r.realignment.alignment_error, 1e-9);
  EXPECT_LT(r.realignment.constraint_error, 1e-9);
  // every constrained tet has an axis exactly on its face normal
  const auto normals = HR::boundary_triangle_unit_normals(m);
  for(Index b = 0; b < m.number_of_boundary_triangles(); ++b) {
    const Eigen::Vector3d c = r.frames[m.boundary_triangle_tetrahedron(b)].transpose() * normals[b];
    ASSERT_NEAR(c.cwiseAbs().maxCoeff(), 1.0, 1e-9);
  }
  for(const Eigen::Matrix3d& E : r.frames) ASSERT_NEAR(E.determinant(), 1.0, 1e-9);
}

} // namespace

TEST(Pipeline, PrismBaselineBreaksTheThirtyDegreeEdge)
{
  const Mesh m = prism_30_60_90();
  const auto r = HR::compute_frame_field_pipeline(m, HR::parameters::baseline(true));
  std::size_t thirty = 0;
  for(Index e : m.boundary_edges())
    if(vertical(m, e) && HR::boundary_edge_dihedral_class(m, e) == 0) {
      ++thirty;
      EXPECT_EQ(r.boundary_valences.achieved[e], 0);
    }
  EXPECT_GT(thirty, 0u);
  EXPECT_EQ(r.singularities.valence3_edges + r.singularities.valence5_edges, 0u);
}

TEST(Pipeline, PrismWithConstraintsGetsValenceOneAndOneInteriorCurve)
{
  const Mesh m = prism_30_60_90();
  const auto r = HR::compute_frame_field_pipeline(m);
  EXPECT_LT(r.constraints.final_energy, CGAL_PI / 4);
  EXPECT_EQ(r.boundary_valences.mismatched, 0u);
  for(Index e : m.boundary_edges())
    if(vertical(m, e) && HR::boundary_edge_dihedral_class(m, e) != 2) EXPECT_EQ(r.boundary_valences.achieved[e], 1);
  EXPECT_EQ(r.singularities.valence5_edges, 0u);
  EXPECT_EQ(r.singularities.improper_edges, 0u);
  ASSERT_EQ(r.singularities.number_of_curves(3), 1u);
  const HR::Singular_curve& c = r.singularities.curves.front();
  const double z0 = m.point(c.vertices.front()).z(), z1 = m.point(c.vertices.back()).z();
  EXPECT_EQ(std::min(z0, z1), 0.0); // from cap to cap
  EXPECT_EQ(std::max(z0, z1), 1.0);
  check_realignment(m, r);
  EXPECT_EQ(r.realignment.changed_edges, 0u);
}

TEST(Pipeline, AcuteEdgeGetsValenceOne)
{
  const Mesh m = load(example_data + "/n13c_acute_line.vtk");
  const auto baseline = HR::compute_frame_field_pipeline(m, HR::parameters::baseline(true));
  const auto ours = HR::compute_frame_field_pipeline(m);
  EXPECT_GT(ours.constraints.initial_energy, CGAL_PI / 4);
  EXPECT_LT(ours.constraints.final_energy, CGAL_PI / 4);
  std::size_t acute = 0;
  for(Index e : m.boundary_edges())
    if(HR::boundary_edge_dihedral_class(m, e) == 0) {
      ++acute;
      EXPECT_EQ(baseline.boundary_valences.achieved[e], 0);
      EXPECT_EQ(ours.boundary_valences.achieved[e], 1);
    }
  EXPECT_GE(acute, 8u);
  EXPECT_EQ(ours.boundary_valences.mismatched, 0u);
  check_realignment(m, ours);
}

TEST(Pipeline, SurfaceMeshInput)
{
  CGAL::Surface_mesh<Point> cube;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(example_data + "/cube.off", cube));
  HR::Tetrahedral_soup_3<Point> soup;
  HR::tetrahedralize_surface(cube, soup, HR::parameters::maximum_tetrahedron_volume(0.002));
  Mesh m;
  HR::build_tetrahedral_mesh(soup, m);
  const auto r = HR::compute_frame_field_pipeline(m);
  EXPECT_LT(r.frame_field.energy, 1e-10);
  EXPECT_EQ(r.singularities.valence3_edges + r.singularities.valence5_edges + r.singularities.improper_edges, 0u);
  EXPECT_EQ(r.boundary_valences.mismatched, 0u);
  check_realignment(m, r);
  EXPECT_EQ(r.realignment.changed_matchings, 0u);
}

#ifdef _OPENMP
// The pipeline on m with 1 thread, then 2: bitwise the same frames, directions and energy. Returns
// the second.
HR::Frame_field_pipeline_result same_with_one_and_two_threads(const Mesh& m)
{
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto one = HR::compute_frame_field_pipeline(m);
  omp_set_num_threads(2);
  auto two = HR::compute_frame_field_pipeline(m);
  omp_set_num_threads(saved);
  EXPECT_EQ(one.frames.size(), two.frames.size());
  for(std::size_t t = 0; t < one.frames.size() && t < two.frames.size(); ++t)
    if(!(one.frames[t] == two.frames[t])) { ADD_FAILURE() << "tet " << t; break; }
  EXPECT_EQ(one.directions, two.directions);
  EXPECT_EQ(one.frame_field.energy, two.frame_field.energy);
  return two;
}
#endif

TEST(Pipeline, DeterministicWhateverTheThreadCount)
{
#ifdef _OPENMP
  same_with_one_and_two_threads(load(example_data + "/n13c_acute_line.vtk"));
#else
  GTEST_SKIP() << "built without OpenMP";
#endif
}

// The pipeline computes the solvers' order of the tets once and passes it to the frame field and
// the realignment: the same result as each computing its own. Given the mesh's own order instead, the
// realignment solves the same system (same frames up to its tolerance); orders that are not
// permutations are rejected. (Without the repair of the singularity graph, which re-optimizes the
// realigned frames with other matchings.)
void check_one_order_for_both_solvers(const Mesh& m)
{
  const HR::Frame_field_pipeline_result r = HR::compute_frame_field_pipeline(m, HR::parameters::singularity_repair(false));
  const std::size_t nt = m.number_of_tetrahedra();
  ASSERT_GE(nt, 30000u);
  std::vector<std::uint32_t> order = HR::solver_tetrahedron_order(m);
  std::vector<std::uint32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  ASSERT_EQ(sorted.size(), nt);
  for(std::size_t i = 0; i < nt; ++i) ASSERT_EQ(sorted[i], i);
  EXPECT_NE(order, sorted); // not the mesh's order: the test below compares two different orders
  EXPECT_TRUE(HR::solver_tetrahedron_order(load(example_data + "/n13c_acute_line.vtk")).empty());

  std::vector<Eigen::Matrix3d> frames;
  HR::compute_frame_field(m, r.directions, frames, HR::parameters::fixed_frames(r.fixed_frames));
  const std::vector<Eigen::Matrix3d> field = frames;
  HR::realign_frame_field(m, frames, r.matchings, r.directions);
  ASSERT_EQ(frames.size(), r.frames.size());
  for(std::size_t t = 0; t < nt; ++t)
    if(!(frames[t] == r.frames[t])) { ADD_FAILURE() << "tet " << t; break; }

  frames = field;
  const auto own = HR::realign_frame_field(m, frames, r.matchings, r.directions,
                                           HR::parameters::tetrahedron_order(std::vector<std::uint32_t>()));
  EXPECT_EQ(own.changed_matchings, 0u);
  double largest = 0;
  for(std::size_t t = 0; t < nt; ++t) largest = (std::max)(largest, (frames[t] - r.frames[t]).cwiseAbs().maxCoeff());
  EXPECT_LT(largest, 1e-3);
  EXPECT_GT(largest, 0.0); // another order sums in another order

  std::vector<std::uint32_t> twice = order;
  twice[1] = twice[0];
  std::vector<std::uint32_t> short_order(order.begin(), order.end() - 1);
  for(const auto& bad : {twice, short_order}) {
    frames = field;
    EXPECT_THROW(HR::realign_frame_field(m, frames, r.matchings, r.directions, HR::parameters::tetrahedron_order(bad)),
                 HR::Error);
    EXPECT_THROW(HR::compute_frame_field(m, r.directions, frames, HR::parameters::tetrahedron_order(bad)), HR::Error);
  }
}

// Above 30,000 tets the frame field and the realignment solve in a Hilbert order of the tets and
// with the multigrid: still bitwise the same with 1 and 2 threads, and the realigned frames come back
// in the mesh's order (each boundary tet keeps an axis on its own normal, no matching changes); the
// order both use is computed once.
TEST(Pipeline, LargeMeshDeterministicAndInTheMeshOrder)
{
#ifdef _OPENMP
  const Mesh m = load(example_data + "/cylinder.off", 0.0004);
  ASSERT_GE(m.number_of_tetrahedra(), 30000u);
  const auto two = same_with_one_and_two_threads(m);
  check_realignment(m, two);
  EXPECT_EQ(two.realignment.changed_matchings, 0u);
  EXPECT_EQ(two.realignment.changed_edges, 0u);
  EXPECT_EQ(two.singularities.number_of_curves(3), 4u);
  check_one_order_for_both_solvers(m);
#else
  GTEST_SKIP() << "built without OpenMP";
#endif
}

// Every shared model with the default (low_angle) heuristic. Known deviations, measured on this
// build (models built with split_boundary_chords): the test fails if a model gets worse or if a
// model that is not listed deviates.
TEST(Pipeline, EverySharedModel)
{
  const auto files = shared_models();
  if(files.empty()) GTEST_SKIP() << "../shared/data not present";
  // boundary edges whose achieved valence differs from the prescribed one although E(v) < pi/4
  const std::map<std::string, std::size_t> known_valence_mismatches = {
    {"i01c_m1", 37}, {"n01c_cross_cyls_sr", 1}, {"n04c_transition_prism", 3}, {"n06c_anti_pentapyr", 1},
    {"n10c_qtorus_cyl", 2}, {"s08c_cross_cyls_dr", 2}, {"s12c_cube_rounded_1", 1}, {"B1_tet", 1}};
  // interior faces whose matching, recomputed on the realigned field, differs from the kept one
  // (the realigned field turns by more than 45 degrees between two tets of a thin feature wedge)
  // (s12c: 37 and no valence mismatch, s13c: 12, before their 41 and 38 edges of 135 degrees that the
  // coordinates' rounding put below the tie got valence 2 like the rest of their curves,
  // boundary_edge_near_tie_class())
  const std::map<std::string, std::size_t> known_changed_matchings = {
    {"i01c_m1", 2}, {"n04c_transition_prism", 21}, {"n05c_box_min_pcyls", 4}, {"n10c_qtorus_cyl", 9},
    {"n13c_acute_line", 8}, {"s08c_cross_cyls_dr", 1}, {"s12c_cube_rounded_1", 67}, {"s13c_cube_rounded_2", 19},
    {"B1_tet", 1}, {"B41", 24}};
  // interior edges whose type changes when evaluated on the realigned frames (the matchings are
  // kept, so only the 3/5 sign of edges nearly perpendicular to their holonomy axis can change)
  const std::map<std::string, std::size_t> known_changed_edges = {
    {"i01c_m1", 3}, {"n01c_cross_cyls_sr", 2}, {"n05c_box_min_pcyls", 2}, {"n10c_qtorus_cyl", 1},
    {"s12c_cube_rounded_1", 5}, {"s13c_cube_rounded_2", 1}};
  auto allowed = [](const std::map<std::string, std::size_t>& known, const std::string& name) {
    return known.count(name) ? known.at(name) : std::size_t(0);
  };
  for(const std::string& f : files) {
    SCOPED_TRACE(f);
    const std::string name = fs::path(f).stem().string();
    const Mesh m = load(f);
    const auto r = HR::compute_frame_field_pipeline(m);
    EXPECT_LT(r.constraints.final_energy, CGAL_PI / 4);
    EXPECT_LE(r.boundary_valences.mismatched, allowed(known_valence_mismatches, name)) << name;
    EXPECT_EQ(r.boundary_valences.total, m.boundary_edges().size());
    check_realignment(m, r);
    EXPECT_LE(r.realignment.changed_matchings, allowed(known_changed_matchings, name)) << name;
    EXPECT_LE(r.realignment.changed_edges, allowed(known_changed_edges, name)) << name;
    std::printf("%-28s tets %6zu  E(n) %.3f  E(v) %.3f  v3 %zu/%zu curves  v5 %zu/%zu  improper %zu  "
                "boundary %zu/%zu  changed matchings %zu edges %zu  %.2f s\n",
                name.c_str(), m.number_of_tetrahedra(), r.constraints.initial_energy, r.constraints.final_energy,
                r.singularities.valence3_edges, r.singularities.number_of_curves(3), r.singularities.valence5_edges,
                r.singularities.number_of_curves(5), r.singularities.improper_edges, r.boundary_valences.matched,
                r.boundary_valences.total, r.realignment.changed_matchings, r.realignment.changed_edges, r.seconds);
  }
}

// The band of fixed frames along the 10-degree edge: without it (and without the repair, whose sweeps
// take most of the curve off the edge too) the field's valence-3 curve runs through the vertices of the
// edge (the known failure of the map); with it no curve vertex is on the edge, the band's frames are the
// returned ones, and every boundary valence stays as prescribed.
TEST(Pipeline, AcuteEdgeBandKeepsTheCurveOffTheEdge)
{
  const Mesh m = load(example_data + "/n13c_acute_line.vtk");
  std::set<Index> acute_vertices;
  for(Index e : m.boundary_edges())
    if(HR::boundary_edge_dihedral_class(m, e) == 0)
      for(Index v : m.edge_vertices(e)) acute_vertices.insert(v);
  ASSERT_GE(acute_vertices.size(), 9u);
  auto on_acute_edge = [&](Index v) { return acute_vertices.count(v) > 0; };
  auto curve_vertices_on_edge = [&](const HR::Frame_field_pipeline_result& r) {
    std::size_t n = 0;
    for(const auto& c : r.singularities.curves)
      for(Index v : c.vertices) n += on_acute_edge(v);
    return n;
  };
  const auto without =
    HR::compute_frame_field_pipeline(m, HR::parameters::singularity_repair(false, HR::parameters::realignment(false)));
  EXPECT_TRUE(without.fixed_frames.empty());
  EXPECT_GT(curve_vertices_on_edge(without), 2u);

  const auto r = HR::compute_frame_field_pipeline(m, HR::parameters::acute_edge_band_radius(0.07, HR::parameters::realignment(false)));
  ASSERT_EQ(r.singularities.number_of_curves(3), 1u);
  EXPECT_EQ(curve_vertices_on_edge(r), 0u);
  ASSERT_FALSE(r.fixed_frames.empty());
  EXPECT_GT(r.redirected_directions, 0u);
  for(const auto& f : r.fixed_frames) ASSERT_TRUE(r.frames[f.first] == f.second);
  // every tetrahedron with a vertex on the edge is in the band
  std::size_t touching = 0;
  for(Index t = 0; t < m.number_of_tetrahedra(); ++t) {
    bool touches = false;
    for(Index v : m.tetrahedron_vertices(t)) touches = touches || on_acute_edge(v);
    touching += touches;
  }
  EXPECT_GE(r.fixed_frames.size(), touching);
  EXPECT_LT(r.constraints.final_energy, CGAL_PI / 4);
  EXPECT_EQ(r.boundary_valences.mismatched, 0u);
  for(Index e : m.boundary_edges())
    if(HR::boundary_edge_dihedral_class(m, e) == 0) EXPECT_EQ(r.boundary_valences.achieved[e], 1);

  EXPECT_THROW(HR::compute_frame_field_pipeline(m, HR::parameters::acute_edge_band_radius(-1.0)), HR::Input_error);
  EXPECT_THROW(HR::compute_frame_field_pipeline(m, HR::parameters::acute_edge_band_radius(std::nan(""))), HR::Input_error);
}
