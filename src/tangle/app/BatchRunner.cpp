/// @file BatchRunner.cpp
/// Load-case batches on local processes and MPI ranks (see BatchRunner.hpp).

#include "tangle/app/BatchRunner.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

#ifdef TANGLE_WITH_MPI
#include <mpi.h>
#endif

#include "tangle/app/BatchFatigue.hpp"
#include "tangle/app/BatchPlan.hpp"
#include "tangle/app/CaseSummary.hpp"
#include "tangle/app/SeedStatistics.hpp"
#include "tangle/core/Error.hpp"
#include "tangle/core/Interrupt.hpp"
#include "tangle/core/OutputFile.hpp"

extern char** environ;

namespace tangle::app {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

std::string readText(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Writes `text` to `file` unless it already holds exactly that (keeps the file of a finished case).
void writeIfChanged(const fs::path& file, const std::string& text) {
  if (fs::exists(file) && readText(file) == text) return;
  core::OutputFile out(file);
  out.write(text);
  out.close();
}

/// The folders of one case.
struct CasePaths {
  fs::path model, results, log, row;
};

CasePaths pathsOf(const fs::path& dir, const std::string& name) {
  return {dir / "models" / (name + ".yaml"), dir / "cases" / name, dir / "logs" / (name + ".log"),
          dir / "logs" / (name + ".row")};
}

/// True when the case's results are complete for this model text (then the batch does not rerun it).
bool finishedBefore(const CasePaths& p, const std::string& modelText) {
  if (!fs::exists(p.row) || !fs::exists(p.results / "model.yaml")) return false;
  if (readText(p.results / "model.yaml") != modelText) return false;
  const CaseSummary row = readCaseSummary(p.results, {});
  return row.status.rfind("completed", 0) == 0;
}

/// The tangle executable itself (children run `tangle run`).
std::string selfExecutable() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw Error("cannot find the tangle executable (/proc/self/exe): " + ec.message());
  return self.string();
}

/// Starts `tangle run` on one case, its output to the case's log. @return the child's pid
pid_t startCase(const std::string& exe, const CasePaths& p, const BatchOptions& options) {
  std::vector<std::string> args = {exe, "run", p.model.string(), "-o", p.results.string(), "--overwrite", "--quiet"};
  if (!options.plots) args.push_back("--no-plots");
  if (!options.reports) args.push_back("--no-report");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, p.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, exe.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw Error(fmt::format("cannot start {}: {}", exe, std::strerror(rc)));
  return pid;
}

/// The summary row of a case whose process ended with wait status `status` after `seconds`.
CaseSummary finishCase(const BatchCase& c, const CasePaths& p, int status, double seconds, int rank) {
  CaseSummary row = readCaseSummary(p.results, p.log);
  row.rank = rank;
  row.name = c.name;
  row.parameterValues = c.parameterValues;
  row.wallSeconds = seconds;
  if (WIFEXITED(status)) {
    row.exitCode = WEXITSTATUS(status);
  } else {
    row.exitCode = 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    row.status = fmt::format("failed: killed by signal {}", WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  }
  if (row.exitCode != 0 && (row.status.empty() || row.status.rfind("completed", 0) == 0 || row.status == "running"))
    row.status = row.exitCode == 1 ? "failed: bad input" : fmt::format("failed (exit code {})", row.exitCode);
  if (row.exitCode != 0 && row.message.empty()) row.message = "see " + p.log.string();
  core::OutputFile out(p.row);
  out.write(row.serialise());
  out.close();
  return row;
}

#ifdef TANGLE_WITH_MPI
/// Runs one case to its end (the blocking form, for MPI worker ranks).
CaseSummary runCase(const std::string& exe, const BatchCase& c, const CasePaths& p, const BatchOptions& options,
                    int rank) {
  const auto start = Clock::now();
  const pid_t pid = startCase(exe, p, options);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return finishCase(c, p, status, std::chrono::duration<double>(Clock::now() - start).count(), rank);
}
#endif

/// MPI ranks of the job; {0, 1} without MPI or when not started by mpirun.
struct Ranks {
  int rank = 0, size = 1;
  bool mpi = false;
};

#ifdef TANGLE_WITH_MPI
constexpr int kTagRequest = 1;  // worker -> rank 0: "give me a case" (payload: the last row, or empty)
constexpr int kTagAssign = 2;   // rank 0 -> worker: case index, or -1 when there is none left

/// True when started by an MPI launcher (MPI_Init outside one would start a singleton job).
bool underMpiLauncher() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"})
    if (std::getenv(v)) return true;
  return false;
}
#endif

}  // namespace

