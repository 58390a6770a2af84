// The depth camera against geometry computed by hand: a wall and a turned box in front of
// depth_camera_robot.urdf's Kinect. Each pixel's depth is the distance along the optical
// axis to the nearest face on the ray through that pixel, NaN where the ray meets nothing
// within the far clip distance or the depth is outside the plugin's cutoffs; each point of
// the cloud is depth * K^-1 [u v 1] and lies on the face that was hit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "bullet_sim/render/camera_renderer.h"
#include "bullet_sim/render/depth_camera.h"
#include "bullet_sim/simulation.h"
#include "depth_fixture.h"

namespace {

using bullet_sim_test::depthFixtureText;
using bullet_sim_test::depthFixtureWith;

using bullet_sim::DepthImageData;
using bullet_sim::ImageData;
using bullet_sim::Pose3;
using bullet_sim::StaticShape;
using Eigen::Vector3d;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kWidth = 160, kHeight = 120;
constexpr double kHfov = 1.0472, kNear = 0.05;
// The base spawns at the origin, yaw 0; camera_link is 0.5 m above it and looks along +x.
const Vector3d kCamera(0, 0, 0.5);
// Depth is stored as a float: 1 mm covers its rounding at these distances many times over.
constexpr double kToleranceM = 1e-3;

struct Box {
  Vector3d centre, size;
  double yaw;
};
// A wall 2.5 m wide and 2 m high whose near face is 3 m ahead, and a box turned by 0.4 rad.
const Box kWall{{3.05, -0.25, 1.0}, {0.1, 2.5, 2.0}, 0.0};
const Box kCrate{{1.5, 0.3, 0.35}, {0.4, 0.3, 0.5}, 0.4};

Eigen::Matrix3d yawMatrix(double yaw) { return Eigen::AngleAxisd(yaw, Vector3d::UnitZ()).matrix(); }

StaticShape shapeOf(const Box& box, const std::string& name) {
  StaticShape s;
  s.kind = StaticShape::Box;
  s.model = s.link = name;
  s.pose.position = box.centre;
  s.pose.orientation = Eigen::Quaterniond(yawMatrix(box.yaw));
  s.size = box.size;
  return s;
}

/// Smallest t > 0 with p + t d inside the box (slabs in the box's frame), else +inf.
double rayBox(const Vector3d& p_world, const Vector3d& d_world, const Box& box) {
  const Eigen::Matrix3d R = yawMatrix(box.yaw).transpose();
  const Vector3d p = R * (p_world - box.centre), d = R * d_world;
  double t_in = 0, t_out = kInf;
  for (int i = 0; i < 3; ++i) {
    const double half = 0.5 * box.size[i];
    if (d[i] == 0) {
      if (std::abs(p[i]) > half) return kInf;
      continue;
    }
    const double a = (-half - p[i]) / d[i], b = (half - p[i]) / d[i];
    t_in = std::max(t_in, std::min(a, b));
    t_out = std::min(t_out, std::max(a, b));
  }
  return t_in <= t_out ? t_in : kInf;
}

double focal() { return (kWidth / 2.0) / std::tan(kHfov / 2.0); }

/// Ray through pixel (u, v) in the world, scaled so that its step along the optical axis
/// (the camera's +x, Gazebo convention: y left, z up) is 1: then t is the depth.
Vector3d pixelRay(int u, int v) {
  return Vector3d(1, -(u - kWidth / 2.0) / focal(), -(v - kHeight / 2.0) / focal());
}

/// Depth the camera should report at (u, v): the nearest face within clip far, if inside
/// the cutoffs (both exclusive), else NaN.
double expectedDepth(int u, int v, double far_m, double cutoff_m, double cutoff_max_m) {
  const Vector3d d = pixelRay(u, v);
  const double t = std::min(rayBox(kCamera, d, kWall), rayBox(kCamera, d, kCrate));
  if (t > far_m || !(t > cutoff_m && t < cutoff_max_m)) return std::nan("");
  return t;
}

struct Frame {
  ImageData image;
  DepthImageData depth;
  bullet_sim::CameraSpec camera;
};

Frame renderFixture(const std::string& urdf) {
  bullet_sim::WorldSpec world;
  world.shapes = {shapeOf(kWall, "wall"), shapeOf(kCrate, "crate")};
  bullet_sim::Simulation sim(world, bullet_sim::SimConfig{});
  sim.spawnRobot("depth_bot", bullet_sim::parseRobot(urdf, "depth_camera_robot.urdf"), Pose3{});
  bullet_sim::CameraRenderer renderer(sim);
  Frame frame;
  frame.camera = sim.robotSpec("depth_bot").cameras.at(0);
  renderer.render("depth_bot", 0, &frame.image, &frame.depth);
  return frame;
}

/// Compares every pixel; returns how many hit something.
int expectDepthsMatch(const Frame& frame, double far_m, double cutoff_m, double cutoff_max_m) {
  EXPECT_EQ(frame.depth.width, kWidth);
  EXPECT_EQ(frame.depth.height, kHeight);
  EXPECT_EQ(frame.depth.depth_m.size(), static_cast<size_t>(kWidth * kHeight));
  int hits = 0, mismatches = 0;
  for (int v = 0; v < kHeight; ++v) {
    for (int u = 0; u < kWidth; ++u) {
      const double expected = expectedDepth(u, v, far_m, cutoff_m, cutoff_max_m);
      const double got = frame.depth.depth_m[v * kWidth + u];
      const bool ok =
          std::isnan(expected) ? std::isnan(got) : std::abs(got - expected) < kToleranceM;
      if (!ok && ++mismatches <= 5) {
        ADD_FAILURE() << "pixel (" << u << ", " << v << "): depth " << got << ", expected "
                      << expected;
      }
      if (!std::isnan(got)) ++hits;
    }
  }
  EXPECT_EQ(mismatches, 0);
  return hits;
}

TEST(DepthCamera, EveryPixelIsTheDistanceAlongTheOpticalAxisOrNaN) {
  const Frame frame = renderFixture(depthFixtureText());
  EXPECT_EQ(frame.depth.frame_id, "camera_depth_optical_frame");
  const int hits = expectDepthsMatch(frame, 8.0, 0.1, 6.0);
  // Both the wall and the crate are in view, and sky is left over (NaN).
  EXPECT_GT(hits, kWidth * kHeight / 4);
  EXPECT_LT(hits, kWidth * kHeight * 3 / 4);
  const float centre_row_left = frame.depth.depth_m[60 * kWidth + 5];
  EXPECT_TRUE(std::isnan(centre_row_left)) << "left of the wall's edge at y = 1.0 nothing is hit";
}

TEST(DepthCamera, ItsColourImageIsLitByTheWorldsPointLights) {
  // The wall's near face (grey 0.7, facing the camera, the sun behind it) under the default
  // ambient 0.4, and an AutoRace lamp 0.5 m in front of it on the optical axis.
  bullet_sim::WorldSpec world;
  world.shapes = {shapeOf(kWall, "wall"), shapeOf(kCrate, "crate")};
  bullet_sim::LightSpec lamp;
  lamp.pose.position = Vector3d(2.5, 0, 0.5);
  lamp.diffuse = Eigen::Vector4f(0.5f, 0.5f, 0.5f, 1);
  lamp.range_m = 20;
  lamp.constant = 0.5;
  lamp.linear = 0.01;
  lamp.quadratic = 0.001;
  auto centre = [](const bullet_sim::WorldSpec& w) {
    bullet_sim::Simulation sim(w, bullet_sim::SimConfig{});
    sim.spawnRobot("depth_bot", bullet_sim::parseRobot(depthFixtureText(), "depth_camera_robot.urdf"),
                   Pose3{});
    bullet_sim::CameraRenderer renderer(sim);
    ImageData image;
    DepthImageData depth;
    renderer.render("depth_bot", 0, &image, &depth);
    return static_cast<int>(image.data[(kHeight / 2) * image.step + 3 * (kWidth / 2)]);
  };
  // 0.7 x 0.4 = 0.28 -> 71 without; with it d = 0.5, cos = 1, 1 / (0.5 + 0.005 + 0.00025)
  // = 1.979218: 0.7 (0.4 + 0.5 x 1.979218) = 0.972726 -> 248.
  EXPECT_EQ(centre(world), 71);
  world.lights.push_back(lamp);
  EXPECT_EQ(centre(world), 248);
}

TEST(DepthCamera, BeyondTheFarClipNothingIsHit) {
  const Frame frame = renderFixture(depthFixtureWith("<far>8.0</far>", "<far>2.5</far>"));
  const int hits = expectDepthsMatch(frame, 2.5, 0.1, 6.0);
  EXPECT_GT(hits, 100);  // the crate alone
}

TEST(DepthCamera, DepthsOutsideTheCutoffsAreNaN) {
  const Frame frame = renderFixture(
      depthFixtureWith("<pointCloudCutoffMax>6.0</pointCloudCutoffMax>",
                  "<pointCloudCutoffMax>2.0</pointCloudCutoffMax>"));
  const int hits = expectDepthsMatch(frame, 8.0, 0.1, 2.0);
  EXPECT_GT(hits, 100);
  const Frame near_cut = renderFixture(depthFixtureWith("<pointCloudCutoff>0.1</pointCloudCutoff>",
                                                   "<pointCloudCutoff>2.0</pointCloudCutoff>"));
  EXPECT_GT(expectDepthsMatch(near_cut, 8.0, 2.0, 6.0), 100);  // the wall alone
}

TEST(DepthCamera, PointsAreDepthTimesInverseKAndLieOnTheSurfaceHit) {
  const Frame frame = renderFixture(depthFixtureText());
  bullet_sim::PointCloudData cloud;
  bullet_sim::makePointCloud(frame.camera, frame.depth, frame.image, &cloud);
  ASSERT_EQ(cloud.width, kWidth);
  ASSERT_EQ(cloud.height, kHeight);
  ASSERT_EQ(cloud.data.size(), static_cast<size_t>(kWidth * kHeight * 32));
  EXPECT_FALSE(cloud.is_dense);  // the sky gives NaN points
  EXPECT_EQ(cloud.frame_id, "camera_depth_optical_frame");
  int on_wall = 0;
  for (int v = 0; v < kHeight; ++v) {
    for (int u = 0; u < kWidth; ++u) {
      const size_t i = static_cast<size_t>(v) * kWidth + u;
      float xyz[3];
      std::memcpy(xyz, &cloud.data[i * 32], sizeof(xyz));
      const double d = frame.depth.depth_m[i];
      if (std::isnan(d)) {
        EXPECT_TRUE(std::isnan(xyz[0]) && std::isnan(xyz[1]) && std::isnan(xyz[2]));
        continue;
      }
      // K^-1 [u v 1] with fx = fy = (w / 2) / tan(hfov / 2), cx = w / 2, cy = h / 2.
      EXPECT_NEAR(xyz[0], d * (u - kWidth / 2.0) / focal(), 1e-5);
      EXPECT_NEAR(xyz[1], d * (v - kHeight / 2.0) / focal(), 1e-5);
      EXPECT_FLOAT_EQ(xyz[2], static_cast<float>(d));
      // Optical frame (x right, y down, z ahead) to the world: ahead is +x, right is -y.
      const Vector3d world = kCamera + Vector3d(xyz[2], -xyz[0], -xyz[1]);
      if (std::abs(world.x() - 3.0) < kToleranceM) ++on_wall;
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(cloud.data[i * 32 + 16 + c], frame.image.data[3 * i + c]);
      }
    }
  }
  EXPECT_GT(on_wall, kWidth * kHeight / 5);  // the wall's near face is the plane x = 3
}

TEST(DepthCamera, ARenderWithDepthOfAPlainCameraIsRefused) {
  const std::string plain = depthFixtureWith("type=\"depth\"", "type=\"camera\"");
  const std::string urdf = plain.substr(0, plain.find("libgazebo_ros_openni_kinect.so")) +
                           "libgazebo_ros_camera.so" +
                           plain.substr(plain.find("libgazebo_ros_openni_kinect.so") + 30);
  bullet_sim::WorldSpec world;
  bullet_sim::Simulation sim(world, bullet_sim::SimConfig{});
  sim.spawnRobot("bot", bullet_sim::parseRobot(urdf, "plain.urdf"), Pose3{});
  bullet_sim::CameraRenderer renderer(sim);
  ImageData image;
  DepthImageData depth;
  try {
    renderer.render("bot", 0, &image, &depth);
    FAIL() << "rendered depth for a plain camera";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "camera 'kinect' on link 'camera_link' of robot 'bot' is not a depth camera");
  }
}

}  // namespace
