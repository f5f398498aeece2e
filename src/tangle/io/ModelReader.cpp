/// @file ModelReader.cpp
/// YAML model reader. Two layers:
///  - a small checked-access layer (Range, Value, Map) that knows about key paths, line numbers,
///    unknown/duplicate/missing keys and value checks, so every error message is uniform;
///  - one reader function per block of the format, registered in kTopLevelBlocks. Adding a top-level
///    block (e.g. `contact:` or `vessels:`) is one function plus one row of that table.

#include "tangle/io/ModelReader.hpp"

#include <fmt/format.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "tangle/analysis/SnCurve.hpp"
#include "tangle/core/Error.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/element/SyropeAxialLaw.hpp"
#include "tangle/hydro/CurrentGrid.hpp"
#include "tangle/io/MoorDynConversion.hpp"
#include "tangle/model/PrescribedMotion.hpp"

namespace tangle::io {

namespace {

using model::ModelSpec;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// Tolerance of the "end below the seabed" check [m].
constexpr double kSeabedTolerance = 1.0e-9;
/// Largest accepted ratio of the end-to-end distance to the unstretched line length [-]: beyond it the
/// geometry is taken as a mistake (a taut line stretched by a few percent is fine).
constexpr double kMaxEndSpanOverLength = 1.2;

// Physical bounds (issue 13): values beyond them are typing or unit mistakes that otherwise end deep in
// the solver (tensions of 1e284 N, internal errors). Generous: an order of magnitude beyond any real
// offshore line or vessel.
constexpr double kMaxCoordinate = 1.0e5;        ///< |x|, |y|, |z| of any position [m] (100 km)
constexpr double kMaxWaterDepth = 12000.0;      ///< deeper than the deepest trench [m]
constexpr double kMaxLineLength = 1.0e5;        ///< one section [m]
constexpr double kMaxDiameter = 20.0;           ///< [m]; above kPlausibleDiameter only a warning
constexpr double kPlausibleDiameter = 5.0;      ///< larger diameters are likely inches or mm [m] (an LMRP or a buoyancy can may reach 4-5 m)
constexpr double kMaxMassPerLength = 1.0e5;     ///< [kg/m]
constexpr double kMaxStiffness = 1.0e13;        ///< EA [N], EI [N m^2], GJ [N m^2/rad]
constexpr double kMaxCoefficient = 20.0;        ///< drag and added-mass coefficients [-]
constexpr double kMaxSpeed = 50.0;              ///< current and wind speeds [m/s]
constexpr double kMaxWaveHeight = 50.0;         ///< H and Hs [m]
constexpr double kMaxWavePeriod = 100.0;        ///< T and Tp [s]
constexpr int kMaxWaveComponents = 10000;       ///< JONSWAP components [-]
constexpr double kMaxDuration = 1.0e6;          ///< dynamic duration [s]
constexpr double kMaxMass = 1.0e10;             ///< vessel and attachment masses [kg]
constexpr double kMaxContentsDensity = 25000.0; ///< densest contents (drilling mud ~2500, mercury 13 500) [kg/m^3]
constexpr double kMaxPressure = 2.0e9;          ///< internal pressure (2000 MPa, beyond any bore) [Pa]
constexpr double kVacuum = -101325.0;           ///< gauge pressure of a vacuum [Pa]
/// Most elements accepted in one model, and the memory each needs for the message: measured 3.4 kB per
/// bar element (peak resident memory of `tangle run --statics-only` on a 20000-element cable model minus
/// that of a 2-element one); 6 kB allows for beams (6 DOFs per node) and the dynamic state.
constexpr long kMaxElements = 500000;
constexpr double kBytesPerElement = 6.0e3;

// =====================================================================================================
// Checked access layer
// =====================================================================================================

/// A number as written in messages: shortest form that reads back exactly (fmt's default).
std::string numberText(double v) { return fmt::format("{}", v); }

/// A computed number as written in messages (6 significant digits).
std::string roundedText(double v) { return fmt::format("{:.6g}", v); }

std::string join(const std::vector<std::string>& items, std::string_view separator = ", ") {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out += separator;
    out += items[i];
  }
  return out;
}

std::string toLower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

/// Levenshtein distance, for "did you mean" suggestions on misspelt keys.
std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

/// 1-based line of a node, or `fallback` when yaml-cpp has no position for it.
int lineOf(const YAML::Node& node, int fallback) {
  const YAML::Mark mark = node.Mark();
  return mark.is_null() ? fallback : mark.line + 1;
}

/// Allowed interval of a number read from the file, with its wording in messages.
struct Range {
  double lo = -kInfinity;
  double hi = kInfinity;
  bool loOpen = false;  ///< lo itself is excluded
  bool hiOpen = false;  ///< hi itself is excluded
  std::string hint;     ///< extra explanation appended to messages, e.g. "at least time_step"
  bool sanityCap = false;  ///< hi is a physical plausibility cap: described as "> lo and <= hi"

  bool contains(double v) const { return (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi); }

  /// " > 0", " >= 0", " in [0, 1]", " <= 0", or "" for any finite number.
  std::string describe() const {
    const bool hasLo = lo > -kInfinity;
    const bool hasHi = hi < kInfinity;
    if (hasLo && hasHi && sanityCap)
      return fmt::format(" {} {} and {} {}", loOpen ? ">" : ">=", numberText(lo), hiOpen ? "<" : "<=",
                         numberText(hi));
    if (hasLo && hasHi)
      return fmt::format(" in {}{}, {}{}", loOpen ? "(" : "[", numberText(lo), numberText(hi),
                         hiOpen ? ")" : "]");
    if (hasLo) return fmt::format(" {} {}", loOpen ? ">" : ">=", numberText(lo));
    if (hasHi) return fmt::format(" {} {}", hiOpen ? "<" : "<=", numberText(hi));
    return "";
  }

  Range withHint(std::string text) const {
    Range r = *this;
    r.hint = std::move(text);
    return r;
  }
};

Range anyNumber() { return {}; }
Range positive() { return {0.0, kInfinity, true, false, {}}; }
Range nonNegative() { return {0.0, kInfinity, false, false, {}}; }
Range atLeast(double lo) { return {lo, kInfinity, false, false, {}}; }
Range atMost(double hi) { return {-kInfinity, hi, false, false, {}}; }
Range closed(double lo, double hi) { return {lo, hi, false, false, {}}; }
/// (0, hi]: a positive physical value with an upper bound.
Range positiveUpTo(double hi) { return {0.0, hi, true, false, {}, true}; }
/// [0, hi].
Range nonNegativeUpTo(double hi) { return {0.0, hi, false, false, {}, true}; }
/// [lo, hi] with hi a plausibility cap.
Range atLeastUpTo(double lo, double hi) { return {lo, hi, false, false, {}, true}; }

/// What a number must be, for messages: "a number > 0 (at least time_step)".
std::string numberExpectation(std::string_view noun, const Range& range) {
  std::string s = std::string(noun) + range.describe();
  if (!range.hint.empty()) s += " (" + range.hint + ")";
  return s;
}

/// How to label the items of a list in key paths.
enum class ItemLabel {
  Index,  ///< lines[0]
  Name    ///< lines[mooring1] when the item has a `name`, else the index
};

/// A YAML node with its key path and line, and checked conversions that throw InputError.
class Value {
 public:
  Value(const std::string& source, YAML::Node node, std::string path, int line)
      : m_source(&source), m_node(std::move(node)), m_path(std::move(path)), m_line(line) {}

  const YAML::Node& node() const { return m_node; }
  const std::string& path() const { return m_path; }  ///< key path, e.g. "lines[mooring1].end_a"
  int line() const { return m_line; }                 ///< 1-based line of the key (or list item)
  const std::string& source() const { return *m_source; }

  /// Throws an InputError at this value.
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(*m_source, m_line, m_path, message);
  }
  /// Throws "expected <what>, got <this value>".
  [[noreturn]] void expected(const std::string& what) const {
    fail("expected " + what + ", got " + describe());
  }

  /// How the value appears in the file, for "got ..." in messages.
  std::string describe() const {
    switch (m_node.Type()) {
      case YAML::NodeType::Null:
      case YAML::NodeType::Undefined:
        return "nothing (empty value)";
      case YAML::NodeType::Sequence:
        return fmt::format("a list of {} item{}", m_node.size(), m_node.size() == 1 ? "" : "s");
      case YAML::NodeType::Map:
        return "a map";
      case YAML::NodeType::Scalar:
        break;
    }
    std::string text = m_node.Scalar();
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    if (isPlain()) return text;
    return "\"" + text + "\" (a quoted string)";
  }

  /// A plain (unquoted, untagged) scalar: the only kind read as a number or a boolean.
  bool isSequence() const { return m_node.IsSequence(); }
  bool isPlain() const {
    if (!m_node.IsScalar()) return false;
    const std::string& tag = m_node.Tag();
    return tag == "?" || tag == "tag:yaml.org,2002:float" || tag == "tag:yaml.org,2002:int";
  }

  /// A finite number in `range`.
  double number(const Range& range = {}) const {
    const std::optional<double> v = parsedNumber();
    if (!v || !range.contains(*v)) expected(numberExpectation("a number", range));
    return *v;
  }

  /// An integer in `range` that fits an int.
  int integer(const Range& range) const {
    const long long v = integer64(range);
    if (v < INT_MIN || v > INT_MAX)
      expected(numberExpectation("an integer", range) + " that fits in 32 bits");
    return static_cast<int>(v);
  }

  /// An integer in `range` (exactly representable: |v| <= 2^53).
  long long integer64(const Range& range) const {
    const std::optional<double> v = parsedNumber();
    if (!v || std::floor(*v) != *v || std::abs(*v) > 9007199254740992.0 || !range.contains(*v))
      expected(numberExpectation("an integer", range));
    return static_cast<long long>(*v);
  }

  /// true/false (yes/no accepted too, any letter case). Numbers and quoted strings are refused.
  bool boolean() const {
    if (isPlain()) {
      const std::string s = toLower(m_node.Scalar());
      if (s == "true" || s == "yes") return true;
      if (s == "false" || s == "no") return false;
    }
    expected("true or false");
  }

  /// A non-empty scalar (names, titles); `what` describes it in messages, e.g. "a name".
  std::string text(std::string_view what) const {
    if (!m_node.IsScalar() || m_node.Scalar().empty()) expected(std::string(what));
    return m_node.Scalar();
  }

  /// One of a fixed set of words (compared case-insensitively).
  template <typename E>
  E choice(std::initializer_list<std::pair<std::string_view, E>> options) const {
    std::vector<std::string> words;
    for (const auto& [word, value] : options) words.emplace_back(word);
    if (m_node.IsScalar()) {
      const std::string s = toLower(m_node.Scalar());
      for (const auto& [word, value] : options)
        if (s == word) return value;
    }
    expected("one of: " + join(words));
  }

  /// The items of a list, with at least `minCount` items.
  std::vector<Value> items(std::size_t minCount, ItemLabel label = ItemLabel::Index) const {
    if (!m_node.IsSequence()) expected(minCount > 0 ? "a list (at least one item)" : "a list");
    if (m_node.size() < minCount)
      fail(fmt::format("expected a list of at least {} item{}, got {}", minCount, minCount == 1 ? "" : "s",
                       describe()));
    std::vector<Value> out;
    out.reserve(m_node.size());
    for (std::size_t i = 0; i < m_node.size(); ++i) {
      const YAML::Node item = m_node[i];
      std::string tag = std::to_string(i);
      if (label == ItemLabel::Name && item.IsMap()) {
        const YAML::Node name = item["name"];
        if (name && name.IsScalar() && !name.Scalar().empty()) tag = name.Scalar();
      }
      out.emplace_back(*m_source, item, fmt::format("{}[{}]", m_path, tag), lineOf(item, m_line));
    }
    return out;
  }

  /// A list of exactly `count` numbers; `shape` names them in messages, e.g. "[x, y, z]".
  std::vector<double> numbers(std::size_t count, std::string_view shape) const {
    const std::string what = fmt::format("a list of {} numbers {}", count, shape);
    if (!m_node.IsSequence() || m_node.size() != count) expected(what);
    std::vector<double> out;
    for (std::size_t i = 0; i < count; ++i) {
      const Value item(*m_source, m_node[i], fmt::format("{}[{}]", m_path, i), lineOf(m_node[i], m_line));
      const std::optional<double> v = item.parsedNumber();
      if (!v) item.fail(fmt::format("expected {}; item {} is {}", what, i, item.describe()));
      out.push_back(*v);
    }
    return out;
  }

  /// A vector [x, y, z].
  Vec3 vec3() const {
    const std::vector<double> v = numbers(3, "[x, y, z]");
    return Vec3(v[0], v[1], v[2]);
  }

  /// A position [x, y, z], each coordinate within +-kMaxCoordinate.
  Vec3 position() const {
    const std::vector<double> v = numbers(3, "[x, y, z]");
    for (std::size_t i = 0; i < 3; ++i)
      if (std::abs(v[i]) > kMaxCoordinate)
        fail(fmt::format("item {} is {}; expected coordinates within +-{} m", i, numberText(v[i]),
                         numberText(kMaxCoordinate)));
    return Vec3(v[0], v[1], v[2]);
  }

  /// "file:line: key 'path': " prefix for warnings about this value.
  std::string where() const { return InputError(*m_source, m_line, m_path, "").what(); }

 private:
  /// The number a plain scalar spells, if it spells a finite one (strict: the whole text must be a number).
  std::optional<double> parsedNumber() const {
    if (!isPlain()) return std::nullopt;
    std::string_view s = m_node.Scalar();
    if (!s.empty() && s.front() == '+') {
      s.remove_prefix(1);
      if (!s.empty() && (s.front() == '+' || s.front() == '-')) return std::nullopt;
    }
    double v = 0.0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
    return v;
  }

  const std::string* m_source;
  YAML::Node m_node;
  std::string m_path;
  int m_line;
};

/// A YAML map whose keys have been checked: every key is one of `allowed` and appears once. A missing
/// or empty block (`seabed:` with nothing after it) reads as an empty map, so all its defaults apply.
class Map {
 public:
  Map(const Value& value, std::vector<std::string> allowed) : m_value(value), m_allowed(std::move(allowed)) {
    const YAML::Node& node = value.node();
    if (node.IsNull()) return;
    if (!node.IsMap()) value.expected("a map with keys: " + join(m_allowed));
    for (auto it = node.begin(); it != node.end(); ++it) {
      const int line = lineOf(it->first, value.line());
      if (!it->first.IsScalar())
        throw InputError(value.source(), line, value.path(), "expected a plain key here");
      const std::string key = it->first.Scalar();
      const std::string path = childPath(key);
      if (std::find(m_allowed.begin(), m_allowed.end(), key) == m_allowed.end()) {
        std::string message = fmt::format("unknown key '{}'; expected one of: {}", key, join(m_allowed));
        if (const std::optional<std::string> guess = closest(key))
          message += "; did you mean '" + *guess + "'?";
        throw InputError(value.source(), line, path, message);
      }
      for (const Entry& e : m_entries)
        if (e.key == key)
          throw InputError(value.source(), line, path,
                           fmt::format("key '{}' is given twice (first at line {})", key, e.line));
      m_entries.push_back({key, it->second, line});
    }
  }

  const Value& value() const { return m_value; }

  /// The value of `key`, if given.
  std::optional<Value> find(std::string_view key) const {
    for (const Entry& e : m_entries)
      if (e.key == key) return Value(m_value.source(), e.node, childPath(e.key), e.line);
    return std::nullopt;
  }

