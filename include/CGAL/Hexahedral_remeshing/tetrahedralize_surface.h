// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_TETRAHEDRALIZE_SURFACE_H
#define CGAL_HEXAHEDRAL_REMESHING_TETRAHEDRALIZE_SURFACE_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_soup_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/parameters.h>
#include <CGAL/Hexahedral_remeshing/internal/isolated_call.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#ifndef TETLIBRARY
#define TETLIBRARY
#endif
#include <tetgen.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Surface_kernel;
typedef CGAL::Surface_mesh<Surface_kernel::Point_3> Checked_surface;

inline std::string point_string(const Surface_kernel::Point_3& p)
{
  std::ostringstream s;
  s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

// Repairs a polygon soup (merges duplicated points and polygons, drops polygons with repeated
// vertices: PMP::repair_polygon_soup), orients it consistently (PMP::orient_polygon_soup) and
// makes a triangulated surface of it. Throws Input_error for what cannot be repaired.
inline void surface_from_polygon_soup(std::vector<Surface_kernel::Point_3>& points,
                                      std::vector<std::vector<std::size_t> >& polygons,
                                      const std::string& source, Checked_surface& sm)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  if(polygons.empty()) throw Input_error(source, 0, "the surface has no faces (empty or unreadable file)");
  for(std::size_t i = 0; i < points.size(); ++i)
    for(int c = 0; c < 3; ++c)
      if(!std::isfinite(points[i][c]))
        throw Input_error(source, 0, "vertex " + std::to_string(i) + ": coordinate is not a finite number");
  for(std::size_t f = 0; f < polygons.size(); ++f) {
    if(polygons[f].size() < 3)
      throw Input_error(source, 0, "face " + std::to_string(f) + " has " + std::to_string(polygons[f].size()) +
                        " vertices (at least 3 are needed)");
    for(std::size_t v : polygons[f])
      if(v >= points.size())
        throw Input_error(source, 0, "face " + std::to_string(f) + ": vertex index " + std::to_string(v) +
                          " out of range (the file has " + std::to_string(points.size()) + " vertices)");
  }
  PMP::repair_polygon_soup(points, polygons);
  if(polygons.empty())
    throw Input_error(source, 0, "every face of the surface is degenerate (repeated vertices)");
  const std::size_t before = points.size();
  if(!PMP::orient_polygon_soup(points, polygons))
    throw Input_error(source, 0, "the surface is not manifold: " + std::to_string(points.size() - before) +
                      " vertices or edges are shared by more than two faces or by several separate fans of faces "
                      "(e.g. two bodies sharing an edge, a face or a corner); separate the bodies or fuse them "
                      "into one solid, and retry");
  PMP::polygon_soup_to_polygon_mesh(points, polygons, sm);
  // Polygons are triangulated in 3D (hole filling), not by a constrained Delaunay triangulation of
  // their projection, which fails on a non-planar polygon whose projection overlaps itself (found
  // by the fuzzer: a precondition of CGAL's CDT, unchecked with NDEBUG). What still fails is an error.
  bool triangulated = CGAL::is_triangle_mesh(sm);
  if(!triangulated) {
    try {
      triangulated = PMP::triangulate_faces(sm, CGAL::parameters::use_delaunay_triangulation(false));
    } catch(const CGAL::Failure_exception&) {
      triangulated = false;
    }
  }
  if(!triangulated)
    throw Input_error(source, 0, "a polygonal face cannot be triangulated (degenerate face); triangulate the "
                      "surface and retry");
}

