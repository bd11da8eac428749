#include "src/fill/cap.hpp"

#include <algorithm>
#include <map>
#include <optional>

#include "src/io/text_scanner.hpp"
#include "src/util/error.hpp"
#include "src/weave/weave.hpp"

namespace loom::fill {

namespace {

constexpr std::string_view corners = "abcd";
constexpr std::array<std::string_view, 4> edge_names = {"ab", "bc", "cd", "da"};

std::optional<std::uint32_t> edge_index(std::string_view name) {
  for (std::uint32_t k = 0; k < 4; ++k)
    if (edge_names[k] == name) return k;
  return std::nullopt;
}

std::optional<CapRole> parse_role(std::string_view s, const std::map<std::string, std::uint32_t, std::less<>>& inside) {
  using K = CapRole::Kind;
  if (s.size() == 3 && s[1] == '_') {
    auto c = corners.find(s[0]);
    if (c == std::string_view::npos) return std::nullopt;
    auto corner = static_cast<std::uint32_t>(c);
    if (s[2] == 't') return CapRole{K::top, corner};
    if (s[2] == 'b') return CapRole{K::bottom, corner};
    if (s[2] == 'm' && corner % 2 == 1) return CapRole{K::white_mid, corner};
    return std::nullopt;
  }
  if (s == "Mdiag") return CapRole{K::diagonal_mid, 0};
  if (s == "Gd0" || s == "Gd1") return CapRole{K::triangle_centroid, static_cast<std::uint32_t>(s[2] - '0')};
  if (s.size() == 3 && (s[0] == 'M' || s[0] == 'W'))
    if (auto e = edge_index(s.substr(1))) return CapRole{s[0] == 'M' ? K::edge_mid : K::wall_centre, *e};
  if (auto it = inside.find(s); it != inside.end()) return CapRole{K::inside, it->second};
  return std::nullopt;
}

}  // namespace

Cap parse_cap(std::string_view text, const std::string& where) {
  TextScanner in(text, where, '#');
  in.set_line_mode(true);
  Cap cap;
  cap.source = where;
  std::map<std::string, std::uint32_t, std::less<>> inside;
  bool have_even = false;
  while (!in.at_end()) {
    std::string_view keyword = in.token();
    if (keyword == "even") {
      std::string_view e = in.token_on_line();
      auto k = edge_index(e);
      if (!k) in.fail(fmt::format("'even {}': not an edge of the quad", printable(e.substr(0, 40))), "write ab, bc, cd or da");
      cap.even_edge = *k;
      have_even = true;
    } else if (keyword == "node") {
      std::string name(in.token_on_line());
      if (name.size() < 2 || name[0] != 'i' || inside.count(name))
        in.fail(fmt::format("{} is not a new inside node", quote_token(name)), "write 'node iN X Y Z' with a name not used above");
      Vec3 p = in.point(quote_token(name));  // the name may be any bytes but blanks
      inside.emplace(name, static_cast<std::uint32_t>(cap.inside.size()));
      cap.inside.push_back(p);
    } else if (keyword == "hex") {
      std::array<CapRole, 8> hex;
      for (auto& role : hex) {
        std::string_view s = in.token_on_line();
        auto r = parse_role(s, inside);
        if (!r)
          in.fail(fmt::format("{} is not a cap node", quote_token(s)),
                  "use a role (a_t, b_m, Mab, Wbc, Mdiag, Gd0, ...) or a node declared above; a hex has 8");
        role = *r;
      }
      cap.hexes.push_back(hex);
    } else {
      in.fail(fmt::format("unknown keyword {}", quote_token(keyword)), "lines are even, node or hex");
    }
    if (auto extra = in.token_on_line(); !extra.empty())
      in.fail(fmt::format("unexpected {} at the end of the line", quote_token(extra)), "remove it");
    in.next_record();
  }
  if (!have_even || cap.hexes.empty()) fail_input(where, "a cap needs an 'even' line and hexes", "see docs/fill.md");
  return cap;
}

std::vector<Cap> load_caps(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec))
    if (e.path().extension() == ".cap") files.push_back(e.path());
  if (ec) fail_input(dir.string(), "cannot read the caps directory", "point LOOM_RULES at a rules directory with fill/");
  std::sort(files.begin(), files.end());
  std::vector<Cap> caps;
  for (const auto& f : files) caps.push_back(parse_cap(read_input_file(f), f.string()));
  for (std::uint32_t even = 0; even < 4; ++even)
    if (std::none_of(caps.begin(), caps.end(), [&](const Cap& c) { return c.even_edge == even; }))
      fail_input(dir.string(), fmt::format("no cap with even wall {}", edge_names[even]),
                 "regenerate the caps with scripts/make-caps.py");
  return caps;
}

std::filesystem::path default_caps_dir() { return weave::default_rules_dir() / "fill"; }

}  // namespace loom::fill
