// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_BOUNDARY_EDGE_VALENCES_H
#define CGAL_HEXAHEDRAL_REMESHING_BOUNDARY_EDGE_VALENCES_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/boundary_dihedral_angles.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/parameters.h>
#include <CGAL/Hexahedral_remeshing/internal/ambiguous_dihedral_class.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// The heuristics of Desobry et al. (Sec. 5) that choose the valence `k` of a boundary edge (the
/// number of hexahedra meeting there) from its interior dihedral angle `phi`. `round()` rounds
/// ties up, and for every heuristic but `GEOMETRIC` the angles within 0.022 degrees below a tie too
/// (`boundary_edge_near_tie_class()`); every threshold is decided exactly (see `boundary_edge_valence()`).
enum class Valence_heuristic
{
  /// `k = round(2 phi / pi)`: what a frame field aligned with the normals produces (may be 0, not meshable).
  GEOMETRIC,
  /// `k = max(round(2 phi / pi), 1)` (Sec. 5.1): edges below 45 degrees get valence 1. The default.
  LOW_ANGLE,
  /// `k = max(round(2 phi / pi + 0.05), 1)` (Sec. 5.2): angles within 4.5 degrees below an odd
  /// multiple of 45 degrees take the larger valence.
  AMBIGUOUS,
  /// `k = min(round(2 phi / pi), 2)` (Sec. 5.4): concave valence-3 edges become regular.
  CAP_TWO
};

/// \ingroup PkgHexahedralRemeshingRef
/// The value stored by `compute_boundary_edge_valences()` for an interior edge (a valence is only
/// defined on the boundary; 0 is a valid, if unmeshable, boundary valence).
constexpr int interior_edge_valence = -1;

/// \ingroup PkgHexahedralRemeshingRef
/// Smallest valence a user may prescribe.
constexpr int minimum_prescribed_valence = 1;
/// \ingroup PkgHexahedralRemeshingRef
/// Largest valence a user may prescribe (Desobry et al., Sec. 6.2: larger ones are hardly realizable).
constexpr int maximum_prescribed_valence = 6;

/// \ingroup PkgHexahedralRemeshingRef
/// Name of a heuristic as used on the command line: `geometric`, `low_angle`, `ambiguous`, `cap_two`.
inline const char* valence_heuristic_name(Valence_heuristic h)
{
  switch(h) {
  case Valence_heuristic::GEOMETRIC: return "geometric";
  case Valence_heuristic::LOW_ANGLE: return "low_angle";
  case Valence_heuristic::AMBIGUOUS: return "ambiguous";
  case Valence_heuristic::CAP_TWO: return "cap_two";
  }
  return "unknown";
}

/// \ingroup PkgHexahedralRemeshingRef
/// Parses a heuristic name (`geometric`, `low_angle`, `ambiguous`, `cap_two`; `-` may replace `_`).
/// \returns `false` if `name` is none of them (then `h` is unchanged).
inline bool parse_valence_heuristic(std::string name, Valence_heuristic& h)
{
  std::replace(name.begin(), name.end(), '-', '_');
  for(Valence_heuristic c : {Valence_heuristic::GEOMETRIC, Valence_heuristic::LOW_ANGLE, Valence_heuristic::AMBIGUOUS,
                             Valence_heuristic::CAP_TWO})
    if(name == valence_heuristic_name(c)) { h = c; return true; }
  return false;
}

/// \ingroup PkgHexahedralRemeshingRef
/// Valence that heuristic `h` gives to boundary edge `e`.
///
/// Exactness: the class `round(2 phi / pi)` of `GEOMETRIC` is decided exactly by the traits'
/// `Dihedral_class_3` (ties at odd multiples of pi/4 round up); `LOW_ANGLE` and `CAP_TWO` start from
/// `boundary_edge_near_tie_class()`, which rounds up the angles within pi/8192 below a tie as well
/// (a CAD chamfer of 45 degrees meshed with rounded coordinates: one valence along it, not the two
/// that the exact sides of the tie give edge by edge). The `AMBIGUOUS` threshold `round(2 phi / pi + 0.05)`,
/// i.e. `phi >= (m + 0.45) pi / 2`, is decided exactly too, for the coordinates of the points
/// converted to `double` (exact for the default kernel): an interval filter, then exact rational
/// arithmetic against enclosures of `tan^2(0.45 pi / 2)` computed with MPFR at increasing
/// precision (that threshold is irrational, so there are no ties). The `max(.,1)` and `min(.,2)`
/// of the other heuristics are integer operations.
/// \pre `mesh.is_boundary_edge(e)`
template <class Traits>
int boundary_edge_valence(const Tetrahedral_mesh_3<Traits>& mesh, typename Tetrahedral_mesh_3<Traits>::Index e,
                          Valence_heuristic h, const Traits& traits = Traits())
{
  if(h == Valence_heuristic::AMBIGUOUS)
    return (std::max)(internal::ambiguous_dihedral_class_exact(internal::boundary_edge_coordinates(mesh, e)), 1);
  const int m = h == Valence_heuristic::GEOMETRIC ? boundary_edge_dihedral_class(mesh, e, traits)
                                                  : boundary_edge_near_tie_class(mesh, e);
  switch(h) {
  case Valence_heuristic::GEOMETRIC: return m;
  case Valence_heuristic::CAP_TWO: return (std::min)(m, 2);
  default: return (std::max)(m, 1);
  }
}

