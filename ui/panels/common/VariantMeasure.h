// Measures the view as it is shown with variants of its technique's parameters, one frame
// each, on the render service (its own renderer, "variants"), against the exact reference:
// what a panel's "measure" button asks for (PublicationPanel::variantErrorsRequested: the
// Covariance panel's error at fixed turns). The UI thread only posts jobs; each answer comes
// back as a queued call. A newer request replaces an unfinished one; a variant already
// measured is never measured again for a stale request.
#pragma once

#include <cstdint>

#include <QList>
#include <QObject>
#include <QPointer>
#include <QStringList>

namespace sl::ui {

class PublicationPanel;
class ViewportWidget;

class VariantMeasure : public QObject {
  Q_OBJECT

 public:
  explicit VariantMeasure(ViewportWidget* viewport, QObject* parent = nullptr);

  /// Starts measuring `variants` for `panel` (replacing an unfinished request): the shown
  /// technique and its parameters, each variant's assignments on top, the view's camera, light
  /// and frame size as shown now.
  void start(PublicationPanel* panel, const QString& tag, const QList<QStringList>& variants);
  /// Stops posting (the variant in progress still answers, and is dropped).
  void cancel();
  bool running() const { return panel_ != nullptr && next_ < variants_.size(); }

 private:
  void measureNext();

  QPointer<ViewportWidget> viewport_;
  QPointer<PublicationPanel> panel_;
  QString tag_;
  QList<QStringList> variants_;
  qsizetype next_ = 0;
  std::uint64_t serial_ = 0;
  std::uint64_t frame_ = 0;  ///< the frame shown when the request came
};

}  // namespace sl::ui
