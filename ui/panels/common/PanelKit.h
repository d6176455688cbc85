// Shared pieces of the debug panels: colour maps, float images to QImage, a zoomable image
// view with a legend and a value readout, a line plot with hover readout, and the base
// class of every panel that shows the renderer's Publication. QPainter only, no GL.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <set>
#include <string>
#include <span>
#include <vector>

#include <QImage>
#include <QJsonObject>
#include <QLabel>
#include <QPointF>
#include <QString>
#include <QStringList>
#include <QWidget>

#include "core/Renderer.h"

class QStackedWidget;
class QVBoxLayout;

namespace sl::ui {

// --- Colour maps ---------------------------------------------------------------------------

enum class ColorMap {
  Viridis,    ///< perceptual, for non-negative quantities (importance)
  Grey,       ///< depth maps
  Diverging,  ///< signed quantities, 0 in the middle (blue - white - red)
};

/// Colour of t in [0, 1] (clamped; NaN -> black).
QRgb mapColor(ColorMap map, float t);

/// How values become t in [0, 1]: linear between lo and hi, or log10 between them (lo > 0).
struct ValueRange {
  float lo = 0.0f;
  float hi = 1.0f;
  bool log = false;
  float normalize(float v) const;
  float denormalize(float t) const;  ///< inverse of normalize, for legend labels
};

/// Range of the finite values of `values` (channel `channel` of `channels`), ignoring values
/// >= ignoreFrom (e.g. 1.0 = the cleared depth of a shadow map). Empty: {0, 1}. A flat
/// range is widened so that normalize() stays finite.
ValueRange finiteRange(std::span<const float> values, int channels = 1, int channel = 0,
                       float ignoreFrom = std::numeric_limits<float>::infinity());
/// Symmetric range [-m, m] with m = max |v| (for ColorMap::Diverging).
ValueRange symmetricRange(std::span<const float> values, int channels = 1, int channel = 0);

/// Colours one channel of a float image. FloatImage row 0 is the bottom; the QImage's row 0
/// is the top (so it displays upright).
QImage colorize(const sl::FloatImage& image, int channel, const ValueRange& range, ColorMap map);

/// A display copy of channel 0 of `image` with at most `maxTexels` per side (point sampled;
/// the image itself when it is small enough).
sl::FloatImage displayCopy(const sl::FloatImage& image, int maxTexels);

/// "0.0123", "1.23e+05": four significant digits.
QString formatValue(double v);
/// A colour-bar or axis tick of a scale spanning `span`: rounded to the digits that step
/// (span / 4) needs, a value within span / 1000 of zero as "0", and a minus that reads as
/// one (U+2212, not a hyphen): "−0.02", not "-0.0218".
QString formatTick(double v, double span);

/// Text for a panel whose data (`keys`) the current technique does not publish, naming
/// the techniques that declare them.
QString noDataText(const QString& techniqueId, const QString& what,
                   const std::set<std::string>& keys);

// --- ImageView -----------------------------------------------------------------------------

/// Shows an image of a texel grid (uv in [0,1]^2, v up) with zoom (wheel), pan (drag),
/// fit (double click), a colour legend and the value under the cursor.
class ImageView : public QWidget {
  Q_OBJECT

 public:
  explicit ImageView(QWidget* parent = nullptr);

  /// `image` shows a texelsW x texelsH grid (the image may be larger or smaller).
  void setImage(const QImage& image, int texelsW, int texelsH);
  /// Width / height the image is drawn at (0: its texels' aspect), e.g. the light frustum's
  /// shape in metres for a square map over a rectangular frustum.
  void setDisplayAspect(double aspect);
  void clearImage(const QString& placeholder);
  bool hasImage() const { return !image_.isNull(); }
  QSize texelSize() const { return {texelsW_, texelsH_}; }

  /// Text for the texel under the cursor (x right, y up from the bottom row).
  void setValueReader(std::function<QString(int x, int y)> reader);
  /// The readout line for the texel under the cursor ("texel (x, y)  uv (u, v)" and the value
  /// reader's text), empty when the cursor is not over the image.
  QString hoverText() const;
  /// Colour legend on the right: `range` through `map`, `unit` under it. An empty unit
  /// and a default range with `show` false hides it.
  void setLegend(const ValueRange& range, ColorMap map, const QString& title, bool show = true);
  /// Drawn over the image; `imageRect` is where uv [0,1]^2 lies in widget coordinates
  /// (u = 0 at left(), v = 0 at bottom()).
  void setOverlay(std::function<void(QPainter&, const QRectF& imageRect)> overlay);
  void setCaption(const QString& caption);
  /// A coloured frame (pass stepping: "this is the output of the current pass").
  void setHighlighted(bool on);

