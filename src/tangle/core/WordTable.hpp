#pragma once
/// @file WordTable.hpp
/// The whitespace-separated text tables of data files (MoorDyn's SeafloorFile, its 4D current grid): rows of
/// words with their line numbers, blank lines skipped, and finite numbers read from them with the file, line
/// and column named in the error.

#include <string>
#include <vector>

namespace tangle::core {

/// One non-blank line of a data file.
struct WordRow {
  int line = 0;                    ///< 1-based line in the file
  std::vector<std::string> words;  ///< its whitespace-separated words
};

/// A data file as rows of words.
class WordTable {
 public:
  /// Reads `path`. @throws tangle::InputError (key `what`) when it cannot be opened
  WordTable(std::string path, const std::string& what);

  const std::string& path() const { return m_path; }
  const std::vector<WordRow>& rows() const { return m_rows; }
  std::size_t size() const { return m_rows.size(); }

  /// Word `column` of row `row` as a finite number. @throws tangle::InputError naming `key`, the row's line
  /// and the word (or that the row has too few words)
  double number(std::size_t row, std::size_t column, const std::string& key) const;
  /// As number(), a whole number within [lo, hi], range-checked before it becomes an integer.
  std::size_t count(std::size_t row, std::size_t column, const std::string& key, double lo, double hi) const;
  /// Row `row`'s words `0..n-1` as numbers that increase strictly (a grid's ticks); exactly n words.
  std::vector<double> ticks(std::size_t row, std::size_t n, const std::string& key) const;

 private:
  std::string m_path;
  std::vector<WordRow> m_rows;
};

}  // namespace tangle::core
