#pragma once
/// @file ModelReader.hpp
/// Reads a tangle model file (YAML, format in docs/model-format.md) into a model::ModelSpec and checks
/// it: unknown or missing keys, wrong types, impossible values, duplicate names, dangling line-type
/// references, ends below the seabed and clearly impossible line geometry are all reported as
/// tangle::InputError naming the file, the 1-based line, the full key path (e.g.
/// "lines[mooring1].sections[1].length") and what was expected.
///
/// Units: the file is in SI units with angles in degrees; the returned ModelSpec stores angles in
/// radians (see ModelSpec.hpp for the unit of every field).

#include <string>

#include "tangle/model/ModelSpec.hpp"

namespace tangle::io {

/// Reads and validates a model file.
/// @param path path of the YAML model file; it is stored in ModelSpec::sourceFile and used in messages
/// @throws tangle::InputError naming file, line, key and what was expected (also when the file cannot
///         be read or is not valid YAML)
model::ModelSpec readModelFile(const std::string& path);

/// Same as readModelFile, from a string holding the YAML text (for tests and embedded models).
/// @param yaml the model text
/// @param sourceName name used as the file in messages and stored in ModelSpec::sourceFile
/// @throws tangle::InputError as readModelFile
model::ModelSpec readModelString(const std::string& yaml, const std::string& sourceName);

}  // namespace tangle::io
