// Tests of the input front door (issue 13): CAD parts and gmsh meshes through gmsh, the everyday
// variants of VTK / MEDIT / STL / OFF / OBJ, and flawed surfaces and meshes, each refused with a
// clear Input_error or repaired. Fixtures: test/Hexahedral_remeshing/data/inputs (written by
// make_inputs.py from unit cubes, so that volumes and components are known exactly); binary
// variants and CAD parts are written here at test time.
#include "data_paths.h"
#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/mesh_statistics.h>

#include <gtest/gtest.h>
#include <gmsh.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

namespace HR = CGAL::Hexahedral_remeshing;
typedef HR::Tetrahedral_mesh_3<> Mesh;
typedef Mesh::Index Index;
typedef Mesh::Point_3 Point;
namespace fs = std::filesystem;

namespace {

const std::string inputs = std::string(HEXREM_TEST_DATA_DIR) + "/inputs/";

std::string temp_dir()
{
  static const std::string dir = [] {
    const fs::path p = fs::temp_directory_path() / ("hexrem_test_inputs_" + std::to_string(::getpid()));
    fs::create_directories(p);
    return p.string() + "/";
  }();
  return dir;
}

// Sum of the (positive) volumes of the tetrahedra, computed here from the points.
double volume(const Mesh& m)
{
  double v = 0;
  for(Index t = 0; t < m.number_of_tetrahedra(); ++t) {
    const auto& c = m.tetrahedron_vertices(t);
    v += CGAL::to_double(CGAL::volume(m.point(c[0]), m.point(c[1]), m.point(c[2]), m.point(c[3])));
  }
  return v;
}

template <class NP = CGAL::parameters::Default_named_parameters>
Mesh read(const std::string& file, const NP& np = CGAL::parameters::default_values())
{
  Mesh m;
  HR::IO::read_tetrahedral_mesh(file, m, np);
  return m;
}

// The Input_error of reading `file` (fails the test if there is none).
template <class NP = CGAL::parameters::Default_named_parameters>
std::string error_of(const std::string& file, const NP& np = CGAL::parameters::default_values())
{
  try {
    Mesh m;
    HR::IO::read_tetrahedral_mesh(file, m, np);
  } catch(const HR::Input_error& e) {
    EXPECT_EQ(e.source(), file);
    return e.what();
  }
  ADD_FAILURE() << file << ": no Input_error";
  return std::string();
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// Runs gmsh in a child process (the process of the test never initializes gmsh itself, except in
// the test that checks exactly that).
void with_gmsh(const std::function<void()>& f)
{
  HR::internal::run_isolated([&]() -> std::string {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    f();
    gmsh::finalize();
    return std::string();
  }, "<test>", "gmsh (test generator)");
}

// Big-endian bytes of a value (legacy binary VTK), written independently of the reader.
template <class T>
void put_be(std::string& out, T v)
{
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  for(std::size_t i = sizeof(T); i-- > 0;) out.push_back(char(b[i]));
}

// Unit cube, 6 tetrahedra around the diagonal 0-7 (vertex i = (i & 1, (i >> 1) & 1, (i >> 2) & 1)).
const int cube_tets[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};

} // namespace

// ---------------------------------------------------------------------------------------------
// Surfaces: repaired, oriented, checked before TetGen; nested shells are cavities.

TEST(Surfaces, NestedShellIsACavity)
{
  const Mesh m = read(inputs + "cavity.off");
  EXPECT_NEAR(volume(m), 27.0 - 1.0, 1e-9);
  EXPECT_EQ(m.number_of_components(), 1u);
  EXPECT_EQ(m.number_of_boundary_components(), 2u);
}

TEST(Surfaces, BodyInsideACavityIsASecondBody)
{
  const Mesh m = read(inputs + "body_in_cavity.off");
  EXPECT_NEAR(volume(m), 125.0 - 27.0 + 1.0, 1e-9);
  EXPECT_EQ(m.number_of_components(), 2u);
  EXPECT_EQ(m.number_of_boundary_components(), 3u);
}

TEST(Surfaces, DisjointShellsAreSeparateBodies)
{
  const Mesh m = read(inputs + "two_bodies.off");
  EXPECT_NEAR(volume(m), 2.0, 1e-12);
  EXPECT_EQ(m.number_of_components(), 2u);
}

TEST(Surfaces, FlippedStlFacetsAreOriented)
{
  const Mesh m = read(inputs + "flipped_facets.stl");
  EXPECT_NEAR(volume(m), 1.0, 1e-12);
  EXPECT_EQ(m.number_of_components(), 1u);
  // binary STL, facets flipped, written here
  std::string stl(80, ' ');
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  const std::uint32_t n = 12;
  stl.append(reinterpret_cast<const char*>(&n), 4);
  for(int q = 0; q < 6; ++q)
    for(int h = 0; h < 2; ++h) {
      int t[3] = {quads[q][0], quads[q][1 + h], quads[q][2 + h]};
      if(q % 2 == 0 && h == 0) std::swap(t[1], t[2]); // flipped
      const float normal[3] = {0, 0, 0};
      stl.append(reinterpret_cast<const char*>(normal), 12);
      for(int v : t) {
        const float p[3] = {float(v & 1), float((v >> 1) & 1), float((v >> 2) & 1)};
        stl.append(reinterpret_cast<const char*>(p), 12);
      }
      stl.append(2, '\0');
    }
  const std::string file = temp_dir() + "flipped_binary.stl";
  std::ofstream(file, std::ios::binary) << stl;
  const Mesh b = read(file);
  EXPECT_NEAR(volume(b), 1.0, 1e-12);
  // a binary STL whose header announces more triangles than it holds
  const std::string truncated = temp_dir() + "truncated_binary.stl";
  std::ofstream(truncated, std::ios::binary) << stl.substr(0, stl.size() - 60);
  EXPECT_TRUE(contains(error_of(truncated), "truncated"));
}

TEST(Surfaces, SoupsWithDuplicatedVerticesAreRepaired)
{
  for(const char* f : {"soup_duplicated_vertices.off", "soup_duplicated_vertices.obj"}) {
    SCOPED_TRACE(f);
    const Mesh m = read(inputs + f);
    EXPECT_NEAR(volume(m), 1.0, 1e-12);
    EXPECT_EQ(m.number_of_components(), 1u);
    EXPECT_EQ(m.number_of_boundary_triangles(), 12u); // the 8 cube corners only, merged
  }
}

TEST(Surfaces, OffQuadsColoursAndBadIndices)
{
  const std::string quads = temp_dir() + "quads.off";
  std::ofstream(quads) << "OFF # a cube of quads, with a colour per face\n8 6 0\n"
                          "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
                          "4 0 2 3 1 255 0 0\n4 4 5 7 6 255 0 0\n4 0 1 5 4 255 0 0\n"
                          "4 2 6 7 3 255 0 0\n4 0 4 6 2 255 0 0\n4 1 3 7 5 255 0 0\n";
  EXPECT_NEAR(volume(read(quads)), 1.0, 1e-12);
  const std::string negative = temp_dir() + "negative.off";
  std::ofstream(negative) << "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 -1 3\n3 0 2 3\n3 1 2 3\n";
  const std::string what = error_of(negative);
  EXPECT_TRUE(contains(what, "negative.off:8: face 1: vertex index -1 out of range")) << what;
  // a non-planar pentagon whose projection overlaps itself (from the fuzzer: it broke the CDT of
  // the triangulation of polygons): triangulated in 3D, then refused as an open surface
  const std::string pentagon = temp_dir() + "pentagon.off";
  std::ofstream(pentagon) << "OFF\n5 1 0\n0 0 0\n0 1 0\n1 1 0\n0 0 1\n0 1 1\n5 0 1 2 3 4\n";
  EXPECT_TRUE(contains(error_of(pentagon), "the surface is not closed")) << error_of(pentagon);
  const std::string huge = temp_dir() + "huge.off";
  std::ofstream(huge) << "OFF\n4000000000 4 0\n0 0 0\n";
  EXPECT_TRUE(contains(error_of(huge), "more vertices than the file can hold")) << error_of(huge);
}

TEST(Surfaces, FlawedSurfacesGiveClearErrors)
{
  struct Case { const char* file; const char* problem; };
  const Case cases[] = {
    {"self_intersecting.off", "the surface intersects itself"},
    {"touching_bodies.stl", "the surface intersects itself"},   // coplanar overlapping facets
    {"open_surface.off", "the surface is not closed: 4 border edges"},
    {"shared_edge.off", "the surface is not manifold"},
  };
  for(const Case& c : cases) {
    SCOPED_TRACE(c.file);
    const std::string what = error_of(inputs + c.file);
    EXPECT_TRUE(contains(what, c.problem)) << what;
    EXPECT_TRUE(contains(what, "retry")) << what; // says what to do
  }
}

TEST(Surfaces, TetGenBoundsThatWouldNotTerminateAreRefused)
{
  const std::string what = error_of(inputs + "cavity.off", HR::parameters::radius_edge_ratio(0.5));
  EXPECT_TRUE(contains(what, "radius-edge ratio must be 0 (no refinement) or at least 1")) << what;
  EXPECT_NEAR(volume(read(inputs + "cavity.off", HR::parameters::radius_edge_ratio(0))), 26.0, 1e-9);
  // a 2000-long spike: the default quality bound refines without end near its tip (found by the fuzzer,
  // which timed out); the Steiner points are bounded (100 per surface vertex) and that is an error
  const std::string spike = error_of(inputs + "spike.off");
  EXPECT_TRUE(contains(spike, "quality refinement does not terminate on this surface: it stopped at 800 added points"))
      << spike;
  EXPECT_TRUE(contains(spike, "radius-edge ratio 0")) << spike;
  // without refinement it is meshed: 667.4667 is the divergence theorem on its 12 triangles
  EXPECT_NEAR(volume(read(inputs + "spike.off", HR::parameters::radius_edge_ratio(0))), 667.46666666666667, 1e-9);
  // the bound grows with the volume bound: 10 per bound in the bounding box (1.2 x 2001 x 1 / 100)
  const std::string bounded = error_of(inputs + "spike.off", HR::parameters::maximum_tetrahedron_volume(100.));
  EXPECT_TRUE(contains(bounded, "it stopped at 1040 added points (100 per surface vertex and 10 per volume bound"))
      << bounded;
}

TEST(Surfaces, CrashOfAnIsolatedLibraryIsAnInputError)
{
  // what protects the process when TetGen or gmsh crash on an input the checks let through
  try {
    HR::internal::run_isolated([]() -> std::string { std::raise(SIGSEGV); return std::string(); }, "part.stl", "TetGen");
    ADD_FAILURE() << "no error";
  } catch(const HR::Input_error& e) {
    EXPECT_EQ(e.source(), "part.stl");
    EXPECT_TRUE(contains(e.problem(), "TetGen crashed on this input (SIGSEGV")) << e.what();
  }
  try {
    HR::internal::run_isolated([]() -> std::string { throw HR::Unsupported_input("x", 12, "inner problem"); },
                               "part.stl", "TetGen");
    ADD_FAILURE() << "no error";
  } catch(const HR::Unsupported_input& e) {
    EXPECT_EQ(e.line(), 12u);
    EXPECT_EQ(e.problem(), "inner problem");
  }
  const std::string big(3 << 20, 'x'); // larger than a pipe buffer
  EXPECT_EQ(HR::internal::run_isolated([&]() -> std::string { return big; }, "s", "w"), big);
}

// ---------------------------------------------------------------------------------------------
// VTK and MEDIT variants.

TEST(Vtk, Version51OffsetsConnectivityMetadataAndFieldData)
{
  const Mesh m = read(inputs + "cube_v51.vtk", HR::parameters::split_multi_boundary_tetrahedra(false));
  EXPECT_EQ(m.number_of_tetrahedra(), 6u);
  EXPECT_NEAR(volume(m), 1.0, 1e-12);
  const auto s = HR::compute_mesh_statistics(m);
  EXPECT_EQ(s.surface_patches, 1u); // gmsh:geometrical 7 on the two triangles
  EXPECT_EQ(s.feature_edges, 1u);
}

// A METADATA block followed directly by the next section (no empty line) ends there: the file is the
// same mesh as with the empty lines.
TEST(Vtk, MetadataWithoutEmptyLineBeforeTheNextSection)
{
  const Mesh m = read(inputs + "cube_v51_metadata_no_blank_line.vtk", HR::parameters::split_multi_boundary_tetrahedra(false));
  EXPECT_EQ(m.number_of_tetrahedra(), 6u);
  EXPECT_NEAR(volume(m), 1.0, 1e-12);
  const auto s = HR::compute_mesh_statistics(m);
  EXPECT_EQ(s.surface_patches, 1u);
  EXPECT_EQ(s.feature_edges, 1u);
}

TEST(Vtk, SecondOrderTetrahedraGiveTheirCorners)
{
  const Mesh m = read(inputs + "cube_quadratic_tets.vtk", HR::parameters::split_multi_boundary_tetrahedra(false));
  EXPECT_EQ(m.number_of_tetrahedra(), 6u);
  EXPECT_NEAR(volume(m), 1.0, 1e-12);
  std::set<Index> used;
  for(Index t = 0; t < m.number_of_tetrahedra(); ++t)
    for(Index v : m.tetrahedron_vertices(t)) used.insert(v);
  EXPECT_EQ(used.size(), 8u);
}

TEST(Vtk, BinaryLegacyClassicAnd51)
{
  for(int version : {42, 51}) {
    SCOPED_TRACE(version);
    std::string f = std::string("# vtk DataFile Version ") + (version == 42 ? "4.2" : "5.1") +
                    "\nbinary cube\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 8 double\n";
    for(int i = 0; i < 8; ++i) { put_be(f, double(i & 1)); put_be(f, double((i >> 1) & 1)); put_be(f, double((i >> 2) & 1)); }
    if(version == 42) {
      f += "\nCELLS 6 30\n";
      for(const auto& t : cube_tets) { put_be(f, std::int32_t(4)); for(int v : t) put_be(f, std::int32_t(v)); }
    } else {
      f += "\nCELLS 7 24\nOFFSETS vtktypeint64\n";
      for(int i = 0; i <= 6; ++i) put_be(f, std::int64_t(4 * i));
      f += "\nCONNECTIVITY vtktypeint64\n";
      for(const auto& t : cube_tets) for(int v : t) put_be(f, std::int64_t(v));
    }
    f += "\nCELL_TYPES 6\n";
    for(int i = 0; i < 6; ++i) put_be(f, std::int32_t(10));
    f += "\nCELL_DATA 6\nSCALARS CellEntityIds int 1\nLOOKUP_TABLE default\n";
    for(int i = 0; i < 6; ++i) put_be(f, std::int32_t(-3 - i)); // negative: sign extension
    f += "\n";
    const std::string file = temp_dir() + "binary_" + std::to_string(version) + ".vtk";
    std::ofstream(file, std::ios::binary) << f;
    const Mesh m = read(file, HR::parameters::split_multi_boundary_tetrahedra(false));
    EXPECT_EQ(m.number_of_tetrahedra(), 6u);
    EXPECT_NEAR(volume(m), 1.0, 1e-12);
    // truncated in the middle of the connectivity
    const std::string cut = temp_dir() + "binary_cut_" + std::to_string(version) + ".vtk";
    std::ofstream(cut, std::ios::binary) << f.substr(0, f.find("CELL_TYPES") - 40);
    EXPECT_TRUE(contains(error_of(cut), "truncated")) << error_of(cut);
  }
}

TEST(Vtk, NonTetrahedralVolumeCellsAreRefusedWithCounts)
{
  const std::string what = error_of(inputs + "tets_and_hexahedron.vtk");
  EXPECT_TRUE(contains(what, "volume cells other than tetrahedra (1 hexahedron cell(s), with 6 tetrahedra)")) << what;
  const std::string medit = error_of(inputs + "tets_and_prism.mesh");
  EXPECT_TRUE(contains(medit, "volume cells other than tetrahedra (1 Prisms, with 6 Tetrahedra)")) << medit;
}

TEST(Medit, SkippedBlocks)
{
  const Mesh m = read(inputs + "cube_extra_blocks.mesh", HR::parameters::split_multi_boundary_tetrahedra(false));
  EXPECT_EQ(m.number_of_tetrahedra(), 6u);
  EXPECT_NEAR(volume(m), 1.0, 1e-12);
  const auto s = HR::compute_mesh_statistics(m);
  EXPECT_EQ(s.surface_patches, 1u);
  EXPECT_EQ(s.feature_edges, 1u);
  EXPECT_EQ(s.corners, 1u);
}

// ---------------------------------------------------------------------------------------------
// Coincident vertices along an interface (a crack).

TEST(CoincidentVertices, RefusedMergedOrKept)
{
  const std::string file = inputs + "cracked_interface.vtk";
  const std::string what = error_of(file);
  EXPECT_TRUE(contains(what, "4 vertices of the tetrahedra coincide with other vertices")) << what;
  EXPECT_TRUE(contains(what, "--coincident-vertices merge")) << what;
  namespace P = HR::parameters;
  const Mesh merged = read(file, P::coincident_vertices(HR::Coincident_vertices::MERGE, P::split_multi_boundary_tetrahedra(false)));
  EXPECT_EQ(merged.number_of_components(), 1u);
  EXPECT_EQ(merged.number_of_boundary_triangles(), 20u); // a 2 x 1 x 1 box: 10 unit squares
  EXPECT_NEAR(volume(merged), 2.0, 1e-12);
  const Mesh kept = read(file, P::coincident_vertices(HR::Coincident_vertices::KEEP, P::split_multi_boundary_tetrahedra(false)));
  EXPECT_EQ(kept.number_of_components(), 2u);
  EXPECT_EQ(kept.number_of_boundary_triangles(), 24u);
}

// ---------------------------------------------------------------------------------------------
// gmsh: .msh files and CAD parts.

// The box [0,2]^3 minus the cavity [0.5,1.5]^3: volume 7, 12 faces, 24 edges, 16 corners.
void expect_box_with_cavity(const Mesh& m)
{
  EXPECT_NEAR(volume(m), 7.0, 1e-9);
  EXPECT_EQ(m.number_of_components(), 1u);
  EXPECT_EQ(m.number_of_boundary_components(), 2u);
  const auto s = HR::compute_mesh_statistics(m);
  EXPECT_EQ(s.surface_patches, 12u);
  EXPECT_EQ(s.feature_curves, 24u);
  EXPECT_EQ(s.corners, 16u);
}

TEST(Gmsh, MshAsciiAndBinaryVersions)
{
  const Mesh v41 = read(inputs + "box_with_cavity_v41.msh");
  expect_box_with_cavity(v41);
  const Mesh v22 = read(inputs + "box_with_cavity_v22.msh");
  expect_box_with_cavity(v22);
  EXPECT_EQ(v41.number_of_tetrahedra(), v22.number_of_tetrahedra());
  const std::string binary = temp_dir() + "box_binary.msh";
  with_gmsh([&] {
    gmsh::open(inputs + "box_with_cavity_v41.msh");
    gmsh::option::setNumber("Mesh.Binary", 1);
    gmsh::write(binary);
  });
  const Mesh b = read(binary);
  expect_box_with_cavity(b);
  EXPECT_EQ(b.number_of_tetrahedra(), v41.number_of_tetrahedra());
}

TEST(Gmsh, MshErrors)
{
  const std::string garbage = temp_dir() + "garbage.msh";
  std::ofstream(garbage) << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 2 3\n";
  EXPECT_TRUE(contains(error_of(garbage), "gmsh could not read the mesh file")) << error_of(garbage);
  EXPECT_TRUE(contains(error_of(temp_dir() + "missing.msh"), "cannot open file"));
  // hexahedra (transfinite, recombined): refused with their count
  const std::string hexes = temp_dir() + "hexes.msh";
  with_gmsh([&] {
    gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1);
    gmsh::model::occ::synchronize();
    gmsh::option::setNumber("Mesh.MeshSizeMax", 0.5);
    gmsh::model::mesh::setTransfiniteAutomatic();
    gmsh::option::setNumber("Mesh.RecombineAll", 1);
    gmsh::model::mesh::generate(3);
    gmsh::write(hexes);
  });
  const std::string what = error_of(hexes);
  EXPECT_TRUE(contains(what, "volume elements other than tetrahedra")) << what;
  EXPECT_TRUE(contains(what, "Hexahedron")) << what;
  // a surface mesh only: tetrahedralized with TetGen
  const std::string surface = temp_dir() + "surface.msh";
  with_gmsh([&] {
    gmsh::model::occ::addBox(0, 0, 0, 2, 1, 1);
    gmsh::model::occ::synchronize();
    gmsh::option::setNumber("Mesh.MeshSizeMax", 0.5);
    gmsh::model::mesh::generate(2);
    gmsh::write(surface);
  });
  EXPECT_NEAR(volume(read(surface)), 2.0, 1e-9);
}

