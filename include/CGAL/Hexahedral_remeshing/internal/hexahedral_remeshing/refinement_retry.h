// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// The second chance of a coarse tetrahedral mesh: where the mesh as given (fewer than 12 tetrahedra per
// hexahedron) gives no valid hex mesh, the pipeline runs again on its red refinement and the refined
// result is kept if it is valid. The field's singular curves, the feature sectors and the map's folds
// live at the scale of the tetrahedra: on the HexMe 10-degree wedge (592 tetrahedra, 2,573 after the
// splits of the build, 1.3 per hexahedron at the default size) the map collapses (1,266 inverted
// tetrahedra, no hexahedron); refined once (20,584 tetrahedra) it gives a valid hex mesh (1,372
// hexahedra, every sharp edge at its prescribed valence). A valid mesh is never traded: the refinement
// runs only after a failure, and its result is kept only if valid.
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_REMESHING_REFINEMENT_RETRY_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_REMESHING_REFINEMENT_RETRY_H

#include <CGAL/Hexahedral_remeshing/build_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_remeshing/run_pipeline.h>
#include <CGAL/Hexahedral_remeshing/refine_tetrahedral_mesh.h>

#include <exception>
#include <functional>
#include <iterator>
#include <string>
#include <utility>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Rounds of refinement for a second run of `mesh` (0: none): the refinement is on, the valences are not
// prescribed per edge of the input (those edges are split), and the mesh is coarser than the hexahedra.
template <class Traits, class NamedParameters>
int refinement_rounds_for_retry(const Tetrahedral_mesh_3<Traits>& mesh, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::get_parameter_reference;
  using CGAL::parameters::is_default_parameter;
  if(!choose_parameter(get_parameter(np, internal_np::tetrahedron_refinement), true)) return 0;
  if constexpr(!is_default_parameter<NamedParameters, internal_np::prescribed_edge_valences_t>::value) {
    const auto& edges = get_parameter_reference(np, internal_np::prescribed_edge_valences);
    if(std::begin(edges) != std::end(edges)) return 0;
  }
  return tetrahedron_refinement_rounds(mesh.number_of_tetrahedra(), tetrahedral_mesh_volume(mesh),
                                       pipeline_hex_edge_length(mesh, np));
}

inline std::string remeshing_outcome(const Hexahedral_remeshing_result& r)
{
  if(r.status == Hexahedral_remeshing_status::OK) return "OK";
  return std::string(status_name(r.status)) + " (failed at the " + r.failed_stage + " stage): " + r.message;
}

// run_hexahedral_remeshing(), then, if it fails on a coarse mesh, the same on the mesh refined
// `refinement_rounds_for_retry()` times, kept if valid. The refined mesh goes to `refined_mesh_output`
// when kept. The hex size is the first run's (the volume of the refined mesh is the same).
template <class Traits, class NamedParameters>
Hexahedral_remeshing_result run_hexahedral_remeshing_or_refine(const Tetrahedral_mesh_3<Traits>& mesh,
                                                               Hexahedral_mesh_3& hexes, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter_reference;
  Hexahedral_remeshing_result r = run_hexahedral_remeshing(mesh, hexes, np);
  if(r.status == Hexahedral_remeshing_status::OK) return r;
  const int rounds = refinement_rounds_for_retry(mesh, np);
  if(rounds == 0) return r;
  Tetrahedral_soup_3<typename Traits::Point_3> soup, refined;
  tetrahedral_soup_from_mesh(mesh, soup);
  refine_tetrahedral_soup(soup, refined, rounds);
  Tetrahedral_mesh_3<Traits> fine;
  try {
    build_tetrahedral_mesh(refined, fine, parameters::split_boundary_chords(true));
  } catch(const std::exception& e) {
    // a sliver of the input whose rounded midpoints make a child flat: the first run's result stands
    r.refinement.rounds = rounds;
    r.refinement.other_outcome = std::string("the refined mesh could not be built: ") + e.what();
    return r;
  }
  const double h = pipeline_hex_edge_length(mesh, np);
  Hexahedral_mesh_3 fine_hexes;
  Integer_grid_map fine_map;
  Hexahedral_remeshing_result f = run_hexahedral_remeshing(
    fine, fine_hexes, parameters::target_edge_length(h, parameters::integer_grid_map_output(std::ref(fine_map), np)));
  Hexahedral_remeshing_result& kept = f.status == Hexahedral_remeshing_status::OK ? f : r;
  const Hexahedral_remeshing_result& other = f.status == Hexahedral_remeshing_status::OK ? r : f;
  kept.refinement.rounds = rounds;
  kept.refinement.tetrahedra = fine.number_of_tetrahedra();
  kept.refinement.used = &kept == &f;
  kept.refinement.other_outcome = remeshing_outcome(other);
  kept.refinement.other_seconds = other.seconds;
  kept.seconds += other.seconds;
  if(kept.refinement.used) {
    adopt_map_and_hexahedra(np, fine_map, fine_hexes, hexes);
    Tetrahedral_mesh_3<Traits> own_mesh;
    Tetrahedral_mesh_3<Traits>& out = choose_parameter(get_parameter_reference(np, internal_np::refined_mesh_output), own_mesh);
    out = std::move(fine);
  }
  return std::move(kept);
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_REMESHING_REFINEMENT_RETRY_H
