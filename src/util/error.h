#pragma once
// Errors that reach the user: every message names where (file, line, key) and what was expected.
#include <stdexcept>
#include <string>
#include <vector>

namespace mb {

// A user-facing error: bad input, bad config, unreadable file. The CLI prints what() and exits 1.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "file:line:col: message" when a location is known; just the message otherwise.
std::string located(const std::string& file, int line, int column, const std::string& message);

// The closest of `candidates` to `word` by edit distance, or "" if none is close enough to be a
// plausible typo. Used for "unknown key 'resolutoin' (did you mean 'resolution'?)".
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace mb
