#include "src/cli/weave_report.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "src/check/edge_valence.hpp"
#include "src/check/hex_sheets.hpp"
#include "src/check/quality_histogram.hpp"
#include "src/check/validity.hpp"
#include "src/geometry/inversion_causes.hpp"

namespace loom::cli {

namespace {

/// Per hex source: its hexes, how many are inverted (scaled Jacobian <= 0),
/// the least scaled Jacobian and the histogram; a source with no hexes is left out.
nlohmann::json quality_by_source(const HexMesh& mesh, const std::vector<closure::HexSource>& source) {
  struct Tally {
    std::size_t hexes = 0, inverted = 0;
    double least = 1;
    QualityHistogram histogram;
  };
  std::map<std::string, Tally> by_source;
  for (std::size_t h = 0; h < mesh.hexes.size() && h < source.size(); ++h) {
    Tally& t = by_source[closure::source_name(source[h])];
    const double sj = scaled_jacobian(mesh, h);
    ++t.hexes;
    t.inverted += !(sj > 0);
    t.least = std::isnan(sj) ? -1 : std::min(t.least, sj);
    t.histogram.add(sj);
  }
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [name, t] : by_source)
    out[name] = {{"hexes", t.hexes}, {"inverted", t.inverted}, {"min_scaled_jacobian", t.least},
                 {"scaled_jacobian_histogram", histogram_json(t.histogram)}};
  return out;
}

}  // namespace

