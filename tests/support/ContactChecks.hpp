#pragma once
/// @file ContactChecks.hpp
/// Checks every contact test with impacts makes on its clash events (issue 29).

#include <gtest/gtest.h>

#include <vector>

#include "tangle/contact/ContactEvents.hpp"

namespace tangle::test {

/// Every impact's energy mass lies between the reduced mass of one element of each line at the impact
/// point and the reduced mass of the two whole lines with their added mass (none when a line is held;
/// docs/theory.md 9.10) (issue 29: the clash report's
/// impact energy must be an energy an engineer can sign; outside these bounds it is an artefact of the
/// measurement, as the 0.014 kg and 4.1e6 kg "effective masses" the issue found), and no impact carries
/// an energy warning (ContactEvents.hpp: Eq. 5 and the absorbed work agree within a factor 2).
inline void expectImpactEnergiesWithinBounds(const std::vector<contact::ContactEvent>& events) {
  for (const contact::ContactEvent& e : events) {
    if (!e.impact) continue;
    EXPECT_GE(e.energyMass, e.massLowerBound * (1.0 - 1e-9)) << "impact at t = " << e.startTime << " s";
    EXPECT_LE(e.energyMass, e.massUpperBound * (1.0 + 1e-9)) << "impact at t = " << e.startTime << " s";
    EXPECT_TRUE(e.energyWarning.empty()) << "impact at t = " << e.startTime << " s: " << e.energyWarning;
  }
}

}  // namespace tangle::test
