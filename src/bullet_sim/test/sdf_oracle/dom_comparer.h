#ifndef BULLET_SIM_TEST_DOM_COMPARER_H
#define BULLET_SIM_TEST_DOM_COMPARER_H

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "description/sdf/sdf_dom.h"

namespace bullet_sim_test {

/// Collects the differences between two readings of one file. Each difference is one
/// line naming the file, the field's path (`world.models[ground_plane].links[link]
/// .collisions[collision].geometry.shape.size`) and both values.
class DomComparer {
 public:
  /// `file` goes first on every line; `ours` and `theirs` name the two readers.
  DomComparer(std::string file, std::string ours = "ours", std::string theirs = "libsdformat");

  /// Puts `segment` on the path for as long as it lives.
  class Scope {
   public:
    Scope(DomComparer* comparer, const std::string& segment);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    DomComparer* comparer_;
  };

  void text(const std::string& field, const std::string& ours, const std::string& theirs);
  void number(const std::string& field, double ours, double theirs, double tolerance = 1e-9);
  void flag(const std::string& field, bool ours, bool theirs);
  void vector(const std::string& field, const Eigen::Vector3d& ours,
              const Eigen::Vector3d& theirs, double tolerance = 1e-9);
  /// Colours are floats: equal to 1e-6.
  void colour(const std::string& field, const Eigen::Vector4f& ours, const Eigen::Vector4f& theirs);
  /// Translations and rotation matrices equal to 1e-9.
  void pose(const std::string& field, const Eigen::Isometry3d& ours,
            const Eigen::Isometry3d& theirs);
  /// The same file (both made canonical) and, where `theirs` knows it, the same line.
  void origin(const std::string& field, const bullet_sim::SdfOrigin& ours,
              const bullet_sim::SdfOrigin& theirs);

  /// Present in both or in neither; when in both, `each(ours, theirs)` compares the values
  /// inside the scope `field`.
  template <class T, class Each>
  void optional(const std::string& field, const std::optional<T>& ours,
                const std::optional<T>& theirs, Each each) {
    if (ours.has_value() != theirs.has_value()) {
      differ(field, ours ? "present" : "absent", theirs ? "present" : "absent");
      return;
    }
    if (!ours) return;
    Scope scope(this, field);
    each(*ours, *theirs);
  }

  /// Items matched by `.name` (a repeated name matched in order, as `name#2`): one that
  /// only one side has is a difference; each pair is compared by `each(ours, theirs,
  /// key)` inside the scope `field[key]`. Order is not compared.
  template <class T, class Each>
  void byName(const std::string& field, const std::vector<T>& ours, const std::vector<T>& theirs,
              Each each) {
    const std::map<std::string, const T*> mine = keyed(ours), other = keyed(theirs);
    for (const auto& [key, item] : mine) {
      const auto match = other.find(key);
      if (match == other.end()) {
        differ(field + "[" + key + "]", "present", "absent");
        continue;
      }
      Scope scope(this, field + "[" + key + "]");
      each(*item, *match->second, key);
    }
    for (const auto& [key, item] : other) {
      if (!mine.count(key)) differ(field + "[" + key + "]", "absent", "present");
    }
  }

  /// The path of `field` under the current scope.
  std::string path(const std::string& field) const;
  const std::vector<std::string>& differences() const { return differences_; }

 private:
  void differ(const std::string& field, const std::string& ours, const std::string& theirs);

  template <class T>
  static std::map<std::string, const T*> keyed(const std::vector<T>& items) {
    std::map<std::string, const T*> out;
    std::map<std::string, int> seen;
    for (const T& item : items) {
      const int n = ++seen[item.name];
      out[n == 1 ? item.name : item.name + "#" + std::to_string(n)] = &item;
    }
    return out;
  }

  std::string file_, ours_, theirs_;
  std::vector<std::string> scopes_;
  std::vector<std::string> differences_;
};

}  // namespace bullet_sim_test

#endif  // BULLET_SIM_TEST_DOM_COMPARER_H
