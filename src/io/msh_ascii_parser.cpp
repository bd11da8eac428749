// Our own reader for ASCII MSH 2.2 and 4.1. Gmsh's reader trusts its input: an
// element naming an undefined node, or a corrupt count, crashes it (found by
// fuzzing; see docs/formats.md). This one checks every count and reference and
// names the line. Sections other than $Nodes and $Elements are skipped.
#include <fmt/format.h>

#include <unordered_map>

#include "src/io/formats.hpp"
#include "src/io/msh_element_types.hpp"
#include "src/io/text_scanner.hpp"
#include "src/util/error.hpp"

namespace loom {

namespace {

class MshAsciiParser {
 public:
  MshAsciiParser(std::string_view text, const std::string& where) : in_(text, where) {}

  RawMesh parse() {
    read_header();
    bool have_nodes = false, have_elements = false;
    for (std::string_view t = in_.token(); !t.empty(); t = in_.token()) {
      if (t == "$Nodes") {
        version_ == 2 ? read_nodes_v2() : read_nodes_v4();
        expect("$EndNodes");
        have_nodes = true;
      } else if (t == "$Elements") {
        version_ == 2 ? read_elements_v2() : read_elements_v4();
        expect("$EndElements");
        have_elements = true;
      } else if (t.starts_with('$') && !t.starts_with("$End")) {
        skip_section(t.substr(1));
      } else {
        in_.fail(fmt::format("unexpected {} outside any section", quote_token(t)), "fix or re-export the file");
      }
    }
    if (!have_nodes) in_.fail_truncated("a $Nodes section");
    if (!have_elements) in_.fail_truncated("an $Elements section");
    return std::move(mesh_);
  }

 private:
  void read_header() {
    if (in_.expect_token("$MeshFormat") != "$MeshFormat")
      fail_input(in_.where(), "line 1 is not $MeshFormat", "this is not a Gmsh MSH file; check the extension");
    std::string_view version = in_.expect_token("the MSH version");
    if (version != "2.2" && version != "4.1")
      in_.fail(fmt::format("MSH version {} is not supported", quote_token(version)),
               "export the mesh as MSH 4.1 or 2.2");
    version_ = version == "2.2" ? 2 : 4;
    in_.integer("the MSH file type");
    in_.integer("the MSH data size");
    expect("$EndMeshFormat");
  }

  void expect(std::string_view word) {
    std::string_view t = in_.expect_token(word);
    if (t != word) in_.fail(fmt::format("expected {}, found {}", word, quote_token(t)), "fix or re-export the file");
  }

  void skip_section(std::string_view name) {
    const std::string end = fmt::format("$End{}", name);
    for (std::string_view t = in_.token(); t != end; t = in_.token())
      if (t.empty()) in_.fail_truncated(quote_token(end));
  }

  std::int64_t tag(std::string_view what) {
    std::int64_t value = in_.integer(what);
    if (value <= 0) in_.fail(fmt::format("{} is {}; tags must be positive", what, value), "fix or re-export the file");
    return value;
  }

  void add_node(std::int64_t node_tag, Vec3 position) {
    if (!index_of_tag_.emplace(node_tag, static_cast<std::int64_t>(mesh_.points.size())).second)
      in_.fail(fmt::format("node {} is defined twice", node_tag), "give every node its own tag");
    mesh_.points.push_back(position);
  }

  void read_nodes_v2() {
    // A node is a tag and three coordinates: at least 8 bytes.
    std::size_t count = in_.count("the node count", 8);
    mesh_.points.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
      std::int64_t node_tag = tag("a node tag");
      add_node(node_tag, in_.point(fmt::format("node {}", node_tag)));
    }
  }

