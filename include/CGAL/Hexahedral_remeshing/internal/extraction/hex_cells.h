// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_HEX_CELLS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_HEX_CELLS_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/hex_vertices.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/map_topology.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/sanitize.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/transitions.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {
namespace extraction {

struct Cell_assembly_report
{
  std::size_t incomplete_cells = 0;     // some corner not found, or two vertices for one corner
  std::size_t missing_corners = 0;      // corners not reached from the cell centre (untraced)
  std::size_t conflicting_corners = 0;  // corners reached as two different hex vertices
  std::size_t resolved_cells = 0;       // cells with such corners completed by their neighbours' vertices
  std::size_t duplicate_cells = 0;      // the same 8 vertices found from two centres
  std::size_t inconsistent_walks = 0;   // a tetrahedron reached with two different transitions
  std::size_t truncated_walks = 0;      // walks stopped by the size limit
  std::size_t folded_cells = 0;         // cells next to inverted tetrahedra whose corners are inverted in space
};

// The corners of one cell as its walk found them: every hex vertex seen at each corner (bits
// x | y << 1 | z << 2), and whether the walk met a tetrahedron near an inverted one.
struct Cell_corners
{
  std::array<std::vector<std::uint32_t>, 8> candidates;
  bool near_inverted = false;
  std::uint32_t source = 0;

  bool complete() const
  {
    for(const auto& c : candidates)
      if(c.empty()) return false;
    return true;
  }
  bool conflicting() const
  {
    for(const auto& c : candidates)
      if(c.size() > 1) return true;
    return false;
  }
};

// Tetrahedra within two vertex rings of an inverted one: a fold reaches that far around it, and a
// cell walk that meets none of them sees a locally injective map.
inline std::vector<char> near_inverted_tetrahedra(const Integer_grid_map& map, const Sanitized_map& sm)
{
  const std::size_t nt = map.tetrahedra.size();
  std::vector<char> inverted(nt, 0);
  for(std::size_t t = 0; t < nt; ++t) inverted[t] = parameter_orientation(sm.parameters[t]) == CGAL::NEGATIVE;
  for(int ring = 0; ring < 2; ++ring) {
    std::vector<char> vertex_near(map.points.size(), 0);
    for(std::size_t t = 0; t < nt; ++t)
      if(inverted[t])
        for(int k = 0; k < 4; ++k) vertex_near[map.tetrahedra[t][k]] = 1;
    for(std::size_t t = 0; t < nt; ++t)
      for(int k = 0; k < 4; ++k)
        if(vertex_near[map.tetrahedra[t][k]]) inverted[t] = 1;
  }
  return inverted;
}

// Walks the tetrahedra covering the open cube of a cell centre and collects its corners. The cell of
// centre c (chart of tetrahedron o) is the open cube c + (-1/2, 1/2)^3; a walk from o across every
// face whose parameter bounding box (in o's chart) meets the open cube reaches all tetrahedra covering
// the cube, and carries the transitions so that each hex vertex on those tetrahedra is seen in o's
// chart. The corner c + d, d in {-1/2, 1/2}^3, is the hex vertex found at that point. Singular curves
// lie on integer lines, i.e. on cell edges, so the open cube contains none and the walk's transitions
// do not depend on the path (checked). `stamp`, `to_centre`, `queue`: work arrays of the walks.
class Cell_walker
{
public:
  Cell_walker(const Map_topology& topo, const Sanitized_map& sm, const Face_transitions& tr, const Lattice_points& lp,
              const std::vector<char>& near_inverted, Cell_assembly_report& report)
    : m_topo(topo), m_sm(sm), m_tr(tr), m_lp(lp), m_near_inverted(near_inverted), m_report(report),
      m_stamp(sm.parameters.size(), no_tetrahedron), m_to_centre(sm.parameters.size())
  {}

  Cell_corners walk(std::size_t ci)
  {
    const Chart_point& centre = m_lp.centres[ci];
    const Eigen::Vector3d& c = centre.x;
    const std::uint32_t mark = std::uint32_t(ci);
    Cell_corners cell;
    cell.source = centre.tetrahedron;
    m_queue.assign(1, centre.tetrahedron);
    m_stamp[centre.tetrahedron] = mark;
    m_to_centre[centre.tetrahedron] = Rigid_transform();
    for(std::size_t q = 0; q < m_queue.size(); ++q) {
      const std::uint32_t t = m_queue[q];
      const Rigid_transform M = m_to_centre[t];
      cell.near_inverted = cell.near_inverted || m_near_inverted[t];
      collect_corners(t, M, c, cell);
      if(m_queue.size() >= max_walk) { ++m_report.truncated_walks; break; }
      for(int f = 0; f < 4; ++f) visit_neighbour(t, f, M, c, mark);
    }
    return cell;
  }

private:
  static constexpr std::size_t max_walk = 100000;

