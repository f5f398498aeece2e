#pragma once
/// @file RunLog.hpp
/// What a run says on the terminal, copied to `run.log` in its output folder so the folder keeps the
/// whole story of the run (warnings, solver messages, errors).

#include <filesystem>
#include <memory>
#include <string>

#include "tangle/core/OutputFile.hpp"

namespace tangle::results {

/// Terminal messages with a copy in the run log.
class RunLog {
 public:
  explicit RunLog(bool quiet) : m_quiet(quiet) {}
  /// Starts copying to `path` (messages said before are written first).
  void open(const std::filesystem::path& path);
  /// Progress and results: stdout (unless quiet) and the log.
  void info(const std::string& text);
  /// Errors: stderr (always) and the log.
  void error(const std::string& text);
  /// Warnings: stderr (unless quiet: `-q` prints only errors) and the log (always).
  void warning(const std::string& text);
  /// Only into the log (what the caller reports on the terminal itself, e.g. a fatal error).
  void logOnly(const std::string& text) { toLog(text); }
  /// Flushes and closes the log. @throws OutputError on a failed write
  void close();

 private:
  void toLog(const std::string& text);
  bool m_quiet;
  std::string m_pending;  ///< said before open()
  std::unique_ptr<core::OutputFile> m_file;
};

}  // namespace tangle::results
