// Object File Format: "OFF", then "nodes faces edges", node lines "x y z", face
// lines "k i1 ... ik" (0-based). Extra values on a line (colours) are ignored.
#include <fmt/format.h>

#include "src/io/formats.hpp"
#include "src/io/text_scanner.hpp"

namespace loom {

RawMesh parse_off(std::string_view text, const std::string& where) {
  TextScanner in(text, where, '#');
  in.set_line_mode(true);
  std::string_view header = in.expect_token("the OFF header");
  // The C, N and 4 prefixes add per-node values after x y z, which skip_line drops.
  if (header != "OFF" && header != "COFF" && header != "NOFF" && header != "CNOFF")
    in.fail(fmt::format("first word is {}, not OFF", quote_token(header)),
            "an OFF file starts with the line OFF (4D and ST variants are not supported)");
  in.next_record();
  // A node line holds at least three numbers, a face line one.
  std::size_t node_count = in.count("the node count", 6);
  std::size_t face_count = in.count("the face count", 2);
  in.skip_line();

  RawMesh mesh;
  mesh.points.reserve(node_count);
  for (std::size_t i = 0; i < node_count; ++i) {
    in.next_record();
    if (in.at_end()) in.fail_truncated(fmt::format("node {} of {}", i, node_count));
    mesh.points.push_back(in.point(fmt::format("node {}", i)));
    in.skip_line();
  }
  for (std::size_t f = 0; f < face_count; ++f) {
    in.next_record();
    if (in.at_end()) in.fail_truncated(fmt::format("face {} of {}", f, face_count));
    std::size_t corners = in.count(fmt::format("the node count of face {}", f), 2);
    RawCell face{CellKind::polygon, {}, {"line", in.line()}, "polygon"};
    for (std::size_t k = 0; k < corners; ++k) face.nodes.push_back(in.integer(fmt::format("node {} of face {}", k, f)));
    mesh.cells.push_back(std::move(face));
    in.skip_line();
  }
  return mesh;
}

std::string off_text(const QuadSurface& surface) {
  fmt::memory_buffer out;
  fmt::format_to(std::back_inserter(out), "OFF\n{} {} 0\n", surface.points.size(), surface.quads.size());
  for (const Vec3& p : surface.points) fmt::format_to(std::back_inserter(out), "{} {} {}\n", p[0], p[1], p[2]);
  for (const Quad& q : surface.quads)
    fmt::format_to(std::back_inserter(out), "4 {} {} {} {}\n", q[0], q[1], q[2], q[3]);
  return fmt::to_string(out);
}

}  // namespace loom
