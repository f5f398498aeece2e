#include "tangle/contact/ContactEvents.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace tangle::contact {

namespace {
constexpr double kPi = 3.141592653589793;
constexpr double kInf = std::numeric_limits<double>::infinity();

/// Spots of one patch, with their aggregates.
struct Patch {
  std::vector<const ContactSpot*> spots;
  double force = 0.0, length = 0.0, peakPerLength = 0.0, arcA = 0.0, arcB = 0.0;
  double aMin = kInf, aMax = -kInf, bMin = kInf, bMax = -kInf;
  double reach = 0.0, approach = 0.0, penetration = 0.0, jumpImpulse = 0.0;
  double lineMass = 0.0, lineStiffness = 0.0;  // sums over Gauss spots
  double power = 0.0;             // sum of force x closing speed [W] (work against the relative motion)
  double relativeVelocity = 0.0;  // weighted relative normal velocity (< 0 approaching; velocityWeight) [m/s]
  double jumpWork = 0.0;          // compression work of impulse-model jumps at this state [J]
  double frictionAlongNormal = 0.0;  // friction on A along the force-weighted mean normal (B to A) [N]
  Vec3 position = Vec3::Zero();   // force centroid on line A
  const ContactSpot* strongest = nullptr;
};

/// One open event's sums over the patches that continue it at this state.
struct StepSums {
  double force = 0.0;       // normal force [N]
  double phaseForce = 0.0;  // normal force plus friction along the patches' mean normals [N] (impact phase)
  double power = 0.0;       // work rate against the relative normal motion [W]
  double momentum = 0.0;    // force x relative normal velocity [N m/s]
  double jump = 0.0;        // impulse-model jumps' impulse [N s]
  double jumpWork = 0.0;    // their compression work [J]
  StepSums& operator+=(const StepSums& o) {
    force += o.force;
    phaseForce += o.phaseForce;
    power += o.power;
    momentum += o.momentum;
    jump += o.jump;
    jumpWork += o.jumpWork;
    return *this;
  }
};

bool overlaps(double lo, double hi, double from, double to) { return hi >= from && lo <= to; }

/// Folds event `from` into `into` (two open events of a pair that one patch now joins: one contact).
void mergeEvent(ContactEvent& into, const ContactEvent& from) {
  into.startTime = std::min(into.startTime, from.startTime);
  into.duration = std::max(into.duration, from.duration);
  into.impactVelocity = std::max(into.impactVelocity, from.impactVelocity);
  into.impact = into.impact || from.impact;
  into.impulse += from.impulse;
  into.jumpImpulse += from.jumpImpulse;
  if (into.phaseOpen && from.phaseOpen) {
    into.phaseImpulse += from.phaseImpulse;
    into.phaseWork += from.phaseWork;
    into.phasePeakForce = std::max(into.phasePeakForce, from.phasePeakForce);
    into.phaseJumped = into.phaseJumped || from.phaseJumped;
  }
  into.lastForce += from.lastForce;
  into.lastPhaseForce += from.lastPhaseForce;
  into.lastPower += from.lastPower;
  into.peakForce = std::max(into.peakForce, from.peakForce);
  into.peakForcePerLength = std::max(into.peakForcePerLength, from.peakForcePerLength);
  into.maxContactLength = std::max(into.maxContactLength, from.maxContactLength);
  into.maxPenetration = std::max(into.maxPenetration, from.maxPenetration);
  into.arcAMin = std::min(into.arcAMin, from.arcAMin);
  into.arcAMax = std::max(into.arcAMax, from.arcAMax);
  into.arcBMin = std::min(into.arcBMin, from.arcBMin);
  into.arcBMax = std::max(into.arcBMax, from.arcBMax);
  into.lastAMin = std::min(into.lastAMin, from.lastAMin);
  into.lastAMax = std::max(into.lastAMax, from.lastAMax);
  into.lastBMin = std::min(into.lastBMin, from.lastBMin);
  into.lastBMax = std::max(into.lastBMax, from.lastBMax);
  into.reach = std::max(into.reach, from.reach);
  into.lastContactTime = std::max(into.lastContactTime, from.lastContactTime);
  into.massUpperBound = std::max(into.massUpperBound, from.massUpperBound);
}
}  // namespace

std::string ContactEvent::kind() const {
  if (impact && sustained) return "impact then sustained";
  return impact ? "impact" : "sustained";
}

