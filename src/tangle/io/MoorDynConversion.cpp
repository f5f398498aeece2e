#include "tangle/io/MoorDynConversion.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>

#include "tangle/core/Error.hpp"
#include "tangle/hydro/CurrentGrid.hpp"

namespace tangle::io {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

/// A number as YAML text: shortest form that reads back to the same double.
std::string num(double v) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), v);
  return ec == std::errc() ? std::string(buffer, end) : fmt::format("{:.17g}", v);
}

/// A name as a YAML double-quoted string: a MoorDyn type name is any word ("#1", "a:b", "*poly"), which plain
/// YAML would read as a comment, a map or an alias.
std::string yamlQuoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string vec(const Vec3& v) { return fmt::format("[{}, {}, {}]", num(v.x()), num(v.y()), num(v.z())); }

/// The options of a deck, resolved (MoorDyn2.cpp defaults; readOptionsLine names, case-insensitive).
struct Options {
  double timeStep = 0.001;  ///< dtM [s]
  double gravity = 9.80665;
  double density = 1025.0;
  double depth = 0.0;                 ///< WtrDpth [m], 0 when not given
  double seabedStiffness = 3.0e6;     ///< kBot [Pa/m]
  double seabedDamping = 3.0e5;       ///< cBot [Pa s/m]
  double friction = 0.0;              ///< FrictionCoefficient [-]
  double frictionDamping = 200.0;     ///< FricDamp [N s/m]
  double staticDynamicScale = 1.0;    ///< StatDynFricScale [-]
  int currentMode = 0;  ///< Currents: 0 none, 1 or 3 a steady profile from current_profile.txt, 2 a history,
                        ///< 5 a grid in space and time (current_profile_4d.txt)
  int waveMode = 0;        ///< WaveKin 2, 3 or 7: components from wave_frequencies/wave_elevation.txt
  double waveStep = 0.25;  ///< dtWave [s]: the resampling of wave_elevation.txt (WaveKin 3)
  std::string seafloorFile;           ///< SeafloorFile, resolved to a readable path; empty: flat
  /// tangleTolerance: tangle's own option (MoorDyn warns of an unknown option and goes on): the dynamics'
  /// Newton tolerance [-, of each line's weight]; unset: the converter's rule (convertMoorDynDeck).
  std::optional<double> tolerance;
  /// tangleTimeStep: tangle's own option: the dynamics' implicit step [s]; unset: max(dtM, 0.01 s).
  std::optional<double> tangleStep;
  std::map<std::string, int> lineOf;  ///< option (lower case) -> deck line, for comments
};

double optionNumber(const MoorDynDeck& deck, const MoorDynOption& o) {
  const std::optional<double> v = deckNumber(o.value);
  if (!v) throw InputError(deck.file, o.sourceLine, o.name, fmt::format("expected a number, got '{}'", o.value));
  return *v;
}

Options readOptions(const MoorDynDeck& deck, std::vector<std::string>& notes) {
  Options opt;
  // Options that change nothing in tangle, noted once per reason: (reason, "name (line N), ...").
  std::vector<std::pair<std::string, std::string>> unused;
  for (const MoorDynOption& o : deck.options) {
    const std::string name = lower(o.name);
    opt.lineOf[name] = o.sourceLine;
    const auto value = [&] { return optionNumber(deck, o); };
    const auto noted = [&](const std::string& why) {
      const std::string entry = fmt::format("{} (line {})", o.name, o.sourceLine);
      auto it = std::find_if(unused.begin(), unused.end(), [&](const auto& u) { return u.first == why; });
      if (it == unused.end())
        unused.push_back({why, entry});
      else
        it->second += ", " + entry;
    };
    if (name == "tangletolerance") {
      opt.tolerance = value();
      if (!(*opt.tolerance > 0.0 && *opt.tolerance <= 0.1))
        throw InputError(
            deck.file, o.sourceLine, o.name,
            fmt::format("expected tangle's Newton tolerance in (0, 0.1] (a fraction of each line's "
                        "weight, e.g. 1e-6), got {}",
                        o.value));
    } else if (name == "tangletimestep") {
      opt.tangleStep = value();
      if (!(*opt.tangleStep > 0.0 && *opt.tangleStep <= 1.0))
        throw InputError(deck.file, o.sourceLine, o.name,
                         fmt::format("expected tangle's implicit time step in (0, 1] s (e.g. 0.025: a host "
                                     "coupled at 0.025 s then takes one step per call), got {}",
                                     o.value));
    } else if (name == "dtm" || name == "dt") {
      opt.timeStep = value();
      if (!(opt.timeStep > 0.0))
        throw InputError(deck.file, o.sourceLine, o.name, "expected a time step > 0");
    } else if (name == "g" || name == "gravity") {
      opt.gravity = value();
    } else if (name == "rho" || name == "wtrdnsty") {
      opt.density = value();
    } else if (name == "wtrdpth") {
      opt.depth = value();
    } else if (name == "kbot" || name == "kb") {
      opt.seabedStiffness = value();
      if (!(opt.seabedStiffness > 0.0))
        throw InputError(deck.file, o.sourceLine, o.name, "expected kBot > 0 (tangle always has a seabed)");
    } else if (name == "cbot" || name == "cb") {
      opt.seabedDamping = value();
    } else if (name == "frictioncoefficient") {
      opt.friction = value();
    } else if (name == "fricdamp") {
      opt.frictionDamping = value();
    } else if (name == "statdynfricscale") {
      opt.staticDynamicScale = value();
    } else if (name == "wavekin" && value() == 1.0) {
      // Kinematics given by the host through MoorDyn_ExternalWaveKinSet (capi/MoorDynSystem): none in a
      // standalone run (still water, as MoorDyn without a host).
      noted(
          "wave kinematics from the host program (WaveKin 1): through the C API (MoorDyn_ExternalWaveKinSet); a "
          "standalone run has still water unless the converted model's `environment` gives waves");
    } else if (name == "wavekin" && (value() == 2.0 || value() == 3.0 || value() == 7.0)) {
      // Waves from files in the deck's folder, as components (MoorDyn's grid or node evaluation aside).
      opt.waveMode = static_cast<int>(value());
    } else if (name == "dtwave") {
      opt.waveStep = value();
      if (!(opt.waveStep > 0.0)) throw InputError(deck.file, o.sourceLine, o.name, "expected dtWave > 0 s");
    } else if (name == "currents" && (value() == 1.0 || value() == 2.0 || value() == 3.0 || value() == 5.0)) {
      // A steady profile, interpolated on a grid (1) or at the nodes (3): the same profile in tangle; one
      // changing in time (2, current_profile_dynamic.txt): a current history; a grid in space and time (5,
      // current_profile_4d.txt): a current grid.
      opt.currentMode = static_cast<int>(value());
    } else if (name == "wavekin" || name == "currents") {
      if (value() != 0.0)
        throw InputError(
            deck.file, o.sourceLine, o.name,
            fmt::format("{} = {}: wave and current kinematics from files or the API are not supported "
                        "(set 0 and give waves and current in the converted model's `environment`)",
                        o.name, o.value));
    } else if (name == "seafloorfile") {
      // MoorDyn opens the path as given (relative to the working directory: its tests run from tests/ with
      // "Mooring/3D_seafloor/..."); tangle tries that, then the deck's folder and the folders above it.
      namespace fs = std::filesystem;
      const fs::path given(o.value);
      std::vector<fs::path> tried{given};
      std::error_code absoluteError;
      const fs::path deckPath = fs::absolute(fs::path(deck.file), absoluteError);
      if (given.is_relative())
        for (fs::path dir = (absoluteError ? fs::path(deck.file) : deckPath).parent_path(); tried.size() < 5;
             dir = dir.parent_path()) {
          tried.push_back(dir / given);
          if (dir.empty() || dir == dir.parent_path()) break;
        }
      std::error_code ec;
      for (const fs::path& p : tried)
        if (fs::is_regular_file(p, ec)) {
          opt.seafloorFile = fs::absolute(p, ec).lexically_normal().string();
          break;
        }
      if (opt.seafloorFile.empty()) {
        std::string where;
        for (const fs::path& p : tried) where += (where.empty() ? "" : ", ") + p.string();
        throw InputError(deck.file, o.sourceLine, o.name,
                         fmt::format("the seafloor file '{}' was not found (looked for {})", o.value, where));
      }
    } else if (name == "tscheme" || name == "cfl") {
      noted(
          "MoorDyn's explicit scheme and its step; tangle integrates with implicit generalized-alpha at "
          "dynamics.time_step (docs/moordyn.md)");
    } else if (name == "dtic" || name == "icdt" || name == "tmaxic" || name == "ictmax" ||
               name == "cdscaleic" || name == "icdfac" || name == "threshic" || name == "icthresh" ||
               name == "gendynamicic" || name == "icgendynamic" || name == "fileic" || name == "icfile") {
      noted(
          "initial-condition generation; tangle starts from its static equilibrium (Newton), not from a "
          "relaxation");
    } else if (name == "writelog" || name == "writeunits" || name == "dtout" || name == "disableoutput" ||
               name == "disableouttime" || name == "outswitch") {
      noted("MoorDyn's output files; tangle writes its own (docs/moordyn.md, output channels)");
    } else if (name == "unifycurrentgrid") {
      noted("MoorDyn's kinematics grid; tangle evaluates the waves and current at each element");
    } else {
      throw InputError(
          deck.file, o.sourceLine, o.name,
          "unknown or unsupported MoorDyn option (docs/moordyn.md lists the options tangle reads)");
    }
  }
  for (const auto& [why, names] : unused) notes.push_back(fmt::format("{}: {}: {}", deck.file, names, why));
  return opt;
}

/// One wave component in tangle's convention (ComponentSea): period [s], amplitude [m], phase [deg], azimuth
/// [deg], and where it came from.
struct DeckWaveComponent {
  double period, amplitude, phase, azimuth;
  int sourceLine;
};

/// The numbers of each non-empty line of a wave file (columns separated by blanks, commas or tabs).
std::vector<std::pair<int, std::vector<double>>> readNumberRows(const std::string& path,
                                                                const MoorDynDeck& deck, int optionLine,
                                                                const char* what) {
  std::ifstream in(path);
  if (!in)
    throw InputError(deck.file, optionLine, "WaveKin",
                     fmt::format("{} is read from {}, which cannot be opened", what, path));
  std::vector<std::pair<int, std::vector<double>>> rows;
  std::string text;
  for (int lineNo = 1; std::getline(in, text); ++lineNo) {
    for (char& c : text)
      if (c == ',' || c == '\t' || c == '\r') c = ' ';
    std::istringstream words(text);
    std::vector<double> row;
    for (std::string w; words >> w;) {
      const std::optional<double> v = deckNumber(w);
      if (!v || !std::isfinite(*v))
        throw InputError(path, lineNo, "", fmt::format("expected a number, got '{}'", w));
      row.push_back(*v);
    }
    if (!row.empty()) rows.emplace_back(lineNo, std::move(row));
  }
  return rows;
}

/// MoorDyn's wave_frequencies.txt (WaveKin 2 and 7; docs/waterkinematics.rst): rows omega [rad/s], the real
/// and imaginary parts of the complex amplitude c [m], and optionally the direction of travel beta [rad].
/// MoorDyn (Waves/SpectrumKin.cpp) sums |c| sin(omega t - k (x cos beta + y sin beta) + arg c): in tangle's
/// a cos(k s - omega t + phase), phase = 90 deg - arg c. The zero frequency (a mean level) is left out.
std::vector<DeckWaveComponent> readWaveFrequencies(const MoorDynDeck& deck, int optionLine,
                                                   std::vector<std::string>& notes) {
  const std::string path = (std::filesystem::path(deck.file).parent_path() / "wave_frequencies.txt").string();
  std::vector<DeckWaveComponent> out;
  for (const auto& [lineNo, r] : readNumberRows(path, deck, optionLine, "the wave spectrum")) {
    if (r.size() < 3 || r.size() > 4)
      throw InputError(path, lineNo, "",
                       "expected 3 or 4 numbers: omega [rad/s], Re(c), Im(c) [m], [beta rad]");
    if (r[0] < 0.0) throw InputError(path, lineNo, "omega", "expected a frequency >= 0 rad/s");
    const double amplitude = std::hypot(r[1], r[2]);
    if (r[0] == 0.0) {
      if (amplitude != 0.0)
        notes.push_back(fmt::format("{}:{}: the zero-frequency component (a mean level of {} m) is left out",
                                    path, lineNo, num(r[2])));
      continue;
    }
    if (amplitude == 0.0) continue;
    const double phase = 90.0 - std::atan2(r[2], r[1]) * 180.0 / std::numbers::pi;
    out.push_back({2.0 * std::numbers::pi / r[0], amplitude, phase,
                   r.size() == 4 ? r[3] * 180.0 / std::numbers::pi : 0.0, lineNo});
  }
  if (out.empty())
    throw InputError(path, 0, "", "no wave component with a frequency > 0 and an amplitude > 0");
  return out;
}

