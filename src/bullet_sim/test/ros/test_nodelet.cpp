// The bullet_sim/Simulator nodelet, loaded into this test process as a nodelet manager
// loads it: subscribers in the same process get its scans, its services answer from its
// stepping thread, a load with a bad world fails with the file named and leaves the
// process running, and an unload stops it. Values come from the wall table (DESIGN.md).
#include <bullet_sim/StepSimulation.h>
#include <gazebo_msgs/GetModelState.h>
#include <nodelet/loader.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <string>
#include <vector>

#include "../core/round_track.h"

namespace {

constexpr double kSpawnYaw = 1.5675;  // the test file's ~spawn_yaw
// base_footprint -> base_scan in the Burger description (scan_joint x -0.032).
constexpr double kScanOffsetX = -0.032;

/// The scans a subscriber of this process received.
class ScanInbox {
 public:
  void add(const sensor_msgs::LaserScan::ConstPtr& scan) {
    std::lock_guard<std::mutex> lock(mutex_);
    received_.push_back(scan);
    arrived_.notify_all();
  }
  /// Waits (at most 30 s) until `count` scans have come.
  bool waitFor(size_t count) {
    std::unique_lock<std::mutex> lock(mutex_);
    return arrived_.wait_for(lock, std::chrono::seconds(30),
                             [&] { return received_.size() >= count; });
  }
  sensor_msgs::LaserScan::ConstPtr scan(size_t i) {
    std::lock_guard<std::mutex> lock(mutex_);
    return received_.at(i);
  }

 private:
  std::mutex mutex_;
  std::condition_variable arrived_;
  std::vector<sensor_msgs::LaserScan::ConstPtr> received_;
};

bool load(nodelet::Loader* loader, const std::string& name) {
  return loader->load(name, "bullet_sim/Simulator", ros::M_string(), std::vector<std::string>());
}

/// rosconsole output of this process, to find what a failed load said.
class LogCapture : public ros::console::LogAppender {
 public:
  void log(ros::console::Level, const char* str, const char*, const char*, int) override {
    std::lock_guard<std::mutex> lock(mutex_);
    text_ += std::string(str) + "\n";
  }
  std::string text() {
    std::lock_guard<std::mutex> lock(mutex_);
    return text_;
  }

 private:
  std::mutex mutex_;
  std::string text_;
};

}  // namespace

TEST(SimulatorNodelet, ASubscriberInItsProcessGetsTheScansAndItsServicesAnswer) {
  nodelet::Loader loader(false);
  ASSERT_TRUE(load(&loader, "/gazebo"));
  ros::NodeHandle nh;
  ScanInbox inbox;
  const ros::Subscriber subscriber = nh.subscribe<sensor_msgs::LaserScan>(
      "/scan", 10, [&inbox](const sensor_msgs::LaserScan::ConstPtr& scan) { inbox.add(scan); });
  ASSERT_TRUE(ros::service::waitForService("/gazebo/step_simulation", ros::Duration(30)));

  // Paused at start: the lidar (5 Hz) falls due at 0.2 s and 0.4 s of sim time.
  bullet_sim::StepSimulation step;
  step.request.steps = 400;
  ASSERT_TRUE(ros::service::call("/gazebo/step_simulation", step));
  ASSERT_TRUE(step.response.success) << step.response.status_message;
  EXPECT_NEAR(step.response.sim_time.toSec(), 0.4, 1e-9);
  ASSERT_TRUE(inbox.waitFor(2));

  for (size_t i = 0; i < 2; ++i) {
    const sensor_msgs::LaserScan::ConstPtr scan = inbox.scan(i);
    EXPECT_EQ(scan->header.frame_id, "base_scan");
    EXPECT_NEAR(scan->header.stamp.toSec(), 0.2 * (i + 1), 1e-9);
    ASSERT_EQ(scan->ranges.size(), 360u);
    // Left and right of the spawn pose: the lane's west wall 0.8 m away and the inner
    // wall 0.5 m away, where the wall table puts them (noise 0.01 m, 4 sigma).
    const Eigen::Vector2d origin(kScanOffsetX * std::cos(kSpawnYaw), kScanOffsetX * std::sin(kSpawnYaw));
    for (int ray : {90, 270}) {
      const double expected = bullet_sim_test::wallDistance(
          origin, kSpawnYaw + scan->angle_min + ray * scan->angle_increment, scan->range_max);
      EXPECT_NEAR(scan->ranges[ray], expected, 0.04) << "ray " << ray;
    }
  }

  gazebo_msgs::GetModelState state;
  state.request.model_name = "burger";
  ASSERT_TRUE(ros::service::call("/gazebo/get_model_state", state));
  ASSERT_TRUE(state.response.success) << state.response.status_message;
  EXPECT_NEAR(state.response.pose.position.x, 0.0, 0.002);
  EXPECT_NEAR(state.response.pose.position.y, 0.0, 0.002);
  EXPECT_NEAR(2 * std::atan2(state.response.pose.orientation.z, state.response.pose.orientation.w),
              kSpawnYaw, 0.002);

  // Unloading stops the stepping thread and takes the services with it.
  ASSERT_TRUE(loader.unload("/gazebo"));
  EXPECT_TRUE(loader.listLoadedNodelets().empty());
  EXPECT_FALSE(ros::service::exists("/gazebo/step_simulation", false));
}

TEST(SimulatorNodelet, ABadWorldFailsTheLoadNamingTheFileAndTheProcessRunsOn) {
  LogCapture log;
  ros::console::register_appender(&log);
  nodelet::Loader loader(false);
  EXPECT_FALSE(load(&loader, "/broken"));
  ros::console::deregister_appender(&log);
  EXPECT_TRUE(loader.listLoadedNodelets().empty());
  std::string world;
  ASSERT_TRUE(ros::param::get("/broken/world_file", world));
  EXPECT_NE(log.text().find(world), std::string::npos) << log.text();
  EXPECT_NE(log.text().find("/broken"), std::string::npos) << log.text();
  // The process (the manager) is still there and loads a good one afterwards.
  EXPECT_TRUE(load(&loader, "/gazebo"));
  EXPECT_TRUE(loader.unload("/gazebo"));
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_nodelet");
  ros::AsyncSpinner spinner(2);  // this process's own subscribers and service clients
  spinner.start();
  const int result = RUN_ALL_TESTS();
  spinner.stop();
  ros::shutdown();
  return result;
}
