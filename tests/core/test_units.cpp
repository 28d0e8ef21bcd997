#include <catch2/catch.hpp>

#include <cmath>

#include "core/errors.hpp"
#include "core/units.hpp"

using namespace latmpm;

TEST_CASE("Quantities convert to SI", "[core][units]") {
  CHECK(parse_quantity("2.4mm", dimension::length) == Approx(0.0024).epsilon(1e-15));
  CHECK(parse_quantity("1.28 mm", dimension::length) == Approx(0.00128).epsilon(1e-15));
  CHECK(parse_quantity("8mm", dimension::length) == Approx(0.008).epsilon(1e-15));
  CHECK(parse_quantity("1in", dimension::length) == Approx(0.0254).epsilon(1e-15));
  CHECK(parse_quantity("30deg", dimension::angle) == Approx(M_PI / 6).epsilon(1e-15));
  CHECK(parse_quantity("0.5rad", dimension::angle) == 0.5);
  CHECK(parse_quantity("10MPa", dimension::pressure) == Approx(1e7).epsilon(1e-15));
  CHECK(parse_quantity("210 GPa", dimension::pressure) == Approx(2.1e11).epsilon(1e-15));
  CHECK(parse_quantity("100mm/s", dimension::velocity) == Approx(0.1).epsilon(1e-15));
  CHECK(parse_quantity("2 m/s", dimension::velocity) == 2.0);
  CHECK(parse_quantity("6300kg/m^3", dimension::density) == Approx(6300).epsilon(1e-15));
  CHECK(parse_quantity("1.05g/cm^3", dimension::density) == Approx(1050).epsilon(1e-12));
  CHECK(parse_quantity("9.81m/s^2", dimension::acceleration) == Approx(9.81).epsilon(1e-15));
  CHECK(parse_quantity("10kg", dimension::mass) == 10.0);
  CHECK(parse_quantity("5e-9s", dimension::time) == Approx(5e-9).epsilon(1e-15));
  CHECK(parse_quantity("150us", dimension::time) == Approx(1.5e-4).epsilon(1e-15));
  CHECK(parse_quantity("20ms", dimension::time) == Approx(0.02).epsilon(1e-15));
  CHECK(parse_quantity("2661.9 1/s", dimension::frequency) == Approx(2661.9).epsilon(1e-15));
  CHECK(parse_quantity("3kN", dimension::force) == Approx(3000).epsilon(1e-15));
  CHECK(parse_quantity("2.5mJ", dimension::energy) == Approx(2.5e-3).epsilon(1e-15));
  CHECK(parse_quantity("1N*m", dimension::energy) == 1.0);
  CHECK(parse_quantity("1e3N/m", dimension::stiffness) == 1000.0);
  CHECK(parse_quantity("-1.5mm", dimension::length) == Approx(-0.0015).epsilon(1e-15));
  CHECK(parse_quantity("5%", dimension::none) == Approx(0.05).epsilon(1e-15));
  CHECK(parse_quantity("0.4", dimension::none) == 0.4);
}

TEST_CASE("Quantity errors name the field and the problem", "[core][units]") {
  auto message = [](const std::string& text, const Dimension& d) -> std::string {
    try {
      parse_quantity(text, d, "--strut-diameter", "");
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  CHECK_THAT(message("2.4", dimension::length), Catch::Contains("--strut-diameter") &&
                                                    Catch::Contains("has no unit"));
  CHECK_THAT(message("30", dimension::angle), Catch::Contains("no unit"));
  CHECK_THAT(message("2.4MPa", dimension::length), Catch::Contains("is a pressure, expected a length"));
  CHECK_THAT(message("2.4 parsecs", dimension::length), Catch::Contains("unknown unit 'parsecs'"));
  CHECK_THAT(message("mm", dimension::length), Catch::Contains("does not start with a number"));
  CHECK_THAT(message("", dimension::length), Catch::Contains("empty"));
  CHECK_THAT(message("nanmm", dimension::length), Catch::Contains("number"));
  CHECK_THAT(message("infmm", dimension::length), Catch::Contains("not a finite number"));
  CHECK_THAT(message("1e999mm", dimension::length), Catch::Contains("not a finite number"));
  CHECK_THAT(message("2mm/", dimension::velocity), Catch::Contains("ends with an operator"));
  CHECK_THAT(message("2m/s^", dimension::velocity), Catch::Contains("integer power"));
  CHECK_THAT(message("2mm)", dimension::length), Catch::Contains("unexpected"));
}

TEST_CASE("Dimensions are described in words and SI units", "[core][units]") {
  CHECK(describe(dimension::pressure) == "pressure");
  CHECK(si_unit(dimension::density) == "kg/m^3");
  CHECK(si_unit(dimension::velocity) == "m/s");
  CHECK(si_unit(dimension::acceleration) == "m/s^2");
  CHECK(si_unit(dimension::force) == "N");
  CHECK(si_unit(dimension::angle) == "rad");
}
