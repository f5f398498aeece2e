// End-to-end checks of the command line: every example validates, a static run writes its result
// files, bad input gets exit code 1 with a message naming the file, line and key, and --version works.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
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

/// A fresh folder temp/<name> holding `yaml` as model.yaml, for a test that runs a model of its own.
fs::path modelFolder(const std::string& name, const std::string& yaml) {
  const fs::path dir = fs::temp_directory_path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "model.yaml") << yaml;
  return dir;
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

/// A model of `count` short wires (10 m, two elements) on a 20 m grid at 50 m depth, every pair allowed to
/// touch (`contact: {}`), written to a temporary file.
fs::path gridOfWires(int count) {
  const fs::path path = fs::temp_directory_path() / ("tangle_cli_grid_" + std::to_string(count) + ".yaml");
  std::ofstream f(path);
  f << "environment: {water_depth: 100}\nline_types:\n  - {name: w, outer_diameter: 0.05, mass_per_length: "
       "10, "
       "axial_stiffness: 1.0e8}\ncontact: {}\nlines:\n";
  int side = 1;
  while (side * side < count) ++side;
  for (int i = 0; i < count; ++i) {
    const double x = 20.0 * (i % side), y = 20.0 * (i / side);
    f << "  - {name: l" << i << ", end_a: {type: pinned, position: [" << x << ", " << y
      << ", -50]}, end_b: {type: pinned, position: [" << x + 9.9 << ", " << y
      << ", -50]}, sections: [{type: w, length: 10, elements: 2}]}\n";
  }
  return path;
}

// Issue 45: the set-up of contact pairs is not quadratic in the lines. `check` of 20 000 wires with every
// pair allowed (2e8 line pairs) took 21 s CPU and 2.4 GB and then refused the model, wanting 90 GB (a table
// of every line pair, the clearance envelope and clash report of every pair). Now the pairs are a rule, and
// the envelope and the clash report of more than 2000 pairs assess the pairs within the clearance margin (50
// m) at the start: on the 20 m grid each wire's neighbours within 50 m, 235 779 pairs. (The time, 3-4 s, is a
// benchmark figure, not asserted here.)
TEST(Cli, CheckOfTwentyThousandLinesWithEveryPairAllowed) {
  const Outcome o = runCli("check " + gridOfWires(20000).string());
  ASSERT_EQ(o.code, 0) << o.output.substr(0, 4000);
  EXPECT_NE(o.output.find("model is valid"), std::string::npos);
  EXPECT_NE(o.output.find("of the 235779 line pairs within the clearance margin at the start, of 199990000 "
                          "allowed"),
            std::string::npos)
      << o.output.substr(o.output.size() > 2000 ? o.output.size() - 2000 : 0);
  EXPECT_NE(o.output.find("clearance envelope (235779 line pairs)"), std::string::npos);
}

// The same rule in a run: 300 wires (44 850 allowed pairs) assess the 3099 within 50 m of each other; the
// terminal lists the 20 nearest pairs and counts the rest, clearance/summary.json has every assessed pair.
TEST(Cli, StaticRunOfManyLinesAssessesThePairsThatAreNear) {
  const fs::path out = fs::temp_directory_path() / "tangle_cli_grid_run";
  fs::remove_all(out);
  const Outcome o = runCli("run " + gridOfWires(300).string() + " --statics-only --no-plots --no-report -o " +
                           out.string());
  ASSERT_EQ(o.code, 0) << o.output.substr(0, 4000);
  EXPECT_NE(
      o.output.find("the 3099 of the 44850 allowed line pairs that are within the clearance margin (50 m)"),
      std::string::npos);
  EXPECT_NE(o.output.find("... the 20 pairs above have the smallest clearances of 3099; 0 of them all FAIL"),
            std::string::npos);
  std::ifstream summary(out / "clearance" / "summary.json");
  std::stringstream text;
  text << summary.rdbuf();
  std::size_t pairs = 0;
  for (std::size_t at = text.str().find("\"line_1\""); at != std::string::npos;
       at = text.str().find("\"line_1\"", at + 1))
    ++pairs;
  EXPECT_EQ(pairs, 3099u);
}

