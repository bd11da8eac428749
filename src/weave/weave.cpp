#include "src/weave/weave.hpp"

#include <cstdlib>
#include <stdexcept>
#include <map>
#include <memory>

#include <fmt/format.h>

#include "engine/strategy_run.hpp"
#include "src/closure/database.hpp"
#include "src/weave/database_closure.hpp"
#include "src/weave/improper.hpp"
#include "src/weave/measures.hpp"
#include "src/weave/pillow.hpp"
#include "src/weave/remove_hex.hpp"

namespace loom::weave {

std::filesystem::path default_rules_dir() {
  if (const char* env = std::getenv("LOOM_RULES"); env && *env) return env;
  return LOOM_RULES_DIR;
}

engine::Strategy strategy_named(const std::string& spec) {
  const bool builtin = spec == "priority" || spec == "random" || spec.rfind("sequence:", 0) == 0;
  engine::Strategy s = engine::Strategy::parse(spec);
  if (!builtin) return s;
  // The engine's builtin repeats one apply; the weave backtracks over it.
  engine::StrategyNode backtrack;
  backtrack.op = engine::StrategyNode::Op::backtrack;
  backtrack.goal = "front";
  backtrack.body.push_back(std::move(s.phases.front().body.front().body.front()));
  s.phases.front() = {"weave", {std::move(backtrack)}};
  return s;
}

engine::Strategy strategy_of(const std::filesystem::path& rules_dir) {
  const auto file = rules_dir / "strategies" / "default.strategy";
  if (std::filesystem::exists(file)) return engine::Strategy::parse(file.string());
  return strategy_named("priority");
}

engine::Strategy default_strategy() {
  static const engine::Strategy shipped = strategy_of(default_rules_dir());
  return shipped;
}

namespace {

/// Open hex sides over all faces, in O(1): each face lacks one hex per open
/// side, so this is 2 per inner face + 1 per boundary face - 6 per hex (each
/// hex names six faces that name it back: STC invariant 5), zero exactly when
/// no whisker is left. The boundary faces are counted once, at construction:
/// no rule adds or removes one.
class OpenSides {
public:
  explicit OpenSides(const stc::Stc& stc) : stc_(stc) {
    for (engine::Id f : stc.graph().members(stc.ids().face)) boundary_faces_ += stc.is_boundary(f);
  }
  std::int64_t operator()() const {
    const auto& g = stc_.graph();
    return 2 * static_cast<std::int64_t>(g.size(stc_.ids().face)) - boundary_faces_ -
           6 * static_cast<std::int64_t>(g.size(stc_.ids().hex));
  }

private:
  const stc::Stc& stc_;
  std::int64_t boundary_faces_ = 0;
};

/// The position of a node, for the placement actions (which need one).
Vec3 placed(const stc::Stc& stc, engine::Id node, const char* action) {
  const Vec3* p = stc.position(node);
  if (!p) throw std::runtime_error(fmt::format("{}: node {} has no position yet", action, node));
  return *p;
}

}  // namespace

engine::Actions weave_actions(stc::Stc& stc, std::function<const closure::Database*()> database) {
  engine::Actions actions;
  add_geometric_measures(actions, stc);
  const engine::KindId node = stc.ids().node, hex = stc.ids().hex;
  // place_hex_corner(n, v, a, b, c): n is the corner of the hex at v opposite
  // v, whose edges from v run to a, b and c: n = a + b + c - 2v.
  actions.add("place_hex_corner", {{"n", node}, {"v", node}, {"a", node}, {"b", node}, {"c", node}}, [&stc](engine::Graph&, std::span<const engine::Id> args) {
    auto at = [&](engine::Id node) { return placed(stc, node, "place_hex_corner"); };
    stc.place(args[0], at(args[2]) + at(args[3]) + at(args[4]) - 2.0 * at(args[1]));
  });
  // place_off_face(n, a, b, d): n is the corner above a of a hex standing on
  // a front face a b . d (which faces away from the hex), at the face's
  // mean edge length from a.
  actions.add("place_off_face", {{"n", node}, {"a", node}, {"b", node}, {"d", node}}, [&stc](engine::Graph&, std::span<const engine::Id> args) {
    auto at = [&](engine::Id node) { return placed(stc, node, "place_off_face"); };
    Vec3 a = at(args[1]), ab = at(args[2]) - a, ad = at(args[3]) - a;
    Vec3 away = cross(ab, ad);
    double length = 0.5 * (norm(ab) + norm(ad)), size = norm(away);
    stc.place(args[0], size > 0 ? a - (length / size) * away : a);
  });
  // pillow_star(n): a pillow sheet around every hex at node n.
  actions.add("pillow_star", {{"n", node}}, [&stc](engine::Graph&, std::span<const engine::Id> args) {
    auto star = hexes_at_node(stc, args[0]);
    insert_pillow(stc, star);
  });
  // pillow_doublet(h1, h2): a pillow sheet around h1 and the hexes across
  // h1's faces at the ends of the edges h1 shares with h2 (their faces
  // there share two edges with h2's: without them in the set, a pillow hex
  // would meet h2 in three nodes).
  actions.add("pillow_doublet", {{"h1", hex}, {"h2", hex}}, [&stc](engine::Graph&, std::span<const engine::Id> args) {
    insert_pillow(stc, doublet_shrink_set(stc, args[0], args[1]));
  });
  // remove_hex(h): h taken off again, the inverse of gluing it on (remove_hex.hpp).
  actions.add("remove_hex", {{"h", hex}}, [&stc](engine::Graph&, std::span<const engine::Id> args) {
    remove_hex(stc, args[0]);
  });
  // closes_from_database(f): the front component of whisker f is closed and
  // small, and the closure database's mesh for it fits (database_closure.hpp);
  // close_from_database(f) puts that mesh in. The database is the one
  // `database` gives, else the default rules directory's, read on first use.
  const engine::KindId face = stc.ids().face;
  auto db = [database = std::move(database)]() -> const closure::Database* {
    if (database) return database();
    static const closure::Database shipped = closure::Database::load(closure::database_file(default_rules_dir()));
    return &shipped;
  };
  actions.add_test("closes_from_database", {{"f", face}}, [&stc, db](engine::Graph&, std::span<const engine::Id> args) {
    const closure::Database* d = db();
    return d && closes_from_database(stc, args[0], *d);
  });
  actions.add("close_from_database", {{"f", face}}, [&stc, db](engine::Graph&, std::span<const engine::Id> args) {
    const closure::Database* d = db();
    if (!d) throw std::runtime_error("close_from_database: the rules directory has no closure database (closure/database.txt)");
    close_from_database(stc, args[0], *d);
  });
  // split_pinched(n): one node per group of n's hexes that meet only at n;
  // each part's boundary flag is 1 exactly when it holds a boundary face.
  actions.add("split_pinched", {{"n", node}}, [&stc](engine::Graph&, std::span<const engine::Id> args) {
    split_pinched_node(stc, args[0]);
  });
  // pillow_improper_helps(n): two hexes at n meet improperly (improper.hpp)
  // and a pillow would leave fewer improper meetings. It tries the pillows
  // and undoes them.
  auto corners = std::make_shared<HexCornerCache>(stc);
  actions.add_test("pillow_improper_helps", {{"n", node}},
                   [&stc, corners](engine::Graph&, std::span<const engine::Id> args) {
                     auto pair = improper_pair_at(stc, args[0], *corners);
                     return pair && best_improper_pillow(stc, pair->first, pair->second).has_value();
                   });
  // pillow_improper(n): the pillow sheet that parts them, where it helps.
  actions.add("pillow_improper", {{"n", node}}, [&stc, corners](engine::Graph&, std::span<const engine::Id> args) {
    auto pair = improper_pair_at(stc, args[0], *corners);
    if (!pair || !pillow_improper_pair(stc, pair->first, pair->second))
      throw std::runtime_error(fmt::format("no pillow helps at node {} (test it with pillow_improper_helps)", args[0]));
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

const std::vector<std::string>& strategy_measures() {
  static const std::vector<std::string> names{"front", "inverted", "irregular"};
  return names;
}

WeaveResult weave(stc::Stc& stc, std::vector<engine::Rule> rules, const WeaveOptions& options) {
  WeaveResult result;
  engine::Engine eng(stc.graph(), std::move(rules), weave_actions(stc, options.database), options.strategy.seed);
  if (stc::invariant_checks_on() || !options.check_rules.empty())
    eng.check_after([&stc](const engine::Graph&) { return stc.check_invariants(); },
                    stc::invariant_checks_on() ? std::vector<std::string>{} : options.check_rules);
  const OpenSides front(stc);
  engine::StrategyDomain domain;
  domain.measures["front"] = [&front] { return front(); };
  domain.measures["inverted"] = [&stc] { return inverted_hexes(stc); };
  domain.measures["irregular"] = [&stc] { return irregular_edges(stc); };
  domain.max_steps = options.max_steps ? options.max_steps : 200 * stc.faces() + 10000;
  if (options.after_step) domain.after_step = [&](const engine::Application& app) { options.after_step(app, stc); };
  domain.after_undo = options.after_undo;
  engine::check_strategy(options.strategy, eng.rules(), strategy_measures());
  const engine::StrategyOutcome run = engine::run_strategy(eng, options.strategy, domain);
  result.backtracks = run.backtracks;
  result.stalled = run.stalled;
  result.phases = run.phases;
  result.steps = eng.counters().steps;
  result.step_limit_hit = run.step_limit_hit;
  result.applications = eng.applications();
  result.counters = eng.counters();
  result.whiskers_left = stc.whiskers();
  result.closed = result.whiskers_left == 0 && stc.hexes() > 0;
  if (!result.closed) {
    result.left = describe_left(stc);
    if (result.backtracks) result.left += fmt::format(" after {} backtracks", result.backtracks);
    if (result.stalled) result.left += fmt::format("; the front stopped shrinking for {} applications", run.stalled_for);
    if (result.step_limit_hit) result.left += fmt::format(" (stopped after {} applications)", result.steps);
  }
  return result;
}

}  // namespace loom::weave
