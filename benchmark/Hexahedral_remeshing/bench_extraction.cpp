// Benchmark: hex extraction from integer-grid maps (.hexex): seconds per step and hexahedra per second,
// medians of several runs, and the check of the extracted mesh.
//   bench_extraction [--runs N] MAP.hexex...   (default: the quantized maps of ../shared/data/igm)
#include <CGAL/Hexahedral_remeshing/IO/read_HexEx.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_extraction.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_validation.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "benchmark_timing.h"

namespace HR = CGAL::Hexahedral_remeshing;

int main(int argc, char** argv)
{
  int runs = 3;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else files.push_back(a);
  }
  if(files.empty()) {
    const std::string igm = std::string(HEXREM_SHARED_DATA_DIR) + "/igm/";
    for(const char* m : {"minimal", "sphere", "hand_q", "fancy_ring_q", "rockerarm_q"}) files.push_back(igm + m + ".hexex");
  }
  std::cout << std::left << std::setw(16) << "map" << std::right << std::setw(8) << "tets" << std::setw(8) << "hexes"
            << std::setw(10) << "topo s" << std::setw(10) << "sanit s" << std::setw(10) << "verts s" << std::setw(10)
            << "cells s" << std::setw(10) << "total s" << std::setw(12) << "hexes/s" << std::setw(8) << "minSJ"
            << std::setw(8) << "valid" << "\n";
  for(const std::string& f : files) {
    HR::Integer_grid_map map;
    try {
      HR::IO::read_HexEx(f, map);
    } catch(const std::exception& e) {
      std::cout << std::left << std::setw(16) << std::filesystem::path(f).stem().string() << " " << e.what() << "\n";
      continue;
    }
    std::vector<double> topo, sanit, verts, cells, total;
    HR::Hexahedral_mesh_3 hexes;
    HR::Hexahedral_extraction_result r;
    for(int k = 0; k < runs; ++k) {
      r = HR::extract_hexahedra(map, hexes);
      topo.push_back(r.topology_seconds);
      sanit.push_back(r.sanitize_seconds);
      verts.push_back(r.vertices_seconds);
      cells.push_back(r.cells_seconds);
      total.push_back(r.seconds);
    }
    const HR::Hexahedral_mesh_check c = HR::check_hexahedral_mesh(hexes);
    std::cout << std::left << std::setw(16) << std::filesystem::path(f).stem().string() << std::right << std::setw(8)
              << map.number_of_tetrahedra() << std::setw(8) << hexes.number_of_hexahedra() << std::fixed
              << std::setprecision(4) << std::setw(10) << median(topo) << std::setw(10) << median(sanit) << std::setw(10)
              << median(verts) << std::setw(10) << median(cells) << std::setw(10) << median(total) << std::setprecision(0)
              << std::setw(12) << hexes.number_of_hexahedra() / std::max(median(total), 1e-9) << std::setprecision(3)
              << std::setw(8) << c.min_scaled_jacobian << std::setw(8) << (c.valid ? "yes" : "no") << "\n"
              << std::defaultfloat;
  }
}
