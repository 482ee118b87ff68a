// Tests of the .hexex IO, of the integer-grid map check and of the hexahedral extraction.
#include <CGAL/Hexahedral_remeshing/IO/read_HexEx.h>
#include <CGAL/Hexahedral_remeshing/IO/write_HexEx.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_extraction.h>

#include <gtest/gtest.h>

#include <cstdio>
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
