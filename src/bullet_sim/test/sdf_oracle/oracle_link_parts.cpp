// What a link holds, as libsdformat reads it: geometries, materials, visuals, collisions
// and sensors.
#include "oracle_parts.h"

namespace bullet_sim_test {
namespace oracle {

using bullet_sim::Geometry;

bullet_sim::SdfGeometry geometryOf(const sdf::Geometry* geometry) {
  bullet_sim::SdfGeometry out;
  if (!geometry) return out;
  // The kind as written: libsdformat's tree holds the one child of <geometry> (its enum
  // has no value for some kinds, such as <image> or <polyline>).
  const sdf::ElementPtr kind = geometry->Element() ? geometry->Element()->GetFirstElement()
                                                   : sdf::ElementPtr();
  out.type = kind ? kind->GetName() : "empty";
  switch (geometry->Type()) {
    case sdf::GeometryType::BOX: {
      const ignition::math::Vector3d s = geometry->BoxShape()->Size();
      out.shape = Geometry::box(s.X(), s.Y(), s.Z());
      break;
    }
    case sdf::GeometryType::CYLINDER:
      out.shape = Geometry::cylinder(geometry->CylinderShape()->Radius(),
                                     geometry->CylinderShape()->Length());
      break;
    case sdf::GeometryType::SPHERE:
      out.shape = Geometry::sphere(geometry->SphereShape()->Radius());
      break;
    case sdf::GeometryType::PLANE: {
      const sdf::Plane& plane = *geometry->PlaneShape();
      out.shape = Geometry::plane(plane.Size().X(), plane.Size().Y(), toVector(plane.Normal()));
      break;
    }
    case sdf::GeometryType::MESH: {
      const sdf::Mesh& mesh = *geometry->MeshShape();
      out.shape = Geometry::mesh(mesh.Uri(), toVector(mesh.Scale()));
      out.submesh = mesh.Submesh();
      break;
    }
    default:
      break;
  }
  return out;
}

bullet_sim::SdfMaterial materialOf(const sdf::Material& material) {
  bullet_sim::SdfMaterial out;
  const sdf::ElementPtr element = material.Element();
  // libsdformat gives every colour a value; the file gave only those its tree holds.
  if (hasChild(element, "ambient")) out.ambient = toColour(material.Ambient());
  if (hasChild(element, "diffuse")) out.diffuse = toColour(material.Diffuse());
  if (hasChild(element, "specular")) out.specular = toColour(material.Specular());
  if (hasChild(element, "emissive")) out.emissive = toColour(material.Emissive());
  out.script_name = material.ScriptName();
  if (hasChild(element, "script")) {
    // sdf::Material keeps one URI; <script> may have several, all in the tree. A missing
    // one is there as "__default__", which sdf::Material reads as none.
    const sdf::ElementPtr script = element->GetElement("script");
    if (hasChild(script, "uri")) {
      for (sdf::ElementPtr u = script->GetElement("uri"); u; u = u->GetNextElement("uri")) {
        const std::string uri = u->Get<std::string>();
        if (uri != "__default__") out.script_uris.push_back(uri);
      }
    }
  }
  out.lighting = material.Lighting();
  return out;
}

bullet_sim::SdfVisual visualOf(const sdf::Visual& visual, Problems* problems) {
  bullet_sim::SdfVisual out;
  out.name = visual.Name();
  out.origin = originOf(visual.Element());
  out.T_link_visual =
      resolvedPose(visual.SemanticPose(), "", "visual '" + out.name + "'", problems);
  out.geometry = geometryOf(visual.Geom());
  if (visual.Material()) out.material = materialOf(*visual.Material());
  out.transparency = visual.Transparency();
  out.cast_shadows = visual.CastShadows();
  return out;
}

bullet_sim::SdfCollision collisionOf(const sdf::Collision& collision, Problems* problems) {
  bullet_sim::SdfCollision out;
  out.name = collision.Name();
  out.origin = originOf(collision.Element());
  out.T_link_collision =
      resolvedPose(collision.SemanticPose(), "", "collision '" + out.name + "'", problems);
  out.geometry = geometryOf(collision.Geom());
  // sdf::Surface has no friction accessor in libsdformat 12: its element tree has them.
  const sdf::ElementPtr element = collision.Element();
  if (hasChild(element, "surface") && hasChild(element->GetElement("surface"), "friction")) {
    const sdf::ElementPtr friction = element->GetElement("surface")->GetElement("friction");
    if (hasChild(friction, "ode")) {
      const sdf::ElementPtr ode = friction->GetElement("ode");
      bullet_sim::SdfFriction f;
      if (hasChild(ode, "mu")) f.mu = ode->Get<double>("mu");
      if (hasChild(ode, "mu2")) f.mu2 = ode->Get<double>("mu2");
      out.ode_friction = f;
    }
  }
  return out;
}

bullet_sim::SdfSensor sensorOf(const sdf::Sensor& sensor, Problems* problems) {
  bullet_sim::SdfSensor out;
  out.name = sensor.Name();
  const sdf::ElementPtr element = sensor.Element();
  // The type as written ("ray", "gpu_ray", ...): sdf::Sensor's enum merges some.
  out.type = element->Get<std::string>("type");
  out.origin = originOf(element);
  out.T_link_sensor =
      resolvedPose(sensor.SemanticPose(), "", "sensor '" + out.name + "'", problems);
  out.update_rate_hz = sensor.UpdateRate();
  out.always_on = element->Get<bool>("always_on");
  out.visualize = element->Get<bool>("visualize");
  out.topic = sensor.Topic();
  out.plugins = pluginsOf(element);
  return out;
}

}  // namespace oracle
}  // namespace bullet_sim_test