nlohmann::json report_json(const std::string& input, const SurfaceFigures& surface, const pipeline::MeshingResult& r) {
  const SurfaceAngleBound& bound = surface.bound;
  const engine::Strategy& strategy = r.strategy;
  nlohmann::json j;
  j["input"] = input;
  j["strategy"] = strategy.name();
  j["seed"] = strategy.seed;
  j["attempts"] = r.attempts;
  j["woven_attempt"] = r.woven_attempt;
  j["backtracks"] = r.weave.backtracks;
  j["phases"] = nlohmann::json::array();
  for (const auto& p : r.weave.phases)
    j["phases"].push_back({{"name", p.name},
                           {"steps", p.steps},
                           {"backtracks", p.backtracks},
                           {"searched", p.searched},
                           {"seconds", p.seconds}});
  j["closed"] = r.weave.closed;
  j["steps"] = r.weave.steps;
  j["rule_applications"] = r.weave.applications;
  j["whiskers_left"] = r.weave.whiskers_left;
  j["filled"] = r.filled();
  j["made_by"] = r.made_by.empty() ? "nothing" : r.made_by;
  j["cut_disks"] = r.cut_disks;
  j["prefer"] = r.prefer == pipeline::Prefer::quality ? "quality" : "fewest-hexes";
  j["woven_hexes"] = r.stc.hexes();
  j["hexes"] = r.mesh ? r.mesh->hexes.size() : 0;
  j["mesh_hexes"] = j["hexes"];
  nlohmann::json sources = nlohmann::json::object();
  for (auto s : {closure::HexSource::woven, closure::HexSource::searched, closure::HexSource::database,
                 closure::HexSource::filled, closure::HexSource::pillow})
    sources[closure::source_name(s)] = std::count(r.source.begin(), r.source.end(), s);
  j["hex_sources"] = sources;
  if (r.made_by == "closed" || r.made_by == "searched" || !r.closure_failure.empty()) {
    const auto& c = r.closure;
    j["closure"] = {{"woven_kept", c.woven}, {"woven_peeled", c.peeled}, {"cavities", c.cavities},
                    {"front_quads", c.front_quads}, {"searched", c.searched}, {"database", c.database},
                    {"filled", c.filled}, {"pillowed", c.pillowed}, {"filled_cavities", c.filled_cavities},
                    {"fill_quads", c.fill_quads}, {"pull_backs", c.pull_backs}, {"search_expanded", c.search.expanded},
                    {"search_states", c.search.generated}, {"search_seconds", c.search.seconds},
                    {"seconds", c.seconds}};
    if (!r.closure_failure.empty()) j["closure_failure"] = r.closure_failure;
  }
  j["sheets"] = r.stc.sheets();
  j["chords"] = r.stc.chords();
  j["valid"] = r.check && r.check->valid();
  j["combinatorially_valid"] = r.combinatorially_valid();
  if (r.check) {
    j["min_scaled_jacobian"] = r.check->quality.min_scaled_jacobian;
    j["mean_scaled_jacobian"] = r.check->quality.mean_scaled_jacobian;
    j["below_zero"] = r.check->quality.below_zero;
    j["below_0_2"] = r.check->quality.below_0_2;
    j["verdict_min_scaled_jacobian"] = r.check->quality.min_verdict_scaled_jacobian;
    j["verdict_below_zero"] = r.check->quality.verdict_below_zero;
    j["scaled_jacobian_histogram"] = histogram_json(quality_histogram(*r.mesh));
    j["quality_by_source"] = quality_by_source(*r.mesh, r.source);
    nlohmann::json valences = nlohmann::json::object();
    std::size_t irregular = 0;
    for (const auto& [valence, edges] : interior_valence_histogram(*r.mesh)) {
      valences[std::to_string(valence)] = edges;
      if (valence != 4) irregular += edges;
    }
    j["interior_edge_valences"] = valences;
    j["irregular_interior_edges"] = irregular;
    const DepthProfile depth = depth_profile(*r.mesh);
    j["depth"] = {{"hexes_by_depth", depth.hexes}, {"inverted_by_depth", depth.inverted}, {"deepest", depth.deepest()}};
    nlohmann::json causes;
    for (auto c : {geometry::InversionCause::locked_corner, geometry::InversionCause::crowded_edge,
                   geometry::InversionCause::unexplained})
      causes[geometry::cause_name(c)] = r.inversions.of(c);
    j["inversion_causes"] = causes;
  }
  j["surface_angle_bound"] = {
      {"least_sine", bound.least_sine}, {"mean_sine", bound.mean_sine}, {"quads_below_0_2", bound.quads_below_0_2}};
  j["surface_half_thickness"] = {{"max", surface.half_thickness.max},
                                 {"median", surface.half_thickness.median},
                                 {"rays", surface.half_thickness.rays}};
  j["boundary_layer_hexes"] = r.boundary_layer.hexes_added;
  j["smoothing_iterations"] = r.smoothing.iterations;
  j["match_attempts"] = r.weave.counters.match_attempts;
  j["seconds"] = r.seconds;
  j["placement"] = {{"meshes", r.placements}, {"seconds", r.placement_seconds}};
  if (!r.weave.closed) j["left"] = r.weave.left;
  if (!r.failure.empty()) j["failure"] = r.failure;
  if (!r.fill_failure.empty()) j["fill_failure"] = r.fill_failure;
  if (!r.wide_search_stopped.empty()) j["wide_search_stopped"] = r.wide_search_stopped;
  return j;
}

std::vector<CellField> cell_fields(const HexMesh& mesh, const std::vector<closure::HexSource>& sources,
                                   const geometry::InversionDiagnosis& inversions) {
  CellField source{"source", {}, CellField::Kind::integer};
  for (auto s : sources) source.values.push_back(static_cast<double>(s));
  CellField quality{"scaled_jacobian", {}, CellField::Kind::real};
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) quality.values.push_back(scaled_jacobian(mesh, h));
  std::vector<CellField> fields{source, quality};
  const HexSheets sheets = hex_sheets(mesh);
  for (int d = 0; d < 3; ++d) {
    CellField sheet{fmt::format("sheet_{}", "ijk"[d]), {}, CellField::Kind::integer};
    for (const auto& three : sheets.of_hex) sheet.values.push_back(three[d]);
    fields.push_back(std::move(sheet));
  }
  CellField cause{"inversion_cause", {}, CellField::Kind::integer};
  for (auto c : inversions.cause) cause.values.push_back(static_cast<double>(c));
  fields.push_back(std::move(cause));
  return fields;
}

}  // namespace loom::cli
