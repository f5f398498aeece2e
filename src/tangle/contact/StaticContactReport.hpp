#pragma once
/// @file StaticContactReport.hpp
/// Contact results of a static equilibrium: where the lines touch and how hard, per contact point (a
/// crossing: force [N]) or Gauss point of a contact along a length (force per unit length [N/m]), per
/// place where two lines touch (a contact zone: one pair may touch in several places, e.g. a flexible
/// riser lying over an SCR near the seabed and leaning on it near the top) and per line pair the total
/// force, the contact length and the largest force per unit length.

#include <filesystem>
#include <string>
#include <vector>

#include "tangle/contact/LineContact.hpp"
#include "tangle/core/Types.hpp"

namespace tangle::contact {

/// One sample of static contact force: a contact point, or a Gauss point of a contact along a length.
struct StaticContactSample {
  int line1 = 0, line2 = 0;       ///< the pair, line1 < line2
  double arc1 = 0.0, arc2 = 0.0;  ///< arc length of the sample on each line [m]
  Vec3 position = Vec3::Zero();   ///< where, on line 1 [m]
  Vec3 force = Vec3::Zero();      ///< contact force on line 1, normal and friction [N]
  double normal = 0.0;            ///< normal force [N] (> 0)
  double length = 0.0;            ///< contact length it stands for [m] (0: a point contact)
  double perLength = 0.0;         ///< normal force per unit length [N/m] (0: a point contact)
};

/// A place where two lines touch: the samples of one pair linked one to the next within each line's join
/// distance along line 1 and along line 2.
struct StaticContactZone {
  int line1 = 0, line2 = 0;
  Vec3 force = Vec3::Zero();   ///< total contact force on line 1 [N]
  double normal = 0.0;         ///< total normal force [N]
  double length = 0.0;         ///< contact length (of the samples along lengths) [m]
  double peakPerLength = 0.0;  ///< largest normal force per unit length [N/m]
  double arc1From = 0.0, arc1To = 0.0, arc2From = 0.0, arc2To = 0.0;  ///< arc ranges on the lines [m]
  Vec3 centre = Vec3::Zero();   ///< the normal forces' centre (their weighted mean position) [m]
  int points = 0, samples = 0;  ///< contact points and length samples in it
};

/// Groups samples into zones, per pair (ascending), in the order of their first sample along line 1: two
/// samples of a pair within joinDistance[line1] [m] along line 1 and joinDistance[line2] [m] along line 2 are
/// of one zone, and so is a chain of such links (a line wrapped round another, touching one arc of it from
/// two arcs of its own, is two places). Each zone sums its samples in ascending arc along line 1. A line
/// touching itself (line1 == line2) is one pair of arcs whichever pass a sample comes from: a sample with
/// arc1 > arc2 is taken with its arcs exchanged and its force negated (the force on the lower arc's side), so
/// that the two passes of one place are one zone.
std::vector<StaticContactZone> groupContactZones(std::vector<StaticContactSample> samples,
                                                 const std::vector<double>& joinDistance);

/// Writes `<dir>/statics/contact_points.csv`, `<dir>/statics/contact_zones.csv` and
/// `<dir>/statics/contact_pairs.csv` for the state the contact was last committed at (after
/// Simulation::solveStatics) and returns a terminal summary (empty when no lines touch). Zones are
/// joined across gaps of up to two of each line's longest elements along it.
std::string writeStaticContact(const std::filesystem::path& dir, const model::Model& model, const LineContact& contact,
                               const model::State& state);

}  // namespace tangle::contact
