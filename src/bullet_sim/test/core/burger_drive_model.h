#ifndef BULLET_SIM_TEST_BURGER_DRIVE_MODEL_H
#define BULLET_SIM_TEST_BURGER_DRIVE_MODEL_H

// The Burger's drive worked out by hand: the rim speeds libgazebo_ros_diff_drive.so gives its
// wheels (rimStaircase), and what the tyres' friction lets the body do with them, from its
// URDF and the friction model of Gazebo's ODE: a contact pushes along the ground with at most
// mu times its normal force, and takes the smaller mu of its two surfaces. Tyres and caster
// have mu 0.1 (turtlebot3_burger.gazebo.xacro), the ground more (1 in the tests' flat world;
// Gazebo's ground_plane has mu 100, mu2 50), so every contact of the robot has mu 0.1. The
// figures in the comments are the functions' values; README "Friction and drive" lists them
// against what the simulator does.

#include <algorithm>
#include <cmath>
#include <vector>

namespace bullet_sim_test {

// ---------------------------------------------------------------- the plugin's ramp ----

// The Burger's diff drive: updates at 30 Hz, ramps the rim speeds at wheelAcceleration
// 1 m/s^2, wheels 0.160 m apart. Its updates keep world-time phase, one at world time 0 and
// every 1/30 s after: a command given at a whole number of periods (0, 0.5 s, 1 s, ...) is
// taken with the next step.
constexpr double kDriveUpdateS = 1.0 / 30, kWheelAccelMps2 = 1.0, kSeparationM = 0.160;
/// Half the wheel separation (m).
constexpr double kHalfTrackM = kSeparationM / 2;
/// Below this rim-speed error the plugin jumps straight to the target (m/s).
constexpr double kSnapMps = 0.01;

/// The rim speeds a rim at rest is given at the plugin's updates until it reaches
/// `target_mps`: wheelAcceleration * Tu more at each, or the target once within kSnapMps.
inline std::vector<double> rimStaircase(double target_mps) {
  std::vector<double> steps;
  double rim_mps = 0;
  while (rim_mps < target_mps) {
    const double error = target_mps - rim_mps;
    rim_mps = error < kSnapMps ? target_mps
                               : rim_mps + std::min(error, kWheelAccelMps2 * kDriveUpdateS);
    steps.push_back(rim_mps);
  }
  return steps;
}

/// How much less a rim travels than one running at `target_mps` from the plugin's first
/// update on: it spends one period Tu on each step of the staircase below the target.
inline double rampLossM(double target_mps) {
  double loss_m = 0;
  for (const double rim_mps : rimStaircase(target_mps)) {
    loss_m += (target_mps - rim_mps) * kDriveUpdateS;
  }
  return loss_m;
}

// ----------------------------------------------------------------- the tyres' limits ----

constexpr double kMu = 0.1, kG = 9.8;
/// The URDF's masses: base_link 0.8257, base_scan 0.114, wheels 2 x 0.0285, mount plate 0.02,
/// camera 0.01, caster and poles 3 x 0.005, flag pole and flag 2 x 0.001.
constexpr double kBurgerMassKg = 1.04374;
/// Moment of inertia about the vertical through the axle's middle (kg m^2): the URDF's
/// inertias moved to that axis, base_link 0.00201, pole_link 0.00100 (its izz is 1e-3),
/// base_scan 0.00029, the wheels 2 x 0.00019, the rest 0.00012. The flag turns freely on its
/// joint and adds nothing.
constexpr double kBurgerYawInertiaKgm2 = 0.003802;

/// How the robot stands, seen from the side, relative to the point under its axle.
struct Stance {
  double pitch_rad;        ///< nose-up
  double caster_behind_m;  ///< the caster's ground contact behind the axle
  double com_behind_m;     ///< the centre of mass behind the axle
  double com_height_m;     ///< the centre of mass above the ground
};

/// Level (base_footprint on the ground) the axle is 0.033 m up; the caster box (0.030 long,
/// 0.009 high once caster_back_joint's roll lays it on its side) is centred 0.081 m behind
/// the axle and 0.006 m up, so its lower back edge, 0.096 m behind, is 1.5 mm above the
/// ground. The centre of mass (the URDF's inertials: base_link's mass at z 0.010, base_scan's
/// at x -0.032 z 0.182, ...) is at x -0.00411, z 0.0395: level, the robot tips back, and it
/// rests pitched about the axle until the caster's edge touches: 0.0157 rad (0.9 deg),
/// caster 0.0955 m behind, centre of mass 0.00421 m behind and 0.0394 m up.
inline Stance restingStance() {
  const double axle_z = 0.033;
  const double edge_x = -0.096, edge_z = 0.0015 - axle_z;  // caster edge, from the axle
  const double com_x = -0.00411, com_z = 0.0395 - axle_z;  // centre of mass, from the axle
  // Pitched nose-up by p about the axle, a point (x, z) goes to
  // (x cos p - z sin p, x sin p + z cos p); the edge touches when its z is -axle_z.
  const double r = std::hypot(edge_x, edge_z);
  const double p = std::asin(axle_z / r) - std::atan2(-edge_z, -edge_x);
  const double c = std::cos(p), s = std::sin(p);
  return {p, -(edge_x * c - edge_z * s), -(com_x * c - com_z * s), axle_z + com_x * s + com_z * c};
}

/// Forward at the tyres' limit: the tyres push with mu N_w, the caster slides and holds
/// back with mu N_c, so m a = mu (N_w - N_c). Moments about the centre of mass (h up, d behind
/// the axle, caster L behind) load the caster the more the harder the robot accelerates:
/// N_c L = m g d + m a h. Together: a = mu g (L - 2 d) / (L + 2 mu h) = 0.825 m/s^2, below
/// the plugin's ramp (wheelAcceleration 1 m/s^2): the body falls behind its rims and the
/// tyres slip until it has caught up.
inline double forwardLimitMps2() {
  const Stance st = restingStance();
  return kMu * kG * (st.caster_behind_m - 2 * st.com_behind_m) /
         (st.caster_behind_m + 2 * kMu * st.com_height_m);
}

/// Braking from forward motion: tyres and caster all slide against it, whatever the load on
/// each: a = mu g = 0.98 m/s^2, again below the ramp's 1 m/s^2.
inline double brakingLimitMps2() { return kMu * kG; }

/// Turning on the spot at the tyres' limit: each tyre pushes mu N_w / 2 at kHalfTrackM from
/// the middle, the caster, sliding sideways, holds back with mu N_c at L behind; its static
/// load share is d / L = 0.044. alpha = mu m g ((1 - d / L) kHalfTrackM - (d / L) L) / I =
/// 19.4 rad/s^2, above the ramp's 1 / 0.08 = 12.5 rad/s^2 on average, so the yaw rate follows
/// each of the ramp's steps within 0.021 s.
inline double spinLimitRadps2() {
  const Stance st = restingStance();
  const double caster_share = st.com_behind_m / st.caster_behind_m;
  return kMu * kBurgerMassKg * kG *
         ((1 - caster_share) * kHalfTrackM - caster_share * st.caster_behind_m) /
         kBurgerYawInertiaKgm2;
}

/// What a turn on the spot with rims ramping to `rim_mps` loses to the tyres' slip on top of
/// rampLossM: each step of the rims asks for dw = step / kHalfTrackM more yaw rate at once,
/// and the body gets there at spinLimitRadps2 (within 0.021 s, before the next step),
/// falling dw^2 / (2 alpha) behind.
inline double spinSlipLossRad(double rim_mps) {
  double loss_rad = 0, before_mps = 0;
  for (const double rim : rimStaircase(rim_mps)) {
    const double dw = (rim - before_mps) / kHalfTrackM;
    loss_rad += dw * dw / (2 * spinLimitRadps2());
    before_mps = rim;
  }
  return loss_rad;
}

}  // namespace bullet_sim_test

#endif  // BULLET_SIM_TEST_BURGER_DRIVE_MODEL_H