  /// The value of a required key; `expectation` says what it should be, for the "missing" message.
  Value get(std::string_view key, std::string_view expectation) const {
    if (std::optional<Value> v = find(key)) return *v;
    missing(key, expectation);
  }

  [[noreturn]] void missing(std::string_view key, std::string_view expectation) const {
    throw InputError(m_value.source(), m_value.line(), childPath(key),
                     fmt::format("missing required key '{}'; expected {}", key, expectation));
  }

  /// Required number in `range`.
  double number(std::string_view key, const Range& range) const {
    return get(key, numberExpectation("a number", range)).number(range);
  }
  /// Optional number in `range`, `fallback` when absent.
  double number(std::string_view key, double fallback, const Range& range) const {
    const std::optional<Value> v = find(key);
    return v ? v->number(range) : fallback;
  }
  /// Optional angle given in degrees, returned in radians.
  double angle(std::string_view key, double fallbackRadians) const {
    const std::optional<Value> v = find(key);
    return v ? degToRad(v->number(anyNumber())) : fallbackRadians;
  }
  /// Optional integer in `range`, `fallback` when absent.
  int integer(std::string_view key, int fallback, const Range& range) const {
    const std::optional<Value> v = find(key);
    return v ? v->integer(range) : fallback;
  }
  /// Optional boolean, `fallback` when absent.
  bool boolean(std::string_view key, bool fallback) const {
    const std::optional<Value> v = find(key);
    return v ? v->boolean() : fallback;
  }

 private:
  struct Entry {
    std::string key;
    YAML::Node node;
    int line;
  };

  std::string childPath(std::string_view key) const {
    return m_value.path().empty() ? std::string(key) : m_value.path() + "." + std::string(key);
  }

  /// The allowed key closest to a misspelt one, when close enough to be a likely typo.
  std::optional<std::string> closest(const std::string& key) const {
    std::optional<std::string> best;
    std::size_t bestDistance = std::max<std::size_t>(2, key.size() / 3) + 1;
    for (const std::string& candidate : m_allowed) {
      const std::size_t d = editDistance(toLower(key), candidate);
      if (d < bestDistance) {
        bestDistance = d;
        best = candidate;
      }
    }
    return best;
  }

  Value m_value;
  std::vector<std::string> m_allowed;
  std::vector<Entry> m_entries;
};

/// Remembers the names given in a list, to report duplicates with the line of the first one.
class NameRegistry {
 public:
  explicit NameRegistry(std::string what) : m_what(std::move(what)) {}
  /// Reads the `name` key of `m` and checks it is new.
  std::string add(const Map& m) {
    const Value v = m.get("name", "a name (unique among the " + m_what + "s)");
    std::string name = v.text("a name");
    const auto [it, inserted] = m_lines.emplace(name, v.line());
    if (!inserted)
      v.fail(fmt::format("duplicate {} name '{}' (first defined at line {}); names must be unique", m_what,
                         name, it->second));
    return name;
  }

 private:
  std::string m_what;
  std::map<std::string, int> m_lines;
};

// =====================================================================================================
// Block readers
// =====================================================================================================

void readTitle(const Value& v, ModelSpec& spec) { spec.title = v.text("a title (text)"); }

/// The seabed's shape: `slope` with `upslope_azimuth`, or `bathymetry` (a grid {x, y, depth}, or {file} in
/// MoorDyn's SeafloorFile format); null for a flat seabed.
std::shared_ptr<const seabed::SeabedSurface> readSeabedShape(const Map& m, double waterDepth) {
  const std::optional<Value> slope = m.find("slope");
  const std::optional<Value> azimuth = m.find("upslope_azimuth");
  const std::optional<Value> bathymetry = m.find("bathymetry");
  if (slope && bathymetry) bathymetry->fail("give either slope (a plane) or bathymetry (a grid), not both");
  if (azimuth && !slope) azimuth->fail("upslope_azimuth applies to a sloping seabed: add slope (degrees)");
  if (slope) {
    const double angle = slope->number(closed(0.0, 60.0).withHint("degrees, from 0 (flat) to 60"));
    if (angle == 0.0) return nullptr;
    if (!azimuth)
      slope->fail(
          "a sloping seabed needs upslope_azimuth: the direction in which it rises [deg], "
          "anticlockwise from +x");
    return std::make_shared<const seabed::SeabedSurface>(
        seabed::SeabedSurface::plane(waterDepth, degToRad(angle), degToRad(azimuth->number(anyNumber()))));
  }
  if (!bathymetry) return nullptr;
  const Map b(*bathymetry, {"x", "y", "depth", "file", "interpolation"});
  // Between the nodes: bicubic by default (a C1 surface: no crease at the cells' edges for a line laid along
  // one); bilinear as MoorDyn (a converted deck says so).
  seabed::SeabedSurface::Interpolation interpolation = seabed::SeabedSurface::Interpolation::Cubic;
  if (const std::optional<Value> i = b.find("interpolation"))
    interpolation = i->choice<seabed::SeabedSurface::Interpolation>(
        {{"cubic", seabed::SeabedSurface::Interpolation::Cubic},
         {"bilinear", seabed::SeabedSurface::Interpolation::Bilinear}});
  if (const std::optional<Value> file = b.find("file")) {
    for (const char* key : {"x", "y", "depth"})
      if (const std::optional<Value> other = b.find(key))
        other->fail("give either a file or the grid {x, y, depth}, not both");
    namespace fs = std::filesystem;
    fs::path path(file->text("a file name (MoorDyn's SeafloorFile format), relative to the model file"));
    if (path.is_relative()) path = fs::path(bathymetry->source()).parent_path() / path;
    try {
      return std::make_shared<const seabed::SeabedSurface>(
          seabed::readSeafloorFile(path.string()).interpolated(interpolation));
    } catch (const InputError& e) {
      file->fail(fmt::format("cannot read the bathymetry: {}", e.what()));
    }
  }
  auto ticks = [&](const char* key) {
    const Value t = b.get(key, "a list of increasing coordinates [m]");
    if (!t.isSequence() || t.node().size() == 0) t.expected("a non-empty list of increasing coordinates [m]");
    const std::vector<double> out = t.numbers(t.node().size(), "[m]");
    for (std::size_t i = 0; i < out.size(); ++i) {
      if (std::abs(out[i]) > kMaxCoordinate)
        t.fail(fmt::format("item {} is {}; expected coordinates within +-{} m", i, numberText(out[i]),
                           numberText(kMaxCoordinate)));
      if (i > 0 && !(out[i] > out[i - 1]))
        t.fail(fmt::format("the coordinates must increase: item {} ({}) follows {}", i, numberText(out[i]),
                           numberText(out[i - 1])));
    }
    return out;
  };
  std::vector<double> x = ticks("x"), y = ticks("y");
  const Value depth = b.get("depth", "a list of rows, one per y, each with one depth [m] per x");
  if (!depth.isSequence() || depth.node().size() != y.size())
    depth.expected(fmt::format("a list of {} rows (one per y), each with {} depths [m] (one per x)", y.size(),
                               x.size()));
  std::vector<double> height;
  for (const Value& row : depth.items(1)) {
    const std::vector<double> values = row.numbers(x.size(), "(one depth [m] per x)");
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (!(values[i] > 0.0 && values[i] <= kMaxWaterDepth))
        row.fail(fmt::format("item {} is {}; expected a depth > 0 and <= {} m (the seabed below still water)",
                             i, numberText(values[i]), numberText(kMaxWaterDepth)));
      height.push_back(-values[i]);
    }
  }
  return std::make_shared<const seabed::SeabedSurface>(
      seabed::SeabedSurface::grid(std::move(x), std::move(y), std::move(height), interpolation));
}

void readSeabed(const Value& v, model::EnvironmentSpec& env) {
  const Map m(v, {"normal_stiffness", "damping", "friction_coefficient", "friction_velocity",
                  "shear_stiffness", "friction_model", "slope", "upslope_azimuth", "bathymetry"});
  seabed::SeabedSpec& bed = env.seabed;
  const seabed::SeabedSpec d;
  bed.normalStiffness = m.number("normal_stiffness", d.normalStiffness, positiveUpTo(1.0e12));
  bed.damping = m.number("damping", d.damping, nonNegativeUpTo(1.0e12));
  bed.frictionCoefficient = m.number("friction_coefficient", d.frictionCoefficient, nonNegativeUpTo(10.0));
  bed.frictionVelocity = m.number("friction_velocity", d.frictionVelocity, positiveUpTo(10.0));
  bed.shearStiffness = m.number("shear_stiffness", bed.normalStiffness, positiveUpTo(1.0e12));
  if (const std::optional<Value> model = m.find("friction_model"))
    bed.elasticFriction = model->choice<bool>({{"elastic", true}, {"viscous", false}});
  env.seabedSurface = readSeabedShape(m, env.waterDepth);
}

/// z of the seabed under (x, y) [m].
double seabedHeight(const model::EnvironmentSpec& env, double x, double y) {
  return env.seabedSurface ? env.seabedSurface->height(x, y) : -env.waterDepth;
}

/// How the seabed's height is given, for messages.
std::string seabedLevelText(const model::EnvironmentSpec& env) {
  return env.seabedSurface ? std::string("the seabed's height there") : std::string("-water_depth");
}

/// A list of levels {z, speed, azimuth}, or one map {speed, azimuth} for a uniform current (stored as a
/// single level at z = 0: the profile is constant beyond its end levels).
std::vector<model::CurrentLevel> readCurrent(const Value& v) {
  if (v.node().IsMap()) {
    const Map m(v, {"speed", "azimuth"});
    return {{0.0, m.number("speed", nonNegativeUpTo(kMaxSpeed)), degToRad(m.number("azimuth", anyNumber()))}};
  }
  if (!v.node().IsSequence())
    v.expected("a list of levels {z, speed, azimuth} or a single map {speed, azimuth} (uniform current)");
  std::vector<model::CurrentLevel> levels;
  std::vector<std::pair<double, int>> seen;  // z and line of each level
  for (const Value& item : v.items(1)) {
    const Map m(item, {"z", "speed", "azimuth"});
    model::CurrentLevel level;
    const Value z = m.get("z", "a number <= 0");
    level.z = z.number(atMost(0.0).withHint("z = 0 at the still water level, negative below"));
    for (const auto& [zOther, lineOther] : seen)
      if (zOther == level.z)
        z.fail(fmt::format("current level z = {} is given twice (first at line {}); levels must be distinct",
                           numberText(level.z), lineOther));
    seen.emplace_back(level.z, z.line());
    level.speed = m.number("speed", nonNegativeUpTo(kMaxSpeed));
    level.azimuth = degToRad(m.number("azimuth", anyNumber()));
    levels.push_back(level);
  }
  return levels;
}

/// `current: {grid: {file}}`: a current on a grid in space and time (MoorDyn's current_profile_4d.txt format,
/// hydro::readCurrentGridFile), the file's path relative to the model file.
std::shared_ptr<const hydro::CurrentGrid> readCurrentGrid(const Value& v) {
  const Map m(v, {"grid"});
  const Map g(m.get("grid", "a map {file}"), {"file"});
  const Value file =
      g.get("file", "a file name (MoorDyn's current_profile_4d.txt format), relative to the model file");
  namespace fs = std::filesystem;
  fs::path path(
      file.text("a file name (MoorDyn's current_profile_4d.txt format), relative to the model file"));
  if (path.is_relative()) path = fs::path(file.source()).parent_path() / path;
  try {
    return std::make_shared<const hydro::CurrentGrid>(hydro::readCurrentGridFile(path.string()));
  } catch (const Error& e) {
    file.fail(fmt::format("cannot read the current grid: {}", e.what()));
  }
}

/// `current: {history: [{time, profile}, ...]}`: a current changing in time, each profile as `current`.
std::vector<model::CurrentSnapshot> readCurrentHistory(const Value& v) {
  const Map m(v, {"history"});
  const Value list = m.get("history", "a list of {time, profile} (the current at increasing times)");
  std::vector<model::CurrentSnapshot> out;
  for (const Value& item : list.items(1)) {
    const Map s(item, {"time", "profile"});
    model::CurrentSnapshot snapshot;
    const Value time = s.get("time", "a time in s");
    snapshot.time = time.number(atLeast(0.0));
    if (!out.empty() && !(snapshot.time > out.back().time))
      time.fail(fmt::format("times must increase: {} s follows {} s", numberText(snapshot.time),
                            numberText(out.back().time)));
    snapshot.levels =
        readCurrent(s.get("profile", "a list of levels {z, speed, azimuth} or a map {speed, azimuth}"));
    out.push_back(std::move(snapshot));
  }
  return out;
}

model::WaveSpec readWaves(const Value& v, double waterDepth) {
  using model::WaveKind;
  static const std::vector<std::string> kAiryKeys{"height", "period", "phase"};
  static const std::vector<std::string> kJonswapKeys{"significant_height", "peak_period", "gamma",
                                                     "components", "seed"};
  static const std::vector<std::string> kComponentKeys{"table"};
  std::vector<std::string> allowed{"type"};
  for (const auto* keys : {&kAiryKeys, &kJonswapKeys, &kComponentKeys})
    allowed.insert(allowed.end(), keys->begin(), keys->end());
  allowed.emplace_back("azimuth");
  allowed.emplace_back("stretching");
  const Map m(v, allowed);

  model::WaveSpec w;
  w.kind = m.get("type", "one of: none, airy, jonswap, components")
               .choice<WaveKind>({{"none", WaveKind::None},
                                  {"airy", WaveKind::Airy},
                                  {"jonswap", WaveKind::Jonswap},
                                  {"components", WaveKind::Components}});
  if (w.kind == WaveKind::None)
    return w;  // the other keys are ignored: waves can be switched off in one place

  const bool airy = w.kind == WaveKind::Airy;
  const bool jonswap = w.kind == WaveKind::Jonswap;
  const std::string typeName = airy ? "airy" : jonswap ? "jonswap" : "components";
  const std::vector<std::string>& own = airy ? kAiryKeys : jonswap ? kJonswapKeys : kComponentKeys;
  for (const auto* keys : {&kAiryKeys, &kJonswapKeys, &kComponentKeys}) {
    if (keys == &own) continue;
    for (const std::string& key : *keys)
      if (const std::optional<Value> foreign = m.find(key))
        foreign->fail(fmt::format(
            "key '{}' does not apply to waves of type {}; their keys are: type, {}, azimuth, stretching", key,
            typeName, join(own)));
  }

  const std::string required = "required for waves of type " + typeName;
  const model::WaveSpec d;
  if (airy) {
    w.height = m.number("height", positiveUpTo(std::min(kMaxWaveHeight, 1.6 * waterDepth))
                                      .withHint(required + "; at most 1.6 x water_depth (crest above the seabed)"));
    w.period = m.number("period", positiveUpTo(kMaxWavePeriod).withHint(required));
    w.phase = m.angle("phase", d.phase);
  } else if (jonswap) {
    w.significantHeight = m.number("significant_height", positiveUpTo(std::min(kMaxWaveHeight, 0.8 * waterDepth))
                                                             .withHint(required + "; at most 0.8 x water_depth"));
    w.peakPeriod = m.number("peak_period", positiveUpTo(kMaxWavePeriod).withHint(required));
    w.gamma = m.number("gamma", d.gamma, closed(1.0, 10.0).withHint("1 gives a Pierson-Moskowitz spectrum"));
    w.components = m.integer("components", d.components, atLeastUpTo(1.0, kMaxWaveComponents));
    const std::optional<Value> seed = m.find("seed");
    w.seed = seed ? static_cast<unsigned>(seed->integer64(closed(0.0, 4294967295.0))) : d.seed;
  } else {
    // Rows [period s, amplitude m, phase deg] or [period, amplitude, phase, azimuth deg] (the azimuth
    // defaults to waves.azimuth).
    const double azimuth = m.angle("azimuth", d.azimuth);
    const Value table =
        m.get("table", "a list of rows [period s, amplitude m, phase deg, azimuth deg] (" + required + ")");
    const std::vector<Value> rows = table.items(1);
    if (rows.size() > static_cast<std::size_t>(kMaxWaveComponents))
      table.fail(fmt::format("{} components; at most {} are accepted", rows.size(), kMaxWaveComponents));
    for (const Value& row : rows) {
      const bool withAzimuth = row.isSequence() && row.node().size() == 4;
      const std::vector<double> r =
          withAzimuth ? row.numbers(4, "[period, amplitude, phase, azimuth] (s, m, deg, deg)")
                      : row.numbers(3, "[period, amplitude, phase] (s, m, deg), or with an azimuth in deg");
      if (!(r[0] > 0.0 && r[0] <= kMaxWavePeriod))
        row.fail(fmt::format("expected a period in (0, {}] s in the first column, got {}",
                             numberText(kMaxWavePeriod), numberText(r[0])));
      if (!(r[1] >= 0.0 && r[1] <= 0.8 * std::min(kMaxWaveHeight, waterDepth)))
        row.fail(fmt::format("expected an amplitude in [0, {}] m in the second column, got {}",
                             numberText(0.8 * std::min(kMaxWaveHeight, waterDepth)), numberText(r[1])));
      for (std::size_t k = 2; k < r.size(); ++k)
        if (!(std::abs(r[k]) <= 3600.0))
          row.fail(fmt::format("expected an angle within +-3600 deg in column {}, got {}", k + 1,
                               numberText(r[k])));
      w.componentTable.push_back({r[0], r[1], degToRad(r[2]), withAzimuth ? degToRad(r[3]) : azimuth});
    }
  }
  w.azimuth = m.angle("azimuth", d.azimuth);
  if (const std::optional<Value> stretching = m.find("stretching"))
    w.stretching = stretching->choice<model::WaveStretching>(
        {{"none", model::WaveStretching::None},
         {"wheeler", model::WaveStretching::Wheeler},
         {"vertical_extrapolation", model::WaveStretching::Extrapolation}});
  return w;
}

