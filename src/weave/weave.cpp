#include "src/weave/weave.hpp"

#include <cstdlib>
#include <map>

#include <fmt/format.h>

namespace loom::weave {

std::filesystem::path default_rules_dir() {
  if (const char* env = std::getenv("LOOM_RULES"); env && *env) return env;
  return LOOM_RULES_DIR;
}

engine::Actions weave_actions(stc::Stc& stc) {
  engine::Actions actions;
  // place_hex_corner(n, v, a, b, c): n is the corner of the hex at v opposite
  // v, whose edges from v run to a, b and c: n = a + b + c - 2v.
  actions.add("place_hex_corner", [&stc](engine::Graph& g, std::span<const engine::Id> args) {
    const auto& ids = stc.ids();
    auto at = [&](engine::Id node) { return stc.points().at(static_cast<std::size_t>(g.get(node, ids.node_point))); };
    Vec3 v = at(args[1]);
    Vec3 n = at(args[2]) + at(args[3]) + at(args[4]) - 2.0 * v;
    g.set(args[0], ids.node_point, static_cast<std::int32_t>(stc.points().size()));
    stc.points().push_back(n);
  });
  return actions;
}

namespace {

std::string describe_left(const stc::Stc& stc) {
  const auto& g = stc.graph();
  std::map<std::size_t, std::size_t> valence;  // front valence -> nodes
  std::vector<std::size_t> front_valence(g.id_bound(), 0);
  for (engine::Id f : g.members(stc.ids().face))
    if (stc.is_whisker(f))
      for (unsigned i = 0; i < 4; ++i) ++front_valence[stc.face_node(f, i)];
  for (engine::Id n : g.members(stc.ids().node))
    if (front_valence[n]) ++valence[front_valence[n]];
  std::string text;
  for (auto [v, count] : valence) text += fmt::format("{}{} of valence {}", text.empty() ? "" : ", ", count, v);
  return fmt::format("{} whiskers (open front faces) left; front nodes: {}", stc.whiskers(), text);
}

}  // namespace

WeaveResult weave(stc::Stc& stc, std::vector<engine::Rule> rules, const WeaveOptions& options) {
  WeaveResult result;
  std::size_t limit = options.max_steps ? options.max_steps : 200 * stc.faces() + 10000;
  engine::Engine eng(stc.graph(), std::move(rules), weave_actions(stc), options.strategy);
  engine::Application app;
  while (eng.counters().steps < limit && eng.step(&app)) {
    stc.debug_check();
    if (options.after_step) options.after_step(app, stc);
  }
  result.steps = eng.counters().steps;
  result.step_limit_hit = result.steps >= limit;
  result.applications = eng.applications();
  result.counters = eng.counters();
  result.whiskers_left = stc.whiskers();
  result.closed = result.whiskers_left == 0 && stc.hexes() > 0;
  if (!result.closed) {
    result.left = describe_left(stc);
    if (result.step_limit_hit) result.left += fmt::format(" (stopped after {} applications)", result.steps);
  }
  return result;
}

}  // namespace loom::weave
