// Robots in parallel: the same run to the bit whatever the number of threads, and robots
// simulated in worlds of their own still push each other and see each other.
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bullet_sim/simulation.h"
#include "burger.h"

using namespace bullet_sim;

namespace {

/// Everything a run produced, as the bits of each number, with what each entry was.
struct Trace {
  std::vector<uint64_t> bits;
  std::vector<std::string> what;
  void add(double value, const std::string& label) {
    uint64_t b;
    std::memcpy(&b, &value, sizeof b);
    bits.push_back(b);
    what.push_back(label);
  }
};

Pose3 poseAt(double x, double y, double yaw) {
  Pose3 p;
  p.position = Eigen::Vector3d(x, y, 0);
  p.orientation = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
  return p;
}

/// 16 Burgers in the round track's west lane, 4 rows of 4; rows 0 and 1 drive at each
/// other, as do rows 2 and 3 (they meet within a second), each robot turning a little
/// differently, so that they push, slide off each other and hit the lane's walls.
void spawnSixteen(Simulation* sim) {
  const double xs[4] = {-0.55, -0.25, 0.05, 0.35};
  const double ys[4] = {-1.4, -0.95, 0.3, 0.75};
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 4; ++col) {
      const std::string name = "tb3_" + std::to_string(4 * row + col);
      const double yaw = row % 2 == 0 ? M_PI / 2 : -M_PI / 2;
      sim->spawnRobot(name, bullet_sim_test::burgerSpec(), poseAt(xs[col], ys[row], yaw));
      sim->setCmdVel(name, 0.2, 0.3 * (col - 1.5) * (row % 2 == 0 ? 1 : -1));
    }
  }
}

void addPose(const Simulation& sim, const std::string& robot, Trace* trace) {
  const Pose3 p = sim.modelPose(robot);
  const std::string at = robot + " pose at " + std::to_string(sim.timeS()) + " s";
  for (int i = 0; i < 3; ++i) trace->add(p.position[i], at);
  for (double q : {p.orientation.w(), p.orientation.x(), p.orientation.y(), p.orientation.z()}) {
    trace->add(q, at);
  }
}

void addReading(Simulation* sim, const DueSensor& due, Trace* trace) {
  const std::string at = due.robot + " sensor at " + std::to_string(sim->timeS()) + " s";
  switch (due.kind) {
    case SensorKind::Ray:
      for (float r : sim->readRay(due.robot, due.index).ranges) trace->add(r, at + " (scan)");
      break;
    case SensorKind::Imu: {
      const ImuData imu = sim->readImu(due.robot, due.index);
      for (int i = 0; i < 3; ++i) trace->add(imu.linear_acceleration[i], at + " (imu)");
      for (int i = 0; i < 3; ++i) trace->add(imu.angular_velocity[i], at + " (imu)");
      break;
    }
    case SensorKind::Odometry:
      trace->add(sim->readOdometry(due.robot).twist_in_child.linear.x(), at + " (odometry)");
      break;
    case SensorKind::JointStates:
      for (double q : sim->readJointStates(due.robot).positions) trace->add(q, at + " (joints)");
      break;
    default:  // cameras and the plugins' readings: the sixteen Burgers have none to trace
      break;
  }
}

/// Every pose after every call and every due reading of `seconds` of the sixteen, stepped
/// by step() (round_steps 0) or by stepToNextReading(round_steps).
Trace runSixteen(unsigned threads, double seconds, unsigned round_steps = 0) {
  SimConfig cfg;
  cfg.threads = threads;
  Simulation sim(loadWorldFile(bullet_sim_test::roundTrackPath()), cfg);
  EXPECT_EQ(sim.threads(), threads);
  spawnSixteen(&sim);
  Trace trace;
  while (sim.timeS() < seconds) {
    const std::vector<DueSensor> due =
        round_steps == 0 ? sim.step() : sim.stepToNextReading(round_steps);
    for (const DueSensor& d : due) addReading(&sim, d, &trace);
    for (const std::string& robot : sim.robotNames()) addPose(sim, robot, &trace);
  }
  return trace;
}

void expectSameBits(const Trace& a, const Trace& b) {
  ASSERT_EQ(a.bits.size(), b.bits.size());
  for (size_t i = 0; i < a.bits.size(); ++i) {
    ASSERT_EQ(a.bits[i], b.bits[i]) << "first difference: entry " << i << ", " << a.what[i];
  }
}

}  // namespace

