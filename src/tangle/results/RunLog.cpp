#include "tangle/results/RunLog.hpp"

#include <iostream>

namespace tangle::results {

void RunLog::open(const std::filesystem::path& path) {
  m_file = std::make_unique<core::OutputFile>(path);
  m_file->write(m_pending);
  m_pending.clear();
  m_file->flush();
}

void RunLog::toLog(const std::string& text) {
  if (m_file) {
    m_file->write(text);
    m_file->flush();  // a killed run keeps its log up to the last message
  } else {
    m_pending += text;
  }
}

void RunLog::info(const std::string& text) {
  if (!m_quiet) std::cout << text << std::flush;
  toLog(text);
}

void RunLog::error(const std::string& text) {
  std::cerr << text << std::flush;
  toLog(text);
}

void RunLog::warning(const std::string& text) {
  if (!m_quiet) std::cerr << text << std::flush;
  toLog(text);
}

void RunLog::close() {
  if (m_file) m_file->close();
}

}  // namespace tangle::results
