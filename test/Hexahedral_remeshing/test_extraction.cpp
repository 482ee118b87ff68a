// Tests of the .hexex IO, of the integer-grid map check and of the hexahedral extraction.
#include "data_paths.h"
#include <CGAL/Hexahedral_remeshing/IO/read_HexEx.h>
#include <CGAL/Hexahedral_remeshing/IO/write_HexEx.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_extraction.h>

#include <gtest/gtest.h>

#include "hex_mesh_generators.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace HR = CGAL::Hexahedral_remeshing;
namespace fs = std::filesystem;

namespace {

const std::string hexex_data = std::string(HEXREM_TEST_DATA_DIR) + "/hexex/";
const std::string igm_data = std::string(HEXREM_SHARED_DATA_DIR) + "/igm/";

HR::Integer_grid_map read(const std::string& file)
{
  HR::Integer_grid_map map;
  HR::IO::read_HexEx(file, map);
  return map;
}

// Independent measures of an extracted hex mesh (not the package's checker).
struct Hex_measures
{
  double min_sj = 2., mean_sj = 0.;
  std::size_t boundary_quads = 0, nonconforming_quads = 0, unused_vertices = 0, bad_boundary_tags = 0;
  std::map<int, std::size_t> interior_irregular, boundary_irregular;
};

double corner_sj(const std::array<Eigen::Vector3d, 8>& p, int i)
{
  static const int nb[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7}, {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
  Eigen::Vector3d e[3];
  for(int k = 0; k < 3; ++k) {
    e[k] = p[nb[i][k]] - p[i];
    const double n = e[k].norm();
    if(n == 0.) return 0.;
    e[k] /= n;
  }
  return e[0].dot(e[1].cross(e[2]));
}

Hex_measures measure(const HR::Hexahedral_mesh_3& m)
{
  Hex_measures r;
  // outward faces of a VTK hexahedron
  static const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  std::map<std::array<std::uint32_t, 4>, std::vector<std::array<std::uint32_t, 4> > > quads;
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_hexes;
  std::vector<char> used(m.points.size(), 0);
  for(const auto& h : m.hexahedra) {
    std::array<Eigen::Vector3d, 8> p;
    for(int i = 0; i < 8; ++i) {
      p[i] = Eigen::Vector3d(m.points[h[i]].x(), m.points[h[i]].y(), m.points[h[i]].z());
      used[h[i]] = 1;
    }
    double sj = 2.;
    for(int i = 0; i < 8; ++i) sj = (std::min)(sj, corner_sj(p, i));
    r.min_sj = (std::min)(r.min_sj, sj);
    r.mean_sj += sj / double(m.hexahedra.size());
    for(const auto& f : faces) {
      std::array<std::uint32_t, 4> c = {{h[f[0]], h[f[1]], h[f[2]], h[f[3]]}};
      std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
      std::array<std::uint32_t, 4> key = c;
      std::sort(key.begin(), key.end());
      quads[key].push_back(c);
    }
    static const int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    for(const auto& e : edges) ++edge_hexes[std::minmax(h[e[0]], h[e[1]])];
  }
  std::set<std::pair<std::uint32_t, std::uint32_t> > boundary_edges;
  std::set<std::uint32_t> boundary_vertices;
  for(const auto& kv : quads) {
    if(kv.second.size() == 1) {
      ++r.boundary_quads;
      const auto& c = kv.second[0];
      for(int i = 0; i < 4; ++i) {
        boundary_edges.insert(std::minmax(c[i], c[(i + 1) % 4]));
        boundary_vertices.insert(c[i]);
      }
    } else if(kv.second.size() == 2) {
      const auto& a = kv.second[0];
      const std::array<std::uint32_t, 4> reversed = {{a[0], a[3], a[2], a[1]}};
      if(kv.second[1] != reversed) ++r.nonconforming_quads;
    } else {
      r.nonconforming_quads += kv.second.size();
    }
  }
  for(const auto& kv : edge_hexes) {
    if(boundary_edges.count(kv.first)) { if(kv.second != 2) ++r.boundary_irregular[kv.second]; }
    else if(kv.second != 4) ++r.interior_irregular[kv.second];
  }
  for(std::size_t v = 0; v < m.points.size(); ++v) {
    r.unused_vertices += used[v] ? 0 : 1;
    if(!m.vertex_tags.empty() && used[v]) {
      const bool tagged = (m.vertex_tags[v] & HR::Hexahedral_mesh_3::BOUNDARY) != 0;
      if(tagged != (boundary_vertices.count(std::uint32_t(v)) > 0)) ++r.bad_boundary_tags;
    }
  }
  return r;
}

std::string error_of_file(const std::string& name)
{
  try {
    read(hexex_data + name);
  } catch(const HR::Input_error& e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST(HexExIO, HostileFilesAreRejectedWithTheLine)
{
  struct Case { const char* file; const char* says; };
  const Case cases[] = {
    {"truncated.hexex", "unexpected end of file"},
    {"huge_count.hexex", "exceeds what the file holds"},
    {"negative_count.hexex", "negative count"},
    {"nan.hexex", "non-finite"},
    {"inf.hexex", "non-finite"},
    {"id_out_of_range.hexex", "out of range"},
    {"repeated_id.hexex", "repeated vertex"},
    {"zero_denominator.hexex", "zero denominator"},
    {"malformed.hexex", "malformed number"},
    {"trailing.hexex", "unexpected content"},
  };
  for(const Case& c : cases) {
    const std::string what = error_of_file(c.file);
    EXPECT_NE(what.find(c.says), std::string::npos) << c.file << ": " << what;
    EXPECT_NE(what.find(c.file), std::string::npos) << what;
  }
  // the line of the problem is named: the NaN is on line 7
  EXPECT_NE(error_of_file("nan.hexex").find("nan.hexex:7:"), std::string::npos);
  EXPECT_THROW(read(hexex_data + "does_not_exist.hexex"), HR::Input_error);
}

TEST(HexExIO, RationalsAsMC3DWritesThem)
{
  const HR::Integer_grid_map map = read(hexex_data + "rational.hexex");
  ASSERT_EQ(map.points.size(), 4u);
  ASSERT_EQ(map.tetrahedra.size(), 1u);
  EXPECT_EQ(map.points[1].x(), 1.);
  EXPECT_EQ(map.parameters[0][1][0], 0.5);
  EXPECT_EQ(map.parameters[0][3][2], 0.5);
}

TEST(HexExIO, RoundTripIsBitExact)
{
  HR::Integer_grid_map map = read(hexex_data + "two_cubes.hexex");
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1e3, 1e3);
  for(auto& p : map.points) p = HR::Integer_grid_map::Point_3(U(rng), U(rng) * 1e-7, U(rng) * 1e11);
  for(auto& t : map.parameters)
    for(auto& u : t) u = Eigen::Vector3d(U(rng), U(rng) * 1e-9, 1. / 3.);
  const std::string file = (fs::temp_directory_path() / "test_extraction_roundtrip.hexex").string();
  HR::IO::write_HexEx(file, map);
  const HR::Integer_grid_map back = read(file);
  std::remove(file.c_str());
  ASSERT_EQ(back.points.size(), map.points.size());
  ASSERT_EQ(back.tetrahedra, map.tetrahedra);
  for(std::size_t i = 0; i < map.points.size(); ++i) EXPECT_TRUE(back.points[i] == map.points[i]);
  for(std::size_t t = 0; t < map.parameters.size(); ++t)
    for(int k = 0; k < 4; ++k)
      for(int c = 0; c < 3; ++c)
        EXPECT_EQ(std::memcmp(&back.parameters[t][k][c], &map.parameters[t][k][c], sizeof(double)), 0);
  // no temporary left behind, and a failed write leaves nothing
  EXPECT_FALSE(fs::exists(file + ".tmp"));
  EXPECT_THROW(HR::IO::write_HexEx("/nonexistent_dir/x.hexex", map), HR::Error);
}

TEST(MapCheck, TwoCubesAreAnIntegerGridMap)
{
  const HR::Integer_grid_map map = read(hexex_data + "two_cubes.hexex");
  const HR::Integer_grid_map_check c = HR::check_integer_grid_map(map);
  EXPECT_EQ(c.tetrahedra, 10u);
  EXPECT_EQ(c.boundary_faces, 20u); // 10 squares, 2 triangles each
  EXPECT_EQ(c.interior_faces, (10u * 4 - 20) / 2);
  EXPECT_TRUE(c.is_integer_grid());
  EXPECT_TRUE(c.is_locally_injective());
  EXPECT_EQ(c.max_jump_deviation, 0.);
  EXPECT_EQ(c.singular_interior_edges(), 0u);
  // boundary: the 20 box edges of angle pi/2 (12 cube-box edges, split: the 4 long ones are 2 edges each)
  EXPECT_EQ(c.boundary_edge_valences.at(1), 4u * 2 + 4u + 4u);
  EXPECT_EQ(c.boundary_edge_valences.count(3), 0u);
}

// A ring of n tetrahedra (a, b, p_k, p_k+1) around the edge a = (0,0,0), b = (0,0,1), the p_k evenly spaced
// on a circle in space, at k * step degrees about the edge in parameter space (p_n = p_0 in space; its
// parameters in the last tetrahedron are turned by n * step, a rotation of the cube group about the
// edge). Every tetrahedron is positive in both; the parameter angles around the edge sum to n * step.
static HR::Integer_grid_map ring_map(int n, double step)
{
  HR::Integer_grid_map map;
  const double pi = 3.14159265358979323846;
  map.points = {{0, 0, 0}, {0, 0, 1}};
  for(int k = 0; k < n; ++k) map.points.emplace_back(std::cos(2 * pi * k / n), std::sin(2 * pi * k / n), 0.5);
  auto param = [&](int k) { return Eigen::Vector3d(std::cos(k * step * pi / 180), std::sin(k * step * pi / 180), 0.5); };
  for(int k = 0; k < n; ++k) {
    map.tetrahedra.push_back({0, 1, std::uint32_t(2 + k), std::uint32_t(2 + (k + 1) % n)});
    map.parameters.push_back({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 1), param(k), param(k + 1)});
  }
  return map;
}

// The map check lists the interior edges whose tetrahedra are all positive but whose valence is not 3, 4
// or 5 (a branched map: the flange of make_parts.py gave one, a valence-5 curve at valence 1 beside a
// regular edge at valence 8, after the untangling); check_hexex.py counts those of valence 1 or less.
TEST(MapCheck, BranchedEdgesAreListed)
{
  for(int n : {4, 5, 8}) {
    // 8 tetrahedra a quarter turn each: the map goes twice around (identity transitions); 4 tetrahedra
    // of 22.5 degrees: once a quarter turn (the last face's transition a quarter turn about the edge);
    // 5 of 90 degrees: a regular valence-5 edge, not listed
    const double step = n == 4 ? 22.5 : 90.;
    const HR::Integer_grid_map map = ring_map(n, step);
    const HR::Integer_grid_map_check c = HR::check_integer_grid_map(map);
    EXPECT_EQ(c.inverted_tetrahedra + c.degenerate_tetrahedra, 0u) << n;
    EXPECT_EQ(c.inverted_positions + c.degenerate_positions, 0u) << n;
    EXPECT_EQ(c.interior_edge_valences.size(), 1u) << n;
    const int valence = int(std::lround(n * step / 90));
    EXPECT_EQ(c.interior_edge_valences.count(valence), 1u) << n;
    if(valence == 5) {
      EXPECT_TRUE(c.unusual_interior_edges.empty());
      continue;
    }
    ASSERT_EQ(c.unusual_interior_edges.size(), 1u) << n;
    EXPECT_EQ(c.unusual_interior_edges[0].vertices, (std::array<std::uint32_t, 2>{{0, 1}}));
    EXPECT_EQ(c.unusual_interior_edges[0].valence, valence);
  }
}

TEST(MapCheck, NonIntegerJumpIsMeasured)
{
  const HR::Integer_grid_map map = read(hexex_data + "non_integer_jump.hexex");
  const HR::Integer_grid_map_check c = HR::check_integer_grid_map(map);
  EXPECT_FALSE(c.is_integer_grid());
  EXPECT_DOUBLE_EQ(c.max_jump_deviation, 0.25);
  EXPECT_DOUBLE_EQ(c.max_boundary_deviation, 0.25);
  EXPECT_EQ(c.max_rotation_deviation, 0.);
}

TEST(MapCheck, SharedMaps)
{
  if(!fs::exists(igm_data + "hand_q.hexex")) GTEST_SKIP() << "no shared data";
  const HR::Integer_grid_map_check hand = HR::check_integer_grid_map(read(igm_data + "hand_q.hexex"));
  EXPECT_TRUE(hand.is_integer_grid(1e-9));
  EXPECT_TRUE(hand.is_locally_injective());
  EXPECT_GT(hand.interior_edge_valences.count(3), 0u);
  EXPECT_GT(hand.interior_edge_valences.count(6), 0u);
  EXPECT_LT(hand.max_valence_deviation, 1e-6);
  const HR::Integer_grid_map_check ring = HR::check_integer_grid_map(read(igm_data + "fancy_ring.hexex"));
  EXPECT_FALSE(ring.is_integer_grid());
  const HR::Integer_grid_map_check rocker = HR::check_integer_grid_map(read(igm_data + "rockerarm_q.hexex"));
  // the 5 inverted tetrahedra of rockerarm_q are inverted in model space; their parameters are fine
  EXPECT_EQ(rocker.inverted_positions, 5u);
  EXPECT_EQ(rocker.inverted_tetrahedra, 0u);
  EXPECT_TRUE(rocker.is_integer_grid(1e-9));
  const HR::Integer_grid_map_check sphere = HR::check_integer_grid_map(read(igm_data + "sphere.hexex"));
  EXPECT_EQ(sphere.degenerate_tetrahedra, 2u);
  EXPECT_TRUE(sphere.is_integer_grid());
}

TEST(Extraction, GeneratedHexMeshesGiveBackKCubedHexesPerHex)
{
  const auto meshes = HR::test::all_generated_hex_meshes();
  unsigned seed = 1;
  for(const auto& g : meshes) {
    for(int k = 1; k <= 3; ++k) {
      const bool given = (seed % 2) == 0; // transitions given by the producer, or recovered
      const HR::Integer_grid_map map = HR::test::map_from_hex_mesh(g.mesh, k, seed++, given);
      HR::Hexahedral_mesh_3 hexes;
      const HR::Hexahedral_extraction_result r = HR::extract_hexahedra(map, hexes);
      const HR::test::Hex_mesh_oracle o = HR::test::scaled_oracle(g.expected, k);
      SCOPED_TRACE(g.name + " k=" + std::to_string(k));
      EXPECT_EQ(r.status, HR::Hexahedral_extraction_result::OK);
      ASSERT_EQ(hexes.hexahedra.size(), o.hexahedra);
      EXPECT_EQ(r.hexahedra, o.hexahedra);
      if(o.vertices) {
        EXPECT_EQ(hexes.points.size(), o.vertices);
      }
      const Hex_measures m = measure(hexes);
      EXPECT_GT(m.min_sj, 0.);
      EXPECT_EQ(m.nonconforming_quads, 0u);
      EXPECT_EQ(m.boundary_quads, o.boundary_quads);
      EXPECT_EQ(m.unused_vertices, 0u);
      EXPECT_EQ(m.bad_boundary_tags, 0u);
      EXPECT_EQ(m.interior_irregular, o.interior_irregular_edges);
      EXPECT_EQ(m.boundary_irregular, o.boundary_irregular_edges);
      ASSERT_EQ(hexes.vertex_locations.size(), hexes.points.size());
      ASSERT_EQ(hexes.hexahedron_source_tetrahedra.size(), hexes.hexahedra.size());
      if(k == 1) {
        // the same hexahedra, vertex positions bit for bit (corners are tet vertices)
        std::set<std::vector<double> > original, extracted;
        auto key = [](const HR::Hexahedral_mesh_3& mesh, const std::array<std::uint32_t, 8>& h) {
          std::vector<std::array<double, 3> > p;
          for(int i = 0; i < 8; ++i) p.push_back({{mesh.points[h[i]].x(), mesh.points[h[i]].y(), mesh.points[h[i]].z()}});
          std::sort(p.begin(), p.end());
          std::vector<double> v;
          for(const auto& q : p) v.insert(v.end(), q.begin(), q.end());
          return v;
        };
        for(const auto& h : g.mesh.hexahedra) original.insert(key(g.mesh, h));
        for(const auto& h : hexes.hexahedra) extracted.insert(key(hexes, h));
        EXPECT_EQ(original, extracted);
      }
    }
  }
}

TEST(Extraction, SharedMapsExactCountsAndValidMeshes)
{
  if(!fs::exists(igm_data + "minimal.hexex")) GTEST_SKIP() << "no shared data";
  struct Case { const char* name; std::size_t hexes; };
  const Case cases[] = {{"minimal", 1}, {"sphere", 216}, {"fancy_ring_q", 1220}, {"hand_q", 956}};
  for(const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const HR::Integer_grid_map map = read(igm_data + c.name + ".hexex");
    HR::Hexahedral_mesh_3 hexes;
    const HR::Hexahedral_extraction_result r = HR::extract_hexahedra(map, hexes);
    const Hex_measures m = measure(hexes);
    std::printf("%-14s hexes %zu/%zu vertices %zu minSJ %.4f meanSJ %.4f status %d degenerate %zu inverted %zu "
                "inverted-in-space %zu untraced %zu incomplete %zu duplicate %zu seconds %.4f\n",
                c.name, c.hexes, r.hexahedra, r.vertices, m.min_sj, m.mean_sj, int(r.status), r.degenerate_tetrahedra,
                r.inverted_tetrahedra, r.inverted_positions, r.untraced_corners, r.incomplete_cells, r.duplicate_cells,
                r.seconds);
    EXPECT_EQ(hexes.hexahedra.size(), c.hexes);
    EXPECT_EQ(r.status, HR::Hexahedral_extraction_result::OK);
    EXPECT_GT(m.min_sj, 0.);
    EXPECT_EQ(m.nonconforming_quads, 0u);
    EXPECT_EQ(m.unused_vertices, 0u);
    EXPECT_EQ(m.bad_boundary_tags, 0u);
  }
}

TEST(Extraction, RockerarmDefectsAreReported)
{
  if(!fs::exists(igm_data + "rockerarm_q.hexex")) GTEST_SKIP() << "no shared data";
  const HR::Integer_grid_map map = read(igm_data + "rockerarm_q.hexex");
  HR::Hexahedral_mesh_3 hexes;
  const HR::Hexahedral_extraction_result r = HR::extract_hexahedra(map, hexes);
  const Hex_measures m = measure(hexes);
  std::printf("%-14s hexes %zu vertices %zu minSJ %.4f meanSJ %.4f status %d inverted-in-space %zu untraced %zu "
              "incomplete %zu seconds %.4f\n", "rockerarm_q", r.hexahedra, r.vertices, m.min_sj, m.mean_sj,
              int(r.status), r.inverted_positions, r.untraced_corners, r.incomplete_cells, r.seconds);
  EXPECT_EQ(r.status, HR::Hexahedral_extraction_result::DEFECTS);
  EXPECT_EQ(r.inverted_positions, 5u);
  EXPECT_GT(hexes.hexahedra.size(), 0u);
  EXPECT_EQ(m.nonconforming_quads, 0u); // cells are complete, never broken
}

TEST(Extraction, MapsThatAreNotIntegerGridAreRefused)
{
  auto refusal = [](const HR::Integer_grid_map& map) -> std::string {
    HR::Hexahedral_mesh_3 hexes;
    try {
      HR::extract_hexahedra(map, hexes);
    } catch(const HR::Input_error& e) {
      return e.what();
    }
    return "";
  };
  const std::string jump = refusal(read(hexex_data + "non_integer_jump.hexex"));
  EXPECT_NE(jump.find("not an integer-grid map"), std::string::npos) << jump;
  EXPECT_NE(jump.find("face ("), std::string::npos) << jump;
  EXPECT_NE(jump.find("0.25"), std::string::npos) << jump;
  EXPECT_NE(jump.find("non_integer_jump.hexex"), std::string::npos) << jump;
  // a boundary face off its integer plane (the jump is fine)
  HR::Integer_grid_map map = read(hexex_data + "two_cubes.hexex");
  for(std::size_t t = 0; t < map.tetrahedra.size(); ++t)
    for(int k = 0; k < 4; ++k)
      if(map.tetrahedra[t][k] == 0) map.parameters[t][k][2] += 0.01; // vertex 0 lies on 3 boundary planes
  const std::string plane = refusal(map);
  EXPECT_NE(plane.find("not an integer-grid map: boundary face"), std::string::npos) << plane;
  if(fs::exists(igm_data + "fancy_ring.hexex")) {
    const std::string ring = refusal(read(igm_data + "fancy_ring.hexex"));
    EXPECT_NE(ring.find("not an integer-grid map"), std::string::npos) << ring;
    std::printf("fancy_ring refused: %s\n", ring.c_str());
  }
}

namespace {
struct Recording_visitor : HR::Hexahedral_extraction_visitor
{
  std::vector<std::string> stages;
  void end_stage(const std::string& s, double seconds)
  {
    stages.push_back(s);
    EXPECT_GE(seconds, 0.);
  }
};
} // namespace

TEST(Extraction, VisitorSeesEveryStep)
{
  const HR::Integer_grid_map map = read(hexex_data + "two_cubes.hexex");
  HR::Hexahedral_mesh_3 hexes;
  Recording_visitor v;
  const HR::Hexahedral_extraction_result r = HR::extract_hexahedra(map, hexes, CGAL::parameters::visitor(std::ref(v)));
  EXPECT_EQ(r.hexahedra, 2u);
  EXPECT_EQ(v.stages, (std::vector<std::string>{"topology", "sanitize", "vertices", "cells"}));
}

TEST(Extraction, FoldedMapsDoNotCrashAndEmitOnlyCompleteCells)
{
  // Move the cell-centre vertex of every hex (its 24 tets share the hex's chart, so the map stays
  // seamless) by up to 0.9 k: tets invert and the map folds.
  for(int k = 1; k <= 2; ++k) {
    const auto g = HR::test::make_grid(3, 3, 3);
    HR::Integer_grid_map map = HR::test::map_from_hex_mesh(g.mesh, k, 11, false);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> U(-0.9 * k, 0.9 * k);
    const std::uint32_t first_centre = std::uint32_t(map.points.size() - g.mesh.hexahedra.size());
    std::map<std::uint32_t, Eigen::Vector3d> moves;
    for(std::uint32_t v = first_centre; v < map.points.size(); ++v)
      moves[v] = Eigen::Vector3d(std::round(U(rng) * 8) / 8, std::round(U(rng) * 8) / 8, std::round(U(rng) * 8) / 8);
    for(std::size_t t = 0; t < map.tetrahedra.size(); ++t)
      for(int c = 0; c < 4; ++c)
        if(map.tetrahedra[t][c] >= first_centre) map.parameters[t][c] += moves[map.tetrahedra[t][c]];
    const HR::Integer_grid_map_check check = HR::check_integer_grid_map(map);
    ASSERT_TRUE(check.is_integer_grid());
    ASSERT_GT(check.inverted_tetrahedra, 0u);
    HR::Hexahedral_mesh_3 hexes;
    const HR::Hexahedral_extraction_result r = HR::extract_hexahedra(map, hexes);
    std::printf("folded grid k=%d: %zu inverted tets, %zu/%zu hexes, %zu incomplete, %zu resolved, %zu folded, %zu duplicate, "
                "%zu untraced corners, %zu spurious vertices removed\n", k, r.inverted_tetrahedra, r.hexahedra,
                g.mesh.hexahedra.size() * k * k * k, r.incomplete_cells, r.resolved_cells, r.folded_cells, r.duplicate_cells,
                r.untraced_corners, r.removed_vertices);
    EXPECT_EQ(r.status, HR::Hexahedral_extraction_result::DEFECTS);
    EXPECT_EQ(r.inverted_tetrahedra, check.inverted_tetrahedra);
    EXPECT_LE(hexes.hexahedra.size(), g.mesh.hexahedra.size() * k * k * k);
    for(const auto& h : hexes.hexahedra) {
      std::array<std::uint32_t, 8> s = h;
      std::sort(s.begin(), s.end());
      EXPECT_TRUE(std::adjacent_find(s.begin(), s.end()) == s.end());
      for(std::uint32_t v : h) EXPECT_LT(v, hexes.points.size());
    }
    // no folded cell is emitted, and the cells kept are the original ones (no overlap)
    const Hex_measures m = measure(hexes);
    EXPECT_GT(m.min_sj, 0.);
    EXPECT_EQ(m.nonconforming_quads, 0u);
    EXPECT_EQ(m.unused_vertices, 0u);
    EXPECT_GT(r.folded_cells + r.incomplete_cells, 0u);
    EXPECT_GT(hexes.hexahedra.size(), g.mesh.hexahedra.size() * k * k * k / 2); // the defects stay local
  }
}

// resolve_conflicting_cells(): a cell whose corner was seen as two hex vertices takes the choice
// that glues it to the most emitted hexahedra, the least distorted of those glued alike; it stays out
// when two choices are alike in both, when none glues it, or when one of its quads has two hexahedra
// already. Two unit cubes side by side
// (vertex x + 3 (y + 2 z) at (x, y, z)), a copy 12 of vertex 1 = (1, 0, 0), vertices 13..16 elsewhere.
TEST(Extraction, ConflictingCornersTakeTheChoiceGluedToTheNeighbours)
{
  namespace ex = HR::internal::extraction;
  std::vector<HR::Hexahedral_mesh_3::Point_3> positions;
  for(int z = 0; z < 2; ++z)
    for(int y = 0; y < 2; ++y)
      for(int x = 0; x < 3; ++x) positions.emplace_back(x, y, z);
  positions.emplace_back(1.1, 0.1, 0.1); // 12: the copy
  for(int i = 0; i < 4; ++i) positions.emplace_back(1.5, 0.25 * i, 2.0); // 13..16
  positions.emplace_back(1, 0, 0); // 17: a copy of vertex 1 at its place
  auto cube = [](std::uint32_t x0) { // corner bits x | y << 1 | z << 2
    std::array<std::uint32_t, 8> c;
    for(std::uint32_t b = 0; b < 8; ++b) c[b] = x0 + (b & 1) + 3 * (((b >> 1) & 1) + 2 * ((b >> 2) & 1));
    return c;
  };
  auto cell_of = [](const std::array<std::uint32_t, 8>& c) {
    ex::Cell_corners cell;
    for(std::size_t b = 0; b < 8; ++b) cell.candidates[b] = {c[b]};
    return cell;
  };
  struct Run { std::size_t hexes, resolved, left; std::array<std::uint32_t, 8> last; };
  auto run = [&](std::vector<std::array<std::uint32_t, 8> > emitted, std::vector<ex::Cell_corners> conflicting) {
    std::vector<std::array<std::uint32_t, 8> > hexes;
    std::vector<std::uint32_t> sources;
    ex::Cell_assembly_report report;
    ex::Cell_emitter emitter(positions, false, hexes, sources, report);
    for(const auto& c : emitted) EXPECT_TRUE(emitter.emit(c, false, 0));
    const std::size_t left = ex::resolve_conflicting_cells(conflicting, emitter, report).size();
    return Run{hexes.size(), report.resolved_cells, left, hexes.empty() ? std::array<std::uint32_t, 8>() : hexes.back()};
  };
  const auto A = cube(0), B = cube(1);
  // the shared corner (bit 0 of B) seen as 1 and as its copy 12: B takes 1, used by A
  ex::Cell_corners b = cell_of(B);
  b.candidates[0] = {12, 1};
  const Run taken = run({A}, {b});
  EXPECT_EQ(taken.hexes, 2u);
  EXPECT_EQ(taken.resolved, 1u);
  EXPECT_EQ(taken.left, 0u);
  EXPECT_EQ(taken.last[0], 1u); // VTK vertex 0 is corner bit 0
  EXPECT_EQ(std::count(taken.last.begin(), taken.last.end(), 12u), 0);
  // a cell D glued to B's other choice (its face 12, 4, 7, 10): two choices glue B once each; the
  // copy 12 is off the corner, so B with 1 (a unit cube) is the less distorted and is taken
  const std::array<std::uint32_t, 8> D = {{13, 12, 14, 4, 15, 7, 16, 10}};
  const Run straighter = run({A, D}, {b});
  EXPECT_EQ(straighter.hexes, 3u);
  EXPECT_EQ(straighter.last[0], 1u);
  // the same with a copy 17 at the corner itself: two choices alike in both, left out
  const std::array<std::uint32_t, 8> D17 = {{13, 17, 14, 4, 15, 7, 16, 10}};
  ex::Cell_corners b17 = cell_of(B);
  b17.candidates[0] = {17, 1};
  const Run tie = run({A, D17}, {b17});
  EXPECT_EQ(tie.hexes, 2u);
  EXPECT_EQ(tie.left, 1u);
  // a cell on A's side of A's face x = 1 (its own face x = 1 is 1, 4, 7, 10: it would overlap A) is not glued
  ex::Cell_corners inside = cell_of({{13, 1, 14, 4, 15, 7, 16, 10}});
  inside.candidates[0] = {13, 12};
  const Run overlap = run({A}, {inside});
  EXPECT_EQ(overlap.hexes, 1u);
  EXPECT_EQ(overlap.left, 1u);
  // no choice glued (A not emitted): left out
  const Run unused = run({}, {b});
  EXPECT_EQ(unused.hexes, 0u);
  EXPECT_EQ(unused.left, 1u);
  // a cell on the face x = 1 that A and B share already (the quad 1, 4, 7, 10): left out
  std::array<std::uint32_t, 8> third = {{1, 13, 4, 14, 7, 15, 10, 16}};
  ex::Cell_corners c = cell_of(third);
  c.candidates[0] = {12, 1};
  const Run crowded = run({A, B, cube(0)}, {c});
  EXPECT_EQ(crowded.hexes, 2u); // cube(0) again is a duplicate
  EXPECT_EQ(crowded.left, 1u);
  // a chain: B resolved first glues the cell C whose corner is {2, 12} through its face 2, 5, 8, 11
  const auto C = std::array<std::uint32_t, 8>{{2, 13, 5, 14, 8, 15, 11, 16}};
  ex::Cell_corners chained = cell_of(C);
  chained.candidates[0] = {12, 2};
  const Run chain = run({A}, {chained, b});
  EXPECT_EQ(chain.hexes, 3u);
  EXPECT_EQ(chain.resolved, 2u);
  EXPECT_EQ(chain.left, 0u);
}

TEST(Extraction, SanitizingAbsorbsSmallNoise)
{
  // Noise of 1e-6 on every corner parameter, independently per tetrahedron: the transitions no longer
  // hold exactly, the boundary leaves its planes and the singular axes move; sanitizing restores them.
  for(const auto& g : {HR::test::make_polygon_prism(3, 2), HR::test::make_polygon_prism(5, 2), HR::test::make_cubed_ball(2, 1)}) {
    SCOPED_TRACE(g.name);
    HR::Integer_grid_map map = HR::test::map_from_hex_mesh(g.mesh, 2, 3, false);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> U(-1e-6, 1e-6);
    for(auto& t : map.parameters)
      for(auto& u : t) u += Eigen::Vector3d(U(rng), U(rng), U(rng));
    HR::Hexahedral_mesh_3 hexes;
    const HR::Hexahedral_extraction_result r = HR::extract_hexahedra(map, hexes);
    const HR::test::Hex_mesh_oracle o = HR::test::scaled_oracle(g.expected, 2);
    EXPECT_EQ(r.hexahedra, o.hexahedra);
    EXPECT_GT(r.max_sanitizing_move, 0.);
    EXPECT_LT(r.max_sanitizing_move, 1e-5);
    if(!o.interior_irregular_edges.empty()) {
      EXPECT_GT(r.singular_snaps, 0u);
    }
    EXPECT_EQ(r.sanitizing_failures, 0u);
    EXPECT_EQ(r.status, HR::Hexahedral_extraction_result::OK);
    const Hex_measures m = measure(hexes);
    EXPECT_EQ(m.nonconforming_quads, 0u);
    EXPECT_GT(m.min_sj, 0.);
    EXPECT_EQ(m.interior_irregular, o.interior_irregular_edges);
  }
}
