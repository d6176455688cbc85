// The status line's permanent readouts: the scene shown, the last frame's time, the shadow
// error of the view (the live reference's in continuous rendering) and the OpenGL renderer.
// It observes the view (its frames, errors and changes) and fills its own labels; the window
// tells it what the view does not publish (a scene loaded, the renderer started).
#pragma once

#include <QObject>
#include <QString>

class QLabel;
class QStatusBar;

namespace sl {
struct Scene;
}

namespace sl::ui {

class ViewportWidget;

/// "llvmpipe (LLVM 15.0.6, 256 bits)" out of Renderer::glDescription()'s "RENDERER | VERSION".
QString shortGlName(const QString& description);

class StatusLine : public QObject {
  Q_OBJECT

 public:
  /// Adds the readouts to `bar` and starts observing `view` (both outlive this object).
  StatusLine(QStatusBar& bar, ViewportWidget& view, QObject* parent);

  void showScene(const sl::Scene& scene);
  /// `description`: Renderer::glDescription() ("RENDERER | VERSION").
  void showGl(const QString& description);
  /// Continuous rendering turned on or off (View > Render continuously).
  void onContinuousChanged(bool on);

  QLabel* errorLabel() const { return errorLabel_; }  ///< the shadow error readout

 private:
  void onFrameRendered();
  void onErrorComputed(double errorPct);
  void onErrorUnmeasured(const QString& why);
  /// Continuous rendering: the live error with its reference's age (greyed when stale).
  void showLiveError();

  ViewportWidget& view_;
  QLabel* sceneLabel_ = nullptr;
  QLabel* frameLabel_ = nullptr;
  QLabel* errorLabel_ = nullptr;
  QLabel* glLabel_ = nullptr;
};

}  // namespace sl::ui
