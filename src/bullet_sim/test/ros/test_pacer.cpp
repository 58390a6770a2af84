// Pacer::stepsDue: one step at a time while the simulation keeps up with the wall clock,
// as many as it is behind (at most a round) when it does not, a whole round unpaced.
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "runner/pacer.h"

using bullet_sim_node::Pacer;

TEST(Pacer, UnpacedTakesWholeRounds) {
  const Pacer pacer(0.0);
  EXPECT_EQ(pacer.stepsDue(0.0, 0.001, 5), 5u);
  EXPECT_EQ(pacer.stepsDue(12.5, 0.001, 1), 1u);
  EXPECT_EQ(pacer.stepsDue(12.5, 0.001, 0), 1u);  // a step at least
}

TEST(Pacer, KeepingUpTakesOneStep) {
  // 1 ms of sim time per wall second: the wall clock allows the next step only a second
  // after the start, so any call within that second finds the simulation keeping up.
  Pacer pacer(0.001);
  pacer.restart(3.0);
  EXPECT_EQ(pacer.stepsDue(3.0, 0.001, 5), 1u);
  // Sim time ahead of the wall clock (a step taken, its wait not over): one step too.
  EXPECT_EQ(pacer.stepsDue(3.004, 0.001, 5), 1u);
}

TEST(Pacer, BehindTakesWhatTheWallClockAllowsUpToARound) {
  // 1000 s of sim time per wall second: after 2 ms of wall time sim time could be 2 s on,
  // 2000 steps, more than a round.
  Pacer pacer(1000.0);
  pacer.restart(0.0);
  std::this_thread::sleep_for(std::chrono::milliseconds(2));
  EXPECT_EQ(pacer.stepsDue(0.0, 0.001, 5), 5u);
  // Behind by fewer steps than a round: that many. From 1.998 s short of the 2 s the wall
  // clock allows at the least, with steps of 1 s: 2 steps at least, never more than 5.
  const unsigned steps = pacer.stepsDue(0.0, 1.0, 5);
  EXPECT_GE(steps, 2u);
  EXPECT_LE(steps, 5u);
}

TEST(Pacer, AResetThatTookSimTimeBackTakesOneStep) {
  Pacer pacer(0.001);
  pacer.restart(50.0);
  EXPECT_EQ(pacer.stepsDue(0.0, 0.001, 5), 1u);
}