  void collect_corners(std::uint32_t t, const Rigid_transform& M, const Eigen::Vector3d& c, Cell_corners& cell) const
  {
    for(std::uint32_t i = m_lp.per_tetrahedron_begin[t]; i < m_lp.per_tetrahedron_begin[t + 1]; ++i) {
      const Eigen::Vector3d d = apply(M, m_lp.copies[i].x) - c;
      if(std::abs(d[0]) != 0.5 || std::abs(d[1]) != 0.5 || std::abs(d[2]) != 0.5) continue;
      auto& candidates = cell.candidates[std::size_t((d[0] > 0 ? 1 : 0) | (d[1] > 0 ? 2 : 0) | (d[2] > 0 ? 4 : 0))];
      if(std::find(candidates.begin(), candidates.end(), m_lp.copies[i].id) == candidates.end())
        candidates.push_back(m_lp.copies[i].id);
    }
  }

  // crosses face f of t if the face meets the open cube (bounding box test in the centre's chart: conservative)
  void visit_neighbour(std::uint32_t t, int f, const Rigid_transform& M, const Eigen::Vector3d& c, std::uint32_t mark)
  {
    const std::uint32_t n = m_topo.neighbor[t][f];
    if(n == no_tetrahedron) return;
    Eigen::Vector3d lo, hi;
    for(int k = 0; k < 3; ++k) {
      const Eigen::Vector3d x = apply(M, m_sm.parameters[t][face_vertices[f][k]]);
      if(k == 0) { lo = hi = x; } else { lo = lo.cwiseMin(x); hi = hi.cwiseMax(x); }
    }
    for(int a = 0; a < 3; ++a)
      if(!(lo[a] < c[a] + 0.5 && hi[a] > c[a] - 0.5)) return;
    const Rigid_transform Mn = compose(M, m_tr.to_this[t][f]);
    if(m_stamp[n] != mark) {
      m_stamp[n] = mark;
      m_to_centre[n] = Mn;
      m_queue.push_back(n);
    } else if(m_to_centre[n] != Mn) {
      ++m_report.inconsistent_walks;
    }
  }

  const Map_topology& m_topo;
  const Sanitized_map& m_sm;
  const Face_transitions& m_tr;
  const Lattice_points& m_lp;
  const std::vector<char>& m_near_inverted;
  Cell_assembly_report& m_report;
  std::vector<std::uint32_t> m_stamp;
  std::vector<Rigid_transform> m_to_centre;
  std::vector<std::uint32_t> m_queue;
};

// The hexahedra found so far, with their vertex sets (duplicates) and, once index_quads() is called,
// the hexahedra on each quad (a resolved cell must not put a third hexahedron on a face).
class Cell_emitter
{
public:
  Cell_emitter(const std::vector<Hexahedral_mesh_3::Point_3>& positions, bool keep_folded, std::vector<std::array<std::uint32_t, 8> >& hexes,
               std::vector<std::uint32_t>& sources, Cell_assembly_report& report)
    : m_positions(positions), m_keep_folded(keep_folded), m_hexes(hexes), m_sources(sources), m_report(report)
  {}

  // Emits the cell of corners `corner` (bits x | y << 1 | z << 2) if its 8 vertices are distinct and
  // new. Returns false if they are not distinct.
  bool emit(const std::array<std::uint32_t, 8>& corner, bool near_inverted, std::uint32_t source)
  {
    std::array<std::uint32_t, 8> sorted;
    if(!distinct(corner, sorted)) return false;
    const std::array<std::uint32_t, 8> hex = vtk_order(corner);
    // Where the map folds, a lattice point is covered more than once and spurious copies of hex
    // vertices appear (HexEx cancels them with its anti-darts). A cell met by inverted tetrahedra is
    // kept only if every corner is positively oriented in space (exact), so no folded cell is emitted,
    // unless the caller untangles afterwards (`keep_folded`): a folded cell left out is a hole in the
    // mesh, one kept is an inverted hexahedron that the untangling repairs (the shipped cylinder at
    // 583 hexahedra: 11 cells left out made slits reaching 0.24 of the diagonal into the solid; kept,
    // the smoothed mesh is valid, min scaled Jacobian 0.83).
    if(near_inverted && folded_in_space(hex)) {
      ++m_report.folded_cells;
      if(!m_keep_folded) return true;
    }
    if(!m_seen.insert(sorted).second) { ++m_report.duplicate_cells; return true; }
    m_hexes.push_back(hex);
    m_sources.push_back(source);
    if(m_indexed) add_quads(hex);
    return true;
  }

  std::size_t size() const { return m_hexes.size(); }

