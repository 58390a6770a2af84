#include "render/image_file.h"

#include <dlfcn.h>

#include <filesystem>

namespace bullet_sim {
namespace {

using DecodeFunction = bool (*)(const char*, RgbImage*);

/// The decoder module's function, or null with the reason.
struct Decoder {
  DecodeFunction decode = nullptr;
  std::string error;
};

/// The module beside the library (or program) that holds this code, if that can be told.
std::string moduleBesideThisLibrary() {
  Dl_info info;
  if (dladdr(reinterpret_cast<void*>(&readRgbImage), &info) == 0 || info.dli_fname == nullptr) {
    return "";
  }
  const std::filesystem::path beside =
      std::filesystem::path(info.dli_fname).parent_path() / kImageFileModule;
  return std::filesystem::exists(beside) ? beside.string() : "";
}

Decoder loadDecoder() {
  const std::string beside = moduleBesideThisLibrary();
  const std::string name = beside.empty() ? kImageFileModule : beside;
  void* module = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (module == nullptr) {
    return {nullptr, "cannot load the image decoder module " + name + ": " + dlerror()};
  }
  auto decode = reinterpret_cast<DecodeFunction>(dlsym(module, "bullet_sim_decode_rgb_image"));
  if (decode == nullptr) {
    return {nullptr, "the image decoder module " + name +
                         " has no bullet_sim_decode_rgb_image: " + dlerror()};
  }
  return {decode, ""};
}

}  // namespace

bool readRgbImage(const std::string& path, RgbImage* image, std::string* error) {
  static const Decoder decoder = loadDecoder();  // once, whichever thread comes first
  if (decoder.decode == nullptr) {
    *error = decoder.error;
    return false;
  }
  if (!decoder.decode(path.c_str(), image)) {
    *error = "cannot read the image";
    return false;
  }
  return true;
}

}  // namespace bullet_sim
