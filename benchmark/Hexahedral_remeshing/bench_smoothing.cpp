// Benchmark: smooth_hexahedral_mesh() on generated tangled grids and on the hex meshes extracted from
// the quantized integer-grid maps of ../shared/data/igm (reference: the boundary of their tet mesh).
// Prints the quality before / after and the seconds (median of the runs) per 100k hexahedra.
//   bench_smoothing [--runs N] [--grids N1,N2,...] [--iterations K] [MAP.hexex...]
#include <CGAL/Hexahedral_remeshing/IO/read_HexEx.h>
#include <CGAL/Hexahedral_remeshing/Tetrahedral_soup_3.h>
#include <CGAL/Hexahedral_remeshing/build_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_extraction.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_smoothing.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "benchmark_timing.h"

namespace HR = CGAL::Hexahedral_remeshing;
typedef HR::Hexahedral_mesh_3::Point_3 Point;

namespace {

// n^3 cubes of [0,1]^3, tags set, interior vertices moved by up to 0.45 cell per axis (some
// hexahedra inverted); the reference is the cube (12 triangles, 12 edges, 8 corners).
void tangled_grid(int n, HR::Hexahedral_mesh_3& mesh, HR::Hexahedral_smoothing_reference& ref)
{
  mesh = HR::Hexahedral_mesh_3();
  ref = HR::Hexahedral_smoothing_reference();
  auto id = [n](int i, int j, int k) { return std::uint32_t((k * (n + 1) + j) * (n + 1) + i); };
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-0.45 / n, 0.45 / n);
  for(int k = 0; k <= n; ++k)
    for(int j = 0; j <= n; ++j)
      for(int i = 0; i <= n; ++i) {
        const int on = int(i == 0 || i == n) + int(j == 0 || j == n) + int(k == 0 || k == n);
        std::uint8_t tag = 0;
        if(on >= 1) tag |= HR::Hexahedral_mesh_3::BOUNDARY;
        if(on >= 2) tag |= HR::Hexahedral_mesh_3::FEATURE_CURVE;
        if(on == 3) tag |= HR::Hexahedral_mesh_3::CORNER;
        double x = double(i) / n, y = double(j) / n, z = double(k) / n;
        if(on == 0) { x += u(rng); y += u(rng); z += u(rng); }
        mesh.points.emplace_back(x, y, z);
        mesh.vertex_tags.push_back(tag);
      }
  for(int k = 0; k < n; ++k)
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i)
        mesh.hexahedra.push_back({ {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                                    id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)} });
  for(int c = 0; c < 8; ++c) ref.points.emplace_back(c & 1, (c >> 1) & 1, (c >> 2) & 1);
  const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for(const auto& q : quads) {
    ref.triangles.push_back({ {q[0], q[1], q[2]} });
    ref.triangles.push_back({ {q[0], q[2], q[3]} });
  }
  for(int a = 0; a < 8; ++a)
    for(int b = a + 1; b < 8; ++b)
      if(__builtin_popcount(unsigned(a ^ b)) == 1) ref.feature_polylines.push_back({ref.points[a], ref.points[b]});
  ref.corners = ref.points;
}

bool extracted(const std::string& file, HR::Hexahedral_mesh_3& hexes, HR::Hexahedral_smoothing_reference& ref)
{
  HR::Integer_grid_map map;
  try {
    HR::IO::read_HexEx(file, map);
  } catch(const std::exception& e) {
    std::cout << std::filesystem::path(file).stem().string() << ": " << e.what() << "\n";
    return false;
  }
  HR::extract_hexahedra(map, hexes);
  HR::Tetrahedral_soup_3<Point> soup;
  soup.points.assign(map.points.begin(), map.points.end());
  for(const auto& t : map.tetrahedra) soup.tetrahedra.push_back({ {t[0], t[1], t[2], t[3]} });
  HR::Tetrahedral_mesh_3<> tets;
  try {
    HR::build_tetrahedral_mesh(soup, tets, HR::parameters::split_multi_boundary_tetrahedra(false));
  } catch(const std::exception& e) {
    std::cout << std::filesystem::path(file).stem().string() << ": no reference (" << e.what() << ")\n";
    return false;
  }
  ref = HR::make_hexahedral_smoothing_reference(tets);
  return hexes.number_of_hexahedra() > 0;
}

