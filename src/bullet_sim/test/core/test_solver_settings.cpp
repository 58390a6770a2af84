// Bullet's solver settings as set_physics_properties and the physics parameters change
// them: every world's btContactSolverInfo, those of homes made later and after a reset;
// values the solver cannot take are refused naming the field.
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "bullet_sim/simulation.h"
#include "physics/physics_worlds.h"

using namespace bullet_sim;

namespace {

void expectSolver(const btDiscreteDynamicsWorld& world, const SolverSettings& s) {
  const btContactSolverInfo& info = const_cast<btDiscreteDynamicsWorld&>(world).getSolverInfo();
  EXPECT_EQ(info.m_numIterations, s.iterations);
  EXPECT_DOUBLE_EQ(info.m_sor, s.sor);
  EXPECT_DOUBLE_EQ(info.m_erp, s.erp);
  EXPECT_DOUBLE_EQ(info.m_globalCfm, s.cfm);
}

}  // namespace

TEST(SolverSettings, DefaultsAreBulletsOwn) {
  PhysicsWorlds worlds(WorldSpec(), 1);
  const btContactSolverInfo bullet_default;
  expectSolver(*worlds.addHome(0), SolverSettings{bullet_default.m_numIterations,
                                                  bullet_default.m_sor, bullet_default.m_erp,
                                                  bullet_default.m_globalCfm});
}

TEST(SolverSettings, ReachEveryWorldAndLaterOnes) {
  PhysicsWorlds worlds(WorldSpec(), 1);
  btDiscreteDynamicsWorld* first = worlds.addHome(0);
  const SolverSettings s{30, 1.3, 0.4, 1e-5};
  worlds.setSolver(s);
  expectSolver(*first, s);
  expectSolver(*worlds.addHome(1), s);
}

TEST(SolverSettings, SimulationRefusesWhatTheSolverCannotTake) {
  Simulation sim{WorldSpec{}, SimConfig{}};
  const auto message = [&sim](const SolverSettings& s) {
    try {
      sim.setSolverSettings(s);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message({0, 1, 0.2, 0}), "solver iterations 0 must be >= 1");
  EXPECT_EQ(message({10, 0, 0.2, 0}), "solver SOR 0 must be > 0");
  EXPECT_EQ(message({10, 1, 1.5, 0}), "solver ERP 1.5 must be in [0, 1]");
  EXPECT_EQ(message({10, 1, 0.2, -1}), "solver CFM -1 must be >= 0");
  EXPECT_EQ(sim.solverSettings(), SolverSettings());
  const SolverSettings s{20, 1.2, 0.3, 0};
  EXPECT_EQ(message(s), "accepted");
  sim.reset();
  EXPECT_EQ(sim.solverSettings(), s);
}
