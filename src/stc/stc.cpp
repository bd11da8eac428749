#include "src/stc/stc.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string_view>

namespace loom::stc {

const StcSchema& StcSchema::get() {
  static const StcSchema ids = [] {
    using engine::PortOrder;
    auto s = std::make_shared<engine::Schema>();
    StcSchema r{};
    r.hex = s->add_kind("hex");
    r.face = s->add_kind("face");
    r.edge = s->add_kind("edge");
    r.node = s->add_kind("node");
    r.chord = s->add_kind("chord");
    r.sheet = s->add_kind("sheet");
    // Only a face's cells may be missing (a whisker's open side): invariants 1-5.
    constexpr auto required = engine::PortPresence::required;
    r.hex_face = s->add_port(r.hex, "face", 6, r.face, PortOrder::ordered, required);
    r.face_edge = s->add_port(r.face, "edge", 4, r.edge, PortOrder::cyclic, required);
    r.face_node = s->add_port(r.face, "node", 4, r.node, PortOrder::cyclic, required);
    r.face_cell = s->add_port(r.face, "cell", 2, r.hex);
    r.face_chord = s->add_port(r.face, "chord", 1, r.chord, PortOrder::ordered, required);
    r.edge_node = s->add_port(r.edge, "node", 2, r.node, PortOrder::ordered, required);
    r.edge_sheet = s->add_port(r.edge, "sheet", 1, r.sheet, PortOrder::ordered, required);
    r.chord_sheet = s->add_port(r.chord, "sheet", 2, r.sheet, PortOrder::ordered, required);
    r.face_boundary = s->add_attribute(r.face, "boundary", -1);
    r.face_layer = s->add_attribute(r.face, "layer", 0);
    r.node_point = s->add_attribute(r.node, "point", -1);
    r.node_boundary = s->add_attribute(r.node, "boundary", 0);
    r.hex_source = s->add_attribute(r.hex, "source", -1);
    r.sheet_self = s->add_attribute(r.sheet, "self", 0);
    r.chord_self = s->add_attribute(r.chord, "self", 0);
    r.schema = std::move(s);
    return r;
  }();
  return ids;
}

Stc::Stc() : ids_(&StcSchema::get()), graph_(ids_->schema) {}

Id Stc::across(Id face, Id hex) const {
  Id a = face_cell(face, 0), b = face_cell(face, 1);
  if (a == hex) return b;
  if (b == hex) return a;
  return no_element;
}

unsigned Stc::slot_in_hex(Id hex, Id face) const {
  for (unsigned i = 0; i < 6; ++i)
    if (hex_face(hex, i) == face) return i;
  return 6;
}

unsigned Stc::slot_in_face(Id face, Id edge) const {
  for (unsigned i = 0; i < 4; ++i)
    if (face_edge(face, i) == edge) return i;
  return 4;
}

Id Stc::face_across_edge(Id hex, Id face, Id edge) const {
  for (unsigned i = 0; i < 6; ++i) {
    Id f = hex_face(hex, i);
    if (f != face && f != no_element && slot_in_face(f, edge) < 4) return f;
  }
  return no_element;
}

Id Stc::hex_sheet(Id hex, unsigned axis) const {
  // A side face touches both faces of the axis; its two edges that lie on
  // neither of them join them.
  Id side = hex_face(hex, (2 * axis + 2) % 6), a = hex_face(hex, 2 * axis), b = hex_face(hex, 2 * axis + 1);
  for (unsigned i = 0; i < 4; ++i) {
    Id e = face_edge(side, i);
    if (slot_in_face(a, e) == 4 && slot_in_face(b, e) == 4) return edge_sheet(e);
  }
  return no_element;
}

bool Stc::is_whisker(Id face) const {
  unsigned cells = (face_cell(face, 0) != no_element) + (face_cell(face, 1) != no_element);
  return cells < (is_boundary(face) ? 1u : 2u);
}

std::size_t Stc::whiskers() const {
  std::size_t n = 0;
  for (Id f : graph_.members(ids_->face)) n += is_whisker(f);
  return n;
}

bool invariant_checks_on() {
  // Read once: the checks cost O(size of the STC) per rewrite, so a weave
  // with them is quadratic; the test command turns them on, users do not.
  static const bool on = [] {
#ifndef NDEBUG
    return true;
#else
    const char* v = std::getenv("LOOM_CHECK_INVARIANTS");
    return v != nullptr && *v != '\0' && std::string_view(v) != "0";
#endif
  }();
  return on;
}

void Stc::debug_check() const {
  if (!invariant_checks_on()) return;
  if (auto v = check_invariants(); !v.empty()) throw std::logic_error("STC invariant violated: " + v);
}

}  // namespace loom::stc
