// The built-in scenes (scenes/*.gltf) and the Scene helpers: every scene loads with a sun,
// cameras and a path; each scene's lesson holds (plane-box's analytic shadow agrees with ray
// casting its geometry, diagonal's row lies at 45 degrees in the light's image, ...).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "algo/omni/OmniMapping.h"
#include "scene/GltfLoader.h"
#include "scene/PlaneBoxAnalytic.h"

namespace sl {
namespace {

namespace fs = std::filesystem;

std::shared_ptr<Scene> loadBuiltin(const std::string& name) {
  SceneLoadResult r = loadSceneByNameOrPath(name);
  EXPECT_TRUE(r) << r.error;
  return r.scene;
}

const CameraBookmark* findCamera(const Scene& s, const std::string& name) {
  for (const CameraBookmark& c : s.cameras)
    if (c.name == name) return &c;
  return nullptr;
}

/// Does the ray from `o` along `d` hit any triangle whose vertices all satisfy `keep`?
template <class Keep>
bool rayHits(const Scene& s, glm::vec3 o, glm::vec3 d, Keep keep) {
  for (const MeshPrimitive& p : s.primitives) {
    for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
      glm::vec3 a = p.positions[p.indices[t]], b = p.positions[p.indices[t + 1]],
                c = p.positions[p.indices[t + 2]];
      if (!keep(a) || !keep(b) || !keep(c)) continue;
      glm::vec3 e1 = b - a, e2 = c - a, pv = glm::cross(d, e2);
      double det = glm::dot(e1, pv);
      if (std::abs(det) < 1e-12) continue;
      glm::vec3 tv = o - a, qv = glm::cross(tv, e1);
      double u = glm::dot(tv, pv) / det, v = glm::dot(d, qv) / det, dist = glm::dot(e2, qv) / det;
      if (u >= 0 && v >= 0 && u + v <= 1 && dist > 0) return true;
    }
  }
  return false;
}

TEST(Scene, BuiltinSceneNamesAreSortedStems) {
  std::vector<std::string> names = builtinSceneNames();
  for (const char* expected : {"corridor", "default", "diagonal", "plane-box"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
}

// SHADOWLAB_SCENE_DIR's value (given here, never set in this process) names the directory;
// names and loading by name use a directory given to them.
TEST(Scene, SceneDirFromEnvironment) {
  EXPECT_EQ(builtinSceneDir(SHADOWLAB_TEST_DATA), fs::path(SHADOWLAB_TEST_DATA));
  EXPECT_EQ(builtinSceneDir(""), builtinSceneDir(nullptr)) << "empty: unset";
  EXPECT_TRUE(fs::exists(builtinSceneDir(nullptr) / "plane-box.gltf"));
  const fs::path dir = builtinSceneDir(SHADOWLAB_TEST_DATA);
  std::vector<std::string> names = builtinSceneNames(dir);
  EXPECT_NE(std::find(names.begin(), names.end(), "cube"), names.end());
  SceneLoadResult cube = loadSceneByNameOrPath("cube", dir);
  ASSERT_TRUE(cube) << cube.error;
  EXPECT_EQ(cube.scene->name, "cube");
  SceneLoadResult elsewhere = loadSceneByNameOrPath("plane-box", dir);
  EXPECT_FALSE(elsewhere) << "plane-box is not in " << dir;
  EXPECT_NE(elsewhere.error.find("cube"), std::string::npos) << elsewhere.error;
}

TEST(Scene, EveryBuiltinSceneLoadsWithSunCamerasAndPath) {
  for (std::string name : {"plane-box", "diagonal", "corridor", "default"}) {
    SCOPED_TRACE(name);
    auto s = loadBuiltin(name);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->name, name);
    EXPECT_TRUE(s->warnings.empty()) << s->warnings.front();
    EXPECT_TRUE(s->light);
    EXPECT_FALSE(s->light->validate());
    EXPECT_GE(s->cameras.size(), 2u);
    for (const CameraBookmark& c : s->cameras) EXPECT_FALSE(c.camera.validate()) << c.name;
    ASSERT_EQ(s->paths.size(), 1u);
    EXPECT_NEAR(s->paths[0].durationS(), 10.0f, 1e-4f);
    EXPECT_FALSE(s->paths[0].sample(5.0f).validate());
    EXPECT_GT(s->triangleCount(), 0u);
    EXPECT_LT(s->triangleCount(), 20000u);
    EXPECT_TRUE(s->bounds.valid());
    EXPECT_NEAR(s->bounds.min.y, 0.0f, 1e-6f);  // everything stands on the ground at y = 0
    EXPECT_LT(fs::file_size(s->sourcePath), 2u * 1024u * 1024u);
    for (const MeshPrimitive& p : s->primitives) {
      ASSERT_EQ(p.normals.size(), p.positions.size());
      for (std::uint32_t i : p.indices) ASSERT_LT(i, p.positions.size());
      for (const glm::vec3& n : p.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-4f);
    }
  }
}

TEST(Scene, PlaneBoxGeometryAndSun) {
  auto s = loadBuiltin("plane-box");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->triangleCount(), 14u);  // ground quad + box
  EXPECT_NEAR(glm::length(s->bounds.min - glm::vec3(-10.0f, 0.0f, -10.0f)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::length(s->bounds.max - glm::vec3(10.0f, 1.01f, 10.0f)), 0.0f, 1e-5f);
  glm::vec3 l = s->light->directionalTowards();
  EXPECT_NEAR(glm::length(l - planebox::sunTowardsLight()), 0.0f, 1e-5f);
  EXPECT_NEAR(s->light->azimuthDeg, 30.0f, 1e-3f);
  EXPECT_NEAR(s->light->elevationDeg, 60.0f, 1e-3f);
  const CameraBookmark* overview = findCamera(*s, "overview");
  ASSERT_TRUE(overview);
  float dist = glm::length(overview->camera.position - overview->camera.target);
  EXPECT_NEAR(dist, 8.0f, 0.05f);  // looks down at the shadow's centre from 8 m
}

TEST(Scene, SpotBoxAndPointBoxCarryTheirPositionalLights) {
  for (std::string name : {"spot-box", "point-box"}) {
    SCOPED_TRACE(name);
    auto s = loadBuiltin(name);
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->warnings.empty()) << s->warnings.front();
    ASSERT_TRUE(s->light);
    EXPECT_FALSE(s->light->validate());
    EXPECT_GE(s->cameras.size(), 2u);
    EXPECT_LT(s->triangleCount(), 100u);
    EXPECT_NEAR(s->bounds.min.y, 0.0f, 1e-6f);
    EXPECT_GT(s->light->positionM.y, s->bounds.max.y);  // above everything
    EXPECT_TRUE(s->light->illuminates({0, 0, 0}));
  }
  auto spot = loadBuiltin("spot-box");
  ASSERT_TRUE(spot && spot->light);
  EXPECT_EQ(spot->light->type, LightType::Spot);
  EXPECT_NEAR(spot->light->outerConeDeg, 40.0f, 1e-3f);
  EXPECT_NEAR(spot->light->innerConeDeg, 30.0f, 1e-3f);
  EXPECT_NEAR(spot->light->rangeM, 20.0f, 1e-5f);
  EXPECT_NEAR(glm::length(spot->light->positionM - glm::vec3(1.5f, 5.0f, 2.0f)), 0.0f, 1e-5f);
  EXPECT_FALSE(spot->light->illuminates({6, 0, 6}));  // a ground corner outside the cone
  auto point = loadBuiltin("point-box");
  ASSERT_TRUE(point && point->light);
  EXPECT_EQ(point->light->type, LightType::Point);
  EXPECT_NEAR(point->light->rangeM, 15.0f, 1e-5f);
}

TEST(Scene, OmniRoomIsClosedWithCastersAboveAndBelowTheLight) {
  auto s = loadBuiltin("omni-room");
  ASSERT_TRUE(s && s->light);
  EXPECT_TRUE(s->warnings.empty());
  EXPECT_EQ(s->light->type, LightType::Point);
  EXPECT_LT(s->triangleCount(), 1000u);  // small: interactive on llvmpipe
  EXPECT_GE(s->cameras.size(), 3u);
  const glm::vec3 L = s->light->positionM;
  EXPECT_TRUE(glm::all(glm::greaterThan(L, s->bounds.min)) &&
              glm::all(glm::lessThan(L, s->bounds.max)));
  // Closed: every ray from the light hits the room.
  auto any = [](const glm::vec3&) { return true; };
  for (int i = 0; i < 200; ++i) {
    const float a = 2.399963f * float(i), y = 1.0f - 2.0f * (float(i) + 0.5f) / 200.0f;
    const float r = std::sqrt(1.0f - y * y);
    EXPECT_TRUE(rayHits(*s, L, {r * std::cos(a), y, r * std::sin(a)}, any)) << i;
  }
  // Shadows straight up and straight down: casters between the light and ceiling / floor.
  const float H = s->bounds.max.y;
  EXPECT_TRUE(rayHits(*s, L, {0, 1, 0}, [&](const glm::vec3& p) { return p.y < H - 0.01f; }));
  EXPECT_TRUE(rayHits(*s, L, {0, -1, 0}, [](const glm::vec3& p) { return p.y > 0.01f; }));
}

TEST(Scene, SpotYardConeReachesThreeCubeFaces) {
  auto s = loadBuiltin("spot-yard");
  ASSERT_TRUE(s && s->light);
  EXPECT_TRUE(s->warnings.empty());
  ASSERT_EQ(s->light->type, LightType::Spot);
  EXPECT_FALSE(s->light->validate());
  EXPECT_TRUE(s->light->illuminates({0.5f, 1.0f, 0.0f}));  // the first crate's top
  const std::uint32_t faces = omni::cubeFacesInCone(glm::dvec3(s->light->spotAxis()),
                                                    glm::radians(double(s->light->outerConeDeg)));
  EXPECT_EQ(faces, (1u << 0) | (1u << 3) | (1u << 4));  // +x, -y, +z
}

TEST(Scene, PlaneBoxAnalyticShadowMatchesRayCastGeometry) {
  auto s = loadBuiltin("plane-box");
  ASSERT_TRUE(s);
  const glm::vec3 l = s->light->directionalTowards();
  auto occluderOnly = [](const glm::vec3& p) { return p.y > 0.5f; };
  int inside = 0, compared = 0;
  for (int i = 0; i <= 125; ++i) {
    for (int j = 0; j <= 125; ++j) {
      const float x = -3.0f + 0.04f * float(i), z = -3.0f + 0.04f * float(j);
      glm::vec2 p(x, z);
      float sd = planeBoxShadowSignedDistanceM(p, l);
      bool analytic = planeBoxAnalyticShadow(p, l);
      if (std::abs(sd) > 1e-4f) {
        EXPECT_EQ(analytic, sd < 0.0f) << x << " " << z;
      }
      if (std::abs(sd) < 2e-3f) continue;  // too close to the outline for float ray casting
      bool traced = rayHits(*s, glm::vec3(x, 0.0f, z), l, occluderOnly);
      EXPECT_EQ(analytic, traced) << x << " " << z;
      inside += analytic;
      ++compared;
    }
  }
  EXPECT_GT(inside, 1500);  // about 4 m^2 of the 25 m^2 sampled at 0.04 m spacing
  EXPECT_GT(compared, 14000);
}

TEST(Scene, PlaneBoxAnalyticShadowIsTheTranslatedSquare) {
  const glm::vec3 l = planebox::sunTowardsLight();
  const glm::vec2 c = planebox::shadowOffsetXZ(1.0f, l);  // -h L.xz / L.y
  EXPECT_NEAR(c.x, -0.25f / std::sqrt(0.75f), 1e-6f);
  EXPECT_NEAR(c.y, -0.5f, 1e-6f);
  EXPECT_TRUE(planeBoxAnalyticShadow(c, l));
  EXPECT_TRUE(planeBoxAnalyticShadow(c + glm::vec2(0.99f, 0.99f), l));
  EXPECT_FALSE(planeBoxAnalyticShadow(c + glm::vec2(1.02f, 0.0f), l));
  EXPECT_FALSE(planeBoxAnalyticShadow(c + glm::vec2(0.0f, -1.02f), l));
  EXPECT_FALSE(planeBoxAnalyticShadow(glm::vec2(5.0f, 5.0f), l));
  // The outline: 6 corners (a square swept by 0.02 m of thickness), area just over 4 m^2.
  int n = 0;
  auto hull = planebox::shadowOutlineXZ(l, n);
  EXPECT_EQ(n, 6);
  float area = 0.0f;
  for (int i = 0; i < n; ++i) {
    glm::vec2 a = hull[std::size_t(i)], b = hull[std::size_t((i + 1) % n)];
    area += 0.5f * (a.x * b.y - a.y * b.x);
  }
  EXPECT_GT(area, 4.0f);
  EXPECT_LT(area, 4.0f + 0.1f);
  // A vertical light: the shadow is the square under the occluder.
  EXPECT_TRUE(planeBoxAnalyticShadow({0.99f, -0.99f}, {0, 1, 0}));
  EXPECT_FALSE(planeBoxAnalyticShadow({1.01f, 0.0f}, {0, 1, 0}));
  EXPECT_NEAR(planeBoxShadowSignedDistanceM({0.0f, 0.0f}, {0, 1, 0}), -1.0f, 1e-5f);
  EXPECT_NEAR(planeBoxShadowSignedDistanceM({3.0f, 0.0f}, {0, 1, 0}), 2.0f, 1e-5f);
  // Light at or below the horizon: no shadow is defined.
  EXPECT_FALSE(planeBoxAnalyticShadow({0.0f, 0.0f}, {1, 0, 0}));
}

TEST(Scene, DiagonalRowLiesAt45DegreesInTheLightImage) {
  auto s = loadBuiltin("diagonal");
  ASSERT_TRUE(s);
  // The light's image axes in the usual light view (lookAt along -L with world +y up).
  glm::vec3 forward = -s->light->directionalTowards();
  glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
  glm::vec3 up = glm::cross(right, forward);
  glm::vec3 row(1, 0, 0);  // the posts stand along +x
  float angle =
      glm::degrees(std::atan2(std::abs(glm::dot(row, up)), std::abs(glm::dot(row, right))));
  EXPECT_NEAR(angle, 45.0f, 1.0f);
  EXPECT_GT(s->triangleCount(), 40u * 12u);  // ~40 posts
  // The first camera stands at the row's end and looks along it.
  const Camera& c = s->cameras[0].camera;
  EXPECT_LT(c.position.x, 0.0f);
  EXPECT_GT(glm::dot(c.forward(), row), 0.9f);
}

TEST(Scene, CorridorSpansTenCentimetresToAKilometre) {
  auto s = loadBuiltin("corridor");
  ASSERT_TRUE(s);
  EXPECT_LE(s->bounds.min.z, -1000.0f);
  EXPECT_LE(s->bounds.size().x, 4.01f);  // narrow
  const CameraBookmark* start = findCamera(*s, "start");
  ASSERT_TRUE(start);
  EXPECT_FLOAT_EQ(start->camera.nearM, 0.05f);
  EXPECT_FLOAT_EQ(start->camera.farM, 1200.0f);
  // Occluders (above the floor) near 0.1 m and near 1 km in front of the camera at z = 0.
  bool nearFrame = false, farFrame = false;
  for (const MeshPrimitive& p : s->primitives) {
    for (const glm::vec3& v : p.positions) {
      if (v.y < 0.1f) continue;  // the floor
      nearFrame |= v.z > -0.15f && v.z < -0.05f;
      farFrame |= v.z < -990.0f;
    }
  }
  EXPECT_TRUE(nearFrame);
  EXPECT_TRUE(farFrame);
}

TEST(Scene, DefaultHasAnAlphaMaskedTexture) {
  auto s = loadBuiltin("default");
  ASSERT_TRUE(s);
  int masked = 0;
  for (const Material& m : s->materials) {
    if (m.alphaMode != AlphaMode::Mask) continue;
    ++masked;
    ASSERT_GE(m.baseColorTexture, 0);
    const SceneImage& img = s->images[std::size_t(m.baseColorTexture)];
    ASSERT_EQ(img.rgba.size(), std::size_t(img.width * img.height * 4));
    int clear = 0, opaque = 0;
    for (std::size_t i = 3; i < img.rgba.size(); i += 4)
      clear += img.rgba[i] == 0, opaque += img.rgba[i] == 255;
    EXPECT_GT(clear, 0) << m.name;
    EXPECT_GT(opaque, 0) << m.name;
    EXPECT_TRUE(m.doubleSided) << m.name;
  }
  EXPECT_GE(masked, 2);  // fence pickets and leaves
}

TEST(Scene, UnknownNameListsTheBuiltinScenes) {
  SceneLoadResult r = loadSceneByNameOrPath("nope");
  EXPECT_FALSE(r);
  EXPECT_NE(r.error.find("unknown scene 'nope'"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("plane-box"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("corridor"), std::string::npos) << r.error;
}

TEST(Scene, PathsLoadThroughLoadSceneByNameOrPath) {
  SceneLoadResult r = loadSceneByNameOrPath(std::string(SHADOWLAB_TEST_DATA) + "/cube.glb");
  ASSERT_TRUE(r) << r.error;
  EXPECT_EQ(r.scene->name, "cube");
  SceneLoadResult missing = loadSceneByNameOrPath("no/such/file.gltf");
  EXPECT_FALSE(missing);
  EXPECT_NE(missing.error.find("no/such/file.gltf: file not found"), std::string::npos)
      << missing.error;
}

TEST(Scene, TriangleCountAndDefaultMaterial) {
  Scene s;
  MeshPrimitive a, b;
  a.indices = {0, 1, 2, 0, 2, 3};
  b.indices = {0, 1, 2};
  b.material = 0;
  s.primitives = {a, b};
  s.materials.push_back(Material{"red", glm::vec4(1, 0, 0, 1)});
  EXPECT_EQ(s.triangleCount(), 3u);
  EXPECT_EQ(s.materialOf(s.primitives[1]).name, "red");
  const Material& fallback = s.materialOf(s.primitives[0]);
  EXPECT_EQ(fallback.baseColorFactor, glm::vec4(1.0f));
  EXPECT_EQ(fallback.alphaMode, AlphaMode::Opaque);
  EXPECT_FALSE(fallback.doubleSided);
  s.primitives[0].material = 7;  // out of range -> the default too
  EXPECT_EQ(&s.materialOf(s.primitives[0]), &fallback);
}

TEST(Scene, DefaultCameraFramesTheBounds) {
  Scene s;
  s.bounds.extend(glm::vec3(-30.0f, 0.0f, -5.0f));
  s.bounds.extend(glm::vec3(10.0f, 4.0f, 5.0f));
  Camera c = s.defaultCamera();
  EXPECT_FALSE(c.validate());
  glm::mat4 vp = c.projection(1.0f) * c.view();
  for (const glm::vec3& corner : s.bounds.corners()) {
    glm::vec4 clip = vp * glm::vec4(corner, 1.0f);
    ASSERT_GT(clip.w, 0.0f);
    glm::vec3 ndc = glm::vec3(clip) / clip.w;
    EXPECT_LE(std::abs(ndc.x), 1.0f);
    EXPECT_LE(std::abs(ndc.y), 1.0f);
    EXPECT_LE(std::abs(ndc.z), 1.0f);  // between near and far
  }
  EXPECT_FALSE(Scene{}.defaultCamera().validate());  // no geometry: still a usable camera
}

TEST(SceneCameraPath, SampleLerpsPositionSlerpsRotationAndClamps) {
  CameraPath path;
  path.fovYDeg = 40.0f;
  path.nearM = 0.2f;
  path.farM = 90.0f;
  glm::quat turned = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
  path.keys = {{0.0f, {0, 1, 0}, glm::quat(1, 0, 0, 0)}, {2.0f, {2, 1, 0}, turned}};
  Camera mid = path.sample(1.0f);
  EXPECT_NEAR(glm::length(mid.position - glm::vec3(1, 1, 0)), 0.0f, 1e-6f);
  float s45 = std::sqrt(0.5f);
  EXPECT_NEAR(glm::length(mid.forward() - glm::vec3(-s45, 0, -s45)), 0.0f, 1e-5f);
  EXPECT_EQ(mid.fovYDeg, 40.0f);
  EXPECT_EQ(mid.nearM, 0.2f);
  EXPECT_EQ(mid.farM, 90.0f);
  EXPECT_EQ(path.sample(-5.0f).position, glm::vec3(0, 1, 0));
  EXPECT_EQ(path.sample(50.0f).position, glm::vec3(2, 1, 0));
  EXPECT_NEAR(glm::length(path.sample(50.0f).forward() - glm::vec3(-1, 0, 0)), 0.0f, 1e-5f);
  EXPECT_FLOAT_EQ(path.durationS(), 2.0f);
  EXPECT_FALSE(CameraPath{}.sample(1.0f).validate());  // empty: a default, valid camera
}

TEST(SceneCameraPath, StraightDownPoseStaysValid) {
  // Looking along -y: world up is parallel to the view, so the pose's own +y is used.
  glm::quat down = glm::angleAxis(glm::radians(-90.0f), glm::vec3(1, 0, 0));
  Camera c = cameraFromPose({0, 10, 0}, down, 50.0f, 0.1f, 100.0f, 10.0f);
  EXPECT_FALSE(c.validate());
  EXPECT_NEAR(glm::length(c.target - glm::vec3(0, 0, 0)), 0.0f, 1e-5f);
}

}  // namespace
}  // namespace sl
