#pragma once
/// @file Csv.hpp
/// The CSV dialect of tangle's result tables (RFC 4180): a field holding a comma, a quote or a newline is
/// quoted, its quotes doubled (a newline becomes a space); rows end with '\n'.

#include <string>
#include <vector>

namespace tangle::core {

/// `s` as one CSV field.
std::string csvField(const std::string& s);

/// The fields of one CSV row (without its line end), quoted fields unquoted.
std::vector<std::string> splitCsvRow(const std::string& row);

}  // namespace tangle::core
