// The glTF loader on small fixtures (tests/data, written by `shadowlab-make-scenes --fixtures`):
// one feature or one failure per file. Failures must be one line naming the file and problem.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "scene/GltfLoader.h"

namespace sl {
namespace {

namespace fs = std::filesystem;

std::string dataPath(const std::string& name) {
  return std::string(SHADOWLAB_TEST_DATA) + "/" + name;
}

std::shared_ptr<Scene> loadOk(const std::string& name) {
  SceneLoadResult r = loadGltf(dataPath(name));
  EXPECT_TRUE(r) << r.error;
  EXPECT_TRUE(r.error.empty()) << r.error;
  return r.scene;
}

const MeshPrimitive* findPrimitive(const Scene& s, const std::string& name) {
  for (const MeshPrimitive& p : s.primitives)
    if (p.name == name) return &p;
  return nullptr;
}

bool hasVertexNear(const MeshPrimitive& p, glm::vec3 v, float eps = 1e-5f) {
  for (const glm::vec3& q : p.positions)
    if (glm::length(q - v) < eps) return true;
  return false;
}

bool anyWarningContains(const Scene& s, const std::string& text) {
  for (const std::string& w : s.warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

/// Every triangle's winding normal points the way its stored vertex normals do.
void expectWindingAgreesWithNormals(const MeshPrimitive& p) {
  ASSERT_EQ(p.normals.size(), p.positions.size());
  for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
    glm::vec3 a = p.positions[p.indices[t]], b = p.positions[p.indices[t + 1]],
              c = p.positions[p.indices[t + 2]];
    glm::vec3 geometric = glm::cross(b - a, c - a);
    for (int k = 0; k < 3; ++k)
      EXPECT_GT(glm::dot(geometric, p.normals[p.indices[t + std::size_t(k)]]), 0.0f)
          << p.name << " triangle " << t / 3;
  }
}

void expectErrorNamesFileAnd(const std::string& file, const std::vector<std::string>& parts) {
  SceneLoadResult r = loadGltf(file);
  EXPECT_FALSE(r);
  EXPECT_EQ(r.scene, nullptr);
  EXPECT_EQ(r.error.rfind(file + ": ", 0), 0u) << r.error;  // starts with the file name
  EXPECT_EQ(r.error.find('\n'), std::string::npos) << r.error;
  for (const std::string& part : parts) EXPECT_NE(r.error.find(part), std::string::npos) << r.error;
}

// ---- good files ----------------------------------------------------------------------------

TEST(GltfLoader, NegativeScaleHierarchyFlipsWindingAndComposesTransforms) {
  auto s = loadOk("hierarchy-negative-scale.gltf");
  ASSERT_TRUE(s);
  ASSERT_EQ(s->primitives.size(), 3u);
  const MeshPrimitive* child = findPrimitive(*s, "child");
  const MeshPrimitive* grandchild = findPrimitive(*s, "grandchild");
  const MeshPrimitive* plain = findPrimitive(*s, "plain");
  ASSERT_TRUE(child && grandchild && plain);
  for (const MeshPrimitive* p : {child, grandchild, plain}) {
    expectWindingAgreesWithNormals(*p);
    for (const glm::vec3& n : p->normals) EXPECT_NEAR(glm::dot(n, glm::vec3(0, 1, 0)), 1.0f, 1e-5f);
  }
  // Local corner (1, 0, 0): scale (1,2,1), +90 degrees about y, +2 in x, then mirrored in x.
  EXPECT_TRUE(hasVertexNear(*child, {-2.0f, 0.0f, -1.0f}));
  // The grandchild's +3 in y is scaled by its parent's 2.
  EXPECT_TRUE(hasVertexNear(*grandchild, {-2.0f, 6.0f, -1.0f}));
  EXPECT_TRUE(hasVertexNear(*plain, {1.0f, 0.0f, 5.0f}));
  // Mirrored instances have their winding flipped, the plain one does not.
  EXPECT_EQ(plain->indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(child->indices, (std::vector<std::uint32_t>{0, 2, 1, 0, 3, 2}));
  EXPECT_EQ(s->name, "hierarchy-negative-scale");
  EXPECT_EQ(s->sourcePath, dataPath("hierarchy-negative-scale.gltf"));
}

TEST(GltfLoader, IndexTypesU8U16U32AndNonIndexed) {
  auto s = loadOk("index-types.gltf");
  ASSERT_TRUE(s);
  ASSERT_EQ(s->primitives.size(), 4u);
  EXPECT_EQ(s->triangleCount(), 8u);
  const std::uint32_t quad[6] = {0, 1, 2, 0, 2, 3};
  for (std::size_t k = 0; k < 4; ++k) {
    const MeshPrimitive& p = s->primitives[k];
    float x0 = 2.0f * float(k);
    const glm::vec3 corners[4] = {{x0, 0, 0}, {x0 + 1, 0, 0}, {x0 + 1, 0, -1}, {x0, 0, -1}};
    ASSERT_EQ(p.indices.size(), 6u) << k;
    for (int i = 0; i < 6; ++i)
      EXPECT_NEAR(glm::length(p.positions[p.indices[std::size_t(i)]] - corners[quad[i]]), 0.0f,
                  1e-6f)
          << "primitive " << k << " corner " << i;
    expectWindingAgreesWithNormals(p);
  }
  // The u16 primitive reads its positions and normals from one interleaved bufferView.
  for (const glm::vec3& n : s->primitives[1].normals) EXPECT_EQ(n, glm::vec3(0, 1, 0));
}

TEST(GltfLoader, SparseAccessorsOverrideAndStandAlone) {
  auto s = loadOk("sparse.gltf");
  ASSERT_TRUE(s);
  ASSERT_EQ(s->primitives.size(), 2u);
  // The file has no normals, so each primitive is flattened (3 corners per triangle).
  const MeshPrimitive& overridden = s->primitives[0];
  EXPECT_EQ(overridden.indices.size(), 6u);
  EXPECT_TRUE(hasVertexNear(overridden, {0, 0, 0}));
  EXPECT_TRUE(hasVertexNear(overridden, {1, 0, 0}));
  EXPECT_TRUE(hasVertexNear(overridden, {1, 5, -1}));   // the sparse substitution
  EXPECT_FALSE(hasVertexNear(overridden, {1, 0, -1}));  // what it replaced
  EXPECT_TRUE(hasVertexNear(overridden, {0, 0, -1}));
  expectWindingAgreesWithNormals(overridden);
  // No bufferView: zeros, then all three vertices from the sparse values. The computed flat
  // normal follows the winding (+y).
  const MeshPrimitive& standalone = s->primitives[1];
  ASSERT_EQ(standalone.positions.size(), 3u);
  EXPECT_EQ(standalone.positions[0], glm::vec3(3, 0, 0));
  EXPECT_EQ(standalone.positions[1], glm::vec3(4, 0, 0));
  EXPECT_EQ(standalone.positions[2], glm::vec3(3, 0, -1));
  EXPECT_EQ(standalone.normals[0], glm::vec3(0, 1, 0));
}

TEST(GltfLoader, MissingNormalsAreComputedFlat) {
  auto s = loadOk("no-normals.gltf");
  ASSERT_TRUE(s);
  ASSERT_EQ(s->primitives.size(), 1u);
  const MeshPrimitive& cube = s->primitives[0];
  EXPECT_EQ(s->triangleCount(), 12u);
  EXPECT_EQ(cube.positions.size(), 36u);  // flat: every triangle has its own corners
  expectWindingAgreesWithNormals(cube);
  for (std::size_t t = 0; t < 36; t += 3) {
    glm::vec3 n = cube.normals[cube.indices[t]];
    EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
    EXPECT_NEAR(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.0f, 1e-6f);  // axis-aligned
    glm::vec3 centroid = (cube.positions[cube.indices[t]] + cube.positions[cube.indices[t + 1]] +
                          cube.positions[cube.indices[t + 2]]) /
                         3.0f;
    EXPECT_GT(glm::dot(n, centroid), 0.0f) << "normal points outwards";
  }
}

TEST(GltfLoader, MaskMaterialTextureAndNormalizedTexcoords) {
  auto s = loadOk("mask-material.gltf");
  ASSERT_TRUE(s);
  ASSERT_EQ(s->materials.size(), 2u);
  const Material& cutout = s->materials[0];
  EXPECT_EQ(cutout.name, "cutout");
  EXPECT_EQ(cutout.alphaMode, AlphaMode::Mask);
  EXPECT_FLOAT_EQ(cutout.alphaCutoff, 0.3f);
  EXPECT_TRUE(cutout.doubleSided);
  EXPECT_EQ(cutout.baseColorFactor, glm::vec4(1.0f, 0.5f, 0.25f, 1.0f));
  EXPECT_EQ(cutout.baseColorTexture, 0);
  EXPECT_EQ(s->materials[1].alphaMode, AlphaMode::Blend);
  EXPECT_FALSE(s->materials[1].doubleSided);

  ASSERT_EQ(s->images.size(), 1u);
  const SceneImage& img = s->images[0];
  EXPECT_EQ(img.width, 2);
  EXPECT_EQ(img.height, 2);
  EXPECT_EQ(img.rgba, (std::vector<std::uint8_t>{255, 0, 0, 255, 0, 255, 0, 0, 0, 0, 255, 128, 255,
                                                 255, 255, 255}));

  ASSERT_EQ(s->primitives.size(), 2u);
  const MeshPrimitive& p = s->primitives[0];
  EXPECT_EQ(&s->materialOf(p), &s->materials[0]);
  ASSERT_EQ(p.uvs.size(), 4u);
  EXPECT_NEAR(p.uvs[0].x, 0.0f, 1e-6f);
  EXPECT_NEAR(p.uvs[0].y, 1.0f, 1e-6f);
  EXPECT_NEAR(p.uvs[1].x, 1.0f, 1e-6f);
  EXPECT_NEAR(p.uvs[3].x, 32768.0f / 65535.0f, 1e-7f);
  // KHR_texture_transform (offset 0.5, 0; scale 2) is baked into the second quad's uvs.
  const MeshPrimitive& q = s->primitives[1];
  ASSERT_EQ(q.uvs.size(), 4u);
  EXPECT_NEAR(q.uvs[0].x, 0.5f, 1e-5f);
  EXPECT_NEAR(q.uvs[0].y, 2.0f, 1e-5f);
  EXPECT_NEAR(q.uvs[2].x, 2.5f, 1e-5f);
  EXPECT_NEAR(q.uvs[2].y, 0.0f, 1e-5f);
}

TEST(GltfLoader, StripsAndFansConvertedLinesAndPointsSkipped) {
  auto s = loadOk("strip-fan-lines.gltf");
  ASSERT_TRUE(s);
  ASSERT_EQ(s->primitives.size(), 2u);
  EXPECT_EQ(s->primitives[0].indices.size() / 3, 3u);  // strip of 5 vertices
  EXPECT_EQ(s->primitives[1].indices.size() / 3, 3u);  // fan of 5 vertices
  for (const MeshPrimitive& p : s->primitives) {
    expectWindingAgreesWithNormals(p);
    for (const glm::vec3& n : p.normals) EXPECT_NEAR(n.y, 1.0f, 1e-6f);
  }
  EXPECT_TRUE(anyWarningContains(*s, "lines skipped"));
  EXPECT_TRUE(anyWarningContains(*s, "points skipped"));
}

TEST(GltfLoader, SunCamerasAndStepAndLinearPaths) {
  auto s = loadOk("camera-path.gltf");
  ASSERT_TRUE(s);
  // The sun's node is turned -60 degrees about x: its +z, towards the light, is (0, sin, cos).
  ASSERT_TRUE(s->light);
  glm::vec3 l = s->light->directionalTowards();
  EXPECT_NEAR(l.x, 0.0f, 1e-5f);
  EXPECT_NEAR(l.y, std::sin(glm::radians(60.0f)), 1e-5f);
  EXPECT_NEAR(l.z, std::cos(glm::radians(60.0f)), 1e-5f);
  EXPECT_TRUE(anyWarningContains(*s, "point light 'lamp' ignored"));
  EXPECT_TRUE(anyWarningContains(*s, "orthographic camera ignored"));

  ASSERT_EQ(s->cameras.size(), 1u);
  const Camera& c = s->cameras[0].camera;
  EXPECT_EQ(s->cameras[0].name, "tracker");
  EXPECT_EQ(c.position, glm::vec3(0, 1, 10));
  EXPECT_NEAR(glm::dot(c.forward(), glm::vec3(0, 0, -1)), 1.0f, 1e-6f);
  EXPECT_NEAR(c.fovYDeg, glm::degrees(0.8f), 1e-4f);
  EXPECT_FLOAT_EQ(c.nearM, 0.05f);
  // No zfar in the file: far reaches the farthest corner of the 20 x 20 m ground.
  EXPECT_GE(c.farM, std::sqrt(10.0f * 10.0f + 1.0f + 20.0f * 20.0f));
  EXPECT_LT(c.farM, 40.0f);
  EXPECT_FALSE(c.validate());

  ASSERT_EQ(s->paths.size(), 1u);
  const CameraPath& path = s->paths[0];
  EXPECT_EQ(path.name, "dolly");
  EXPECT_FLOAT_EQ(path.durationS(), 4.0f);
  EXPECT_NEAR(glm::length(path.sample(1.0f).position - glm::vec3(0, 1, 8)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::length(path.sample(3.0f).position - glm::vec3(0, 1, 4)), 0.0f, 1e-5f);
  // STEP rotation: unturned until t = 3, then +90 degrees about y (looking along -x).
  EXPECT_NEAR(glm::dot(path.sample(2.9f).forward(), glm::vec3(0, 0, -1)), 1.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(path.sample(3.0f).forward(), glm::vec3(-1, 0, 0)), 1.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(path.sample(3.5f).forward(), glm::vec3(-1, 0, 0)), 1.0f, 1e-5f);
  EXPECT_NEAR(path.fovYDeg, glm::degrees(0.8f), 1e-4f);
}

TEST(GltfLoader, SpotAndPointLightsFromTheirNodes) {
  auto s = loadOk("punctual-lights.gltf");
  ASSERT_TRUE(s);
  // No directional light: the first valid light in node order, the spot, lights the scene.
  ASSERT_TRUE(s->light);
  const Light& l = *s->light;
  EXPECT_EQ(l.type, LightType::Spot);
  // Parent at (1, 3, -2), child at (0, 1, 0) turned -90 degrees about x: -z becomes -y.
  EXPECT_NEAR(glm::length(l.positionM - glm::vec3(1, 4, -2)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::length(l.spotAxis() - glm::vec3(0, -1, 0)), 0.0f, 1e-5f);
  EXPECT_NEAR(l.outerConeDeg, glm::degrees(0.6f), 1e-3f);
  EXPECT_NEAR(l.innerConeDeg, glm::degrees(0.3f), 1e-3f);
  EXPECT_FLOAT_EQ(l.rangeM, 12.0f);
  EXPECT_TRUE(anyWarningContains(*s,
                                 "point light 'bulb' ignored (ShadowLab lights the scene "
                                 "with one light: spot light 'lamp')"));
  EXPECT_TRUE(anyWarningContains(*s, "spot light 'too-wide' ignored: spot light: outer cone"));
  EXPECT_TRUE(anyWarningContains(*s, "light 'odd' of unknown type 'area' ignored"));
  EXPECT_FALSE(anyWarningContains(*s, "no directional light"));
}

TEST(GltfLoader, PointLightOnly) {
  auto s = loadOk("point-light.gltf");
  ASSERT_TRUE(s);
  ASSERT_TRUE(s->light);
  EXPECT_EQ(s->light->type, LightType::Point);
  EXPECT_NEAR(glm::length(s->light->positionM - glm::vec3(0.5f, 4, -0.25f)), 0.0f, 1e-6f);
  EXPECT_EQ(s->light->rangeM, 0.0f);  // absent: infinite
  EXPECT_TRUE(s->warnings.empty()) << s->warnings.front();
}

TEST(GltfLoader, SkinnedAndAnimatedMeshesStayInRestPose) {
  auto s = loadOk("skinned-animated.gltf");
  ASSERT_TRUE(s);
  ASSERT_EQ(s->primitives.size(), 1u);
  EXPECT_TRUE(hasVertexNear(s->primitives[0], {1, 1, 0}));  // the node's rest translation
  EXPECT_TRUE(s->paths.empty());
  EXPECT_TRUE(anyWarningContains(*s, "skin ignored"));
  EXPECT_TRUE(anyWarningContains(*s, "animation 'bounce' moves non-camera nodes"));
}

TEST(GltfLoader, BinaryGlbLoads) {
  auto s = loadOk("cube.glb");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->name, "cube");
  EXPECT_EQ(s->triangleCount(), 12u);
  EXPECT_NEAR(glm::length(s->bounds.min - glm::vec3(-0.5f, 0.0f, -0.5f)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(s->bounds.max - glm::vec3(0.5f, 1.0f, 0.5f)), 0.0f, 1e-6f);
  expectWindingAgreesWithNormals(s->primitives[0]);
  EXPECT_FALSE(s->light);
  EXPECT_TRUE(anyWarningContains(*s, "no directional light"));
}

// ---- bad files -----------------------------------------------------------------------------

TEST(GltfLoader, MissingFile) {
  expectErrorNamesFileAnd(dataPath("does-not-exist.gltf"), {"file not found"});
}

TEST(GltfLoader, DirectoryIsNotAFile) {
  expectErrorNamesFileAnd(std::string(SHADOWLAB_TEST_DATA), {"is a directory"});
}

TEST(GltfLoader, MalformedJson) {
  expectErrorNamesFileAnd(dataPath("malformed.gltf"), {"malformed JSON"});
}

TEST(GltfLoader, TruncatedGlb) {
  expectErrorNamesFileAnd(dataPath("truncated.glb"), {"truncated .glb"});
}

TEST(GltfLoader, NoTriangles) {
  expectErrorNamesFileAnd(dataPath("no-triangles.gltf"), {"no triangles"});
}

TEST(GltfLoader, NanPosition) {
  expectErrorNamesFileAnd(dataPath("nan-position.gltf"), {"POSITION of vertex 1", "NaN"});
}

TEST(GltfLoader, UnsupportedRequiredExtension) {
  expectErrorNamesFileAnd(dataPath("draco-required.gltf"),
                          {"requires unsupported extension 'KHR_draco_mesh_compression'"});
}

TEST(GltfLoader, OutOfRangeIndex) {
  expectErrorNamesFileAnd(dataPath("bad-index.gltf"), {"index 7", "out of range", "3 vertices"});
}

TEST(GltfLoader, AccessorOutOfBufferRange) {
  expectErrorNamesFileAnd(dataPath("buffer-out-of-range.gltf"),
                          {"accessor 0", "out of range of bufferView 0"});
}

/// Every prefix of a good .glb and of a good .gltf either loads or fails with one line naming
/// the file; none crashes or throws.
TEST(GltfLoader, TruncatedFilesNeverThrow) {
  fs::path outDir = fs::path(SHADOWLAB_TEST_OUT) / "gltf-loader";
  fs::create_directories(outDir);
  for (const char* name : {"cube.glb", "mask-material.gltf"}) {
    std::ifstream in(dataPath(name), std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_FALSE(bytes.empty());
    fs::path cut = outDir / (std::string("cut-") + name);
    for (std::size_t len = 0; len < bytes.size(); len += 13) {
      std::ofstream(cut, std::ios::binary).write(bytes.data(), std::streamsize(len));
      SceneLoadResult r;
      EXPECT_NO_THROW(r = loadGltf(cut));
      if (!r) {
        EXPECT_EQ(r.error.rfind(cut.string() + ": ", 0), 0u) << r.error;
        EXPECT_EQ(r.error.find('\n'), std::string::npos) << r.error;
      }
    }
  }
}

}  // namespace
}  // namespace sl
