// Storage factor of warped and partitioned shadow maps (Lloyd et al., EGSR 2006, §4-5):
// beam widths at the vertices of each partition, summed over partitions.
#include "StorageFactor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sl::partition {

using warp::ViewFrustum;
using warp::WarpFit;
using warp::WarpKind;
using warp::WarpSettings;

const char* schemeName(Scheme s) {
  switch (s) {
    case Scheme::Uniform:
      return "uniform";
    case Scheme::Eta:
      return "eta";
    case Scheme::Lispsm:
      return "lispsm";
    case Scheme::Psm:
      return "psm";
    case Scheme::Tsm:
      return "tsm";
    case Scheme::Cascades:
      return "cascades";
    case Scheme::Face:
      return "face";
    case Scheme::FaceCascades:
      return "face+cascades";
  }
  return "?";
}

std::optional<Scheme> parseScheme(const std::string& name) {
  for (Scheme s : {Scheme::Uniform, Scheme::Eta, Scheme::Lispsm, Scheme::Psm, Scheme::Tsm,
                   Scheme::Cascades, Scheme::Face, Scheme::FaceCascades})
    if (name == schemeName(s)) return s;
  return std::nullopt;
}

const char* faceName(int face) {
  static const char* names[] = {"near", "far", "-x", "+x", "-y", "+y"};
  return face >= 0 && face < 6 ? names[face] : "?";
}

double imageBeamWidth(const ViewFrustum& view, const glm::dvec3& world) {
  return 2.0 * view.tanHalfY() * glm::dot(world - view.eye, view.forward);
}

glm::dvec2 aliasingAt(const ViewFrustum& view, const WarpFit& fit, const glm::dvec3& world) {
  return fit.beamWidths(world) / imageBeamWidth(view, world);
}

Storage storageOfBody(const ViewFrustum& view, const WarpFit& fit,
                      const std::vector<glm::dvec3>& body) {
  Storage st;
  for (const glm::dvec3& p : body) {
    const glm::dvec2 m = aliasingAt(view, fit, p);
    st.mx = std::max(st.mx, m.x);
    st.mz = std::max(st.mz, m.y);
  }
  st.s = st.mx * st.mz;
  return st;
}

namespace {

struct Plane {  // inside: dot(n, p) <= d
  glm::dvec3 n;
  double d;
};

/// Vertices of the convex polytope {p : dot(n_i, p) <= d_i} (bounded), by plane triples.
std::vector<glm::dvec3> polytopeVertices(const std::vector<Plane>& planes, double scale) {
  std::vector<glm::dvec3> out;
  const double tol = 1e-9 * scale;
  for (std::size_t i = 0; i < planes.size(); ++i)
    for (std::size_t j = i + 1; j < planes.size(); ++j)
      for (std::size_t k = j + 1; k < planes.size(); ++k) {
        const glm::dmat3 m = glm::transpose(glm::dmat3(planes[i].n, planes[j].n, planes[k].n));
        const double det = glm::determinant(m);
        if (std::abs(det) < 1e-12) continue;
        const glm::dvec3 p = glm::inverse(m) * glm::dvec3(planes[i].d, planes[j].d, planes[k].d);
        bool inside = true;
        for (const Plane& q : planes) inside = inside && glm::dot(q.n, p) <= q.d + tol;
        if (!inside) continue;
        bool dup = false;
        for (const glm::dvec3& o : out) dup = dup || glm::length(o - p) <= 1e-7 * scale;
        if (!dup) out.push_back(p);
      }
  return out;
}

// Corner indices of each face (ViewFrustum::corners order), near corners of side faces first.
constexpr std::array<std::array<int, 4>, 6> kFaces = {
    {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 3, 7, 4}, {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 2, 6, 7}}};

}  // namespace

std::array<glm::dvec4, 6> frustumFacePlanes(const ViewFrustum& view, double a, double b) {
  const std::array<glm::dvec3, 8> c = view.corners(a, b);
  glm::dvec3 centroid(0.0);
  for (const glm::dvec3& p : c) centroid += p / 8.0;
  std::array<glm::dvec4, 6> out;
  for (int f = 0; f < 6; ++f) {
    const auto& q = kFaces[std::size_t(f)];
    glm::dvec3 n = glm::normalize(glm::cross(c[std::size_t(q[1])] - c[std::size_t(q[0])],
                                             c[std::size_t(q[3])] - c[std::size_t(q[0])]));
    if (glm::dot(n, centroid - c[std::size_t(q[0])]) > 0.0) n = -n;  // outward
    out[std::size_t(f)] = glm::dvec4(n, glm::dot(n, c[std::size_t(q[0])]));
  }
  return out;
}

