#include "tangle/io/MoorDynDeck.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tangle/core/Error.hpp"
#include "tangle/core/PiecewiseLinear.hpp"

namespace tangle::io {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return s;
}

/// The words of a row up to a comment: as MoorDyn (Misc.cpp, str::split), the first word holding a '#' and
/// everything after it are left out (decks put notes after a row's values: "... 1.0  # data sheet").
std::vector<std::string> words(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  std::string w;
  while (in >> w && w.find('#') == std::string::npos) out.push_back(w);
  return out;
}

/// The leading letters of a word, upper case: MoorDyn2.cpp (str::decomposeString) splits an attachment word
/// into letters and a number, and the letters decide its kind ("Body1" -> "BODY", "R2A" -> "R").
std::string leadingLetters(const std::string& word) {
  const std::string u = upper(word);
  std::size_t i = 0;
  while (i < u.size() && std::isalpha(static_cast<unsigned char>(u[i]))) ++i;
  return u.substr(0, i);
}

bool isBlank(const std::string& line) {
  return std::all_of(line.begin(), line.end(), [](unsigned char c) { return std::isspace(c) != 0; });
}

/// The sections of a MoorDyn v2 deck (MoorDyn2.cpp, ReadInFile): the names a "---" line may hold.
enum class Section {
  None,
  LineTypes,
  Bodies,
  RodTypes,
  Rods,
  Points,
  Lines,
  Failures,
  SyropeIc,
  Options,
  Outputs,
  Unsupported
};

struct SectionName {
  const char* name;
  Section section;
  const char* why;  ///< for unsupported sections: what tangle lacks
};

// Longer names first: "LINE TYPES" must not be taken for "LINES", "ROD TYPES" for "RODS".
const SectionName kSections[] = {
    {"LINE DICTIONARY", Section::LineTypes, ""},
    {"LINE TYPES", Section::LineTypes, ""},
    {"LINE PROPERTIES", Section::Lines, ""},
    {"LINE LIST", Section::Lines, ""},
    {"LINES", Section::Lines, ""},
    {"ROD DICTIONARY", Section::RodTypes, ""},
    {"ROD TYPES", Section::RodTypes, ""},
    {"ROD PROPERTIES", Section::Rods, ""},
    {"ROD LIST", Section::Rods, ""},
    {"RODS", Section::Rods, ""},
    {"BODY PROPERTIES", Section::Bodies, ""},
    {"BODY LIST", Section::Bodies, ""},
    {"BODIES", Section::Bodies, ""},
    {"POINT PROPERTIES", Section::Points, ""},
    {"POINT LIST", Section::Points, ""},
    {"CONNECTION PROPERTIES", Section::Points, ""},
    {"NODE PROPERTIES", Section::Points, ""},
    {"POINTS", Section::Points, ""},
    {"FAILURE", Section::Failures, ""},
    {"SYROPE IC", Section::SyropeIc, ""},
    {"EXTERNAL LOADS", Section::Unsupported, "external loads on points and bodies are not supported"},
    {"OPTIONS", Section::Options, ""},
    {"OUTPUT", Section::Outputs, ""},
};

