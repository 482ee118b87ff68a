// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_TETRAHEDRAL_MESH_3_H
#define CGAL_HEXAHEDRAL_REMESHING_TETRAHEDRAL_MESH_3_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_remeshing_traits_3.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

namespace internal { template <class Traits> class Tetrahedral_mesh_builder; }

/// \ingroup PkgHexahedralRemeshingRef
/// A read-only range of indices stored contiguously in a `Tetrahedral_mesh_3`.
template <class Index>
class Index_range
{
public:
  /// The range `[b, e)`.
  Index_range(const Index* b, const Index* e) : m_begin(b), m_end(e) {}
  /// Pointer to the first index.
  const Index* begin() const { return m_begin; }
  /// Pointer past the last index.
  const Index* end() const { return m_end; }
  /// Number of indices.
  std::size_t size() const { return std::size_t(m_end - m_begin); }
  /// True if the range holds no index.
  bool empty() const { return m_begin == m_end; }
  /// The `i`-th index. \pre `i < size()`
  Index operator[](std::size_t i) const { return m_begin[i]; }
  /// The first index. \pre `!empty()`
  Index front() const { return *m_begin; }
  /// The last index. \pre `!empty()`
  Index back() const { return *(m_end - 1); }
private:
  const Index* m_begin;
  const Index* m_end;
};

/// \ingroup PkgHexahedralRemeshingRef
/// Tetrahedral mesh with the complete, exact topology every stage of hexahedral remeshing needs.
///
/// Everything is stored in flat arrays indexed by 32-bit integers and built once, in O(n log n),
/// by `build_tetrahedral_mesh()` or one of the readers. The mesh is immutable afterwards.
///
/// Conventions:
/// - tetrahedra are positively oriented (`CGAL::orientation` of their four points is `POSITIVE`,
///   decided exactly);
/// - face `i` of a tetrahedron is the face opposite its local vertex `i`;
/// - boundary triangles are oriented outward (counter-clockwise seen from outside);
/// - the ring of an edge `(v0, v1)` lists its tetrahedra counter-clockwise about `p(v1) - p(v0)`
///   (right-hand rule). For an interior edge the ring is closed and starts at the tetrahedron of
///   smallest index. For a boundary edge it goes from the tetrahedron of its first boundary triangle
///   to the tetrahedron of its second one; then the first triangle contains the half-edge `v1 -> v0`
///   (this is the half-edge `e_ij` of the paper's dihedral angle formula, with `i` the first triangle).
///
/// \tparam Traits a model of `HexahedralRemeshingTraits_3`.
template <class Traits = Hexahedral_remeshing_traits_3<> >
class Tetrahedral_mesh_3
{
public:
  /// The traits class.
  typedef Traits Geom_traits;
  /// Point type.
  typedef typename Traits::Point_3 Point_3;
  /// Vector type.
  typedef typename Traits::Vector_3 Vector_3;
  /// Index of every element (vertex, tetrahedron, face, edge, boundary triangle).
  typedef std::uint32_t Index;
  /// The index meaning "no element" (the missing second tetrahedron of a boundary face, ...).
  static constexpr Index null_index = (std::numeric_limits<Index>::max)();

  Tetrahedral_mesh_3() = default;

  /// \name Vertices
  /// @{

  /// Number of vertices (input vertices first, then the ones added by preprocessing).
  std::size_t number_of_vertices() const { return m_points.size(); }
  /// Number of vertices of the input; vertex `v < number_of_input_vertices()` is input vertex `v`.
  std::size_t number_of_input_vertices() const { return m_number_of_input_vertices; }
  /// Position of vertex `v`.
  const Point_3& point(Index v) const { return m_points[v]; }
  /// All positions.
  const std::vector<Point_3>& points() const { return m_points; }
  /// True if `v` lies on the boundary.
  bool is_boundary_vertex(Index v) const { return m_vertex_on_boundary[v] != 0; }
  /// Edges incident to `v`, sorted by the index of their other endpoint.
  Index_range<Index> vertex_edges(Index v) const { return range(m_vertex_edge_offsets, m_vertex_edges, v); }
  /// Moves the interior vertex `v` to `p`: the boundary, the connectivity and every index stay as they
  /// are. The caller keeps every tetrahedron of `v` positively oriented (the operations that move
  /// vertices decide it with exact orientations).
  /// \throws std::invalid_argument if `v` is out of range or a boundary vertex.
  void move_interior_vertex(Index v, const Point_3& p)
  {
    if(v >= m_points.size() || is_boundary_vertex(v))
      throw std::invalid_argument("Tetrahedral_mesh_3::move_interior_vertex: vertex " + std::to_string(v) +
                                  " is not an interior vertex");
    m_points[v] = p;
  }
  /// @}

  /// \name Tetrahedra
  /// @{

