#pragma once
// Schema: the types of a typed incidence graph.
//
// A schema names the element kinds of a graph, and for each kind its ports and
// attributes. A port is a fixed number of ordered incidence slots pointing at
// elements of one target kind ("a hex has 6 faces", "a face has 4 edges in
// cyclic order"); fixed arities make every slot an O(1) lookup. Attributes are
// named 32-bit integers per kind. A schema is built once, then frozen by being
// handed to a Graph; it knows nothing of what the kinds mean.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace loom::engine {

using KindId = std::uint8_t;
using PortId = std::uint16_t;
using AttrId = std::uint16_t;

/// How the slots of a port relate: `ordered` (slot i means something fixed),
/// `cyclic` (slot i+1 follows slot i, and the last is followed by the first).
enum class PortOrder : std::uint8_t { ordered, cyclic };

/// Whether a port's slots may be empty. The engine holds every rewrite to
/// this: once it is complete, no slot of a `required` port of an element it
/// changed or created is empty, or the rewrite is rolled back.
enum class PortPresence : std::uint8_t { optional, required };

struct PortSpec {
  std::string name;
  KindId owner = 0;
  KindId target = 0;
  std::uint8_t arity = 0;
  std::uint8_t first_slot = 0;  ///< offset of this port's slots in the owner's slot block
  PortOrder order = PortOrder::ordered;
  PortPresence presence = PortPresence::optional;
};

struct AttrSpec {
  std::string name;
  KindId owner = 0;
  std::int32_t default_value = 0;
  std::uint16_t column = 0;  ///< index among the owner kind's attributes
};

struct KindSpec {
  std::string name;
  std::vector<PortId> ports;
  std::vector<AttrId> attributes;
  std::uint8_t slot_count = 0;  ///< sum of the arities of its ports
  std::vector<PortId> slot_ports;  ///< the port of each slot, for O(1) lookups
};

class Schema {
public:
  /// Adds a kind; names must be unique. At most 255 kinds.
  KindId add_kind(std::string_view name);
  /// Adds a port of `arity` slots (1..255 slots per kind in all) to `owner`.
  PortId add_port(KindId owner, std::string_view name, unsigned arity, KindId target,
                  PortOrder order = PortOrder::ordered, PortPresence presence = PortPresence::optional);
  /// Adds an integer attribute to `owner`, `default_value` for new elements.
  AttrId add_attribute(KindId owner, std::string_view name, std::int32_t default_value = 0);

  std::size_t kind_count() const { return kinds_.size(); }
  const KindSpec& kind(KindId k) const { return kinds_.at(k); }
  const PortSpec& port(PortId p) const { return ports_.at(p); }
  const AttrSpec& attribute(AttrId a) const { return attrs_.at(a); }
  std::size_t port_count() const { return ports_.size(); }
  std::size_t attribute_count() const { return attrs_.size(); }

  std::optional<KindId> find_kind(std::string_view name) const;
  std::optional<PortId> find_port(KindId owner, std::string_view name) const;
  std::optional<AttrId> find_attribute(KindId owner, std::string_view name) const;

  /// The port that slot `slot` of a `kind` element belongs to.
  PortId port_of_slot(KindId kind, unsigned slot) const { return kinds_[kind].slot_ports[slot]; }

private:
  std::vector<KindSpec> kinds_;
  std::vector<PortSpec> ports_;
  std::vector<AttrSpec> attrs_;
};

}  // namespace loom::engine