// Checks that `sm` bounds a volume TetGen can fill: closed, no zero-area triangle, no intersection
// between triangles (of one shell or of two shells: touching bodies). Then orients every shell
// so that the surface bounds a volume (PMP::orient_to_bound_a_volume: outer shells outward,
// cavities inward) and returns for each triangle whether some shell nests another.
inline bool check_and_orient_surface(Checked_surface& sm, const std::string& source)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  if(faces(sm).empty()) throw Input_error(source, 0, "the surface has no faces");
  std::size_t border = 0;
  std::string example;
  for(auto h : halfedges(sm))
    if(CGAL::is_border(h, sm)) {
      if(border++ == 0)
        example = point_string(sm.point(sm.source(h))) + " - " + point_string(sm.point(target(h, sm)));
    }
  if(border > 0)
    throw Input_error(source, 0, "the surface is not closed: " + std::to_string(border) + " border edge" +
                      (border > 1 ? "s" : "") + " (first: " + example + "); close the holes (a solid's surface "
                      "must be watertight) and retry");
  std::size_t degenerate = 0;
  for(auto f : faces(sm))
    if(PMP::is_degenerate_triangle_face(f, sm)) {
      if(degenerate++ == 0) example = point_string(sm.point(target(halfedge(f, sm), sm)));
    }
  if(degenerate > 0)
    throw Input_error(source, 0, std::to_string(degenerate) + " triangle" + (degenerate > 1 ? "s have" : " has") +
                      " zero area (first near " + example + "); remove the degenerate triangles and retry");
  std::vector<std::pair<Checked_surface::Face_index, Checked_surface::Face_index> > pairs;
  PMP::self_intersections(sm, std::back_inserter(pairs));
  if(!pairs.empty()) {
    const auto f = pairs.front().first;
    throw Input_error(source, 0, "the surface intersects itself: " + std::to_string(pairs.size()) +
                      " pair" + (pairs.size() > 1 ? "s" : "") + " of triangles intersect (first near " +
                      point_string(sm.point(target(halfedge(f, sm), sm))) + "); shells that touch or overlap "
                      "(an assembly of touching bodies) or a surface crossing itself do not bound a volume: "
                      "fuse or separate the bodies and retry");
  }
  PMP::orient_to_bound_a_volume(sm);
  auto vid = sm.add_property_map<Checked_surface::Face_index, std::size_t>("f:hexrem_volume", 0).first;
  std::vector<std::size_t> levels;
  PMP::volume_connected_components(sm, vid, CGAL::parameters::nesting_levels(std::ref(levels)).do_orientation_tests(false));
  sm.remove_property_map(vid);
  for(std::size_t l : levels) if(l > 0) return true;
  return false;
}

// Bound on TetGen's Steiner points (switch S), per surface vertex and per volume bound
// (maximum_tetrahedron_volume) in the bounding box of the surface.
constexpr double steiner_points_per_surface_vertex = 100;
constexpr double steiner_points_per_volume_bound = 10;

inline std::string tetgen_error(int code)
{
  switch(code) {
    case 1: return "out of memory";
    case 2: return "internal error";
    case 3: return "the surface intersects itself";
    case 4: return "a feature of the surface is too small for the floating-point tolerance";
    case 5: return "two facets are too close to each other";
    case 10: return "invalid input";
    default: return "error " + std::to_string(code);
  }
}

} // namespace internal