  /// Number of tetrahedra.
  std::size_t number_of_tetrahedra() const { return m_tets.size(); }
  /// The four vertices of `t`, positively oriented.
  const std::array<Index, 4>& tetrahedron_vertices(Index t) const { return m_tets[t]; }
  /// The face of `t` opposite its local vertex `i`.
  Index tetrahedron_face(Index t, int i) const { return m_tet_faces[t][i]; }
  /// The tetrahedron sharing the face of `t` opposite local vertex `i`, or `null_index` on the boundary.
  Index tetrahedron_neighbor(Index t, int i) const
  {
    const std::array<Index, 2>& ft = m_face_tets[m_tet_faces[t][i]];
    return ft[0] == t ? ft[1] : ft[0];
  }
  /// Index of the input tetrahedron that `t` comes from (differs from `t` after preprocessing).
  Index tetrahedron_input_index(Index t) const { return m_tet_input_index[t]; }
  /// Connected component of `t` (components are connected through faces).
  Index tetrahedron_component(Index t) const { return m_tet_component[t]; }
  /// Number of connected components.
  std::size_t number_of_components() const { return m_number_of_components; }
  /// Number of tetrahedra split by preprocessing (each into four).
  std::size_t number_of_split_tetrahedra() const { return m_number_of_split_tetrahedra; }
  /// Number of interior edges joining two boundary vertices split by preprocessing.
  std::size_t number_of_split_chords() const { return m_number_of_split_chords; }
  /// Number of input tetrahedra that were inverted and have been re-oriented.
  std::size_t number_of_reoriented_tetrahedra() const { return m_number_of_reoriented_tetrahedra; }
  /// @}

  /// \name Faces
  /// @{

  /// Number of faces (triangles of the tetrahedra, each counted once).
  std::size_t number_of_faces() const { return m_face_vertices.size(); }
  /// Vertices of `f`, oriented outward from `face_tetrahedra(f)[0]` (hence outward from the mesh on the boundary).
  const std::array<Index, 3>& face_vertices(Index f) const { return m_face_vertices[f]; }
  /// The one or two tetrahedra of `f`; the second is `null_index` on the boundary.
  const std::array<Index, 2>& face_tetrahedra(Index f) const { return m_face_tets[f]; }
  /// True if `f` has a single tetrahedron.
  bool is_boundary_face(Index f) const { return m_face_tets[f][1] == null_index; }
  /// The boundary triangle of `f`, or `null_index` for an interior face.
  Index face_boundary_triangle(Index f) const { return m_face_boundary_triangle[f]; }
  /// @}

  /// \name Boundary triangles
  /// Boundary triangles are the boundary faces, numbered `0 .. number_of_boundary_triangles()-1`.
  /// @{

  /// Number of boundary triangles.
  std::size_t number_of_boundary_triangles() const { return m_bt_face.size(); }
  /// The face of boundary triangle `b`.
  Index boundary_triangle_face(Index b) const { return m_bt_face[b]; }
  /// Vertices of `b`, counter-clockwise seen from outside.
  const std::array<Index, 3>& boundary_triangle_vertices(Index b) const { return m_face_vertices[m_bt_face[b]]; }
  /// The tetrahedron of `b`.
  Index boundary_triangle_tetrahedron(Index b) const { return m_face_tets[m_bt_face[b]][0]; }
  /// Edge of `b` opposite its local vertex `i`.
  Index boundary_triangle_edge(Index b, int i) const { return m_bt_edges[b][i]; }
  /// Boundary triangle across the edge of `b` opposite its local vertex `i`.
  Index boundary_triangle_neighbor(Index b, int i) const
  {
    const std::array<Index, 2>& tt = m_edge_bt[m_bt_edges[b][i]];
    return tt[0] == b ? tt[1] : tt[0];
  }
  /// Surface patch of `b` given by the input (C3t3 patch, gmsh entity), or -1.
  int boundary_triangle_patch(Index b) const { return m_bt_patch[b]; }
  /// Outward normal of `b` (not normalized: its length is twice the area).
  Vector_3 boundary_triangle_normal(Index b) const
  {
    const std::array<Index, 3>& v = boundary_triangle_vertices(b);
    return CGAL::cross_product(m_points[v[1]] - m_points[v[0]], m_points[v[2]] - m_points[v[0]]);
  }
  /// Connected component of the boundary surface that `b` belongs to.
  Index boundary_triangle_component(Index b) const { return m_bt_component[b]; }
  /// Number of connected components of the boundary surface.
  std::size_t number_of_boundary_components() const { return m_number_of_boundary_components; }
  /// @}

  /// \name Edges
  /// @{

