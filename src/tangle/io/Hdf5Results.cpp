/// @file Hdf5Results.cpp
/// results.h5 and results.xdmf (see Hdf5Results.hpp).

#include "tangle/io/Hdf5Results.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <functional>

#include "tangle/core/OutputFile.hpp"
#include "tangle/io/ResultWriter.hpp"

namespace tangle::io {

namespace fs = std::filesystem;

namespace {

/// The fields of a ParaView frame (writeFrame, results.xdmf), in the order of Hdf5Results::m_frameSeries.
struct FrameField {
  const char* name;
  bool vector;  ///< [node, 3], else [node]
  const char* units;
  const char* description;
};
constexpr std::array<FrameField, 5> kFrameFieldSpecs{{
    {"position", true, "m", "node positions at each frame [frame, node, xyz]"},
    {"effective_tension", false, "N", "effective tension at each frame [frame, node]"},
    {"bending_moment", false, "N m", "bending moment magnitude at each frame [frame, node]"},
    {"curvature", false, "1/m", "curvature at each frame [frame, node]"},
    {"torque", false, "N m", "torque at each frame [frame, node]"},
}};
/// Frames per chunk of the frame series: at the default output.vtk_interval of 1 s, what a run that stops
/// abruptly (a crash) may lose of them.
constexpr int kFrameChunkRows = 8;

/// Series of one line, in this order in Hdf5Results::m_lineSeries.
enum LineSeries {
  kPosition,
  kTension,
  kMoment,
  kMomentVector,
  kCurvature,
  kTorque,
  kWallTension,
  kEndTension,
  kEndForce,
  kCount
};

std::vector<double> flatten(const std::vector<Vec3>& v) {
  std::vector<double> out;
  out.reserve(3 * v.size());
  for (const Vec3& x : v) out.insert(out.end(), {x.x(), x.y(), x.z()});
  return out;
}

std::string linePath(const std::string& root, const std::string& stem) { return root + "/lines/" + stem; }

}  // namespace

Hdf5Results::Hdf5Results(const fs::path& dir, const model::Model& model, const std::string& modelText)
    : m_dir(dir), m_model(&model) {
  fs::create_directories(dir);
  m_file = std::make_unique<Hdf5File>(dir / "results.h5");
  m_file->setAttribute("/", "tangle_version", TANGLE_VERSION);
  m_file->setAttribute("/", "title", model.spec().title);
  m_file->setAttribute("/", "model_file", model.spec().sourceFile);
  m_file->setAttribute("/", "model_text", modelText);
  m_file->setAttribute("/", "units",
                       "SI: m, kg, N, s; angles in degrees; every dataset has a 'units' attribute");
  m_file->setAttribute("/", "layout", "docs/results-hdf5.md");
  std::vector<std::string> names;
  for (const model::Line& l : model.lines()) {
    names.push_back(l.name);
    m_nodes.push_back(static_cast<std::size_t>(l.nodeCount));
  }
  m_stems = uniqueFileStems(names);
  for (std::size_t l = 0; l < m_stems.size(); ++l) {
    const std::string g = "/xdmf/" + m_stems[l];
    m_file->createGroup(g);
    m_file->setAttribute(g, "line", names[l]);
    std::vector<int> segments;
    for (std::size_t i = 0; i + 1 < m_nodes[l]; ++i)
      segments.insert(segments.end(), {static_cast<int>(i), static_cast<int>(i + 1)});
    m_file->writeIntArray(g + "/segments", segments, {m_nodes[l] - 1, 2},
                          "node indices of each element (polyline)");
  }
}

Hdf5Results::~Hdf5Results() {
  try {
    close();
  } catch (const std::exception&) {  // NOLINT(bugprone-empty-catch): a destructor must not throw
  }
}

void Hdf5Results::writeStatics(const std::vector<solver::LineSnapshot>& lines) {
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const solver::LineSnapshot& s = lines[l];
    const std::string g = linePath("/statics", m_stems[l]);
    const std::uint64_t n = s.arcLength.size();
    m_file->createGroup(g);
    m_file->setAttribute(g, "line", s.name);
    m_file->writeArray(g + "/arc_length", s.arcLength, {n}, "m", "unstretched arc length from end A");
    m_file->writeArray(g + "/position", flatten(s.position), {n, 3}, "m", "node position, global axes");
    m_file->writeArray(g + "/effective_tension", s.tension, {n}, "N", "effective tension");
    if (!s.wallTension.empty()) {  // pipe lines only
      m_file->writeArray(g + "/wall_tension", s.wallTension, {n}, "N", "wall tension T_e + p_i A_i - p_e A_e");
      m_file->writeArray(g + "/internal_pressure", s.internalPressure, {n}, "Pa", "internal pressure (gauge)");
    }
    m_file->writeArray(g + "/bending_moment", s.bendingMoment, {n}, "N m", "bending moment magnitude");
    m_file->writeArray(g + "/bending_moment_vector", flatten(s.bendingMomentVector), {n, 3}, "N m",
                       "bending moment, global axes");
    m_file->writeArray(g + "/curvature", s.curvature, {n}, "1/m", "curvature");
    m_file->writeArray(g + "/torque", s.torque, {n}, "N m", "torsional moment about the line axis");
    m_file->writeArray(g + "/rotation", flatten(s.rotation), {n, 3}, "deg",
                       "node triad as a rotation vector from the global axes (zero for cable nodes)");
    m_file->setAttribute(g, "end_a_tension_N", s.endTensionA);
    m_file->setAttribute(g, "end_b_tension_N", s.endTensionB);
    m_file->setAttribute(g, "touchdown_arc_length_m",
                         s.touchdownArcLength >= 0.0 ? s.touchdownArcLength : std::nan(""));
  }
  m_hasStatics = true;
  m_file->flush();
}