/// MoorDyn's wave_elevation.txt (WaveKin 3): rows t [s], eta [m] at the origin, resampled every dtWave [s]
/// (linearly; an odd count drops its last sample, as MoorDyn) and expanded in its discrete Fourier series:
/// eta(t) = sum_k a_k cos(omega_k t + psi_k), omega_k = 2 pi k / (N dtWave), a_k = 2 |X_k| / N (|X_k| / N at
/// the Nyquist frequency), psi_k = arg X_k. Waves travelling towards +x, phase = -psi_k in tangle's form.
std::vector<DeckWaveComponent> readWaveElevation(const MoorDynDeck& deck, int optionLine, double step,
                                                 std::vector<std::string>& notes) {
  const std::string path = (std::filesystem::path(deck.file).parent_path() / "wave_elevation.txt").string();
  std::vector<double> t, eta;
  for (const auto& [lineNo, r] : readNumberRows(path, deck, optionLine, "the wave elevation record")) {
    if (r.size() != 2) throw InputError(path, lineNo, "", "expected 2 numbers: t [s], eta [m]");
    if (!t.empty() && r[0] <= t.back()) throw InputError(path, lineNo, "t", "times must increase");
    t.push_back(r[0]);
    eta.push_back(r[1]);
  }
  if (t.size() < 3) throw InputError(path, 0, "", "a wave elevation record needs at least 3 samples");
  // Range first: a double beyond size_t's range does not convert (the fuzzers' lesson).
  const double samplesInRecord = std::floor((t.back() - t.front()) / step + 1e-9) + 1.0;
  if (!(samplesInRecord <= 20001.0))
    throw InputError(deck.file, optionLine, "dtWave",
                     fmt::format("{} samples of the wave record at dtWave = {} s; at most 20001 (a longer dtWave)",
                                 num(samplesInRecord), num(step)));
  auto count = static_cast<std::size_t>(samplesInRecord);
  if (count % 2 == 1) --count;
  if (count < 2) throw InputError(deck.file, optionLine, "dtWave", "dtWave is longer than the wave record");
  std::vector<double> samples(count);
  for (std::size_t n = 0, j = 0; n < count; ++n) {
    const double tn = t.front() + static_cast<double>(n) * step;
    while (j + 2 < t.size() && t[j + 1] < tn) ++j;
    const double w = std::clamp((tn - t[j]) / (t[j + 1] - t[j]), 0.0, 1.0);
    samples[n] = eta[j] + w * (eta[j + 1] - eta[j]);
  }
  std::vector<DeckWaveComponent> out;
  const double duration = static_cast<double>(count) * step;
  double mean = 0.0;
  for (const double v : samples) mean += v / static_cast<double>(count);
  for (std::size_t k = 1; k <= count / 2; ++k) {
    double re = 0.0, im = 0.0;
    for (std::size_t n = 0; n < count; ++n) {
      const double angle =
          2.0 * std::numbers::pi * static_cast<double>(k * n % count) / static_cast<double>(count);
      re += samples[n] * std::cos(angle);
      im -= samples[n] * std::sin(angle);
    }
    const double scale = (k == count / 2 ? 1.0 : 2.0) / static_cast<double>(count);
    const double amplitude = scale * std::hypot(re, im);
    if (amplitude <= 1e-12 * (1.0 + std::abs(mean))) continue;
    // X_k = sum eta_n e^{-i omega_k t_n}: eta carries Re(X_k e^{i omega_k t}) = |X_k| cos(omega_k t + arg
    // X_k).
    const double psi =
        std::atan2(im, re) - 2.0 * std::numbers::pi * static_cast<double>(k) * t.front() / duration;
    out.push_back({duration / static_cast<double>(k), amplitude, -psi * 180.0 / std::numbers::pi, 0.0, 0});
  }
  if (std::abs(mean) > 1e-9)
    notes.push_back(fmt::format(
        "{}: the record's mean level {} m is left out (tangle's waves are about z = 0)", path, num(mean)));
  if (out.empty()) throw InputError(path, 0, "", "the wave elevation record is flat: no wave component");
  notes.push_back(
      fmt::format("{}: {} samples at dtWave = {} s become {} wave components, a series that repeats every "
                  "{} s; they travel towards +x",
                  path, count, num(step), out.size(), num(duration)));
  return out;
}

/// One level of a MoorDyn steady current profile (current_profile.txt).
struct ProfileLevel {
  double z = 0.0;
  Vec3 velocity = Vec3::Zero();  ///< ux, uy, uz [m/s]
  int sourceLine = 0;
};

/// MoorDyn's steady current profile (Waves/WaveGrid.cpp, constructSteadyCurrentGrid): current_profile.txt
/// beside the deck, three header lines, then rows `z ux [uy [uz]]`. tangle's current is horizontal, below
/// the still water level, one value per level. @throws InputError naming the file and its line
std::vector<ProfileLevel> readCurrentProfile(const MoorDynDeck& deck, int optionLine,
                                             std::vector<std::string>& notes) {
  const std::string path = (std::filesystem::path(deck.file).parent_path() / "current_profile.txt").string();
  std::ifstream in(path);
  if (!in)
    throw InputError(deck.file, optionLine, "Currents",
                     fmt::format("a steady current profile is read from {}, which cannot be opened", path));
  std::vector<ProfileLevel> levels;
  int above = 0;
  std::string text;
  for (int lineNo = 1; std::getline(in, text); ++lineNo) {
    if (lineNo <= 3) continue;  // title, description, column names
    for (char& c : text)
      if (c == ',' || c == '\t' || c == '\r') c = ' ';
    std::istringstream words(text);
    std::vector<std::string> w;
    for (std::string s; words >> s;) w.push_back(s);
    if (w.empty()) continue;
    if (w.size() < 2) throw InputError(path, lineNo, "z ux", "expected at least two columns: z [m], ux [m/s]");
    ProfileLevel level;
    level.sourceLine = lineNo;
    const char* names[] = {"z", "ux", "uy", "uz"};
    double values[4] = {0.0, 0.0, 0.0, 0.0};
    for (std::size_t k = 0; k < std::min<std::size_t>(w.size(), 4); ++k) {
      const std::optional<double> v = deckNumber(w[k]);
      if (!v) throw InputError(path, lineNo, names[k], fmt::format("expected a number, got '{}'", w[k]));
      values[k] = *v;
    }
    level.z = values[0];
    level.velocity = Vec3(values[1], values[2], values[3]);
    if (level.z > 0.0) {  // in the air above still water: tangle's profile ends at z = 0
      ++above;
      continue;
    }
    if (level.velocity.z() != 0.0)
      throw InputError(path, lineNo, "uz", "a vertical current is not supported (tangle's current is horizontal)");
    for (const ProfileLevel& other : levels)
      if (other.z == level.z)
        throw InputError(path, lineNo, "z", fmt::format("level z = {} is given twice (line {})", num(level.z),
                                                          other.sourceLine));
    levels.push_back(level);
  }
  if (levels.empty()) throw InputError(path, 0, "", "the current profile has no level at or below z = 0");
  if (above > 0)
    notes.push_back(
        fmt::format("{}: {} level(s) above the still water level (z > 0) left out: tangle's current "
                    "profile ends at z = 0",
                    path, above));
  return levels;
}

/// MoorDyn's current_profile_dynamic.txt (Currents 2; Waves/WaveGrid.cpp, constructDynamicCurrentGrid): line
/// 5 the levels z [m], from line 7 one row per time: t [s], ux at each level, then uy and uz at each level
/// (each block optional: zero when missing). Returns the profiles at each time, levels above z = 0 left out.
std::vector<std::pair<double, std::vector<ProfileLevel>>> readDynamicCurrent(
    const MoorDynDeck& deck, int optionLine, std::vector<std::string>& notes) {
  const std::string path =
      (std::filesystem::path(deck.file).parent_path() / "current_profile_dynamic.txt").string();
  std::ifstream in(path);
  if (!in)
    throw InputError(deck.file, optionLine, "Currents",
                     fmt::format("a current changing in time is read from {}, which cannot be opened", path));
  std::vector<std::string> lines;
  for (std::string text; std::getline(in, text);) lines.push_back(text);
  if (lines.size() < 7) throw InputError(path, 0, "", "expected at least 7 lines (MoorDyn's format)");
  const auto numbers = [&](std::size_t row, const char* what) {
    std::string text = lines[row];
    for (char& c : text)
      if (c == ',' || c == '\t' || c == '\r') c = ' ';
    std::istringstream words(text);
    std::vector<double> out;
    for (std::string w; words >> w;) {
      const std::optional<double> v = deckNumber(w);
      if (!v)
        throw InputError(path, static_cast<int>(row) + 1, what,
                         fmt::format("expected a number, got '{}'", w));
      out.push_back(*v);
    }
    return out;
  };
  const std::vector<double> z = numbers(4, "z");
  if (z.empty()) throw InputError(path, 5, "z", "expected the levels z [m] on line 5");
  std::vector<std::pair<double, std::vector<ProfileLevel>>> out;
  int above = 0;
  for (std::size_t row = 6; row < lines.size(); ++row) {
    const std::vector<double> v = numbers(row, "t ux");
    if (v.empty()) continue;
    if (v.size() <= z.size())
      throw InputError(
          path, static_cast<int>(row) + 1, "t ux",
          fmt::format("expected t and ux at each of the {} levels (then uy and uz), got {} numbers", z.size(),
                      v.size()));
    if (!out.empty() && !(v[0] > out.back().first))
      throw InputError(
          path, static_cast<int>(row) + 1, "t",
          fmt::format("times must increase: {} s follows {} s", num(v[0]), num(out.back().first)));
    std::vector<ProfileLevel> levels;
    above = 0;
    for (std::size_t k = 0; k < z.size(); ++k) {
      ProfileLevel level;
      level.z = z[k];
      level.sourceLine = static_cast<int>(row) + 1;
      const auto at = [&](std::size_t block) {
        const std::size_t i = 1 + block * z.size() + k;
        return i < v.size() && v.size() >= 1 + (block + 1) * z.size() ? v[i] : 0.0;
      };
      level.velocity = Vec3(at(0), at(1), at(2));
      if (level.z > 0.0) {
        ++above;
        continue;
      }
      if (level.velocity.z() != 0.0)
        throw InputError(path, static_cast<int>(row) + 1, "uz",
                         "a vertical current is not supported (tangle's current is horizontal)");
      levels.push_back(level);
    }
    if (levels.empty()) throw InputError(path, 5, "z", "no level at or below z = 0");
    out.push_back({v[0], std::move(levels)});
  }
  if (out.empty()) throw InputError(path, 7, "t ux", "no time row");
  if (above > 0)
    notes.push_back(
        fmt::format("{}: {} level(s) above the still water level (z > 0) left out: tangle's current "
                    "profile ends at z = 0",
                    path, above));
  notes.push_back(
      fmt::format("{}: the current after its last time ({} s) stays at its last profile in tangle", path,
                  num(out.back().first)));
  return out;
}

/// Largest seabed friction_velocity the model reader accepts [m/s].
constexpr double kMaxFrictionVelocity = 10.0;

/// A MoorDyn body as a tangle vessel (docs/moordyn.md, bodies): a free body is a free vessel `body<id>` whose
/// reference point is the centre of gravity of the body and the masses fixed to it; a fixed or coupled one
/// holds what is fixed to it where the deck puts it.
struct BodyFrame {
  bool free = false;
  bool pinned =
      false;  ///< a CoupledPinned body: a free vessel held at its reference point (VesselSpec::pinned)
  Mat3 rotation = Mat3::Identity();  ///< body axes to global at t = 0 (MoorDyn: Rx(r0) Ry(p0) Rz(y0))
  Vec3 origin = Vec3::Zero();        ///< the deck's reference point X0, Y0, Z0 [m]
  Vec3 reference = Vec3::Zero();     ///< the vessel's reference point: the centre of gravity [m]
  double mass = 0.0;                 ///< the body's and its points' [kg]
  Vec3 inertia = Vec3::Zero();       ///< about the reference point, global axes at t = 0 (diagonal) [kg m^2]
  double volume = 0.0;               ///< the body's and its points' [m^3]
  Vec3 centreOfBuoyancy = Vec3::Zero();      ///< from the reference point, vessel axes [m]
  Vec3 addedMass = Vec3::Zero();             ///< translational [kg]
  std::array<double, 6> quadraticDamping{};  ///< 1/2 rho CdA [kg/m, kg m^2]
  bool held = false;                         ///< a line holds it (directly or through its rods)
  /// A body-fixed offset (body axes, from the deck's reference point) in the vessel's axes from its reference
  /// point (tangle's vessel axes are the global axes at t = 0: heading 0).
  Vec3 vesselOffset(const Vec3& bodyOffset) const { return origin + rotation * bodyOffset - reference; }
  Vec3 global(const Vec3& bodyOffset) const { return origin + rotation * bodyOffset; }
};

