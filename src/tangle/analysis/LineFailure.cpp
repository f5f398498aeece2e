#include "tangle/analysis/LineFailure.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tangle::analysis {

namespace {
using Where = model::FailureSpec::Where;
/// Slack of the time trigger [s]: a step cut to land on the failure time ends within round-off of it.
constexpr double kTimeSlack = 1e-9;
/// First step after a break, as a fraction of the time step [-] (limitStep).
constexpr double kRestartFraction = 1.0 / 64.0;
}  // namespace

bool LineFailure::wanted(const model::Model& model) {
  return std::any_of(model.lines().begin(), model.lines().end(),
                     [](const model::Line& l) { return l.spec->failure.enabled; });
}

int LineFailure::elementAt(const model::Model& model, int line, const model::FailureSpec& failure) {
  const model::Line& l = model.lines()[static_cast<std::size_t>(line)];
  switch (failure.where) {
    case Where::Trigger:
      return -1;
    case Where::EndA:
      return l.firstElement;
    case Where::EndB:
      return l.firstElement + l.elementCount - 1;
    case Where::Arc:
      break;
  }
  // The element holding the arc length; at a node, the one after it (the last one at end B).
  const auto it = std::upper_bound(l.arcLength.begin(), l.arcLength.end(), failure.arcLength);
  const int index = std::clamp(static_cast<int>(it - l.arcLength.begin()) - 1, 0, l.elementCount - 1);
  return l.firstElement + index;
}

LineFailure::LineFailure(const model::Model& model, solver::Assembler& assembler,
                         contact::LineContact* contact)
    : m_model(&model), m_assembler(&assembler), m_contact(contact) {
  for (int l = 0; l < static_cast<int>(model.lines().size()); ++l) {
    const model::FailureSpec& f = model.lines()[static_cast<std::size_t>(l)].spec->failure;
    if (!f.enabled) continue;
    if (f.time == 0.0) {
      part(l, elementAt(model, l, f), -std::numeric_limits<double>::infinity(), "time", 0.0, 0.0);
      continue;
    }
    m_pending.push_back(l);
  }
}

double LineFailure::tensionThreshold(const model::FailureSpec& failure, std::size_t element) const {
  return failure.tensionIsBreakingLoad ? m_model->elements()[element].type->minimumBreakingLoad
                                       : failure.tension;
}

double LineFailure::limitStep(const model::State& state, double /*step*/) {
  double limit = std::numeric_limits<double>::infinity();
  if (m_justParted) {
    // The step after a break starts small (kRestartFraction of the time step) and regrows twofold per step:
    // the force of the parted element stops at once, and generalized-alpha spreads a force that jumps over
    // the step it jumps in (a released chain lagged its free fall by half a 0.01 s step, 0.04 m/s).
    m_justParted = false;
    limit = kRestartFraction * m_model->spec().dynamics.timeStep;
  }
  for (const int l : m_pending) {
    const double t = m_model->lines()[static_cast<std::size_t>(l)].spec->failure.time;
    if (std::isfinite(t) && t > state.time + kTimeSlack) limit = std::min(limit, t - state.time);
  }
  return limit;
}

