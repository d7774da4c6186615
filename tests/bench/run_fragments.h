#pragma once
// The fragments of the LP runs the benchmarks time (bench_runs.h), apart from the scene that made
// them: each fragment's kernel distribution, z_f - delta_f and warm-start place. Written to a file
// by lp_runs_dump and read back by lp_replay, which links the LP engine alone, so that
// scripts/check_isa_builds.sh compiles only lp/ (and what it reads) for other -march targets.
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "eval/warm_runs.h"
#include "lp/problem.h"
#include "lp/solution.h"
#include "util/error.h"

namespace mb::bench {

struct RunFragment {
  int layer = 0, x = 0, y = 0;  // the warm start's lane and place (eval/warm_runs.h)
  double zf = 0;
  std::vector<double> depths, weights;  // the kernel's depth distribution
};
using FragmentRuns = std::vector<std::vector<RunFragment>>;

struct Run {
  std::vector<lp::Problem> problems;
  std::vector<lp::WarmStart> positions;
};

// The sweep's atom map for its 9 x 9 kernel (eval/warm_runs.h).
inline const KernelAtomMap& atom_map() {
  static const KernelAtomMap map(9);
  return map;
}

// The runs' LPs for one basis and grid, built as the sweep builds them.
inline std::vector<Run> build_runs(const FragmentRuns& fragments,
                                   const std::vector<std::string>& functions, int grid) {
  lp::ProblemFactory factory(Basis::parse(functions), lp::Discretization{0, 1, grid, false});
  std::vector<Run> out;
  for (const auto& list : fragments) {
    Run run;
    for (const RunFragment& f : list) {
      run.problems.push_back(factory.from_distribution(f.depths, f.weights, f.zf));
      run.positions.push_back(warm_start_at(f.layer, f.x, f.y, &atom_map()));
    }
    out.push_back(std::move(run));
  }
  return out;
}

namespace detail {
template <typename T>
void put(std::ofstream& out, const T& value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}
template <typename T>
T get(std::ifstream& in, const std::string& path) {
  T value{};
  if (!in.read(reinterpret_cast<char*>(&value), sizeof(T)))
    throw InputError(path + ": truncated run file");
  return value;
}
constexpr uint64_t kMagic = 0x31534e5552424d00ull;  // "\0MBRUNS1", little-endian
}  // namespace detail

// Native byte order: the file is read back on the machine that wrote it.
inline void write_fragment_runs(const std::string& path, const FragmentRuns& runs) {
  std::ofstream out(path, std::ios::binary);
  detail::put(out, detail::kMagic);
  detail::put(out, uint64_t(runs.size()));
  for (const auto& list : runs) {
    detail::put(out, uint64_t(list.size()));
    for (const RunFragment& f : list) {
      for (int v : {f.layer, f.x, f.y}) detail::put(out, int32_t(v));
      detail::put(out, f.zf);
      detail::put(out, uint64_t(f.depths.size()));
      for (double d : f.depths) detail::put(out, d);
      for (double w : f.weights) detail::put(out, w);
    }
  }
  if (!out) throw InputError(path + ": cannot write the run file");
}

inline FragmentRuns read_fragment_runs(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the run file");
  if (detail::get<uint64_t>(in, path) != detail::kMagic)
    throw InputError(path + ": not a run file of lp_runs_dump");
  FragmentRuns runs(detail::get<uint64_t>(in, path));
  for (auto& list : runs) {
    list.resize(detail::get<uint64_t>(in, path));
    for (RunFragment& f : list) {
      f.layer = detail::get<int32_t>(in, path);
      f.x = detail::get<int32_t>(in, path);
      f.y = detail::get<int32_t>(in, path);
      f.zf = detail::get<double>(in, path);
      const size_t n = detail::get<uint64_t>(in, path);
      f.depths.resize(n), f.weights.resize(n);
      for (double& d : f.depths) d = detail::get<double>(in, path);
      for (double& w : f.weights) w = detail::get<double>(in, path);
    }
  }
  return runs;
}

}  // namespace mb::bench