TEST(Gmsh, StepPartWithCadCurvesAndCorners)
{
  const Mesh m = read(inputs + "box_with_cavity.step");
  expect_box_with_cavity(m);
  // the mesh size sets the edge length of gmsh's tetrahedra (their mean, edges between input
  // vertices: gmsh's sizes are targets, not bounds)
  std::vector<double> means;
  for(double h : {0.5, 0.25}) {
    const Mesh m = read(inputs + "box_with_cavity.step", HR::parameters::mesh_size(h));
    expect_box_with_cavity(m);
    double longest = 0, total = 0;
    std::size_t n = 0;
    for(Index e = 0; e < m.number_of_edges(); ++e) {
      const auto& v = m.edge_vertices(e);
      if(v[0] >= m.number_of_input_vertices() || v[1] >= m.number_of_input_vertices()) continue;
      const double l = std::sqrt(CGAL::to_double(CGAL::squared_distance(m.point(v[0]), m.point(v[1]))));
      longest = (std::max)(longest, l);
      total += l;
      ++n;
    }
    std::printf("mesh size %g: %zu tetrahedra, input edges: longest %g, mean %g\n", h,
                std::size_t(m.number_of_tetrahedra()), longest, total / double(n));
    EXPECT_LT(total / double(n), 1.25 * h);
    EXPECT_LT(longest, 2.5 * h);
    means.push_back(total / double(n));
  }
  EXPECT_LT(means[1], 0.8 * means[0]);
  EXPECT_TRUE(contains(error_of(inputs + "box_with_cavity.step", HR::parameters::mesh_size(-1.)), "mesh size"));
}

