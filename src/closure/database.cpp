#include "src/closure/database.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>

#include <fmt/format.h>

#include "src/closure/hex_meeting.hpp"
#include "src/io/text_scanner.hpp"
#include "src/util/atomic_file.hpp"
#include "src/util/error.hpp"

namespace loom::closure {

using quadmap::Code;
using quadmap::QuadMap;

namespace {

QuadMap front_of(const Code& code, const std::vector<Hex>& hexes) {
  QuadMap front = quadmap::map_of_code(code);
  for (const Hex& h : hexes)
    for (std::uint32_t v : h) front.vertex_bound = std::max(front.vertex_bound, v + 1);
  return front;
}

/// The corner of `hex` joined to corner `at` by an edge and not among `bottom`.
std::uint32_t above(const Hex& hex, std::uint32_t at, const Quad& bottom) {
  static constexpr int next[8][3] = {{1, 3, 4}, {0, 2, 5}, {1, 3, 6}, {0, 2, 7},
                                     {0, 5, 7}, {1, 4, 6}, {2, 5, 7}, {3, 4, 6}};
  const auto i = static_cast<std::size_t>(std::find(hex.begin(), hex.end(), at) - hex.begin());
  for (int n : next[i])
    if (std::find(bottom.begin(), bottom.end(), hex[static_cast<std::size_t>(n)]) == bottom.end())
      return hex[static_cast<std::size_t>(n)];
  throw std::logic_error("database: a hex with no corner above its bottom");
}

}  // namespace

void Database::add(Entry e) {
  replayed_.emplace_back();
  meshes_.emplace_back();
  index_.emplace(e.code, static_cast<std::uint32_t>(entries_.size()));
  entries_.push_back(std::move(e));
}

void Database::replace(Entry e) {
  auto it = index_.find(e.code);
  if (it == index_.end()) throw std::logic_error("database: replacing an entry it does not hold");
  std::vector<Hex> hexes = mesh_of(e);  // before anything changes: it throws on a corrupt entry
  std::call_once(replayed_[it->second], [] {});
  meshes_[it->second] = std::move(hexes);
  entries_[it->second] = std::move(e);
}

const std::vector<Hex>& Database::mesh(const Entry& e) const {
  const auto i = static_cast<std::size_t>(&e - entries_.data());
  if (&e < entries_.data() || i >= entries_.size()) throw std::logic_error("database: mesh() of another database's entry");
  std::call_once(replayed_[i], [&] { meshes_[i] = mesh_of(entries_[i]); });
  return meshes_[i];
}

const Database::Entry* Database::find(const Code& code) const {
  auto it = index_.find(code);
  return it == index_.end() ? nullptr : &entries_[it->second];
}

std::vector<Hex> mesh_of(const Database::Entry& e) {
  QuadMap front = quadmap::map_of_code(e.code);
  std::vector<Hex> hexes;
  quadmap::GluedHex glued;
  for (const quadmap::Gluing& g : e.shelling) {
    // plan_gluing asks for a closed map; a corrupt file need not give one.
    if (!quadmap::why_not_simple(front).empty())
      throw std::logic_error("database: a front of the shelling is not a closed quad map");
    if (g.bottom >= front.size() || !quadmap::glue_hex(front, quadmap::twins(front), quadmap::degrees(front), g, glued))
      throw std::logic_error("database: a gluing of the shelling does not apply");
    hexes.push_back(glued.hex);
    front = std::move(glued.after);
  }
  Hex last;
  if (!quadmap::why_not_simple(front).empty() || !quadmap::fill_cube(front, quadmap::twins(front), last))
    throw std::logic_error("database: the shelling does not end in a cube");
  hexes.push_back(last);
  return hexes;
}

std::vector<Hex> Database::mesh_on(const Entry& e, const QuadMap& read, const std::vector<quadmap::Dart>& twin,
                                   quadmap::Dart start, bool mirrored) const {
  const std::uint32_t boundary_vertices = quadmap::map_of_code(e.code).vertex_bound;
  const auto label = quadmap::labels_from(read, twin, start);
  std::vector<std::uint32_t> vertex_of(boundary_vertices, quadmap::no_vertex);
  for (std::uint32_t v = 0; v < label.size(); ++v)
    if (label[v] != quadmap::no_vertex) vertex_of[label[v]] = v;
  std::vector<Hex> hexes;
  for (Hex h : mesh(e)) {
    for (auto& v : h) v = v < boundary_vertices ? vertex_of[v] : read.vertex_bound + (v - boundary_vertices);
    hexes.push_back(mirrored ? mirror_hex(h) : h);
  }
  return hexes;
}

Database::Entry entry_of_mesh(const Code& code, const std::vector<Hex>& hexes) {
  Database::Entry e{code, {}};
  QuadMap front = front_of(code, hexes);
  quadmap::GluedHex glued;
  for (std::size_t n = hexes.size(); n-- > 1;) {
    const Hex& hex = hexes[n];
    // The hex's faces on the front, as bits over the front's quads.
    std::vector<std::uint32_t> covered;
    for (std::uint32_t q = 0; q < front.size(); ++q) {
      std::uint8_t bits = 0;
      for (std::uint32_t v : front.quads[q])
        for (int i = 0; i < 8; ++i)
          if (hex[static_cast<std::size_t>(i)] == v) bits |= static_cast<std::uint8_t>(1u << i);
      if (is_hex_face(bits)) covered.push_back(q);
    }
    bool done = false;
    for (std::uint32_t bottom : covered) {
      const auto twin = quadmap::twins(front);
      std::uint8_t sides = 0;
      for (unsigned i = 0; i < 4; ++i)
        if (std::find(covered.begin(), covered.end(), twin[4 * bottom + i] / 4) != covered.end())
          sides |= static_cast<std::uint8_t>(1u << i);
      if (std::popcount(sides) + 1 != static_cast<int>(covered.size())) continue;  // its opposite is covered too
      if (!quadmap::glue_hex(front, twin, quadmap::degrees(front), {bottom, sides}, glued))
        throw std::logic_error("database: a hex of the mesh cannot be taken off its boundary");
      // Name the gluing's new corners as the mesh does.
      const Quad& b = front.quads[bottom];
      for (Quad& q : glued.after.quads)
        for (std::uint32_t& v : q)
          if (v >= front.vertex_bound)
            for (int i = 0; i < 4; ++i)
              if (glued.hex[static_cast<std::size_t>(4 + (4 - i) % 4)] == v) v = above(hex, b[static_cast<std::size_t>(i)], b);
      glued.after.vertex_bound = front.vertex_bound;
      e.shelling.push_back({bottom, sides});
      front = std::move(glued.after);
      done = true;
      break;
    }
    if (!done) throw std::logic_error("database: the mesh is not shelled in the reverse of its hex order");
  }
  return e;
}

Database Database::load(const std::filesystem::path& file) { return parse(read_input_file(file), file.string()); }

Database Database::parse(std::string_view text, const std::string& where) {
  TextScanner in(text, where, '#');
  in.set_line_mode(true);
  Database db;
  const std::string hint = "rebuild it with scripts/make-database.sh";
  while (!in.at_end()) {
    if (in.token() != "entry") in.fail("expected 'entry'", hint);
    const std::size_t quads = in.count("quad count");
    const std::size_t hexes = in.count("hex count");
    if (hexes == 0) in.fail("an entry of no hexes", hint);
    if (in.token_on_line() != "|") in.fail("expected '|' after the counts", hint);
    Entry e;
    for (std::size_t i = 0; i < quadmap::kCodePrefix + 4 * quads; ++i) {
      const std::int64_t x = in.integer("code number");
      if (x < 0 || x >= 4 * static_cast<std::int64_t>(quads)) in.fail(fmt::format("code number {} out of range", x), hint);
      e.code.push_back(static_cast<std::uint16_t>(x));
    }
    if (in.token_on_line() != "|") in.fail("expected '|' after the code", hint);
    for (std::size_t h = 0; h + 1 < hexes; ++h) {
      const std::string_view t = in.token_on_line();
      const auto dot = t.find('.');
      std::int64_t bottom = -1, sides = -1;
      if (dot == std::string_view::npos || !parse_integer(t.substr(0, dot), bottom) ||
          !parse_integer(t.substr(dot + 1), sides) || bottom < 0 || sides < 0 || sides > 15 ||
          bottom >= static_cast<std::int64_t>(quads + 4 * hexes))
        in.fail(fmt::format("{} is not a gluing BOTTOM.SIDES", quote_token(t)), hint);
      e.shelling.push_back({static_cast<std::uint32_t>(bottom), static_cast<std::uint8_t>(sides)});
    }
    if (!in.token_on_line().empty()) in.fail("more gluings than the hex count says", hint);
    if (db.find(e.code)) in.fail("a boundary listed twice", hint);
    db.add(std::move(e));
    in.next_record();
  }
  return db;
}

void Database::save(const std::filesystem::path& file) const {
  std::string out =
      "# Loom's database of small hexahedrizations (docs/closure.md). Made by\n"
      "# scripts/make-database.sh; do not edit. One line per boundary:\n"
      "# entry QUADS HEXES | canonical code (4 numbers, then 4 per quad) |\n"
      "#   its mesh as a shelling from the boundary inwards: BOTTOM.SIDES per hex but the last\n";
  for (const Entry& e : entries_) {
    out += fmt::format("entry {} {} |", quadmap::code_quads(e.code), e.hexes());
    for (std::uint16_t x : e.code) out += fmt::format(" {}", x);
    out += " |";
    for (const quadmap::Gluing& g : e.shelling) out += fmt::format(" {}.{}", g.bottom, g.sides);
    out += '\n';
  }
  write_text_atomically(file, out);
}

std::filesystem::path database_file(const std::filesystem::path& rules_dir) {
  return rules_dir / "closure" / "database.txt";
}

}  // namespace loom::closure