/// A deck whose rods' and bodies' attachments are points: for each rod end that lines attach to, a point
/// (after the deck's own) and the lines' rod ends rewritten to it (docs/moordyn.md, rods and bodies). A fixed
/// or coupled rod's end is a fixed point; a pinned rod's end A too; a moving rod's other ends are tangle
/// points carried by the rod's line (its end node is the point); a zero-length rod is one point (free for a
/// free rod). A point or rod end on a free body is a Body point at its offset in the vessel's axes; on a
/// fixed or coupled body, a fixed point where the deck puts it.
struct RodEnds {
  MoorDynDeck deck;
  std::size_t deckPoints = 0;   ///< points of the deck as written (the rest are rod ends)
  std::vector<int> carrierRod;  ///< per point (id - 1): the rod whose line's end is the point, 0: none
  std::vector<int> carrierEnd;  ///< and which end of it (0 = A, 1 = B)
  std::vector<Vec3> clampAxis;  ///< per point: outward unit axis of a fixed rod's end (lines with EI clamp to
                                ///< it), zero: none
  std::vector<bool> movingRod;  ///< per rod (id - 1): a tangle line (pinned or free, of length > 0)
  std::vector<std::array<int, 2>> endPoint;  ///< per rod: the point id of each end, 0: no line there
  std::vector<std::array<Vec3, 2>> rodOffset;  ///< per rod on a free body: its ends in the vessel's axes
  std::vector<BodyFrame> bodies;               ///< per body (id - 1)
};

/// The rod's type (the deck reader checked that it exists).
const MoorDynRodType& rodTypeOf(const MoorDynDeck& deck, const MoorDynRod& rod) {
  return *std::find_if(deck.rodTypes.begin(), deck.rodTypes.end(),
                       [&](const MoorDynRodType& t) { return t.name == rod.rodType; });
}

/// Pi/4 d^2 [m^2].
double circleArea(double d) { return std::numbers::pi / 4.0 * d * d; }

/// MoorDyn's Euler2Quat: Rx(roll) Ry(pitch) Rz(yaw), angles in degrees.
Mat3 bodyRotation(const Vec3& degrees) {
  const Vec3 a = degrees * std::numbers::pi / 180.0;
  return (Eigen::AngleAxisd(a.x(), Vec3::UnitX()) * Eigen::AngleAxisd(a.y(), Vec3::UnitY()) *
          Eigen::AngleAxisd(a.z(), Vec3::UnitZ()))
      .toRotationMatrix();
}

/// Adds a mass m at d from the reference point to a diagonal inertia (parallel axes; the products of inertia
/// a free vessel has no place for are left out).
void addPointInertia(Vec3& inertia, double m, const Vec3& d) {
  inertia +=
      m * Vec3(d.y() * d.y() + d.z() * d.z(), d.x() * d.x() + d.z() * d.z(), d.x() * d.x() + d.y() * d.y());
}

std::vector<BodyFrame> bodyFrames(const MoorDynDeck& deck, double density, std::vector<std::string>& notes) {
  std::vector<BodyFrame> frames;
  for (const MoorDynBody& b : deck.bodies) {
    BodyFrame f;
    f.pinned = b.kind == MoorDynBodyKind::CoupledPinned;
    f.free = b.kind == MoorDynBodyKind::Free || f.pinned;
    f.rotation = bodyRotation(b.rotation);
    f.origin = b.position;
    if (b.kind == MoorDynBodyKind::Fixed || b.kind == MoorDynBodyKind::Coupled)
      notes.push_back(fmt::format(
          "{}:{}: body {} is {}: held where the deck puts it (a standalone run), and what is "
          "fixed to it with it{}",
          deck.file, b.sourceLine, b.id, b.kindWord,
          b.kind == MoorDynBodyKind::Fixed ? ""
                                           : "; through the C API the host's 6 DOFs move the points on it"));
    if (f.pinned)
      notes.push_back(
          fmt::format("{}:{}: body {} is {}: a free vessel pinned at its reference point (held there in a "
                      "standalone run; "
                      "through the C API the host's 3 DOFs move it), its rotations solved",
                      deck.file, b.sourceLine, b.id, b.kindWord));
    if (!f.free) {
      f.reference = b.position;
      frames.push_back(f);
      continue;
    }
    // Masses and volumes: the body's own at its centre of gravity (MoorDyn's Body.cpp applies its weight and
    // buoyancy both there), and its points'.
    struct Lump {
      double mass, volume;
      Vec3 at;
      double dragArea, addedMass;
    };
    std::vector<Lump> lumps{{b.mass, b.volume, f.global(b.centreOfGravity), 0.0, 0.0}};
    for (const MoorDynPoint& p : deck.points)
      if (p.kind == MoorDynPointKind::Body && p.body == b.id)
        lumps.push_back(
            {p.mass, p.volume, f.global(p.position), p.dragArea, p.addedMass * density * p.volume});
    double mass = 0.0, volume = 0.0, pointDrag = 0.0, pointAdded = 0.0;
    Vec3 moment = Vec3::Zero(), volumeMoment = Vec3::Zero();
    for (const Lump& l : lumps) {
      mass += l.mass;
      volume += l.volume;
      moment += l.mass * l.at;
      volumeMoment += l.volume * l.at;
      pointDrag += l.dragArea;
      pointAdded += l.addedMass;
    }
    f.reference = mass > 0.0 ? Vec3(moment / mass) : lumps.front().at;
    if (f.pinned) {
      // Held at the pin, the vessel carries its mass, weight and buoyancy there: a mass or volume elsewhere
      // would swing the body, which a vessel whose reference point is its centre of gravity cannot show.
      for (const Lump& l : lumps)
        if ((l.mass != 0.0 || l.volume != 0.0) &&
            (l.at - b.position).norm() > 1e-9 * std::max(1.0, b.position.norm()))
          throw InputError(deck.file, b.sourceLine, fmt::format("body {}", b.id),
                           fmt::format("a CoupledPinned body with a mass or volume off its reference point "
                                       "(at {}) is not supported by tangle: its pinned vessel carries them "
                                       "at the pin (put what swings on a rod fixed to the body)",
                                       vec(l.at)));
      f.reference = b.position;
    }
    f.mass = mass;
    f.volume = volume;
    f.centreOfBuoyancy = volume > 0.0 ? Vec3(volumeMoment / volume - f.reference) : Vec3::Zero();
    // The body's inertia (about its centre of gravity, body axes) in global axes: the diagonal of R I R^T.
    const Mat3 own = f.rotation * b.inertia.asDiagonal() * f.rotation.transpose();
    f.inertia = own.diagonal();
    const double offDiagonal = std::max({std::abs(own(0, 1)), std::abs(own(0, 2)), std::abs(own(1, 2))});
    if (offDiagonal > 1e-9 * std::max(own.diagonal().maxCoeff(), 1e-300))
      notes.push_back(
          fmt::format("{}:{}: body {}'s inertia turned by its initial roll and pitch has products of "
                      "inertia up to {} kg m^2, left out (a tangle vessel's inertia is diagonal)",
                      deck.file, b.sourceLine, b.id, num(offDiagonal)));
    for (const Lump& l : lumps) addPointInertia(f.inertia, l.mass, l.at - f.reference);
    if (!(f.mass > 0.0) || (f.inertia.array() <= 0.0).any()) {
      // A body whose mass is all in its rods (their lines carry it) or whose masses lie on one axis: tangle's
      // free vessel needs a mass and three moments of inertia > 0.
      const double floorMass = 1e-3, floorInertia = std::max(1e-3, 1e-6 * f.inertia.maxCoeff());
      notes.push_back(fmt::format(
          "{}:{}: body {} has {}: tangle's free vessel needs some, so it gets {} kg and at least {} kg m^2 "
          "about "
          "each axis (what is fixed to it, its rods and lines, carries its own mass)",
          deck.file, b.sourceLine, b.id,
          f.mass > 0.0 ? "a zero moment of inertia about an axis" : "no mass of its own or of its points",
          num(std::max(f.mass, floorMass)), num(floorInertia)));
      f.mass = std::max(f.mass, floorMass);
      for (int k = 0; k < 3; ++k) f.inertia[k] = std::max(f.inertia[k], floorInertia);
    }
    // Added mass: Ca rho V along the body's axes (MoorDyn: about its reference point), and the points'.
    const Mat3 added = f.rotation * (density * b.volume * b.addedMass).asDiagonal() * f.rotation.transpose();
    f.addedMass = added.diagonal() + Vec3::Constant(pointAdded);
    // Drag: MoorDyn's 1/2 rho CdA |v| v per body axis on the velocity relative to the water (Body.cpp).
    for (std::size_t k = 0; k < 6; ++k) f.quadraticDamping[k] = 0.5 * density * b.dragArea[k];
    for (std::size_t k = 0; k < 3; ++k) f.quadraticDamping[k] += 0.5 * density * pointDrag;
    if (!b.centreOfGravity.isZero() || lumps.size() > 1)
      notes.push_back(
          fmt::format("{}:{}: body {}: the vessel's reference point is the centre of gravity of the body and "
                      "its points, {} "
                      "(MoorDyn's is the deck's {}); its drag and added mass act there",
                      deck.file, b.sourceLine, b.id, vec(f.reference), vec(b.position)));
    frames.push_back(f);
  }
  return frames;
}

RodEnds resolveRodEnds(const MoorDynDeck& input, double density, std::vector<std::string>& notes) {
  RodEnds r;
  r.deck = input;
  MoorDynDeck& deck = r.deck;
  r.bodies = bodyFrames(input, density, notes);
  r.deckPoints = deck.points.size();
  r.carrierRod.assign(deck.points.size(), 0);
  r.carrierEnd.assign(deck.points.size(), 0);
  r.clampAxis.assign(deck.points.size(), Vec3::Zero());
  r.movingRod.assign(deck.rods.size(), false);
  r.endPoint.assign(deck.rods.size(), {0, 0});
  r.rodOffset.assign(deck.rods.size(), {Vec3::Zero(), Vec3::Zero()});
  const auto frame = [&](int body) -> BodyFrame& { return r.bodies[static_cast<std::size_t>(body - 1)]; };
  // Points on bodies: on a free body, at their offset in the vessel's axes; on a held one, fixed points.
  for (MoorDynPoint& p : deck.points) {
    if (p.kind != MoorDynPointKind::Body) continue;
    const BodyFrame& f = frame(p.body);
    if (f.free) {
      p.position = f.vesselOffset(p.position);
    } else {
      p.position = f.global(p.position);
      p.kind = MoorDynPointKind::Fixed;
    }
  }
  // Rods on bodies: their ends in global axes (and in the vessel's, on a free body); on a held body, a rod
  // fixed to it is a fixed rod and one pinned to it a pinned rod.
  for (MoorDynRod& rod : deck.rods) {
    if (rod.body == 0) continue;
    const BodyFrame& f = frame(rod.body);
    r.rodOffset[static_cast<std::size_t>(rod.id - 1)] = {f.vesselOffset(rod.endA), f.vesselOffset(rod.endB)};
    rod.endA = f.global(rod.endA);
    rod.endB = f.global(rod.endB);
    if (!f.free) rod.body = 0;
  }
  // On a free body: a rod fixed to it moves with it (a line with both ends on the vessel); one pinned to it
  // turns about its end A on the vessel.
  const auto onFreeBody = [&](const MoorDynRod& rod) { return rod.body != 0; };
  for (const MoorDynRod& rod : deck.rods) {
    const bool zeroLength = rod.length() == 0.0;
    r.movingRod[static_cast<std::size_t>(rod.id - 1)] =
        !zeroLength && (onFreeBody(rod) || rod.kind == MoorDynRodKind::Pinned ||
                        rod.kind == MoorDynRodKind::CoupledPinned || rod.kind == MoorDynRodKind::Free);
    if (rod.kind == MoorDynRodKind::Coupled || rod.kind == MoorDynRodKind::CoupledPinned)
      notes.push_back(fmt::format(
          "{}:{}: rod {} is {}: held where the deck puts it (a standalone run); through the C API the host "
          "moves {}",
          deck.file, rod.sourceLine, rod.id, rod.kindWord,
          rod.kind == MoorDynRodKind::Coupled ? "it rigidly (6 DOFs: its ends and the lines there)"
                                              : "its end A (3 DOFs), its rotation solved"));
  }
  const auto addPoint = [&](const MoorDynRod& rod, int end, MoorDynPointKind kind) {
    MoorDynPoint p;
    p.id = static_cast<int>(deck.points.size()) + 1;
    p.kind = kind;
    p.kindWord = fmt::format("rod {} end {}", rod.id, end == 0 ? 'A' : 'B');
    p.position = end == 0 ? rod.endA : rod.endB;
    if (kind == MoorDynPointKind::Body) {
      p.body = rod.body;
      p.position = r.rodOffset[static_cast<std::size_t>(rod.id - 1)][static_cast<std::size_t>(end)];
    }
    p.sourceLine = rod.sourceLine;
    deck.points.push_back(p);
    r.carrierRod.push_back(0);
    r.carrierEnd.push_back(0);
    r.clampAxis.push_back(Vec3::Zero());
    return p.id;
  };
  for (MoorDynLine& l : deck.lines) {
    for (int side = 0; side < 2; ++side) {
      const int rodId = side == 0 ? l.rodA : l.rodB;
      if (rodId == 0) continue;
      const MoorDynRod& rod = deck.rods[static_cast<std::size_t>(rodId - 1)];
      const int rodEnd = side == 0 ? l.rodEndA : l.rodEndB;
      const bool zeroLength = rod.length() == 0.0;
      std::array<int, 2>& ends = r.endPoint[static_cast<std::size_t>(rodId - 1)];
      // A zero-length rod's two ends are one point.
      const int slot = zeroLength ? 0 : rodEnd;
      if (ends[static_cast<std::size_t>(slot)] == 0) {
        const bool pinnedEnd =
            (rod.kind == MoorDynRodKind::Pinned || rod.kind == MoorDynRodKind::CoupledPinned) &&
            (slot == 0 || zeroLength);
        const bool onBody = onFreeBody(rod) && (rod.kind == MoorDynRodKind::Fixed || pinnedEnd);
        const bool held = !onFreeBody(rod) && (rod.kind == MoorDynRodKind::Fixed ||
                                               rod.kind == MoorDynRodKind::Coupled || pinnedEnd);
        const int id = addPoint(rod, slot,
                                onBody ? MoorDynPointKind::Body
                                : held ? MoorDynPointKind::Fixed
                                       : MoorDynPointKind::Free);
        ends[static_cast<std::size_t>(slot)] = id;
        MoorDynPoint& p = deck.points.back();
        if (held && !zeroLength &&
            (rod.kind == MoorDynRodKind::Fixed || rod.kind == MoorDynRodKind::Coupled)) {
          const Vec3 axis = (rod.endB - rod.endA) / rod.length();
          r.clampAxis.back() = slot == 1 ? axis : Vec3(-axis);
        }
        if (!held && !onBody && zeroLength) {
          // MoorDyn's zero-length rod (Rod.cpp): no length, so no mass, net buoyancy or side drag; the axial
          // drag CdEnd on pi/4 d^2 of both its ends (applied at its one node) becomes the point's drag area.
          const MoorDynRodType& t = rodTypeOf(deck, rod);
          p.dragArea = 2.0 * t.dragEnd * circleArea(t.diameter);
          if (t.addedMassEnd > 0.0)
            notes.push_back(fmt::format(
                "{}:{}: zero-length rod {} is a free point with drag area CdEnd pi/4 d^2 = {} m^2; its end "
                "added mass (CaEnd = {}) is left out",
                deck.file, rod.sourceLine, rod.id, p.dragArea, t.addedMassEnd));
        }
        if (!held && !onBody && !zeroLength) {
          r.carrierRod.back() = rod.id;
          r.carrierEnd.back() = slot;
        }
      }
      (side == 0 ? l.pointA : l.pointB) = ends[static_cast<std::size_t>(slot)];
      l.rodA = side == 0 ? 0 : l.rodA;
      l.rodB = side == 1 ? 0 : l.rodB;
    }
    if (l.pointA == l.pointB)
      throw InputError(deck.file, l.sourceLine, fmt::format("line {}", l.id),
                       "both ends of the line are on the same rod end (a zero-length rod's two ends are one "
                       "point)");
  }
  // A free body is held when a line ends on it (at one of its points or at a rod fixed or pinned to it).
  for (const MoorDynLine& l : deck.lines)
    for (const int pointId : {l.pointA, l.pointB}) {
      const MoorDynPoint& p = deck.points[static_cast<std::size_t>(pointId - 1)];
      if (p.kind == MoorDynPointKind::Body) frame(p.body).held = true;
    }
  return r;
}

