#ifndef BULLET_SIM_TEST_MESH_FIXTURES_H
#define BULLET_SIM_TEST_MESH_FIXTURES_H

#include <array>
#include <string>
#include <vector>

#include <Eigen/Geometry>

/// Mesh files written by the tests themselves (STL, COLLADA, OBJ), from triangles whose
/// geometry the tests know.
namespace bullet_sim_test {

/// Three corners, counter-clockwise seen from outside.
using Triangle = std::array<Eigen::Vector3d, 3>;

/// The 12 triangles of a box of full size `size` centred on `centre`.
std::vector<Triangle> boxTriangles(const Eigen::Vector3d& size,
                                   const Eigen::Vector3d& centre = Eigen::Vector3d::Zero());
/// A closed cylinder along z centred on the origin, `segments` facets around.
std::vector<Triangle> cylinderTriangles(double radius, double length, int segments);

/// A fresh empty folder under the system's temp folder, removed with everything in it
/// when the test program ends.
std::string makeTempDir();
void writeText(const std::string& path, const std::string& text);

void writeBinaryStl(const std::string& path, const std::vector<Triangle>& triangles);
void writeAsciiStl(const std::string& path, const std::vector<Triangle>& triangles);
/// A COLLADA 1.4.1 file with `triangles` as written (in the file's units and up axis),
/// <unit meter="unit_m">, <up_axis>up_axis</up_axis>, one material of diffuse `rgba`.
void writeCollada(const std::string& path, const std::vector<Triangle>& triangles, double unit_m,
                  const std::string& up_axis, const Eigen::Vector4f& rgba);
/// An OBJ file with one group per entry of `parts`, each with its own MTL material of
/// diffuse colour `colours[i]` (the MTL file is written beside it).
void writeObj(const std::string& path, const std::vector<std::vector<Triangle>>& parts,
              const std::vector<Eigen::Vector3f>& colours);

}  // namespace bullet_sim_test

#endif  // BULLET_SIM_TEST_MESH_FIXTURES_H
