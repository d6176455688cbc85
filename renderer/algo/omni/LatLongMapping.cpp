// Latitude-longitude mapping of the sphere of directions (LatLongMapping.h): uv and inverse,
// texels and their wrapping across the seam and the poles, density, triangle bounds.
#include "LatLongMapping.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "OmniMapping.h"

namespace sl::omni {

namespace {

constexpr double kPi = std::numbers::pi;

/// `a` - `b` brought into (-pi, pi].
double wrappedDifference(double a, double b) {
  double d = std::remainder(a - b, 2.0 * kPi);  // [-pi, pi]
  if (d <= -kPi) d += 2.0 * kPi;
  return d;
}

glm::dvec3 local(const LatLongFrame& f, const glm::dvec3& d) {
  return {glm::dot(d, f.x), glm::dot(d, f.y), glm::dot(d, f.pole)};
}

}  // namespace

LatLongFrame latLongFrame(const glm::dvec3& pole) {
  LatLongFrame f;
  f.pole = glm::normalize(pole);
  completeFrame(f.pole, f.x, f.y);
  return f;
}

LatLong latLong(const LatLongFrame& frame, const glm::dvec3& dir) {
  const glm::dvec3 l = local(frame, glm::normalize(dir));
  LatLong ll;
  ll.longitudeRad = std::atan2(l.y, l.x);
  if (ll.longitudeRad <= -kPi) ll.longitudeRad = kPi;  // atan2(-0, x < 0) = -pi: the seam is +pi
  ll.latitudeRad = std::asin(std::clamp(l.z, -1.0, 1.0));
  return ll;
}

glm::dvec3 latLongDirection(const LatLongFrame& frame, const LatLong& ll) {
  const double c = std::cos(ll.latitudeRad);
  return glm::normalize(c * std::cos(ll.longitudeRad) * frame.x +
                        c * std::sin(ll.longitudeRad) * frame.y +
                        std::sin(ll.latitudeRad) * frame.pole);
}

glm::dvec2 latLongUv(const LatLongFrame& frame, const glm::dvec3& dir) {
  const LatLong ll = latLong(frame, dir);
  return {(ll.longitudeRad + kPi) / (2.0 * kPi), ll.latitudeRad / kPi + 0.5};
}

glm::dvec3 latLongUvDirection(const LatLongFrame& frame, const glm::dvec2& uv) {
  return latLongDirection(frame, {uv.x * 2.0 * kPi - kPi, (uv.y - 0.5) * kPi});
}

glm::ivec2 latLongTexel(const LatLongFrame& frame, const glm::dvec3& dir, int height) {
  const glm::dvec2 uv = latLongUv(frame, dir);
  const int width = 2 * height;
  int x = int(std::floor(uv.x * double(width))) % width;
  if (x < 0) x += width;
  const int y = std::clamp(int(std::floor(uv.y * double(height))), 0, height - 1);
  return {x, y};
}

glm::dvec3 latLongTexelCentreDirection(const LatLongFrame& frame, const glm::ivec2& texel,
                                       int height) {
  return latLongUvDirection(
      frame, (glm::dvec2(texel) + 0.5) / glm::dvec2(2.0 * double(height), double(height)));
}

glm::ivec2 latLongWrapTexel(glm::ivec2 t, int height) {
  const int width = 2 * height;
  if (t.y >= height) {  // over the north pole
    t.y = 2 * height - 1 - t.y;
    t.x += height;
  } else if (t.y < 0) {  // over the south pole
    t.y = -1 - t.y;
    t.x += height;
  }
  t.y = std::clamp(t.y, 0, height - 1);  // beyond a whole hemisphere: the nearest row
  t.x %= width;
  if (t.x < 0) t.x += width;
  return t;
}

LatLongHalfCoord latLongHalfUv(const LatLongFrame& frame, const glm::dvec3& dir) {
  const LatLong ll = latLong(frame, dir);
  LatLongHalfCoord c;
  c.half = ll.longitudeRad < 0.0 ? 0 : 1;
  c.uv = {(ll.longitudeRad - (c.half == 0 ? -kPi : 0.0)) / kPi, ll.latitudeRad / kPi + 0.5};
  return c;
}

glm::dvec2 latLongUvInHalf(const LatLongFrame& frame, int half, const glm::dvec3& dir) {
  const LatLong ll = latLong(frame, dir);
  const double centre = half == 0 ? -0.5 * kPi : 0.5 * kPi;
  const double lon = centre + wrappedDifference(ll.longitudeRad, centre);
  return {(lon - (centre - 0.5 * kPi)) / kPi, ll.latitudeRad / kPi + 0.5};
}

double latLongTexelsPerSteradian(const LatLongFrame& frame, const glm::dvec3& dir, int height) {
  // cos(latitude) as the length of the equatorial part: exactly 0 at a pole.
  const glm::dvec3 l = local(frame, glm::normalize(dir));
  const double cosLat = std::hypot(l.x, l.y);
  const double h = double(height);
  return h * h / (kPi * kPi * cosLat);
}

double latLongTexelSolidAngle(int row, int height) {
  const double lat0 = (double(row) / double(height) - 0.5) * kPi;
  const double lat1 = (double(row + 1) / double(height) - 0.5) * kPi;
  return 2.0 * kPi / (2.0 * double(height)) * (std::sin(lat1) - std::sin(lat0));
}

double rayTriangleDistance(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& a,
                           const glm::dvec3& b, const glm::dvec3& c, double edgeEps) {
  const glm::dvec3 e1 = b - a, e2 = c - a;
  const glm::dvec3 p = glm::cross(dir, e2);
  const double det = glm::dot(e1, p);
  if (std::abs(det) < 1e-14 * glm::length(e1) * glm::length(e2)) return -1.0;
  const glm::dvec3 s = origin - a;
  const double u = glm::dot(s, p) / det;
  if (u < -edgeEps || u > 1.0 + edgeEps) return -1.0;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(dir, q) / det;
  if (v < -edgeEps || u + v > 1.0 + edgeEps) return -1.0;
  const double t = glm::dot(e2, q) / det;
  return t > 0.0 ? t : -1.0;
}

LatLongBounds latLongTriangleBounds(const LatLongFrame& frame, const glm::dvec3& lightM,
                                    const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  LatLongBounds bounds;
  const glm::dvec3 v[3] = {a - lightM, b - lightM, c - lightM};
  for (const glm::dvec3& d : v)
    if (glm::length(d) <= 1e-12) return bounds;
  const glm::dvec3 n = glm::cross(v[1] - v[0], v[2] - v[0]);
  // Edge-on to the light (its plane through the light): no texel's ray meets its area.
  if (std::abs(glm::dot(n, v[0])) <= 1e-12 * glm::length(n) * glm::length(v[0])) return bounds;
  bounds.valid = true;
  const glm::dvec3 u[3] = {glm::normalize(v[0]), glm::normalize(v[1]), glm::normalize(v[2])};
  LatLong ll[3];
  for (int i = 0; i < 3; ++i) ll[i] = latLong(frame, u[i]);
  if (rayTriangleDistance(lightM, frame.pole, a, b, c, 1e-9) > 0.0) bounds.pole = 1;
  if (rayTriangleDistance(lightM, -frame.pole, a, b, c, 1e-9) > 0.0) bounds.pole = -1;

  bounds.latMinRad = std::min({ll[0].latitudeRad, ll[1].latitudeRad, ll[2].latitudeRad});
  bounds.latMaxRad = std::max({ll[0].latitudeRad, ll[1].latitudeRad, ll[2].latitudeRad});
  // An edge is a great-circle arc: its highest point e (the pole projected onto the arc's
  // plane) and lowest point -e count where they lie between the edge's ends.
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3& p = u[i];
    const glm::dvec3& q = u[(i + 1) % 3];
    const glm::dvec3 arcN = glm::cross(p, q);
    const double len = glm::length(arcN);
    if (len <= 1e-12) continue;
    const glm::dvec3 nn = arcN / len;
    glm::dvec3 e = frame.pole - glm::dot(frame.pole, nn) * nn;
    if (glm::length(e) <= 1e-12) continue;  // the arc lies on the equator
    e = glm::normalize(e);
    for (const glm::dvec3& x : {e, -e}) {
      if (glm::dot(glm::cross(p, x), nn) < 0.0 || glm::dot(glm::cross(x, q), nn) < 0.0) continue;
      const double lat = std::asin(std::clamp(glm::dot(x, frame.pole), -1.0, 1.0));
      bounds.latMinRad = std::min(bounds.latMinRad, lat);
      bounds.latMaxRad = std::max(bounds.latMaxRad, lat);
    }
  }
  if (bounds.pole != 0) {
    (bounds.pole > 0 ? bounds.latMaxRad : bounds.latMinRad) = bounds.pole * 0.5 * kPi;
    bounds.lonMinRad = -kPi;
    bounds.lonMaxRad = kPi;
    return bounds;
  }
  // No pole inside: longitude is monotonic along each edge (an arc shorter than pi not
  // through a pole turns less than pi in longitude), so the vertices bound it, unwrapped
  // along the edges from vertex a.
  const double l0 = ll[0].longitudeRad;
  const double l1 = l0 + wrappedDifference(ll[1].longitudeRad, l0);
  const double l2 = l1 + wrappedDifference(ll[2].longitudeRad, l1);
  bounds.lonMinRad = std::min({l0, l1, l2});
  bounds.lonMaxRad = std::max({l0, l1, l2});
  return bounds;
}

}  // namespace sl::omni