class DeckParser {
 public:
  DeckParser(const std::string& text, std::string file) : m_file(std::move(file)) {
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      m_lines.push_back(line);
    }
  }

  MoorDynDeck parse() {
    MoorDynDeck deck;
    deck.file = m_file;
    if (m_lines.size() >= 2 && m_lines[0].find("---") != std::string::npos) deck.title = trim(m_lines[1]);
    bool sawLineTypes = false;
    for (std::size_t i = 0; i < m_lines.size(); ++i) {
      if (m_lines[i].find("---") == std::string::npos) continue;
      const std::string head = upper(m_lines[i]);
      const SectionName* found = nullptr;
      for (const SectionName& s : kSections)
        if (head.find(s.name) != std::string::npos) {
          found = &s;
          break;
        }
      if (!found) continue;  // a decoration ("--- MoorDyn Input File ---", "--- need this line ---")
      const int lineNo = static_cast<int>(i) + 1;
      switch (found->section) {
        case Section::Unsupported:
          fail(lineNo, found->name, found->why);
          break;
        case Section::LineTypes:
          sawLineTypes = true;
          i = readTable(i + 3, [&](int n, const std::vector<std::string>& w) {
            deck.lineTypes.push_back(lineType(n, w));
          });
          break;
        case Section::Bodies:
          i = readTable(i + 3, [&](int n, const std::vector<std::string>& w) {
            deck.bodies.push_back(body(n, w, deck));
          });
          break;
        case Section::RodTypes:
          i = readTable(i + 3, [&](int n, const std::vector<std::string>& w) {
            deck.rodTypes.push_back(rodType(n, w));
          });
          break;
        case Section::Rods:
          i = readTable(
              i + 3, [&](int n, const std::vector<std::string>& w) { deck.rods.push_back(rod(n, w, deck)); });
          break;
        case Section::Points:
          i = readTable(i + 3, [&](int n, const std::vector<std::string>& w) {
            deck.points.push_back(point(n, w, deck));
          });
          break;
        case Section::Lines:
          i = readTable(i + 3, [&](int n, const std::vector<std::string>& w) {
            deck.lines.push_back(line(n, w, deck));
          });
          break;
        case Section::Failures:
          i = readTable(i + 3, [&](int n, const std::vector<std::string>& w) {
            deck.failures.push_back(failure(n, w));
          });
          break;
        case Section::SyropeIc:
          i = readTable(i + 3, [&](int n, const std::vector<std::string>& w) {
            if (w.size() < 3)
              fail(n, "SYROPE IC", "expected `Line(s) Tmax0 Tmean0` (e.g. `1,2 1.4e6 4.3e5`)");
            MoorDynSyropeIc ic;
            ic.sourceLine = n;
            std::string ids = w[0];
            std::replace(ids.begin(), ids.end(), ',', ' ');
            for (const std::string& id : words(ids)) ic.lines.push_back(integer(n, "SYROPE IC Line(s)", id));
            ic.maxTension = number(n, "SYROPE IC Tmax0", w[1]);
            ic.meanTension = number(n, "SYROPE IC Tmean0", w[2]);
            if (!(ic.maxTension > 0.0) || ic.meanTension < 0.0 || ic.meanTension > ic.maxTension)
              fail(n, "SYROPE IC", "expected 0 <= Tmean0 <= Tmax0 and Tmax0 > 0 (N)");
            deck.syropeIc.push_back(std::move(ic));
          });
          break;
        case Section::Options:
          i = readTable(i + 1, [&](int n, const std::vector<std::string>& w) {
            if (w.size() < 2) fail(n, "OPTIONS", "expected `value name [description]`");
            deck.options.push_back({w[1], w[0], n});
          });
          break;
        case Section::Outputs:
          i = readTable(i + 1, [&](int, const std::vector<std::string>& w) {
            for (const std::string& channel : w) {
              if (upper(channel) == "END") return;
              deck.outputs.push_back(channel);
            }
          });
          break;
        case Section::None:
          break;
      }
    }
    if (!sawLineTypes && deck.rods.empty())
      fail(0, "LINE TYPES", "the deck has no LINE TYPES section (is it a MoorDyn v2 input file?)");
    if (deck.lines.empty() && deck.rods.empty())
      fail(0, "LINES", "the deck has no line and no rod (a LINES or RODS section with at least one row)");
    for (const MoorDynPoint& p : deck.points)
      if (p.kind == MoorDynPointKind::Body && (p.body < 1 || p.body > static_cast<int>(deck.bodies.size())))
        fail(p.sourceLine, fmt::format("point {} Attachment", p.id),
             fmt::format("body {} does not exist (the deck has {} bodies)", p.body, deck.bodies.size()));
    for (const MoorDynRod& r : deck.rods) {
      if (r.body != 0 && (r.body < 1 || r.body > static_cast<int>(deck.bodies.size())))
        fail(r.sourceLine, fmt::format("rod {} Attachment", r.id),
             fmt::format("body {} does not exist (the deck has {} bodies)", r.body, deck.bodies.size()));
      const bool known = std::any_of(deck.rodTypes.begin(), deck.rodTypes.end(),
                                     [&](const MoorDynRodType& t) { return t.name == r.rodType; });
      if (!known)
        fail(r.sourceLine, fmt::format("rod {} RodType", r.id),
             fmt::format("no rod type named '{}'", r.rodType));
    }
    // Lines may be listed before the points they name only if MoorDyn would read them: MoorDyn reads the
    // sections in its own order (types, points, lines), so check the references once everything is read.
    for (const MoorDynLine& l : deck.lines) {
      for (const auto& [p, r] : {std::pair{l.pointA, l.rodA}, std::pair{l.pointB, l.rodB}}) {
        if (r != 0) {
          if (r < 1 || r > static_cast<int>(deck.rods.size()))
            fail(l.sourceLine, fmt::format("line {} AttachA/AttachB", l.id),
                 fmt::format("rod {} does not exist (the deck has {} rods)", r, deck.rods.size()));
          continue;
        }
        if (p < 1 || p > static_cast<int>(deck.points.size()))
          fail(l.sourceLine, fmt::format("line {} AttachA/AttachB", l.id),
               fmt::format("point {} does not exist (the deck has {} points)", p, deck.points.size()));
      }
      if (l.rodA != 0 && l.rodA == l.rodB && l.rodEndA == l.rodEndB)
        fail(l.sourceLine, fmt::format("line {} AttachB", l.id),
             "both ends of the line are on the same rod end");
      const bool known = std::any_of(deck.lineTypes.begin(), deck.lineTypes.end(),
                                     [&](const MoorDynLineType& t) { return t.name == l.lineType; });
      if (!known)
        fail(l.sourceLine, fmt::format("line {} LineType", l.id),
             fmt::format("no line type named '{}'", l.lineType));
    }
    for (const MoorDynFailure& f : deck.failures) {
      if (f.point < 1 || f.point > static_cast<int>(deck.points.size()))
        fail(f.sourceLine, fmt::format("failure {} Point", f.id),
             fmt::format("point {} does not exist (the deck has {} points)", f.point, deck.points.size()));
      for (const int l : f.lines) {
        if (l < 1 || l > static_cast<int>(deck.lines.size()))
          fail(f.sourceLine, fmt::format("failure {} Line(s)", f.id),
               fmt::format("line {} does not exist (the deck has {} lines)", l, deck.lines.size()));
        const MoorDynLine& line = deck.lines[static_cast<std::size_t>(l - 1)];
        if (line.pointA != f.point && line.pointB != f.point)
          fail(f.sourceLine, fmt::format("failure {} Line(s)", f.id),
               fmt::format("line {} is not attached to point {} (its ends are at points {} and {})", l,
                           f.point, line.pointA, line.pointB));
      }
    }
    return deck;
  }

 private:
  /// One FAILURE row: FailureID Point Line(s) FailTime FailTen (MoorDyn2.cpp; docs/inputs.rst "Failure").
  MoorDynFailure failure(int n, const std::vector<std::string>& w) const {
    if (w.size() < 4)
      fail(n, "FAILURE", "expected `FailureID Point Line(s) FailTime [FailTen]` (e.g. `1 3 1,2 0 1.2e6`)");
    MoorDynFailure f;
    f.id = integer(n, "FAILURE FailureID", w[0]);
    f.sourceLine = n;
    const auto key = [&](const char* column) { return fmt::format("failure {} {}", f.id, column); };
    std::string letters, digits;
    for (const char c : upper(w[1]))
      (std::isalpha(static_cast<unsigned char>(c)) && digits.empty() ? letters : digits) += c;
    if (letters == "R" || letters == "ROD")
      fail(n, key("Point"),
           fmt::format("'{}': a failure at a rod end (rods are not supported by tangle)", w[1]));
    if (!(letters.empty() || letters == "C" || letters == "CON" || letters == "P" || letters == "POINT"))
      fail(n, key("Point"), fmt::format("unknown point '{}' (expected a point number, e.g. 3 or P3)", w[1]));
    f.point = integer(n, key("Point"), digits);
    std::string list = w[2];
    std::replace(list.begin(), list.end(), ',', ' ');
    for (const std::string& l : words(list)) f.lines.push_back(integer(n, key("Line(s)"), l));
    if (f.lines.empty()) fail(n, key("Line(s)"), "expected the lines that part from the point, e.g. 1,2");
    f.time = number(n, key("FailTime"), w[3]);
    f.tension = w.size() > 4 ? number(n, key("FailTen"), w[4]) : 0.0;
    if (f.time < 0.0 || f.tension < 0.0)
      fail(n, key(f.time < 0.0 ? "FailTime" : "FailTen"), "expected a value >= 0 (0: no such trigger)");
    return f;
  }

  [[noreturn]] void fail(int line, const std::string& key, const std::string& expected) const {
    throw InputError(m_file, line, key, expected);
  }

  static std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string::npos) return "";
    return s.substr(b, s.find_last_not_of(" \t") - b + 1);
  }

  /// Reads rows from `first` to the next "---" line (or the end); returns the index of the last line read.
  template <class Row>
  std::size_t readTable(std::size_t first, Row row) {
    std::size_t i = first;
    for (; i < m_lines.size(); ++i) {
      if (m_lines[i].find("---") != std::string::npos) break;
      if (isBlank(m_lines[i])) continue;
      row(static_cast<int>(i) + 1, words(m_lines[i]));
    }
    return i - 1;
  }

  double number(int line, const std::string& key, const std::string& word) const {
    const std::optional<double> v = deckNumber(word);
    if (!v) fail(line, key, fmt::format("expected a number, got '{}'", word));
    return *v;
  }

  /// A table's ID column: MoorDyn's rule, IDs 1, 2, 3, ... in order (`read` rows read before this one).
  int sequentialId(int line, const std::string& table, const std::string& what, const std::string& word,
                   std::size_t read) const {
    const int id = integer(line, table + " ID", word);
    if (id != static_cast<int>(read) + 1)
      fail(line, table + " ID",
           fmt::format("{} IDs must run 1, 2, 3, ... in order (MoorDyn's rule): expected {}, got {}", what,
                       read + 1, id));
    return id;
  }

  int integer(int line, const std::string& key, const std::string& word) const {
    const double v = number(line, key, word);
    // Range first: converting a double outside int's range is undefined (the reader fuzzer found 7.8e125).
    constexpr double kLargest = 2147483647.0;
    if (!(std::abs(v) <= kLargest) || v != std::floor(v))
      fail(line, key, fmt::format("expected an integer, got '{}'", word));
    return static_cast<int>(v);
  }

  /// A value of a line-type column that MoorDyn may also take as a table file or a bar-separated set
  /// (nonlinear or viscoelastic laws): tangle takes a single number.
  double scalarProperty(int line, const std::string& type, const char* column, const std::string& word,
                        const char* what) const {
    const std::string key = fmt::format("line type {} {}", type, column);
    if (word.find('|') != std::string::npos || upper(word).rfind("SYROPE:", 0) == 0)
      fail(
          line, key,
          fmt::format("'{}': {} are not supported by tangle (one constant value per line type)", word, what));
    const std::optional<double> v = deckNumber(word);
    if (!v)
      fail(line, key,
           fmt::format("'{}' is not a number: {} from a table file are not supported by tangle (one constant "
                       "value per line type)",
                       word, what));
    return *v;
  }

  /// MoorDyn's EA curve file (MoorDyn2.hpp, read_curve; relative to the deck's folder): three header lines,
  /// then `strain tension` rows, strains and tensions increasing.
  void readTensionStrain(int n, MoorDynLineType& t, const std::string& word) const {
    const std::string key = fmt::format("line type {} EA", t.name);
    const std::filesystem::path path = std::filesystem::path(m_file).parent_path() / word;
    t.tensionStrainFile = path.string();
    t.tensionStrain = readCurve(n, key, path, word);
    // EA: the largest slope of the curve tangle builds from it (from (0, 0): MoorDynConversion).
    std::vector<double> strains{0.0}, tensions{0.0};
    for (const auto& [strain, tension] : t.tensionStrain)
      if (strain > 0.0) {
        strains.push_back(strain);
        tensions.push_back(tension);
      }
    t.axialStiffness = core::PiecewiseLinear(strains, tensions).largestSlope();
    if (t.tensionStrain.back().first > 0.0)
      t.moorDynStiffness = t.tensionStrain.back().second / t.tensionStrain.back().first;
  }

  /// A curve file as MoorDyn's read_curve reads it: three header lines, then `strain tension` rows, both
  /// increasing from >= 0.
  std::vector<std::pair<double, double>> readCurve(int n, const std::string& key,
                                                   const std::filesystem::path& path,
                                                   const std::string& word) const {
    std::ifstream in(path);
    if (!in)
      fail(n, key,
           fmt::format("'{}' is neither a number nor a curve file that can be opened ({})", word,
                       path.string()));
    std::vector<std::pair<double, double>> curve;
    std::string text;
    for (int row = 1; std::getline(in, text); ++row) {
      if (row <= 3) continue;  // headers
      if (!text.empty() && text.back() == '\r') text.pop_back();
      const std::vector<std::string> v = words(text);
      if (v.empty()) continue;
      const auto value = [&](std::size_t k, const char* what) {
        const std::optional<double> x = v.size() > k ? deckNumber(v[k]) : std::nullopt;
        if (!x)
          throw InputError(path.string(), row, what,
                           fmt::format("expected `strain tension` (two numbers), got '{}'", text));
        return *x;
      };
      const double strain = value(0, "strain"), tension = value(1, "tension");
      const double lastStrain = curve.empty() ? -1.0 : curve.back().first;
      const double lastTension = curve.empty() ? -1.0 : curve.back().second;
      if (!(strain > lastStrain) || strain < 0.0 || !(tension > lastTension) || tension < 0.0)
        throw InputError(
            path.string(), row, "strain tension",
            "strains and tensions increasing from >= 0 (tangle's curve is monotonic: a rope that "
            "softens to nothing has no equilibrium)");
      curve.push_back({strain, tension});
    }
    if (curve.size() < 2)
      fail(n, key, fmt::format("the curve file {} has fewer than two points", path.string()));
    return curve;
  }

  /// A SYROPE line type's EA "SYROPE:settings|alphaMBL|vbeta" (MoorDyn2.cpp, readLineType and
  /// read_syrope_working_curves): the settings file beside the deck, rows `value name`: OWC (the curve file,
  /// relative to the deck), WCType (linear, quadratic, exp), k1, k2.
  void readSyrope(int n, MoorDynLineType& t, const std::string& word) const {
    const std::string key = fmt::format("line type {} EA", t.name);
    const std::vector<std::string> parts = [&] {
      std::string list = word.substr(7);
      std::replace(list.begin(), list.end(), '|', ' ');
      return words(list);
    }();
    if (parts.size() != 3)
      fail(n, key, fmt::format("'{}': expected SYROPE:settings-file|alphaMBL|vbeta (3 values)", word));
    t.syrope = true;
    t.dynamicStiffness = number(n, key, parts[1]);
    t.dynamicStiffnessSlope = number(n, key, parts[2]);
    if (!(t.dynamicStiffness > 0.0) || t.dynamicStiffnessSlope < 0.0)
      fail(n, key, fmt::format("'{}': expected alphaMBL > 0 and vbeta >= 0", word));
    const std::filesystem::path folder = std::filesystem::path(m_file).parent_path();
    const std::filesystem::path settings = folder / parts[0];
    t.syropeSettingsFile = settings.string();
    std::ifstream in(settings);
    if (!in) fail(n, key, fmt::format("the SYROPE settings file {} cannot be opened", settings.string()));
    std::string owc;
    bool haveK1 = false, haveK2 = false;
    std::string text;
    for (int row = 1; std::getline(in, text); ++row) {
      const std::vector<std::string> v = words(text);
      if (v.size() < 2) continue;
      const std::string name = upper(v[1]);
      const auto value = [&] {
        const std::optional<double> x = deckNumber(v[0]);
        if (!x)
          throw InputError(settings.string(), row, v[1], fmt::format("expected a number, got '{}'", v[0]));
        return *x;
      };
      if (name == "OWC") {
        owc = v[0];
      } else if (name == "WCTYPE") {
        t.syropeForm = lower(v[0]);
        if (t.syropeForm != "linear" && t.syropeForm != "quadratic" && t.syropeForm != "exp")
          throw InputError(settings.string(), row, "WCType",
                           fmt::format("expected LINEAR, QUADRATIC or EXP, got '{}'", v[0]));
      } else if (name == "K1") {
        t.syropeK1 = value();
        haveK1 = true;
      } else if (name == "K2") {
        t.syropeK2 = value();
        haveK2 = true;
      }
    }
    if (owc.empty() || t.syropeForm.empty() || !haveK1 || !haveK2)
      fail(n, key,
           fmt::format("the SYROPE settings file {} needs OWC, WCType, k1 and k2", settings.string()));
    const std::filesystem::path curve = folder / owc;
    t.syropeCurveFile = curve.string();
    t.syropeCurve = readCurve(n, key, curve, owc);
    // The static EA's stand-in (rod stiffness, notes): the curve's largest slope.
    std::vector<double> strains, tensions;
    for (const auto& [s, f] : t.syropeCurve) {
      strains.push_back(s);
      tensions.push_back(f);
    }
    t.axialStiffness = core::PiecewiseLinear(strains, tensions).largestSlope();
  }

  MoorDynLineType lineType(int n, const std::vector<std::string>& w) const {
    if (w.size() < 10)
      fail(n, "LINE TYPES",
           fmt::format("expected 10 columns (TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx), got {}",
                       w.size()));
    MoorDynLineType t;
    t.name = w[0];
    t.sourceLine = n;
    const auto key = [&](const char* column) { return fmt::format("line type {} {}", t.name, column); };
    t.diameter = number(n, key("Diam"), w[1]);
    t.massPerLength = number(n, key("Mass/m"), w[2]);
    // A rope's dashpots "BA|BA_d" (MoorDyn2.cpp, readLineType; BA_d 0 if not given): BA its slow one.
    const auto ropeDashpots = [&](const char* rope) {
      const std::vector<double> damping = bar(n, key("BA/-zeta"), w[4]);
      if (damping.size() > 2)
        fail(n, key("BA/-zeta"), fmt::format("'{}': expected BA or BA|BA_d (1 or 2 values)", w[4]));
      t.axialDamping = damping[0];
      if (damping.size() == 2) t.dynamicDamping = damping[1];
      if (!(t.axialDamping > 0.0) || t.dynamicDamping < 0.0)
        fail(n, key("BA/-zeta"),
             fmt::format("'{}': a {} rope needs BA > 0 in N s (its slow dashpot; not a damping ratio) and "
                         "BA_d >= 0",
                         w[4], rope));
    };
    if (upper(w[3]).rfind("SYROPE:", 0) == 0) {
      readSyrope(n, t, w[3]);
      ropeDashpots("SYROPE");
    } else if (w[3].find('|') != std::string::npos) {
      // MoorDyn's viscoelastic model (MoorDyn2.cpp, readLineType): "EA_s|EA_d" (a constant dynamic stiffness)
      // or "EA_s|alphaMBL|vbeta" (EA_d = alphaMBL + vbeta T_mean).
      const std::vector<double> parts = bar(n, key("EA"), w[3]);
      if (parts.size() != 2 && parts.size() != 3)
        fail(n, key("EA"), fmt::format("'{}': expected EA|EA_d or EA|alphaMBL|vbeta (2 or 3 values)", w[3]));
      t.axialStiffness = parts[0];
      t.dynamicStiffness = parts[1];
      if (parts.size() == 3) t.dynamicStiffnessSlope = parts[2];
      if (!(t.dynamicStiffness > t.axialStiffness) || t.dynamicStiffnessSlope < 0.0)
        fail(n, key("EA"),
             fmt::format("'{}': the dynamic stiffness must exceed the static one and its slope be >= 0",
                         w[3]));
      ropeDashpots("viscoelastic");
    } else if (!deckNumber(w[3])) {
      readTensionStrain(n, t, w[3]);  // a nonlinear EA from a curve file
    } else {
      t.axialStiffness = scalarProperty(n, t.name, "EA", w[3], "viscoelastic axial stiffness laws");
    }
    if (t.dynamicStiffness == 0.0 && !t.syrope)
      t.axialDamping =
          scalarProperty(n, t.name, "BA/-zeta", w[4], "tension-dependent or viscoelastic axial damping laws");
    t.bendingStiffness = scalarProperty(n, t.name, "EI", w[5], "nonlinear bending stiffness laws");
    t.dragNormal = number(n, key("Cd"), w[6]);
    t.addedMassNormal = number(n, key("Ca"), w[7]);
    t.dragAxial = number(n, key("CdAx"), w[8]);
    t.addedMassAxial = number(n, key("CaAx"), w[9]);
    if (w.size() > 10) {
      const double lift = number(n, key("Cl"), w[10]);
      if (lift != 0.0)
        fail(n, key("Cl"), "vortex-induced vibration (a lift coefficient Cl > 0) is not supported by tangle");
      if (w.size() != 11 && w.size() != 13)
        fail(n, "LINE TYPES", fmt::format("expected 10, 11 or 13 columns, got {}", w.size()));
    }
    if (!(t.diameter > 0.0)) fail(n, key("Diam"), "expected a diameter > 0");
    if (!(t.massPerLength > 0.0)) fail(n, key("Mass/m"), "expected a mass per length > 0");
    if (!(t.axialStiffness > 0.0)) fail(n, key("EA"), "expected EA > 0");
    if (!(t.moorDynStiffness > 0.0)) t.moorDynStiffness = t.axialStiffness;
    if (t.bendingStiffness < 0.0) fail(n, key("EI"), "expected EI >= 0");
    for (const auto& [value, column] : {std::pair{t.dragNormal, "Cd"}, std::pair{t.addedMassNormal, "Ca"},
                                        std::pair{t.dragAxial, "CdAx"}, std::pair{t.addedMassAxial, "CaAx"}})
      if (value < 0.0) fail(n, key(column), "expected a coefficient >= 0");
    return t;
  }

  /// A column of `|`-separated numbers (MoorDyn's CG, I, CdA, Ca columns).
  std::vector<double> bar(int n, const std::string& key, const std::string& word) const {
    std::string list = word;
    std::replace(list.begin(), list.end(), '|', ' ');
    std::vector<double> out;
    for (const std::string& v : words(list)) out.push_back(number(n, key, v));
    if (out.empty())
      fail(n, key, fmt::format("expected a number or numbers separated by '|', got '{}'", word));
    return out;
  }

  /// One BODIES row: ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca* (MoorDyn2.cpp, readBody).
  MoorDynBody body(int n, const std::vector<std::string>& w, const MoorDynDeck& deck) const {
    if (w.size() < 14)
      fail(
          n, "BODIES",
          fmt::format("expected 14 columns (ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG I Volume CdA Ca), got {}",
                      w.size()));
    MoorDynBody b;
    b.sourceLine = n;
    b.id = sequentialId(n, "BODIES", "body", w[0], deck.bodies.size());
    const auto key = [&](const char* column) { return fmt::format("body {} {}", b.id, column); };
    b.kindWord = w[1];
    const std::string letters = leadingLetters(w[1]);
    if (letters == "ANCHOR" || letters == "FIXED" || letters == "FIX")
      b.kind = MoorDynBodyKind::Fixed;
    else if (letters == "VESSEL" || letters == "VES" || letters == "COUPLED" || letters == "CPLD")
      b.kind = MoorDynBodyKind::Coupled;
    else if (letters == "VESSELPINNED" || letters == "VESPIN" || letters == "CPLDPIN" ||
             letters == "COUPLEDPINNED")
      b.kind = MoorDynBodyKind::CoupledPinned;
    else
      b.kind = MoorDynBodyKind::Free;  // MoorDyn: anything else is free
    const char* const names[] = {"X0", "Y0", "Z0", "r0", "p0", "y0"};
    for (int k = 0; k < 3; ++k) {
      b.position[k] = number(n, key(names[k]), w[2 + static_cast<std::size_t>(k)]);
      b.rotation[k] = number(n, key(names[3 + k]), w[5 + static_cast<std::size_t>(k)]);
    }
    b.mass = number(n, key("Mass"), w[8]);
    const std::vector<double> cg = bar(n, key("CG"), w[9]);
    if (cg.size() == 1)
      b.centreOfGravity = Vec3(0.0, 0.0, cg[0]);
    else if (cg.size() == 3)
      b.centreOfGravity = Vec3(cg[0], cg[1], cg[2]);
    else
      fail(n, key("CG"), "expected 1 (z) or 3 (x|y|z) numbers");
    const std::vector<double> inertia = bar(n, key("I"), w[10]);
    if (inertia.size() == 1)
      b.inertia = Vec3::Constant(inertia[0]);
    else if (inertia.size() == 3)
      b.inertia = Vec3(inertia[0], inertia[1], inertia[2]);
    else
      fail(n, key("I"), "expected 1 or 3 (Ix|Iy|Iz) numbers");
    b.volume = number(n, key("Volume"), w[11]);
    // CdA: 1 value (all six), 2 (translations | rotations), 3 (x|y|z, the same for the rotations) or 6.
    // (MoorDyn2.cpp's loops for 3 and 6 values skip the first one; tangle reads them as documented.)
    const std::vector<double> cda = bar(n, key("CdA"), w[12]);
    if (cda.size() == 1) {
      b.dragArea.fill(cda[0]);
    } else if (cda.size() == 2) {
      for (std::size_t k = 0; k < 3; ++k) {
        b.dragArea[k] = cda[0];
        b.dragArea[k + 3] = cda[1];
      }
    } else if (cda.size() == 3) {
      for (std::size_t k = 0; k < 3; ++k) b.dragArea[k] = b.dragArea[k + 3] = cda[k];
    } else if (cda.size() == 6) {
      for (std::size_t k = 0; k < 6; ++k) b.dragArea[k] = cda[k];
    } else {
      fail(n, key("CdA"), "expected 1, 2, 3 or 6 numbers separated by '|'");
    }
    const std::vector<double> ca = bar(n, key("Ca"), w[13]);
    if (ca.size() == 1)
      b.addedMass = Vec3::Constant(ca[0]);
    else if (ca.size() == 3)
      b.addedMass = Vec3(ca[0], ca[1], ca[2]);
    else
      fail(n, key("Ca"), "expected 1 or 3 (x|y|z) numbers");
    if (b.mass < 0.0) fail(n, key("Mass"), "expected a mass >= 0");
    if (b.volume < 0.0) fail(n, key("Volume"), "expected a volume >= 0");
    if ((b.inertia.array() < 0.0).any()) fail(n, key("I"), "expected moments of inertia >= 0");
    for (const double v : b.dragArea)
      if (v < 0.0) fail(n, key("CdA"), "expected drag areas >= 0");
    if ((b.addedMass.array() < 0.0).any()) fail(n, key("Ca"), "expected coefficients >= 0");
    return b;
  }

  /// One ROD TYPES row: TypeName Diam Mass/m Cd Ca CdEnd CaEnd (MoorDyn2.cpp, readRodProps).
  MoorDynRodType rodType(int n, const std::vector<std::string>& w) const {
    if (w.size() < 7)
      fail(n, "ROD TYPES",
           fmt::format("expected 7 columns (TypeName Diam Mass/m Cd Ca CdEnd CaEnd), got {}", w.size()));
    MoorDynRodType t;
    t.name = w[0];
    t.sourceLine = n;
    const auto key = [&](const char* column) { return fmt::format("rod type {} {}", t.name, column); };
    t.diameter = number(n, key("Diam"), w[1]);
    t.massPerLength = number(n, key("Mass/m"), w[2]);
    t.drag = number(n, key("Cd"), w[3]);
    t.addedMass = number(n, key("Ca"), w[4]);
    t.dragEnd = number(n, key("CdEnd"), w[5]);
    t.addedMassEnd = number(n, key("CaEnd"), w[6]);
    if (!(t.diameter > 0.0)) fail(n, key("Diam"), "expected a diameter > 0");
    if (!(t.massPerLength > 0.0)) fail(n, key("Mass/m"), "expected a mass per length > 0");
    for (const auto& [value, column] : {std::pair{t.drag, "Cd"}, std::pair{t.addedMass, "Ca"},
                                        std::pair{t.dragEnd, "CdEnd"}, std::pair{t.addedMassEnd, "CaEnd"}})
      if (value < 0.0) fail(n, key(column), "expected a coefficient >= 0");
    return t;
  }

  /// One RODS row: ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs (MoorDyn2.cpp, readRod).
  MoorDynRod rod(int n, const std::vector<std::string>& w, const MoorDynDeck& deck) const {
    if (w.size() < 11)
      fail(n, "RODS",
           fmt::format(
               "expected 11 columns (ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs), got {}",
               w.size()));
    MoorDynRod r;
    r.sourceLine = n;
    r.id = sequentialId(n, "RODS", "rod", w[0], deck.rods.size());
    const auto key = [&](const char* column) { return fmt::format("rod {} {}", r.id, column); };
    r.rodType = w[1];
    r.kindWord = w[2];
    const std::string letters = leadingLetters(w[2]);
    if (letters == "ANCHOR" || letters == "FIXED" || letters == "FIX") {
      r.kind = MoorDynRodKind::Fixed;
    } else if (letters == "PINNED" || letters == "PIN") {
      r.kind = MoorDynRodKind::Pinned;
    } else if (letters == "POINT" || letters == "CON" || letters == "FREE") {
      r.kind = MoorDynRodKind::Free;
    } else if (letters == "VESSEL" || letters == "VES" || letters == "COUPLED" || letters == "CPLD") {
      r.kind = MoorDynRodKind::Coupled;
    } else if (letters == "VESSELPINNED" || letters == "VESPIN" || letters == "CPLDPIN" ||
               letters == "COUPLEDPINNED") {
      r.kind = MoorDynRodKind::CoupledPinned;
    } else if (letters == "BODY") {
      // Body<n> (fixed to it) or Body<n>Pinned (end A on it): MoorDyn2.cpp, decomposeString.
      const std::string u = upper(w[2]);
      std::size_t j = letters.size();
      while (j < u.size() && std::isdigit(static_cast<unsigned char>(u[j]))) ++j;
      const std::string rest = u.substr(j);
      if (j == letters.size() || !(rest.empty() || rest == "PINNED" || rest == "PIN"))
        fail(n, key("Attachment"), fmt::format("'{}': expected Body<n> or Body<n>Pinned (e.g. Body1)", w[2]));
      r.body = integer(n, key("Attachment"), u.substr(letters.size(), j - letters.size()));
      r.kind = rest.empty() ? MoorDynRodKind::Fixed : MoorDynRodKind::Pinned;
    } else if (letters == "TURBINE") {
      fail(n, key("Attachment"), fmt::format("'{}': rods on turbines (FAST.Farm) are not supported", w[2]));
    } else {
      fail(n, key("Attachment"),
           fmt::format("unknown rod type '{}' (expected Fixed/Anchor, Pinned, Free, Coupled/Vessel or "
                       "CoupledPinned/VesselPinned)",
                       w[2]));
    }
    const char* const names[] = {"Xa", "Ya", "Za", "Xb", "Yb", "Zb"};
    for (int k = 0; k < 3; ++k) {
      r.endA[k] = number(n, key(names[k]), w[3 + static_cast<std::size_t>(k)]);
      r.endB[k] = number(n, key(names[3 + k]), w[6 + static_cast<std::size_t>(k)]);
    }
    r.segments = integer(n, key("NumSegs"), w[9]);
    r.outputs = w[10];
    if (r.segments < 0) fail(n, key("NumSegs"), "expected NumSegs >= 0 (0 for a zero-length rod)");
    const double length = r.length();
    if (length > 0.0 && r.segments < 1)
      fail(n, key("NumSegs"),
           "expected at least 1 segment for a rod of length > 0 (0 only when its ends coincide)");
    return r;
  }

  MoorDynPoint point(int n, const std::vector<std::string>& w, const MoorDynDeck& deck) const {
    if (w.size() < 9)
      fail(n, "POINTS",
           fmt::format("expected 9 columns (ID Attachment X Y Z Mass Volume CdA Ca), got {}", w.size()));
    MoorDynPoint p;
    p.sourceLine = n;
    p.id = sequentialId(n, "POINTS", "point", w[0], deck.points.size());
    const auto key = [&](const char* column) { return fmt::format("point {} {}", p.id, column); };
    p.kindWord = w[1];
    const std::string kind = upper(w[1]);
    // MoorDyn2.cpp splits the word into letters and a number; the letters decide the kind.
    const std::string letters = leadingLetters(w[1]);
    if (letters == "ANCHOR" || letters == "FIXED" || letters == "FIX") {
      p.kind = MoorDynPointKind::Fixed;
    } else if (letters == "FAIRLEAD" || letters == "VESSEL" || letters == "VES" || letters == "COUPLED" ||
               letters == "CPLD") {
      p.kind = MoorDynPointKind::Coupled;
    } else if (letters == "POINT" || letters == "CONNECT" || letters == "CON" || letters == "FREE") {
      p.kind = MoorDynPointKind::Free;
    } else if (letters == "BODY" || letters == "B") {
      p.kind = MoorDynPointKind::Body;
      const std::string digits = kind.substr(letters.size());
      if (digits.empty())
        fail(n, key("Attachment"), fmt::format("'{}': expected the body's number, e.g. Body1", w[1]));
      p.body = integer(n, key("Attachment"), digits);
    } else if (letters == "TURBINE") {
      fail(n, key("Attachment"), fmt::format("'{}': points on turbines (FAST.Farm) are not supported", w[1]));
    } else {
      fail(n, key("Attachment"),
           fmt::format("unknown point type '{}' (expected Fixed/Anchor, Coupled/Vessel/Fairlead or "
                       "Free/Point/Connect)",
                       w[1]));
    }
    for (int k = 0; k < 3; ++k) p.position[k] = number(n, key(k == 0 ? "X" : k == 1 ? "Y" : "Z"), w[2 + k]);
    p.mass = number(n, key("Mass"), w[5]);
    p.volume = number(n, key("Volume"), w[6]);
    std::size_t next = 7;
    if (w.size() >= 12) {
      for (int k = 0; k < 3; ++k)
        if (number(n, key("F"), w[7 + k]) != 0.0)
          fail(n,
               key(k == 0   ? "FX"
                   : k == 1 ? "FY"
                            : "FZ"),
               "a constant external force on a point is not supported by tangle (use mass and volume for "
               "weight and "
               "buoyancy)");
      next = 10;
    }
    p.dragArea = number(n, key("CdA"), w[next]);
    p.addedMass = number(n, key("Ca"), w[next + 1]);
    if (p.mass < 0.0) fail(n, key("Mass"), "expected a mass >= 0");
    if (p.volume < 0.0) fail(n, key("Volume"), "expected a volume >= 0");
    if (p.dragArea < 0.0) fail(n, key("CdA"), "expected CdA >= 0");
    if (p.addedMass < 0.0) fail(n, key("Ca"), "expected Ca >= 0");
    return p;
  }

  /// A line end's attachment: a point number (`3`, `P3`, `C3`), or a rod's end (`R2A`, `ROD2B`: rod, end).
  struct Attachment {
    int point = 0;
    int rod = 0;
    int rodEnd = 0;
  };

  Attachment attachment(int n, const std::string& key, const std::string& word) const {
    const std::string u = upper(word);
    const std::string letters = leadingLetters(word);
    const std::size_t i = letters.size();
    if (letters == "R" || letters == "ROD") {
      // MoorDyn2.cpp (decomposeString): letters, the rod's number, then A or B.
      std::size_t j = i;
      while (j < u.size() && std::isdigit(static_cast<unsigned char>(u[j]))) ++j;
      const std::string end = u.substr(j);
      if (j == i || (end != "A" && end != "B"))
        fail(n, key, fmt::format("'{}': expected a rod's end as R<number>A or R<number>B (e.g. R1A)", word));
      Attachment a;
      a.rod = integer(n, key, u.substr(i, j - i));
      a.rodEnd = end == "A" ? 0 : 1;
      return a;
    }
    if (letters == "B" || letters == "BODY")
      fail(n, key,
           fmt::format(
               "'{}': a line end on a body itself: attach it to a point on the body (Body<n> in POINTS)",
               word));
    if (!(letters.empty() || letters == "C" || letters == "CON" || letters == "P" || letters == "POINT"))
      fail(n, key, fmt::format("'{}': expected a point number (e.g. 3 or P3) or a rod end (e.g. R1A)", word));
    Attachment a;
    a.point = integer(n, key, word.substr(i));
    return a;
  }

  MoorDynLine line(int n, const std::vector<std::string>& w, const MoorDynDeck& deck) const {
    if (w.size() < 7)
      fail(
          n, "LINES",
          fmt::format("expected 7 columns (ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs), got {}",
                      w.size()));
    MoorDynLine l;
    l.sourceLine = n;
    l.id = sequentialId(n, "LINES", "line", w[0], deck.lines.size());
    const auto key = [&](const char* column) { return fmt::format("line {} {}", l.id, column); };
    l.lineType = w[1];
    const Attachment a = attachment(n, key("AttachA"), w[2]);
    const Attachment b = attachment(n, key("AttachB"), w[3]);
    l.pointA = a.point;
    l.rodA = a.rod;
    l.rodEndA = a.rodEnd;
    l.pointB = b.point;
    l.rodB = b.rod;
    l.rodEndB = b.rodEnd;
    l.length = number(n, key("UnstrLen"), w[4]);
    l.segments = integer(n, key("NumSegs"), w[5]);
    l.outputs = w[6];
    if (!(l.length > 0.0)) fail(n, key("UnstrLen"), "expected an unstretched length > 0");
    if (l.segments < 1) fail(n, key("NumSegs"), "expected at least 1 segment");
    if (l.rodA == 0 && l.rodB == 0 && l.pointA == l.pointB)
      fail(n, key("AttachB"), "both ends of the line are on the same point");
    return l;
  }

  std::string m_file;
  std::vector<std::string> m_lines;
};

}  // namespace

