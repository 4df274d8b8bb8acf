#pragma once
// An enum's names, written once: next to the enum, a specialisation of EnumNames holds its table
// of (value, name) pairs, each value's own name first and any other names it is read by after
// them (tessellation "tri", then "triangle"). Every name and from-name lookup, every list of
// choices in a message and every reader of design.json goes through the functions below.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace paver {

template <class E>
struct EnumName {
  E value;
  std::string_view name;
};

template <class E>
struct EnumNames;  // specialised: static constexpr EnumName<E> table[] = {{E::A, "a"}, ...};

template <class E>
concept NamedEnum = requires { EnumNames<E>::table; };

// The specialisation in one line: PAVER_ENUM_NAMES(Units, {Units::Millimetre, "mm"}, ...);
#define PAVER_ENUM_NAMES(E, ...)                                 \
  template <>                                                    \
  struct EnumNames<E> {                                          \
    static constexpr EnumName<E> table[] = {__VA_ARGS__};        \
  }

// The value's own name ("?" for a value the table lacks, which a test of each table rules out).
template <NamedEnum E>
constexpr std::string_view enum_name(E value) {
  for (const auto& [v, name] : EnumNames<E>::table)
    if (v == value) return name;
  return "?";
}

// The value a name (its own or another it is read by) stands for.
template <NamedEnum E>
constexpr std::optional<E> enum_from_name(std::string_view name) {
  for (const auto& [v, n] : EnumNames<E>::table)
    if (n == name) return v;
  return std::nullopt;
}

// Every value once, in the table's order.
template <NamedEnum E>
std::vector<E> enum_values() {
  std::vector<E> values;
  for (const auto& [v, name] : EnumNames<E>::table)
    if (enum_name(v) == name) values.push_back(v);
  return values;
}

// The values' own names: quoted and comma-separated for a design key ("\"tri\", \"grid\",
// \"hex\""), or as words for a flag ("tri, grid or hex").
template <NamedEnum E>
std::string enum_choices_quoted() {
  std::string list;
  for (E v : enum_values<E>()) list += (list.empty() ? "\"" : ", \"") + std::string(enum_name(v)) + "\"";
  return list;
}
template <NamedEnum E>
std::string enum_choices_words() {
  const std::vector<E> values = enum_values<E>();
  std::string list;
  for (std::size_t i = 0; i < values.size(); ++i)
    list += (i == 0 ? "" : i + 1 == values.size() ? " or " : ", ") + std::string(enum_name(values[i]));
  return list;
}

}  // namespace paver
