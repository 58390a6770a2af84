#ifndef BULLET_SIM_TEST_DOM_COMPARE_H
#define BULLET_SIM_TEST_DOM_COMPARE_H

#include <map>
#include <string>
#include <vector>

#include "description/sdf/sdf_dom.h"
#include "dom_comparer.h"
#include "sdformat_oracle.h"

namespace bullet_sim_test {

/// The canonical link the oracle picked per model field path (OracleResult).
using CanonicalLinks = std::map<std::string, OracleCanonicalLink>;

/// Every field of two readings of one file, into `cmp`; each model's canonicalLink()
/// of `ours` against `canonical` at the model's field path.
void compareDocuments(DomComparer* cmp, const bullet_sim::SdfDocument& ours,
                      const bullet_sim::SdfDocument& theirs, const CanonicalLinks& canonical);

void compareModels(DomComparer* cmp, const bullet_sim::SdfModel& ours,
                   const bullet_sim::SdfModel& theirs, const std::string& field_path,
                   const CanonicalLinks& canonical);
void compareLights(DomComparer* cmp, const bullet_sim::SdfLight& ours,
                   const bullet_sim::SdfLight& theirs);
/// Name, file and parameters (pluginParameters) of each plugin of `field`.
void comparePlugins(DomComparer* cmp, const std::string& field,
                    const std::vector<bullet_sim::SdfPlugin>& ours,
                    const std::vector<bullet_sim::SdfPlugin>& theirs);
void compareGeometries(DomComparer* cmp, const bullet_sim::SdfGeometry& ours,
                       const bullet_sim::SdfGeometry& theirs);
void compareMaterials(DomComparer* cmp, const bullet_sim::SdfMaterial& ours,
                      const bullet_sim::SdfMaterial& theirs);

}  // namespace bullet_sim_test

#endif  // BULLET_SIM_TEST_DOM_COMPARE_H
