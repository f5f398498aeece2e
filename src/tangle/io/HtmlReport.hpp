#pragma once
/// @file HtmlReport.hpp
/// The results report in the browser: one self-contained `report.html` (three.js from Debian's
/// libjs-three inlined, the data embedded as JSON, no server) with a 3D replay of the lines (tubes of
/// their contact diameter coloured by tension, bending moment, curvature or clearance), vessels (boxes
/// at their position and attitude), seabed, sea surface, contact points and forces; interactive plots
/// (end tensions, range graphs, clearance, drift path); the clash table; the model summary and run log.
///
/// During a run the report collects compact frames: at most kMaxFrames, and at most kMaxNodeFrames node
/// positions in all, so an output time is kept every `stride` output times (stated in the page);
/// positions are rounded to 1 mm, tensions and moments to 4 significant digits. The end tensions and
/// vessel positions for the plots are kept at every output time. The data go to
/// `<results>/report/data.json`, from which writePage() builds the page (`tangle report DIR` does it
/// again from the folder). docs/report.md describes the page.

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "tangle/analysis/ClashDamage.hpp"
#include "tangle/analysis/ExtremeStatistics.hpp"
#include "tangle/analysis/FatigueDamage.hpp"
#include "tangle/analysis/SeabedImpacts.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/model/State.hpp"
#include "tangle/solver/LineResults.hpp"
#include "tangle/vessel/HullImpacts.hpp"

namespace tangle::contact {
class LineContact;
class ClearanceEnvelope;
class ClashReport;
}  // namespace tangle::contact

namespace tangle::io {

/// Collects the data of one report and writes them as JSON.
class HtmlReport {
 public:
  static constexpr int kMaxFrames = 400;
  static constexpr long kMaxNodeFrames = 100000;

  /// @param kind "run" or "view" (a model before any analysis)
  /// @param summary the model summary text (as on the terminal)
  HtmlReport(const model::Model& model, std::string kind, std::string summary);

  /// Sets the frame stride from the number of output times expected (dynamics: duration / interval + 1).
  void planFrames(int expectedOutputs);
  int stride() const { return m_stride; }
  /// Frames kept so far (dynamics).
  int frameCount() const { return static_cast<int>(m_frames.size()); }

  /// The static equilibrium (or, for `view`, the initial shape). `contact` and `envelope` may be null.
  void setStatics(const std::vector<solver::LineSnapshot>& lines, const model::State& state,
                  const contact::LineContact* contact, const contact::ClearanceEnvelope* envelope);
  /// One output time of the dynamics: always into the histories, and a frame every stride() calls.
  void recordOutput(const std::vector<solver::LineSnapshot>& lines, const model::State& state,
                    const contact::LineContact* contact, const contact::ClearanceEnvelope* envelope);
  /// Range graphs along line `line` [N, N m, 1/m] (dynamics).
  void setRange(int line, const std::vector<double>& tensionMin, const std::vector<double>& tensionMax,
                const std::vector<double>& momentMin, const std::vector<double>& momentMax,
                const std::vector<double>& curvatureMin, const std::vector<double>& curvatureMax);
  /// Contact events and clearance histories of the run.
  void setClash(const contact::LineContact& contact, const contact::ClashReport& clash);
  /// Static and dynamic clearance envelopes.
  void setEnvelope(const contact::ClearanceEnvelope& envelope);
  /// Fatigue damage per year along the lines with fatigue properties (plotted as log10).
  void setFatigue(const analysis::FatigueDamage& fatigue, const std::vector<analysis::FatigueDamage::Line>& damage);
  /// The impacts on vessels' hulls (vessel::HullImpacts), rows of the report's impacts table.
  void addHullImpacts(const std::vector<vessel::HullImpact>& events);
  /// The lines' impacts on the seabed (analysis::SeabedImpacts), rows of the same table.
  void addSeabedImpacts(const std::vector<analysis::SeabedImpact>& events);
  /// Impact energy accumulated per bin along the lines (clash damage).
  void setClashDamage(const std::vector<analysis::LineClashDamage>& damage);
  /// The peaks of line `line`'s end B tension [N] and their fits (extreme statistics), for a Weibull plot.
  void setPeakFit(int line, const analysis::PeakSet& peaks, const analysis::PeakFit& rayleigh,
                  const analysis::PeakFit& weibull);
  /// Status of the run ("completed", ...) and its end time [s].
  void setStatus(const std::string& status) { m_status = status; }
  const std::string& status() const { return m_status; }

  /// The data as JSON text.
  std::string json() const;
  /// Writes json() to a file (`<dir>/report/data.json` for a run).
  void writeData(const std::filesystem::path& file) const;

  /// Builds the page from the data (json()) and the run log text. Needs three.js (libjs-three).
  /// @throws InputError when three.js is not installed; OutputError on a failed write
  static void writePage(const std::string& data, const std::string& log, const std::filesystem::path& page);
  /// `tangle report DIR`: DIR/report.html again from DIR/report/data.json and DIR/run.log.
  /// @throws InputError when the data file is missing
  static void rebuildPage(const std::filesystem::path& dir);
  /// Where three.js is read from (libjs-three).
  static std::filesystem::path threeDirectory();

 private:
  std::string frameJson(const std::vector<solver::LineSnapshot>& lines, const model::State& state,
                        const contact::LineContact* contact,
                        const contact::ClearanceEnvelope* envelope) const;

  const model::Model* m_model;
  std::string m_kind, m_summary, m_status;
  int m_stride = 1;
  int m_outputs = 0;
  std::string m_statics;                          ///< JSON of the static frame
  std::vector<std::string> m_frames;              ///< JSON of each kept dynamic frame
  std::vector<double> m_time;                     ///< every output time [s]
  std::vector<std::vector<double>> m_endTension;  ///< per line end (2 per line), per output [N]
  std::vector<std::vector<double>> m_vesselXY;    ///< per vessel x, y (2 per vessel), per output [m]
  std::vector<std::string> m_rangeParts;          ///< JSON range graphs per line
  std::string m_clash = "null", m_envelope = "[]", m_fatigue = "[]", m_clashDamage = "[]";
  /// The clearance envelope's margin [m] (frames' clearances beyond it are null); NaN without an envelope.
  double m_clearanceMargin = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::string> m_peakFits;
  std::vector<std::string> m_impacts;  ///< JSON rows of the hull and seabed impacts table
};

}  // namespace tangle::io