void Hdf5Results::writeAudit(const solver::EquilibriumAudit& audit) {
  const std::string root = "/statics/equilibrium_audit";
  m_file->createGroup(root);
  m_file->setAttribute(root, "worst_relative_residual", audit.worstRelativeResidual());
  const auto write = [&](const std::string& kind, const std::vector<solver::ForceBalance>& bodies) {
    m_file->createGroup(root + "/" + kind);
    std::vector<std::string> names;
    for (const solver::ForceBalance& b : bodies) names.push_back(b.name);
    const std::vector<std::string> stems = uniqueFileStems(names);
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const solver::ForceBalance& b = bodies[i];
      const std::string g = root + "/" + kind + "/" + stems[i];
      m_file->createGroup(g);
      m_file->setAttribute(g, "name", b.name);
      std::vector<double> rows;
      std::string sources;
      for (const auto& [name, force] : b.terms) {
        rows.insert(rows.end(), {force.x(), force.y(), force.z()});
        sources += (sources.empty() ? "" : ";") + name;
      }
      m_file->writeArray(g + "/terms", rows, {b.terms.size(), 3}, "N", "force on the body from each source");
      m_file->setAttribute(g, "sources", sources);
      m_file->writeArray(g + "/residual", {b.residual.x(), b.residual.y(), b.residual.z()}, {3}, "N",
                         "sum of the terms");
      m_file->setAttribute(g, "reference_force_N", b.scale);
      m_file->setAttribute(g, "relative_residual", b.relativeResidual());
      m_file->setAttribute(g, "tolerance", b.tolerance);
    }
  };
  write("lines", audit.lines);
  write("vessels", audit.vessels);
  if (!audit.points.empty()) write("points", audit.points);
  m_file->flush();
}

