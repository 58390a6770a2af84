#include "description/sdf/sdf_surface.h"

#include <sstream>

#include "bullet_sim/errors.h"

namespace bullet_sim {
namespace {

/// The coefficient `name` of an <ode> friction element, if given. libsdformat refuses a
/// negative one itself, but takes "nan".
void readCoefficient(const sdf::ElementPtr& ode, const char* name, const std::string& where,
                     double* mu) {
  if (!ode->HasElement(name)) return;
  const double value = ode->Get<double>(name);
  if (!(value >= 0)) {
    std::ostringstream text;
    text << value;
    throw LoadError(where + ": <surface><friction><ode><" + name + ">: '" + text.str() +
                    "' is not a friction coefficient >= 0");
  }
  *mu = value;
}

}  // namespace

bool readOdeFriction(const sdf::Collision& collision, const std::string& where,
                     SurfaceParams* surface) {
  sdf::ElementPtr e = collision.Element();
  for (const char* name : {"surface", "friction", "ode"}) {
    if (!e || !e->HasElement(name)) return false;
    e = e->GetElement(name);
  }
  readCoefficient(e, "mu", where, &surface->mu1);
  readCoefficient(e, "mu2", where, &surface->mu2);
  return true;
}

}  // namespace bullet_sim
