#include "tangle/core/ConsoleProgress.hpp"

#include <fmt/format.h>

#include <iostream>

namespace tangle::core {

namespace {
std::chrono::steady_clock::duration seconds(double s) {
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(s));
}
}  // namespace

ConsoleProgress::ConsoleProgress(double delay, double interval)
    : m_start(Clock::now()), m_delayEnd(m_start + seconds(delay)), m_next(m_delayEnd), m_interval(interval) {}

bool ConsoleProgress::due() const { return Clock::now() >= m_next; }

void ConsoleProgress::print(const std::string& text) {
  std::cerr << fmt::format("  {} ({:.0f} s)\n", text, elapsed());
  m_next = Clock::now() + seconds(m_interval);
}

void ConsoleProgress::stage(const std::string& text) {
  if (Clock::now() >= m_delayEnd) print(text);
}

double ConsoleProgress::elapsed() const {
  return std::chrono::duration<double>(Clock::now() - m_start).count();
}

}  // namespace tangle::core
