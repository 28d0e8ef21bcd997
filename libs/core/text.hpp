// Lists of names in messages and logs: "a, b, c".
#pragma once
#include <string>

namespace latmpm {

// The items of a range of strings with `separator` between them ("" for none).
template <class Strings>
std::string joined(const Strings& items, const std::string& separator = ", ") {
  std::string text;
  for (const auto& item : items) {
    if (!text.empty()) text += separator;
    text += item;
  }
  return text;
}

// joined(items), or "none" when there are none.
template <class Strings>
std::string listed_or_none(const Strings& items) {
  const std::string text = joined(items);
  return text.empty() ? "none" : text;
}

}  // namespace latmpm
