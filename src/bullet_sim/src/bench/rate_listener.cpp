// bench_rate_listener: the subscriber side of bench/sim_rtf.sh and bench/multi_robot.py.
// Subscribes to odom, scan, imu and joint_states of every robot namespace given (the root
// when none is), and to /tf and /clock (the simulator starts paused); once every
// subscription is connected it unpauses the simulation, counts the messages stamped inside
// a window of sim time and prints each topic's rate in sim time, then the window's
// real-time factor as the last line. With --simulator it first loads the bullet_sim/Simulator
// nodelet into its own process, as /gazebo (parameters in /gazebo/...), so that its
// subscriptions are in-process: messages arrive without serialisation or a socket; it
// prints "subscribed" once its subscriptions are made. The caller then spawns the other
// robots and unpauses it (once its robots have their commands), and it keeps running
// after the figures until SIGINT.
// With --camera it also subscribes to a depth camera's camera/image_raw,
// camera/depth/image_raw and camera/points in each namespace.
// Usage: bench_rate_listener [--simulator] [--camera] WARMUP_SIM_S MEASURE_SIM_S
//        [NAMESPACE...]   ("/" for the root)
#include <nav_msgs/Odometry.h>
#include <nodelet/loader.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/JointState.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_srvs/Empty.h>
#include <tf2_msgs/TFMessage.h>

#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

using WallClock = std::chrono::steady_clock;

struct Window {
  double start_s = 0, end_s = 0;
  std::map<std::string, long> counts;
  bool started = false, done = false;
  WallClock::time_point wall_start, wall_end;
  double sim_start_s = 0, sim_end_s = 0;

  void onClock(const rosgraph_msgs::Clock& msg) {
    const double now_s = msg.clock.toSec();
    if (!started && now_s >= start_s) {
      started = true;
      wall_start = WallClock::now();
      sim_start_s = now_s;
    }
    if (!done && now_s >= end_s) {
      done = true;
      wall_end = WallClock::now();
      sim_end_s = now_s;
    }
  }
  void count(const std::string& topic, const ros::Time& stamp) {
    const double stamp_s = stamp.toSec();
    if (stamp_s >= start_s && stamp_s < end_s) ++counts[topic];
  }
};

template <class Msg>
ros::Subscriber countHeader(ros::NodeHandle& nh, const std::string& topic, Window& window) {
  window.counts[topic] = 0;
  const boost::function<void(const typename Msg::ConstPtr&)> callback =
      [&window, topic](const typename Msg::ConstPtr& msg) {
        window.count(topic, msg->header.stamp);
      };
  return nh.subscribe<Msg>(topic, 1000, callback);
}

/// Waits until every subscription has its publisher; false after 60 s.
bool waitForPublishers(const std::vector<ros::Subscriber>& subs) {
  const WallClock::time_point deadline = WallClock::now() + std::chrono::seconds(60);
  for (const ros::Subscriber& sub : subs) {
    while (ros::ok() && sub.getNumPublishers() == 0) {
      if (WallClock::now() > deadline) {
        std::fprintf(stderr, "%s did not connect within 60 s\n", sub.getTopic().c_str());
        return false;
      }
      ros::WallDuration(0.05).sleep();
    }
  }
  return true;
}

