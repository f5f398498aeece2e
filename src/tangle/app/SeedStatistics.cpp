#include "tangle/app/SeedStatistics.hpp"

#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <string_view>
#include <utility>

#include "tangle/analysis/ExtremeStatistics.hpp"
#include "tangle/core/Csv.hpp"
#include "tangle/core/OutputFile.hpp"

namespace tangle::app {

namespace {

std::string number(double v) { return std::isfinite(v) ? fmt::format("{:.6e}", v) : ""; }

/// The terminal table's name and scale of a quantity: forces in kN as in the batch's summary table (issue 45:
/// the statistics were printed in N beside it), the file keeps SI units.
std::pair<std::string, double> display(const std::string& quantity) {
  constexpr std::string_view newtons = "_N";
  if (quantity.size() > newtons.size() && quantity.ends_with(newtons))
    return {quantity.substr(0, quantity.size() - newtons.size()) + " [kN]", 1e-3};
  return {quantity, 1.0};
}

/// One maximum of a row: its name and how to read it (NaN where the case has none).
struct Quantity {
  std::string name;
  std::function<double(const CaseSummary&)> value;
};

}  // namespace

std::string writeSeedStatistics(const std::filesystem::path& file, const BatchPlan& plan,
                                const std::vector<std::string>& lineNames, const std::vector<CaseSummary>& rows) {
  const std::size_t seeds = plan.seeds.size();
  std::vector<Quantity> quantities;
  const auto lineValue = [](const std::string& line, double CaseSummary::LineRow::*field) {
    return [line, field](const CaseSummary& r) {
      for (const CaseSummary::LineRow& l : r.lines)
        if (l.name == line) return l.*field;
      return std::nan("");
    };
  };
  for (const std::string& l : lineNames) {
    quantities.push_back({l + "_max_tension_N", lineValue(l, &CaseSummary::LineRow::maxTension)});
    quantities.push_back({l + "_end_a_max_tension_N", lineValue(l, &CaseSummary::LineRow::endAMax)});
    quantities.push_back({l + "_end_b_max_tension_N", lineValue(l, &CaseSummary::LineRow::endBMax)});
  }
  quantities.push_back({"max_offset_m", [](const CaseSummary& r) { return r.maxOffset; }});
  quantities.push_back({"max_contact_force_N", [](const CaseSummary& r) { return r.maxContactForce; }});

  core::OutputFile out(file);
  std::string header = "case";
  for (std::size_t k = 0; k + 1 < plan.parameterNames.size(); ++k) header += "," + core::csvField(plan.parameterNames[k]);
  const std::string q = fmt::format("{:g}", 100.0 * plan.probability);
  header += ",quantity,seeds,completed_seeds,mean,standard_deviation,min,max,gumbel_scale,most_probable_maximum,"
            "value_at_" + q + "_percent,maxima\n";
  out.write(header);
  std::string table = fmt::format("{:<36} {:<36} {:>6} {:>14} {:>14} {:>14}\n", "case", "quantity", "seeds", "mean",
                                  "MPM (Gumbel)", q + " % value");
  for (std::size_t first = 0; first + seeds <= rows.size(); first += seeds) {
    // The case's name: its first seed's, without "_seed=<value>".
    std::string name = rows[first].name;
    if (const std::size_t cut = name.rfind("seed="); cut != std::string::npos)
      name = name.substr(0, cut > 0 && name[cut - 1] == '_' ? cut - 1 : cut);
    if (name.empty()) name = "base";
    for (const Quantity& quantity : quantities) {
      std::vector<double> maxima;
      std::string list;
      bool any = false;
      for (std::size_t s = first; s < first + seeds; ++s) {
        const double v = quantity.value(rows[s]);
        any = any || std::isfinite(v);
        if (rows[s].exitCode == 0 && std::isfinite(v)) maxima.push_back(v);
        list += (s == first ? "" : ";") + number(v);
      }
      if (!any) continue;  // a quantity no seed has (no vessel, no contact)
      std::string row = core::csvField(name);
      for (std::size_t k = 0; k + 1 < plan.parameterNames.size(); ++k)
        row += "," + core::csvField(k < rows[first].parameterValues.size() ? rows[first].parameterValues[k] : "");
      row += fmt::format(",{},{},{}", core::csvField(quantity.name), seeds, maxima.size());
      if (maxima.size() >= 2) {
        const analysis::GumbelFit g = analysis::fitGumbel(maxima);
        double lo = maxima.front(), hi = maxima.front();
        for (const double v : maxima) {
          lo = std::min(lo, v);
          hi = std::max(hi, v);
        }
        const double atQ = g.quantile(plan.probability);
        row += fmt::format(",{},{},{},{},{},{},{}", number(g.mean), number(g.standardDeviation), number(lo),
                           number(hi), number(g.scale), number(g.mode), number(atQ));
        const auto [label, scale] = display(quantity.name);
        table += fmt::format("{:<36} {:<36} {:>6} {:>14.6g} {:>14.6g} {:>14.6g}\n", name.substr(0, 36),
                             label.substr(0, 36), maxima.size(), scale * g.mean, scale * g.mode, scale * atQ);
      } else {
        row += ",,,,,,,";
      }
      out.write(row + "," + core::csvField(list) + "\n");
    }
  }
  out.close();
  table += fmt::format("statistics over {} seeds per case in {}\n", seeds, file.string());
  return table;
}

}  // namespace tangle::app