void readEnvironment(const Value& v, ModelSpec& spec) {
  const Map m(v, {"water_depth", "water_density", "gravity", "seabed", "current", "waves", "wind"});
  model::EnvironmentSpec& env = spec.environment;
  const model::EnvironmentSpec d;
  env.waterDepth = m.number("water_depth", positiveUpTo(kMaxWaterDepth).withHint("seabed at z = -water_depth"));
  // 0 is allowed for both: a line in air (no buoyancy, added mass or drag) and a model without weight (a
  // MoorDyn kinematics test); waves need gravity (their dispersion), refused below.
  env.waterDensity =
      m.number("water_density", d.waterDensity, closed(0.0, 2000.0).withHint("0 for a model in air"));
  env.gravity = m.number("gravity", d.gravity, closed(0.0, 30.0).withHint("0 for a model without weight"));
  if (const std::optional<Value> seabed = m.find("seabed")) readSeabed(*seabed, env);
  if (const std::optional<Value> current = m.find("current")) {
    if (current->node().IsMap() && current->node()["history"]) {
      env.currentHistory = readCurrentHistory(*current);
      env.current = env.currentHistory.front().levels;
    } else if (current->node().IsMap() && current->node()["grid"]) {
      env.currentGrid = readCurrentGrid(*current);
    } else {
      env.current = readCurrent(*current);
    }
  }
  if (const std::optional<Value> waves = m.find("waves")) {
    if (!(env.gravity > 0.0))
      waves->fail("waves need gravity (their dispersion relation): give environment.gravity > 0");
    env.waves = readWaves(*waves, env.waterDepth);
  }
  if (const std::optional<Value> wind = m.find("wind")) {
    const Map w(*wind, {"speed", "azimuth", "air_density"});
    env.windSpeed = w.number("speed", nonNegativeUpTo(kMaxSpeed));
    env.windAzimuth = degToRad(w.number("azimuth", 0.0, {}));
    env.airDensity = w.number("air_density", d.airDensity, positiveUpTo(10.0));
  }
}

/// line_types[].syrope: a SYROPE rope (element::SyropeAxialLaw); its static law (tensionStrain) is the
/// working curve of its initial largest mean tension.
void readSyrope(const Value& v, const Map& type, section::LineType& t) {
  if (t.bendingStiffness > 0.0) v.fail("a SYROPE rope is a cable (no bending_stiffness)");
  for (const char* other : {"tension_strain", "axial_stiffness", "viscoelastic"})
    if (type.find(other))
      v.fail(fmt::format("a SYROPE rope's curves replace {}: give one or the other", other));
  const Map m(v, {"original_curve", "working_curve", "k1", "k2", "dynamic_stiffness",
                  "dynamic_stiffness_slope", "slow_damping", "dynamic_damping", "initial_max_mean_tension"});
  auto curves = std::make_shared<section::SyropeCurves>();
  const Value owc = m.get("original_curve", "a list of [strain, tension] from a point of zero tension");
  std::vector<double> strain, tension;
  for (const Value& row : owc.items(2)) {
    const std::vector<double> p = row.numbers(2, "[strain (a fraction), tension in N]");
    if (!strain.empty() && (!(p[0] > strain.back()) || !(p[1] > tension.back())))
      row.fail("strains and tensions must increase");
    if (strain.empty() && (p[1] != 0.0 || p[0] < 0.0))
      row.fail("the curve starts at zero tension (a strain >= 0)");
    strain.push_back(p[0]);
    tension.push_back(p[1]);
  }
  curves->originalCurve = std::make_shared<const core::PiecewiseLinear>(strain, tension);
  curves->form =
      m.get("working_curve", "linear, quadratic or exponential")
          .choice<section::SyropeCurves::Form>({{"linear", section::SyropeCurves::Form::Linear},
                                                {"quadratic", section::SyropeCurves::Form::Quadratic},
                                                {"exponential", section::SyropeCurves::Form::Exponential}});
  curves->k1 = m.number("k1", nonNegativeUpTo(kMaxStiffness));
  curves->k2 = m.number("k2", 0.0, closed(-50.0, 50.0));
  const Value tmax = m.get("initial_max_mean_tension", "Tmax at the start, in N");
  curves->initialMaxMeanTension =
      tmax.number(nonNegativeUpTo(kMaxStiffness).withHint("Tmax at the start, N"));
  if (curves->initialMaxMeanTension > tension.back())
    tmax.fail(fmt::format("Tmax {} N is beyond the original curve's last tension {} N",
                          numberText(curves->initialMaxMeanTension), numberText(tension.back())));
  section::Viscoelasticity& ve = t.viscoelastic;
  ve.dynamicStiffness =
      m.number("dynamic_stiffness", positiveUpTo(kMaxStiffness).withHint("alpha (alphaMBL) in N"));
  ve.dynamicStiffnessSlope = m.number("dynamic_stiffness_slope", 0.0, nonNegativeUpTo(1.0e4));
  ve.slowDamping = m.number("slow_damping", positiveUpTo(kMaxStiffness * 1e3).withHint("BA in N s"));
  ve.dynamicDamping = m.number("dynamic_damping", 0.0, nonNegativeUpTo(kMaxStiffness * 1e3));
  try {
    const element::SyropeAxialLaw law({curves->originalCurve,
                                       static_cast<element::WorkingCurveForm>(static_cast<int>(curves->form)),
                                       curves->k1, curves->k2, ve.dynamicStiffness, ve.dynamicStiffnessSlope,
                                       ve.slowDamping, ve.dynamicDamping});
    t.tensionStrain = law.staticCurve(curves->initialMaxMeanTension);
  } catch (const Error& e) {
    v.fail(e.what());
  }
  t.axialStiffness = t.tensionStrain->largestSlope();
  t.syrope = std::move(curves);
}

void readLineTypes(const Value& v, ModelSpec& spec) {
  NameRegistry names("line type");
  for (const Value& item : v.items(1, ItemLabel::Name)) {
    const Map m(item,
                {"name", "outer_diameter", "buoyancy_diameter", "contact_diameter", "mass_per_length",
                 "axial_stiffness", "bending_stiffness", "torsional_stiffness", "drag_normal", "drag_axial",
                 "added_mass_normal", "added_mass_axial", "axial_damping", "minimum_breaking_load",
                 "internal_diameter", "maximum_strain", "tension_strain", "viscoelastic", "syrope"});
    const section::LineType d;
    section::LineType t;
    t.name = names.add(m);
    const Range diameter = positiveUpTo(kMaxDiameter).withHint("in m");
    t.outerDiameter = m.number("outer_diameter", diameter);
    t.buoyancyDiameter = m.number("buoyancy_diameter", t.outerDiameter, diameter);
    t.contactDiameter = m.number("contact_diameter", t.outerDiameter, diameter);
    t.massPerLength = m.number("mass_per_length", positiveUpTo(kMaxMassPerLength));
    const std::optional<Value> curve = m.find("tension_strain");
    if ((!curve && !m.find("syrope")) || m.find("axial_stiffness"))
      t.axialStiffness = m.number("axial_stiffness", positiveUpTo(kMaxStiffness));
    t.bendingStiffness = m.number("bending_stiffness", d.bendingStiffness, nonNegativeUpTo(kMaxStiffness));
    if (curve) {
      if (m.find("axial_stiffness"))
        curve->fail("give either axial_stiffness (a linear EA) or tension_strain (a curve), not both");
      if (t.bendingStiffness > 0.0)
        curve->fail("a tension-strain curve is for cables (no bending_stiffness): a beam's EA is linear");
      // [[strain, tension], ...] from [0, 0], both increasing: a rope stiffening or softening as it
      // stretches.
      std::vector<double> strain{0.0}, tension{0.0};
      const std::vector<Value> rows = curve->items(1);
      for (const Value& row : rows) {
        const std::vector<double> p = row.numbers(2, "[strain (a fraction), tension in N]");
        if (!(p[0] > strain.back()) || p[0] > 1.0)
          row.fail(
              fmt::format("strains must increase from 0 (the first point is [0, 0], implied) and stay <= 1 "
                          "(a fraction: 0.05 for 5 %); got {} after {}",
                          numberText(p[0]), numberText(strain.back())));
        if (!(p[1] > tension.back()) || p[1] > kMaxStiffness)
          row.fail(
              fmt::format("tensions must increase with the strain (a rope that softens to nothing has no "
                          "equilibrium); got {} N after {} N",
                          numberText(p[1]), numberText(tension.back())));
        strain.push_back(p[0]);
        tension.push_back(p[1]);
      }
      t.tensionStrain = std::make_shared<const core::PiecewiseLinear>(strain, tension);
      t.axialStiffness = t.tensionStrain->largestSlope();
    }
    t.torsionalStiffness = m.number("torsional_stiffness", d.torsionalStiffness, nonNegativeUpTo(kMaxStiffness));
    t.dragNormal = m.number("drag_normal", d.dragNormal, nonNegativeUpTo(kMaxCoefficient));
    t.dragAxial = m.number("drag_axial", d.dragAxial, nonNegativeUpTo(kMaxCoefficient));
    t.addedMassNormal = m.number("added_mass_normal", d.addedMassNormal, nonNegativeUpTo(kMaxCoefficient));
    t.addedMassAxial = m.number("added_mass_axial", d.addedMassAxial, nonNegativeUpTo(kMaxCoefficient));
    t.axialDamping = m.number("axial_damping", d.axialDamping, nonNegativeUpTo(kMaxStiffness));
    if (const std::optional<Value> visco = m.find("viscoelastic")) {
      // A polyester rope's static-dynamic stiffness (element::ViscoelasticAxialLaw): the static EA is
      // axial_stiffness; the dynamics follows the dynamic stiffness and the two dashpots.
      if (t.bendingStiffness > 0.0) visco->fail("a viscoelastic rope is a cable (no bending_stiffness)");
      if (curve) visco->fail("give either a tension_strain curve or viscoelastic, not both");
      const Map vm(*visco,
                   {"dynamic_stiffness", "dynamic_stiffness_slope", "slow_damping", "dynamic_damping"});
      section::Viscoelasticity& ve = t.viscoelastic;
      const Value dynamic =
          vm.get("dynamic_stiffness", "the dynamic stiffness EA_d in N, above axial_stiffness");
      ve.dynamicStiffness =
          dynamic.number(positiveUpTo(kMaxStiffness).withHint("EA_d in N, above axial_stiffness"));
      if (!(ve.dynamicStiffness > t.axialStiffness))
        dynamic.fail(fmt::format("the dynamic stiffness ({} N) must exceed the static axial_stiffness ({} N)",
                                 numberText(ve.dynamicStiffness), numberText(t.axialStiffness)));
      ve.dynamicStiffnessSlope =
          vm.number("dynamic_stiffness_slope", 0.0,
                    nonNegativeUpTo(1.0e4).withHint("d EA_d / d T_mean, dimensionless (0: a constant EA_d)"));
      ve.slowDamping = vm.number("slow_damping", positiveUpTo(kMaxStiffness * 1e3).withHint("BA in N s"));
      ve.dynamicDamping =
          vm.number("dynamic_damping", 0.0, nonNegativeUpTo(kMaxStiffness * 1e3).withHint("BA_d in N s"));
    }
    if (const std::optional<Value> syrope = m.find("syrope")) readSyrope(*syrope, m, t);
    if (m.find("maximum_strain"))
      t.maximumStrain = m.number("maximum_strain", positiveUpTo(1.0).withHint("a fraction: 0.005 for 0.5 %"));
    if (const std::optional<Value> bore = m.find("internal_diameter")) {
      t.internalDiameter = bore->number(nonNegativeUpTo(kMaxDiameter).withHint("the bore of the pipe in m"));
      if (t.internalDiameter >= t.outerDiameter)
        bore->fail(fmt::format("the bore ({} m) must be smaller than the outer_diameter ({} m)",
                               numberText(t.internalDiameter), numberText(t.outerDiameter)));
      if (t.internalDiameter >= t.buoyancyDiameter)
        bore->fail(fmt::format("the bore ({} m) must be smaller than the buoyancy_diameter ({} m): the pipe's "
                               "displaced area must hold it",
                               numberText(t.internalDiameter), numberText(t.buoyancyDiameter)));
    }
    if (m.find("minimum_breaking_load"))
      t.minimumBreakingLoad =
          m.number("minimum_breaking_load", positiveUpTo(kMaxStiffness).withHint("in N (e.g. 6.5e6 for a 76 mm R4 chain)"));
    // Plausibility (warnings, not errors: the values are legal, but usually a unit mistake).
    for (const char* key : {"outer_diameter", "buoyancy_diameter"}) {
      const double value = std::string_view(key) == "outer_diameter" ? t.outerDiameter : t.buoyancyDiameter;
      if (m.find(key) && value > kPlausibleDiameter)
        spec.warnings.push_back(m.find(key)->where() +
                                fmt::format("diameter of {} m: diameters are in metres (an 18 in riser is 0.457)",
                                            numberText(value)));
    }
    const double submerged = t.submergedWeight(spec.environment.waterDensity, spec.environment.gravity);
    if (submerged < 0.0)
      spec.warnings.push_back(
          item.where() +
          fmt::format("line type '{}' floats: submerged weight {} N/m (mass_per_length {} kg/m displaces {} kg/m of "
                      "water); fine for buoyancy modules, otherwise check the units of the diameters and the mass",
                      t.name, roundedText(submerged), numberText(t.massPerLength),
                      roundedText(spec.environment.waterDensity * kPi / 4.0 * t.buoyancyDiameter *
                                  t.buoyancyDiameter)));
    spec.lineTypes.emplace(t.name, t);
  }
}

