// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_READ_GMSH_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_READ_GMSH_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_soup_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/parameters.h>
#include <CGAL/Hexahedral_remeshing/internal/cad/acute_curve_grading.h>
#include <CGAL/Hexahedral_remeshing/internal/isolated_call.h>
#include <CGAL/Hexahedral_remeshing/internal/wall_thickness.h>
#include <CGAL/Hexahedral_remeshing/tetrahedralize_surface.h>

#include <CGAL/Named_function_parameters.h>

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

namespace internal_np {
enum mesh_size_t { mesh_size };
enum acute_edge_grading_t { acute_edge_grading };
} // namespace internal_np

namespace parameters {
#ifdef DOXYGEN_RUNNING
/// CAD input: target edge length of gmsh's tetrahedra, in the units of the part (`double`,
/// default: the diagonal of the part's bounding box divided by 20).
template <class T> unspecified_type mesh_size(const T& value);
/// CAD input: grade the tetrahedra towards the CAD curves where the solid's angle is below 45
/// degrees (`bool`, default `true`; see `read_CAD()`).
template <class T> unspecified_type acute_edge_grading(const T& value);
#else
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(mesh_size)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(acute_edge_grading)
#endif
} // namespace parameters

namespace IO {
namespace internal_gmsh {

// gmsh is a process-wide singleton that prints on the terminal: it only ever runs in the child
// process of internal::run_isolated(), initialized there and silenced, so that every call starts
// from a clean state, any number of calls (and calls from a process that uses gmsh itself) are
// safe, and nothing is printed.
inline void start()
{
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.Verbosity", 1);
  gmsh::option::setNumber("General.NumThreads", 1);
  gmsh::logger::start();
}

// The last error gmsh logged, or `fallback`.
inline std::string last_error(const std::string& fallback)
{
  std::vector<std::string> log;
  try { gmsh::logger::get(log); } catch(...) {}
  for(auto it = log.rbegin(); it != log.rend(); ++it)
    if(it->compare(0, 6, "Error:") == 0) {
      std::string s = it->substr(6);
      while(!s.empty() && s.front() == ' ') s.erase(s.begin());
      return s;
    }
  return fallback;
}

// Runs a gmsh call; a failure becomes an Input_error with gmsh's own message.
template <class F>
void call(const std::string& source, const std::string& doing, const F& f)
{
  try {
    f();
  } catch(const Input_error&) {
    throw;
  } catch(...) {
    throw Input_error(source, 0, "gmsh could not " + doing + ": " + last_error("unknown error"));
  }
}

// Where a solid touches itself: over the pairs of CAD faces that share no curve, the mesh node of
// one closest (on the CAD geometry) to the other; "" if no pair is closer than `tolerance`. Called
// after the 3D mesher failed with its PLC error ("a segment and a facet intersect"), which names no
// point: a face tangent to another (a sphere touching a face) is the usual cause.
inline std::string touching_faces(double tolerance)
{
  std::vector<std::pair<int, int> > faces;
  gmsh::model::getEntities(faces, 2);
  if(faces.size() > 400) return std::string(); // the error path stays quick
  std::vector<std::set<int> > curves(faces.size());
  for(std::size_t i = 0; i < faces.size(); ++i) {
    std::vector<int> up, down;
    gmsh::model::getAdjacencies(2, faces[i].second, up, down);
    curves[i].insert(down.begin(), down.end());
  }
  double best = tolerance;
  std::string found;
  for(std::size_t i = 0; i < faces.size(); ++i) {
    std::vector<std::size_t> tags;
    std::vector<double> coords, parametric;
    try { gmsh::model::mesh::getNodes(tags, coords, parametric, 2, faces[i].second, true, false); } catch(...) { continue; }
    const std::size_t stride = (std::max)(std::size_t(1), tags.size() / 2000);
    for(std::size_t j = 0; j < faces.size(); ++j) {
      if(j == i) continue;
      bool adjacent = false;
      for(int c : curves[j]) adjacent = adjacent || curves[i].count(c) > 0;
      if(adjacent) continue;
      for(std::size_t n = 0; n < tags.size(); n += stride) {
        std::vector<double> point(coords.begin() + 3 * n, coords.begin() + 3 * n + 3), closest, uv;
        try { gmsh::model::getClosestPoint(2, faces[j].second, point, closest, uv); } catch(...) { break; }
        const double d = std::sqrt((closest[0] - point[0]) * (closest[0] - point[0]) + (closest[1] - point[1]) * (closest[1] - point[1]) +
                                   (closest[2] - point[2]) * (closest[2] - point[2]));
        if(d < best) {
          best = d;
          std::ostringstream os;
          os << "near (" << point[0] << ", " << point[1] << ", " << point[2] << "), CAD faces " << faces[i].second << " and "
             << faces[j].second << " meet (distance " << d << ") without sharing an edge";
          found = os.str();
        }
      }
    }
  }
  return found;
}

// A failure of the 3D mesher in our words: the PLC error of gmsh's boundary recovery means that two
// faces of the boundary touch or cross.
inline std::string mesher_failure(const std::string& source, double diagonal, double h)
{
  const std::string raw = last_error("unknown error");
  if(raw.find("PLC Error") == std::string::npos && raw.find("intersect") == std::string::npos)
    return "gmsh could not tetrahedralize the part (mesh size " + std::to_string(h) + "): " + raw;
  (void)source;
  std::string where;
  try { where = touching_faces(1e-3 * diagonal); } catch(...) {}
  return "the solid touches itself" + (where.empty() ? std::string(" (two of its faces touch or cross)") : ": " + where) +
         ", where a solid has zero thickness; no tetrahedral mesh can fill it: leave a gap between those faces "
         "or fuse them along an edge in the CAD tool, and retry (gmsh: " + raw + ")";
}

// A solid that touches itself may also come out of gmsh meshed, with tetrahedra of zero volume where
// its faces touch (a sphere tangent to a face, at a fine size): "" if every tetrahedron has a volume,
// else the reason, as mesher_failure() gives it, with the place of the first flat tetrahedron.
template <class Point>
std::string flat_tetrahedra_failure(const Tetrahedral_soup_3<Point>& soup, double diagonal)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 P;
  auto point = [&](std::size_t v) {
    return P(CGAL::to_double(soup.points[v][0]), CGAL::to_double(soup.points[v][1]), CGAL::to_double(soup.points[v][2]));
  };
  for(const auto& t : soup.tetrahedra) {
    const P a = point(t[0]), b = point(t[1]), c = point(t[2]), d = point(t[3]);
    if(CGAL::orientation(a, b, c, d) != CGAL::COPLANAR) continue;
    std::string where;
    try { where = touching_faces(1e-3 * diagonal); } catch(...) {}
    if(where.empty()) {
      std::ostringstream os;
      os.precision(4);
      os << "near (" << (a.x() + b.x() + c.x() + d.x()) / 4 << ", " << (a.y() + b.y() + c.y() + d.y()) / 4 << ", "
         << (a.z() + b.z() + c.z() + d.z()) / 4 << ")";
      where = os.str();
    }
    return "the solid touches itself: " + where + ", where a solid has zero thickness (gmsh made a flat tetrahedron "
           "there); no tetrahedral mesh can fill it: leave a gap between those faces or fuse them along an edge in "
           "the CAD tool, and retry";
  }
  return std::string();
}

inline void check_readable(const std::string& filename)
{
  std::ifstream probe(filename, std::ios::binary);
  if(!probe) throw Input_error(filename, 0, "cannot open file for reading");
}

// Corners among the candidate vertices: where the number of feature curves met is not 2, or where
// two curves meet at an angle (not a smooth continuation: the end of a circle split into arcs, the
// end of a seam-free closed curve).
template <class Point>
std::vector<std::size_t> select_corners(const Tetrahedral_soup_3<Point>& soup, const std::set<std::size_t>& candidates)
{
  std::map<std::size_t, std::vector<std::pair<int, std::size_t> > > ends; // vertex -> (curve, other end)
  for(std::size_t i = 0; i < soup.feature_edges.size(); ++i) {
    const auto& e = soup.feature_edges[i];
    if(candidates.count(e[0])) ends[e[0]].push_back({soup.feature_edge_curves[i], e[1]});
    if(candidates.count(e[1])) ends[e[1]].push_back({soup.feature_edge_curves[i], e[0]});
  }
  std::vector<std::size_t> corners;
  for(std::size_t v : candidates) {
    const auto it = ends.find(v);
    if(it == ends.end()) continue; // a point of a seam or of no feature curve
    const auto& list = it->second;
    bool corner = list.size() != 2;
    if(!corner) {
      const Point& p = soup.points[v];
      const Point& a = soup.points[list[0].second];
      const Point& b = soup.points[list[1].second];
      double u[3], w[3], nu = 0, nw = 0, dot = 0;
      for(int i = 0; i < 3; ++i) {
        u[i] = CGAL::to_double(a[i]) - CGAL::to_double(p[i]);
        w[i] = CGAL::to_double(b[i]) - CGAL::to_double(p[i]);
        nu += u[i] * u[i]; nw += w[i] * w[i]; dot += u[i] * w[i];
      }
      // straight continuation: the two segments point in opposite directions (angle > 150 degrees)
      corner = !(nu > 0 && nw > 0 && dot / std::sqrt(nu * nw) < -0.866);
    }
    if(corner) corners.push_back(v);
  }
  return corners;
}

// Copies the mesh of the current gmsh model into `soup`: tetrahedra (corner nodes of any order),
// triangles tagged by their surface entity, line segments tagged by their curve entity (but seam
// curves, which bound one surface only), and corners. Volume elements other than tetrahedra are
// refused with their counts.
// The name of surface entity `tag`: its physical group's name (a .msh file, a model with physical
// groups), else its own (a CAD face with a name), if any.
template <class Point>
void add_patch_name(int tag, Tetrahedral_soup_3<Point>& soup)
{
  for(const auto& pn : soup.patch_names)
    if(pn.first == tag) return;
  std::string name;
  try {
    std::vector<int> groups;
    gmsh::model::getPhysicalGroupsForEntity(2, tag, groups);
    for(int g : groups) {
      gmsh::model::getPhysicalName(2, g, name);
      if(!name.empty()) break;
    }
    if(name.empty()) gmsh::model::getEntityName(2, tag, name);
  } catch(...) {
    name.clear();
  }
  if(!name.empty()) soup.patch_names.emplace_back(tag, name);
}

template <class Point>
void extract(const std::string& source, Tetrahedral_soup_3<Point>& soup)
{
  std::vector<std::size_t> node_tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, false, false);
  std::unordered_map<std::size_t, std::size_t> index;
  index.reserve(node_tags.size());
  for(std::size_t i = 0; i < node_tags.size(); ++i) {
    if(!index.emplace(node_tags[i], soup.points.size()).second) continue;
    soup.points.push_back(Point(coords[3 * i], coords[3 * i + 1], coords[3 * i + 2]));
  }
  auto node = [&](std::size_t tag) {
    const auto it = index.find(tag);
    if(it == index.end()) throw Input_error(source, 0, "an element refers to node " + std::to_string(tag) + ", which does not exist");
    return it->second;
  };

