#pragma once
/// @file Hdf5Results.hpp
/// One HDF5 file per run, `results.h5`, with XDMF files beside it (`results.xdmf` for ParaView's XDMF 3
/// readers, `results.xdmf2` for its XDMF 2 reader) that let ParaView open the lines' motion and fields.
/// Layout (docs/results-hdf5.md; every dataset has `units` and `description` attributes, series are
/// chunked along time and deflate + shuffle compressed):
///
///     /                       attrs: tangle_version, title, model_file, model_text (the model as run)
///     /statics/lines/<line>/  arc_length, position [node, xyz], effective_tension, bending_moment,
///                             bending_moment_vector [node, xyz], curvature, torque, rotation [node, xyz]
///                             attrs: end_a_tension, end_b_tension, touchdown_arc_length
///     /dynamics/time          [time]
///     /dynamics/lines/<line>/ position [time, node, xyz], effective_tension, bending_moment, curvature,
///                             torque [time, node], bending_moment_vector [time, node, xyz],
///                             end_tension [time, end], end_force [time, end, xyz],
///                             range/<quantity>_{min,max,mean}
///     /dynamics/vessels/<vessel>/motion [time, (x, y, z, rx, ry, rz)]
///     /contact/events/<field> [event], /clearance/<line>/<other>/... [node]
///     /contact/clash_damage/<line>/ from, to, impacts, impacts_above, energy, largest_energy,
///                             largest_velocity [bin]
///     /fatigue/<line>/        arc_length, damage_run, damage_per_year, life_years, cycles, largest_range,
///                             worst_point [node]
///     /xdmf/<line>/segments   [element, 2] node indices (the XDMF polyline topology)
///     /xdmf/<line>/frames/    position [frame, node, xyz], effective_tension, bending_moment, curvature,
///                             torque [frame, node], a row every output.vtk_interval (the frames
///                             results.xdmf and results.xdmf2 show in ParaView); /xdmf/frame_time [frame]
///
/// Rows are written a chunk at a time and the file is flushed at every chunk, so a run that stops midway
/// (or crashes) keeps everything up to the last chunk; a run that fails with an error keeps all of it.

#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "tangle/analysis/ClashDamage.hpp"
#include "tangle/analysis/FatigueDamage.hpp"
#include "tangle/contact/ClearanceEnvelope.hpp"
#include "tangle/contact/ContactEvents.hpp"
#include "tangle/io/DynamicRecorder.hpp"
#include "tangle/io/Hdf5File.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/solver/ForceBalance.hpp"
#include "tangle/solver/LineResults.hpp"

namespace tangle::io {

class Hdf5Results {
 public:
  /// Creates `dir`/results.h5 and stores the model. `modelText` is the model file as run.
  Hdf5Results(const std::filesystem::path& dir, const model::Model& model, const std::string& modelText);
  ~Hdf5Results();

  void writeStatics(const std::vector<solver::LineSnapshot>& lines);
  /// The static equilibrium audit: /statics/equilibrium_audit/{lines,vessels}/<name>/terms (one row of
  /// force per source [N], names in the attribute `sources`), residual [N], attributes reference_force_N and
  /// relative_residual.
  void writeAudit(const solver::EquilibriumAudit& audit);
  /// Starts the time series (call once, before the first record).
  void beginDynamics(const std::vector<solver::LineSnapshot>& initial);
  /// One output time: the lines and, per vessel, (x, y, z [m], rx, ry, rz [deg]).
  void record(double time, const std::vector<solver::LineSnapshot>& lines,
              const std::vector<double>& vesselMotion);
  /// Range graphs accumulated by the CSV recorder (same numbers as dynamics/<line>/range.csv).
  void writeRanges(const DynamicRecorder& recorder);
  void writeContactEvents(const std::vector<contact::ContactEvent>& events);
  void writeClearance(const contact::ClearanceEnvelope& envelope);
  /// Fatigue damage along the lines (analysis::FatigueDamage::finish of `fatigue`; same numbers as
  /// fatigue/<line>.csv).
  void writeFatigue(const analysis::FatigueDamage& fatigue, const std::vector<analysis::FatigueDamage::Line>& damage);
  /// Clash damage along the lines (same numbers as contact/clash_damage.csv).
  void writeClashDamage(const std::vector<analysis::LineClashDamage>& damage, double energyThreshold);
  /// Flushes, closes the file and writes results.xdmf (the dynamics, or the static shape).
  void close();

 private:
  void writeXdmf() const;
  /// The lines at output time m_times.back() as a row of each line's frame series for the XDMF files.
  void writeFrame(const std::vector<solver::LineSnapshot>& lines);

  std::filesystem::path m_dir;
  const model::Model* m_model;
  std::unique_ptr<Hdf5File> m_file;
  std::vector<std::string> m_stems;
  std::vector<std::size_t> m_nodes;
  bool m_hasStatics = false;
  int m_time = -1;
  std::vector<std::vector<int>> m_lineSeries;  ///< per line: series handles (see the .cpp)
  std::vector<int> m_vesselSeries;             ///< per vessel: its motion series
  std::vector<double> m_times;
  std::vector<std::size_t> m_frames;  ///< output indices written as XDMF frames (every output.vtk_interval)
  /// Number of fields of a frame: position, effective tension, bending moment, curvature, torque.
  static constexpr std::size_t kFrameFields = 5;
  std::vector<std::array<int, kFrameFields>> m_frameSeries;  ///< per line: its frame series (writeFrame)
  int m_frameTime = -1;                                      ///< the frames' times [frame]
  double m_nextFrame = 0.0;           ///< s, time of the next XDMF frame
};

}  // namespace tangle::io
