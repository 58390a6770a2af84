#include "mesh_fixtures.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <stdexcept>

namespace bullet_sim_test {
namespace {

using Eigen::Vector3d;

Vector3d normalOf(const Triangle& t) { return (t[1] - t[0]).cross(t[2] - t[0]).normalized(); }

std::ofstream openFile(const std::string& path, std::ios::openmode mode = std::ios::out) {
  std::ofstream out(path, mode);
  if (!out) throw std::runtime_error("cannot write " + path);
  return out;
}

}  // namespace

std::vector<Triangle> boxTriangles(const Vector3d& size, const Vector3d& centre) {
  std::vector<Triangle> out;
  const Vector3d h = size / 2;
  for (int axis = 0; axis < 3; ++axis) {
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;  // e_axis = e_a x e_b
    for (double sign : {-1.0, 1.0}) {
      auto corner = [&](double sa, double sb) -> Vector3d {
        Vector3d p;
        p[axis] = sign * h[axis];
        p[a] = sa * h[a];
        p[b] = sb * h[b];
        return p + centre;
      };
      // Counter-clockwise about +e_axis; reversed on the -e_axis face.
      Triangle t1{corner(-1, -1), corner(1, -1), corner(1, 1)};
      Triangle t2{corner(-1, -1), corner(1, 1), corner(-1, 1)};
      if (sign < 0) {
        std::swap(t1[1], t1[2]);
        std::swap(t2[1], t2[2]);
      }
      out.push_back(t1);
      out.push_back(t2);
    }
  }
  return out;
}

std::vector<Triangle> cylinderTriangles(double radius, double length, int segments) {
  std::vector<Triangle> out;
  const Vector3d top(0, 0, length / 2), bottom(0, 0, -length / 2);
  for (int k = 0; k < segments; ++k) {
    const double a0 = 2 * M_PI * k / segments, a1 = 2 * M_PI * (k + 1) / segments;
    const Vector3d r0(radius * std::cos(a0), radius * std::sin(a0), 0);
    const Vector3d r1(radius * std::cos(a1), radius * std::sin(a1), 0);
    out.push_back({r0 + bottom, r1 + bottom, r1 + top});
    out.push_back({r0 + bottom, r1 + top, r0 + top});
    out.push_back({top, r0 + top, r1 + top});
    out.push_back({bottom, r1 + bottom, r0 + bottom});
  }
  return out;
}

namespace {

/// The folders makeTempDir() made, removed with everything in them when the program ends.
class MadeFolders {
 public:
  ~MadeFolders() {
    std::error_code ignored;
    for (const std::string& path : paths_) std::filesystem::remove_all(path, ignored);
  }
  void add(const std::string& path) {
    const std::lock_guard<std::mutex> lock(mutex_);
    paths_.push_back(path);
  }

 private:
  std::mutex mutex_;
  std::vector<std::string> paths_;
};

MadeFolders& madeFolders() {
  static MadeFolders folders;
  return folders;
}

}  // namespace

std::string makeTempDir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "bullet_sim_mesh_XXXXXX").string();
  if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed for " + pattern);
  madeFolders().add(pattern);
  return pattern;
}

void writeText(const std::string& path, const std::string& text) { openFile(path) << text; }

void writeBinaryStl(const std::string& path, const std::vector<Triangle>& triangles) {
  std::ofstream out = openFile(path, std::ios::out | std::ios::binary);
  const std::string header(80, ' ');
  out.write(header.data(), header.size());
  const auto count = static_cast<uint32_t>(triangles.size());
  out.write(reinterpret_cast<const char*>(&count), 4);
  for (const Triangle& t : triangles) {
    auto put = [&](const Vector3d& v) {
      const float f[3] = {static_cast<float>(v.x()), static_cast<float>(v.y()),
                          static_cast<float>(v.z())};
      out.write(reinterpret_cast<const char*>(f), sizeof(f));
    };
    put(normalOf(t));
    for (const Vector3d& v : t) put(v);
    const uint16_t attributes = 0;
    out.write(reinterpret_cast<const char*>(&attributes), 2);
  }
}

