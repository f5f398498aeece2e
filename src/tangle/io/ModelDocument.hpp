#pragma once
/// @file ModelDocument.hpp
/// A model file as an editable YAML tree: what a load-case batch and the Python module change before a
/// run. Changes are addressed by key paths written as the reader writes them in its messages,
/// e.g. `environment.current.speed`, `lines[mooring1].end_b.position`, `line_types[chain76].axial_stiffness`,
/// `lines[riser].sections[0].length`: a list item is chosen by its `name` or by its 0-based index.
///
/// The document is never validated on its own: spec() hands its text to the model reader, so every
/// change gets exactly the reader's checks and messages (file, line, key, what was expected).

#include <string>
#include <yaml-cpp/yaml.h>

#include "tangle/model/ModelSpec.hpp"

namespace tangle::io {

class ModelDocument {
 public:
  /// Reads a model file (YAML syntax only; the model is checked by spec()). @throws InputError
  static ModelDocument fromFile(const std::string& path);
  /// A model from YAML text; `sourceName` is the file named in messages. @throws InputError
  static ModelDocument fromText(const std::string& yaml, const std::string& sourceName);
  /// A model from a YAML tree (deep-copied).
  static ModelDocument fromNode(const YAML::Node& root, const std::string& sourceName);

  ModelDocument(const ModelDocument& other);
  ModelDocument& operator=(const ModelDocument& other);

  /// The value at `path` (a deep copy). @throws InputError naming the path when it does not exist.
  YAML::Node get(const std::string& path) const;
  /// True when `path` exists.
  bool has(const std::string& path) const;
  /// Sets the value at `path` (deep copy of `value`). Missing map keys on the way are created (the reader
  /// then refuses keys it does not know); list items must exist. @throws InputError naming the path.
  void set(const std::string& path, const YAML::Node& value);

  /// The whole tree (a deep copy).
  YAML::Node root() const;
  /// The model as YAML text: the original text while nothing was set (so the reader's line numbers are
  /// those of the file), else the tree emitted in block style (comments are not kept).
  std::string text() const;
  const std::string& sourceName() const { return m_source; }
  void setSourceName(const std::string& name) { m_source = name; }
  /// The checked model (ModelReader on text()). @throws InputError with the reader's message.
  model::ModelSpec spec() const;

 private:
  ModelDocument(YAML::Node root, std::string source, std::string text = {})
      : m_root(std::move(root)), m_source(std::move(source)), m_text(std::move(text)) {}
  /// The node at `path`, creating missing map keys when `create`; a null node when absent and !create.
  YAML::Node walk(const std::string& path, bool create) const;

  YAML::Node m_root;
  std::string m_source;
  std::string m_text;  ///< the original text, until the first set() (then empty)
};

}  // namespace tangle::io