model::EndMotionSpec readMotion(const Value& v) {
  const Map m(v, {"amplitude", "period", "phase", "table", "interpolation"});
  model::EndMotionSpec motion;
  motion.enabled = true;
  if (const std::optional<Value> table = m.find("table")) {
    for (const char* key : {"amplitude", "period", "phase"})
      if (const std::optional<Value> harmonic = m.find(key))
        harmonic->fail(
            fmt::format("'{}' cannot be combined with 'table': give either amplitude, period and phase "
                        "(harmonic motion) or table (time history)",
                        key));
    if (const std::optional<Value> interpolation = m.find("interpolation"))
      motion.cubic = interpolation->choice<bool>({{"linear", false}, {"cubic", true}});
    double previousTime = 0.0;
    for (const Value& row : table->items(2)) {
      const std::vector<double> r = row.numbers(4, "[t, dx, dy, dz] (s, m, m, m)");
      for (std::size_t k = 1; k < 4; ++k)
        if (std::abs(r[k]) > kMaxCoordinate)
          row.fail(fmt::format("offset {} m is beyond +-{} m", numberText(r[k]), numberText(kMaxCoordinate)));
      if (r[0] < 0.0)
        row.fail(fmt::format("expected a time t >= 0 s in the first column, got {}", numberText(r[0])));
      if (!motion.table.empty() && r[0] <= previousTime)
        row.fail(fmt::format("times must be strictly increasing: t = {} s comes after t = {} s",
                             numberText(r[0]), numberText(previousTime)));
      previousTime = r[0];
      motion.table.push_back({r[0], r[1], r[2], r[3]});
    }
    return motion;
  }
  if (const std::optional<Value> interpolation = m.find("interpolation"))
    interpolation->fail("'interpolation' applies only to a motion 'table'");
  motion.amplitude = m.get("amplitude", "a list of 3 numbers [x, y, z] in m (or a 'table')").vec3();
  motion.period = m.number("period", positiveUpTo(kMaxDuration));
  motion.phase = m.angle("phase", 0.0);
  return motion;
}

model::EndSpec readEnd(const Value& v, const ModelSpec& spec) {
  const model::EnvironmentSpec& env = spec.environment;
  using model::EndKind;
  const Map m(v, {"type", "position", "vessel", "point", "motion", "release", "tensioner", "flex_joint"});
  model::EndSpec end;
  end.sourceLine = v.line();
  const Value type = m.get("type", "one of: anchored, fixed, pinned, free, vessel, point");
  end.kind = type.choice<EndKind>({{"anchored", EndKind::Anchored},
                                   {"fixed", EndKind::Fixed},
                                   {"pinned", EndKind::Pinned},
                                   {"free", EndKind::Free},
                                   {"vessel", EndKind::Vessel},
                                   {"point", EndKind::Point}});
  const std::string typeName = toLower(type.node().Scalar());
  if (const std::optional<Value> point = m.find("point"); point && end.kind != EndKind::Point)
    point->fail(fmt::format("'point' applies only to ends of type point; this end is of type {}", typeName));
  if (end.kind == EndKind::Point) {
    // The end starts where its point is: a position of its own would contradict it.
    if (const std::optional<Value> position = m.find("position"))
      position->fail(
          "an end of type point starts at its point's position (points[].position): remove 'position'");
    const Value point =
        m.get("point", "the name of a point under 'points' (required for ends of type point)");
    end.point = point.text("a point name");
    const auto found = std::find_if(spec.points.begin(), spec.points.end(),
                                    [&](const model::PointSpec& p) { return p.name == end.point; });
    if (found == spec.points.end()) {
      std::vector<std::string> names;
      for (const model::PointSpec& p : spec.points) names.push_back("'" + p.name + "'");
      point.fail(fmt::format("unknown point '{}'; {}", end.point,
                             names.empty() ? "the model defines no points (add a 'points' block)"
                                           : "points defined under points: " + join(names)));
    }
    end.position = found->position;
    for (const char* key : {"motion", "release", "tensioner", "flex_joint"})
      if (const std::optional<Value> other = m.find(key))
        other->fail(
            fmt::format("'{}' does not apply to an end of type point (the point is free; its lines "
                        "hold it)",
                        key));
    return end;
  }
  const Value position = m.get("position", "a list of 3 numbers [x, y, z] in m");
  end.position = position.position();

  if (end.kind == EndKind::Vessel) {
    const Value vessel = m.get("vessel", "the name of the vessel (required for ends of type vessel)");
    end.vessel = vessel.text("a vessel name");
    const auto found = std::find_if(spec.vessels.begin(), spec.vessels.end(),
                                    [&](const model::VesselSpec& vs) { return vs.name == end.vessel; });
    if (found == spec.vessels.end()) {
      std::vector<std::string> names;
      for (const model::VesselSpec& vs : spec.vessels) names.push_back("'" + vs.name + "'");
      vessel.fail(fmt::format("unknown vessel '{}'; {}", end.vessel,
                              names.empty() ? "the model defines no vessels (add a 'vessels' block)"
                                            : "vessels defined under vessels: " + join(names)));
    }
    // The end in global axes at t = 0 (vessel axes rotated by the heading about z keep z): below the
    // seabed it would pull the line into the ground.
    const double z = found->position.z() + end.position.z();
    const double heading = found->heading;
    const double x =
        found->position.x() + std::cos(heading) * end.position.x() - std::sin(heading) * end.position.y();
    const double y =
        found->position.y() + std::sin(heading) * end.position.x() + std::cos(heading) * end.position.y();
    const double bottom = seabedHeight(env, x, y);
    if (z < bottom - kSeabedTolerance)
      position.fail(
          fmt::format("the end is below the seabed: vessel '{}' at z = {} m plus the offset z = {} m "
                      "gives z = {} m, the seabed is at z = {} m ({})",
                      end.vessel, numberText(found->position.z()), numberText(end.position.z()),
                      numberText(z), numberText(bottom), seabedLevelText(env)));
  } else {
    if (const std::optional<Value> vessel = m.find("vessel"))
      vessel->fail(
          fmt::format("'vessel' applies only to ends of type vessel; this end is of type {}", typeName));
    const double seabedZ = seabedHeight(env, end.position.x(), end.position.y());
    if (end.position.z() < seabedZ - kSeabedTolerance)
      position.fail(fmt::format(
          "the end is below the seabed: z = {} m, the seabed is at z = {} m ({}); "
          "expected z >= {}",
          numberText(end.position.z()), numberText(seabedZ), seabedLevelText(env), numberText(seabedZ)));
    // An anchor sits on the seabed or in the water, never above the surface.
    if (end.kind == EndKind::Anchored && end.position.z() > 0.0)
      position.fail(fmt::format("an anchored end is above the water surface: z = {} m; anchors are at "
                                "-water_depth <= z <= 0 (use type fixed or pinned for a point in the air)",
                                numberText(end.position.z())));
  }

  if (const std::optional<Value> tensioner = m.find("tensioner")) {
    if (end.kind != EndKind::Vessel) tensioner->fail("a tensioner applies only to ends of type vessel");
    const Map t(*tensioner, {"tension", "stroke", "stop_stiffness", "stiffness"});
    end.tensioner.enabled = true;
    end.tensioner.tension = t.number("tension", positiveUpTo(1.0e9));
    end.tensioner.stroke = t.number("stroke", end.tensioner.stroke, positiveUpTo(100.0));
    end.tensioner.stopStiffness = t.number("stop_stiffness", end.tensioner.stopStiffness, positiveUpTo(1.0e12));
    end.tensioner.stiffness = t.number("stiffness", end.tensioner.stiffness, nonNegativeUpTo(1.0e12));
  }
  if (const std::optional<Value> flex = m.find("flex_joint")) {
    if (end.kind != EndKind::Vessel) flex->fail("a flex joint applies only to ends of type vessel");
    const Map f(*flex, {"stiffness"});
    end.flexJoint.enabled = true;
    end.flexJoint.stiffness = f.number("stiffness", nonNegativeUpTo(kMaxStiffness));
  }

  if (const std::optional<Value> release = m.find("release")) {
    if (end.kind == EndKind::Free || end.kind == EndKind::Vessel)
      release->fail(fmt::format("'release' applies only to held ends (anchored, fixed, pinned); this end is {}",
                                typeName));
    for (const Value& axis : release->items(1))
      end.release[static_cast<std::size_t>(axis.choice<int>({{"x", 0}, {"y", 1}, {"z", 2}}))] = true;
  }

  if (const std::optional<Value> motion = m.find("motion")) {
    if (end.kind == EndKind::Free || end.kind == EndKind::Vessel)
      motion->fail(
          fmt::format("a prescribed motion applies only to ends of type anchored, fixed or pinned; this end "
                      "is of type {}",
                      typeName));
    end.motion = readMotion(*motion);
  }
  return end;
}

model::SectionSpec readSection(const Value& v, const ModelSpec& spec) {
  const Map m(v, {"type", "length", "elements", "contents_density"});
  model::SectionSpec section;
  const Value type = m.get("type", "the name of a line type");
  section.lineType = type.text("the name of a line type");
  if (!spec.lineTypes.contains(section.lineType)) {
    std::vector<std::string> known;
    for (const auto& [name, lineType] : spec.lineTypes) known.push_back(name);
    type.fail(fmt::format("unknown line type '{}'; line types defined under line_types: {}", section.lineType,
                          join(known)));
  }
  section.length = m.number("length", positiveUpTo(kMaxLineLength).withHint("unstretched length in m"));
  const Value elements = m.get("elements", "an integer >= 1");
  const long long count = elements.integer64(atLeast(1.0));
  if (count > kMaxElements)
    elements.fail(fmt::format("{} elements would need about {:.3g} GB of memory; at most {} elements are "
                              "accepted in a model",
                              count, static_cast<double>(count) * kBytesPerElement / 1e9, kMaxElements));
  section.elements = static_cast<int>(count);
  if (const std::optional<Value> density = m.find("contents_density")) {
    section.contentsDensity =
        density->number(nonNegativeUpTo(kMaxContentsDensity).withHint("in kg/m^3; 0 for an empty section"));
    if (spec.lineTypes.at(section.lineType).internalDiameter <= 0.0)
      density->fail(fmt::format("line type '{}' has no bore to hold contents: give it an internal_diameter",
                                section.lineType));
  }
  return section;
}

/// `lines[].contents`: what fills the bore of the line's pipe sections.
model::ContentsSpec readContents(const Value& v) {
  const Map m(v, {"density", "pressure", "reference_z"});
  model::ContentsSpec c;
  c.density = m.number("density", 0.0, nonNegativeUpTo(kMaxContentsDensity).withHint("in kg/m^3, e.g. 800 for oil"));
  c.pressure = m.number("pressure", 0.0,
                        atLeastUpTo(kVacuum, kMaxPressure).withHint("gauge pressure in Pa at reference_z, e.g. 1.0e7 "
                                                                    "for 10 MPa"));
  if (const std::optional<Value> z = m.find("reference_z"))
    c.referenceZ = z->number(closed(-kMaxCoordinate, kMaxCoordinate).withHint("in m"));
  return c;
}

/// One entry of `lines[].attachments`: an attachment, or a row of `count` modules every `pitch` m from
/// `arc_length` (buoyancy modules, strakes' clamps), each shared between the nodes of its element.
std::vector<model::AttachmentSpec> readAttachment(const Value& v, double lineLength) {
  const Map m(v, {"arc_length", "mass", "volume", "drag_area", "added_mass", "pitch", "count"});
  model::AttachmentSpec a;
  a.arcLength =
      m.number("arc_length", closed(0.0, lineLength).withHint("from end A, within the line's length"));
  a.mass = m.number("mass", 0.0, nonNegativeUpTo(kMaxMass));
  a.volume = m.number("volume", 0.0, nonNegativeUpTo(kMaxMass / 1000.0));
  a.dragArea = m.number("drag_area", 0.0, nonNegativeUpTo(1.0e4));
  a.addedMass = m.number("added_mass", 0.0, nonNegativeUpTo(kMaxMass));
  const std::optional<Value> pitch = m.find("pitch"), count = m.find("count");
  if (!pitch && !count) return {a};
  if (!pitch || !count)
    (pitch ? *pitch : *count)
        .fail("a row of modules needs both 'pitch' (the distance between them, m) and 'count' (how many)");
  const double spacing = pitch->number(positiveUpTo(kMaxLineLength).withHint("distance between modules in m"));
  const long long modules = count->integer64(atLeastUpTo(1.0, 100000.0));
  const double last = a.arcLength + static_cast<double>(modules - 1) * spacing;
  if (last > lineLength + 1e-9)
    count->fail(fmt::format("{} modules every {} m from {} m reach {} m, beyond the line's length {} m", modules,
                            numberText(spacing), numberText(a.arcLength), roundedText(last),
                            roundedText(lineLength)));
  std::vector<model::AttachmentSpec> row;
  for (long long k = 0; k < modules; ++k) {
    model::AttachmentSpec module = a;
    module.arcLength = std::min(lineLength, a.arcLength + static_cast<double>(k) * spacing);
    module.shared = true;
    row.push_back(module);
  }
  return row;
}

/// `lines[].start_shape`: intermediate points [x, y, z], or maps {position, arc_length} (all with an arc
/// length or none), from end A to end B.
std::vector<model::StartPoint> readStartShape(const Value& v, double lineLength,
                                              const model::EnvironmentSpec& env) {
  std::vector<model::StartPoint> points;
  int withArc = 0;
  for (const Value& item : v.items(1)) {
    model::StartPoint p;
    if (item.isSequence()) {
      p.position = item.position();
    } else {
      const Map m(item, {"position", "arc_length"});
      p.position = m.get("position", "a list of 3 numbers [x, y, z] in m").position();
      if (const std::optional<Value> arc = m.find("arc_length")) {
        p.arcLength =
            arc->number(Range{0.0, lineLength, true, true, "from end A, strictly between the line's ends"});
        if (!points.empty() && std::isfinite(points.back().arcLength) &&
            p.arcLength <= points.back().arcLength)
          arc->fail(fmt::format("arc lengths must increase from end A to end B; the point before is at {} m",
                                numberText(points.back().arcLength)));
        ++withArc;
      }
    }
    const double bottom = seabedHeight(env, p.position.x(), p.position.y());
    if (p.position.z() < bottom - kSeabedTolerance)
      item.fail(fmt::format("the point is below the seabed: z = {} m, the seabed is at z = {} m ({})",
                            numberText(p.position.z()), numberText(bottom), seabedLevelText(env)));
    points.push_back(p);
  }
  if (withArc != 0 && withArc != static_cast<int>(points.size()))
    v.fail(fmt::format("{} of the {} points have an arc_length: give it for all of them or for none (then the "
                       "points share the line's length in proportion to the distances between them)",
                       withArc, points.size()));
  return points;
}

