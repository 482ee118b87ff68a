// Benchmark of the integer-grid map against the frame field of the same mesh (medians of several
// runs), with the map's stages and peak memory; "complex": tracing the motorcycle complex of the
// seamless map when it is injective (the map traces it only where the rounded map folds), with its
// blocks and the tetrahedra after the walls' splits.
//   bench_integer_grid_map [--runs N] [--target-edge-length H] [--mesh-size S] FILE...
//   (default: mambo/B0 and hexme/i01c_m1 of ../shared/data; --mesh-size: gmsh's element size for CAD
//   parts, e.g. the flange of make_parts.py at 1.7 for about 100,000 tetrahedra)
// Meshes are built with split_boundary_chords(true), as hexmesh does.
#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/frame_field_pipeline.h>
#include <CGAL/Hexahedral_remeshing/integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/motorcycle_complex.h>

#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "benchmark_timing.h"

namespace HR = CGAL::Hexahedral_remeshing;
typedef HR::Tetrahedral_mesh_3<> Mesh;

namespace {

double peak_mib()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

struct Stage_timer : HR::Integer_grid_map_visitor
{
  std::map<std::string, double> seconds;
  void end_stage(const std::string& stage, double s) { seconds[stage] += s; } // the untangling may run twice
};

const std::vector<std::string> stages = {"cut", "reduction", "elimination", "seamless_map", "rounding", "stiffening", "untangling",
                                         "continuation", "sanitizing"};

void run(const std::string& name, const Mesh& mesh, int runs, double h)
{
  std::vector<double> field_seconds, map_seconds;
  std::map<std::string, std::vector<double> > samples;
  HR::Integer_grid_map_result last;
  std::vector<double> complex_seconds;
  HR::internal::motorcycle::Motorcycle_complex_report complex;
  for(int r = 0; r < runs; ++r) {
    const auto t = std::chrono::steady_clock::now();
    const HR::Frame_field_pipeline_result field = HR::compute_frame_field_pipeline(mesh);
    field_seconds.push_back(seconds_since(t));
    HR::Integer_grid_map map;
    Stage_timer timer;
    std::vector<std::array<Eigen::Vector3d, 4> > seamless;
    last = h > 0 ? HR::compute_integer_grid_map(mesh, field, map, HR::parameters::target_edge_length(h, HR::parameters::seamless_map_parameters(&seamless, CGAL::parameters::visitor(std::ref(timer)))))
                 : HR::compute_integer_grid_map(mesh, field, map, HR::parameters::seamless_map_parameters(&seamless, CGAL::parameters::visitor(std::ref(timer))));
    map_seconds.push_back(last.seconds);
    for(const std::string& s : stages) samples[s].push_back(timer.seconds[s]);
    if(last.seamless_injective && last.map_tetrahedra == mesh.number_of_tetrahedra()) {
      std::vector<std::array<double, 3> > points;
      for(const auto& p : mesh.points()) points.push_back({{p.x(), p.y(), p.z()}});
      std::vector<std::array<std::uint32_t, 4> > tets;
      for(std::size_t t = 0; t < mesh.number_of_tetrahedra(); ++t) {
        const auto& v = mesh.tetrahedron_vertices(Mesh::Index(t));
        tets.push_back({{std::uint32_t(v[0]), std::uint32_t(v[1]), std::uint32_t(v[2]), std::uint32_t(v[3])}});
      }
      complex = HR::internal::motorcycle::trace_motorcycle_complex(points, tets, seamless).report;
      complex_seconds.push_back(complex.seconds);
    }
  }
  std::cout << std::left << std::setw(18) << name << std::right << std::setw(8) << mesh.number_of_tetrahedra()
            << std::fixed << std::setprecision(3) << std::setw(10) << median(field_seconds) << std::setw(10)
            << median(map_seconds);
  for(const std::string& s : stages) std::cout << std::setw(10) << median(samples[s]);
  std::cout << std::setw(7) << int(last.status) << std::setw(9) << last.inverted_tetrahedra << std::setw(9)
            << last.degenerate_tetrahedra << std::setw(7) << last.integer_variables << std::setw(9)
            << std::setprecision(4) << last.target_edge_length << std::setw(9) << std::setprecision(0) << peak_mib();
  if(complex_seconds.empty()) std::cout << "  no complex (seamless map not injective)";
  else
    std::cout << std::setprecision(3) << std::setw(10) << median(complex_seconds) << std::setw(8) << complex.blocks << std::setw(10)
              << complex.tetrahedra_after << (complex.success ? "" : "  " + complex.reason);
  std::cout << std::endl;
}

} // namespace

int main(int argc, char** argv)
{
  int runs = 3;
  double h = 0, mesh_size = 0;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--runs" && i + 1 < argc) runs = std::stoi(argv[++i]);
    else if(a == "--target-edge-length" && i + 1 < argc) h = std::stod(argv[++i]);
    else if(a == "--mesh-size" && i + 1 < argc) mesh_size = std::stod(argv[++i]);
    else files.push_back(a);
  }
  if(files.empty()) {
    const std::string data = HEXREM_SHARED_DATA_DIR;
    files = {data + "/mambo/B0.vtk", data + "/hexme/i01c_m1.vtk"};
  }
  std::cout << std::left << std::setw(18) << "model" << std::right << std::setw(8) << "tets" << std::setw(10) << "field"
            << std::setw(10) << "map";
  for(const std::string& s : stages) std::cout << std::setw(10) << s.substr(0, 9);
  std::cout << std::setw(7) << "status" << std::setw(9) << "inverted" << std::setw(9) << "flat" << std::setw(7) << "ints"
            << std::setw(9) << "h" << std::setw(9) << "MiB" << std::setw(10) << "complex" << std::setw(8) << "blocks"
            << std::setw(10) << "split" << "\n";
  for(const std::string& f : files) {
    Mesh mesh;
    try {
      if(mesh_size > 0) HR::IO::read_tetrahedral_mesh(f, mesh, HR::parameters::split_boundary_chords(true, HR::parameters::mesh_size(mesh_size)));
      else HR::IO::read_tetrahedral_mesh(f, mesh, HR::parameters::split_boundary_chords(true));
    } catch(const HR::Error& e) {
      std::cerr << e.what() << "\n";
      return 1;
    }
    run(std::filesystem::path(f).stem().string(), mesh, runs, h);
  }
  return 0;
}
