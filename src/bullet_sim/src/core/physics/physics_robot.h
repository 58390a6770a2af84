#ifndef BULLET_SIM_CORE_PHYSICS_ROBOT_H
#define BULLET_SIM_CORE_PHYSICS_ROBOT_H

#include <memory>
#include <string>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "bullet_sim/types.h"
#include "bullet_sim/world/entity_frames.h"
#include "description/robot_plan.h"
#include "physics/body_contacts.h"

namespace bullet_sim {

/// Per-body data Bullet's contact callback reads: the friction of each child
/// shape of the body's compound (links merged into one body keep their own mu). A body
/// of a single shape has no compound: its friction is the rigid body's.
struct BodyMaterial {
  int robot_id = -1;
  std::vector<double> child_friction;
};

/// The Bullet bodies and hinges of one robot, added to a dynamics world.
class PhysicsRobot {
 public:
  PhysicsRobot(btDiscreteDynamicsWorld* world, int robot_id, RobotPlan plan,
               const Eigen::Isometry3d& T_world_model);
  ~PhysicsRobot();
  PhysicsRobot(const PhysicsRobot&) = delete;
  PhysicsRobot& operator=(const PhysicsRobot&) = delete;

  /// Moves the robot rigidly so that its root link lands on T_world_root,
  /// keeping its joint configuration.
  void moveRoot(const Eigen::Isometry3d& T_world_root, const Twist3& twist);

  Eigen::Isometry3d linkPose(const std::string& link) const;
  /// World-frame velocity of a link's origin.
  Twist3 linkTwist(const std::string& link) const;
  bool hasLink(const std::string& link) const;
  /// How deep (m, >= 0) any body of the robot reaches into a static body (a wall, the
  /// ground), from the contacts of the last collision pass.
  double staticPenetrationM() const;

  /// Where something touches body `body` (an index into plan().bodies), from the last
  /// step of dt_s; BodyContact::part indexes that body's plan collisions.
  std::vector<BodyContact> contacts(size_t body, double dt_s) const;
  /// The index into plan().bodies of the body that is `object`, or -1.
  int bodyIndexOf(const btCollisionObject* object) const;

  const RobotPlan& plan() const { return plan_; }
  /// Index into plan().joints, or -1.
  int jointIndex(const std::string& name) const;
  double jointPosition(size_t joint) const { return joint_angles_[joint]; }
  double jointVelocity(size_t joint) const;
  /// Drives a joint at velocity_radps with at most max_torque_nm. The motor
  /// follows a reference angle that advances at that velocity, so a wheel told
  /// to stand still holds its angle instead of creeping under load.
  void setJointMotor(size_t joint, double velocity_radps, double max_torque_nm);
  /// Puts every hinge at angles_rad (one per plan().joints entry), keeping the root
  /// link's pose; every body ends at rest.
  void setJointPositions(const std::vector<double>& angles_rad);
  /// Adds a wrench (world axes) at the centre of mass of the body holding `link`, for the
  /// coming step.
  void applyLinkWrench(const std::string& link, const Wrench& wrench);
  /// Adds a torque about a hinge's axis (child turned positively, parent the other way),
  /// for the coming step.
  void applyJointEffort(size_t joint, double effort_nm);
  /// The wrench applyLinkWrench and applyJointEffort put on body `body` (index into
  /// plan().bodies) for the last step: world axes, torque about its centre of mass. Gravity,
  /// contacts, joint constraints, motors and damping are not in it.
  Wrench appliedWrench(size_t body) const;
  /// The wrench hinge `joint` passed to its child body in the last step: world axes, torque
  /// about the child body's centre of mass. Its constraint forces (from Bullet's joint
  /// feedback: the hinge, its limits and motor) plus the efforts applyJointEffort put on it.
  /// A sleeping body keeps the value of its last step awake.
  Wrench jointWrenchOnChild(size_t joint) const;
  /// World position of body `body`'s centre of mass.
  Eigen::Vector3d bodyCentreOfMass(size_t body) const;
  /// Makes the loads applied since the last call the ones appliedWrench and
  /// jointWrenchOnChild report; called after every physics step.
  void latchAppliedLoads();
  /// The body (index into plan().bodies) that holds `link`.
  size_t bodyOfLink(const std::string& link) const { return plan_.body_of_link.at(link); }
  /// New mass and principal moments of a body, about its centre of mass and axes.
  void setBodyMass(size_t body, double mass_kg, const Eigen::Vector3d& principal_inertia);
  /// Gravity on a body on or off (off: it floats, whatever the world's gravity).
  void setBodyGravity(size_t body, bool on);
  /// Viscous damping of a hinge: a torque -damping * rate between its bodies every step.
  void setJointDamping(size_t joint, double damping_nms_per_rad);
  /// A hinge's limits; lower > upper frees it.
  void setJointLimits(size_t joint, double lower_rad, double upper_rad);
  /// One of Bullet's hinge parameters (BT_CONSTRAINT_ERP, _CFM, _STOP_ERP, _STOP_CFM).
  void setJointParam(size_t joint, int param, double value);
  /// Gives every body the same velocity (world axes): `twist.linear` at its centre of
  /// mass, `twist.angular` about it, as Gazebo's Model::SetLinearVel and SetAngularVel set
  /// every link's; the hinges pull them together again in the next step.
  void setBodyVelocities(const Twist3& twist);
  /// Wakes every body of the robot (a sleeping robot is not simulated).
  void wake();
  /// Sets every motor's velocity target for the coming physics step of dt_s.
  void applyMotors(double dt_s);
  /// Tracks the hinge angles across +-pi; called after every physics step.
  void updateJointAngles();

