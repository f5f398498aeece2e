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

/// Strain above which a warning is given [-]: steel and chain yield near 0.2-0.5 %, polyester and nylon
/// ropes break at 10-20 %: 5 % flags input mistakes without flagging fibre ropes in normal use.
inline constexpr double kStrainWarning = 0.05;

/// The model summary of `check` and `run`: environment, waves, current, vessels, lines, contact.
std::string modelSummary(const model::Model& m);
/// Plausibility warnings of the reader, one per line.
std::string warningText(const model::ModelSpec& spec);
/// Largest axial strain T / EA along each line [-] above `limit`: a line much shorter than its span
/// converges to a strain no real line survives, silently.
std::string strainWarnings(const model::Model& m, const std::vector<solver::LineSnapshot>& lines,
                           double limit);
/// Tensioner strokes and stop forces, one line each.
std::string tensionerText(const model::Model& m,
                          const std::vector<vessel::VesselSystem::TensionerReading>& readings);

}  // namespace tangle::results
