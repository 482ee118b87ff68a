// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_BUILD_TETRAHEDRAL_MESH_H
#define CGAL_HEXAHEDRAL_REMESHING_BUILD_TETRAHEDRAL_MESH_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/Tetrahedral_soup_3.h>
#include <CGAL/Hexahedral_remeshing/parameters.h>
#include <CGAL/Hexahedral_remeshing/internal/build_tetrahedral_mesh.h>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// What `build_tetrahedral_mesh()` does with distinct vertices of the tetrahedra that have exactly
/// the same coordinates (a mesh cracked along an interface: its two sides meshed with separate,
/// duplicated nodes, as multi-threaded gmsh sometimes writes).
enum class Coincident_vertices
{
  REFUSE, ///< throw an `Input_error` with their count and the first pair (default)
  MERGE,  ///< merge each group into the vertex of smallest index (the crack is closed)
  KEEP    ///< keep them: separate bodies that touch
};

namespace internal_np {
enum coincident_vertices_t { coincident_vertices };
} // namespace internal_np

namespace parameters {
#ifdef DOXYGEN_RUNNING
/// Policy for coincident vertices of a tetrahedral mesh (`Coincident_vertices`, default `REFUSE`).
template <class T> unspecified_type coincident_vertices(const T& value);
#else
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(coincident_vertices)
#endif
} // namespace parameters

/// \ingroup PkgHexahedralRemeshingRef
/// Builds `mesh` from a soup of tetrahedra: checks the input, re-orients inverted tetrahedra,
/// builds faces, boundary triangles, edges and their rings, components, and transfers the feature
/// hints of the soup (patches, curves, corners). Runs in O(n log n).
///
/// Every finite `double` coordinate is accepted, from subnormal numbers to the largest double:
/// orientations and the topology are decided exactly, and the barycentres of the split are computed
/// without overflow. A tetrahedron whose four points are coplanar is degenerate even when this is
/// not visible in floating point (the test is exact); a sliver of positive volume, however thin, is
/// valid.
///
/// \throws Input_error naming the source, the element and the problem for: no tetrahedra, a
/// non-finite coordinate, an out-of-range index, a degenerate tetrahedron (exact test), a duplicated
/// tetrahedron, a face shared by more than two tetrahedra, overlapping tetrahedra, a non-manifold
/// boundary edge or vertex (a "bow-tie"), distinct vertices at the same position (unless
/// `coincident_vertices` says to merge or keep them), and, with `split_multi_boundary_tetrahedra`, a tetrahedron
/// so flat that a child of its split at the rounded barycentre would be degenerate.
///
/// \param soup the input
/// \param mesh the output (overwritten)
/// \param np an optional sequence of named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{split_multi_boundary_tetrahedra}
///     \cgalParamDescription{split every tetrahedron with two or more boundary faces 1-to-4 at its
///       barycentre, so that each tetrahedron carries at most one boundary alignment constraint;
///       new vertices are appended after the input ones}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{split_boundary_chords}
///     \cgalParamDescription{split at its midpoint every interior edge whose two endpoints lie on the
///       boundary, so that frames can turn smoothly between two boundary constraints (thin wedges at
///       acute features); new vertices are appended}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{coincident_vertices}
///     \cgalParamDescription{what to do with distinct vertices of the tetrahedra at exactly the same
///       position (compared exactly): refuse, merge, or keep as touching bodies}
///     \cgalParamType{`Coincident_vertices`}
///     \cgalParamDefault{`Coincident_vertices::REFUSE`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of the traits}
///     \cgalParamType{a model of `HexahedralRemeshingTraits_3`}
///     \cgalParamDefault{`Traits()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class Traits, class NamedParameters = CGAL::parameters::Default_named_parameters>
void build_tetrahedral_mesh(const Tetrahedral_soup_3<typename Traits::Point_3>& soup,
                            Tetrahedral_mesh_3<Traits>& mesh,
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const bool split = choose_parameter(get_parameter(np, internal_np::split_multi_boundary_tetrahedra), true);
  const bool chords = choose_parameter(get_parameter(np, internal_np::split_boundary_chords), false);
  const Traits traits = choose_parameter(get_parameter(np, CGAL::internal_np::geom_traits), Traits());
  const Coincident_vertices coincident =
    choose_parameter(get_parameter(np, internal_np::coincident_vertices), Coincident_vertices::REFUSE);
  internal::Tetrahedral_mesh_builder<Traits>(traits).build(soup, mesh, split, chords, int(coincident));
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_BUILD_TETRAHEDRAL_MESH_H
