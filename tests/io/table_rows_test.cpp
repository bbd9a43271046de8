// The row policy's pieces (io/table_rows.hpp): the field-count message, the
// resolution of a written number, and the tolerance of a value given twice.
#include "io/table_rows.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "io/io_test_files.hpp"

namespace dilatant::io::table_rows_test {
namespace {

TEST(TableRows, AFieldCountOtherThanTheHeadersNamesTheLine) {
  check_field_count("t.csv", 3, 4, 4);
  EXPECT_EQ(test::input_error_message([] {
              check_field_count("t.csv", 3, 5, 4);
            }).rfind("t.csv:3: 5 fields, the header has 4", 0),
            0u);
}

TEST(TableRows, WrittenResolutionIsOneUnitOfTheLastDigit) {
  EXPECT_DOUBLE_EQ(written_resolution("12.5"), 0.1 / 12.5);
  EXPECT_DOUBLE_EQ(written_resolution("8633,9"), 0.1 / 8633.9);
  EXPECT_DOUBLE_EQ(written_resolution("1.5e3"), 100.0 / 1500.0);
  EXPECT_DOUBLE_EQ(written_resolution("-2.50E-2"), 1e-4 / 0.025);
  EXPECT_DOUBLE_EQ(written_resolution("700"), 100.0 / 700.0);  // trailing zeros: rounding
  EXPECT_DOUBLE_EQ(written_resolution("700.0"), 0.1 / 700.0);
  EXPECT_DOUBLE_EQ(written_resolution("0"), 1.0);
}

TEST(TableRows, ImpliedValueToleranceBoundsTheRatioOfRoundedValues) {
  // Five significant digits each: about 3 x 1e-4 relative at most.
  const double t = implied_value_tolerance(1e-4, 1e-4, 1e-4);
  EXPECT_GT(t, 3e-4);
  EXPECT_LT(t, 3.1e-4);
  check_implied_value("t.csv", 2, "viscosity", 2.0002, "stress / rate", 2.0, t);
  EXPECT_NE(test::input_error_message([&] {
              check_implied_value("t.csv", 2, "viscosity", 2.2, "stress / rate", 2.0, t);
            }).find("t.csv:2: viscosity 2.2 disagrees with stress / rate = 2 by 10%"),
            std::string::npos);
}

TEST(TableRows, DroppedRowsAreCountedOncePerLine) {
  DroppedRows d;
  EXPECT_EQ(d.positive("t.csv", 2, "a", "1.5", 1.5), 1.5);
  EXPECT_FALSE(d.positive("t.csv", 3, "a", "0", 0.0));
  EXPECT_FALSE(d.positive("t.csv", 3, "b", "", std::nullopt));
  EXPECT_FALSE(d.positive("t.csv", 4, "a", "nan", std::nan("")));
  EXPECT_EQ(d.count(), 2u);
  EXPECT_EQ(d.summary(), "2 rows dropped (missing value: line 4; zero or negative value: line 3)");
  EXPECT_NE(test::input_error_message([&] {
              d.positive("t.csv", 5, "a", "x", std::nullopt);
            }).find("t.csv:5: column 'a': 'x' is not a number"),
            std::string::npos);
}

}  // namespace
}  // namespace dilatant::io::table_rows_test
