#include "tangle/io/HtmlReport.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "tangle/contact/ClashReport.hpp"
#include "tangle/contact/ClearanceEnvelope.hpp"
#include "tangle/contact/LineContact.hpp"
#include "tangle/core/Error.hpp"
#include "tangle/geometry/Rotation.hpp"
#include "tangle/core/OutputFile.hpp"
#include "tangle/io/ReportTemplate.hpp"

namespace tangle::io {

namespace fs = std::filesystem;

namespace {

/// A JSON string literal; "</" is written "<\/" so the text cannot close the page's <script> element.
std::string quote(std::string_view s) {
  std::string out = "\"";
  char prev = 0;
  for (char c : s) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      case '/':
        out += prev == '<' ? "\\/" : "/";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          out += fmt::format("\\u{:04x}", static_cast<int>(c));
        } else {
          out += c;
        }
    }
    prev = c;
  }
  return out + "\"";
}

/// Appends a number with `digits` significant digits (null when not finite). The report's usual precisions
/// with compiled formats into a stack buffer: a frame's arrays formatted value by value through a parsed
/// format and a string each cost more for the same text (docs/performance.md).
void appendSig(std::string& out, double v, int digits) {
  if (!std::isfinite(v)) {
    out += "null";
    return;
  }
  if (v == 0.0) {
    out += '0';
    return;
  }
  char buffer[40];
  char* end = nullptr;
  switch (digits) {
    case 3:
      end = fmt::format_to(buffer, FMT_COMPILE("{:.3g}"), v);
      break;
    case 4:
      end = fmt::format_to(buffer, FMT_COMPILE("{:.4g}"), v);
      break;
    case 6:
      end = fmt::format_to(buffer, FMT_COMPILE("{:.6g}"), v);
      break;
    default:
      end = fmt::format_to(buffer, "{:.{}g}", v, digits);
  }
  out.append(buffer, end);
}

/// A number with `digits` significant digits (null when not finite).
std::string sig(double v, int digits) {
  std::string out;
  appendSig(out, v, digits);
  return out;
}

/// A number rounded to `decimals` decimals, without trailing zeros (null when not finite).
std::string fixed(double v, int decimals) {
  if (!std::isfinite(v)) return "null";
  std::string s = fmt::format("{:.{}f}", v, decimals);
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

template <class F>
std::string array(std::size_t n, F&& item) {
  std::string out = "[";
  for (std::size_t i = 0; i < n; ++i) {
    if (i) out += ',';
    out += item(i);
  }
  return out + "]";
}

std::string sigArray(const std::vector<double>& v, int digits, double scale = 1.0) {
  std::string out = "[";
  out.reserve(8 * v.size() + 2);
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i) out += ',';
    appendSig(out, v[i] * scale, digits);
  }
  return out + "]";
}

/// Position along a line at unstretched arc length `arc` [m] (linear between nodes).
Vec3 pointAt(const solver::LineSnapshot& s, double arc) {
  const auto& a = s.arcLength;
  if (a.empty()) return Vec3::Zero();
  if (arc <= a.front()) return s.position.front();
  if (arc >= a.back()) return s.position.back();
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(a.begin(), a.end(), arc) - a.begin());
  const double w = (arc - a[i - 1]) / std::max(a[i] - a[i - 1], 1e-12);
  return (1.0 - w) * s.position[i - 1] + w * s.position[i];
}

std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return {};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

HtmlReport::HtmlReport(const model::Model& model, std::string kind, std::string summary)
    : m_model(&model), m_kind(std::move(kind)), m_summary(std::move(summary)) {
  m_endTension.resize(2 * model.lines().size());
  m_vesselXY.resize(2 * model.vessels().size());
}

void HtmlReport::planFrames(int expectedOutputs) {
  long nodes = 0;
  for (const model::Line& l : m_model->lines()) nodes += l.nodeCount;
  const long maxFrames = std::max(2L, std::min<long>(kMaxFrames, kMaxNodeFrames / std::max(nodes, 1L)));
  m_stride = static_cast<int>(std::max(1L, (expectedOutputs + maxFrames - 1) / maxFrames));
}

