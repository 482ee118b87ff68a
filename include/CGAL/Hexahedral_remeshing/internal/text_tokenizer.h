// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_TEXT_TOKENIZER_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_TEXT_TOKENIZER_H

#include <CGAL/Hexahedral_remeshing/exceptions.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Whitespace-separated tokens of a text file with the line each comes from, so that every parse
// error names the file and the line. Windows line ends are accepted ('\r' is whitespace).
class Text_tokenizer
{
public:
  Text_tokenizer(const std::string& text, const std::string& source)
    : m_text(text), m_source(source) {}

  static std::string read_file(const std::string& filename)
  {
    std::error_code ec;
    if(std::filesystem::is_directory(filename, ec)) throw Input_error(filename, 0, "is a directory, not a file");
    std::ifstream in(filename, std::ios::binary);
    if(!in) throw Input_error(filename, 0, "cannot open file for reading");
    std::ostringstream ss;
    ss << in.rdbuf();
    if(in.bad()) throw Input_error(filename, 0, "read error");
    return ss.str();
  }

  const std::string& source() const { return m_source; }
  std::size_t line() const { return m_line; }

  // Next token, or an empty string at the end of the text.
  std::string next_or_empty()
  {
    skip_space();
    const std::size_t b = m_pos;
    while(m_pos < m_text.size() && !is_space(m_text[m_pos])) ++m_pos;
    m_token_line = m_line;
    return m_text.substr(b, m_pos - b);
  }

  std::string next(const char* what)
  {
    std::string t = next_or_empty();
    if(t.empty()) fail("unexpected end of file while reading " + std::string(what));
    return t;
  }

  bool at_end()
  {
    skip_space();
    return m_pos >= m_text.size();
  }

  // The rest of the current line (used for titles and comments).
  std::string rest_of_line()
  {
    const std::size_t b = m_pos;
    while(m_pos < m_text.size() && m_text[m_pos] != '\n') ++m_pos;
    std::string s = m_text.substr(b, m_pos - b);
    while(!s.empty() && (s.back() == '\r' || s.back() == ' ')) s.pop_back();
    return s;
  }

  double next_double(const char* what)
  {
    const std::string t = next(what);
    errno = 0;
    char* end = nullptr;
    const double d = std::strtod(t.c_str(), &end);
    if(end != t.c_str() + t.size() || t.empty()) fail("malformed number '" + t + "' in " + what);
    return d; // non-finite values are accepted here and rejected by the mesh checks, with the vertex named
  }

  long long next_integer(const char* what)
  {
    const std::string t = next(what);
    errno = 0;
    char* end = nullptr;
    const long long v = std::strtoll(t.c_str(), &end, 10);
    if(end != t.c_str() + t.size() || t.empty()) fail("malformed integer '" + t + "' in " + what);
    if(errno == ERANGE) fail("integer '" + t + "' out of range in " + what);
    return v;
  }

  // A count of items that must fit in the file: a huge count in a small file is a defect, not a
  // reason to allocate gigabytes.
  std::size_t next_count(const char* what, std::size_t tokens_per_item)
  {
    const long long v = next_integer(what);
    if(v < 0) fail("negative count " + std::to_string(v) + " in " + what);
    const std::size_t remaining = m_text.size() - m_pos;
    if(tokens_per_item > 0 && std::size_t(v) > remaining / (2 * tokens_per_item) + 1)
      fail("count " + std::to_string(v) + " in " + std::string(what) + " exceeds what the file holds (truncated file?)");
    return std::size_t(v);
  }

  [[noreturn]] void fail(const std::string& problem) const
  {
    throw Input_error(m_source, m_token_line, problem);
  }
  [[noreturn]] void unsupported(const std::string& problem) const
  {
    throw Unsupported_input(m_source, m_token_line, problem);
  }

private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
  void skip_space()
  {
    while(m_pos < m_text.size() && is_space(m_text[m_pos])) {
      if(m_text[m_pos] == '\n') ++m_line;
      ++m_pos;
    }
  }

  const std::string& m_text;
  std::string m_source;
  std::size_t m_pos = 0;
  std::size_t m_line = 1;
  std::size_t m_token_line = 1;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_TEXT_TOKENIZER_H
