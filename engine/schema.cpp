#include "engine/schema.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "engine/quoted.hpp"

namespace loom::engine {

namespace {
std::string quoted_member(std::string_view owner, std::string_view name) {
  return quoted(fmt::format("{}.{}", owner, name));
}
}  // namespace

KindId Schema::add_kind(std::string_view name) {
  if (find_kind(name)) throw std::invalid_argument(fmt::format("schema: kind {} declared twice", quoted(name)));
  if (kinds_.size() >= 255) throw std::invalid_argument("schema: more than 255 kinds");
  kinds_.push_back(KindSpec{std::string(name), {}, {}, 0, {}});
  return static_cast<KindId>(kinds_.size() - 1);
}

PortId Schema::add_port(KindId owner, std::string_view name, unsigned arity, KindId target,
                        PortOrder order, PortPresence presence) {
  KindSpec& k = kinds_.at(owner);
  kinds_.at(target);
  if (find_port(owner, name))
    throw std::invalid_argument(fmt::format("schema: port {} declared twice", quoted_member(k.name, name)));
  if (arity == 0 || k.slot_count + arity > 255)
    throw std::invalid_argument(fmt::format("schema: port {} has a bad arity {}", quoted_member(k.name, name), arity));
  ports_.push_back(PortSpec{std::string(name), owner, target, static_cast<std::uint8_t>(arity),
                            k.slot_count, order, presence});
  k.slot_count = static_cast<std::uint8_t>(k.slot_count + arity);
  k.ports.push_back(static_cast<PortId>(ports_.size() - 1));
  k.slot_ports.insert(k.slot_ports.end(), arity, k.ports.back());
  return k.ports.back();
}

AttrId Schema::add_attribute(KindId owner, std::string_view name, std::int32_t default_value) {
  KindSpec& k = kinds_.at(owner);
  if (find_attribute(owner, name))
    throw std::invalid_argument(fmt::format("schema: attribute {} declared twice", quoted_member(k.name, name)));
  attrs_.push_back(AttrSpec{std::string(name), owner, default_value,
                            static_cast<std::uint16_t>(k.attributes.size())});
  k.attributes.push_back(static_cast<AttrId>(attrs_.size() - 1));
  return k.attributes.back();
}

std::optional<KindId> Schema::find_kind(std::string_view name) const {
  for (std::size_t i = 0; i < kinds_.size(); ++i)
    if (kinds_[i].name == name) return static_cast<KindId>(i);
  return std::nullopt;
}

std::optional<PortId> Schema::find_port(KindId owner, std::string_view name) const {
  for (PortId p : kinds_.at(owner).ports)
    if (ports_[p].name == name) return p;
  return std::nullopt;
}

std::optional<AttrId> Schema::find_attribute(KindId owner, std::string_view name) const {
  for (AttrId a : kinds_.at(owner).attributes)
    if (attrs_[a].name == name) return a;
  return std::nullopt;
}

}  // namespace loom::engine
