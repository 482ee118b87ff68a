// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_EXCEPTIONS_H
#define CGAL_HEXAHEDRAL_REMESHING_EXCEPTIONS_H

#include <cstddef>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// Base class of every exception thrown by the package.
class Error : public std::runtime_error
{
public:
  /// An error with the complete message `what`.
  explicit Error(const std::string& what) : std::runtime_error(what) {}
};

/// \ingroup PkgHexahedralRemeshingRef
/// Thrown when an input (a file, a soup of tetrahedra, a C3t3, a surface, a parameter) is defective.
/// The message names the source (file name or `"<memory>"`), the line or the element when known,
/// and the problem, for example `part.vtk:1204: malformed number 'x.5'` or
/// `part.vtk: tetrahedron 17: degenerate (zero volume)`.
class Input_error : public Error
{
public:
  /// `line` is 1-based, 0 when unknown.
  Input_error(const std::string& source, std::size_t line, const std::string& problem)
    : Error(compose(source, line, problem)), m_source(source), m_line(line), m_problem(problem)
  {}
  /// The file name, or `"<memory>"` for in-memory inputs.
  const std::string& source() const { return m_source; }
  /// The 1-based line of the file where the problem was found, 0 if not applicable.
  std::size_t line() const { return m_line; }
  /// The problem without the location prefix.
  const std::string& problem() const { return m_problem; }

private:
  static std::string compose(const std::string& source, std::size_t line, const std::string& problem)
  {
    std::string s = source.empty() ? std::string("<memory>") : source;
    if(line > 0) s += ":" + std::to_string(line);
    return s + ": " + problem;
  }
  std::string m_source;
  std::size_t m_line;
  std::string m_problem;
};

/// \ingroup PkgHexahedralRemeshingRef
/// Thrown when an input is valid but uses a feature the package does not support (binary VTK, ...).
class Unsupported_input : public Input_error
{
public:
  using Input_error::Input_error;
};

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_EXCEPTIONS_H
