// The Burger driven at its tyres' limits (mu 0.1 on tyres and caster) on flat ground: how
// fast it gets going, stops and turns, against the hand figures of burger_drive_model.h (the
// friction model of Gazebo's ODE with the same values). Each robot first settles on wheels
// and caster for 1 s; world time 1 s is a drive update, so a command is taken at once.
#include <cmath>

#include <gtest/gtest.h>

#include "bullet_sim/simulation.h"
#include "burger.h"
#include "burger_drive_model.h"

using namespace bullet_sim;
using namespace bullet_sim_test;

namespace {

constexpr double kDt = 0.001;
/// Bullet's tyres, holding the sliding caster's drag, creep: the body runs up to this much
/// slower than its rims say, straight ahead (m/s) or turning on the spot (rad/s); measured
/// 0.0002-0.0003 m/s and 0.003-0.0045 rad/s at every speed. ODE's model would hold them.
constexpr double kCreepMps = 0.0004, kSpinCreepRadps = 0.005;

void run(Simulation* sim, double seconds) {
  const long steps = std::lround(seconds / kDt);
  for (long i = 0; i < steps; ++i) sim->step();
}

/// A Burger (with its `spec`) settled on the flat ground.
class SettledBurger {
 public:
  explicit SettledBurger(const RobotSpec& spec = burgerSpec()) : sim_(flatWorld(), SimConfig()) {
    sim_.spawnRobot("burger", spec, Pose3());
    run(&sim_, 1.0);
  }
  Simulation& sim() { return sim_; }
  Pose3 pose() const { return sim_.modelPose("burger"); }
  /// Speed along the robot's heading (m/s).
  double forwardMps() const {
    return sim_.modelTwist("burger").linear.dot(pose().orientation * Eigen::Vector3d::UnitX());
  }

 private:
  Simulation sim_;
};

}  // namespace

TEST(Traction, GetsGoingAsFastAsItsTyresGripThenRunsAtTheCommand) {
  SettledBurger burger;
  const Pose3 start = burger.pose();
  const double v = 0.2, a = forwardLimitMps2();  // 0.825 m/s^2
  burger.sim().setCmdVel("burger", v, 0);
  run(&burger.sim(), 0.15);
  // After five updates (at 0, Tu, ..., 4 Tu) the rims run at 0.167 m/s; the body, pushed at
  // the tyres' limit from the first, at a * 0.15 s = 0.124 m/s (with tyres that gripped it
  // would keep up with its rims). Coulomb friction allows no more; Bullet gives 99.5 % of it.
  EXPECT_LE(burger.forwardMps(), a * 0.15 + 0.001);
  EXPECT_GE(burger.forwardMps(), 0.97 * a * 0.15);
  run(&burger.sim(), 4.85);
  // It reaches v after v / a = 0.242 s, v^2 / (2 a) = 0.0242 m behind a body that ran at v
  // from the command: 0.9758 m in 5 s. From then on the tyres push the caster along (it
  // slides: mu N_c = 0.045 N), and creep.
  const Pose3 end = burger.pose();
  const double hand_m = v * 5.0 - v * v / (2 * a);
  EXPECT_LE((end.position - start.position).norm(), hand_m + 0.0005);
  EXPECT_GE((end.position - start.position).norm(), hand_m - kCreepMps * 5.0);
  EXPECT_NEAR(burger.forwardMps(), v, kCreepMps);
  // Nothing holds the heading while both tyres slip alike (a slipping tyre pushes along its
  // slip, whichever way the robot points). With ODE's model a symmetric robot would not turn;
  // Bullet's contacts turn the Burger by about 0.01 rad in the 0.24 s of slip, one way or the
  // other (the sign changes with the last digits of the wheel joints' rpy). Within 0.015 rad.
  EXPECT_LT(std::fabs(std::remainder(yawOf(end.orientation) - yawOf(start.orientation), 2 * M_PI)),
            0.015);
  EXPECT_NEAR(end.position.z(), 0.0, 0.001);  // on its wheels: base_footprint on the ground
}

TEST(Traction, StopsNoShorterThanItsTyresAllow) {
  SettledBurger burger;
  const double v = 0.2;
  burger.sim().setCmdVel("burger", v, 0);
  run(&burger.sim(), 1.0);  // at v after 0.242 s; world time 2 s is a drive update
  ASSERT_NEAR(burger.forwardMps(), v, kCreepMps);
  const Pose3 moving = burger.pose();
  burger.sim().setCmdVel("burger", 0, 0);
  run(&burger.sim(), 1.0);
  // The rims step down by 0.033 m/s at each update, faster than mu g = 0.98 m/s^2 slows the
  // body (0.0327 m/s a period): tyres and caster all slide against the motion until it
  // stops, v^2 / (2 mu g) = 0.0204 m on. Friction is all that brakes it, so it cannot stop
  // shorter; Bullet's contacts brake at about 96 % of mu g here (0.0211 m): within 5 %.
  const double hand_m = v * v / (2 * brakingLimitMps2());
  const double stopped_m = (burger.pose().position - moving.position).norm();
  EXPECT_GE(stopped_m, hand_m - 0.0002);
  EXPECT_LE(stopped_m, 1.05 * hand_m);
  EXPECT_LT(std::fabs(burger.forwardMps()), 0.001);
}

