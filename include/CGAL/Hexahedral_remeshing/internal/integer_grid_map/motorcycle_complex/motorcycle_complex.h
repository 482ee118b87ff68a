// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_MOTORCYCLE_COMPLEX_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_MOTORCYCLE_COMPLEX_H

#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/block_extents.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/complex_elements.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/trace_walls.h>

#include <CGAL/Interval_nt.h>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {
namespace motorcycle {

// What tracing the complex did (issue 27 step 2).
struct Motorcycle_complex_report
{
  bool success = false;
  std::string reason;                 // why there is no complex
  std::size_t inverted_tetrahedra = 0; // exact orientation <= 0 in parameter space
  std::size_t singular_edges = 0, feature_edges = 0, walls = 0, split_edges = 0;
  std::size_t tetrahedra_before = 0, tetrahedra_after = 0;
  std::size_t blocks = 0, patches = 0, arcs = 0, nodes = 0;
  double seconds = 0;
};

struct Motorcycle_complex
{
  std::unique_ptr<Exact_map_mesh> mesh; // the map's tetrahedra, split where the walls cross them
  Complex_elements elements;
  Block_extents extents; // with forms only
  Motorcycle_complex_report report;
};

// The extents of the blocks as functions of the map's variables (Block_extent_reader).
inline Block_extents block_extents(const Exact_map_mesh& mesh, const Complex_elements& elements, const Map_forms& forms,
                                   const std::vector<std::array<std::uint32_t, 4> >& tets,
                                   const std::vector<std::array<Eigen::Vector3d, 4> >& parameters,
                                   const std::map<std::pair<int, std::uint32_t>, std::vector<Plane_form> >& wall_planes)
{
  return Block_extent_reader(mesh, elements, forms, tets, parameters, wall_planes, mesh.singular_edges).read();
}

// Exact orientation of tetrahedron t in its chart: in interval arithmetic first, exactly where the
// intervals cannot tell.
inline CGAL::Sign parameter_orientation(const Map_tetrahedron& T)
{
  {
    typedef CGAL::Interval_nt<> Interval;
    std::array<std::array<Interval, 3>, 3> d;
    for(std::size_t i = 0; i < 3; ++i)
      for(std::size_t k = 0; k < 3; ++k)
        d[i][k] = interval_of(T.parameter[i + 1][k]) - interval_of(T.parameter[0][k]);
    const Interval det = d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) - d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
                         d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
    const CGAL::Uncertain<CGAL::Sign> sign = CGAL::sign(det);
    if(CGAL::is_certain(sign)) return CGAL::get_certain(sign);
  }
  std::array<std::array<Rational, 3>, 3> d;
  for(std::size_t i = 0; i < 3; ++i)
    for(std::size_t k = 0; k < 3; ++k) d[i][k] = T.parameter[i + 1][k] - T.parameter[0][k];
  const Rational det = d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) - d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
                       d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
  return CGAL::sign(det);
}

// The motorcycle complex of a seamless map (robust_pipeline.md §3.1): `tets` with the map's
// `parameters` at their corners (each tetrahedron in its own chart; the transitions between
// adjacent charts must be rotations of the cube plus translations, exactly), `positions` of the
// vertices in the model. The map must be locally injective (every tetrahedron positively oriented in
// parameter space, exactly) and put boundary faces on planes and curves on lines of its charts;
// else the report says why and there is no complex. `maximum_growth`: the tracing stops (no complex)
// when the split mesh has that many times the input's tetrahedra (a wall that never meets another);
// `seconds`: or after that time.
// With `forms` (the parameters as functions of the map's variables), the extents of the blocks too.
// A toroidal block is not cut by a wall: its extent around the ring is its period, which is what a
// cutting wall's two sides would be apart (block_extents.h). Not yet: the complex is not reduced.
inline Motorcycle_complex trace_motorcycle_complex(const std::vector<std::array<double, 3> >& positions,
                                                   const std::vector<std::array<std::uint32_t, 4> >& tets,
                                                   const std::vector<std::array<Eigen::Vector3d, 4> >& parameters,
                                                   double maximum_growth = 50, const Map_forms* forms = nullptr,
                                                   double seconds = 60)
{
  const auto start = std::chrono::steady_clock::now();
  Motorcycle_complex mc;
  Motorcycle_complex_report& r = mc.report;
  mc.mesh.reset(new Exact_map_mesh(positions, tets, parameters));
  Exact_map_mesh& mesh = *mc.mesh;
  r.tetrahedra_before = tets.size();
  for(const Map_tetrahedron& T : mesh.tetrahedra) r.inverted_tetrahedra += parameter_orientation(T) != CGAL::POSITIVE;
  const Curve_edges curves = curve_edges(mesh);
  r.singular_edges = curves.singular.size();
  for(const auto& e : curves.singular)
    mesh.singular_edges.emplace(std::min(e.second[0], e.second[1]), std::max(e.second[0], e.second[1]));
  r.feature_edges = curves.feature.size();
  if(r.inverted_tetrahedra > 0) r.reason = "the map is not locally injective";
  else if(curves.not_seamless > 0) r.reason = "the map is not seamless (a transition is not a rotation of the cube)";
  else {
    Wall_tracer tracer(mesh, std::size_t(maximum_growth * double(tets.size())), forms, &tets, seconds);
    for(const auto& e : curves.singular) tracer.seed(e.first, e.second[0], e.second[1]);
    for(const auto& e : curves.feature) tracer.seed(e.first, e.second[0], e.second[1]);
    const bool traced = tracer.run();
    r.walls = std::size_t(tracer.walls());
    r.split_edges = tracer.split_edges;
    std::size_t not_positive = 0;
    for(const Map_tetrahedron& T : mesh.tetrahedra) not_positive += traced && parameter_orientation(T) != CGAL::POSITIVE;
    if(tracer.out_of_time) r.reason = "the walls were not traced in the time limit";
    else if(not_positive > 0) r.reason = "a part of a split tetrahedron is not positive (the rounding of a split point)";
    else if(!traced) r.reason = "the walls split the mesh past the size limit";
    else if(tracer.not_seamless > 0) r.reason = "a wall crossed a face that is not seamless";
    else if(r.walls != 2 * (r.singular_edges + r.feature_edges)) r.reason = "a curve edge is not on a line of its chart";
    else {
      mc.elements = complex_elements(mesh);
      r.blocks = mc.elements.blocks;
      r.patches = mc.elements.patches;
      r.arcs = mc.elements.arcs;
      r.nodes = mc.elements.nodes;
      r.success = true;
      if(forms) mc.extents = block_extents(mesh, mc.elements, *forms, tets, parameters, tracer.wall_planes);
    }
  }
  r.tetrahedra_after = mesh.tetrahedra.size();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return mc;
}

} // namespace motorcycle
} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_MOTORCYCLE_COMPLEX_H