  std::map<std::string, std::size_t> other_volume_cells;
  std::set<std::size_t> corner_candidates;
  for(int dim = 3; dim >= 0; --dim) {
    std::vector<std::pair<int, int> > entities;
    gmsh::model::getEntities(entities, dim);
    for(const auto& dt : entities) {
      bool seam = false;
      if(dim == 1) {
        std::vector<int> up, down;
        try { gmsh::model::getAdjacencies(1, dt.second, up, down); } catch(...) { up.clear(); }
        std::sort(up.begin(), up.end());
        seam = up.size() == 1 || (up.size() == 2 && up[0] == up[1]);
      }
      std::vector<int> types;
      std::vector<std::vector<std::size_t> > element_tags, nodes;
      gmsh::model::mesh::getElements(types, element_tags, nodes, dim, dt.second);
      for(std::size_t k = 0; k < types.size(); ++k) {
        std::string name;
        int edim = 0, order = 0, num_nodes = 0, num_primary = 0;
        std::vector<double> local;
        gmsh::model::mesh::getElementProperties(types[k], name, edim, order, num_nodes, local, num_primary);
        if(num_nodes <= 0) continue;
        const std::size_t n = nodes[k].size() / std::size_t(num_nodes);
        const std::vector<std::size_t>& nk = nodes[k];
        const std::string family = name.substr(0, name.find(' '));
        for(std::size_t e = 0; e < n; ++e) {
          const std::size_t* c = nk.data() + e * std::size_t(num_nodes);
          if(edim == 3) {
            if(family == "Tetrahedron") {
              soup.tetrahedra.push_back({node(c[0]), node(c[1]), node(c[2]), node(c[3])});
            } else {
              ++other_volume_cells[family];
            }
          } else if(edim == 2 && family == "Triangle") {
            if(e == 0) add_patch_name(dt.second, soup);
            soup.triangles.push_back({node(c[0]), node(c[1]), node(c[2])});
            soup.triangle_patches.push_back(dt.second);
          } else if(edim == 1 && !seam) {
            soup.feature_edges.push_back({node(c[0]), node(c[1])});
            soup.feature_edge_curves.push_back(dt.second);
          } else if(edim == 0) {
            corner_candidates.insert(node(c[0]));
          }
        }
      }
    }
  }
  if(!other_volume_cells.empty()) {
    std::string list;
    for(const auto& kv : other_volume_cells)
      list += (list.empty() ? "" : ", ") + std::to_string(kv.second) + " " + kv.first;
    throw Input_error(source, 0, "the mesh has volume elements other than tetrahedra (" + list + " element(s), with " +
                      std::to_string(soup.tetrahedra.size()) + " tetrahedra); they would be lost: mesh with "
                      "tetrahedra only (gmsh: no Recombine, Mesh.SubdivisionAlgorithm = 0) and retry");
  }
  soup.corners = select_corners(soup, corner_candidates);
}