TEST(Threads, SixteenBurgersGiveTheSameRunToTheBitOnOneTwoAndThreeThreads) {
  const Trace one = runSixteen(1, 2.5);
  const Trace two = runSixteen(2, 2.5);
  const Trace three = runSixteen(3, 2.5);
  expectSameBits(one, two);
  expectSameBits(one, three);
}

TEST(Threads, SixteenBurgersInRoundsGiveTheSameRunToTheBitOnOneAndTwoThreads) {
  expectSameBits(runSixteen(1, 2.5, 5), runSixteen(2, 2.5, 5));
}

TEST(Threads, SixteenBurgersMeetEachOther) {
  // The runs above are only a test of the grouping if the robots touch: the rows that
  // drive at each other are stopped short of where they would be alone.
  for (unsigned round_steps : {0u, 5u}) {
    SimConfig cfg;
    cfg.threads = 2;
    Simulation sim(loadWorldFile(bullet_sim_test::roundTrackPath()), cfg);
    spawnSixteen(&sim);
    while (sim.timeS() < 2.5) {
      if (round_steps == 0) {
        sim.step();
      } else {
        sim.stepToNextReading(round_steps);
      }
    }
    int held_back = 0;
    for (int row = 0; row < 2; ++row) {
      for (int col = 0; col < 4; ++col) {
        const double y = sim.modelPose("tb3_" + std::to_string(4 * row + col)).position.y();
        // Alone, 2.5 s at 0.2 m/s moves a robot about 0.45 m along y (less its turn); the
        // rows start 0.45 m apart, so neither row could pass the other's start.
        const double start = row == 0 ? -1.4 : -0.95;
        if (std::fabs(y - start) < 0.3) ++held_back;
      }
    }
    EXPECT_GE(held_back, 4) << "rounds of " << round_steps << " steps";
  }
}

namespace {

/// The Burger without its lidar, IMU and camera: only its odometry and joint states (30 Hz)
/// end a round, so rounds are up to 34 steps long.
RobotSpec blindBurger() {
  RobotSpec spec = bullet_sim_test::burgerSpec();
  spec.rays.clear();
  spec.imus.clear();
  spec.cameras.clear();
  return spec;
}

/// After 6 s of "pusher" driving at 0.2 m/s into "pushed", 1 m ahead: alone the pusher
/// would drive 1.2 m, through the other. The pusher's front is 0.038 m ahead of its
/// base_footprint (base box 0.14 m centred 0.032 m behind it), the other's back 0.102 m
/// behind its own: they stay at least 0.14 m apart.
void expectPushed(const Simulation& sim, unsigned threads) {
  const double pusher = sim.modelPose("pusher").position.x();
  const double pushed = sim.modelPose("pushed").position.x();
  EXPECT_GT(pushed - pusher, 0.14 - 0.005) << threads << " threads";
  EXPECT_GT(pusher, 0.8) << threads << " threads";
}

/// Sim time in whole milliseconds (1 ms steps).
long millis(const Simulation& sim) { return std::lround(sim.timeS() * 1000); }

}  // namespace

TEST(Rounds, EachEndsWithTheFirstStepAtWhichASensorIsDue) {
  SimConfig cfg;
  cfg.threads = 1;
  Simulation sim(bullet_sim_test::flatWorld(), cfg);
  sim.spawnRobot("tb3", bullet_sim_test::burgerSpec(), poseAt(0, 0, 0));
  const RobotSpec& spec = sim.robotSpec("tb3");
  ASSERT_EQ(spec.imus.size(), 1u);
  ASSERT_EQ(spec.imus[0].update_rate_hz, 200.0);
  ASSERT_EQ(spec.diff_drive->update_rate_hz, 30.0);
  ASSERT_EQ(spec.cameras.at(0).update_rate_hz, 30.0);
  // The IMU's 5 ms periods end with steps 5, 10, ...; a 30 Hz period (odometry, joint
  // states, camera) within step 34 (34 ms x 30 Hz = 1.02 periods), then 67 (2.01).
  std::vector<long> ends;
  std::vector<size_t> due_counts;
  while (sim.timeS() < 0.0695) {
    due_counts.push_back(sim.stepToNextReading(100).size());
    ends.push_back(millis(sim));
  }
  EXPECT_EQ(ends, (std::vector<long>{5, 10, 15, 20, 25, 30, 34, 35, 40, 45, 50, 55, 60, 65, 67,
                                     70}));
  EXPECT_EQ(due_counts, (std::vector<size_t>{1, 1, 1, 1, 1, 1, 3, 1, 1, 1, 1, 1, 1, 1, 3, 1}));
}