  void read_nodes_v4() {
    // A block header is four numbers, a node a tag and three coordinates.
    std::size_t blocks = in_.count("the number of node blocks", 8);
    std::size_t total = in_.count("the node count", 8);
    in_.integer("the smallest node tag");
    in_.integer("the largest node tag");
    mesh_.points.reserve(total);
    for (std::size_t b = 0; b < blocks; ++b) {
      std::int64_t dimension = in_.integer("a node block's entity dimension");
      in_.integer("a node block's entity tag");
      std::int64_t parametric = in_.integer("a node block's parametric flag");
      std::size_t count = in_.count("a node block's node count", 8);
      if (dimension < 0 || dimension > 3 || parametric < 0 || parametric > 1)
        in_.fail(fmt::format("node block {} has entity dimension {} and parametric flag {}", b, dimension, parametric),
                 "fix or re-export the file");
      std::vector<std::int64_t> tags(count);
      for (auto& t : tags) t = tag("a node tag");
      for (std::int64_t node_tag : tags) {
        add_node(node_tag, in_.point(fmt::format("node {}", node_tag)));
        for (std::int64_t k = 0; k < (parametric ? dimension : 0); ++k) in_.real("a parametric coordinate");
      }
    }
    if (mesh_.points.size() != total)
      in_.fail(fmt::format("$Nodes declares {} nodes but its blocks hold {}", total, mesh_.points.size()),
               "fix or re-export the file");
  }

  MshElementType element_type(std::int64_t code, const std::string& owner) {
    auto type = code == static_cast<int>(code) ? msh_element_type(static_cast<int>(code)) : std::nullopt;
    if (!type)
      in_.fail(fmt::format("{} has unsupported element type {}", owner, code),
               "Loom reads points, lines, triangles, quadrangles and volume elements up to second order");
    return *type;
  }

  void read_element_nodes(std::int64_t element_tag, int type_code, const MshElementType& type, int line) {
    RawCell cell{msh_cell_kind(type_code, type.dimension), {}, {"line", line}, type.name};
    cell.nodes.reserve(static_cast<std::size_t>(type.node_count));
    for (int k = 0; k < type.node_count; ++k) {
      std::int64_t node_tag = in_.integer(fmt::format("node {} of element {}", k + 1, element_tag));
      auto found = index_of_tag_.find(node_tag);
      if (found == index_of_tag_.end())
        in_.fail(fmt::format("element {} refers to node {}, which $Nodes does not define", element_tag, node_tag),
                 "fix the node tag or add the missing node");
      cell.nodes.push_back(found->second);
    }
    mesh_.cells.push_back(std::move(cell));
  }

  void read_elements_v2() {
    // An element is at least a tag, a type, a tag count and a node.
    std::size_t count = in_.count("the element count", 8);
    for (std::size_t i = 0; i < count; ++i) {
      std::int64_t element_tag = tag("an element tag");
      int line = in_.line();
      std::int64_t code = in_.integer(fmt::format("the type of element {}", element_tag));
      MshElementType type = element_type(code, fmt::format("element {}", element_tag));
      std::size_t tags = in_.count(fmt::format("the tag count of element {}", element_tag), 2);
      for (std::size_t k = 0; k < tags; ++k) in_.integer(fmt::format("a tag of element {}", element_tag));
      read_element_nodes(element_tag, static_cast<int>(code), type, line);
    }
  }

  void read_elements_v4() {
    std::size_t blocks = in_.count("the number of element blocks", 8);
    std::size_t total = in_.count("the element count", 4);
    in_.integer("the smallest element tag");
    in_.integer("the largest element tag");
    std::size_t read = 0;
    for (std::size_t b = 0; b < blocks; ++b) {
      in_.integer("an element block's entity dimension");
      in_.integer("an element block's entity tag");
      std::int64_t code = in_.integer("an element block's element type");
      MshElementType type = element_type(code, fmt::format("element block {}", b));
      std::size_t count = in_.count("an element block's element count", 4);
      for (std::size_t i = 0; i < count; ++i) {
        std::int64_t element_tag = tag("an element tag");
        read_element_nodes(element_tag, static_cast<int>(code), type, in_.line());
      }
      read += count;
    }
    if (read != total)
      in_.fail(fmt::format("$Elements declares {} elements but its blocks hold {}", total, read),
               "fix or re-export the file");
  }

  TextScanner in_;
  int version_ = 4;
  RawMesh mesh_;
  std::unordered_map<std::int64_t, std::int64_t> index_of_tag_;
};

}  // namespace

RawMesh parse_msh_ascii(std::string_view text, const std::string& where) { return MshAsciiParser(text, where).parse(); }

}  // namespace loom