/// `lines[].failure`: when and where the line parts (FailureSpec).
model::FailureSpec readFailure(const Value& v, const model::LineSpec& line, const ModelSpec& spec,
                               double length) {
  const Map m(v, {"time", "tension", "clash_energy", "at"});
  model::FailureSpec f;
  f.enabled = true;
  if (const std::optional<Value> time = m.find("time"))
    f.time = time->number(
        nonNegativeUpTo(kMaxDuration).withHint("in s of the dynamics; 0 parts it before the statics"));
  if (const std::optional<Value> tension = m.find("tension")) {
    if (tension->isPlain() && tension->node().Scalar() == "mbl") {
      f.tensionIsBreakingLoad = true;
      for (const model::SectionSpec& section : line.sections)
        if (spec.lineTypes.at(section.lineType).minimumBreakingLoad <= 0.0)
          tension->fail(
              fmt::format("'mbl' is each line type's minimum_breaking_load, and line type '{}' of line "
                          "'{}' has none: give it one, or give the tension in N",
                          section.lineType, line.name));
    } else {
      f.tension = tension->number(
          positiveUpTo(kMaxStiffness).withHint("in N, or 'mbl' for each line type's minimum_breaking_load"));
    }
  }
  if (const std::optional<Value> energy = m.find("clash_energy"))
    f.clashEnergy =
        energy->number(positiveUpTo(1.0e12).withHint("impact energy of a clash on the line in J"));
  if (std::isnan(f.time) && f.tension <= 0.0 && !f.tensionIsBreakingLoad && f.clashEnergy <= 0.0)
    v.fail("a failure needs a trigger: 'time' (s), 'tension' (N or 'mbl') or 'clash_energy' (J)");
  if (const std::optional<Value> at = m.find("at")) {
    if (at->isPlain() && at->node().Scalar() == "end_a") {
      f.where = model::FailureSpec::Where::EndA;
    } else if (at->isPlain() && at->node().Scalar() == "end_b") {
      f.where = model::FailureSpec::Where::EndB;
    } else {
      f.where = model::FailureSpec::Where::Arc;
      f.arcLength = at->number(
          closed(0.0, length)
              .withHint(
                  "end_a, end_b, or the arc length from end A in m where the line parts, within its length"));
    }
    const model::EndSpec& end = f.where == model::FailureSpec::Where::EndB ? line.endB : line.endA;
    if (f.where != model::FailureSpec::Where::Arc && end.kind == model::EndKind::Free)
      at->fail(fmt::format("end {} of line '{}' is free already: nothing holds it to part from",
                           f.where == model::FailureSpec::Where::EndA ? "A" : "B", line.name));
  } else if (!std::isnan(f.time) && f.tension <= 0.0 && !f.tensionIsBreakingLoad && f.clashEnergy <= 0.0) {
    v.fail(
        "a failure by time needs 'at': end_a, end_b, or the arc length from end A in m where the line parts");
  }
  return f;
}

model::LineSpec readLine(const Value& v, const ModelSpec& spec, NameRegistry& names) {
  const Map m(v, {"name", "contact", "end_a", "end_b", "sections", "attachments", "start_shape", "span_check",
                  "contents", "failure"});
  model::LineSpec line;
  line.name = names.add(m);
  line.contact = m.boolean("contact", line.contact);
  const bool spanCheck = m.boolean("span_check", true);
  const std::string endExpectation = "a map {type, position} describing the end";
  line.endA = readEnd(m.get("end_a", endExpectation), spec);
  line.endB = readEnd(m.get("end_b", endExpectation), spec);

  double length = 0.0;
  for (const Value& item :
       m.get("sections", "a list of sections {type, length, elements} from end A to end B").items(1))
    length += line.sections.emplace_back(readSection(item, spec)).length;

  if (const std::optional<Value> contents = m.find("contents")) {
    line.contents = readContents(*contents);
    if (std::none_of(line.sections.begin(), line.sections.end(), [&](const model::SectionSpec& section) {
          return spec.lineTypes.at(section.lineType).internalDiameter > 0.0;
        }))
      contents->fail(fmt::format("line '{}' has contents but none of its line types has a bore to hold them: give "
                                 "the pipe's line type an internal_diameter",
                                 line.name));
  }
  if (const std::optional<Value> attachments = m.find("attachments"))
    for (const Value& item : attachments->items(0))
      for (const model::AttachmentSpec& a : readAttachment(item, length)) line.attachments.push_back(a);
  if (const std::optional<Value> shape = m.find("start_shape"))
    line.startShape = readStartShape(*shape, length, spec.environment);
  if (const std::optional<Value> failure = m.find("failure"))
    line.failure = readFailure(*failure, line, spec, length);
  if (line.endA.kind == model::EndKind::Point && line.endB.kind == model::EndKind::Point &&
      line.endA.point == line.endB.point)
    m.get("end_b", endExpectation)
        .fail(
            fmt::format("both ends of line '{}' are at point '{}': a line from a point back to it is a loop "
                        "that holds nothing",
                        line.name, line.endA.point));

  // Ends clearly too far apart for the line's length: a mistake in the positions or lengths (a line
  // stretched by half its length ran to its end with 1.25 GN of tension and only a warning). Vessel ends
  // are placed with their vessel's initial position and heading. `span_check: false` accepts it.
  using model::EndKind;
  const auto globalEnd = [&](const model::EndSpec& end) -> std::optional<Vec3> {
    if (end.kind != EndKind::Vessel) return end.position;
    for (const model::VesselSpec& vessel : spec.vessels) {
      if (vessel.name != end.vessel) continue;
      const double c = std::cos(vessel.heading), s = std::sin(vessel.heading);
      return Vec3(vessel.position.x() + c * end.position.x() - s * end.position.y(),
                  vessel.position.y() + s * end.position.x() + c * end.position.y(),
                  vessel.position.z() + end.position.z());
    }
    return std::nullopt;  // an unknown vessel is reported where the end is read
  };
  const std::optional<Vec3> a = globalEnd(line.endA), b = globalEnd(line.endB);
  if (spanCheck && a && b) {
    double span = (*b - *a).norm();
    if (!line.startShape.empty()) {
      // Through the start shape's points: the path the line must stretch along.
      span = (line.startShape.front().position - *a).norm() + (*b - line.startShape.back().position).norm();
      for (std::size_t i = 1; i < line.startShape.size(); ++i)
        span += (line.startShape[i].position - line.startShape[i - 1].position).norm();
    }
    const bool vesselEnd = line.endA.kind == EndKind::Vessel || line.endB.kind == EndKind::Vessel;
    if (span > kMaxEndSpanOverLength * length)
      v.fail(fmt::format(
          "line '{}': its ends are {} m apart{}{} but its unstretched length is only {} m (sum of the "
          "sections); at most {} x the length ({} m) is accepted: check the end positions{}{} and section "
          "lengths, or set span_check: false for a line meant to start stretched that far",
          line.name, roundedText(span), vesselEnd ? " (vessel ends at the vessels' initial positions)" : "",
          line.startShape.empty() ? "" : " along its start_shape points", roundedText(length),
          kMaxEndSpanOverLength, roundedText(kMaxEndSpanOverLength * length),
          vesselEnd ? ", the vessel positions" : "", line.startShape.empty() ? "" : ", the start shape"));
  }
  return line;
}

void readLines(const Value& v, ModelSpec& spec) {
  NameRegistry names("line");
  long long elements = 0;
  for (const Value& item : v.items(1, ItemLabel::Name)) {
    spec.lines.push_back(readLine(item, spec, names));
    // A cubic table's spline can pass a hold and come back to it (docs/model-format.md "motion").
    for (const auto& [key, end] :
         {std::pair{"end_a", &spec.lines.back().endA}, {"end_b", &spec.lines.back().endB}}) {
      if (!end->motion.enabled || !end->motion.cubic || end->motion.table.size() < 3) continue;
      double range = 0.0;
      for (const auto& row : end->motion.table)
        for (std::size_t k = 1; k < 4; ++k)
          range = std::max(range, std::abs(row[k] - end->motion.table.front()[k]));
      const model::PrescribedMotion::Overshoot o = model::PrescribedMotion(end->motion, 0.0).tableOvershoot();
      if (o.distance > std::max(1e-3, 0.01 * range))
        spec.warnings.push_back(
            item.where() +
            fmt::format(
                "{}.motion: the cubic spline through the table's rows goes {:.3g} m beyond them in {} at t = "
                "{:.3g} s "
                "(between the rows at {} s and {} s); with interpolation: linear, or a row that eases into a "
                "hold, the end stays within them",
                key, o.distance, "xyz"[o.axis], o.time, numberText(o.rowTimeA), numberText(o.rowTimeB)));
    }
    for (const model::SectionSpec& section : spec.lines.back().sections) elements += section.elements;
    if (elements > kMaxElements)
      item.fail(fmt::format("the model has {} elements up to this line; they would need about {:.3g} GB of memory; "
                            "at most {} elements are accepted in a model",
                            elements, static_cast<double>(elements) * kBytesPerElement / 1e9, kMaxElements));
  }
}

/// `points`: free points where line ends meet (`lines[].end_a/end_b: {type: point, point: NAME}`).
void readPoints(const Value& v, ModelSpec& spec) {
  NameRegistry names("point");
  for (const Value& item : v.items(1, ItemLabel::Name)) {
    const Map m(item, {"name", "position", "mass", "volume", "drag_area", "added_mass"});
    model::PointSpec p;
    p.sourceLine = item.line();
    p.name = names.add(m);
    const Value position = m.get("position", "the initial position [x, y, z] in m");
    p.position = position.position();
    const double seabedZ = seabedHeight(spec.environment, p.position.x(), p.position.y());
    if (p.position.z() < seabedZ - kSeabedTolerance)
      position.fail(
          fmt::format("the point is below the seabed: z = {} m, the seabed is at z = {} m ({}); "
                      "expected z >= {}",
                      numberText(p.position.z()), numberText(seabedZ), seabedLevelText(spec.environment),
                      numberText(seabedZ)));
    p.body.mass = m.number("mass", 0.0, nonNegativeUpTo(kMaxMass));
    p.body.volume = m.number("volume", 0.0, nonNegativeUpTo(kMaxMass / 1000.0));
    p.body.dragArea = m.number("drag_area", 0.0, nonNegativeUpTo(1.0e4));
    p.body.addedMass = m.number("added_mass", 0.0, nonNegativeUpTo(kMaxMass));
    spec.points.push_back(p);
  }
}

/// Every point holds at least one line end (runs after `lines`).
void checkPointsUsed(const ModelSpec& spec) {
  for (const model::PointSpec& p : spec.points) {
    const bool used = std::any_of(spec.lines.begin(), spec.lines.end(), [&](const model::LineSpec& l) {
      return (l.endA.kind == model::EndKind::Point && l.endA.point == p.name) ||
             (l.endB.kind == model::EndKind::Point && l.endB.point == p.name);
    });
    if (!used)
      throw InputError(spec.sourceFile, p.sourceLine, "points[" + p.name + "]",
                       "no line end is at this point: give a line an end {type: point, point: " + p.name +
                           "}, or remove the point");
  }
}

void readStatics(const Value& v, ModelSpec& spec) {
  const Map m(v, {"max_iterations", "tolerance", "displacement_tolerance", "method"});
  const model::StaticSpec d;
  model::StaticSpec& s = spec.statics;
  if (const std::optional<Value> method = m.find("method"))
    s.skip = method->choice<bool>({{"newton", false}, {"none", true}});
  s.maxIterations = m.integer("max_iterations", d.maxIterations, atLeast(1.0));
  s.tolerance = m.number("tolerance", d.tolerance, positive());
  s.displacementTolerance = m.number("displacement_tolerance", d.displacementTolerance, positive());
}

void readDynamics(const Value& v, ModelSpec& spec) {
  using model::IntegratorKind;
  const Map m(v, {"duration", "time_step", "min_time_step", "ramp_time", "output_interval", "integrator",
                  "spectral_radius", "mass", "rayleigh", "max_iterations", "tolerance", "max_cable_strain_step",
                  "error_tolerance", "max_time_step", "solver"});
  const model::DynamicSpec d;
  model::DynamicSpec& s = spec.dynamics;
  s.duration = m.number("duration", nonNegativeUpTo(kMaxDuration).withHint("0 switches dynamics off"));
  s.enabled = s.duration > 0.0;
  s.timeStep = m.number("time_step", d.timeStep, positiveUpTo(100.0));
  // Defaults that would contradict a user's time step follow it instead.
  s.minTimeStep = m.number("min_time_step", std::min(d.minTimeStep, s.timeStep),
                           Range{0.0, s.timeStep, true, false, "at most time_step"});
  s.rampTime = m.number("ramp_time", d.rampTime, nonNegativeUpTo(kMaxDuration));
  s.outputInterval = m.number("output_interval", std::max(d.outputInterval, s.timeStep),
                              atLeast(s.timeStep).withHint("at least time_step"));
  if (const std::optional<Value> integrator = m.find("integrator"))
    s.integrator =
        integrator->choice<IntegratorKind>({{"generalized_alpha", IntegratorKind::GeneralizedAlpha},
                                            {"hht", IntegratorKind::Hht},
                                            {"newmark", IntegratorKind::Newmark}});
  s.spectralRadius = m.number("spectral_radius", d.spectralRadius, closed(0.0, 1.0));
  if (const std::optional<Value> mass = m.find("mass"))
    s.lumpedMass = mass->choice<bool>({{"lumped", true}, {"consistent", false}});
  if (const std::optional<Value> rayleigh = m.find("rayleigh")) {
    const Map r(*rayleigh, {"alpha", "beta"});
    s.rayleighAlpha = r.number("alpha", d.rayleighAlpha, nonNegative());
    s.rayleighBeta = r.number("beta", d.rayleighBeta, nonNegative());
  }
  s.maxIterations = m.integer("max_iterations", d.maxIterations, atLeast(1.0));
  s.tolerance = m.number("tolerance", d.tolerance, positive());
  s.maxCableStrainStep = m.number("max_cable_strain_step", d.maxCableStrainStep,
                                  closed(0.0, 1.0).withHint("0 switches the snap step limit off"));
  s.errorTolerance = m.number("error_tolerance", d.errorTolerance,
                              closed(0.0, 0.5).withHint("0: fixed steps of time_step; e.g. 1e-3 asks for error control"));
  s.maxTimeStep = m.number("max_time_step", s.outputInterval,
                           Range{s.timeStep, s.outputInterval, false, false, "between time_step and output_interval"});
  if (const std::optional<Value> solver = m.find("solver")) {
    using Choices = model::DynamicSolverSpec;
    std::vector<std::string> keys;
    for (const Choices::Choice& c : Choices::kChoices) keys.emplace_back(c.key);
    const Map sm(*solver, keys);
    for (const Choices::Choice& c : Choices::kChoices)
      if (const std::optional<Value> x = sm.find(c.key))
        s.solver.*c.member = x->choice<bool>({{c.whenTrue, true}, {c.whenFalse, false}});
  }
}