void ContactEventTracker::update(double time, double dt, bool dynamic, const std::vector<ContactSpot>& spots,
                                 const GapFunction& gapIn, const ContinuumFunction& continuum) {
  // Patches per line pair: spots sorted along line A, split where consecutive spots are farther apart
  // than the reach along A or B.
  std::map<std::pair<int, int>, std::vector<const ContactSpot*>> byPair;
  for (const ContactSpot& s : spots)
    if (s.force > 0.0) byPair[{s.lineA, s.lineB}].push_back(&s);
  std::vector<Patch> patches;
  for (auto& [pair, list] : byPair) {
    std::sort(list.begin(), list.end(),
              [](const ContactSpot* a, const ContactSpot* b) { return a->arcA < b->arcA; });
    Patch current;
    const ContactSpot* previous = nullptr;
    for (const ContactSpot* s : list) {
      const double reach = 2.0 * s->elementLength + s->radii;
      if (previous && (s->arcA - previous->arcA > reach || std::abs(s->arcB - previous->arcB) > reach)) {
        patches.push_back(current);
        current = Patch();
      }
      current.spots.push_back(s);
      previous = s;
    }
    patches.push_back(current);
  }
  for (Patch& p : patches) {
    double strongest = -1.0, velocityWeight = 0.0;
    Vec3 meanNormal = Vec3::Zero(), friction = Vec3::Zero();  // force-weighted normal, total friction on A
    for (const ContactSpot* s : p.spots) {
      p.force += s->force;
      meanNormal += s->force * s->normal;
      friction += s->friction;
      p.length += s->length;
      p.peakPerLength = std::max(p.peakPerLength, s->forcePerLength);
      p.arcA += s->force * s->arcA;
      p.arcB += s->force * s->arcB;
      p.position += s->force * s->position;
      p.aMin = std::min(p.aMin, s->arcA);
      p.aMax = std::max(p.aMax, s->arcA);
      p.bMin = std::min(p.bMin, s->arcB);
      p.bMax = std::max(p.bMax, s->arcB);
      p.reach = std::max(p.reach, 2.0 * s->elementLength + s->radii);
      p.approach = std::max(p.approach, s->approachSpeed);
      p.penetration = std::max(p.penetration, -s->gap);
      p.jumpImpulse += s->jumpImpulse;
      const double u = s->normal.dot(s->velocityA - s->velocityB);
      p.power -= s->force * u;
      const double weight = s->velocityWeight >= 0.0 ? s->velocityWeight : s->force;
      p.relativeVelocity += weight * u;
      velocityWeight += weight;
      if (s->jumpImpulse > 0.0) {
        // A velocity jump from u_before < 0 to u_after: the part of its impulse that stops the approach,
        // I u_before / (u_before - u_after), does the work 1/2 I_c |u_before| (a constant force).
        const double before = s->normal.dot(s->velocityBeforeA - s->velocityBeforeB);
        if (before < 0.0 && u > before) p.jumpWork += 0.5 * s->jumpImpulse * before * before / (u - before);
      }
      if (s->length > 0.0) {
        p.lineMass += s->pairMass;
        p.lineStiffness += s->stiffness;
      }
      if (s->force > strongest) {
        strongest = s->force;
        p.strongest = s;
      }
    }
    p.arcA /= p.force;
    p.arcB /= p.force;
    p.relativeVelocity = velocityWeight > 0.0 ? p.relativeVelocity / velocityWeight : 0.0;
    // Friction along the patch's mean normal: each Gauss point's friction is tangent to its own normal, but
    // the normals of a patch spread (a crossing over a bent line, a fold), and where they do, friction
    // helps stop the approach. Its part along the mean normal is part of the impulse that stops it (Eq. 5
    // over the impact phase: the momentum the lines exchanged). Left out, the short wire dropped across a
    // taut wire with mu 0.3 (DrapeDynamicsTest) measured an Eq. 5 mass of 0.787 kg against 0.815 kg
    // without friction, below one element's reduced mass (0.800 kg); with it 0.8145 kg. The work estimate
    // stays the normal law's (what the contact itself took up, the local energy of a dent check, 9.10):
    // the work friction does goes into sliding, not into the contact.
    const double meanNorm = meanNormal.norm();
    if (meanNorm > 0.0) p.frictionAlongNormal = friction.dot(meanNormal) / meanNorm;
    p.position /= p.force;
  }

  // Match patches to open events; the forces of several patches of one event add up.
  std::vector<StepSums> sums(m_open.size());
  std::vector<bool> continued(m_open.size(), false);
  std::vector<int> absorbedInto(m_open.size(), -1);  // an event folded into another (below)
  // Each open event's extent at the last committed state, which every patch of this step is matched
  // against: the events' own last extents are replaced by this step's as patches continue them. (Matched
  // against those, the second patch of a contact whose middle had lifted off, [0, 10] and [90, 100] m of a
  // contact over [0, 100] m, met the first patch's [0, 10] m and opened an event of its own: a new impact in
  // the clash statistics.)
  struct Extent {
    double aMin, aMax, bMin, bMax;
  };
  std::vector<Extent> lastExtent;
  lastExtent.reserve(m_open.size());
  for (const ContactEvent& e : m_open) lastExtent.push_back({e.lastAMin, e.lastAMax, e.lastBMin, e.lastBMax});
  m_patches.clear();
  for (const Patch& p : patches) {
    const ContactSpot& s = *p.strongest;
    int match = -1;
    for (std::size_t k = 0; k < m_open.size(); ++k) {
      const ContactEvent& e = m_open[k];
      if (e.lineA != s.lineA || e.lineB != s.lineB) continue;
      const double r = std::max(e.reach, p.reach);
      const Extent& last = lastExtent[k];
      if (!overlaps(p.aMin, p.aMax, last.aMin - r, last.aMax + r) ||
          !overlaps(p.bMin, p.bMax, last.bMin - r, last.bMax + r))
        continue;
      // The first open event it overlaps continues; any other it overlaps is the same contact, joined by
      // this patch, and is folded into it below. (Two risers closing side by side touched at first in
      // slivers of 1e-26 N here and there along the length, each an event of its own that then closed with
      // nothing: RisersClosingTest counted 3 events for one impact.)
      if (match < 0)
        match = static_cast<int>(k);
      else if (absorbedInto[k] < 0 && k != static_cast<std::size_t>(match))
        absorbedInto[k] = match;
    }
    if (match < 0) {
      // A new event.
      ContactEvent e;
      e.lineA = s.lineA;
      e.lineB = s.lineB;
      e.startTime = time;
      e.arcAStart = p.arcA;
      e.arcBStart = p.arcB;
      e.positionStart = p.position;
      e.arcAMin = e.lastAMin = p.aMin;
      e.arcAMax = e.lastAMax = p.aMax;
      e.arcBMin = e.lastBMin = p.bMin;
      e.arcBMax = e.lastBMax = p.bMax;
      e.impactVelocity = dynamic ? p.approach : 0.0;
      e.pointStart = s.length <= 0.0;
      e.pairMass = e.pointStart ? s.pairMass : p.lineMass;
      e.stiffness = e.pointStart ? s.stiffness : p.lineStiffness;
      const auto period = [](double mass, double stiffness) {
        return std::isfinite(mass) && mass > 0.0 && stiffness > 0.0 ? kPi * std::sqrt(mass / stiffness) : 0.0;
      };
      e.duration = e.pointStart ? period(s.pairMass, s.stiffness)
                                : std::max(period(p.lineMass, p.lineStiffness),
                                           period(s.lumpedPairMass, s.pointStiffness));
      e.radii = s.radii;
      e.minRadius = s.minRadius;
      e.reach = p.reach;
      e.normalStart = s.normal;
      e.startVelocityA = s.velocityBeforeA;
      e.startVelocityB = s.velocityBeforeB;
      e.lumpedMassA = e.lumpedMassB = 0.0;
      e.impact = dynamic && e.impactVelocity > m_impactVelocity;
      e.sustained = !dynamic;
      // An impact phase needs an approach: a contact that comes back at rest (a resting contact that
      // breathes) has none, and its work against a separating motion would read as negative energy.
      e.phaseOpen = dynamic && e.impactVelocity > 0.0;
      if (!e.phaseOpen) {
        e.phaseEnd = "no approach";
        e.phaseEndTime = time;
      }
      e.lastRelativeVelocity = -e.impactVelocity;
      e.massLowerBound = s.elementPairMass;
      e.massUpperBound = s.linePairMass;
      e.continuumMass = e.continuumEnergy = e.continuumLengthA = e.continuumLengthB = std::nan("");
      e.continuumDuration = e.continuumPeakForce = std::nan("");
      e.continuumNote = "not an impact";
      if (e.impact) {
        e.continuumNote = "not estimated";
        if (continuum) continuum(e);
      }
      lastExtent.push_back({e.lastAMin, e.lastAMax, e.lastBMin, e.lastBMax});
      m_open.push_back(std::move(e));
      sums.emplace_back();
      continued.push_back(false);
      absorbedInto.push_back(-1);
      match = static_cast<int>(m_open.size()) - 1;
    }
    ContactEvent& e = m_open[match];
    if (!continued[match]) {
      continued[match] = true;
      e.lastAMin = p.aMin;
      e.lastAMax = p.aMax;
      e.lastBMin = p.bMin;
      e.lastBMax = p.bMax;
      e.lastVelocityA = s.velocityA;
      e.lastVelocityB = s.velocityB;
    } else {
      e.lastAMin = std::min(e.lastAMin, p.aMin);
      e.lastAMax = std::max(e.lastAMax, p.aMax);
      e.lastBMin = std::min(e.lastBMin, p.bMin);
      e.lastBMax = std::max(e.lastBMax, p.bMax);
    }
    sums[match] += StepSums{p.force,       p.force + p.frictionAlongNormal,
                            p.power,       p.force * p.relativeVelocity,
                            p.jumpImpulse, p.jumpWork};
    e.arcAMin = std::min(e.arcAMin, p.aMin);
    e.arcAMax = std::max(e.arcAMax, p.aMax);
    e.arcBMin = std::min(e.arcBMin, p.bMin);
    e.arcBMax = std::max(e.arcBMax, p.bMax);
    e.peakForcePerLength = std::max(e.peakForcePerLength, p.peakPerLength);
    e.maxContactLength = std::max(e.maxContactLength, p.length);
    e.maxPenetration = std::max(e.maxPenetration, p.penetration);
    e.jumpImpulse += p.jumpImpulse;
    e.reach = std::max(e.reach, p.reach);
    e.path.push_back({time, p.arcA, p.arcB});
    m_patches.push_back({s.lineA, s.lineB, p.force, p.peakPerLength, p.length, p.arcA, p.arcB, p.aMin, p.aMax,
                         p.bMin, p.bMax});
  }
  // Fold the events a patch joined into the one it continued (to the root of a chain), then drop them.
  for (std::size_t k = 0; k < m_open.size(); ++k) {
    if (absorbedInto[k] < 0) continue;
    std::size_t root = static_cast<std::size_t>(absorbedInto[k]);
    while (absorbedInto[root] >= 0) root = static_cast<std::size_t>(absorbedInto[root]);
    mergeEvent(m_open[root], m_open[k]);
    sums[root] += sums[k];
    continued[root] = continued[root] || continued[k];
  }
  for (std::size_t k = m_open.size(); k-- > 0;) {
    if (absorbedInto[k] < 0) continue;
    const auto at = static_cast<std::ptrdiff_t>(k);
    m_open.erase(m_open.begin() + at);
    sums.erase(sums.begin() + at);
    continued.erase(continued.begin() + at);
  }
  for (std::size_t k = 0; k < m_open.size(); ++k) {
    if (!continued[k]) continue;
    ContactEvent& e = m_open[k];
    const StepSums& step = sums[k];
    e.impulse += 0.5 * (e.lastForce + step.force) * dt;
    const double u = step.momentum / step.force;  // force-weighted relative normal velocity
    // The impact phase ends where the relative normal velocity reverses: within this step at the fraction
    // theta (u linear in time between the commits), and only that part of the step's impulse and work is
    // the phase's. (The whole step's, before: the distributed law's force drops from (1 + a) f to f at
    // the reversal, within a step, and the step's trapezoid after it put the Eq. 5 mass of two risers
    // closing side by side at +1.2 % (e = 0.5) and +2.6 % (e = 0) of their 1500 kg: RisersClosingTest.)
    const double previous = e.lastRelativeVelocity;
    // (Not in a step with a velocity jump of the impulse model: the jump is the reversal, whole.)
    const double theta =
        e.phaseOpen && u >= 0.0 && previous < 0.0 && step.jump == 0.0 ? -previous / (u - previous) : 1.0;
    if (e.phaseOpen) {
      const double force = e.lastPhaseForce + theta * (step.phaseForce - e.lastPhaseForce);
      const double power = e.lastPower + theta * (step.power - e.lastPower);
      e.phaseImpulse += 0.5 * (e.lastPhaseForce + force) * theta * dt + step.jump;
      e.phaseWork += 0.5 * (e.lastPower + power) * theta * dt + step.jumpWork;
      // The normal force at the phase's end within this step (linear, as the impulse's), else the step's.
      e.phasePeakForce = std::max(
          e.phasePeakForce, theta < 1.0 ? e.lastForce + theta * (step.force - e.lastForce) : step.force);
      e.phaseJumped = e.phaseJumped || step.jump != 0.0;
    }
    e.lastForce = step.force;
    e.lastPhaseForce = step.phaseForce;
    e.lastPower = step.power;
    e.lastRelativeVelocity = u;
    e.peakForce = std::max(e.peakForce, step.force);
    e.endTime = time;
    e.lastContactTime = time;
    if (!dynamic) e.sustained = true;
    if (e.duration > 0.0 && time - e.startTime > kSustainedDurations * e.duration) e.sustained = true;
    if (e.phaseOpen && u >= 0.0) {
      endPhase(e, time - (1.0 - theta) * dt, theta < 1.0 ? 0.0 : u, "reversed");
    } else if (e.phaseOpen && e.sustained) {
      endPhase(e, time, u, "sustained");
    }
  }
  // Events no patch continued: closed once the surfaces have parted (see the file comment).
  for (std::size_t k = m_open.size(); k-- > 0;) {
    if (continued[k]) continue;
    ContactEvent& e = m_open[k];
    const double r = e.reach;
    const double gap =
        gapIn(e.lineA, e.lineB, e.lastAMin - r, e.lastAMax + r, e.lastBMin - r, e.lastBMax + r);
    const double closing = 0.5 * e.lastForce * dt;
    if (gap > kSeparationFraction * e.radii || time - e.lastContactTime > m_separationTime) {
      close(k, time, closing, "separated");
    } else {
      e.impulse += closing;
      e.lastForce = 0.0;
      e.lastPhaseForce = 0.0;
      e.lastPower = 0.0;
      // The force is gone while the surfaces stay close (a resting contact that breathes): whatever the
      // impact was, it is over at the last state with contact.
      if (e.phaseOpen) endPhase(e, e.lastContactTime, e.lastRelativeVelocity, "separated");
    }
  }
}

