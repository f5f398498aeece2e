#pragma once
/// @file SeabedImpacts.hpp
/// Impacts of lines on the seabed (issue 46: "a line hitting the seabed is an event in the clash report,
/// impact velocity and energy, as line to line"). The seabed is a body of infinite mass, so the pair's Eq. 5
/// mass is the line's own effective mass at the contact.
///
/// The rule, as the line-to-line events' (docs/theory.md 9.9, 9.10), on the seabed's node contacts:
/// - At every accepted state the nodes of a line in contact with the seabed (normal reaction > 0) are grouped
///   into patches: touching nodes at most kReachNodes apart along the line belong to one patch.
/// - A patch continues the open event of its line whose node range, grown by kReachNodes, it overlaps;
///   otherwise it opens a new event. An event that no patch continues closes (a bounce is two events).
/// - Approach speed v0: the largest normal approach speed -v.n of the patch's nodes at the accepted state
///   before first contact. The event is an impact when v0 exceeds the threshold.
/// - Impact phase: from first contact until the force-weighted mean normal velocity of the event's nodes
///   has turned (they stop approaching) or the event closes. Eq. 5 (the seed paper): m = impulse of the
///   phase / change of that mean normal velocity over it; energy 1/2 m v0^2. Beside it the work the seabed
///   did against the approach over the phase, W (the kinetic energy of approach absorbed).

#include <filesystem>
#include <string>
#include <vector>

#include "tangle/core/Types.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/seabed/Seabed.hpp"

namespace tangle::analysis {

/// One contact of a line with the seabed.
struct SeabedImpact {
  int line = 0;
  double startTime = 0.0, endTime = 0.0;  ///< [s]
  /// Where it began along the line [m]: the node of the largest reaction at first contact (a resting
  /// contact at the start: its first node).
  double arcLength = 0.0;
  Vec3 position = Vec3::Zero();           ///< that node's position then [m]
  int firstNode = 0, lastNode = 0;        ///< node range (global indices) over the event
  double impactVelocity = 0.0;            ///< v0 [m/s]
  double peakForce = 0.0;                 ///< largest total normal reaction of the event's nodes [N]
  double impulse = 0.0;                   ///< of the normal reaction over the event [N s]
  double phaseEndTime = 0.0;              ///< end of the impact phase [s]
  double phaseImpulse = 0.0;              ///< [N s]
  double phaseVelocityChange = 0.0;       ///< of the force-weighted mean normal velocity [m/s]
  double phaseWork = 0.0;                 ///< work against the approach [J]
  double eq5Mass = 0.0;                   ///< phaseImpulse / phaseVelocityChange [kg] (NaN: not measurable)
  /// 1/2 eq5Mass v0^2 [J] (0 for a contact that is not an impact; NaN for an impact whose approach was not
  /// stopped within its phase, e.g. at the end of the run: the Eq. 5 mass is not measurable)
  double impactEnergy = 0.0;
  bool impact = false;                    ///< v0 above the threshold
  bool open = false;                      ///< still in contact at the end of the run

  // Tracking (not reported).
  bool phaseOpen = true;
  double startNormalVelocity = 0.0;  ///< force-weighted mean normal velocity at the first contact [m/s]
  double lastNormalVelocity = 0.0;
  double lastForce = 0.0;  ///< total reaction at the last accepted state [N]
};

class SeabedImpacts {
 public:
  /// Touching nodes closer than this along a line (in nodes) belong to one patch.
  static constexpr int kReachNodes = 2;

  /// @param impactVelocityThreshold contacts starting faster than this are impacts [m/s]
  SeabedImpacts(const model::Model& model, double impactVelocityThreshold);

  /// The state the dynamics starts from (statics' contacts are resting contacts, never impacts).
  void start(const model::State& state);
  /// An accepted state, `dt` [s] after the previous one.
  void commit(const model::State& state, double dt);
  /// Closes the open events at the end of the run (marked open).
  void finish();

  const std::vector<SeabedImpact>& events() const { return m_events; }
  /// Number of impacts (events with v0 above the threshold).
  int impactCount() const;
  /// Writes `seabed_impacts.csv` into `dir` (every event, impacts and resting contacts), if any event.
  void write(const std::filesystem::path& dir) const;
  /// One line for the log: the count of impacts and the largest energy.
  std::string terminalSummary() const;

 private:
  struct NodeContact {
    int node = 0;
    double force = 0.0;           ///< normal reaction [N]
    double normalVelocity = 0.0;  ///< v . n [m/s]
    Vec3 normal = Vec3::UnitZ();  ///< the seabed's normal under it
  };
  std::vector<NodeContact> contactsOf(const model::State& state, int line) const;
  /// End (exclusive) of the patch of `contacts` (sorted by node) that starts at `begin`.
  static std::size_t patchEnd(const std::vector<NodeContact>& contacts, std::size_t begin);
  /// Ends `e`'s impact phase at `time` [s] with the mean normal velocity then [m/s]: Eq. 5 mass and energy.
  static void endPhase(SeabedImpact& e, double time, double normalVelocity);

  const model::Model* m_model;
  seabed::Seabed m_seabed;
  double m_threshold;
  std::vector<SeabedImpact> m_events;
  std::vector<int> m_open;  // indices into m_events of the open events
  VecX m_lastVelocity;      // velocities at the previous accepted state
};

}  // namespace tangle::analysis
