/// @file BackgroundWriter.cpp
/// One writer thread with a bounded queue (contract in BackgroundWriter.hpp).

#include "tangle/io/BackgroundWriter.hpp"

#include <utility>

namespace tangle::io {

BackgroundWriter::BackgroundWriter(std::size_t maxQueued)
    : m_maxQueued(maxQueued > 0 ? maxQueued : 1), m_thread([this] { run(); }) {}

BackgroundWriter::~BackgroundWriter() {
  {
    std::unique_lock lock(m_mutex);
    m_stop = true;
  }
  m_changed.notify_all();
  m_thread.join();  // run() empties the queue before it returns
}

void BackgroundWriter::submit(std::function<void()> job) {
  std::unique_lock lock(m_mutex);
  m_changed.wait(lock, [this] { return m_error || m_queue.size() < m_maxQueued; });
  if (m_error) std::rethrow_exception(std::exchange(m_error, nullptr));
  m_queue.push_back(std::move(job));
  lock.unlock();
  m_changed.notify_all();
}

void BackgroundWriter::finish() {
  std::unique_lock lock(m_mutex);
  m_changed.wait(lock, [this] { return m_queue.empty() && !m_running; });
  if (m_error) std::rethrow_exception(std::exchange(m_error, nullptr));
}

void BackgroundWriter::run() {
  std::unique_lock lock(m_mutex);
  for (;;) {
    m_changed.wait(lock, [this] { return m_stop || !m_queue.empty(); });
    if (m_queue.empty()) return;  // stopping, nothing left
    std::function<void()> job = std::move(m_queue.front());
    m_queue.pop_front();
    m_running = true;
    lock.unlock();
    std::exception_ptr error;
    try {
      job();
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    m_running = false;
    if (error) {
      // Stop writing: later jobs would write after a missing record. Kept for the next submit/finish.
      if (!m_error) m_error = error;
      m_queue.clear();
    }
    m_changed.notify_all();
  }
}

}  // namespace tangle::io