void ContactEventTracker::endPhase(ContactEvent& e, double time, double u, const char* why) {
  e.phaseOpen = false;
  e.phaseEndTime = time;
  e.phaseEnd = why;
  e.phaseVelocityChange = u + e.impactVelocity;  // from -v0 at first contact to u
  measureImpact(e);  // known from here on, while the event goes on (a line that parts by clash energy)
}

void ContactEventTracker::measureImpact(ContactEvent& e) {
  // What the mesh engaged over the impact phase: Eq. 5 where the phase changed the relative normal
  // velocity measurably, the work estimate where it did not (a graze), the lumped FE pair mass where
  // neither has anything to measure.
  const double v0 = e.impactVelocity;
  e.eq5Mass = v0 > 0.0 && e.phaseVelocityChange > 0.05 * v0 && e.phaseImpulse > 0.0
                  ? e.phaseImpulse / e.phaseVelocityChange
                  : std::nan("");
  e.workMass = v0 > 0.0 && e.phaseWork > 0.0 ? 2.0 * e.phaseWork / (v0 * v0) : std::nan("");
  if (std::isfinite(e.eq5Mass)) {
    e.meshMass = e.eq5Mass;
    e.meshMassBasis = "eq5";
  } else if (std::isfinite(e.workMass)) {
    e.meshMass = e.workMass;
    e.meshMassBasis = "work";
  } else {
    e.meshMass = std::isfinite(e.pairMass) ? e.pairMass : 0.0;
    e.meshMassBasis = "lumped";
  }
  e.meshEnergy = 0.5 * e.meshMass * v0 * v0;
  // The impact energy: the mesh-free estimate where it holds (a point contact on lines whose waves do not
  // reach an end within the impact: what a long line engages is set by its impedance, not by its
  // elements), the mesh's otherwise.
  const bool continuum = e.continuumNote.empty() && std::isfinite(e.continuumMass) && e.continuumMass > 0.0;
  e.energyMass = continuum ? e.continuumMass : e.meshMass;
  e.energyMassBasis = continuum ? "continuum" : e.meshMassBasis;
  e.impactEnergy = 0.5 * e.energyMass * v0 * v0;
  e.meshImpactPeakForce = !e.impact ? 0.0 : e.phaseJumped ? std::nan("") : e.phasePeakForce;
  e.impactPeakForce = continuum && e.impact ? e.continuumPeakForce : e.meshImpactPeakForce;
  e.energyWarning.clear();
  if (!e.impact) return;
  if (continuum) {
    // The mesh's two estimates and its one-element bound describe what the elements engaged, which the
    // continuum estimate replaces; only the bound of the whole lines applies.
    if (e.massUpperBound > 0.0 && e.energyMass > e.massUpperBound * (1.0 + 1e-9))
      e.energyWarning = fmt::format(
          "the impact's participating mass {:.4g} kg exceeds the two whole lines' reduced "
          "mass with added mass ({:.4g} kg)",
          e.energyMass, e.massUpperBound);
    return;
  }
  if (std::isfinite(e.eq5Mass) && std::isfinite(e.workMass) &&
      (e.eq5Mass > kEnergyAgreement * e.workMass || e.workMass > kEnergyAgreement * e.eq5Mass))
    e.energyWarning = fmt::format(
        "the impact energy by Eq. 5 ({:.4g} J) and the work absorbed in the impact "
        "phase ({:.4g} J) differ by more than a factor {:g}",
        e.impactEnergy, e.phaseWork, kEnergyAgreement);
  else if (e.massUpperBound > 0.0 && e.energyMass > e.massUpperBound * (1.0 + 1e-9))
    e.energyWarning = fmt::format(
        "the impact's effective mass {:.4g} kg exceeds the two whole lines' reduced "
        "mass with added mass ({:.4g} kg)",
        e.energyMass, e.massUpperBound);
  else if (e.energyMass < e.massLowerBound * (1.0 - 1e-9))
    e.energyWarning = fmt::format(
        "the impact's effective mass {:.4g} kg is below the reduced mass of one "
        "element of each line ({:.4g} kg)",
        e.energyMass, e.massLowerBound);
}

