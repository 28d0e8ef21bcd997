// Name tables of enumerations, both ways: a table is an array of rows (enum value, name, ...)
// as std::pair or std::tuple. Used by mpm/names.cpp (the solver's choices) and by the static
// solver's linear-solver names, so every scene choice reads, lists and refuses alike.
#pragma once
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/errors.hpp"

namespace latmpm::mpm::name_table {

template <class Enum, class Table>
std::string name_of(Enum value, const Table& names) {
  for (const auto& row : names)
    if (std::get<0>(row) == value) return std::get<1>(row);
  return "?";
}

template <class Table>
std::vector<std::string> names_in(const Table& names) {
  std::vector<std::string> out;
  for (const auto& row : names) out.emplace_back(std::get<1>(row));
  return out;
}

// The row's enum value for `text`; else InputError(where, field) listing every name.
template <class Table>
auto parse_name(const std::string& text, const Table& names, const std::string& where, const std::string& field) {
  std::string choices;
  for (const auto& row : names) {
    if (text == std::get<1>(row)) return std::get<0>(row);
    choices += (choices.empty() ? "" : ", ") + std::string(std::get<1>(row));
  }
  throw InputError(where, field, "unknown value '" + text + "' (expected one of: " + choices + ")");
}

}  // namespace latmpm::mpm::name_table
