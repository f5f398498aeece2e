#pragma once
/// @file HullImpacts.hpp
/// The events of the hull contact (vessel::HullContact): a line or a hull touching a hull, one event per
/// continuous contact of a pair (from the first accepted state with a contact force to the first without:
/// a bounce is two events), and what the clash report needs of each (issue 46: "impact velocity, energy from
/// the two bodies' masses with added mass").
///
/// - Impact velocity v0: the largest normal approach speed of the pair's points within reach of contact at
///   the accepted state before the first contact (the first contact's own, when there is none).
/// - Rebound speed: the normal separation speed of the point that touched last, at the first state without
///   contact; the ratio to v0 is the measured restitution.
/// - Bodies' effective mass at the contact point along its normal (both hulls' 6x6 mass with added mass,
///   1/m = sum over the free bodies of [n, r x n]^T M^-1 [n, r x n]; a fixed or prescribed hull counts as
///   infinite; Pedersen & Zhang 1998, "On impact mechanics in ship collisions", Marine Structures 11, or the
///   energy of a ship-platform collision in DNV-RP-C204), and the impact energy 1/2 m v0^2 with it. For a
///   line on a hull the line's share is not a body mass: its effective mass is then the Eq. 5 one.
/// - Eq. 5 mass (the seed paper): the event's impulse / (v0 + rebound speed), the mass that changed
///   momentum; for two free hulls it should equal the bodies' effective mass (restitution test).

#include <filesystem>
#include <string>
#include <vector>

#include "tangle/core/Types.hpp"

namespace tangle::vessel {

/// One contact event of the hull contact.
struct HullImpact {
  std::string bodyA;             ///< line or vessel name
  std::string bodyB;             ///< vessel name (the hull touched)
  bool lineOnHull = false;       ///< bodyA is a line
  double startTime = 0.0;        ///< [s]
  double endTime = 0.0;          ///< [s]
  Vec3 position = Vec3::Zero();  ///< first contact point [m]
  double impactVelocity = 0.0;   ///< v0 [m/s]
  double reboundVelocity = 0.0;  ///< [m/s] (> 0 separating)
  double peakForce = 0.0;        ///< largest total normal force [N]
  double impulse = 0.0;          ///< of the normal force over the event [N s]
  double maxPenetration = 0.0;   ///< [m]
  double bodiesMass = 0.0;       ///< bodies' effective mass at the first contact (NaN for a line) [kg]
  double eq5Mass = 0.0;          ///< impulse / (v0 + rebound) [kg] (NaN while open)
  double impactEnergy = 0.0;     ///< 1/2 m v0^2, m the bodies' mass (hull on hull) or Eq. 5's [J]
  bool impact = false;           ///< v0 above the impact velocity threshold
  bool open = false;             ///< still in contact at the end of the run
};

/// What one pair did at one accepted state (HullContact::commitStep).
struct HullPairReading {
  double force = 0.0;            ///< total normal force [N]
  double penetration = 0.0;      ///< deepest penetration [m]
  double approachSpeed = 0.0;    ///< largest normal approach speed of points within reach [m/s] (may be < 0)
  double separationSpeed = 0.0;  ///< normal separation speed at the deepest (or nearest) point [m/s]
  Vec3 position = Vec3::Zero();  ///< deepest (or nearest) point [m]
  double bodiesMass = 0.0;       ///< bodies' effective mass there [kg] (NaN for a line)
  bool near = false;             ///< some point within reach
};

/// The event tracking of the hull contact.
class HullImpacts {
 public:
  /// `pairs` names each pair (bodyA, bodyB, line on hull); threshold: the impact velocity threshold [m/s].
  HullImpacts(std::vector<HullImpact> pairs, double threshold)
      : m_pairs(std::move(pairs)), m_threshold(threshold) {
    m_open.assign(m_pairs.size(), -1);
    m_last.resize(m_pairs.size());
  }
  /// An accepted state at `time` [s], `dt` [s] after the one before (0 at the start), with each pair's
  /// reading.
  void commit(double time, double dt, const std::vector<HullPairReading>& readings);
  /// The run ends at `time` [s]: events still in contact are closed as open.
  void finish(double time);
  const std::vector<HullImpact>& events() const { return m_events; }
  int impactCount() const;
  /// dynamics/hull_impacts.csv (written when the model has a hull, even without events).
  void write(const std::filesystem::path& folder) const;
  /// A few lines for the log: the count and the largest energy per pair.
  std::string terminalSummary() const;

 private:
  std::vector<HullImpact> m_pairs;  ///< pair names (templates of events)
  double m_threshold = 0.0;
  std::vector<int> m_open;  ///< per pair: index of its open event, -1 none
  std::vector<HullPairReading> m_last;
  std::vector<HullImpact> m_events;
};

}  // namespace tangle::vessel
