// spawn_model's command line, as Gazebo users type it, with the messages of Python's
// argparse (which read it before spawn_model was a C++ program).
#include "../src/spawn_model/model_text.h"
#include "../src/spawn_model/rpy.h"
#include "../src/spawn_model/spawn_args.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace gazebo_ros_spawn;

namespace {

std::string usageErrorOf(const std::vector<std::string>& argv) {
  try {
    parseSpawnArgs(argv);
  } catch (const UsageError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no usage error";
  return "";
}

void expectUsageError(const std::vector<std::string>& argv, const std::string& error_line) {
  EXPECT_EQ(usageErrorOf(argv), usage() + "spawn_model: error: " + error_line);
}

}  // namespace

TEST(SpawnArgs, TheTrainingsCommandLine) {
  const SpawnArgs args = parseSpawnArgs({"-urdf", "-model", "turtlebot3_burger", "-x", "0.0",
                                         "-y", "0.0", "-z", "0.0", "-R", "0", "-P", "0", "-Y",
                                         "1.5675", "-param", "robot_description"});
  EXPECT_TRUE(args.urdf);
  EXPECT_FALSE(args.sdf);
  EXPECT_TRUE(args.has_param);
  EXPECT_EQ(args.param, "robot_description");
  EXPECT_EQ(args.model, "turtlebot3_burger");
  EXPECT_EQ(std::vector<double>({args.x, args.y, args.z, args.R, args.P, args.Y}),
            std::vector<double>({0, 0, 0, 0, 0, 1.5675}));
  EXPECT_EQ(args.gazebo_namespace, "/gazebo");
  EXPECT_EQ(args.reference_frame, "");
  EXPECT_FALSE(args.has_robot_namespace);
  EXPECT_FALSE(args.unpause || args.bond || args.package_to_model);
}

TEST(SpawnArgs, JointsNamespacesAndFlags) {
  const SpawnArgs args = parseSpawnArgs(
      {"-sdf", "-file", "m.sdf", "-model", "arm", "-J", "shoulder", "0.5", "-J", "elbow",
       "-1.25", "-unpause", "-wait", "table", "-robot_namespace", "tb3_1", "-reference_frame",
       "table", "-gazebo_namespace", "/sim", "__name:=spawner", "-b", "-package_to_model"});
  ASSERT_EQ(args.joints.size(), 2u);
  EXPECT_EQ(args.joints[0], std::make_pair(std::string("shoulder"), 0.5));
  EXPECT_EQ(args.joints[1], std::make_pair(std::string("elbow"), -1.25));
  EXPECT_TRUE(args.sdf && args.has_file && args.unpause && args.bond && args.package_to_model);
  EXPECT_EQ(args.file, "m.sdf");
  EXPECT_EQ(args.wait, "table");
  EXPECT_TRUE(args.has_robot_namespace);
  EXPECT_EQ(args.robot_namespace, "tb3_1");
  EXPECT_EQ(args.reference_frame, "table");
  EXPECT_EQ(args.gazebo_namespace, "/sim");
}

TEST(SpawnArgs, ArgparseSpellingsOfValues) {
  // Unique prefixes, "=" and attached values, negative numbers and Python's float forms.
  SpawnArgs args = parseSpawnArgs({"-ur", "-para", "p", "-mo", "m", "-x=3", "-y-2", "-z", "-.5",
                                   "-R", " 1_000 ", "-P", "1e-3", "-Y", "-7"});
  EXPECT_TRUE(args.urdf);
  EXPECT_EQ(args.param, "p");
  EXPECT_EQ(args.model, "m");
  EXPECT_EQ(std::vector<double>({args.x, args.y, args.z, args.R, args.P, args.Y}),
            std::vector<double>({3, -2, -0.5, 1000, 0.001, -7}));
  args = parseSpawnArgs({"-sdf", "-st", "-model", "m", "-x", "5", "-x1.5"});
  EXPECT_TRUE(args.sdf && args.from_stdin);
  EXPECT_EQ(args.x, 1.5);  // the last one given
}

TEST(SpawnArgs, HelpIsRequested) {
  EXPECT_THROW(parseSpawnArgs({"-urdf", "-h"}), HelpRequested);
  EXPECT_THROW(parseSpawnArgs({"--he"}), HelpRequested);
  EXPECT_EQ(help().rfind(usage(), 0), 0u);
  EXPECT_NE(help().find("  -J JOINT_NAME JOINT_POSITION\n"), std::string::npos);
}

TEST(SpawnArgs, WrongArgumentsGiveTheUsage) {
  expectUsageError({"-param", "robot_description", "-model", "m"},
                   "one of the arguments -urdf -sdf is required");
  expectUsageError({"-urdf", "-model", "m"},
                   "one of the arguments -file -param -database -stdin is required");
  expectUsageError({"-urdf", "-sdf", "-param", "p", "-model", "m"},
                   "argument -sdf: not allowed with argument -urdf");
  expectUsageError({"-urdf", "-param", "p"}, "the following arguments are required: -model");
  expectUsageError({"-urdf", "-param", "p", "-model", "m", "-x", "left"},
                   "argument -x: invalid float value: 'left'");
  expectUsageError({"-urdf", "-param", "p", "-model", "m", "-x", "it's"},
                   "argument -x: invalid float value: \"it's\"");
  expectUsageError({"-urdf", "-param", "p", "-model", "m", "-x", "0x10"},
                   "argument -x: invalid float value: '0x10'");
  expectUsageError({"-urdf", "-param", "p", "-model", "m", "-speed", "3"},
                   "unrecognized arguments: -speed 3");
  expectUsageError({"-u", "-param", "p", "-model", "m"},
                   "ambiguous option: -u could match -urdf, -unpause");
  expectUsageError({"-urdf", "-param", "p", "-model"}, "argument -model: expected one argument");
  expectUsageError({"-urdf", "-param", "p", "-model", "m", "-J", "a"},
                   "argument -J: expected 2 arguments");
  expectUsageError({"-urdf", "-param", "p", "-model", "m", "-Y", "-1e-3"},
                   "argument -Y: expected one argument");
  expectUsageError({"-urdf", "-param", "p", "-model", "m", "-bogus"},
                   "argument -b: ignored explicit argument 'ogus'");
  expectUsageError({"-urdf=1", "-param", "p", "-model", "m"},
                   "argument -urdf: ignored explicit argument '1'");
  expectUsageError({"-urdf", "-param", "p", "-model", "m", "-mod=m"},
                   "unrecognized arguments: -mod=m");
  expectUsageError({"-urdf", "-param", "p", "-model", "m", "-stdin=x"},
                   "argument -x: expected one argument");  // -stdin, then -x with no value
  expectUsageError({"-urdf", "-param", "p", "-model", "m", "--", "x"},
                   "unrecognized arguments: -- x");
  expectUsageError({"-urdf", "-param", "p", "-model", "--", "m"},
                   "argument -model: expected one argument");
}

TEST(SpawnArgs, NonFiniteValuesAreRefused) {
  try {
    parseSpawnArgs({"-sdf", "-stdin", "-model", "m", "-Y", "InFinity"});
    FAIL() << "InFinity accepted";
  } catch (const UsageError& error) {
    EXPECT_STREQ(error.what(), "spawn_model: error: -Y inf is not a finite number");
  }
  try {
    parseSpawnArgs({"-urdf", "-param", "p", "-model", "m", "-y", "nan"});
    FAIL() << "nan accepted";
  } catch (const UsageError& error) {
    EXPECT_STREQ(error.what(), "spawn_model: error: -y nan is not a finite number");
  }
  try {
    parseSpawnArgs({"-urdf", "-param", "p", "-model", "m", "-J", "wheel", "x"});
    FAIL() << "a joint position 'x' accepted";
  } catch (const UsageError& error) {
    EXPECT_STREQ(error.what(), "spawn_model: error: -J wheel x: the position is not a number");
  }
  try {
    parseSpawnArgs({"-urdf", "-param", "p", "-model", "m", "-J", "wheel", "inf"});
    FAIL() << "a joint position inf accepted";
  } catch (const UsageError& error) {
    EXPECT_STREQ(error.what(), "spawn_model: error: -J wheel inf is not finite");
  }
}

TEST(SpawnArgs, TheModelDatabaseIsOutOfReach) {
  try {
    parseSpawnArgs({"-sdf", "-database", "coke_can", "-model", "can"});
    FAIL() << "-database accepted";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("-database coke_can: Gazebo's online model database"),
              std::string::npos);
  }
}

