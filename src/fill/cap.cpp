#include "src/fill/cap.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

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

std::optional<CapRole> parse_role(std::string_view s, const std::map<std::string, std::uint32_t>& inside) {
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
  if (auto it = inside.find(std::string(s)); it != inside.end()) return CapRole{K::inside, it->second};
  return std::nullopt;
}

Cap read_cap(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) fail_input(file.string(), "cannot read the cap file", "check the rules directory's fill/ folder");
  Cap cap;
  cap.source = file.string();
  std::map<std::string, std::uint32_t> inside;
  bool have_even = false;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    auto where = [&] { return fmt::format("{}:{}", file.string(), number); };
    if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::string keyword;
    if (!(words >> keyword)) continue;
    std::string rest;
    if (keyword == "even") {
      std::string e;
      words >> e;
      auto k = edge_index(e);
      if (!k) fail_input(where(), fmt::format("'even {}': not an edge of the quad", e), "write ab, bc, cd or da");
      cap.even_edge = *k;
      have_even = true;
    } else if (keyword == "node") {
      std::string name;
      Vec3 p;
      if (!(words >> name >> p[0] >> p[1] >> p[2]) || name.empty() || name[0] != 'i' || inside.count(name))
        fail_input(where(), "expected 'node iN X Y Z' with a new name iN", "fix the line");
      inside.emplace(name, static_cast<std::uint32_t>(cap.inside.size()));
      cap.inside.push_back(p);
    } else if (keyword == "hex") {
      std::array<CapRole, 8> hex;
      for (auto& role : hex) {
        std::string s;
        std::optional<CapRole> r;
        if (!(words >> s) || !(r = parse_role(s, inside)))
          fail_input(where(), fmt::format("'{}' is not a cap node", s),
                     "use a role (a_t, b_m, Mab, Wbc, Mdiag, Gd0, ...) or a node declared above");
        role = *r;
      }
      cap.hexes.push_back(hex);
    } else {
      fail_input(where(), fmt::format("unknown keyword '{}'", keyword), "lines are even, node or hex");
    }
    if (words >> rest) fail_input(where(), fmt::format("unexpected '{}' at the end of the line", rest), "remove it");
  }
  if (!have_even || cap.hexes.empty()) fail_input(file.string(), "a cap needs an 'even' line and hexes", "see docs/fill.md");
  return cap;
}

}  // namespace

std::vector<Cap> load_caps(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec))
    if (e.path().extension() == ".cap") files.push_back(e.path());
  if (ec) fail_input(dir.string(), "cannot read the caps directory", "point LOOM_RULES at a rules directory with fill/");
  std::sort(files.begin(), files.end());
  std::vector<Cap> caps;
  for (const auto& f : files) caps.push_back(read_cap(f));
  for (std::uint32_t even = 0; even < 4; ++even)
    if (std::none_of(caps.begin(), caps.end(), [&](const Cap& c) { return c.even_edge == even; }))
      fail_input(dir.string(), fmt::format("no cap with even wall {}", edge_names[even]),
                 "regenerate the caps with scripts/make-caps.py");
  return caps;
}

std::filesystem::path default_caps_dir() { return weave::default_rules_dir() / "fill"; }

}  // namespace loom::fill
