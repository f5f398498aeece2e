#pragma once
/// @file FatigueDamage.hpp
/// Fatigue damage along every line of a dynamic run (docs/theory.md 13.4): at every node of a line type
/// with fatigue properties (model::FatigueSpec), the stress at `points` points round the circumference,
///   sigma_k = SCF (T_w / A_s + (r / I) (M2 sin theta_k - M3 cos theta_k)),  theta_k = 2 pi k / points,
/// (T_w the wall tension T_e + p_i A_i - p_e A_e, or the effective tension T_e; A_s = pi/4 (D^2 - (D - 2t)^2) and
/// I = pi/64 (D^4 - (D - 2t)^4) of the steel pipe; r = D/2 (outer surface) or D/2 - t (inner); M2, M3 the
/// bending moment in the node's material axes 2 and 3, so the points turn with the section), or the
/// tension of a chain or rope against a T-N curve, is rainflow counted as the run goes (RainflowCounter,
/// every accepted step after the start time) and summed by Miner's rule against the section's curve.
/// A node between two line types with fatigue properties is counted with both; it reports the larger.
/// Units: SI (stress ranges in Pa, tension in N); angles in degrees in the results.

#include <string>
#include <vector>

#include "tangle/analysis/Rainflow.hpp"
#include "tangle/analysis/SnCurve.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/solver/LineResults.hpp"

namespace tangle::analysis {

/// Accumulates fatigue damage over the steps of a run.
class FatigueDamage {
 public:
  /// The damage at one node: of the worst point round the section, and of the worst section when two
  /// line types meet there.
  struct Node {
    int node = 0;               ///< index along the line (0 at end A)
    double arcLength = 0.0;     ///< [m]
    std::string lineType;       ///< the line type of the worst section
    bool tension = false;       ///< a T-N curve (ranges of tension [N]) rather than S-N (stress [Pa])
    double damage = 0.0;        ///< Miner sum over the counted duration [-]
    double cycles = 0.0;        ///< cycles counted at the worst point (half cycles count 0.5) [-]
    double largestRange = 0.0;  ///< largest range counted at the worst point [Pa] or [N]
    double worstAngle = 0.0;    ///< angle of the worst point from material axis 2 towards axis 3 [deg]
  };
  /// The nodes of one line with fatigue properties (a line without any is not listed).
  struct Line {
    int line = 0;  ///< index of the line in the model
    std::string name;
    std::vector<Node> nodes;
  };

  /// Prepares the counters of every node of a line type named in model.spec().fatigue. Counting starts at
  /// FatigueSpec::startTime (or the ramp time when negative).
  explicit FatigueDamage(const model::Model& model);

  /// True when no line has fatigue properties (nothing to count).
  bool empty() const { return m_stations.empty(); }
  /// Adds one accepted state (`lines` computed from `state`; LineResultDetail::SectionForces suffices).
  /// States before the start time are skipped. Call in time order.
  void accumulate(const std::vector<solver::LineSnapshot>& lines, const model::State& state);
  /// Ends the histories (the residues count as half cycles) and returns the damage along every line. Call
  /// once, after the last accumulate().
  std::vector<Line> finish();

  /// Duration counted so far: from the first to the last accumulated state [s].
  double countedDuration() const { return m_started ? m_lastTime - m_firstTime : 0.0; }
  /// Time of the first counted state [s].
  double firstCountedTime() const { return m_firstTime; }
  /// Factor from the run's damage to the damage of one year: occurrence x one year / counted duration [-].
  double annualFactor() const;
  /// Fatigue life [years] of a node with run damage `damage`: 1 / (DFF x annual damage); +inf without
  /// damage.
  double life(double damage) const;
  /// Number of stress or tension histories counted (one per point round each section at each node).
  std::size_t historyCount() const { return m_counters.size(); }

 private:
  /// A node of a line with the properties of one fatigue section.
  struct Station {
    int line = 0, node = 0, globalNode = 0;
    int section = 0;      ///< index into m_sections
    int firstHistory = 0;  ///< its points' counters are m_counters[firstHistory, firstHistory + points)
    int points = 1;
  };
  /// A section's constants.
  struct Section {
    std::string lineType;
    bool tension = false;
    SnCurve sn;
    TnCurve tn;
    double axial = 0.0;    ///< SCF / A_s [1/m^2]
    double bending = 0.0;  ///< SCF r / I [1/m^3]
    /// The line type whose areas the wall tension's pressure term takes (ModelSpec's); null: the effective
    /// tension (fatigue `tension: effective`).
    const section::LineType* wallType = nullptr;
    int points = 1;
    std::vector<double> sinTheta, cosTheta;  ///< of the points' angles theta_k
  };
  /// Miner's sum: `count` cycles of `range` at history `history` against section `s`'s curve.
  void addCycles(const Section& s, std::size_t history, double range, double count);

  const model::Model* m_model;
  std::vector<Section> m_sections;
  std::vector<Station> m_stations;
  std::vector<RainflowCounter> m_counters;
  std::vector<double> m_damage, m_cycles, m_largest;  // per history
  double m_startTime = 0.0;
  double m_firstTime = 0.0, m_lastTime = 0.0;
  bool m_started = false;
};

}  // namespace tangle::analysis
