// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_REMESHING_TRAITS_3_H
#define CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_REMESHING_TRAITS_3_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Hexahedral_remeshing/internal/dihedral_class.h>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// Default model of the concept `HexahedralRemeshingTraits_3`.
///
/// \tparam Kernel a CGAL kernel whose coordinates convert exactly to `double`
///         (default `CGAL::Exact_predicates_inexact_constructions_kernel`).
/// \cgalModels `HexahedralRemeshingTraits_3`
template <class Kernel = CGAL::Exact_predicates_inexact_constructions_kernel>
class Hexahedral_remeshing_traits_3
{
public:
  /// The geometric kernel.
  typedef Kernel K;
  /// Number type.
  typedef typename Kernel::FT FT;
  /// Point type.
  typedef typename Kernel::Point_3 Point_3;
  /// Vector type.
  typedef typename Kernel::Vector_3 Vector_3;
  /// Exact orientation of four points (the kernel's predicate).
  typedef typename Kernel::Orientation_3 Orientation_3;
  /// Exact class `round(2 phi / pi)` of a boundary dihedral angle, ties at odd multiples of pi/4
  /// rounded up. See `HexahedralRemeshingTraits_3::Dihedral_class_3`.
  typedef internal::Dihedral_class_3<Kernel> Dihedral_class_3;

  /// Returns the orientation functor.
  Orientation_3 orientation_3_object() const { return Kernel().orientation_3_object(); }
  /// Returns the dihedral class functor.
  Dihedral_class_3 dihedral_class_3_object() const { return Dihedral_class_3(); }
};

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_REMESHING_TRAITS_3_H
