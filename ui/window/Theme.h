// The look of the GUI: Qt's Fusion style with a dark palette, so that the rendered image
// stands out and screenshots look the same on every desktop.
#pragma once

#include <functional>

#include <QFont>

class QApplication;
class QChart;
class QSize;
class QWidget;

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

/// The one place every font the UI sets explicitly goes through: `relative` times the
/// application's body font (which presenter mode sets, scaled to the screen), on `base`'s
/// family and weight. Painted text (chart labels, captions) asks for it when it paints;
/// widgets and Qt Charts items take it through followBodyFont, so no explicit size stays
/// behind when presenter mode turns on or off. Smaller text is at least kSmallText.
QFont bodyRelativeFont(double relative, const QFont& base);
QFont bodyRelativeFont(double relative);
/// Pixel size of the application's body font.
int bodyPixelSize();
/// The smallest relative size any explicit font uses (annotations, chart ticks).
inline constexpr double kSmallText = 0.85;

/// A Qt Charts chart's title (body size), axis titles and labels and legend (kSmallText):
/// Qt Charts' themes set fixed fonts of their own otherwise.
void setChartFonts(QChart& chart);

/// Calls `apply` now and whenever the application font changes (presenter mode on or off),
/// for as long as `owner` lives: explicit fonts (a title's larger size, a chart's axis and
/// legend fonts) are set there from bodyRelativeFont.
void followBodyFont(QWidget* owner, std::function<void()> apply);
/// `widget`'s own font at `relative` x the body size (bold if asked), now and after every
/// application font change.
void followBodyFont(QWidget* widget, double relative, bool bold = false);

}  // namespace sl::ui