void readOutput(const Value& v, ModelSpec& spec) {
  const Map m(v, {"format", "vtk", "vtk_interval", "plots", "energy", "storm_duration", "time_histories"});
  const model::OutputSpec d;
  if (const std::optional<Value> format = m.find("format"))
    spec.output.format = format->choice<model::ResultFormat>({{"auto", model::ResultFormat::Auto},
                                                              {"csv", model::ResultFormat::Csv},
                                                              {"hdf5", model::ResultFormat::Hdf5},
                                                              {"both", model::ResultFormat::Both}});
  spec.output.vtk = m.boolean("vtk", d.vtk);
  spec.output.vtkInterval = m.number("vtk_interval", d.vtkInterval, positive());
  spec.output.plots = m.boolean("plots", d.plots);
  spec.output.energy = m.boolean("energy", d.energy);
  spec.output.stormDuration =
      m.number("storm_duration", d.stormDuration, positiveUpTo(1e7).withHint("seconds: 10800 for a 3 h storm"));
  if (const std::optional<Value> histories = m.find("time_histories")) {
    // `all`, `none`, or a list of quantity names.
    model::TimeHistorySelection& t = spec.output.timeHistories;
    const std::string names =
        "position, effective_tension, wall_tension, bending_moment, bending_moment_vector, curvature, torque";
    const auto every = [&t](bool value) {
      t.position = t.effectiveTension = t.wallTension = t.bendingMoment = t.bendingMomentVector = t.curvature =
          t.torque = value;
    };
    if (histories->isSequence()) {
      every(false);
      for (const Value& item : histories->items(0)) {
        const std::string q = item.text("a quantity name");
        bool* flag = q == "position"                ? &t.position
                     : q == "effective_tension"     ? &t.effectiveTension
                     : q == "wall_tension"          ? &t.wallTension
                     : q == "bending_moment"        ? &t.bendingMoment
                     : q == "bending_moment_vector" ? &t.bendingMomentVector
                     : q == "curvature"             ? &t.curvature
                     : q == "torque"                ? &t.torque
                                                    : nullptr;
        if (!flag) item.fail(fmt::format("unknown quantity '{}'; expected one of {}", q, names));
        *flag = true;
      }
    } else {
      const bool all = histories->choice<bool>({{"all", true}, {"none", false}});
      every(all);
    }
  }
}

/// `name` read as the name of a line of `spec`; an unknown one fails with "unknown line 'X'", followed by
/// " in <context>" when a context is given.
std::string knownLine(const Value& name, const ModelSpec& spec, std::string_view context) {
  const std::string n = name.text("a line name");
  const bool known =
      std::any_of(spec.lines.begin(), spec.lines.end(), [&](const model::LineSpec& l) { return l.name == n; });
  if (!known) name.fail("unknown line '" + n + "'" + (context.empty() ? "" : " in " + std::string(context)));
  return n;
}

void readContact(const Value& v, ModelSpec& spec) {
  const Map m(v, {"formulation", "pairs", "self_contact", "stiffness", "restitution", "model", "friction_coefficient",
                  "friction_velocity", "clearance_margin", "exclude", "exclusion_zones", "exclude_connections",
                  "impact_velocity_threshold", "event_separation_time", "clash_damage"});
  const model::ContactSpec d;
  model::ContactSpec& c = spec.contact;
  c.enabled = true;
  if (const std::optional<Value> pairs = m.find("pairs")) {
    for (const Value& item : pairs->items(1)) {
      const std::vector<Value> names = item.items(2);
      if (names.size() != 2) item.expected("a pair of line names [line_a, line_b]");
      std::pair<std::string, std::string> pair{knownLine(names[0], spec, ""), knownLine(names[1], spec, "")};
      if (pair.first == pair.second && !m.boolean("self_contact", d.selfContact))
        item.fail("a line paired with itself needs self_contact: true");
      c.pairs.push_back(pair);
    }
  }
  c.selfContact = m.boolean("self_contact", d.selfContact);
  c.stiffness = m.number("stiffness", d.stiffness, nonNegative().withHint("0 chooses it from the line properties"));
  c.restitution = m.number("restitution", d.restitution, closed(0.0, 1.0));
  if (const std::optional<Value> model = m.find("model"))
    c.model = model->choice<model::ImpactModel>(
        {{"penalty", model::ImpactModel::Penalty}, {"impulse", model::ImpactModel::Impulse}});
  if (const std::optional<Value> formulation = m.find("formulation")) {
    c.formulation = formulation->choice<model::ContactFormulation>(
        {{"point", model::ContactFormulation::Point}, {"distributed", model::ContactFormulation::Distributed}});
    if (c.formulation == model::ContactFormulation::Distributed && c.model == model::ImpactModel::Impulse)
      formulation->fail("formulation: distributed has no velocity-jump (impulse) model: use model: penalty");
  } else if (c.model == model::ImpactModel::Impulse) {
    c.formulation = model::ContactFormulation::Point;  // the impulse model is the point formulation's
  }
  c.frictionCoefficient = m.number("friction_coefficient", d.frictionCoefficient, nonNegative());
  c.frictionVelocity = m.number("friction_velocity", d.frictionVelocity, positive());
  c.clearanceMargin = m.number("clearance_margin", d.clearanceMargin, positive());
  auto lineName = [&](const Value& name) {
    return knownLine(name, spec, "contact.exclude / contact.exclusion_zones");
  };
  if (const std::optional<Value> exclude = m.find("exclude")) {
    for (const Value& item : exclude->items(1)) {
      const std::vector<Value> names = item.items(2);
      if (names.size() != 2) item.expected("a pair of line names [line_a, line_b] (contact.exclude)");
      c.exclude.emplace_back(lineName(names[0]), lineName(names[1]));
    }
  }
  if (const std::optional<Value> zones = m.find("exclusion_zones")) {
    for (const Value& item : zones->items(1)) {
      const Map z(item, {"line", "from", "to", "with"});
      model::ContactSpec::ExclusionZone zone;
      zone.line = lineName(z.get("line", "the name of the line the zone is on (contact.exclusion_zones)"));
      zone.from = z.number("from", nonNegative().withHint("arc length from end A [m]"));
      zone.to = z.number("to", nonNegative().withHint("arc length from end A [m]"));
      if (zone.to <= zone.from) item.fail("contact.exclusion_zones: 'to' must be larger than 'from'");
      const auto& lines = spec.lines;
      const auto it = std::find_if(lines.begin(), lines.end(), [&](const model::LineSpec& l) { return l.name == zone.line; });
      double length = 0.0;
      for (const auto& sec : it->sections) length += sec.length;
      if (zone.from >= length)
        item.fail(fmt::format("contact.exclusion_zones: 'from' ({} m) is beyond the end of line '{}' ({} m long)",
                              zone.from, zone.line, length));
      // Past the end: the zone runs to it, as meant, but a 'to' longer than the line may be another line's
      // length or a typing slip, so it is said.
      if (zone.to > length)
        spec.warnings.push_back(
            z.find("to")->where() +
            fmt::format(
                "contact.exclusion_zones: 'to' ({} m) is beyond the end of line '{}' ({} m long): the zone "
                "runs from {} m to its end",
                numberText(zone.to), zone.line, numberText(length), numberText(zone.from)));
      if (const std::optional<Value> with = z.find("with")) zone.other = lineName(*with);
      c.exclusionZones.push_back(zone);
    }
  }
  c.excludeConnections = m.boolean("exclude_connections", d.excludeConnections);
  c.impactVelocityThreshold = m.number("impact_velocity_threshold", d.impactVelocityThreshold, nonNegative());
  c.eventSeparationTime = m.number("event_separation_time", d.eventSeparationTime, nonNegative());
  if (const std::optional<Value> damage = m.find("clash_damage")) {
    const Map cd(*damage, {"bin_length", "energy_threshold"});
    c.damageBinLength = cd.number("bin_length", d.damageBinLength, positive().withHint("length of a bin along a line [m]"));
    c.damageEnergyThreshold = cd.number("energy_threshold", d.damageEnergyThreshold,
                                        nonNegative().withHint("impact energy the line tolerates [J]"));
  }
}

/// hull_contact: {stiffness, line_stiffness, restitution, friction, friction_velocity, point_spacing,
/// own_lines, exclude} (model::HullContactSpec; docs/model-format.md).
void readHullContact(const Value& v, ModelSpec& spec) {
  const Map m(v, {"stiffness", "line_stiffness", "restitution", "friction", "friction_velocity",
                  "point_spacing", "own_lines", "exclude"});
  const model::HullContactSpec d;
  model::HullContactSpec& h = spec.hullContact;
  h.sourceLine = v.line();
  h.stiffness =
      m.number("stiffness", d.stiffness,
               positiveUpTo(kMaxStiffness).withHint("of each hull point inside another hull [N/m]"));
  h.lineStiffness = m.number("line_stiffness", d.lineStiffness,
                             positiveUpTo(kMaxStiffness).withHint("per metre of line inside a hull [N/m/m]"));
  h.restitution = m.number("restitution", d.restitution, closed(0.0, 1.0));
  h.friction = m.number("friction", d.friction, nonNegativeUpTo(10.0));
  h.frictionVelocity = m.number("friction_velocity", d.frictionVelocity, positiveUpTo(kMaxSpeed));
  h.pointSpacing = m.number("point_spacing", d.pointSpacing, positiveUpTo(kMaxCoordinate));
  h.ownLines = m.boolean("own_lines", d.ownLines);
  if (const std::optional<Value> exclude = m.find("exclude")) {
    for (const Value& item : exclude->items(1)) {
      const std::vector<Value> names = item.items(2);
      if (names.size() != 2) item.expected("a pair [line or vessel, vessel] (hull_contact.exclude)");
      const std::string first = names[0].text("a line or vessel name");
      const std::string second = names[1].text("a vessel name");
      const auto isVessel = [&](const std::string& n) {
        return std::any_of(spec.vessels.begin(), spec.vessels.end(),
                           [&](const model::VesselSpec& vs) { return vs.name == n; });
      };
      const bool isLine = std::any_of(spec.lines.begin(), spec.lines.end(),
                                      [&](const model::LineSpec& l) { return l.name == first; });
      if (!isLine && !isVessel(first))
        names[0].fail("unknown line or vessel '" + first + "' in hull_contact.exclude");
      if (!isVessel(second)) names[1].fail("unknown vessel '" + second + "' in hull_contact.exclude");
      h.exclude.emplace_back(first, second);
    }
  }
  if (std::none_of(spec.vessels.begin(), spec.vessels.end(),
                   [](const model::VesselSpec& vs) { return !vs.hull.empty(); }))
    v.fail("hull_contact applies to vessels with a hull: give a vessel a 'hull' (a list of shapes)");
}

/// fatigue: {start_time, occurrence, design_factor, sn_curves, tn_curves, sections} (docs/model-format.md).
void readFatigue(const Value& v, ModelSpec& spec) {
  const Map m(v, {"start_time", "occurrence", "design_factor", "sn_curves", "tn_curves", "sections"});
  const model::FatigueSpec d;
  model::FatigueSpec& f = spec.fatigue;
  f.enabled = true;
  f.startTime = m.number("start_time", d.startTime, anyNumber().withHint("seconds; default: the ramp time"));
  f.occurrence = m.number("occurrence", d.occurrence, Range{0.0, 1.0, true, false, "in (0, 1]"}.withHint(
                                                          "fraction of a year the sea state stands for"));
  f.designFactor = m.number("design_factor", d.designFactor, atLeastUpTo(1.0, 100.0).withHint("DFF, e.g. 3 or 10"));
  NameRegistry curveNames("fatigue curve");
  const auto presetConflict = [](const Map& c, std::initializer_list<const char*> keys) {
    for (const char* k : keys)
      if (const std::optional<Value> given = c.find(k))
        given->fail(fmt::format("'{}' with 'preset': give a preset or the curve's constants, not both", k));
  };
  if (const std::optional<Value> curves = m.find("sn_curves")) {
    for (const Value& item : curves->items(1, ItemLabel::Name)) {
      const Map c(item, {"name", "preset", "m1", "log_a1", "m2", "log_a2", "knee_cycles", "thickness_exponent",
                         "reference_thickness"});
      model::SnCurveSpec sn;
      sn.name = curveNames.add(c);
      if (const std::optional<Value> preset = c.find("preset")) {
        presetConflict(c, {"m1", "log_a1", "m2", "log_a2", "knee_cycles", "thickness_exponent", "reference_thickness"});
        const std::string name = preset->text("a preset name");
        const std::optional<analysis::SnCurve> p = analysis::SnCurve::preset(name);
        if (!p) {
          std::string known;
          for (const std::string& n : analysis::SnCurve::presetNames()) known += (known.empty() ? "" : ", ") + n;
          preset->fail(fmt::format("unknown S-N curve preset '{}'; expected one of {}", name, known));
        }
        sn.m1 = p->m1;
        sn.logA1 = p->logA1;
        sn.m2 = p->m2;
        sn.logA2 = p->logA2;
        sn.kneeCycles = p->kneeCycles;
        sn.thicknessExponent = p->thicknessExponent;
        sn.referenceThickness = p->referenceThickness;
      } else {
        sn.m1 = c.number("m1", closed(1.0, 20.0).withHint("slope of the S-N curve, 3 for welds"));
        sn.logA1 = c.number("log_a1", closed(0.0, 40.0).withHint("log10 of the intercept, stress in MPa"));
        sn.singleSlope = !c.find("m2");
        sn.m2 = sn.singleSlope ? sn.m1 : c.number("m2", closed(1.0, 20.0));
        sn.logA2 = sn.singleSlope ? sn.logA1 : c.number("log_a2", closed(0.0, 40.0));
        if (sn.singleSlope && c.find("log_a2")) c.find("log_a2")->fail("log_a2 without m2: give both for a two-slope curve");
        sn.kneeCycles = c.number("knee_cycles", 1e7, closed(1e3, 1e12).withHint("1e7 in air, 1e6 in seawater"));
        sn.thicknessExponent = c.number("thickness_exponent", 0.0, closed(0.0, 1.0));
        sn.referenceThickness = c.number("reference_thickness", 0.025, positiveUpTo(1.0).withHint("in m"));
      }
      f.snCurves.push_back(sn);
    }
  }
  if (const std::optional<Value> curves = m.find("tn_curves")) {
    for (const Value& item : curves->items(1, ItemLabel::Name)) {
      const Map c(item, {"name", "preset", "m", "k", "a_d"});
      model::TnCurveSpec tn;
      tn.name = curveNames.add(c);
      if (const std::optional<Value> preset = c.find("preset")) {
        presetConflict(c, {"m", "k", "a_d"});
        const std::string name = preset->text("a preset name");
        const std::optional<analysis::TnCurve> p = analysis::TnCurve::preset(name);
        if (!p)
          preset->fail(fmt::format("unknown T-N curve preset '{}'; expected one of api-studlink, api-studless, "
                                   "dnv-studlink, dnv-studless",
                                   name));
        tn.m = p->m;
        tn.intercept = p->aD;
        tn.stressBased = p->stressBased;
      } else {
        tn.m = c.number("m", closed(1.0, 20.0).withHint("slope of the T-N curve, 3 for chain"));
        const bool api = c.find("k").has_value(), dnv = c.find("a_d").has_value();
        if (api == dnv)
          item.fail("a T-N curve needs exactly one of 'k' (API RP 2SK, on the ratio to the breaking strength) "
                    "and 'a_d' (DNV-OS-E301, on the nominal stress in MPa)");
        tn.stressBased = dnv;
        tn.intercept = api ? c.number("k", positive()) : c.number("a_d", positive());
      }
      f.tnCurves.push_back(tn);
    }
  }
  const Value sections = m.get("sections", "a list of {line_type, sn_curve or tn_curve, ...}");
  for (const Value& item : sections.items(1)) {
    const Map c(item, {"line_type", "sn_curve", "tn_curve", "outer_diameter", "wall_thickness", "scf", "points",
                       "surface", "tension", "breaking_strength", "nominal_area", "chain_diameter"});
    model::FatigueSectionSpec s;
    const Value typeValue = c.get("line_type", "the name of a line type");
    s.lineType = typeValue.text("a line type name");
    const auto type = spec.lineTypes.find(s.lineType);
    if (type == spec.lineTypes.end()) typeValue.fail(fmt::format("unknown line type '{}'", s.lineType));
    for (const model::FatigueSectionSpec& other : f.sections)
      if (other.lineType == s.lineType)
        typeValue.fail(fmt::format("line type '{}' has fatigue properties already", s.lineType));
    const std::optional<Value> snName = c.find("sn_curve"), tnName = c.find("tn_curve");
    if (snName.has_value() == tnName.has_value())
      item.fail("a fatigue section needs exactly one of 'sn_curve' (stress) and 'tn_curve' (tension)");
    s.tensionCurve = tnName.has_value();
    const Value& curveValue = s.tensionCurve ? *tnName : *snName;
    s.curve = curveValue.text("a curve name");
    if (s.tensionCurve) {
      const auto it = std::find_if(f.tnCurves.begin(), f.tnCurves.end(),
                                   [&](const model::TnCurveSpec& t) { return t.name == s.curve; });
      if (it == f.tnCurves.end()) curveValue.fail(fmt::format("unknown T-N curve '{}' (fatigue.tn_curves)", s.curve));
      for (const char* k : {"wall_thickness", "scf", "points", "surface", "tension", "outer_diameter"})
        if (const std::optional<Value> given = c.find(k)) given->fail(fmt::format("'{}' is for S-N curves (stress)", k));
      if (it->stressBased) {
        const bool area = c.find("nominal_area").has_value(), chain = c.find("chain_diameter").has_value();
        if (area == chain)
          item.fail("a DNV T-N curve needs exactly one of 'nominal_area' [m^2] and 'chain_diameter' [m] (nominal "
                    "area of two legs, pi d^2 / 2)");
        s.nominalArea = area ? c.number("nominal_area", positiveUpTo(1.0).withHint("in m^2"))
                             : 0.5 * kPi * std::pow(c.number("chain_diameter", positiveUpTo(1.0).withHint("in m")), 2);
      } else {
        s.breakingStrength = c.number("breaking_strength", positive().withHint("reference breaking strength [N]"));
      }
    } else {
      if (std::none_of(f.snCurves.begin(), f.snCurves.end(), [&](const model::SnCurveSpec& t) { return t.name == s.curve; }))
        curveValue.fail(fmt::format("unknown S-N curve '{}' (fatigue.sn_curves)", s.curve));
      for (const char* k : {"breaking_strength", "nominal_area", "chain_diameter"})
        if (const std::optional<Value> given = c.find(k)) given->fail(fmt::format("'{}' is for T-N curves (tension)", k));
      s.outerDiameter = c.number("outer_diameter", type->second.outerDiameter,
                                 positiveUpTo(kMaxDiameter).withHint("steel outer diameter [m]"));
      s.wallThickness = c.number("wall_thickness", Range{0.0, 0.5 * s.outerDiameter, true, false,
                                                         "above 0 and below half the outer diameter"});
      s.stressConcentration = c.number("scf", 1.0, closed(1.0, 20.0).withHint("stress concentration factor"));
      s.points = c.integer("points", s.points, closed(8.0, 360.0).withHint("points round the circumference"));
      if (const std::optional<Value> surface = c.find("surface"))
        s.innerSurface = surface->choice<bool>({{"outer", false}, {"inner", true}});
      if (const std::optional<Value> tension = c.find("tension"))
        s.wallTension = tension->choice<bool>({{"wall", true}, {"effective", false}});
    }
    f.sections.push_back(s);
  }
  if (!spec.dynamics.enabled)
    spec.warnings.push_back(v.where() + "fatigue is computed from the dynamics, and this model has none (dynamics.duration)");
}

