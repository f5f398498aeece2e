#pragma once
/// @file RunText.hpp
/// What a run says about its model and results on the terminal and in run.log (shared by `tangle check`,
/// `tangle run` and the Python module's runs into a folder).

#include <string>
#include <vector>

#include "tangle/model/Model.hpp"
#include "tangle/solver/LineResults.hpp"
#include "tangle/vessel/VesselSystem.hpp"

namespace tangle::results {

/// The model summary of `check` and `run`: environment, waves, current, vessels, lines, contact.
std::string modelSummary(const model::Model& m);
/// Plausibility warnings of the reader, one per line.
std::string warningText(const model::ModelSpec& spec);
/// Largest axial strain T / EA along each line [-] beyond its line type's limit
/// (LineType::strainWarningLimit): a line much shorter than its span converges to a strain no real line
/// survives, silently.
std::string strainWarnings(const model::Model& m, const std::vector<solver::LineSnapshot>& lines);
/// The largest effective tension over its line type's minimum breaking load along one line.
struct BreakingLoadUse {
  double ratio = 0.0;    ///< largest tension / MBL [-]; 0 when no line type of the line gives an MBL
  double arc = 0.0;      ///< where [m from end A]
  double tension = 0.0;  ///< the tension there [N]
  double mbl = 0.0;      ///< the MBL there [N]
  std::string lineType;  ///< of the section there
};
/// breakingLoadUse of line `line` with `nodeTension` its effective tension at every node [N]; a node takes
/// the smaller MBL of the elements beside it.
BreakingLoadUse breakingLoadUse(const model::Model& m, std::size_t line, const std::vector<double>& nodeTension);
/// "warning: ..." where a line's tension exceeds its minimum breaking load (`when`: "at the static
/// equilibrium", "during the dynamics"), one line each; empty if none does.
std::string breakingLoadWarnings(const model::Model& m, const std::vector<BreakingLoadUse>& use, const std::string& when);
/// Tensioner strokes and stop forces, one line each.
std::string tensionerText(const model::Model& m,
                          const std::vector<vessel::VesselSystem::TensionerReading>& readings);

}  // namespace tangle::results
