#pragma once
/// @file Rainflow.hpp
/// Rainflow cycle counting of a load or stress history (ASTM E1049-85 (2017), "Standard Practices for Cycle
/// Counting in Fatigue Analysis", section 5.4.4: the three-point method with the starting point, half cycles
/// kept) and Miner's damage sum against an S-N curve (SnCurve.hpp).

#include <vector>

namespace tangle::analysis {

/// One counted cycle: range and mean in the units of the history, count 1 (a closed cycle) or 0.5 (a half
/// cycle: a range of the residue, or one that contains the starting point).
struct RainflowCycle {
  double range = 0.0;
  double mean = 0.0;
  double count = 1.0;
};

/// The turning points (peaks and valleys) of `history`, in order: the first and last values, and every value
/// where the history changes direction (plateaus collapse to one point). ASTM E1049-85 5.4.4 counts these.
std::vector<double> turningPoints(const std::vector<double>& history);

/// Rainflow cycles of `history` (ASTM E1049-85 5.4.4). For the standard's example (Fig. 6: -2, 1, -3, 5, -1,
/// 3, -4, 4, -2) the ranges 3, 4, 6, 8, 9 have counts 0.5, 1.5, 0.5, 1.0, 0.5. The total count is half the
/// number of turning points less one.
std::vector<RainflowCycle> rainflow(const std::vector<double>& history);

}  // namespace tangle::analysis
