#include "src/weave/step_dump.hpp"

#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "engine/dot.hpp"
#include "src/stc/sheet_diagram.hpp"
#include "src/util/atomic_file.hpp"
#include "src/util/error.hpp"

namespace loom::weave {

StepDumper::StepDumper(std::filesystem::path dir, bool svg) : dir_(std::move(dir)), svg_(svg) {
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec) fail_input(dir_.string(), "cannot create the DOT directory (" + ec.message() + ")", "choose another --dot DIR");
}

void StepDumper::emit(const std::string& stem, const std::string& dot) {
  write_text_atomically(dir_ / (stem + ".dot"), dot);
  written_.push_back(dir_ / (stem + ".dot"));
  if (svg_) to_draw_.push_back(dir_ / stem);
}

std::size_t StepDumper::render() {
  const std::size_t drawn = to_draw_.size();
  // Read back from the DOT files: a long weave's texts would not all fit in memory.
  for (const auto& stem : to_draw_) {
    std::ifstream in(stem.string() + ".dot", std::ios::binary);
    const std::string dot((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::filesystem::path svg = stem.string() + ".svg";
    stc::write_svg(svg, dot, failures_);
    written_.push_back(svg);
  }
  to_draw_.clear();
  return drawn;
}

void StepDumper::clear() {
  std::error_code ec;
  for (const auto& file : written_) std::filesystem::remove(file, ec);
  written_.clear();
  to_draw_.clear();
  failures_ = {};
}

void StepDumper::dump(const engine::Application& step, const stc::Stc& stc) {
  const engine::Graph& g = stc.graph();
  const auto& ids = stc.ids();
  engine::DotStyle style;
  style.graph_name = fmt::format("step {}: {}", step.step, step.rule->name);
  style.layout = "neato";
  std::set<engine::Id> touched;
  for (const engine::Match* m : {&step.matched, &step.result})
    for (engine::Id e : m->elements)
      if (e != engine::no_element && g.alive(e)) touched.insert(e);
  // What actions made (a pillow sheet's hexes, faces, edges, nodes, chords).
  for (engine::Id e = step.first_new; e < g.id_bound(); ++e)
    if (g.alive(e)) touched.insert(e);
  std::set<engine::Id> sheets;
  // Only what the step matched and made: a whole neighbourhood is unreadable.
  for (engine::Id e : touched) {
    style.highlight.insert(e);
    style.only.insert(e);
    if (g.kind(e) == ids.edge) sheets.insert(stc.edge_sheet(e));
  }
  std::ostringstream dot;
  engine::write_dot(dot, g, style);
  std::string stem = fmt::format("step-{:04}-{}", step.step, step.rule->name);
  emit(stem, dot.str());
  // Sheets are named by rank, as in `loom stc` and the final diagrams.
  std::size_t rank = 0;
  for (engine::Id sheet : g.members(ids.sheet)) {
    if (sheets.count(sheet)) {
      const std::string stem = fmt::format("step-{:04}-sheet-{}", step.step, rank);
      std::string diagram;
      try {
        diagram = stc::sheet_diagram_dot(stc, sheet);
      } catch (const std::runtime_error& e) {
        failures_.add(dir_ / (stem + ".dot"), e.what());
      }
      if (!diagram.empty()) emit(stem, diagram);
    }
    ++rank;
  }
}

}  // namespace loom::weave
