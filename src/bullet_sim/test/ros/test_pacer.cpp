// Pacer::stepsDue: one step at a time while the simulation keeps up with the wall clock,
// as many as it is behind (at most a round) when it does not, a whole round unpaced.
// Pacer::waitUntil after a stall: paces on from the stall's end, not catching it up.
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "runner/pacer.h"

using bullet_sim_node::Pacer;

namespace {

// A wall clock that moves only when slept on or stalled: steps take no wall time.
struct FakeWall {
  Pacer::Clock::time_point now{};
  Pacer make(double real_time_factor) {
    return Pacer(
        real_time_factor, [this] { return now; },
        [this](Pacer::Clock::time_point t) { now = std::max(now, t); });
  }
  void pass(double s) {
    now += std::chrono::duration_cast<Pacer::Clock::duration>(std::chrono::duration<double>(s));
  }
  double secondsSince(Pacer::Clock::time_point t) const {
    return std::chrono::duration<double>(now - t).count();
  }
};

// The node's loop (SimulatorNode::spinOnce) for `wall_s` of wall time from `*sim_s`:
// the steps due, then the wait. Returns the sim time it reached.
double run(Pacer* pacer, FakeWall* wall, double sim_s, double wall_s) {
  constexpr double kStepS = 0.001;
  const Pacer::Clock::time_point start = wall->now;
  while (wall->secondsSince(start) < wall_s) {
    sim_s += pacer->stepsDue(sim_s, kStepS, 5) * kStepS;
    pacer->waitUntil(sim_s);
  }
  return sim_s;
}

// The sim time run in `wall_s` of wall time at `real_time_factor`, after `run_s` of wall
// time paced and then a stall of `stall_s` (the wall clock moves, the simulation does
// not).
double simTimeAfterStall(double real_time_factor, double run_s, double stall_s,
                         double wall_s) {
  FakeWall wall;
  Pacer pacer = wall.make(real_time_factor);
  const double before = run(&pacer, &wall, 0.0, run_s);
  EXPECT_NEAR(before, run_s * real_time_factor, 0.0015);
  wall.pass(stall_s);
  return run(&pacer, &wall, before, wall_s) - before;
}

}  // namespace

TEST(Pacer, AfterAStallPacesOnFromNowWithoutCatchingUp) {
  // Real time, a stall of 1 s, then 0.1 s of wall time: 0.1 s of sim time, as Gazebo's
  // world waits from the previous step's wall time, not the 1.1 s that catching up would
  // run. At most the lag still caught up (Pacer::kMaxLagS) and a step more.
  const double sim_s = simTimeAfterStall(1.0, 1.0, 1.0, 0.1);
  EXPECT_GE(sim_s, 0.1 - 0.0015);
  EXPECT_LE(sim_s, 0.1 + Pacer::kMaxLagS + 0.0015);
}

TEST(Pacer, AfterAStallKeepsTheFactor) {
  // Four times real time: 0.1 s of wall time after a 0.5 s stall gives 0.4 s of sim time.
  const double sim_s = simTimeAfterStall(4.0, 0.2, 0.5, 0.1);
  EXPECT_GE(sim_s, 0.4 - 0.0015);
  EXPECT_LE(sim_s, 0.4 + 4 * Pacer::kMaxLagS + 0.0015);
}

TEST(Pacer, ALateWakeWithinTheToleranceIsCaughtUp) {
  // A sleep that wakes 5 ms late (within Pacer::kMaxLagS) costs no sim time: after it,
  // 0.1 s of wall time has run 0.105 s of sim time, the factor over the whole stretch.
  EXPECT_NEAR(simTimeAfterStall(1.0, 0.1, 0.005, 0.1), 0.105, 0.0015);
}

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
