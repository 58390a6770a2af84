// Hand-worked poses for the generated fixtures, and the writing of their files.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "generated_fixtures.h"

namespace bullet_sim_test {

namespace fs = std::filesystem;

std::string sdfText(const std::string& version, const std::string& body) {
  return "<?xml version=\"1.0\"?>\n<sdf version=\"" + version + "\">\n" + body + "\n</sdf>\n";
}

Eigen::Isometry3d sdfPose(double x, double y, double z, double roll, double pitch, double yaw) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(x, y, z);
  T.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  return T;
}

void expectPose(const Eigen::Isometry3d& actual, const Eigen::Isometry3d& expected,
                const std::string& what) {
  EXPECT_LE((actual.matrix() - expected.matrix()).cwiseAbs().maxCoeff(), 1e-9)
      << what << ":\nread\n"
      << actual.matrix() << "\nexpected\n"
      << expected.matrix();
}

void expectVector(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected,
                  const std::string& what) {
  EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(), 1e-9)
      << what << ": read " << actual.transpose() << ", expected " << expected.transpose();
}

std::vector<CorpusFile> writeFixtures(const std::vector<GeneratedFixture>& fixtures,
                                      const std::string& dir) {
  std::vector<CorpusFile> out;
  const std::string models = (fs::path(dir) / "models").string();
  for (const GeneratedFixture& fixture : fixtures) {
    for (const auto& [relative, text] : fixture.files) {
      std::string content = text;
      for (size_t at = content.find("@DIR@"); at != std::string::npos;
           at = content.find("@DIR@", at)) {
        content.replace(at, 5, dir);
      }
      const fs::path file = fs::path(dir) / relative;
      fs::create_directories(file.parent_path());
      std::ofstream(file) << content;
    }
    out.push_back({(fs::path(dir) / fixture.name).string(), {models}});
  }
  return out;
}

}  // namespace bullet_sim_test
