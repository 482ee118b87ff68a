// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// Shared helpers of the hexmesh command-line tool: argument parsing, JSON output, progress.
#ifndef HEXMESH_CLI_COMMON_H
#define HEXMESH_CLI_COMMON_H

#include <CGAL/Hexahedral_remeshing/IO/write_VTK.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace hexmesh {

// Exit codes: documented in `hexmesh --help`.
enum Exit_code { EXIT_OK = 0, EXIT_USAGE = 2, EXIT_INPUT = 3, EXIT_FAILURE_STAGE = 4, EXIT_OUTPUT = 5 };

struct Usage_error : std::runtime_error { using std::runtime_error::runtime_error; };

// Options of a subcommand: positional arguments and --name [value] pairs.
class Arguments
{
public:
  Arguments(int argc, char** argv, int first, const std::vector<std::string>& flags_with_value,
            const std::vector<std::string>& flags_without_value)
  {
    for(int i = first; i < argc; ++i) {
      const std::string a = argv[i];
      if(a.size() > 2 && a.compare(0, 2, "--") == 0) {
        const std::string name = a.substr(2);
        if(contains(flags_with_value, name)) {
          if(i + 1 >= argc) throw Usage_error("option --" + name + " needs a value");
          m_values[name] = argv[++i];
        } else if(contains(flags_without_value, name)) {
          m_values[name] = "";
        } else {
          throw Usage_error("unknown option " + a);
        }
      } else {
        m_positional.push_back(a);
      }
    }
  }
  bool has(const std::string& name) const { return m_values.count(name) != 0; }
  std::string value(const std::string& name, const std::string& fallback = std::string()) const
  {
    auto it = m_values.find(name);
    return it == m_values.end() ? fallback : it->second;
  }
  double number(const std::string& name, double fallback) const
  {
    if(!has(name)) return fallback;
    const std::string v = value(name);
    char* end = nullptr;
    const double d = std::strtod(v.c_str(), &end);
    if(v.empty() || end != v.c_str() + v.size() || !std::isfinite(d))
      throw Usage_error("option --" + name + " expects a number, got '" + v + "'");
    return d;
  }
  const std::vector<std::string>& positional() const { return m_positional; }

private:
  static bool contains(const std::vector<std::string>& v, const std::string& s)
  {
    for(const std::string& x : v) if(x == s) return true;
    return false;
  }
  std::map<std::string, std::string> m_values;
  std::vector<std::string> m_positional;
};

// Minimal JSON writer (objects, numbers, strings, arrays of numbers), keys in insertion order.
class Json
{
public:
  Json& begin(const std::string& key = std::string()) { item(key); m_out << "{"; m_first = true; return *this; }
  Json& end() { m_out << "}"; m_first = false; return *this; }
  Json& value(const std::string& key, double v)
  {
    item(key);
    if(std::isfinite(v)) m_out << std::setprecision(12) << v; else m_out << "null";
    return *this;
  }
  Json& value(const std::string& key, long long v) { item(key); m_out << v; return *this; }
  Json& value(const std::string& key, std::size_t v) { item(key); m_out << v; return *this; }
  Json& value(const std::string& key, int v) { item(key); m_out << v; return *this; }
  Json& value(const std::string& key, bool v) { item(key); m_out << (v ? "true" : "false"); return *this; }
  Json& value(const std::string& key, const std::string& v) { item(key); m_out << quote(v); return *this; }
  Json& value(const std::string& key, const char* v) { return value(key, std::string(v)); }
  template <class Range>
  Json& array(const std::string& key, const Range& r)
  {
    item(key);
    m_out << "[";
    bool first = true;
    for(const auto& x : r) { m_out << (first ? "" : ", ") << x; first = false; }
    m_out << "]";
    return *this;
  }
  std::string str() const { return m_out.str() + "\n"; }

  void write(const std::string& filename) const
  {
    const std::string s = str();
    CGAL::Hexahedral_remeshing::IO::write_file_atomically(filename, [&](std::ostream& out) { out << s; });
  }

private:
  void item(const std::string& key)
  {
    if(!m_first) m_out << ", ";
    m_first = false;
    if(!key.empty()) m_out << quote(key) << ": ";
  }
  static std::string quote(const std::string& s)
  {
    std::string q = "\"";
    for(char c : s) {
      if(c == '"' || c == '\\') { q += '\\'; q += c; }
      else if(c == '\n') q += "\\n";
      else if(static_cast<unsigned char>(c) < 0x20) q += ' ';
      else q += c;
    }
    return q + "\"";
  }
  std::ostringstream m_out;
  bool m_first = true;
};

// Prints "stage... done (1.23 s)" on stderr for stages that take more than a second.
class Progress
{
public:
  explicit Progress(bool quiet) : m_quiet(quiet) {}
  void start(const std::string& stage) { m_stage = stage; m_start = std::chrono::steady_clock::now(); }
  double finish()
  {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    if(!m_quiet && s > 1.0) std::cerr << "hexmesh: " << m_stage << ": " << std::fixed << std::setprecision(2) << s << " s\n";
    return s;
  }
private:
  bool m_quiet;
  std::string m_stage;
  std::chrono::steady_clock::time_point m_start;
};

} // namespace hexmesh

#endif // HEXMESH_CLI_COMMON_H
