#pragma once
// DOT output of a whole graph, and in-process rendering of DOT with Graphviz.
#include <functional>
#include <ostream>
#include <string>
#include <unordered_set>

#include "engine/graph.hpp"

namespace loom::engine {

struct DotStyle {
  /// Label of an element; default "kind id".
  std::function<std::string(Id)> label;
  /// Elements drawn highlighted (e.g. the elements of a match).
  std::unordered_set<Id> highlight;
  std::string graph_name = "G";
  /// Graphviz layout engine named in the DOT text (empty: the renderer's default),
  /// with curved edges up to 40 elements drawn and straight ones above.
  std::string layout;
  /// When not empty, only these elements (and incidences between them) are drawn.
  std::unordered_set<Id> only;
};

/// Writes every live element and incidence (labelled "port[i]") as DOT, with
/// Boost's write_graphviz (or, with `only`, the elements listed). Element ids
/// are the DOT node ids, so dumps of one graph are stable across runs.
void write_dot(std::ostream& out, const Graph& g, const DotStyle& style = {});

/// Renders DOT text to SVG with Graphviz's gvc library, using the layout
/// engine named in the graph's "layout" attribute, else `layout`. The library
/// runs in a forked child of this process: Graphviz 2.43 crashes on some
/// graphs, and a picture must never take the caller down. A layout that
/// crashes is tried once more with straight edges (splines=line); one that
/// runs longer than `max_seconds` is stopped. Throws std::runtime_error with
/// Graphviz's message, the signal or the time on failure.
std::string render_svg(const std::string& dot, const std::string& layout = "dot", unsigned max_seconds = 60);

/// Escapes a string for a double-quoted DOT attribute value.
std::string dot_quote(const std::string& s);

}  // namespace loom::engine
