#include "src/stc/sheet_diagram.hpp"

#include <cmath>
#include <numbers>
#include <algorithm>
#include <sstream>
#include <unordered_map>

#include <fmt/format.h>

#include "engine/dot.hpp"
#include "src/stc/loops.hpp"
#include "src/util/atomic_file.hpp"
#include "src/util/error.hpp"

namespace loom::stc {

namespace {

using engine::dot_quote;

/// Ordinals of the elements of one kind: the ids shown to users.
std::unordered_map<Id, std::size_t> ordinals(const Stc& stc, engine::KindId kind) {
  std::unordered_map<Id, std::size_t> out;
  for (Id e : stc.graph().members(kind)) out.emplace(e, out.size());
  return out;
}

/// The axis of `hex` along which the edges f.edge[k], f.edge[k+2] run: the one
/// neither perpendicular to `face` nor to the face across edge k.
unsigned edge_axis(const Stc& stc, Id hex, Id face, unsigned k) {
  unsigned a = stc.slot_in_hex(hex, face) / 2;
  Id other = stc.face_across_edge(hex, face, stc.face_edge(face, k));
  unsigned b = other == no_element ? a : stc.slot_in_hex(hex, other) / 2;
  return a == b ? a : 3 - a - b;
}

std::string loop_point(Id face, unsigned k) { return fmt::format("L{}p{}", face, k); }

/// Diagrams of at most this many edges (visible or not) get curved edges.
constexpr std::size_t kCurvedUpTo = 40;

class DiagramWriter {
public:
  DiagramWriter(const Stc& stc, Id sheet, const std::vector<Loop>& loops)
      : stc_(stc), sheet_(sheet), loops_(loops),
        sheet_ordinal_(ordinals(stc, stc.ids().sheet)),
        hex_ordinal_(ordinals(stc, stc.ids().hex)) {}

  std::string write() {
    write_loops();
    write_chords();
    // Hexes are free to move, but each is tied to the loop's centre by an
    // invisible spring, so that a weave in progress is drawn inside its loop.
    if (!declared_.empty()) {
      out_ << "centre [shape=point, style=invis, pos=\"0,0!\"];\n";
      for (const auto& id : declared_order_)
        out_ << "centre -- " << id << fmt::format(" [style=invis, len={:.2f}, weight=0.5];\n", 0.5 * radius_);
    }
    out_ << "}\n";
    const std::string body = out_.str();
    // Graphviz's spline router takes seconds from about 50 edges on (47 s for
    // a 136-edge sheet of randquad 60, 0.04 s with straight edges).
    std::size_t edges = 0;
    for (auto at = body.find(" -- "); at != std::string::npos; at = body.find(" -- ", at + 4)) ++edges;
    std::ostringstream head;
    head << "graph " << dot_quote(fmt::format("sheet {}", sheet_ordinal_.at(sheet_))) << " {\n"
         << "layout=neato; splines=" << (edges <= kCurvedUpTo ? "true" : "line") << "; overlap=true; fontsize=12;\n"
         << "label=" << dot_quote(fmt::format("sheet {}", sheet_ordinal_.at(sheet_))) << ";\n"
         << "node [fontsize=9, width=0.25, height=0.25, fixedsize=true];\nedge [fontsize=8];\n";
    return head.str() + body;
  }

private:
  void write_loops() {
    double radius = 1.0;
    for (const Loop& loop : loops_) {
      std::size_t n = loop.faces.size();
      if (radius == 1.0) radius_ = radius = std::max(1.5, 0.9 * static_cast<double>(n) / (2 * std::numbers::pi));
      for (std::size_t i = 0; i < n; ++i) {
        double angle = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
        Id f = loop.faces[i];
        unsigned k = stc_.slot_in_face(f, loop.edges[i]) % 2;
        double x = radius * std::cos(angle), y = radius * std::sin(angle);
        whisker_pos_[loop_point(f, k)] = fmt::format("{:.3f},{:.3f}!", 0.8 * x, 0.8 * y);
        out_ << loop_point(f, k) << " [shape=point, width=0.06, xlabel=" << dot_quote(std::to_string(stc_.boundary_index(f)))
             << ", pos=\"" << fmt::format("{:.3f},{:.3f}", x, y) << "!\"];\n";
      }
      for (std::size_t i = 0; i < n; ++i) {
        Id f = loop.faces[i], g = loop.faces[(i + 1) % n];
        out_ << loop_point(f, stc_.slot_in_face(f, loop.edges[i]) % 2) << " -- "
             << loop_point(g, stc_.slot_in_face(g, loop.edges[(i + 1) % n]) % 2)
             << " [color=\"#555555\", penwidth=2];\n";
      }
      radius *= 0.5;  // further loops of a merged sheet drawn inside
    }
  }