  /// Back to "fit to view".
  void resetZoom();

  /// Where the image was drawn last (widget pixels, zoom and pan applied); empty without one.
  QRectF shownImageRect() const { return image_.isNull() ? QRectF() : imageRect(); }

  QSize sizeHint() const override { return {320, 300}; }
  /// Small (120 x 110), or inside a panel that asks for readable sizes (setReadableMinimums)
  /// the size that draws the image kReadableSide px on its longer side under its caption
  /// (wrapped to the current width), over its readout line and beside its legend.
  QSize minimumSizeHint() const override;
  /// The size an image is readable at from the back of a lecture hall, on its longer side.
  static constexpr int kReadableSide = 160;
  /// The minimum size is measured again (setReadableMinimums changed, the font changed).
  void updateReadableMinimum();

 protected:
  void paintEvent(QPaintEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void leaveEvent(QEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void changeEvent(QEvent* event) override;

 private:
  int legendWidth() const;  ///< 0 without a legend
  /// Heights of the caption (top) and the readout (bottom), wrapped to the widget's width
  /// (or `width`): a caption or a readout is never cut, the image gets what is left.
  int captionHeight(int width = -1) const;
  int wrappedHeight(const QString& text, int width = -1) const;
  /// The readable minimum at the width the widget has (its size hint's before a layout set
  /// one); the layout is told when it changes.
  QSize readableMinimumSize() const;
  int readoutHeight(const QString& readout) const;
  QString legendTick(float t) const;  ///< the colour bar's label at t in [0, 1]
  QRectF viewArea() const;            ///< the part of the widget available to the image
  QRectF imageRect() const;           ///< where the image lies, zoom and pan applied

  QImage image_;
  int texelsW_ = 0, texelsH_ = 0;
  double displayAspect_ = 0.0;
  QString placeholder_;
  QString caption_;
  std::function<QString(int, int)> reader_;
  std::function<void(QPainter&, const QRectF&)> overlay_;
  ValueRange legendRange_;
  ColorMap legendMap_ = ColorMap::Viridis;
  QString legendTitle_;
  bool legend_ = false;
  bool highlighted_ = false;
  mutable QSize readableMinimumSize_;  ///< the last readableMinimumSize() the layout was told of
  double zoom_ = 1.0;
  QPointF pan_;  ///< offset of the image centre from the view centre, widget pixels
  QPoint lastMouse_;
  bool dragging_ = false;
  QPoint hover_{-1, -1};
};

// --- PlotWidget ----------------------------------------------------------------------------

/// A small line plot: several series over a shared x axis, optional log y, horizontal
/// reference lines, and a hover cursor that reads every series at the cursor's x.
class PlotWidget : public QWidget {
  Q_OBJECT

 public:
  struct Series {
    QString name;
    std::vector<QPointF> points;  ///< ascending x
    QColor color;
    Qt::PenStyle style = Qt::SolidLine;
    qreal width = 1.6;
    bool highlighted = false;  ///< drawn thicker with a glow
    bool dots = false;         ///< a dot at every point (sparse measurements)
  };
  struct Line {
    double y = 0.0;
    QColor color;
    QString label;
  };
  /// A vertical line at x (a chosen value of the x axis), its label along its top.
  struct Marker {
    double x = 0.0;
    QColor color;
    QString label;
    Qt::PenStyle style = Qt::SolidLine;
  };

  explicit PlotWidget(QWidget* parent = nullptr);

  void setTitle(const QString& title);
  void setAxisLabels(const QString& x, const QString& y);
  void setSeries(std::vector<Series> series);
  void setLines(std::vector<Line> lines);
  void setMarkers(std::vector<Marker> markers);
  const std::vector<Marker>& markers() const { return markers_; }
  /// Fixed ranges (lo >= hi: automatic from the data).
  void setXRange(double lo, double hi);
  void setYRange(double lo, double hi);
  void setLogY(bool on);
  void setPlaceholder(const QString& text);
  void setHighlighted(bool on);
  const std::vector<Series>& series() const { return series_; }
  /// Where the curves are drawn and where the legend's entries stand (widget pixels): the
  /// legend has a band of its own between the title and the curves, never over them.
  QRectF curveArea() const { return plotArea(); }
  std::vector<QRectF> legendEntries() const;

  QSize sizeHint() const override { return {320, 190}; }
  /// The size a plot is readable at from the back of a lecture hall: the widget, and the
  /// curves under its title and legend.
  static constexpr int kReadableHeight = 120;
  static constexpr int kReadableCurves = 60;
  /// Small (140 x 100), or inside a panel that asks for readable sizes (setReadableMinimums)
  /// the height that leaves kReadableCurves px of curves under the title and the legend,
  /// wrapped to the current width (at least kReadableHeight).
  QSize minimumSizeHint() const override;
  /// The minimum size is measured again (setReadableMinimums changed, the font changed).
  void updateReadableMinimum();

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void leaveEvent(QEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void changeEvent(QEvent* event) override;

 private:
  struct Ranges {
    double x0, x1, y0, y1;
  };
  Ranges ranges() const;
  QRectF plotArea() const;
  /// The title wrapped to the widget's width (or `width`), never cut.
  int titleHeight(int width = -1) const;
  /// The legend's entries laid out left to right, wrapping, in a band starting at `top`
  /// across the widget's width (or `width`); `height` is the band's.
  std::vector<QRectF> legendLayout(double top, int* height, int width = -1) const;
  /// The readable minimum height at the width the widget has (its size hint's before a
  /// layout set one); the layout is told when it changes.
  int readableMinimumHeight() const;
  QString fullTitle() const;
  double yToT(double y, const Ranges& r) const;

  QString title_, xLabel_, yLabel_, placeholder_;
  std::vector<Series> series_;
  std::vector<Line> lines_;
  std::vector<Marker> markers_;
  double fixedX0_ = 0, fixedX1_ = 0, fixedY0_ = 0, fixedY1_ = 0;
  bool logY_ = false;
  bool highlighted_ = false;
  mutable int readableMinimumHeight_ = 0;  ///< the last readableMinimumHeight() told, 0: none
  int hoverX_ = -1;
};

// --- WrappedLabel --------------------------------------------------------------------------

/// A word-wrapped label (a panel's table or notes) whose minimum height, inside a panel that
/// asks for readable sizes (setReadableMinimums), is its text wrapped to its current width:
/// QLabel's own is a line or so, so a presenter's window (which fits its panels by their
/// minimum sizes) squeezed it, or the plots and images beside it, to make room for the lines
/// it really needs. Elsewhere QLabel's own (a narrow panel is not held tall).
class WrappedLabel : public QLabel {
  Q_OBJECT

 public:
  explicit WrappedLabel(QWidget* parent = nullptr);
  QSize minimumSizeHint() const override;

 protected:
  void resizeEvent(QResizeEvent* event) override;

 private:
  mutable int wrappedHeight_ = -1;  ///< the last minimum height the layout was told of
};

/// Two parts of a panel side by side where it is wide enough for the first at its usual width
/// (its size hint's, or its minimum's if larger) and the second at least `secondEms` wide (em:
/// the font's average character), else the second under the first: a wide panel (a
/// presenter's, short for its content) reads its notes beside its image, a narrow one under it.
class BesideWhenWide : public QWidget {
  Q_OBJECT

 public:
  BesideWhenWide(QWidget* first, QWidget* second, int secondEms, QWidget* parent = nullptr);
  bool beside() const;
  /// As wide as the parts under each other need: a panel that narrows puts them so again.
  QSize minimumSizeHint() const override;

 protected:
  void resizeEvent(QResizeEvent* event) override;

 private:
  QWidget* first_;
  QWidget* second_;
  int secondEms_;
};

// --- Panels --------------------------------------------------------------------------------

/// Base of the panels that show the renderer's Publication. The main window requests the
/// panel's observedKeys() while it is visible and calls showPublication() after each frame;
/// a panel keeps whatever it needs (the Publication is replaced by the next frame). A
/// technique that does not publish a panel's keys gets the placeholder (showContent(false,
/// noDataText(...))).
class PublicationPanel : public QWidget {
  Q_OBJECT

 public:
  explicit PublicationPanel(QWidget* parent = nullptr);

  /// The publication keys (or patterns) this panel draws: requested from the renderer
  /// while the panel is visible, nothing while it is hidden.
  virtual std::set<std::string> observedKeys() const = 0;
  virtual void showPublication(const sl::Publication& publication) = 0;
  /// Pass stepping: emphasise what shows pass `passId` ("" = nothing).
  virtual void highlightPass(const QString& passId) { (void)passId; }
  /// Whether the panel has something to say about technique `info`: by default, it draws a
  /// key the technique itself declares (not only the renderer's keys every frame has). The
  /// window shows such panels and hides the others when the technique changes.
  virtual bool describes(const sl::TechniqueInfo& info) const;
  /// The placeholder's text while the panel shows it instead of its content, else empty.
  QString placeholderShown() const;
  /// Values the panel computed or drew (for --grab's published.json).
  virtual QJsonObject drawnValues() const { return {}; }
  /// Forgets accumulated history (new scene or technique).
  virtual void resetHistory() {}
  /// Its plots and images were asked for (or gave up) their readable sizes
  /// (setReadableMinimums): a panel that lays its views out by their minimum width does it again.
  virtual void readableMinimumsChanged() {}
  /// The view's pixel under the mouse (ViewportWidget::pixelProbed), or nothing.
  virtual void showProbe(const std::optional<sl::PixelProbe>& probe) { (void)probe; }
  /// Whether showProbe draws anything: the view reads the pixel back (a GPU sync) only
  /// while a visible panel says so.
  virtual bool wantsProbe() const { return false; }
  /// The answer to variantErrorsRequested, one call per variant as it is measured: its error
  /// (% of the covered pixels that disagree with the exact reference; NaN when not measured,
  /// `problem` then says why), for the view of frame `frame` (the frame shown when asked).
  virtual void showVariantError(const QString& tag, int index, double errorPct, std::uint64_t frame,
                                const QString& problem) {
    (void)tag, (void)index, (void)errorPct, (void)frame, (void)problem;
  }

 Q_SIGNALS:
  /// The panel asks the window to move the light (degrees; e.g. a click on the Storage
  /// factor panel's hemisphere).
  void lightChosen(double azimuthDeg, double elevationDeg);
  /// The panel asks the window to set one of the shown technique's parameters, as its editor
  /// in the Parameters panel would (e.g. the Covariance panel's vibration threshold, dragged
  /// on its log scale of 1 - threshold).
  void parameterChosen(const QString& key, double value);
  /// The panel asks the window to measure the view as it is shown with each variant of the
  /// shown technique's parameters ("key=value" assignments on top of the view's), one frame
  /// each on the render thread, against the exact reference (e.g. the Covariance panel's
  /// error at fixed turns). A newer request with the same tag replaces an unfinished one;
  /// the errors come back through showVariantError.
  void variantErrorsRequested(const QString& tag, const QList<QStringList>& variants);

 protected:
  /// Puts `content` under a placeholder switch: showContent(false, text) shows the text.
  void setContent(QWidget* content);
  void showContent(bool on, const QString& placeholder = {});

 private:
  QStackedWidget* stack_ = nullptr;
  QLabel* placeholder_ = nullptr;
};

/// A publication panel's content, before PublicationPanel::setContent: the widget and its
/// column layout, with the panels' margins (kPanelColumnMargin on every side).
inline constexpr int kPanelColumnMargin = 4;  ///< px
struct PanelColumn {
  QWidget* content = nullptr;
  QVBoxLayout* layout = nullptr;
};
PanelColumn newPanelColumn();

/// The plots and images of `panel` shown on screen below the size they read at from the back
/// of a lecture hall (PlotWidget::kReadableHeight and kReadableCurves, ImageView::kReadableSide)
/// or with a legend over the curves: one phrase each ("a plot 25 px tall, its curves 10 px").
/// Hidden ones, and ones behind another tab, are not counted.
QStringList unreadableParts(const QWidget& panel);
/// Whether the plots and images of `panel` (also ones it makes later) take their readable
/// size as their minimum: presenter mode asks the layouts for readable sizes, and gives that
/// up for a panel that cannot have them on its screen.
void setReadableMinimums(QWidget& panel, bool on);
/// Whether `widget` lies in a panel that asks for readable sizes.
bool asksReadableMinimum(const QWidget& widget);

}  // namespace sl::ui
