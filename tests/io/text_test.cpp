#include "io/text.hpp"

#include <gtest/gtest.h>

namespace dilatant::text_test {
namespace {

TEST(Trim, DropsBlanksAtBothEndsOnly) {
  EXPECT_EQ(trim("  shear rate\t"), "shear rate");
  EXPECT_EQ(trim("a b"), "a b");
  EXPECT_EQ(trim("x"), "x");
}

TEST(Trim, DropsTheLineEndsOfAnotherSystem) {
  EXPECT_EQ(trim("0.5\r"), "0.5");
  EXPECT_EQ(trim("\r\n 1e-3 \r\n"), "1e-3");
}

TEST(Trim, ABlankOrEmptyTextIsEmpty) {
  EXPECT_TRUE(trim("").empty());
  EXPECT_TRUE(trim(" \t\r\n").empty());
}

}  // namespace
}  // namespace dilatant::text_test
