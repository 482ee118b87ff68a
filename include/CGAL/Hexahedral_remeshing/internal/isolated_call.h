// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_ISOLATED_CALL_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_ISOLATED_CALL_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_soup_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/parameters.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <exception>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#define CGAL_HEXAHEDRAL_REMESHING_HAS_FORK 1
#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

namespace CGAL {
namespace Hexahedral_remeshing {

namespace internal_np {
enum time_limit_t { time_limit };
} // namespace internal_np

namespace parameters {
#ifdef DOXYGEN_RUNNING
/// The readers that run gmsh or TetGen (`read_CAD()`, `read_gmsh()`, `tetrahedralize_surface()`,
/// `read_tetrahedral_mesh()`): seconds after which the child process running them is stopped and
/// an `Input_error` says so (`double`, default 0: no limit).
template <class T> unspecified_type time_limit(const T& value);
#else
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(time_limit)
#endif
} // namespace parameters

namespace internal {

// Flat binary encoding of plain values and strings (native byte order: both ends are the same
// process image).
class Byte_writer
{
public:
  template <class T> void put(const T& v)
  {
    const char* p = reinterpret_cast<const char*>(&v);
    m_bytes.append(p, sizeof(T));
  }
  void put_string(const std::string& s)
  {
    put(std::uint64_t(s.size()));
    m_bytes += s;
  }
  std::string& bytes() { return m_bytes; }

private:
  std::string m_bytes;
};

class Byte_reader
{
public:
  explicit Byte_reader(const std::string& bytes) : m_bytes(bytes) {}
  template <class T> T get()
  {
    T v;
    if(m_bytes.size() - m_pos < sizeof(T)) throw Error("internal error: truncated result of an isolated call");
    std::memcpy(&v, m_bytes.data() + m_pos, sizeof(T));
    m_pos += sizeof(T);
    return v;
  }
  std::string get_string()
  {
    const std::uint64_t n = get<std::uint64_t>();
    if(m_bytes.size() - m_pos < n) throw Error("internal error: truncated result of an isolated call");
    std::string s = m_bytes.substr(m_pos, std::size_t(n));
    m_pos += std::size_t(n);
    return s;
  }
  // Number of items of `item_size` bytes that may still be read (bounds a count before allocating).
  std::size_t remaining(std::size_t item_size) const { return (m_bytes.size() - m_pos) / item_size; }

private:
  const std::string& m_bytes;
  std::size_t m_pos = 0;
};

template <class Point>
std::string serialize_soup(const Tetrahedral_soup_3<Point>& soup)
{
  Byte_writer w;
  w.put(std::uint64_t(soup.points.size()));
  for(const Point& p : soup.points)
    for(int i = 0; i < 3; ++i) w.put(double(CGAL::to_double(p[i])));
  w.put(std::uint64_t(soup.tetrahedra.size()));
  for(const auto& t : soup.tetrahedra) for(std::size_t v : t) w.put(std::uint64_t(v));
  w.put(std::uint64_t(soup.triangles.size()));
  for(std::size_t i = 0; i < soup.triangles.size(); ++i) {
    for(std::size_t v : soup.triangles[i]) w.put(std::uint64_t(v));
    w.put(std::int64_t(i < soup.triangle_patches.size() ? soup.triangle_patches[i] : 0));
  }
  w.put(std::uint64_t(soup.feature_edges.size()));
  for(std::size_t i = 0; i < soup.feature_edges.size(); ++i) {
    for(std::size_t v : soup.feature_edges[i]) w.put(std::uint64_t(v));
    w.put(std::int64_t(i < soup.feature_edge_curves.size() ? soup.feature_edge_curves[i] : 0));
  }
  w.put(std::uint64_t(soup.corners.size()));
  for(std::size_t v : soup.corners) w.put(std::uint64_t(v));
  w.put(std::uint64_t(soup.patch_names.size()));
  for(const auto& pn : soup.patch_names) { w.put(std::int64_t(pn.first)); w.put_string(pn.second); }
  return std::move(w.bytes());
}

template <class Point>
void deserialize_soup(const std::string& bytes, Tetrahedral_soup_3<Point>& soup)
{
  Byte_reader r(bytes);
  auto count = [&](std::size_t item_size) {
    const std::uint64_t n = r.get<std::uint64_t>();
    if(n > r.remaining(item_size)) throw Error("internal error: truncated result of an isolated call");
    return std::size_t(n);
  };
  const std::size_t np = count(24);
  soup.points.clear();
  soup.points.reserve(np);
  for(std::size_t i = 0; i < np; ++i) {
    const double x = r.get<double>(), y = r.get<double>(), z = r.get<double>();
    soup.points.push_back(Point(x, y, z));
  }
  const std::size_t nt = count(32);
  soup.tetrahedra.resize(nt);
  for(auto& t : soup.tetrahedra) for(std::size_t& v : t) v = std::size_t(r.get<std::uint64_t>());
  soup.tetrahedron_lines.clear();
  const std::size_t nb = count(32);
  soup.triangles.resize(nb);
  soup.triangle_patches.resize(nb);
  for(std::size_t i = 0; i < nb; ++i) {
    for(std::size_t& v : soup.triangles[i]) v = std::size_t(r.get<std::uint64_t>());
    soup.triangle_patches[i] = int(r.get<std::int64_t>());
  }
  const std::size_t ne = count(24);
  soup.feature_edges.resize(ne);
  soup.feature_edge_curves.resize(ne);
  for(std::size_t i = 0; i < ne; ++i) {
    for(std::size_t& v : soup.feature_edges[i]) v = std::size_t(r.get<std::uint64_t>());
    soup.feature_edge_curves[i] = int(r.get<std::int64_t>());
  }
  const std::size_t nc = count(8);
  soup.corners.resize(nc);
  for(std::size_t& v : soup.corners) v = std::size_t(r.get<std::uint64_t>());
  const std::size_t nn = count(16);
  soup.patch_names.resize(nn);
  for(auto& pn : soup.patch_names) {
    pn.first = int(r.get<std::int64_t>());
    pn.second = r.get_string();
  }
}

// Runs `task` in a child process so that a crash (or an abort, or a stray print) of a third-party
// library on a hostile input cannot take the calling process down, and so that a library with
// global state (gmsh) starts afresh on every call. `task` returns its result as bytes or throws;
// an `Input_error` thrown by `task` is re-thrown here with the same source, line and problem (an
// `Unsupported_input` stays one), any other exception becomes an `Input_error` with its message.
// A child killed by a signal becomes an `Input_error` naming `what` and the signal. A child still
// running after `time_limit` seconds (> 0) is killed, and an `Input_error` says so.
// Where fork() is not available, `task` runs in the calling process (without a time limit).
inline std::string run_isolated(const std::function<std::string()>& task, const std::string& source,
                                const std::string& what, double time_limit = 0)
{
#ifdef CGAL_HEXAHEDRAL_REMESHING_HAS_FORK
  int fds[2];
  if(::pipe(fds) != 0) throw Error("cannot create a pipe to run " + what + ": " + std::strerror(errno));
  const pid_t pid = ::fork();
  if(pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw Error("cannot fork to run " + what + ": " + std::strerror(errno));
  }
  if(pid == 0) {
    ::close(fds[0]);
    // third-party libraries print on the terminal: library code never does
    const int devnull = ::open("/dev/null", O_WRONLY);
    if(devnull >= 0) { ::dup2(devnull, 1); ::dup2(devnull, 2); }
    Byte_writer w;
    try {
      const std::string result = task();
      w.put('O');
      w.bytes() += result;
    } catch(const Unsupported_input& e) {
      w.put('U'); w.put(std::uint64_t(e.line())); w.put_string(e.problem());
    } catch(const Input_error& e) {
      w.put('E'); w.put(std::uint64_t(e.line())); w.put_string(e.problem());
    } catch(const std::exception& e) {
      w.put('X'); w.put(std::uint64_t(0)); w.put_string(e.what());
    } catch(...) {
      w.put('X'); w.put(std::uint64_t(0)); w.put_string("unknown exception");
    }
    const std::string& b = w.bytes();
    std::size_t done = 0;
    while(done < b.size()) {
      const ssize_t k = ::write(fds[1], b.data() + done, b.size() - done);
      if(k < 0 && errno == EINTR) continue;
      if(k <= 0) ::_exit(3);
      done += std::size_t(k);
    }
    ::close(fds[1]);
    ::_exit(0); // no atexit handlers, no static destructors of the libraries
  }
  ::close(fds[1]);
  std::string bytes;
  char buffer[1 << 16];
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(time_limit > 0 ? time_limit : 0.);
  while(true) {
    if(time_limit > 0) {
      const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
      pollfd p{fds[0], POLLIN, 0};
      const int ready = left > 0 ? ::poll(&p, 1, int((std::min)(left * 1000. + 1, 2.0e9))) : 0;
      if(ready < 0 && errno == EINTR) continue;
      if(ready == 0) {
        ::kill(pid, SIGKILL);
        int ignored = 0;
        while(::waitpid(pid, &ignored, 0) < 0 && errno == EINTR) {}
        ::close(fds[0]);
        std::ostringstream limit;
        limit << time_limit;
        throw Input_error(source, 0, what + " did not finish within the time limit of " + limit.str() +
                          " s and was stopped: the input is too large or too fine for it at this size (or makes it loop); "
                          "coarsen it, or raise the limit (named parameter time_limit; hexmesh --time-limit)");
      }
    }
    const ssize_t k = ::read(fds[0], buffer, sizeof(buffer));
    if(k < 0 && errno == EINTR) continue;
    if(k <= 0) break;
    bytes.append(buffer, std::size_t(k));
  }
  ::close(fds[0]);
  int status = 0;
  while(::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
  if(WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    const char* name = sig == SIGSEGV ? "SIGSEGV" : sig == SIGABRT ? "SIGABRT" : sig == SIGFPE ? "SIGFPE"
                     : sig == SIGBUS ? "SIGBUS" : sig == SIGKILL ? "SIGKILL (out of memory?)" : "a signal";
    throw Input_error(source, 0, what + " crashed on this input (" + name + ", signal " + std::to_string(sig) +
                      "); the input is probably defective (self-intersecting, degenerate or overlapping "
                      "parts): repair it and retry");
  }
  if(bytes.empty())
    throw Input_error(source, 0, what + " stopped without a result (exit status " +
                      std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
  const char kind = bytes[0];
  if(kind == 'O') return bytes.substr(1);
  const std::string rest = bytes.substr(1);
  Byte_reader r(rest);
  const std::size_t line = std::size_t(r.get<std::uint64_t>());
  const std::string problem = r.get_string();
  if(kind == 'U') throw Unsupported_input(source, line, problem);
  if(kind == 'X') throw Input_error(source, line, what + " failed: " + problem);
  throw Input_error(source, line, problem);
#else
  try {
    return task();
  } catch(const Input_error&) {
    throw;
  } catch(const std::exception& e) {
    throw Input_error(source, 0, e.what());
  }
#endif
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_ISOLATED_CALL_H
