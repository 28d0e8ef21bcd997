// Quantities with units: the one parser for every tool option and scene value.
//   parse_quantity("2.4mm", dimension::length)        -> 0.0024   (SI)
//   parse_quantity("100 mm/s", dimension::velocity)   -> 0.1
//   parse_quantity("6300kg/m^3", dimension::density)  -> 6300
//   parse_quantity("30deg", dimension::angle)         -> 0.5235987755982988 (radians)
// A bare number where a dimension is expected is an error; so is a unit of the wrong
// dimension. Angles are their own dimension so that "30" cannot be mistaken for radians.
#pragma once
#include <string>

namespace latmpm {

// Exponents of length, mass, time and plane angle.
struct Dimension {
  int length = 0, mass = 0, time = 0, angle = 0;
  bool operator==(const Dimension& o) const {
    return length == o.length && mass == o.mass && time == o.time && angle == o.angle;
  }
  bool operator!=(const Dimension& o) const { return !(*this == o); }
  bool is_dimensionless() const { return *this == Dimension{}; }
};

namespace dimension {
inline constexpr Dimension none{0, 0, 0, 0};
inline constexpr Dimension length{1, 0, 0, 0};
inline constexpr Dimension mass{0, 1, 0, 0};
inline constexpr Dimension time{0, 0, 1, 0};
inline constexpr Dimension angle{0, 0, 0, 1};
inline constexpr Dimension area{2, 0, 0, 0};
inline constexpr Dimension volume{3, 0, 0, 0};
inline constexpr Dimension velocity{1, 0, -1, 0};
inline constexpr Dimension acceleration{1, 0, -2, 0};
inline constexpr Dimension frequency{0, 0, -1, 0};  // also strain rate
inline constexpr Dimension density{-3, 1, 0, 0};
inline constexpr Dimension force{1, 1, -2, 0};
inline constexpr Dimension pressure{-1, 1, -2, 0};  // stress, modulus
inline constexpr Dimension energy{2, 1, -2, 0};
inline constexpr Dimension stiffness{0, 1, -2, 0};  // N/m
}  // namespace dimension

// "L^1 M^0 T^-2" style description, for messages: e.g. "length/time".
std::string describe(const Dimension& d);

// The SI unit of a dimension as text ("m", "Pa", "kg/m^3", "rad", "1").
std::string si_unit(const Dimension& d);

struct Quantity {
  double value = 0;  // SI (angles in radians)
  Dimension dimension;
};

// A length for messages and summaries: "1.28 mm", with `significant_digits` digits (%g).
std::string format_millimetres(double metres, int significant_digits);

// Parses "<number>[ ]<unit>". Throws InputError(where, field, problem) on any error,
// where/field name the file or option so the message points at the input.
Quantity parse_quantity(const std::string& text, const std::string& where = "",
                        const std::string& field = "");

// Parses and checks the dimension; returns the SI value.
double parse_quantity(const std::string& text, const Dimension& expected,
                      const std::string& where = "", const std::string& field = "");

}  // namespace latmpm