void writeAsciiStl(const std::string& path, const std::vector<Triangle>& triangles) {
  std::ofstream out = openFile(path);
  out.precision(9);
  out << "solid fixture\n";
  for (const Triangle& t : triangles) {
    const Vector3d n = normalOf(t);
    out << " facet normal " << n.x() << " " << n.y() << " " << n.z() << "\n  outer loop\n";
    for (const Vector3d& v : t) out << "   vertex " << v.x() << " " << v.y() << " " << v.z() << "\n";
    out << "  endloop\n endfacet\n";
  }
  out << "endsolid fixture\n";
}

void writeCollada(const std::string& path, const std::vector<Triangle>& triangles, double unit_m,
                  const std::string& up_axis, const Eigen::Vector4f& rgba) {
  std::ostringstream positions, indices;
  positions.precision(9);
  for (size_t i = 0; i < triangles.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const Vector3d& v = triangles[i][c];
      positions << v.x() << " " << v.y() << " " << v.z() << " ";
      indices << 3 * i + c << " ";
    }
  }
  const size_t n = 3 * triangles.size();
  std::ofstream out = openFile(path);
  out << "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      << "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
      << " <asset><unit name=\"u\" meter=\"" << unit_m << "\"/><up_axis>" << up_axis
      << "</up_axis></asset>\n"
      << " <library_effects><effect id=\"paint-fx\"><profile_COMMON><technique sid=\"common\">"
      << "<lambert><diffuse><color>" << rgba.x() << " " << rgba.y() << " " << rgba.z() << " "
      << rgba.w() << "</color></diffuse></lambert></technique></profile_COMMON></effect>"
      << "</library_effects>\n"
      << " <library_materials><material id=\"paint\" name=\"paint\">"
      << "<instance_effect url=\"#paint-fx\"/></material></library_materials>\n"
      << " <library_geometries><geometry id=\"g\" name=\"g\"><mesh>\n"
      << "  <source id=\"g-pos\"><float_array id=\"g-pos-a\" count=\"" << 3 * n << "\">"
      << positions.str() << "</float_array><technique_common><accessor source=\"#g-pos-a\" "
      << "count=\"" << n << "\" stride=\"3\"><param name=\"X\" type=\"float\"/>"
      << "<param name=\"Y\" type=\"float\"/><param name=\"Z\" type=\"float\"/></accessor>"
      << "</technique_common></source>\n"
      << "  <vertices id=\"g-v\"><input semantic=\"POSITION\" source=\"#g-pos\"/></vertices>\n"
      << "  <triangles material=\"m\" count=\"" << triangles.size() << "\">"
      << "<input semantic=\"VERTEX\" source=\"#g-v\" offset=\"0\"/><p>" << indices.str()
      << "</p></triangles>\n"
      << " </mesh></geometry></library_geometries>\n"
      << " <library_visual_scenes><visual_scene id=\"s\"><node id=\"n\" name=\"n\">"
      << "<instance_geometry url=\"#g\"><bind_material><technique_common>"
      << "<instance_material symbol=\"m\" target=\"#paint\"/></technique_common></bind_material>"
      << "</instance_geometry></node></visual_scene></library_visual_scenes>\n"
      << " <scene><instance_visual_scene url=\"#s\"/></scene>\n</COLLADA>\n";
}

void writeObj(const std::string& path, const std::vector<std::vector<Triangle>>& parts,
              const std::vector<Eigen::Vector3f>& colours) {
  const std::filesystem::path obj(path);
  const std::string mtl_name = obj.stem().string() + ".mtl";
  std::ofstream mtl = openFile((obj.parent_path() / mtl_name).string());
  for (size_t i = 0; i < colours.size(); ++i) {
    mtl << "newmtl paint" << i << "\nKd " << colours[i].x() << " " << colours[i].y() << " "
        << colours[i].z() << "\n";
  }
  std::ofstream out = openFile(path);
  out.precision(9);
  out << "mtllib " << mtl_name << "\n";
  size_t next_vertex = 1;
  for (size_t i = 0; i < parts.size(); ++i) {
    out << "g part" << i << "\nusemtl paint" << i << "\n";
    for (const Triangle& t : parts[i]) {
      for (const Vector3d& v : t) out << "v " << v.x() << " " << v.y() << " " << v.z() << "\n";
      out << "f " << next_vertex << " " << next_vertex + 1 << " " << next_vertex + 2 << "\n";
      next_vertex += 3;
    }
  }
}

}  // namespace bullet_sim_test
