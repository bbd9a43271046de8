// The text layer under the flow-curve reader: encodings, separators, fields
// and numbers as rheometer software writes them.
#include "analysis/delimited_text.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "io/io_test_files.hpp"

namespace dilatant::analysis::delimited_text_test {
namespace {

TEST(DelimitedText, ParsesDecimalPointsAndDecimalCommas) {
  EXPECT_EQ(parse_number("1.5"), 1.5);
  EXPECT_EQ(parse_number("1,5"), 1.5);
  EXPECT_EQ(parse_number(" 2,5e3 "), 2500.0);
  EXPECT_EQ(parse_number("+7"), 7.0);
  EXPECT_EQ(parse_number("-0,01"), -0.01);
  EXPECT_FALSE(parse_number(""));
  EXPECT_FALSE(parse_number("abc"));
  EXPECT_FALSE(parse_number("1.234,5"));  // thousands separators are not guessed
  EXPECT_FALSE(parse_number("1,2,3"));
  EXPECT_FALSE(parse_number("12 Pa"));
  ASSERT_TRUE(parse_number("nan"));  // a number, but not finite: the caller refuses it
  EXPECT_TRUE(std::isnan(*parse_number("nan")));
}

TEST(DelimitedText, SplitsOnTheLinesSeparatorAndKeepsQuotedSeparators) {
  EXPECT_EQ(detect_separator("a\tb;c,d"), '\t');
  EXPECT_EQ(detect_separator("a;b,c"), ';');
  EXPECT_EQ(detect_separator("a,b"), ',');
  const auto f = split_fields(" 1 ,\"2,5\", \"x\" ,", ',');
  ASSERT_EQ(f.size(), 4u);
  EXPECT_EQ(f[0], "1");
  EXPECT_EQ(f[1], "2,5");
  EXPECT_EQ(f[2], "x");
  EXPECT_EQ(f[3], "");
}

TEST(DelimitedText, DecodesUtf16WithBomAndStripsUtf8BomAndCarriageReturns) {
  test::TempDir dir;
  // "ab\r\nη\n" in UTF-16 LE with its byte-order mark.
  const std::string utf16(
      "\xFF\xFE"
      "a\0b\0\r\0\n\0\xB7\x03\n\0",
      14);
  const auto lines = read_text_lines(dir.write("u16.csv", utf16));
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "ab");
  EXPECT_EQ(lines[1], "\xCE\xB7");
  const auto utf8 = read_text_lines(dir.write("u8.csv", "\xEF\xBB\xBFx;y\r\n1;2\r\n"));
  ASSERT_EQ(utf8.size(), 2u);
  EXPECT_EQ(utf8[0], "x;y");
  EXPECT_EQ(utf8[1], "1;2");
}

}  // namespace
}  // namespace dilatant::analysis::delimited_text_test