// Issue 45: the storm extremes where they are credible, end to end. A taut vertical tether (EA 5 MN,
// unstretched 90 m between an anchor at -100 m and a fairlead at -5 m: 0.28 MN pretension) under a buoy that
// heaves with the waves (heave RAO 1 at every period), JONSWAP Hs 2 m, Tp 10 s, 1200 s after the ramp. The
// wire's axial period (4 L / sqrt(EA / m) = 0.9 s) is far below the waves': the fairlead tension follows the
// heave quasi-statically, T_B = T_0 + (EA / L_0) heave, a Gaussian process of standard deviation
// sigma = (EA / L_0) Hs / 4 = 27.8 kN whose peaks are Rayleigh: the most probable maximum of N = T_storm / Tz
// peaks is the mean + sigma sqrt(2 ln N) (Ochi 1998, "Ocean waves", 8.3; DNV-RP-C205 (2021) 3.5.8). The
// run's standard deviation within 10 % of sigma (the sampling error of a 1200 s realisation, 145 periods, is
// some 5 %) and its Rayleigh MPM's excess over the mean within 10 % of sigma sqrt(2 ln N) (measured: -3.6 %
// and -3.4 %); the fit is credible (Weibull shape in [1.5, 3]) and the log quotes it.
TEST(Cli, StormExtremesOfALinearResponseAgainstTheGaussianClosedForm) {
  const fs::path dir =
      modelFolder("tangle_cli_storm_extremes", R"(title: taut tether under a heaving buoy in a JONSWAP sea
environment:
  water_depth: 100
  waves: {type: jonswap, significant_height: 2.0, peak_period: 10.0, azimuth: 0}
line_types:
  - {name: wire, outer_diameter: 0.08, mass_per_length: 30, axial_stiffness: 5.0e6, drag_normal: 0,
     drag_axial: 0, added_mass_normal: 0}
vessels:
  - name: buoy
    mode: fixed
    position: [0, 0, 0]
    raos:
      periods: [1, 40]
      headings: [0, 180]
      rows:
        - [1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0]
        - [1, 180, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0]
        - [40, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0]
        - [40, 180, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0]
lines:
  - name: tether
    end_a: {type: anchored, position: [0, 0, -100]}
    end_b: {type: vessel, vessel: buoy, position: [0, 0, -5]}
    sections: [{type: wire, length: 90, elements: 10}]
dynamics: {duration: 1230, time_step: 0.1, ramp_time: 30, output_interval: 1.0}
output: {vtk: false}
)");
  const fs::path out = dir / "out";
  const Outcome o =
      runCli("run " + (dir / "model.yaml").string() + " -o " + out.string() + " --no-plots --no-report");
  ASSERT_EQ(o.code, 0) << o.output;
  EXPECT_NE(o.output.find("line 'tether' end B: "), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("most probable maximum of a 3.0 h storm"), std::string::npos) << o.output;
  std::ifstream file(out / "dynamics" / "statistics.csv");
  std::string header, row, text;
  std::getline(file, header);
  while (std::getline(file, text))
    if (text.rfind("tether,B,", 0) == 0) row = text;
  ASSERT_FALSE(row.empty());
  std::vector<std::string> names, fields;
  for (std::stringstream h(header); std::getline(h, text, ',');) names.push_back(text);
  for (std::stringstream r(row); std::getline(r, text, ',');) fields.push_back(text);
  const auto value = [&](const std::string& name) {
    const auto at = std::find(names.begin(), names.end(), name);
    EXPECT_NE(at, names.end()) << name;
    const std::string& f = fields.at(static_cast<std::size_t>(at - names.begin()));
    EXPECT_FALSE(f.empty()) << name << " is empty: the fit was not credible: " << row;
    return f.empty() ? std::nan("") : std::stod(f);
  };
  const double sigma = 5.0e6 / 90.0 * 2.0 / 4.0;  // (EA / L0) Hs / 4 [N]
  const double mean = value("mean_N"), tz = value("upcrossing_period_s");
  EXPECT_NEAR(value("standard_deviation_N") / sigma, 1.0, 0.10);
  const double excess = sigma * std::sqrt(2.0 * std::log(10800.0 / tz));
  EXPECT_NEAR((value("rayleigh_mpm_N") - mean) / excess, 1.0, 0.10);
  EXPECT_GE(value("rayleigh_mpm_N"), value("max_N"));
  EXPECT_GE(value("weibull_shape"), 1.5);
  EXPECT_LE(value("weibull_shape"), 3.0);
  EXPECT_GT(value("peaks"), 100.0);
}

