#pragma once
// Lists of names in one string: a candidate's functions ("z; z^2; z^3; z^4"), an lp:<basis>
// technique's, the names an error message lists. Written and read back in one place, so that a
// candidate printed by a sweep is the string `storage --basis` and `candidates:` accept.
#include <string>
#include <string_view>
#include <vector>

namespace mb {

// `names` joined by `separator`: {"a", "b"}, ", " -> "a, b"; {} -> "".
std::string joined(const std::vector<std::string>& names, std::string_view separator);

// `text` split at each character of `separators`, each item trimmed of spaces, empty items
// dropped: "z; z^2 ;" with ";" -> {"z", "z^2"}.
std::vector<std::string> split_list(std::string_view text, std::string_view separators);

}  // namespace mb