TEST(Traction, TurnsOnTheSpotAsFarAsTheRampAndTheTyresLetIt) {
  SettledBurger burger;
  const Eigen::Vector3d start = burger.pose().position;
  const double w = 1.0, t = M_PI;
  burger.sim().setCmdVel("burger", 0, w);
  const double heading = turnFor(&burger.sim(), "burger", t);
  // Each rim ramps to w * 0.08 = 0.08 m/s in the staircase 0.033, 0.067, 0.08, losing
  // Tu * (0.047 + 0.013) = 0.0020 m: the heading falls 2 * 0.0020 / 0.16 = 0.025 rad short of
  // w t = pi. Each step asks for 0.417, 0.417 and 0.167 rad/s more at once, which the tyres
  // give at 19.4 rad/s^2: 0.0097 rad more: 3.107 rad. Then the tyres grip, and creep while
  // they drag the caster round 0.0955 m behind the axle.
  const double rim_mps = w * kHalfTrackM;
  const double hand_rad = w * t - 2 * rampLossM(rim_mps) / kSeparationM - spinSlipLossRad(rim_mps);
  EXPECT_LE(heading, hand_rad + 0.001);
  EXPECT_GE(heading, hand_rad - kSpinCreepRadps * t);
  // In kinematics the axle's middle stays put; the caster's drag lets it wander, by under
  // 2 cm in this half turn.
  EXPECT_LT((burger.pose().position - start).head<2>().norm(), 0.02);
}

TEST(Traction, SpinsAtTheBurgersTopTurnRate) {
  SettledBurger burger;
  const double w = 2.84;  // the real Burger's limit
  burger.sim().setCmdVel("burger", 0, w);
  const double first_rad = turnFor(&burger.sim(), "burger", 0.25);
  // The rims (w * 0.08 = 0.2272 m/s) get there at the 7th update, 6 Tu = 0.2 s (six steps
  // of 0.033 m/s, then 0.027); the body follows each step within 0.021 s: at 0.25 s it turns
  // at w, less the tyres' creep.
  EXPECT_NEAR(burger.sim().modelTwist("burger").angular.z(), w, kSpinCreepRadps);
  const double heading = first_rad + turnFor(&burger.sim(), "burger", 1.75);
  // In 2 s: w t = 5.68 rad, less the ramp's 2 * 0.0221 / 0.16 = 0.276 rad, less the slip
  // while following its steps (0.417 rad/s six times, 0.34 once, at 19.4 rad/s^2):
  // 0.030 rad: 5.374 rad; less the creep, and the slip may take a fifth more than that
  // (the tyres pivot the robot about its axle's middle only on average).
  const double rim_mps = w * kHalfTrackM;
  const double hand_rad =
      w * 2.0 - 2 * rampLossM(rim_mps) / kSeparationM - spinSlipLossRad(rim_mps);
  EXPECT_LE(heading, hand_rad + 0.002);
  EXPECT_GE(heading, hand_rad - kSpinCreepRadps * 1.75 - 0.2 * spinSlipLossRad(rim_mps));
}

TEST(EncoderOdometry, PartsFromTheTruePoseByWhatTheTyresSlip) {
  RobotSpec spec = burgerSpec();
  spec.diff_drive->odometry_source = OdomSource::Encoder;
  SettledBurger burger(spec);
  const Pose3 start = burger.pose();
  const double v = 0.2, w = 0.4;
  burger.sim().setCmdVel("burger", v, 0);
  run(&burger.sim(), 1.0);
  // The encoder counts what the rims turned: v t less the ramp, Tu * (0.167 + 0.133 + 0.1 +
  // 0.067 + 0.033) = 0.0167 m: 0.1833 m. The body, slipping until it reached v, went
  // v t - v^2 / (2 a) = 0.1758 m: the encoder runs 7.6 mm ahead of it (and the tyres' creep,
  // up to 0.3 mm in the 0.76 s at v).
  const OdometryData straight = burger.sim().readOdometry("burger");
  const double driven_m = (burger.pose().position - start.position).norm();
  EXPECT_NEAR(straight.pose.position.x(), v * 1.0 - rampLossM(v), 0.0005);
  EXPECT_NEAR(straight.pose.position.x() - driven_m, v * v / (2 * forwardLimitMps2()) - rampLossM(v),
              0.0005);
  const double true_yaw = yawOf(burger.pose().orientation);
  const double encoder_yaw = yawOf(straight.pose.orientation);
  burger.sim().setCmdVel("burger", v, w);
  run(&burger.sim(), 2.0);
  // Into an arc at speed: the next update turns the rims to v -+ w * 0.08 = 0.168 and
  // 0.232 m/s at once (each within one step of the ramp), so the encoder turns at w from
  // then on: w t = 0.8 rad. The body has to be brought to w by the tyres slipping opposite
  // ways, at 19.4 rad/s^2 (0.021 s), and turns w^2 / (2 alpha) = 0.0041 rad less (and
  // creeps in the arc, about 0.001 rad/s).
  const OdometryData arc = burger.sim().readOdometry("burger");
  const double encoder_turn = std::remainder(yawOf(arc.pose.orientation) - encoder_yaw, 2 * M_PI);
  const double true_turn = std::remainder(yawOf(burger.pose().orientation) - true_yaw, 2 * M_PI);
  EXPECT_NEAR(encoder_turn, w * 2.0, 0.001);
  EXPECT_NEAR(encoder_turn - true_turn, w * w / (2 * spinLimitRadps2()), 0.002);
  // The encoder's own rates are the command's.
  EXPECT_NEAR(arc.twist_in_child.linear.x(), v, 0.002);
  EXPECT_NEAR(arc.twist_in_child.angular.z(), w, 0.005);
}