void Hdf5Results::beginDynamics(const std::vector<solver::LineSnapshot>& initial) {
  m_file->createGroup("/dynamics");
  m_time = m_file->createSeries("/dynamics/time", {}, "s", "output times", 64, false);
  for (std::size_t l = 0; l < initial.size(); ++l) {
    const std::string g = linePath("/dynamics", m_stems[l]);
    const std::uint64_t n = m_nodes[l];
    m_file->createGroup(g);
    m_file->setAttribute(g, "line", initial[l].name);
    m_file->writeArray(g + "/arc_length", initial[l].arcLength, {n}, "m",
                       "unstretched arc length from end A");
    // Only the time histories the model asks for (output.time_histories); -1: not written.
    const model::TimeHistorySelection& t = m_model->spec().output.timeHistories;
    std::vector<int> series(kCount, -1);
    if (t.position)
      series[kPosition] = m_file->createSeries(g + "/position", {n, 3}, "m", "node positions [time, node, xyz]");
    if (t.effectiveTension)
      series[kTension] = m_file->createSeries(g + "/effective_tension", {n}, "N", "effective tension [time, node]");
    if (t.bendingMoment)
      series[kMoment] =
          m_file->createSeries(g + "/bending_moment", {n}, "N m", "bending moment magnitude [time, node]");
    if (t.bendingMomentVector)
      series[kMomentVector] = m_file->createSeries(g + "/bending_moment_vector", {n, 3}, "N m",
                                                   "bending moment, global axes [time, node, xyz]");
    if (t.curvature) series[kCurvature] = m_file->createSeries(g + "/curvature", {n}, "1/m", "curvature [time, node]");
    if (t.torque) series[kTorque] = m_file->createSeries(g + "/torque", {n}, "N m", "torque [time, node]");
    if (t.wallTension && !initial[l].wallTension.empty())  // lines with a bore only
      series[kWallTension] = m_file->createSeries(g + "/wall_tension", {n}, "N",
                                                  "wall tension T_e + p_i A_i - p_e A_e [time, node]");
    series[kEndTension] = m_file->createSeries(g + "/end_tension", {2}, "N",
                                               "effective tension at end A and end B [time, end]");
    series[kEndForce] = m_file->createSeries(g + "/end_force", {2, 3}, "N",
                                             "force the line exerts on what holds each end [time, end, xyz]");
    m_lineSeries.push_back(std::move(series));
  }
  // The ParaView frames (writeFrame): one series per line and field, a row every output.vtk_interval.
  m_frameTime = m_file->createSeries("/xdmf/frame_time", {}, "s", "time of each ParaView frame [frame]",
                                     kFrameChunkRows, false);
  for (std::size_t l = 0; l < initial.size(); ++l) {
    const std::string g = "/xdmf/" + m_stems[l] + "/frames";
    const std::uint64_t n = m_nodes[l];
    m_file->createGroup(g);
    std::array<int, kFrameFields> series{};
    for (std::size_t f = 0; f < kFrameFields; ++f) {
      const FrameField& field = kFrameFieldSpecs[f];
      series[f] = m_file->createSeries(
          g + "/" + field.name,
          field.vector ? std::vector<std::uint64_t>{n, 3} : std::vector<std::uint64_t>{n}, field.units,
          field.description, kFrameChunkRows);
    }
    m_frameSeries.push_back(series);
  }
  for (const auto& v : m_model->vessels()) {
    const std::string g = "/dynamics/vessels/" + v.name;
    m_file->createGroup(g);
    m_vesselSeries.push_back(
        m_file->createSeries(g + "/motion", {6}, "m, m, m, deg, deg, deg",
                             "reference point x, y, z and rotation vector rx, ry, rz from the "
                             "initial attitude [time, 6]"));
  }
}

void Hdf5Results::record(double time, const std::vector<solver::LineSnapshot>& lines,
                         const std::vector<double>& vesselMotion) {
  m_file->append(m_time, &time);
  m_times.push_back(time);
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const solver::LineSnapshot& s = lines[l];
    const std::vector<int>& k = m_lineSeries[l];
    if (k[kPosition] >= 0) m_file->append(k[kPosition], flatten(s.position).data());
    if (k[kTension] >= 0) m_file->append(k[kTension], s.tension.data());
    if (k[kMoment] >= 0) m_file->append(k[kMoment], s.bendingMoment.data());
    if (k[kMomentVector] >= 0) m_file->append(k[kMomentVector], flatten(s.bendingMomentVector).data());
    if (k[kCurvature] >= 0) m_file->append(k[kCurvature], s.curvature.data());
    if (k[kTorque] >= 0) m_file->append(k[kTorque], s.torque.data());
    if (k[kWallTension] >= 0) m_file->append(k[kWallTension], s.wallTension.data());
    const double ends[2] = {s.endTensionA, s.endTensionB};
    m_file->append(k[kEndTension], ends);
    const Vec3 &a = s.endTensionForceA, &b = s.endTensionForceB;
    const double forces[6] = {a.x(), a.y(), a.z(), b.x(), b.y(), b.z()};
    m_file->append(k[kEndForce], forces);
  }
  for (std::size_t v = 0; v < m_vesselSeries.size(); ++v)
    m_file->append(m_vesselSeries[v], vesselMotion.data() + 6 * v);
  if (time >= m_nextFrame - 1e-9) {
    writeFrame(lines);
    m_nextFrame += m_model->spec().output.vtkInterval;
  }
}

