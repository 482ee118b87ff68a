// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_READ_HEXEX_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_READ_HEXEX_H

#include <CGAL/Hexahedral_remeshing/Integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/internal/text_tokenizer.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <istream>
#include <sstream>
#include <string>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace IO {

namespace internal_hexex_reader {

// A decimal number or a rational `p/q` (MC3D writes exact rationals this way); both must be finite.
inline double number(Hexahedral_remeshing::internal::Text_tokenizer& tk, const char* what)
{
  const std::string t = tk.next(what);
  const std::size_t slash = t.find('/');
  auto parse = [&](const std::string& s) {
    char* end = nullptr;
    errno = 0;
    const double d = std::strtod(s.c_str(), &end);
    if(s.empty() || end != s.c_str() + s.size()) tk.fail("malformed number '" + t + "' in " + what);
    return d;
  };
  double d;
  if(slash == std::string::npos) {
    d = parse(t);
  } else {
    const double p = parse(t.substr(0, slash)), q = parse(t.substr(slash + 1));
    if(q == 0.) tk.fail("zero denominator in '" + t + "' in " + what);
    d = p / q;
  }
  if(!std::isfinite(d)) tk.fail("non-finite number '" + t + "' in " + what);
  return d;
}

} // namespace internal_hexex_reader

/// \ingroup PkgHexahedralRemeshingRef
/// Reads an integer-grid map in libHexEx's `.hexex` text format (Lyon, Bommes, Kobbelt 2016):
/// line 1 the vertex count `n`, `n` lines `x y z`, the tetrahedron count `m`, `m` lines
/// `i0 i1 i2 i3 u0 v0 w0 u1 v1 w1 u2 v2 w2 u3 v3 w3` (0-based vertex ids, then the parameters of each
/// corner in that tetrahedron's own chart). Numbers are decimal or rationals `p/q` (as MC3D writes
/// them). The optional trailing feature block of MC3D (`n_fv n_fe n_ff`, then vertex ids, vertex pairs,
/// vertex triples) is checked and skipped. `map.transitions` is left empty (they are implicit in the
/// format); `map.source` is set to `source`.
///
/// A count larger than what the rest of the text can hold is rejected before anything is allocated.
/// \param in the stream to read (read completely)
/// \param source the name used in error messages
/// \param map the output (overwritten)
/// \throws Input_error (source, line, problem) for a truncated file, a malformed, NaN or infinite
///         number, a negative or oversized count, a vertex id out of range, a tetrahedron with a
///         repeated vertex, or trailing garbage.
inline void read_HexEx(std::istream& in, const std::string& source, Integer_grid_map& map)
{
  std::ostringstream ss;
  ss << in.rdbuf();
  if(in.bad()) throw Input_error(source, 0, "read error");
  const std::string text = ss.str();
  Hexahedral_remeshing::internal::Text_tokenizer tk(text, source);
  using internal_hexex_reader::number;

  map = Integer_grid_map();
  map.source = source;
  if(tk.at_end()) tk.fail("empty file");
  const std::size_t n = tk.next_count("the vertex count", 3);
  map.points.reserve(n);
  for(std::size_t i = 0; i < n; ++i) {
    const double x = number(tk, "a vertex"), y = number(tk, "a vertex"), z = number(tk, "a vertex");
    map.points.emplace_back(x, y, z);
  }
  const std::size_t m = tk.next_count("the tetrahedron count", 16);
  map.tetrahedra.reserve(m);
  map.parameters.reserve(m);
  for(std::size_t t = 0; t < m; ++t) {
    std::array<std::uint32_t, 4> tet;
    for(int k = 0; k < 4; ++k) {
      const long long id = tk.next_integer("a tetrahedron");
      if(id < 0 || std::size_t(id) >= n)
        tk.fail("tetrahedron " + std::to_string(t) + ": vertex id " + std::to_string(id) + " out of range [0, " +
                std::to_string(n) + ")");
      tet[k] = std::uint32_t(id);
    }
    for(int a = 0; a < 4; ++a)
      for(int b = a + 1; b < 4; ++b)
        if(tet[a] == tet[b])
          tk.fail("tetrahedron " + std::to_string(t) + ": repeated vertex " + std::to_string(tet[a]));
    std::array<Eigen::Vector3d, 4> uvw;
    for(int k = 0; k < 4; ++k)
      for(int c = 0; c < 3; ++c) uvw[k][c] = number(tk, "the parameters of a tetrahedron");
    map.tetrahedra.push_back(tet);
    map.parameters.push_back(uvw);
  }
  if(tk.at_end()) return;
  // MC3D's optional feature block: feature vertices, edges and faces (ids only).
  const std::size_t nfv = tk.next_count("the feature vertex count", 1);
  const std::size_t nfe = tk.next_count("the feature edge count", 2);
  const std::size_t nff = tk.next_count("the feature face count", 3);
  auto id = [&](const char* what) {
    const long long v = tk.next_integer(what);
    if(v < 0 || std::size_t(v) >= n) tk.fail(std::string(what) + ": vertex id " + std::to_string(v) + " out of range");
  };
  for(std::size_t i = 0; i < nfv; ++i) id("a feature vertex");
  for(std::size_t i = 0; i < 2 * nfe; ++i) id("a feature edge");
  for(std::size_t i = 0; i < 3 * nff; ++i) id("a feature face");
  if(!tk.at_end()) tk.fail("unexpected content after the tetrahedra: '" + tk.next("content") + "'");
}

/// \ingroup PkgHexahedralRemeshingRef
/// Reads the `.hexex` file `file` into `map` (see the stream overload for the format and the errors).
/// \throws Input_error if the file cannot be opened or is defective.
inline void read_HexEx(const std::string& file, Integer_grid_map& map)
{
  const std::string text = Hexahedral_remeshing::internal::Text_tokenizer::read_file(file);
  std::istringstream in(text);
  read_HexEx(in, file, map);
}

} // namespace IO
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_IO_READ_HEXEX_H
