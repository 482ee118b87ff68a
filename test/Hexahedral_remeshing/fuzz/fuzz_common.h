// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// Shared body of the fuzz targets of the file readers: read the bytes as a file of the format,
// build the tetrahedral mesh (with and without the barycentric split), compute its statistics and
// check the invariants every later stage relies on. Input_error (including Unsupported_input) is
// the only accepted failure: any other exception, crash, sanitizer report, hang or leak is a bug.
#ifndef HEXREM_FUZZ_COMMON_H
#define HEXREM_FUZZ_COMMON_H

#include <CGAL/Hexahedral_remeshing/build_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/mesh_statistics.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace hexrem_fuzz {

namespace HR = CGAL::Hexahedral_remeshing;
typedef HR::Tetrahedral_mesh_3<> Mesh;
typedef Mesh::Point_3 Point;
typedef Mesh::Index Index;

inline void check(bool ok, const char* what)
{
  if(ok) return;
  std::fprintf(stderr, "hexrem fuzz: invariant violated: %s\n", what);
  std::abort();
}

inline void check_mesh(const Mesh& m)
{
  check(m.number_of_tetrahedra() > 0, "at least one tetrahedron");
  for(Index t = 0; t < m.number_of_tetrahedra(); ++t) {
    const auto& v = m.tetrahedron_vertices(t);
    check(CGAL::orientation(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])) == CGAL::POSITIVE,
          "tetrahedra positively oriented");
    for(int i = 0; i < 4; ++i) {
      const auto& ft = m.face_tetrahedra(m.tetrahedron_face(t, i));
      check(ft[0] == t || ft[1] == t, "face of a tetrahedron lists the tetrahedron");
    }
  }
  check(3 * m.number_of_boundary_triangles() == 2 * m.boundary_edges().size(), "closed boundary: 3 F = 2 E");
  check(m.boundary_euler_characteristic() % 2 == 0, "even Euler characteristic of a closed surface");
  for(Index e = 0; e < m.number_of_edges(); ++e) {
    const std::size_t ring = m.edge_ring(e).size(), faces = m.edge_ring_faces(e).size();
    check(ring > 0, "non-empty edge ring");
    check(faces == ring + (m.is_boundary_edge(e) ? 1 : 0), "ring faces");
  }
  for(Index b = 0; b < m.number_of_boundary_triangles(); ++b)
    for(int i = 0; i < 3; ++i) check(m.boundary_triangle_neighbor(b, i) != Mesh::null_index, "boundary neighbour");
  const HR::Mesh_statistics s = HR::compute_mesh_statistics(m);
  std::size_t classes = 0;
  for(std::size_t k : s.dihedral_class_histogram) classes += k;
  check(classes == s.boundary_edges, "every boundary edge has a class");
}

// Builds the mesh of a soup the reader accepted (twice: with and without the split).
inline void build_and_check(const HR::Tetrahedral_soup_3<Point>& soup)
{
  for(bool split : {true, false}) {
    Mesh mesh;
    try {
      HR::build_tetrahedral_mesh(soup, mesh, HR::parameters::split_multi_boundary_tetrahedra(split));
    } catch(const HR::Input_error& e) {
      // the builder's messages never quote the input text: "internal error" is a broken invariant
      check(e.problem().compare(0, 14, "internal error") != 0, "no internal error");
      continue;
    }
    check_mesh(mesh);
  }
}

// Runs `read(text, source, soup)` then builds; returns 0 as libFuzzer expects.
template <class Reader>
int fuzz_one_input(const std::uint8_t* data, std::size_t size, const char* source, const Reader& read)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  HR::Tetrahedral_soup_3<Point> soup;
  try {
    read(text, std::string(source), soup);
  } catch(const HR::Input_error&) {
    return 0;
  }
  build_and_check(soup);
  return 0;
}

} // namespace hexrem_fuzz

#endif // HEXREM_FUZZ_COMMON_H