void run(const std::string& name, const HR::Hexahedral_mesh_3& input, const HR::Hexahedral_smoothing_reference& ref,
         int runs, int iterations)
{
  std::vector<double> seconds;
  HR::Hexahedral_smoothing_report r;
  for(int k = 0; k < runs; ++k) {
    HR::Hexahedral_mesh_3 hexes = input;
    const auto t0 = std::chrono::steady_clock::now();
    r = HR::smooth_hexahedral_mesh(hexes, ref, CGAL::parameters::number_of_iterations(iterations));
    seconds.push_back(seconds_since(t0));
  }
  const double s = median(seconds);
  auto q = [](const HR::Hexahedral_mesh_quality& x) {
    std::ostringstream o;
    o << std::fixed << std::setprecision(3) << std::setw(7) << x.min_scaled_jacobian << std::setw(7)
      << x.mean_scaled_jacobian << std::setw(7) << x.low_quality_share << std::setw(7) << x.non_positive
      << std::scientific << std::setprecision(1) << std::setw(9) << x.hausdorff_distance;
    return o.str();
  };
  std::cout << std::left << std::setw(14) << name << std::right << std::setw(9) << input.number_of_hexahedra() << " |"
            << q(r.before) << " |" << q(r.after) << " |" << std::setw(4) << r.rounds << std::setw(3)
            << (r.untangling_run ? (r.global_untangling_run ? "G" : "L") : "-") << std::fixed << std::setprecision(3)
            << std::setw(9) << s << std::setw(10) << std::setprecision(2) << s * 1e5 / double(input.number_of_hexahedra())
            << "\n" << std::flush;
}

} // namespace

int main(int argc, char** argv)
{
  int runs = 3, iterations = 10;
  std::vector<int> grids{20, 30, 46};
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else if(a == "--iterations" && i + 1 < argc) iterations = std::max(0, std::atoi(argv[++i]));
    else if(a == "--grids" && i + 1 < argc) {
      grids.clear();
      std::istringstream in(argv[++i]);
      std::string x;
      while(std::getline(in, x, ',')) if(!x.empty()) grids.push_back(std::atoi(x.c_str()));
    } else files.push_back(a);
  }
  if(files.empty()) {
    const std::string igm = std::string(HEXREM_SHARED_DATA_DIR) + "/igm/";
    for(const char* m : {"hand_q", "fancy_ring_q", "rockerarm_q"})
      if(std::filesystem::exists(igm + m + ".hexex")) files.push_back(igm + m + ".hexex");
  }
  std::cout << "smooth_hexahedral_mesh, " << iterations << " sweeps at most, median of " << runs << " runs\n"
            << std::left << std::setw(14) << "mesh" << std::right << std::setw(9) << "hexes" << " |"
            << "  before: minSJ  mean  <0.3   <=0  Hausdorff |   after: minSJ  mean  <0.3   <=0  Hausdorff | sweeps untangle"
            << "  seconds  s/100k\n";
  for(int n : grids) {
    HR::Hexahedral_mesh_3 hexes;
    HR::Hexahedral_smoothing_reference ref;
    tangled_grid(n, hexes, ref);
    run("grid" + std::to_string(n), hexes, ref, runs, iterations);
  }
  for(const std::string& f : files) {
    HR::Hexahedral_mesh_3 hexes;
    HR::Hexahedral_smoothing_reference ref;
    if(extracted(f, hexes, ref)) run(std::filesystem::path(f).stem().string(), hexes, ref, runs, iterations);
  }
  return 0;
}