// The log's extremes name a line's end with the larger tension, whichever end the model puts the fairlead at
// (a new user's model in the OrcaFlex convention, end A at the vessel, was quoted at its anchor end B: 26.4
// kN against the hang-off's 80.6 kN in statistics.csv, 2026-12-07). The tether above turned round: its top
// (end A) carries its anchor's tension plus its submerged weight (30 kg/m less the water's 5.2, over 90 m:
// 21.9 kN more).
TEST(Cli, TheLogsExtremesNameTheEndWithTheLargerTension) {
  const fs::path dir = modelFolder("tangle_cli_extremes_end_a", R"(title: taut tether, end A at the buoy
environment:
  water_depth: 100
line_types:
  - {name: wire, outer_diameter: 0.08, mass_per_length: 30, axial_stiffness: 5.0e6}
vessels:
  - name: buoy
    mode: prescribed
    position: [0, 0, 0]
    motion: {period: 10, amplitude: [0, 0, 1, 0, 0, 0]}
lines:
  - name: tether
    end_a: {type: vessel, vessel: buoy, position: [0, 0, -5]}
    end_b: {type: anchored, position: [0, 0, -100]}
    sections: [{type: wire, length: 90, elements: 10}]
dynamics: {duration: 40, time_step: 0.1, ramp_time: 10, output_interval: 1.0}
output: {vtk: false}
)");
  const Outcome o = runCli("run " + (dir / "model.yaml").string() + " -o " + (dir / "out").string() +
                           " --no-plots --no-report");
  ASSERT_EQ(o.code, 0) << o.output;
  EXPECT_NE(o.output.find("line 'tether' end A: "), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("line 'tether' end B: "), std::string::npos) << o.output;
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

// A mooring chain laid across a pipeline on the seabed: the program's start shapes pass through each other
// and the later line (the chain) is laid over the earlier one before statics; the log says which, where and
// how to choose otherwise, and the static chain rests on the pipeline (SeabedCrossingTest has the physics).
TEST(Cli, CrossedStartShapesAreLaidOverAndTheLogSaysSo) {
  const fs::path dir = modelFolder("tangle_cli_crossing", R"(title: chain across a pipeline
environment:
  water_depth: 100
  seabed: {normal_stiffness: 1.0e5, friction_coefficient: 0.5}
line_types:
  - {name: chain76, outer_diameter: 0.1368, mass_per_length: 114.9, axial_stiffness: 4.93e8}
  - {name: pipe16, outer_diameter: 0.4064, mass_per_length: 250, axial_stiffness: 6.0e9, bending_stiffness: 1.2e8, torsional_stiffness: 9.0e7}
lines:
  - name: pipeline
    end_a: {type: anchored, position: [0, -150, -100]}
    end_b: {type: anchored, position: [0, 150, -100]}
    sections: [{type: pipe16, length: 300, elements: 60}]
  - name: chain
    end_a: {type: anchored, position: [-250, 0, -100]}
    end_b: {type: pinned, position: [250, 0, -10]}
    sections: [{type: chain76, length: 560, elements: 112}]
contact: {}
)");
  // `check` says so before any run.
  const Outcome check = runCli("check " + (dir / "model.yaml").string());
  ASSERT_EQ(check.code, 0) << check.output;
  EXPECT_NE(check.output.find("start shapes: line 'chain' laid over line 'pipeline'"), std::string::npos)
      << check.output;
  const fs::path out = dir / "out";
  const Outcome o =
      runCli("run " + (dir / "model.yaml").string() + " -o " + out.string() + " --statics-only --no-plots");
  ASSERT_EQ(o.code, 0) << o.output;
  EXPECT_NE(o.output.find("start shapes: line 'chain' laid over line 'pipeline' at 249.99 m along 'chain'"),
            std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("list them the other way round or give lines[chain].start_shape"),
            std::string::npos)
      << o.output;
  // The chain's node at the crossing (arc 250 m, x = 0) lies above the pipeline's top (z = -100 + 0.41 m).
  std::ifstream csv(out / "statics" / "chain.csv");
  std::string row;
  std::getline(csv, row);
  double crossingZ = -1e9;
  while (std::getline(csv, row)) {
    double arc = 0.0, x = 0.0, y = 0.0, z = 0.0;
    ASSERT_EQ(std::sscanf(row.c_str(), "%lf,%lf,%lf,%lf", &arc, &x, &y, &z), 4) << row;
    if (std::abs(arc - 250.0) < 1e-6) crossingZ = z;
  }
  EXPECT_GT(crossingZ, -100.0 + 0.4064);
}

// The no-collision check of two pipes crossing 0.3 m apart between nodes of both (9 elements of 11.1 m
// each, the crossing mid-element): the terminal's FAIL against a required 0.5 m (the nodes alone read 5.3 m
// and passed before the crossing pass, ClearanceEnvelope.hpp).
TEST(Cli, ClearanceCheckFailsTwoLinesCrossingBetweenNodes) {
  const fs::path dir = modelFolder("tangle_cli_crossing_clearance", R"(title: two pipes crossing mid-element
environment:
  water_depth: 200
line_types:
  - {name: pipe, outer_diameter: 0.3, mass_per_length: 50, axial_stiffness: 1.0e9, bending_stiffness: 1.0e6, torsional_stiffness: 1.0e6}
lines:
  - name: a
    end_a: {type: fixed, position: [-50, 0, -50]}
    end_b: {type: fixed, position: [50, 0, -50]}
    sections: [{type: pipe, length: 100, elements: 9}]
  - name: b
    end_a: {type: fixed, position: [0, -50, -49.4]}
    end_b: {type: fixed, position: [0, 50, -49.4]}
    sections: [{type: pipe, length: 100, elements: 9}]
contact: {}
clearance: {required: 0.5}
)");
  const fs::path out = dir / "out";
  const Outcome o =
      runCli("run " + (dir / "model.yaml").string() + " -o " + out.string() + " --statics-only --no-plots");
  ASSERT_EQ(o.code, 0) << o.output;
  EXPECT_NE(o.output.find("a / b: static min 0.300 m: FAIL"), std::string::npos) << o.output;
}

// A pair designed to touch (examples/flexibles-at-touchdown: the riser laid across the flowline) is assessed
// by its impacts (DNV-RP-F203 sec. 4, collision allowed), not failed for touching: the verdict follows
// clearance.allowed_impact_energy against the largest impact energy of the pair, the one the clash report
// gives (contact/summary.json), and without that energy the impacts are reported, not assessed. The first
// 60 s hold the example's three impacts (47.5-49 s).
TEST(Cli, ACollisionAllowedPairIsAssessedByItsImpacts) {
  std::ifstream in(std::string(tangle::test::kExamplesDir) + "/flexibles-at-touchdown/model.yaml");
  std::stringstream example;
  example << in.rdbuf();
  const std::string key = "collision_allowed: [[flowline, riser]]";
  ASSERT_NE(example.str().find(key), std::string::npos) << "the example's clearance block changed";
  ASSERT_NE(example.str().find("duration: 300"), std::string::npos);
  const auto variant = [&](const std::string& name, const std::string& energy) {
    std::string text = example.str();
    text.replace(text.find("duration: 300"), 13, "duration: 60");
    if (!energy.empty())
      text.replace(text.find(key), key.size(), key + "\n  allowed_impact_energy: " + energy);
    const fs::path dir = modelFolder(name, text);
    const Outcome o = runCli("run " + (dir / "model.yaml").string() + " -o " + (dir / "out").string() +
                             " --no-plots --no-report");
    return std::pair(o, dir / "out");
  };
  const auto [reported, reportedOut] = variant("tangle_cli_collision_allowed", "");
  ASSERT_EQ(reported.code, 0) << reported.output;
  const YAML::Node clash = YAML::LoadFile((reportedOut / "contact" / "summary.json").string());
  const YAML::Node pair = YAML::LoadFile((reportedOut / "clearance" / "summary.json").string())["pairs"][0];
  const int impacts = clash["pairs"][0]["impacts"].as<int>();
  const double largest = clash["pairs"][0]["impact_energy_J"]["max"].as<double>();
  ASSERT_GE(impacts, 1);
  EXPECT_EQ(pair["criterion"].as<std::string>(), "collision allowed");
  EXPECT_EQ(pair["impacts"].as<int>(), impacts);
  EXPECT_DOUBLE_EQ(pair["max_impact_energy_J"].as<double>(), largest);
  EXPECT_TRUE(pair["pass"].IsNull());
  EXPECT_LT(pair["min_clearance_m"].as<double>(), 0.0);  // they touch, and that is not a FAIL
  EXPECT_NE(reported.output.find("collision allowed, " + std::to_string(impacts) + " impact(s)"),
            std::string::npos)
      << reported.output;
  EXPECT_NE(reported.output.find("(not assessed: no clearance.allowed_impact_energy)"), std::string::npos);
  EXPECT_EQ(reported.output.find(": FAIL"), std::string::npos) << reported.output;
  // An allowed energy above the largest impact passes, one below it fails.
  const auto exact = [](double v) {
    std::ostringstream text;
    text.precision(17);
    text << v;
    return text.str();
  };
  const auto [above, aboveOut] = variant("tangle_cli_collision_allowed_above", exact(2.0 * largest));
  ASSERT_EQ(above.code, 0) << above.output;
  EXPECT_TRUE(
      YAML::LoadFile((aboveOut / "clearance" / "summary.json").string())["pairs"][0]["pass"].as<bool>());
  EXPECT_NE(above.output.find(": PASS"), std::string::npos) << above.output;
  const auto [below, belowOut] = variant("tangle_cli_collision_allowed_below", exact(0.5 * largest));
  ASSERT_EQ(below.code, 0) << below.output;
  EXPECT_FALSE(
      YAML::LoadFile((belowOut / "clearance" / "summary.json").string())["pairs"][0]["pass"].as<bool>());
  EXPECT_NE(below.output.find(": FAIL"), std::string::npos) << below.output;
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
  EXPECT_NE(o.output.find(
                "  lines 'mooring' / 'riser': smallest clearance at the output times after the ramp -0.00"),
            std::string::npos)
      << o.output;
  // The clash summary's minimum is the same one, after the ramp (it took the ramp's output times too until
  // 2026-12-06, unlabelled).
  const auto numberAfter = [&](const std::string& key) {
    const std::size_t at = o.output.find(key);
    return at == std::string::npos ? std::nan("") : std::stod(o.output.substr(at + key.size()));
  };
  const double extremes =
      numberAfter("'mooring' / 'riser': smallest clearance at the output times after the ramp ");
  const double clash = numberAfter("; min clearance at the output times after the ramp ");
  EXPECT_TRUE(std::isfinite(clash)) << o.output;
  EXPECT_NEAR(clash, extremes, 1e-3) << o.output;
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
  EXPECT_EQ(
      firstLine(out / "dynamics" / "mooring" / "range.csv"),
      "arc_length_m,tension_min_N,tension_max_N,tension_mean_N,curvature_min_1_per_m,curvature_max_1_per_m,"
      "curvature_mean_1_per_m,seabed_clearance_min_m");
  EXPECT_NE(firstLine(out / "dynamics" / "riser" / "range.csv").find("bending_moment_max_Nm"),
            std::string::npos);
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

// A viscoelastic rope's range graph covers its tension histories: every node's range.csv minimum and
// maximum bracket the column of effective_tension_N.csv (printed to 7 digits: 1e-6 of the value). The
// ranges are taken at every step on the writer's thread from a copy of the step's state, which held the
// positions only: the rope's tension, an internal variable of the committed state, fell back to its static
// EA (examples/polyester-taut-mooring: a fairlead maximum 2.512 MN in range.csv and summary.json against
// 2.758 MN in the history, 9 % low, and the fatigue ranges with it; review, 2026-12-06).
TEST(Cli, ViscoelasticRopesRangeGraphCoversItsTensionHistories) {
  const fs::path out = fs::temp_directory_path() / "tangle_cli_polyester_range";
  fs::remove_all(out);
  const Outcome o =
      runCli("run " + std::string(tangle::test::kExamplesDir) + "/polyester-taut-mooring/model.yaml -o " +
             out.string() + " --no-plots --no-report -q");
  ASSERT_EQ(o.code, 0) << o.output;
  const auto [rangeHeader, range] = readNumericCsv(out / "dynamics" / "leg" / "range.csv");
  const auto [historyHeader, history] = readNumericCsv(out / "dynamics" / "leg" / "effective_tension_N.csv");
  ASSERT_EQ(rangeHeader[1], "tension_min_N");
  ASSERT_EQ(rangeHeader[2], "tension_max_N");
  ASSERT_EQ(historyHeader.size(), range.size() + 1);  // time, then one column per node
  for (std::size_t node = 0; node < range.size(); ++node) {
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const auto& row : history) {
      low = std::min(low, row[node + 1]);
      high = std::max(high, row[node + 1]);
    }
    EXPECT_LE(range[node][1], low + 1e-6 * std::abs(low)) << historyHeader[node + 1];
    EXPECT_GE(range[node][2], high - 1e-6 * std::abs(high)) << historyHeader[node + 1];
  }
  fs::remove_all(out);
}

/// A fixed vessel at the origin with the given RAO row values (surge ... yaw, amplitude and lag per DOF,
/// every period and heading of its table alike) in a regular wave of 2 m and 10 s along its axis, holding
/// a tether's top 10 m forward and 5 m down: the model of the wave-frequency motion tests below.
std::string fixedVesselWithRaos(const std::string& title, const std::string& rowValues) {
  std::string rows;
  for (const char* at : {"5, 0", "5, 180", "15, 0", "15, 180"})
    rows += "        - [" + std::string(at) + ", " + rowValues + "]\n";
  return "title: " + title + R"(
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
)" + rows +
         R"(lines:
  - name: tether
    end_a: {type: anchored, position: [10, 0, -100]}
    end_b: {type: vessel, vessel: ship, position: [10, 0, -5]}
    sections: [{type: wire, length: 94.9, elements: 10}]
dynamics: {duration: 30, time_step: 0.05, ramp_time: 10, output_interval: 0.1}
)";
}

