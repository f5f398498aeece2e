#pragma once
/// @file HullContact.hpp
/// Contact with vessels' hulls (issue 46, "hulls that can be hit"): lines on hulls (a riser swinging into a
/// pontoon, a mooring line on a bilge) and hulls on hulls (two units colliding), with restitution and
/// friction, the forces into both bodies' equations of motion, and the events (vessel::HullImpacts).
///
/// Geometry (geometry::HullShape): a hull is a set of boxes, cylinders and capsules in its vessel's axes.
/// - A line meets a hull at points along its elements, at most hull_contact.point_spacing apart (nodes
///   included), each the centre of a sphere of the line's contact radius and the representative of its
///   share of the element's length (trapezoidal weights w, so a line's stiffness per metre does not depend on
///   its mesh); its force goes to the element's two nodes by the linear shape functions.
/// - A hull meets another hull at its surface points (HullShape::surfacePoints) inside the other's shapes,
///   both ways round.
/// At each point inside a shape: penetration p = -(signed distance - radius) > 0, outward normal n of that
/// shape (the deepest shape when a point is inside several).
///
/// Law (docs/theory.md 10.9): the elastic penalty k p (k = hull_contact.stiffness per hull point, or
/// line_stiffness * w per line point) times the hysteretic restitution factor of the distributed line
/// contact (contact::HystereticRestitution: loads along (1 + a) k p, unloads along (1 - a) k p, so the
/// rebound speed is e v0 whatever the masses, the number of points or the stiffness), and regularised
/// Coulomb friction on the relative tangential velocity at the point, mu N v_t / sqrt(|v_t|^2 + v_f^2)
/// (dynamics only). The force acts on body A (line or hull with the point) along +n and on hull B along -n,
/// at the point, so both bodies' momenta change by equal and opposite amounts.
///
/// Tangent: the normal stiffness k psi J^T J and its damping k p psi'(v) J^T J, the friction's dependence
/// on the tangential velocity, with J the point's velocity in terms of the bodies' DOFs (a line node's
/// translation times its shape function; a hull's V + omega x r). The turning of the normal and of the
/// lever arms is left out (a second-order term, f times the curvature: it costs Newton iterations, not
/// accuracy).
///
/// The time step is limited, while a pair in contact closes or opens faster than
/// contact.impact_velocity_threshold or closes that fast within three steps of contact (and for two half
/// periods after: through the deepest point and the unloading), to a 20th of the contact's half period
/// pi sqrt(m / k) (a hull pair: the bodies' effective mass and the points in contact; a line: its mass per
/// metre over the stiffness per metre).

#include <memory>
#include <string>
#include <vector>

#include "tangle/contact/ContactLaw.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/solver/LoadContributor.hpp"
#include "tangle/vessel/HullImpacts.hpp"

namespace tangle::vessel {

class HullContact final : public solver::LoadContributor {
 public:
  /// True when some vessel of the model has a hull.
  static bool wanted(const model::Model& model);
  /// @throws InputError when two hulls overlap at the start.
  HullContact(const model::Model& model, const model::State& start);

  void addForces(const model::State& state, const solver::AssemblyRequest& request, VecX& force,
                 solver::SystemMatrix* matrix) override;
  solver::LoadSource source() const override { return solver::LoadSource::Contact; }
  /// Its forces act near the hulls only: a part of the model away from them leaves it out (markLoadedNodes:
  /// the nodes of elements within 2 m of a hull at the last whole assembly, and the hulls' vessel nodes).
  bool supportsParts() const override { return true; }
  bool markLoadedNodes(std::vector<char>& mark) const override;
  double limitStep(const model::State& state, double step) override;
  void commitStep(model::State& state, double dt) override;
  void finish(double time) override;

  const HullImpacts& impacts() const { return *m_impacts; }
  /// The hulls for the log: per vessel with one, its shapes.
  std::string describe() const;

  /// One point of contact (or near it) at a state.
  struct Point {
    int pair = 0;
    Vec3 position = Vec3::Zero();          ///< the point [m]
    Vec3 normal = Vec3::UnitZ();           ///< outward normal of hull B [-]
    double gap = 0.0;                      ///< signed surface gap (< 0 in contact) [m]
    Vec3 relativeVelocity = Vec3::Zero();  ///< of A's point relative to B's [m/s]
    double stiffness = 0.0;                ///< k of the point [N/m]
  };

 private:
  struct Hull {
    int vessel = 0;
    int node = 0;
    bool free = false;
    std::vector<geometry::HullShape> shapes;
    std::vector<Vec3> points;  ///< surface points, vessel axes [m]
    double reach = 0.0;        ///< bounding radius about the reference point [m]
    std::vector<Vec3> shapeCentre;   ///< each shape's centre, vessel axes [m]
    std::vector<double> shapeReach;  ///< each shape's bounding radius about it [m]
    Mat6 mass = Mat6::Zero();  ///< mass with added mass, vessel axes [kg, kg m^2]
  };
  struct Pair {
    int line = -1;           ///< line index for a line on a hull, else -1
    int hullA = -1;          ///< index into m_hulls of the hull with the points (hull on hull)
    int hullB = 0;           ///< index into m_hulls of the hull touched
    int event = 0;           ///< index of the pair of events (a hull pair's two directions share one)
    std::vector<char> skip;  ///< line on hull: elements left out (inside the hull at the start)
  };

  /// Calls `visit` with every point of every pair whose gap is below `reach` [m] (0: in contact only).
  template <class Visit>
  void forEachPoint(const model::State& state, double reach, bool velocities, Visit&& visit) const;
  /// The signed distance of a global point to hull h at a state (deepest shape) with its normal; shapes whose
  /// bounding sphere is `cutoff` [m] or more away are skipped (the distance is +inf when all are).
  geometry::ShapeDistance hullDistance(const model::State& state, const Hull& h, const Vec3& p,
                                       double cutoff) const;
  /// The bodies' effective mass along n at point p of a pair [kg] (NaN for a line; inf for two held hulls).
  double bodiesMass(const model::State& state, const Pair& pair, const Vec3& p, const Vec3& n) const;
  /// The 6x6 mass of hull h in global axes at a state.
  Mat6 globalMass(const model::State& state, const Hull& h) const;

  const model::Model* m_model;
  model::HullContactSpec m_spec;
  contact::HystereticRestitution m_restitution;
  std::vector<Hull> m_hulls;
  std::vector<Pair> m_pairs;
  std::unique_ptr<HullImpacts> m_impacts;
  std::vector<double> m_lineHalfPeriod;  ///< per line: pi sqrt(m' / k_line) [s]
  double m_lastDt = 0.0;
  std::vector<char> m_nearNodes;      ///< per node: within reach of a hull at the last addForces
  std::vector<double> m_impactUntil;  ///< per pair: the step limit holds until this time [s] (limitStep)
  std::vector<double> m_impactLimit;  ///< per pair: that limit [s]
};

}  // namespace tangle::vessel
