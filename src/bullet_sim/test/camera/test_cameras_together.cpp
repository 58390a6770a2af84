// Camera frames rendered together (CameraRenderer::renderTogether, on the simulation's
// threads) against the same frames rendered one by one (render()): four Burgers facing each
// other among boxes (their cameras in rgb8, bgr8 and mono8), a depth camera and a
// wide-angle camera, on one and on two threads, bit for bit; a frame that cannot be
// rendered says why, as render() would, and the others are rendered all the same.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <exception>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "../core/burger.h"
#include "bullet_sim/errors.h"
#include "bullet_sim/render/camera_renderer.h"
#include "bullet_sim/render/depth_camera.h"
#include "bullet_sim/simulation.h"
#include "depth_fixture.h"
#include "wide_angle_fixture.h"

namespace {

using bullet_sim::CameraFrame;
using bullet_sim::CameraRenderer;
using bullet_sim::DepthImageData;
using bullet_sim::ImageData;
using bullet_sim::Pose3;
using bullet_sim::Simulation;
using Eigen::Vector3d;

Pose3 poseAt(double x, double y, double yaw) {
  Pose3 p;
  p.position = Vector3d(x, y, 0);
  p.orientation = Eigen::AngleAxisd(yaw, Vector3d::UnitZ());
  return p;
}

/// A flat floor with eight coloured boxes on a circle of 2.5 m around the origin.
bullet_sim::WorldSpec floorWithBoxes() {
  bullet_sim::WorldSpec world = bullet_sim_test::flatWorld();
  for (int i = 0; i < 8; ++i) {
    const double angle = M_PI / 8 + i * M_PI / 4;
    bullet_sim::StaticShape box;
    static_cast<bullet_sim::Geometry&>(box) = bullet_sim::Geometry::box(0.3, 0.4, 0.5 + 0.1 * i);
    box.model = box.link = "box" + std::to_string(i);
    box.pose = poseAt(2.5 * std::cos(angle), 2.5 * std::sin(angle), angle);
    box.pose.position.z() = 0.25 + 0.05 * i;
    box.rgba = Eigen::Vector4f(0.2f + 0.1f * i, 0.9f - 0.1f * i, 0.5f, 1.0f);
    world.shapes.push_back(box);
  }
  return world;
}

/// The Burger with its camera's image in `format` (Gazebo's name).
bullet_sim::RobotSpec burgerWithFormat(const std::string& format) {
  bullet_sim::RobotSpec spec = bullet_sim_test::burgerSpec();
  spec.cameras.at(0).format = format;
  return spec;
}

/// Four Burgers 1 m from the origin facing it (so each sees two others and boxes behind
/// them), the depth and the wide-angle fixture robots looking past them, and a Burger whose
/// camera has a field of view of 0 (which the renderer refuses); 0.3 s on `threads` threads.
std::unique_ptr<Simulation> cameraScene(unsigned threads) {
  bullet_sim::SimConfig cfg;
  cfg.threads = threads;
  auto sim = std::make_unique<Simulation>(floorWithBoxes(), cfg);
  const char* formats[4] = {"R8G8B8", "B8G8R8", "L8", "R8G8B8"};
  for (int i = 0; i < 4; ++i) {
    const double angle = i * M_PI / 2;
    const std::string name = "tb3_" + std::to_string(i);
    sim->spawnRobot(name, burgerWithFormat(formats[i]),
                    poseAt(std::cos(angle), std::sin(angle), angle + M_PI));
    sim->setCmdVel(name, 0.1, 0.3 * (i - 1.5));
  }
  sim->spawnRobot("depth_bot",
                  bullet_sim::parseRobot(bullet_sim_test::depthFixtureText(), "depth_bot"),
                  poseAt(-1.5, -1.5, M_PI / 4));
  sim->spawnRobot("wide_bot",
                  bullet_sim::parseRobot(bullet_sim_test::wideAngleFixtureWith(), "wide_bot"),
                  poseAt(1.5, -1.5, 3 * M_PI / 4));
  bullet_sim::RobotSpec no_fov = bullet_sim_test::burgerSpec();
  no_fov.cameras.at(0).horizontal_fov_rad = 0;  // the URDF parser would refuse it
  sim->spawnRobot("no_fov_bot", no_fov, poseAt(0, -1.8, M_PI / 2));
  while (sim->timeS() < 0.3) sim->stepToNextReading(5);
  return sim;
}

/// A frame as it came out: its image and depth image, or the message of what was thrown.
struct Result {
  ImageData image;
  DepthImageData depth;
  std::string error;
};

/// Every camera of every robot, a depth camera with its depth image, each into its result.
std::vector<CameraFrame> everyCamera(const Simulation& sim, std::vector<Result>* results) {
  std::vector<CameraFrame> frames;
  for (const std::string& robot : sim.robotNames()) {
    for (size_t i = 0; i < sim.robotSpec(robot).cameras.size(); ++i) {
      frames.push_back({robot, i, nullptr, nullptr, nullptr});
    }
  }
  results->assign(frames.size(), Result());
  for (size_t i = 0; i < frames.size(); ++i) {
    frames[i].image = &(*results)[i].image;
    if (sim.robotSpec(frames[i].robot).cameras[frames[i].index].depth) {
      frames[i].depth = &(*results)[i].depth;
    }
  }
  return frames;
}

/// The result of robot `robot`'s camera among `frames`.
const Result& resultOf(const std::string& robot, const std::vector<CameraFrame>& frames,
                       const std::vector<Result>& results) {
  for (size_t i = 0; i < frames.size(); ++i) {
    if (frames[i].robot == robot) return results[i];
  }
  throw std::out_of_range("no frame of " + robot);
}

std::string messageOf(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const std::exception& e) {
    return e.what();
  }
}