void Hdf5Results::writeFrame(const std::vector<solver::LineSnapshot>& lines) {
  // A row of each line's frame series (single precision, as the time series), whatever time histories the
  // model asks for: the XDMF files point into them by hyperslabs. (Stored as five plain datasets per line
  // and frame, their creation in the file took 13 % of the CPU of a 12-line run: docs/performance.md.)
  const std::size_t k = m_times.size() - 1;
  m_frames.push_back(k);
  m_file->append(m_frameTime, &m_times[k]);
  for (std::size_t l = 0; l < lines.size() && l < m_frameSeries.size(); ++l) {
    const solver::LineSnapshot& s = lines[l];
    const std::array<int, kFrameFields>& series = m_frameSeries[l];
    m_file->append(series[0], flatten(s.position).data());
    m_file->append(series[1], s.tension.data());
    m_file->append(series[2], s.bendingMoment.data());
    m_file->append(series[3], s.curvature.data());
    m_file->append(series[4], s.torque.data());
  }
}

void Hdf5Results::writeRanges(const DynamicRecorder& recorder) {
  const auto& ranges = recorder.ranges();
  const double weight = recorder.meanWeight();
  for (std::size_t l = 0; l < ranges.size() && l < m_stems.size(); ++l) {
    const analysis::RangeGraphs::Range& r = ranges[l];
    const std::string g = linePath("/dynamics", m_stems[l]) + "/range";
    const std::uint64_t n = m_nodes[l];
    m_file->createGroup(g);
    m_file->setAttribute(g, "over", "every accepted time step; means time-weighted");
    const auto mean = [&](const std::vector<double>& sum, const std::vector<double>& only) {
      std::vector<double> v(sum.size());
      for (std::size_t i = 0; i < v.size(); ++i) v[i] = weight > 0.0 ? sum[i] / weight : only[i];
      return v;
    };
    m_file->writeArray(g + "/effective_tension_min", r.tensionMin, {n}, "N", "minimum effective tension");
    m_file->writeArray(g + "/effective_tension_max", r.tensionMax, {n}, "N", "maximum effective tension");
    m_file->writeArray(g + "/effective_tension_mean", mean(r.tensionSum, r.tensionMin), {n}, "N",
                       "mean effective tension");
    if (!r.wallTensionSum.empty()) {  // pipe lines only
      m_file->writeArray(g + "/wall_tension_min", r.wallTensionMin, {n}, "N", "minimum wall tension");
      m_file->writeArray(g + "/wall_tension_max", r.wallTensionMax, {n}, "N", "maximum wall tension");
      m_file->writeArray(g + "/wall_tension_mean", mean(r.wallTensionSum, r.wallTensionMin), {n}, "N",
                         "mean wall tension");
    }
    m_file->writeArray(g + "/bending_moment_min", r.momentMin, {n}, "N m", "minimum bending moment");
    m_file->writeArray(g + "/bending_moment_max", r.momentMax, {n}, "N m", "maximum bending moment");
    m_file->writeArray(g + "/bending_moment_mean", mean(r.momentSum, r.momentMin), {n}, "N m",
                       "mean bending moment");
    m_file->writeArray(g + "/curvature_min", r.curvatureMin, {n}, "1/m", "minimum curvature");
    m_file->writeArray(g + "/curvature_max", r.curvatureMax, {n}, "1/m", "maximum curvature");
    m_file->writeArray(g + "/curvature_mean", mean(r.curvatureSum, r.curvatureMin), {n}, "1/m",
                       "mean curvature");
  }
}