std::string HtmlReport::frameJson(const std::vector<solver::LineSnapshot>& lines, const model::State& state,
                                  const contact::LineContact* contact,
                                  const contact::ClearanceEnvelope* envelope) const {
  std::string out = fmt::format("{{\"t\":{},\"lines\":[", fixed(state.time, 4));
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const solver::LineSnapshot& s = lines[l];
    if (l) out += ',';
    out += "{\"p\":[";
    for (std::size_t i = 0; i < 3 * s.position.size(); ++i) {
      if (i) out += ',';
      const fmt::format_int millimetres(std::llround(1000.0 * s.position[i / 3][static_cast<int>(i % 3)]));
      out.append(millimetres.data(), millimetres.size());
    }
    out += ']';
    out += ",\"T\":" + sigArray(s.tension, 4, 1e-3);
    out += ",\"M\":" + sigArray(s.bendingMoment, 4, 1e-3);
    out += ",\"C\":" + sigArray(s.curvature, 3);
    if (envelope) {
      // Clearance of each node to the nearest other line it is assessed against (null beyond the margin).
      const std::vector<double> c = envelope->nearestClearance(state, static_cast<int>(l));
      if (!c.empty()) out += ",\"c\":" + array(c.size(), [&](std::size_t i) { return fixed(c[i], 3); });
    }
    out += '}';
  }
  out += "],\"v\":" + array(m_model->vessels().size(), [&](std::size_t v) {
           const int node = m_model->vesselNode(static_cast<int>(v));
           const Vec3 r = geometry::logMap(state.triad[node]);
           const Vec3& x = state.position[node];
           return fmt::format("[{},{},{},{},{},{}]", fixed(x.x(), 3), fixed(x.y(), 3), fixed(x.z(), 3),
                              sig(r.x(), 6), sig(r.y(), 6), sig(r.z(), 6));
         });
  // Contact patches: force centroid on both lines and the total normal force.
  out += ",\"k\":[";
  if (contact) {
    bool first = true;
    for (const contact::ContactPatch& p : contact->patches()) {
      if (p.lineA < 0 || p.lineB < 0 || p.lineA >= static_cast<int>(lines.size()) ||
          p.lineB >= static_cast<int>(lines.size()) || !(p.force > 0.0))
        continue;
      const Vec3 a = pointAt(lines[p.lineA], p.arcA), b = pointAt(lines[p.lineB], p.arcB);
      if (!first) out += ',';
      first = false;
      out += fmt::format("[{},{},{},{},{},{},{},{},{}]", p.lineA, p.lineB, fixed(a.x(), 3), fixed(a.y(), 3),
                         fixed(a.z(), 3), fixed(b.x(), 3), fixed(b.y(), 3), fixed(b.z(), 3), sig(p.force, 4));
    }
  }
  return out + "]}";
}

void HtmlReport::setStatics(const std::vector<solver::LineSnapshot>& lines, const model::State& state,
                            const contact::LineContact* contact, const contact::ClearanceEnvelope* envelope) {
  m_statics = frameJson(lines, state, contact, envelope);
  m_clearanceMargin = envelope ? envelope->margin() : std::numeric_limits<double>::quiet_NaN();
  // Static ranges (the values themselves) until the dynamics replace them.
  for (std::size_t l = 0; l < lines.size(); ++l)
    setRange(static_cast<int>(l), lines[l].tension, lines[l].tension, lines[l].bendingMoment,
             lines[l].bendingMoment, lines[l].curvature, lines[l].curvature);
}

