// libFuzzer target: the glTF loader (loadGltf) on arbitrary bytes, as a .glb when they start
// with the GLB magic "glTF", else as a .gltf. It must load or refuse with one bounded line
// naming the file; crashes, leaks, hangs and sanitizer reports are findings.
#include <cstring>

#include "FuzzInput.h"
#include "scene/GltfLoader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  const std::filesystem::path path =
      sl::fuzz::writeInput(data, size, glb ? "scene.glb" : "scene.gltf");
  sl::SceneLoadResult r = sl::loadGltf(path);
  if (!r) sl::fuzz::checkMessage(r.error, path.string() + ": ");
  return 0;
}
