// Benchmark of the boundary edge valences and of the boundary direction constraints (Desobry et
// al., Sec. 4 and 5) with the default low_angle heuristic: medians of several runs of each step,
// the counters of Algorithm 1 (queue pops, searches, accepted updates), E(n) and E(v); the
// constraint step is also timed without the early exit (energy_tolerance 0), to show what the
// triangles whose normals already meet their valences cost.
//   bench_constraints [--runs N] FILE...      (default: B0 and i01c_m1 of ../shared/data)
#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/boundary_direction_constraints.h>
#include <CGAL/Hexahedral_remeshing/boundary_edge_valences.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "benchmark_timing.h"

namespace HR = CGAL::Hexahedral_remeshing;
namespace HP = CGAL::Hexahedral_remeshing::parameters;

int main(int argc, char** argv)
{
  int runs = 7;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else files.push_back(a);
  }
  if(files.empty()) {
    const std::string shared = HEXREM_SHARED_DATA_DIR;
    files = {shared + "/mambo/B0.vtk", shared + "/hexme/i01c_m1.vtk"};
  }
  std::cout << "hardware threads: " << std::thread::hardware_concurrency() << " (the computation is sequential)\n";
  std::cout << std::left << std::setw(14) << "model" << std::right << std::setw(8) << "tets" << std::setw(7) << "tris"
            << std::setw(11) << "valence s" << std::setw(12) << "constrain s" << std::setw(9) << "pops" << std::setw(9)
            << "searches" << std::setw(9) << "updates" << std::setw(12) << "no-exit s" << std::setw(9) << "searches"
            << std::setw(8) << "E(n)" << std::setw(8) << "E(v)" << "\n";
  for(const std::string& f : files) {
    HR::Tetrahedral_mesh_3<> mesh;
    try {
      HR::IO::read_tetrahedral_mesh(f, mesh);
    } catch(const std::exception& e) {
      std::cerr << e.what() << "\n";
      return 1;
    }
    std::vector<double> valence_s, constraint_s, no_exit_s;
    std::vector<int> valences;
    std::vector<Eigen::Vector3d> directions;
    HR::Boundary_direction_constraints_result result, no_exit;
    for(int r = 0; r < runs; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      HR::compute_boundary_edge_valences(mesh, valences);
      valence_s.push_back(seconds_since(t0));
      result = HR::compute_boundary_direction_constraints(mesh, valences, directions);
      constraint_s.push_back(result.seconds);
      no_exit = HR::compute_boundary_direction_constraints(mesh, valences, directions, HP::energy_tolerance(0.));
      no_exit_s.push_back(no_exit.seconds);
    }
    const std::string name = f.substr(f.find_last_of('/') + 1);
    std::cout << std::left << std::setw(14) << name << std::right << std::setw(8) << mesh.number_of_tetrahedra()
              << std::setw(7) << mesh.number_of_boundary_triangles() << std::fixed << std::setprecision(4)
              << std::setw(11) << median(valence_s) << std::setw(12) << median(constraint_s) << std::setw(9)
              << result.queue_pops << std::setw(9) << result.searches << std::setw(9) << result.iterations
              << std::setw(12) << median(no_exit_s) << std::setw(9) << no_exit.searches << std::setw(8)
              << result.initial_energy << std::setw(8) << result.final_energy << std::defaultfloat << "\n";
  }
  std::cout << "(" << runs << " runs, medians; E in radians)\n";
  return 0;
}
