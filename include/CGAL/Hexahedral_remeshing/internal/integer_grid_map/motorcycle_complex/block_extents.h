// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_BLOCK_EXTENTS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_BLOCK_EXTENTS_H

#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/complex_elements.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/wall_forms.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {
namespace motorcycle {

// The extent of a block along one axis of its chart: the distance between its two sides, as a function
// of the map's variables (its value in the seamless map: `seamless`). Each block is a box of the map,
// so its 3 extents are its arc lengths; the integer program keeps them >= 0, and >= 1 where the two
// sides must stay apart (`separate`: both are boundary, or a singular curve runs on each: a zero
// extent would pinch the part or merge two curves).
struct Block_extent
{
  std::uint32_t block = 0;
  int axis = 0;
  Rational seamless;
  Linear_form form;
  bool separate = false;
  std::vector<std::uint32_t> input_tetrahedra; // the input tetrahedra the block overlaps
  // Each side (0: low, 1: high) is critical if it is wholly boundary or on a singular curve; the
  // extents of the blocks across it, along the same direction: (extent index, entered through its
  // low side).
  std::array<bool, 2> critical{{false, false}};
  std::array<std::vector<std::pair<std::uint32_t, bool> >, 2> neighbors;
};

struct Block_extents
{
  std::vector<Block_extent> extents;
  std::size_t sides_without_form = 0; // sides whose position is not known as a function (skipped)
  std::size_t not_boxes = 0;          // blocks whose sides are not on two planes per axis (skipped)
  std::size_t rings = 0;              // extents around a toroidal block: its period (kept >= 1)
};

namespace extents_detail {

// A tetrahedron of a block developed into the block's chart: q_tet = R q_root + t.
struct Pose
{
  Chart_transition chart;
  std::array<Linear_form, 3> translation;
};

// What is known of one side of a block along one axis of its chart.
struct Side
{
  bool found = false, has_form = false, on_curve = false;
  std::size_t faces = 0, boundary_faces = 0;
  // two sides that are both wholly boundary (a wall of the part) or both on a singular curve must
  // stay apart; a side only partly on the boundary may merge with the opposite one (a step of the
  // boundary smaller than a hex edge disappears), the program finds the folds that would make
  bool critical() const { return on_curve || (faces > 0 && boundary_faces == faces); }
  Rational value;
  Linear_form form;
};

// A toroidal block along one axis of its chart: developed around the ring, the block comes back onto
// itself shifted by its period along that axis (the translation part of the transitions composed
// around the ring). A wall cutting the ring would bound a box whose extent between the wall's two
// sides is that period, whatever the wall's position: so the period is the extent, without the cut.
struct Ring
{
  bool found = false;
  Rational period; // > 0
  Linear_form form;
};

struct Box
{
  bool is_box = true; // every face of a side on one plane, no rotation around a ring
  std::array<Side, 3> low, high;
  std::array<Ring, 3> ring;
  std::set<std::uint32_t> input;
};

} // namespace extents_detail

// Develops every block into one chart and reads its sides. `parameters` are the map's values at the
// corners of the input tetrahedra `input`; `wall_planes` the walls' planes per input tetrahedron
// (Wall_tracer::wall_planes); `singular` the singular edges of the traced mesh (vertex pairs, sorted).
class Block_extent_reader
{
public:
  Block_extent_reader(const Exact_map_mesh& mesh, const Complex_elements& elements, const Map_forms& forms,
                      const std::vector<std::array<std::uint32_t, 4> >& input,
                      const std::vector<std::array<Eigen::Vector3d, 4> >& parameters,
                      const std::map<std::pair<int, std::uint32_t>, std::vector<Plane_form> >& wall_planes,
                      const std::set<std::pair<std::uint32_t, std::uint32_t> >& singular)
    : m_mesh(mesh), m_elements(elements), m_forms(forms), m_input(input), m_parameters(parameters),
      m_wall_planes(wall_planes), m_singular(singular)
  {}

