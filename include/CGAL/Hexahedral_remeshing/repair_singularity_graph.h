// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_REPAIR_SINGULARITY_GRAPH_H
#define CGAL_HEXAHEDRAL_REMESHING_REPAIR_SINGULARITY_GRAPH_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/local_meshability.h>
#include <CGAL/Hexahedral_remeshing/parameters.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/greedy_surgery.h>
#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/local_matching_search.h>
#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/move_singular_edge.h>
#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/pull_curve_end.h>
#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/remove_zigzag.h>
#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/simplify_at_hex_scale.h>
#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/slide_curve_end.h>
#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/slide_jog.h>
#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/sweep_curve.h>

#include <Eigen/Dense>

#include <array>
#include <chrono>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

namespace internal_np {
enum singularity_repair_t { singularity_repair };
enum maximum_repair_steps_t { maximum_repair_steps };
enum repair_hex_edge_length_t { repair_hex_edge_length };
enum repair_sweeps_t { repair_sweeps };
enum maximum_repair_rounds_t { maximum_repair_rounds };
} // namespace internal_np

namespace parameters {
#ifdef DOXYGEN_RUNNING
/// Pipeline: repair the singularity graph of the realigned field (`bool`, default `true`, `false` with
/// `baseline(true)`).
template <class T> unspecified_type singularity_repair(const T& value);
/// Repair: maximum number of defects visited by the matching surgery (`std::size_t`, default
/// `20 * (defects + 100)`).
template <class T> unspecified_type maximum_repair_steps(const T& value);
/// Repair: the hex edge length of the map to come (model units, default `0`: no hex-scale
/// simplification); `hexahedral_remeshing()` passes its own.
template <class T> unspecified_type repair_hex_edge_length(const T& value);
/// Repair: after the short changes, sweep the curves that no short change repairs (`"sweep_curve"`;
/// `bool`, default `true`).
template <class T> unspecified_type repair_sweeps(const T& value);
/// Pipeline: rounds of repair of the realigned field at most (surgery, then the frames re-optimized),
/// each from the field the previous one kept, until one is not kept (`int`, default `8`).
template <class T> unspecified_type maximum_repair_rounds(const T& value);
#else
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(singularity_repair)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(maximum_repair_steps)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(repair_hex_edge_length)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(repair_sweeps)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(maximum_repair_rounds)
#endif
} // namespace parameters

/// \ingroup PkgHexahedralRemeshingRef
/// Report of `repair_singularity_graph()`.
struct Singularity_repair_result
{
  /// Violations of the local check by reason (indexed by `Meshability_reason`) before the repair.
  std::array<std::size_t, number_of_meshability_reasons> defects_before{};
  /// Violations of the local check by reason after the repair (same frames, repaired matchings;
  /// `DISAGREEING_FACE` counts the faces the surgery changed until the frames follow them).
  std::array<std::size_t, number_of_meshability_reasons> defects_after{};
  /// Changes applied by each operation: (name, count), in the order the operations are tried.
  std::vector<std::pair<std::string, std::size_t> > operations;
  /// Faces whose matching differs from the input matching at the end.
  std::size_t changed_faces = 0;
  /// Clusters of singular curves with no room at the hex scale (named parameter
  /// `repair_hex_edge_length`): curves within a hex edge of each other, loops and stubs smaller than one.
  std::size_t hex_scale_clusters = 0;
  /// Those of `hex_scale_clusters` that the repair removed.
  std::size_t simplified_clusters = 0;
  /// Why the others stay, (reason, count): `"too_large"` (region over the size limit),
  /// `"collar_not_flat"` (another curve crosses the region's collar, or the holonomies do not cancel),
  /// `"not_editable"`, `"boundary_valence"` (an achieved boundary valence would change), `"not_cheaper"`;
  /// every reason is listed, with 0 where the repair did not run.
  std::vector<std::pair<std::string, std::size_t> > hex_scale_kept = {
    {"too_large", 0}, {"collar_not_flat", 0}, {"not_editable", 0}, {"boundary_valence", 0}, {"not_cheaper", 0}};
  /// Changes of `"sweep_curve"` (also in `operations`).
  std::size_t swept_curves = 0;
  /// Changes of `"pull_end"` (also in `operations`): curve ends in boundary planes pulled onto the faces
  /// their curves cross, tried once the sweeps are done and only if such ends are left.
  std::size_t pulled_curve_ends = 0;
  /// In the pipeline: the first round's repair with the sweeps was not kept, and the one without them
  /// was tried (and kept if `accepted`).
  bool without_sweeps = false;
  /// In the pipeline: rounds kept (named parameter `maximum_repair_rounds`). A round is the surgery
  /// on the field the previous one kept, with that field's re-optimized frames, then the frames
  /// re-optimized again; the rounds stop at the first one not kept. `operations`, `swept_curves`,
  /// `pulled_curve_ends` and `simplified_clusters` add up the rounds kept (the first round's if none
  /// is); `defects_before`, `hex_scale_clusters` and `hex_scale_kept` are the first round's,
  /// `defects_after` the last round kept's. `repair_singularity_graph()` alone sets it to 1 if it
  /// changed a face, 0 otherwise.
  int rounds = 0;
  /// In the pipeline (`compute_frame_field_pipeline()`), which repairs the realigned field and
  /// re-optimizes its frames: true if the repaired field was kept (no worse with the kept matchings and
  /// from the frames alone, better in one), false if the field was left as the realignment made it.
  /// `repair_singularity_graph()` alone sets it to `changed_faces > 0`.
  bool accepted = false;
  /// In the pipeline: graph defects of the check (every reason but the feature sectors and the
  /// disagreeing faces) of the realigned field with the kept matchings, before and after the repair.
  std::size_t graph_defects_before = 0;
  /// See `graph_defects_before`.
  std::size_t graph_defects_after = 0;
  /// In the pipeline: graph defects of the frames with their own closest matchings (what a reader of
  /// the frames alone sees), before and after the repair.
  std::size_t frame_graph_defects_before = 0;
  /// See `frame_graph_defects_before`.
  std::size_t frame_graph_defects_after = 0;
  /// Seconds.
  double seconds = 0;