  // The smallest scaled Jacobian of the cell's corners in space (-1 to 1; the cell of corners `corner`,
  // bits x | y << 1 | z << 2).
  double corner_quality(const std::array<std::uint32_t, 8>& corner) const
  {
    double worst = 1.;
    for(std::uint32_t b = 0; b < 8; ++b) {
      const auto& o = m_positions[corner[b]];
      Eigen::Matrix3d J;
      for(int a = 0; a < 3; ++a) {
        const auto& n = m_positions[corner[b ^ (1u << a)]];
        J.col(a) = Eigen::Vector3d(n.x() - o.x(), n.y() - o.y(), n.z() - o.z()) * ((b >> a) & 1 ? -1. : 1.);
      }
      const double scale = J.col(0).norm() * J.col(1).norm() * J.col(2).norm();
      worst = std::min(worst, scale > 0 ? J.determinant() / scale : -1.);
    }
    return worst;
  }

  // Quads of the cell of corners `corner` that one emitted hexahedron has already, on its other side
  // (the cell would close them); -1 if its corners are not distinct, if one of its quads has two
  // hexahedra, or one hexahedron on the same side (the cell would overlap it).
  int glued_faces(const std::array<std::uint32_t, 8>& corner) const
  {
    std::array<std::uint32_t, 8> sorted;
    if(!distinct(corner, sorted)) return -1;
    const std::array<std::uint32_t, 8> hex = vtk_order(corner);
    int glued = 0;
    for(int f = 0; f < 6; ++f) {
      const auto it = m_quads.find(quad(hex, f));
      if(it == m_quads.end()) continue;
      if(it->second.first >= 2 || same_orientation(outward_quad(hex, f), it->second.second)) return -1;
      ++glued;
    }
    return glued;
  }

