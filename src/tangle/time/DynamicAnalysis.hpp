#pragma once
/// @file DynamicAnalysis.hpp
/// Time-domain run from the static equilibrium: generalized-alpha steps with automatic step cutting
/// on Newton failure (halving down to the minimum step, then regrowing), output at a fixed interval
/// through an observer, a progress line on the terminal, and a clean stop that keeps everything
/// recorded so far when the run cannot go on.

#include <chrono>
#include <functional>
#include <memory>
#include <string>

#include "tangle/model/State.hpp"
#include "tangle/solver/Assembler.hpp"
#include "tangle/time/GeneralizedAlpha.hpp"

namespace tangle::time {

/// Outcome of a dynamic run.
struct DynamicResult {
  bool completed = false;   ///< reached the requested duration
  double endTime = 0.0;     ///< last time reached [s]
  int steps = 0;            ///< accepted steps
  int cutbacks = 0;         ///< step cuts after Newton failures
  int errorRejections = 0;  ///< steps redone because the local error estimate exceeded the tolerance
  /// Steps redone shorter because a cable element went from tension into slack within them
  /// (cableUnloadStepFraction, CableSnapLimit.hpp).
  int unloadRejections = 0;
  long newtonIterations = 0;
  long partIterations = 0;   ///< Newton iterations evaluated on a part of the model (theory manual 8.2)
  long blocksLeft = 0;       ///< converged independent blocks left out of a Newton correction (8.2)
  long matrixRefreshes = 0;  ///< iteration matrices assembled and factorised (modified Newton, 8.2)
  long blockRefreshes = 0;   ///< independent blocks of it (lines) assembled and factorised on their own
  /// Kept matrices made for a new step length with the mass matrix alone, without an assembly (8.2).
  long matrixStepLengthChanges = 0;
  /// Steps the chosen Newton path (dynamics.solver) did not converge and a fallback did (a whole refresh,
  /// then full Newton: GeneralizedAlpha::step), steps cut after every fallback failed included.
  long fallbackSteps = 0;
  double wallSeconds = 0.0;  ///< wall-clock time of the run [s]
  std::string message;       ///< summary or the reason the run stopped (time, line, node)
  bool interrupted = false;  ///< stopped by Ctrl-C / SIGTERM (core::interruptRequested)
};

/// Local error estimate of a generalized-alpha step [-]: |(beta - 1/6) h^2 (a_{n+1} - a_n)| / |u_{n+1} - u_n|
/// over the translational DOFs (Zienkiewicz & Xie 1991). `betaError` = |beta - 1/6|, h the step [s].
double localErrorEstimate(const model::Model& model, const model::State& before, const model::State& after,
                          double h, double betaError);

/// Drives the time integration.
class DynamicAnalysis {
 public:
  /// Called at t = 0 and at every output time with the state and the out-of-balance force (whose
  /// values at constrained DOFs are the support reactions).
  using Observer = std::function<void(const model::State&, const VecX& force)>;
  /// Called at t = 0 (dt = 0) and after every accepted step with the step length dt [s]: extremes and
  /// range graphs must see every step, not only the output times (a short impact falls between them).
  using StepObserver = std::function<void(const model::State&, double dt)>;
  /// Returns true when the caller wants the run to stop before the next step (as Ctrl-C does, but for this
  /// run only: the Python module stops one run when its progress callback raises or Ctrl-C reaches Python).
  using StopRequest = std::function<bool()>;

  DynamicAnalysis(solver::Assembler& assembler, const model::DynamicSpec& settings);

  void setObserver(Observer observer) { m_observer = std::move(observer); }
  void setStepObserver(StepObserver observer) { m_stepObserver = std::move(observer); }
  /// Off: the contributors' step control (LoadContributor::limitStep and rejectStep) is skipped, to verify
  /// what it adds (TunnellingTest). On by default. Commits are never skipped.
  void setStepControl(bool on) { m_stepControl = on; }
  void setStopRequest(StopRequest stop) { m_stop = std::move(stop); }
  /// Adds held nodes whose motion is imposed by other parts of the model (vessels).
  void addPrescribed(std::vector<model::PrescribedNode> nodes) {
    for (auto& n : nodes) m_extraPrescribed.push_back(std::move(n));
  }
  /// Print a progress line (simulated time, real-time factor) to stderr about every 2 s of wall time.
  void setProgress(bool on) { m_progress = on; }

  /// Runs from `state` (the static equilibrium at t = 0, velocities zero) to the requested duration. The
  /// path-dependent state of the model follows LoadContributor's protocol: before each step the assembler's
  /// limitStep, after a converged one its rejectStep (a refused step is undone and cut like a Newton failure,
  /// with the reason in the message if it cannot be cut further), after an accepted one its commitStep (which
  /// may change the velocities: an impulse model), and finish at the end, however the run ends.
  DynamicResult run(model::State& state);

  /// The same run in parts, for a host program that drives the model step by step (analysis::CoupledRun):
  /// start (t = 0, the observers' first call), then advance to each time the host asks for (the steps are
  /// cut to land on it; the step control carries over between calls), then finish. run() is these three.
  void start(model::State& state);
  /// Advances to `until` [s] (at most the duration). Returns false when the run had to stop (Newton failed
  /// at the minimum step, a refused step, an interruption): result().message says why and the state is the
  /// last accepted one.
  bool advance(model::State& state, double until);
  /// Ends the run (the contributors' finish) and returns its summary.
  DynamicResult finish(model::State& state);
  /// The summary so far.
  const DynamicResult& result() const { return m_result; }

 private:
  solver::Assembler* m_assembler;
  model::DynamicSpec m_settings;
  Observer m_observer;
  StepObserver m_stepObserver;
  bool m_stepControl = true;
  StopRequest m_stop;
  std::vector<model::PrescribedNode> m_extraPrescribed;
  bool m_progress = false;

  // The run's progress between start, advance and finish.
  std::unique_ptr<GeneralizedAlpha> m_stepper;
  DynamicResult m_result;
  std::chrono::steady_clock::time_point m_wallStart, m_lastPrint;
  long m_outputIndex = 1;
  double m_nextOutput = 0.0;
  double m_dt = 0.0;        ///< step to try next [s]
  double m_lastStep = 0.0;  ///< last accepted step [s] (a step grows at most twofold)
  int m_successes = 0;      ///< accepted steps since the last cut
  bool m_stopped = false;   ///< advance failed: no further advance
};

/// The prescribed-motion nodes of a model (held ends with a motion).
std::vector<model::PrescribedNode> prescribedNodes(const model::Model& model);

}  // namespace tangle::time