  Block_extents read() const
  {
    using namespace extents_detail;
    Block_extents out;
    std::vector<Box> boxes(m_elements.blocks);
    std::vector<char> seen(m_mesh.tetrahedra.size(), 0);
    m_face_sides.clear();
    for(std::size_t t = 0; t < m_mesh.tetrahedra.size(); ++t)
      if(!seen[t]) develop(t, boxes[m_elements.block_of_tetrahedron[t]], seen, out);
    std::map<std::pair<std::uint32_t, int>, std::uint32_t> extent_of;
    for(std::size_t b = 0; b < boxes.size(); ++b) {
      if(!boxes[b].is_box) { ++out.not_boxes; continue; }
      for(int k = 0; k < 3; ++k) {
        const Side& lo = boxes[b].low[std::size_t(k)];
        const Side& hi = boxes[b].high[std::size_t(k)];
        const Ring& ring = boxes[b].ring[std::size_t(k)];
        Block_extent e;
        e.block = std::uint32_t(b);
        e.axis = k;
        if(ring.found && !lo.found && !hi.found) {
          // a ring of zero period would flatten the whole block
          e.seamless = ring.period;
          e.form = ring.form;
          e.separate = true;
          ++out.rings;
        } else if(!lo.found || !hi.found || !lo.has_form || !hi.has_form || ring.found) {
          ++out.sides_without_form;
          continue;
        } else {
          e.seamless = hi.value - lo.value;
          e.form = hi.form.plus(lo.form, -1.0);
          e.separate = lo.critical() && hi.critical();
        }
        e.critical = {{lo.critical(), hi.critical()}};
        e.input_tetrahedra.assign(boxes[b].input.begin(), boxes[b].input.end());
        extent_of[std::make_pair(std::uint32_t(b), k)] = std::uint32_t(out.extents.size());
        out.extents.push_back(std::move(e));
      }
    }
    link_sides(extent_of, out);
    return out;
  }

private:
  // One side of a block seen from a face of a wall: the block, the axis of its chart, low or high.
  struct Face_side
  {
    std::uint32_t block;
    int axis;
    bool low;
  };

  // The extents on either side of each wall face are neighbors (each pair once).
  void link_sides(const std::map<std::pair<std::uint32_t, int>, std::uint32_t>& extent_of, Block_extents& out) const
  {
    std::set<std::array<std::uint32_t, 4> > links;
    for(const auto& face : m_face_sides) {
      if(face.second.size() != 2) continue;
      const Face_side& a = face.second[0];
      const Face_side& b = face.second[1];
      const auto ea = extent_of.find(std::make_pair(a.block, a.axis));
      const auto eb = extent_of.find(std::make_pair(b.block, b.axis));
      if(ea == extent_of.end() || eb == extent_of.end()) continue;
      links.insert({{ea->second, std::uint32_t(a.low), eb->second, std::uint32_t(b.low)}});
      links.insert({{eb->second, std::uint32_t(b.low), ea->second, std::uint32_t(a.low)}});
    }
    for(const auto& l : links) out.extents[l[0]].neighbors[l[1] ? 0 : 1].emplace_back(l[2], l[3] != 0);
  }

  // Breadth-first over the block's tetrahedra (across faces that are not walls), each posed in the
  // root's chart; a face between two tetrahedra already posed closes a loop: different poses there
  // are a ring (add_ring()).
  void develop(std::size_t root, extents_detail::Box& box, std::vector<char>& seen, Block_extents& out) const
  {
    using namespace extents_detail;
    std::deque<std::size_t> queue{root};
    std::map<std::size_t, Pose> poses{{root, Pose()}};
    seen[root] = 1;
    while(!queue.empty()) {
      const std::size_t t = queue.front();
      queue.pop_front();
      const Pose pose = poses.at(t);
      const Map_tetrahedron& T = m_mesh.tetrahedra[t];
      box.input.insert(T.origin);
      for(int f = 0; f < 4; ++f) {
        if(T.wall[std::size_t(f)] != NOT_A_WALL) { read_side(t, f, pose, box); continue; }
        const std::size_t n = std::size_t(T.neighbor[std::size_t(f)]);
        Pose next;
        if(!pose_across(t, f, pose, next)) {
          if(!seen[n]) ++out.sides_without_form;
          seen[n] = 1;
          continue;
        }
        const auto known = poses.find(n);
        if(known != poses.end()) { add_ring(known->second, next, box); continue; }
        if(seen[n]) continue;
        seen[n] = 1;
        poses.emplace(n, next);
        queue.push_back(n);
      }
    }
  }