/// \ingroup PkgHexahedralRemeshingRef
/// Same as `tetrahedralize_surface()` for a surface already made by
/// `CGAL::Polygon_mesh_processing` from a repaired soup: runs the checks (closed, no zero-area
/// triangle, no intersection), orients the shells to bound a volume (which modifies `sm`), runs
/// TetGen in a child process and removes the tetrahedra of the cavities.
/// \param sm a triangulated surface
/// \param soup the output (its `source` names the input in error messages)
/// \param np the named parameters of `tetrahedralize_surface()` but `vertex_point_map`
/// \throws Input_error as `tetrahedralize_surface()`.
template <class Point, class NamedParameters = CGAL::parameters::Default_named_parameters>
void tetrahedralize_checked_surface(CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>& sm,
                                    Tetrahedral_soup_3<Point>& soup,
                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef internal::Checked_surface SM;
  const std::string source = soup.source;
  soup = Tetrahedral_soup_3<Point>();
  soup.source = source;
  const double max_volume = choose_parameter(get_parameter(np, internal_np::maximum_tetrahedron_volume), 0.);
  const double ratio = choose_parameter(get_parameter(np, internal_np::radius_edge_ratio), 2.0);
  const bool preserve = choose_parameter(get_parameter(np, internal_np::preserve_surface_triangles), false);

  // TetGen does not terminate with a radius-edge bound below 1, and reads a non-positive volume
  // bound as none: refused rather than run forever in the child process
  if(!(ratio == 0 || ratio >= 1) || !std::isfinite(ratio))
    throw Input_error(source, 0, "the radius-edge ratio must be 0 (no refinement) or at least 1, got " +
                      std::to_string(ratio));
  if(!(max_volume >= 0) || !std::isfinite(max_volume))
    throw Input_error(source, 0, "the maximum tetrahedron volume must be positive, got " + std::to_string(max_volume));
  const bool nested = internal::check_and_orient_surface(sm, source);

  std::vector<double> coords;
  std::unordered_map<SM::Vertex_index, int> vindex;
  for(SM::Vertex_index v : sm.vertices()) {
    vindex[v] = int(vindex.size());
    const auto& p = sm.point(v);
    coords.insert(coords.end(), {p.x(), p.y(), p.z()});
  }
  std::vector<int> triangles;
  for(SM::Face_index f : sm.faces())
    for(SM::Vertex_index v : vertices_around_face(sm.halfedge(f), sm)) triangles.push_back(vindex[v]);

  // TetGen's quality refinement need not terminate near very acute angles of the surface (a spike,
  // a thin sliver of volume: a 2000:1 box never stops). Its Steiner points are bounded far above
  // what a surface that it can mesh needs (the surfaces of 42 CAD parts, hexme and MAMBO: at most 3.2 per
  // surface vertex, 0.7 per volume bound of the bounding box), and reaching the bound is an error.
  const std::size_t surface_vertices = coords.size() / 3;
  double steiner_bound = internal::steiner_points_per_surface_vertex * double(surface_vertices);
  if(max_volume > 0) {
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(sm);
    steiner_bound += internal::steiner_points_per_volume_bound * (box.xmax() - box.xmin()) * (box.ymax() - box.ymin()) *
                     (box.zmax() - box.zmin()) / max_volume;
  }
  // TetGen counts them in an int
  const long steiner_limit = long(std::min(steiner_bound, 2.0e9));
  std::ostringstream sw;
  sw << "pzQ";
  if(preserve) sw << "Y";
  if(ratio > 0) sw << "q" << ratio;
  if(max_volume > 0) sw << "a" << max_volume;
  sw << "S" << steiner_limit;
  const std::string switches = sw.str();

  // TetGen runs in a child process: the checks above keep it from the inputs known to crash it,
  // the isolation turns any other crash into an Input_error.
  const std::string bytes = internal::run_isolated([&]() -> std::string {
    tetgenio in, out;
    in.firstnumber = 0;
    in.numberofpoints = int(coords.size() / 3);
    in.pointlist = new REAL[coords.size()];
    std::copy(coords.begin(), coords.end(), in.pointlist);
    const std::size_t nf = triangles.size() / 3;
    in.numberoffacets = int(nf);
    in.facetlist = new tetgenio::facet[nf];
    in.facetmarkerlist = new int[nf];
    for(std::size_t fi = 0; fi < nf; ++fi) {
      tetgenio::facet& tf = in.facetlist[fi];
      tetgenio::init(&tf);
      tf.numberofpolygons = 1;
      tf.polygonlist = new tetgenio::polygon[1];
      tetgenio::polygon& poly = tf.polygonlist[0];
      tetgenio::init(&poly);
      poly.numberofvertices = 3;
      poly.vertexlist = new int[3];
      for(int k = 0; k < 3; ++k) poly.vertexlist[k] = triangles[3 * fi + std::size_t(k)];
      in.facetmarkerlist[fi] = 0;
    }
    std::string sws = switches;
    try {
      tetrahedralize(&sws[0], &in, &out);
    } catch(int code) {
      throw Input_error(source, 0, "TetGen failed (" + internal::tetgen_error(code) + ") although the surface "
                        "passed the checks (closed, manifold, no intersection); try --radius-edge 0 or repair "
                        "the surface (nearly coincident or nearly degenerate triangles)");
    }
    Tetrahedral_soup_3<Point> result;
    for(int i = 0; i < out.numberofpoints; ++i)
      result.points.push_back(Point(out.pointlist[3 * i], out.pointlist[3 * i + 1], out.pointlist[3 * i + 2]));
    for(int t = 0; t < out.numberoftetrahedra; ++t) {
      const int* c = out.tetrahedronlist + t * out.numberofcorners;
      result.tetrahedra.push_back({std::size_t(c[0]), std::size_t(c[1]), std::size_t(c[2]), std::size_t(c[3])});
    }
    return internal::serialize_soup(result);
  }, source, "TetGen", choose_parameter(get_parameter(np, internal_np::time_limit), 0.));
  Tetrahedral_soup_3<Point> result;
  internal::deserialize_soup(bytes, result);
  if(result.tetrahedra.empty()) throw Input_error(source, 0, "TetGen produced no tetrahedra");
  if(result.points.size() >= surface_vertices + std::size_t(steiner_limit))
    throw Input_error(source, 0, "TetGen's quality refinement does not terminate on this surface: it stopped at " +
                      std::to_string(steiner_limit) + " added points (" +
                      std::to_string(long(internal::steiner_points_per_surface_vertex)) + " per surface vertex" +
                      (max_volume > 0 ? std::string(" and ") + std::to_string(long(internal::steiner_points_per_volume_bound)) +
                                        " per volume bound in the bounding box" : std::string()) +
                      "); a very acute angle (a spike or a thin sliver of volume) makes it refine without end: "
                      "remove it, or turn the refinement off (radius-edge ratio 0) or loosen it (a larger ratio)");
  for(const auto& t : result.tetrahedra)
    for(std::size_t v : t)
      if(v >= result.points.size()) throw Error("internal error: TetGen returned an index out of range");

  if(nested) {
    // TetGen fills the inside of the outermost shells: the tetrahedra of the cavities (inside an
    // even number of shells) are removed. A tetrahedron never crosses the surface, so its
    // centroid decides (ray parity, CGAL::Side_of_triangle_mesh).
    CGAL::Side_of_triangle_mesh<SM, internal::Surface_kernel> side(sm);
    std::vector<std::array<std::size_t, 4> > kept;
    for(const auto& t : result.tetrahedra) {
      double c[3] = {0, 0, 0};
      for(std::size_t v : t)
        for(int i = 0; i < 3; ++i) c[i] += CGAL::to_double(result.points[v][i]) / 4;
      if(side(internal::Surface_kernel::Point_3(c[0], c[1], c[2])) == CGAL::ON_BOUNDED_SIDE) kept.push_back(t);
    }
    if(kept.empty()) throw Input_error(source, 0, "the surface encloses no volume");
    std::vector<std::size_t> renumber(result.points.size(), std::size_t(-1));
    for(auto& t : kept)
      for(std::size_t& v : t) {
        if(renumber[v] == std::size_t(-1)) {
          renumber[v] = soup.points.size();
          soup.points.push_back(result.points[v]);
        }
        v = renumber[v];
      }
    soup.tetrahedra.swap(kept);
  } else {
    soup.points.swap(result.points);
    soup.tetrahedra.swap(result.tetrahedra);
  }
}

