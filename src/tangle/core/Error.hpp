#pragma once
/// @file Error.hpp
/// Exceptions with context. tangle never uses integer error codes: every failure is an
/// exception that says what went wrong and where.

#include <stdexcept>
#include <string>

namespace tangle {

/// Base of every error tangle throws on purpose.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

/// Bad input: names the file, the line (1-based, 0 if unknown), the key and what was expected.
class InputError : public Error {
 public:
  InputError(std::string file, int line, std::string key, const std::string& expected)
      : Error(format(file, line, key, expected)),
        m_file(std::move(file)),
        m_line(line),
        m_key(std::move(key)) {}

  /// File the error was found in.
  const std::string& file() const { return m_file; }
  /// 1-based line in the file (0 when unknown).
  int line() const { return m_line; }
  /// Key path, e.g. "lines[0].sections[1].length".
  const std::string& key() const { return m_key; }

 private:
  static std::string format(const std::string& file, int line, const std::string& key,
                            const std::string& expected);
  std::string m_file;
  int m_line;
  std::string m_key;
};

/// A nonlinear solve did not converge. Carries where it stopped so the caller can report it.
class ConvergenceError : public Error {
 public:
  explicit ConvergenceError(const std::string& message) : Error(message) {}
};

/// A result file could not be written (disk full, permissions, ...): names the file. Exit code 3.
class OutputError : public Error {
 public:
  explicit OutputError(const std::string& message) : Error(message) {}
};

}  // namespace tangle
