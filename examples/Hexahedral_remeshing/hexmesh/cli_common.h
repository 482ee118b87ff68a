// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// Shared helpers of the hexmesh command-line tool: argument parsing, JSON output, progress.
#ifndef HEXMESH_CLI_COMMON_H
#define HEXMESH_CLI_COMMON_H

#include <CGAL/Hexahedral_remeshing/IO/write_VTK.h>
#include <CGAL/Hexahedral_remeshing/boundary_edge_valences.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
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
// A computation stage failed (exit code EXIT_FAILURE_STAGE).
struct Stage_error : std::runtime_error { using std::runtime_error::runtime_error; };

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
          m_all[name].push_back(argv[i]);
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
  void set(const std::string& name, const std::string& value) { m_values[name] = value; }
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
  // A non-negative integer option in [lo, hi].
  int integer(const std::string& name, int fallback, int lo, int hi) const
  {
    const double d = number(name, fallback);
    if(d < lo || d > hi || d != std::floor(d))
      throw Usage_error("option --" + name + " expects an integer from " + std::to_string(lo) + " to " + std::to_string(hi));
    return int(d);
  }
  const std::vector<std::string>& positional() const { return m_positional; }
  // Every value of an option given several times (e.g. --out A.mesh --out A.inp), in order.
  std::vector<std::string> all(const std::string& name) const
  {
    auto it = m_all.find(name);
    return it == m_all.end() ? std::vector<std::string>() : it->second;
  }

private:
  static bool contains(const std::vector<std::string>& v, const std::string& s)
  {
    for(const std::string& x : v) if(x == s) return true;
    return false;
  }
  std::map<std::string, std::string> m_values;
  std::map<std::string, std::vector<std::string> > m_all;
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
  // An array of arrays of numbers.
  template <class Rows>
  Json& matrix(const std::string& key, const Rows& rows)
  {
    item(key);
    m_out << "[";
    bool first = true;
    for(const auto& row : rows) {
      m_out << (first ? "[" : ", [");
      bool first_in_row = true;
      for(const auto& x : row) { m_out << (first_in_row ? "" : ", ") << x; first_in_row = false; }
      m_out << "]";
      first = false;
    }
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

// Prints "hexmesh: stage: 1.23 s" on stderr for stages that take more than a second, and, within a
// long stage, at most one progress note every few seconds.
class Progress
{
public:
  explicit Progress(bool quiet) : m_quiet(quiet) {}
  void start(const std::string& stage)
  {
    m_stage = stage;
    m_start = m_last_note = std::chrono::steady_clock::now();
  }
  double finish()
  {
    const double s = seconds();
    if(!m_quiet && s > 1.0)
      std::cerr << "hexmesh: " << m_stage << ": " << std::fixed << std::setprecision(2) << s << " s\n" << std::defaultfloat;
    return s;
  }
  // Seconds since the stage started.
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count(); }
  // Prints "hexmesh: stage: what (12.3 s)" if the stage runs for more than a second and no note
  // was printed in the last `interval` seconds.
  void note(const std::string& what, double interval = 5.0)
  {
    const auto now = std::chrono::steady_clock::now();
    if(m_quiet || seconds() < 1.0 || std::chrono::duration<double>(now - m_last_note).count() < interval) return;
    m_last_note = now;
    std::cerr << "hexmesh: " << m_stage << ": " << what << " (" << std::fixed << std::setprecision(1) << seconds()
              << " s)\n" << std::defaultfloat;
  }
private:
  bool m_quiet;
  std::string m_stage;
  std::chrono::steady_clock::time_point m_start, m_last_note;
};

// "k: n, k: n" of a valence histogram, "none" if empty.
inline std::string valence_list(const std::map<int, std::size_t>& h)
{
  std::ostringstream s;
  bool first = true;
  for(const auto& kv : h) { s << (first ? "" : ", ") << kv.first << ": " << kv.second; first = false; }
  return first ? std::string("none") : s.str();
}

// The --heuristic option (default low_angle).
inline CGAL::Hexahedral_remeshing::Valence_heuristic heuristic_option(const Arguments& args)
{
  CGAL::Hexahedral_remeshing::Valence_heuristic heuristic = CGAL::Hexahedral_remeshing::Valence_heuristic::LOW_ANGLE;
  if(args.has("heuristic") && !CGAL::Hexahedral_remeshing::parse_valence_heuristic(args.value("heuristic"), heuristic))
    throw Usage_error("unknown heuristic '" + args.value("heuristic") +
                      "' (expected geometric, low_angle, ambiguous or cap_two)");
  return heuristic;
}

// The output files of a command: checked for writability before any computation (so that a long
// run does not end with "cannot open file"), then written one by one, each atomically; if one
// cannot be written, those already written by this command are removed: no partial set of outputs.
class Output_files
{
public:
  // Registers an output file; throws Usage_error (exit 2) if two outputs share a path, Error (exit 5)
  // naming it if it cannot be written (a directory, a missing or read-only directory, a read-only file).
  // Nothing is created or removed here.
  void add(const std::string& filename)
  {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(filename, ec);
    for(const std::string& other : m_registered)
      if(fs::weakly_canonical(other, ec) == canonical)
        throw Usage_error("two outputs are the same file: " + filename);
    m_registered.push_back(filename);
    const fs::file_status status = fs::status(filename, ec);
    if(fs::is_directory(status)) throw CGAL::Hexahedral_remeshing::Error(filename + ": is a directory, not a file");
    if(fs::exists(status)) {
      if(::access(filename.c_str(), W_OK) != 0)
        throw CGAL::Hexahedral_remeshing::Error(filename + ": cannot open file for writing (permission denied)");
      if(!fs::is_regular_file(status)) return; // a device or a FIFO is written directly
    }
    fs::path dir = canonical.parent_path();
    if(dir.empty()) dir = ".";
    if(!fs::is_directory(dir, ec) || ::access(dir.c_str(), W_OK) != 0)
      throw CGAL::Hexahedral_remeshing::Error(filename + ": cannot open file for writing (no writable directory " +
                                              dir.string() + ")");
  }
  // Runs `write` (which writes `filenames`); on failure removes every file written so far.
  void write(const std::vector<std::string>& filenames, const std::function<void()>& write)
  {
    try {
      write();
    } catch(...) {
      for(const std::string& f : m_written) std::remove(f.c_str());
      m_written.clear();
      throw;
    }
    m_written.insert(m_written.end(), filenames.begin(), filenames.end());
  }
private:
  std::vector<std::string> m_written, m_registered;
};

} // namespace hexmesh

#endif // HEXMESH_CLI_COMMON_H