  // From now on the quads of the emitted hexahedra are counted (glued_faces()).
  void index_quads()
  {
    if(m_indexed) return;
    m_indexed = true;
    for(const auto& h : m_hexes) add_quads(h);
  }

private:
  typedef std::array<std::uint32_t, 4> Quad;
  static std::array<std::uint32_t, 8> vtk_order(const std::array<std::uint32_t, 8>& corner)
  {
    static const int vtk_corner[8] = {0, 1, 3, 2, 4, 5, 7, 6}; // VTK vertex i -> corner bits
    std::array<std::uint32_t, 8> hex;
    for(int i = 0; i < 8; ++i) hex[std::size_t(i)] = corner[std::size_t(vtk_corner[i])];
    return hex;
  }
  // face f of a hexahedron in VTK order, its vertices in the order seen from outside
  static Quad outward_quad(const std::array<std::uint32_t, 8>& hex, int f)
  {
    static const int q[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    return Quad{{hex[q[f][0]], hex[q[f][1]], hex[q[f][2]], hex[q[f][3]]}};
  }
  static Quad quad(const std::array<std::uint32_t, 8>& hex, int f)
  {
    Quad k = outward_quad(hex, f);
    std::sort(k.begin(), k.end());
    return k;
  }
  // two cycles of the same four vertices, in the same rotational order
  static bool same_orientation(const Quad& a, const Quad& b)
  {
    const std::size_t i = std::size_t(std::find(b.begin(), b.end(), a[0]) - b.begin());
    return i < 4 && b[(i + 1) % 4] == a[1];
  }
  void add_quads(const std::array<std::uint32_t, 8>& hex)
  {
    for(int f = 0; f < 6; ++f) {
      auto& q = m_quads[quad(hex, f)];
      if(q.first++ == 0) q.second = outward_quad(hex, f);
    }
  }
  static bool distinct(const std::array<std::uint32_t, 8>& corner, std::array<std::uint32_t, 8>& sorted)
  {
    sorted = corner;
    std::sort(sorted.begin(), sorted.end());
    return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
  }
  bool folded_in_space(const std::array<std::uint32_t, 8>& hex) const
  {
    static const int nb[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7}, {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
    for(int i = 0; i < 8; ++i)
      if(CGAL::orientation(m_positions[hex[i]], m_positions[hex[nb[i][0]]], m_positions[hex[nb[i][1]]],
                           m_positions[hex[nb[i][2]]]) != CGAL::POSITIVE)
        return true;
    return false;
  }

  const std::vector<Hexahedral_mesh_3::Point_3>& m_positions;
  bool m_keep_folded;
  std::vector<std::array<std::uint32_t, 8> >& m_hexes;
  std::vector<std::uint32_t>& m_sources;
  Cell_assembly_report& m_report;
  std::set<std::array<std::uint32_t, 8> > m_seen;
  bool m_indexed = false;
  std::map<Quad, std::pair<int, Quad> > m_quads; // hexahedra on the quad, the first one's outward cycle
};

// The corners of a cell whose corners were seen as several hex vertices: of every choice of one
// candidate per corner, the one whose cell closes the most quads that one emitted hexahedron has
// already (glued to its neighbours) and closes at least one; between choices glued alike, the one
// whose worst corner is the least distorted in space (Cell_emitter::corner_quality()) if `by_quality`.
// False if two choices are equal in both, if no choice is glued, or if there are more than
// `max_choices` choices.
inline bool choose_corners(const Cell_corners& cell, const Cell_emitter& emitter, std::array<std::uint32_t, 8>& best,
                           bool by_quality = true)
{
  const std::size_t max_choices = 4096;
  std::size_t choices = 1;
  for(const auto& c : cell.candidates) {
    choices *= c.size();
    if(choices > max_choices) return false;
  }
  std::pair<int, double> best_score(0, 0.);
  bool tie = false;
  for(std::size_t k = 0; k < choices; ++k) {
    std::array<std::uint32_t, 8> corner;
    for(std::size_t b = 0, rest = k; b < 8; ++b) {
      corner[b] = cell.candidates[b][rest % cell.candidates[b].size()];
      rest /= cell.candidates[b].size();
    }
    const int glued = emitter.glued_faces(corner);
    if(glued <= 0 || glued < best_score.first) continue;
    const std::pair<int, double> score(glued, by_quality ? emitter.corner_quality(corner) : 0.);
    if(score > best_score) {
      best_score = score;
      best = corner;
      tie = false;
    } else if(score == best_score) {
      tie = true;
    }
  }
  return best_score.first > 0 && !tie;
}

// Completes the cells whose corners were all found but some as two or more hex vertices. Where the
// map folds, a lattice point is covered more than once (its spurious copies belong to no cell);
// where it is flat, two distinct hex vertices share one parameter point (each with its own cells):
// the cells across such places see both. The cell that fills the hole is the one glued to its
// neighbours (choose_corners()); it is emitted only if no quad of it has two hexahedra already.
// Completed cells glue their neighbours in turn, so the pass repeats while it completes cells.
// Returns the cells still left out.
inline std::vector<Cell_corners> resolve_conflicting_cells(std::vector<Cell_corners> cells, Cell_emitter& emitter,
                                                           Cell_assembly_report& report)
{
  if(cells.empty()) return cells;
  emitter.index_quads();
  // the cells glued best by one choice first, all of them: a tie decided by the shape before its
  // neighbours are in can take the wrong copy (B1_tet: a non-manifold boundary)
  for(bool by_quality : {false, true})
    for(bool progress = true; progress && !cells.empty();) {
      progress = false;
      std::vector<Cell_corners> left;
      for(const Cell_corners& cell : cells) {
        std::array<std::uint32_t, 8> corner;
        const std::size_t before = emitter.size();
        // choose_corners() checked the quads of the choice: none has two hexahedra or one on its side
        if(choose_corners(cell, emitter, corner, by_quality) && emitter.emit(corner, cell.near_inverted, cell.source)) {
          report.resolved_cells += emitter.size() - before;
          progress = true;
        } else {
          left.push_back(cell);
        }
      }
      cells.swap(left);
    }
  return cells;
}

// Hex cells from their centres (Cell_walker), each emitted only with 8 distinct corners, in VTK
// order of its centre's chart (positive orientation); cells with corners seen twice completed
// afterwards from their neighbours (resolve_conflicting_cells()).
inline void assemble_hex_cells(const Integer_grid_map& map, const Map_topology& topo, const Sanitized_map& sm,
                               const Face_transitions& tr, const Lattice_points& lp,
                               std::vector<std::array<std::uint32_t, 8> >& hexes, std::vector<std::uint32_t>& sources,
                               Cell_assembly_report& report, bool keep_folded = false)
{
  const std::vector<char> near_inverted = near_inverted_tetrahedra(map, sm);
  Cell_walker walker(topo, sm, tr, lp, near_inverted, report);
  Cell_emitter emitter(lp.positions, keep_folded, hexes, sources, report);
  std::vector<Cell_corners> conflicting;
  std::size_t left_out = 0;
  for(std::size_t ci = 0; ci < lp.centres.size(); ++ci) {
    const Cell_corners cell = walker.walk(ci);
    if(!cell.complete()) {
      ++left_out;
      for(const auto& c : cell.candidates) report.missing_corners += c.empty();
      continue;
    }
    if(cell.conflicting()) {
      ++report.conflicting_corners;
      conflicting.push_back(cell);
      continue;
    }
    std::array<std::uint32_t, 8> corner;
    for(std::size_t b = 0; b < 8; ++b) corner[b] = cell.candidates[b].front();
    if(!emitter.emit(corner, cell.near_inverted, cell.source)) ++left_out;
  }
  report.incomplete_cells = left_out + resolve_conflicting_cells(std::move(conflicting), emitter, report).size();
}

} // namespace extraction
} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_HEX_CELLS_H