  // The pose of the neighbor of t across face f; false if the face is not seamless.
  bool pose_across(std::size_t t, int f, const extents_detail::Pose& pose, extents_detail::Pose& next) const
  {
    const Map_tetrahedron& T = m_mesh.tetrahedra[t];
    const std::size_t n = std::size_t(T.neighbor[std::size_t(f)]);
    if(m_mesh.tetrahedra[n].origin == T.origin) { next = pose; return true; }
    const Chart_transition* c = m_mesh.transition(t, f);
    if(!c) return false;
    next.chart = pose.chart.then(*c);
    const std::array<Linear_form, 3> tf = translation_forms(m_forms, m_input, T.origin, m_mesh.tetrahedra[n].origin, *c);
    for(std::size_t i = 0; i < 3; ++i)
      next.translation[i] = pose.translation[std::size_t(c->R.axis[i])].scaled(double(c->R.sign[i])).plus(tf[i], 1.0);
    return true;
  }

  // Two poses of one tetrahedron, q = R q_root + t1 and q = R q_root' + t2: the root comes back shifted
  // by q_root' - q_root = R^-1 (t1 - t2), the block's period (the shortest one found is kept). With
  // two rotations the block turns around the ring: not a box.
  static void add_ring(const extents_detail::Pose& known, const extents_detail::Pose& again, extents_detail::Box& box)
  {
    if(!(known.chart.R == again.chart.R)) { box.is_box = false; return; }
    for(std::size_t i = 0; i < 3; ++i) {
      if(known.chart.t[i] == again.chart.t[i]) continue;
      const int s = known.chart.R.sign[i];
      Rational period = s > 0 ? again.chart.t[i] - known.chart.t[i] : known.chart.t[i] - again.chart.t[i];
      Linear_form form = again.translation[i].plus(known.translation[i], -1.0).scaled(double(s));
      if(period < 0) { period = -period; form = form.scaled(-1.0); }
      extents_detail::Ring& ring = box.ring[std::size_t(known.chart.R.axis[i])];
      if(ring.found && !(period < ring.period)) continue;
      ring.found = true;
      ring.period = period;
      ring.form = form;
    }
  }

  // The plane of face f of t with its value form (false if the form is not known).
  bool face_plane(std::size_t t, int f, Plane_form& p) const
  {
    const Map_tetrahedron& T = m_mesh.tetrahedra[t];
    if(!plane_of_face(m_mesh, t, f, p.plane)) return false;
    if(T.wall[std::size_t(f)] >= 0) {
      const auto it = m_wall_planes.find(std::make_pair(T.wall[std::size_t(f)], T.origin));
      if(it == m_wall_planes.end()) return false;
      for(const Plane_form& q : it->second)
        if(q.plane.axis == p.plane.axis && q.plane.value == p.plane.value) { p.value = q.value; return true; }
      return false;
    }
    // a boundary face: the plane of the input tetrahedron's corners on it
    for(std::size_t c = 0; c < 4; ++c)
      if(Rational(m_parameters[T.origin][c][p.plane.axis]) == p.plane.value) {
        p.value = m_forms.corner(T.origin, m_input[T.origin][c], p.plane.axis);
        return true;
      }
    return false;
  }

  bool touches_singular_edge(std::size_t t, int f) const
  {
    const Map_tetrahedron& T = m_mesh.tetrahedra[t];
    for(int a = 0; a < 4; ++a)
      for(int b = a + 1; b < 4; ++b) {
        if(a == f || b == f) continue;
        std::uint32_t x = T.vertex[std::size_t(a)], y = T.vertex[std::size_t(b)];
        if(x > y) std::swap(x, y);
        if(m_singular.count(std::make_pair(x, y))) return true;
      }
    return false;
  }

