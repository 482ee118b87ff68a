// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_EDGE_VALENCES_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_EDGE_VALENCES_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/boundary_edge_valences.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK.h>
#include <CGAL/Hexahedral_remeshing/internal/text_tokenizer.h>

#include <cerrno>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace IO {

namespace internal_edge_valences {
inline long long parse_integer(const std::string& token, const std::string& filename, std::size_t line, const char* what)
{
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(token.c_str(), &end, 10);
  if(token.empty() || end != token.c_str() + token.size())
    throw Input_error(filename, line, "malformed integer '" + token + "' for " + what + " (expected lines 'a b k')");
  if(errno == ERANGE) throw Input_error(filename, line, "integer '" + token + "' out of range for " + what);
  return v;
}
} // namespace internal_edge_valences

/// \ingroup PkgHexahedralRemeshingRef
/// Reads prescribed boundary edge valences from a text file with one line `a b k` per edge: `a` and
/// `b` are the 0-based indices, in the input file of `mesh`, of the two vertices of a boundary edge
/// and `k` its valence (1 to 6). `#` starts a comment that runs to the end of the line; empty
/// lines are ignored.
/// The result can be passed as the named parameter `prescribed_edge_valences`.
///
/// \param filename the file to read
/// \param mesh the mesh built from the input file whose vertex indices the file uses
/// \returns the pairs (edge index, valence), in the order of the file
/// \throws Input_error naming the file and the line for: a line that is not three integers, a
///         vertex index that is not a vertex of the input, two vertices that do not form an edge, an
///         interior edge, a valence outside 1..6, an edge given twice with two valences.
template <class Traits>
std::vector<std::pair<typename Tetrahedral_mesh_3<Traits>::Index, int> >
read_edge_valences(const std::string& filename, const Tetrahedral_mesh_3<Traits>& mesh)
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  const std::string text = Hexahedral_remeshing::internal::Text_tokenizer::read_file(filename);
  std::vector<std::pair<Index, int> > result;
  std::map<Index, std::pair<int, std::size_t> > seen; // edge -> (k, line)
  std::istringstream lines(text);
  std::string line;
  std::size_t line_number = 0;
  const long long nv = static_cast<long long>(mesh.number_of_input_vertices());
  while(std::getline(lines, line)) {
    ++line_number;
    const std::size_t hash = line.find('#');
    if(hash != std::string::npos) line.erase(hash);
    std::istringstream tokens(line);
    std::vector<std::string> t;
    std::string tok;
    while(tokens >> tok) t.push_back(tok);
    if(t.empty()) continue;
    if(t.size() != 3)
      throw Input_error(filename, line_number, "expected three integers 'a b k', found " + std::to_string(t.size()) +
                        " fields");
    const long long a = internal_edge_valences::parse_integer(t[0], filename, line_number, "the vertex a");
    const long long b = internal_edge_valences::parse_integer(t[1], filename, line_number, "the vertex b");
    const long long k = internal_edge_valences::parse_integer(t[2], filename, line_number, "the valence k");
    const std::string pair = std::to_string(a) + " " + std::to_string(b);
    for(long long x : {a, b})
      if(x < 0 || x >= nv)
        throw Input_error(filename, line_number, "vertex " + std::to_string(x) + " does not exist (the input has " +
                          std::to_string(nv) + " vertices, numbered from 0)");
    const Index e = (a == b) ? Tetrahedral_mesh_3<Traits>::null_index : mesh.find_edge(Index(a), Index(b));
    if(e == Tetrahedral_mesh_3<Traits>::null_index)
      throw Input_error(filename, line_number, "vertices " + pair + " do not form an edge of the mesh");
    if(!mesh.is_boundary_edge(e))
      throw Input_error(filename, line_number, "edge " + pair + " is not a boundary edge (a valence can only be "
                        "prescribed on the boundary)");
    if(k < minimum_prescribed_valence || k > maximum_prescribed_valence)
      throw Input_error(filename, line_number, "valence " + std::to_string(k) + " of edge " + pair +
                        " is impossible (a boundary edge valence must be between " +
                        std::to_string(minimum_prescribed_valence) + " and " +
                        std::to_string(maximum_prescribed_valence) + ")");
    auto ins = seen.emplace(e, std::make_pair(int(k), line_number));
    if(!ins.second) {
      if(ins.first->second.first != int(k))
        throw Input_error(filename, line_number, "edge " + pair + " was given valence " +
                          std::to_string(ins.first->second.first) + " on line " +
                          std::to_string(ins.first->second.second) + " and now " + std::to_string(k));
      continue;
    }
    result.emplace_back(e, int(k));
  }
  return result;
}

/// \ingroup PkgHexahedralRemeshingRef
/// Writes the valence of every boundary edge in the format of `read_edge_valences()`: a comment
/// line, then one line `a b k` per boundary edge, in increasing edge index (`a`, `b` are the vertex
/// indices of `mesh.edge_vertices()`, which are input indices on the boundary). The file is written
/// atomically.
/// \param filename the output file
/// \param mesh the mesh the valences belong to
/// \param valences valence per edge, as filled by `compute_boundary_edge_valences()`
/// \throws Error if the file cannot be written or `valences` does not have one entry per edge.
template <class Traits>
void write_edge_valences(const std::string& filename, const Tetrahedral_mesh_3<Traits>& mesh,
                         const std::vector<int>& valences)
{
  if(valences.size() != mesh.number_of_edges())
    throw Error(filename + ": " + std::to_string(valences.size()) + " valences for " +
                std::to_string(mesh.number_of_edges()) + " edges");
  write_file_atomically(filename, [&](std::ostream& out) {
    out << "# boundary edge valences: a b k (0-based vertex indices of the input, valence)\n";
    for(auto e : mesh.boundary_edges()) {
      const auto& ev = mesh.edge_vertices(e);
      out << ev[0] << " " << ev[1] << " " << valences[e] << "\n";
    }
  });
}

} // namespace IO
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_IO_EDGE_VALENCES_H
