// An evaluation of a frame field's singular edges written for the tests, independently of the
// package's matchings, singularity graph and meshability check: the rings of tetrahedra around each
// edge are rebuilt from the tetrahedra's vertices, the rotations of the cube are enumerated here, the
// holonomy of an edge is the product of the steps around its ring and is classified from its matrix.
// A step is the closest rotation between the two frames (frames alone), or a given matrix per face.
#ifndef HEXREM_TEST_INDEPENDENT_HOLONOMY_H
#define HEXREM_TEST_INDEPENDENT_HOLONOMY_H

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace independent {

// The 24 signed permutation matrices with determinant +1.
inline const std::vector<Eigen::Matrix3d>& cube_rotations()
{
  static const std::vector<Eigen::Matrix3d> rotations = [] {
    std::vector<Eigen::Matrix3d> r;
    std::array<int, 3> p = {{0, 1, 2}};
    do {
      for(int s = 0; s < 8; ++s) {
        Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
        for(int c = 0; c < 3; ++c) M(p[c], c) = (s >> c & 1) ? -1 : 1;
        if(M.determinant() > 0) r.push_back(M);
      }
    } while(std::next_permutation(p.begin(), p.end()));
    return r;
  }();
  return rotations;
}

// g minimizing |E_i - E_j g|: E_i ~ E_j g.
inline Eigen::Matrix3d closest_rotation(const Eigen::Matrix3d& Ei, const Eigen::Matrix3d& Ej)
{
  const Eigen::Matrix3d P = Ej.transpose() * Ei;
  double best = -1e300;
  Eigen::Matrix3d g = Eigen::Matrix3d::Identity();
  for(const Eigen::Matrix3d& R : cube_rotations()) {
    const double t = (R.transpose() * P).trace();
    if(t > best) { best = t; g = R; }
  }
  return g;
}

struct Edge_verdict
{
  std::array<std::size_t, 2> vertices;
  // 4 regular, 3 / 5 quarter turn within 45 degrees of the edge, 1 jog, 0 other rotation
  int kind = 4;
  // of a quarter turn (3, 5, jog): its unit axis in world coordinates, read in the first tetrahedron's frame
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();
};

// The reading of a map that accepts edges up to about 75.5 degrees off their axis (|cos| > 1/4: valence 3
// or 5 by the sign), where an edge nearly perpendicular to its axis takes the valence of a singular edge
// at one of its vertices whose axis is within 45 degrees of its own (repeatedly), and is improper if
// none: non-meshable are its improper edges, dangling ends and zippers (two singular edges of different
// valences at an interior vertex, an improper one included).
struct Lenient_verdict
{
  std::size_t improper = 0, zippers = 0, dangling = 0;
  std::size_t defects() const { return improper + zippers + dangling; }
};

struct Field_verdict
{
  std::vector<Edge_verdict> singular; // the non-regular interior edges
  std::size_t improper = 0, jogs = 0, zippers = 0, dangling = 0;
  // quarter-turn edges whose axis, read in the frame of each tetrahedron of the ring in turn (the
  // holonomy of the loop from that tetrahedron), is within 45 degrees of the edge in some frames and not
  // in others: a reading from one tetrahedron (as `jogs`, from the first) may call them either way
  std::size_t ambiguous = 0;
  std::size_t defects() const { return improper + jogs + zippers + dangling; }
  Lenient_verdict lenient;
};

struct Lenient_edge
{
  std::array<std::size_t, 2> vertices;
  int valence = 0;         // 3, 5, 0 (improper or not yet decided)
  bool perpendicular = false;
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();
};

inline Lenient_verdict lenient_reading(std::vector<Lenient_edge> edges, const std::set<std::size_t>& boundary_vertices)
{
  std::map<std::size_t, std::vector<std::size_t> > at;
  for(std::size_t i = 0; i < edges.size(); ++i)
    for(std::size_t v : edges[i].vertices) at[v].push_back(i);
  for(bool changed = true; changed;) {
    changed = false;
    for(Lenient_edge& e : edges) {
      if(!e.perpendicular || e.valence != 0) continue;
      for(std::size_t v : e.vertices)
        for(std::size_t n : at[v]) {
          const Lenient_edge& o = edges[n];
          if(&o == &e || (o.valence != 3 && o.valence != 5) || std::abs(o.axis.dot(e.axis)) < std::sqrt(0.5)) continue;
          if(e.valence == 0) { e.valence = o.valence; changed = true; }
        }
    }
  }
  Lenient_verdict r;
  for(const Lenient_edge& e : edges) r.improper += (e.valence == 0);
  for(const auto& a : at) {
    if(boundary_vertices.count(a.first)) continue;
    if(a.second.size() == 1) ++r.dangling;
    if(a.second.size() == 2 && edges[a.second[0]].valence != edges[a.second[1]].valence) ++r.zippers;
  }
  return r;
}

// The unit axis, in world coordinates, of the quarter turn G of the frame E: the skew part of E G E^T.
inline Eigen::Vector3d world_axis(const Eigen::Matrix3d& E, const Eigen::Matrix3d& G)
{
  const Eigen::Matrix3d W = E * G * E.transpose();
  return Eigen::Vector3d(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1)).normalized(); // 2 sin(90) axis
}

