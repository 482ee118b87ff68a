// Timing helpers shared by the benchmarks.
#ifndef HEXREM_BENCHMARK_TIMING_H
#define HEXREM_BENCHMARK_TIMING_H

#include <algorithm>
#include <chrono>
#include <vector>

inline double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

inline double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

#endif // HEXREM_BENCHMARK_TIMING_H