int runBatch(const BatchOptions& options) {
  const BatchPlan plan = readBatchPlan(options.batchPath);
  fs::path dir = options.outputDir;
  if (dir.empty()) {
    const fs::path b(options.batchPath);
    dir = b.parent_path() / (b.stem().string() + "_results");
  }

  Ranks ranks;
#ifdef TANGLE_WITH_MPI
  if (underMpiLauncher()) {
    MPI_Init(nullptr, nullptr);
    MPI_Comm_rank(MPI_COMM_WORLD, &ranks.rank);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks.size);
    ranks.mpi = true;
  }
#endif
  const int jobs = options.jobs > 0 ? options.jobs
                                    : (ranks.mpi ? 1 : std::max(1, static_cast<int>(std::thread::hardware_concurrency())));
  const std::string exe = selfExecutable();
  const int n = static_cast<int>(plan.cases.size());
  std::vector<CasePaths> paths;
  for (const BatchCase& c : plan.cases) paths.push_back(pathsOf(dir, c.name));

  // Rank 0 prepares the folder (every rank sees it) and finds the cases finished by an earlier run.
  std::vector<CaseSummary> rows(static_cast<std::size_t>(n));
  std::vector<char> done(static_cast<std::size_t>(n), 0);
  std::deque<int> pending;
  if (ranks.rank == 0) {
    for (const char* sub : {"models", "cases", "logs"}) fs::create_directories(dir / sub);
    writeIfChanged(dir / "batch.yaml", readText(options.batchPath));
    for (int i = 0; i < n; ++i) {
      const BatchCase& c = plan.cases[static_cast<std::size_t>(i)];
      const std::string text = c.model.text();
      writeIfChanged(paths[static_cast<std::size_t>(i)].model, text);
      if (finishedBefore(paths[static_cast<std::size_t>(i)], text)) {
        CaseSummary row = CaseSummary::deserialise(readText(paths[static_cast<std::size_t>(i)].row));
        row.reused = true;
        rows[static_cast<std::size_t>(i)] = row;
        done[static_cast<std::size_t>(i)] = 1;
      } else {
        pending.push_back(i);
      }
    }
    if (!options.quiet)
      std::cout << fmt::format("batch {}: {} case(s), {} already done, {} to run on {} process(es) x {} job(s)\n",
                               plan.batchFile, n, n - static_cast<int>(pending.size()), pending.size(), ranks.size,
                               jobs)
                << std::flush;
  }
#ifdef TANGLE_WITH_MPI
  if (ranks.mpi) MPI_Barrier(MPI_COMM_WORLD);
