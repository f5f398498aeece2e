// Unit tests of tangle::io::BackgroundWriter (contract in BackgroundWriter.hpp): jobs run in submission
// order on one thread that is not the caller's; finish() waits for all of them; the first error comes back
// from finish() or submit() and drops the jobs after it; the destructor runs what is queued (a run that
// stops keeps its results); a full queue makes submit() wait instead of failing or dropping jobs.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "tangle/io/BackgroundWriter.hpp"

namespace tangle::io {
namespace {

TEST(BackgroundWriter, RunsJobsInOrderOnAnotherThread) {
  std::vector<int> order;  // touched by the jobs only until finish() returns
  std::thread::id jobThread;
  {
    BackgroundWriter writer(4);  // smaller than the job count: submit() must wait, not drop
    for (int i = 0; i < 100; ++i)
      writer.submit([&order, &jobThread, i] {
        if (i % 10 == 0) std::this_thread::sleep_for(std::chrono::microseconds(200));
        order.push_back(i);
        jobThread = std::this_thread::get_id();
      });
    writer.finish();
    ASSERT_EQ(order.size(), 100u);
    for (int i = 0; i < 100; ++i) EXPECT_EQ(order[static_cast<std::size_t>(i)], i);
    EXPECT_NE(jobThread, std::this_thread::get_id());
  }
}

TEST(BackgroundWriter, DestructorRunsTheQueuedJobs) {
  std::atomic<int> done{0};
  {
    BackgroundWriter writer;
    for (int i = 0; i < 20; ++i)
      writer.submit([&done] {
        std::this_thread::sleep_for(std::chrono::microseconds(100));
        ++done;
      });
  }  // no finish(): the destructor must not drop what was computed
  EXPECT_EQ(done.load(), 20);
}

TEST(BackgroundWriter, FirstErrorComesBackOnceAndStopsTheJobsAfterIt) {
  BackgroundWriter writer;
  std::atomic<int> after{0};
  int reported = 0;
  writer.submit([] { throw std::runtime_error("disk full"); });
  // The error comes back from this submit (if the job has already failed) or from finish(), once; the
  // job after the failing one never runs (dropped, or refused).
  for (int k = 0; k < 2; ++k) {
    try {
      if (k == 0)
        writer.submit([&after] { ++after; });
      else
        writer.finish();
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "disk full");
      ++reported;
    }
  }
  EXPECT_EQ(reported, 1);
  EXPECT_EQ(after.load(), 0);
  EXPECT_NO_THROW(writer.finish());
  // The writer accepts work again afterwards.
  writer.submit([&after] { ++after; });
  writer.finish();
  EXPECT_EQ(after.load(), 1);
}

TEST(BackgroundWriter, SubmitReportsAnEarlierError) {
  BackgroundWriter writer;
  writer.submit([] { throw std::runtime_error("bad write"); });
  // The error surfaces at a later submit (once the job has run) or at finish, never silently.
  bool seen = false;
  for (int i = 0; i < 1000 && !seen; ++i) {
    try {
      writer.submit([] {});
      std::this_thread::sleep_for(std::chrono::microseconds(50));
    } catch (const std::runtime_error&) {
      seen = true;
    }
  }
  if (!seen) {
    try {
      writer.finish();
    } catch (const std::runtime_error&) {
      seen = true;
    }
  }
  EXPECT_TRUE(seen);
}

}  // namespace
}  // namespace tangle::io