/// wake_interference: a list of {upstream, downstream, model, coefficients, upstream_drag_coefficient};
/// upstream and downstream each a line name or a list of names (every upstream line acts on every
/// downstream one), or `lines: [...]` for a group in which every line acts on every other one.
void readWakes(const Value& v, ModelSpec& spec) {
  auto names = [&](const Value& item) {
    std::vector<std::string> out;
    if (item.isSequence()) {
      for (const Value& n : item.items(1)) out.push_back(knownLine(n, spec, "wake_interference"));
    } else {
      out.push_back(knownLine(item, spec, "wake_interference"));
    }
    return out;
  };
  for (const Value& item : v.items(1)) {
    const Map m(item, {"upstream", "downstream", "lines", "model", "coefficients", "upstream_drag_coefficient"});
    model::WakeSpec w;
    if (const std::optional<Value> model = m.find("model"))
      w.model = model->choice<model::WakeSpec::Model>(
          {{"huse", model::WakeSpec::Model::Huse}, {"blevins", model::WakeSpec::Model::Blevins}});
    if (const std::optional<Value> c = m.find("coefficients")) {
      if (w.model == model::WakeSpec::Model::Huse) {
        const Map k(*c, {"k1", "k2", "k3"});
        w.k1 = k.number("k1", w.k1, positive().withHint("wake half-width factor, Huse 1993: 0.25"));
        w.k2 = k.number("k2", w.k2, positive().withHint("centre-line deficit factor, Huse 1993: 1.0"));
        w.k3 = k.number("k3", w.k3, positive().withHint("Gaussian profile factor, Huse 1993: 0.693"));
      } else {
        const Map k(*c, {"a1", "a2", "a3"});
        w.a1 = k.number("a1", w.a1, positive().withHint("centre-line deficit factor, Blevins 2005: 1.0"));
        w.a2 = k.number("a2", w.a2, positive().withHint("Gaussian profile factor, Blevins 2005: 4.5"));
        w.a3 = k.number("a3", w.a3, Range{-1e3, 0.0, false, false, "lift factor (Blevins 2005: -10.6)"});
      }
    }
    w.upstreamDragCoefficient =
        m.number("upstream_drag_coefficient", 0.0, nonNegative().withHint("0 takes the upstream line type's drag_normal"));
    std::vector<std::pair<std::string, std::string>> pairs;
    if (const std::optional<Value> group = m.find("lines")) {
      if (m.find("upstream") || m.find("downstream"))
        item.fail("give either 'lines' (a group) or 'upstream' and 'downstream', not both");
      const std::vector<std::string> all = names(*group);
      if (all.size() < 2) group->fail("a wake group needs at least two lines");
      for (const auto& a : all)
        for (const auto& b : all)
          if (a != b) pairs.emplace_back(a, b);
    } else {
      const std::vector<std::string> up = names(m.get("upstream", "the line (or list of lines) whose wake acts"));
      const std::vector<std::string> down =
          names(m.get("downstream", "the line (or list of lines) that sees the reduced current"));
      for (const auto& a : up)
        for (const auto& b : down) {
          if (a == b) item.fail(fmt::format("line '{}' cannot be in its own wake", a));
          pairs.emplace_back(a, b);
        }
    }
    for (const auto& [a, b] : pairs) {
      model::WakeSpec one = w;
      one.upstream = a;
      one.downstream = b;
      spec.wakes.push_back(one);
    }
  }
}

/// clearance: {required [m], pairs: [[a, b], ...], margin [m], collision_allowed: [[a, b], ...],
/// allowed_impact_energy [J]}.
void readClearance(const Value& v, ModelSpec& spec) {
  const Map m(v, {"required", "pairs", "margin", "collision_allowed", "allowed_impact_energy"});
  spec.clearance.required =
      m.number("required", 0.0, nonNegative().withHint("required surface-to-surface clearance [m] (DNV-RP-F203)"));
  if (const std::optional<Value> margin = m.find("margin"))
    spec.clearance.margin =
        margin->number(positive().withHint("the dynamic minima are kept up to this clearance [m]"));
  // One pair of distinct known lines [line_a, line_b] of the list `key` (clearance.pairs, ...).
  const auto linePair = [&](const Value& item, const std::vector<Value>& names, std::string_view key) {
    if (names.size() != 2) item.expected(fmt::format("a pair of line names [line_a, line_b] ({})", key));
    std::array<std::string, 2> pair;
    for (std::size_t k = 0; k < 2; ++k) pair[k] = knownLine(names[k], spec, key);
    if (pair[0] == pair[1]) item.fail(fmt::format("{}: a line paired with itself", key));
    return pair;
  };
  if (const std::optional<Value> pairs = m.find("pairs")) {
    for (const Value& item : pairs->items(1)) {
      const std::array<std::string, 2> pair = linePair(item, item.items(2), "clearance.pairs");
      spec.clearance.pairs.emplace_back(pair[0], pair[1]);
    }
  }
  // Pairs designed to touch: assessed by their impacts, which only line-to-line contact gives (without it the
  // lines pass through each other and there are none).
  if (const std::optional<Value> allowed = m.find("collision_allowed")) {
    if (!spec.contact.enabled)
      allowed->fail(
          "clearance.collision_allowed needs a 'contact' block: without line-to-line contact the lines pass "
          "through each other, and a collision-allowed pair is assessed by its impacts");
    for (const Value& item : allowed->items(1)) {
      const std::vector<Value> names = item.items(2);
      const std::array<std::string, 2> pair = linePair(item, names, "clearance.collision_allowed");
      for (std::size_t k = 0; k < 2; ++k)
        for (const model::LineSpec& line : spec.lines)
          if (line.name == pair[k] && !line.contact)
            names[k].fail(
                fmt::format("clearance.collision_allowed: line '{}' has 'contact: false' (it touches "
                            "no line, so it has no impacts to assess)",
                            pair[k]));
      // Whether `list` holds the pair, in either order.
      const auto listed = [&](const std::vector<std::pair<std::string, std::string>>& list) {
        return std::any_of(list.begin(), list.end(), [&](const auto& p) {
          return (p.first == pair[0] && p.second == pair[1]) || (p.first == pair[1] && p.second == pair[0]);
        });
      };
      if (!spec.contact.pairs.empty() && !listed(spec.contact.pairs))
        item.fail(
            fmt::format("clearance.collision_allowed: lines '{}' and '{}' may not touch (they are not "
                        "among contact.pairs)",
                        pair[0], pair[1]));
      if (listed(spec.contact.exclude))
        item.fail(
            fmt::format("clearance.collision_allowed: lines '{}' and '{}' never touch (contact.exclude)",
                        pair[0], pair[1]));
      if (!spec.clearance.pairs.empty() && !listed(spec.clearance.pairs))
        item.fail(
            fmt::format("clearance.collision_allowed: lines '{}' and '{}' are not among clearance.pairs, "
                        "the pairs checked: add them there",
                        pair[0], pair[1]));
      spec.clearance.collisionAllowed.emplace_back(pair[0], pair[1]);
    }
  }
  if (const std::optional<Value> energy = m.find("allowed_impact_energy")) {
    if (spec.clearance.collisionAllowed.empty())
      energy->fail(
          "clearance.allowed_impact_energy is the energy collision-allowed pairs tolerate: give the pairs in "
          "clearance.collision_allowed");
    spec.clearance.allowedImpactEnergy = energy->number(
        positive().withHint("the largest impact energy a collision-allowed pair tolerates [J]"));
  }
}

/// A heading table: list of [heading_deg, x, y, yaw] rows, headings ascending in [0, 360).
model::HeadingTable readHeadingTable(const Value& v) {
  model::HeadingTable t;
  double previous = -1.0;
  for (const Value& row : v.items(1)) {
    const std::vector<double> r = row.numbers(4, "[heading_deg, x, y, yaw]");
    if (r[0] < 0.0 || r[0] >= 360.0 || r[0] <= previous)
      row.fail(fmt::format("headings must increase within [0, 360) degrees; got {}", numberText(r[0])));
    previous = r[0];
    t.heading.push_back(degToRad(r[0]));
    t.values.emplace_back(r[1], r[2], r[3]);
  }
  return t;
}

std::array<double, 6> readSix(const Map& m, std::string_view key, const Range& range) {
  std::array<double, 6> out{};
  if (const std::optional<Value> v = m.find(key)) {
    const std::vector<double> n = v->numbers(6, "[surge, sway, heave, roll, pitch, yaw]");
    for (int i = 0; i < 6; ++i) {
      if (!range.contains(n[i])) v->fail(fmt::format("item {} is {}; expected {}", i, numberText(n[i]), range.describe()));
      out[i] = n[i];
    }
  }
  return out;
}

model::RaoTable readRaos(const Value& v) {
  // raos: {periods: [...], headings: [...deg], rows: [[period, heading, a1, p1, ..., a6, p6], ...]} with
  // translations [m/m], rotations [deg/m], phases [deg] (lag).
  const Map m(v, {"periods", "headings", "rows"});
  model::RaoTable t;
  const Value periods = m.get("periods", "a list of wave periods [s], ascending");
  for (const Value& p : periods.items(1)) t.period.push_back(p.number(positive()));
  const Value headings = m.get("headings", "a list of relative wave headings [deg], ascending in [0, 360)");
  for (const Value& h : headings.items(1)) t.heading.push_back(degToRad(h.number(Range{0.0, 360.0, false, true, {}})));
  // Strictly: a repeated period or heading would have no row of its own ("missing the row" for a value
  // that has one).
  const auto strictlyAscending = [](const std::vector<double>& x) {
    return std::adjacent_find(x.begin(), x.end(), std::greater_equal<>()) == x.end();
  };
  if (!strictlyAscending(t.period)) periods.fail("periods must be strictly ascending (each listed once)");
  if (!strictlyAscending(t.heading)) headings.fail("headings must be strictly ascending (each listed once)");
  t.amplitude.assign(t.period.size(), std::vector<std::array<double, 6>>(t.heading.size()));
  t.phase = t.amplitude;
  std::vector<std::vector<bool>> seen(t.period.size(), std::vector<bool>(t.heading.size(), false));
  const Value rows = m.get("rows", "a list of rows [period, heading_deg, surge_amp, surge_phase, ..., yaw_amp, yaw_phase]");
  for (const Value& row : rows.items(1)) {
    const std::vector<double> r = row.numbers(14, "[period, heading, 6 x (amplitude, phase_deg)]");
    const auto ip = std::find(t.period.begin(), t.period.end(), r[0]);
    const auto ih = std::find(t.heading.begin(), t.heading.end(), degToRad(r[1]));
    if (ip == t.period.end() || ih == t.heading.end())
      row.fail("period and heading of a row must be listed in 'periods' and 'headings'");
    const std::size_t a = static_cast<std::size_t>(ip - t.period.begin());
    const std::size_t b = static_cast<std::size_t>(ih - t.heading.begin());
    for (int k = 0; k < 6; ++k) {
      t.amplitude[a][b][k] = k < 3 ? r[2 + 2 * k] : degToRad(r[2 + 2 * k]);
      t.phase[a][b][k] = degToRad(r[3 + 2 * k]);
    }
    seen[a][b] = true;
  }
  for (std::size_t a = 0; a < seen.size(); ++a)
    for (std::size_t b = 0; b < seen[a].size(); ++b)
      if (!seen[a][b])
        rows.fail(fmt::format("missing the row for period {} s, heading {} deg", numberText(t.period[a]),
                              numberText(radToDeg(t.heading[b]))));
  return t;
}