#endif

  const auto report = [&](const CaseSummary& row) {
    if (!options.quiet)
      std::cout << fmt::format("  case {}: {} ({:.1f} s)\n", row.name, row.status, row.wallSeconds) << std::flush;
  };

  if (ranks.rank != 0) {
#ifdef TANGLE_WITH_MPI
    // Worker rank: ask for a case, run it, send its row with the next request.
    std::string last;
    while (true) {
      MPI_Send(last.data(), static_cast<int>(last.size()), MPI_CHAR, 0, kTagRequest, MPI_COMM_WORLD);
      int index = -1;
      MPI_Recv(&index, 1, MPI_INT, 0, kTagAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (index < 0) break;
      last = runCase(exe, plan.cases[static_cast<std::size_t>(index)], paths[static_cast<std::size_t>(index)],
                     options, ranks.rank)
                 .serialise();
    }
    MPI_Finalize();
#endif
    return 0;
  }

  // Rank 0 (or the only process): local jobs, and the dispatcher of the other ranks.
  struct Running {
    int index;
    Clock::time_point start;
  };
  std::map<pid_t, Running> running;
  int workersActive = ranks.size - 1;
  const auto nextCase = [&]() {
    if (pending.empty() || core::interruptRequested()) return -1;
    const int i = pending.front();
    pending.pop_front();
    return i;
  };
  const auto store = [&](const CaseSummary& row) {
    for (int i = 0; i < n; ++i)
      if (plan.cases[static_cast<std::size_t>(i)].name == row.name) {
        rows[static_cast<std::size_t>(i)] = row;
        done[static_cast<std::size_t>(i)] = 1;
      }
    report(row);
  };
  while (true) {
    bool busy = false;
    while (static_cast<int>(running.size()) < jobs) {
      const int i = nextCase();
      if (i < 0) break;
      running[startCase(exe, paths[static_cast<std::size_t>(i)], options)] = {i, Clock::now()};
      busy = true;
    }
#ifdef TANGLE_WITH_MPI
    if (ranks.mpi) {
      int flag = 0;
      MPI_Status st;
      MPI_Iprobe(MPI_ANY_SOURCE, kTagRequest, MPI_COMM_WORLD, &flag, &st);
      if (flag) {
        int count = 0;
        MPI_Get_count(&st, MPI_CHAR, &count);
        std::string text(static_cast<std::size_t>(count), '\0');
        MPI_Recv(text.data(), count, MPI_CHAR, st.MPI_SOURCE, kTagRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (!text.empty()) store(CaseSummary::deserialise(text));
        const int i = nextCase();
        MPI_Send(&i, 1, MPI_INT, st.MPI_SOURCE, kTagAssign, MPI_COMM_WORLD);
        if (i < 0) --workersActive;
        busy = true;
      }
    }
#endif
    int status = 0;
    const pid_t pid = running.empty() ? 0 : waitpid(-1, &status, WNOHANG);
    if (pid > 0 && running.count(pid)) {
      const Running r = running[pid];
      running.erase(pid);
      store(finishCase(plan.cases[static_cast<std::size_t>(r.index)], paths[static_cast<std::size_t>(r.index)], status,
                       std::chrono::duration<double>(Clock::now() - r.start).count(), 0));
      busy = true;
    }
    if (running.empty() && workersActive == 0 && (pending.empty() || core::interruptRequested())) break;
    if (!busy) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }

  int failed = 0;
  for (int i = 0; i < n; ++i) {
    CaseSummary& row = rows[static_cast<std::size_t>(i)];
    if (!done[static_cast<std::size_t>(i)]) {
      row.name = plan.cases[static_cast<std::size_t>(i)].name;
      row.parameterValues = plan.cases[static_cast<std::size_t>(i)].parameterValues;
      row.status = "not run (batch interrupted)";
      row.minClearance = std::nan("");
    }
    if (row.exitCode != 0) ++failed;
  }
  // The line columns come from the models, so a batch whose cases all fail keeps them.
  std::vector<std::string> lineNames;
  for (const BatchCase& c : plan.cases) {
    try {
      for (const model::LineSpec& l : c.model.spec().lines)
        if (std::find(lineNames.begin(), lineNames.end(), l.name) == lineNames.end()) lineNames.push_back(l.name);
    } catch (const InputError&) {
      // Refused when the plan was read; its row says so.
    }
  }
  const std::string table = writeSummaryTable(dir / "summary.csv", plan.parameterNames, lineNames, rows);
  if (!options.quiet) std::cout << table;
  // Over the seeds of every case (docs/batch.md, theory 13.4).
  if (!plan.seeds.empty()) {
    const std::string statistics = writeSeedStatistics(dir / "summary_statistics.csv", plan, lineNames, rows);
    if (!options.quiet) std::cout << statistics;
  }
  // Long-term fatigue: the damage of every sea state (case) summed (docs/batch.md).
  {
    std::vector<fs::path> caseDirs;
    for (const CasePaths& p : paths) caseDirs.push_back(p.results);
    const std::string fatigue = writeBatchFatigue(dir, plan, caseDirs, rows);
    if (!options.quiet) std::cout << fatigue;
  }
#ifdef TANGLE_WITH_MPI
  if (ranks.mpi) MPI_Finalize();
#endif
  return failed == 0 ? 0 : 2;
}

}  // namespace tangle::app
