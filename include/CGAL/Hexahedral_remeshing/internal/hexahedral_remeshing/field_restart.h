// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// The third chance, after the repair's fallbacks and the refinement: where the field smoothed from the
// relaxation gives no valid hex mesh, the whole run (with its fallbacks and its refinement) is done again
// from the boundary propagation (`Frame_field_initialization::BOUNDARY_PROPAGATION`), and kept if valid.
// The smoothing is local: it keeps the singular structure of the field it starts from. On the HexMe torus
// s16c the relaxation's start leads to 3 valence-3 curves placed irregularly around the tube (the map folds
// 145 tetrahedra), the propagated start to a field whose map gives a valid hex mesh (949 hexahedra,
// minimum scaled Jacobian 0.77). The two starts are not ranked by energy: the torus's twisted field has the
// lower one (1535.6 against 1562.5). A valid mesh is never traded: the restart runs only after a failure.
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_REMESHING_FIELD_RESTART_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_REMESHING_FIELD_RESTART_H

#include <CGAL/Hexahedral_remeshing/frame_field.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_remeshing/refinement_retry.h>

#include <functional>
#include <utility>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// run_hexahedral_remeshing_or_refine() from the relaxation, then, if its mesh is not valid and the
// initialization is AUTOMATIC, the same from the boundary propagation, kept if valid.
template <class Traits, class NamedParameters>
Hexahedral_remeshing_result run_hexahedral_remeshing_with_restart(const Tetrahedral_mesh_3<Traits>& mesh,
                                                                  Hexahedral_mesh_3& hexes, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::get_parameter_reference;
  const Frame_field_initialization start =
    choose_parameter(get_parameter(np, internal_np::frame_field_initialization), Frame_field_initialization::AUTOMATIC);
  Hexahedral_remeshing_result r = run_hexahedral_remeshing_or_refine(
    mesh, hexes,
    parameters::frame_field_initialization(
      start == Frame_field_initialization::AUTOMATIC ? Frame_field_initialization::RELAXATION : start, np));
  if(r.status == Hexahedral_remeshing_status::OK || start != Frame_field_initialization::AUTOMATIC) return r;
  Hexahedral_mesh_3 other_hexes;
  Integer_grid_map other_map;
  Tetrahedral_mesh_3<Traits> other_fine;
  Hexahedral_remeshing_result p = run_hexahedral_remeshing_or_refine(
    mesh, other_hexes,
    parameters::frame_field_initialization(
      Frame_field_initialization::BOUNDARY_PROPAGATION,
      parameters::integer_grid_map_output(std::ref(other_map), parameters::refined_mesh_output(std::ref(other_fine), np))));
  Hexahedral_remeshing_result& kept = p.status == Hexahedral_remeshing_status::OK ? p : r;
  const Hexahedral_remeshing_result& other = p.status == Hexahedral_remeshing_status::OK ? r : p;
  kept.field_restart.tried = true;
  kept.field_restart.used = &kept == &p;
  kept.field_restart.other_outcome = remeshing_outcome(other);
  kept.field_restart.other_seconds = other.seconds;
  kept.seconds += other.seconds;
  if(kept.field_restart.used) {
    adopt_map_and_hexahedra(np, other_map, other_hexes, hexes);
    if(kept.refinement.used) {
      Tetrahedral_mesh_3<Traits> own_mesh;
      Tetrahedral_mesh_3<Traits>& out = choose_parameter(get_parameter_reference(np, internal_np::refined_mesh_output), own_mesh);
      out = std::move(other_fine);
    }
  }
  return std::move(kept);
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_REMESHING_FIELD_RESTART_H
