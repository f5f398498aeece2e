#include "tangle/io/OutputFolder.hpp"

#include <chrono>
#include <ctime>
#include <fmt/format.h>
#include <system_error>

#include "tangle/core/Error.hpp"
#include "tangle/core/JsonWriter.hpp"
#include "tangle/core/OutputFile.hpp"
#include "tangle/io/MoorDynConversion.hpp"

namespace tangle::io {

namespace fs = std::filesystem;

namespace {

std::string utcNow() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

}  // namespace

OutputFolder::OutputFolder(fs::path dir, const std::string& modelPath, bool overwrite)
    : m_dir(std::move(dir)), m_modelPath(modelPath), m_started(utcNow()) {
  prepare(overwrite);
  // The model as it was run: results are only readable with the input that made them.
  std::error_code ec;
  if (isMoorDynDeck(modelPath)) {
    // A MoorDyn deck: the deck as given and the tangle model it became (what results.h5 and a re-run read).
    const fs::path deckCopy = m_dir / ("moordyn_" + fs::path(modelPath).filename().string());
    fs::copy_file(modelPath, deckCopy, fs::copy_options::overwrite_existing, ec);
    if (ec) throw OutputError(fmt::format("cannot write {}: {}", deckCopy.string(), ec.message()));
    core::OutputFile copy(m_dir / "model.yaml");
    copy.write(convertMoorDynDeck(readMoorDynDeck(modelPath)).yaml);
    copy.close();
    return;
  }
  fs::copy_file(modelPath, m_dir / "model.yaml", fs::copy_options::overwrite_existing, ec);
  if (ec) throw OutputError(fmt::format("cannot write {}: {}", (m_dir / "model.yaml").string(), ec.message()));
}

OutputFolder::OutputFolder(fs::path dir, const std::string& source, const std::string& modelText, bool overwrite)
    : m_dir(std::move(dir)), m_modelPath(source), m_started(utcNow()) {
  prepare(overwrite);
  core::OutputFile copy(m_dir / "model.yaml");
  copy.write(modelText);
  copy.close();
}

void OutputFolder::prepare(bool overwrite) {
  std::error_code ec;
  const std::string where = m_dir.string();
  if (fs::exists(m_dir, ec)) {
    if (!fs::is_directory(m_dir, ec))
      throw InputError(where, 0, "", "the output path exists and is not a folder; choose another with -o");
    if (!fs::is_empty(m_dir, ec)) {
      const bool ours = fs::exists(m_dir / kManifest, ec);
      if (!overwrite)
        throw InputError(where, 0, "",
                         "the output folder already holds files (an earlier run?); results of two runs are never "
                         "mixed: give --overwrite to replace them, or choose another folder with -o");
      if (!ours)
        throw InputError(where, 0, "",
                         fmt::format("the output folder holds files that tangle did not write (no {}); "
                                     "--overwrite only clears folders of earlier tangle runs: choose another "
                                     "folder with -o",
                                     kManifest));
      // Manifest first: a clear cut short by a crash leaves a folder still marked as tangle's.
      for (const fs::directory_entry& entry : fs::directory_iterator(m_dir)) {
        if (entry.path().filename() == kManifest) continue;
        fs::remove_all(entry.path(), ec);
        if (ec) throw OutputError(fmt::format("cannot clear {}: {}", entry.path().string(), ec.message()));
      }
    }
  }
  fs::create_directories(m_dir, ec);
  if (ec) throw OutputError(fmt::format("cannot create the output folder {}: {}", where, ec.message()));
  writeManifest();
}

void OutputFolder::setStatus(const std::string& status) {
  m_status = status;
  writeManifest();
}

void OutputFolder::writeManifest() {
  core::OutputFile f(m_dir / kManifest);
  core::JsonWriter j(f.stream());
  j.beginObject();
  j.field("tangle_version", TANGLE_VERSION);
  j.field("model", m_modelPath);
  j.field("model_copy", "model.yaml");
  j.field("log", "run.log");
  j.field("started_utc", m_started);
  j.field("status", m_status);
  j.endObject();
  f.close();
}

}  // namespace tangle::io
