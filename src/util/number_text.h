#pragma once
// Numbers as text for files a researcher reads back: the shortest decimal that parses to the same
// double (std::to_chars), so CSVs and databases lose nothing and carry no noise digits.
#include <string>

namespace mb {

// 0.1 -> "0.1", 1e-4 -> "0.0001", 2.4 -> "2.4", NaN -> "nan", infinity -> "inf".
std::string round_trip(double value);

// `v` as printf's `format` ("%.3g", "%.5f") prints it, for report tables.
std::string format_number(double v, const char* format);

}  // namespace mb
