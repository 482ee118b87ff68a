// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_VTK_FRAME_FIELD_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_VTK_FRAME_FIELD_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/local_meshability.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK_polylines.h>

#include <Eigen/Dense>

#include <array>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace IO {

/// \ingroup PkgHexahedralRemeshingRef
/// Writes a frame field as the tetrahedral mesh (see `write_VTK()`: vertex `v` of the file is vertex
/// `v` of `mesh`, so the input vertices come first, in input order) with the cell data
/// `VECTORS frame_u double`, `frame_v`, `frame_w`: the three axes of the frame of each tetrahedron
/// (the columns of `frames[t]`), normalized and right-handed (`frame_w` is negated in the
/// improbable case of a reflection: a frame is only defined up to the symmetries of the cube).
/// In ParaView, apply a Glyph filter to each array to see the crosses.
/// \param filename the output file (written atomically)
/// \param mesh the mesh
/// \param frames one frame per tetrahedron, as computed by `compute_frame_field()`
/// \param cell_arrays further per-tetrahedron arrays, written after the frames
/// \throws Error if the file cannot be written or `frames` does not have one entry per tetrahedron.
template <class Traits>
void write_VTK_frame_field(const std::string& filename, const Tetrahedral_mesh_3<Traits>& mesh,
                           const std::vector<Eigen::Matrix3d>& frames, std::vector<VTK_array> cell_arrays = {})
{
  if(frames.size() != mesh.number_of_tetrahedra())
    throw Error(filename + ": " + std::to_string(frames.size()) + " frames for " +
                std::to_string(mesh.number_of_tetrahedra()) + " tetrahedra");
  std::vector<VTK_array> axes(3);
  const char* names[3] = {"frame_u", "frame_v", "frame_w"};
  for(int c = 0; c < 3; ++c) {
    axes[std::size_t(c)].name = names[c];
    axes[std::size_t(c)].components = 3;
    axes[std::size_t(c)].values.reserve(3 * frames.size());
  }
  for(const Eigen::Matrix3d& E : frames) {
    Eigen::Matrix3d U;
    for(int c = 0; c < 3; ++c) {
      const double n = E.col(c).norm();
      U.col(c) = n > 0 ? Eigen::Vector3d(E.col(c) / n) : Eigen::Vector3d::Zero();
    }
    if(U.determinant() < 0) U.col(2) = -U.col(2);
    for(int c = 0; c < 3; ++c)
      for(int i = 0; i < 3; ++i) axes[std::size_t(c)].values.push_back(U(i, c));
  }
  cell_arrays.insert(cell_arrays.begin(), axes.begin(), axes.end());
  write_VTK(filename, mesh, cell_arrays);
}

namespace internal_singularity_writer {

// The mesh vertices a polyline file uses, each once, in order of first use: their positions and
// their index in the mesh (the point array `vertex`).
template <class Mesh>
struct Polyline_points
{
  Polyline_points(const Mesh& m, const std::string& file) : mesh(m), filename(file), local(m.number_of_vertices(), std::size_t(-1)) {}

  // The file's point of mesh vertex v.
  std::size_t add(std::uint32_t v)
  {
    if(v >= mesh.number_of_vertices()) throw Error(filename + ": vertex " + std::to_string(v) + " is not a vertex of the mesh");
    if(local[v] == std::size_t(-1)) {
      local[v] = points.size();
      const auto& p = mesh.point(typename Mesh::Index(v));
      points.push_back({{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}});
      vertex.values.push_back(double(v));
    }
    return local[v];
  }

  const Mesh& mesh;
  const std::string& filename;
  std::vector<std::size_t> local;
  std::vector<std::array<double, 3> > points;
  VTK_array vertex;
};

} // namespace internal_singularity_writer

