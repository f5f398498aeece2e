// End-to-end checks of the command line: every example validates, a static run writes its result
// files, bad input gets exit code 1 with a message naming the file, line and key, and --version works.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "TestPaths.hpp"

namespace {

namespace fs = std::filesystem;

struct Outcome {
  int code;
  std::string output;  // stdout and stderr
};

Outcome runCli(const std::string& arguments) {
  // One log per test: ctest runs the tests of this file in parallel processes.
  const fs::path log =
      fs::temp_directory_path() /
      ("tangle_cli_test_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
       ".log");
  const std::string cmd = std::string(TANGLE_CLI_PATH) + " " + arguments + " > " + log.string() + " 2>&1";
  const int status = std::system(cmd.c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  return {WEXITSTATUS(status), text.str()};
}

TEST(Cli, EveryExampleValidates) {
  int count = 0;
  for (const auto& entry : fs::recursive_directory_iterator(tangle::test::kExamplesDir)) {
    if (entry.path().extension() != ".yaml") continue;
    if (entry.path().filename() == "batch.yaml") continue;  // a load-case batch (docs/batch.md), not a model
    const Outcome o = runCli("check " + entry.path().string());
    EXPECT_EQ(o.code, 0) << entry.path() << "\n" << o.output;
    EXPECT_NE(o.output.find("model is valid"), std::string::npos) << o.output;
    ++count;
  }
  EXPECT_GE(count, 5);
}

// Issue 30: `check` estimates the memory of a run and refuses, as `run` does before it starts, a model the
// machine cannot hold (a model of many lines with contact ended in std::bad_alloc after 32 s). The available
// memory is forced low (TANGLE_MEMORY_AVAILABLE_MB) so that the example must be refused; with the real
// machine's the same model passes (EveryExampleValidates) and its estimate is printed.
TEST(Cli, CheckAndRunRefuseAModelTheMachineCannotHold) {
  const std::string model = std::string(tangle::test::kExamplesDir) + "/risers-in-contact/model.yaml";
  const Outcome fits = runCli("check " + model);
  ASSERT_EQ(fits.code, 0) << fits.output;
  EXPECT_NE(fits.output.find("memory: a run needs about"), std::string::npos) << fits.output;
  EXPECT_NE(fits.output.find("contact candidate pairs"), std::string::npos) << fits.output;
  const Outcome check = runCli("check " + model + " --memory-available-mb 1");
  EXPECT_EQ(check.code, 1) << check.output;
  EXPECT_NE(check.output.find(model + ": a run of this model needs about"), std::string::npos)
      << check.output;
  EXPECT_NE(check.output.find("Remedies"), std::string::npos) << check.output;
  const fs::path out = fs::temp_directory_path() / "tangle_cli_memory_refused";
  fs::remove_all(out);
  const Outcome run = runCli("run " + model + " -o " + out.string() + " --memory-available-mb 1");
  EXPECT_EQ(run.code, 1) << run.output;
  EXPECT_NE(run.output.find("a run of this model needs about"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
}

TEST(Cli, StaticRunWritesResults) {
  const fs::path out = fs::temp_directory_path() / "tangle_cli_catenary";
  fs::remove_all(out);
  const Outcome o = runCli("run " + std::string(tangle::test::kExamplesDir) +
                           "/catenary-mooring/model.yaml -o " + out.string() + " --no-plots -q");
  ASSERT_EQ(o.code, 0) << o.output;
  EXPECT_TRUE(fs::exists(out / "summary.json"));
  std::ifstream csv(out / "statics" / "mooring1.csv");
  std::string header;
  std::getline(csv, header);
  // A chain (a cable line: no bending stiffness) has no bending moment, torque or rotation columns
  // (issue 45: no columns of zeros for what a line does not have).
  EXPECT_EQ(header, "arc_length_m,x_m,y_m,z_m,effective_tension_N,curvature_1_per_m");
  int rows = 0;
  for (std::string row; std::getline(csv, row);) ++rows;
  EXPECT_EQ(rows, 201);  // 200 elements
}

// Issue 45: a transient run (examples/drilling-riser-drift: the DP unit drifts 85 m, the mooring line's
// tension mean moves between the halves of its record) says once that it has no storm extremes, and why,
// and lists the largest values seen, instead of a reason per line end, vessel and pair; the storm's files
// keep the reasons, row by row.
TEST(Cli, TransientRunSaysSoOnceInsteadOfStormExtremes) {
  const fs::path out = fs::temp_directory_path() / "tangle_cli_transient";
  fs::remove_all(out);
  const Outcome o = runCli("run " + std::string(tangle::test::kExamplesDir) +
                           "/drilling-riser-drift/model.yaml -o " + out.string() + " --no-plots --no-report");
  ASSERT_EQ(o.code, 0) << o.output;
  EXPECT_NE(o.output.find("extreme statistics (dynamics/statistics.csv): none: the run is a transient"),
            std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("  vessel 'drilling_unit': offset 85."), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("  lines 'mooring' / 'riser': smallest clearance -0.00"), std::string::npos)
      << o.output;
  EXPECT_EQ(o.output.find("no storm extreme"), std::string::npos) << o.output;
  std::ifstream csv(out / "dynamics" / "statistics.csv");
  std::stringstream rows;
  rows << csv.rdbuf();
  EXPECT_NE(rows.str().find("not stationary"), std::string::npos) << rows.str();
  // The same run's tables: the cable mooring line has no bending moment or torque files and no bending
  // moment columns in its range graphs and statics; the riser (a beam) has them all.
  for (const char* file : {"bending_moment_Nm.csv", "bending_moment_x_Nm.csv", "torque_Nm.csv"}) {
    EXPECT_FALSE(fs::exists(out / "dynamics" / "mooring" / file)) << file;
    EXPECT_TRUE(fs::exists(out / "dynamics" / "riser" / file)) << file;
  }
  const auto firstLine = [](const fs::path& file) {
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    return line;
  };
  EXPECT_EQ(firstLine(out / "dynamics" / "mooring" / "range.csv"),
            "arc_length_m,tension_min_N,tension_max_N,tension_mean_N,curvature_min_1_per_m,curvature_max_1_per_m,"
            "curvature_mean_1_per_m");
  EXPECT_NE(firstLine(out / "dynamics" / "riser" / "range.csv").find("bending_moment_max_Nm"), std::string::npos);
  EXPECT_EQ(firstLine(out / "statics" / "mooring.csv"),
            "arc_length_m,x_m,y_m,z_m,effective_tension_N,curvature_1_per_m");
  EXPECT_NE(firstLine(out / "statics" / "riser.csv").find("torque_Nm"), std::string::npos);
}

// Where statics put each vessel: statics/vessels.csv, and the free vessel's position in the log. The fixed
// production unit stays where the model puts it (offset 0 to the printed digits); the free drilling unit
// settles somewhere finite under its riser and the current.
TEST(Cli, StaticsReportsWhereTheVesselsAre) {
  const fs::path out = fs::temp_directory_path() / "tangle_cli_vessels";
  fs::remove_all(out);
  const Outcome o =
      runCli("run " + std::string(tangle::test::kExamplesDir) +
             "/drilling-riser-drift/model.yaml --statics-only --no-plots --no-report -o " + out.string());
  ASSERT_EQ(o.code, 0) << o.output;
  EXPECT_NE(o.output.find("vessel 'drilling_unit': static position ("), std::string::npos) << o.output;
  std::ifstream csv(out / "statics" / "vessels.csv");
  std::string header, fixedRow, freeRow;
  std::getline(csv, header);
  std::getline(csv, fixedRow);
  std::getline(csv, freeRow);
  EXPECT_EQ(header,
            "vessel,mode,x_m,y_m,z_m,heading_deg,offset_x_m,offset_y_m,offset_z_m,heading_change_deg");
  EXPECT_EQ(fixedRow.rfind("production_unit,fixed,", 0), 0u) << fixedRow;
  std::vector<double> fixedValues;
  {
    std::stringstream fields(fixedRow);
    std::string field;
    for (int k = 0; std::getline(fields, field, ','); ++k)
      if (k >= 6) fixedValues.push_back(std::stod(field));
  }
  ASSERT_EQ(fixedValues.size(), 4u) << fixedRow;
  for (double v : fixedValues) EXPECT_NEAR(v, 0.0, 1e-4) << fixedRow;  // offsets [m] and heading change [deg]
  EXPECT_EQ(freeRow.rfind("drilling_unit,free,", 0), 0u) << freeRow;
  EXPECT_EQ(freeRow.find("nan"), std::string::npos) << freeRow;
}

/// Reads a CSV file into its header and rows of numbers.
std::pair<std::vector<std::string>, std::vector<std::vector<double>>> readNumericCsv(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  {
    std::stringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) header.push_back(cell);
  }
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    std::vector<double> row;
    for (std::string cell; std::getline(fields, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return {header, rows};
}

// Issue 45: dynamics/vessels.csv gives, beside each vessel's low-frequency pose, the wave-frequency (RAO)
// motion its line ends get. A fixed vessel with heave 0.5 m/m (lag 0) and pitch 2 deg/m (lag 90) in a
// regular wave of 2 m (amplitude a = 1 m) along its axis: the _wf_z_ column's amplitude is 0.5 m and
// _wf_ry_ 2 deg (first order, RaoMotion.hpp; sampled every 0.1 s, a tenth of a percent below the peak at
// most), the low-frequency pose stays 0; and the fairlead, 10 m forward and 5 m down, moves as the vessel
// point: z = z0 + wf_z - 10 m x wf_ry (small rotation about +y; rad), to the columns' printed digits.
TEST(Cli, VesselsCsvGivesTheWaveFrequencyMotionTheFairleadsGet) {
  const fs::path dir = fs::temp_directory_path() / "tangle_cli_vessel_wf";
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    std::ofstream model(dir / "model.yaml");
    model << R"(title: fixed vessel with RAOs
environment:
  water_depth: 100
  waves: {type: airy, height: 2.0, period: 10.0, azimuth: 0}
line_types:
  - {name: wire, outer_diameter: 0.08, mass_per_length: 30, axial_stiffness: 5.0e8}
vessels:
  - name: ship
    mode: fixed
    position: [0, 0, 0]
    heading: 0
    raos:
      periods: [5, 15]
      headings: [0, 180]
      rows:
        - [5, 0, 0, 0, 0, 0, 0.5, 0, 0, 0, 2.0, 90, 0, 0]
        - [5, 180, 0, 0, 0, 0, 0.5, 0, 0, 0, 2.0, 90, 0, 0]
        - [15, 0, 0, 0, 0, 0, 0.5, 0, 0, 0, 2.0, 90, 0, 0]
        - [15, 180, 0, 0, 0, 0, 0.5, 0, 0, 0, 2.0, 90, 0, 0]
lines:
  - name: tether
    end_a: {type: anchored, position: [10, 0, -100]}
    end_b: {type: vessel, vessel: ship, position: [10, 0, -5]}
    sections: [{type: wire, length: 94.9, elements: 10}]
dynamics: {duration: 30, time_step: 0.05, ramp_time: 10, output_interval: 0.1}
)";
  }
  const fs::path out = dir / "out";
  const Outcome o =
      runCli("run " + (dir / "model.yaml").string() + " -o " + out.string() + " --no-plots --no-report -q");
  ASSERT_EQ(o.code, 0) << o.output;
  const auto [header, rows] = readNumericCsv(out / "dynamics" / "vessels.csv");
  const std::vector<std::string> expected{"time_s",        "ship_x_m",    "ship_y_m",       "ship_z_m",
                                          "ship_rx_deg",   "ship_ry_deg", "ship_rz_deg",    "ship_wf_x_m",
                                          "ship_wf_y_m",   "ship_wf_z_m", "ship_wf_rx_deg", "ship_wf_ry_deg",
                                          "ship_wf_rz_deg"};
  ASSERT_EQ(header, expected);
  const auto [lineHeader, fairleadZ] = readNumericCsv(out / "dynamics" / "tether" / "z_m.csv");
  ASSERT_EQ(fairleadZ.size(), rows.size());
  double heave = 0.0, pitch = 0.0, worstFairlead = 0.0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::vector<double>& r = rows[i];
    ASSERT_EQ(r.size(), expected.size());
    for (int k = 1; k <= 6; ++k) EXPECT_NEAR(r[k], 0.0, 1e-4) << "low-frequency pose at t = " << r[0];
    EXPECT_NEAR(r[7], 0.0, 1e-4);  // no surge, sway, roll or yaw RAO
    EXPECT_NEAR(r[8], 0.0, 1e-4);
    EXPECT_NEAR(r[10], 0.0, 1e-5);
    EXPECT_NEAR(r[12], 0.0, 1e-5);
    if (r[0] >= 20.0) {
      heave = std::max(heave, std::abs(r[9]));
      pitch = std::max(pitch, std::abs(r[11]));
    }
    const double predicted = -5.0 + r[9] - 10.0 * r[11] * 3.141592653589793 / 180.0;
    worstFairlead = std::max(worstFairlead, std::abs(fairleadZ[i].back() - predicted));
  }
  EXPECT_NEAR(heave, 0.5, 0.001 * 0.5);
  EXPECT_NEAR(pitch, 2.0, 0.001 * 2.0);
  EXPECT_LT(worstFairlead, 2e-4) << "the fairlead does not follow the vessel point";
}

// Issue 9: the riser-interference example end to end: the wake closes the gap between the risers, the
// clearance check writes its envelope (static and dynamic, every node of both risers) and a verdict.
TEST(Cli, RiserInterferenceExampleWritesTheClearanceCheck) {
  const fs::path out = fs::temp_directory_path() / "tangle_cli_riser_interference";
  fs::remove_all(out);
  const Outcome o = runCli("run " + std::string(tangle::test::kExamplesDir) +
                           "/riser-interference/model.yaml -o " + out.string() + " --no-plots -q");
  ASSERT_EQ(o.code, 0) << o.output;
  std::ifstream csv(out / "clearance" / "envelope.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "line,other_line,arc_length_m,static_clearance_m,min_clearance_m,time_of_min_s");
  int rows = 0;
  double smallest = 1e30;
  for (std::string row; std::getline(csv, row);) {
    ++rows;
    std::stringstream fields(row);
    std::string cell;
    for (int k = 0; k < 5; ++k) std::getline(fields, cell, ',');
    smallest = std::min(smallest, std::stod(cell));
  }
  EXPECT_EQ(rows, 2 * 51);  // both sides, 51 nodes each
  // Risers 8 m apart at the ends, OD 0.2731 m: without the wake the static gap is 5.27 m (A and B
  // deflect alike), with it about 3.76 m; the waves close it a little more.
  EXPECT_LT(smallest, 4.5);
  EXPECT_GT(smallest, 1.0);
  std::ifstream summary(out / "clearance" / "summary.json");
  std::stringstream text;
  text << summary.rdbuf();
  EXPECT_NE(text.str().find("\"pass\": true"), std::string::npos) << text.str();
}

// Issue 13: a folder holds one run, described by itself (model copy, log, manifest with the version).
TEST(Cli, OutputFolderIsSelfDescribingAndNeverMixesRuns) {
  const fs::path out = fs::temp_directory_path() / "tangle_cli_folder";
  fs::remove_all(out);
  const std::string model = std::string(tangle::test::kExamplesDir) + "/catenary-mooring/model.yaml";
  ASSERT_EQ(runCli("run " + model + " -o " + out.string() + " --no-plots -q").code, 0);
  EXPECT_TRUE(fs::exists(out / "model.yaml"));
  EXPECT_TRUE(fs::exists(out / "run.log"));
  EXPECT_TRUE(fs::exists(out / "vtk" / "statics.pvd"));
  std::ifstream manifest(out / "tangle-run.json");
  std::stringstream text;
  text << manifest.rdbuf();
  EXPECT_NE(text.str().find("\"tangle_version\""), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("\"status\": \"completed"), std::string::npos) << text.str();
  // A stale file of an earlier run: a second run into the folder is refused (exit 1) and leaves it...
  std::ofstream(out / "statics" / "stale.csv") << "old\n";
  const Outcome again = runCli("run " + model + " -o " + out.string() + " --no-plots -q");
  EXPECT_EQ(again.code, 1) << again.output;
  EXPECT_NE(again.output.find("--overwrite"), std::string::npos) << again.output;
  // ... and --overwrite clears it first: nothing of the earlier run survives.
  ASSERT_EQ(runCli("run " + model + " -o " + out.string() + " --no-plots -q --overwrite").code, 0);
  EXPECT_FALSE(fs::exists(out / "statics" / "stale.csv"));
  EXPECT_TRUE(fs::exists(out / "statics" / "mooring1.csv"));
  // A folder tangle did not write is never cleared, even with --overwrite.
  const fs::path foreign = fs::temp_directory_path() / "tangle_cli_foreign";
  fs::remove_all(foreign);
  fs::create_directories(foreign);
  std::ofstream(foreign / "thesis.tex") << "precious\n";
  EXPECT_EQ(runCli("run " + model + " -o " + foreign.string() + " --no-plots -q --overwrite").code, 1);
  EXPECT_TRUE(fs::exists(foreign / "thesis.tex"));
  fs::remove_all(foreign);
}

// Issue 13: a 2-byte model ',' made `check` loop forever; now it is refused at once (exit 1).
TEST(Cli, StrayCommaModelIsRefusedQuickly) {
  const fs::path bad = fs::temp_directory_path() / "tangle_cli_comma.yaml";
  std::ofstream(bad) << ",\n";
  const Outcome o = runCli("check " + bad.string());
  EXPECT_EQ(o.code, 1) << o.output;
}

TEST(Cli, BadInputExitsWithOneAndNamesFileLineAndKey) {
  const fs::path bad = fs::temp_directory_path() / "tangle_cli_bad.yaml";
  std::ofstream(bad)
      << "environment:\n  water_depth: 100\nline_types:\n  - name: a\n    outer_diameter: 0.1\n"
         "    mass_per_length: 10\n    axial_stiffness: 1e8\nlines:\n  - name: l\n"
         "    end_a: {type: anchored, position: [0, 0, -100]}\n"
         "    end_b: {type: fixed, position: [50, 0, -10]}\n"
         "    sections:\n      - {type: a, lenght: 100, elements: 10}\n";
  const Outcome o = runCli("run " + bad.string() + " --no-plots");
  EXPECT_EQ(o.code, 1) << o.output;
  EXPECT_NE(o.output.find(bad.string() + ":13"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("lenght"), std::string::npos) << o.output;
}

TEST(Cli, MissingFileAndVersion) {
  EXPECT_NE(runCli("run /nonexistent/model.yaml").code, 0);
  const Outcome v = runCli("--version");
  EXPECT_EQ(v.code, 0);
  EXPECT_NE(v.output.find("tangle"), std::string::npos);
}

}  // namespace
