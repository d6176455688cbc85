// The look of the GUI: Qt's Fusion style with a dark palette, so that the rendered image
// stands out and screenshots look the same on every desktop.
#pragma once

class QApplication;
class QSize;

namespace sl::ui {

void applyTheme(QApplication& app);

/// Presenter mode's look (a projector, the back of a room): white and yellow on black, no
/// grey text, and the application font at `bodyPixelSize` pixels (set in points at the
/// screen's `logicalDpi`, so that code scaling a font's point size keeps working).
void applyPresenterTheme(QApplication& app, int bodyPixelSize, double logicalDpi);

/// Body text size for presenter mode, from the screen's logical size and DPI: 24 px on a
/// 1920x1080 screen, in proportion to the smaller of width / 1920 and height / 1080
/// elsewhere (16 px at 1280x720), and never below 11 pt at the screen's logical DPI.
int presenterBodyPixelSize(const QSize& screenLogicalSize, double logicalDpi);

}  // namespace sl::ui
