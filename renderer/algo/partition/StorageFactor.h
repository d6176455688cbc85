// Maximum perspective aliasing and the storage factor S = M_x M_z of warped and
// partitioned shadow maps (Lloyd, Tuft, Yoon, Manocha, EGSR 2006: eqs. 2-4 and 7-14, §4.4
// beam widths at the view-frustum vertices, §5.1 face partitioning, §5.2 z-partitioning).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "Splits.h"
#include "algo/warp/PerspectiveWarp.h"

namespace sl::partition {

/// Maximum errors over a body for a 1x1 shadow map and a 1x1 image (res = 1): mx = M_x,
/// mz = M_z, s = S = M_x M_z, the storage factor (eq. 12): the critical-resolution map's
/// texels per image pixel.
struct Storage {
  double mx = 0.0, mz = 0.0, s = 0.0;
};

/// One shadow map of a scheme: the region it covers, its warp and its numbers.
struct PartStorage {
  std::string label;             ///< "z 1/4", "face -x", "whole"
  std::vector<glm::dvec3> body;  ///< vertices of the region (world)
  warp::WarpFit fit;
  Storage storage;
};

enum class Scheme {
  Uniform,       ///< one orthographic map
  Eta,           ///< one warp with the given eta (eq. 11)
  Lispsm,        ///< eta = 0
  Psm,           ///< eta = 1
  Tsm,           ///< focus on the 80 % line
  Cascades,      ///< z-partitioning, k parts, each uniform or LiSPSM
  Face,          ///< face partitioning, LiSPSM per face
  FaceCascades,  ///< z-partitioning, then face partitioning of every slice
};
const char* schemeName(Scheme s);
std::optional<Scheme> parseScheme(const std::string& name);

struct SchemeSettings {
  Scheme scheme = Scheme::Lispsm;
  double eta = 0.0;                      ///< Scheme::Eta
  int partitions = 1;                    ///< k for Cascades, FaceCascades
  SplitScheme split = SplitScheme::Log;  ///< how the k parts are cut
  double lambda = kDefaultSplitLambda;   ///< practical split blend
  std::vector<double> customSplits;      ///< k + 1 distances overriding `split` when set
  bool partitionWarp = true;             ///< Cascades: LiSPSM per part (else uniform)
  double tsmFocusFraction = 0.5;         ///< Scheme::Tsm
};

struct StorageResult {
  double s = 0.0;             ///< total storage factor: sum over parts
  double mx = 0.0, mz = 0.0;  ///< the largest M_x, M_z of any part
  std::vector<PartStorage> parts;
};

/// Image beam width at `world` for res_i = 1 (eq. 2): 2 tan(theta) (p - eye) . v.
double imageBeamWidth(const warp::ViewFrustum& view, const glm::dvec3& world);
/// (m_x, m_z) = (w_lx, w_lz) / w_i at `world` (eqs. 7-8 generalised, res = 1).
glm::dvec2 aliasingAt(const warp::ViewFrustum& view, const warp::WarpFit& fit,
                      const glm::dvec3& world);
/// M_x, M_z, S over `body`: the maxima at its vertices (the beam widths are monotonic over
/// a convex body, §4.4).
Storage storageOfBody(const warp::ViewFrustum& view, const warp::WarpFit& fit,
                      const std::vector<glm::dvec3>& body);

/// The scheme's maps for the light `towardsLight` and their storage. Errors name the input.
std::optional<std::string> evaluateScheme(const warp::ViewFrustum& view,
                                          const glm::dvec3& towardsLight,
                                          const SchemeSettings& settings, StorageResult& out);

/// A face partition (§5.1): the part of the frustum slice whose light rays cross one face
/// (front faces when v . y < 0, back faces otherwise), its LiSPSM axes.
struct FacePartition {
  int face = 0;  ///< 0 near, 1 far, 2 -x, 3 +x, 4 -y, 5 +y
  std::vector<glm::dvec3> body;
  std::optional<glm::dvec3> axis;      ///< 3D central direction of the side edges
  std::optional<glm::dvec3> bisector;  ///< bisector of the projected side edges
};
const char* faceName(int face);
/// The 6 faces of the frustum slice as planes: xyz = outward unit normal, w = d (inside:
/// dot(n, p) <= d), in facePartitions' face order (0 near, 1 far, 2 -x, 3 +x, 4 -y, 5 +y).
std::array<glm::dvec4, 6> frustumFacePlanes(const warp::ViewFrustum& view, double sliceNear,
                                            double sliceFar);
/// `clipMin`/`clipMax`, when given, also clip every partition's body to that box (the
/// scene's bounds: a map need not cover empty space).
/// `depthSlab`, when given, clips every body to view depths [x, y] while the faces stay
/// those of the slice [sliceNear, sliceFar]: the faces of the whole frustum, then each face's
/// part of one depth slice (faces first, Lloyd et al.'s nesting).
std::vector<FacePartition> facePartitions(const warp::ViewFrustum& view, double sliceNear,
                                          double sliceFar, const glm::dvec3& towardsLight,
                                          const std::optional<glm::dvec3>& clipMin = {},
                                          const std::optional<glm::dvec3>& clipMax = {},
                                          const std::optional<glm::dvec2>& depthSlab = {});

/// Closed forms for the overhead light (light space aligned with the view, §4.1), res = 1.
namespace overhead {
double mx(double z, double nPrime, double n, double f);                   ///< eq. 7
double mz(double z, double nPrime, double n, double f, double tanTheta);  ///< eq. 8
double maxMx(double nPrime, double n, double f);                          ///< eq. 9
double maxMz(double nPrime, double n, double f, double tanTheta);         ///< eq. 10
double storage(double nPrime, double n, double f, double tanTheta);       ///< eq. 12
double nPrimeLispsm(double n, double f);                                  ///< n + sqrt(f n)
}  // namespace overhead

/// Shadow-map resolution for a fixed budget of S0 texels that splits the error equally
/// between x and z (eqs. 13-14): res_s = sqrt(S0 M_x / M_z), res_t = sqrt(S0 M_z / M_x)
/// (M_x, M_z at res = 1: the image's resolution cancels in their ratio).
glm::dvec2 budgetResolution(const Storage& st, double budgetTexels);

}  // namespace sl::partition