TEST(Gmsh, CylinderSeamIsNoFeatureAndBrepRead)
{
  // cylinder of radius 1, height 2: two circles are the CAD feature curves, the seam is not
  // (gmsh reads IGES but cannot write it: no IGES case here)
  const std::string step = temp_dir() + "cylinder.step", brep = temp_dir() + "cylinder.brep";
  with_gmsh([&] {
    gmsh::model::occ::addCylinder(0, 0, 0, 0, 0, 2, 1);
    gmsh::model::occ::synchronize();
    gmsh::write(step);
    gmsh::write(brep);
  });
  for(const std::string& file : {step, brep}) {
    SCOPED_TRACE(file);
    const Mesh m = read(file, HR::parameters::mesh_size(0.2));
    EXPECT_NEAR(volume(m), 2 * M_PI, 0.02 * 2 * M_PI);
    const auto s = HR::compute_mesh_statistics(m);
    EXPECT_EQ(s.feature_curves, 2u);
    EXPECT_EQ(s.corners, 0u);
    EXPECT_EQ(s.surface_patches, 3u);
  }
}

TEST(Gmsh, CadPartGradedTowardsItsAcuteEdge)
{
  // a 20-degree wedge (the x axis is its acute edge) and a box (no edge below 45 degrees)
  const std::string wedge = temp_dir() + "wedge20.brep", box = temp_dir() + "box.brep";
  with_gmsh([&] {
    const double s = std::sin(20 * M_PI / 180), c = std::cos(20 * M_PI / 180);
    const int p0 = gmsh::model::occ::addPoint(0, 0, 0), p1 = gmsh::model::occ::addPoint(0, 0, 1),
              p2 = gmsh::model::occ::addPoint(0, -s, c);
    const int loop = gmsh::model::occ::addCurveLoop({gmsh::model::occ::addLine(p0, p1), gmsh::model::occ::addLine(p1, p2),
                                                     gmsh::model::occ::addLine(p2, p0)});
    std::vector<std::pair<int, int> > out;
    gmsh::model::occ::extrude({{2, gmsh::model::occ::addPlaneSurface({loop})}}, 1, 0, 0, out);
    gmsh::model::occ::synchronize();
    gmsh::write(wedge);
  });
  with_gmsh([&] {
    gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1);
    gmsh::model::occ::synchronize();
    gmsh::write(box);
  });
  const double h = 0.1;
  // mean length of the mesh edges on the x axis (the acute edge), and the number of tetrahedra
  auto measure = [](const Mesh& m, double& on_axis) {
    double total = 0;
    std::size_t n = 0;
    for(Index e = 0; e < m.number_of_edges(); ++e) {
      const auto& v = m.edge_vertices(e);
      auto axis = [&](Index i) { return std::abs(CGAL::to_double(m.point(i).y())) < 1e-9 && std::abs(CGAL::to_double(m.point(i).z())) < 1e-9; };
      if(!axis(v[0]) || !axis(v[1])) continue;
      total += std::sqrt(CGAL::to_double(CGAL::squared_distance(m.point(v[0]), m.point(v[1]))));
      ++n;
    }
    on_axis = n > 0 ? total / double(n) : 0;
    return m.number_of_tetrahedra();
  };
  double graded_edge = 0, uniform_edge = 0;
  const std::size_t graded = measure(read(wedge, HR::parameters::mesh_size(h)), graded_edge);
  const std::size_t uniform = measure(read(wedge, HR::parameters::acute_edge_grading(false, HR::parameters::mesh_size(h))), uniform_edge);
  std::printf("20-degree wedge, mesh size %g: graded %zu tetrahedra (edges on the acute edge %g), uniform %zu (%g)\n", h,
              graded, graded_edge, uniform, uniform_edge);
  EXPECT_GT(uniform_edge, h / 2);
  EXPECT_LT(graded_edge, h / 4);     // h / 7 asked
  EXPECT_GT(graded_edge, h / 14);
  EXPECT_GT(graded, uniform);        // finer near the edge only (2,741 against 1,361)
  double unused = 0;
  EXPECT_EQ(measure(read(box, HR::parameters::mesh_size(0.25)), unused),
            measure(read(box, HR::parameters::acute_edge_grading(false, HR::parameters::mesh_size(0.25))), unused));
}