/// \ingroup PkgHexahedralRemeshingRef
/// Tetrahedralizes the closed surface `surface` with TetGen (piecewise linear complex, switch `p`)
/// and stores the result in `soup` (which is cleared first). The boundary of the result is the
/// input surface, geometrically: TetGen may insert points on it to meet the quality and volume
/// bounds, unless `preserve_surface_triangles` is set (switch `Y`, which in TetGen 1.5 also
/// prevents most refinement).
///
/// Before TetGen the surface is repaired and checked with CGAL's Polygon Mesh Processing:
/// duplicated points and faces are merged (`repair_polygon_soup()`), faces are oriented
/// consistently (`orient_polygon_soup()`), then the surface must be closed, manifold, free of
/// zero-area triangles and of intersections (within a shell and between shells), so that TetGen
/// only sees surfaces that bound a volume. The shells are then oriented to bound a volume
/// (`orient_to_bound_a_volume()`): a shell nested in another one is a cavity, a shell nested in a
/// cavity is a body again, and disjoint shells are separate bodies. TetGen runs in a child process
/// (where `fork()` exists), so that even a crash of TetGen becomes an `Input_error`.
/// The surface carries no patch or feature information, so the soup has no hints.
///
/// \tparam FaceListGraph a model of `FaceListGraph` (e.g. `CGAL::Surface_mesh`)
/// \param surface a closed surface with no self-intersection (faces of any orientation)
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
/// \throws Input_error naming `soup.source`, the problem, an example location and what to do, if the
///         surface is empty, not closed, not manifold, has zero-area triangles, intersects itself
///         (or two shells touch), if TetGen fails or crashes, if its quality refinement does not terminate
///         (it reaches 100 added points per surface vertex plus 10 per `maximum_tetrahedron_volume` in the
///         bounding box: a very acute angle), or for a radius-edge ratio in (0, 1) (TetGen would not terminate)
///         or a negative volume bound.
template <class FaceListGraph, class Point, class NamedParameters = CGAL::parameters::Default_named_parameters>
void tetrahedralize_surface(const FaceListGraph& surface, Tetrahedral_soup_3<Point>& soup,
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<FaceListGraph>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<FaceListGraph>::face_descriptor face_descriptor;
  typedef internal::Surface_kernel::Point_3 SPoint;

  const std::string source = soup.source;
  soup = Tetrahedral_soup_3<Point>();
  soup.source = source;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_const_property_map(CGAL::vertex_point, surface));

  std::vector<SPoint> points;
  std::vector<std::vector<std::size_t> > polygons;
  std::unordered_map<vertex_descriptor, std::size_t> vindex;
  for(vertex_descriptor v : vertices(surface)) {
    const auto& p = get(vpm, v);
    vindex[v] = points.size();
    points.push_back(SPoint(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
  }
  for(face_descriptor f : faces(surface)) {
    polygons.emplace_back();
    for(vertex_descriptor v : vertices_around_face(halfedge(f, surface), surface)) polygons.back().push_back(vindex[v]);
  }
  internal::Checked_surface sm;
  internal::surface_from_polygon_soup(points, polygons, source, sm);
  tetrahedralize_checked_surface(sm, soup, np);
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_TETRAHEDRALIZE_SURFACE_H
