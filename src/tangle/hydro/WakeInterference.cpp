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

WakeInterference::ActingWake WakeInterference::actingWake(const model::State& state, int element,
                                                          double rho) {
  ActingWake a;
  const model::LineElement& el = m_model->elements()[static_cast<std::size_t>(element)];
  const Vec3& p1 = state.position[el.node1];
  const Vec3& p2 = state.position[el.node2];
  a.midpoint = 0.5 * (p1 + p2);
  a.tangent = (p2 - p1).normalized();
  a.step = 1e-4 * std::max(el.type->outerDiameter, 1e-3);
  for (Pair& pair : m_pairs) {
    const model::Line& down = m_model->lines()[static_cast<std::size_t>(pair.downstream)];
    if (element < down.firstElement || element >= down.firstElement + down.elementCount) continue;
    const ElementWake here =
        wakeAtPoint(state, pair, element - down.firstElement, a.midpoint, a.tangent, rho);
    if (here.deficit > a.centre.deficit) {
      a.centre = here;
      a.pair = &pair;
      a.k = element - down.firstElement;
    }
  }
  return a;
}

Mat3 WakeInterference::liftGradient(const model::State& state, int element, double rho) {
  // The acting wake only, as velocityChangeGradient: the others' lift does not act. (Every Blevins pair's
  // gradient was summed, also where a Huse pair's deficit acts, which has no lift.)
  const ActingWake a = actingWake(state, element, rho);
  if (a.pair == nullptr || a.pair->coefficients.kind != WakeKind::Blevins)
    return Mat3::Zero();  // Huse: no lift
  return difference(state, *a.pair, a.k, a.midpoint, a.tangent, rho, a.step, a.centre,
                    &ElementWake::liftPerLength);
}