TEST(Gmsh, CadErrors)
{
  const std::string garbage = temp_dir() + "garbage.step";
  std::ofstream(garbage) << "ISO-10303-21;\nHEADER;\nnot a step file\n";
  EXPECT_TRUE(contains(error_of(garbage), "gmsh could not read the CAD file")) << error_of(garbage);
  // a face without a solid
  const std::string sheet = temp_dir() + "sheet.step";
  with_gmsh([&] {
    gmsh::model::occ::addRectangle(0, 0, 0, 1, 1);
    gmsh::model::occ::synchronize();
    gmsh::write(sheet);
  });
  const std::string what = error_of(sheet);
  EXPECT_TRUE(contains(what, "the CAD file has no solid")) << what;
  // assemblies: solids that touch or overlap are refused (meshed one by one they would overlap or
  // touch without sharing nodes); solids apart are separate bodies
  const std::string touching = temp_dir() + "touching.step", overlapping = temp_dir() + "overlapping.step",
                    apart = temp_dir() + "apart.step";
  with_gmsh([&] {
    const double second[3][3] = {{1, 0.5, 0}, {0.5, 0.5, 0.5}, {3, 0, 0}};
    const std::string files[3] = {touching, overlapping, apart};
    for(int k = 0; k < 3; ++k) {
      gmsh::model::add("assembly " + std::to_string(k));
      gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1);
      gmsh::model::occ::addBox(second[k][0], second[k][1], second[k][2], 1, 1, 1);
      gmsh::model::occ::synchronize();
      gmsh::write(files[k]);
    }
  });
  for(const std::string& f : {touching, overlapping}) {
    const std::string e = error_of(f, HR::parameters::mesh_size(0.5));
    EXPECT_TRUE(contains(e, "the part has 2 solids that touch or overlap")) << e;
  }
  const Mesh two = read(apart, HR::parameters::mesh_size(0.5));
  EXPECT_EQ(two.number_of_components(), 2u);
  EXPECT_NEAR(volume(two), 2.0, 1e-9);
}