std::vector<FacePartition> facePartitions(const ViewFrustum& view, double a, double b,
                                          const glm::dvec3& towardsLight,
                                          const std::optional<glm::dvec3>& clipMin,
                                          const std::optional<glm::dvec3>& clipMax,
                                          const std::optional<glm::dvec2>& depthSlab) {
  const std::array<glm::dvec3, 8> c = view.corners(a, b);
  const glm::dvec3 y = glm::normalize(towardsLight);
  const double scale = std::max(b, glm::length(c[7] - c[0]));
  std::vector<Plane> frustum;
  std::array<glm::dvec3, 6> normals;
  const std::array<glm::dvec4, 6> planes6 = frustumFacePlanes(view, a, b);
  for (int f = 0; f < 6; ++f) {
    normals[std::size_t(f)] = glm::dvec3(planes6[std::size_t(f)]);
    frustum.push_back({normals[std::size_t(f)], planes6[std::size_t(f)].w});
  }
  if (clipMin && clipMax)
    for (int axis = 0; axis < 3; ++axis) {
      glm::dvec3 n(0.0);
      n[axis] = 1.0;
      frustum.push_back({n, (*clipMax)[axis]});
      frustum.push_back({-n, -(*clipMin)[axis]});
    }
  if (depthSlab) {
    const double e = glm::dot(view.forward, view.eye);
    frustum.push_back({view.forward, depthSlab->y + e});
    frustum.push_back({-view.forward, -(depthSlab->x + e)});
  }
  // Front faces (towards the light) when v . y < 0, back faces otherwise (§5.1).
  const bool front = glm::dot(view.forward, y) < 0.0;
  std::vector<FacePartition> out;
  for (int f = 0; f < 6; ++f) {
    const double d = glm::dot(normals[std::size_t(f)], y);
    if (!(front ? d > 1e-9 : d < -1e-9)) continue;
    const auto& q = kFaces[std::size_t(f)];
    glm::dvec3 fc(0.0);
    for (int i : q) fc += c[std::size_t(i)] / 4.0;
    std::vector<Plane> planes = frustum;
    for (int e = 0; e < 4; ++e) {  // the prism through the face's edges along the light
      const glm::dvec3 A = c[std::size_t(q[std::size_t(e)])];
      const glm::dvec3 B = c[std::size_t(q[std::size_t((e + 1) % 4)])];
      glm::dvec3 m = glm::cross(B - A, y);
      if (glm::length(m) < 1e-12 * scale) continue;
      m = glm::normalize(m);
      if (glm::dot(m, fc - A) < 0.0) m = -m;  // m points inside
      planes.push_back({-m, -glm::dot(m, A)});
    }
    FacePartition part;
    part.face = f;
    part.body = polytopeVertices(planes, scale);
    if (part.body.size() < 4) continue;
    if (f >= 2) {  // a side face: its two edges from the near to the far plane
      const glm::dvec3 e0 = c[std::size_t(q[0] + 4)] - c[std::size_t(q[0])];
      const glm::dvec3 e1 = c[std::size_t(q[1] + 4)] - c[std::size_t(q[1])];
      part.axis = glm::normalize(glm::normalize(e0) + glm::normalize(e1));
      glm::dvec3 p0 = e0 - glm::dot(e0, y) * y, p1 = e1 - glm::dot(e1, y) * y;
      if (glm::length(p0) > 1e-12 && glm::length(p1) > 1e-12) {
        const glm::dvec3 bis = glm::normalize(p0) + glm::normalize(p1);
        if (glm::length(bis) > 1e-9) part.bisector = glm::normalize(bis);
      }
      if (!part.bisector) part.axis.reset();
    }
    out.push_back(std::move(part));
  }
  return out;
}

