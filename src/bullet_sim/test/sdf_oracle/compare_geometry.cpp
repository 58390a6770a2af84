// Geometries and materials field by field.
#include "dom_compare.h"

namespace bullet_sim_test {

using namespace bullet_sim;

namespace {

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

}  // namespace

void compareGeometries(DomComparer* cmp, const SdfGeometry& ours, const SdfGeometry& theirs) {
  cmp->text("type", ours.type, theirs.type);
  cmp->optional("shape", ours.shape, theirs.shape, [cmp](const Geometry& a, const Geometry& b) {
    cmp->text("kind", sim_render::kindName(a.kind), sim_render::kindName(b.kind));
    cmp->vector("size", a.size, b.size);
    cmp->vector("normal", a.normal, b.normal);
    cmp->text("mesh_uri", a.mesh_uri, b.mesh_uri);
  });
  cmp->text("submesh", ours.submesh, theirs.submesh);
}

void compareMaterials(DomComparer* cmp, const SdfMaterial& ours, const SdfMaterial& theirs) {
  const auto colour = [cmp](const char* field, const std::optional<Eigen::Vector4f>& a,
                            const std::optional<Eigen::Vector4f>& b) {
    cmp->optional(field, a, b, [cmp](const Eigen::Vector4f& x, const Eigen::Vector4f& y) {
      cmp->colour("", x, y);
    });
  };
  colour("ambient", ours.ambient, theirs.ambient);
  colour("diffuse", ours.diffuse, theirs.diffuse);
  colour("specular", ours.specular, theirs.specular);
  colour("emissive", ours.emissive, theirs.emissive);
  cmp->text("script_name", ours.script_name, theirs.script_name);
  cmp->text("script_uris", joined(ours.script_uris), joined(theirs.script_uris));
  cmp->flag("lighting", ours.lighting, theirs.lighting);
}

}  // namespace bullet_sim_test
