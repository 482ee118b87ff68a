// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_TETRAHEDRALIZE_SURFACE_H
#define CGAL_HEXAHEDRAL_REMESHING_TETRAHEDRALIZE_SURFACE_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_soup_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#ifndef TETLIBRARY
#define TETLIBRARY
#endif
#include <tetgen.h>

#include <cmath>
#include <sstream>
#include <string>
#include <unordered_map>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// Tetrahedralizes the closed surface `surface` with TetGen (piecewise linear complex, switch `p`)
/// and stores the result in `soup` (which is cleared first). The boundary of the result is the
/// input surface, geometrically: TetGen may insert points on it to meet the quality and volume
/// bounds, unless `preserve_surface_triangles` is set (switch `Y`, which in TetGen 1.5 also
/// prevents most refinement).
/// The surface carries no patch or feature information, so the soup has no hints.
///
/// \tparam FaceListGraph a model of `FaceListGraph` (e.g. `CGAL::Surface_mesh`)
/// \param surface a closed surface with no self-intersection
/// \param soup the output
/// \param np an optional sequence of named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `surface`}
///     \cgalParamType{a model of `ReadablePropertyMap` from `vertex_descriptor` to a point type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, surface)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{preserve_surface_triangles}
///     \cgalParamDescription{keep every surface triangle as a boundary face (no Steiner point on the surface)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_tetrahedron_volume}
///     \cgalParamDescription{upper bound on the volume of the tetrahedra (TetGen switch `a`)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{no bound}
///   \cgalParamNEnd
///   \cgalParamNBegin{radius_edge_ratio}
///     \cgalParamDescription{radius-edge ratio bound of TetGen's quality refinement (switch `q`);
///       0 disables the refinement}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`2.0`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Input_error if the surface is empty or not closed, or if TetGen fails (for example on a
///         self-intersecting surface).
template <class FaceListGraph, class Point, class NamedParameters = CGAL::parameters::Default_named_parameters>
void tetrahedralize_surface(const FaceListGraph& surface, Tetrahedral_soup_3<Point>& soup,
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<FaceListGraph>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<FaceListGraph>::face_descriptor face_descriptor;

  const std::string source = soup.source;
  soup = Tetrahedral_soup_3<Point>();
  soup.source = source;
  const double max_volume = choose_parameter(get_parameter(np, internal_np::maximum_tetrahedron_volume), 0.);
  const double ratio = choose_parameter(get_parameter(np, internal_np::radius_edge_ratio), 2.0);
  const bool preserve = choose_parameter(get_parameter(np, internal_np::preserve_surface_triangles), false);
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_const_property_map(CGAL::vertex_point, surface));

  if(faces(surface).empty()) throw Input_error(source, 0, "the surface has no faces");
  if(!CGAL::is_closed(surface)) throw Input_error(source, 0, "the surface is not closed (it has border edges)");

  tetgenio in, out;
  in.firstnumber = 0;
  std::unordered_map<vertex_descriptor, int> vindex;
  std::vector<double> coords;
  for(vertex_descriptor v : vertices(surface)) {
    const auto& p = get(vpm, v);
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
    if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
      throw Input_error(source, 0, "vertex " + std::to_string(vindex.size()) + ": coordinate is not a finite number");
    vindex[v] = int(vindex.size());
    coords.insert(coords.end(), {x, y, z});
  }
  in.numberofpoints = int(vindex.size());
  in.pointlist = new REAL[coords.size()];
  std::copy(coords.begin(), coords.end(), in.pointlist);
  const std::size_t nf = std::size_t(std::distance(faces(surface).begin(), faces(surface).end()));
  in.numberoffacets = int(nf);
  in.facetlist = new tetgenio::facet[nf];
  in.facetmarkerlist = new int[nf];
  std::size_t fi = 0;
  for(face_descriptor f : faces(surface)) {
    tetgenio::facet& tf = in.facetlist[fi];
    tetgenio::init(&tf);
    tf.numberofpolygons = 1;
    tf.polygonlist = new tetgenio::polygon[1];
    tetgenio::polygon& poly = tf.polygonlist[0];
    tetgenio::init(&poly);
    std::vector<int> ids;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, surface), surface)) ids.push_back(vindex[v]);
    poly.numberofvertices = int(ids.size());
    poly.vertexlist = new int[ids.size()];
    std::copy(ids.begin(), ids.end(), poly.vertexlist);
    in.facetmarkerlist[fi] = 0;
    ++fi;
  }

  std::ostringstream sw;
  sw << "pzQ";
  if(preserve) sw << "Y";
  if(ratio > 0) sw << "q" << ratio;
  if(max_volume > 0) sw << "a" << max_volume;
  std::string switches = sw.str();
  try {
    tetrahedralize(&switches[0], &in, &out);
  } catch(int code) {
    throw Input_error(source, 0, "TetGen failed (error " + std::to_string(code) +
                      "): the surface may self-intersect or be degenerate");
  }
  if(out.numberoftetrahedra <= 0) throw Input_error(source, 0, "TetGen produced no tetrahedra");
  soup.points.reserve(std::size_t(out.numberofpoints));
  for(int i = 0; i < out.numberofpoints; ++i)
    soup.points.push_back(Point(out.pointlist[3 * i], out.pointlist[3 * i + 1], out.pointlist[3 * i + 2]));
  soup.tetrahedra.reserve(std::size_t(out.numberoftetrahedra));
  for(int t = 0; t < out.numberoftetrahedra; ++t) {
    const int* c = out.tetrahedronlist + t * out.numberofcorners;
    soup.tetrahedra.push_back({std::size_t(c[0]), std::size_t(c[1]), std::size_t(c[2]), std::size_t(c[3])});
  }
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_TETRAHEDRALIZE_SURFACE_H