void HtmlReport::recordOutput(const std::vector<solver::LineSnapshot>& lines, const model::State& state,
                              const contact::LineContact* contact,
                              const contact::ClearanceEnvelope* envelope) {
  m_time.push_back(state.time);
  for (std::size_t l = 0; l < lines.size() && 2 * l + 1 < m_endTension.size(); ++l) {
    m_endTension[2 * l].push_back(lines[l].endTensionA);
    m_endTension[2 * l + 1].push_back(lines[l].endTensionB);
  }
  for (std::size_t v = 0; v < m_model->vessels().size(); ++v) {
    const Vec3& x = state.position[m_model->vesselNode(static_cast<int>(v))];
    m_vesselXY[2 * v].push_back(x.x());
    m_vesselXY[2 * v + 1].push_back(x.y());
  }
  if (m_outputs % m_stride == 0) m_frames.push_back(frameJson(lines, state, contact, envelope));
  ++m_outputs;
}

void HtmlReport::setRange(int line, const std::vector<double>& tensionMin,
                          const std::vector<double>& tensionMax, const std::vector<double>& momentMin,
                          const std::vector<double>& momentMax, const std::vector<double>& curvatureMin,
                          const std::vector<double>& curvatureMax) {
  if (static_cast<int>(m_rangeParts.size()) <= line) m_rangeParts.resize(line + 1);
  m_rangeParts[line] =
      fmt::format("{{\"Tmin\":{},\"Tmax\":{},\"Mmin\":{},\"Mmax\":{},\"Cmin\":{},\"Cmax\":{}}}",
                  sigArray(tensionMin, 4, 1e-3), sigArray(tensionMax, 4, 1e-3), sigArray(momentMin, 4, 1e-3),
                  sigArray(momentMax, 4, 1e-3), sigArray(curvatureMin, 3), sigArray(curvatureMax, 3));
}

void HtmlReport::setFatigue(const analysis::FatigueDamage& fatigue,
                            const std::vector<analysis::FatigueDamage::Line>& damage) {
  const double factor = fatigue.annualFactor();
  m_fatigue = array(damage.size(), [&](std::size_t i) {
    const analysis::FatigueDamage::Line& l = damage[i];
    std::vector<double> arc, annual;
    for (const analysis::FatigueDamage::Node& n : l.nodes) {
      arc.push_back(n.arcLength);
      annual.push_back(n.damage * factor);
    }
    return fmt::format("{{\"line\":{},\"arc\":{},\"damage\":{}}}", l.line, sigArray(arc, 6), sigArray(annual, 4));
  });
}

void HtmlReport::setPeakFit(int line, const analysis::PeakSet& peaks, const analysis::PeakFit& rayleigh,
                            const analysis::PeakFit& weibull) {
  m_peakFits.push_back(fmt::format("{{\"line\":{},\"mean\":{},\"peaks\":{},\"rayleigh\":[{},{}],\"weibull\":[{},{}]}}",
                                   line, sig(peaks.mean, 8), sigArray(peaks.peaks, 6), sig(rayleigh.scale, 6),
                                   sig(rayleigh.shape, 6), sig(weibull.scale, 6), sig(weibull.shape, 6)));
}

void HtmlReport::setClashDamage(const std::vector<analysis::LineClashDamage>& damage) {
  m_clashDamage = array(damage.size(), [&](std::size_t i) {
    const analysis::LineClashDamage& l = damage[i];
    std::vector<double> mid, energy, impacts;
    for (const analysis::ClashDamageBin& b : l.bins) {
      mid.push_back(0.5 * (b.from + b.to));
      energy.push_back(b.energy);
      impacts.push_back(b.impacts);
    }
    return fmt::format("{{\"line\":{},\"arc\":{},\"energy\":{},\"impacts\":{}}}", l.line, sigArray(mid, 6),
                       sigArray(energy, 4), sigArray(impacts, 6));
  });
}

