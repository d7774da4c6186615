#pragma once
// Where the tool's own files are (datasets, scenes, meshes, plot scripts): the tree laid out as
// the repository's configs/, data/ and scripts/. Found, in order, at $MOMENTBENCH_HOME; at
// <prefix>/share/momentbench beside an installed binary (<prefix>/bin/momentbench); in the source
// tree the binary was built from. So a binary runs from any directory, installed or not
// (docs/design.md §Layout).
#include <filesystem>
#include <string>
#include <vector>

namespace mb {

// The root that holds configs/datasets; InputError naming every place tried when none does.
std::filesystem::path data_root();
// Runs `program` with `arguments` (no shell), its standard output discarded when `quiet`; returns
// its exit status (127 when it cannot be started).
int run_program(const std::string& program, const std::vector<std::string>& arguments, bool quiet);

}  // namespace mb
