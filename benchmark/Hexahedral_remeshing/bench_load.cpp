// Benchmark: time to read a tetrahedral mesh file and build Tetrahedral_mesh_3 (faces, rings,
// boundary, validation), median of several runs, and the peak resident memory of the process.
//   bench_load [--runs N] FILE...      (default: B0 and i01c_m1 of ../shared/data)
#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "benchmark_timing.h"

namespace HR = CGAL::Hexahedral_remeshing;

int main(int argc, char** argv)
{
  int runs = 5;
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
  std::cout << std::left << std::setw(16) << "model" << std::right << std::setw(10) << "tets in" << std::setw(10)
            << "tets" << std::setw(12) << "read s" << std::setw(12) << "build s" << std::setw(12) << "total s\n";
  for(const std::string& f : files) {
    std::vector<double> read_s, build_s;
    HR::Tetrahedral_mesh_3<> mesh;
    std::size_t input_tets = 0;
    try {
      for(int r = 0; r < runs; ++r) {
        auto t0 = std::chrono::steady_clock::now();
        HR::Tetrahedral_soup_3<HR::Tetrahedral_mesh_3<>::Point_3> soup;
        HR::IO::read_tetrahedral_soup(f, soup);
        read_s.push_back(seconds_since(t0));
        input_tets = soup.tetrahedra.size();
        t0 = std::chrono::steady_clock::now();
        HR::build_tetrahedral_mesh(soup, mesh);
        build_s.push_back(seconds_since(t0));
      }
    } catch(const std::exception& e) {
      std::cerr << e.what() << "\n";
      return 1;
    }
    std::string name = f.substr(f.find_last_of('/') + 1);
    std::cout << std::left << std::setw(16) << name << std::right << std::setw(10) << input_tets << std::setw(10)
              << mesh.number_of_tetrahedra() << std::fixed << std::setprecision(4) << std::setw(12) << median(read_s)
              << std::setw(12) << median(build_s) << std::setw(12) << median(read_s) + median(build_s) << "\n";
  }
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  std::cout << "peak resident memory: " << usage.ru_maxrss / 1024.0 << " MiB (" << runs << " runs, medians)\n";
  return 0;
}
