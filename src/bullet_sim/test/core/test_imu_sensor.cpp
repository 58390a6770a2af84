// The IMU model read directly: at rest it feels the ground pushing up (+g along the
// sensor's own up axis), turning at a steady rate its gyro reads that rate, a change of
// velocity adds its acceleration, everything in the sensor frame; noise is seeded. Then the
// same on the Burger through Simulation::readImu.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "bullet_sim/simulation.h"
#include "burger.h"
#include "sensors/imu_sensor.h"

using namespace bullet_sim;

namespace {

const Eigen::Vector3d kGravity(0, 0, -9.81);
const Eigen::Vector3d kZero = Eigen::Vector3d::Zero();

Eigen::Isometry3d turned(const Eigen::AngleAxisd& rotation) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translate(Eigen::Vector3d(1, 2, 0.07));  // where it is does not matter
  T.rotate(rotation);
  return T;
}

ImuSpec noiseless() {
  ImuSpec spec;
  spec.frame_id = "imu_link";
  return spec;
}

}  // namespace

TEST(ImuSensor, AtRestLevelItReadsPlusGUpAndNoRotation) {
  ImuSensor imu;
  std::mt19937_64 rng(1);
  const Eigen::Isometry3d level = turned(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()));
  for (double t : {0.0, 0.005, 0.010}) {  // the first read has no previous one to differ from
    const ImuData d = imu.read(noiseless(), level, kZero, kZero, kGravity, t, &rng);
    EXPECT_TRUE(d.linear_acceleration.isApprox(Eigen::Vector3d(0, 0, 9.81), 1e-12))
        << d.linear_acceleration.transpose();
    EXPECT_TRUE(d.angular_velocity.isZero(1e-15));
    EXPECT_NEAR(d.orientation.angularDistance(Eigen::Quaterniond(level.linear())), 0, 1e-12);
    EXPECT_EQ(d.frame_id, "imu_link");
    EXPECT_EQ(d.time_s, t);
  }
}

