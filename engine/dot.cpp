#include "engine/dot.hpp"

#include <algorithm>
#include <mutex>
#include <stdexcept>

#include <boost/graph/graphviz.hpp>
#include <fmt/format.h>
#include <graphviz/gvc.h>

#include "engine/graph_traits.hpp"

namespace loom::engine {

std::string dot_quote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c == '\n' ? ' ' : c;
  }
  return out + "\"";
}

void write_dot(std::ostream& out, const Graph& g, const DotStyle& style) {
  const Schema& schema = g.schema();
  auto vertex_writer = [&](std::ostream& os, Id v) {
    std::string label = style.label ? style.label(v) : fmt::format("{} {}", schema.kind(g.kind(v)).name, v);
    os << "[label=" << dot_quote(label);
    if (style.highlight.count(v)) os << ", style=filled, fillcolor=\"#ffb000\", penwidth=2";
    os << "]";
  };
  auto edge_writer = [&](std::ostream& os, Incidence e) {
    const PortSpec& p = schema.port(g.slot_port(e.slot));
    os << "[label=" << dot_quote(p.arity > 1 ? fmt::format("{}[{}]", p.name, g.slot_index(e.slot)) : p.name);
    if (style.highlight.count(g.slot_owner(e.slot)) && style.highlight.count(g.slot_target(e.slot)))
      os << ", color=\"#ff7000\", penwidth=2";
    os << "]";
  };
  auto graph_writer = [&](std::ostream& os) {
    os << "label=" << dot_quote(style.graph_name) << ";\nnode [shape=box, fontsize=10];\nedge [fontsize=8];\n";
    if (!style.layout.empty()) os << "layout=" << style.layout << "; overlap=false; splines=true;\n";
  };
  if (style.only.empty()) {
    boost::write_graphviz(out, g, vertex_writer, edge_writer, graph_writer);
    return;
  }
  std::vector<Id> shown(style.only.begin(), style.only.end());
  std::sort(shown.begin(), shown.end());
  out << "digraph G {\n";
  graph_writer(out);
  for (Id v : shown)
    if (g.alive(v)) {
      out << v;
      vertex_writer(out, v);
      out << ";\n";
    }
  for (Id v : shown) {
    if (!g.alive(v)) continue;
    for (SlotId s = g.first_slot(v), e = s + g.slot_count(v); s < e; ++s)
      if (Id t = g.slot_target(s); t != no_element && style.only.count(t)) {
        out << v << "->" << t;
        edge_writer(out, Incidence{s});
        out << ";\n";
      }
  }
  out << "}\n";
}

namespace {
// Graphviz reports through a global callback; collect its messages instead of
// letting it print to stderr.
std::string graphviz_messages;
int collect_graphviz_message(char* text) {
  graphviz_messages += text;
  return 0;
}
}  // namespace

std::string render_svg(const std::string& dot, const std::string& layout) {
  // Graphviz keeps global state; one rendering at a time.
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  static GVC_t* gvc = [] {
    agseterrf(collect_graphviz_message);
    agseterr(AGERR);
    return gvContext();
  }();
  graphviz_messages.clear();
  Agraph_t* graph = agmemread(dot.c_str());
  if (!graph) throw std::runtime_error("Graphviz could not parse the DOT text: " + graphviz_messages);
  const char* engine = agget(graph, const_cast<char*>("layout"));
  std::string chosen = engine && *engine ? engine : layout;
  if (gvLayout(gvc, graph, chosen.c_str()) != 0) {
    agclose(graph);
    throw std::runtime_error("Graphviz layout '" + chosen + "' failed");
  }
  char* data = nullptr;
  unsigned int length = 0;
  int rc = gvRenderData(gvc, graph, "svg", &data, &length);
  std::string svg = rc == 0 && data ? std::string(data, length) : std::string();
  if (data) gvFreeRenderData(data);
  gvFreeLayout(gvc, graph);
  agclose(graph);
  if (rc != 0) throw std::runtime_error("Graphviz could not render SVG");
  return svg;
}

}  // namespace loom::engine
