// The repair of the singularity graph per model: defects of the local check by reason before the
// repair, after the matching surgery, after the realignment with the repaired matchings, and from the
// realigned frames alone (their closest matchings, what an independent reader of the frames sees);
// the repair's seconds against the frame field's (medians of --runs runs). The repair runs at the
// hex scale of the map's default size (about 2000 hexahedra), as hexahedral_remeshing() runs it.
//   bench_singularity_repair [--runs N] FILE...   (default: every model of ../shared/data)
// Meshes are built with split_boundary_chords(true), as hexmesh does.
#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/frame_field_pipeline.h>
#include <CGAL/Hexahedral_remeshing/local_meshability.h>

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "benchmark_timing.h"

namespace HR = CGAL::Hexahedral_remeshing;
typedef HR::Tetrahedral_mesh_3<> Mesh;
typedef Mesh::Index Index;
namespace fs = std::filesystem;

namespace {

// "improper/jog/zipper/node/contact/plane/zigzag" (plane: curve ends in a boundary plane; dangling ends are
// impossible with exact matchings: printed only when present), then the feature sectors and the
// disagreeing faces
std::string counts(const std::array<std::size_t, HR::number_of_meshability_reasons>& c)
{
  typedef HR::Meshability_reason R;
  auto n = [&](R r) { return std::to_string(c[std::size_t(r)]); };
  std::string s = n(R::IMPROPER_EDGE) + "/" + n(R::JOG) + "/" + n(R::ZIPPER) + "/" + n(R::INVALID_NODE) + "/" +
                  n(R::BOUNDARY_CONTACT) + "/" + n(R::END_IN_BOUNDARY_PLANE) + "/" + n(R::ZIGZAG_FACE);
  if(c[std::size_t(R::DANGLING_END)] > 0) s += " dangling " + n(R::DANGLING_END);
  return s;
}

// The hex edge of about 2000 hexahedra (the map's default size).
double default_hex_edge(const Mesh& mesh)
{
  double volume = 0;
  for(Index t = 0; t < mesh.number_of_tetrahedra(); ++t) {
    const auto& v = mesh.tetrahedron_vertices(t);
    volume += CGAL::to_double(CGAL::volume(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3])));
  }
  return std::cbrt(volume / 2000);
}

void run(const std::string& name, const Mesh& mesh, int runs)
{
  std::vector<double> field_seconds, repair_seconds;
  HR::Frame_field_pipeline_result r;
  const double h = default_hex_edge(mesh);
  for(int k = 0; k < runs; ++k) {
    r = HR::compute_frame_field_pipeline(mesh, HR::parameters::singularity_repair(true, HR::parameters::repair_hex_edge_length(h)));
    field_seconds.push_back(r.frame_field.seconds);
    repair_seconds.push_back(r.repair.seconds);
  }
  const HR::Local_meshability_report alone =
    HR::check_local_meshability(mesh, r.frames, HR::compute_matchings(mesh, r.frames));
  std::string operations;
  for(const auto& o : r.repair.operations) operations += (operations.empty() ? "" : " ") + std::to_string(o.second);
  std::cout << std::left << std::setw(28) << name << std::right << std::setw(8) << mesh.number_of_tetrahedra() << "  "
            << std::setw(18) << counts(r.meshability_before.counts) << std::setw(18) << counts(r.repair.defects_after)
            << std::setw(18) << counts(r.meshability.counts) << std::setw(18) << counts(alone.counts) << std::setw(7)
            << r.meshability.count(HR::Meshability_reason::DISAGREEING_FACE) << std::setw(6)
            << r.meshability.count(HR::Meshability_reason::FEATURE_SECTOR) << std::setw(14)
            << (operations.empty() ? "-" : (r.repair.accepted ? "" : "x ") + operations) << std::setw(7)
            << (std::to_string(r.repair.simplified_clusters) + "/" + std::to_string(r.repair.hex_scale_clusters)) << std::fixed << std::setprecision(3) << std::setw(9)
            << median(repair_seconds) << std::setw(9) << median(field_seconds) << "\n" << std::defaultfloat;
}

} // namespace

int main(int argc, char** argv)
{
  int runs = 1;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else files.push_back(a);
  }
  if(files.empty()) {
    for(const char* dir : {"hexme", "mambo"}) {
      const fs::path d = fs::path(HEXREM_SHARED_DATA_DIR) / dir;
      if(!fs::exists(d)) continue;
      std::vector<std::string> found;
      for(const auto& entry : fs::directory_iterator(d))
        if(entry.path().extension() == ".vtk") found.push_back(entry.path().string());
      std::sort(found.begin(), found.end());
      files.insert(files.end(), found.begin(), found.end());
    }
  }
  std::cout << "defects improper/jog/zipper/node/contact/plane/zigzag: field of step 3 before the repair | realigned field after the"
               " surgery | returned field (kept matchings) | returned frames alone; disagreeing faces and feature sectors after the realignment;"
               " changes by operation (move/zigzag/search/slide jog/slide end/sweep/hex scale; x: not kept); clusters of curves removed/found at the"
               " hex scale; seconds of the repair and of the frame field (median of "
            << runs << ")\n";
  for(const std::string& f : files) {
    Mesh mesh;
    try {
      HR::IO::read_tetrahedral_mesh(f, mesh, HR::parameters::split_boundary_chords(true));
      run(fs::path(f).stem().string(), mesh, runs);
    } catch(const std::exception& e) {
      std::cout << fs::path(f).stem().string() << ": " << e.what() << "\n";
    }
  }
  return 0;
}
