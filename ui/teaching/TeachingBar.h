// The Teaching toolbar: the overlay choice (from the declaration of the shared
// `view.overlay` parameter; O cycles), the split view against a second technique (F7),
// pause, step frame and step passes.
#pragma once

#include <map>
#include <string>

#include <QObject>
#include <QString>

class QComboBox;

namespace sl::ui {

class MainWindow;

class TeachingBar : public QObject {
  Q_OBJECT

 public:
  explicit TeachingBar(MainWindow& window);

  /// Adds the toolbar to the window (after the pause action exists).
  void create();

  void syncOverlayCombo();
  void setOverlay(int value);
  void cycleOverlay();
  /// `params`: the right technique's own parameters (ViewportWidget::setSplitTechnique).
  void setSplitTechnique(const QString& id, const std::map<std::string, std::string>& params = {});
  void toggleSplit();
  /// After a new renderer: restores the split view chosen before.
  void restoreSplit();
  void setRendererAvailable(bool on);

 private:
  MainWindow& w_;
  QComboBox* overlayCombo_ = nullptr;
  QComboBox* splitCombo_ = nullptr;
  QString lastSplitTechnique_;
};

}  // namespace sl::ui
