// An enum's values and the names scenes and the command line write them with, in one table that
// gives both directions and the list of choices for messages.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace sim::core {

template <class Enum, size_t N>
class EnumNames {
 public:
  struct Entry {
    Enum value;
    std::string_view name;
  };
  constexpr explicit EnumNames(std::array<Entry, N> entries) : entries_(entries) {}

  // the name of `value` ("" for a value not in the table)
  constexpr std::string_view name(Enum value) const {
    for (const Entry& e : entries_)
      if (e.value == value) return e.name;
    return {};
  }
  std::optional<Enum> parse(std::string_view name) const {
    for (const Entry& e : entries_)
      if (e.name == name) return e.value;
    return std::nullopt;
  }
  // "a, b, c": the choices, in the table's order
  std::string list() const {
    std::string s;
    for (const Entry& e : entries_) s += (s.empty() ? "" : ", ") + std::string(e.name);
    return s;
  }
  const std::array<Entry, N>& entries() const { return entries_; }

 private:
  std::array<Entry, N> entries_;
};

}  // namespace sim::core
