#pragma once
/// @file OutputFile.hpp
/// A result file whose every write is checked: a full disk or a vanished folder throws OutputError
/// naming the file, instead of leaving a truncated table behind a "results written" message.

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace tangle::core {

/// One result file, opened for writing (truncated). Text is written with write(); flush() and close()
/// check the stream and throw OutputError ("cannot write <path>: <reason>") on any failure.
class OutputFile {
 public:
  /// Opens (creates or truncates) `path`. @throws OutputError when it cannot be opened.
  explicit OutputFile(std::filesystem::path path);
  /// Closes without throwing (call close() to see errors).
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  /// Appends text. @throws OutputError when the stream has failed.
  void write(std::string_view text);
  /// The underlying stream (for writers that take an std::ostream); errors show at flush()/close().
  std::ostream& stream() { return m_out; }
  /// Appends `rows` and empties it once it holds a megabyte or more, or always with `last`: for writers that
  /// format a table row by row into one string (a string and a stream write per row cost more than the
  /// formatting of short rows). @throws OutputError when the stream has failed.
  void writeRows(std::string& rows, bool last = false);
  /// Pushes buffered text to the file. @throws OutputError on failure.
  void flush();
  /// Flushes and closes; idempotent. @throws OutputError on failure.
  void close();
  const std::filesystem::path& path() const { return m_path; }

 private:
  [[noreturn]] void fail(int savedErrno) const;
  void check();
  std::filesystem::path m_path;
  std::ofstream m_out;
  bool m_open = false;
};

}  // namespace tangle::core
