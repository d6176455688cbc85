// The look of the GUI: Qt's Fusion style with a dark palette, so that the rendered image
// stands out and screenshots look the same on every desktop.
#pragma once

class QApplication;

namespace sl::ui {

void applyTheme(QApplication& app);

}  // namespace sl::ui
