// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_WALL_FORMS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_WALL_FORMS_H

#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/linear_form.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/exact_map_mesh.h>

#include <array>
#include <cstdint>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {
namespace motorcycle {

// The map's parameters as affine functions of the variables of the map problem (Linear_form), so that
// the position of every wall, and the extent of every block, is known as a function of the integer
// variables that the quantization chooses.
class Map_forms
{
public:
  virtual ~Map_forms() = default;
  // Coordinate `axis` of the input vertex v in the chart of the input tetrahedron t (a corner of it).
  virtual Linear_form corner(std::uint32_t t, std::uint32_t v, int axis) const = 0;
};

// A plane of a chart with its value as a function of the variables.
struct Plane_form
{
  Axis_plane plane;
  Linear_form value;
};

// The translation of the chart change `c` from input tetrahedron `from` to the adjacent `to`, per
// coordinate of `to`, as functions of the variables: t = p_to(v) - R p_from(v) at a shared vertex v.
inline std::array<Linear_form, 3> translation_forms(const Map_forms& forms, const std::vector<std::array<std::uint32_t, 4> >& input,
                                                    std::uint32_t from, std::uint32_t to, const Chart_transition& c)
{
  std::uint32_t v = input[from][0];
  for(std::uint32_t a : input[from])
    for(std::uint32_t b : input[to])
      if(a == b) v = a;
  std::array<Linear_form, 3> t;
  for(int i = 0; i < 3; ++i)
    t[std::size_t(i)] = forms.corner(to, v, i).plus(forms.corner(from, v, c.R.axis[std::size_t(i)]), -double(c.R.sign[std::size_t(i)]));
  return t;
}

// The plane `p` (of a chart) with its value form, in the chart after the change `c` whose translation
// forms are `t`.
inline Plane_form plane_form_in(const Plane_form& p, const Chart_transition& c, const std::array<Linear_form, 3>& t)
{
  Plane_form q;
  q.plane = p.plane.in(c);
  const std::size_t i = std::size_t(q.plane.axis);
  q.value = p.value.scaled(double(c.R.sign[i])).plus(t[i], 1.0);
  return q;
}

} // namespace motorcycle
} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_WALL_FORMS_H