// Opens a CAD part in gmsh (in the child process) and checks that it is one or more separate solids;
// returns the diagonal of its bounding box.
inline double open_cad_part(const std::string& filename)
{
  internal_gmsh::start();
  internal_gmsh::call(filename, "read the CAD file", [&] { gmsh::open(filename); });
  std::vector<std::pair<int, int> > volumes, surfaces;
  gmsh::model::getEntities(volumes, 3);
  gmsh::model::getEntities(surfaces, 2);
  if(volumes.empty())
    throw Input_error(filename, 0, "the CAD file has no solid (" + std::to_string(surfaces.size()) +
                      " surfaces, no volume): export the part as a solid (closed shells sewn into a volume) and retry");
  if(volumes.size() > 1) {
    // Solids meshed one by one would overlap or touch without sharing nodes: the boolean
    // fragments of the solids tell whether they intersect (more pieces, or a shared face).
    std::vector<std::pair<int, int> > pieces, tools(volumes.begin() + 1, volumes.end());
    std::vector<std::vector<std::pair<int, int> > > map;
    internal_gmsh::call(filename, "intersect the solids of the part", [&] {
      gmsh::model::occ::fragment({volumes.front()}, tools, pieces, map);
      gmsh::model::occ::synchronize();
    });
    std::vector<std::pair<int, int> > after, faces;
    gmsh::model::getEntities(after, 3);
    gmsh::model::getEntities(faces, 2);
    std::size_t shared = 0;
    for(const auto& f : faces) {
      std::vector<int> up, down;
      gmsh::model::getAdjacencies(2, f.second, up, down);
      shared += up.size() > 1;
    }
    if(after.size() != volumes.size() || shared > 0)
      throw Input_error(filename, 0, "the part has " + std::to_string(volumes.size()) + " solids that touch or "
                        "overlap (" + std::to_string(shared) + " shared faces after intersecting them); each body "
                        "must be one solid: fuse them in the CAD tool (boolean union) or separate them, and retry");
  }
  double xmin = 0, ymin = 0, zmin = 0, xmax = 0, ymax = 0, zmax = 0;
  gmsh::model::getBoundingBox(-1, -1, xmin, ymin, zmin, xmax, ymax, zmax);
  const double diagonal = std::sqrt((xmax - xmin) * (xmax - xmin) + (ymax - ymin) * (ymax - ymin) +
                                    (zmax - zmin) * (zmax - zmin));
  if(!(diagonal > 0) || !std::isfinite(diagonal))
    throw Input_error(filename, 0, "the part has an empty or infinite bounding box");
  return diagonal;
}