// A part whose walls are much thinner than the tetrahedra is refused before the 3D mesher runs (which
// takes minutes on such a plate), with the thickness and a size that fits; the measure of a box, from
// its surface mesh: the area-weighted median distance across it is its smallest side.
TEST(Gmsh, ThinWallsAreMeasuredAndRefusedQuickly)
{
  const auto start = std::chrono::steady_clock::now();
  const std::string e = error_of(inputs + "thin_plate.step", HR::parameters::mesh_size(0.5));
  EXPECT_TRUE(contains(e, "the part's walls are 0.03 thick")) << e;
  EXPECT_TRUE(contains(e, "a mesh size of at most 0.03")) << e;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 20.);
  const HR::IO::CAD_part_measures box = HR::IO::measure_CAD_part(inputs + "box_1x2x3.step");
  EXPECT_NEAR(box.volume, 6.0, 1e-9);
  EXPECT_NEAR(box.wall_thickness, 1.0, 1e-9);
  EXPECT_NEAR(box.diagonal, std::sqrt(14.0), 1e-6); // OpenCASCADE pads its boxes by the shape tolerance (1e-7)
  const HR::IO::CAD_part_measures plate = HR::IO::measure_CAD_part(inputs + "thin_plate.step");
  EXPECT_NEAR(plate.wall_thickness, 0.03, 1e-9);
  EXPECT_NEAR(plate.volume, 0.12, 1e-9);
}