/// \ingroup PkgHexahedralRemeshingRef
/// What `compute_boundary_edge_valences()` reports.
struct Boundary_edge_valences_statistics
{
  /// Number of boundary edges per valence 0 to 6.
  std::array<std::size_t, 7> histogram{{0, 0, 0, 0, 0, 0, 0}};
  /// Number of boundary edges whose valence was prescribed (per edge or per curve).
  std::size_t prescribed_edges = 0;
  /// Number of boundary edges whose valence differs from the exact class `round(2 phi / pi)`,
  /// i.e. where the direction constraints must differ from the normals.
  std::size_t edges_differing_from_geometry = 0;
};

namespace internal {

// Resolves the key of a per-edge prescription: an edge index, or a pair of vertex indices.
template <class Traits, class Key>
typename Tetrahedral_mesh_3<Traits>::Index
prescribed_edge(const Tetrahedral_mesh_3<Traits>& mesh, const Key& key, std::string& what)
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  if constexpr(std::is_integral<Key>::value) {
    const long long index = static_cast<long long>(key);
    what = "edge " + std::to_string(index);
    if(index < 0 || static_cast<unsigned long long>(index) >= mesh.number_of_edges())
      throw Input_error("prescribed_edge_valences", 0, what + ": no such edge (the mesh has " +
                        std::to_string(mesh.number_of_edges()) + " edges)");
    return Index(key);
  } else {
    const long long a = static_cast<long long>(std::get<0>(key)), b = static_cast<long long>(std::get<1>(key));
    what = "vertices " + std::to_string(a) + " " + std::to_string(b);
    const long long nv = static_cast<long long>(mesh.number_of_vertices());
    const Index e = (a < 0 || b < 0 || a >= nv || b >= nv || a == b) ? Tetrahedral_mesh_3<Traits>::null_index
                                                                     : mesh.find_edge(Index(a), Index(b));
    if(e == Tetrahedral_mesh_3<Traits>::null_index)
      throw Input_error("prescribed_edge_valences", 0, what + ": not an edge of the mesh");
    return e;
  }
}

inline void check_prescribed_valence(const char* source, const std::string& what, long long k)
{
  if(k < minimum_prescribed_valence || k > maximum_prescribed_valence)
    throw Input_error(source, 0, what + ": prescribed valence " + std::to_string(k) +
                      " is impossible (a boundary edge valence must be between " +
                      std::to_string(minimum_prescribed_valence) + " and " +
                      std::to_string(maximum_prescribed_valence) + ")");
}

} // namespace internal

