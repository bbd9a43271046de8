// Column headings of flow-curve tables: names in the spellings of rheometer
// software and of our own files, and their units converted to SI.
#include "analysis/column_names.hpp"

#include <gtest/gtest.h>

#include <string>

namespace dilatant::analysis::column_names_test {
namespace {

struct Case {
  std::string heading;
  std::optional<Quantity> quantity;
  std::string unit;
};

TEST(ColumnNames, RecognisesCommonSpellingsAndSplitsOffTheUnit) {
  const Case cases[] = {
      {"Shear Rate [1/s]", Quantity::ShearRate, "1/s"},
      {"shear_rate", Quantity::ShearRate, ""},
      {"gamma_dot", Quantity::ShearRate, ""},
      {"Shear rate (\xCE\xB3\xCC\x87)", Quantity::ShearRate, ""},  // symbol in parentheses
      {"Shear Rate \xCE\xB3\xCC\x87 [s\xE2\x81\xBB\xC2\xB9]", Quantity::ShearRate,
       "s\xE2\x81\xBB\xC2\xB9"},
      {"Shear Stress (Pa)", Quantity::ShearStress, "Pa"},
      {"shear_stress", Quantity::ShearStress, ""},
      {"tau / Pa", Quantity::ShearStress, "Pa"},
      {"Shear Stress in mPa", Quantity::ShearStress, "mPa"},
      {"Viscosity [mPa\xC2\xB7s]", Quantity::Viscosity, "mPa\xC2\xB7s"},
      {"eta", Quantity::Viscosity, ""},
      {"\xCE\xB7 (Pa.s)", Quantity::Viscosity, "Pa.s"},
      {"Apparent Viscosity [Pa s]", Quantity::Viscosity, "Pa s"},
      {"Complex Viscosity [Pa s]", std::nullopt, "Pa s"},
      {"Time [s]", std::nullopt, "s"},
      {"Rate:", std::nullopt, ""},  // a metadata key, not a heading
      {"Point No.", std::nullopt, ""},
      // German and French exports (Anton Paar, Malvern, TA in those languages).
      {"Contrainte de Cisaillement", Quantity::ShearStress, ""},
      {"Gradient de Cisaillement", Quantity::ShearRate, ""},
      {"Viscosit\xC3\xA9", Quantity::Viscosity, ""},
      {"VISCOSIT\xC3\x89 [Pa\xC2\xB7s]", Quantity::Viscosity, "Pa\xC2\xB7s"},
      {"Schubspannung [Pa]", Quantity::ShearStress, "Pa"},
      {"Scherrate [1/s]", Quantity::ShearRate, "1/s"},
      {"Viskosit\xC3\xA4t [mPa\xC2\xB7s]", Quantity::Viscosity, "mPa\xC2\xB7s"},
      {"Shear rate(s-\xC2\xB9)", Quantity::ShearRate, "s-\xC2\xB9"},  // Malvern rSpace
      {"Contrainte normale", std::nullopt, ""},
  };
  for (const Case& c : cases) {
    const Heading h = parse_heading(c.heading);
    EXPECT_EQ(h.quantity, c.quantity) << c.heading;
    if (c.quantity) {
      EXPECT_EQ(h.unit, c.unit) << c.heading;
    }
  }
}

TEST(ColumnNames, ConvertsUnitsToSI) {
  EXPECT_EQ(si_factor(Quantity::ShearRate, "1/s"), 1.0);
  EXPECT_EQ(si_factor(Quantity::ShearRate, "s^-1"), 1.0);
  EXPECT_EQ(si_factor(Quantity::ShearRate, "s\xE2\x81\xBB\xC2\xB9"), 1.0);  // s⁻¹
  EXPECT_EQ(si_factor(Quantity::ShearRate, "s-\xC2\xB9"), 1.0);             // Malvern's s-¹
  EXPECT_EQ(si_factor(Quantity::ShearRate, "s-1"), 1.0);
  EXPECT_FALSE(si_factor(Quantity::ShearRate, "s\xC2\xB2"));  // s² is no rate
  EXPECT_EQ(si_factor(Quantity::ShearStress, "Pa"), 1.0);
  EXPECT_EQ(si_factor(Quantity::ShearStress, "mPa"), 1e-3);
  EXPECT_EQ(si_factor(Quantity::ShearStress, "kPa"), 1e3);
  EXPECT_EQ(si_factor(Quantity::ShearStress, "dyn/cm\xC2\xB2"), 0.1);
  for (const char* pas : {"Pa\xC2\xB7s", "Pa.s", "Pa s", "Pa*s", "Pas", "Pa\xB7s"})
    EXPECT_EQ(si_factor(Quantity::Viscosity, pas), 1.0) << pas;  // last: Windows-1252 middle dot
  for (const char* mpas : {"mPa\xC2\xB7s", "mPa.s", "mPa s", "cP"})
    EXPECT_EQ(si_factor(Quantity::Viscosity, mpas), 1e-3) << mpas;
  EXPECT_EQ(si_factor(Quantity::Viscosity, "P"), 0.1);
  EXPECT_EQ(si_factor(Quantity::Viscosity, ""), 1.0);  // no unit: SI (documented)
  // A unit of another quantity, or an unknown one, is refused, never guessed.
  EXPECT_FALSE(si_factor(Quantity::Viscosity, "Pa"));
  EXPECT_FALSE(si_factor(Quantity::ShearRate, "1/min"));
  EXPECT_FALSE(si_factor(Quantity::Viscosity, "Poise"));
}

TEST(ColumnNames, ReadsTheUnitOfAUnitsRowField) {
  EXPECT_EQ(unit_of_units_field("[mPa\xC2\xB7s]"), "mPa\xC2\xB7s");
  EXPECT_EQ(unit_of_units_field(" (1/s) "), "1/s");
  EXPECT_EQ(unit_of_units_field("Pa"), "Pa");
}

}  // namespace
}  // namespace dilatant::analysis::column_names_test