/// vessels[].hull: a list of shapes in vessel axes, {shape: box, centre, size}, {shape: cylinder | capsule,
/// end_a, end_b, diameter} (geometry::HullShape).
std::vector<geometry::HullShape> readHull(const Value& v) {
  std::vector<geometry::HullShape> out;
  for (const Value& item : v.items(1)) {
    const Map m(item, {"shape", "centre", "size", "end_a", "end_b", "diameter"});
    const std::string kind =
        m.get("shape", "box, cylinder or capsule")
            .choice<std::string>({{"box", "box"}, {"cylinder", "cylinder"}, {"capsule", "capsule"}});
    if (kind == "box") {
      for (const char* key : {"end_a", "end_b", "diameter"})
        if (m.find(key)) m.get(key, "").fail(fmt::format("a box has no {}: give centre and size", key));
      const Vec3 centre = m.get("centre", "the box's centre [x, y, z] in vessel axes [m]").position();
      const Value sizeValue = m.get("size", "the box's lengths [along x, along y, along z] [m]");
      const Vec3 size = sizeValue.vec3();
      if (!(size.array() > 0.0).all() || (size.array() > kMaxCoordinate).any())
        sizeValue.fail(fmt::format("expected three lengths in (0, {}] m", numberText(kMaxCoordinate)));
      out.push_back(geometry::HullShape::box(centre, size));
      continue;
    }
    for (const char* key : {"centre", "size"})
      if (m.find(key))
        m.get(key, "").fail(fmt::format("a {} has no {}: give end_a, end_b and diameter", kind, key));
    const Vec3 a = m.get("end_a", "the centre of one end [x, y, z] in vessel axes [m]").position();
    const Value bValue = m.get("end_b", "the centre of the other end [x, y, z] in vessel axes [m]");
    const Vec3 b = bValue.position();
    const double diameter = m.number("diameter", positiveUpTo(kMaxCoordinate));
    if (kind == "cylinder") {
      if ((b - a).norm() <= 0.0)
        bValue.fail("a cylinder's end_b must differ from its end_a (a sphere is a capsule)");
      out.push_back(geometry::HullShape::cylinder(a, b, diameter));
    } else {
      out.push_back(geometry::HullShape::capsule(a, b, diameter));
    }
  }
  return out;
}

void readVessels(const Value& v, ModelSpec& spec) {
  NameRegistry names("vessel");
  for (const Value& item : v.items(1, ItemLabel::Name)) {
    const Map m(item, {"name",
                       "mode",
                       "position",
                       "heading",
                       "mass",
                       "inertia",
                       "added_mass",
                       "linear_damping",
                       "quadratic_damping",
                       "hydrostatic_stiffness",
                       "current_coefficients",
                       "current_areas",
                       "wind_coefficients",
                       "wind_areas",
                       "wave_drift",
                       "raos",
                       "motion",
                       "held_in_statics",
                       "pinned",
                       "hull",
                       "displaced_volume",
                       "centre_of_buoyancy"});
    model::VesselSpec vs;
    vs.sourceLine = item.line();
    vs.name = names.add(m);
    if (const std::optional<Value> mode = m.find("mode"))
      vs.mode = mode->choice<model::VesselMode>({{"fixed", model::VesselMode::Fixed},
                                                 {"prescribed", model::VesselMode::Prescribed},
                                                 {"free", model::VesselMode::Free}});
    vs.position = m.get("position", "the reference point [x, y, z] in m").position();
    vs.heading = degToRad(m.number("heading", 0.0, {}));
    const bool free = vs.mode == model::VesselMode::Free;
    vs.heldInStatics = m.boolean("held_in_statics", false);
    if (vs.heldInStatics && !free) m.get("held_in_statics", "").fail("held_in_statics applies only to free vessels");
    vs.pinned = m.boolean("pinned", false);
    if (vs.pinned && !free)
      m.get("pinned", "").fail("pinned applies only to free vessels (their rotations are solved)");
    if (vs.pinned && vs.heldInStatics)
      m.get("pinned", "").fail("a pinned vessel is held in translation always: leave out held_in_statics");
    vs.mass = free ? m.number("mass", positiveUpTo(kMaxMass)) : m.number("mass", 0.0, nonNegativeUpTo(kMaxMass));
    if (const std::optional<Value> inertia = m.find("inertia")) {
      vs.inertia = inertia->vec3();
      if ((vs.inertia.array() <= 0.0).any() || (vs.inertia.array() > 1.0e16).any())
        inertia->fail("expected three moments of inertia in (0, 1e16] [kg m^2]");
    } else if (free) {
      m.get("inertia", "[Ixx, Iyy, Izz] about the reference point in kg m^2 (required for a free vessel)");
    }
    vs.addedMass = readSix(m, "added_mass", nonNegativeUpTo(1.0e16));
    vs.linearDamping = readSix(m, "linear_damping", nonNegativeUpTo(1.0e16));
    vs.quadraticDamping = readSix(m, "quadratic_damping", nonNegativeUpTo(1.0e16));
    vs.hydrostaticStiffness = readSix(m, "hydrostatic_stiffness", nonNegativeUpTo(1.0e16));
    // A submerged body: its weight and buoyancy act on it (VesselLoads), and its lines hold it.
    if (const std::optional<Value> volume = m.find("displaced_volume")) {
      if (!free) volume->fail("displaced_volume applies only to free vessels (a submerged body)");
      vs.displacedVolume = m.number("displaced_volume", nonNegativeUpTo(1.0e9));
    }
    if (const std::optional<Value> centre = m.find("centre_of_buoyancy")) {
      if (std::isnan(vs.displacedVolume)) centre->fail("centre_of_buoyancy needs displaced_volume");
      vs.centreOfBuoyancy = centre->vec3();
    }
    // A free vessel floats on its waterplane: without heave stiffness nothing holds it up in statics
    // (the solve would end with a residual that does not name the cause). A submerged body hangs on its
    // lines.
    if (free && !vs.heldInStatics && !vs.pinned && vs.hydrostaticStiffness[2] <= 0.0 &&
        std::isnan(vs.displacedVolume))
      item.fail(fmt::format(
          "free vessel '{}' has no restoring force in heave: give hydrostatic_stiffness "
          "[0, 0, heave, roll, pitch, 0] (heave = rho g waterplane area), or held_in_statics: true, "
          "or displaced_volume for a submerged body",
          vs.name));
    if (const std::optional<Value> t = m.find("current_coefficients")) vs.currentCoefficients = readHeadingTable(*t);
    // Reference areas and the yaw lever [A_x, A_y, L], each >= 0 (refused here by key, not later by the
    // loads).
    const auto areas = [](const Value& a) {
      const std::vector<double> values = a.numbers(3, "[A_x (m^2), A_y (m^2), L (m)]");
      for (std::size_t i = 0; i < 3; ++i)
        if (values[i] < 0.0)
          a.fail(fmt::format("item {} is {}; expected areas and a lever >= 0", i, numberText(values[i])));
      return Vec3(values[0], values[1], values[2]);
    };
    if (const std::optional<Value> a = m.find("current_areas")) vs.currentAreas = areas(*a);
    if (const std::optional<Value> t = m.find("wind_coefficients")) vs.windCoefficients = readHeadingTable(*t);
    if (const std::optional<Value> a = m.find("wind_areas")) vs.windAreas = areas(*a);
    if (const std::optional<Value> t = m.find("wave_drift")) vs.waveDrift = readHeadingTable(*t);
    if (const std::optional<Value> r = m.find("raos")) vs.raos = readRaos(*r);
    if (const std::optional<Value> motion = m.find("motion")) {
      if (vs.mode != model::VesselMode::Prescribed) motion->fail("a motion applies only to vessels of mode prescribed");
      const Map mm(*motion, {"amplitude", "phase", "period"});
      const std::vector<double> a = mm.get("amplitude", "[x, y, z (m), roll, pitch, yaw (deg)]").numbers(6, "[x, y, z, roll, pitch, yaw]");
      std::vector<double> ph(6, 0.0);
      if (const std::optional<Value> p = mm.find("phase")) ph = p->numbers(6, "[x, y, z, roll, pitch, yaw] in deg");
      for (int k = 0; k < 6; ++k) {
        vs.motionAmplitude[k] = k < 3 ? a[k] : degToRad(a[k]);
        vs.motionPhase[k] = degToRad(ph[k]);
      }
      vs.motionPeriod = mm.number("period", positiveUpTo(kMaxDuration));
    }
    if (const std::optional<Value> hull = m.find("hull")) vs.hull = readHull(*hull);
    spec.vessels.push_back(std::move(vs));
  }
}

/// A top-level block of the model file.
struct TopLevelBlock {
  std::string_view key;
  bool required;
  std::string_view expectation;  ///< what the block is, for the "missing" message
  void (*read)(const Value&, ModelSpec&);
};

/// The top-level blocks, read in this order whatever their order in the file (a block may use the ones
/// before it: lines need the environment and the line types).
constexpr std::array kTopLevelBlocks{
    TopLevelBlock{"title", false, "a title", readTitle},
    TopLevelBlock{"environment", true, "a map {water_depth, ...}", readEnvironment},
    TopLevelBlock{"line_types", true, "a list of line types {name, outer_diameter, ...}", readLineTypes},
    TopLevelBlock{"vessels", false, "a list of vessels {name, mode, position, ...}", readVessels},
    TopLevelBlock{"points", false,
                  "a list of free points {name, position, mass, volume, ...} joining line ends", readPoints},
    TopLevelBlock{"lines", true, "a list of lines {name, end_a, end_b, sections, ...}", readLines},
    TopLevelBlock{"statics", false, "a map of static solver settings", readStatics},
    TopLevelBlock{"dynamics", false, "a map of dynamic analysis settings", readDynamics},
    TopLevelBlock{"contact", false, "a map of line-to-line contact settings", readContact},
    TopLevelBlock{"hull_contact", false,
                  "a map of hull contact settings {stiffness, line_stiffness, restitution, ...}",
                  readHullContact},
    TopLevelBlock{"clearance", false,
                  "a map {required, pairs, margin, collision_allowed, allowed_impact_energy} (DNV-RP-F203 "
                  "clearance check)",
                  readClearance},
    TopLevelBlock{"wake_interference", false, "a list of wake pairs {upstream, downstream, model}",
                  readWakes},
    TopLevelBlock{"output", false, "a map of output settings", readOutput},
    TopLevelBlock{"fatigue", false, "a map {sections, sn_curves, tn_curves, ...} (fatigue of the dynamics)",
                  readFatigue},
};

ModelSpec readDocument(const YAML::Node& root, const std::string& source) {
  std::vector<std::string> keys;
  for (const TopLevelBlock& block : kTopLevelBlocks) keys.emplace_back(block.key);
  const Map m(Value(source, root, "", lineOf(root, 1)), keys);
  ModelSpec spec;
  spec.sourceFile = source;
  for (const TopLevelBlock& block : kTopLevelBlocks) {
    if (const std::optional<Value> v = m.find(block.key))
      block.read(*v, spec);
    else if (block.required)
      m.missing(block.key, block.expectation);
  }
  checkPointsUsed(spec);
  // A clash can part only a line that takes part in contact.
  for (const model::LineSpec& line : spec.lines)
    if (line.failure.clashEnergy > 0.0 && (!spec.contact.enabled || !line.contact))
      throw InputError(
          source, 0, "lines[" + line.name + "].failure.clash_energy",
          !spec.contact.enabled
              ? "a clash energy trigger needs line-to-line contact: add a 'contact' block, or give "
                "the failure a 'time' or 'tension'"
              : "a clash energy trigger on a line with 'contact: false': no clash can reach it");
  return spec;
}

[[noreturn]] void rethrowYamlError(const YAML::Exception& e, const std::string& source) {
  const int line = e.mark.is_null() ? 0 : e.mark.line + 1;
  const std::string where = e.mark.is_null() ? "" : fmt::format(" (column {})", e.mark.column + 1);
  throw InputError(source, line, "", "invalid YAML" + where + ": " + e.msg);
}

/// Largest model text read [bytes]: a model is kilobytes (RAO tables perhaps a megabyte); anything far
/// larger is the wrong file and would only cost memory.
constexpr std::size_t kMaxModelBytes = 64u << 20;
/// Deepest flow nesting ('[' and '{') accepted; models need 3 or 4 levels. Guards the recursive parser's
/// stack against crafted input.
constexpr int kMaxFlowNesting = 64;

/// Refuses flow nesting deeper than kMaxFlowNesting (quoted text and comments are skipped).
void checkNesting(const std::string& yaml, const std::string& source) {
  int depth = 0;
  int line = 1;
  char quote = 0;
  bool comment = false;
  for (std::size_t i = 0; i < yaml.size(); ++i) {
    const char c = yaml[i];
    if (c == '\n') {
      ++line;
      comment = false;
      continue;
    }
    if (comment) continue;
    if (quote) {
      if (c == quote) quote = 0;
      continue;
    }
    if (c == '"' || c == '\'') quote = c;
    else if (c == '#' && (i == 0 || std::isspace(static_cast<unsigned char>(yaml[i - 1])))) comment = true;
    else if (c == '[' || c == '{') {
      if (++depth > kMaxFlowNesting)
        throw InputError(source, line, "",
                         fmt::format("lists or maps nested more than {} levels deep ('[' or '{{')", kMaxFlowNesting));
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
}

/// Receives parser events and ignores them: used only to see whether a second document exists.
class IgnoreEvents : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
};

/// Where a second document starts, if the text holds one. Exactly two parser calls: never loops.
std::optional<YAML::Mark> secondDocument(const std::string& yaml) {
  std::istringstream in(yaml);
  YAML::Parser parser(in);
  IgnoreEvents ignore;
  if (!parser.HandleNextDocument(ignore)) return std::nullopt;
  // The mark of the second document is not exposed; report the position the stream reached.
  class FirstMark : public IgnoreEvents {
   public:
    std::optional<YAML::Mark> mark;
    void OnDocumentStart(const YAML::Mark& m) override {
      if (!mark) mark = m;
    }
  } second;
  if (!parser.HandleNextDocument(second)) return std::nullopt;
  return second.mark ? second.mark : std::optional<YAML::Mark>(YAML::Mark());
}

}  // namespace

model::ModelSpec readModelString(const std::string& yaml, const std::string& sourceName) {
  if (yaml.size() > kMaxModelBytes)
    throw InputError(sourceName, 0, "",
                     fmt::format("the model file is {} bytes; at most {} bytes are read (a model is a few "
                                 "kilobytes: is this the right file?)",
                                 yaml.size(), kMaxModelBytes));
  checkNesting(yaml, sourceName);
  YAML::Node root;
  try {
    // Not YAML::LoadAll: in yaml-cpp 0.7 it loops forever, allocating, on a stray ',' (fixed upstream
    // after 0.7). Load reads the first document; secondDocument looks for a second one in at most two
    // parser calls, so no input can make the reader loop.
    root = YAML::Load(yaml);
    if (const std::optional<YAML::Mark> second = secondDocument(yaml))
      throw InputError(sourceName, second->line + 1, "",
                       "expected a single YAML document, found more after the first one (a second "
                       "document after '---', or a stray character such as ',' or ']'); put one model per "
                       "file");
  } catch (const YAML::Exception& e) {
    rethrowYamlError(e, sourceName);
  }
  if (root.IsNull() || !root.IsDefined())
    throw InputError(sourceName, 0, "",
                     "the model is empty; expected at least the blocks environment, line_types and lines");
  try {
    return readDocument(root, sourceName);
  } catch (const YAML::Exception& e) {
    rethrowYamlError(e, sourceName);
  }
}

model::ModelSpec readModelFile(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path, 0, "", "cannot read the model file: it does not exist");
  if (fs::is_directory(path, ec))
    throw InputError(path, 0, "", "cannot read the model file: it is a directory");
  // A MoorDyn v2 input file is converted (docs/moordyn.md); its own errors name the deck's lines.
  if (isMoorDynDeck(path)) {
    const MoorDynConversion conversion = convertMoorDynDeck(readMoorDynDeck(path));
    model::ModelSpec spec;
    try {
      spec = readModelString(conversion.yaml, path);
    } catch (const InputError& e) {
      throw InputError(path, 0, "",
                       fmt::format("the model converted from this MoorDyn deck is not valid: {} (`tangle convert {} -o "
                                   "model.yaml` writes it, with the deck line of every value)",
                                   e.what(), path));
    }
    for (const std::string& note : conversion.notes) spec.warnings.push_back("MoorDyn deck: " + note);
    return spec;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "", "cannot open the model file for reading");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path, 0, "", "error while reading the model file");
  return readModelString(text.str(), path);
}

}  // namespace tangle::io