TEST(Rounds, EndAtTheirLengthWhenNoSensorIsDueAndTakeOneStepAtLeast) {
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  unsigned taken = 0;
  EXPECT_TRUE(sim.stepToNextReading(7, &taken).empty());
  EXPECT_EQ(millis(sim), 7);
  EXPECT_EQ(taken, 7u);
  sim.stepToNextReading(0, &taken);
  EXPECT_EQ(millis(sim), 8);
  EXPECT_EQ(taken, 1u);
  sim.spawnRobot("tb3", blindBurger(), poseAt(0, 0, 0));
  EXPECT_TRUE(sim.stepToNextReading(20).empty());
  EXPECT_EQ(millis(sim), 28);
  EXPECT_EQ(sim.stepToNextReading(20).size(), 2u);  // odometry and joint states
  EXPECT_EQ(millis(sim), 34);
}

TEST(Rounds, TakeOneStepAtATimeWhileAnExternalWrenchIsSet) {
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  sim.spawnRobot("tb3", blindBurger(), poseAt(0, 0, 0));
  BodyWrench push;
  push.robot = "tb3";
  push.link = "base_link";
  push.wrench.force_n = Eigen::Vector3d(1.0, 0, 0);
  push.window.duration_s = 0.003;
  sim.externalForces().addWrench(push, sim.timeS());
  std::vector<long> ends;
  while (sim.timeS() < 0.0335) {
    sim.stepToNextReading(20);
    ends.push_back(millis(sim));
  }
  // The wrench acts in the steps that start at 0, 1 and 2 ms and is dropped at the next.
  EXPECT_EQ(ends, (std::vector<long>{1, 2, 3, 4, 24, 34}));
}

TEST(Rounds, AreStepByStepToTheBitForRobotsApart) {
  // Robots that never come near each other are grouped alike whatever the rounds' length:
  // every pose and reading is the same as step by step.
  const auto run = [](unsigned round_steps) {
    SimConfig cfg;
    cfg.threads = 2;
    Simulation sim(loadWorldFile(bullet_sim_test::roundTrackPath()), cfg);
    sim.spawnRobot("south", bullet_sim_test::burgerSpec(), poseAt(-0.55, -1.4, M_PI / 2));
    sim.spawnRobot("north", bullet_sim_test::burgerSpec(), poseAt(0.35, 0.75, -M_PI / 2));
    sim.setCmdVel("south", 0.15, 0.2);
    sim.setCmdVel("north", 0.1, -0.3);
    Trace trace;
    while (sim.timeS() < 1.0) {
      const std::vector<DueSensor> due =
          round_steps == 0 ? sim.step() : sim.stepToNextReading(round_steps);
      for (const DueSensor& d : due) addReading(&sim, d, &trace);
      if (!due.empty()) {
        for (const std::string& robot : sim.robotNames()) addPose(sim, robot, &trace);
      }
    }
    return trace;
  };
  const Trace by_step = run(0);
  EXPECT_GT(by_step.bits.size(), 1000u);
  expectSameBits(by_step, run(5));
  expectSameBits(by_step, run(40));
}

TEST(Threads, ABurgerPushesAnotherSimulatedInAWorldOfItsOwn) {
  for (unsigned threads : {1u, 2u}) {
    SimConfig cfg;
    cfg.threads = threads;
    Simulation sim(bullet_sim_test::flatWorld(), cfg);
    sim.spawnRobot("pusher", bullet_sim_test::burgerSpec(), poseAt(0, 0, 0));
    sim.spawnRobot("pushed", bullet_sim_test::burgerSpec(), poseAt(1.0, 0, 0));
    sim.setCmdVel("pusher", 0.2, 0);
    while (sim.timeS() < 6.0) sim.step();
    expectPushed(sim, threads);
  }
}

TEST(Rounds, ABurgerPushesAnotherSimulatedInAWorldOfItsOwn) {
  // Rounds of up to 34 steps: the worlds are grouped for all of a round's steps at once.
  for (unsigned threads : {1u, 2u}) {
    SimConfig cfg;
    cfg.threads = threads;
    Simulation sim(bullet_sim_test::flatWorld(), cfg);
    sim.spawnRobot("pusher", blindBurger(), poseAt(0, 0, 0));
    sim.spawnRobot("pushed", blindBurger(), poseAt(1.0, 0, 0));
    sim.setCmdVel("pusher", 0.2, 0);
    while (sim.timeS() < 6.0) sim.stepToNextReading(100);
    expectPushed(sim, threads);
  }
}

