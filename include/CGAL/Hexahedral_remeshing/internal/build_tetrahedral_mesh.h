// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_BUILD_TETRAHEDRAL_MESH_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_BUILD_TETRAHEDRAL_MESH_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/Tetrahedral_soup_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/internal/union_find.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Outward faces of a positively oriented tetrahedron (0,1,2,3): face i is opposite vertex i and its
// normal points away from vertex i (orientation(face, i) is NEGATIVE for each of these orderings).
constexpr int tet_face_local[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
// Local edges of a tetrahedron and, for each, the other two local vertices (k, l) such that the
// permutation (i, j, k, l) is even: then orientation(v_i, v_j, v_k, v_l) is POSITIVE, i.e. turning
// counter-clockwise about v_j - v_i leads from v_k to v_l.
constexpr int tet_edge_local[6][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2},
                                      {1, 2, 0, 3}, {1, 3, 2, 0}, {2, 3, 0, 1}};

inline std::string describe_tet(std::size_t t) { return "tetrahedron " + std::to_string(t); }

template <class Traits>
class Tetrahedral_mesh_builder
{
public:
  typedef Tetrahedral_mesh_3<Traits> Mesh;
  typedef typename Mesh::Index Index;
  typedef typename Traits::Point_3 Point_3;
  static constexpr Index null_index = Mesh::null_index;

  Tetrahedral_mesh_builder(const Traits& traits) : m_traits(traits) {}

  // What to do with distinct vertices at the same position, both used by tetrahedra.
  enum Coincident_policy { REFUSE_COINCIDENT = 0, MERGE_COINCIDENT = 1, KEEP_COINCIDENT = 2 };

  void build(const Tetrahedral_soup_3<Point_3>& soup, Mesh& mesh, bool split_multi_boundary_tetrahedra,
             bool split_boundary_chords = false, int coincident_policy = REFUSE_COINCIDENT)
  {
    m_coincident_policy = coincident_policy;
    m_remap.clear();
    m_merged_vertices = 0;
    m_source = soup.source.empty() ? std::string("<memory>") : soup.source;
    mesh = Mesh();
    mesh.m_source = m_source;
    check_and_copy(soup, mesh);
    build_faces(mesh, soup.tetrahedron_lines);
    if(split_boundary_chords && split_chords(mesh)) {
      m_original_tet = mesh.m_tet_input_index;
      build_faces(mesh, soup.tetrahedron_lines);
    }
    if(split_multi_boundary_tetrahedra && split(mesh, soup.tetrahedron_lines)) {
      build_faces(mesh, soup.tetrahedron_lines);
    }
    build_boundary_triangles(mesh);
    build_edges_and_rings(mesh);
    build_vertex_edges(mesh);
    link_boundary_triangles_to_edges(mesh);
    check_boundary_vertices_manifold(mesh);
    build_components(mesh);
    apply_hints(soup, mesh);
  }

