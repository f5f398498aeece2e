#pragma once
/// @file ConsoleProgress.hpp
/// Progress lines on stderr for a computation that may take long (statics of a long riser): nothing while it
/// is quick, then a line every few seconds, so a user can tell a slow solve from a hung one.

#include <chrono>
#include <string>

namespace tangle::core {

/// Prints nothing for the first `delay` seconds of wall time after construction, then at most one line every
/// `interval` seconds. The caller asks due() (cheap) and builds its line only when it is.
class ConsoleProgress {
 public:
  explicit ConsoleProgress(double delay = 3.0, double interval = 2.0);
  /// True when a line may be printed now [wall clock].
  bool due() const;
  /// Prints "  <text> (<elapsed> s)" on stderr and starts the next interval.
  void print(const std::string& text);
  /// Prints `text` at once when lines are already being printed (the delay has passed): a change of stage.
  void stage(const std::string& text);
  /// Wall time since construction [s].
  double elapsed() const;

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point m_start;
  Clock::time_point m_delayEnd;  // no line before it
  Clock::time_point m_next;      // when the next line may be printed
  double m_interval;             // [s]
};

}  // namespace tangle::core