void HtmlReport::addHullImpacts(const std::vector<vessel::HullImpact>& events) {
  for (const vessel::HullImpact& e : events) {
    if (!e.impact) continue;
    const double mass = e.lineOnHull || !std::isfinite(e.bodiesMass) ? e.eq5Mass : e.bodiesMass;
    m_impacts.push_back(fmt::format(
        "{{\"bodies\":{},\"kind\":{},\"start\":{},\"end\":{},\"peak\":{},\"impulse\":{},\"speed\":{},"
        "\"rebound\":{},\"energy\":{},\"mass\":{},\"pos\":[{},{},{}]}}",
        quote(e.bodyA + " / " + e.bodyB), quote(e.lineOnHull ? "line on hull" : "hull on hull"),
        fixed(e.startTime, 4), fixed(e.endTime, 4), sig(e.peakForce, 4), sig(e.impulse, 4),
        sig(e.impactVelocity, 4), sig(e.reboundVelocity, 4), sig(e.impactEnergy, 4), sig(mass, 4),
        fixed(e.position.x(), 3), fixed(e.position.y(), 3), fixed(e.position.z(), 3)));
  }
}

void HtmlReport::addSeabedImpacts(const std::vector<analysis::SeabedImpact>& events) {
  for (const analysis::SeabedImpact& e : events) {
    if (!e.impact) continue;
    m_impacts.push_back(fmt::format(
        "{{\"bodies\":{},\"kind\":\"line on seabed\",\"start\":{},\"end\":{},\"peak\":{},\"impulse\":{},"
        "\"speed\":{},\"rebound\":null,\"energy\":{},\"mass\":{},\"pos\":[{},{},{}]}}",
        quote(m_model->lines()[static_cast<std::size_t>(e.line)].name + " / seabed"), fixed(e.startTime, 4),
        fixed(e.endTime, 4), sig(e.peakForce, 4), sig(e.impulse, 4), sig(e.impactVelocity, 4),
        sig(e.impactEnergy, 4), sig(e.eq5Mass, 4), fixed(e.position.x(), 3), fixed(e.position.y(), 3),
        fixed(e.position.z(), 3)));
  }
}

void HtmlReport::setClash(const contact::LineContact& contact, const contact::ClashReport& clash) {
  const auto& lines = m_model->lines();
  std::string out = "{\"events\":";
  const auto& events = contact.events();
  out += array(events.size(), [&](std::size_t i) {
    const contact::ContactEvent& e = events[i];
    return fmt::format(
        "{{\"a\":{},\"b\":{},\"start\":{},\"end\":{},\"kind\":{},\"peak\":{},\"impulse\":{},\"speed\":{},"
        "\"energy\":{},\"arcA\":{},\"arcB\":{},\"pos\":[{},{},{}]}}",
        e.lineA, e.lineB, fixed(e.startTime, 4), fixed(e.endTime, 4), quote(e.kind()), sig(e.peakForce, 4),
        sig(e.impulse, 4), sig(e.impactVelocity, 4), sig(e.impactEnergy, 4), fixed(e.arcAStart, 2),
        fixed(e.arcBStart, 2), fixed(e.positionStart.x(), 3), fixed(e.positionStart.y(), 3),
        fixed(e.positionStart.z(), 3));
  });
  // Minimum clearance of each pair against time (output times).
  const auto& pairs = clash.pairs();
  out += ",\"pairs\":" + array(pairs.size(), [&](std::size_t p) {
           return fmt::format("[{},{}]", quote(lines[pairs[p][0]].name), quote(lines[pairs[p][1]].name));
         });
  std::vector<double> times;
  std::vector<std::vector<double>> values(pairs.size());
  for (const auto& s : clash.samples()) {
    if (times.empty() || s.time > times.back() + 1e-12) {
      times.push_back(s.time);
      for (auto& v : values) v.push_back(std::numeric_limits<double>::quiet_NaN());
    }
    if (s.pair >= 0 && s.pair < static_cast<int>(values.size())) values[s.pair].back() = s.clearance;
  }
  out += ",\"t\":" + array(times.size(), [&](std::size_t i) { return fixed(times[i], 4); });
  out += ",\"clearance\":" + array(values.size(), [&](std::size_t p) {
           return array(values[p].size(), [&](std::size_t i) { return fixed(values[p][i], 4); });
         });
  m_clash = out + "}";
}