void ContactEventTracker::close(std::size_t openIndex, double time, double closingImpulse,
                                const char* phaseEnd) {
  ContactEvent e = std::move(m_open[openIndex]);
  m_open.erase(m_open.begin() + static_cast<std::ptrdiff_t>(openIndex));
  e.endTime = time;
  e.impulse += closingImpulse + e.jumpImpulse;
  e.jumpImpulse = 0.0;
  // An impact phase still open ends at the last state with contact (its impulse and velocity belong
  // together; the closing half step's impulse has no velocity to go with it).
  if (e.phaseOpen) endPhase(e, e.lastContactTime, e.lastRelativeVelocity, phaseEnd);
  // Paper Eq. 5 per line: the impulse over the change of the normal velocity of the line's contact point.
  const double dva = std::abs(e.normalStart.dot(e.lastVelocityA - e.startVelocityA));
  const double dvb = std::abs(e.normalStart.dot(e.lastVelocityB - e.startVelocityB));
  // Only an impact has a velocity change to measure (in a sustained contact the impulse grows while
  // the velocity does not change): NaN otherwise.
  e.effectiveMassA = !e.impact ? std::nan("") : dva > 1e-12 ? e.impulse / dva : kInf;
  e.effectiveMassB = !e.impact ? std::nan("") : dvb > 1e-12 ? e.impulse / dvb : kInf;
  // The paper's Eq. 5 pair mass over the whole event, as the paper defines it (kept for reference: over
  // a sustained contact the impulse grows without the velocity changing, and so does this quotient).
  const double dvRelative = std::abs(
      e.normalStart.dot((e.lastVelocityA - e.lastVelocityB) - (e.startVelocityA - e.startVelocityB)));
  e.eventEq5Mass = e.impact && dvRelative > 0.05 * e.impactVelocity ? e.impulse / dvRelative : std::nan("");
  measureImpact(e);
  m_closed.push_back(std::move(e));
}

void ContactEventTracker::finish(double time) {
  while (!m_open.empty()) {
    m_open.back().open = true;
    close(m_open.size() - 1, time, 0.0, "run end");
    m_closed.back().endTime = time;
  }
  std::stable_sort(m_closed.begin(), m_closed.end(),
                   [](const ContactEvent& a, const ContactEvent& b) { return a.startTime < b.startTime; });
}

}  // namespace tangle::contact
