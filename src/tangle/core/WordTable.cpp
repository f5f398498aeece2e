/// @file WordTable.cpp
#include "tangle/core/WordTable.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "tangle/core/Error.hpp"

namespace tangle::core {

WordTable::WordTable(std::string path, const std::string& what) : m_path(std::move(path)) {
  std::ifstream in(m_path);
  if (!in) throw InputError(m_path, 0, what, "a readable file; it cannot be opened");
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    std::istringstream words(text);
    WordRow row{line, {}};
    for (std::string w; words >> w;) row.words.push_back(w);
    if (!row.words.empty()) m_rows.push_back(std::move(row));
  }
}

double WordTable::number(std::size_t row, std::size_t column, const std::string& key) const {
  const WordRow& r = m_rows.at(row);
  if (column >= r.words.size())
    throw InputError(m_path, r.line, key,
                     fmt::format("at least {} numbers on the line, got {}", column + 1, r.words.size()));
  const std::string& w = r.words[column];
  char* end = nullptr;
  const double v = std::strtod(w.c_str(), &end);
  if (end == w.c_str() || *end != '\0' || !std::isfinite(v))
    throw InputError(m_path, r.line, key, "a finite number, got '" + w + "'");
  return v;
}

std::size_t WordTable::count(std::size_t row, std::size_t column, const std::string& key, double lo,
                             double hi) const {
  const double v = number(row, column, key);
  // Range-checked before it becomes an integer (no undefined conversion of 1e84).
  if (!(v >= lo && v <= hi) || v != std::floor(v))
    throw InputError(
        m_path, m_rows[row].line, key,
        fmt::format("a whole number from {} to {}, got '{}'", lo, hi, m_rows[row].words[column]));
  return static_cast<std::size_t>(v);
}

std::vector<double> WordTable::ticks(std::size_t row, std::size_t n, const std::string& key) const {
  const WordRow& r = m_rows.at(row);
  if (r.words.size() != n)
    throw InputError(m_path, r.line, key,
                     fmt::format("{} ticks (as the first line says), got {}", n, r.words.size()));
  std::vector<double> t;
  for (std::size_t c = 0; c < n; ++c) t.push_back(number(row, c, key));
  for (std::size_t c = 1; c < n; ++c)
    if (!(t[c] > t[c - 1]))
      throw InputError(m_path, r.line, key, fmt::format("increasing ticks; {} follows {}", t[c], t[c - 1]));
  return t;
}

}  // namespace tangle::core
