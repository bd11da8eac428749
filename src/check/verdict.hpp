#pragma once
// How `loom check` reports a ValidityReport: one verdict line, or JSON.
#include <nlohmann/json.hpp>
#include <string>

#include "src/check/validity.hpp"

namespace loom {

/// "valid: 60 hexes, min scaled Jacobian 1.000, mean 1.000, 0 below 0.2" (and
/// centre_note's words when a centre is at or below 0), or
/// "invalid: criterion 3 (no doublets) fails: hexes 4 and 9 share 2 faces; also fails 4, 7"
/// (the first failed criterion's detail, then the other evaluated failures).
std::string verdict_line(const ValidityReport& report);

/// "; but 3 hexes with every corner positive have a centre Jacobian <= 0
/// (...)" when criterion 7 holds and Verdict's centre test does not; "" otherwise.
std::string centre_note(const QualitySummary& quality);

/// {"valid", "combinatorial_valid", "verdict", "hexes", "nodes",
///  "min_scaled_jacobian", "mean_scaled_jacobian", "below_zero", "below_0_2",
///  "verdict_min_scaled_jacobian", "verdict_below_zero", "boundary_components", "boundary_genus",
///  "criteria": [{"number", "name", "passed", "evaluated", "detail"}...]}
nlohmann::json validity_json(const ValidityReport& report);

}  // namespace loom
