#include "description/sdf/sdf_surface.h"

#include <cmath>
#include <sstream>

#include "bullet_sim/errors.h"

namespace bullet_sim {
namespace {

void takeCoefficient(const std::optional<double>& value, const char* name,
                     const std::string& where, double* mu) {
  if (!value) return;
  if (std::isnan(*value)) {
    std::ostringstream text;
    text << *value;
    throw LoadError(where + ": <surface><friction><ode><" + name + ">: '" + text.str() +
                    "' is not a friction coefficient");
  }
  *mu = frictionCoefficient(*value);
}

}  // namespace

bool readOdeFriction(const SdfCollision& collision, const std::string& where,
                     SurfaceParams* surface) {
  if (!collision.ode_friction) return false;
  takeCoefficient(collision.ode_friction->mu, "mu", where, &surface->mu1);
  takeCoefficient(collision.ode_friction->mu2, "mu2", where, &surface->mu2);
  return true;
}

}  // namespace bullet_sim
