// The flattening's light, camera bookmarks and camera paths (Flattener.h):
// KHR_lights_punctual's one light, perspective cameras placed from their nodes, animated
// camera nodes sampled into paths.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "scene/gltf/Accessors.h"
#include "scene/gltf/Flattener.h"

namespace sl::gltf {

void Flattener::addLights() {
  struct Candidate {
    Light light;
    std::string label;  ///< "spot light 'lamp'"
  };
  std::vector<Candidate> found;
  for (const NodeInstance& inst : instances_) {
    const tinygltf::Node& node = model_.nodes[std::size_t(inst.node)];
    auto it = node.extensions.find("KHR_lights_punctual");
    if (it == node.extensions.end() || !it->second.IsObject()) continue;
    const tinygltf::Value& ref = it->second.Get("light");
    if (!ref.IsNumber()) continue;
    int index = ref.GetNumberAsInt();
    if (index < 0 || std::size_t(index) >= model_.lights.size()) {
      warn(nodeName(inst.node) + ": light " + std::to_string(index) + " does not exist, ignored");
      continue;
    }
    const tinygltf::Light& gl = model_.lights[std::size_t(index)];
    std::string name = gl.name.empty() ? "light " + std::to_string(index) : inQuotes(gl.name);
    std::optional<LightType> type = lightTypeFromName(gl.type);
    if (!type) {
      warn("light " + name + " of unknown type '" + gl.type + "' ignored");
      continue;
    }
    const std::string label = gl.type + " light " + name;
    // glTF lights shine along their node's -z: the light lies towards +z.
    glm::dvec3 towards = glm::dvec3(inst.world * glm::dvec4(0.0, 0.0, 1.0, 0.0));
    glm::dvec3 position = glm::dvec3(inst.world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    double len = glm::length(towards);
    if (*type != LightType::Point && (!(len > 0.0) || !std::isfinite(len))) {
      warn(label + " has a degenerate node transform, ignored");
      continue;
    }
    Light light;
    if (*type == LightType::Directional) {
      light = Light::directionalFromTowards(glm::vec3(towards / len));
    } else {
      light.type = *type;
      light.positionM = glm::vec3(position);
      light.rangeM = float(gl.range);
      if (*type == LightType::Spot) {
        light.direction = -glm::vec3(towards / len);
        light.outerConeDeg = float(glm::degrees(gl.spot.outerConeAngle));
        light.innerConeDeg = float(glm::degrees(gl.spot.innerConeAngle));
        // glTF allows up to 90 degrees; every light ShadowLab renders stays within
        // kMaxSpotConeDeg (Light::validate refuses wider cones from other inputs).
        if (light.outerConeDeg > kMaxSpotConeDeg && light.outerConeDeg <= 90.0f) {
          char angle[32];
          std::snprintf(angle, sizeof angle, "%.7g", double(light.outerConeDeg));
          warn(label + ": outer cone angle " + angle + " degrees narrowed to " +
               std::to_string(int(kMaxSpotConeDeg)) +
               " (kMaxSpotConeDeg: one perspective shadow map covers less than a "
               "half-space)");
          light.outerConeDeg = kMaxSpotConeDeg;
          light.innerConeDeg = std::min(light.innerConeDeg, light.outerConeDeg);
        }
      }
      if (gl.intensity <= 0.0) warn(label + " has no intensity; it still casts shadows");
    }
    if (auto err = light.validate()) {
      warn(label + " ignored: " + *err);
      continue;
    }
    found.push_back({light, label});
  }
  std::size_t chosen = found.size();
  for (std::size_t i = 0; i < found.size() && chosen == found.size(); ++i)
    if (found[i].light.type == LightType::Directional) chosen = i;
  if (chosen == found.size() && !found.empty()) chosen = 0;
  for (std::size_t i = 0; i < found.size(); ++i) {
    if (i == chosen) continue;
    warn(found[i].label +
         " ignored (ShadowLab lights the scene with one light: " + found[chosen].label + ")");
  }
  if (chosen < found.size()) scene_.light = found[chosen].light;
  if (!scene_.light)
    warn("no directional light (KHR_lights_punctual): the scene has no sun of its own");
}

float Flattener::firstHit(const glm::vec3& origin, const glm::vec3& dir) {
  if (!bvh_) {
    std::vector<TriangleMeshView> meshes;
    meshes.reserve(scene_.primitives.size());
    for (const MeshPrimitive& prim : scene_.primitives)
      meshes.push_back({prim.positions, prim.indices});
    bvh_.emplace(std::move(meshes));
  }
  return bvh_->firstHit(origin, dir);
}

float Flattener::farFromBounds(const glm::vec3& position, float nearM) const {
  float far = 0.0f;
  for (const glm::vec3& c : scene_.bounds.corners())
    far = std::max(far, glm::distance(position, c));
  return std::max(far * 1.05f, nearM * 10.0f);
}

std::optional<Flattener::CameraLens> Flattener::lensOf(int cameraIndex, const std::string& where) {
  if (cameraIndex < 0 || std::size_t(cameraIndex) >= model_.cameras.size()) {
    warn(where + ": camera " + std::to_string(cameraIndex) + " does not exist, ignored");
    return std::nullopt;
  }
  const tinygltf::Camera& cam = model_.cameras[std::size_t(cameraIndex)];
  if (cam.type != "perspective") {
    warnOnce("ortho" + std::to_string(cameraIndex),
             where + ": " + (cam.type.empty() ? "untyped" : cam.type) +
                 " camera ignored (only perspective cameras become bookmarks)");
    return std::nullopt;
  }
  CameraLens lens;
  double fov = glm::degrees(cam.perspective.yfov);
  if (fov > 1.0 && fov < 170.0) {
    lens.fovYDeg = float(fov);
  } else {
    warn(where + ": yfov out of range, using 50 degrees");
  }
  // glTF: 0 < znear < zfar (zfar absent: infinite, the far plane then comes from the
  // scene's bounds). Anything else is said, not silently replaced.
  const double znear = cam.perspective.znear, zfar = cam.perspective.zfar;
  auto metres = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g m", v);
    return std::string(buf);
  };
  if (!(znear > 0.0) || !std::isfinite(znear)) {
    warn(where + ": znear " + metres(znear) + " is not above 0, using " + metres(lens.nearM));
  } else if (znear < double(Camera::kMinNearM)) {
    lens.nearM = Camera::kMinNearM;
    warn(where + ": znear " + metres(znear) + " is below " + metres(Camera::kMinNearM) +
         ", using that");
  } else {
    lens.nearM = float(znear);
  }
  if (zfar > double(lens.nearM) && zfar <= double(Camera::kMaxFarM)) {
    lens.farM = float(zfar);
  } else if (zfar > double(Camera::kMaxFarM)) {
    lens.farM = Camera::kMaxFarM;
    warn(where + ": zfar " + metres(zfar) + " is beyond " + metres(Camera::kMaxFarM) +
         ", using that");
  } else if (zfar != 0.0) {
    warn(where + ": zfar " + metres(zfar) + " is not beyond znear " + metres(lens.nearM) +
         ", ignored (the far plane comes from the scene's bounds)");
  }
  return lens;
}

std::string Flattener::cameraName(const NodeInstance& inst) const {
  const tinygltf::Node& node = model_.nodes[std::size_t(inst.node)];
  const tinygltf::Camera& cam = model_.cameras[std::size_t(node.camera)];
  if (!cam.name.empty()) return cam.name;
  if (!node.name.empty()) return node.name;
  return "camera " + std::to_string(scene_.cameras.size() + 1);
}

float Flattener::nearWithinDepthPrecision(float nearM, float farM, const std::string& where) {
  if (!Camera::depthPrecisionError(nearM, farM)) return nearM;
  const float raised = farM / Camera::kMaxFarOverNear;
  char buf[160];
  std::snprintf(buf, sizeof buf,
                ": znear %.3g m raised to %.3g m (far %.3g m; kMaxFarOverNear, float depth "
                "precision)",
                double(nearM), double(raised), double(farM));
  warn(where + buf);
  return raised;
}

void Flattener::addCameras() {
  for (const NodeInstance& inst : instances_) {
    const tinygltf::Node& node = model_.nodes[std::size_t(inst.node)];
    if (node.camera < 0) continue;
    std::optional<CameraLens> lens = lensOf(node.camera, nodeName(inst.node));
    if (!lens) continue;
    glm::vec3 position;
    glm::quat rotation;
    decomposePose(inst.world, position, rotation);
    float far = lens->farM > 0.0f ? lens->farM : farFromBounds(position, lens->nearM);
    lens->nearM = nearWithinDepthPrecision(lens->nearM, far, "camera " + nodeName(inst.node));
    glm::vec3 forward = glm::normalize(rotation * glm::vec3(0.0f, 0.0f, -1.0f));
    // Orbit target: what the camera looks at, else the point nearest the scene centre.
    float dist = firstHit(position, forward);
    if (!(dist > lens->nearM && dist < far))
      dist = std::max(glm::dot(scene_.bounds.center() - position, forward), 1.0f);
    CameraBookmark bookmark;
    bookmark.name = cameraName(inst);
    bookmark.camera = cameraFromPose(position, rotation, lens->fovYDeg, lens->nearM, far, dist);
    if (auto problem = bookmark.camera.validate()) {
      warn("camera " + inQuotes(bookmark.name) + " ignored: " + Camera::withoutPrefix(*problem));
      continue;
    }
    scene_.cameras.push_back(std::move(bookmark));
  }
}

Flattener::Track Flattener::readTrack(const tinygltf::Animation& anim,
                                      const tinygltf::AnimationChannel& channel,
                                      const std::string& label) {
  if (channel.sampler < 0 || std::size_t(channel.sampler) >= anim.samplers.size())
    fail(label + ": sampler " + std::to_string(channel.sampler) + " is out of range");
  const tinygltf::AnimationSampler& sampler = anim.samplers[std::size_t(channel.sampler)];
  Track track;
  track.rotation = channel.target_path == "rotation";
  track.step = sampler.interpolation == "STEP";
  bool cubic = sampler.interpolation == "CUBICSPLINE";
  if (cubic) warn(label + ": CUBICSPLINE keys are followed linearly (tangents ignored)");
  track.times = readFloats(model_, sampler.input, "times of " + label, TINYGLTF_TYPE_SCALAR);
  int type = track.rotation ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3;
  std::vector<float> out = readFloats(model_, sampler.output, "values of " + label, type);
  std::size_t comps = track.rotation ? 4 : 3;
  std::size_t perKey = cubic ? 3 : 1;  // cubic: in-tangent, value, out-tangent
  if (track.times.empty() || out.size() != track.times.size() * comps * perKey)
    fail(label + ": " + std::to_string(track.times.size()) + " key times but " +
         std::to_string(out.size() / comps) + " values");
  for (std::size_t k = 0; k < track.times.size(); ++k) {
    if (!std::isfinite(track.times[k]) || (k > 0 && track.times[k] < track.times[k - 1]))
      fail(label + ": key times must be finite and increasing");
    const float* v = &out[(k * perKey + (cubic ? 1 : 0)) * comps];
    for (std::size_t c = 0; c < comps; ++c)
      if (!std::isfinite(v[c]))
        fail(label + ": key " + std::to_string(k) + " (at " + secondsText(track.times[k]) +
             ") has a value that is not finite");
    track.values.emplace_back(v[0], v[1], v[2], track.rotation ? v[3] : 0.0f);
  }
  return track;
}

void Flattener::addPaths() {
  // Parent world matrix of each camera node (its first instance).
  std::map<int, const NodeInstance*> cameraNodes;
  for (const NodeInstance& inst : instances_)
    if (model_.nodes[std::size_t(inst.node)].camera >= 0) cameraNodes.emplace(inst.node, &inst);

  for (std::size_t a = 0; a < model_.animations.size(); ++a) {
    const tinygltf::Animation& anim = model_.animations[a];
    std::string animName = anim.name.empty() ? "animation " + std::to_string(a) : anim.name;
    std::map<int, std::vector<Track>> translation, rotation;  // by camera node
    for (std::size_t c = 0; c < anim.channels.size(); ++c) {
      const tinygltf::AnimationChannel& ch = anim.channels[c];
      std::string label = "animation " + inQuotes(animName) + " channel " + std::to_string(c);
      if (ch.target_node < 0 || std::size_t(ch.target_node) >= model_.nodes.size())
        fail(label + ": target node " + std::to_string(ch.target_node) + " is out of range");
      if (!cameraNodes.count(ch.target_node)) {
        warnOnce("anim" + std::to_string(a),
                 "animation " + inQuotes(animName) +
                     " moves non-camera nodes; they are shown in their rest pose");
        continue;
      }
      if (ch.target_path == "translation") {
        translation[ch.target_node].push_back(readTrack(anim, ch, label));
      } else if (ch.target_path == "rotation") {
        rotation[ch.target_node].push_back(readTrack(anim, ch, label));
      } else {
        warn(label + ": " + ch.target_path + " of a camera ignored");
      }
    }
    std::set<int> animated;
    for (auto& [node, tracks] : translation) animated.insert(node);
    for (auto& [node, tracks] : rotation) animated.insert(node);
    for (int node : animated) {
      const NodeInstance& inst = *cameraNodes.at(node);
      std::optional<CameraLens> lens =
          lensOf(model_.nodes[std::size_t(node)].camera, nodeName(node));
      if (!lens) continue;
      const Track* tTrack = translation.count(node) ? &translation[node].back() : nullptr;
      const Track* rTrack = rotation.count(node) ? &rotation[node].back() : nullptr;
      CameraPath path;
      path.name = animated.size() > 1 ? animName + " (" + cameraName(inst) + ")" : animName;
      path.keys = sampleKeys(inst, tTrack, rTrack);
      path.fovYDeg = lens->fovYDeg;
      path.nearM = lens->nearM;
      float far = lens->farM;
      if (!(far > 0.0f))
        for (const CameraKey& k : path.keys)
          far = std::max(far, farFromBounds(k.position, lens->nearM));
      path.farM = far;
      path.nearM = nearWithinDepthPrecision(path.nearM, far, "camera path " + inQuotes(path.name));
      scene_.paths.push_back(std::move(path));
    }
  }
}

std::vector<CameraKey> Flattener::sampleKeys(const NodeInstance& inst, const Track* tTrack,
                                             const Track* rTrack) const {
  std::vector<float> times;
  for (const Track* tr : {tTrack, rTrack}) {
    if (!tr) continue;
    for (std::size_t k = 0; k < tr->times.size(); ++k) {
      times.push_back(tr->times[k]);
      if (tr->step && k > 0)
        times.push_back(std::nextafter(tr->times[k], -std::numeric_limits<float>::infinity()));
    }
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  const tinygltf::Node& node = model_.nodes[std::size_t(inst.node)];
  std::vector<CameraKey> keys;
  for (float t : times) {
    tinygltf::Node posed = node;
    posed.matrix.clear();
    if (node.matrix.size() == 16) {
      // Animated nodes use TRS; a matrix node's animation replaces its decomposition.
      glm::vec3 p;
      glm::quat q;
      decomposePose(localMatrix(node), p, q);
      posed.translation = {p.x, p.y, p.z};
      posed.rotation = {q.x, q.y, q.z, q.w};
    }
    if (tTrack) {
      glm::vec4 v = tTrack->at(t);
      posed.translation = {v.x, v.y, v.z};
    }
    if (rTrack) {
      glm::vec4 v = rTrack->at(t);
      posed.rotation = {v.x, v.y, v.z, v.w};
    }
    CameraKey key;
    key.timeS = t;
    decomposePose(inst.parentWorld * localMatrix(posed), key.position, key.rotation);
    const float pose[7] = {key.position.x, key.position.y, key.position.z, key.rotation.x,
                           key.rotation.y, key.rotation.z, key.rotation.w};
    if (!std::all_of(std::begin(pose), std::end(pose), [](float v) { return std::isfinite(v); }))
      fail("camera " + inQuotes(cameraName(inst)) + ": its animated pose at " + secondsText(t) +
           " is not finite");
    keys.push_back(key);
  }
  return keys;
}

}  // namespace sl::gltf
