// `shadowlab-cli storage`: the storage factor S = M_x M_z of warped and partitioned shadow
// maps (Lloyd, Tuft, Yoon, Manocha, EGSR 2006): S, M_x, M_z for one light and scheme, their
// Fig. 6 (over eta) and Fig. 7 (over the hemisphere of light directions) as PNG and CSV.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include "Commands.h"
#include "StorageCharts.h"
#include "algo/partition/StorageFactor.h"
#include "algo/partition/StoragePlots.h"

namespace sl::cli {

const char* const kStorageUsage =
    "       shadowlab-cli storage [--near N] [--far F] [--fov DEG] [--light AZIMUTH,ELEVATION]\n"
    "                             [--scheme uniform|psm|lispsm|tsm|cascades|face]\n"
    "                             [--eta E] [--focus F]\n"
    "                             [--partitions K] [--split uniform|log|practical]\n"
    "                             [--lambda L] [--partition-warp on|off] [--grid N]\n"
    "                             [--csv FILE.csv] [--out PREFIX]\n";

namespace {

using partition::Scheme;
using partition::SchemeSettings;
using partition::StorageResult;

constexpr const char* kStorageHelp =
    "  The viewer looks horizontally (fov: full vertical angle, square image). --light is\n"
    "  relative to it: azimuth 0 behind, 90 to its right, 180 in front; elevation 90\n"
    "  overhead (default 0,90). --out PREFIX writes PREFIX-eta.png (Fig. 6: M_x, M_z, S\n"
    "  over eta for this light) and PREFIX-hemisphere.png (Fig. 7: S over the light's\n"
    "  hemisphere, one disk per scheme); --csv both as rows\n"
    "  plot,scheme,eta,azimuth_deg,elevation_deg,mx,mz,s.\n"
    "  --eta (psm, lispsm: one warp with this eta, their warp.eta; default 1 and 0) and\n"
    "  --focus (tsm: its warp.focus, default 0.5). A TSM is one warp too: the eta its focus\n"
    "  gives (printed) with --scheme lispsm --eta prints the same S, M_x, M_z.\n";

struct StorageOptions {
  double nearM = 1.0, farM = 100.0, fovDeg = 60.0;
  double azimuthDeg = 0.0, elevationDeg = 90.0;
  std::string scheme = "lispsm";
  std::optional<double> eta;    // --eta: psm, lispsm
  std::optional<double> focus;  // --focus: tsm
  int partitions = 0;           // 0: the scheme's default (4 for cascades, 1 otherwise)
  partition::SplitScheme split = partition::SplitScheme::Log;
  double lambda = partition::kDefaultSplitLambda;
  bool partitionWarp = true;
  int grid = 101;
  std::string csv, out;
};

glm::dvec3 towardsLight(double azDeg, double elDeg) {
  const double az = glm::radians(azDeg), el = glm::radians(elDeg);
  return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
}

warp::ViewFrustum viewOf(const StorageOptions& o) {
  warp::ViewFrustum v;  // at the origin, looking along -z (behind the viewer is +z)
  v.nearM = o.nearM;
  v.farM = o.farM;
  v.fovYRad = glm::radians(o.fovDeg);
  return v;
}

SchemeSettings settingsFor(const std::string& name, int k, const StorageOptions& o) {
  SchemeSettings s;
  s.split = o.split;
  s.lambda = o.lambda;
  s.partitionWarp = o.partitionWarp;
  if (name == "face") {
    s.scheme = k > 1 ? Scheme::FaceCascades : Scheme::Face;
    s.partitions = k;
  } else if (name == "cascades") {
    s.scheme = Scheme::Cascades;
    s.partitions = k;
  } else {
    s.scheme = *partition::parseScheme(name);
  }
  if (name == "tsm" && o.focus) s.tsmFocusFraction = *o.focus;
  return s;
}

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

StorageOptions parse(Args& a) {
  StorageOptions o;
  bool nearGiven = false;
  for (std::size_t i = 1; i < a.rest.size(); ++i) {
    const std::string& opt = a.rest[i];
    if (opt == "--near") {
      o.nearM = parseDouble(opt, a.take(i, opt), 1e-9, 1e12), nearGiven = true;
    } else if (opt == "--far") {
      o.farM = parseDouble(opt, a.take(i, opt), 1e-9, 1e15);
    } else if (opt == "--fov") {
      o.fovDeg = parseDouble(opt, a.take(i, opt), 1.0, 170.0);
    } else if (opt == "--light") {
      const Light l = parseLight(opt, a.take(i, opt));
      if (l.type != LightType::Directional)
        throw UsageError(
            "--light: the storage analysis is for a directional light "
            "([dir:]AZIMUTH,ELEVATION), got a " +
            std::string(lightTypeName(l.type)) + " light");
      if (l.elevationDeg < 0.0f)
        throw UsageError(
            "--light: elevation must be in 0..90 degrees (the hemisphere above "
            "the viewer), got " +
            fmt(l.elevationDeg));
      o.azimuthDeg = l.azimuthDeg, o.elevationDeg = l.elevationDeg;
    } else if (opt == "--scheme") {
      o.scheme = a.take(i, opt);
      if (o.scheme != "uniform" && o.scheme != "psm" && o.scheme != "lispsm" && o.scheme != "tsm" &&
          o.scheme != "cascades" && o.scheme != "face")
        throw UsageError("--scheme: unknown '" + o.scheme +
                         "' (uniform, psm, lispsm, tsm, cascades, face)");
    } else if (opt == "--eta") {
      o.eta = parseDouble(opt, a.take(i, opt), -1.0, 1.0);
    } else if (opt == "--focus") {
      o.focus = parseDouble(opt, a.take(i, opt), 0.0, 1.0);
    } else if (opt == "--partitions") {
      o.partitions = parseInt(opt, a.take(i, opt), 1, 8);
    } else if (opt == "--split") {
      const std::string v = a.take(i, opt);
      auto s = partition::parseSplitScheme(v);
      if (!s) throw UsageError("--split: unknown '" + v + "' (uniform, log, practical)");
      o.split = *s;
    } else if (opt == "--lambda") {
      o.lambda = parseDouble(opt, a.take(i, opt), 0.0, 1.0);
    } else if (opt == "--partition-warp") {
      const std::string v = a.take(i, opt);
      if (v != "on" && v != "off")
        throw UsageError("--partition-warp: expected on or off, got '" + v + "'");
      o.partitionWarp = v == "on";
    } else if (opt == "--grid") {
      o.grid = parseInt(opt, a.take(i, opt), 9, 501);
    } else if (opt == "--csv") {
      o.csv = a.take(i, opt);
    } else if (opt == "--out") {
      o.out = a.take(i, opt);
    } else {
      throw UsageError("unknown option '" + opt + "'\n" + kStorageUsage + kStorageHelp);
    }
  }
  if (!(o.farM > o.nearM))
    throw UsageError("--far: " + fmt(o.farM) + " must be greater than --near (" + fmt(o.nearM) +
                     (nearGiven ? ")" : ", the default)"));
  if (o.eta && o.scheme != "psm" && o.scheme != "lispsm")
    throw UsageError("--eta: only psm and lispsm take an eta (got --scheme " + o.scheme +
                     (o.scheme == "tsm" ? ": its eta follows from --focus, and is printed)" : ")"));
  if (o.focus && o.scheme != "tsm")
    throw UsageError("--focus: only tsm takes a focus (got --scheme " + o.scheme + ")");
  if (o.partitions == 0) o.partitions = o.scheme == "cascades" ? 4 : 1;
  if (o.partitions > 1 && o.scheme != "cascades" && o.scheme != "face")
    throw UsageError("--partitions: only cascades and face take partitions (got --scheme " +
                     o.scheme + ")");
  return o;
}

}  // namespace

StorageQuery storageQuery(const std::vector<std::string>& args) {
  Args a;
  a.rest.push_back("storage");
  a.rest.insert(a.rest.end(), args.begin(), args.end());
  const StorageOptions o = parse(a);
  if (!o.csv.empty() || !o.out.empty())
    throw UsageError("--csv, --out: outputs are not part of a storage query");
  SchemeSettings chosen = settingsFor(o.scheme, o.partitions, o);
  if (o.eta) {
    chosen.scheme = Scheme::Eta;
    chosen.eta = *o.eta;
  }
  StorageQuery q;
  if (auto e = partition::evaluateScheme(viewOf(o), towardsLight(o.azimuthDeg, o.elevationDeg),
                                         chosen, q.result))
    throw UsageError(*e);
  q.splits = partition::splitDistances(o.split, o.nearM, o.farM, o.partitions, o.lambda);
  return q;
}

int cmdStorage(Args& a) {
  const StorageOptions o = parse(a);
  std::vector<OutputFile> outputs;
  if (!o.csv.empty()) outputs.push_back({"--csv", o.csv});
  if (!o.out.empty()) {
    outputs.push_back({"--out", o.out + "-eta.png"});
    outputs.push_back({"--out", o.out + "-hemisphere.png"});
  }
  checkOutputs(outputs);

  const warp::ViewFrustum view = viewOf(o);
  const glm::dvec3 light = towardsLight(o.azimuthDeg, o.elevationDeg);
  auto evaluate = [&](const SchemeSettings& s, const glm::dvec3& l) {
    StorageResult r;
    if (auto e = partition::evaluateScheme(view, l, s, r)) throw UsageError(*e);
    return r;
  };

  // The asked-for light and scheme.
  SchemeSettings chosen = settingsFor(o.scheme, o.partitions, o);
  if (o.eta) {
    chosen.scheme = Scheme::Eta;
    chosen.eta = *o.eta;
  }
  const StorageResult res = evaluate(chosen, light);
  std::printf(
      "storage factor (Lloyd et al. 2006): scheme %s, near %s, far %s, fov %s deg, "
      "light azimuth %s elevation %s\n",
      // The scheme asked for, with the eta given (the analysis' own name for it is "eta").
      (o.eta ? o.scheme + " with eta " + fmt(*o.eta) : partition::schemeName(chosen.scheme))
          .c_str(),
      fmt(o.nearM).c_str(), fmt(o.farM).c_str(), fmt(o.fovDeg).c_str(), fmt(o.azimuthDeg).c_str(),
      fmt(o.elevationDeg).c_str());
  std::printf("S = %s  M_x = %s  M_z = %s  (%zu shadow map%s)\n", fmt(res.s).c_str(),
              fmt(res.mx).c_str(), fmt(res.mz).c_str(), res.parts.size(),
              res.parts.size() == 1 ? "" : "s");
  for (const partition::PartStorage& p : res.parts) {
    std::printf("  %-14s S %-10s M_x %-10s M_z %-10s n' %-10s eta %s%s%s\n", p.label.c_str(),
                fmt(p.storage.s).c_str(), fmt(p.storage.mx).c_str(), fmt(p.storage.mz).c_str(),
                fmt(p.fit.nPrime).c_str(), fmt(p.fit.eta).c_str(),
                p.fit.fallback ? ("  fallback: " + p.fit.fallbackReason).c_str() : "",
                p.fit.note.empty() ? "" : ("  note: " + p.fit.note).c_str());
  }
  if (o.csv.empty() && o.out.empty()) return 0;

  // Fig. 6: one warp over eta for this light.
  partition::EtaCurve curve;
  if (auto e = partition::etaCurve(view, light, 201, curve)) throw UsageError(*e);
  curve.title =
      "Maximum error and storage factor over the warp parameter eta (Lloyd et al. 2006, Fig. 6)";
  curve.subtitle = "n " + fmt(o.nearM) + ", f " + fmt(o.farM) + ", fov " + fmt(o.fovDeg) +
                   " deg, light azimuth " + fmt(o.azimuthDeg) + " elevation " +
                   fmt(o.elevationDeg) + " (90: overhead)";

  // Fig. 7: S over the hemisphere (equal-angle disk: centre overhead, rim the horizon; left
  // behind the viewer, right in front, top to its right) for each scheme.
  const int k = std::max(o.partitions, o.scheme == "cascades" || o.scheme == "face" ? 1 : 4);
  const int kz = k > 1 ? k : 4;
  struct Panel {
    std::string title;
    SchemeSettings s;
  };
  std::vector<Panel> panels;
  for (const char* n : {"uniform", "lispsm", "psm", "tsm"})
    panels.push_back({n, settingsFor(n, 1, o)});
  panels.push_back({"face", settingsFor("face", 1, o)});
  SchemeSettings zo = settingsFor("cascades", kz, o);
  zo.partitionWarp = false;
  panels.push_back(
      {"cascades k=" + std::to_string(kz) + " (" + splitSchemeName(o.split) + " split; ortho)",
       zo});
  SchemeSettings zw = zo;
  zw.partitionWarp = true;
  panels.push_back({"cascades k=" + std::to_string(kz) + " + LiSPSM", zw});
  panels.push_back({"face + cascades k=" + std::to_string(kz), settingsFor("face", kz, o)});
  partition::HemisphereFigure fig;
  fig.title = "Storage factor S over the light's hemisphere (Lloyd et al. 2006, Fig. 7)";
  fig.subtitle = "n " + fmt(o.nearM) + ", f " + fmt(o.farM) + ", fov " + fmt(o.fovDeg) +
                 " deg. Centre: light overhead; rim: horizon; left: behind the viewer; right: in "
                 "front; top: to its right. Cross: --light. One colour scale (log10) for all.";
  const partition::HemisphereFrame frame;  // the viewer looks along -z, y up
  const glm::dvec2 mark = frame.disk(light);
  fig.markU = mark.x, fig.markV = mark.y;
  std::ostringstream csv;
  csv << "plot,scheme,eta,azimuth_deg,elevation_deg,mx,mz,s\n";
  for (std::size_t i = 0; i < curve.eta.size(); ++i)
    csv << "eta,eta," << fmt(curve.eta[i]) << ',' << fmt(o.azimuthDeg) << ',' << fmt(o.elevationDeg)
        << ',' << fmt(curve.mx[i]) << ',' << fmt(curve.mz[i]) << ',' << fmt(curve.s[i]) << '\n';
  for (const Panel& p : panels) {
    partition::HemispherePanel hp;
    hp.title = p.title;
    if (auto e = partition::hemispherePanel(view, frame, p.s, o.grid, hp)) throw UsageError(*e);
    for (int r = 0; r < o.grid; ++r)
      for (int c = 0; c < o.grid; ++c) {
        const glm::dvec2 uv = hp.cellCentre(r, c);
        const std::optional<glm::dvec3> l = frame.direction(uv.x, uv.y);
        if (!l) continue;
        const std::size_t i = std::size_t(r * o.grid + c);
        csv << "hemisphere," << p.title << ",," << fmt(glm::degrees(std::atan2(l->x, l->z))) << ','
            << fmt(glm::degrees(std::asin(std::clamp(l->y, -1.0, 1.0)))) << ',' << fmt(hp.mx[i])
            << ',' << fmt(hp.mz[i]) << ',' << fmt(hp.s[i]) << '\n';
      }
    fig.panels.push_back(std::move(hp));
  }
  if (!o.csv.empty()) {
    writeAtomically(o.csv, [&](const std::string& tmp) -> std::optional<std::string> {
      std::ofstream f(tmp, std::ios::binary);
      f << csv.str();
      f.flush();
      if (!f) return "cannot write " + tmp;
      return std::nullopt;
    });
    std::printf("wrote %s\n", o.csv.c_str());
  }
  if (!o.out.empty()) {
    const std::string eta = o.out + "-eta.png", hemi = o.out + "-hemisphere.png";
    writeAtomically(eta, [&](const std::string& tmp) { return writeEtaChart(curve, tmp); });
    writeAtomically(hemi, [&](const std::string& tmp) { return writeHemisphereChart(fig, tmp); });
    std::printf("wrote %s and %s\n", eta.c_str(), hemi.c_str());
  }
  return 0;
}

}  // namespace sl::cli