// gmsh (here on a thin plate at a size it takes some 10 s for) is stopped at the time limit.
TEST(Gmsh, ChildProcessStoppedAtTheTimeLimit)
{
  const auto start = std::chrono::steady_clock::now();
  const std::string e = error_of(inputs + "thin_plate_20x20.step", HR::parameters::mesh_size(0.15, HR::parameters::time_limit(1.0)));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(contains(e, "did not finish within the time limit of 1 s")) << e;
  EXPECT_LT(seconds, 6.);
}

TEST(Gmsh, SilentAndSafeTwiceAndWithGmshInitializedByTheCaller)
{
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  const Mesh a = read(inputs + "box_with_cavity_v41.msh");
  const Mesh b = read(inputs + "box_with_cavity_v41.msh");
  gmsh::initialize(0, nullptr, false); // the caller uses gmsh too
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::model::add("caller's model");
  gmsh::model::occ::addSphere(0, 0, 0, 1);
  gmsh::model::occ::synchronize();
  const Mesh c = read(inputs + "box_with_cavity.step", HR::parameters::mesh_size(0.5));
  std::vector<std::pair<int, int> > entities;
  gmsh::model::getEntities(entities, 3);
  EXPECT_EQ(entities.size(), 1u); // the caller's model is untouched
  gmsh::finalize();
  const std::string out = testing::internal::GetCapturedStdout();
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(out, "");
  EXPECT_EQ(err, "");
  EXPECT_EQ(a.number_of_tetrahedra(), b.number_of_tetrahedra());
  expect_box_with_cavity(c);
}

TEST(Dispatch, UnknownExtensionListsTheFormats)
{
  try {
    read(temp_dir() + "part.xyz");
    ADD_FAILURE();
  } catch(const HR::Unsupported_input& e) {
    EXPECT_TRUE(contains(e.problem(), ".msh, .step, .stp, .brep, .iges, .igs")) << e.what();
  }
}
