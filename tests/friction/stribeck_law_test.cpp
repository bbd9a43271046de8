#include "friction/stribeck_law.hpp"

#include <gtest/gtest.h>

TEST(Smoke, Builds) { EXPECT_GT(dilatant::StribeckLaw::hydrodynamic_mu(0.01), 0.0); }
