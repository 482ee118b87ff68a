// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_READ_MEDIT_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_READ_MEDIT_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_soup_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/internal/text_tokenizer.h>

#include <string>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace IO {

namespace internal_medit {

// Tokens per item of the blocks that are skipped (0: not a skipped block).
inline std::size_t tokens_per_item(const std::string& key)
{
  static const char* const names[] = {
    "Quadrilaterals", "Ridges", "RequiredVertices", "RequiredEdges", "RequiredTriangles",
    "RequiredQuadrilaterals", "RequiredTetrahedra", "Normals", "NormalAtVertices",
    "NormalAtTriangleVertices", "NormalAtQuadrilateralVertices", "Tangents", "TangentAtVertices",
    "TangentAtEdges", "VertexOnGeometricVertex", "VertexOnGeometricEdge", "VertexOnGeometricTriangle",
    "EdgeOnGeometricEdge", "TriangleOnGeometricTriangle", "TrianglesP2", "EdgesP2", "QuadrilateralsQ2",
    "SubDomainFromMesh", "SubDomainFromGeom", "Crack"};
  static const std::size_t per[] = {5, 1, 1, 1, 1, 1, 1, 3, 2, 3, 3, 3, 2, 2, 2, 3, 4, 2, 2, 7, 4, 10, 4, 4, 2};
  for(std::size_t i = 0; i < sizeof(per) / sizeof(per[0]); ++i)
    if(key == names[i]) return per[i];
  return 0;
}

} // namespace internal_medit