// The wall thickness of a part from its surface triangles (gmsh's, of any orientation), oriented to
// bound a volume first; a surface that cannot be oriented gives no measure (infinite thickness).
template <class Point>
internal::Wall_thickness surface_wall_thickness(const Tetrahedral_soup_3<Point>& soup)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  typedef internal::Checked_surface SM;
  try {
    std::vector<internal::Surface_kernel::Point_3> points;
    for(const Point& p : soup.points)
      points.emplace_back(CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2]));
    std::vector<std::vector<std::size_t> > polygons;
    for(const auto& t : soup.triangles) polygons.push_back({t[0], t[1], t[2]});
    PMP::repair_polygon_soup(points, polygons);
    if(polygons.empty() || !PMP::orient_polygon_soup(points, polygons)) return internal::Wall_thickness();
    SM sm;
    PMP::polygon_soup_to_polygon_mesh(points, polygons, sm);
    if(!CGAL::is_closed(sm) || !CGAL::is_triangle_mesh(sm)) return internal::Wall_thickness();
    PMP::orient_to_bound_a_volume(sm);
    std::vector<internal::Surface_kernel::Point_3> vertex_points;
    std::map<SM::Vertex_index, std::uint32_t> index;
    for(SM::Vertex_index v : sm.vertices()) {
      index[v] = std::uint32_t(vertex_points.size());
      vertex_points.push_back(sm.point(v));
    }
    std::vector<std::array<std::uint32_t, 3> > triangles;
    for(SM::Face_index f : sm.faces()) {
      std::array<std::uint32_t, 3> t;
      int k = 0;
      for(SM::Vertex_index v : vertices_around_face(sm.halfedge(f), sm)) t[std::size_t(k++)] = index[v];
      triangles.push_back(t);
    }
    return internal::wall_thickness(vertex_points, triangles);
  } catch(...) {
    return internal::Wall_thickness();
  }
}