// step(ti, tj): g with E_ti ~ E_tj g for face-adjacent tetrahedra.
template <class Step>
Field_verdict evaluate(const std::vector<Eigen::Vector3d>& points, const std::vector<std::array<std::size_t, 4> >& tets,
                       const std::vector<Eigen::Matrix3d>& frames, const Step& step)
{
  typedef std::pair<std::size_t, std::size_t> Edge;
  std::map<Edge, std::vector<std::size_t> > edge_tets;
  std::map<std::array<std::size_t, 3>, int> face_count;
  for(std::size_t t = 0; t < tets.size(); ++t) {
    const auto& v = tets[t];
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) edge_tets[{std::min(v[i], v[j]), std::max(v[i], v[j])}].push_back(t);
    for(int i = 0; i < 4; ++i) {
      std::array<std::size_t, 3> f;
      int k = 0;
      for(int j = 0; j < 4; ++j) if(j != i) f[k++] = v[j];
      std::sort(f.begin(), f.end());
      ++face_count[f];
    }
  }
  std::set<std::size_t> boundary_vertices;
  std::set<Edge> boundary_edges;
  for(const auto& fc : face_count)
    if(fc.second == 1) {
      const auto& f = fc.first;
      for(std::size_t v : f) boundary_vertices.insert(v);
      for(int i = 0; i < 3; ++i) boundary_edges.insert({std::min(f[i], f[(i + 1) % 3]), std::max(f[i], f[(i + 1) % 3])});
    }
  auto centroid = [&](std::size_t t) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for(std::size_t v : tets[t]) c += points[v];
    return Eigen::Vector3d(c / 4);
  };
  auto shares_face = [&](std::size_t a, std::size_t b) {
    int common = 0;
    for(std::size_t v : tets[a]) common += int(std::count(tets[b].begin(), tets[b].end(), v));
    return common == 3;
  };
  Field_verdict verdict;
  std::map<std::size_t, std::vector<std::pair<int, double> > > at_vertex; // kind, signed s
  std::vector<Lenient_edge> lenient;
  for(const auto& et : edge_tets) {
    const Edge e = et.first;
    if(boundary_edges.count(e)) continue;
    // order the ring by face adjacency, counter-clockwise about d = p1 - p0
    const std::vector<std::size_t>& ring_set = et.second;
    std::vector<std::size_t> ring = {ring_set[0]};
    std::vector<char> used(ring_set.size(), 0);
    used[0] = 1;
    for(bool grown = true; grown;) {
      grown = false;
      for(std::size_t k = 0; k < ring_set.size(); ++k)
        if(!used[k] && shares_face(ring.back(), ring_set[k])) { ring.push_back(ring_set[k]); used[k] = 1; grown = true; break; }
    }
    const Eigen::Vector3d p0 = points[e.first], d = (points[e.second] - p0).normalized();
    if((centroid(ring[0]) - p0).cross(centroid(ring[1]) - p0).dot(d) < 0) std::reverse(ring.begin() + 1, ring.end());
    // E_t0 ~ E_t0 G with G = g_{m-1,0} ... g_{01}
    Eigen::Matrix3d G = Eigen::Matrix3d::Identity();
    for(std::size_t k = 0; k < ring.size(); ++k) G = step(ring[(k + 1) % ring.size()], ring[k]).transpose() * G;
    // step(b, a) gives E_b ~ E_a g; E_a ~ E_b g^T
    if((G - Eigen::Matrix3d::Identity()).norm() < 1e-9) continue;
    Edge_verdict v;
    v.vertices = {{e.first, e.second}};
    double s = 0;
    Lenient_edge l;
    l.vertices = v.vertices;
    if(std::abs(G.trace() - 1) > 1e-9) {
      v.kind = 0;
      ++verdict.improper;
    } else {
      const Eigen::Vector3d axis = world_axis(frames[ring[0]], G);
      v.axis = axis;
      s = axis.dot(d);
      bool jog_somewhere = false, proper_somewhere = false;
      for(std::size_t j = 0; j < ring.size(); ++j) {
        Eigen::Matrix3d Gj = Eigen::Matrix3d::Identity();
        for(std::size_t k = 0; k < ring.size(); ++k)
          Gj = step(ring[(j + k + 1) % ring.size()], ring[(j + k) % ring.size()]).transpose() * Gj;
        (std::abs(world_axis(frames[ring[j]], Gj).dot(d)) < std::sqrt(0.5) ? jog_somewhere : proper_somewhere) = true;
      }
      verdict.ambiguous += jog_somewhere && proper_somewhere;
      if(std::abs(s) < std::sqrt(0.5)) { v.kind = 1; ++verdict.jogs; }
      else v.kind = s > 0 ? 3 : 5;
      l.axis = axis;
      if(std::abs(s) > 0.25) l.valence = s > 0 ? 3 : 5;
      else l.perpendicular = true;
    }
    lenient.push_back(l);
    verdict.singular.push_back(v);
    for(std::size_t x : {e.first, e.second}) at_vertex[x].push_back({v.kind, s});
  }
  for(const auto& av : at_vertex) {
    if(boundary_vertices.count(av.first)) continue;
    if(av.second.size() == 1) ++verdict.dangling;
    if(av.second.size() == 2 && av.second[0].first >= 3 && av.second[1].first >= 3 && av.second[0].first != av.second[1].first)
      ++verdict.zippers;
  }
  verdict.lenient = lenient_reading(lenient, boundary_vertices);
  return verdict;
}

// From the frames alone: every step is the closest rotation.
inline Field_verdict evaluate_frames(const std::vector<Eigen::Vector3d>& points, const std::vector<std::array<std::size_t, 4> >& tets,
                                     const std::vector<Eigen::Matrix3d>& frames)
{
  return evaluate(points, tets, frames, [&](std::size_t b, std::size_t a) { return closest_rotation(frames[b], frames[a]); });
}

} // namespace independent

#endif // HEXREM_TEST_INDEPENDENT_HOLONOMY_H