void Hdf5Results::writeContactEvents(const std::vector<contact::ContactEvent>& events) {
  const std::string g = "/contact/events";
  m_file->createGroup(g);
  std::string names;
  for (const model::Line& l : m_model->lines()) names += (names.empty() ? "" : ",") + l.name;
  m_file->setAttribute(g, "line_names", names);
  m_file->setAttribute(g, "count", static_cast<double>(events.size()));
  const std::uint64_t n = events.size();
  const auto column = [&](const char* name, const char* units, const char* description, auto get) {
    std::vector<double> v;
    for (const contact::ContactEvent& e : events) v.push_back(get(e));
    m_file->writeArray(g + "/" + name, v, {n}, units, description);
  };
  column("line_1", "-", "index of line 1 in the line_names attribute",
         [](const auto& e) { return double(e.lineA); });
  column("line_2", "-", "index of line 2 in the line_names attribute",
         [](const auto& e) { return double(e.lineB); });
  column("start_time", "s", "start of the event", [](const auto& e) { return e.startTime; });
  column("end_time", "s", "end of the event", [](const auto& e) { return e.endTime; });
  column("arc_1", "m", "where it began along line 1", [](const auto& e) { return e.arcAStart; });
  column("arc_2", "m", "where it began along line 2", [](const auto& e) { return e.arcBStart; });
  std::vector<double> where;
  for (const contact::ContactEvent& e : events)
    where.insert(where.end(), {e.positionStart.x(), e.positionStart.y(), e.positionStart.z()});
  m_file->writeArray(g + "/position", where, {n, 3}, "m", "where it began (on line 1)");
  column("impact_velocity", "m/s", "relative normal approach speed at first contact",
         [](const auto& e) { return e.impactVelocity; });
  column("impact_energy", "J",
         "1/2 m v^2 with the energy mass (the lines' point impedance where it holds, else Eq. 5 over the "
         "impact phase)",
         [](const auto& e) { return e.impactEnergy; });
  column("mesh_energy", "J", "1/2 m v^2 with the mass the mesh engaged (Eq. 5 over the impact phase)",
         [](const auto& e) { return e.meshEnergy; });
  column("continuum_energy", "J", "1/2 m v^2 with the lines' continuum participating mass (NaN: none)",
         [](const auto& e) { return e.continuumEnergy; });
  column("energy_mass", "kg", "mass of the impact energy", [](const auto& e) { return e.energyMass; });
  column("absorbed_energy", "J", "work of the contact force against the approach over the impact phase",
         [](const auto& e) { return e.phaseWork; });
  column("energy_warning", "-", "1: the two energy estimates or the mass bounds disagree",
         [](const auto& e) { return e.energyWarning.empty() ? 0.0 : 1.0; });
  column("peak_force", "N", "largest total contact force", [](const auto& e) { return e.peakForce; });
  column("impact_peak_force", "N",
         "the impact's peak force on the impact energy's basis (the continuum estimate's where the energy is "
         "the continuum's, else the mesh's over the impact phase; 0: not an impact; NaN: an impulse model's "
         "velocity jump)",
         [](const auto& e) { return e.impactPeakForce; });
  column("mesh_impact_peak_force", "N", "the mesh's largest contact force over the impact phase",
         [](const auto& e) { return e.meshImpactPeakForce; });
  column("peak_force_per_length", "N/m", "largest contact force per unit length",
         [](const auto& e) { return e.peakForcePerLength; });
  column("impulse", "N s", "integral of the contact force", [](const auto& e) { return e.impulse; });
  column("max_penetration", "m", "deepest penetration", [](const auto& e) { return e.maxPenetration; });
  column("impact", "-", "1: an impact, 0: sustained contact only",
         [](const auto& e) { return e.impact ? 1.0 : 0.0; });
  column("sustained", "-", "1: sustained contact", [](const auto& e) { return e.sustained ? 1.0 : 0.0; });
}

void Hdf5Results::writeClearance(const contact::ClearanceEnvelope& envelope) {
  for (const contact::ClearanceEnvelope::Side& s : envelope.sides()) {
    const model::Line& line = m_model->lines()[static_cast<std::size_t>(s.line)];
    const std::string g = "/clearance/" + m_stems[static_cast<std::size_t>(s.line)] + "/" +
                          m_stems[static_cast<std::size_t>(s.other)];
    const std::uint64_t n = s.staticClearance.size();
    m_file->createGroup(g);
    m_file->writeArray(g + "/arc_length", line.arcLength, {n}, "m", "arc length along the line");
    m_file->writeArray(g + "/static_clearance", s.staticClearance, {n}, "m",
                       "surface clearance to the other line, statics");
    m_file->writeArray(g + "/min_clearance", s.dynamicClearance, {n}, "m",
                       "smallest clearance over every accepted step");
    m_file->writeArray(g + "/time_of_min", s.timeOfMinimum, {n}, "s", "time of the smallest clearance");
  }
}