TEST(ImuSensor, ReadingsAreInTheSensorFrame) {
  // Rolled +90 degrees about x: the sensor's y axis points up, its z axis along world -y.
  ImuSensor imu;
  std::mt19937_64 rng(1);
  const Eigen::Isometry3d rolled = turned(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
  const Eigen::Vector3d yaw_rate(0, 0, 0.8);  // world z
  imu.read(noiseless(), rolled, kZero, yaw_rate, kGravity, 0, &rng);
  const ImuData d = imu.read(noiseless(), rolled, kZero, yaw_rate, kGravity, 0.01, &rng);
  EXPECT_TRUE(d.linear_acceleration.isApprox(Eigen::Vector3d(0, 9.81, 0), 1e-12))
      << d.linear_acceleration.transpose();
  EXPECT_TRUE(d.angular_velocity.isApprox(Eigen::Vector3d(0, 0.8, 0), 1e-12))
      << d.angular_velocity.transpose();
}

TEST(ImuSensor, TurningSteadilyTheGyroReadsTheRateAndSpeedingUpAddsTheAcceleration) {
  // Yawed 90 degrees (sensor x = world y, sensor y = world -x), turning at 1.2 rad/s while
  // its velocity goes from 0 to 0.5 m/s along world x in 0.1 s: 5 m/s^2 along world x,
  // which is -5 along the sensor's y.
  ImuSensor imu;
  std::mt19937_64 rng(1);
  const Eigen::Isometry3d yawed = turned(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  const Eigen::Vector3d turning(0, 0, 1.2);
  imu.read(noiseless(), yawed, kZero, turning, kGravity, 1.0, &rng);
  const ImuData d =
      imu.read(noiseless(), yawed, Eigen::Vector3d(0.5, 0, 0), turning, kGravity, 1.1, &rng);
  EXPECT_TRUE(d.angular_velocity.isApprox(Eigen::Vector3d(0, 0, 1.2), 1e-12));
  EXPECT_TRUE(d.linear_acceleration.isApprox(Eigen::Vector3d(0, -5, 9.81), 1e-9))
      << d.linear_acceleration.transpose();
  // After a reset (a teleport) the first read has nothing to differ from: +g only.
  imu.reset();
  const ImuData after =
      imu.read(noiseless(), yawed, Eigen::Vector3d(3, 0, 0), turning, kGravity, 1.2, &rng);
  EXPECT_TRUE(after.linear_acceleration.isApprox(Eigen::Vector3d(0, 0, 9.81), 1e-12));
}

TEST(ImuSensor, SeededNoiseHasTheSpecifiedSpreadAndRepeats) {
  ImuSpec spec = noiseless();
  spec.gaussian_noise = 0.02;
  const Eigen::Isometry3d level = turned(Eigen::AngleAxisd(0, Eigen::Vector3d::UnitZ()));
  auto readMany = [&](uint64_t seed, std::vector<double>* z_accel, std::vector<double>* z_gyro) {
    ImuSensor imu;
    std::mt19937_64 rng(seed);
    for (int i = 0; i < 4000; ++i) {
      const ImuData d = imu.read(spec, level, kZero, kZero, kGravity, 0.005 * i, &rng);
      z_accel->push_back(d.linear_acceleration.z());
      z_gyro->push_back(d.angular_velocity.z());
      EXPECT_DOUBLE_EQ(d.linear_acceleration_cov, 0.02 * 0.02);
    }
  };
  std::vector<double> accel, gyro, accel_again, gyro_again, accel_other, gyro_other;
  readMany(7, &accel, &gyro);
  readMany(7, &accel_again, &gyro_again);
  readMany(8, &accel_other, &gyro_other);
  EXPECT_EQ(accel, accel_again);
  EXPECT_EQ(gyro, gyro_again);
  EXPECT_NE(accel, accel_other);
  // Mean and spread of 4000 samples: the mean within 4 standard errors (0.02 / sqrt(4000)
  // = 0.00032) of 9.81 and of 0, the standard deviation within 5 % of 0.02 (its relative
  // standard error is 1 / sqrt(2 * 4000) = 1.1 %).
  for (const auto& [samples, truth] : {std::make_pair(&accel, 9.81), std::make_pair(&gyro, 0.0)}) {
    double sum = 0, sum_sq = 0;
    for (double x : *samples) {
      sum += x - truth;
      sum_sq += (x - truth) * (x - truth);
    }
    const double n = static_cast<double>(samples->size());
    EXPECT_NEAR(sum / n, 0, 4 * 0.02 / std::sqrt(n));
    EXPECT_NEAR(std::sqrt(sum_sq / n), 0.02, 0.05 * 0.02);
  }
}

namespace {

/// The means of the Burger's IMU (noise sd 0.01, seeded) over `reads` reads at its 200 Hz,
/// with the simulation stepped in between.
struct MeanImu {
  Eigen::Vector3d linear_acceleration = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
};
MeanImu meanImu(Simulation* sim, int reads) {
  MeanImu mean;
  sim->readImu("burger", 0);  // the next read differentiates from here
  for (int i = 0; i < reads; ++i) {
    for (int k = 0; k < 5; ++k) sim->step();
    const ImuData d = sim->readImu("burger", 0);
    mean.linear_acceleration += d.linear_acceleration / reads;
    mean.angular_velocity += d.angular_velocity / reads;
  }
  return mean;
}

Eigen::Matrix3d imuOrientation(const Simulation& sim) {
  for (const LinkPose& link : sim.linkPoses("burger")) {
    if (link.link == "imu_link") return link.pose.orientation.toRotationMatrix();
  }
  ADD_FAILURE() << "no imu_link";
  return Eigen::Matrix3d::Identity();
}

}  // namespace

TEST(BurgerImu, AtRestItFeelsGravityAlongItsUpAxisAndTurningItsGyroReadsTheTurnRate) {
  RobotSpec spec = bullet_sim_test::burgerSpec();
  spec.imus.at(0).gaussian_noise = 0.01;
  SimConfig cfg;
  cfg.seed = 3;
  Simulation sim(bullet_sim_test::flatWorld(), cfg);  // gravity 9.8
  sim.spawnRobot("burger", spec, Pose3());
  for (int i = 0; i < 2000; ++i) sim.step();  // settled on wheels and caster
  // At rest: +9.8 along the world's up, in the sensor frame. The Burger leans back a little
  // on its caster, so the sensor's up is not quite the world's: take its true orientation.
  const Eigen::Matrix3d R_world_imu = imuOrientation(sim);
  ASSERT_GT(R_world_imu(2, 2), std::cos(0.05));  // within 3 degrees of level
  // 200 reads: the noise's mean has a standard error of 0.01 / sqrt(200) = 0.0007.
  const MeanImu rest = meanImu(&sim, 200);
  const Eigen::Vector3d up_in_imu = R_world_imu.transpose() * Eigen::Vector3d(0, 0, 9.8);
  EXPECT_LT((rest.linear_acceleration - up_in_imu).cwiseAbs().maxCoeff(), 0.005)
      << rest.linear_acceleration.transpose() << " vs " << up_in_imu.transpose();
  EXPECT_LT(rest.angular_velocity.norm(), 0.003) << rest.angular_velocity.transpose();
  // Turning on the spot at 1 rad/s, 1 s after the command (the ramp takes 0.1 s): over
  // one second of reads the gyro averages the turn rate about the world's up, seen in the
  // leaning sensor's frame (its lean keeps its direction relative to the robot). The
  // Burger rocks on its caster as it turns, which the mean over the second smooths out.
  sim.setCmdVel("burger", 0, 1.0);
  for (int i = 0; i < 1000; ++i) sim.step();
  const MeanImu turning = meanImu(&sim, 200);
  const Eigen::Vector3d expected = imuOrientation(sim).transpose() * Eigen::Vector3d(0, 0, 1.0);
  EXPECT_TRUE((turning.angular_velocity - expected).cwiseAbs().maxCoeff() < 0.005)
      << turning.angular_velocity.transpose() << " vs " << expected.transpose();
}
