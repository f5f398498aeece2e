#pragma once
/// @file BackgroundWriter.hpp
/// Runs output jobs in submission order on one background thread, so that formatting, compressing and
/// writing the results of an output time overlaps the integration of the next steps (issue 8: the CSV rows
/// and the deflate compression of results.h5; docs/performance.md).
///
/// Contract: the jobs run one at a time, in order, on the writer's thread; whatever a job touches must not
/// be touched by the submitting thread until finish() has returned (the caller hands over copies). The
/// first job that throws stops the writer; its exception is rethrown by the next submit() or finish(), and
/// the jobs after it are dropped. The destructor finishes the queued jobs (a run that stops keeps every
/// result it computed) and swallows their errors; call finish() to see them.
///
/// The writer is woken when half the queue's room is filled (or by finish() and the destructor), not at
/// every job: a wake-up per job was a futex call per output time on the solver's thread (docs/performance.md).

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace tangle::io {

class BackgroundWriter {
 public:
  /// @param maxQueued jobs that may wait before submit() blocks (bounds the memory of a slow disk)
  explicit BackgroundWriter(std::size_t maxQueued = 32);
  ~BackgroundWriter();
  BackgroundWriter(const BackgroundWriter&) = delete;
  BackgroundWriter& operator=(const BackgroundWriter&) = delete;

  /// Queues `job` (blocks while maxQueued jobs wait). Rethrows the error of an earlier job.
  void submit(std::function<void()> job);
  /// Waits until every queued job has run. Rethrows the error of a job, once.
  void finish();

 private:
  void run();

  std::size_t m_maxQueued;
  std::mutex m_mutex;
  std::size_t m_wakeAt;            // queued jobs that wake the writer
  std::condition_variable m_work;  // for the writer: jobs to run, a flush asked for, or stop
  std::condition_variable m_done;  // for the submitter: room in the queue, or everything run
  std::deque<std::function<void()>> m_queue;
  bool m_running = false;  // a job is running (popped from the queue, not finished)
  bool m_writerWaiting = false;     // the writer sleeps on m_work
  bool m_submitterWaiting = false;  // submit() or finish() sleeps on m_done
  bool m_flush = false;             // finish() waits: run every queued job without waiting for more
  bool m_stop = false;
  std::exception_ptr m_error;
  std::thread m_thread;  // last: started when everything it uses exists
};

}  // namespace tangle::io
