#include "dom_comparer.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace bullet_sim_test {

namespace {

/// Shortest of %.15g and %.17g that tells `a` from `b` (both printed the same way).
std::pair<std::string, std::string> printedPair(double a, double b) {
  char x[64], y[64];
  std::snprintf(x, sizeof x, "%.15g", a);
  std::snprintf(y, sizeof y, "%.15g", b);
  if (std::string(x) == y) {
    std::snprintf(x, sizeof x, "%.17g", a);
    std::snprintf(y, sizeof y, "%.17g", b);
  }
  return {x, y};
}

std::string printed(const double* values, int n) {
  std::string out;
  char buffer[64];
  for (int i = 0; i < n; ++i) {
    std::snprintf(buffer, sizeof buffer, "%.12g", values[i] + 0.0);  // -0 prints as 0
    out += (i ? " " : "") + std::string(buffer);
  }
  return out;
}

/// "xyz (x y z) rpy (r p y)": roll about x, then pitch about y, then yaw about z.
std::string printedPose(const Eigen::Isometry3d& T) {
  const Eigen::Matrix3d& R = T.linear();
  const double rpy[3] = {std::atan2(R(2, 1), R(2, 2)),
                         std::asin(std::max(-1.0, std::min(1.0, -R(2, 0)))),
                         std::atan2(R(1, 0), R(0, 0))};
  return "xyz (" + printed(T.translation().data(), 3) + ") rpy (" + printed(rpy, 3) + ")";
}

bool near(double a, double b, double tolerance) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  if (std::isinf(a) || std::isinf(b)) return a == b;
  return std::abs(a - b) <= tolerance;
}

std::string canonicalFile(const std::string& file) {
  if (file.empty()) return file;
  std::error_code ec;
  const std::filesystem::path p = std::filesystem::weakly_canonical(file, ec);
  return ec ? file : p.string();
}

}  // namespace

DomComparer::DomComparer(std::string file, std::string ours, std::string theirs)
    : file_(std::move(file)), ours_(std::move(ours)), theirs_(std::move(theirs)) {}

DomComparer::Scope::Scope(DomComparer* comparer, const std::string& segment)
    : comparer_(comparer) {
  comparer_->scopes_.push_back(segment);
}

DomComparer::Scope::~Scope() { comparer_->scopes_.pop_back(); }

std::string DomComparer::path(const std::string& field) const {
  std::string out;
  for (const std::string& s : scopes_) out += (out.empty() ? "" : ".") + s;
  if (!field.empty()) out += (out.empty() ? "" : ".") + field;
  return out;
}

void DomComparer::differ(const std::string& field, const std::string& ours,
                         const std::string& theirs) {
  differences_.push_back(file_ + ": " + path(field) + ": " + ours_ + " '" + ours + "', " +
                         theirs_ + " '" + theirs + "'");
}

void DomComparer::text(const std::string& field, const std::string& ours,
                       const std::string& theirs) {
  if (ours != theirs) differ(field, ours, theirs);
}

void DomComparer::number(const std::string& field, double ours, double theirs,
                         double tolerance) {
  if (near(ours, theirs, tolerance)) return;
  const auto [a, b] = printedPair(ours, theirs);
  differ(field, a, b);
}

void DomComparer::flag(const std::string& field, bool ours, bool theirs) {
  if (ours != theirs) differ(field, ours ? "true" : "false", theirs ? "true" : "false");
}

void DomComparer::vector(const std::string& field, const Eigen::Vector3d& ours,
                         const Eigen::Vector3d& theirs, double tolerance) {
  for (int i = 0; i < 3; ++i) {
    if (!near(ours[i], theirs[i], tolerance)) {
      differ(field, printed(ours.data(), 3), printed(theirs.data(), 3));
      return;
    }
  }
}

void DomComparer::colour(const std::string& field, const Eigen::Vector4f& ours,
                         const Eigen::Vector4f& theirs) {
  const Eigen::Vector4d a = ours.cast<double>(), b = theirs.cast<double>();
  for (int i = 0; i < 4; ++i) {
    if (!near(a[i], b[i], 1e-6)) {
      differ(field, printed(a.data(), 4), printed(b.data(), 4));
      return;
    }
  }
}

void DomComparer::pose(const std::string& field, const Eigen::Isometry3d& ours,
                       const Eigen::Isometry3d& theirs) {
  const Eigen::Matrix4d a = ours.matrix(), b = theirs.matrix();
  for (int i = 0; i < 16; ++i) {
    if (!near(a.data()[i], b.data()[i], 1e-9)) {
      differ(field, printedPose(ours), printedPose(theirs));
      return;
    }
  }
}

void DomComparer::origin(const std::string& field, const bullet_sim::SdfOrigin& ours,
                         const bullet_sim::SdfOrigin& theirs) {
  text(field + ".file", canonicalFile(ours.file), canonicalFile(theirs.file));
  if (theirs.line > 0 && ours.line != theirs.line) {
    differ(field + ".line", std::to_string(ours.line), std::to_string(theirs.line));
  }
}

}  // namespace bullet_sim_test