/// `frames` rendered one by one with render(), each into its own result.
std::vector<Result> oneByOne(CameraRenderer* renderer, const std::vector<CameraFrame>& frames) {
  std::vector<Result> results(frames.size());
  for (size_t i = 0; i < frames.size(); ++i) {
    try {
      renderer->render(frames[i].robot, frames[i].index, &results[i].image,
                       frames[i].depth ? &results[i].depth : nullptr);
    } catch (const std::exception& e) {
      results[i].error = e.what();
    }
  }
  return results;
}

/// `frames` (pointing into `results`) rendered together; errors copied into the results.
void together(CameraRenderer* renderer, std::vector<CameraFrame>* frames,
              std::vector<Result>* results) {
  renderer->renderTogether(frames);
  for (size_t i = 0; i < frames->size(); ++i) {
    (*results)[i].error = (*frames)[i].error ? messageOf((*frames)[i].error) : "";
  }
}

void expectSameFrames(const std::vector<Result>& expected, const std::vector<Result>& got,
                      const std::vector<CameraFrame>& frames) {
  ASSERT_EQ(got.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE("camera " + std::to_string(frames[i].index) + " of " + frames[i].robot);
    const Result &want = expected[i], &have = got[i];
    EXPECT_EQ(have.error, want.error);
    if (!want.error.empty()) continue;
    EXPECT_EQ(have.image.time_s, want.image.time_s);
    EXPECT_EQ(have.image.frame_id, want.image.frame_id);
    EXPECT_EQ(have.image.width, want.image.width);
    EXPECT_EQ(have.image.height, want.image.height);
    EXPECT_EQ(have.image.encoding, want.image.encoding);
    EXPECT_EQ(have.image.step, want.image.step);
    EXPECT_TRUE(have.image.data == want.image.data) << "the pixels differ";
    EXPECT_EQ(have.depth.time_s, want.depth.time_s);
    EXPECT_EQ(have.depth.frame_id, want.depth.frame_id);
    ASSERT_EQ(have.depth.depth_m.size(), want.depth.depth_m.size());
    EXPECT_EQ(std::memcmp(have.depth.depth_m.data(), want.depth.depth_m.data(),
                          want.depth.depth_m.size() * sizeof(float)), 0)
        << "the depths differ";
  }
}