void spinFor(std::chrono::milliseconds period) {
  const WallClock::time_point until = WallClock::now() + period;
  while (WallClock::now() < until)
    ros::getGlobalCallbackQueue()->callAvailable(ros::WallDuration(0.01));
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "bench_rate_listener", ros::init_options::AnonymousName);
  bool in_process = false, camera = false;
  for (; argc > 1 && std::string(argv[1]).rfind("--", 0) == 0; --argc, ++argv) {
    const std::string option = argv[1];
    if (option == "--simulator") {
      in_process = true;
    } else if (option == "--camera") {
      camera = true;
    } else {
      argc = 0;  // usage
    }
  }
  if (argc < 3) {
    std::fprintf(stderr,
                 "usage: bench_rate_listener [--simulator] [--camera] WARMUP_SIM_S "
                 "MEASURE_SIM_S [NAMESPACE...]\n");
    return 2;
  }
  std::unique_ptr<nodelet::Loader> simulator;
  if (in_process) {
    simulator = std::make_unique<nodelet::Loader>(false);
    if (!simulator->load("/gazebo", "bullet_sim/Simulator", ros::M_string(), {})) return 1;
  }
  Window window;
  window.start_s = std::stod(argv[1]);
  const double measure_s = std::stod(argv[2]);
  window.end_s = window.start_s + measure_s;
  ros::NodeHandle nh;
  std::vector<std::string> namespaces(argv + 3, argv + argc);
  if (namespaces.empty()) namespaces.push_back("/");
  std::vector<ros::Subscriber> subs;
  for (const std::string& name : namespaces) {
    const std::string ns = name == "/" ? "/" : "/" + name + "/";
    subs.push_back(countHeader<nav_msgs::Odometry>(nh, ns + "odom", window));
    subs.push_back(countHeader<sensor_msgs::LaserScan>(nh, ns + "scan", window));
    subs.push_back(countHeader<sensor_msgs::Imu>(nh, ns + "imu", window));
    subs.push_back(countHeader<sensor_msgs::JointState>(nh, ns + "joint_states", window));
    if (camera) {  // a depth camera's colour and depth images and point cloud
      subs.push_back(countHeader<sensor_msgs::Image>(nh, ns + "camera/image_raw", window));
      subs.push_back(countHeader<sensor_msgs::Image>(nh, ns + "camera/depth/image_raw", window));
      subs.push_back(countHeader<sensor_msgs::PointCloud2>(nh, ns + "camera/points", window));
    }
  }
  window.counts["/tf"] = 0;
  const boost::function<void(const tf2_msgs::TFMessage::ConstPtr&)> tf_callback =
      [&window](const tf2_msgs::TFMessage::ConstPtr& msg) {
        for (const auto& transform : msg->transforms) window.count("/tf", transform.header.stamp);
      };
  const boost::function<void(const rosgraph_msgs::Clock::ConstPtr&)> clock_callback =
      [&window](const rosgraph_msgs::Clock::ConstPtr& msg) { window.onClock(*msg); };
  subs.push_back(nh.subscribe<tf2_msgs::TFMessage>("/tf", 1000, tf_callback));
  subs.push_back(nh.subscribe<rosgraph_msgs::Clock>("/clock", 100, clock_callback));
  if (simulator) {
    // roscpp links a subscription twice to a publisher of its own process when the
    // publisher is advertised while the subscription registers with the master (each
    // message then arrives twice): the caller spawns the other robots only after this line.
    std::printf("subscribed\n");
    std::fflush(stdout);
  }
  if (!waitForPublishers(subs)) return 1;
  if (!simulator) {
    if (!ros::service::waitForService("/gazebo/unpause_physics", ros::Duration(60))) return 1;
    std_srvs::Empty unpause;
    ros::service::call("/gazebo/unpause_physics", unpause);
  }
  const WallClock::time_point run_deadline = WallClock::now() + std::chrono::minutes(10);
  while (ros::ok() && !window.done && WallClock::now() < run_deadline)
    ros::getGlobalCallbackQueue()->callAvailable(ros::WallDuration(0.01));
  if (!window.done) {
    std::fprintf(stderr, "sim time did not reach %.1f s\n", window.end_s);
    return 1;
  }
  spinFor(std::chrono::milliseconds(500));  // messages still in flight
  for (const auto& [topic, count] : window.counts)
    std::printf("%-22s %8.1f Hz (sim time)\n", topic.c_str(), count / measure_s);
  const double wall_s = std::chrono::duration<double>(window.wall_end - window.wall_start).count();
  const double sim_s = window.sim_end_s - window.sim_start_s;
  std::printf("sim %.2f s in %.3f s wall\n", sim_s, wall_s);
  std::printf("real-time factor %.1f\n", sim_s / wall_s);
  if (simulator) {
    // The simulator lives in this process: it runs on (unwatched) until SIGINT, so that
    // the caller can still ask it how the robots move.
    std::fflush(stdout);
    subs.clear();
    while (ros::ok()) ros::WallDuration(0.05).sleep();
  }
  return 0;
}
