#pragma once
/// @file OutputFolder.hpp
/// The results folder of one run: self-describing (a copy of the model, the run log, a manifest
/// `tangle-run.json` with the tangle version, model path and run status) and never mixed with another
/// run's files: a folder that already holds files is refused, unless `overwrite` is set and the folder
/// is one tangle wrote (it holds a manifest), in which case it is emptied first.

#include <filesystem>
#include <string>

namespace tangle::io {

/// Prepares and describes a run's output folder.
class OutputFolder {
 public:
  /// Name of the manifest that marks a folder as tangle's.
  static constexpr const char* kManifest = "tangle-run.json";

  /// Creates `dir` (or empties it, see the file comment) and writes the manifest with status "running".
  /// @param modelPath the model file (copied to `dir/model.yaml`)
  /// @throws InputError (exit 1) when the folder holds files and may not be cleared; OutputError when
  ///         it cannot be created or written
  OutputFolder(std::filesystem::path dir, const std::string& modelPath, bool overwrite);
  /// As above for a model given as text (the Python module's, possibly edited): `source` names it in the
  /// manifest, `modelText` is written to `dir/model.yaml`.
  OutputFolder(std::filesystem::path dir, const std::string& source, const std::string& modelText, bool overwrite);

  const std::filesystem::path& path() const { return m_dir; }
  /// The run's status as the manifest says it ("running", "completed", "failed: ...").
  const std::string& status() const { return m_status; }
  /// Rewrites the manifest with a final status ("completed", "statics did not converge", ...).
  void setStatus(const std::string& status);

 private:
  /// Creates `dir` or empties it (see the file comment) and writes the manifest.
  void prepare(bool overwrite);
  void writeManifest();
  std::filesystem::path m_dir;
  std::string m_modelPath;
  std::string m_started;
  std::string m_status = "running";
};

}  // namespace tangle::io
