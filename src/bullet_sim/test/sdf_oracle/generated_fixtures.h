#ifndef BULLET_SIM_TEST_GENERATED_FIXTURES_H
#define BULLET_SIM_TEST_GENERATED_FIXTURES_H

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "description/sdf/sdf_dom.h"
#include "differential_corpus.h"
#include "field_paths.h"

namespace bullet_sim_test {

/// The canonical link a reader picks for a model (at its field path, see modelFieldPath):
/// SdfModel::canonicalLink() for ours, what libsdformat named for the oracle.
using CanonicalOf = std::function<std::optional<std::pair<std::string, Eigen::Isometry3d>>(
    const std::string& model_field_path, const bullet_sim::SdfModel& model)>;

/// An SDF file written by the test, one per difference between SDF versions or per
/// feature, with the values that matter in it worked out by hand.
struct GeneratedFixture {
  std::string name;  ///< the main file, relative to the folder it is written into
  /// Every file (the main one first): path relative to the folder, text. "@DIR@" in a
  /// text stands for the folder (for file:// URIs).
  std::vector<std::pair<std::string, std::string>> files;
  /// Asserts the hand-worked values (gtest assertions) on a reading of the main file;
  /// throws std::runtime_error when something it looks at was not read at all.
  std::function<void(const bullet_sim::SdfDocument&, const CanonicalOf&)> check;
};

/// SDF 1.4 to 1.8: joint axes of 1.4, use_parent_model_frame, <pose frame>, gravity in
/// <physics>, relative_to, <frame> chains, and modelScopeFixtures().
std::vector<GeneratedFixture> versionFixtures();
/// expressed_in, canonical_link, nested models with joints between them.
std::vector<GeneratedFixture> modelScopeFixtures();
/// <include> URIs and overrides, plugins and sensors, and appearanceFixtures().
std::vector<GeneratedFixture> featureFixtures();
/// Lights of the three types, materials, link properties and inertials, geometries.
std::vector<GeneratedFixture> appearanceFixtures();

/// Writes every file of `fixtures` under `dir`; returns the main files, each with the
/// model folder `dir`/models.
std::vector<CorpusFile> writeFixtures(const std::vector<GeneratedFixture>& fixtures,
                                      const std::string& dir);

// Hand-worked values and the lookups that reach them.

/// `body` inside an XML declaration and <sdf version=`version`>.
std::string sdfText(const std::string& version, const std::string& body);

/// The pose x y z, rotated by roll, pitch, yaw (about fixed x, y, z in that order), as
/// SDF writes it.
Eigen::Isometry3d sdfPose(double x, double y, double z, double roll, double pitch, double yaw);
/// Every entry of `actual` within 1e-9 of `expected`; `what` names it.
void expectPose(const Eigen::Isometry3d& actual, const Eigen::Isometry3d& expected,
                const std::string& what);
void expectVector(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected,
                  const std::string& what);

/// The item of `items` named `name`.
/// @throws std::runtime_error naming `name` when there is none (a check stops there).
template <class T>
const T& need(const std::vector<T>& items, const std::string& name) {
  for (const T& item : items) {
    if (item.name == name) return item;
  }
  throw std::runtime_error("nothing named '" + name + "' was read");
}

/// The value of `value`. @throws std::runtime_error naming `what` when it is absent.
template <class T>
const T& need(const std::optional<T>& value, const std::string& what) {
  if (!value) throw std::runtime_error(what + " was not read");
  return *value;
}

/// π/2 as the fixtures write it (17 digits: the double nearest π/2).
constexpr double kQuarterTurn = 1.5707963267948966;

}  // namespace bullet_sim_test

#endif  // BULLET_SIM_TEST_GENERATED_FIXTURES_H
