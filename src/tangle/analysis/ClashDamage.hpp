#pragma once
/// @file ClashDamage.hpp
/// Clash damage along each line (DNV-RP-F203 (2009) 4.3, "Collision allowed"): the impacts of a run
/// (contact events that began with an approach speed, contact/ContactEvents.hpp) binned by where they hit
/// each line, with the number of impacts, their accumulated and largest energy, the largest impact
/// velocity and the number of impacts above the energy the line tolerates. An impact counts on both lines
/// it involves, at the arc length where it began on each. Units: SI (m, J, m/s).

#include <vector>

#include "tangle/contact/ContactEvents.hpp"
#include "tangle/model/Model.hpp"

namespace tangle::analysis {

/// One bin [from, to) of a line.
struct ClashDamageBin {
  double from = 0.0, to = 0.0;  ///< arc length from end A [m]
  int impacts = 0;              ///< impacts that began in the bin
  int impactsAbove = 0;         ///< of those, with an energy above the threshold
  double energy = 0.0;          ///< accumulated impact energy [J]
  double largestEnergy = 0.0;   ///< [J]
  double largestVelocity = 0.0; ///< largest impact (normal approach) velocity [m/s]
};

/// The bins of one line.
struct LineClashDamage {
  int line = 0;  ///< index of the line in the model
  std::vector<ClashDamageBin> bins;
  int impacts() const;
  double energy() const;
};

/// Bins of `binLength` [m] along each line in `lines` (indices into model.lines(); the last bin of a line
/// ends at its end) filled with the impacts among `events`; impacts with energy above `energyThreshold`
/// [J] are counted apart.
std::vector<LineClashDamage> clashDamage(const model::Model& model, const std::vector<int>& lines,
                                         const std::vector<contact::ContactEvent>& events, double binLength,
                                         double energyThreshold);

}  // namespace tangle::analysis