void Hdf5Results::writeFatigue(const analysis::FatigueDamage& fatigue,
                               const std::vector<analysis::FatigueDamage::Line>& damage) {
  for (const analysis::FatigueDamage::Line& line : damage) {
    const std::string g = "/fatigue/" + m_stems[static_cast<std::size_t>(line.line)];
    m_file->createGroup(g);
    const std::uint64_t n = line.nodes.size();
    const auto column = [&](const char* name, const char* units, const char* description, auto get) {
      std::vector<double> v;
      for (const analysis::FatigueDamage::Node& node : line.nodes) v.push_back(get(node));
      m_file->writeArray(g + "/" + name, v, {n}, units, description);
    };
    const double factor = fatigue.annualFactor();
    column("arc_length", "m", "arc length from end A", [](const auto& x) { return x.arcLength; });
    column("damage_run", "-", "Miner damage over the counted duration", [](const auto& x) { return x.damage; });
    column("damage_per_year", "-", "Miner damage per year (occurrence x year / counted duration)",
           [&](const auto& x) { return x.damage * factor; });
    column("life_years", "year", "fatigue life 1 / (design factor x damage per year)",
           [&](const auto& x) { return fatigue.life(x.damage); });
    column("cycles", "-", "rainflow cycles at the worst point", [](const auto& x) { return x.cycles; });
    column("largest_range", "Pa or N", "largest stress range [Pa] (S-N) or tension range [N] (T-N)",
           [](const auto& x) { return x.largestRange; });
    column("worst_point", "deg", "angle of the worst point round the section from material axis 2",
           [](const auto& x) { return x.worstAngle; });
    m_file->setAttribute(g, "counted_duration_s", fatigue.countedDuration());
  }
}

void Hdf5Results::writeClashDamage(const std::vector<analysis::LineClashDamage>& damage, double energyThreshold) {
  for (const analysis::LineClashDamage& line : damage) {
    const std::string g = "/contact/clash_damage/" + m_stems[static_cast<std::size_t>(line.line)];
    m_file->createGroup(g);
    const std::uint64_t n = line.bins.size();
    const auto column = [&](const char* name, const char* units, const char* description, auto get) {
      std::vector<double> v;
      for (const analysis::ClashDamageBin& b : line.bins) v.push_back(get(b));
      m_file->writeArray(g + "/" + name, v, {n}, units, description);
    };
    column("from", "m", "start of the bin (arc length from end A)", [](const auto& b) { return b.from; });
    column("to", "m", "end of the bin", [](const auto& b) { return b.to; });
    column("impacts", "-", "impacts that began in the bin", [](const auto& b) { return double(b.impacts); });
    column("impacts_above", "-", "impacts with an energy above the threshold (attribute energy_threshold_J)",
           [](const auto& b) { return double(b.impactsAbove); });
    column("energy", "J", "accumulated impact energy", [](const auto& b) { return b.energy; });
    column("largest_energy", "J", "largest impact energy", [](const auto& b) { return b.largestEnergy; });
    column("largest_velocity", "m/s", "largest impact velocity", [](const auto& b) { return b.largestVelocity; });
    m_file->setAttribute(g, "energy_threshold_J", energyThreshold);
  }
}

void Hdf5Results::close() {
  if (!m_file) return;
  m_file->close();
  m_file.reset();
  writeXdmf();
}