namespace {

// Where ray 90 (+y) of a Burger's scanner at x -0.032 meets, at the scan plane, another
// Burger's lidar housing, short of that robot's base_footprint: the housing is a cylinder
// of radius 0.055 m whose axis is 0.017 m behind its base_footprint (scan_joint x -0.032,
// collision origin x +0.015).
double housingNearSide() {
  const double dx = -0.017 - -0.032;
  return std::sqrt(0.055 * 0.055 - dx * dx);
}

/// "looker" at the origin and "seen" 1 m to its left, each in a world of its own (2 threads),
/// after 0.2 s at rest.
std::unique_ptr<Simulation> twoBurgersApart() {
  SimConfig cfg;
  cfg.threads = 2;
  auto sim = std::make_unique<Simulation>(bullet_sim_test::flatWorld(), cfg);
  sim->spawnRobot("looker", bullet_sim_test::burgerSpec(), poseAt(0, 0, 0));
  sim->spawnRobot("seen", bullet_sim_test::burgerSpec(), poseAt(0, 1.0, 0));
  while (sim->timeS() < 0.2) sim->step();
  return sim;
}

}  // namespace

TEST(Threads, LidarSeesARobotSimulatedInAnotherWorld) {
  const auto sim = twoBurgersApart();
  EXPECT_NEAR(sim->readRay("looker", 0).ranges[90], 1.0 - housingNearSide(), 0.03);
}

TEST(Threads, LidarSeesARobotMovedBetweenStepsAtOnce) {
  // Two lidar reads in one step with the seen robot moved between them: each read sees it
  // where it is.
  const auto sim = twoBurgersApart();
  const Pose3 seen_at = sim->modelPose("seen");
  EXPECT_NEAR(sim->readRay("looker", 0).ranges[90], 1.0 - housingNearSide(), 0.03);
  for (double y : {2.0, 1.5}) {
    Pose3 moved = seen_at;
    moved.position.y() = y;
    sim->setModelState("seen", moved, Twist3());
    EXPECT_NEAR(sim->readRay("looker", 0).ranges[90], y - housingNearSide(), 0.03)
        << "at y " << y;
  }
}

namespace {

/// Scans as bits, in order.
Trace traceOf(const std::vector<DueSensor>& rays, const std::vector<LaserScanData>& scans) {
  Trace trace;
  for (size_t i = 0; i < scans.size(); ++i) {
    trace.add(scans[i].time_s, rays[i].robot + " scan time");
    for (float r : scans[i].ranges) trace.add(r, rays[i].robot + " scan");
  }
  return trace;
}

/// Every robot's first lidar, read together with readRays or one by one with readRay.
Trace scansOf(Simulation* sim, bool together) {
  std::vector<DueSensor> rays;
  for (const std::string& robot : sim->robotNames()) rays.push_back({robot, SensorKind::Ray, 0});
  std::vector<LaserScanData> scans;
  if (together) {
    scans = sim->readRays(rays);
  } else {
    for (const DueSensor& ray : rays) scans.push_back(sim->readRay(ray.robot, ray.index));
  }
  return traceOf(rays, scans);
}

/// The sixteen after 1 s on the round track.
std::unique_ptr<Simulation> sixteenAfterOneSecond(unsigned threads) {
  SimConfig cfg;
  cfg.threads = threads;
  auto sim = std::make_unique<Simulation>(loadWorldFile(bullet_sim_test::roundTrackPath()), cfg);
  spawnSixteen(sim.get());
  while (sim->timeS() < 1.0) sim->stepToNextReading(5);
  return sim;
}

/// A Burger at the origin facing +x and one at (0, 1), on a flat floor with a pile of 600
/// posts (2 x 2 x 20 cm) at (1, 0), through the scan plane: more parts within the lidars'
/// 3.5 m than castScan lists, so their scans walk Bullet's broadphase.
std::unique_ptr<Simulation> twoBurgersAndAPile(unsigned threads) {
  SimConfig cfg;
  cfg.threads = threads;
  WorldSpec world = bullet_sim_test::flatWorld();
  for (int i = 0; i < 600; ++i) {
    StaticShape box;
    static_cast<Geometry&>(box) = Geometry::box(0.02, 0.02, 0.2);
    box.pose.position = Eigen::Vector3d(1.0, 0, 0.1);
    world.shapes.push_back(box);
  }
  auto sim = std::make_unique<Simulation>(world, cfg);
  sim->spawnRobot("looker", bullet_sim_test::burgerSpec(), poseAt(0, 0, 0));
  sim->spawnRobot("seen", bullet_sim_test::burgerSpec(), poseAt(0, 1.0, 0));
  while (sim->timeS() < 0.2) sim->stepToNextReading(5);
  return sim;
}

}  // namespace

