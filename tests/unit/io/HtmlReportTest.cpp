#include <gtest/gtest.h>

#include <cmath>
#include <yaml-cpp/yaml.h>

#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/HtmlReport.hpp"

namespace tangle {
namespace {

model::ModelSpec reportSpec() {
  model::ModelSpec spec;
  spec.sourceFile = "report-test.yaml";
  spec.title = "a title with </script> in it";
  spec.environment.waterDepth = 100.0;
  spec.lineTypes["wire"] = test::cableType("wire", 0.1, 30.0, 1e8);
  spec.lines.push_back(test::simpleLine("wire </b>", "wire", 120.0, 50, model::EndKind::Anchored,
                                        Vec3(-100.0, 0.0, -100.0), model::EndKind::Fixed, Vec3(0.0, 0.0, -10.0)));
  return spec;
}

// A long run is decimated to at most kMaxFrames frames, every `stride` output times, while the end-tension
// history keeps every output time; the data are valid JSON (read here by yaml-cpp, JSON being YAML) with
// positions in mm, and no text can close the page's <script> element.
TEST(HtmlReport, DecimatesLongRunsAndEscapesText) {
  analysis::Simulation sim(reportSpec());
  const std::vector<solver::LineSnapshot> lines = sim.snapshot();
  io::HtmlReport report(sim.model(), "run", "summary with </script> too");
  const int outputs = 10001;
  report.planFrames(outputs);
  EXPECT_EQ(report.stride(), 26);  // ceil(10001 / 400): 51 nodes allow 400 frames
  report.setStatics(lines, sim.state(), nullptr, nullptr);
  model::State state = sim.state();
  for (int k = 0; k < outputs; ++k) {
    state.time = 0.1 * k;
    report.recordOutput(lines, state, nullptr, nullptr);
  }
  EXPECT_EQ(report.frameCount(), (outputs + 25) / 26);
  EXPECT_LE(report.frameCount(), io::HtmlReport::kMaxFrames);

  const std::string json = report.json();
  EXPECT_EQ(json.find("</script"), std::string::npos);
  EXPECT_EQ(json.find("</b"), std::string::npos);
  const YAML::Node data = YAML::Load(json);
  EXPECT_EQ(data["kind"].as<std::string>(), "run");
  EXPECT_EQ(data["decimation"]["stride"].as<int>(), 26);
  EXPECT_EQ(data["decimation"]["outputs"].as<int>(), outputs);
  ASSERT_EQ(data["frames"].size(), static_cast<std::size_t>(report.frameCount()));
  EXPECT_NEAR(data["frames"][1]["t"].as<double>(), 2.6, 1e-9);
  EXPECT_EQ(data["history"]["t"].size(), static_cast<std::size_t>(outputs));
  ASSERT_EQ(data["history"]["endTension"].size(), 2u);
  EXPECT_NEAR(data["history"]["endTension"][1][7].as<double>(), lines[0].endTensionB / 1000.0,
              1e-4 * std::abs(lines[0].endTensionB / 1000.0));
  const YAML::Node p = data["frames"][3]["lines"][0]["p"];
  ASSERT_EQ(p.size(), 3u * 51u);
  for (int i = 0; i < 51; ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(p[3 * i + c].as<long long>(), std::llround(1000.0 * lines[0].position[i][c]));
  const YAML::Node t = data["statics"]["lines"][0]["T"];
  for (int i = 0; i < 51; i += 10)
    EXPECT_NEAR(t[i].as<double>(), lines[0].tension[i] / 1000.0, 5e-4 * std::abs(lines[0].tension[i] / 1000.0));
}

}  // namespace
}  // namespace tangle