  /// Each face with a pair of opposite edges on this sheet is a chord segment
  /// (an STC edge) between its two sides.
  void write_chords() {
    const engine::Graph& g = stc_.graph();
    for (Id f : g.members(stc_.ids().face)) {
      for (unsigned k = 0; k < 2; ++k) {
        if (stc_.edge_sheet(stc_.face_edge(f, k)) != sheet_) continue;
        Id other = stc_.edge_sheet(stc_.face_edge(f, k + 1));
        std::string ends[2];
        for (unsigned side = 0; side < 2; ++side) ends[side] = endpoint(f, k, side);
        out_ << ends[0] << " -- " << ends[1] << " [label=" << dot_quote(std::to_string(sheet_ordinal_.at(other)))
             << ", tooltip=" << dot_quote(fmt::format("face {}, chord {}", f, stc_.face_chord(f))) << "];\n";
      }
    }
  }

  std::string endpoint(Id f, unsigned k, unsigned side) {
    Id h = stc_.face_cell(f, side);
    if (h != no_element) {
      std::string id = fmt::format("H{}a{}", h, edge_axis(stc_, h, f, k));
      if (declared_.insert(id).second) {
        declared_order_.push_back(id);
        out_ << id << " [shape=circle, label=" << dot_quote(std::to_string(hex_ordinal_.at(h))) << "];\n";
      }
      return id;
    }
    if (side == 1 && stc_.is_boundary(f)) return loop_point(f, k);
    // An open end of a boundary face's chord points inward from its loop point.
    std::string id = fmt::format("W{}p{}s{}", f, k, side);
    out_ << id << " [shape=point, width=0.05, color=\"#888888\"";
    if (auto it = whisker_pos_.find(loop_point(f, k)); it != whisker_pos_.end() && stc_.is_boundary(f))
      out_ << ", pos=\"" << it->second << "\"";
    else
      declared_order_.push_back(id);  // an open end inside: pulled towards the centre too
    out_ << "];\n";
    return id;
  }

  const Stc& stc_;
  Id sheet_;
  const std::vector<Loop>& loops_;
  std::unordered_map<Id, std::size_t> sheet_ordinal_, hex_ordinal_;
  std::unordered_set<std::string> declared_;
  std::vector<std::string> declared_order_;
  double radius_ = 1.5;  ///< of the outer loop
  std::unordered_map<std::string, std::string> whisker_pos_;  ///< loop point -> pinned whisker end
  std::ostringstream out_;
};

std::vector<Loop> loops_of(const std::vector<Loop>& all, Id sheet) {
  std::vector<Loop> out;
  for (const Loop& l : all)
    if (l.sheet == sheet) out.push_back(l);
  return out;
}

}  // namespace

std::string sheet_diagram_dot(const Stc& stc, Id sheet) {
  auto loops = loops_of(trace_loops(stc), sheet);
  return DiagramWriter(stc, sheet, loops).write();
}

std::size_t write_stc_dot(const Stc& stc, const std::filesystem::path& dir, PictureFailures& failures,
                          std::size_t svg_limit) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) fail_input(dir.string(), "cannot create the DOT directory (" + ec.message() + ")", "choose another --dot DIR");
  std::size_t written = 0;
  auto emit = [&](const std::string& stem, const std::string& dot, std::size_t elements) {
    write_text_atomically(dir / (stem + ".dot"), dot);
    ++written;
    if (elements <= svg_limit) {
      const std::size_t failed = failures.count;
      write_svg(dir / (stem + ".svg"), dot, failures);
      written += failures.count == failed;
    }
  };

  const engine::Graph& g = stc.graph();
  auto sheet_ordinal = ordinals(stc, stc.ids().sheet);
  engine::DotStyle style;
  style.graph_name = "STC";
  style.label = [&](Id e) { return fmt::format("{} {}", g.schema().kind(g.kind(e)).name, e); };
  std::ostringstream whole;
  engine::write_dot(whole, g, style);
  emit("stc", whole.str(), g.size() * 8);  // the whole graph lays out far slower than a sheet

  std::vector<Loop> all_loops;
  try {
    all_loops = trace_loops(stc);
  } catch (const std::runtime_error& e) {
    failures.add(dir / "sheet-*.dot", e.what());
    return written;
  }
  for (Id sheet : g.members(stc.ids().sheet)) {
    auto loops = loops_of(all_loops, sheet);
    std::string dot = DiagramWriter(stc, sheet, loops).write();
    emit(fmt::format("sheet-{}", sheet_ordinal.at(sheet)), dot, static_cast<std::size_t>(std::count(dot.begin(), dot.end(), '\n')));
  }
  return written;
}

}  // namespace loom::stc