Mat3 WakeInterference::difference(const model::State& state, Pair& pair, int k, const Vec3& p, const Vec3& td,
                                  double rho, double h, const ElementWake& centre, Vec3 ElementWake::*field) {
  Mat3 gradient = Mat3::Zero();
  for (int c = 0; c < 3; ++c) {
    const Vec3 step = h * Vec3::Unit(c);
    const ElementWake plus = wakeAtPoint(state, pair, k, p + step, td, rho);
    const ElementWake minus = wakeAtPoint(state, pair, k, p - step, td, rho);
    // Where the wake is zero on one side (upstream of the upstream centre, where the current has no normal
    // component, or where its Gaussian underflows): take the one-sided difference on the wake's side.
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
  const ActingWake a = actingWake(state, element, rho);
  if (a.pair == nullptr) return result;
  const ElementWake& centre = a.centre;
  result.midpoint = difference(state, *a.pair, a.k, a.midpoint, a.tangent, rho, a.step, centre,
                               &ElementWake::velocityChange);
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
  // The upstream axis: the chords, with the tangent interpolated along each between its nodes' tangents
  // (a node's the mean direction of its two elements, an end node's its element's). p projects onto the
  // point q(s) = a + s (b - a) of the chord where d = p - q is normal to that tangent, g(s) = d . T(s) = 0,
  // T(s) = (1 - s) t1 + s t2. g is continuous along the whole line (equal at a node from both of its
  // elements) and falls along it wherever p is nearer the axis than its radius of curvature, so its root is
  // unique and moves continuously with p and the line. (Projected on each chord square to the chord, a
  // point in the wedge outside a kink projected onto neither element and took the node with the tangent of
  // whichever element the walk came from: two lazy waves anchored side by side in a current across them saw
  // the deficit jump by 5 % between evaluations of the same state, and the static arc length stalled at
  // 6-60 N against a tolerance of 1 N.)
  auto direction = [&](int i) -> Vec3 {
    const model::LineElement& u = elements[static_cast<std::size_t>(i)];
    const Vec3 c = state.position[u.node2] - state.position[u.node1];
    const double n = c.norm();
    return n > 0.0 ? Vec3(c / n) : Vec3::Zero();
  };
  auto meanDirection = [](const Vec3& u, const Vec3& v) -> Vec3 {
    const Vec3 t = u + v;
    const double n = t.norm();
    return n > 0.0 ? Vec3(t / n) : t;
  };
  int j = std::clamp(pair.guess[static_cast<std::size_t>(k)], firstUp, lastUp);
  double s = 0.0;
  Vec3 a = Vec3::Zero(), axis = Vec3::Zero(), t1 = Vec3::Zero(), t2 = Vec3::Zero();
  int previousStep = 0;
  bool beyondEnd = false;
  for (int step = 0; step <= up.elementCount; ++step) {
    const model::LineElement& u = elements[static_cast<std::size_t>(j)];
    a = state.position[u.node1];
    axis = state.position[u.node2] - a;
    const Vec3 here = direction(j);
    t1 = meanDirection(j > firstUp ? direction(j - 1) : Vec3::Zero(), here);
    t2 = meanDirection(here, j < lastUp ? direction(j + 1) : Vec3::Zero());
    const Vec3 pa = p - a;
    const double g0 = pa.dot(t1), g1 = (pa - axis).dot(t2);
    int move = 0;
    if (g0 < 0.0 && j > firstUp) move = -1;
    if (g1 > 0.0 && j < lastUp) move = 1;
    if (move != 0 && move != -previousStep) {
      previousStep = move;
      j += move;
      continue;
    }
    if (g0 < 0.0 && j == firstUp) {
      s = 0.0;
      beyondEnd = true;
    } else if (g1 > 0.0 && j == lastUp) {
      s = 1.0;
      beyondEnd = true;
    } else if (g0 <= 0.0) {
      s = 0.0;  // g not falling here (p farther than the radius of curvature): the nearer end
    } else if (g1 >= 0.0) {
      s = 1.0;
    } else {
      // g(s) = g0 + c1 s + c2 s^2, a root in (0, 1): the one that tends to the chord's projection as the
      // tangents align (c2 -> 0), in the form without cancellation.
      const Vec3 dt = t2 - t1;
      const double c2 = -axis.dot(dt);
      const double c1 = pa.dot(dt) - axis.dot(t1);
      const double disc = c1 * c1 - 4.0 * c2 * g0;
      const double root = std::sqrt(std::max(disc, 0.0));
      const double denominator = c1 + (c1 >= 0.0 ? root : -root);
      s = denominator != 0.0 ? std::clamp(-2.0 * g0 / denominator, 0.0, 1.0) : 0.5;
    }
    break;
  }
  pair.guess[static_cast<std::size_t>(k)] = j;
  const double length = axis.norm();
  if (length <= 0.0) return o;
  const Vec3 blended = (1.0 - s) * t1 + s * t2;
  if (!(blended.norm() > 0.0)) return o;
  const Vec3 t = blended.normalized();
  const Vec3 q = a + s * axis;
  const Vec3 current = m_current->velocity(p, 0.0);  // the steady (first) current, as the wake model assumes
  const Vec3 normalFlow = current - current.dot(t) * t;
  const double speed = normalFlow.norm();
  if (speed <= 1e-9) return o;
  const Vec3 ex = normalFlow / speed;
  const Vec3 d = p - q;
  const double x = d.dot(ex);
  if (x <= 0.0) return o;
  // Across the wake, normal to the flow: d - x e_x, in the plane normal to the axis where p projects onto it
  // (d . t = 0 there). Beyond an end of the upstream line (q that end) it includes the overshoot d . t along
  // the line, so the wake fades past the end over its own width (Huse's Gaussian in the overshoot) instead
  // of stopping there, where a downstream line running past the end saw part of an element's drag switch
  // on and off as its midpoint's projection crossed the end node. Continuous with the inside (d . t = 0 at
  // the end) and C1 (the overshoot enters squared).
  const Vec3 across = beyondEnd ? Vec3(d - x * ex) : Vec3(d - x * ex - d.dot(t) * t);
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
