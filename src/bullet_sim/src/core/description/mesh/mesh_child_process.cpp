// readMeshFile: assimp in a child process. assimp 5.2 (Debian 12) dereferences null or
// reads out of bounds on damaged COLLADA files (fuzz_mesh found a <triangles> without
// <p>, a <float_array count="0"> read through its accessor); in the simulator's process
// that would end the node. The child reads the file and sends the triangles back; a child
// that dies becomes a LoadError.
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <array>
#include <cstring>
#include <string>

#include "bullet_sim/description/mesh.h"
#include "bullet_sim/errors.h"
#include "description/mesh/mesh_import.h"

namespace bullet_sim {
namespace {

// Wire format (host byte order, the same machine): a status byte, then the error text or
// the part count and each part: vertex count, vertices (3 doubles), triangle count,
// triangles (3 uint32), a byte for "has colour", the colour (4 floats), the texture
// coordinates (count, 2 floats each), the texture path and the missing texture's name
// (length, bytes). Counts are uint64.
constexpr char kOk = 0;
// Far beyond any real mesh (a 100 MB STL reads in about a second here).
constexpr double kReadTimeoutS = 60;
constexpr char kLoadError = 1;

template <typename T>
void put(std::string* out, const T& value) {
  out->append(reinterpret_cast<const char*>(&value), sizeof(T));
}

void putText(std::string* out, const std::string& text) {
  put(out, static_cast<uint64_t>(text.size()));
  out->append(text);
}

std::string encode(const TriangleMesh& mesh) {
  std::string out(1, kOk);
  put(&out, static_cast<uint64_t>(mesh.parts.size()));
  for (const MeshPart& part : mesh.parts) {
    put(&out, static_cast<uint64_t>(part.vertices.size()));
    for (const Eigen::Vector3d& v : part.vertices) {
      put(&out, std::array<double, 3>{v.x(), v.y(), v.z()});
    }
    put(&out, static_cast<uint64_t>(part.triangles.size()));
    for (const auto& t : part.triangles) put(&out, t);
    put(&out, static_cast<char>(part.rgba.has_value()));
    const Eigen::Vector4f rgba = part.rgba.value_or(Eigen::Vector4f::Zero());
    put(&out, std::array<float, 4>{rgba[0], rgba[1], rgba[2], rgba[3]});
    put(&out, static_cast<uint64_t>(part.uvs.size()));
    for (const Eigen::Vector2f& uv : part.uvs) put(&out, std::array<float, 2>{uv.x(), uv.y()});
    putText(&out, part.texture_path);
    putText(&out, part.missing_texture);
  }
  return out;
}

/// Reads what encode wrote; the child wrote it whole or died (then the status says so).
class Reader {
 public:
  Reader(const std::string& data, const std::string& path) : data_(data), path_(path) {}
  template <typename T>
  T get() {
    T value;
    if (pos_ + sizeof(T) > data_.size()) {
      throw LoadError(path_ + ": cannot read mesh: the reading process's answer is cut short");
    }
    std::memcpy(&value, data_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return value;
  }
  std::string text() {
    const auto size = get<uint64_t>();
    if (pos_ + size > data_.size()) {
      throw LoadError(path_ + ": cannot read mesh: the reading process's answer is cut short");
    }
    std::string out = data_.substr(pos_, size);
    pos_ += size;
    return out;
  }

 private:
  const std::string& data_;
  const std::string& path_;
  size_t pos_ = 0;
};

TriangleMesh decode(const std::string& data, const std::string& path) {
  Reader in(data, path);
  in.get<char>();
  TriangleMesh mesh;
  mesh.path = path;
  mesh.parts.resize(in.get<uint64_t>());
  for (MeshPart& part : mesh.parts) {
    part.vertices.resize(in.get<uint64_t>());
    for (Eigen::Vector3d& v : part.vertices) {
      const auto xyz = in.get<std::array<double, 3>>();
      v = Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
    }
    part.triangles.resize(in.get<uint64_t>());
    for (auto& t : part.triangles) t = in.get<std::array<uint32_t, 3>>();
    const bool has_rgba = in.get<char>() != 0;
    const auto rgba = in.get<std::array<float, 4>>();
    if (has_rgba) part.rgba = Eigen::Vector4f(rgba[0], rgba[1], rgba[2], rgba[3]);
    part.uvs.resize(in.get<uint64_t>());
    for (Eigen::Vector2f& uv : part.uvs) {
      const auto st = in.get<std::array<float, 2>>();
      uv = Eigen::Vector2f(st[0], st[1]);
    }
    part.texture_path = in.text();
    part.missing_texture = in.text();
  }
  return mesh;
}

void writeAll(int fd, const std::string& data) {
  for (size_t done = 0; done < data.size();) {
    const ssize_t n = write(fd, data.data() + done, data.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += static_cast<size_t>(n);
  }
}

/// The child: imports, writes the answer, leaves without running the parent's atexit work.
[[noreturn]] void childMain(int fd, const std::string& path) {
  std::string answer;
  try {
    answer = encode(importMeshFile(path));
  } catch (const std::exception& e) {
    answer = std::string(1, kLoadError) + e.what();
  }
  writeAll(fd, answer);
  _exit(0);
}

/// Everything the child writes until it closes the pipe; false when `timeout_s` of wall
/// time passes first (a file assimp loops on, or a child stuck on a lock another thread of
/// the parent held at the fork).
bool readAll(int fd, double timeout_s, std::string* data) {
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  char buffer[65536];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd ready{fd, POLLIN, 0};
    const int polled = poll(&ready, 1, static_cast<int>(left.count()));
    if (polled < 0 && errno == EINTR) continue;
    if (polled <= 0) return false;
    const ssize_t n = read(fd, buffer, sizeof(buffer));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return true;
    data->append(buffer, static_cast<size_t>(n));
  }
}

}  // namespace

TriangleMesh readMeshFile(const std::string& path) {
  int fds[2];
  if (pipe(fds) != 0) throw LoadError(path + ": cannot read mesh: pipe: " + strerror(errno));
  const pid_t child = fork();
  if (child < 0) {
    close(fds[0]);
    close(fds[1]);
    throw LoadError(path + ": cannot read mesh: fork: " + strerror(errno));
  }
  if (child == 0) {
    close(fds[0]);
    childMain(fds[1], path);
  }
  close(fds[1]);
  std::string answer;
  const bool finished = readAll(fds[0], kReadTimeoutS, &answer);
  close(fds[0]);
  if (!finished) {
    kill(child, SIGKILL);
    while (waitpid(child, nullptr, 0) < 0 && errno == EINTR) {
    }
    throw LoadError(path + ": cannot read mesh: assimp did not finish reading it in " +
                    std::to_string(static_cast<int>(kReadTimeoutS)) + " s");
  }
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status) || answer.empty()) {
    const int sig = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    throw LoadError(path + ": cannot read mesh: assimp crashed reading it (" +
                    (sig ? std::string(strsignal(sig)) : "no answer") + ")");
  }
  if (answer[0] == kLoadError) throw LoadError(answer.substr(1));
  return decode(answer, path);
}

}  // namespace bullet_sim
