#pragma once
/// @file RangeGraphs.hpp
/// Range graphs of a dynamic run (min, max and time-weighted mean of effective tension, bending moment and
/// curvature at every node of every line), the extremes of the end tensions and the slack events, over
/// every accepted time step, not only the output times: a short impact between two output times is in the
/// range graph and the extremes. One accumulator for every user (the run's files through
/// io::DynamicRecorder, results.h5, the report, the Python module), so every output gives the same number
/// for one quantity.

#include <memory>
#include <vector>

#include "tangle/model/Model.hpp"
#include "tangle/solver/LineResults.hpp"

namespace tangle::analysis {

/// Min / max / mean accumulators along each line.
class RangeGraphs {
 public:
  /// Min/max/mean accumulators of one line (per node), and the extremes of its end tensions [N].
  struct Range {
    std::vector<double> tensionMin, tensionMax, tensionSum;        ///< effective tension [N], sum [N s]
    std::vector<double> momentMin, momentMax, momentSum;           ///< bending moment [N m], sum [N m s]
    std::vector<double> curvatureMin, curvatureMax, curvatureSum;  ///< curvature [1/m], sum [s/m]
    double endTensionMaxA = 0.0, endTensionMaxB = 0.0, endTensionMinA = 0.0, endTensionMinB = 0.0;  ///< [N]
    /// Slack events (snap loading, DNV-OS-E301 Ch.2 Sec.2): an event starts at a step where the lowest
    /// tension of the line's suspended nodes (setSeabedLevels) falls below zero (a cable gone slack, a riser
    /// in effective compression) and ends when every node is back above `retension` (1 % of the line's
    /// largest static tension, at least 1 N), so that tension hovering about zero is one event, not one per
    /// step.
    int slackEvents = 0;
    double slackTime = 0.0;  ///< time with the lowest tension below zero [s]
    bool slack = false;      ///< in an event now
    double retension = 1.0;  ///< [N]
    /// Smallest clearance of the line's surface to the seabed along its normal over the run [m] (0: on the
    /// seabed), per node: empty without a seabed (setSeabed).
    std::vector<double> seabedClearanceMin;
    /// Wall tension [N], sum [N s] (LineSnapshot::wallTension): pipe lines only, empty otherwise.
    std::vector<double> wallTensionMin, wallTensionMax, wallTensionSum;
  };

  /// @param initial the lines at t = 0 (node counts; their largest tension sets each line's re-tension level)
  explicit RangeGraphs(const std::vector<solver::LineSnapshot>& initial);

  /// The seabed and each line's node contact radii [m] (one vector per line, as the snapshots' nodes).
  struct SeabedNodes {
    std::shared_ptr<const seabed::SeabedSurface> surface;
    std::vector<std::vector<double>> radius;
  };
  /// A node is on the seabed when its contact surface is within one contact radius of the seabed (resting
  /// height plus half a diameter). Slack events count suspended nodes only: a laid chain at rest may carry
  /// no tension. Without it every node counts.
  void setSeabed(SeabedNodes seabed) { m_seabed = std::move(seabed); }
  /// `model`'s seabed and nodes as setSeabed takes them.
  static SeabedNodes seabedNodes(const model::Model& model);

  /// Adds one accepted step (of length dt [s]; dt = 0 for the initial state). Means are time-weighted (each
  /// state stands for the step of length dt that led to it): steps are not equal when the step controller
  /// cuts them. The initial state counts in the extremes only.
  void accumulate(const std::vector<solver::LineSnapshot>& lines, double dt);

  const std::vector<Range>& ranges() const { return m_ranges; }
  /// Number of accumulated states (initial state + accepted steps).
  long stepCount() const { return m_steps; }
  /// Time the means are weighted over [s] (0: only the initial state; then the means are its values).
  double meanWeight() const { return m_weight; }
  /// Time-weighted mean of an accumulated sum, or the state's value `only` when no time has passed.
  double mean(double sum, double only) const { return m_weight > 0.0 ? sum / m_weight : only; }

 private:
  std::vector<Range> m_ranges;
  SeabedNodes m_seabed;  // (no surface: no seabed test)
  double m_weight = 0.0;
  long m_steps = 0;
};

}  // namespace tangle::analysis