  void read_side(std::size_t t, int f, const extents_detail::Pose& pose, extents_detail::Box& box) const
  {
    Plane_form p;
    const bool has_form = face_plane(t, f, p);
    if(!plane_of_face(m_mesh, t, f, p.plane)) return;
    // q_t[k] = s_k q_root[a_k] + t_k = v  <=>  q_root[a_k] = s_k (v - t_k)
    const std::size_t k = std::size_t(p.plane.axis);
    const std::size_t K = std::size_t(pose.chart.R.axis[k]);
    const double s = double(pose.chart.R.sign[k]);
    const Rational V = pose.chart.R.sign[k] > 0 ? p.plane.value - pose.chart.t[k] : pose.chart.t[k] - p.plane.value;
    const bool boundary = m_mesh.tetrahedra[t].wall[std::size_t(f)] == BOUNDARY;
    // the side is the low one if the block is on the positive side of the face
    const Map_tetrahedron& T = m_mesh.tetrahedra[t];
    const bool low = (pose.chart.R.sign[k] > 0) == (p.plane.side(T.parameter[std::size_t(f)]) == CGAL::POSITIVE);
    extents_detail::Side& side = low ? box.low[K] : box.high[K];
    if(!boundary) {
      std::array<std::uint32_t, 3> key;
      for(int i = 0, j = 0; i < 4; ++i)
        if(i != f) key[std::size_t(j++)] = T.vertex[std::size_t(i)];
      std::sort(key.begin(), key.end());
      m_face_sides[key].push_back(Face_side{m_elements.block_of_tetrahedron[t], int(K), low});
    }
    ++side.faces;
    side.boundary_faces += boundary;
    side.on_curve = side.on_curve || touches_singular_edge(t, f);
    if(side.found && side.value != V) box.is_box = false;
    if(side.found && side.has_form) return;
    side.found = true;
    side.value = V;
    if(has_form) {
      side.has_form = true;
      side.form = p.value.plus(pose.translation[k], -1.0).scaled(s);
    }
  }

  const Exact_map_mesh& m_mesh;
  const Complex_elements& m_elements;
  const Map_forms& m_forms;
  const std::vector<std::array<std::uint32_t, 4> >& m_input;
  const std::vector<std::array<Eigen::Vector3d, 4> >& m_parameters;
  const std::map<std::pair<int, std::uint32_t>, std::vector<Plane_form> >& m_wall_planes;
  const std::set<std::pair<std::uint32_t, std::uint32_t> >& m_singular;
  mutable std::map<std::array<std::uint32_t, 3>, std::vector<Face_side> > m_face_sides; // wall faces
};

// QGP3D's separation on the blocks: chains of blocks stacked along one direction whose extents are
// all zero in `values` (one per extent; NaN: unknown, not crossed) and that join two critical sides
// (the two ends would merge: two boundary sheets, two curves, or one of each). Each chain is returned
// once, as the indices of its extents (at least two: a single block with two critical sides is
// `separate` already), searched from every critical side within `maximum_length` blocks.
inline std::vector<std::vector<std::uint32_t> > zero_length_paths(const Block_extents& extents, const std::vector<double>& values,
                                                                  std::size_t maximum_length = 16)
{
  std::set<std::vector<std::uint32_t> > found;
  std::vector<std::uint32_t> path;
  auto zero = [&](std::uint32_t i) { return values[i] == values[i] && values[i] < 0.5; };
  // enter extent i through side `from` (0 low, 1 high), leave through the other one
  std::function<void(std::uint32_t, int)> walk = [&](std::uint32_t i, int from) {
    path.push_back(i);
    const Block_extent& e = extents.extents[i];
    const int exit = 1 - from;
    if(e.critical[std::size_t(exit)] && path.size() >= 2) {
      std::vector<std::uint32_t> key = path;
      std::sort(key.begin(), key.end());
      found.insert(key);
    } else if(path.size() < maximum_length) {
      for(const auto& n : e.neighbors[std::size_t(exit)])
        if(zero(n.first) && std::find(path.begin(), path.end(), n.first) == path.end()) walk(n.first, n.second ? 0 : 1);
    }
    path.pop_back();
  };
  for(std::uint32_t i = 0; i < extents.extents.size(); ++i)
    for(int side = 0; side < 2; ++side)
      if(zero(i) && extents.extents[i].critical[std::size_t(side)]) walk(i, side);
  return std::vector<std::vector<std::uint32_t> >(found.begin(), found.end());
}

} // namespace motorcycle
} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_BLOCK_EXTENTS_H