/// \ingroup PkgHexahedralRemeshingRef
/// Writes the singular curves of a frame field as VTK polylines (see `write_VTK_polylines()`), one
/// polyline per curve of `graph.curves`, through the vertices of the curve. The points of the file
/// are the mesh vertices lying on a curve, each once, in order of first appearance; the point array
/// `vertex` gives their index in `mesh`. Cell arrays: `valence` (3 or 5, 0 for a chain of improper
/// edges), `edges` (number of edges of the curve) and `closed` (1 for a loop).
/// \param filename the output file (written atomically)
/// \param mesh the mesh the graph was computed on
/// \param graph the singularity graph, as computed by `compute_singularity_graph()`
/// \throws Error if the file cannot be written or a curve vertex is not a vertex of `mesh`.
template <class Traits>
void write_VTK_singularity_graph(const std::string& filename, const Tetrahedral_mesh_3<Traits>& mesh,
                                 const Singularity_graph& graph)
{
  internal_singularity_writer::Polyline_points<Tetrahedral_mesh_3<Traits> > points(mesh, filename);
  points.vertex.name = "vertex";
  std::vector<std::vector<std::size_t> > lines;
  std::vector<VTK_array> cell_arrays(3);
  cell_arrays[0].name = "valence";
  cell_arrays[1].name = "edges";
  cell_arrays[2].name = "closed";
  for(const Singular_curve& c : graph.curves) {
    std::vector<std::size_t> line;
    for(std::uint32_t v : c.vertices) line.push_back(points.add(v));
    if(line.size() < 2) continue; // a curve always has an edge; be safe
    lines.push_back(line);
    cell_arrays[0].values.push_back(double(c.valence));
    cell_arrays[1].values.push_back(double(c.edges.size()));
    cell_arrays[2].values.push_back(c.closed ? 1. : 0.);
  }
  write_VTK_polylines(filename, points.points, lines, cell_arrays, {points.vertex});
}

/// \ingroup PkgHexahedralRemeshingRef
/// Writes the singular edges of a frame field with the verdict of the local meshability check, one
/// VTK line cell per singular edge (every edge of `graph.curves`), so that the reason can be read
/// per edge. Points: the vertices of those edges and the vertices where the check fails, point
/// arrays `vertex` (index in `mesh`) and `reason` (the `Meshability_reason` of a failing vertex:
/// 2 dangling end, 3 zipper, 4 invalid node, 5 boundary contact, 8 end in a boundary plane, 9 the bend of
/// a zigzag face; -1 none).
/// Cell arrays: `valence` (3, 5, 0 improper), `curve` (index in `graph.curves`), `reason` (0 improper
/// edge, 1 jog, -1 none).
/// \param filename the output file (written atomically)
/// \param mesh the mesh the graph was computed on
/// \param graph the singularity graph
/// \param check the local check of the same field (`check_local_meshability()`)
/// \throws Error if the file cannot be written or the graph or the check belong to another mesh.
template <class Traits>
void write_VTK_singularity_graph(const std::string& filename, const Tetrahedral_mesh_3<Traits>& mesh,
                                 const Singularity_graph& graph, const Local_meshability_report& check)
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  if(check.edge_class.size() != mesh.number_of_edges())
    throw Error(filename + ": the meshability check is not of this mesh");
  std::vector<int> vertex_reason(mesh.number_of_vertices(), -1);
  std::vector<int> edge_reason(mesh.number_of_edges(), -1);
  for(const Meshability_violation& v : check.violations) {
    if(v.reason == Meshability_reason::IMPROPER_EDGE || v.reason == Meshability_reason::JOG) edge_reason[v.index] = int(v.reason);
    else if(v.reason != Meshability_reason::FEATURE_SECTOR && v.reason != Meshability_reason::DISAGREEING_FACE)
      vertex_reason[v.index] = int(v.reason);
  }
  internal_singularity_writer::Polyline_points<Tetrahedral_mesh_3<Traits> > points(mesh, filename);
  points.vertex.name = "vertex";
  std::vector<std::vector<std::size_t> > lines;
  std::vector<VTK_array> cell_arrays(3);
  cell_arrays[0].name = "valence";
  cell_arrays[1].name = "curve";
  cell_arrays[2].name = "reason";
  for(std::size_t c = 0; c < graph.curves.size(); ++c)
    for(std::uint32_t e : graph.curves[c].edges) {
      if(e >= mesh.number_of_edges()) throw Error(filename + ": curve edge " + std::to_string(e) + " is not an edge of the mesh");
      const auto& ev = mesh.edge_vertices(Index(e));
      lines.push_back({points.add(std::uint32_t(ev[0])), points.add(std::uint32_t(ev[1]))});
      cell_arrays[0].values.push_back(double(graph.curves[c].valence));
      cell_arrays[1].values.push_back(double(c));
      cell_arrays[2].values.push_back(double(edge_reason[e]));
    }
  for(Index v = 0; v < mesh.number_of_vertices(); ++v)
    if(vertex_reason[v] >= 0) points.add(std::uint32_t(v));
  VTK_array reason;
  reason.name = "reason";
  for(double v : points.vertex.values) reason.values.push_back(double(vertex_reason[std::size_t(v)]));
  write_VTK_polylines(filename, points.points, lines, cell_arrays, {points.vertex, reason});
}

} // namespace IO
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_VTK_FRAME_FIELD_H
