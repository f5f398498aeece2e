/// @file BackgroundWriter.cpp
/// One writer thread with a bounded queue (contract in BackgroundWriter.hpp).

#include "tangle/io/BackgroundWriter.hpp"

#include <algorithm>
#include <utility>

namespace tangle::io {

BackgroundWriter::BackgroundWriter(std::size_t maxQueued)
    : m_maxQueued(maxQueued > 0 ? maxQueued : 1),
      m_wakeAt(std::max<std::size_t>(1, m_maxQueued / 2)),
      m_thread([this] { run(); }) {}

BackgroundWriter::~BackgroundWriter() {
  {
    std::unique_lock lock(m_mutex);
    m_stop = true;
  }
  m_work.notify_one();
  m_thread.join();  // run() empties the queue before it returns
}

void BackgroundWriter::submit(std::function<void()> job) {
  std::unique_lock lock(m_mutex);
  if (!m_error && m_queue.size() >= m_maxQueued) {
    m_submitterWaiting = true;
    m_work.notify_one();  // the queue is full: the writer must be running or be woken
    m_done.wait(lock, [this] { return m_error || m_queue.size() < m_maxQueued; });
    m_submitterWaiting = false;
  }
  if (m_error) std::rethrow_exception(std::exchange(m_error, nullptr));
  m_queue.push_back(std::move(job));
  const bool wake = m_writerWaiting && m_queue.size() >= m_wakeAt;
  lock.unlock();
  if (wake) m_work.notify_one();
}

void BackgroundWriter::finish() {
  std::unique_lock lock(m_mutex);
  m_flush = true;
  m_submitterWaiting = true;
  m_work.notify_one();
  m_done.wait(lock, [this] { return m_queue.empty() && !m_running; });
  m_submitterWaiting = false;
  m_flush = false;
  if (m_error) std::rethrow_exception(std::exchange(m_error, nullptr));
}

void BackgroundWriter::run() {
  std::unique_lock lock(m_mutex);
  for (;;) {
    // Sleep until enough jobs wait (or a flush or the stop asks for the rest); once awake, run the queue
    // empty before sleeping again.
    const auto awake = [this] {
      return m_stop || (m_flush && !m_queue.empty()) || m_queue.size() >= m_wakeAt;
    };
    if (!awake()) {
      m_writerWaiting = true;
      m_work.wait(lock, awake);
      m_writerWaiting = false;
    }
    while (!m_queue.empty()) {
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
      if (m_submitterWaiting) m_done.notify_all();
    }
    if (m_submitterWaiting) m_done.notify_all();
    if (m_stop) return;  // stopping, nothing left
  }
}

}  // namespace tangle::io
