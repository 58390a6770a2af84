// planRobot merges links joined by fixed joints into one rigid body: the masses add, the
// centre of mass is their weighted mean, and the inertia about it follows from each link's
// own inertia (turned into the body's frame) by the parallel-axis theorem, worked out here
// by hand.
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "bullet_sim/description/robot_spec.h"
#include "description/robot_plan.h"

using namespace bullet_sim;

namespace {

/// Link a, and link b on a fixed joint at `joint_origin` (an <origin> element's attributes);
/// each link's centre of mass at its origin.
std::string twoFixedLinks(const std::string& a_inertia, const std::string& b_inertia,
                          double b_mass_kg, const std::string& joint_origin) {
  return R"(<robot name="pair">
    <link name="a"><inertial><mass value="2"/><inertia )" + a_inertia + R"(/></inertial></link>
    <joint name="weld" type="fixed"><parent link="a"/><child link="b"/>
      <origin )" + joint_origin + R"(/></joint>
    <link name="b"><inertial><mass value=")" + std::to_string(b_mass_kg) + R"("/>
      <inertia )" + b_inertia + R"(/></inertial></link>
  </robot>)";
}

}  // namespace

TEST(Inertia, FixedLinksAddByTheParallelAxisTheorem) {
  // a: 2 kg, diag(0.1, 0.2, 0.3). b: 1 kg, diag(0.01, 0.02, 0.03) in its own frame, 0.3 m
  // along a's x and turned 90 degrees about z, so in a's frame it is diag(0.02, 0.01, 0.03).
  const RobotSpec spec = parseRobot(
      twoFixedLinks(R"(ixx="0.1" ixy="0" ixz="0" iyy="0.2" iyz="0" izz="0.3")",
                    R"(ixx="0.01" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.03")", 1.0,
                    R"(xyz="0.3 0 0" rpy="0 0 1.5707963267948966")"),
      "pair.urdf");
  const RobotPlan plan = planRobot(spec);
  ASSERT_EQ(plan.bodies.size(), 1u);
  const BodyPlan& body = plan.bodies[0];
  EXPECT_DOUBLE_EQ(body.mass_kg, 3.0);
  // Centre of mass: (2 * 0 + 1 * 0.3) / 3 = 0.1 along x. a sits 0.1 m from it, b 0.2 m,
  // both along x: m d^2 adds 2 * 0.01 = 0.02 and 1 * 0.04 = 0.04 about y and z, nothing
  // about x. Ixx = 0.1 + 0.02 = 0.12; Iyy = 0.2 + 0.02 + 0.01 + 0.04 = 0.27;
  // Izz = 0.3 + 0.02 + 0.03 + 0.04 = 0.39. No product of inertia: the link axes are principal.
  EXPECT_TRUE(body.T_root_com.translation().isApprox(Eigen::Vector3d(0.1, 0, 0), 1e-12));
  EXPECT_TRUE(body.T_root_com.linear().isApprox(Eigen::Matrix3d::Identity(), 1e-9));
  EXPECT_NEAR(body.principal_inertia.x(), 0.12, 1e-6);
  EXPECT_NEAR(body.principal_inertia.y(), 0.27, 1e-6);
  EXPECT_NEAR(body.principal_inertia.z(), 0.39, 1e-6);
}

TEST(Inertia, TwoMassesOnADiagonalHavePrincipalAxesAlongAndAcrossIt) {
  // Two 2 kg links, each isotropic 0.001, 0.2 m apart along the diagonal (1, 1, 0).
  std::ostringstream b_origin;
  b_origin << std::setprecision(17) << "xyz=\"" << 0.2 / std::sqrt(2.0) << " "
           << 0.2 / std::sqrt(2.0) << " 0\"";
  const RobotSpec spec = parseRobot(
      twoFixedLinks(R"(ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001")",
                    R"(ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001")", 2.0,
                    b_origin.str()),
      "pair.urdf");
  const RobotPlan plan = planRobot(spec);
  ASSERT_EQ(plan.bodies.size(), 1u);
  const BodyPlan& body = plan.bodies[0];
  EXPECT_DOUBLE_EQ(body.mass_kg, 4.0);
  const Eigen::Vector3d along = Eigen::Vector3d(1, 1, 0).normalized();
  EXPECT_TRUE(body.T_root_com.translation().isApprox(0.1 * along, 1e-9));
  // Each mass is d = 0.1 m from the centre, on the diagonal. About the diagonal: only the
  // links' own 2 * 0.001 = 0.002. About the two axes across it: 0.002 + 2 * 2 * 0.1^2 =
  // 0.042. The solver lists them smallest first.
  EXPECT_NEAR(body.principal_inertia.x(), 0.002, 1e-6);
  EXPECT_NEAR(body.principal_inertia.y(), 0.042, 1e-6);
  EXPECT_NEAR(body.principal_inertia.z(), 0.042, 1e-6);
  const Eigen::Vector3d first_axis = body.T_root_com.linear().col(0);
  EXPECT_NEAR(std::fabs(first_axis.dot(along)), 1.0, 1e-6);
  EXPECT_NEAR(body.T_root_com.linear().determinant(), 1.0, 1e-9);  // a rotation
}

TEST(Inertia, AHingeKeepsTheLinksApartAndALinkWithoutMassGetsTheFloor) {
  const RobotSpec spec = parseRobot(R"(<robot name="hinged">
    <link name="a"><inertial><mass value="2"/>
      <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial></link>
    <joint name="pin" type="continuous"><parent link="a"/><child link="b"/>
      <origin xyz="0.5 0 0"/><axis xyz="0 0 1"/></joint>
    <link name="b"/>
  </robot>)",
                                    "hinged.urdf");
  const RobotPlan plan = planRobot(spec);
  ASSERT_EQ(plan.bodies.size(), 2u);
  EXPECT_DOUBLE_EQ(plan.bodies[0].mass_kg, 2.0);  // b's side of the hinge is not added
  EXPECT_TRUE(plan.bodies[0].T_root_com.translation().isZero(1e-12));
  // b has no inertial: Bullet would take a massless body as static, so it gets 1 g.
  EXPECT_DOUBLE_EQ(plan.bodies[1].mass_kg, 1e-3);
  ASSERT_EQ(plan.warnings.size(), 1u);
  EXPECT_EQ(plan.warnings[0], "body of link 'b' has no mass: given 0.001000 kg");
}