TEST(SpawnArgs, QuaternionFromRpy) {
  // yaw only: rotation of psi about z -> (0, 0, sin(psi/2), cos(psi/2))
  Quaternion q = quaternionFromRpy(0, 0, 1.5675);
  EXPECT_NEAR(q.z, std::sin(1.5675 / 2), 1e-12);
  EXPECT_NEAR(q.w, std::cos(1.5675 / 2), 1e-12);
  EXPECT_NEAR(q.x, 0, 1e-12);
  EXPECT_NEAR(q.y, 0, 1e-12);
  // roll of pi/2 then yaw of pi/2 (fixed axes): the body x axis ends on world y and the
  // body y axis on world z; checked through the rotation matrix of the quaternion.
  q = quaternionFromRpy(M_PI / 2, 0, M_PI / 2);
  const double x = q.x, y = q.y, z = q.z, w = q.w;
  const double got[6] = {1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y),
                         2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)};
  const double want[6] = {0, 1, 0, 0, 0, 1};
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(got[i], want[i], 1e-12) << i;
}

TEST(ModelText, Checks) {
  EXPECT_THROW(checkXml("  ", "parameter robot_description"), ModelError);
  try {
    checkXml("<robot name=\"r\">", "file a.urdf");
    FAIL() << "unclosed element accepted";
  } catch (const ModelError& error) {
    EXPECT_EQ(std::string(error.what()).rfind("file a.urdf is not valid XML: ", 0), 0u);
  }
  try {
    readModelFile("/nonexistent.urdf");
    FAIL() << "a missing file read";
  } catch (const ModelError& error) {
    EXPECT_STREQ(error.what(), "specified file /nonexistent.urdf does not exist");
  }
  EXPECT_THROW(readModelFile("/"), ModelError);
  EXPECT_EQ(packageToModel("<mesh filename=\"package://p/m.stl\"/><m f=\"package://q\"/>"),
            "<mesh filename=\"model://p/m.stl\"/><m f=\"model://q\"/>");
  EXPECT_NO_THROW(checkXml("<robot name=\"r\"/>", "file a.urdf"));
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