// The mesh size, over the part's wall thickness, above which read_CAD() refuses to tetrahedralize.
constexpr double maximum_mesh_size_over_wall_thickness = 8;

// Where the part is thinner than the tetrahedra can follow (a wall `ratio` times thinner than the mesh
// size `h`): gmsh would run for minutes and fill memory with slivers.
inline std::string thin_wall_message(const internal::Wall_thickness& w, double h)
{
  std::ostringstream os;
  os.precision(3);
  os << "the part's walls are " << w.thickness << " thick (near " << w.where() << "; half of its surface is "
     << "closer than that to the opposite side), " << h / w.thickness << " times thinner than the tetrahedra "
     << "(mesh size " << h << "): tetrahedralize with a mesh size of at most " << w.thickness
     << " (named parameter mesh_size; hexmesh --mesh-size, or --target-edge-length for the hexahedra), or thicken the walls";
  return os.str();
}

} // namespace internal_gmsh

/// \ingroup PkgHexahedralRemeshingRef
/// Reads a gmsh mesh file (`.msh`, formats 4.1 ASCII and binary, 2.2 ASCII and binary, read by
/// the gmsh library, the format's reference) into `soup`.
///
/// Tetrahedra of any order give their four corner nodes; triangles become tagged boundary
/// triangles (patch = the gmsh surface entity tag), line elements feature edges (curve = the
/// gmsh curve entity tag; seam curves, which bound a single surface, are left out), point
/// elements corners (where the feature curves meet at an angle or where their number is not 2).
/// A file with triangles but no volume element is taken as a closed surface and tetrahedralized
/// (see `tetrahedralize_surface()`, whose named parameters apply).
///
/// gmsh runs in a child process (where `fork()` exists): silent, from a clean state at every
/// call, and a crash of the library on a hostile file becomes an `Input_error`.
///
/// \param filename the `.msh` file
/// \param soup the output (overwritten)
/// \param np the named parameters of `tetrahedralize_surface()`, for surface meshes
/// \throws Input_error naming the file and the problem: unreadable or malformed file (gmsh's
///         message), volume elements other than tetrahedra (with their counts), no element.
template <class Point, class NamedParameters = CGAL::parameters::Default_named_parameters>
void read_gmsh(const std::string& filename, Tetrahedral_soup_3<Point>& soup,
               const NamedParameters& np = CGAL::parameters::default_values());

