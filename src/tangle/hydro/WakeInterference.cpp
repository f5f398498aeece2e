/// @file WakeInterference.cpp
/// The wake of upstream lines on downstream line elements (geometry in WakeInterference.hpp).

#include "tangle/hydro/WakeInterference.hpp"

#include <algorithm>
#include <cmath>

namespace tangle::hydro {

WakeInterference::WakeInterference(const model::Model& model, const CurrentProfile& current)
    : m_model(&model), m_current(&current), m_downstream(model.elements().size(), false) {
  for (const model::WakeSpec& w : model.spec().wakes) {
    Pair p;
    p.upstream = model.lineIndex(w.upstream);
    p.downstream = model.lineIndex(w.downstream);
    if (p.upstream < 0 || p.downstream < 0) continue;  // the reader checked the names
    p.coefficients.kind = w.model == model::WakeSpec::Model::Huse ? WakeKind::Huse : WakeKind::Blevins;
    p.coefficients.k1 = w.k1;
    p.coefficients.k2 = w.k2;
    p.coefficients.k3 = w.k3;
    p.coefficients.a1 = w.a1;
    p.coefficients.a2 = w.a2;
    p.coefficients.a3 = w.a3;
    p.dragCoefficient = w.upstreamDragCoefficient;
    const model::Line& up = model.lines()[static_cast<std::size_t>(p.upstream)];
    const model::Line& down = model.lines()[static_cast<std::size_t>(p.downstream)];
    for (int e = 0; e < up.elementCount; ++e)
      p.blendLength = std::max(
          p.blendLength, model.elements()[static_cast<std::size_t>(up.firstElement + e)].type->outerDiameter);
    // First guess: the upstream element at the same fraction of the line.
    p.guess.resize(static_cast<std::size_t>(down.elementCount));
    for (int e = 0; e < down.elementCount; ++e)
      p.guess[static_cast<std::size_t>(e)] =
          up.firstElement +
          std::min(up.elementCount - 1, e * up.elementCount / std::max(1, down.elementCount));
    for (int e = 0; e < down.elementCount; ++e)
      m_downstream[static_cast<std::size_t>(down.firstElement + e)] = true;
    m_pairs.push_back(std::move(p));
  }
}

void WakeInterference::evaluate(const model::State& state, double rho, std::vector<ElementWake>& out) {
  const auto& elements = m_model->elements();
  out.assign(elements.size(), ElementWake{});
  for (Pair& pair : m_pairs) {
    const model::Line& down = m_model->lines()[static_cast<std::size_t>(pair.downstream)];
    for (int k = 0; k < down.elementCount; ++k) {
      const int e = down.firstElement + k;
      const model::LineElement& el = elements[static_cast<std::size_t>(e)];
      const Vec3& p1 = state.position[el.node1];
      const Vec3& p2 = state.position[el.node2];
      const ElementWake w = wakeAtPoint(state, pair, k, 0.5 * (p1 + p2), (p2 - p1).normalized(), rho);
      ElementWake& o = out[static_cast<std::size_t>(e)];
      if (w.deficit > o.deficit) o = w;
    }
  }
}

Mat3 WakeInterference::liftGradient(const model::State& state, int element, double rho) {
  Mat3 lift = Mat3::Zero();
  const model::LineElement& el = m_model->elements()[static_cast<std::size_t>(element)];
  const Vec3& p1 = state.position[el.node1];
  const Vec3& p2 = state.position[el.node2];
  const Vec3 p = 0.5 * (p1 + p2);
  const Vec3 td = (p2 - p1).normalized();
  // Central differences with a step of 1e-4 of the diameter: the wake varies over its width (~D and more).
  const double h = 1e-4 * std::max(el.type->outerDiameter, 1e-3);
  for (Pair& pair : m_pairs) {
    if (pair.coefficients.kind != WakeKind::Blevins) continue;  // Huse's wake has no lift
    const model::Line& down = m_model->lines()[static_cast<std::size_t>(pair.downstream)];
    if (element < down.firstElement || element >= down.firstElement + down.elementCount) continue;
    const int k = element - down.firstElement;
    const ElementWake centre = wakeAtPoint(state, pair, k, p, td, rho);
    if (centre.deficit <= 0.0) continue;
    lift += difference(state, pair, k, p, td, rho, h, centre, &ElementWake::liftPerLength);
  }
  return lift;
}

Mat3 WakeInterference::difference(const model::State& state, Pair& pair, int k, const Vec3& p, const Vec3& td,
                                  double rho, double h, const ElementWake& centre, Vec3 ElementWake::*field) {
  Mat3 gradient = Mat3::Zero();
  for (int c = 0; c < 3; ++c) {
    const Vec3 step = h * Vec3::Unit(c);
    const ElementWake plus = wakeAtPoint(state, pair, k, p + step, td, rho);
    const ElementWake minus = wakeAtPoint(state, pair, k, p - step, td, rho);
    // The wake ends abruptly (level with the upstream centre, beyond the upstream line's ends): a
    // difference across that edge is not a derivative; take the one-sided one on the wake's side.
    const bool inPlus = plus.deficit > 0.0 && plus.upstreamLine == centre.upstreamLine;
    const bool inMinus = minus.deficit > 0.0 && minus.upstreamLine == centre.upstreamLine;
    if (inPlus && inMinus)
      gradient.col(c) = (plus.*field - minus.*field) / (2.0 * h);
    else if (inPlus)
      gradient.col(c) = (plus.*field - centre.*field) / h;
    else if (inMinus)
      gradient.col(c) = (centre.*field - minus.*field) / h;
  }
  return gradient;
}

WakeGradient WakeInterference::velocityChangeGradient(const model::State& state, int element, double rho) {
  WakeGradient result;
  const model::LineElement& el = m_model->elements()[static_cast<std::size_t>(element)];
  const Vec3& p1 = state.position[el.node1];
  const Vec3& p2 = state.position[el.node2];
  const Vec3 p = 0.5 * (p1 + p2);
  const Vec3 td = (p2 - p1).normalized();
  const double h = 1e-4 * std::max(el.type->outerDiameter, 1e-3);  // as liftGradient
  // The acting wake: of the pairs with this element downstream, the largest deficit at the midpoint.
  Pair* acting = nullptr;
  int k = -1;
  ElementWake centre;
  for (Pair& pair : m_pairs) {
    const model::Line& down = m_model->lines()[static_cast<std::size_t>(pair.downstream)];
    if (element < down.firstElement || element >= down.firstElement + down.elementCount) continue;
    const ElementWake here = wakeAtPoint(state, pair, element - down.firstElement, p, td, rho);
    if (here.deficit > centre.deficit) {
      centre = here;
      acting = &pair;
      k = element - down.firstElement;
    }
  }
  if (acting == nullptr) return result;
  result.midpoint = difference(state, *acting, k, p, td, rho, h, centre, &ElementWake::velocityChange);
  // The upstream element's nodes: the wake moves with it (the midpoint's position relative to it, at the
  // same current, is what counts), so a translation of both by x changes the velocity as the midpoint's by
  // -x would (the current's change with depth at the midpoint is not the upstream's: left out).
  if (centre.upstreamElement >= 0) {
    const model::LineElement& u = m_model->elements()[static_cast<std::size_t>(centre.upstreamElement)];
    const double s = centre.upstreamParameter;
    result.upstreamNode1 = u.node1;
    result.upstreamNode2 = u.node2;
    result.upstream1 = -(1.0 - s) * result.midpoint;
    result.upstream2 = -s * result.midpoint;
  }
  return result;
}

ElementWake WakeInterference::wakeAtPoint(const model::State& state, Pair& pair, int k, const Vec3& p,
                                          const Vec3& td, double rho) const {
  ElementWake o;
  const auto& elements = m_model->elements();
  const model::Line& up = m_model->lines()[static_cast<std::size_t>(pair.upstream)];
  const model::LineElement& el = elements[static_cast<std::size_t>(
      m_model->lines()[static_cast<std::size_t>(pair.downstream)].firstElement + k)];
  const int firstUp = up.firstElement;
  const int lastUp = up.firstElement + up.elementCount - 1;
  // Walk along the upstream line to the element p projects onto.
  int j = std::clamp(pair.guess[static_cast<std::size_t>(k)], firstUp, lastUp);
  double s = 0.0;
  Vec3 a, axis;
  int previousStep = 0;
  bool inside = false;
  for (int step = 0; step <= up.elementCount; ++step) {
    const model::LineElement& u = elements[static_cast<std::size_t>(j)];
    a = state.position[u.node1];
    axis = state.position[u.node2] - a;
    const double length2 = axis.squaredNorm();
    s = length2 > 0.0 ? (p - a).dot(axis) / length2 : 0.5;
    int move = 0;
    if (s < 0.0 && j > firstUp) move = -1;
    if (s > 1.0 && j < lastUp) move = 1;
    if (move == 0) {
      inside = s >= 0.0 && s <= 1.0;
      break;
    }
    if (move == -previousStep) {  // p lies in the gap outside a kink of the upstream line
      inside = true;
      break;
    }
    previousStep = move;
    j += move;
  }
  pair.guess[static_cast<std::size_t>(k)] = j;
  if (!inside) return o;  // beyond an end of the upstream line
  s = std::clamp(s, 0.0, 1.0);
  const double length = axis.norm();
  if (length <= 0.0) return o;
  const Vec3 t = axis / length;
  const Vec3 q = a + s * axis;
  const Vec3 current = m_current->velocity(p, 0.0);  // the steady (first) current, as the wake model assumes
  const Vec3 normalFlow = current - current.dot(t) * t;
  const double speed = normalFlow.norm();
  if (speed <= 1e-9) return o;
  const Vec3 ex = normalFlow / speed;
  const Vec3 d = p - q;
  const double x = d.dot(ex);
  if (x <= 0.0) return o;
  const Vec3 across = d - x * ex - d.dot(t) * t;
  const double y = across.norm();
  const auto [upDiameter, cd] = upstreamSection(state, pair, j, s);
  const double downDiameter = el.type->outerDiameter;
  const WakeValue w = wakeAt(pair.coefficients, x, y, cd, upDiameter, downDiameter);
  // The wake starts at the upstream cylinder's rear surface: between its centre (x = 0) and x = D / 2 the
  // deficit and lift rise from zero by a smoothstep, f = r^2 (3 - 2 r) with r = 2 x / D. Cut off at x = 0
  // instead, a point passing level with the upstream centre (beside it, or with the lines crossing) saw
  // the drag jump by the whole deficit (Huse: 0.6 U on the axis at x = 0+), a force step that stopped the
  // dynamics at steps of 1e-5 s (Newton flipping between the two sides). Beyond x = D / 2 (every point
  // in contact or farther) nothing changes.
  const double r = std::min(1.0, 2.0 * x / upDiameter);
  const double onset = r * r * (3.0 - 2.0 * r);
  const double deficit = onset * w.deficit;
  if (deficit <= 0.0) return o;
  o.deficit = deficit;
  o.upstreamLine = pair.upstream;
  o.upstreamElement = j;
  o.upstreamParameter = s;
  o.velocityChange = -deficit * speed * ex;
  if (w.liftCoefficient != 0.0 && y > 0.0) {
    const Vec3 lift = 0.5 * rho * onset * w.liftCoefficient * downDiameter * speed * speed * (across / y);
    o.liftPerLength = lift - lift.dot(td) * td;
  }
  return o;
}

std::pair<double, double> WakeInterference::upstreamSection(const model::State& state, const Pair& pair,
                                                            int j, double s) const {
  const auto& elements = m_model->elements();
  const model::Line& up = m_model->lines()[static_cast<std::size_t>(pair.upstream)];
  const int first = up.firstElement, last = up.firstElement + up.elementCount - 1;
  auto chord = [&](int i) {
    const model::LineElement& u = elements[static_cast<std::size_t>(i)];
    return (state.position[u.node2] - state.position[u.node1]).norm();
  };
  const section::LineType& own = *elements[static_cast<std::size_t>(j)].type;
  const double ownCd = pair.dragCoefficient > 0.0 ? pair.dragCoefficient : own.dragNormal;
  double length = 0.0, diameter = 0.0, dragArea = 0.0;  // [m], [m^2], [m^2]
  bool uniform = true;  // every element within reach has j's D and C_d (then those, exactly)
  auto add = [&](int i, double covered) {
    const section::LineType& type = *elements[static_cast<std::size_t>(i)].type;
    const double cd = pair.dragCoefficient > 0.0 ? pair.dragCoefficient : type.dragNormal;
    uniform = uniform && type.outerDiameter == own.outerDiameter && cd == ownCd;
    length += covered;
    diameter += covered * type.outerDiameter;
    dragArea += covered * cd * type.outerDiameter;
  };
  // Element j from q backwards and forwards, then its neighbours until blendLength is covered each way.
  const double h = pair.blendLength;
  const double lj = chord(j);
  double back = std::min(h, s * lj), ahead = std::min(h, (1.0 - s) * lj);
  add(j, back + ahead);
  for (int i = j - 1; i >= first && back < h; --i) {
    const double c = std::min(chord(i), h - back);
    add(i, c);
    back += c;
  }
  for (int i = j + 1; i <= last && ahead < h; ++i) {
    const double c = std::min(chord(i), h - ahead);
    add(i, c);
    ahead += c;
  }
  if (uniform || !(length > 0.0)) return {own.outerDiameter, ownCd};
  return {diameter / length, dragArea / diameter};
}

}  // namespace tangle::hydro
