// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_H
#define CGAL_HEXAHEDRAL_REMESHING_H

/// \file hexahedral_remeshing.h
/// The entry point of the package, `CGAL::hexahedral_remeshing()`: from tetrahedra (or a CGAL
/// C3t3, or a closed surface) to hexahedra in one call. Includes every public header.

#include <CGAL/Hexahedral_remeshing/Hexahedral_remeshing_traits_3.h>
#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/Tetrahedral_soup_3.h>
#include <CGAL/Hexahedral_remeshing/boundary_dihedral_angles.h>
#include <CGAL/Hexahedral_remeshing/boundary_direction_constraints.h>
#include <CGAL/Hexahedral_remeshing/boundary_edge_valences.h>
#include <CGAL/Hexahedral_remeshing/boundary_triangle_normals.h>
#include <CGAL/Hexahedral_remeshing/build_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/frame_field.h>
#include <CGAL/Hexahedral_remeshing/frame_field_pipeline.h>
#include <CGAL/Hexahedral_remeshing/mesh_statistics.h>
#include <CGAL/Hexahedral_remeshing/parameters.h>
#include <CGAL/Hexahedral_remeshing/realign_frame_field.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/tetrahedral_soup_from_c3t3.h>
#include <CGAL/Hexahedral_remeshing/tetrahedralize_surface.h>
#include <CGAL/Hexahedral_remeshing/IO/edge_valences.h>
#include <CGAL/Hexahedral_remeshing/IO/read_MEDIT.h>
#include <CGAL/Hexahedral_remeshing/IO/read_VTK.h>
#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/IO/write_CubeCover.h>
#include <CGAL/Hexahedral_remeshing/IO/write_MEDIT.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK_boundary.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK_frame_field.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK_polylines.h>

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/Integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_extraction.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_smoothing.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_to_lcc.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_validation.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_remeshing_result.h>
#include <CGAL/Hexahedral_remeshing/integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/IO/read_HexEx.h>
#include <CGAL/Hexahedral_remeshing/IO/read_hexahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/IO/write_HexEx.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK_integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/IO/write_hexahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_remeshing/field_restart.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_remeshing/refinement_retry.h>
#include <CGAL/Hexahedral_remeshing/refine_tetrahedral_mesh.h>

#include <type_traits>
#include <utility>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

template <class T> struct Is_tetrahedral_mesh : std::false_type {};
template <class Traits> struct Is_tetrahedral_mesh<Tetrahedral_mesh_3<Traits> > : std::true_type {};
// A C3t3 (`Mesh_complex_3_in_triangulation_3`) is recognized by its cells in the complex.
template <class T, class = void> struct Is_c3t3 : std::false_type {};
template <class T>
struct Is_c3t3<T, std::void_t<decltype(std::declval<const T&>().cells_in_complex_begin())> > : std::true_type {};

} // namespace internal
} // namespace Hexahedral_remeshing

