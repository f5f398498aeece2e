#include "tangle/contact/StaticContactReport.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include "tangle/core/OutputFile.hpp"

namespace tangle::contact {

namespace {
/// Adds `from` to `into`: the sums (forces, length, counts) and the extremes (peak per length, arc ranges).
/// The centre is left to the caller (a weighted mean).
void addZone(StaticContactZone& into, const StaticContactZone& from) {
  into.force += from.force;
  into.normal += from.normal;
  into.length += from.length;
  into.peakPerLength = std::max(into.peakPerLength, from.peakPerLength);
  into.arc1From = std::min(into.arc1From, from.arc1From);
  into.arc1To = std::max(into.arc1To, from.arc1To);
  into.arc2From = std::min(into.arc2From, from.arc2From);
  into.arc2To = std::max(into.arc2To, from.arc2To);
  into.points += from.points;
  into.samples += from.samples;
}
}  // namespace

std::vector<StaticContactZone> groupContactZones(std::vector<StaticContactSample> samples,
                                                 const std::vector<double>& joinDistance) {
  // A self-contact's samples with the lower arc first (the header's comment).
  for (StaticContactSample& s : samples) {
    if (s.line1 != s.line2 || !(s.arc1 > s.arc2)) continue;
    std::swap(s.arc1, s.arc2);
    s.force = -s.force;
  }
  std::stable_sort(samples.begin(), samples.end(),
                   [](const StaticContactSample& a, const StaticContactSample& b) {
                     if (a.line1 != b.line1) return a.line1 < b.line1;
                     if (a.line2 != b.line2) return a.line2 < b.line2;
                     return a.arc1 < b.arc1;
                   });
  // Two samples of a pair are of one place when they are within the join distances along both lines; a
  // place is a chain of such links (union-find, each root the place's first sample along line 1). Along line
  // 1 alone, a line wrapped round another (touching it at one arc of line 1 from two arcs of line 2) was one
  // place.
  const std::size_t n = samples.size();
  std::vector<std::size_t> root(n);
  for (std::size_t i = 0; i < n; ++i) root[i] = i;
  const auto find = [&](std::size_t i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const StaticContactSample& a = samples[i];
    const double join1 = joinDistance[static_cast<std::size_t>(a.line1)];
    const double join2 = joinDistance[static_cast<std::size_t>(a.line2)];
    for (std::size_t j = i + 1; j < n; ++j) {
      const StaticContactSample& b = samples[j];
      if (b.line1 != a.line1 || b.line2 != a.line2 || b.arc1 - a.arc1 > join1) break;
      if (std::abs(b.arc2 - a.arc2) > join2) continue;
      const std::size_t ra = find(i), rb = find(j);
      if (ra != rb) root[std::max(ra, rb)] = std::min(ra, rb);
    }
  }
  std::vector<StaticContactZone> zones;
  std::vector<int> zoneOf(n, -1);  // per root sample: its zone
  for (std::size_t i = 0; i < n; ++i) {
    const StaticContactSample& s = samples[i];
    // The sample as a zone of its own; its centre the normal force times the position (divided below).
    StaticContactZone one;
    one.line1 = s.line1;
    one.line2 = s.line2;
    one.force = s.force;
    one.normal = s.normal;
    one.length = s.length;
    one.peakPerLength = s.perLength;
    one.arc1From = one.arc1To = s.arc1;
    one.arc2From = one.arc2To = s.arc2;
    one.centre = s.normal * s.position;
    (s.length > 0.0 ? one.samples : one.points) = 1;
    int& zone = zoneOf[find(i)];
    if (zone >= 0) {
      addZone(zones[static_cast<std::size_t>(zone)], one);
      zones[static_cast<std::size_t>(zone)].centre += one.centre;
    } else {
      zone = static_cast<int>(zones.size());
      zones.push_back(one);
    }
  }
  for (StaticContactZone& z : zones)
    if (z.normal > 0.0) z.centre /= z.normal;
  return zones;
}

std::string writeStaticContact(const std::filesystem::path& dir, const model::Model& model, const LineContact& contact,
                               const model::State& state) {
  const auto& lines = model.lines();
  const auto& elements = model.elements();
  std::filesystem::create_directories(dir / "statics");
  std::vector<StaticContactSample> samples;
  // A sample with its pair in ascending order (the force is the one on the lower line index).
  const auto add = [&](int lineA, int lineB, double arcA, double arcB, const Vec3& position,
                       const Vec3& forceOnA, double normal, double length, double perLength) {
    StaticContactSample s;
    const bool swapped = lineA > lineB;
    s.line1 = swapped ? lineB : lineA;
    s.line2 = swapped ? lineA : lineB;
    s.arc1 = swapped ? arcB : arcA;
    s.arc2 = swapped ? arcA : arcB;
    s.position = position;
    s.force = swapped ? Vec3(-forceOnA) : forceOnA;
    s.normal = normal;
    s.length = length;
    s.perLength = perLength;
    samples.push_back(s);
  };
  core::OutputFile file(dir / "statics" / "contact_points.csv");
  std::ostream& f = file.stream();
  f << "line_1,line_2,kind,arc_1_m,arc_2_m,x_m,y_m,z_m,normal_x,normal_y,normal_z,force_N,force_per_length_N_per_m,"
       "length_m,gap_m\n";
  for (const ContactPoint& c : contact.contacts()) {
    if (c.normalForce <= 0.0) continue;
    add(c.lineA, c.lineB, c.arcA, c.arcB, c.pointA, c.normalForce * c.normal + c.frictionForce, c.normalForce,
        0.0, 0.0);
    f << fmt::format("{},{},point,{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.5f},{:.5f},{:.5f},{:.6e},,,{:.4e}\n",
                     lines[c.lineA].name, lines[c.lineB].name, c.arcA, c.arcB, c.pointA.x(), c.pointA.y(), c.pointA.z(),
                     c.normal.x(), c.normal.y(), c.normal.z(), c.normalForce, c.gap);
  }
  for (const LineSample& s : contact.lineSamples()) {
    if (s.lineForce <= 0.0) continue;
    const model::LineElement& ea = elements[s.elementA];
    const Vec3 x = (1.0 - s.xi) * state.position[ea.node1] + s.xi * state.position[ea.node2];
    add(s.lineA, s.lineB, s.arcA, s.arcB, x, s.lineForce * s.length * s.normal, s.lineForce * s.length,
        s.length, s.lineForce);
    f << fmt::format("{},{},length,{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.5f},{:.5f},{:.5f},{:.6e},{:.6e},{:.5f},{:.4e}\n",
                     lines[s.lineA].name, lines[s.lineB].name, s.arcA, s.arcB, x.x(), x.y(), x.z(), s.normal.x(),
                     s.normal.y(), s.normal.z(), s.lineForce * s.length, s.lineForce, s.length, s.gap);
  }
  if (const DistributedContact* distributed = contact.distributed()) {
    // Gauss points of both passes, each with half the weight: a pair's sums are over both (the contact
    // length is the mean of the lengths along the two lines), reported with the lower line index first.
    for (const ContactSample& s : distributed->samples()) {
      if (s.lineForce <= 0.0) continue;
      const bool swapped = s.lineA > s.lineB;
      const int first = swapped ? s.lineB : s.lineA, second = swapped ? s.lineA : s.lineB;
      const double arc1 = swapped ? s.arcB : s.arcA, arc2 = swapped ? s.arcA : s.arcB;
      const Vec3 normal = swapped ? Vec3(-s.normal) : s.normal;
      const Vec3 x = s.curve.pointA;
      add(s.lineA, s.lineB, s.arcA, s.arcB, x, s.length * (s.lineForce * s.normal + s.friction),
          s.lineForce * s.length, s.length, s.lineForce);
      f << fmt::format("{},{},length,{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.5f},{:.5f},{:.5f},{:.6e},{:.6e},{:.5f},{:.4e}\n",
                       lines[first].name, lines[second].name, arc1, arc2, x.x(), x.y(), x.z(), normal.x(),
                       normal.y(), normal.z(), s.lineForce * s.length, s.lineForce, s.length, s.gap);
    }
  }
  file.close();
  // Zones joined across gaps of up to two of line 1's longest elements (the samples of neighbouring
  // elements, and Gauss points of an element whose middle is clear, belong to one place).
  std::vector<double> joinDistance;
  for (const model::Line& line : lines) {
    double longest = 0.0;
    for (int e = line.firstElement; e < line.firstElement + line.elementCount; ++e)
      longest = std::max(longest, elements[static_cast<std::size_t>(e)].restLength);
    joinDistance.push_back(2.0 * longest);
  }
  std::vector<StaticContactZone> zones = groupContactZones(std::move(samples), joinDistance);
  // Friction of the line-to-line patches (not in the samples' forces): to the zone of its pair nearest
  // the patch's element on line A.
  // Arc length at the middle of nodes n1-n2 of `line` [m]; nullopt when they are not both on it.
  const auto middleArc = [&](int lineIndex, int n1, int n2) -> std::optional<double> {
    const model::Line& line = lines[static_cast<std::size_t>(lineIndex)];
    const auto on = [&](int n) { return n >= line.firstNode && n <= line.lastNode(); };
    if (!on(n1) || !on(n2)) return std::nullopt;
    return 0.5 * (line.arcLength[static_cast<std::size_t>(n1 - line.firstNode)] +
                  line.arcLength[static_cast<std::size_t>(n2 - line.firstNode)]);
  };
  for (const FrictionPatch& p : contact.frictionPatches()) {
    const model::LineElement& el = elements[static_cast<std::size_t>(p.elementA)];
    const double arc = middleArc(p.lineA, el.node1, el.node2).value_or(0.0);
    // And of its element on line B (a wrap: two places at the same arcs of one line).
    const std::optional<double> arcOnB = middleArc(p.lineB, p.nodeB[0], p.nodeB[1]);
    // (A self-contact's zones have the lower arc first: groupContactZones.)
    const bool swapped = p.lineA > p.lineB || (p.lineA == p.lineB && arcOnB && arc > *arcOnB);
    StaticContactZone* nearest = nullptr;
    double distance = 0.0;
    for (StaticContactZone& z : zones) {
      if (z.line1 != std::min(p.lineA, p.lineB) || z.line2 != std::max(p.lineA, p.lineB)) continue;
      const double from = swapped ? z.arc2From : z.arc1From, to = swapped ? z.arc2To : z.arc1To;
      double d = std::max({from - arc, arc - to, 0.0});
      if (arcOnB) {
        const double fromB = swapped ? z.arc1From : z.arc2From, toB = swapped ? z.arc1To : z.arc2To;
        d = std::max({d, fromB - *arcOnB, *arcOnB - toB});
      }
      if (!nearest || d < distance) {
        nearest = &z;
        distance = d;
      }
    }
    if (nearest) nearest->force += swapped ? Vec3(-p.force) : p.force;
  }

  core::OutputFile zoneFile(dir / "statics" / "contact_zones.csv");
  std::ostream& zf = zoneFile.stream();
  zf << "line_1,line_2,zone,normal_force_N,force_on_1_x_N,force_on_1_y_N,force_on_1_z_N,contact_length_m,"
        "peak_force_per_length_N_per_m,arc_1_from_m,arc_1_to_m,arc_2_from_m,arc_2_to_m,x_m,y_m,z_m,points,"
        "length_samples\n";
  core::OutputFile pairFile(dir / "statics" / "contact_pairs.csv");
  std::ostream& g = pairFile.stream();
  g << "line_1,line_2,normal_force_N,force_on_1_x_N,force_on_1_y_N,force_on_1_z_N,contact_length_m,"
       "peak_force_per_length_N_per_m,arc_1_from_m,arc_1_to_m,arc_2_from_m,arc_2_to_m,points,length_samples,"
       "zones\n";
  std::string text;
  const auto describe = [](const StaticContactZone& z) {
    std::string s = fmt::format("{:.2f} kN", z.normal / 1000.0);
    if (z.length > 0.0)
      s += fmt::format(" over {:.2f} m (up to {:.3g} kN/m)", z.length, z.peakPerLength / 1000.0);
    return s;
  };
  for (std::size_t first = 0; first < zones.size();) {
    std::size_t last = first;
    while (last + 1 < zones.size() && zones[last + 1].line1 == zones[first].line1 &&
           zones[last + 1].line2 == zones[first].line2)
      ++last;
    const std::string& name1 = lines[static_cast<std::size_t>(zones[first].line1)].name;
    const std::string& name2 = lines[static_cast<std::size_t>(zones[first].line2)].name;
    // The pair: sums and extremes over its zones.
    StaticContactZone pair = zones[first];
    for (std::size_t k = first + 1; k <= last; ++k) addZone(pair, zones[k]);
    g << fmt::format("{},{},{:.6e},{:.6e},{:.6e},{:.6e},{:.4f},{:.6e},{:.4f},{:.4f},{:.4f},{:.4f},{},{},{}\n",
                     name1, name2, pair.normal, pair.force.x(), pair.force.y(), pair.force.z(), pair.length,
                     pair.peakPerLength, pair.arc1From, pair.arc1To, pair.arc2From, pair.arc2To, pair.points,
                     pair.samples, last - first + 1);
    const auto where = [&](const StaticContactZone& z) {
      return fmt::format("at z = {:.1f} m, arc {:.2f}-{:.2f} m on '{}', {:.2f}-{:.2f} m on '{}'",
                         z.centre.z(), z.arc1From, z.arc1To, name1, z.arc2From, z.arc2To, name2);
    };
    if (last == first) {
      text += fmt::format("  contact '{}' / '{}': {}, {}\n", name1, name2, describe(pair), where(pair));
    } else {
      text += fmt::format("  contact '{}' / '{}': {} in {} places:\n", name1, name2, describe(pair),
                          last - first + 1);
      for (std::size_t k = first; k <= last; ++k)
        text += fmt::format("    {}, {}\n", describe(zones[k]), where(zones[k]));
    }
    for (std::size_t k = first; k <= last; ++k) {
      const StaticContactZone& z = zones[k];
      zf << fmt::format(
          "{},{},{},{:.6e},{:.6e},{:.6e},{:.6e},{:.4f},{:.6e},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},"
          "{:.4f},{},{}\n",
          name1, name2, k - first + 1, z.normal, z.force.x(), z.force.y(), z.force.z(), z.length,
          z.peakPerLength, z.arc1From, z.arc1To, z.arc2From, z.arc2To, z.centre.x(), z.centre.y(),
          z.centre.z(), z.points, z.samples);
    }
    first = last + 1;
  }
  zoneFile.close();
  pairFile.close();
  return text;
}

}  // namespace tangle::contact
