// Wavefront OBJ: "v x y z" and "f i j k l" lines, 1-based (negative = relative)
// indices, "i/t/n" corner forms. Other known statements are ignored.
#include <fmt/format.h>

#include <algorithm>
#include <array>

#include "src/io/formats.hpp"
#include "src/io/text_scanner.hpp"

namespace loom {

namespace {

// Statements of the OBJ specification that carry nothing a quad surface needs.
constexpr std::array<std::string_view, 38> ignored_statements = {
    "vt",     "vn",         "vp",        "l",     "p",     "g",     "o",        "s",        "usemtl", "mtllib",
    "cstype", "deg",        "bmat",      "step",  "curv",  "curv2", "surf",     "parm",     "trim",   "hole",
    "scrv",   "sp",         "end",       "con",   "mg",    "bevel", "c_interp", "d_interp", "lod",    "maplib",
    "usemap", "shadow_obj", "trace_obj", "ctech", "stech", "call",  "csh",      "res"};

std::int64_t face_corner_index(TextScanner& in, std::string_view corner, std::size_t vertices_so_far) {
  std::string_view index_text = corner.substr(0, corner.find('/'));
  std::int64_t index = 0;
  if (!parse_integer(index_text, index))
    in.fail(fmt::format("face corner {} does not start with a node index", quote_token(corner)),
            "write face corners as i, i/t, i//n or i/t/n");
  if (index == 0) in.fail("face refers to node 0", "OBJ node indices start at 1 (negative ones count back)");
  // Negative indices count back from the last vertex read so far.
  return index > 0 ? index - 1 : static_cast<std::int64_t>(vertices_so_far) + index;
}

}  // namespace

RawMesh parse_obj(std::string_view text, const std::string& where) {
  TextScanner in(text, where, '#');
  in.set_line_mode(true);
  RawMesh mesh;
  mesh.node_numbering_base = 1;
  const bool ends_with_newline = !text.empty() && text.back() == '\n';
  while (!in.at_end()) {
    std::string_view keyword = in.token();
    if (keyword == "v") {
      mesh.points.push_back(in.point(fmt::format("node {}", mesh.points.size() + 1)));
    } else if (keyword == "f") {
      RawCell face{CellKind::polygon, {}, {"line", in.line()}, "polygon"};
      for (auto corner = in.token_on_line(); !corner.empty(); corner = in.token_on_line())
        face.nodes.push_back(face_corner_index(in, corner, mesh.points.size()));
      if (face.nodes.size() != 4 && !ends_with_newline && in.at_end()) in.fail_truncated("the rest of the last face");
      mesh.cells.push_back(std::move(face));
    } else if (std::find(ignored_statements.begin(), ignored_statements.end(), keyword) == ignored_statements.end()) {
      in.fail(fmt::format("unknown OBJ statement {}", quote_token(keyword)),
              "is this an OBJ file? lines must start with v, f or another OBJ keyword");
    }
    in.skip_line();
  }
  return mesh;
}

std::string obj_text(const QuadSurface& surface) {
  fmt::memory_buffer out;
  fmt::format_to(std::back_inserter(out), "# quad surface written by Loom: {} nodes, {} quads\n", surface.points.size(),
                 surface.quads.size());
  for (const Vec3& p : surface.points) fmt::format_to(std::back_inserter(out), "v {} {} {}\n", p[0], p[1], p[2]);
  for (const Quad& q : surface.quads)
    fmt::format_to(std::back_inserter(out), "f {} {} {} {}\n", q[0] + 1, q[1] + 1, q[2] + 1, q[3] + 1);
  return fmt::to_string(out);
}

}  // namespace loom