// Issue 45: dynamics/vessels.csv gives, beside each vessel's low-frequency pose, the wave-frequency (RAO)
// motion its line ends get. A fixed vessel with heave 0.5 m/m (lag 0) and pitch 2 deg/m (lag 90) in a
// regular wave of 2 m (amplitude a = 1 m) along its axis: the _wf_z_ column's amplitude is 0.5 m and
// _wf_ry_ 2 deg (first order, RaoMotion.hpp; sampled every 0.1 s, a tenth of a percent below the peak at
// most), the low-frequency pose stays 0; and the fairlead, 10 m forward and 5 m down, moves as the vessel
// point: z = z0 + wf_z - 10 m x wf_ry (small rotation about +y; rad), to the columns' printed digits.
TEST(Cli, VesselsCsvGivesTheWaveFrequencyMotionTheFairleadsGet) {
  const fs::path dir =
      modelFolder("tangle_cli_vessel_wf",
                  fixedVesselWithRaos("fixed vessel with RAOs", "0, 0, 0, 0, 0.5, 0, 0, 0, 2.0, 90, 0, 0"));
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

// A vessel's offset is its total offset (DNV-OS-E301 Ch.2 Sec.2: mean, low- and wave-frequency combined): a
// fixed vessel with a surge RAO of 0.7 m/m (lag 0) in a regular wave of 2 m along its axis (amplitude 1 m)
// surges 0.7 m at the wave frequency about its model position, so its largest offset over the run is 0.7 m
// (first order, RaoMotion.hpp; every step of 0.05 s samples the 10 s cycle within 0.012 % of its peak;
// tolerance 0.1 %). Until 2026-12-06 the offset was the vessel node's, the low-frequency pose alone: 0.
TEST(Cli, AVesselsOffsetIncludesItsWaveFrequencyMotion) {
  const fs::path dir = modelFolder(
      "tangle_cli_vessel_offset",
      fixedVesselWithRaos("fixed vessel surging with the waves", "0.7, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0"));
  const fs::path out = dir / "out";
  const Outcome o =
      runCli("run " + (dir / "model.yaml").string() + " -o " + out.string() + " --no-plots --no-report -q");
  ASSERT_EQ(o.code, 0) << o.output;
  std::ifstream in(out / "dynamics" / "summary.json");
  std::stringstream text;
  text << in.rdbuf();
  const std::string summary = text.str();
  const std::string key = "\"max_offset_m\":";
  const std::size_t at = summary.find(key);
  ASSERT_NE(at, std::string::npos) << summary;
  const double offset = std::stod(summary.substr(at + key.size()));
  EXPECT_NEAR(offset, 0.7, 0.001 * 0.7);
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

// Issue 45: a riser with contents and pressure writes its wall tension wherever it writes its effective
// tension: the statics table (with the internal pressure), the time history at every output time, the range
// graph and results.h5. Each time history value is T_e + p_i A_i - p_e A_e of the same node and time (the
// effective tension and z files; p_i = p_ref + rho_c g (z_ref - z), one contents density), to the precision
// of the printed values (7 digits of 3 MN: 20 N over the three numbers). A vertical TTR on a tensioner, the
// vessel heaving 0.5 m.
TEST(Cli, PipeLineWritesItsWallTensionEverywhere) {
  const fs::path dir = modelFolder("tangle_cli_wall_tension", R"(title: TTR with oil at 20 MPa
environment: {water_depth: 300}
line_types:
  - {name: riser, outer_diameter: 0.32, internal_diameter: 0.25, mass_per_length: 150,
     axial_stiffness: 5.0e9, bending_stiffness: 2.0e7}
vessels:
  - {name: tlp, mode: prescribed, position: [0, 0, 0], motion: {amplitude: [0, 0, 0.5, 0, 0, 0], period: 10}}
lines:
  - name: riser
    contents: {density: 850, pressure: 2.0e7, reference_z: 0}
    end_a: {type: pinned, position: [0, 0, -290]}
    end_b: {type: vessel, vessel: tlp, position: [0, 0, -10], tensioner: {tension: 2.0e6}}
    sections: [{type: riser, length: 279.9, elements: 28}]
dynamics: {duration: 20, time_step: 0.05, ramp_time: 5, output_interval: 0.5}
output: {vtk: false, format: both}
)");
  const fs::path out = dir / "out";
  const Outcome o =
      runCli("run " + (dir / "model.yaml").string() + " -o " + out.string() + " --no-plots --no-report");
  ASSERT_EQ(o.code, 0) << o.output;
  // 150 kg/m of pipe and 850 x pi/4 0.25^2 = 41.7 kg/m of oil over 279.9 m.
  EXPECT_NE(o.output.find("mass 53.7 t (contents 11.7 t)"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("contents: internal pressure 20.00 MPa at z = 0.00 m (gauge)"), std::string::npos);
  std::ifstream statics(out / "statics" / "riser.csv");
  std::string header;
  std::getline(statics, header);
  EXPECT_EQ(
      header.rfind("arc_length_m,x_m,y_m,z_m,effective_tension_N,wall_tension_N,internal_pressure_Pa,", 0),
      0u)
      << header;
  std::ifstream range(out / "dynamics" / "riser" / "range.csv");
  std::getline(range, header);
  EXPECT_NE(header.find(",wall_tension_min_N,wall_tension_max_N,wall_tension_mean_N,"), std::string::npos)
      << header;
  const auto [wallHeader, wall] = readNumericCsv(out / "dynamics" / "riser" / "wall_tension_N.csv");
  const auto [tensionHeader, tension] =
      readNumericCsv(out / "dynamics" / "riser" / "effective_tension_N.csv");
  const auto [zHeader, z] = readNumericCsv(out / "dynamics" / "riser" / "z_m.csv");
  ASSERT_EQ(wallHeader, tensionHeader);
  ASSERT_EQ(wall.size(), tension.size());
  ASSERT_GE(wall.size(), 40u);
  const double pi = 3.141592653589793, g = 9.80665, rho = 1025.0;
  const double ai = pi / 4.0 * 0.25 * 0.25, ae = pi / 4.0 * 0.32 * 0.32;
  double worst = 0.0;
  for (std::size_t k = 0; k < wall.size(); ++k)
    for (std::size_t i = 1; i < wall[k].size(); ++i) {
      const double depth = -z[k][i];
      const double expected = tension[k][i] + (2.0e7 + 850.0 * g * depth) * ai - rho * g * depth * ae;
      worst = std::max(worst, std::abs(wall[k][i] - expected));
    }
  EXPECT_LT(worst, 20.0);
  RecordProperty("largest_wall_tension_difference_N", std::to_string(worst));
}

}  // namespace
