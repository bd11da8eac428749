#include "src/check/verdict.hpp"

#include <fmt/format.h>

namespace loom {

std::string verdict_line(const ValidityReport& report) {
  const CriterionResult* first = report.first_failure();
  if (!first)
    return fmt::format("valid: {} hexes, min scaled Jacobian {:.3f}, mean {:.3f}, {} below 0.2", report.hexes,
                       report.quality.min_scaled_jacobian, report.quality.mean_scaled_jacobian,
                       report.quality.below_0_2);
  std::vector<int> others;
  for (const auto& c : report.criteria)
    if (!c.passed && c.evaluated && &c != first) others.push_back(c.number);
  std::string line = fmt::format("invalid: criterion {} ({}) fails: {}", first->number, first->name, first->detail);
  if (!others.empty()) line += fmt::format("; also fails {}", fmt::join(others, ", "));
  return line;
}

nlohmann::json validity_json(const ValidityReport& report) {
  nlohmann::json criteria = nlohmann::json::array();
  for (const auto& c : report.criteria)
    criteria.push_back({{"number", c.number},
                        {"name", c.name},
                        {"passed", c.passed},
                        {"evaluated", c.evaluated},
                        {"detail", c.detail}});
  return {{"valid", report.valid()},
          {"combinatorial_valid", report.combinatorial_valid()},
          {"verdict", verdict_line(report)},
          {"hexes", report.hexes},
          {"nodes", report.nodes},
          {"min_scaled_jacobian", report.quality.min_scaled_jacobian},
          {"mean_scaled_jacobian", report.quality.mean_scaled_jacobian},
          {"below_zero", report.quality.below_zero},
          {"below_0_2", report.quality.below_0_2},
          {"boundary_components", report.boundary_components},
          {"boundary_genus", report.boundary_genus},
          {"criteria", criteria}};
}

}  // namespace loom
