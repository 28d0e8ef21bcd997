#include "core/units.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>

#include "core/errors.hpp"

namespace latmpm {
namespace {

constexpr double pi = 3.14159265358979323846;

struct UnitDef {
  double factor;  // to SI
  Dimension dimension;
};

// Symbols with their own prefix set where SI prefixes apply.
const std::map<std::string, UnitDef>& base_units() {
  static const std::map<std::string, UnitDef> units = {
      {"m", {1.0, dimension::length}},
      {"g", {1e-3, dimension::mass}},
      {"s", {1.0, dimension::time}},
      {"Pa", {1.0, dimension::pressure}},
      {"N", {1.0, dimension::force}},
      {"J", {1.0, dimension::energy}},
      {"Hz", {1.0, dimension::frequency}},
  };
  return units;
}

// Symbols taken whole (no prefixes).
const std::map<std::string, UnitDef>& plain_units() {
  static const std::map<std::string, UnitDef> units = {
      {"in", {0.0254, dimension::length}},
      {"min", {60.0, dimension::time}},
      {"h", {3600.0, dimension::time}},
      {"rad", {1.0, dimension::angle}},
      {"deg", {pi / 180.0, dimension::angle}},
      {"°", {pi / 180.0, dimension::angle}},
      {"bar", {1e5, dimension::pressure}},
      {"%", {0.01, dimension::none}},
      {"1", {1.0, dimension::none}},
  };
  return units;
}

const std::map<std::string, double>& prefixes() {
  static const std::map<std::string, double> p = {
      {"G", 1e9}, {"M", 1e6}, {"k", 1e3}, {"c", 1e-2}, {"m", 1e-3},
      {"u", 1e-6}, {"µ", 1e-6}, {"n", 1e-9},
  };
  return p;
}

bool lookup_symbol(const std::string& symbol, UnitDef& out) {
  if (auto it = plain_units().find(symbol); it != plain_units().end()) {
    out = it->second;
    return true;
  }
  if (auto it = base_units().find(symbol); it != base_units().end()) {
    out = it->second;
    return true;
  }
  for (const auto& [prefix, factor] : prefixes()) {
    if (symbol.size() > prefix.size() && symbol.compare(0, prefix.size(), prefix) == 0) {
      auto it = base_units().find(symbol.substr(prefix.size()));
      if (it != base_units().end()) {
        out = {factor * it->second.factor, it->second.dimension};
        return true;
      }
    }
  }
  return false;
}

Dimension scaled(const Dimension& d, int power) {
  return {d.length * power, d.mass * power, d.time * power, d.angle * power};
}
Dimension added(const Dimension& a, const Dimension& b) {
  return {a.length + b.length, a.mass + b.mass, a.time + b.time, a.angle + b.angle};
}

bool is_symbol_char(unsigned char c) {
  return std::isalpha(c) || c == '%' || c >= 0x80;  // 0x80+: the bytes of µ and °
}

// unit := term (('/' | '*' | '.' | '·') term)* ; term := symbol ('^' int)? | '1'
UnitDef parse_unit(const std::string& text, const std::string& where, const std::string& field,
                   const std::string& whole) {
  UnitDef result{1.0, dimension::none};
  size_t i = 0;
  int sign = +1;
  bool expect_term = true;
  auto fail = [&](const std::string& why) -> InputError {
    return InputError(where, field, "'" + whole + "': " + why);
  };
  while (i < text.size()) {
    if (expect_term) {
      size_t start = i;
      if (text[i] == '1') {
        ++i;
      } else {
        while (i < text.size() && is_symbol_char(static_cast<unsigned char>(text[i]))) ++i;
      }
      std::string symbol = text.substr(start, i - start);
      if (symbol.empty()) throw fail("expected a unit symbol at '" + text.substr(start) + "'");
      UnitDef def{};
      if (!lookup_symbol(symbol, def)) throw fail("unknown unit '" + symbol + "'");
      int power = 1;
      if (i < text.size() && text[i] == '^') {
        ++i;
        size_t pstart = i;
        if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
        while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
        std::string p = text.substr(pstart, i - pstart);
        if (p.empty() || p == "-" || p == "+") throw fail("expected an integer power after '^'");
        power = std::stoi(p);
      }
      power *= sign;
      result.factor *= std::pow(def.factor, power);
      result.dimension = added(result.dimension, scaled(def.dimension, power));
      expect_term = false;
    } else {
      if (text[i] == '/') {
        sign = -1;
        ++i;
      } else if (text[i] == '*' || text[i] == '.') {
        sign = +1;
        ++i;
      } else if (text.compare(i, 2, "·") == 0) {
        sign = +1;
        i += 2;
      } else {
        throw fail("unexpected '" + text.substr(i) + "' in unit");
      }
      expect_term = true;
    }
  }
  if (expect_term) throw fail("unit ends with an operator");
  return result;
}

std::string trim(const std::string& s) {
  size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return s.substr(a, b - a);
}

}  // namespace

std::string format_millimetres(double metres, int significant_digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*g mm", significant_digits, metres * 1e3);
  return text;
}

std::string describe(const Dimension& d) {
  struct Named {
    Dimension d;
    const char* name;
  };
  static const Named names[] = {
      {dimension::none, "dimensionless"},   {dimension::length, "length"},
      {dimension::mass, "mass"},            {dimension::time, "time"},
      {dimension::angle, "angle"},          {dimension::area, "area"},
      {dimension::volume, "volume"},        {dimension::velocity, "velocity"},
      {dimension::acceleration, "acceleration"}, {dimension::frequency, "frequency"},
      {dimension::density, "density"},      {dimension::force, "force"},
      {dimension::pressure, "pressure"},    {dimension::energy, "energy"},
      {dimension::stiffness, "stiffness"},
  };
  for (const auto& n : names)
    if (n.d == d) return n.name;
  std::ostringstream os;
  os << "m^" << d.length << " kg^" << d.mass << " s^" << d.time << " rad^" << d.angle;
  return os.str();
}

std::string si_unit(const Dimension& d) {
  if (d == dimension::pressure) return "Pa";
  if (d == dimension::force) return "N";
  if (d == dimension::energy) return "J";
  if (d == dimension::none) return "1";
  std::string num, den;
  auto put = [](std::string& s, const char* sym, int p) {
    if (p == 0) return;
    if (!s.empty()) s += "*";
    s += sym;
    if (p != 1) s += "^" + std::to_string(p);
  };
  put(num, "kg", d.mass > 0 ? d.mass : 0);
  put(num, "m", d.length > 0 ? d.length : 0);
  put(num, "rad", d.angle > 0 ? d.angle : 0);
  put(num, "s", d.time > 0 ? d.time : 0);
  put(den, "kg", d.mass < 0 ? -d.mass : 0);
  put(den, "m", d.length < 0 ? -d.length : 0);
  put(den, "rad", d.angle < 0 ? -d.angle : 0);
  put(den, "s", d.time < 0 ? -d.time : 0);
  if (num.empty()) num = "1";
  return den.empty() ? num : num + "/" + den;
}

Quantity parse_quantity(const std::string& raw, const std::string& where,
                        const std::string& field) {
  const std::string text = trim(raw);
  if (text.empty()) throw InputError(where, field, "empty value, expected a number with a unit");
  const char* begin = text.c_str();
  char* end = nullptr;
  double number = std::strtod(begin, &end);
  if (end == begin) throw InputError(where, field, "'" + raw + "' does not start with a number");
  std::string number_text(begin, static_cast<const char*>(end));
  for (char c : number_text)
    if (std::isalpha(static_cast<unsigned char>(c)) && c != 'e' && c != 'E')
      throw InputError(where, field, "'" + raw + "' is not a finite number");
  if (!std::isfinite(number)) throw InputError(where, field, "'" + raw + "' is not a finite number");
  std::string unit = trim(std::string(end));
  Quantity q{number, dimension::none};
  if (unit.empty()) return q;
  UnitDef def = parse_unit(unit, where, field, raw);
  q.value = number * def.factor;
  q.dimension = def.dimension;
  return q;
}

double parse_quantity(const std::string& text, const Dimension& expected, const std::string& where,
                      const std::string& field) {
  Quantity q = parse_quantity(text, where, field);
  if (q.dimension != expected) {
    if (q.dimension.is_dimensionless() && !expected.is_dimensionless()) {
      bool has_unit = text.find_first_not_of("0123456789.eE+- \t") != std::string::npos;
      throw InputError(where, field,
                       "'" + text + "' " +
                           (has_unit ? "is dimensionless" : "has no unit") + "; expected a " +
                           describe(expected) + " such as '" +
                           (expected == dimension::length ? "2.4mm"
                            : expected == dimension::angle ? "30deg"
                            : "1" + si_unit(expected)) +
                           "'");
    }
    throw InputError(where, field,
                     "'" + text + "' is a " + describe(q.dimension) + ", expected a " +
                         describe(expected) + " (" + si_unit(expected) + ")");
  }
  return q.value;
}

}  // namespace latmpm
