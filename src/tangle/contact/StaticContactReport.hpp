#pragma once
/// @file StaticContactReport.hpp
/// Contact results of a static equilibrium: where the lines touch and how hard, per contact point (a
/// crossing: force [N]) or Gauss point of a contact along a length (force per unit length [N/m]), and per
/// line pair the total force, the contact length and the largest force per unit length.

#include <filesystem>
#include <string>

#include "tangle/contact/LineContact.hpp"

namespace tangle::contact {

/// Writes `<dir>/statics/contact_points.csv` and `<dir>/statics/contact_pairs.csv` for the state the
/// contact was last committed at (after Simulation::solveStatics) and returns a terminal summary (empty
/// when no lines touch).
std::string writeStaticContact(const std::filesystem::path& dir, const model::Model& model, const LineContact& contact,
                               const model::State& state);

}  // namespace tangle::contact
