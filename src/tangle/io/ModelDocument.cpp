/// @file ModelDocument.cpp
/// Editable model tree (see ModelDocument.hpp).

#include "tangle/io/ModelDocument.hpp"

#include <fmt/format.h>

#include <cctype>
#include <fstream>
#include <sstream>
#include <vector>

#include "tangle/core/Error.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle::io {

namespace {

/// One step of a key path: a map key, or a list item by index or by name.
struct PathStep {
  enum class Kind { Key, Index, Name } kind;
  std::string text;
  std::size_t index = 0;
};

/// Splits `a.b[2].c[name]` into steps. @throws InputError for malformed paths.
std::vector<PathStep> parsePath(const std::string& path, const std::string& source) {
  std::vector<PathStep> steps;
  const auto bad = [&](const std::string& why) {
    throw InputError(source, 0, path, fmt::format("a key path such as environment.current.speed or "
                                                  "lines[mooring1].end_b.position ({})",
                                                  why));
  };
  if (path.empty()) bad("the path is empty");
  std::size_t i = 0;
  while (i < path.size()) {
    std::size_t j = i;
    while (j < path.size() && (std::isalnum(static_cast<unsigned char>(path[j])) || path[j] == '_')) ++j;
    if (j == i) bad(fmt::format("a key name expected at character {}", i + 1));
    steps.push_back({PathStep::Kind::Key, path.substr(i, j - i)});
    i = j;
    while (i < path.size() && path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string::npos) bad("a '[' without its ']'");
      const std::string inside = path.substr(i + 1, close - i - 1);
      if (inside.empty()) bad("an empty '[]'");
      const bool numeric = inside.find_first_not_of("0123456789") == std::string::npos;
      if (numeric) {
        steps.push_back({PathStep::Kind::Index, inside, static_cast<std::size_t>(std::stoul(inside))});
      } else {
        steps.push_back({PathStep::Kind::Name, inside});
      }
      i = close + 1;
    }
    if (i < path.size()) {
      if (path[i] != '.') bad(fmt::format("'.' or '[' expected at character {}", i + 1));
      ++i;
      if (i == path.size()) bad("the path ends with '.'");
    }
  }
  return steps;
}

/// The path up to and including step k, as the reader writes it in messages.
std::string prefix(const std::vector<PathStep>& steps, std::size_t k) {
  std::string out;
  for (std::size_t i = 0; i <= k; ++i) {
    if (steps[i].kind == PathStep::Kind::Key) {
      if (!out.empty()) out += '.';
      out += steps[i].text;
    } else {
      out += '[' + steps[i].text + ']';
    }
  }
  return out;
}

}  // namespace

ModelDocument ModelDocument::fromText(const std::string& yaml, const std::string& sourceName) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml);
  } catch (const YAML::Exception& e) {
    throw InputError(sourceName, e.mark.is_null() ? 0 : e.mark.line + 1, "", "invalid YAML: " + e.msg);
  }
  if (!root.IsMap()) throw InputError(sourceName, 0, "", "a model: a map of blocks {environment, line_types, lines, ...}");
  return ModelDocument(root, sourceName, yaml);
}

ModelDocument ModelDocument::fromFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "", "cannot open the model file for reading");
  std::ostringstream text;
  text << in.rdbuf();
  return fromText(text.str(), path);
}

ModelDocument ModelDocument::fromNode(const YAML::Node& root, const std::string& sourceName) {
  if (!root.IsMap()) throw InputError(sourceName, 0, "", "a model: a map of blocks {environment, line_types, lines, ...}");
  return ModelDocument(YAML::Clone(root), sourceName);
}

ModelDocument::ModelDocument(const ModelDocument& other)
    : m_root(YAML::Clone(other.m_root)), m_source(other.m_source), m_text(other.m_text) {}

ModelDocument& ModelDocument::operator=(const ModelDocument& other) {
  if (this != &other) {
    m_root = YAML::Node();  // rebinding: YAML::Node assignment would write into the shared tree
    m_root.reset(YAML::Clone(other.m_root));
    m_source = other.m_source;
    m_text = other.m_text;
  }
  return *this;
}

YAML::Node ModelDocument::walk(const std::string& path, bool create) const {
  const std::vector<PathStep> steps = parsePath(path, m_source);
  YAML::Node node;
  node.reset(m_root);  // yaml-cpp nodes are handles: reset() rebinds, '=' would assign contents
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const PathStep& s = steps[k];
    YAML::Node next;
    if (s.kind == PathStep::Kind::Key) {
      if (!node.IsMap() && !(create && node.IsNull()))
        throw InputError(m_source, 0, prefix(steps, k),
                         fmt::format("'{}' to be a key of a map, but {} is not a map", s.text,
                                     k == 0 ? "the model" : prefix(steps, k - 1)));
      if (!node[s.text]) {
        if (!create) return YAML::Node(YAML::NodeType::Undefined);
        node[s.text] = YAML::Node(YAML::NodeType::Null);
      }
      next.reset(node[s.text]);
    } else {
      if (!node.IsSequence())
        throw InputError(m_source, 0, prefix(steps, k),
                         fmt::format("{} to be a list", prefix(steps, k - 1)));
      if (s.kind == PathStep::Kind::Index) {
        if (s.index >= node.size())
          throw InputError(m_source, 0, prefix(steps, k),
                           fmt::format("an index below {} (the list {} has {} item(s); indices start at 0)",
                                       node.size(), prefix(steps, k - 1), node.size()));
        next.reset(node[s.index]);
      } else {
        bool found = false;
        std::string names;
        for (std::size_t i = 0; i < node.size(); ++i) {
          const YAML::Node item = node[i];
          const YAML::Node name = item.IsMap() ? item["name"] : YAML::Node();
          if (name && name.IsScalar()) {
            names += (names.empty() ? "" : ", ") + name.Scalar();
            if (name.Scalar() == s.text) {
              next.reset(node[i]);
              found = true;
              break;
            }
          }
        }
        if (!found)
          throw InputError(m_source, 0, prefix(steps, k),
                           fmt::format("the name of an item of {} (one of: {})", prefix(steps, k - 1),
                                       names.empty() ? "none has a name" : names));
      }
    }
    node.reset(next);
  }
  return node;
}

YAML::Node ModelDocument::get(const std::string& path) const {
  const YAML::Node node = walk(path, false);
  if (!node.IsDefined()) throw InputError(m_source, 0, path, "a key present in the model (it is not set)");
  return YAML::Clone(node);
}

bool ModelDocument::has(const std::string& path) const {
  try {
    return walk(path, false).IsDefined();
  } catch (const InputError&) {
    return false;
  }
}

void ModelDocument::set(const std::string& path, const YAML::Node& value) {
  YAML::Node node = walk(path, true);
  node = YAML::Clone(value);  // assignment through the handle writes into the tree
  m_text.clear();
}

YAML::Node ModelDocument::root() const { return YAML::Clone(m_root); }

std::string ModelDocument::text() const {
  if (!m_text.empty()) return m_text;
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << m_root;
  return std::string(out.c_str()) + "\n";
}

model::ModelSpec ModelDocument::spec() const { return readModelString(text(), m_source); }

}  // namespace tangle::io
