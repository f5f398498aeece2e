/// @file BatchPlan.cpp
/// Batch file reader (see BatchPlan.hpp).

#include "tangle/app/BatchPlan.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <set>

#include "tangle/core/Error.hpp"

namespace tangle::app {

namespace fs = std::filesystem;

namespace {

/// Most cases a batch expands to: a product of long lists is usually a typing mistake.
constexpr std::size_t kMaxCases = 100000;

int lineOf(const YAML::Node& n) { return n.Mark().is_null() ? 0 : n.Mark().line + 1; }

/// The value as the summary table shows it (scalars as written, lists flow-style).
std::string valueText(const YAML::Node& v) {
  if (v.IsScalar()) return v.Scalar();
  YAML::Emitter out;
  out << YAML::Flow << v;
  return out.c_str();
}

/// Folder-safe form of a case name part.
std::string safeName(const std::string& s) {
  std::string out;
  for (char c : s) {
    const bool ok = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-' || c == '=';
    out += ok ? c : '-';
  }
  return out;
}

class BatchReader {
 public:
  explicit BatchReader(std::string file) : m_file(std::move(file)) {}

  [[noreturn]] void fail(const YAML::Node& at, const std::string& key, const std::string& expected) const {
    throw InputError(m_file, lineOf(at), key, expected);
  }

  void checkKeys(const YAML::Node& map, const std::string& path, const std::set<std::string>& known) const {
    for (const auto& kv : map) {
      const std::string k = kv.first.as<std::string>();
      if (!known.count(k)) {
        std::string list;
        for (const std::string& s : known) list += (list.empty() ? "" : ", ") + s;
        fail(kv.first, path.empty() ? k : path + "." + k, "one of the keys: " + list);
      }
    }
  }

  /// A `set` map: key path -> value; each path is applied to `doc` (checked against the model).
  void applySet(const YAML::Node& set, const std::string& path, io::ModelDocument& doc) const {
    if (!set.IsMap()) fail(set, path, "a map of model key paths to values, e.g. {environment.current.speed: 1.0}");
    for (const auto& kv : set) {
      const std::string key = kv.first.as<std::string>();
      try {
        doc.set(key, kv.second);
      } catch (const InputError& e) {
        fail(kv.first, path + "." + key, fmt::format("a key path of the base model: {}", e.what()));
      }
    }
  }

