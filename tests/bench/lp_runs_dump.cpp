// Writes the fragments of lp_bench's runs (bench_runs.h) to a file, for lp_replay:
//   lp_runs_dump FILE
#include <cstdio>
#include <exception>

#include "bench_runs.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: lp_runs_dump FILE\n");
    return 2;
  }
  try {
    mb::bench::write_fragment_runs(argv[1], mb::bench::fragment_runs());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lp_runs_dump: %s\n", e.what());
    return 1;
  }
  return 0;
}
