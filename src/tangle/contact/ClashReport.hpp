#pragma once
/// @file ClashReport.hpp
/// The clash report analysts and DNV-RP-F203 ("Riser interference", 2009) ask for: every contact event
/// (when, where along each line and the path it slid along, peak force, impulse, impact velocity and
/// energy, effective masses), the minimum clearance between every pair of contact-enabled lines over
/// time, and per line pair the number of impacts with the distribution of impact velocity and energy.
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
  ClashReport(const model::Model& model, const LineContact& contact);

  /// Records the minimum clearance of every allowed line pair at this state (call at output times).
  void recordClearance(const model::State& state);
  /// Writes contact/events.csv, contact/event_paths.csv, contact/clearance.csv and contact/summary.json.
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

 private:
  const model::Model* m_model;
  const LineContact* m_contact;
  std::vector<std::array<int, 2>> m_pairs;
  std::vector<ClearanceSample> m_samples;
};

}  // namespace tangle::contact
