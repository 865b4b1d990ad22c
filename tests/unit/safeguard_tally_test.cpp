// The run's safeguard tally (solver/run/safeguard_tally.hpp): every step counted, the
// steps with a hit, the largest count, and the line validation/report.py parses.
#include "run/safeguard_tally.hpp"

#include <gtest/gtest.h>

using namespace sphdem;

TEST(SafeguardTally, CountsEveryStepAndTheLargestHit) {
  SafeguardTally t;
  t.add(0, 0);
  t.add(3, 0);
  t.add(0, 7);
  t.add(5, 2);
  EXPECT_EQ(t.steps, 4);
  EXPECT_EQ(t.floor_steps, 2);
  EXPECT_EQ(t.clamp_steps, 2);
  EXPECT_EQ(t.floor_largest, 5u);
  EXPECT_EQ(t.clamp_largest, 7u);
  EXPECT_TRUE(t.hit());
  // 8 floor and 9 clamp particle-steps over 4 steps of 100 particles
  EXPECT_EQ(t.describe(100),
            "safeguards over 4 steps: voidage floor hit in 2 steps (largest 5 particles, 2 % of "
            "particle-steps), Omega clamp hit in 2 steps (largest 7 particles, 2.25 % of "
            "particle-steps)");
}

TEST(SafeguardTally, QuietRunSaysNeverHit) {
  SafeguardTally t;
  for (int k = 0; k < 10; ++k) t.add(0, 0);
  EXPECT_FALSE(t.hit());
  EXPECT_EQ(t.describe(50),
            "safeguards over 10 steps: voidage floor hit in 0 steps (largest 0 particles, 0 % of "
            "particle-steps), Omega clamp hit in 0 steps (largest 0 particles, 0 % of "
            "particle-steps)");
}