/// \ingroup PkgHexahedralRemeshingRef
/// Imports a CAD part with gmsh and OpenCASCADE (`.step`/`.stp`, `.brep`, `.iges`/`.igs`),
/// tetrahedralizes its solids with gmsh (mesh size `mesh_size`, by default the diagonal of the
/// bounding box over 20) and stores the result in `soup`, with the CAD's structure as hints: the
/// triangles of each CAD face are tagged with the face (surface patch), the edges of each CAD curve
/// are feature edges of that curve (seams of periodic faces excluded), and the CAD vertices where
/// curves meet at an angle are corners.
///
/// Along CAD curves where the solid's angle is below 45 degrees (acute edges, which the pipeline
/// gives valence 1 and surrounds with fixed frames, see `compute_frame_field_pipeline()`), the
/// tetrahedra are graded: `mesh_size / 7` on the curve, growing as tan(angle) times the distance to
/// it, up to `mesh_size` (at most 8 `mesh_size` away). The angle is measured on a first
/// tetrahedralization (sum of the tetrahedra's dihedral angles at the curve's edges), which is then
/// redone with the graded size. Without it, the singular curve that such a wedge needs lies against
/// its faces and the integer-grid map folds (the 10-degree wedge: no hexahedron; graded: a valid mesh).
///
/// gmsh runs in a child process (where `fork()` exists): silent, from a clean state at every
/// call, and a crash of the library on a hostile file becomes an `Input_error`.
///
/// \param filename the CAD file
/// \param soup the output (overwritten)
/// \param np an optional sequence of named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{mesh_size}
///     \cgalParamDescription{target edge length of the tetrahedra, in the units of the part}
///     \cgalParamType{`double`}
///     \cgalParamDefault{bounding-box diagonal / 20}
///   \cgalParamNEnd
///   \cgalParamNBegin{acute_edge_grading}
///     \cgalParamDescription{grade the tetrahedra towards the acute CAD curves (below 45 degrees)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{time_limit}
///     \cgalParamDescription{seconds after which gmsh is stopped with an `Input_error`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0 (no limit)}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Input_error naming the file and the problem: unreadable file (gmsh's message), a part
///         without any solid (only surfaces or curves), solids that touch or overlap (an
///         assembly: each body must be one solid), a meshing failure, a non-positive
///         `mesh_size`, walls more than 8 times thinner than `mesh_size` over half of the surface
///         (gmsh would take minutes; the message names the thickness), the time limit reached.
template <class Point, class NamedParameters = CGAL::parameters::Default_named_parameters>
void read_CAD(const std::string& filename, Tetrahedral_soup_3<Point>& soup,
              const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double size = choose_parameter(get_parameter(np, internal_np::mesh_size), 0.);
  const bool grading = choose_parameter(get_parameter(np, internal_np::acute_edge_grading), true);
  if(!(size >= 0) || !std::isfinite(size))
    throw Input_error(filename, 0, "the mesh size must be a positive number");
  internal_gmsh::check_readable(filename);
  const std::string bytes = internal::run_isolated([&]() -> std::string {
    const double diagonal = internal_gmsh::open_cad_part(filename);
    const double h = size > 0 ? size : diagonal / 20;
    gmsh::option::setNumber("Mesh.MeshSizeMax", h);
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
    try {
      gmsh::model::mesh::generate(2);
    } catch(...) {
      throw Input_error(filename, 0, internal_gmsh::mesher_failure(filename, diagonal, h));
    }
    {
      // walls much thinner than the tetrahedra: the 3D mesher would run for minutes (a 20 x 20 x 0.02
      // plate at the default size: no result after 400 s, 2 GB) for slivers no map can use
      Tetrahedral_soup_3<Point> surface;
      internal_gmsh::extract(filename, surface);
      const internal::Wall_thickness w = internal_gmsh::surface_wall_thickness(surface);
      if(w.thickness < h / internal_gmsh::maximum_mesh_size_over_wall_thickness)
        throw Input_error(filename, 0, internal_gmsh::thin_wall_message(w, h));
    }
    try {
      gmsh::model::mesh::generate(3);
    } catch(...) {
      throw Input_error(filename, 0, internal_gmsh::mesher_failure(filename, diagonal, h));
    }
    Tetrahedral_soup_3<Point> result;
    internal_gmsh::extract(filename, result);
    if(result.tetrahedra.empty())
      throw Input_error(filename, 0, "gmsh produced no tetrahedra (" + internal_gmsh::last_error("no message") +
                        "); check that the part is a valid solid, or try another --mesh-size");
    const std::string flat = internal_gmsh::flat_tetrahedra_failure(result, diagonal);
    if(!flat.empty()) throw Input_error(filename, 0, flat);
    const std::map<int, double> acute = grading ? internal::acute_cad_curves(result, std::atan(1.0)) : std::map<int, double>();
    if(!acute.empty()) {
      gmsh::model::mesh::clear();
      internal::set_acute_curve_grading(acute, h);
      internal_gmsh::call(filename, "tetrahedralize the part graded towards its " + std::to_string(acute.size()) +
                          " acute edges (mesh size " + std::to_string(h) + ")",
                          [&] { gmsh::model::mesh::generate(3); });
      result = Tetrahedral_soup_3<Point>();
      internal_gmsh::extract(filename, result);
      if(result.tetrahedra.empty())
        throw Input_error(filename, 0, "gmsh produced no tetrahedra graded towards the acute edges (" +
                          internal_gmsh::last_error("no message") + "); try another --mesh-size");
    }
    return internal::serialize_soup(result);
  }, filename, "gmsh", choose_parameter(get_parameter(np, internal_np::time_limit), 0.));
  soup = Tetrahedral_soup_3<Point>();
  internal::deserialize_soup(bytes, soup);
  soup.source = filename;
}

