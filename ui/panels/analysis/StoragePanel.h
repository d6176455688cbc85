// The Storage factor panel (Lloyd et al. 2006): S = M_x M_z over the hemisphere of light
// directions for the current camera and the technique's scheme (their Fig. 7; a click moves
// the light there), M_x, M_z, S over eta with the current eta marked (Fig. 6), and the
// predicted maximum error next to the frame's measured m (p95, max). The analysis runs off
// the UI thread, and only when camera, light or scheme change.
#pragma once

#include <memory>
#include <optional>

#include <QPointF>

#include "algo/partition/StoragePlots.h"
#include "panels/analysis/StoragePanelKeys.h"
#include "measure/StorageScheme.h"
#include "panels/common/PanelKit.h"

class QLabel;

namespace sl::ui {

using sl::measure::analysesScheme;
using sl::measure::schemeFromDeclarations;
using sl::measure::StorageInputs;

class HemisphereView;
class EtaView;

class StoragePanel : public PublicationPanel {
  Q_OBJECT

 public:
  explicit StoragePanel(QWidget* parent = nullptr);
  ~StoragePanel() override;

  std::set<std::string> observedKeys() const override { return analysis::storagePanelKeys(); }
  /// Every frame has its keys: it describes the techniques whose scheme it analyses.
  bool describes(const sl::TechniqueInfo& info) const override { return analysesScheme(info); }
  void showPublication(const sl::Publication& publication) override;
  /// A click on the hemisphere emits lightChosen (PublicationPanel) with that direction.
  /// "scheme", "s", "mx", "mz" (the current light), "predicted_m_x", "predicted_m_z"
  /// (texels per pixel at this resolution), "measured_p95", "measured_max", "grid",
  /// "compute_ms", "mark_u", "mark_v" (the light's mark on the disk), "light_azimuth_deg",
  /// "light_elevation_deg" (the analysed light), "eta" (marked on the eta plot, when the
  /// scheme warps), "fallback" (a part of the scheme falls back to uniform).
  QJsonObject drawnValues() const override;
  /// The hemisphere disk and where disk coordinates (u right = in front, v up = the viewer's
  /// right) lie in it: what a click there picks (the storage-click GUI test clicks there).
  QWidget* hemisphereWidget() const;
  QPointF hemispherePoint(double u, double v) const;

 private:
  struct Result;
  struct Shared;
  void start();
  void finished(std::shared_ptr<const Result> result);
  void updateNumbers();

  HemisphereView* hemisphere_ = nullptr;
  EtaView* eta_ = nullptr;
  QLabel* numbers_ = nullptr;
  std::optional<StorageInputs> inputs_;  ///< the latest frame's
  std::optional<StorageInputs> running_;
  std::shared_ptr<const Result> result_;
  std::shared_ptr<Shared> shared_;
  double measuredP95_ = -1.0, measuredMax_ = -1.0, binOctaves_ = 0.0;
  double heightPx_ = 0.0, mapResolution_ = 0.0;
  QJsonObject drawn_;
};

}  // namespace sl::ui
