// ocean/names.hpp — enum ⇄ name tables, shared by every module that names its enums.
//
// Each module keeps one table per enum, beside the enum and in declaration order: an array of
// {value, name} rows. Its to_string, its parser and every list of the allowed names (help texts,
// error messages) read that table, so a name is written once. Lookups are constexpr and do not
// allocate; name_list allocates the string it returns.
#pragma once

#include <array>
#include <cstddef>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>

namespace ocean {

/// One row of an enum ⇄ name table: a value and the name that files, flags and messages use.
template <class E>
struct EnumName {
  E value;
  std::string_view name;  ///< a string literal, so name.data() is null-terminated
};

/// The name of `value` in `table`; `fallback` when the table lacks it.
template <class E, std::size_t N>
constexpr std::string_view name_of(const std::array<EnumName<E>, N>& table, E value,
                                   std::string_view fallback = "unknown") {
  for (const EnumName<E>& row : table) {
    if (row.value == value) return row.name;
  }
  return fallback;
}

/// The value named `name` in `table` (exact match); nullopt when no row has that name.
template <class E, std::size_t N>
constexpr std::optional<E> value_of(const std::array<EnumName<E>, N>& table,
                                    std::string_view name) {
  for (const EnumName<E>& row : table) {
    if (row.name == name) return row.value;
  }
  return std::nullopt;
}

namespace enum_names_detail {
constexpr std::string_view row_name(std::string_view name) { return name; }
template <class E>
constexpr std::string_view row_name(const EnumName<E>& row) {
  return row.name;
}
}  // namespace enum_names_detail

/// The names of a table (of EnumName rows, or of plain names) in order, `separator` between them
/// and `last_separator` before the last, each inside `quote`:
/// name_list(lod::kQualityPresetNames, ", ", " or ") is "low, medium, high or ultra".
template <class Table>
std::string name_list(const Table& table, std::string_view separator,
                      std::string_view last_separator, std::string_view quote = {}) {
  std::string list;
  const std::size_t count = std::size(table);
  std::size_t i = 0;
  for (const auto& row : table) {
    if (i > 0) list += i + 1 == count ? last_separator : separator;
    list += quote;
    list += enum_names_detail::row_name(row);
    list += quote;
    ++i;
  }
  return list;
}

}  // namespace ocean
