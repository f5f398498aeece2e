#include "tangle/core/OutputFile.hpp"

#include <cerrno>
#include <cstring>
#include <string>
#include <utility>

#include "tangle/core/Error.hpp"

namespace tangle::core {

OutputFile::OutputFile(std::filesystem::path path) : m_path(std::move(path)) {
  errno = 0;
  m_out.open(m_path, std::ios::out | std::ios::trunc | std::ios::binary);
  if (!m_out) fail(errno);
  m_open = true;
}

OutputFile::~OutputFile() {
  try {
    close();
  } catch (...) {  // NOLINT(bugprone-empty-catch): a destructor must not throw; close() reports errors
  }
}

[[noreturn]] void OutputFile::fail(int savedErrno) const {
  const std::string reason = savedErrno != 0 ? std::strerror(savedErrno) : "write failed (disk full?)";
  throw OutputError("cannot write " + m_path.string() + ": " + reason);
}

void OutputFile::check() {
  if (!m_out) {
    const int saved = errno;
    m_open = false;
    fail(saved);
  }
}

void OutputFile::write(std::string_view text) {
  if (!m_open) fail(0);
  errno = 0;
  m_out.write(text.data(), static_cast<std::streamsize>(text.size()));
  check();
}

void OutputFile::writeRows(std::string& rows, bool last) {
  if (!last && rows.size() < (std::size_t{1} << 20)) return;
  write(rows);
  rows.clear();
}

void OutputFile::flush() {
  if (!m_open) return;
  errno = 0;
  m_out.flush();
  check();
}

void OutputFile::close() {
  if (!m_open) return;
  errno = 0;
  m_out.flush();
  check();
  m_out.close();
  m_open = false;
  if (m_out.fail()) fail(errno);
}

}  // namespace tangle::core