/// \ingroup PkgHexahedralRemeshingRef
/// Remeshes a solid with hexahedra by the method of Desobry et al. (*Frame Fields with Prescribed
/// Boundary Singularity Graph for Hexahedral Meshing*): boundary edge valences (heuristic or
/// prescribed) -> boundary direction constraints (Alg. 1 and 2) -> smooth frame field -> matchings and
/// singularity graph -> realignment with the normals (Sec. 3.3) -> repair of the singularity graph
/// (`repair_singularity_graph()`, named parameter `singularity_repair`) -> seamless integer-grid map
/// (Sec. 3.4) -> hex extraction (HexEx, Lyon et al. 2016) -> untangling and smoothing -> check. When the
/// repaired field gives no valid hex mesh, the field of the repair's first round (if it kept more), the
/// field of one round without the sweeps (if the repair swept curves), then the field without the repair
/// are tried and the first valid mesh is kept (`Hexahedral_remeshing_result::rounds_fallback`,
/// `sweep_fallback`, `repair_fallback`). When a tetrahedral mesh coarser than the
/// hexahedra (fewer than 12 tetrahedra per hexahedron) gives no valid hex mesh, its red refinement is tried
/// and kept if its mesh is valid (`Hexahedral_remeshing_result::refinement`, `tetrahedron_refinement`).
/// When all this gives no valid mesh, it runs again with the frame field smoothed from the boundary
/// propagation instead of the relaxation (`Frame_field_initialization`), kept if valid
/// (`Hexahedral_remeshing_result::field_restart`).
///
/// \tparam Input `Hexahedral_remeshing::Tetrahedral_mesh_3<Traits>`, a CGAL
///         `Mesh_complex_3_in_triangulation_3` (its cells, surface patches, feature curves and corners;
///         converted with `tetrahedral_soup_from_c3t3()`), or a closed triangulated surface model of
///         `FaceListGraph` such as `CGAL::Surface_mesh` (tetrahedralized with TetGen,
///         `tetrahedralize_surface()`). C3t3 and surfaces are built with `split_boundary_chords(true)`.
/// \tparam Output `Hexahedral_remeshing::Hexahedral_mesh_3`, or a CGAL
///         `Linear_cell_complex_for_combinatorial_map<3>` (filled by `hexahedral_mesh_to_lcc()`).
/// \param input the solid
/// \param output receives the hex mesh (cleared first); when the status is `NO_HEXAHEDRA` it is empty.
/// \param np an optional sequence of named parameters: those of `compute_frame_field_pipeline()`
///        (`valence_heuristic`, `prescribed_edge_valences`, `baseline`, `face_weights`, ...), of
///        `compute_integer_grid_map()` (`maximum_stiffening_iterations`, `untangling`), of
///        `smooth_hexahedral_mesh()` (`number_of_iterations`, `smoothing_boundary`,
///        `smoothing_sharp_angle`, with its defaults), of `tetrahedralize_surface()` for a surface
///        input, and:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{acute_edge_band_radius}
///     \cgalParamDescription{radius of the band of fixed frames around the acute edges of valence 1
///       (see `compute_frame_field_pipeline()`), in model units; 0 disables it, a negative value
///       means the default}
///     \cgalParamType{`double`}
///     \cgalParamDefault{twice the hex edge length}
///   \cgalParamNEnd
///   \cgalParamNBegin{target_edge_length}
///     \cgalParamDescription{hex edge length in model units}
///     \cgalParamType{`double`}
///     \cgalParamDefault{from `number_of_hexahedra`, else the default of `compute_integer_grid_map()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_hexahedra}
///     \cgalParamDescription{approximate number of hexahedra: the edge length is `cbrt(volume / n)`}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{unused}
///   \cgalParamNEnd
///   \cgalParamNBegin{hexahedral_smoothing}
///     \cgalParamDescription{untangle and smooth the extracted mesh (`smooth_hexahedral_mesh()`)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{integer_grid_map_output}
///     \cgalParamDescription{receives the integer-grid map the hexahedra were extracted from (to write it
///       with `IO::write_HexEx()` or check it with `check_integer_grid_map()`)}
///     \cgalParamType{`std::reference_wrapper<Hexahedral_remeshing::Integer_grid_map>`}
///     \cgalParamDefault{none: the map is discarded}
///   \cgalParamNEnd
///   \cgalParamNBegin{tetrahedron_refinement}
///     \cgalParamDescription{if the mesh has fewer than 12 tetrahedra per hexahedron and gives no valid
///       hex mesh, run again on its red refinement (`refine_tetrahedral_soup()`, once, or twice below 0.75
///       per hexahedron; the boundary, its patches and features unchanged) and keep that mesh if it is
///       valid; never with `prescribed_edge_valences` (their edges are the input's)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{frame_field_initialization}
///     \cgalParamDescription{the field the frame-field smoothing starts from; `AUTOMATIC`: the relaxation,
///       then, if everything else gave no valid hex mesh, the boundary propagation}
///     \cgalParamType{`Hexahedral_remeshing::Frame_field_initialization`}
///     \cgalParamDefault{`Frame_field_initialization::AUTOMATIC`}
///   \cgalParamNEnd
///   \cgalParamNBegin{refined_mesh_output}
///     \cgalParamDescription{receives the refined tetrahedral mesh when the hex mesh comes from it
///       (its first vertices are the input's; `frame_field` and the map refer to it)}
///     \cgalParamType{`std::reference_wrapper<Hexahedral_remeshing::Tetrahedral_mesh_3<Traits> >`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{progress hooks of every stage}
///     \cgalParamType{a class with the member functions of `Hexahedral_remeshing::Hexahedral_remeshing_visitor`}
///     \cgalParamDefault{`Hexahedral_remeshing::Hexahedral_remeshing_visitor()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the report of every stage, their seconds and one overall status: `OK` for a valid hex mesh
///          (conforming, manifold boundary, every scaled Jacobian >= 1e-6), `INVALID_HEX_MESH` when a mesh
///          was produced but is not valid, `NO_HEXAHEDRA` when the map has no complete cell; `message`
///          says why in one line.
/// \throws Hexahedral_remeshing::Input_error for a defective input (an invalid C3t3 or surface, an
///         impossible prescription, a non-positive target edge length, a hex size that fits no layer of
///         hexahedra in the part's walls: thinner than half the hex edge over most of the surface, the
///         message naming the thickness and a size that fits); Hexahedral_remeshing::Error if a stage
///         cannot run.
template <class Input, class Output, class NamedParameters = CGAL::parameters::Default_named_parameters>
Hexahedral_remeshing::Hexahedral_remeshing_result
hexahedral_remeshing(const Input& input, Output& output, const NamedParameters& np = CGAL::parameters::default_values())
{
  namespace HR = Hexahedral_remeshing;
  if constexpr(!std::is_same<Output, HR::Hexahedral_mesh_3>::value) {
    HR::Hexahedral_mesh_3 hexes;
    HR::Hexahedral_remeshing_result r = hexahedral_remeshing(input, hexes, np);
    output.clear();
    HR::hexahedral_mesh_to_lcc(hexes, output);
    return r;
  } else if constexpr(HR::internal::Is_tetrahedral_mesh<Input>::value) {
    return HR::internal::run_hexahedral_remeshing_with_restart(input, output, np);
  } else {
    typedef std::chrono::steady_clock Clock;
    const auto start = Clock::now();
    typedef HR::Tetrahedral_mesh_3<> Mesh;
    HR::Tetrahedral_soup_3<Mesh::Point_3> soup;
    if constexpr(HR::internal::Is_c3t3<Input>::value)
      HR::tetrahedral_soup_from_c3t3(input, soup);
    else if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters,
                                                             HR::internal_np::maximum_tetrahedron_volume_t>::value)
      HR::tetrahedralize_surface(input, soup, np);
    else {
      // At the hex size: tetrahedra of at most h^3 / 6 (some 30 per hexahedron). A field on
      // tetrahedra coarser than the hexahedra places its singular curves badly (the shipped
      // cylinder from its surface alone: 854 tetrahedra, an inverted map; at h^3 / 6 a valid mesh).
      HR::tetrahedralize_surface(input, soup, np);
      Mesh coarse;
      HR::build_tetrahedral_mesh(soup, coarse);
      const double v = HR::internal::hex_size_tetrahedron_volume(HR::internal::tetrahedral_mesh_volume(coarse),
                                                                 HR::internal::pipeline_hex_edge_length(coarse, np));
      if(v > 0) HR::tetrahedralize_surface(input, soup, HR::parameters::maximum_tetrahedron_volume(v, np));
    }
    Mesh mesh;
    HR::build_tetrahedral_mesh(soup, mesh, HR::parameters::split_boundary_chords(true));
    const double preprocessing = std::chrono::duration<double>(Clock::now() - start).count();
    HR::Hexahedral_remeshing_result r = HR::internal::run_hexahedral_remeshing_with_restart(mesh, output, np);
    r.preprocessing_seconds = preprocessing;
    r.seconds += preprocessing;
    return r;
  }
}

} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_H