void LineFailure::commitStep(model::State& state, double dt) {
  if (dt <= 0.0 || m_pending.empty()) return;
  bool tensions = false;
  std::vector<int> still;
  for (const int l : m_pending) {
    const model::Line& line = m_model->lines()[static_cast<std::size_t>(l)];
    const model::FailureSpec& f = line.spec->failure;
    const int at = elementAt(*m_model, l, f);
    // Time.
    if (!std::isnan(f.time) && state.time >= f.time - kTimeSlack) {
      part(l, at, state.time, "time", state.time, f.time);
      continue;
    }
    // Tension: the element of the highest tension over its threshold.
    if (f.tension > 0.0 || f.tensionIsBreakingLoad) {
      if (!tensions) {
        m_assembler->elementTension(state, m_tension, nullptr);
        tensions = true;
      }
      int worst = -1;
      double worstRatio = 0.0;
      // Where it parts, when given, is where the tension is measured (a connection at an end parts on the
      // end's tension); otherwise anywhere along the line.
      const int from = at >= 0 ? at : line.firstElement;
      const int to = at >= 0 ? at + 1 : line.firstElement + line.elementCount;
      for (int e = from; e < to; ++e) {
        const double threshold = tensionThreshold(f, static_cast<std::size_t>(e));
        const double ratio = m_tension[static_cast<std::size_t>(e)] / threshold;
        if (ratio >= 1.0 && ratio > worstRatio) {
          worst = e;
          worstRatio = ratio;
        }
      }
      if (worst >= 0) {
        part(l, at >= 0 ? at : worst, state.time, "tension", m_tension[static_cast<std::size_t>(worst)],
             tensionThreshold(f, static_cast<std::size_t>(worst)));
        continue;
      }
    }
    // Clash energy: an impact on the line whose impact phase has ended.
    if (f.clashEnergy > 0.0 && m_contact) {
      const contact::ContactEvent* hit = nullptr;
      const auto consider = [&](const std::vector<contact::ContactEvent>& events) {
        for (const contact::ContactEvent& e : events)
          if ((e.lineA == l || e.lineB == l) && e.impact && !e.phaseOpen && e.impactEnergy >= f.clashEnergy &&
              (!hit || e.startTime < hit->startTime))
            hit = &e;
      };
      consider(m_contact->events());
      consider(m_contact->openEvents());
      if (hit) {
        int element = at;
        if (element < 0) {
          const double arc = hit->lineA == l ? hit->arcAStart : hit->arcBStart;
          model::FailureSpec there = f;
          there.where = Where::Arc;
          there.arcLength = std::clamp(arc, 0.0, line.length);
          element = elementAt(*m_model, l, there);
        }
        part(l, element, state.time, "clash energy", hit->impactEnergy, f.clashEnergy);
        continue;
      }
    }
    still.push_back(l);
  }
  m_pending = std::move(still);
}

void LineFailure::part(int line, int element, double time, const std::string& trigger, double value,
                       double threshold) {
  const model::Line& l = m_model->lines()[static_cast<std::size_t>(line)];
  m_model->parted().part(static_cast<std::size_t>(element), time);
  m_justParted = std::isfinite(time);
  if (m_contact) m_contact->elementsParted();
  LineBreak b;
  b.line = line;
  b.element = element;
  b.time = time;
  b.arcFrom = l.arcLength[static_cast<std::size_t>(element - l.firstElement)];
  b.arcTo = l.arcLength[static_cast<std::size_t>(element - l.firstElement + 1)];
  b.trigger = trigger;
  b.value = value;
  b.threshold = threshold;
  const std::string where =
      fmt::format("in its element from {:.4g} to {:.4g} m from end A", b.arcFrom, b.arcTo);
  if (!std::isfinite(time))
    b.description = fmt::format(
        "line '{}' is parted {} from the start (failure time 0): the statics and the "
        "dynamics are those of the damaged system",
        l.name, where);
  else if (trigger == "time")
    b.description = fmt::format("line '{}' parted at t = {:.6g} s {} (failure time)", l.name, time, where);
  else if (trigger == "tension")
    b.description = fmt::format(
        "line '{}' parted at t = {:.6g} s {}: effective tension {:.4g} kN reached the "
        "threshold {:.4g} kN",
        l.name, time, where, value / 1000.0, threshold / 1000.0);
  else
    b.description = fmt::format(
        "line '{}' parted at t = {:.6g} s {}: a clash of {:.4g} J reached the "
        "threshold {:.4g} J",
        l.name, time, where, value, threshold);
  m_breaks.push_back(std::move(b));
}

}  // namespace tangle::analysis