  // Number of vertices merged into another one (MERGE_COINCIDENT).
  std::size_t merged_vertices() const { return m_merged_vertices; }

private:
  // Vertices used by tetrahedra at exactly the same position as another used vertex: the mesh is
  // cracked there (two sides of an interface meshed with separate nodes, as multi-threaded gmsh
  // sometimes writes), which the builder would take for two bodies touching, with spurious
  // boundary and feature edges along the crack.
  void find_coincident_vertices(const Tetrahedral_soup_3<Point_3>& soup)
  {
    if(m_coincident_policy == KEEP_COINCIDENT) return;
    const std::size_t nv = soup.points.size();
    std::vector<char> used(nv, 0);
    for(const auto& t : soup.tetrahedra)
      for(std::size_t v : t) if(v < nv) used[v] = 1;
    std::vector<Index> order;
    for(std::size_t v = 0; v < nv; ++v) if(used[v]) order.push_back(Index(v));
    auto key = [&](Index v) {
      const Point_3& p = soup.points[v];
      return std::array<double, 3>{CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2])};
    };
    std::sort(order.begin(), order.end(), [&](Index a, Index b) {
      const auto ka = key(a), kb = key(b);
      return ka < kb || (ka == kb && a < b);
    });
    std::size_t count = 0;
    Index first_a = 0, first_b = 0;
    std::vector<Index> remap;
    for(std::size_t i = 1; i < order.size(); ++i) {
      if(key(order[i]) != key(order[i - 1])) continue;
      if(count++ == 0) { first_a = order[i - 1]; first_b = order[i]; }
      if(m_coincident_policy == MERGE_COINCIDENT) {
        if(remap.empty()) {
          remap.resize(nv);
          for(std::size_t v = 0; v < nv; ++v) remap[v] = Index(v);
        }
        remap[order[i]] = remap[order[i - 1]]; // the smallest index of the group
      }
    }
    if(count == 0) return;
    if(m_coincident_policy == MERGE_COINCIDENT) {
      m_remap.swap(remap);
      m_merged_vertices = count;
      return;
    }
    const Point_3& p = soup.points[first_a];
    fail(0, std::to_string(count) + " vertices of the tetrahedra coincide with other vertices (first: vertices " +
         std::to_string(first_a) + " and " + std::to_string(first_b) + " at (" + std::to_string(CGAL::to_double(p[0])) +
         ", " + std::to_string(CGAL::to_double(p[1])) + ", " + std::to_string(CGAL::to_double(p[2])) +
         ")): the mesh is cracked along an interface (duplicated nodes). Merge them (hexmesh option "
         "--coincident-vertices merge, named parameter coincident_vertices(Coincident_vertices::MERGE)), or keep "
         "separate bodies that touch (--coincident-vertices keep)");
  }

  [[noreturn]] void fail(std::size_t line, const std::string& problem) const
  {
    throw Input_error(m_source, line, problem);
  }

  static std::size_t line_of(std::size_t t, const std::vector<std::size_t>& lines)
  {
    return t < lines.size() ? lines[t] : 0;
  }

  void check_and_copy(const Tetrahedral_soup_3<Point_3>& soup, Mesh& mesh)
  {
    if(soup.tetrahedra.empty()) fail(0, "the mesh has no tetrahedra");
    if(soup.points.size() >= std::size_t(null_index)) fail(0, "too many vertices");
    if(soup.tetrahedra.size() >= std::size_t(null_index) / 4) fail(0, "too many tetrahedra");
    for(std::size_t v = 0; v < soup.points.size(); ++v) {
      const Point_3& p = soup.points[v];
      for(int c = 0; c < 3; ++c)
        if(!std::isfinite(CGAL::to_double(p[c])))
          fail(0, "vertex " + std::to_string(v) + ": coordinate is not a finite number");
    }
    mesh.m_points = soup.points;
    mesh.m_number_of_input_vertices = soup.points.size();
    find_coincident_vertices(soup);

    typename Traits::Orientation_3 orientation = m_traits.orientation_3_object();
    const std::size_t nv = soup.points.size();
    mesh.m_tets.resize(soup.tetrahedra.size());
    mesh.m_tet_input_index.resize(soup.tetrahedra.size());
    for(std::size_t t = 0; t < soup.tetrahedra.size(); ++t) {
      const std::array<std::size_t, 4>& in = soup.tetrahedra[t];
      std::array<Index, 4> tv;
      for(int i = 0; i < 4; ++i) {
        if(in[i] >= nv)
          fail(line_of(t, soup.tetrahedron_lines), describe_tet(t) + ": vertex index " + std::to_string(in[i]) +
               " out of range (the mesh has " + std::to_string(nv) + " vertices)");
        tv[i] = m_remap.empty() ? Index(in[i]) : m_remap[in[i]];
      }
      const CGAL::Orientation o = orientation(mesh.m_points[tv[0]], mesh.m_points[tv[1]],
                                              mesh.m_points[tv[2]], mesh.m_points[tv[3]]);
      if(o == CGAL::COPLANAR)
        fail(line_of(t, soup.tetrahedron_lines), describe_tet(t) + ": degenerate (zero volume)");
      if(o == CGAL::NEGATIVE) {
        std::swap(tv[2], tv[3]);
        ++mesh.m_number_of_reoriented_tetrahedra;
      }
      mesh.m_tets[t] = tv;
      mesh.m_tet_input_index[t] = Index(t);
    }
    // Duplicated tetrahedra (same four vertices).
    std::vector<std::pair<std::array<Index, 4>, Index> > keys(mesh.m_tets.size());
    for(std::size_t t = 0; t < mesh.m_tets.size(); ++t) {
      keys[t].first = mesh.m_tets[t];
      std::sort(keys[t].first.begin(), keys[t].first.end());
      keys[t].second = Index(t);
    }
    std::sort(keys.begin(), keys.end());
    for(std::size_t k = 1; k < keys.size(); ++k)
      if(keys[k].first == keys[k - 1].first)
        fail(line_of(keys[k].second, soup.tetrahedron_lines),
             describe_tet(keys[k].second) + ": duplicate of tetrahedron " + std::to_string(keys[k - 1].second));
  }

  struct Face_record
  {
    std::array<Index, 3> key;
    Index tet;
    int local;
    bool operator<(const Face_record& o) const
    {
      return key < o.key || (key == o.key && tet < o.tet);
    }
  };

  // Parity of the permutation mapping a to b (both hold the same three values).
  static bool same_cyclic_order(const std::array<Index, 3>& a, const std::array<Index, 3>& b)
  {
    for(int r = 0; r < 3; ++r)
      if(a[0] == b[r] && a[1] == b[(r + 1) % 3] && a[2] == b[(r + 2) % 3]) return true;
    return false;
  }

  void build_faces(Mesh& mesh, const std::vector<std::size_t>& lines)
  {
    const std::size_t nt = mesh.m_tets.size();
    std::vector<Face_record> records(4 * nt);
    for(std::size_t t = 0; t < nt; ++t)
      for(int i = 0; i < 4; ++i) {
        Face_record& r = records[4 * t + i];
        for(int k = 0; k < 3; ++k) r.key[k] = mesh.m_tets[t][tet_face_local[i][k]];
        std::sort(r.key.begin(), r.key.end());
        r.tet = Index(t);
        r.local = i;
      }
    std::sort(records.begin(), records.end());
    mesh.m_face_vertices.clear();
    mesh.m_face_tets.clear();
    mesh.m_tet_faces.assign(nt, {null_index, null_index, null_index, null_index});
    m_face_keys.clear();
    for(std::size_t b = 0; b < records.size();) {
      std::size_t e = b + 1;
      while(e < records.size() && records[e].key == records[b].key) ++e;
      const Index f = Index(mesh.m_face_vertices.size());
      const Face_record& r0 = records[b];
      if(e - b > 2) {
        const Index t = m_original_tet.empty() ? records[b + 2].tet : m_original_tet[records[b + 2].tet];
        fail(line_of(t, lines), "face (" + std::to_string(r0.key[0]) + ", " + std::to_string(r0.key[1]) + ", " +
             std::to_string(r0.key[2]) + ") is shared by " + std::to_string(e - b) + " tetrahedra");
      }
      std::array<Index, 3> fv;
      for(int k = 0; k < 3; ++k) fv[k] = mesh.m_tets[r0.tet][tet_face_local[r0.local][k]];
      if(e - b == 2) {
        const Face_record& r1 = records[b + 1];
        std::array<Index, 3> fv1;
        for(int k = 0; k < 3; ++k) fv1[k] = mesh.m_tets[r1.tet][tet_face_local[r1.local][k]];
        // Two positively oriented tetrahedra on opposite sides see the face with opposite orientations.
        if(same_cyclic_order(fv, fv1)) {
          const Index t = m_original_tet.empty() ? r1.tet : m_original_tet[r1.tet];
          fail(line_of(t, lines), describe_tet(t) + " overlaps a neighbour: both lie on the same side of face (" +
               std::to_string(r0.key[0]) + ", " + std::to_string(r0.key[1]) + ", " + std::to_string(r0.key[2]) + ")");
        }
        mesh.m_face_tets.push_back({r0.tet, r1.tet});
        mesh.m_tet_faces[r1.tet][r1.local] = f;
      } else {
        mesh.m_face_tets.push_back({r0.tet, null_index});
      }
      mesh.m_tet_faces[r0.tet][r0.local] = f;
      mesh.m_face_vertices.push_back(fv);
      m_face_keys.push_back(r0.key);
      b = e;
    }
  }

  // Barycentre of four points, computed as a/4 + b/4 + c/4 + d/4 so that it cannot overflow for
  // coordinates near the largest double (the scaling by 1/4 is exact for normal numbers, so the
  // result is the same as (a + b + c + d) / 4 whenever that one does not overflow).
  static Point_3 barycentre(const Point_3& a, const Point_3& b, const Point_3& c, const Point_3& d)
  {
    double xyz[3];
    for(int i = 0; i < 3; ++i)
      xyz[i] = CGAL::to_double(a[i]) * 0.25 + CGAL::to_double(b[i]) * 0.25 + CGAL::to_double(c[i]) * 0.25 +
               CGAL::to_double(d[i]) * 0.25;
    return Point_3(xyz[0], xyz[1], xyz[2]);
  }

  // 1-to-4 barycentric split of every tetrahedron with two or more boundary faces, so that each
  // tetrahedron carries at most one boundary alignment constraint. One pass suffices: each of the
  // four children keeps exactly one face of its parent.
  bool split(Mesh& mesh, const std::vector<std::size_t>& lines)
  {
    std::vector<std::array<Index, 4> > tets;
    std::vector<Index> input_index;
    tets.reserve(mesh.m_tets.size());
    typename Traits::Orientation_3 orientation = m_traits.orientation_3_object();
    std::size_t count = 0;
    for(std::size_t t = 0; t < mesh.m_tets.size(); ++t) {
      int nb = 0;
      for(int i = 0; i < 4; ++i) nb += mesh.m_face_tets[mesh.m_tet_faces[t][i]][1] == null_index;
      if(nb < 2) {
        tets.push_back(mesh.m_tets[t]);
        input_index.push_back(mesh.m_tet_input_index[t]);
        continue;
      }
      ++count;
      const std::array<Index, 4>& tv = mesh.m_tets[t];
      const Point_3 g = barycentre(mesh.m_points[tv[0]], mesh.m_points[tv[1]],
                                   mesh.m_points[tv[2]], mesh.m_points[tv[3]]);
      const Index gi = Index(mesh.m_points.size());
      mesh.m_points.push_back(g);
      for(int i = 0; i < 4; ++i) {
        std::array<Index, 4> child = tv;
        child[i] = gi;
        if(orientation(mesh.m_points[child[0]], mesh.m_points[child[1]], mesh.m_points[child[2]],
                       mesh.m_points[child[3]]) != CGAL::POSITIVE)
          fail(line_of(mesh.m_tet_input_index[t], lines), describe_tet(mesh.m_tet_input_index[t]) +
               ": too flat to be split at its barycentre (a child tetrahedron is degenerate)");
        tets.push_back(child);
        input_index.push_back(mesh.m_tet_input_index[t]);
      }
    }
    if(count == 0) return false;
    mesh.m_tets.swap(tets);
    mesh.m_tet_input_index.swap(input_index);
    mesh.m_number_of_split_tetrahedra = count;
    m_original_tet = mesh.m_tet_input_index;
    return true;
  }

  // Splits at its midpoint every interior edge whose two endpoints lie on the boundary (a "chord").
  // Such an edge joins two boundary constraints with nothing in between, so the frames of its ring
  // must turn abruptly (typically across a thin wedge at an acute feature, or where a curved
  // surface faces itself): splitting it gives the field room to turn smoothly.
  bool split_chords(Mesh& mesh)
  {
    std::vector<char> on_boundary(mesh.m_points.size(), 0);
    std::set<std::array<Index, 2> > boundary_edges;
    for(std::size_t f = 0; f < mesh.m_face_tets.size(); ++f)
      if(mesh.m_face_tets[f][1] == null_index) {
        const auto& v = mesh.m_face_vertices[f];
        for(int i = 0; i < 3; ++i) {
          on_boundary[v[i]] = 1;
          boundary_edges.insert({(std::min)(v[i], v[(i + 1) % 3]), (std::max)(v[i], v[(i + 1) % 3])});
        }
      }
    std::set<std::array<Index, 2> > chords;
    for(const auto& t : mesh.m_tets)
      for(int k = 0; k < 6; ++k) {
        const Index a = t[tet_edge_local[k][0]], b = t[tet_edge_local[k][1]];
        const std::array<Index, 2> key{(std::min)(a, b), (std::max)(a, b)};
        if(on_boundary[a] && on_boundary[b] && !boundary_edges.count(key)) chords.insert(key);
      }
    if(chords.empty()) return false;
    std::vector<std::vector<Index> > vertex_tets(mesh.m_points.size());
    for(std::size_t t = 0; t < mesh.m_tets.size(); ++t)
      for(Index v : mesh.m_tets[t]) vertex_tets[v].push_back(Index(t));
    typename Traits::Orientation_3 orientation = m_traits.orientation_3_object();
    auto positive = [&](const std::array<Index, 4>& t) {
      return orientation(mesh.m_points[t[0]], mesh.m_points[t[1]], mesh.m_points[t[2]], mesh.m_points[t[3]]) == CGAL::POSITIVE;
    };
    std::size_t count = 0;
    for(const auto& chord : chords) { // std::set: deterministic order
      const Index a = chord[0], b = chord[1];
      std::vector<Index> ring;
      for(Index t : vertex_tets[a])
        if(std::find(mesh.m_tets[t].begin(), mesh.m_tets[t].end(), b) != mesh.m_tets[t].end()) ring.push_back(t);
      const Index m = Index(mesh.m_points.size());
      // a/2 + b/2 rather than (a + b)/2: no overflow near the largest doubles
      const Point_3& pa = mesh.m_points[a];
      const Point_3& pb = mesh.m_points[b];
      mesh.m_points.push_back(Point_3(pa.x() / 2 + pb.x() / 2, pa.y() / 2 + pb.y() / 2, pa.z() / 2 + pb.z() / 2));
      // all children must be positively oriented, else the chord is left alone
      bool ok = true;
      std::vector<std::pair<std::array<Index, 4>, std::array<Index, 4> > > children;
      for(Index t : ring) {
        std::array<Index, 4> keep_a = mesh.m_tets[t], keep_b = mesh.m_tets[t];
        for(int i = 0; i < 4; ++i) {
          if(keep_a[i] == b) keep_a[i] = m;
          if(keep_b[i] == a) keep_b[i] = m;
        }
        ok = ok && positive(keep_a) && positive(keep_b);
        children.push_back({keep_a, keep_b});
      }
      if(!ok) { mesh.m_points.pop_back(); continue; }
      vertex_tets.emplace_back();
      for(std::size_t k = 0; k < ring.size(); ++k) {
        const Index t = ring[k];
        const Index nt = Index(mesh.m_tets.size());
        mesh.m_tets[t] = children[k].first;
        mesh.m_tets.push_back(children[k].second);
        mesh.m_tet_input_index.push_back(mesh.m_tet_input_index[t]);
        auto& lb = vertex_tets[b];
        lb.erase(std::find(lb.begin(), lb.end(), t));
        vertex_tets[m].push_back(t);
        for(Index v : children[k].second) vertex_tets[v].push_back(nt);
      }
      ++count;
    }
    mesh.m_number_of_split_chords = count;
    return count > 0;
  }

  void build_boundary_triangles(Mesh& mesh)
  {
    mesh.m_face_boundary_triangle.assign(mesh.m_face_vertices.size(), null_index);
    mesh.m_bt_face.clear();
    for(std::size_t f = 0; f < mesh.m_face_vertices.size(); ++f)
      if(mesh.m_face_tets[f][1] == null_index) {
        mesh.m_face_boundary_triangle[f] = Index(mesh.m_bt_face.size());
        mesh.m_bt_face.push_back(Index(f));
      }
    mesh.m_bt_patch.assign(mesh.m_bt_face.size(), -1);
    mesh.m_vertex_on_boundary.assign(mesh.m_points.size(), 0);
    for(Index f : mesh.m_bt_face)
      for(Index v : mesh.m_face_vertices[f]) mesh.m_vertex_on_boundary[v] = 1;
  }

  struct Edge_record
  {
    std::array<Index, 2> key;
    Index tet;
    int local;
    bool operator<(const Edge_record& o) const { return key < o.key || (key == o.key && tet < o.tet); }
  };

  void build_edges_and_rings(Mesh& mesh)
  {
    const std::size_t nt = mesh.m_tets.size();
    std::vector<Edge_record> records(6 * nt);
    for(std::size_t t = 0; t < nt; ++t)
      for(int k = 0; k < 6; ++k) {
        Edge_record& r = records[6 * t + k];
        const Index a = mesh.m_tets[t][tet_edge_local[k][0]], b = mesh.m_tets[t][tet_edge_local[k][1]];
        r.key = {(std::min)(a, b), (std::max)(a, b)};
        r.tet = Index(t);
        r.local = k;
      }
    std::sort(records.begin(), records.end());

    mesh.m_edge_vertices.clear();
    mesh.m_edge_bt.clear();
    mesh.m_ring_offsets.assign(1, 0);
    mesh.m_ring_face_offsets.assign(1, 0);
    mesh.m_ring_tets.clear();
    mesh.m_ring_faces.clear();
    mesh.m_ring_tets.reserve(records.size());
    mesh.m_ring_faces.reserve(records.size() + records.size() / 4);

    struct Incidence { Index tet, entry, exit; bool used; };
    std::vector<Incidence> inc;
    for(std::size_t b = 0; b < records.size();) {
      std::size_t e = b + 1;
      while(e < records.size() && records[e].key == records[b].key) ++e;
      const std::array<Index, 2> key = records[b].key;
      // For each incident tetrahedron: the face through which the counter-clockwise walk about
      // key[1] - key[0] enters it and the one through which it leaves it (combinatorial: the
      // tetrahedra are positively oriented, so no geometric test is needed).
      inc.clear();
      for(std::size_t r = b; r < e; ++r) {
        const Index t = records[r].tet;
        const int* le = tet_edge_local[records[r].local];
        int k = le[2], l = le[3];
        if(mesh.m_tets[t][le[0]] != key[0]) std::swap(k, l); // edge reversed: odd permutation
        // turning ccw about the edge leads from v_k to v_l: enter through the face holding v_k
        // (opposite l), leave through the face holding v_l (opposite k)
        inc.push_back({t, mesh.m_tet_faces[t][l], mesh.m_tet_faces[t][k], false});
      }
      std::size_t start = 0, boundary_entries = 0;
      for(std::size_t i = 0; i < inc.size(); ++i)
        if(mesh.m_face_tets[inc[i].entry][1] == null_index) { ++boundary_entries; start = i; }
      if(boundary_entries > 1)
        fail(0, "edge (" + std::to_string(key[0]) + ", " + std::to_string(key[1]) +
             "): non-manifold boundary (" + std::to_string(2 * boundary_entries) + " boundary faces meet there)");
      const bool on_boundary = boundary_entries == 1;
      // interior edges start at the tetrahedron of smallest index (records are sorted by tet)
      std::size_t cur = start;
      const Index first_entry = inc[start].entry;
      mesh.m_ring_faces.push_back(first_entry);
      std::size_t visited = 0;
      Index last_exit = null_index;
      while(true) {
        Incidence& c = inc[cur];
        if(c.used) break;
        c.used = true;
        ++visited;
        mesh.m_ring_tets.push_back(c.tet);
        last_exit = c.exit;
        const std::array<Index, 2>& ft = mesh.m_face_tets[c.exit];
        if(ft[1] == null_index) break;
        const Index next = ft[0] == c.tet ? ft[1] : ft[0];
        // inc is sorted by tetrahedron (the records are sorted by (edge, tetrahedron)): binary search,
        // so that an edge with k tetrahedra costs O(k log k), not O(k^2)
        const auto it = std::lower_bound(inc.begin(), inc.end(), next,
                                         [](const Incidence& a, Index t) { return a.tet < t; });
        if(it == inc.end() || it->tet != next) fail(0, "internal error: broken ring around edge");
        const std::size_t n = std::size_t(it - inc.begin());
        if(!on_boundary && n == start) break;
        mesh.m_ring_faces.push_back(c.exit);
        cur = n;
      }
      if(on_boundary) mesh.m_ring_faces.push_back(last_exit);
      if(visited != inc.size())
        fail(0, "edge (" + std::to_string(key[0]) + ", " + std::to_string(key[1]) +
             "): non-manifold (its tetrahedra form several separate fans)");
      if(!on_boundary) {
        // closed ring: the exit of the last tetrahedron is the entry of the first, pushed first;
        // rotate it to the end so that face k separates ring tetrahedra k and k+1.
        const std::size_t off = mesh.m_ring_face_offsets.back();
        std::rotate(mesh.m_ring_faces.begin() + off, mesh.m_ring_faces.begin() + off + 1, mesh.m_ring_faces.end());
      }
      mesh.m_edge_vertices.push_back(key);
      mesh.m_edge_bt.push_back(on_boundary
        ? std::array<Index, 2>{mesh.m_face_boundary_triangle[first_entry], mesh.m_face_boundary_triangle[last_exit]}
        : std::array<Index, 2>{null_index, null_index});
      mesh.m_ring_offsets.push_back(Index(mesh.m_ring_tets.size()));
      mesh.m_ring_face_offsets.push_back(Index(mesh.m_ring_faces.size()));
      b = e;
    }
    mesh.m_edge_curve.assign(mesh.m_edge_vertices.size(), -1);
    mesh.m_boundary_edges.clear();
    for(std::size_t e = 0; e < mesh.m_edge_bt.size(); ++e)
      if(mesh.m_edge_bt[e][0] != null_index) mesh.m_boundary_edges.push_back(Index(e));
  }

  void build_vertex_edges(Mesh& mesh)
  {
    const std::size_t nv = mesh.m_points.size();
    mesh.m_vertex_edge_offsets.assign(nv + 1, 0);
    for(const std::array<Index, 2>& ev : mesh.m_edge_vertices) {
      ++mesh.m_vertex_edge_offsets[ev[0] + 1];
      ++mesh.m_vertex_edge_offsets[ev[1] + 1];
    }
    for(std::size_t v = 0; v < nv; ++v) mesh.m_vertex_edge_offsets[v + 1] += mesh.m_vertex_edge_offsets[v];
    mesh.m_vertex_edges.assign(mesh.m_vertex_edge_offsets.back(), 0);
    std::vector<Index> fill(mesh.m_vertex_edge_offsets.begin(), mesh.m_vertex_edge_offsets.end() - 1);
    // edges are sorted by (v0, v1) with v0 < v1, so each list comes out sorted by the other endpoint
    // for the v0 lists; sort explicitly to cover both roles.
    for(std::size_t e = 0; e < mesh.m_edge_vertices.size(); ++e) {
      mesh.m_vertex_edges[fill[mesh.m_edge_vertices[e][0]]++] = Index(e);
      mesh.m_vertex_edges[fill[mesh.m_edge_vertices[e][1]]++] = Index(e);
    }
    for(std::size_t v = 0; v < nv; ++v) {
      auto other = [&](Index e) { const auto& ev = mesh.m_edge_vertices[e]; return ev[0] == v ? ev[1] : ev[0]; };
      std::sort(mesh.m_vertex_edges.begin() + mesh.m_vertex_edge_offsets[v],
                mesh.m_vertex_edges.begin() + mesh.m_vertex_edge_offsets[v + 1],
                [&](Index a, Index b) { return other(a) < other(b); });
    }
  }

  Index find_edge(const Mesh& mesh, Index a, Index b) const
  {
    const std::array<Index, 2> key{(std::min)(a, b), (std::max)(a, b)};
    auto it = std::lower_bound(mesh.m_edge_vertices.begin(), mesh.m_edge_vertices.end(), key);
    return (it != mesh.m_edge_vertices.end() && *it == key) ? Index(it - mesh.m_edge_vertices.begin()) : null_index;
  }

  void link_boundary_triangles_to_edges(Mesh& mesh)
  {
    mesh.m_bt_edges.resize(mesh.m_bt_face.size());
    for(std::size_t b = 0; b < mesh.m_bt_face.size(); ++b) {
      const std::array<Index, 3>& v = mesh.m_face_vertices[mesh.m_bt_face[b]];
      for(int i = 0; i < 3; ++i) {
        const Index e = find_edge(mesh, v[(i + 1) % 3], v[(i + 2) % 3]);
        if(e == null_index || (mesh.m_edge_bt[e][0] != b && mesh.m_edge_bt[e][1] != b))
          fail(0, "internal error: boundary triangle " + std::to_string(b) + " is not linked to its edges");
        mesh.m_bt_edges[b][i] = e;
      }
    }
  }

  // A boundary vertex whose boundary triangles form several fans (a pinched, "bow-tie" vertex)
  // has no well-defined normal cone and breaks the hex-meshing of its neighbourhood.
  void check_boundary_vertices_manifold(Mesh& mesh)
  {
    const std::size_t nv = mesh.m_points.size();
    std::vector<Index> offsets(nv + 1, 0);
    for(Index f : mesh.m_bt_face)
      for(Index v : mesh.m_face_vertices[f]) ++offsets[v + 1];
    for(std::size_t v = 0; v < nv; ++v) offsets[v + 1] += offsets[v];
    std::vector<Index> corner_bt(offsets.back());
    std::vector<Index> fill(offsets.begin(), offsets.end() - 1);
    for(std::size_t b = 0; b < mesh.m_bt_face.size(); ++b)
      for(Index v : mesh.m_face_vertices[mesh.m_bt_face[b]]) corner_bt[fill[v]++] = Index(b);
    // the boundary triangles of each vertex are listed in increasing order: binary search
    auto corner_of = [&](Index v, Index b) {
      const auto first = corner_bt.begin() + offsets[v], last = corner_bt.begin() + offsets[v + 1];
      const auto it = std::lower_bound(first, last, b);
      if(it == last || *it != b) fail(0, "internal error: boundary triangle missing at a vertex");
      return Index(it - corner_bt.begin());
    };
    Union_find uf(corner_bt.size());
    for(Index e : mesh.m_boundary_edges)
      for(Index v : mesh.m_edge_vertices[e])
        uf.unite(corner_of(v, mesh.m_edge_bt[e][0]), corner_of(v, mesh.m_edge_bt[e][1]));
    for(std::size_t v = 0; v < nv; ++v) {
      std::size_t fans = 0;
      for(Index c = offsets[v]; c < offsets[v + 1]; ++c) fans += (uf.find(c) == c);
      if(fans > 1)
        fail(0, "vertex " + std::to_string(v) + ": non-manifold boundary (" + std::to_string(fans) +
             " separate fans of boundary triangles meet there)");
    }
  }

  void build_components(Mesh& mesh)
  {
    Union_find tets(mesh.m_tets.size());
    for(const std::array<Index, 2>& ft : mesh.m_face_tets)
      if(ft[1] != null_index) tets.unite(ft[0], ft[1]);
    mesh.m_tet_component = tets.labels(mesh.m_number_of_components);
    Union_find tris(mesh.m_bt_face.size());
    for(Index e : mesh.m_boundary_edges) tris.unite(mesh.m_edge_bt[e][0], mesh.m_edge_bt[e][1]);
    mesh.m_bt_component = tris.labels(mesh.m_number_of_boundary_components);
  }

  void apply_hints(const Tetrahedral_soup_3<Point_3>& soup, Mesh& mesh)
  {
    const std::size_t nv = soup.points.size();
    auto check_index = [&](std::size_t v, const char* what, std::size_t i) {
      if(v >= nv) fail(0, std::string(what) + " " + std::to_string(i) + ": vertex index " + std::to_string(v) + " out of range");
    };
    auto map = [&](std::size_t v) { return m_remap.empty() ? Index(v) : m_remap[v]; };
    std::set<int> patches, curves;
    for(std::size_t i = 0; i < soup.triangles.size(); ++i) {
      std::array<Index, 3> key;
      for(int k = 0; k < 3; ++k) { check_index(soup.triangles[i][k], "triangle", i); key[k] = map(soup.triangles[i][k]); }
      std::sort(key.begin(), key.end());
      auto it = std::lower_bound(m_face_keys.begin(), m_face_keys.end(), key);
      if(it == m_face_keys.end() || *it != key) continue; // not a face of the mesh: only a hint
      const Index b = mesh.m_face_boundary_triangle[Index(it - m_face_keys.begin())];
      if(b == null_index) continue; // interface between sub-domains
      const int patch = i < soup.triangle_patches.size() ? soup.triangle_patches[i] : 0;
      mesh.m_bt_patch[b] = patch;
      patches.insert(patch);
    }
    for(std::size_t i = 0; i < soup.feature_edges.size(); ++i) {
      check_index(soup.feature_edges[i][0], "feature edge", i);
      check_index(soup.feature_edges[i][1], "feature edge", i);
      const Index e = find_edge(mesh, map(soup.feature_edges[i][0]), map(soup.feature_edges[i][1]));
      if(e == null_index) continue;
      const int curve = i < soup.feature_edge_curves.size() ? soup.feature_edge_curves[i] : 0;
      if(mesh.m_edge_curve[e] < 0) ++mesh.m_number_of_feature_edges;
      mesh.m_edge_curve[e] = curve;
      curves.insert(curve);
    }
    std::set<Index> corners;
    for(std::size_t i = 0; i < soup.corners.size(); ++i) {
      check_index(soup.corners[i], "corner", i);
      corners.insert(map(soup.corners[i]));
    }
    mesh.m_corners.assign(corners.begin(), corners.end());
    mesh.m_number_of_patches = patches.size();
    mesh.m_patch_names.clear();
    for(const auto& pn : soup.patch_names)
      if(patches.count(pn.first) > 0 && !pn.second.empty()) mesh.m_patch_names.push_back(pn);
    std::sort(mesh.m_patch_names.begin(), mesh.m_patch_names.end());
    mesh.m_number_of_curves = curves.size();
  }

  const Traits& m_traits;
  std::string m_source;
  int m_coincident_policy = REFUSE_COINCIDENT;
  std::vector<Index> m_remap;   // vertex -> representative of its position (empty: identity)
  std::size_t m_merged_vertices = 0;
  std::vector<std::array<Index, 3> > m_face_keys; // sorted: face f has key m_face_keys[f]
  std::vector<Index> m_original_tet;              // input tetrahedron of each tetrahedron after a split
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_BUILD_TETRAHEDRAL_MESH_H