TEST(Threads, ScansReadTogetherOnTwoThreadsAreTheScansReadOneByOne) {
  const auto one_by_one = sixteenAfterOneSecond(1), together = sixteenAfterOneSecond(2);
  const Trace expected = scansOf(one_by_one.get(), false);
  ASSERT_EQ(expected.bits.size(), 16u * 361u);
  expectSameBits(expected, scansOf(together.get(), true));
}

TEST(Threads, ScansThatWalkTheBroadphaseAreReadTogetherAsOneByOne) {
  const auto one_by_one = twoBurgersAndAPile(1), together = twoBurgersAndAPile(2);
  const Trace expected = scansOf(one_by_one.get(), false);
  expectSameBits(expected, scansOf(together.get(), true));
  // The pile is in the scans: the looker's scanner, 0.032 m behind its base_footprint,
  // sees its near face 1.032 - 0.01 m straight ahead (ray 0).
  const std::vector<DueSensor> looker = {{"looker", SensorKind::Ray, 0}};
  EXPECT_NEAR(together->readRays(looker)[0].ranges[0], 1.022, 0.03);
}

TEST(Threads, ReadRaysRefusesASensorNamedTwice) {
  const auto sim = twoBurgersApart();
  const std::vector<DueSensor> twice = {{"looker", SensorKind::Ray, 0},
                                        {"looker", SensorKind::Ray, 0}};
  EXPECT_THROW(sim->readRays(twice), std::invalid_argument);
}

TEST(Threads, RunInParallelCallsEveryPieceOnceAndRethrowsWhatOneThrewAfterTheOthersRan) {
  for (unsigned threads : {1u, 2u}) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    SimConfig cfg;
    cfg.threads = threads;
    const Simulation sim(bullet_sim_test::flatWorld(), cfg);
    for (int job = 0; job < 3; ++job) {
      std::vector<std::atomic<int>> calls(7);
      sim.runInParallel(calls.size(), [&calls](size_t i) { ++calls[i]; });
      for (const std::atomic<int>& n : calls) EXPECT_EQ(n.load(), 1);
    }
    std::vector<std::atomic<int>> calls(5);
    EXPECT_THROW(sim.runInParallel(calls.size(), [&calls](size_t i) {
      ++calls[i];
      if (i == 1) throw std::runtime_error("piece 1");
    }), std::runtime_error);
    for (const std::atomic<int>& n : calls) EXPECT_EQ(n.load(), 1);
  }
}

TEST(Threads, RobotsInOneWorldCanBeDeletedAndResetInAnyOrder) {
  for (const char* first : {"pusher", "pushed"}) {
    SimConfig cfg;
    cfg.threads = 2;
    Simulation sim(bullet_sim_test::flatWorld(), cfg);
    sim.spawnRobot("pusher", bullet_sim_test::burgerSpec(), poseAt(0, 0, 0));
    sim.spawnRobot("pushed", bullet_sim_test::burgerSpec(), poseAt(0.3, 0, 0));
    sim.spawnRobot("third", bullet_sim_test::burgerSpec(), poseAt(0.6, 0, 0));
    sim.setCmdVel("pusher", 0.2, 0);
    while (sim.timeS() < 1.5) sim.step();  // the three touch: one world
    ASSERT_TRUE(sim.deleteRobot(first));
    while (sim.timeS() < 2.0) sim.step();
    sim.reset();
    while (sim.timeS() < 0.5) sim.step();
    for (const std::string& robot : sim.robotNames()) {
      EXPECT_LT(std::fabs(sim.modelPose(robot).position.z()), 0.01) << robot << ", " << first;
    }
    EXPECT_EQ(sim.robotNames().size(), 2u);
  }
}