/// \ingroup PkgHexahedralRemeshingRef
/// Measures of a CAD part, from a surface mesh only (quick: no tetrahedra).
struct CAD_part_measures
{
  /// Diagonal of the bounding box (model units).
  double diagonal = 0;
  /// Volume of the solid.
  double volume = 0;
  /// The wall thickness of most of the part: the area-weighted median, over the boundary triangles,
  /// of the distance along the inward normal to the other side (infinite if it could not be measured).
  double wall_thickness = 0;
  /// A point of the surface where the walls are about that thick.
  std::array<double, 3> wall_location{ {0, 0, 0} };
};

/// \ingroup PkgHexahedralRemeshingRef
/// Imports a CAD part as `read_CAD()` does and measures it on a surface mesh (size: the bounding-box
/// diagonal over 20), without tetrahedralizing it: so that a size can be chosen, and a part whose
/// walls are too thin for it refused, before the tetrahedralization (which, at a size much larger
/// than a wall's thickness, takes minutes).
/// `time_limit`: seconds after which gmsh is stopped (0: none).
/// \throws Input_error as `read_CAD()`.
inline CAD_part_measures measure_CAD_part(const std::string& filename, double time_limit = 0)
{
  internal_gmsh::check_readable(filename);
  const std::string bytes = internal::run_isolated([&]() -> std::string {
    const double diagonal = internal_gmsh::open_cad_part(filename);
    gmsh::option::setNumber("Mesh.MeshSizeMax", diagonal / 20);
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
    try {
      gmsh::model::mesh::generate(2);
    } catch(...) {
      throw Input_error(filename, 0, internal_gmsh::mesher_failure(filename, diagonal, diagonal / 20));
    }
    Tetrahedral_soup_3<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> surface;
    internal_gmsh::extract(filename, surface);
    const internal::Wall_thickness w = internal_gmsh::surface_wall_thickness(surface);
    internal::Byte_writer out;
    for(double x : {diagonal, w.volume, w.thickness, w.location[0], w.location[1], w.location[2]}) out.put(x);
    return std::move(out.bytes());
  }, filename, "gmsh", time_limit);
  internal::Byte_reader in(bytes);
  CAD_part_measures m;
  m.diagonal = in.get<double>();
  m.volume = std::abs(in.get<double>());
  m.wall_thickness = in.get<double>();
  for(double& x : m.wall_location) x = in.get<double>();
  return m;
}