/// \ingroup PkgHexahedralRemeshingRef
/// Chooses the valence `k` of every boundary edge (Desobry et al., Sec. 5): from a heuristic, except
/// where the user prescribes it, per edge or per feature curve (Sec. 5.3). Flat and smooth edges get 2.
///
/// \param mesh the tetrahedral mesh
/// \param valences output, resized to `mesh.number_of_edges()`: `valences[e]` is the valence of
///        boundary edge `e`, and `interior_edge_valence` (-1) for an interior edge
/// \param np an optional sequence of named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{valence_heuristic}
///     \cgalParamDescription{the heuristic for the edges without prescription}
///     \cgalParamType{`Valence_heuristic`}
///     \cgalParamDefault{`Valence_heuristic::LOW_ANGLE`}
///   \cgalParamNEnd
///   \cgalParamNBegin{prescribed_edge_valences}
///     \cgalParamDescription{valences prescribed per boundary edge; they override the curve
///       prescriptions and the heuristic}
///     \cgalParamType{a range of pairs `(key, k)` (e.g. `std::map` or `std::vector<std::pair>`) where
///       `key` is an edge index (an integral type) or a pair of vertex indices (`std::pair` or
///       `std::array` of two integers), and `k` an integer from 1 to 6}
///     \cgalParamDefault{none}
///     \cgalParamExtra{the range is copied into the parameter pack unless passed as `std::cref(range)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{prescribed_curve_valences}
///     \cgalParamDescription{valences prescribed per feature curve of the input (`edge_curve()`):
///       every boundary edge of the curve gets `k`; they override the heuristic}
///     \cgalParamType{a range of pairs `(curve id, k)` of integers, `k` from 1 to 6}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of the traits}
///     \cgalParamType{a model of `HexahedralRemeshingTraits_3`}
///     \cgalParamDefault{`Traits()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the histogram of the valences and the number of prescribed edges.
/// \throws Input_error for an impossible prescription: a valence outside 1..6, an edge index out of
///         range, two vertices that are not joined by an edge, an interior (non-boundary) edge, a
///         curve id carried by no boundary edge, or the same edge prescribed twice with two valences.
template <class Traits, class NamedParameters = CGAL::parameters::Default_named_parameters>
Boundary_edge_valences_statistics
compute_boundary_edge_valences(const Tetrahedral_mesh_3<Traits>& mesh, std::vector<int>& valences,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  using CGAL::parameters::get_parameter_reference;
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;

  const Valence_heuristic heuristic =
    choose_parameter(get_parameter(np, internal_np::valence_heuristic), Valence_heuristic::LOW_ANGLE);
  const Traits traits = choose_parameter(get_parameter(np, CGAL::internal_np::geom_traits), Traits());

  // Prescriptions first (so that errors come before any work), per curve then per edge.
  std::map<int, int> curve_valence;
  if constexpr(!is_default_parameter<NamedParameters, internal_np::prescribed_curve_valences_t>::value) {
    const auto& curves = get_parameter_reference(np, internal_np::prescribed_curve_valences);
    for(const auto& cp : curves) {
      const long long id = static_cast<long long>(cp.first), k = static_cast<long long>(cp.second);
      const std::string what = "curve " + std::to_string(id);
      internal::check_prescribed_valence("prescribed_curve_valences", what, k);
      auto ins = curve_valence.emplace(int(id), int(k));
      if(!ins.second && ins.first->second != int(k))
        throw Input_error("prescribed_curve_valences", 0, what + ": prescribed twice, with valences " +
                          std::to_string(ins.first->second) + " and " + std::to_string(k));
    }
    if(!curve_valence.empty()) {
      std::map<int, std::size_t> curve_use;
      for(Index e : mesh.boundary_edges())
        if(mesh.edge_curve(e) >= 0) ++curve_use[mesh.edge_curve(e)];
      for(const auto& cv : curve_valence)
        if(curve_use.count(cv.first) == 0)
          throw Input_error("prescribed_curve_valences", 0, "curve " + std::to_string(cv.first) +
                            ": no boundary edge carries this feature curve id");
    }
  }
  std::map<Index, int> edge_valence;
  if constexpr(!is_default_parameter<NamedParameters, internal_np::prescribed_edge_valences_t>::value) {
    const auto& edges = get_parameter_reference(np, internal_np::prescribed_edge_valences);
    for(const auto& ep : edges) {
      std::string what;
      const Index e = internal::prescribed_edge(mesh, ep.first, what);
      const long long k = static_cast<long long>(ep.second);
      internal::check_prescribed_valence("prescribed_edge_valences", what, k);
      if(!mesh.is_boundary_edge(e))
        throw Input_error("prescribed_edge_valences", 0, what + ": not a boundary edge (a valence can only be "
                          "prescribed on the boundary)");
      auto ins = edge_valence.emplace(e, int(k));
      if(!ins.second && ins.first->second != int(k))
        throw Input_error("prescribed_edge_valences", 0, what + ": prescribed twice, with valences " +
                          std::to_string(ins.first->second) + " and " + std::to_string(k));
    }
  }

  Boundary_edge_valences_statistics stats;
  valences.assign(mesh.number_of_edges(), interior_edge_valence);
  for(Index e : mesh.boundary_edges()) {
    const int geometric = boundary_edge_dihedral_class(mesh, e, traits);
    int k = -1;
    auto pe = edge_valence.find(e);
    if(pe != edge_valence.end()) {
      k = pe->second;
    } else if(!curve_valence.empty() && mesh.edge_curve(e) >= 0) {
      auto pc = curve_valence.find(mesh.edge_curve(e));
      if(pc != curve_valence.end()) k = pc->second;
    }
    if(k >= 0) ++stats.prescribed_edges;
    else if(heuristic == Valence_heuristic::GEOMETRIC) k = geometric;
    else k = boundary_edge_valence(mesh, e, heuristic, traits);
    valences[e] = k;
    ++stats.histogram[std::size_t(k)];
    if(k != geometric) ++stats.edges_differing_from_geometry;
  }
  return stats;
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_BOUNDARY_EDGE_VALENCES_H
