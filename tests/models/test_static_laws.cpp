#include <gtest/gtest.h>

#include "frictionlab/models/coulomb.hpp"

TEST(Coulomb, Smoke) { EXPECT_EQ(frictionlab::Coulomb{2.0}.sliding(-1.0), -2.0); }