/// \ingroup PkgHexahedralRemeshingRef
/// Reads a MEDIT ASCII `.mesh` file into `soup`: `Vertices` (x y z ref), `Tetrahedra` (4 indices,
/// 1-based, ref) and `TetrahedraP2` (their 4 corner nodes), and the hints `Triangles` (ref =
/// surface patch), `Edges` (ref = feature curve), `Corners`. The blocks that carry nothing for a
/// tetrahedral mesh are skipped, as the MEDIT manual prescribes: `Quadrilaterals`, `Ridges`,
/// `Required*`, `Normals`, `NormalAt*`, `Tangents`, `TangentAt*`, `Identifier`, `Geometry`,
/// `*OnGeometric*`, `TrianglesP2`, `EdgesP2`, and `#` comments. Non-empty `Hexahedra`, `Prisms`
/// or `Pyramids` blocks are refused with their counts (dropping them would shrink the domain).
///
/// Windows line ends are accepted. A count larger than what the rest of the file can hold is
/// rejected before anything is allocated.
///
/// \param text the content of the file
/// \param source the name of the file, used in error messages
/// \param soup the output (overwritten)
/// \throws Input_error (file, line, problem) for an unreadable, truncated or malformed file, a count
///         larger than the file, an index below 1, volume cells other than tetrahedra;
///         Unsupported_input for an unknown keyword (binary `.meshb` content) or a 2D mesh.
template <class Point>
void read_MEDIT(const std::string& text, const std::string& source, Tetrahedral_soup_3<Point>& soup)
{
  using Hexahedral_remeshing::internal::Text_tokenizer;
  Text_tokenizer tk(text, source);
  soup = Tetrahedral_soup_3<Point>();
  soup.source = source;
  bool have_vertices = false, ended = false;
  std::string other_volume_cells;
  std::size_t first_other_line = 0;

  auto index = [&](const char* what) -> std::size_t {
    const long long v = tk.next_integer(what);
    if(v < 1) tk.fail(std::string("invalid index ") + std::to_string(v) + " in " + what + " (indices are 1-based)");
    return std::size_t(v - 1);
  };

  while(!ended && !tk.at_end()) {
    const std::string key = tk.next("a keyword");
    if(key.empty()) break;
    if(key[0] == '#') { tk.rest_of_line(); continue; }
    if(key == "MeshVersionFormatted") {
      tk.next_integer("MeshVersionFormatted");
    } else if(key == "Dimension") {
      const long long d = tk.next_integer("Dimension");
      if(d != 3) tk.unsupported("only 3D meshes are supported (Dimension " + std::to_string(d) + ")");
    } else if(key == "Vertices") {
      const std::size_t n = tk.next_count("Vertices", 4);
      soup.points.reserve(n);
      for(std::size_t i = 0; i < n; ++i) {
        const double x = tk.next_double("Vertices"), y = tk.next_double("Vertices"), z = tk.next_double("Vertices");
        tk.next_integer("Vertices reference");
        soup.points.push_back(Point(x, y, z));
      }
      have_vertices = true;
    } else if(key == "Tetrahedra") {
      const std::size_t n = tk.next_count("Tetrahedra", 5);
      for(std::size_t i = 0; i < n; ++i) {
        std::array<std::size_t, 4> t;
        for(int k = 0; k < 4; ++k) t[k] = index("Tetrahedra");
        soup.tetrahedron_lines.push_back(tk.line());
        tk.next_integer("Tetrahedra reference");
        soup.tetrahedra.push_back(t);
      }
    } else if(key == "Triangles") {
      const std::size_t n = tk.next_count("Triangles", 4);
      for(std::size_t i = 0; i < n; ++i) {
        std::array<std::size_t, 3> t;
        for(int k = 0; k < 3; ++k) t[k] = index("Triangles");
        soup.triangles.push_back(t);
        soup.triangle_patches.push_back(int(tk.next_integer("Triangles reference")));
      }
    } else if(key == "Edges") {
      const std::size_t n = tk.next_count("Edges", 3);
      for(std::size_t i = 0; i < n; ++i) {
        const std::size_t a = index("Edges"), b = index("Edges");
        soup.feature_edges.push_back({a, b});
        soup.feature_edge_curves.push_back(int(tk.next_integer("Edges reference")));
      }
    } else if(key == "Corners") {
      const std::size_t n = tk.next_count("Corners", 1);
      for(std::size_t i = 0; i < n; ++i) soup.corners.push_back(index("Corners"));
    } else if(key == "TetrahedraP2") {
      // second-order tetrahedra: the four corner nodes come first
      const std::size_t n = tk.next_count("TetrahedraP2", 11);
      for(std::size_t i = 0; i < n; ++i) {
        std::array<std::size_t, 4> t;
        for(int k = 0; k < 4; ++k) t[k] = index("TetrahedraP2");
        soup.tetrahedron_lines.push_back(tk.line());
        for(int k = 4; k < 10; ++k) index("TetrahedraP2");
        tk.next_integer("TetrahedraP2 reference");
        soup.tetrahedra.push_back(t);
      }
    } else if(key == "Hexahedra" || key == "Prisms" || key == "Pyramids" || key == "HexahedraQ2") {
      const std::size_t per = key == "Hexahedra" ? 9 : key == "Prisms" ? 7 : key == "Pyramids" ? 6 : 28;
      const std::size_t n = tk.next_count(key.c_str(), per);
      if(n > 0) {
        other_volume_cells += (other_volume_cells.empty() ? "" : ", ") + std::to_string(n) + " " + key;
        if(first_other_line == 0) first_other_line = tk.line();
      }
      for(std::size_t i = 0; i < n * per; ++i) tk.next_integer(key.c_str());
    } else if(key == "Identifier" || key == "Geometry") {
      // a string (possibly quoted, with spaces)
      std::string w = tk.next(key.c_str());
      if(w[0] == '"')
        while(w.size() < 2 || w.back() != '"') w = tk.next(key.c_str());
    } else if(const std::size_t per = internal_medit::tokens_per_item(key)) {
      // blocks that carry nothing for a tetrahedral mesh (normals, tangents, required entities,
      // quadrilaterals, ridges, links to a geometry): skipped, as the MEDIT manual prescribes
      const std::size_t n = tk.next_count(key.c_str(), per);
      for(std::size_t i = 0; i < n * per; ++i) tk.next(key.c_str());
    } else if(key == "End") {
      ended = true;
    } else {
      tk.unsupported("unsupported MEDIT keyword '" + key + "'");
    }
  }
  if(!have_vertices) tk.fail("no Vertices block");
  if(!other_volume_cells.empty())
    throw Input_error(source, first_other_line, "the mesh has volume cells other than tetrahedra (" + other_volume_cells +
                      ", with " + std::to_string(soup.tetrahedra.size()) + " Tetrahedra); they would be lost and the "
                      "domain would shrink: split them into tetrahedra and retry");
}

} // namespace IO
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_IO_READ_MEDIT_H