void HtmlReport::setEnvelope(const contact::ClearanceEnvelope& envelope) {
  const auto& sides = envelope.sides();
  m_envelope = array(sides.size(), [&](std::size_t i) {
    const auto& s = sides[i];
    return fmt::format(
        "{{\"line\":{},\"other\":{},\"static\":{},\"dynamic\":{}}}", s.line, s.other,
        array(s.staticClearance.size(), [&](std::size_t k) { return fixed(s.staticClearance[k], 4); }),
        array(s.dynamicClearance.size(), [&](std::size_t k) { return fixed(s.dynamicClearance[k], 4); }));
  });
}

void HtmlReport::writeData(const fs::path& file) const {
  fs::create_directories(file.parent_path());
  core::OutputFile out(file);
  out.write(json());
  out.close();
}

std::string HtmlReport::json() const {
  struct Text {
    std::string s;
    void write(const std::string& t) { s += t; }
  } f;
  const model::Model& m = *m_model;
  const model::ModelSpec& spec = m.spec();
  const auto& env = m.environment();
  f.write(fmt::format("{{\"format\":1,\"version\":{},\"kind\":{},\"model\":{},\"title\":{},\"status\":{},",
                      quote(TANGLE_VERSION), quote(m_kind), quote(spec.sourceFile), quote(spec.title),
                      quote(m_status)));
  f.write("\"summary\":" + quote(m_summary) + ",");
  const seabed::SeabedSurface& bed = m.seabedSurface();
  if (bed.isFlat()) {
    f.write(fmt::format("\"depth\":{},", fixed(env.waterDepth, 3)));
  } else {
    // A seabed that is not flat: its heights on a square grid about the lines (41 x 41 points, twice their
    // extent), which the viewer interpolates bilinearly under its seabed plane.
    const model::State start = m.initialState();
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const Vec3& p : start.position) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    if (start.position.empty()) lo = hi = Vec3::Zero();
    const double half = std::max({hi.x() - lo.x(), hi.y() - lo.y(), 50.0});
    const double cx = 0.5 * (lo.x() + hi.x()), cy = 0.5 * (lo.y() + hi.y());
    constexpr int kSamples = 41;
    std::vector<double> heights;
    double deepest = 0.0;
    for (int j = 0; j < kSamples; ++j)
      for (int i = 0; i < kSamples; ++i) {
        const double h = bed.height(cx - half + 2.0 * half * i / (kSamples - 1),
                                    cy - half + 2.0 * half * j / (kSamples - 1));
        heights.push_back(h);
        deepest = std::max(deepest, -h);
      }
    f.write(fmt::format("\"depth\":{},", fixed(deepest, 3)));
    f.write(fmt::format("\"seabed\":{{\"x0\":{},\"y0\":{},\"step\":{},\"n\":{},\"describe\":{},\"z\":{}}},",
                        fixed(cx - half, 3), fixed(cy - half, 3), fixed(2.0 * half / (kSamples - 1), 6),
                        kSamples, quote(bed.describe()),
                        array(heights.size(), [&](std::size_t k) { return fixed(heights[k], 3); })));
  }
  // Lines: names, arc lengths, contact diameters, sections.
  f.write("\"lines\":" +
          array(m.lines().size(),
                [&](std::size_t l) {
                  const model::Line& line = m.lines()[l];
                  const auto& d = m.nodeContactDiameter();
                  std::string sections = array(line.spec->sections.size(), [&](std::size_t k) {
                    const model::SectionSpec& s = line.spec->sections[k];
                    return fmt::format("{{\"type\":{},\"length\":{},\"elements\":{}}}", quote(s.lineType),
                                       fixed(s.length, 3), s.elements);
                  });
                  return fmt::format("{{\"name\":{},\"length\":{},\"arc\":{},\"diam\":{},\"sections\":{}}}",
                                     quote(line.name), fixed(line.length, 3),
                                     array(line.arcLength.size(),
                                           [&](std::size_t i) { return fixed(line.arcLength[i], 3); }),
                                     array(static_cast<std::size_t>(line.nodeCount),
                                           [&](std::size_t i) { return fixed(d[line.firstNode + i], 4); }),
                                     sections);
                }) +
          ",");
  // Vessels as boxes: length L from the current-force areas (A_y = L T, A_x = B T) when given.
  f.write("\"vessels\":" +
          array(m.vessels().size(),
                [&](std::size_t v) {
                  const model::VesselSpec& s = m.vessels()[v];
                  const Vec3& a = s.currentAreas;
                  const double length = a.z() > 0.0 ? a.z() : 100.0;
                  const double draft =
                      a.y() > 0.0 ? std::clamp(a.y() / length, 1.0, 0.5 * length) : 0.1 * length;
                  const double breadth = a.x() > 0.0 ? std::clamp(a.x() / draft, 1.0, length) : 0.2 * length;
                  const bool sized = a.x() > 0.0 && a.y() > 0.0 && a.z() > 0.0;
                  // Its hull's shapes (vessels[].hull), vessel axes, drawn instead of the box.
                  std::string hull;
                  if (!s.hull.empty()) {
                    const auto vec = [](const Vec3& x) {
                      return fmt::format("[{},{},{}]", fixed(x.x(), 3), fixed(x.y(), 3), fixed(x.z(), 3));
                    };
                    hull = ",\"hull\":" + array(s.hull.size(), [&](std::size_t k) {
                             const geometry::HullShape& h = s.hull[k];
                             if (h.kind() == geometry::HullShape::Kind::Box)
                               return fmt::format("{{\"kind\":\"box\",\"c\":{},\"s\":{}}}", vec(h.centre()),
                                                  vec(h.size()));
                             return fmt::format("{{\"kind\":{},\"a\":{},\"b\":{},\"d\":{}}}",
                                                quote(h.kindName()), vec(h.endA()), vec(h.endB()),
                                                fixed(h.diameter(), 3));
                           });
                  }
                  return fmt::format(
                      "{{\"name\":{},\"mode\":{},\"length\":{},\"breadth\":{},\"draft\":{},\"sized\":{}{}}}",
                      quote(s.name), quote(model::vesselModeName(s.mode)), fixed(length, 2),
                      fixed(breadth, 2), fixed(draft, 2), sized ? "true" : "false", hull);
                }) +
          ",");
  f.write("\"current\":" +
          array(env.current.size(),
                [&](std::size_t i) {
                  const auto& c = env.current[i];
                  return fmt::format("{{\"z\":{},\"speed\":{},\"azimuth\":{}}}", fixed(c.z, 3),
                                     fixed(c.speed, 4), fixed(c.azimuth, 6));
                }) +
          ",");
  const model::WaveSpec& w = env.waves;
  // The arrow's label: H and T of a regular wave, Hs and Tp of a sea; for given components Hs = 4 sqrt(m0) and
  // the period and direction of the largest component.
  double height = w.kind == model::WaveKind::Jonswap ? w.significantHeight : w.height;
  double period = w.kind == model::WaveKind::Jonswap ? w.peakPeriod : w.period;
  double azimuth = w.azimuth;
  if (w.kind == model::WaveKind::Components && !w.componentTable.empty()) {
    double m0 = 0.0;
    const std::array<double, 4>* largest = &w.componentTable.front();
    for (const auto& c : w.componentTable) {
      m0 += 0.5 * c[1] * c[1];
      if (c[1] > (*largest)[1]) largest = &c;
    }
    height = 4.0 * std::sqrt(m0);
    period = (*largest)[0];
    azimuth = (*largest)[3];
  }
  f.write(fmt::format("\"waves\":{{\"kind\":{},\"height\":{},\"period\":{},\"azimuth\":{}}},",
                      quote(w.kind == model::WaveKind::None         ? "none"
                            : w.kind == model::WaveKind::Airy       ? "airy"
                            : w.kind == model::WaveKind::Components ? "components"
                                                                    : "jonswap"),
                      fixed(height, 3), fixed(period, 3), fixed(azimuth, 6)));
  f.write(fmt::format("\"wind\":{{\"speed\":{},\"azimuth\":{}}},", fixed(env.windSpeed, 3),
                      fixed(env.windAzimuth, 6)));
  const double interval = spec.dynamics.outputInterval;
  f.write(fmt::format("\"decimation\":{{\"stride\":{},\"output_interval\":{},\"outputs\":{},\"frames\":{}}},",
                      m_stride, sig(interval, 6), m_outputs, m_frames.size()));
  f.write("\"statics\":" + (m_statics.empty() ? std::string("null") : m_statics) + ",");
  f.write("\"frames\":[");
  for (std::size_t i = 0; i < m_frames.size(); ++i) {
    if (i) f.write(",");
    f.write(m_frames[i]);
    f.write("\n");
  }
  f.write("],");
  // Histories at every output time (end tensions [kN], vessel x, y [m]).
  f.write("\"history\":{\"t\":" + array(m_time.size(), [&](std::size_t i) { return fixed(m_time[i], 4); }));
  f.write(",\"endTension\":" +
          array(m_endTension.size(), [&](std::size_t k) { return sigArray(m_endTension[k], 5, 1e-3); }));
  f.write(",\"vesselXY\":" +
          array(m_vesselXY.size(),
                [&](std::size_t k) {
                  return array(m_vesselXY[k].size(),
                               [&](std::size_t i) { return fixed(m_vesselXY[k][i], 3); });
                }) +
          "},");
  f.write(
      "\"ranges\":" +
      array(m_rangeParts.size(),
            [&](std::size_t l) { return m_rangeParts[l].empty() ? std::string("null") : m_rangeParts[l]; }) +
      ",");
  f.write("\"clash\":" + m_clash + ",\"envelope\":" + m_envelope + ",\"clearanceMargin\":" +
          fixed(m_clearanceMargin, 3) + ",\"fatigue\":" + m_fatigue + ",\"clashDamage\":" + m_clashDamage +
          ",\"impacts\":" + array(m_impacts.size(), [&](std::size_t i) { return m_impacts[i]; }) +
          ",\"peakFits\":" + array(m_peakFits.size(), [&](std::size_t i) { return m_peakFits[i]; }) + "}\n");
  return std::move(f.s);
}