  BatchPlan read() {
    YAML::Node root;
    try {
      root = YAML::LoadFile(m_file);
    } catch (const YAML::BadFile&) {
      throw InputError(m_file, 0, "", "cannot read the batch file");
    } catch (const YAML::Exception& e) {
      throw InputError(m_file, e.mark.is_null() ? 0 : e.mark.line + 1, "", "invalid YAML: " + e.msg);
    }
    if (!root.IsMap()) fail(root, "", "a batch: a map {model, set, parameters, cases}");
    checkKeys(root, "",
              {"model", "set", "parameters", "seeds", "statistics", "cases", "break_each", "title"});
    BatchPlan plan;
    plan.batchFile = m_file;
    const YAML::Node model = root["model"];
    if (!model || !model.IsScalar() || model.Scalar().empty())
      fail(model ? model : root, "model", "the path of the base model file (relative to the batch file)");
    fs::path base = model.Scalar();
    if (base.is_relative()) base = fs::path(m_file).parent_path() / base;
    plan.baseModel = base.lexically_normal().string();
    if (!fs::is_regular_file(plan.baseModel))
      fail(model, "model", fmt::format("an existing model file ({} does not exist)", plan.baseModel));
    io::ModelDocument common = io::ModelDocument::fromFile(plan.baseModel);
    if (const YAML::Node set = root["set"]) applySet(set, "set", common);

    // Parameters: each a key (or keys, set together) and its values.
    struct Parameter {
      std::string name;
      std::vector<std::string> keys;
      std::vector<YAML::Node> values;  // per value: one node per key
    };
    std::vector<Parameter> parameters;
    if (const YAML::Node ps = root["parameters"]) {
      if (!ps.IsSequence() || ps.size() == 0) fail(ps, "parameters", "a list of {name, key, values}");
      for (std::size_t i = 0; i < ps.size(); ++i) {
        const YAML::Node p = ps[i];
        const std::string path = fmt::format("parameters[{}]", i);
        if (!p.IsMap()) fail(p, path, "a map {name, key, values}");
        checkKeys(p, path, {"name", "key", "keys", "values"});
        Parameter par;
        if (!p["name"] || !p["name"].IsScalar() || p["name"].Scalar().empty())
          fail(p, path + ".name", "a name (the column of the summary table)");
        par.name = p["name"].Scalar();
        for (const Parameter& q : parameters)
          if (q.name == par.name) fail(p["name"], path + ".name", "a name not used by another parameter");
        if (p["key"] && p["keys"]) fail(p, path, "either key or keys, not both");
        if (p["key"]) {
          if (!p["key"].IsScalar()) fail(p["key"], path + ".key", "a model key path");
          par.keys.push_back(p["key"].Scalar());
        } else if (p["keys"] && p["keys"].IsSequence() && p["keys"].size() > 0) {
          for (const auto& k : p["keys"]) {
            if (!k.IsScalar()) fail(k, path + ".keys", "a list of model key paths");
            par.keys.push_back(k.Scalar());
          }
        } else {
          fail(p, path + ".key", "the model key path the parameter sets (or keys: a list of paths)");
        }
        const YAML::Node values = p["values"];
        if (!values || !values.IsSequence() || values.size() == 0)
          fail(values ? values : p, path + ".values", "a list of at least one value");
        for (std::size_t v = 0; v < values.size(); ++v) {
          if (par.keys.size() > 1 && (!values[v].IsSequence() || values[v].size() != par.keys.size()))
            fail(values[v], fmt::format("{}.values[{}]", path, v),
                 fmt::format("a list of {} values, one per key", par.keys.size()));
          par.values.push_back(values[v]);
        }
        plan.parameterNames.push_back(par.name);
        parameters.push_back(std::move(par));
      }
    }

    // Seeds: the last parameter, `seed`, of the JONSWAP sea (summary_statistics.csv over them).
    if (const YAML::Node seeds = root["seeds"]) {
      const auto seedValue = [&](const YAML::Node& n, const std::string& path) {
        long long v = -1;
        try {
          v = n.as<long long>();
        } catch (const YAML::Exception&) {
        }
        if (v < 0 || v > 4294967295LL) fail(n, path, "a seed: an integer from 0 to 4294967295");
        return v;
      };
      if (seeds.IsSequence() && seeds.size() >= 2) {
        for (std::size_t i = 0; i < seeds.size(); ++i) plan.seeds.push_back(seedValue(seeds[i], fmt::format("seeds[{}]", i)));
      } else if (seeds.IsMap()) {
        checkKeys(seeds, "seeds", {"count", "first"});
        const long long count = seeds["count"] ? seedValue(seeds["count"], "seeds.count") : 0;
        const long long first = seeds["first"] ? seedValue(seeds["first"], "seeds.first") : 1;
        if (count < 2 || count > 1000) fail(seeds["count"] ? seeds["count"] : seeds, "seeds.count", "from 2 to 1000 seeds");
        for (long long k = 0; k < count; ++k) plan.seeds.push_back(first + k);
      } else {
        fail(seeds, "seeds", "a list of at least two seeds, or {count: N, first: S}");
      }
      if (std::set<long long>(plan.seeds.begin(), plan.seeds.end()).size() != plan.seeds.size())
        fail(seeds, "seeds", "distinct seeds (a seed twice is the same sea twice)");
      for (const Parameter& q : parameters)
        if (q.name == "seed") fail(root["parameters"], "parameters", "no parameter named 'seed' when the batch has seeds");
      Parameter par;
      par.name = "seed";
      par.keys.push_back("environment.waves.seed");
      for (const long long v : plan.seeds) par.values.push_back(YAML::Node(v));
      plan.parameterNames.push_back(par.name);
      parameters.push_back(std::move(par));
    }
    if (const YAML::Node st = root["statistics"]) {
      if (!st.IsMap()) fail(st, "statistics", "a map {probability}");
      checkKeys(st, "statistics", {"probability"});
      if (const YAML::Node q = st["probability"]) {
        double v = -1.0;
        try {
          v = q.as<double>();
        } catch (const YAML::Exception&) {
        }
        if (!(v > 0.0 && v < 1.0)) fail(q, "statistics.probability", "a non-exceedance probability between 0 and 1 (e.g. 0.9)");
        plan.probability = v;
      }
      if (plan.seeds.empty()) fail(st, "statistics", "seeds: the statistics are over the seeds of each case");
    }

    // Named cases (default: one unnamed case).
    struct Named {
      std::string name;
      YAML::Node set;
      YAML::Node at;
      YAML::Node broken;  ///< break_each's set for this case (undefined: none)
    };
    std::vector<Named> named;
    if (const YAML::Node cs = root["cases"]) {
      if (!cs.IsSequence() || cs.size() == 0) fail(cs, "cases", "a list of {name, set}");
      for (std::size_t i = 0; i < cs.size(); ++i) {
        const YAML::Node c = cs[i];
        const std::string path = fmt::format("cases[{}]", i);
        if (!c.IsMap()) fail(c, path, "a map {name, set}");
        checkKeys(c, path, {"name", "set"});
        if (!c["name"] || !c["name"].IsScalar() || c["name"].Scalar().empty())
          fail(c, path + ".name", "a case name");
        named.push_back({c["name"].Scalar(), c["set"], c, YAML::Node(YAML::NodeType::Undefined)});
      }
    } else {
      named.push_back(
          {"", YAML::Node(YAML::NodeType::Undefined), root, YAML::Node(YAML::NodeType::Undefined)});
    }
    // The accidental limit state: each of a list of lines broken in turn (lines[].failure), beside the intact
    // case, for every named case.
    if (const YAML::Node be = root["break_each"]) {
      if (!be.IsMap()) fail(be, "break_each", "a map {lines, failure, intact}");
      checkKeys(be, "break_each", {"lines", "failure", "intact"});
      const YAML::Node lines = be["lines"];
      if (!lines || !lines.IsSequence() || lines.size() == 0)
        fail(lines ? lines : be, "break_each.lines",
             "a list of the names of the lines to break, one per case");
      const YAML::Node failure = be["failure"];
      if (!failure || !failure.IsMap())
        fail(failure ? failure : be, "break_each.failure",
             "a line failure {time, tension, clash_energy, at} (docs/model-format.md), e.g. {time: 60, at: "
             "end_b}");
      bool intact = true;
      if (const YAML::Node i = be["intact"]) {
        if (!i.IsScalar() || (i.Scalar() != "true" && i.Scalar() != "false"))
          fail(i, "break_each.intact", "true (the intact case is run too, the default) or false");
        intact = i.Scalar() == "true";
      }
      const auto joined = [](const std::string& a, const std::string& b) {
        return a.empty() ? b : a + "_" + b;
      };
      std::vector<Named> expanded;
      for (const Named& n : named) {
        if (intact)
          expanded.push_back({joined(n.name, "intact"), n.set, n.at, YAML::Node(YAML::NodeType::Undefined)});
        for (std::size_t k = 0; k < lines.size(); ++k) {
          if (!lines[k].IsScalar() || lines[k].Scalar().empty())
            fail(lines[k], fmt::format("break_each.lines[{}]", k), "a line name");
          YAML::Node set(YAML::NodeType::Map);
          set["lines[" + lines[k].Scalar() + "].failure"] = failure;
          expanded.push_back({joined(n.name, "broken=" + lines[k].Scalar()), n.set, be, set});
        }
      }
      named = std::move(expanded);
    }

    std::size_t total = named.size();
    for (const Parameter& p : parameters) {
      total *= p.values.size();
      if (total > kMaxCases)
        fail(root["parameters"], "parameters", fmt::format("at most {} cases in one batch", kMaxCases));
    }
    std::set<std::string> names;
    for (const Named& n : named) {
      io::ModelDocument caseModel = common;
      if (n.set) applySet(n.set, "cases[" + n.name + "].set", caseModel);
      if (n.broken) applySet(n.broken, "break_each", caseModel);
      std::vector<std::size_t> index(parameters.size(), 0);
      while (true) {
        BatchCase c{n.name, {}, caseModel};
        std::string name = safeName(n.name);
        for (std::size_t k = 0; k < parameters.size(); ++k) {
          const Parameter& p = parameters[k];
          const YAML::Node& v = p.values[index[k]];
          for (std::size_t key = 0; key < p.keys.size(); ++key) {
            try {
              c.model.set(p.keys[key], p.keys.size() > 1 ? v[key] : v);
            } catch (const InputError& e) {
              fail(v, fmt::format("parameters[{}].key", p.name), fmt::format("a key path of the base model: {}", e.what()));
            }
          }
          c.parameterValues.push_back(valueText(v));
          name += (name.empty() ? "" : "_") + safeName(p.name + "=" + valueText(v));
        }
        if (name.empty()) name = "base";
        if (!names.insert(name).second) fail(n.at, "cases", fmt::format("unique case names ('{}' twice)", name));
        c.name = name;
        c.model.setSourceName(fmt::format("{} (case {} of {})", plan.baseModel, name, m_file));
        plan.cases.push_back(std::move(c));
        // Next combination, the last parameter fastest.
        bool done = true;
        for (std::size_t k = parameters.size(); k-- > 0;) {
          if (++index[k] < parameters[k].values.size()) {
            done = false;
            break;
          }
          index[k] = 0;
        }
        if (done) break;
      }
    }
    // Every case is read as a model now, before anything runs: a key path with a typo
    // (environment.curent.azimuth creates a map the reader does not know) or a value out of range would
    // otherwise start every case and fail each with "bad input".
    for (const BatchCase& c : plan.cases) {
      model::WaveKind waves = model::WaveKind::None;
      try {
        waves = c.model.spec().environment.waves.kind;
      } catch (const InputError& e) {
        throw InputError(m_file, 0, "cases",
                         fmt::format("every case to be a valid model; case '{}' is not: {}", c.name, e.what()));
      }
      if (!plan.seeds.empty() && waves != model::WaveKind::Jonswap)
        fail(root["seeds"], "seeds",
             fmt::format("irregular waves in every case (seeds vary the JONSWAP sea's phases); case '{}' has "
                         "no JONSWAP sea: set environment.waves.type: jonswap",
                         c.name));
    }
    return plan;
  }

 private:
  std::string m_file;
};

}  // namespace

BatchPlan readBatchPlan(const std::string& batchFile) { return BatchReader(batchFile).read(); }

}  // namespace tangle::app
