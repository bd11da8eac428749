#include "src/check/verdict.hpp"

#include <fmt/format.h>

namespace loom {

std::string centre_note(const QualitySummary& q) {
  if (q.below_zero > 0 || q.verdict_below_zero == 0) return {};
  return fmt::format("; but {} hex{} with every corner positive {} a centre Jacobian <= 0 (Verdict's hex scaled "
                     "Jacobian, as ParaView's Mesh Quality shows it: minimum {:.3f})",
                     q.verdict_below_zero, q.verdict_below_zero == 1 ? "" : "es",
                     q.verdict_below_zero == 1 ? "has" : "have", q.min_verdict_scaled_jacobian);
}

std::string verdict_line(const ValidityReport& report) {
  const CriterionResult* first = report.first_failure();
  const QualitySummary& q = report.quality;
  if (!first)
    return fmt::format("valid: {} hexes, min scaled Jacobian {:.3f}, mean {:.3f}, {} below 0.2{}", report.hexes,
                       q.min_scaled_jacobian, q.mean_scaled_jacobian, q.below_0_2, centre_note(q));
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
          {"verdict_min_scaled_jacobian", report.quality.min_verdict_scaled_jacobian},
          {"verdict_below_zero", report.quality.verdict_below_zero},
          {"boundary_components", report.boundary_components},
          {"boundary_genus", report.boundary_genus},
          {"criteria", criteria}};
}

}  // namespace loom