std::optional<double> deckNumber(std::string_view word) {
  double v = 0.0;
  const char* end = word.data() + word.size();
  const auto [ptr, ec] = std::from_chars(word.data(), end, v);
  if (word.empty() || ec != std::errc() || ptr != end) return std::nullopt;
  return v;
}

MoorDynDeck parseMoorDynDeck(const std::string& text, const std::string& file) {
  return DeckParser(text, file).parse();
}

MoorDynDeck readMoorDynDeck(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "", "cannot open the file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parseMoorDynDeck(buffer.str(), path);
}

bool isMoorDynDeck(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::string line;
  // A line of dashes naming one of the sections MoorDyn2.cpp looks for (findStartOfSection): a deck of rods
  // or bodies only has no line types (MoorDyn's RodPinnedFloating.txt). Only lines that start with the
  // dashes: a YAML comment ("# --- lines ---") starts with '#'.
  static const char* const kSections[] = {"LINE TYPES",      "LINE DICTIONARY", "ROD TYPES",
                                          "ROD DICTIONARY",  "BODIES",          "BODY LIST",
                                          "BODY PROPERTIES", "ROD LIST",        "ROD PROPERTIES",
                                          "POINT LIST",      "NODE PROPERTIES", "CONNECTION PROPERTIES"};
  for (int i = 0; i < 200 && std::getline(in, line); ++i) {
    const std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line.compare(start, 3, "---") != 0) continue;
    const std::string head = upper(line);
    for (const char* section : kSections)
      if (head.find(section) != std::string::npos) return true;
    // "RODS" alone (not inside another word) also names the rods' section.
    const std::size_t rods = head.find(" RODS ");
    if (rods != std::string::npos) return true;
  }
  return false;
}

}  // namespace tangle::io