  /// Number of edges.
  std::size_t number_of_edges() const { return m_edge_vertices.size(); }
  /// Endpoints `(v0, v1)` of `e`; the ring of `e` turns counter-clockwise about `p(v1) - p(v0)`.
  const std::array<Index, 2>& edge_vertices(Index e) const { return m_edge_vertices[e]; }
  /// True if `e` lies on the boundary.
  bool is_boundary_edge(Index e) const { return m_edge_bt[e][0] != null_index; }
  /// The tetrahedra around `e`, counter-clockwise (see the class documentation).
  Index_range<Index> edge_ring(Index e) const { return range(m_ring_offsets, m_ring_tets, e); }
  /// The faces around `e` in ring order: face `k` separates ring tetrahedra `k` and `k+1`
  /// (cyclically for an interior edge, `m` faces); for a boundary edge there are `m+1` faces,
  /// the first and last being the boundary faces of the first and second boundary triangle.
  Index_range<Index> edge_ring_faces(Index e) const { return range(m_ring_face_offsets, m_ring_faces, e); }
  /// The two boundary triangles of a boundary edge, in ring order (`null_index` for an interior edge).
  const std::array<Index, 2>& edge_boundary_triangles(Index e) const { return m_edge_bt[e]; }
  /// Feature curve of `e` given by the input, or -1.
  int edge_curve(Index e) const { return m_edge_curve[e]; }
  /// The edge joining `a` and `b`, or `null_index`.
  Index find_edge(Index a, Index b) const
  {
    if(a >= m_points.size() || b >= m_points.size()) return null_index;
    for(Index e : vertex_edges(a)) {
      const std::array<Index, 2>& ev = m_edge_vertices[e];
      if(ev[0] == b || ev[1] == b) return e;
    }
    return null_index;
  }
  /// Indices of the boundary edges, increasing.
  const std::vector<Index>& boundary_edges() const { return m_boundary_edges; }
  /// @}

  /// \name Features given by the input
  /// @{

  /// Corner vertices (C3t3 corners, gmsh point cells).
  const std::vector<Index>& corners() const { return m_corners; }
  /// Number of distinct feature curve ids.
  std::size_t number_of_feature_curves() const { return m_number_of_curves; }
  /// Number of distinct surface patch ids.
  std::size_t number_of_surface_patches() const { return m_number_of_patches; }
  /// Names of surface patches given by the input (gmsh physical group or entity names), as
  /// (patch id, name) pairs sorted by patch; empty if the input names none.
  const std::vector<std::pair<int, std::string> >& surface_patch_names() const { return m_patch_names; }
  /// Number of edges tagged with a feature curve.
  std::size_t number_of_feature_edges() const { return m_number_of_feature_edges; }
  /// @}

  /// Name of the source (file) the mesh was built from, used in error messages.
  const std::string& source() const { return m_source; }

  /// Euler characteristic V - E + F of the boundary surface.
  long boundary_euler_characteristic() const
  {
    std::size_t nv = 0;
    for(char c : m_vertex_on_boundary) nv += (c != 0);
    return long(nv) - long(m_boundary_edges.size()) + long(m_bt_face.size());
  }

private:
  friend class internal::Tetrahedral_mesh_builder<Traits>;

  static Index_range<Index> range(const std::vector<Index>& offsets, const std::vector<Index>& values, Index i)
  {
    return Index_range<Index>(values.data() + offsets[i], values.data() + offsets[i + 1]);
  }

  std::vector<Point_3> m_points;
  std::size_t m_number_of_input_vertices = 0;
  std::vector<char> m_vertex_on_boundary;
  std::vector<Index> m_vertex_edge_offsets, m_vertex_edges;

  std::vector<std::array<Index, 4> > m_tets;
  std::vector<std::array<Index, 4> > m_tet_faces;
  std::vector<Index> m_tet_input_index, m_tet_component;
  std::size_t m_number_of_components = 0;
  std::size_t m_number_of_split_tetrahedra = 0;
  std::size_t m_number_of_reoriented_tetrahedra = 0;
  std::size_t m_number_of_split_chords = 0;

  std::vector<std::array<Index, 3> > m_face_vertices;
  std::vector<std::array<Index, 2> > m_face_tets;
  std::vector<Index> m_face_boundary_triangle;

  std::vector<Index> m_bt_face;
  std::vector<std::array<Index, 3> > m_bt_edges;
  std::vector<int> m_bt_patch;
  std::vector<Index> m_bt_component;
  std::size_t m_number_of_boundary_components = 0;

  std::vector<std::array<Index, 2> > m_edge_vertices;
  std::vector<std::array<Index, 2> > m_edge_bt;
  std::vector<int> m_edge_curve;
  std::vector<Index> m_ring_offsets, m_ring_tets, m_ring_face_offsets, m_ring_faces;
  std::vector<Index> m_boundary_edges;

  std::vector<Index> m_corners;
  std::size_t m_number_of_curves = 0, m_number_of_patches = 0, m_number_of_feature_edges = 0;
  std::string m_source;
  std::vector<std::pair<int, std::string> > m_patch_names;
};

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_TETRAHEDRAL_MESH_3_H
