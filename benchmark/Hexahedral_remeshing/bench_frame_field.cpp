// Benchmark of the frame-field pipeline, stage by stage (medians of several runs) and peak memory.
//   bench_frame_field [--runs N] [--threads T] [--max-volume V] FILE...   (default: B0 and i01c_m1 of
//                     ../shared/data; V: TetGen's volume bound for surfaces, see boundary_surface.py)
//   bench_frame_field --series [--runs N] [--threads T] N1 N2 ...   (TetGen cylinders of about N tets)
// Meshes are built with split_boundary_chords(true), as hexmesh does. Columns: seconds per stage, peak
// memory, CG iterations of the relaxation, L-BFGS iterations, CG iterations of the realignment, and the
// energy before and after the smoothing; a series ends with the fitted growth exponents.
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

struct Row
{
  double tets = 0, field = 0, realignment = 0;
};

// One model: medians of the stage times, the iterations and energies of the last run (they do not
// vary between runs: the pipeline is deterministic), the peak memory of the process so far.
Row run(const std::string& name, const Mesh& mesh, int runs)
{
  std::map<std::string, std::vector<double> > samples;
  std::vector<double> frame_field, total;
  HR::Frame_field_pipeline_result result;
  for(int r = 0; r < runs; ++r) {
    Stage_timer timer;
    result = HR::compute_frame_field_pipeline(mesh, CGAL::parameters::visitor(std::ref(timer)));
    for(const std::string& s : stages) samples[s].push_back(timer.seconds[s]);
    frame_field.push_back(result.frame_field.seconds);
    total.push_back(result.seconds);
  }
  std::cout << std::left << std::setw(22) << name << std::right << std::setw(9) << mesh.number_of_tetrahedra();
  std::cout << std::fixed << std::setprecision(3);
  for(const std::string& s : stages) std::cout << std::setw(10) << median(samples[s]);
  std::cout << std::setw(10) << median(frame_field) << std::setw(10) << median(total) << std::setw(10)
            << std::setprecision(0) << peak_mib() << std::setw(9) << std::setprecision(0)
            << peak_mib() * 1024.0 * 1024.0 / double(mesh.number_of_tetrahedra());
  std::cout << std::setw(7) << result.frame_field.relaxation_iterations << std::setw(7)
            << result.frame_field.smoothing_iterations << std::setw(7) << result.realignment.solver_iterations
            << std::setprecision(4) << std::setw(14) << result.frame_field.initial_energy << std::setw(14)
            << result.frame_field.energy << "\n";
  Row row;
  row.tets = double(mesh.number_of_tetrahedra());
  row.field = median(frame_field);
  row.realignment = median(samples["realignment"]);
  return row;
}

// Least-squares slope of log(seconds) against log(tets): the growth exponent.
double growth_exponent(const std::vector<Row>& rows, double Row::*time, double Row::*plus = nullptr)
{
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for(const Row& r : rows) {
    const double x = std::log(r.tets), y = std::log(r.*time + (plus ? r.*plus : 0.0));
    sx += x; sy += y; sxx += x * x; sxy += x * y;
  }
  const double n = double(rows.size());
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

} // namespace

int main(int argc, char** argv)
{
  int runs = 3;
  bool series = false;
  double max_volume = 0;
  std::vector<std::string> args;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
#ifdef _OPENMP
    else if(a == "--threads" && i + 1 < argc) omp_set_num_threads(std::max(1, std::atoi(argv[++i])));
#endif
    else if(a == "--series") series = true;
    else if(a == "--max-volume" && i + 1 < argc) max_volume = std::atof(argv[++i]);
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
  std::cout << std::setw(10) << "field" << std::setw(10) << "total" << std::setw(10) << "MiB" << std::setw(9) << "B/tet"
            << std::setw(7) << "cg_it" << std::setw(7) << "lbfgs" << std::setw(7) << "re_it" << std::setw(14) << "E_initial"
            << std::setw(14) << "E_smoothed\n";
  std::vector<Row> rows;
  try {
    for(const std::string& a : args) {
      Mesh mesh;
      if(series) {
        // cylinder r = 1, h = 2 (volume ~6.24): the volume bound that gives about N tets
        const double target = std::atof(a.c_str());
        HR::IO::read_tetrahedral_mesh(std::string(HEXREM_EXAMPLE_DATA_DIR) + "/cylinder.off", mesh,
                                      HR::parameters::split_boundary_chords(true, HR::parameters::maximum_tetrahedron_volume(6.24 / (target / 1.2))));
        rows.push_back(run("cylinder~" + a, mesh, runs));
      } else {
        HR::IO::read_tetrahedral_mesh(a, mesh, HR::parameters::split_boundary_chords(true,
                                                HR::parameters::maximum_tetrahedron_volume(max_volume)));
        rows.push_back(run(a.substr(a.find_last_of('/') + 1), mesh, runs));
      }
    }
    if(series && rows.size() >= 2)
      std::cout << std::setprecision(2) << "growth exponent (seconds ~ tets^k): field " << growth_exponent(rows, &Row::field)
                << ", realignment " << growth_exponent(rows, &Row::realignment) << ", field + realignment "
                << growth_exponent(rows, &Row::field, &Row::realignment) << "\n";
  } catch(const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