template <class Point, class NamedParameters>
void read_gmsh(const std::string& filename, Tetrahedral_soup_3<Point>& soup, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  internal_gmsh::check_readable(filename);
  const std::string bytes = internal::run_isolated([&]() -> std::string {
    internal_gmsh::start();
    internal_gmsh::call(filename, "read the mesh file", [&] { gmsh::open(filename); });
    Tetrahedral_soup_3<Point> result;
    internal_gmsh::extract(filename, result);
    if(result.tetrahedra.empty() && result.triangles.empty())
      throw Input_error(filename, 0, "the file has no tetrahedra and no triangles (" +
                        internal_gmsh::last_error("no element") + "); mesh the volume (gmsh -3) and retry");
    return internal::serialize_soup(result);
  }, filename, "gmsh", choose_parameter(get_parameter(np, internal_np::time_limit), 0.));
  soup = Tetrahedral_soup_3<Point>();
  internal::deserialize_soup(bytes, soup);
  soup.source = filename;
  if(soup.tetrahedra.empty()) {
    // a surface mesh: tetrahedralized like the other surface formats
    std::vector<internal::Surface_kernel::Point_3> points;
    for(const Point& p : soup.points)
      points.push_back(internal::Surface_kernel::Point_3(CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2])));
    std::vector<std::vector<std::size_t> > polygons;
    for(const auto& t : soup.triangles) polygons.push_back({t[0], t[1], t[2]});
    internal::Checked_surface sm;
    internal::surface_from_polygon_soup(points, polygons, filename, sm);
    tetrahedralize_checked_surface(sm, soup, np);
  }
}

} // namespace IO
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_IO_READ_GMSH_H