/// Renders every camera one by one and together at the scene's time, then again 0.2 s
/// later with one Burger deleted and another spawned, and compares.
void expectTogetherIsOneByOne(unsigned threads) {
  const std::unique_ptr<Simulation> sim = cameraScene(threads);
  ASSERT_EQ(sim->threads(), threads);
  CameraRenderer alone(*sim), with_others(*sim);
  for (int round = 0; round < 2; ++round) {
    SCOPED_TRACE("round " + std::to_string(round) + " on " + std::to_string(threads) +
                 " threads");
    std::vector<Result> got;
    std::vector<CameraFrame> frames = everyCamera(*sim, &got);
    ASSERT_EQ(frames.size(), 7u);
    const std::vector<Result> expected = oneByOne(&alone, frames);
    together(&with_others, &frames, &got);
    expectSameFrames(expected, got, frames);
    // What is compared is worth comparing: the Burgers' frames are different pictures,
    // each in its own encoding, and the depth camera's depth image is there.
    std::set<std::vector<uint8_t>> pictures;
    for (const char* robot : {"tb3_0", "tb3_1", "tb3_2", "tb3_3"}) {
      pictures.insert(resultOf(robot, frames, expected).image.data);
    }
    EXPECT_EQ(pictures.size(), 4u);
    EXPECT_EQ(resultOf("tb3_1", frames, expected).image.encoding, "bgr8");
    EXPECT_EQ(resultOf("tb3_2", frames, expected).image.encoding, "mono8");
    EXPECT_EQ(resultOf("depth_bot", frames, expected).depth.depth_m.size(), 160u * 120u);
    const std::string& no_fov = resultOf("no_fov_bot", frames, expected).error;
    EXPECT_NE(no_fov.find("horizontal"), std::string::npos) << no_fov;
    // On: the robots drive, one leaves and another comes in its place.
    const double until = sim->timeS() + 0.2;
    while (sim->timeS() < until) sim->stepToNextReading(5);
    ASSERT_TRUE(sim->deleteRobot("tb3_3"));
    sim->spawnRobot("tb3_3", burgerWithFormat("R8G8B8"), poseAt(0, -1, M_PI / 2));
  }
}

}  // namespace

TEST(CamerasTogether, AreTheFramesRenderedOneByOneOnOneThread) { expectTogetherIsOneByOne(1); }

TEST(CamerasTogether, AreTheFramesRenderedOneByOneOnTwoThreads) { expectTogetherIsOneByOne(2); }

TEST(CamerasTogether, AFrameThatCannotBeRenderedSaysWhyAndTheOthersAreRendered) {
  const std::unique_ptr<Simulation> sim = cameraScene(2);
  std::vector<Result> got(7);
  std::vector<CameraFrame> frames = {
      {"tb3_0", 0, &got[0].image, nullptr, nullptr},
      {"no_fov_bot", 0, &got[1].image, nullptr, nullptr},   // LoadError: fov 0
      {"ghost", 0, &got[2].image, nullptr, nullptr},        // no such robot
      {"tb3_1", 0, &got[3].image, &got[3].depth, nullptr},  // not a depth camera
      {"tb3_2", 3, &got[4].image, nullptr, nullptr},        // no camera 3
      {"depth_bot", 0, &got[5].image, &got[5].depth, nullptr},
      {"wide_bot", 0, &got[6].image, nullptr, nullptr}};
  CameraRenderer alone(*sim), with_others(*sim);
  const std::vector<Result> expected = oneByOne(&alone, frames);
  together(&with_others, &frames, &got);
  expectSameFrames(expected, got, frames);
  const auto throws = [&frames](size_t i) {
    SCOPED_TRACE(frames[i].robot);
    EXPECT_TRUE(frames[i].error);
    std::rethrow_exception(frames[i].error);
  };
  EXPECT_THROW(throws(1), bullet_sim::LoadError);
  EXPECT_THROW(throws(2), std::out_of_range);
  EXPECT_THROW(throws(3), std::invalid_argument);
  EXPECT_THROW(throws(4), std::out_of_range);
  for (size_t i : {0, 5, 6}) {
    EXPECT_FALSE(frames[i].error) << frames[i].robot;
    EXPECT_FALSE(got[i].image.data.empty()) << frames[i].robot;
  }
  EXPECT_NE(got[1].error.find("horizontal_fov_rad = 0"), std::string::npos) << got[1].error;
  EXPECT_NE(got[2].error.find("ghost"), std::string::npos) << got[2].error;
}

TEST(CamerasTogether, ACameraNamedTwiceIsRefusedBeforeAnythingIsRendered) {
  const std::unique_ptr<Simulation> sim = cameraScene(2);
  ImageData first, second, other;
  std::vector<CameraFrame> frames = {{"tb3_0", 0, &first, nullptr, nullptr},
                                     {"tb3_1", 0, &other, nullptr, nullptr},
                                     {"tb3_0", 0, &second, nullptr, nullptr}};
  CameraRenderer renderer(*sim);
  EXPECT_THROW(renderer.renderTogether(&frames), std::invalid_argument);
  EXPECT_TRUE(first.data.empty());
  EXPECT_TRUE(other.data.empty());
  EXPECT_TRUE(second.data.empty());
}