  /// Number of changes of all operations.
  std::size_t applied() const
  {
    std::size_t n = 0;
    for(const auto& o : operations) n += o.second;
    return n;
  }
};

namespace internal {

template <class Mesh>
std::vector<std::unique_ptr<Singularity_repair_operation<Mesh> > > singularity_repair_operations()
{
  std::vector<std::unique_ptr<Singularity_repair_operation<Mesh> > > operations;
  operations.emplace_back(new Move_singular_edge<Mesh>());
  operations.emplace_back(new Remove_zigzag<Mesh>());
  operations.emplace_back(new Local_matching_search<Mesh>());
  operations.emplace_back(new Slide_jog<Mesh>());
  operations.emplace_back(new Slide_curve_end<Mesh>());
  return operations;
}


} // namespace internal

/// \ingroup PkgHexahedralRemeshingRef
/// Repairs the singularity graph of a frame field by matching surgery, so that it passes the local
/// check of `check_local_meshability()` (design notes `robust_pipeline.md` §1; Li et al. 2012;
/// Liu, Bommes et al. 2023): the matching of one face at a time is changed, which moves the
/// holonomy between the three edges of the face. Operations, tried at every defect (jog, improper
/// edge, zipper, invalid node, boundary contact, curve end in a boundary plane): a defective edge moved across a triangle of its
/// ring (`"move_singular_edge"`), two singular edges of one triangle replaced by the third or
/// cancelled (`"remove_zigzag"`), any other matching of a face around the defect
/// (`"matching_search"`), a jog slid one vertex along its curve by two changes evaluated together
/// (`"slide_jog"`), the end of a curve in a boundary plane slid by two triangles evaluated together
/// (`"slide_end"`); then, where none of these helps, a piece of a curve swept across a sheet of up to 24
/// triangles, each edge move chosen as the cheapest next one (from the 8 cheapest first moves) and the
/// cheapest prefix of three moves or more kept (`"sweep_curve"`, named parameter `repair_sweeps`: a curve bent into a side face). A change
/// is kept only if it lowers a cost in which defects dominate
/// (improper edges, then jogs by their angle, then defective vertices) and the length of the
/// singular curves breaks ties; so the repair never adds defects, and it stops at a local minimum.
/// Every achieved boundary valence (the paper's guarantee) stays as it was: with the `directions`
/// the frames follow, a face with a boundary edge may change only if the valence of Eq. 3 of each of
/// its boundary edges stays the same (a singular curve's end slides along the boundary); without
/// them, such faces are never changed.
///
/// At the hex scale (named parameter `repair_hex_edge_length` = h > 0), after the surgery
/// (`"simplify_at_hex_scale"`, counted in clusters): a connected set of singular curves whose bounding
/// box is smaller than h (a small loop, a short stub between two boundary points), and two sets within
/// h of each other everywhere (Hausdorff distance; a valence-3 curve beside a valence-5 one), have no
/// room in a map of hex edge h. Such a cluster is removed by making the field flat in a region around
/// it (every face there gets the matching of one gauge carried across the region's collar), where the
/// collar is flat itself (no other curve crosses it; the holonomies of the cluster cancel), no
/// achieved boundary valence changes and the cost goes down; otherwise the cluster stays.
///
/// The frames are not changed: re-optimize them with the repaired matchings fixed
/// (`realign_frame_field()`, which `compute_frame_field_pipeline()` runs after the repair).
///
/// \param mesh the tetrahedral mesh
/// \param frames one frame per tetrahedron (they give the world axes of the holonomies)
/// \param matchings the kept matchings, repaired in place
/// \param directions empty, or one direction per boundary triangle: those the boundary frames follow
///        (the constraints `v` before the realignment, the normals after it)
/// \param np optional named parameters: `maximum_repair_steps`, `repair_hex_edge_length`, `repair_sweeps`
/// \returns the defects by reason before and after, the changes by operation, the seconds
/// \throws Error if `frames` or `matchings` are not sized for `mesh`.
template <class Traits, class NamedParameters = CGAL::parameters::Default_named_parameters>
Singularity_repair_result repair_singularity_graph(const Tetrahedral_mesh_3<Traits>& mesh,
                                                   const std::vector<Eigen::Matrix3d>& frames,
                                                   Matchings& matchings,
                                                   const std::vector<Eigen::Vector3d>& directions = std::vector<Eigen::Vector3d>(),
                                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef Tetrahedral_mesh_3<Traits> Mesh;
  const auto start = std::chrono::steady_clock::now();
  Singularity_repair_result r;
  r.defects_before = check_local_meshability(mesh, frames, matchings).counts;
  const std::size_t defects = internal::graph_defect_count(r.defects_before);
  const std::size_t max_steps = choose_parameter(get_parameter(np, internal_np::maximum_repair_steps), 20 * (defects + 100));
  const std::vector<int> input = matchings.face_matching;
  if(!directions.empty() && directions.size() != mesh.number_of_boundary_triangles())
    throw Error("repair_singularity_graph: one direction per boundary triangle expected");
  const double hex_edge = choose_parameter(get_parameter(np, internal_np::repair_hex_edge_length), 0.);
  if(defects > 0 || hex_edge > 0) {
    const auto operations = internal::singularity_repair_operations<Mesh>();
    internal::Singularity_repair_state<Mesh> state(mesh, frames, matchings.face_matching, directions.empty() ? nullptr : &directions);
    std::vector<std::size_t> applied, again;
    internal::greedy_surgery(state, operations, max_steps, applied);
    // the defects no short change repairs: with the sweeps too (proposed from the start, a sweep would
    // take defects that the short changes repair better)
    std::vector<std::size_t> swept(operations.size() + 1, 0);
    if(choose_parameter(get_parameter(np, internal_np::repair_sweeps), true)) {
      auto with_sweep = internal::singularity_repair_operations<Mesh>();
      with_sweep.emplace_back(new internal::Sweep_curve<Mesh>());
      internal::greedy_surgery(state, with_sweep, max_steps, swept);
      for(std::size_t k = 0; k < applied.size(); ++k) applied[k] += swept[k];
    }
    r.swept_curves = swept.back();
    // curve ends in boundary planes that neither the short changes nor the sweeps moved: pulled onto
    // the faces they cross (only then, so that a field the sweeps repair is left as they leave it)
    std::vector<std::size_t> pulled(operations.size() + 2, 0);
    if(choose_parameter(get_parameter(np, internal_np::repair_sweeps), true) && internal::has_curve_end_in_boundary_plane(state)) {
      auto with_pull = internal::singularity_repair_operations<Mesh>();
      with_pull.emplace_back(new internal::Sweep_curve<Mesh>());
      with_pull.emplace_back(new internal::Pull_curve_end<Mesh>());
      internal::greedy_surgery(state, with_pull, max_steps, pulled);
      for(std::size_t k = 0; k < applied.size(); ++k) applied[k] += pulled[k];
      r.swept_curves += pulled[operations.size()];
    }
    r.pulled_curve_ends = pulled.back();
    const internal::Hex_scale_simplification s = internal::simplify_at_hex_scale(state, hex_edge);
    r.hex_scale_clusters = s.clusters;
    r.simplified_clusters = s.removed;
    r.hex_scale_kept = {{"too_large", s.too_large}, {"collar_not_flat", s.collar_not_flat}, {"not_editable", s.not_editable},
                        {"boundary_valence", s.boundary_valence}, {"not_cheaper", s.not_cheaper}};
    // a removed cluster may leave defects of its neighbours free to go
    if(r.simplified_clusters > 0) internal::greedy_surgery(state, operations, max_steps, again);
    for(std::size_t k = 0; k < operations.size(); ++k)
      r.operations.emplace_back(operations[k]->name(), applied[k] + (again.empty() ? 0 : again[k]));
    r.operations.emplace_back("sweep_curve", r.swept_curves);
    r.operations.emplace_back("pull_end", r.pulled_curve_ends);
    r.operations.emplace_back("simplify_at_hex_scale", r.simplified_clusters);
  }
  for(std::size_t f = 0; f < input.size(); ++f) r.changed_faces += (input[f] != matchings.face_matching[f]);
  r.defects_after = r.changed_faces > 0 ? check_local_meshability(mesh, frames, matchings).counts : r.defects_before;
  r.accepted = r.changed_faces > 0;
  r.rounds = r.accepted ? 1 : 0;
  r.graph_defects_before = internal::graph_defect_count(r.defects_before);
  r.graph_defects_after = internal::graph_defect_count(r.defects_after);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_REPAIR_SINGULARITY_GRAPH_H
