// Benchmark of the integer-grid map against the frame field of the same mesh (medians of several
// runs), with the map's stages and peak memory; "complex": tracing the motorcycle complex of the
// seamless map when it is injective (the map traces it only where the rounded map folds), with its
// blocks and the tetrahedra after the walls' splits.
//   bench_integer_grid_map [--runs N] [--target-edge-length H] [--mesh-size S] [--evaluator] FILE...
//   --evaluator: instead, the foldover-free untangling's evaluation (energy and gradient: the inner
//   loop of every untangling of the map) on the mesh's own shape, three variables per vertex (every
//   seventh tetrahedron reads its y coordinates negated, as a chart across a transition does), the
//   vertices moved at random by 5% of the mean tetrahedron size, epsilon 0.1: nanoseconds per element
//   and evaluation, medians of `runs` (at least 5) batches of 20 evaluations, on 1 thread and on all.
//   (default: mambo/B0 and hexme/i01c_m1 of ../shared/data; --mesh-size: gmsh's element size for CAD
//   parts, e.g. the flange of make_parts.py at 1.7 for about 100,000 tetrahedra)
// Meshes are built with split_boundary_chords(true), as hexmesh does.
#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/frame_field_pipeline.h>
#include <CGAL/Hexahedral_remeshing/integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/motorcycle_complex.h>
#include <CGAL/Hexahedral_remeshing/internal/untangling/foldover_free_map.h>

#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "benchmark_timing.h"

#ifdef _OPENMP
#include <omp.h>
#endif

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

// The untangling's problem on the mesh's own shape: y the vertices' coordinates, M_e the inverse of
// the tetrahedron's edge matrix (the input is the ideal element), w_e its volume.
HR::internal::Foldover_free_problem shape_problem(const Mesh& mesh, Eigen::VectorXd& y)
{
  const std::size_t nt = mesh.number_of_tetrahedra(), nv = mesh.number_of_vertices();
  HR::internal::Foldover_free_problem p;
  std::vector<Eigen::Triplet<double> > triplets;
  p.x0 = Eigen::VectorXd::Zero(Eigen::Index(12 * nt));
  y.resize(Eigen::Index(3 * nv));
  for(std::size_t v = 0; v < nv; ++v) {
    const auto& q = mesh.point(Mesh::Index(v));
    y.segment<3>(Eigen::Index(3 * v)) = Eigen::Vector3d(q.x(), q.y(), q.z());
  }
  double volume = 0;
  for(std::size_t t = 0; t < nt; ++t) {
    const auto& tv = mesh.tetrahedron_vertices(Mesh::Index(t));
    const bool across = t % 7 == 3;
    Eigen::Matrix3d D;
    for(int c = 0; c < 4; ++c)
      for(int k = 0; k < 3; ++k) {
        const bool negated = across && k == 1;
        triplets.emplace_back(int(12 * t + 3 * c + k), int(3 * tv[std::size_t(c)] + std::size_t(k)), negated ? -1. : 1.);
        if(c > 0) D(k, c - 1) = (negated ? -1. : 1.) * (y[Eigen::Index(3 * tv[std::size_t(c)]) + k] - y[Eigen::Index(3 * tv[0]) + k]);
      }
    p.M.push_back(D.inverse());
    p.w.push_back(std::abs(D.determinant()) / 6);
    volume += p.w.back();
  }
  p.P.resize(Eigen::Index(12 * nt), Eigen::Index(3 * nv));
  p.P.setFromTriplets(triplets.begin(), triplets.end());
  std::mt19937 rng(1);
  std::normal_distribution<double> noise(0, 0.05 * std::cbrt(volume / double(nt)));
  for(Eigen::Index i = 0; i < y.size(); ++i) y[i] += noise(rng);
  return p;
}

void run_evaluator(const std::string& name, const Mesh& mesh, int runs)
{
  Eigen::VectorXd y, g;
  const HR::internal::Foldover_free_problem p = shape_problem(mesh, y);
  HR::internal::Foldover_free_evaluator ev(p, 0.5);
  ev.epsilon = 0.1;
  int all = 1;
#ifdef _OPENMP
  all = omp_get_max_threads();
#endif
  std::cout << std::left << std::setw(18) << name << std::right << std::setw(8) << mesh.number_of_tetrahedra();
  for(int threads : {1, all}) {
#ifdef _OPENMP
    omp_set_num_threads(threads);
#endif
    std::vector<double> ns;
    double energy = 0;
    for(int r = 0; r < (std::max)(runs, 5); ++r) {
      const auto t = std::chrono::steady_clock::now();
      for(int i = 0; i < 20; ++i) energy = ev(y, g);
      ns.push_back(seconds_since(t) / 20 / double(mesh.number_of_tetrahedra()) * 1e9);
    }
    std::cout << std::fixed << std::setprecision(1) << std::setw(12) << median(ns) << " (" << threads << " thr)";
    if(threads == all) std::cout << std::setprecision(6) << "  energy " << energy;
  }
  std::cout << std::endl;
#ifdef _OPENMP
  omp_set_num_threads(all);
#endif
}

} // namespace

int main(int argc, char** argv)
{
  int runs = 3;
  double h = 0, mesh_size = 0;
  bool evaluator = false;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--runs" && i + 1 < argc) runs = std::stoi(argv[++i]);
    else if(a == "--target-edge-length" && i + 1 < argc) h = std::stod(argv[++i]);
    else if(a == "--mesh-size" && i + 1 < argc) mesh_size = std::stod(argv[++i]);
    else if(a == "--evaluator") evaluator = true;
    else files.push_back(a);
  }
  if(files.empty()) {
    const std::string data = HEXREM_SHARED_DATA_DIR;
    files = {data + "/mambo/B0.vtk", data + "/hexme/i01c_m1.vtk"};
  }
  std::cout << std::left << std::setw(18) << "model" << std::right << std::setw(8) << "tets";
  if(evaluator) std::cout << "  ns per element and evaluation\n";
  else {
    std::cout << std::setw(10) << "field" << std::setw(10) << "map";
    for(const std::string& s : stages) std::cout << std::setw(10) << s.substr(0, 9);
    std::cout << std::setw(7) << "status" << std::setw(9) << "inverted" << std::setw(9) << "flat" << std::setw(7) << "ints"
              << std::setw(9) << "h" << std::setw(9) << "MiB" << std::setw(10) << "complex" << std::setw(8) << "blocks"
              << std::setw(10) << "split" << "\n";
  }
  for(const std::string& f : files) {
    Mesh mesh;
    try {
      if(mesh_size > 0) HR::IO::read_tetrahedral_mesh(f, mesh, HR::parameters::split_boundary_chords(true, HR::parameters::mesh_size(mesh_size)));
      else HR::IO::read_tetrahedral_mesh(f, mesh, HR::parameters::split_boundary_chords(true));
    } catch(const HR::Error& e) {
      std::cerr << e.what() << "\n";
      return 1;
    }
    if(evaluator) run_evaluator(std::filesystem::path(f).stem().string(), mesh, runs);
    else run(std::filesystem::path(f).stem().string(), mesh, runs, h);
  }
  return 0;
}
