// Benchmark of the frame-field pipeline, stage by stage (medians of several runs) and peak memory.
//   bench_frame_field [--runs N] [--threads T] FILE...   (default: B0 and i01c_m1 of ../shared/data)
//   bench_frame_field --series [--runs N] [--threads T] N1 N2 ...   (TetGen cylinders of about N tets)
// Meshes are built with split_boundary_chords(true), as hexmesh does.
#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/frame_field_pipeline.h>

#include <sys/resource.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
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

struct Stage_timer : HR::Frame_field_pipeline_visitor
{
  std::map<std::string, double> seconds;
  void end_stage(const std::string& stage, double s) { seconds[stage] = s; }
};

const std::vector<std::string> stages = {"constraints", "setup", "initialization", "smoothing", "matchings", "realignment"};

void run(const std::string& name, const Mesh& mesh, int runs)
{
  std::map<std::string, std::vector<double> > samples;
  std::vector<double> frame_field, total;
  for(int r = 0; r < runs; ++r) {
    Stage_timer timer;
    const auto result = HR::compute_frame_field_pipeline(mesh, CGAL::parameters::visitor(std::ref(timer)));
    for(const std::string& s : stages) samples[s].push_back(timer.seconds[s]);
    frame_field.push_back(result.frame_field.seconds);
    total.push_back(result.seconds);
  }
  std::cout << std::left << std::setw(22) << name << std::right << std::setw(9) << mesh.number_of_tetrahedra();
  std::cout << std::fixed << std::setprecision(3);
  for(const std::string& s : stages) std::cout << std::setw(10) << median(samples[s]);
  std::cout << std::setw(10) << median(frame_field) << std::setw(10) << median(total) << std::setw(10)
            << std::setprecision(0) << peak_mib() << std::setw(9) << std::setprecision(0)
            << peak_mib() * 1024.0 * 1024.0 / double(mesh.number_of_tetrahedra()) << "\n";
}

} // namespace

int main(int argc, char** argv)
{
  int runs = 3;
  bool series = false;
  std::vector<std::string> args;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
#ifdef _OPENMP
    else if(a == "--threads" && i + 1 < argc) omp_set_num_threads(std::max(1, std::atoi(argv[++i])));
#endif
    else if(a == "--series") series = true;
    else args.push_back(a);
  }
  const std::string shared = HEXREM_SHARED_DATA_DIR;
  if(args.empty() && !series) args = {shared + "/mambo/B0.vtk", shared + "/hexme/i01c_m1.vtk"};
  if(args.empty() && series) args = {"10000", "50000", "200000", "500000"};
  int threads = 1;
#ifdef _OPENMP
  threads = omp_get_max_threads();
#endif
  std::cout << "runs " << runs << " (medians), threads " << threads << "; seconds per stage; peak RSS of the process\n";
  std::cout << std::left << std::setw(22) << "model" << std::right << std::setw(9) << "tets";
  for(const std::string& s : stages) std::cout << std::setw(10) << s.substr(0, 9);
  std::cout << std::setw(10) << "field" << std::setw(10) << "total" << std::setw(10) << "MiB" << std::setw(9) << "B/tet\n";
  try {
    for(const std::string& a : args) {
      Mesh mesh;
      if(series) {
        // cylinder r = 1, h = 2 (volume ~6.24): the volume bound that gives about N tets
        const double target = std::atof(a.c_str());
        HR::IO::read_tetrahedral_mesh(std::string(HEXREM_EXAMPLE_DATA_DIR) + "/cylinder.off", mesh,
                                      HR::parameters::split_boundary_chords(true, HR::parameters::maximum_tetrahedron_volume(6.24 / (target / 1.2))));
        run("cylinder~" + a, mesh, runs);
      } else {
        HR::IO::read_tetrahedral_mesh(a, mesh, HR::parameters::split_boundary_chords(true));
        run(a.substr(a.find_last_of('/') + 1), mesh, runs);
      }
    }
  } catch(const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