/// One deck line placed in a chain of deck lines joined at free points.
struct ChainEntry {
  int line = 0;           ///< index in deck.lines
  bool reversed = false;  ///< traversed from its end B to its end A
};

}  // namespace

MoorDynConversion convertMoorDynDeck(const MoorDynDeck& input) {
  MoorDynConversion out;
  std::vector<std::string>& notes = out.notes;
  const Options opt = readOptions(input, notes);
  const RodEnds rodEnds = resolveRodEnds(input, opt.density, notes);
  const MoorDynDeck& deck = rodEnds.deck;  // rod ends that lines attach to are points in it
  const auto pointLine = [&](int id) { return deck.points[static_cast<std::size_t>(id - 1)].sourceLine; };
  const auto carrier = [&](int pointId) { return rodEnds.carrierRod[static_cast<std::size_t>(pointId - 1)]; };
  // A tangle point's name: a free point's `point<id>`, a moving rod's end `rod<id>a` / `rod<id>b`.
  const auto pointName = [&](int pointId) {
    const int rod = carrier(pointId);
    return rod != 0 ? fmt::format("rod{}{}", rod,
                                  rodEnds.carrierEnd[static_cast<std::size_t>(pointId - 1)] == 0 ? 'a' : 'b')
                    : fmt::format("point{}", pointId);
  };

  // Water depth: WtrDpth, deepened to the lowest point as MoorDyn does (MoorDyn2.cpp, point list).
  double depth = opt.depth;
  for (const MoorDynPoint& p : deck.points)
    if (p.kind != MoorDynPointKind::Body && -p.position.z() > depth) {
      if (opt.depth > 0.0)
        notes.push_back(
            fmt::format("{}:{}: point {} is below WtrDpth = {} m: the water depth is set to {} m, as "
                        "MoorDyn does",
                        deck.file, p.sourceLine, p.id, num(opt.depth), num(-p.position.z())));
      depth = -p.position.z();
    }
  for (const MoorDynRod& rod : deck.rods)
    for (const Vec3& e : {rod.endA, rod.endB})
      if (-e.z() > depth) {
        if (opt.depth > 0.0)
          notes.push_back(
              fmt::format("{}:{}: rod {} reaches below WtrDpth = {} m: the water depth is set to {} m",
                          deck.file, rod.sourceLine, rod.id, num(opt.depth), num(-e.z())));
        depth = -e.z();
      }
  if (!(depth > 0.0))
    throw InputError(deck.file, opt.lineOf.count("wtrdpth") ? opt.lineOf.at("wtrdpth") : 0, "WtrDpth",
                     "expected a water depth > 0 (option WtrDpth, or a point below the surface)");

  // Which deck line ends sit at each point.
  std::vector<std::vector<std::pair<int, int>>> atPoint(deck.points.size());
  for (std::size_t l = 0; l < deck.lines.size(); ++l) {
    atPoint[static_cast<std::size_t>(deck.lines[l].pointA - 1)].push_back({static_cast<int>(l), 0});
    atPoint[static_cast<std::size_t>(deck.lines[l].pointB - 1)].push_back({static_cast<int>(l), 1});
  }
  for (const MoorDynPoint& p : deck.points) {
    const std::size_t n = atPoint[static_cast<std::size_t>(p.id - 1)].size();
    // A point on a body may hold no line (a mass on it; MoorDyn's orbitalBody.txt).
    const bool onBody = static_cast<std::size_t>(p.id) <= input.points.size() &&
                        input.points[static_cast<std::size_t>(p.id - 1)].kind == MoorDynPointKind::Body;
    if (n == 0 && !onBody)
      throw InputError(
          deck.file, p.sourceLine, fmt::format("point {}", p.id),
          "no line is attached to this point (tangle models lines; a lone point has nothing to hold)");
  }
  // A free point joining three or more deck lines (a bridle's apex, a triplate) is a tangle point, where the
  // lines end with `type: point`; a free point joining two is a node inside one tangle line (a chain).
  // A moving rod's end is a tangle point too, carried by the rod's line (written first: its end node).
  const auto isHub = [&](int pointId) {
    return carrier(pointId) != 0 ||
           (deck.points[static_cast<std::size_t>(pointId - 1)].kind == MoorDynPointKind::Free &&
            atPoint[static_cast<std::size_t>(pointId - 1)].size() > 2);
  };
  const auto isJunction = [&](int pointId) {
    return carrier(pointId) == 0 &&
           deck.points[static_cast<std::size_t>(pointId - 1)].kind == MoorDynPointKind::Free &&
           atPoint[static_cast<std::size_t>(pointId - 1)].size() == 2;
  };
  const auto pointAt = [&](int line, int end) {
    const MoorDynLine& l = deck.lines[static_cast<std::size_t>(line)];
    return end == 0 ? l.pointA : l.pointB;
  };
  const auto otherAt = [&](int pointId, int line) {
    for (const auto& [l, e] : atPoint[static_cast<std::size_t>(pointId - 1)])
      if (l != line) return std::pair{l, e};
    return std::pair{-1, -1};
  };

  // Chains of deck lines joined in series at free points; each becomes one tangle line.
  std::vector<std::vector<ChainEntry>> chains;
  std::vector<bool> placed(deck.lines.size(), false);
  for (std::size_t first = 0; first < deck.lines.size(); ++first) {
    if (placed[first]) continue;
    // Walk out through end A to the chain's start.
    int line = static_cast<int>(first), outEnd = 0;
    for (std::size_t guard = 0;; ++guard) {
      const int p = pointAt(line, outEnd);
      if (!isJunction(p)) break;
      const auto [next, nextEnd] = otherAt(p, line);
      if (next == static_cast<int>(first) || guard > deck.lines.size())
        throw InputError(
            deck.file, deck.lines[first].sourceLine, fmt::format("line {}", deck.lines[first].id),
            "the lines joined at free points close a loop: tangle needs every chain of lines to end at a "
            "fixed, coupled or free end point");
      line = next;
      outEnd = 1 - nextEnd;
    }
    // Walk forward from that end.
    std::vector<ChainEntry> chain;
    int inEnd = outEnd;
    while (true) {
      chain.push_back({line, inEnd == 1});
      placed[static_cast<std::size_t>(line)] = true;
      const int p = pointAt(line, 1 - inEnd);
      if (!isJunction(p)) break;
      const auto [next, nextEnd] = otherAt(p, line);
      line = next;
      inEnd = nextEnd;
    }
    chains.push_back(std::move(chain));
  }

  // FAILURE rows (docs/moordyn.md): the listed lines part from the point. At a chain's end point that is the
  // tangle line's failure at that end; at a free point joining two deck lines in series, its failure at the
  // junction's arc length. tangle parts a line once and in one place.
  std::map<std::size_t, std::string> failureOfChain;
  {
    std::vector<std::size_t> chainOf(deck.lines.size());
    std::vector<double> arcBefore(deck.lines.size(), 0.0);  // arc length of the line's start in its chain
    for (std::size_t c = 0; c < chains.size(); ++c) {
      double arc = 0.0;
      for (const ChainEntry& e : chains[c]) {
        chainOf[static_cast<std::size_t>(e.line)] = c;
        arcBefore[static_cast<std::size_t>(e.line)] = arc;
        arc += deck.lines[static_cast<std::size_t>(e.line)].length;
      }
    }
    for (const MoorDynFailure& f : deck.failures) {
      if (f.time <= 0.0 && f.tension <= 0.0) {
        notes.push_back(
            fmt::format("{}:{}: failure {} has neither FailTime nor FailTen: it never happens and is "
                        "left out",
                        deck.file, f.sourceLine, f.id));
        continue;
      }
      const bool junction = isJunction(f.point);
      if (junction && f.lines.size() > 1) {
        notes.push_back(
            fmt::format("{}:{}: failure {} parts both lines at free point {} from it: they stay "
                        "joined to each other (MoorDyn's rule), so nothing parts; left out",
                        deck.file, f.sourceLine, f.id, f.point));
        continue;
      }
      for (const int id : f.lines) {
        const std::size_t l = static_cast<std::size_t>(id - 1);
        const MoorDynLine& dl = deck.lines[l];
        const std::size_t c = chainOf[l];
        std::string at;
        if (junction) {
          // The junction is at the end of this deck line that sits at the point, inside the chain.
          const bool reversed = std::find_if(chains[c].begin(), chains[c].end(), [&](const ChainEntry& e) {
                                  return e.line == static_cast<int>(l);
                                })->reversed;
          const bool atEndB = (dl.pointB == f.point) != reversed;
          at = num(arcBefore[l] + (atEndB ? dl.length : 0.0));
        } else {
          const ChainEntry& head = chains[c].front();
          at = pointAt(head.line, head.reversed ? 1 : 0) == f.point && head.line == static_cast<int>(l)
                   ? "end_a"
                   : "end_b";
        }
        std::string triggers;
        if (f.time > 0.0) triggers += "time: " + num(f.time) + ", ";
        if (f.tension > 0.0) triggers += "tension: " + num(f.tension) + ", ";
        if (failureOfChain.count(c))
          throw InputError(
              deck.file, f.sourceLine, fmt::format("failure {}", f.id),
              fmt::format("line {} would part a second time (tangle parts a line once): one FAILURE "
                          "row per line, or lines joined in series at free points, in one row",
                          id));
        failureOfChain[c] = fmt::format(
            "    failure: {{{}at: {}}}   # FAILURE {} (deck line {}): line {} parts from "
            "point {}",
            triggers, at, f.id, f.sourceLine, id, f.point);
      }
    }
  }

  // Bending stiffness: a line type whose bending reaches over a small part of its shortest segment acts as a
  // cable. Its bending length (EI / w)^(1/3) (w its submerged weight per length, or its weight in air when it
  // is neutral) below a tenth of the segment: tangle makes it a cable (bar elements), whose statics a beam
  // of nearly no stiffness would only make ill-conditioned (EA h^2 / EI ~ 1e8: MoorDyn's complex_system.txt).
  std::map<std::string, double> bendingOfType;
  for (const MoorDynLineType& t : deck.lineTypes) {
    double shortest = std::numeric_limits<double>::infinity();
    for (const MoorDynLine& l : deck.lines)
      if (l.lineType == t.name) shortest = std::min(shortest, l.length / l.segments);
    const double wet =
        std::abs(t.massPerLength - opt.density * std::numbers::pi / 4.0 * t.diameter * t.diameter);
    const double w = std::max(wet, 1e-3 * t.massPerLength) * std::max(opt.gravity, 1e-3);
    const double bendingLength = std::cbrt(t.bendingStiffness / w);
    bendingOfType[t.name] = t.bendingStiffness;
    if (t.bendingStiffness > 0.0 && std::isfinite(shortest) && bendingLength < 0.1 * shortest) {
      bendingOfType[t.name] = 0.0;
      notes.push_back(
          fmt::format("line type {}: EI = {} N m^2 bends over (EI / w)^(1/3) = {} m, under a tenth of its "
                      "shortest segment ({} "
                      "m): a cable in tangle (EI 0)",
                      t.name, num(t.bendingStiffness), num(bendingLength), num(shortest)));
    }
  }

  // Line types: one per deck type, or per deck line where a damping ratio (negative BA) gives each line's
  // segments a different coefficient. MoorDyn (Line.cpp, setup): BA = -BA_in * (L/N) * sqrt(EA * w) [N s],
  // with a curve file's EA its secant to the last point (MoorDynLineType::moorDynStiffness; until
  // 2026-12-06 the curve's largest slope: a stiffening rope's damping came out sqrt(slope / secant) high).
  struct TypeUse {
    std::string name;
    const MoorDynLineType* type;
    double damping;
    std::vector<int> lines;
  };
  std::vector<TypeUse> types;
  std::vector<std::string> typeOfLine(deck.lines.size());
  for (const MoorDynLineType& t : deck.lineTypes) {
    std::vector<TypeUse> uses;
    for (std::size_t l = 0; l < deck.lines.size(); ++l) {
      const MoorDynLine& dl = deck.lines[l];
      if (dl.lineType != t.name) continue;
      const double damping = t.axialDamping >= 0.0 ? t.axialDamping
                                                   : -t.axialDamping * dl.length / dl.segments *
                                                         std::sqrt(t.moorDynStiffness * t.massPerLength);
      auto same = std::find_if(uses.begin(), uses.end(), [&](const TypeUse& u) {
        return std::abs(u.damping - damping) <= 1e-12 * std::max(std::abs(damping), 1.0);
      });
      if (same == uses.end()) {
        uses.push_back({t.name, &t, damping, {}});
        same = uses.end() - 1;
      }
      same->lines.push_back(static_cast<int>(l));
    }
    if (uses.size() > 1)
      for (TypeUse& u : uses)
        u.name = fmt::format("{}-line{}", t.name, deck.lines[static_cast<std::size_t>(u.lines[0])].id);
    for (TypeUse& u : uses) {
      for (const int l : u.lines) typeOfLine[static_cast<std::size_t>(l)] = u.name;
      types.push_back(std::move(u));
    }
  }

  // Seabed: MoorDyn's kBot, cBot are per contact area (Pa/m, Pa s/m) over the node's diameter; tangle's per
  // metre of line: the deck's longest line type sets the width.
  const MoorDynLineType* widest = nullptr;
  double longest = -1.0, longestSegment = 1.0;
  for (const MoorDynLineType& t : deck.lineTypes) {
    double total = 0.0, segment = 1.0;
    for (const MoorDynLine& l : deck.lines)
      if (l.lineType == t.name) {
        total += l.length;
        segment = l.length / l.segments;
      }
    if (total > longest) {
      longest = total;
      widest = &t;
      longestSegment = segment;
    }
  }
  // A deck of rods only: the widest rod sets it (nothing lies on the seabed along its length but a rod).
  double width = widest != nullptr ? widest->diameter : 0.0;
  for (const MoorDynRodType& t : deck.rodTypes)
    if (widest == nullptr) width = std::max(width, t.diameter);
  bool typesDiffer = false;
  for (const MoorDynLineType& t : deck.lineTypes) typesDiffer = typesDiffer || t.diameter != width;
  if (typesDiffer)
    notes.push_back(
        fmt::format("seabed stiffness and damping per metre of line are kBot and cBot times the diameter "
                    "{} m of line type {} (the longest); tangle has one seabed stiffness per metre for "
                    "every line",
                    num(width), widest->name));

  // Layout of the YAML text.
  std::string y;
  const auto line = [&](const std::string& s) { y += s + "\n"; };
  line(fmt::format("# tangle model converted from the MoorDyn input file {}", deck.file));
  if (!deck.title.empty()) line(fmt::format("# deck title: {}", deck.title));
  line(
      "# Each value says where it came from (`deck line N`). The mapping and the differences from MoorDyn "
      "are in");
  line("# docs/moordyn.md. Units: SI (m, kg, N, s); angles in degrees.");
  line("");
  std::string title = deck.title.empty() ? std::string("MoorDyn deck") : deck.title;
  std::replace(title.begin(), title.end(), '"', '\'');
  line(fmt::format("title: \"{}\"", title));
  line("");
  line("environment:");
  line(fmt::format("  water_depth: {}          # WtrDpth{}", num(depth),
                   opt.lineOf.count("wtrdpth") ? fmt::format(" (deck line {})", opt.lineOf.at("wtrdpth"))
                                               : " (deepest point)"));
  // The deck line of an option under any of its names (readOptions takes `rho` for WtrDnsty, `gravity` for
  // g, `kb` for kBot, `cb` for cBot), else MoorDyn's default.
  const auto optionComment = [&](std::initializer_list<const char*> names, const char* fallback) {
    for (const char* name : names)
      if (const auto it = opt.lineOf.find(name); it != opt.lineOf.end())
        return fmt::format("deck line {}", it->second);
    return fmt::format("MoorDyn default {}", fallback);
  };
  line(fmt::format("  water_density: {}        # WtrDnsty ({})", num(opt.density),
                   optionComment({"wtrdnsty", "rho"}, "1025")));
  line(fmt::format("  gravity: {}               # g ({})", num(opt.gravity),
                   optionComment({"g", "gravity"}, "9.80665")));
  line("  seabed:");
  line(fmt::format("    normal_stiffness: {}    # kBot {} Pa/m x diameter {} m ({})",
                   num(opt.seabedStiffness * width), num(opt.seabedStiffness), num(width),
                   optionComment({"kbot", "kb"}, "3e6")));
  line(fmt::format("    damping: {}             # cBot {} Pa s/m x diameter {} m ({})",
                   num(opt.seabedDamping * width), num(opt.seabedDamping), num(width),
                   optionComment({"cbot", "cb"}, "3e5")));
  line(fmt::format("    friction_coefficient: {}  # FrictionCoefficient ({})", num(opt.friction),
                   optionComment({"frictioncoefficient"}, "0")));
  if (!opt.seafloorFile.empty())
    line(
        fmt::format("    bathymetry: {{file: {}, interpolation: bilinear}}  # SeafloorFile ({}; bilinear as "
                    "MoorDyn's interp2)",
                    yamlQuoted(opt.seafloorFile), optionComment({"seafloorfile"}, "")));
  if (opt.friction > 0.0 && widest == nullptr)
    notes.push_back("FrictionCoefficient: a deck without lines; the seabed friction is left out");
  if (opt.friction > 0.0 && widest != nullptr) {
    // MoorDyn (Line.cpp): friction = min(mu FricDamp |v|, mu N) with N the node's seabed force: a viscous
    // law saturating at |v| = N / FricDamp. tangle's viscous law mu N v / max(|v|, v_f) has the same slope
    // when v_f = N / FricDamp, with N the submerged weight of one segment of the longest line type.
    const double submerged =
        (widest->massPerLength - opt.density * std::numbers::pi / 4.0 * width * width) * opt.gravity;
    const double normal = std::max(submerged, 1e-6) * longestSegment;
    const double matching = normal / opt.frictionDamping;
    const double velocity = std::clamp(matching, 1e-4, kMaxFrictionVelocity);
    if (velocity != matching)
      notes.push_back(
          fmt::format("seabed friction: MoorDyn's friction saturates only above {} m/s here (a weak viscous "
                      "drag of mu FricDamp = "
                      "{} N s/m per node below); tangle's friction_velocity is limited to {} m/s, so its "
                      "friction is stronger "
                      "at low speeds",
                      num(matching), num(opt.friction * opt.frictionDamping), num(kMaxFrictionVelocity)));
    line("    friction_model: viscous   # MoorDyn's saturated viscous friction");
    line(fmt::format("    friction_velocity: {}   # = segment weight {} N / FricDamp {} N s/m ({})",
                     num(velocity), num(normal), num(opt.frictionDamping),
                     optionComment({"fricdamp"}, "200")));
    notes.push_back(fmt::format(
        "seabed friction: MoorDyn's friction saturates at |v| = N / FricDamp with N each node's bottom "
        "force; tangle "
        "uses one friction_velocity = {} m/s (a segment of line type {} on the seabed) and holds the static "
        "equilibrium with its elastic friction law",
        num(velocity), widest->name));
    if (opt.staticDynamicScale != 1.0)
      notes.push_back(
          fmt::format("StatDynFricScale = {}: tangle has one friction coefficient (static = dynamic)",
                      num(opt.staticDynamicScale)));
  }
  if (opt.waveMode != 0) {
    const int optionLine = opt.lineOf.at("wavekin");
    const std::vector<DeckWaveComponent> components =
        opt.waveMode == 3 ? readWaveElevation(deck, optionLine, opt.waveStep, notes)
                          : readWaveFrequencies(deck, optionLine, notes);
    line(fmt::format("  waves:                    # WaveKin {} (deck line {}): {}", opt.waveMode, optionLine,
                     opt.waveMode == 3 ? "wave_elevation.txt as its Fourier series"
                                       : "wave_frequencies.txt, summed as MoorDyn's WaveKin 7"));
    line("    type: components");
    line("    table:                  # [period s, amplitude m, phase deg, azimuth deg]");
    for (const DeckWaveComponent& c : components)
      line(fmt::format(
          "      - [{}, {}, {}, {}]{}", num(c.period), num(c.amplitude), num(c.phase), num(c.azimuth),
          c.sourceLine > 0 ? fmt::format("   # wave_frequencies.txt line {}", c.sourceLine) : ""));
    if (opt.waveMode == 2)
      notes.push_back(
          "WaveKin 2: the components are summed at each element (MoorDyn's WaveKin 7), not "
          "interpolated on an inverse-FFT grid");
  }
  if (opt.currentMode == 5) {
    const std::string path =
        std::filesystem::absolute(std::filesystem::path(deck.file).parent_path() / "current_profile_4d.txt")
            .lexically_normal()
            .string();
    // Read here too, so that a bad file is reported against the deck's option.
    try {
      hydro::readCurrentGridFile(path);
    } catch (const InputError& e) {
      throw InputError(
          deck.file, opt.lineOf.at("currents"), "Currents",
          fmt::format("Currents = 5 reads current_profile_4d.txt next to the deck: {}", e.what()));
    }
    line(fmt::format("  current:                  # Currents 5 (deck line {}): a grid in space and time",
                     opt.lineOf.at("currents")));
    line(fmt::format("    grid: {{file: {}}}", yamlQuoted(path)));
    notes.push_back(
        "Currents 5: tangle holds the grid's last velocities after its last time (MoorDyn repeats the grid) "
        "and "
        "reads every node row of current_profile_4d.txt (MoorDyn skips the first)");
  } else if (opt.currentMode == 2) {
    const auto history = readDynamicCurrent(deck, opt.lineOf.at("currents"), notes);
    line(fmt::format(
        "  current:                  # Currents 2 (deck line {}): current_profile_dynamic.txt, (ux, uy) as "
        "speed and azimuth at each time",
        opt.lineOf.at("currents")));
    line("    history:");
    for (const auto& [time, levels] : history) {
      line(fmt::format("      - time: {}             # current_profile_dynamic.txt line {}", num(time),
                       levels.front().sourceLine));
      line("        profile:");
      for (const ProfileLevel& l : levels) {
        const double speed = std::hypot(l.velocity.x(), l.velocity.y());
        const double azimuth =
            speed > 0.0 ? std::atan2(l.velocity.y(), l.velocity.x()) * 180.0 / std::numbers::pi : 0.0;
        line(
            fmt::format("          - {{z: {}, speed: {}, azimuth: {}}}", num(l.z), num(speed), num(azimuth)));
      }
    }
    notes.push_back(
        "current history: tangle interpolates each profile's speed and direction between levels and the "
        "velocity components between times; MoorDyn the components in both");
  } else if (opt.currentMode != 0) {
    const std::vector<ProfileLevel> levels = readCurrentProfile(deck, opt.lineOf.at("currents"), notes);
    line(fmt::format("  current:                  # Currents {} (deck line {}): current_profile.txt, (ux, uy) as "
                     "speed and azimuth",
                     opt.currentMode, opt.lineOf.at("currents")));
    bool turning = false;
    for (const ProfileLevel& l : levels) {
      const double speed = std::hypot(l.velocity.x(), l.velocity.y());
      const double azimuth = speed > 0.0 ? std::atan2(l.velocity.y(), l.velocity.x()) * 180.0 / std::numbers::pi : 0.0;
      line(fmt::format("    - {{z: {}, speed: {}, azimuth: {}}}   # current_profile.txt line {}", num(l.z), num(speed),
                       num(azimuth), l.sourceLine));
      const Vec3& first = levels.front().velocity;
      turning = turning || std::abs(first.x() * l.velocity.y() - first.y() * l.velocity.x()) >
                               1e-12 * std::max(first.squaredNorm() + l.velocity.squaredNorm(), 1e-300);
    }
    if (turning)
      notes.push_back("current profile: its direction turns with depth; tangle interpolates the speed and the "
                      "direction between levels, MoorDyn the components (the same where the direction is constant)");
  }
  line("");

  line("line_types:");
  for (const TypeUse& u : types) {
    const MoorDynLineType& t = *u.type;
    line(fmt::format("  - name: {}                # deck line {}", yamlQuoted(u.name), t.sourceLine));
    line(fmt::format("    outer_diameter: {}      # Diam: drag, added mass and buoyancy (pi/4 d^2)",
                     num(t.diameter)));
    line(fmt::format("    mass_per_length: {}     # Mass/m", num(t.massPerLength)));
    if (t.syrope) {
      // The SYROPE IC rows of its lines: one Tmax0 for the type (tangle keeps it per line type).
      const MoorDynSyropeIc* ic = nullptr;
      for (const int l : u.lines) {
        const int id = deck.lines[static_cast<std::size_t>(l)].id;
        for (const MoorDynSyropeIc& row : deck.syropeIc)
          if (std::find(row.lines.begin(), row.lines.end(), id) != row.lines.end()) {
            if (ic && ic->maxTension != row.maxTension)
              throw InputError(
                  deck.file, row.sourceLine, "SYROPE IC",
                  fmt::format("lines of line type {} start from different Tmax0 ({} and {} N): tangle "
                              "keeps one per line type; give them types of their own",
                              t.name, num(ic->maxTension), num(row.maxTension)));
            ic = &row;
          }
        if (!ic)
          throw InputError(deck.file, t.sourceLine, fmt::format("line type {} EA", t.name),
                           fmt::format("line {} is a SYROPE rope without a row in the SYROPE IC section (its "
                                       "initial Tmax0 and Tmean0, as MoorDyn needs)",
                                       id));
      }
      std::vector<std::pair<double, double>> curve = t.syropeCurve;
      if (curve.front().second > 0.0) {
        notes.push_back(
            fmt::format("line type {}: its original working curve ({}) starts at tension {} N (MoorDyn's "
                        "read_curve skips "
                        "three header lines); tangle starts it at (0, 0), which moves the working curves' "
                        "eps_0 from {} to 0 "
                        "for the quadratic and exponential forms",
                        t.name, t.syropeCurveFile, num(curve.front().second), num(curve.front().first)));
        curve.insert(curve.begin(), {0.0, 0.0});
      }
      std::string points;
      for (const auto& [strain, tension] : curve)
        points += fmt::format("{}[{}, {}]", points.empty() ? "" : ", ", num(strain), num(tension));
      line(fmt::format("    syrope:                 # EA SYROPE:{}|alphaMBL|vbeta (deck line {})",
                       t.syropeSettingsFile, t.sourceLine));
      line(fmt::format("      original_curve: [{}]   # OWC {}", points, t.syropeCurveFile));
      line(fmt::format("      working_curve: {}       # WCType",
                       t.syropeForm == "exp" ? "exponential" : t.syropeForm));
      line(fmt::format("      k1: {}", num(t.syropeK1)));
      line(fmt::format("      k2: {}", num(t.syropeK2)));
      line(fmt::format("      dynamic_stiffness: {}   # alphaMBL", num(t.dynamicStiffness)));
      line(fmt::format("      dynamic_stiffness_slope: {}   # vbeta", num(t.dynamicStiffnessSlope)));
      line(fmt::format("      slow_damping: {}        # BA", num(t.axialDamping)));
      if (t.dynamicDamping > 0.0)
        line(fmt::format("      dynamic_damping: {}     # BA_d", num(t.dynamicDamping)));
      line(fmt::format("      initial_max_mean_tension: {}   # SYROPE IC Tmax0 (deck line {})",
                       num(ic->maxTension), ic->sourceLine));
      notes.push_back(fmt::format(
          "line type {}: SYROPE; tangle's statics follows the working curve of Tmax0 and its dynamics starts "
          "from that equilibrium (MoorDyn starts the slow strain at Tmean0 = {} N whatever the stretch); the "
          "working curves are exact (MoorDyn tabulates them)",
          t.name, num(ic->meanTension)));
    } else if (t.tensionStrain.empty()) {
      line(fmt::format("    axial_stiffness: {}     # EA", num(t.axialStiffness)));
    } else {
      // MoorDyn (Line.cpp, getNonlinearEA; Util/Interp.hpp): the tension is interpolated in the curve's
      // points, held at the first point's below it and at the last one's beyond it. tangle's curve starts at
      // (0, 0) and continues the last slope.
      std::string points;
      for (const auto& [strain, tension] : t.tensionStrain)
        if (strain > 0.0)
          points += fmt::format("{}[{}, {}]", points.empty() ? "" : ", ", num(strain), num(tension));
      line(fmt::format("    tension_strain: [{}]   # EA: the curve file {}", points, t.tensionStrainFile));
      if (t.tensionStrain.front().first > 0.0)
        notes.push_back(
            fmt::format("line type {}: its EA curve starts at strain {}: MoorDyn holds the first "
                        "point's tension {} N from zero strain up to it, tangle rises linearly from "
                        "(0, 0)",
                        t.name, num(t.tensionStrain.front().first), num(t.tensionStrain.front().second)));
      notes.push_back(
          fmt::format("line type {}: beyond its EA curve's last strain {} MoorDyn holds the tension at "
                      "{} N, tangle continues the last segment's slope",
                      t.name, num(t.tensionStrain.back().first), num(t.tensionStrain.back().second)));
    }
    if (bendingOfType.at(t.name) > 0.0)
      line(fmt::format("    bending_stiffness: {}   # EI", num(t.bendingStiffness)));
    else if (t.bendingStiffness > 0.0)
      line(fmt::format(
          "    # bending_stiffness: {}   # EI: negligible over its segments, a cable (see the notes)",
          num(t.bendingStiffness)));
    if (t.syrope) {
      // (the dashpots are in its syrope block)
    } else if (t.dynamicStiffness > 0.0) {
      line(fmt::format("    viscoelastic:           # EA|{} (deck line {}): the static EA above, and",
                       t.dynamicStiffnessSlope > 0.0 ? "alphaMBL|vbeta" : "EA_d", t.sourceLine));
      line(fmt::format("      dynamic_stiffness: {}   # {}", num(t.dynamicStiffness),
                       t.dynamicStiffnessSlope > 0.0 ? "alphaMBL" : "EA_d"));
      if (t.dynamicStiffnessSlope > 0.0)
        line(fmt::format("      dynamic_stiffness_slope: {}   # vbeta", num(t.dynamicStiffnessSlope)));
      line(fmt::format("      slow_damping: {}        # BA", num(t.axialDamping)));
      if (t.dynamicDamping > 0.0)
        line(fmt::format("      dynamic_damping: {}     # BA_d", num(t.dynamicDamping)));
      notes.push_back(fmt::format(
          "line type {}: viscoelastic; tangle's dynamics starts from the rope relaxed at its static solution "
          "(MoorDyn from its slow stretch equal to the whole stretch, relaxed by its initial-condition run)",
          t.name));
    } else if (u.damping > 0.0) {
      if (t.axialDamping < 0.0)
        line(fmt::format(
            "    axial_damping: {}       # BA/-zeta = {}: zeta x (L/N) x sqrt(EA m) of line {}, as MoorDyn",
            num(u.damping), num(t.axialDamping), deck.lines[static_cast<std::size_t>(u.lines[0])].id));
      else
        line(fmt::format("    axial_damping: {}       # BA", num(u.damping)));
    }
    line(fmt::format("    drag_normal: {}         # Cd (on Diam)", num(t.dragNormal)));
    line(fmt::format("    drag_axial: {}          # CdAx (on pi Diam, as MoorDyn)", num(t.dragAxial)));
    line(fmt::format("    added_mass_normal: {}   # Ca", num(t.addedMassNormal)));
    line(fmt::format("    added_mass_axial: {}    # CaAx", num(t.addedMassAxial)));
  }
  // Rods that move (pinned or free, of length > 0): MoorDyn's rigid cylinder as a stiff beam line. Its
  // stiffness is set by its own load scale q = (m + rho pi/4 d^2) g [N/m] over its length L, so that its
  // sag under that load is about 1e-7 L (EI = 1e5 q L^3: 5/384 q L^4 / EI) and its stretch about 1e-7
  // (EA = 1e7 q L), and its elements at least 100 times as stiff axially as the stiffest line segment (EA /
  // h) that pulls on it; both at most 1e13. (Stiffer still would only raise the round-off of the links that
  // tie the lines to it, 100 x its own elements' EA / h: a 0.2 m clamp rod at 100 x its lines' EA left the
  // riser decks' statics at a 13 N round-off floor.)
  double lineSegmentStiffness = 0.0;  // the largest EA / h of the deck's line segments [N/m]
  for (const MoorDynLine& l : deck.lines)
    for (const MoorDynLineType& t : deck.lineTypes)
      if (t.name == l.lineType)
        lineSegmentStiffness = std::max(lineSegmentStiffness, t.axialStiffness * l.segments / l.length);
  std::set<std::string> rodTypesWritten;
  for (const MoorDynRodType& t : deck.rodTypes) {
    double rodLength = 0.0, rodElement = std::numeric_limits<double>::infinity();
    for (const MoorDynRod& rod : deck.rods)
      if (rod.rodType == t.name && rodEnds.movingRod[static_cast<std::size_t>(rod.id - 1)]) {
        rodLength = std::max(rodLength, rod.length());
        rodElement = std::min(rodElement, rod.length() / rod.segments);
      }
    if (rodLength == 0.0) continue;
    rodTypesWritten.insert(t.name);
    const double q = (t.massPerLength + opt.density * circleArea(t.diameter)) * std::max(opt.gravity, 1.0);
    // At most tangle's largest stiffness, 1e13 (a 10 m diameter can's sag is then still 1e-8 of its length).
    const double axial =
        std::min(std::max({1e7 * q * rodLength, 1e2 * lineSegmentStiffness * rodElement, 1e6}), 1e13);
    const double bending = std::min(std::max(1e5 * q * rodLength * rodLength * rodLength, 1e3), 1e13);
    line(fmt::format(
        "  - name: {}                # rod type {} (deck line {}): MoorDyn's rigid rod as a stiff beam",
        yamlQuoted("rod-" + t.name), t.name, t.sourceLine));
    line(fmt::format("    outer_diameter: {}      # Diam", num(t.diameter)));
    line(fmt::format("    mass_per_length: {}     # Mass/m", num(t.massPerLength)));
    line(fmt::format(
        "    axial_stiffness: {}     # rigid: max(1e7 q L, 100 x the stiffest line segment's EA / h x "
        "its element {} m), q = (m + rho pi/4 d^2) g, L = {} m",
        num(axial), num(rodElement), num(rodLength)));
    line(fmt::format("    bending_stiffness: {}   # rigid: 1e5 q L^3 (sag about 1e-7 L)", num(bending)));
    line(fmt::format("    drag_normal: {}         # Cd", num(t.drag)));
    line("    drag_axial: 0             # a rod's side has no axial drag (CdEnd at its ends)");
    line(fmt::format("    added_mass_normal: {}   # Ca", num(t.addedMass)));
    line("    added_mass_axial: 0");
    line("    maximum_strain: 0.001       # a rigid rod");
  }
  line("");

  // Point maps, filled as the lines are written.
  out.points.resize(deck.points.size());
  for (const MoorDynPoint& p : deck.points) {
    MoorDynPointMap& m = out.points[static_cast<std::size_t>(p.id - 1)];
    m.deckId = p.id;
    m.kind = p.kind;
    m.position = p.position;
    for (const auto& [l, e] : atPoint[static_cast<std::size_t>(p.id - 1)])
      m.attachedLines.push_back({deck.lines[static_cast<std::size_t>(l)].id, e});
  }
  out.lines.resize(deck.lines.size());
  for (const MoorDynPoint& p : deck.points)
    if (p.kind == MoorDynPointKind::Coupled && (p.mass != 0.0 || p.volume != 0.0 || p.dragArea != 0.0))
      notes.push_back(
          fmt::format("{}:{}: point {} is coupled and has a mass, volume or drag area: the host carries "
                      "them (tangle's force on the host is the lines' alone; MoorDyn adds the point's "
                      "weight, buoyancy, drag and inertia)",
                      deck.file, p.sourceLine, p.id));

  // A line end at point `pointId`; `bending` is the EI of the line's end section. Returns true when the end
  // is clamped to a fixed rod's axis (a `fixed` end: the line's start shape then leaves along that axis).
  const auto endBlock = [&](const char* key, int pointId, const std::string& lineName, int end,
                            double bending) {
    const MoorDynPoint& p = deck.points[static_cast<std::size_t>(pointId - 1)];
    MoorDynPointMap& m = out.points[static_cast<std::size_t>(pointId - 1)];
    m.ends.push_back({lineName, end});
    const bool rodEnd = static_cast<std::size_t>(pointId) > rodEnds.deckPoints;
    if (rodEnd && bending > 0.0 &&
        (p.kind != MoorDynPointKind::Fixed ||
         rodEnds.clampAxis[static_cast<std::size_t>(pointId - 1)].isZero()))
      notes.push_back(
          fmt::format("{}:{}: line {} (EI > 0) is pinned to {} (MoorDyn clamps a line with bending stiffness "
                      "to the rod's "
                      "axis; tangle's free and pinned rods carry no moment from their lines)",
                      deck.file, p.sourceLine, lineName, p.kindWord));
    switch (p.kind) {
      case MoorDynPointKind::Fixed: {
        const bool clamped =
            bending > 0.0 && !rodEnds.clampAxis[static_cast<std::size_t>(pointId - 1)].isZero();
        const bool onSeabed = p.position.z() <= -depth + 1e-9 * depth;
        line(fmt::format("    {}:", key));
        if (clamped)
          line(fmt::format(
              "      type: fixed             # {} (deck line {}): fixed rod, the line clamped to its axis",
              p.kindWord, p.sourceLine));
        else
          line(fmt::format("      type: {}          # {} {} (deck line {})", onSeabed ? "anchored" : "pinned",
                           rodEnd ? "" : fmt::format("point {}", p.id), p.kindWord, p.sourceLine));
        line(fmt::format("      position: {}", vec(p.position)));
        return clamped;
      }
      case MoorDynPointKind::Body:
        line(fmt::format(
            "    {}: {{type: vessel, vessel: body{}, position: {}}}   # {} (deck line {}) on body {}", key,
            p.body, vec(p.position), rodEnd ? p.kindWord : fmt::format("point {}", p.id), p.sourceLine,
            p.body));
        return false;
      case MoorDynPointKind::Coupled:
        line(fmt::format("    {}:", key));
        line(
            fmt::format("      type: pinned            # point {} {} (deck line {}): coupled, held here in a "
                        "standalone run, moved by the host through the C API or tangle.Coupling",
                        p.id, p.kindWord, p.sourceLine));
        line(fmt::format("      position: {}", vec(p.position)));
        break;
      case MoorDynPointKind::Free:
        if (isHub(pointId)) {
          if (carrier(pointId) != 0)
            line(fmt::format("    {}: {{type: point, point: {}}}   # {} (deck line {})", key,
                             pointName(pointId), p.kindWord, p.sourceLine));
          else
            line(fmt::format(
                "    {}: {{type: point, point: {}}}   # point {} free (deck line {}), joining {} lines", key,
                pointName(pointId), p.id, p.sourceLine,
                atPoint[static_cast<std::size_t>(pointId - 1)].size()));
          // The first line end at the point carries it (the Model's rule): its end node is the point.
          if (m.junctionLine.empty()) {
            m.junctionLine = lineName;
            m.junctionNode = end == 0 ? 0 : -2;  // -2: the last node, set when the line's segments are known
          }
          return false;
        }
        line(fmt::format("    {}:", key));
        line(fmt::format(
            "      type: free              # point {} {} (deck line {}): the position is the starting "
            "guess",
            p.id, p.kindWord, p.sourceLine));
        line(fmt::format("      position: {}", vec(p.position)));
        break;
    }
    return false;
  };
  const auto attachment = [&](const MoorDynPoint& p, double arcLength) {
    if (p.mass == 0.0 && p.volume == 0.0 && p.dragArea == 0.0) return;
    line(fmt::format("      - arc_length: {}        # point {} (deck line {})", num(arcLength), p.id,
                     p.sourceLine));
    line(fmt::format("        mass: {}", num(p.mass)));
    line(fmt::format("        volume: {}", num(p.volume)));
    line(fmt::format("        drag_area: {}        # CdA", num(p.dragArea)));
    line(fmt::format("        added_mass: {}       # Ca {} x rho x Volume",
                     num(p.addedMass * opt.density * p.volume), num(p.addedMass)));
  };

  // Free bodies: free vessels (submerged bodies: their weight and buoyancy act on them).
  bool anyVessel = false;
  for (std::size_t b = 0; b < deck.bodies.size(); ++b) {
    const BodyFrame& f = rodEnds.bodies[b];
    const MoorDynBody& body = deck.bodies[b];
    out.bodies.push_back({body.id, body.kind, f.free ? fmt::format("body{}", body.id) : std::string(),
                          f.origin, f.rotation, f.reference});
    if (!f.free) continue;
    if (!anyVessel) line("vessels:                         # MoorDyn's free bodies");
    anyVessel = true;
    line(fmt::format("  - name: body{}                 # body {} (deck line {}): {}", body.id, body.id,
                     body.sourceLine, body.kindWord));
    line("    mode: free");
    if (f.pinned)
      line(
          "    pinned: true               # CoupledPinned: its reference point held (moved by a host through "
          "the C API)");
    line(fmt::format("    position: {}   # {}", vec(f.reference),
                     f.pinned ? "the body's reference point, the pin"
                              : "the centre of gravity of the body and its points"));
    line(
        "    heading: 0                 # vessel axes = global axes at t = 0 (positions on it are turned by "
        "r0, p0, y0)");
    line(fmt::format("    mass: {}                   # Mass (and its points')", num(f.mass)));
    line(fmt::format("    inertia: {}   # I about the {} (and its points')", vec(f.inertia),
                     f.pinned ? "pin" : "centre of gravity"));
    line(fmt::format(
        "    displaced_volume: {}       # Volume (and its points'): weight and buoyancy act on it",
        num(f.volume)));
    if (!f.centreOfBuoyancy.isZero())
      line(fmt::format("    centre_of_buoyancy: {}", vec(f.centreOfBuoyancy)));
    line(fmt::format("    added_mass: [{}, {}, {}, 0, 0, 0]   # Ca rho Volume", num(f.addedMass.x()),
                     num(f.addedMass.y()), num(f.addedMass.z())));
    const auto& q = f.quadraticDamping;
    if (std::any_of(q.begin(), q.end(), [](double v) { return v != 0.0; }))
      line(fmt::format("    quadratic_damping: [{}, {}, {}, {}, {}, {}]   # 1/2 rho CdA", num(q[0]),
                       num(q[1]), num(q[2]), num(q[3]), num(q[4]), num(q[5])));
    if (std::any_of(q.begin(), q.end(), [](double v) { return v != 0.0; }) &&
        (opt.currentMode != 0 || opt.waveMode != 0))
      notes.push_back(
          fmt::format("body {}: its drag 1/2 rho CdA |v| v is on its own velocity in tangle, on its "
                      "velocity relative to the water in MoorDyn",
                      body.id));
  }
  if (anyVessel) line("");

  bool anyHub = false;
  for (const MoorDynPoint& p : deck.points) {
    if (!isHub(p.id)) continue;
    if (!anyHub)
      line("points:                          # free points joining three or more lines, moving rods' ends");
    anyHub = true;
    if (carrier(p.id) != 0)
      line(fmt::format("  - name: {}                # {} (deck line {}), where its lines join it",
                       pointName(p.id), p.kindWord, p.sourceLine));
    else
      line(fmt::format("  - name: {}                # point {} (deck line {})", pointName(p.id), p.id,
                       p.sourceLine));
    line(fmt::format("    position: {}", vec(p.position)));
    if (p.mass != 0.0) line(fmt::format("    mass: {}", num(p.mass)));
    if (p.volume != 0.0) {
      line(fmt::format("    volume: {}", num(p.volume)));
      line(fmt::format("    added_mass: {}       # Ca {} x rho x Volume",
                       num(p.addedMass * opt.density * p.volume), num(p.addedMass)));
    }
    if (p.dragArea != 0.0) line(fmt::format("    drag_area: {}        # CdA", num(p.dragArea)));
  }
  if (anyHub) line("");

  out.rods.resize(deck.rods.size());
  for (const MoorDynRod& rod : deck.rods) {
    MoorDynRodMap& m = out.rods[static_cast<std::size_t>(rod.id - 1)];
    m.deckId = rod.id;
    m.kind = rod.kind;
    if (rodEnds.movingRod[static_cast<std::size_t>(rod.id - 1)]) {
      m.tangleLine = fmt::format("rod{}", rod.id);
      m.segments = rod.segments;
    }
  }
  bool anyMovingRod = false;
  for (const bool moving : rodEnds.movingRod) anyMovingRod = anyMovingRod || moving;
  if (chains.empty() && !anyMovingRod)
    throw InputError(deck.file, deck.rods.empty() ? 0 : deck.rods.front().sourceLine, "RODS",
                     "nothing to model: the deck has no line and no rod that moves (fixed and coupled rods "
                     "hold lines; tangle models lines)");
  line("lines:");
  // Moving rods first: a rod's end node carries the tangle point where its lines join it (the Model's rule:
  // the first line end at a point in input order).
  const auto bendingOf = [&](const std::string& typeName) {
    const auto it = bendingOfType.find(typeName);
    return it != bendingOfType.end() ? it->second : 0.0;
  };
  for (const MoorDynRod& rod : deck.rods) {
    if (!rodEnds.movingRod[static_cast<std::size_t>(rod.id - 1)]) continue;
    const MoorDynRodType& t = rodTypeOf(deck, rod);
    const std::string name = fmt::format("rod{}", rod.id);
    const std::array<int, 2>& ends = rodEnds.endPoint[static_cast<std::size_t>(rod.id - 1)];
    line(fmt::format("  - name: {}                  # rod {} (deck line {}): {}, a stiff beam", name, rod.id,
                     rod.sourceLine, rod.kindWord));
    for (int end = 0; end < 2; ++end) {
      const char* key = end == 0 ? "end_a" : "end_b";
      const Vec3& at = end == 0 ? rod.endA : rod.endB;
      const int pointId = ends[static_cast<std::size_t>(end)];
      const bool pinned =
          end == 0 && (rod.kind == MoorDynRodKind::Pinned || rod.kind == MoorDynRodKind::CoupledPinned);
      if (rod.body != 0 && (pinned || rod.kind == MoorDynRodKind::Fixed)) {
        line(fmt::format(
            "    {}: {{type: vessel, vessel: body{}, position: {}}}   # {} on body {}", key, rod.body,
            vec(rodEnds.rodOffset[static_cast<std::size_t>(rod.id - 1)][static_cast<std::size_t>(end)]),
            rod.kindWord, rod.body));
      } else if (pinned) {
        line(fmt::format("    {}: {{type: pinned, position: {}}}   # {}: end A held, free to rotate", key,
                         vec(at), rod.kindWord));
      } else if (pointId != 0) {
        line(fmt::format("    {}: {{type: point, point: {}}}   # where its lines join it", key,
                         pointName(pointId)));
        MoorDynPointMap& m = out.points[static_cast<std::size_t>(pointId - 1)];
        m.ends.push_back({name, end});
        m.junctionLine = name;
        m.junctionNode = end == 0 ? 0 : rod.segments;
      } else {
        line(fmt::format("    {}: {{type: free, position: {}}}", key, vec(at)));
      }
    }
    line("    sections:");
    line(fmt::format("      - {{type: {}, length: {}, elements: {}}}   # the rod's length and NumSegs",
                     yamlQuoted("rod-" + t.name), num(rod.length()), rod.segments));
    // MoorDyn's end effects (Rod.cpp): axial drag CdEnd on pi/4 d^2 and added mass CaEnd rho 2/3 pi (d/2)^3
    // at each end; tangle's attachments act in every direction (MoorDyn's along the axis only).
    const double endDrag = t.dragEnd * circleArea(t.diameter);
    const double endAdded =
        t.addedMassEnd * opt.density * 2.0 / 3.0 * std::numbers::pi * std::pow(t.diameter / 2.0, 3);
    if (endDrag > 0.0 || endAdded > 0.0) {
      line(
          "    attachments:                # end effects: CdEnd pi/4 d^2, CaEnd rho 2/3 pi (d/2)^3 at each "
          "end");
      for (const double arc : {0.0, rod.length()})
        line(fmt::format("      - {{arc_length: {}, drag_area: {}, added_mass: {}}}", num(arc), num(endDrag),
                         num(endAdded)));
      notes.push_back(
          fmt::format("{}:{}: rod {}'s end drag and added mass (CdEnd, CaEnd) act in every direction in "
                      "tangle, along the rod's axis in MoorDyn",
                      deck.file, rod.sourceLine, rod.id));
    }
  }
  for (std::size_t chainIndex = 0; chainIndex < chains.size(); ++chainIndex) {
    const std::vector<ChainEntry>& chain = chains[chainIndex];
    std::string name;
    for (const ChainEntry& c : chain)
      name +=
          (name.empty() ? "line" : "-line") + std::to_string(deck.lines[static_cast<std::size_t>(c.line)].id);
    const ChainEntry& head = chain.front();
    const ChainEntry& tail = chain.back();
    const int startPoint = pointAt(head.line, head.reversed ? 1 : 0);
    const int endPoint = pointAt(tail.line, tail.reversed ? 0 : 1);
    std::string sources;
    for (const ChainEntry& c : chain)
      sources += fmt::format("{}{}", sources.empty() ? "" : ", ",
                             deck.lines[static_cast<std::size_t>(c.line)].sourceLine);
    line(fmt::format("  - name: {}                  # deck line{} {}{}", name, chain.size() > 1 ? "s" : "",
                     sources, chain.size() > 1 ? " (joined in series at free points)" : ""));
    const MoorDynLine& headLine = deck.lines[static_cast<std::size_t>(head.line)];
    const MoorDynLine& tailLine = deck.lines[static_cast<std::size_t>(tail.line)];
    const bool clampA = endBlock("end_a", startPoint, name, 0, bendingOf(headLine.lineType));
    const bool clampB = endBlock("end_b", endPoint, name, 1, bendingOf(tailLine.lineType));
    if (const auto f = failureOfChain.find(chainIndex); f != failureOfChain.end()) line(f->second);
    {
      // MoorDyn starts a line between any two points; tangle refuses ends more than 1.2 x the line's length
      // apart (a units mistake, usually) unless told: a deck that starts a line that stretched (a rope's
      // constitutive test) says so.
      double length = 0.0;
      for (const ChainEntry& c : chain) length += deck.lines[static_cast<std::size_t>(c.line)].length;
      const auto located = [&](int id) -> const MoorDynPoint* {
        if (id <= 0) return nullptr;
        const MoorDynPoint& p = deck.points[static_cast<std::size_t>(id - 1)];
        return p.kind == MoorDynPointKind::Body ? nullptr : &p;
      };
      const MoorDynPoint* a = located(startPoint);
      const MoorDynPoint* b = located(endPoint);
      if (a && b && (b->position - a->position).norm() > 1.2 * length) {
        const double stretch = (b->position - a->position).norm() / length - 1.0;
        line(
            fmt::format("    span_check: false         # its ends are {:.0f} % farther apart than its length",
                        100.0 * stretch));
        notes.push_back(
            fmt::format("line {}: starts stretched {:.0f} % (its points' distance against its "
                        "UnstrLen); accepted, as MoorDyn does",
                        name, 100.0 * stretch));
      }
    }
    line("    sections:");
    int node = 0;
    double arc = 0.0;
    std::vector<std::pair<int, double>> junctions;  // (point id, arc length)
    for (std::size_t k = 0; k < chain.size(); ++k) {
      const MoorDynLine& dl = deck.lines[static_cast<std::size_t>(chain[k].line)];
      line(fmt::format("      - {{type: {}, length: {}, elements: {}}}   # line {}: UnstrLen, NumSegs{}",
                       yamlQuoted(typeOfLine[static_cast<std::size_t>(chain[k].line)]), num(dl.length), dl.segments,
                       dl.id, chain[k].reversed ? " (its end A is at the far end)" : ""));
      MoorDynLineMap& map = out.lines[static_cast<std::size_t>(chain[k].line)];
      map.deckId = dl.id;
      map.tangleLine = name;
      map.segments = dl.segments;
      map.reversed = chain[k].reversed;
      map.firstNode = chain[k].reversed ? node + dl.segments : node;
      node += dl.segments;
      arc += dl.length;
      if (k + 1 < chain.size()) {
        const int p = pointAt(chain[k].line, chain[k].reversed ? 0 : 1);
        junctions.push_back({p, arc});
        MoorDynPointMap& m = out.points[static_cast<std::size_t>(p - 1)];
        m.junctionLine = name;
        m.junctionNode = node;
      }
    }
    const MoorDynPoint& first = deck.points[static_cast<std::size_t>(startPoint - 1)];
    const MoorDynPoint& last = deck.points[static_cast<std::size_t>(endPoint - 1)];
    // A hub's body is its point's (the `points` block), not an attachment.
    const bool startMass = first.kind == MoorDynPointKind::Free && !isHub(startPoint) &&
                           (first.mass != 0.0 || first.volume != 0.0 || first.dragArea != 0.0);
    const bool endMass = last.kind == MoorDynPointKind::Free && !isHub(endPoint) &&
                         (last.mass != 0.0 || last.volume != 0.0 || last.dragArea != 0.0);
    MoorDynPointMap& endMap = out.points[static_cast<std::size_t>(endPoint - 1)];
    if (endMap.junctionLine == name && endMap.junctionNode == -2) endMap.junctionNode = node;
    bool junctionMass = false;
    for (const auto& [p, s] : junctions) {
      const MoorDynPoint& jp = deck.points[static_cast<std::size_t>(p - 1)];
      junctionMass = junctionMass || jp.mass != 0.0 || jp.volume != 0.0 || jp.dragArea != 0.0;
    }
    if (startMass || endMass || junctionMass) {
      line("    attachments:                # free points' mass, volume, drag and added mass");
      if (startMass) attachment(first, 0.0);
      for (const auto& [p, s] : junctions) attachment(deck.points[static_cast<std::size_t>(p - 1)], s);
      if (endMass) attachment(last, arc);
    }
    if (!junctions.empty() || clampA || clampB) {
      line("    start_shape:                # the free points' positions in the deck, as the starting shape");
      // A line clamped to a fixed rod leaves along the rod's axis: its first element starts along it.
      if (clampA) {
        const double h = headLine.length / headLine.segments;
        line(fmt::format("      - {{position: {}, arc_length: {}}}   # one element along the rod's axis",
                         vec(deck.points[static_cast<std::size_t>(startPoint - 1)].position +
                             h * rodEnds.clampAxis[static_cast<std::size_t>(startPoint - 1)]),
                         num(h)));
      }
      for (const auto& [p, s] : junctions)
        line(fmt::format("      - {{position: {}, arc_length: {}}}   # point {} (deck line {})",
                         vec(deck.points[static_cast<std::size_t>(p - 1)].position), num(s), p,
                         pointLine(p)));
      if (clampB) {
        const double h = tailLine.length / tailLine.segments;
        line(fmt::format("      - {{position: {}, arc_length: {}}}   # one element along the rod's axis",
                         vec(deck.points[static_cast<std::size_t>(endPoint - 1)].position +
                             h * rodEnds.clampAxis[static_cast<std::size_t>(endPoint - 1)]),
                         num(arc - h)));
      }
    }
  }
  line("");

  // A free rod that no line holds has no static equilibrium (it sinks or rises, and drifts): start from the
  // deck's positions at rest, as MoorDyn does without its initial-condition solve (TmaxIC = 0).
  std::string unheld;
  for (const MoorDynRod& rod : deck.rods) {
    const std::array<int, 2>& ends = rodEnds.endPoint[static_cast<std::size_t>(rod.id - 1)];
    if (rod.kind == MoorDynRodKind::Free && rod.body == 0 && ends[0] == 0 && ends[1] == 0)
      unheld += fmt::format("{}rod {}", unheld.empty() ? "" : ", ", rod.id);
  }
  for (std::size_t b = 0; b < deck.bodies.size(); ++b)
    if (rodEnds.bodies[b].free && !rodEnds.bodies[b].pinned && !rodEnds.bodies[b].held)
      unheld += fmt::format("{}body {}", unheld.empty() ? "" : ", ", b + 1);
  if (!unheld.empty()) {
    line("statics:");
    line(fmt::format(
        "  method: none                  # free {} held by no line: no static equilibrium; the dynamics "
        "starts from the deck's positions at rest",
        unheld));
    line("");
    notes.push_back(
        fmt::format("free {} held by no line: no static solve (statics.method: none); the run starts "
                    "from the deck's positions at rest",
                    unheld));
  }

  // Dynamics: MoorDyn has no duration of its own (the host decides): a standalone run is the statics, the
  // initial conditions. The step is tangle's own (implicit), never below 0.01 s for dtM's explicit limit, or
  // the deck's tangleTimeStep.
  const double step = opt.tangleStep ? *opt.tangleStep : std::max(opt.timeStep, 0.01);
  line("dynamics:");
  line(
      "  duration: 0                   # MoorDyn decks have no duration (the host program sets it): statics "
      "only;");
  line(
      "                                # give a duration and a motion of the coupled ends to run dynamics "
      "here");
  line(fmt::format("  time_step: {}                # {}", num(step),
                   opt.tangleStep ? fmt::format("the deck's tangleTimeStep (dtM = {} s)", num(opt.timeStep))
                                  : fmt::format("tangle's implicit step (dtM = {} s is an explicit scheme's "
                                                "stability limit; a host's smaller step is used as given)",
                                                num(opt.timeStep))));
  // The Newton tolerance of a model of cables only (no line type with EI, no moving rod, no free body):
  // 1e-5 of each line's weight, between the 1e-4 docs/model-format.md recommends for cable moorings at dt
  // 0.05 s and tangle's default 1e-6 (kept for beams and bodies, as for risers). A host may step at
  // 0.002 s, where 1e-4's latitude on the tension range is as large as the coupling's own difference
  // (docs/moordyn.md, OPTIONS).
  const bool cablesOnly =
      !anyVessel &&
      std::none_of(rodEnds.movingRod.begin(), rodEnds.movingRod.end(), [](bool moving) { return moving; }) &&
      std::none_of(deck.lines.begin(), deck.lines.end(),
                   [&](const MoorDynLine& l) { return bendingOf(l.lineType) > 0.0; });
  if (opt.tolerance)
    line(fmt::format("  tolerance: {}             # the deck's tangleTolerance", num(*opt.tolerance)));
  else if (cablesOnly)
    line("  tolerance: 1.0e-5             # cables only (docs/moordyn.md, OPTIONS)");
  line("  ramp_time: 0                  # MoorDyn ramps nothing");
  line("  mass: lumped                  # as MoorDyn");
  line("");
  line("output:");
  line("  plots: false");
  if (!deck.outputs.empty()) {
    std::string channels;
    for (const std::string& c : deck.outputs) channels += (channels.empty() ? "" : " ") + c;
    line(fmt::format("# MoorDyn OUTPUTS: {}", channels));
    line(
        "# tangle writes end forces (FairTen = end B, AnchTen = end A), tensions and positions at every node "
        "instead");
    line("# (dynamics/end_forces.csv, results.h5; docs/moordyn.md, output channels).");
  }
  if (!notes.empty()) {
    y += "\n# Differences from MoorDyn for this deck:\n";
    for (const std::string& n : notes) y += "#  - " + n + "\n";
  }
  // The maps keep the deck's own points (a rod's ends are in `rods`).
  for (const MoorDynRod& rod : deck.rods) {
    MoorDynRodMap& m = out.rods[static_cast<std::size_t>(rod.id - 1)];
    const int pointId = rodEnds.endPoint[static_cast<std::size_t>(rod.id - 1)][0];
    if (rod.length() == 0.0 && pointId != 0) m.point = out.points[static_cast<std::size_t>(pointId - 1)];
    m.point.position = rod.endA;
    for (std::size_t end = 0; end < 2; ++end) {
      const int id = rodEnds.endPoint[static_cast<std::size_t>(rod.id - 1)][end];
      if (id != 0) m.endLines[end] = out.points[static_cast<std::size_t>(id - 1)].ends;
    }
    if (!m.tangleLine.empty() &&
        (rod.kind == MoorDynRodKind::Pinned || rod.kind == MoorDynRodKind::CoupledPinned) && rod.body == 0)
      m.endLines[0].insert(m.endLines[0].begin(), {m.tangleLine, 0});
  }
  out.points.resize(rodEnds.deckPoints);
  out.yaml = std::move(y);
  return out;
}

}  // namespace tangle::io