  /// Takes the bodies and hinges out of the world they are in and adds them, in the order
  /// they were built, to `world` (contacts are made anew there); nothing if already there.
  void moveToWorld(btDiscreteDynamicsWorld* world);
  btDiscreteDynamicsWorld* world() const { return world_; }
  /// The bodies that collide (and that rays see), in build order.
  std::vector<const btRigidBody*> collidingBodies() const;
  /// The box around every colliding body's shape, and the largest speed (m/s) any point of
  /// a colliding body can have; false if none collides.
  bool bounds(btVector3* aabb_min, btVector3* aabb_max, double* speed_mps) const;

 private:
  struct Body {
    std::unique_ptr<btCollisionShape> shape;
    std::vector<std::unique_ptr<btCollisionShape>> children;
    std::unique_ptr<btRigidBody> rigid;
    BodyMaterial material;
    Eigen::Isometry3d T_com_root;  ///< inverse of the plan's T_root_com
  };
  void buildBody(const BodyPlan& plan, int robot_id);
  void addBody(btRigidBody* body, bool collides);
  bool ownsBody(const btCollisionObject* object) const;
  /// Puts every body where the zero-joint configuration at T_world_model puts it.
  void placeBodies(const Eigen::Isometry3d& T_world_model);
  Eigen::Isometry3d T_world_body(size_t body) const;
  btVector3 jointAxisInWorld(size_t joint) const;

  btDiscreteDynamicsWorld* world_;
  RobotPlan plan_;
  std::vector<Body> bodies_;
  std::vector<std::unique_ptr<btHingeConstraint>> hinges_;
  /// Bullet's feedback of each hinge (sized once: the hinges point into it).
  std::vector<btJointFeedback> feedback_;
  /// Loads applied for the coming step and for the last one: per body, per hinge.
  std::vector<Wrench> body_loads_pending_, body_loads_last_;
  std::vector<double> effort_pending_nm_, effort_last_nm_;
  std::vector<double> joint_angles_, last_raw_angles_;
  struct Motor {
    bool enabled = false;
    double velocity_radps = 0, max_torque_nm = 0;
    double reference_rad = 0;  ///< angle the joint should be at
  };
  std::vector<Motor> motors_;
  std::vector<double> damping_;  ///< per hinge, N m s / rad
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_PHYSICS_ROBOT_H