fs::path HtmlReport::threeDirectory() { return fs::path(TANGLE_THREE_DIR); }

void HtmlReport::rebuildPage(const fs::path& dir) {
  const fs::path dataFile = dir / "report" / "data.json";
  if (!fs::exists(dataFile))
    throw InputError(dataFile.string(), 0, "",
                     "report data not found (tangle run writes it with the results; run the analysis again)");
  writePage(readText(dataFile), readText(dir / "run.log"), dir / "report.html");
}

void HtmlReport::writePage(const std::string& data, const std::string& log, const fs::path& page) {
  const fs::path threeFile = threeDirectory() / "three.min.js";
  const fs::path controlsFile = threeDirectory() / "examples" / "js" / "controls" / "OrbitControls.js";
  const std::string three = readText(threeFile);
  const std::string controls = readText(controlsFile);
  if (three.empty() || controls.empty())
    throw InputError(three.empty() ? threeFile.string() : controlsFile.string(), 0, "",
                     "not found: the report page needs three.js (Debian package libjs-three)");
  std::string html(kReportHtml);
  auto replace = [&](std::string_view marker, const std::string& text) {
    const std::size_t at = html.find(marker);
    if (at == std::string::npos) throw std::logic_error(fmt::format("report template lacks {}", marker));
    html.replace(at, marker.size(), text);
  };
  // The data last: it may be large and must not be searched for markers.
  replace("/*@CSS@*/", kReportCss);
  replace("/*@THREE@*/", three + "\n" + controls);
  replace("/*@APP@*/", kReportJs);
  replace("/*@LOG@*/", quote(log));
  replace("/*@DATA@*/", data);
  fs::create_directories(page.parent_path().empty() ? fs::path(".") : page.parent_path());
  core::OutputFile out(page);
  out.write(html);
  out.close();
}

}  // namespace tangle::io
