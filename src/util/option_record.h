#pragma once
// Options declared once and bound to a field (after HiGHS' option records): a record is an
// OptionSpec (key, type, default, range, doc) and the member of a settings struct it fills. A
// command's table is a list of records; read_options fills the struct from a resolved Config, so
// code reads typed fields and the key is written only in its record.
#include <cstdint>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "util/config.h"

namespace mb {

template <class S>
struct OptionRecord {
  OptionSpec spec;
  std::variant<int S::*, int64_t S::*, uint64_t S::*, double S::*, bool S::*, std::string S::*,
               std::vector<std::string> S::*, std::vector<double> S::*, std::vector<int64_t> S::*>
      field;
};

template <class S>
std::vector<OptionSpec> option_specs(const std::vector<OptionRecord<S>>& records) {
  std::vector<OptionSpec> specs;
  for (const auto& r : records) specs.push_back(r.spec);
  return specs;
}

// GCC 12 instantiates every alternative of `field` against S and, for a settings struct smaller
// than a std::string (one bool), warns that the alternatives never taken would read out of its
// bounds (-Warray-bounds). Only the alternative the variant holds runs.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Warray-bounds"
#endif
// The value of `key` from `config` into `settings.*member`, whichever member pointer the variant
// `field` holds (a record's, or another table's bound to the same kinds of fields).
template <class S, class Field>
void read_option(const Config& config, const std::string& key, const Field& field, S& settings) {
  std::visit(
      [&](auto member) {
        using T = std::remove_reference_t<decltype(settings.*member)>;
        if constexpr (std::is_same_v<T, bool>)
          settings.*member = config.boolean(key);
        else if constexpr (std::is_integral_v<T>)
          settings.*member = T(config.integer(key));
        else if constexpr (std::is_same_v<T, double>)
          settings.*member = config.number(key);
        else if constexpr (std::is_same_v<T, std::string>)
          settings.*member = config.string(key);
        else if constexpr (std::is_same_v<T, std::vector<std::string>>)
          settings.*member = config.strings(key);
        else if constexpr (std::is_same_v<T, std::vector<double>>)
          settings.*member = config.numbers(key);
        else
          settings.*member = config.integers(key);
      },
      field);
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

// Every record's value from `config` into its field of `settings`.
template <class S>
void read_options(const Config& config, const std::vector<OptionRecord<S>>& records, S& settings) {
  for (const auto& r : records) read_option(config, r.spec.name, r.field, settings);
}

// Fills `settings` with its records' defaults, parsed from the records' text (the only place a
// default is written): what a settings struct made without a config (a test, a library caller)
// holds.
template <class S>
void read_defaults(const std::vector<OptionRecord<S>>& records, S& settings) {
  read_options(Config(option_specs(records)), records, settings);
}

}  // namespace mb
