#include "tangle/contact/StaticContactReport.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <map>
#include <utility>

#include "tangle/core/OutputFile.hpp"

namespace tangle::contact {

std::string writeStaticContact(const std::filesystem::path& dir, const model::Model& model, const LineContact& contact,
                               const model::State& state) {
  const auto& lines = model.lines();
  const auto& elements = model.elements();
  std::filesystem::create_directories(dir / "statics");
  struct PairTotal {
    Vec3 force = Vec3::Zero();  // total contact force on line 1 (normal and friction) [N]
    double normal = 0.0, length = 0.0, peakPerLength = 0.0;
    double a0 = 1e300, a1 = -1e300, b0 = 1e300, b1 = -1e300;
    int points = 0, samples = 0;
  };
  std::map<std::pair<int, int>, PairTotal> pairs;
  auto extend = [](PairTotal& t, double arcA, double arcB) {
    t.a0 = std::min(t.a0, arcA);
    t.a1 = std::max(t.a1, arcA);
    t.b0 = std::min(t.b0, arcB);
    t.b1 = std::max(t.b1, arcB);
  };
  core::OutputFile file(dir / "statics" / "contact_points.csv");
  std::ostream& f = file.stream();
  f << "line_1,line_2,kind,arc_1_m,arc_2_m,x_m,y_m,z_m,normal_x,normal_y,normal_z,force_N,force_per_length_N_per_m,"
       "length_m,gap_m\n";
  for (const ContactPoint& c : contact.contacts()) {
    if (c.normalForce <= 0.0) continue;
    PairTotal& t = pairs[{c.lineA, c.lineB}];
    t.force += c.normalForce * c.normal + c.frictionForce;
    t.normal += c.normalForce;
    ++t.points;
    extend(t, c.arcA, c.arcB);
    f << fmt::format("{},{},point,{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.5f},{:.5f},{:.5f},{:.6e},,,{:.4e}\n",
                     lines[c.lineA].name, lines[c.lineB].name, c.arcA, c.arcB, c.pointA.x(), c.pointA.y(), c.pointA.z(),
                     c.normal.x(), c.normal.y(), c.normal.z(), c.normalForce, c.gap);
  }
  for (const LineSample& s : contact.lineSamples()) {
    if (s.lineForce <= 0.0) continue;
    PairTotal& t = pairs[{s.lineA, s.lineB}];
    t.force += s.lineForce * s.length * s.normal;
    t.normal += s.lineForce * s.length;
    t.length += s.length;
    t.peakPerLength = std::max(t.peakPerLength, s.lineForce);
    ++t.samples;
    extend(t, s.arcA, s.arcB);
    const model::LineElement& ea = elements[s.elementA];
    const Vec3 x = (1.0 - s.xi) * state.position[ea.node1] + s.xi * state.position[ea.node2];
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
      const Vec3 onFirst = (swapped ? -1.0 : 1.0) * s.length * (s.lineForce * s.normal + s.friction);
      const Vec3 normal = swapped ? Vec3(-s.normal) : s.normal;
      PairTotal& t = pairs[{first, second}];
      t.force += onFirst;
      t.normal += s.lineForce * s.length;
      t.length += s.length;
      t.peakPerLength = std::max(t.peakPerLength, s.lineForce);
      ++t.samples;
      extend(t, arc1, arc2);
      const Vec3 x = s.curve.pointA;
      f << fmt::format("{},{},length,{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.5f},{:.5f},{:.5f},{:.6e},{:.6e},{:.5f},{:.4e}\n",
                       lines[first].name, lines[second].name, arc1, arc2, x.x(), x.y(), x.z(), normal.x(),
                       normal.y(), normal.z(), s.lineForce * s.length, s.lineForce, s.length, s.gap);
    }
  }
  for (const FrictionPatch& p : contact.frictionPatches()) {
    auto it = pairs.find({p.lineA, p.lineB});
    if (it != pairs.end()) it->second.force += p.force;
  }
  file.close();

  core::OutputFile pairFile(dir / "statics" / "contact_pairs.csv");
  std::ostream& g = pairFile.stream();
  g << "line_1,line_2,normal_force_N,force_on_1_x_N,force_on_1_y_N,force_on_1_z_N,contact_length_m,"
       "peak_force_per_length_N_per_m,arc_1_from_m,arc_1_to_m,arc_2_from_m,arc_2_to_m,points,length_samples\n";
  std::string text;
  for (const auto& [key, t] : pairs) {
    g << fmt::format("{},{},{:.6e},{:.6e},{:.6e},{:.6e},{:.4f},{:.6e},{:.4f},{:.4f},{:.4f},{:.4f},{},{}\n",
                     lines[key.first].name, lines[key.second].name, t.normal, t.force.x(), t.force.y(), t.force.z(),
                     t.length, t.peakPerLength, t.a0, t.a1, t.b0, t.b1, t.points, t.samples);
    text += fmt::format("  contact '{}' / '{}': {:.2f} kN", lines[key.first].name, lines[key.second].name, t.normal / 1000.0);
    if (t.length > 0.0) text += fmt::format(" over {:.2f} m (up to {:.3g} kN/m)", t.length, t.peakPerLength / 1000.0);
    text += fmt::format(", arc {:.2f}-{:.2f} m on '{}', {:.2f}-{:.2f} m on '{}'\n", t.a0, t.a1, lines[key.first].name,
                        t.b0, t.b1, lines[key.second].name);
  }
  pairFile.close();
  return text;
}

}  // namespace tangle::contact