void Hdf5Results::writeXdmf() const {
  // XDMF (xdmf.org): a temporal collection of spatial collections, one polyline grid per line. Two files,
  // as ParaView's two reader families read a part of a dataset in two syntaxes and each skips the other's
  // (measured with ParaView 5.11: the XDMF 3 readers showed no points for a HyperSlab item, the XDMF 2
  // reader could not open a path with a hyperslab after '|'): results.xdmf for "Xdmf3 Reader S/T" (the
  // HDF path followed by "|start:stride:count:dimensions" of the frame series), results.xdmf2 for "XDMF
  // Reader" (HyperSlab data items; the .xdmf2 extension selects that reader). The statics are whole
  // datasets in both.
  const bool dynamic = m_time >= 0 && !m_frames.empty();
  if (!dynamic && !m_hasStatics) return;
  const std::uint64_t frames = m_frames.size();
  for (const bool xdmf3 : {true, false}) {
    // Which reader, in the file itself: ParaView offers every XDMF reader for either file.
    std::string x = "<?xml version=\"1.0\" ?>\n";
    const char* xdmf3Readers = "\"Xdmf3 Reader S\" or \"Xdmf3 Reader T\"";
    const char* xdmf2Reader = "\"XDMF Reader\"";
    x += fmt::format("<!-- tangle: open with ParaView's {}; for its {} open {} (docs/results-hdf5.md) -->\n",
                     xdmf3 ? xdmf3Readers : xdmf2Reader, xdmf3 ? xdmf2Reader : xdmf3Readers,
                     xdmf3 ? "results.xdmf2" : "results.xdmf");
    x += "<Xdmf Version=\"3.0\">\n <Domain>\n";
    // The grids of every line: `item(l, field, dims, vector)` the data item of a field of line l, whose
    // values have dimensions `dims` ("n 3" for a vector per node, else "n").
    const auto grids =
        [&](const std::function<std::string(std::size_t, const char*, const std::string&, bool)>& item) {
          std::string out;
          for (std::size_t l = 0; l < m_stems.size(); ++l) {
            const std::uint64_t n = m_nodes[l];
            const auto fieldItem = [&](const FrameField& f) {
              return item(l, f.name, f.vector ? fmt::format("{} 3", n) : fmt::format("{}", n), f.vector);
            };
            out += fmt::format("    <Grid Name=\"{}\" GridType=\"Uniform\">\n", m_stems[l]);
            out += fmt::format(
                "     <Topology TopologyType=\"Polyline\" NodesPerElement=\"2\" NumberOfElements=\"{}\">"
                "<DataItem Dimensions=\"{} 2\" NumberType=\"Int\" Format=\"HDF\">results.h5:/xdmf/{}/segments"
                "</DataItem></Topology>\n",
                n - 1, n - 1, m_stems[l]);
            // The frame fields (kFrameFieldSpecs): the position as the geometry, the others as node
            // attributes.
            out += "     <Geometry GeometryType=\"XYZ\">" + fieldItem(kFrameFieldSpecs[0]) + "</Geometry>\n";
            for (std::size_t f = 1; f < kFrameFieldSpecs.size(); ++f)
              out += fmt::format(
                  "     <Attribute Name=\"{}\" AttributeType=\"Scalar\" Center=\"Node\">{}</Attribute>\n",
                  kFrameFieldSpecs[f].name, fieldItem(kFrameFieldSpecs[f]));
            out += "    </Grid>\n";
          }
          return out;
        };
    if (dynamic) {
      x += "  <Grid Name=\"lines\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
      for (std::uint64_t frame = 0; frame < frames; ++frame) {
        x += fmt::format(
            "   <Grid Name=\"t{}\" GridType=\"Collection\" CollectionType=\"Spatial\">\n    <Time "
            "Value=\"{:.9g}\"/>\n",
            m_frames[frame], m_times[m_frames[frame]]);
        x += grids([&](std::size_t l, const char* field, const std::string& dims, bool vector) {
          // Row `frame` of the series [frame, node(, xyz)]: start, stride, count, the series' dimensions.
          const std::string path = fmt::format("results.h5:/xdmf/{}/frames/{}", m_stems[l], field);
          const std::string all = fmt::format("{} {}", frames, dims);
          const std::string zeros = vector ? " 0 0" : " 0", ones = vector ? " 1 1" : " 1";
          if (xdmf3)
            return fmt::format(
                "<DataItem Dimensions=\"{}\" NumberType=\"Float\" Precision=\"4\" Format=\"HDF\">"
                "{}|{}{}:1{}:1 {}:{}</DataItem>",
                dims, path, frame, zeros, ones, dims, all);
          return fmt::format(
              "<DataItem ItemType=\"HyperSlab\" Dimensions=\"{}\" Type=\"HyperSlab\">"
              "<DataItem Dimensions=\"3 {}\" Format=\"XML\">{}{} 1{} 1 {}</DataItem>"
              "<DataItem Dimensions=\"{}\" NumberType=\"Float\" Precision=\"4\" Format=\"HDF\">{}</DataItem>"
              "</DataItem>",
              dims, vector ? 3 : 2, frame, zeros, ones, dims, all, path);
        });
        x += "   </Grid>\n";
      }
      x += "  </Grid>\n";
    } else {
      x += "  <Grid Name=\"statics\" GridType=\"Collection\" CollectionType=\"Spatial\">\n";
      x += grids([&](std::size_t l, const char* field, const std::string& dims, bool) {
        return fmt::format(
            "<DataItem Dimensions=\"{}\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
            "results.h5:{}/{}</DataItem>",
            dims, linePath("/statics", m_stems[l]), field);
      });
      x += "  </Grid>\n";
    }
    x += " </Domain>\n</Xdmf>\n";
    core::OutputFile out(m_dir / (xdmf3 ? "results.xdmf" : "results.xdmf2"));
    out.write(x);
    out.close();
  }
}

}  // namespace tangle::io
