#include "src/stc/summary.hpp"

#include <unordered_map>

#include <fmt/format.h>

#include "src/stc/loops.hpp"

namespace loom::stc {

StcSummary summarize(const Stc& stc) {
  const engine::Graph& g = stc.graph();
  const StcSchema& ids = stc.ids();
  StcSummary s;
  s.hexes = stc.hexes(), s.faces = stc.faces(), s.edges = stc.edges(), s.nodes = stc.nodes();
  s.sheets = stc.sheets(), s.chords = stc.chords();
  s.whiskers = stc.whiskers();
  std::unordered_map<Id, std::size_t> ordinal;
  for (Id sh : g.members(ids.sheet)) {
    ordinal[sh] = s.sheet_list.size();
    s.sheet_list.push_back(SheetSummary{s.sheet_list.size(), 0, 0, 0, 0, g.get(sh, ids.sheet_self) != 0});
  }
  for (Id f : g.members(ids.face)) s.boundary_faces += stc.is_boundary(f);
  for (const Loop& loop : trace_loops(stc)) {
    SheetSummary& sh = s.sheet_list[ordinal[loop.sheet]];
    ++sh.loops;
    ++s.loops;
    sh.loop_length += loop.edges.size();
    sh.self_crossing_quads += loop.self_crossings();
  }
  for (Id h : g.members(ids.hex)) {
    Id sheets[3] = {stc.hex_sheet(h, 0), stc.hex_sheet(h, 1), stc.hex_sheet(h, 2)};
    for (unsigned k = 0; k < 3; ++k)
      if (sheets[k] != no_element && (sheets[k] == sheets[(k + 1) % 3] || sheets[k] == sheets[(k + 2) % 3]))
        ++s.sheet_list[ordinal[sheets[k]]].self_hexes;
  }
  for (auto& sh : s.sheet_list) s.self_intersecting_sheets += sh.self_intersecting;
  for (Id c : g.members(ids.chord)) s.self_intersecting_chords += g.get(c, ids.chord_self) != 0;
  return s;
}

std::string to_text(const StcSummary& s, bool surface) {
  std::string out;
  if (surface) {
    out += fmt::format("surface STC: {} quads, {} nodes, {} edges; {} loops, {} whisker chords\n", s.faces, s.nodes,
                       s.edges, s.loops, s.chords);
    out += fmt::format("self-crossing loops: {}\n", s.self_intersecting_sheets);
    for (const auto& sh : s.sheet_list)
      if (sh.self_intersecting)
        out += fmt::format("  loop {} (length {}) crosses itself in {} quads\n", sh.index, sh.loop_length,
                           sh.self_crossing_quads);
  } else {
    out += fmt::format("hex STC: {} hexes, {} faces, {} edges, {} nodes; {} sheets, {} chords\n", s.hexes, s.faces,
                       s.edges, s.nodes, s.sheets, s.chords);
    out += fmt::format("self-intersecting sheets: {}, self-intersecting chords: {}, whiskers: {}\n",
                       s.self_intersecting_sheets, s.self_intersecting_chords, s.whiskers);
    for (const auto& sh : s.sheet_list)
      if (sh.self_intersecting)
        out += fmt::format("  sheet {} meets itself in {} hexes ({} boundary quads)\n", sh.index, sh.self_hexes,
                           sh.self_crossing_quads);
  }
  return out;
}

nlohmann::json to_json(const StcSummary& s) {
  nlohmann::json sheets = nlohmann::json::array();
  for (const auto& sh : s.sheet_list)
    sheets.push_back({{"id", sh.index},
                      {"loops", sh.loops},
                      {"loop_length", sh.loop_length},
                      {"self_intersecting", sh.self_intersecting},
                      {"self_crossing_quads", sh.self_crossing_quads},
                      {"self_hexes", sh.self_hexes}});
  return {{"hexes", s.hexes},
          {"faces", s.faces},
          {"edges", s.edges},
          {"nodes", s.nodes},
          {"sheets", s.sheets},
          {"chords", s.chords},
          {"loops", s.loops},
          {"boundary_faces", s.boundary_faces},
          {"whiskers", s.whiskers},
          {"self_intersecting_sheets", s.self_intersecting_sheets},
          {"self_intersecting_chords", s.self_intersecting_chords},
          {"sheet_list", sheets}};
}

}  // namespace loom::stc