std::optional<std::string> evaluateScheme(const ViewFrustum& view, const glm::dvec3& towardsLight,
                                          const SchemeSettings& st, StorageResult& out) {
  if (auto e = view.validate()) return e;
  if (!(glm::length(towardsLight) > 1e-12) || !std::isfinite(glm::length(towardsLight)))
    return "storage: the light direction is zero or not finite";
  const bool partitioned = st.scheme == Scheme::Cascades || st.scheme == Scheme::FaceCascades;
  if (st.partitions < 1 || st.partitions > 64) return "storage: partitions must be in 1..64";
  std::vector<double> z{view.nearM, view.farM};
  if (partitioned) {
    if (!st.customSplits.empty()) {
      z = st.customSplits;
      if (z.size() < 2 || std::abs(z.front() - view.nearM) > 1e-9 * view.farM ||
          std::abs(z.back() - view.farM) > 1e-9 * view.farM)
        return "storage: custom splits must run from near to far";
      for (std::size_t i = 1; i < z.size(); ++i)
        if (!(z[i] > z[i - 1])) return "storage: custom splits must increase";
    } else {
      try {
        z = splitDistances(st.split, view.nearM, view.farM, st.partitions, st.lambda);
      } catch (const std::invalid_argument& e) {
        return std::string("storage: ") + e.what();
      }
    }
  }
  StorageResult res;
  auto add = [&](std::string label, std::vector<glm::dvec3> body,
                 const WarpSettings& ws) -> std::optional<std::string> {
    PartStorage p;
    p.label = std::move(label);
    p.body = std::move(body);
    if (auto e = warp::fitWarp(view, p.body, towardsLight, ws, p.fit)) return e;
    p.storage = storageOfBody(view, p.fit, p.body);
    res.s += p.storage.s;
    res.mx = std::max(res.mx, p.storage.mx);
    res.mz = std::max(res.mz, p.storage.mz);
    res.parts.push_back(std::move(p));
    return std::nullopt;
  };
  auto faces = [&](double a, double b, const std::string& prefix) -> std::optional<std::string> {
    for (FacePartition& f : facePartitions(view, a, b, towardsLight)) {
      WarpSettings ws;
      ws.kind = WarpKind::Lispsm;
      ws.axis = f.axis;
      if (f.axis) ws.projectedAxis = f.bisector;
      if (auto e = add(prefix + "face " + faceName(f.face), std::move(f.body), ws)) return e;
    }
    return std::nullopt;
  };
  auto corners = [&](double a, double b) {
    const auto c = view.corners(a, b);
    return std::vector<glm::dvec3>(c.begin(), c.end());
  };
  WarpSettings ws;
  std::optional<std::string> err;
  switch (st.scheme) {
    case Scheme::Uniform:
      ws.kind = WarpKind::Uniform;
      break;
    case Scheme::Eta:
      if (!(st.eta >= -1.0 && st.eta <= 1.0)) return "storage: eta must be in [-1, 1]";
      ws.kind = WarpKind::Eta;
      ws.eta = st.eta;
      break;
    case Scheme::Lispsm:
      ws.kind = WarpKind::Lispsm;
      break;
    case Scheme::Psm:
      ws.kind = WarpKind::Psm;
      break;
    case Scheme::Tsm:
      ws.kind = WarpKind::Tsm;
      ws.tsmFocusFraction = st.tsmFocusFraction;
      break;
    default:
      break;
  }
  switch (st.scheme) {
    case Scheme::Cascades:
      for (std::size_t i = 0; i + 1 < z.size(); ++i) {
        WarpSettings part;
        part.kind = st.partitionWarp ? WarpKind::Lispsm : WarpKind::Uniform;
        err = add("z " + std::to_string(i + 1) + "/" + std::to_string(z.size() - 1),
                  corners(z[i], z[i + 1]), part);
        if (err) return err;
      }
      break;
    case Scheme::Face:
      err = faces(view.nearM, view.farM, "");
      break;
    case Scheme::FaceCascades:
      for (std::size_t i = 0; i + 1 < z.size() && !err; ++i)
        err = faces(z[i], z[i + 1],
                    "z " + std::to_string(i + 1) + "/" + std::to_string(z.size() - 1) + " ");
      break;
    default:
      err = add("whole", corners(view.nearM, view.farM), ws);
      break;
  }
  if (err) return err;
  if (res.parts.empty()) return "storage: no partition covers the view frustum";
  out = std::move(res);
  return std::nullopt;
}

namespace overhead {

double mx(double z, double np, double n, double f) {
  if (std::isinf(np)) return f / z;
  return f * (np + z - n) / (z * (np + f - n));
}
double mz(double z, double np, double n, double f, double t) {
  if (std::isinf(np)) return (f - n) / (2.0 * t * z);
  return (f - n) / (2.0 * t * z) * (np + z - n) * (np + z - n) / (np * (np + f - n));
}
double maxMx(double np, double n, double f) {
  if (std::isinf(np)) return f / n;
  return f * np / (n * (np + f - n));
}
double maxMz(double np, double n, double f, double t) {
  if (std::isinf(np)) return (f - n) / (2.0 * t * n);
  if (np <= nPrimeLispsm(n, f)) return (f - n) / (2.0 * t) * (np + f - n) / (f * np);
  return (f - n) / (2.0 * t) * np / (n * (np + f - n));
}
double storage(double np, double n, double f, double t) {
  const double base = (f / n - 1.0) / (2.0 * t);
  if (np <= nPrimeLispsm(n, f)) return base;
  if (std::isinf(np)) return base * f / n;
  return base * f * np * np / (n * (np + f - n) * (np + f - n));
}
double nPrimeLispsm(double n, double f) {
  return n + std::sqrt(f * n);
}

}  // namespace overhead

glm::dvec2 budgetResolution(const Storage& st, double budgetTexels) {
  return {std::sqrt(budgetTexels * st.mx / st.mz), std::sqrt(budgetTexels * st.mz / st.mx)};
}

}  // namespace sl::partition
