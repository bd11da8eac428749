#include "engine/dot.hpp"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <mutex>
#include <stdexcept>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

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

/// Curved edges cost most of a layout: a 1,255-element step picture took 14 s
/// with them and 0.3 s without. Larger pictures get straight ones.
constexpr std::size_t kCurvedUpTo = 40;

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
  const std::size_t drawn = style.only.empty() ? g.size() : style.only.size();
  auto graph_writer = [&](std::ostream& os) {
    os << "label=" << dot_quote(style.graph_name) << ";\nnode [shape=box, fontsize=10];\nedge [fontsize=8];\n";
    if (!style.layout.empty())
      os << "layout=" << style.layout << "; overlap=false; splines=" << (drawn <= kCurvedUpTo ? "true" : "line")
         << ";\n";
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

GVC_t* graphviz_context() {
  static GVC_t* gvc = [] {
    agseterrf(collect_graphviz_message);
    agseterr(AGERR);
    return gvContext();
  }();
  return gvc;
}

/// Lays out and renders in this process; throws with Graphviz's message.
std::string render_here(const std::string& dot, const std::string& layout, bool straight_edges) {
  GVC_t* gvc = graphviz_context();
  graphviz_messages.clear();
  Agraph_t* graph = agmemread(dot.c_str());
  if (!graph) throw std::runtime_error("Graphviz could not parse the DOT text: " + graphviz_messages);
  if (straight_edges) agattr(graph, AGRAPH, const_cast<char*>("splines"), const_cast<char*>("line"));
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

void write_all(int fd, const std::string& text) {
  for (std::size_t done = 0; done < text.size();) {
    ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += static_cast<std::size_t>(n);
  }
}

struct ChildOutcome {
  bool rendered = false;
  bool crashed = false;   ///< killed by a signal
  std::string text;       ///< the SVG, or what went wrong
};

/// render_here() in a child process, so that a crash inside Graphviz ends the
/// child and not the caller; the SVG comes back through a pipe.
ChildOutcome render_in_child(const std::string& dot, const std::string& layout, bool straight_edges,
                             unsigned max_seconds) {
  graphviz_context();  // loaded once, in the parent, and inherited
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("cannot open a pipe to Graphviz");
  pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error("cannot start a process for Graphviz");
  }
  if (pid == 0) {
    ::close(fds[0]);
    // A crash here must end the child quietly, not run the parent's handlers.
    for (int sig : {SIGSEGV, SIGABRT, SIGBUS, SIGFPE, SIGILL}) std::signal(sig, SIG_DFL);
    // What Graphviz's libraries print as they die (GLib's "Bail out!", on
    // stdout) is not the user's business; the SVG comes back through the pipe.
    if (int null = ::open("/dev/null", O_WRONLY); null >= 0) {
      ::dup2(null, STDOUT_FILENO);
      ::dup2(null, STDERR_FILENO);
    }
    ::alarm(max_seconds);
    int status = 0;
    std::string out;
    try {
      out = render_here(dot, layout, straight_edges);
    } catch (const std::exception& e) {
      out = e.what();
      status = 1;
    }
    write_all(fds[1], out);
    ::_exit(status);
  }
  ::close(fds[1]);
  ChildOutcome outcome;
  char buffer[65536];
  for (;;) {
    ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    outcome.text.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status)) {
    outcome.rendered = WEXITSTATUS(status) == 0;
  } else {
    outcome.crashed = true;
    int signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    outcome.text = signal == SIGALRM ? fmt::format("Graphviz took longer than {} s", max_seconds)
                                     : fmt::format("Graphviz crashed (signal {})", signal);
  }
  return outcome;
}
}  // namespace

std::string render_svg(const std::string& dot, const std::string& layout, unsigned max_seconds) {
  // Graphviz keeps global state; one rendering at a time.
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  ChildOutcome first = render_in_child(dot, layout, false, max_seconds);
  if (first.rendered) return first.text;
  if (!first.crashed) throw std::runtime_error(first.text);
  // Graphviz 2.43's spline router is where the crashes are: straight edges avoid it.
  ChildOutcome again = render_in_child(dot, layout, true, max_seconds);
  if (again.rendered) return again.text;
  throw std::runtime_error(first.text + (again.crashed ? ", also with straight edges" : "; with straight edges: " + again.text));
}

}  // namespace loom::engine
