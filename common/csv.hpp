#pragma once
// CSV (RFC 4180): every CSV file of the grader: the driver's task tables, the front end's
// gradebook and benchmark tables.

#include <string>
#include <string_view>
#include <vector>

namespace fmbd::csv {

// `field` as a CSV field: as it is, or between double quotes (each quote doubled) when it holds
// a comma, a double quote, a line feed or a carriage return.
std::string field(std::string_view text);

// The fields joined by commas, each through field(), ending in "\n".
std::string row(const std::vector<std::string>& fields);

// The fields of one CSV line as row() writes it (quoted fields unquoted, doubled quotes undone);
// a line of a file, without its newline.
std::vector<std::string> split(std::string_view line);

}  // namespace fmbd::csv
