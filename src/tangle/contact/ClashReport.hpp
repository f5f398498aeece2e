#pragma once
/// @file ClashReport.hpp
/// The clash report analysts and DNV-RP-F203 ("Riser interference", 2009) ask for: every contact event
/// (when, where in space and along each line and the path it slid along, whether an impact or a
/// sustained contact, peak force and force per unit length, impulse, impact velocity and energy with the
/// mass it uses, effective masses), the minimum clearance and the contact force of every pair of
/// contact-enabled lines over time, and per line pair the number of impacts with the distribution of
/// impact velocity, energy and force (impacts only; ContactEvents.hpp gives the event rule).
/// Written as CSV + JSON into `<output>/contact/` and summarised on the terminal.

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "tangle/contact/LineContact.hpp"

namespace tangle::contact {

/// Collects clearances during a run and writes the report.
class ClashReport {
 public:
  /// `pairs`: the line pairs (a <= b) it assesses, LineContact::assessedPairs.
  ClashReport(const model::Model& model, const LineContact& contact, std::vector<std::array<int, 2>> pairs);

  /// Records the minimum clearance and the contact force (total, peak per unit length, contact length)
  /// of every allowed line pair at this committed state (call at output times).
  void recordClearance(const model::State& state);
  /// Writes contact/events.csv, contact/event_paths.csv, contact/clearance.csv, contact/forces.csv and
  /// contact/summary.json.
  void write(const std::filesystem::path& dir) const;
  /// A few lines for the terminal.
  std::string terminalSummary() const;

  /// One clearance sample of one pair.
  struct ClearanceSample {
    double time;      ///< [s]
    int pair;         ///< index into pairs()
    double clearance; ///< [m] (+inf beyond the margin)
    double arcA, arcB;  ///< where it occurs [m]
  };
  const std::vector<std::array<int, 2>>& pairs() const { return m_pairs; }
  const std::vector<ClearanceSample>& samples() const { return m_samples; }
  /// One contact-force sample of one pair.
  struct ForceSample {
    double time;            ///< [s]
    int pair;               ///< index into pairs()
    double force;           ///< total normal contact force [N]
    double peakPerLength;   ///< largest line-to-line force per unit length [N/m]
    double length;          ///< contact length [m]
    int patches;            ///< separate contact patches
  };
  const std::vector<ForceSample>& forceSamples() const { return m_forces; }

 private:
  const model::Model* m_model;
  const LineContact* m_contact;
  std::vector<std::array<int, 2>> m_pairs;
  std::vector<ClearanceSample> m_samples;
  std::vector<ForceSample> m_forces;
};

}  // namespace tangle::contact
