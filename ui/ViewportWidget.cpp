// The 3D view (see ViewportWidget.h). Every renderer call that may touch GL runs with this
// widget's context current; the widget itself issues no GL calls.
#include "ViewportWidget.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <QGuiApplication>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QPainter>
#include <QWheelEvent>

#include "GlSupport.h"
#include "MessageText.h"
#include "WindowShortcuts.h"
#include "algo/CameraNavigation.h"
#include "algo/MemoryMatch.h"
#include "common/shared_constants.h"
#include "metrics/ErrorMetrics.h"

namespace sl::ui {

namespace {
constexpr int kFlyTickMs = 16;

/// The error of a frame, or nothing when it measured nothing (no covered pixel): never a 0
/// that was not measured.
std::optional<double> errorPercentOf(const sl::ShadowErrorStats& stats) {
  if (stats.covered == 0) return std::nullopt;
  return stats.errorPct;
}

/// Why a frame's error is not a number ("no covered pixel"), for "error n/a (...)".
QString unmeasuredReason(const sl::ShadowErrorStats& stats) {
  return stats.covered == 0 ? QObject::tr("no covered pixel") : QString();
}

/// Index of `name` in the enum declaration of the shared parameter `key`, or -1.
int enumIndexOf(const sl::ParamSet& params, const char* key, const char* name) {
  const sl::ParamDecl* d = params.find(key);
  if (!d) return -1;
  for (std::size_t i = 0; i < d->enumNames.size(); ++i)
    if (d->enumNames[i] == name) return static_cast<int>(i);
  return -1;
}

/// "name · error 0.420 % · [note ·] 3.1 ms": the error first (a narrow half elides the end),
/// `errorNote` (the live reference's age) right after it.
/// `unmeasured`: why there is no error (a failed frame, no covered pixel): "error n/a (why)"
/// instead of "error —" (not computed yet).
QString captionFor(const std::string& techniqueId, const sl::FrameStats& stats,
                   std::optional<double> errorPct, const QString& errorNote = {},
                   const QString& unmeasured = {}) {
  const sl::TechniqueInfo* info = sl::Renderer::findTechnique(techniqueId);
  QString s = info ? QString::fromStdString(info->name) : QString::fromStdString(techniqueId);
  s += errorPct               ? QStringLiteral("  \u00b7  error %1 %").arg(*errorPct, 0, 'f', 3)
       : unmeasured.isEmpty() ? QStringLiteral("  \u00b7  error \u2014")
                              : QStringLiteral("  \u00b7  error n/a (%1)").arg(unmeasured);
  if (!errorNote.isEmpty()) s += QStringLiteral("  \u00b7  ") + errorNote;
  s += QStringLiteral("  \u00b7  %1 ms").arg(stats.totalMs, 0, 'f', stats.totalMs < 10 ? 2 : 1);
  return s;
}
}  // namespace

/// Drawn over the GL view (a plain child widget, composited by Qt; no GL): the split view's
/// right half, the captions, the banner, the pause badge and the overlay legends.
class ViewOverlay : public QWidget {
 public:
  explicit ViewOverlay(QWidget* parent) : QWidget(parent) {
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
  }

  QImage split;  ///< right half (device pixels), null when the split view is off
  QString leftCaption, rightCaption, bannerTitle, bannerText, pausedText;
  enum class Legend { None, Error, Aliasing, WarpGrid, Changed } legend = Legend::None;
  /// The outside view's line colours and what they stand for (empty: not in outside view).
  QVector<QPair<QColor, QString>> outsideLegend;
  /// The light gizmo (widget pixels): lines, and the light's own point when on screen.
  QVector<QLineF> gizmoLines;
  std::optional<QPointF> gizmoPoint;
  QString errorNote;       ///< under the error legend: the reference's state, empty when current
  QString resolutionNote;  ///< adaptive resolution: the internal size and why (empty: full)
  /// The changed overlay's count (pixels whose hard test flipped since the last frame, of
  /// those covered in both), or nothing yet.
  std::optional<std::pair<std::uint64_t, std::uint64_t>> changedCount;
  std::optional<QPointF> pointerRing;  ///< presenter mode's pointer highlight (widget px)
  QImage zoomSource;                   ///< the zoom area's pixels, device pixels
  QRect zoomArea;                      ///< widget pixels (empty: no inset)
  QRect zoomDrag;                      ///< the rectangle being dragged (empty: none)
  QRect insetRect;                     ///< where paintEvent drew the inset (widget px)
  int insetFactor = 0;

  /// The inset's place: the largest whole magnification of `zoomArea` that fits in 45 % of
  /// the view's width and height, in the bottom-right corner.
  void placeInset() {
    insetRect = QRect();
    insetFactor = 0;
    if (zoomArea.isEmpty() || zoomSource.isNull()) return;
    const int f = std::min(width() * 45 / 100 / zoomArea.width(),
                           (height() - fontMetrics().height() - 34) * 45 / 100 / zoomArea.height());
    if (f < 2) return;
    insetFactor = f;
    const QSize size(zoomArea.width() * f, zoomArea.height() * f);
    // Above the bottom row of legends and captions (one line of text and their margins).
    const int bottom = fontMetrics().height() + 34;
    insetRect = QRect(QPoint(width() - size.width() - 14, height() - size.height() - bottom), size);
  }

  bool hasContent() const {
    return !split.isNull() || !bannerTitle.isEmpty() || !bannerText.isEmpty() || pointerRing ||
           !zoomArea.isEmpty() || !zoomDrag.isEmpty() || changedCount || !pausedText.isEmpty() ||
           legend != Legend::None || !gizmoLines.isEmpty() || gizmoPoint ||
           !outsideLegend.isEmpty() || !resolutionNote.isEmpty();
  }

 protected:
  void paintEvent(QPaintEvent*) override {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QFontMetrics fm = fontMetrics();
    const int line = fm.height();
    QColor boxColor(20, 22, 25, 200);
    auto box = [&](const QRectF& r) {
      p.setPen(Qt::NoPen);
      p.setBrush(boxColor);
      p.drawRoundedRect(r, 5, 5);
    };
    int bottomInset = 8;
    if (!gizmoLines.isEmpty() || gizmoPoint) {  // the light (Alt+drag moves it)
      p.setPen(QPen(QColor(255, 214, 60, 230), 1.6));
      p.drawLines(gizmoLines);
      if (gizmoPoint) {
        p.setBrush(QColor(255, 230, 120, 230));
        p.drawEllipse(*gizmoPoint, 6.0, 6.0);
      }
    }
    if (!split.isNull()) {
      const int half = width() / 2;
      p.drawImage(QRect(half, 0, width() - half, height()), split);
      p.setPen(QPen(QColor(255, 255, 255, 220), 2));
      p.drawLine(half, 0, half, height());
      // The captions wrap (never cut: the error is the number a comparison is about).
      int captionsH = line;
      for (int side = 0; side < 2; ++side) {
        const QString& text = side == 0 ? leftCaption : rightCaption;
        const int x0 = side == 0 ? 0 : half;
        const int w = side == 0 ? half : width() - half;
        const int tw = std::min(w - 16, fm.horizontalAdvance(text) + 16);
        const QRect bounds = fm.boundingRect(QRect(0, 0, std::max(1, tw - 8), 10000),
                                             Qt::TextWordWrap | Qt::AlignCenter, text);
        const int th = std::max(line, bounds.height());
        captionsH = std::max(captionsH, th);
        const QRectF r(x0 + (w - tw) / 2.0, height() - th - 18, tw, th + 10);
        box(r);
        p.setPen(Qt::white);
        p.drawText(r.adjusted(4, 0, -4, 0), Qt::AlignCenter | Qt::TextWordWrap, text);
      }
      bottomInset = captionsH + 26;
    }
    if (!bannerTitle.isEmpty() || !bannerText.isEmpty()) {
      const int w = std::min(width() - 24, std::max(360, width() * 2 / 3));
      QFont bold = font();
      bold.setBold(true);
      const QRect textRect(0, 0, w - 20, 10000);
      const QRect textBounds =
          fm.boundingRect(textRect, Qt::TextWordWrap | Qt::AlignLeft, bannerText);
      const QRect titleBounds = QFontMetrics(bold).boundingRect(
          textRect, Qt::TextWordWrap | Qt::AlignLeft, bannerTitle);  // wrapped, never cut
      const int titleH = bannerTitle.isEmpty() ? 0 : titleBounds.height() + 4;
      const QRectF r(12, 10, w, titleH + (bannerText.isEmpty() ? 0 : textBounds.height()) + 14);
      boxColor = QColor(20, 22, 25, 215);
      box(r);
      p.setPen(QColor(255, 200, 60));
      p.setFont(bold);
      p.drawText(QRectF(r.left() + 10, r.top() + 6, w - 20, titleH),
                 Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, bannerTitle);
      p.setFont(font());
      p.setPen(Qt::white);
      p.drawText(QRectF(r.left() + 10, r.top() + 7 + titleH, w - 20, textBounds.height() + 2),
                 Qt::TextWordWrap | Qt::AlignLeft, bannerText);
      boxColor = QColor(20, 22, 25, 200);
    }
    if (!pausedText.isEmpty()) {
      const int tw = fm.horizontalAdvance(pausedText) + 20;
      const QRectF r(width() - tw - 12, bannerTitle.isEmpty() && bannerText.isEmpty() ? 10 : 10, tw,
                     line + 10);
      boxColor = QColor(150, 40, 40, 220);
      box(r);
      boxColor = QColor(20, 22, 25, 200);
      p.setPen(Qt::white);
      p.drawText(r, Qt::AlignCenter, pausedText);
    }
    if (!outsideLegend.isEmpty()) {  // top right, under the pause badge
      int tw = fm.horizontalAdvance(tr("OUTSIDE VIEW (V)"));
      for (const auto& [colour, text] : outsideLegend)
        tw = std::max(tw, fm.horizontalAdvance(text));
      tw += 44;
      const int rows = int(outsideLegend.size()) + 1;
      const QRectF r(width() - tw - 12, line + 28, tw, rows * line + 12);
      box(r);
      p.setPen(QColor(255, 200, 60));
      p.drawText(QRectF(r.left() + 10, r.top() + 6, tw - 16, line),
                 Qt::AlignLeft | Qt::AlignVCenter, tr("OUTSIDE VIEW (V)"));
      for (int i = 0; i < int(outsideLegend.size()); ++i) {
        const double y = r.top() + 6 + (i + 1) * line;
        p.fillRect(QRectF(r.left() + 10, y + line / 2.0 - 1.5, 18, 3), outsideLegend[i].first);
        p.setPen(Qt::white);
        p.drawText(QRectF(r.left() + 34, y, tw - 40, line), Qt::AlignLeft | Qt::AlignVCenter,
                   outsideLegend[i].second);
      }
    }
    if (!resolutionNote.isEmpty()) {  // bottom right: the view is not at full size
      const int tw = std::min(width() - 24, fm.horizontalAdvance(resolutionNote) + 20);
      const int th =
          std::max(line, fm.boundingRect(QRect(0, 0, std::max(1, tw - 8), 10000),
                                         Qt::TextWordWrap | Qt::AlignCenter, resolutionNote)
                             .height());
      const QRectF r(width() - tw - 12, height() - bottomInset - th - 10, tw, th + 10);
      box(r);
      p.setPen(QColor(255, 200, 60));
      p.drawText(r.adjusted(4, 0, -4, 0), Qt::AlignCenter | Qt::TextWordWrap, resolutionNote);
    }
    if (legend == Legend::Aliasing) {
      // Same colours as aliasingColor() in shaders/common/composite.frag (log2 m in -4..4,
      // blended at 70 % over the shaded scene there).
      // As wide as its caption (and at least the bar's 260 px), never cutting it.
      const QString caption = tr("texels per pixel m (red: undersampled)");
      const double legendW =
          std::min<double>(width() - 24, std::max(260, fm.horizontalAdvance(caption) + 24));
      const QRectF r(12, height() - bottomInset - 2 * line - 30, legendW, 2 * line + 22);
      box(r);
      const QRectF bar(r.left() + 10, r.top() + 8, r.width() - 20, 10);
      for (int i = 0; i < int(bar.width()); ++i) {
        const double t = (i + 0.5) / bar.width() * 2.0 - 1.0;  // log2(m) / 4
        const QColor blue(38, 89, 242), red(230, 26, 26);
        const QColor end = t < 0 ? blue : red;
        const double f = std::abs(t);
        p.fillRect(QRectF(bar.left() + i, bar.top(), 1, bar.height()),
                   QColor::fromRgbF(1 + (end.redF() - 1) * f, 1 + (end.greenF() - 1) * f,
                                    1 + (end.blueF() - 1) * f));
      }
      p.setPen(Qt::white);
      const QRectF labels(bar.left(), bar.bottom() + 2, bar.width(), line);
      p.drawText(labels, Qt::AlignLeft, QStringLiteral("m \u2264 1/16"));
      p.drawText(labels, Qt::AlignHCenter, QStringLiteral("1"));
      p.drawText(labels, Qt::AlignRight, QStringLiteral("\u2265 16"));
      p.drawText(QRectF(bar.left(), labels.bottom(), bar.width(), line), Qt::AlignHCenter, caption);
    } else if (legend == Legend::Error) {
      const QString a = tr("false lit (light leak)"), b = tr("false shadowed");
      const QString& note = errorNote;
      const int tw =
          std::max({fm.horizontalAdvance(a), fm.horizontalAdvance(b), fm.horizontalAdvance(note)}) +
          44;
      const int rows = note.isEmpty() ? 2 : 3;
      const QRectF r(12, height() - bottomInset - rows * line - 16, tw, rows * line + 12);
      box(r);
      const QColor colors[] = {QColor(255, 0, 255), QColor(0, 255, 255)};
      const QString texts[] = {a, b};
      for (int i = 0; i < 2; ++i) {
        const double y = r.top() + 6 + i * line;
        p.fillRect(QRectF(r.left() + 10, y + 3, 18, line - 6), colors[i]);
        p.setPen(Qt::white);
        p.drawText(QRectF(r.left() + 34, y, tw - 40, line), Qt::AlignLeft | Qt::AlignVCenter,
                   texts[i]);
      }
      if (!note.isEmpty())
        p.drawText(QRectF(r.left() + 10, r.top() + 6 + 2 * line, tw - 16, line),
                   Qt::AlignLeft | Qt::AlignVCenter, note);
    } else if (legend == Legend::Changed) {
      const QString t = changedCount ? tr("%L1 pixels changed since the last frame (of %L2)")
                                           .arg(changedCount->first)
                                           .arg(changedCount->second)
                                     : tr("pixels changed since the last frame: needs two frames");
      const int swatch = line - 6;
      const QRectF r(12, height() - bottomInset - line - 12, fm.horizontalAdvance(t) + swatch + 30,
                     line + 10);
      box(r);
      const float c[3] = {SL_CHANGED_COLOUR};
      p.fillRect(QRectF(r.left() + 10, r.top() + 8, swatch, swatch),
                 QColor::fromRgbF(c[0], c[1], c[2]));
      p.setPen(Qt::white);
      p.drawText(QRectF(r.left() + swatch + 18, r.top(), r.width() - swatch - 22, r.height()),
                 Qt::AlignLeft | Qt::AlignVCenter, t);
    } else if (legend == Legend::WarpGrid) {
      const QString t = tr("shadow-map grid: every 1/16 of the map");
      const QRectF r(12, height() - bottomInset - line - 12, fm.horizontalAdvance(t) + 20,
                     line + 10);
      box(r);
      p.setPen(QColor(255, 217, 26));
      p.drawText(r, Qt::AlignCenter, t);
    }
    placeInset();
    if (insetFactor > 0) {  // the zoom inset: nearest neighbour, whole texels per pixel
      const QRectF source(zoomArea.topLeft() * zoomSource.devicePixelRatio(),
                          zoomArea.size() * zoomSource.devicePixelRatio());
      p.setRenderHint(QPainter::SmoothPixmapTransform, false);
      p.drawImage(QRectF(insetRect), zoomSource, source);
      p.setBrush(Qt::NoBrush);
      p.setPen(QPen(QColor(255, 230, 0), 3));
      p.drawRect(QRectF(insetRect).adjusted(-1.5, -1.5, 1.5, 1.5));
      p.setPen(QPen(QColor(255, 230, 0), 2, Qt::DashLine));
      p.drawRect(QRectF(zoomArea).adjusted(-1, -1, 1, 1));
      const QString label = QStringLiteral("\u00d7%1").arg(insetFactor);
      const QRectF lr(insetRect.left(), insetRect.top() - line - 8,
                      fm.horizontalAdvance(label) + 16, line + 6);
      box(lr);
      p.setPen(QColor(255, 230, 0));
      p.drawText(lr, Qt::AlignCenter, label);
    }
    if (!zoomDrag.isEmpty()) {
      p.setBrush(Qt::NoBrush);
      p.setPen(QPen(QColor(255, 230, 0), 2, Qt::DashLine));
      p.drawRect(zoomDrag);
    }
    if (pointerRing) {  // presenter mode: a ring around the pointer, dark halo for contrast
      const double radius = std::max(18.0, line * 1.1);
      p.setBrush(Qt::NoBrush);
      p.setPen(QPen(QColor(0, 0, 0, 170), 7));
      p.drawEllipse(*pointerRing, radius, radius);
      p.setPen(QPen(QColor(255, 40, 200), 4));
      p.drawEllipse(*pointerRing, radius, radius);
    }
  }
};

ViewportWidget::ViewportWidget(QWidget* parent) : QOpenGLWidget(parent) {
  // Keep the last frame in the FBO: a paused view repaints without rendering.
  setUpdateBehavior(QOpenGLWidget::PartialUpdate);
  overlay_ = new ViewOverlay(this);
  overlay_->hide();
  setFocusPolicy(Qt::StrongFocus);
  setMouseTracking(true);  // hover: the pixel under the mouse (pixelProbed)
  setMinimumSize(160, 120);
  errorTimer_.setSingleShot(true);
  connect(&errorTimer_, &QTimer::timeout, this, &ViewportWidget::computeErrorIfStill);
  // Adaptive resolution: once the view is still, a reduced frame is redrawn at full size.
  settleTimer_.setSingleShot(true);
  connect(&settleTimer_, &QTimer::timeout, this, [this] {
    if (frameDivisor_ == 1) return;
    if (dragButton_ != Qt::NoButton || !heldKeys_.empty()) return settleTimer_.start();
    fullSizeNext_ = true;
    update();
  });
  flyTimer_.setInterval(kFlyTickMs);
  connect(&flyTimer_, &QTimer::timeout, this, &ViewportWidget::flyStep);
}

ViewportWidget::~ViewportWidget() {
  liveReference_.reset();  // cancels a running trace and joins the worker
  splitLiveReference_.reset();
  destroyRenderer();
}

void ViewportWidget::initializeGL() {
  // A new context (first show, or after re-parenting): free the renderer with it.
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &ViewportWidget::destroyRenderer,
          Qt::UniqueConnection);
  // Signals go out queued: their receivers may open dialogs, which must not happen while
  // Qt is inside initializeGL.
  auto fail = [this](const QString& message) {
    QMetaObject::invokeMethod(
        this, [this, message] { Q_EMIT initializationFailed(message); }, Qt::QueuedConnection);
  };
  if (auto problem = checkContext(*context())) return fail(*problem);
  try {
    renderer_ = std::make_unique<sl::Renderer>();
  } catch (const std::exception& e) {
    return fail(
        QStringLiteral("the renderer could not start: %1").arg(QString::fromStdString(e.what())));
  }
  applyStateToRenderer();
  QMetaObject::invokeMethod(
      this, [this] { Q_EMIT rendererReady(); }, Qt::QueuedConnection);
}

void ViewportWidget::applyStateToRenderer() {
  if (scene_) renderer_->setScene(scene_);
  if (!techniqueId_.empty()) {
    if (auto error = renderer_->setTechnique(techniqueId_))
      Q_EMIT renderProblem(QString::fromStdString(*error));
  }
  techniqueId_ = renderer_->techniqueId();
  renderer_->setCamera(camera_);
  renderer_->setLight(light_);
  lastTechniqueId_.clear();
}

void ViewportWidget::destroyRenderer() {
  cancelLiveReferences();  // their results would be of a renderer gone
  if (!renderer_) return;
  Q_EMIT rendererAboutToBeDestroyed();
  makeCurrent();
  splitRenderer_.reset();
  renderer_.reset();
  doneCurrent();
}

void ViewportWidget::paintGL() {
  if (!renderer_) return;
  const qreal dpr = devicePixelRatioF();
  const int w = static_cast<int>(std::lround(width() * dpr));
  const int h = static_cast<int>(std::lround(height() * dpr));
  // Paused: the last frame stays in the FBO (PartialUpdate) unless a step is pending or the
  // size changed (a resized FBO holds nothing).
  if (paused_ && pendingSteps_ == 0 && lastFrameSize_ == QSize(w, h) && framesRendered_ > 0) return;
  if (pendingSteps_ > 0) --pendingSteps_;
  lastFrameSize_ = QSize(w, h);

  // Parameters are edited by panels directly in the renderer's ParamSets: notice it here.
  if (renderer_->techniqueId() != lastTechniqueId_ ||
      renderer_->params().revision() != lastParamRevision_ ||
      renderer_->rendererParams().revision() != lastRendererParamRevision_) {
    lastTechniqueId_ = renderer_->techniqueId();
    lastParamRevision_ = renderer_->params().revision();
    lastRendererParamRevision_ = renderer_->rendererParams().revision();
    markViewChanged();
  }
  if (splitRenderer_ && !splitParamsPending_ &&
      splitRenderer_->params().revision() != lastSplitParamRevision_) {
    lastSplitParamRevision_ = splitRenderer_->params().revision();  // edited in its panel
    splitErrorPct_.reset();
    markViewChanged();
  }
  renderer_->setCamera(camera_);
  renderer_->setLight(light_);

  // A view dragged down to a few pixels draws nothing: a frame that small feeds temporal
  // state (DA-RTW's rotation, kept by its vibration threshold) a degenerate importance
  // map, and the restored view measured 0.188 % error instead of 0.174 % (split_resize.sh).
  if (w < kMinDrawnPx || h < kMinDrawnPx) {
    sl::Renderer::clearFrame(w, h, defaultFramebufferObject());
    ++framesRendered_;
    Q_EMIT frameRendered();
    return;
  }
  std::string problem;
  // No right half narrower than the smallest drawn view: the left half takes it all.
  const bool split = !splitTechniqueId_.empty() && w / 2 >= kMinDrawnPx;
  const int mainWidth = split ? w / 2 : w;
  lastMainWidth_ = mainWidth;

  // Adaptive resolution: render at 1/divisor of the size (never below the smallest drawn
  // view), stretched over it by the renderer.
  const sl::ParamSet& shared = renderer_->rendererParams();
  const bool adaptive = adaptiveActive();
  if (!adaptive && adaptive_.divisor() != 1) adaptive_.reset();
  // A still view's settle frame (and an export's) is drawn at full size: what stays on
  // screen, and what is measured, is never the reduced image.
  const bool settle = std::exchange(fullSizeNext_, false);
  int divisor = settle ? 1 : adaptive_.divisor();
  while (divisor > 1 && (mainWidth / divisor < kMinDrawnPx || h / divisor < kMinDrawnPx))
    divisor /= 2;
  if (divisor != frameDivisor_) markViewChanged();  // another image: the error is not its
  frameDivisor_ = divisor;
  const int frameW = sl::AdaptiveResolution::scaled(mainWidth, divisor);
  const int frameH = sl::AdaptiveResolution::scaled(h, divisor);
  internalSize_ = QSize(frameW, frameH);
  // Progressive resolve (continuous rendering with adaptive resolution on): a technique that
  // resolves tile by tile spends at most half the budget on tiles per frame and keeps its
  // result between frames, so that no frame blocks the event loop for seconds
  // (virtual-tiled's 256 tiles). Scripted runs and on-demand frames resolve in one call.
  const bool progressive = adaptiveAllowed_ && continuous_ && !paused_;
  renderer_->setProgressiveBudget(
      progressive ? kProgressiveShare * double(shared.getInt("view.adaptive.budget_ms")) : 0.0);
  QElapsedTimer frameClock;
  frameClock.start();
  if (split)
    renderSplitHalf(sl::AdaptiveResolution::scaled(w - mainWidth, divisor), frameH, problem);

  std::optional<std::string> error;
  try {
    error = renderer_->renderFrame(frameW, frameH, defaultFramebufferObject(), mainWidth, h);
  } catch (const std::exception& e) {
    error = std::string("renderer: ") + e.what();
  }
  lastFrameMs_ = std::max(double(frameClock.nsecsElapsed()) / 1e6, renderer_->stats().totalMs);
  frameFailure_ = error ? QString::fromStdString(*error) : QString();
  // A progressive frame's tiles are bounded by their own budget: the resolution follows the
  // rest (the per-pixel work), else a slow tile would drop the view and restart the tiles.
  const auto& progress = renderer_->stats().progress;
  if (adaptive && !error && !settle)
    adaptive_.onFrame(progress ? std::max(0.0, lastFrameMs_ - progress->spentMs) : lastFrameMs_,
                      double(shared.getInt("view.adaptive.budget_ms")));
  if (progress && !error)
    progressNote_ = *progress;
  else
    progressNote_.reset();
  ++framesRendered_;
  if (error) problem += (problem.empty() ? "" : "; ") + *error;
  for (const std::string& glError : renderer_->takeGlErrors())
    problem += (problem.empty() ? "" : "; ") + glError;
  if (!problem.empty() && problem != lastProblem_)
    Q_EMIT renderProblem(QString::fromStdString(problem));
  lastProblem_ = problem;

  updateZoomInset();
  // A partial progressive frame is neither traced nor measured: the error waits for the
  // complete one.
  const bool partial = !renderer_->stats().complete();
  if (continuous_ && !error && !partial) updateLiveReference();
  updateOverlayWidget();
  Q_EMIT frameRendered();
  probeHover();  // the frame changed under a still mouse
  // On demand (or paused): the error is computed once the view is still (restarted by every
  // frame). Continuous: the live reference above keeps it.
  if (frameDivisor_ > 1 && (!continuous_ || paused_))
    settleTimer_.start(kSettleDelayMs);
  else
    settleTimer_.stop();
  if (partial)
    errorTimer_.stop();
  else if (!errorIsCurrent() && (!continuous_ || paused_))
    errorTimer_.start(kErrorDelayMs);
  // A progressive frame yields to the event loop before the next one: the next frame is
  // asked for from a 1 ms timer, so that timers and input already due (ordered by due
  // time) run first instead of queueing behind back-to-back frames.
  if (continuous_ && !paused_) {
    if (progress && !error)
      QTimer::singleShot(1, this, [this] { update(); });
    else
      update();
  }
}

// GL current. Creates the split renderer and applies the technique and parameters
// setSplitTechnique gave; the problem, or nothing.
std::optional<std::string> ViewportWidget::prepareSplitRenderer() {
  if (!splitRenderer_) {
    sl::RendererOptions options;
    options.debugOutput = false;  // the main renderer keeps the context's debug callback
    splitRenderer_ = std::make_unique<sl::Renderer>(options);
    if (scene_) splitRenderer_->setScene(scene_);
  }
  if (splitRenderer_->techniqueId() != splitTechniqueId_)
    if (auto e = splitRenderer_->setTechnique(splitTechniqueId_)) return "split view: " + *e;
  std::optional<std::string> problem;
  if (splitParamsPending_) {  // checked by setSplitTechnique: cannot fail here
    splitRenderer_->params().resetToDefaults();
    for (const auto& [key, value] : splitParams_)
      if (auto e = splitRenderer_->params().setFromString(key, value))
        problem = "split view: " + *e;
    splitRenderer_->resetTemporalState();
    splitParamsPending_ = false;
    lastSplitParamRevision_ = splitRenderer_->params().revision();
  }
  splitRenderer_->requestPublications(splitPublicationKeys_);
  return problem;
}

sl::Renderer* ViewportWidget::splitRenderer() {
  if (!renderer_ || splitTechniqueId_.empty()) return nullptr;
  makeCurrent();
  std::optional<std::string> problem;
  try {
    problem = prepareSplitRenderer();
  } catch (const std::exception& e) {
    problem = std::string("split view: ") + e.what();
  }
  doneCurrent();
  if (problem) {
    Q_EMIT renderProblem(QString::fromStdString(*problem));
    return splitRenderer_ && splitRenderer_->techniqueId() == splitTechniqueId_
               ? splitRenderer_.get()
               : nullptr;
  }
  return splitRenderer_.get();
}

std::optional<ViewportWidget::MemoryMatch> ViewportWidget::matchSplitMemory(std::string* error) {
  auto fail = [&](const std::string& why) -> std::optional<MemoryMatch> {
    if (error) *error = why;
    return std::nullopt;
  };
  sl::Renderer* split = splitRenderer();
  if (!split) return fail("the split view is off");
  if (framesRendered_ == 0 || renderer_->stats().frameIndex == 0)
    return fail("no frame of the main technique yet");
  sl::ParamSet& params = split->params();
  const sl::ParamDecl* decl = sl::memoryKnob(params.decls());
  if (!decl)
    return fail("technique '" + splitTechniqueId_ +
                "' declares no parameter its memory grows with, so there is nothing to match");
  MemoryMatch match;
  match.key = decl->key;
  match.mainBytes = renderer_->stats().memory.bytes();
  const qreal dpr = devicePixelRatioF();
  const int w = static_cast<int>(std::lround(width() * dpr));
  const int h = static_cast<int>(std::lround(height() * dpr));
  const int halfW = w - w / 2;
  if (halfW < kMinDrawnPx || h < kMinDrawnPx) return fail("the view is too small to measure");
  makeCurrent();
  split->setCamera(camera_);
  split->setLight(light_);
  // The bytes at a value: one frame of the right half (its size, this camera and light).
  const sl::MemoryMatchResult m = sl::matchMemory(
      std::llround(decl->minValue), std::llround(decl->maxValue), std::llround(decl->step),
      match.mainBytes, [&](long long value, std::string& problem) -> std::optional<std::uint64_t> {
        if (auto e = params.set(decl->key, double(value))) {
          problem = *e;
          return std::nullopt;
        }
        if (auto e = split->renderFrame(halfW, h, defaultFramebufferObject())) {
          problem = *e;
          return std::nullopt;
        }
        return split->stats().memory.bytes();
      });
  match.framesMeasured = m.evaluations;
  match.value = m.value;
  match.belowMinimum = m.belowMinimum;
  split->resetTemporalState();
  doneCurrent();
  if (!m.ok()) return fail("split view: " + m.problem);
  match.splitBytes = m.bytes;
  splitParams_[decl->key] = params.format(decl->key);
  lastSplitParamRevision_ = ~0u;  // the next frame notices the change
  update();
  return match;
}

void ViewportWidget::renderSplitHalf(int width, int height, std::string& problem) {
  try {
    if (auto e = prepareSplitRenderer()) {
      problem = *e;
      if (!splitRenderer_ || splitRenderer_->techniqueId() != splitTechniqueId_) return;
    }
    // Same camera, light and shared (view/shading) parameters as the left half.
    sl::ParamSet& mine = splitRenderer_->rendererParams();
    for (const sl::ParamDecl& d : renderer_->rendererParams().decls())
      if (mine.has(d.key) && mine.get(d.key) != renderer_->rendererParams().get(d.key))
        (void)mine.set(d.key, renderer_->rendererParams().get(d.key));
    splitRenderer_->setCamera(camera_);
    splitRenderer_->setLight(light_);
    // renderFrame always draws at the target's origin: render the right half first, read
    // its colour back for the overlay widget, then let the left half overwrite the origin.
    if (auto e = splitRenderer_->renderFrame(width, height, defaultFramebufferObject())) {
      problem = "split view: " + *e;
      return;
    }
    const sl::ImageRGBA8 color = splitRenderer_->readColor();  // the colour only
    splitImage_ =
        QImage(color.pixels.data(), color.width, color.height, QImage::Format_RGBA8888).copy();
  } catch (const std::exception& e) {
    problem = std::string("split view: ") + e.what();
  }
}

void ViewportWidget::updateOverlayWidget() {
  updateLightGizmo();
  const bool split = !splitTechniqueId_.empty() && splitRenderer_;
  overlay_->split = split ? splitImage_ : QImage();
  if (split) {
    // Continuous rendering: each half's live error (its own reference) and how old it is.
    auto caption = [this](const std::string& id, const sl::FrameStats& stats,
                          std::optional<double> exact, const std::optional<LiveError>& live,
                          const QString& unmeasured) {
      if (!continuous_)
        return captionFor(id, stats, errorIsCurrent() ? exact : std::nullopt, {},
                          errorIsCurrent() ? unmeasured : QString());
      const bool measured = live && live->unmeasured.isEmpty();
      return captionFor(id, stats, measured ? std::optional(live->errorPct) : std::nullopt,
                        live ? QString::fromStdString(sl::describeReferenceAge(live->age))
                             : tr("tracing the reference\u2026"),
                        live ? live->unmeasured : QString());
    };
    overlay_->leftCaption = caption(renderer_->techniqueId(), renderer_->stats(), mainErrorPct_,
                                    liveError(), errorUnmeasured_);
    overlay_->rightCaption = caption(splitTechniqueId_, splitRenderer_->stats(), splitErrorPct_,
                                     splitLiveError(), splitErrorUnmeasured_);
  }
  overlay_->legend = ViewOverlay::Legend::None;
  if (renderer_ && renderer_->rendererParams().has("view.overlay")) {
    const sl::ParamSet& p = renderer_->rendererParams();
    const int v = p.getInt("view.overlay");
    if (v == enumIndexOf(p, "view.overlay", "error"))
      overlay_->legend = ViewOverlay::Legend::Error;
    else if (v == enumIndexOf(p, "view.overlay", "aliasing"))
      overlay_->legend = ViewOverlay::Legend::Aliasing;
    else if (v == enumIndexOf(p, "view.overlay", "warp-grid"))
      overlay_->legend = ViewOverlay::Legend::WarpGrid;
    else if (v == enumIndexOf(p, "view.overlay", "changed"))
      overlay_->legend = ViewOverlay::Legend::Changed;
  }
  overlay_->changedCount.reset();
  if (overlay_->legend == ViewOverlay::Legend::Changed && renderer_->stats().maskChange)
    overlay_->changedCount = std::make_pair(renderer_->stats().maskChange->changed,
                                            renderer_->stats().maskChange->compared);
  overlay_->pointerRing.reset();
  if (pointerHighlight_ && hover_.x() >= 0) overlay_->pointerRing = hover_;
  overlay_->zoomArea = zoomArea_.value_or(QRect());
  overlay_->zoomDrag = zoomDragging_.value_or(QRect());
  overlay_->outsideLegend.clear();
  if (renderer_ && outsideView() && renderer_->stats().outsideCamera) {
    auto colour = [](sl::OutlineRole role, int map) {
      const glm::vec3 c = sl::outlineColour(role, map);
      return QColor::fromRgbF(c.r, c.g, c.b);
    };
    const sl::FrameOutlines& o = renderer_->stats().outlines;
    auto& legend = overlay_->outsideLegend;
    legend.append(
        {colour(sl::OutlineRole::Camera, 0), tr("camera frustum (to the scene's far end)")});
    if (!o.splitDepthsM.empty())
      legend.append({colour(sl::OutlineRole::Split, 0), tr("split planes")});
    int maps = 0;
    bool warp = false;
    for (const sl::FrustumOutline& f : o.frusta) {
      if (f.role == sl::OutlineRole::LightMap) maps = std::max(maps, f.map + 1);
      warp = warp || f.role == sl::OutlineRole::Warp;
    }
    for (int i = 0; i < std::min(maps, 8); ++i)
      legend.append({colour(sl::OutlineRole::LightMap, i),
                     maps == 1 ? (warp ? tr("light frustum (unwarped)") : tr("light frustum"))
                               : tr("light frustum, map %1").arg(i)});
    if (warp)
      legend.append({colour(sl::OutlineRole::Warp, 0), tr("warped map's frustum, to its centre")});
    // m and the error are the main camera's pixels' (Renderer: compositeInto): not drawn here.
    if (overlay_->legend == ViewOverlay::Legend::Aliasing ||
        overlay_->legend == ViewOverlay::Legend::Error) {
      legend.append({QColor(0, 0, 0, 0), overlay_->legend == ViewOverlay::Legend::Aliasing
                                             ? tr("aliasing overlay: main view only (V)")
                                             : tr("error overlay: main view only (V)")});
      overlay_->legend = ViewOverlay::Legend::None;
    }
  }
  overlay_->resolutionNote = resolutionNote();
  overlay_->errorNote.clear();
  if (continuous_) {  // the live reference: how old, or being traced for this view
    const auto live = liveError();
    overlay_->errorNote = !live || live->age.stale
                              ? tr("view changed: tracing its reference\u2026")
                              : QString::fromStdString(sl::describeReferenceAge(live->age));
  } else if (!errorIsCurrent()) {
    overlay_->errorNote = tr("(computing the reference\u2026)");
  }
  overlay_->pausedText =
      paused_ && pausedBadge_
          ? tr("PAUSED at frame %1  \u00b7  . step  \u00b7  Space resume")
                .arg(renderer_ ? static_cast<qulonglong>(renderer_->stats().frameIndex) : 0)
          : QString();
  overlay_->setVisible(overlay_->hasContent());
  overlay_->raise();
  overlay_->update();
}

void ViewportWidget::resizeEvent(QResizeEvent* event) {
  QOpenGLWidget::resizeEvent(event);
  overlay_->setGeometry(rect());
}

void ViewportWidget::setPaused(bool paused, bool badge) {
  pausedBadge_ = badge;
  if (paused_ == paused) return updateOverlayWidget();
  paused_ = paused;
  pendingSteps_ = 0;
  // Paused in continuous rendering: no more frames, so the still view's error is computed
  // as on demand.
  if (paused_ && !errorIsCurrent()) errorTimer_.start(kErrorDelayMs);
  updateOverlayWidget();
  update();
}

void ViewportWidget::stepFrame() {
  ++pendingSteps_;
  update();
}

std::optional<std::string> ViewportWidget::setSplitTechnique(
    const std::string& techniqueId, const std::map<std::string, std::string>& params) {
  const sl::TechniqueInfo* info =
      techniqueId.empty() ? nullptr : sl::Renderer::findTechnique(techniqueId);
  if (!techniqueId.empty() && !info) {
    std::string known;
    for (const sl::TechniqueInfo& t : sl::Renderer::techniques())
      known += (known.empty() ? "" : ", ") + t.id;
    return "unknown technique '" + techniqueId + "' (known: " + known + ")";
  }
  if (info) {
    sl::ParamSet check(info->params);
    for (const auto& [key, value] : params) {
      if (!check.has(key))
        return "split view: technique '" + techniqueId + "' has no parameter '" + key + "'";
      if (auto e = check.setFromString(key, value)) return "split view: " + *e;
    }
  }
  splitTechniqueId_ = techniqueId;
  splitParams_ = info ? params : std::map<std::string, std::string>{};
  splitParamsPending_ = true;
  splitErrorPct_.reset();
  if (splitLiveReference_) splitLiveReference_->cancel();  // of the previous right half
  splitLiveLatest_.reset();
  markViewChanged();
  if (paused_) ++pendingSteps_;
  update();
  if (techniqueId.empty()) updateOverlayWidget();
  Q_EMIT splitChanged();
  return std::nullopt;
}

std::map<std::string, std::string> ViewportWidget::splitParams() const {
  if (splitTechniqueId_.empty()) return {};
  if (splitParamsPending_ || !splitRenderer_ || splitRenderer_->techniqueId() != splitTechniqueId_)
    return splitParams_;
  std::map<std::string, std::string> out;
  const sl::ParamSet& set = splitRenderer_->params();
  for (const sl::ParamDecl& d : set.decls()) out[d.key] = set.format(d.key);
  return out;
}

void ViewportWidget::setBanner(const QString& title, const QString& text) {
  overlay_->bannerTitle = shownMessage(title);
  overlay_->bannerText = shownSummary(text);
  overlay_->setVisible(overlay_->hasContent());
  overlay_->raise();
  overlay_->update();
}

void ViewportWidget::setPointerHighlight(bool on) {
  pointerHighlight_ = on;
  setMouseTracking(true);
  updateOverlayWidget();
}

void ViewportWidget::setZoomArea(const std::optional<QRect>& area) {
  zoomArea_ = area ? std::optional<QRect>(area->intersected(rect())) : std::nullopt;
  if (zoomArea_ && zoomArea_->isEmpty()) zoomArea_.reset();
  if (renderer_) {
    makeCurrent();
    updateZoomInset();
    doneCurrent();
  }
  updateOverlayWidget();
}

ViewportWidget::Readouts ViewportWidget::readouts() const {
  Readouts r;
  r.internalDivisor = frameDivisor_;
  r.adaptiveDivisor = adaptive_.divisor();
  r.lastFrameMs = lastFrameMs_;
  r.progress = progressNote_;
  r.probesRead = probesRead_;
  r.leftCaption = splitCaption(false);
  r.rightCaption = splitCaption(true);
  r.errorOverlayNote = errorOverlayNote();
  r.pointerHighlight = pointerHighlight_;
  r.zoomArea = zoomArea_;
  r.zoomInset = zoomInsetRect();
  r.zoomFactor = zoomFactor();
  r.liveReference = liveReference_.get();
  r.splitLiveReference = splitLiveReference_.get();
  return r;
}

QRect ViewportWidget::zoomInsetRect() const {
  overlay_->placeInset();
  return overlay_->insetRect;
}

int ViewportWidget::zoomFactor() const {
  overlay_->placeInset();
  return overlay_->insetFactor;
}

QImage ViewportWidget::renderedImage() {
  if (!renderer_ || framesRendered_ == 0) return {};
  const sl::ImageRGBA8 main = renderer_->readColor();
  if (main.width == 0) return {};
  const QImage left =
      QImage(main.pixels.data(), main.width, main.height, QImage::Format_RGBA8888).copy();
  const bool split = !splitTechniqueId_.empty() && splitRenderer_ && !splitImage_.isNull();
  if (!split) return left;
  QImage both(left.width() + splitImage_.width(), std::max(left.height(), splitImage_.height()),
              QImage::Format_RGBA8888);
  both.fill(Qt::black);
  QPainter p(&both);
  p.drawImage(0, 0, left);
  p.drawImage(left.width(), 0, splitImage_);
  return both;
}

// GL current (paintGL, or made current by the caller).
void ViewportWidget::updateZoomInset() {
  if (!zoomArea_) {
    overlay_->zoomSource = QImage();
    return;
  }
  QImage image = renderedImage();
  image.setDevicePixelRatio(devicePixelRatioF());
  overlay_->zoomSource = image;
}

QImage ViewportWidget::grabView() {
  QImage image = grabFramebuffer();
  if (overlay_->isVisible()) {
    QPainter p(&image);
    p.scale(image.width() / std::max(1.0, double(width())),
            image.height() / std::max(1.0, double(height())));
    overlay_->render(&p, QPoint(), QRegion(), QWidget::DrawChildren);
  }
  return image;
}

void ViewportWidget::resizeGL(int, int) {
  markViewChanged();
}

void ViewportWidget::setScene(std::shared_ptr<const sl::Scene> scene) {
  scene_ = std::move(scene);
  cancelLiveReferences();  // a trace of the old scene is never shown
  if (scene_ && scene_->light) light_ = *scene_->light;
  Q_EMIT lightChanged();
  if (renderer_) {
    makeCurrent();
    renderer_->setScene(scene_);
    renderer_->setLight(light_);
    renderer_->resetTemporalState();
    if (splitRenderer_) splitRenderer_->setScene(scene_);
    doneCurrent();
  }
  resetView();
}

std::optional<std::string> ViewportWidget::setTechnique(const std::string& id) {
  if (!renderer_) {
    if (!sl::Renderer::findTechnique(id)) {
      std::string known;
      for (const sl::TechniqueInfo& t : sl::Renderer::techniques())
        known += (known.empty() ? "" : ", ") + t.id;
      return "unknown technique '" + id + "' (known: " + known + ")";
    }
    techniqueId_ = id;
    return std::nullopt;
  }
  makeCurrent();
  auto error = renderer_->setTechnique(id);
  doneCurrent();
  if (error) return error;
  techniqueId_ = renderer_->techniqueId();
  update();
  return std::nullopt;
}

void ViewportWidget::setCamera(const sl::Camera& camera) {
  camera_ = camera;
  markViewChanged();
  Q_EMIT cameraChanged();
  update();
}

void ViewportWidget::goToBookmark(int index) {
  if (!scene_) return;
  if (index >= 0 && index < static_cast<int>(scene_->cameras.size()))
    setCamera(scene_->cameras[static_cast<size_t>(index)].camera);
  else
    setCamera(scene_->defaultCamera());
}

void ViewportWidget::resetView() {
  goToBookmark(0);
}

void ViewportWidget::setLight(const sl::Light& light) {
  if (light_ == light) return;
  light_ = light;
  markViewChanged();
  update();
  Q_EMIT lightChanged();
}

bool ViewportWidget::outsideView() const {
  return renderer_ && renderer_->rendererParams().has("view.outside") &&
         renderer_->rendererParams().getBool("view.outside");
}

bool ViewportWidget::setOutsideView(bool on) {
  if (!renderer_ || !renderer_->rendererParams().has("view.outside")) return false;
  if (outsideView() == on) return true;
  if (renderer_->rendererParams().set("view.outside", on ? 1.0 : 0.0)) return false;
  updateOverlayWidget();
  update();
  return true;
}

void ViewportWidget::adjustOutsideView(float azimuthDeg, float elevationDeg, float zoomFactor) {
  sl::ParamSet& p = renderer_->rendererParams();
  auto clampSet = [&](const char* key, double v) {
    const sl::ParamDecl* d = p.find(key);
    if (d) (void)p.set(key, std::clamp(v, d->minValue, d->maxValue));
  };
  double az = p.get("view.outside.azimuth_deg") + azimuthDeg;
  az = std::remainder(az, 360.0);
  clampSet("view.outside.azimuth_deg", az);
  clampSet("view.outside.elevation_deg", p.get("view.outside.elevation_deg") + elevationDeg);
  clampSet("view.outside.zoom", p.get("view.outside.zoom") * zoomFactor);
  update();
}

void ViewportWidget::updateLightGizmo() {
  overlay_->gizmoLines.clear();
  overlay_->gizmoPoint.reset();
  if (outsideView()) return;  // the gizmo is drawn for the main camera's projection
  if (!scene_ || !scene_->bounds.valid() || width() <= 0 || height() <= 0) return;
  const glm::mat4 viewProj = camera_.projection(float(width()) / float(height())) * camera_.view();
  auto project = [&](const glm::vec3& p) -> std::optional<QPointF> {
    const glm::vec4 c = viewProj * glm::vec4(p, 1.0f);
    if (!(c.w > 1e-4f)) return std::nullopt;  // behind the camera
    return QPointF((c.x / c.w * 0.5 + 0.5) * width(), (0.5 - c.y / c.w * 0.5) * height());
  };
  auto line = [&](const glm::vec3& a, const glm::vec3& b) {
    auto pa = project(a), pb = project(b);
    if (pa && pb) overlay_->gizmoLines.append(QLineF(*pa, *pb));
  };
  const float size = glm::length(scene_->bounds.size());
  if (light_.type == sl::LightType::Directional) {
    // An arrow from the sky down to the scene's centre, along the light.
    const glm::vec3 end = scene_->bounds.center();
    const glm::vec3 start = end + light_.directionalTowards() * (0.35f * size);
    line(start, end);
    const glm::vec3 d = glm::normalize(end - start);
    const glm::vec3 side = glm::normalize(
        glm::cross(d, std::abs(d.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
    const float head = 0.04f * size;
    line(end, end - d * head + side * (0.5f * head));
    line(end, end - d * head - side * (0.5f * head));
    overlay_->gizmoPoint = project(start);
    return;
  }
  const glm::vec3 pos = light_.positionM;
  overlay_->gizmoPoint = project(pos);
  if (light_.type == sl::LightType::Point) {  // a bulb: short rays around the point
    const float r = 0.03f * size;
    for (glm::vec3 d : {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)}) {
      line(pos + d * r, pos + d * (2.0f * r));
      line(pos - d * r, pos - d * (2.0f * r));
    }
    line(pos, glm::vec3(pos.x, scene_->bounds.min.y, pos.z));  // its foot on the ground
    return;
  }
  // Spot: the outer cone's outline down to the scene's floor (or 1/3 of its size).
  const glm::vec3 axis = light_.spotAxis();
  float len = 0.33f * size;
  if (axis.y < -0.05f) len = std::min(2.0f * size, (pos.y - scene_->bounds.min.y) / -axis.y);
  const glm::vec3 u = glm::normalize(
      glm::cross(axis, std::abs(axis.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
  const glm::vec3 v = glm::cross(axis, u);
  const float radius = len * std::tan(glm::radians(light_.outerConeDeg));
  glm::vec3 previous{};
  for (int i = 0; i <= 32; ++i) {
    const float a = float(i) / 32.0f * 6.2831853f;
    const glm::vec3 p = pos + axis * len + (u * std::cos(a) + v * std::sin(a)) * radius;
    if (i > 0) line(previous, p);
    if (i % 8 == 0 && i < 32) line(pos, p);
    previous = p;
  }
}

void ViewportWidget::dragLight(const QPoint& d) {
  sl::Light l = light_;
  if (l.type == sl::LightType::Directional) {
    l.azimuthDeg = std::remainder(l.azimuthDeg + float(d.x()) * 0.5f, 360.0f);
    l.elevationDeg = std::clamp(l.elevationDeg - float(d.y()) * 0.5f, 1.0f, 90.0f);
  } else {
    // Move on the horizontal plane through the light, right/forward as the camera sees it.
    const glm::vec3 fw = camera_.forward();
    glm::vec3 forward(fw.x, 0.0f, fw.z);
    if (glm::length(forward) < 1e-3f) forward = glm::vec3(0, 0, -1);
    forward = glm::normalize(forward);
    const glm::vec3 right(-forward.z, 0.0f, forward.x);
    const float distM = std::max(0.1f, glm::length(l.positionM - camera_.position));
    const float mPerPixel = 2.0f * distM * std::tan(glm::radians(camera_.fovYDeg) * 0.5f) /
                            float(std::max(1, height()));
    l.positionM += right * (float(d.x()) * mPerPixel) - forward * (float(d.y()) * mPerPixel);
  }
  if (!l.validate()) setLight(l);
}

void ViewportWidget::setContinuous(bool on) {
  continuous_ = on;
  if (on) {
    errorTimer_.stop();
    for (auto* worker : {&liveReference_, &splitLiveReference_})
      if (!*worker)
        *worker = std::make_unique<sl::AsyncReference>(kLiveReferenceMinIntervalS,
                                                       kLiveReferenceDurationFactor);
    update();
  } else {
    cancelLiveReferences();
    if (!errorIsCurrent()) errorTimer_.start(kErrorDelayMs);
  }
  updateOverlayWidget();
}

// GL current (paintGL).
void ViewportWidget::updateLiveReference() {
  if (!liveReference_ || !renderer_) return;
  if (auto failure = liveReference_->takeFailure())
    Q_EMIT renderProblem(
        QStringLiteral("reference trace failed: %1").arg(QString::fromStdString(*failure)));
  if (auto done = liveReference_->takeFinished()) {
    const bool current = done->viewRevision == viewRevision_;
    // The error overlay draws the mask only while frames show what was traced (the
    // renderer compares frame signatures); a mask of an earlier view is not drawn.
    if (current)
      renderer_->setReferenceMask(done->trace.frameSignature, done->trace.referenceMask,
                                  done->trace.width, done->trace.height);
    done->trace.referenceMask = {};
    liveLatest_ = std::move(done);
    if (current) {
      mainErrorPct_ = errorPercentOf(liveLatest_->trace.stats);
      errorUnmeasured_ = unmeasuredReason(liveLatest_->trace.stats);
      errorRevision_ = viewRevision_;
      if (mainErrorPct_)
        Q_EMIT errorComputed(*mainErrorPct_);
      else
        Q_EMIT errorUnmeasured(errorUnmeasured_);
    }
  }
  updateSplitLiveReference();
  if (!liveReference_->wantsTrace(viewRevision_)) return;
  if (auto job = referenceJob(*renderer_, viewRevision_, framesRendered_))
    liveReference_->submit(std::move(*job));
}

void ViewportWidget::cancelLiveReferences() {
  for (sl::AsyncReference* worker : {liveReference_.get(), splitLiveReference_.get()})
    if (worker) worker->cancel();
  liveLatest_.reset();
  splitLiveLatest_.reset();
}

// GL current (paintGL, after both halves rendered).
void ViewportWidget::updateSplitLiveReference() {
  const bool split = !splitTechniqueId_.empty() && splitRenderer_ &&
                     splitRenderer_->techniqueId() == splitTechniqueId_ && !splitImage_.isNull();
  if (!splitLiveReference_ || !split) return;
  if (auto failure = splitLiveReference_->takeFailure())
    Q_EMIT renderProblem(QStringLiteral("split view: reference trace failed: %1")
                             .arg(QString::fromStdString(*failure)));
  if (auto done = splitLiveReference_->takeFinished()) {
    done->trace.referenceMask = {};  // the error overlay is the left half's only
    splitLiveLatest_ = std::move(done);
    if (splitLiveLatest_->viewRevision == viewRevision_)
      splitErrorPct_ = splitLiveLatest_->trace.stats.errorPct;
  }
  if (!splitLiveReference_->wantsTrace(viewRevision_)) return;
  if (auto job = referenceJob(*splitRenderer_, viewRevision_, framesRendered_))
    splitLiveReference_->submit(std::move(*job));
}

std::optional<ViewportWidget::LiveError> ViewportWidget::splitLiveError() const {
  if (!continuous_ || !splitLiveLatest_ || splitTechniqueId_.empty()) return std::nullopt;
  LiveError e;
  e.errorPct = splitLiveLatest_->trace.stats.errorPct;
  e.unmeasured = unmeasuredReason(splitLiveLatest_->trace.stats);
  e.age = sl::referenceAge(*splitLiveLatest_, viewRevision_, framesRendered_,
                           sl::AsyncReference::steadySeconds());
  return e;
}

QString ViewportWidget::splitCaption(bool right) const {
  return right ? overlay_->rightCaption : overlay_->leftCaption;
}

// GL current: the snapshot is read here; the worker traces CPU copies only.
std::optional<sl::ReferenceJob> ViewportWidget::referenceJob(sl::Renderer& renderer,
                                                             std::uint64_t viewRevision,
                                                             std::uint64_t frameNumber) {
  auto snapshot =
      std::make_shared<sl::Renderer::ReferenceSnapshot>(renderer.snapshotForReference());
  if (!snapshot->reference) return std::nullopt;
  sl::ReferenceJob job;
  job.viewRevision = viewRevision;
  job.frameNumber = frameNumber;
  job.trace = [snapshot](const std::atomic<bool>& cancelled) -> std::optional<sl::ReferenceTrace> {
    const int width = snapshot->frame.width, height = snapshot->frame.height;
    std::string signature = snapshot->frameSignature;
    auto result = sl::Renderer::traceReference(std::move(*snapshot), &cancelled);
    if (!result) return std::nullopt;
    sl::ReferenceTrace t;
    t.stats = result->stats;
    t.referenceMask = std::move(result->referenceMask);
    t.width = width;
    t.height = height;
    t.frameSignature = std::move(signature);
    return t;
  };
  return job;
}

std::optional<ViewportWidget::LiveError> ViewportWidget::liveError() const {
  if (!continuous_ || !liveLatest_) return std::nullopt;
  LiveError e;
  e.errorPct = liveLatest_->trace.stats.errorPct;
  e.unmeasured = unmeasuredReason(liveLatest_->trace.stats);
  e.age = sl::referenceAge(*liveLatest_, viewRevision_, framesRendered_,
                           sl::AsyncReference::steadySeconds());
  return e;
}

QString ViewportWidget::errorOverlayNote() const {
  return overlay_->errorNote;
}

QString ViewportWidget::liveErrorText() const {
  if (!continuous_) return {};
  const auto e = liveError();
  if (!e) return tr("error \u2014  \u00b7  tracing the reference\u2026");
  const QString age = QString::fromStdString(sl::describeReferenceAge(e->age));
  if (!e->unmeasured.isEmpty()) return tr("error n/a (%1)  \u00b7  %2").arg(e->unmeasured, age);
  const QString pct = QString::number(e->errorPct, 'f', e->errorPct < 1 ? 3 : 2);
  if (e->age.stale) return tr("error %1 %  \u00b7  %2  \u00b7  re-tracing").arg(pct, age);
  return tr("error %1 %  \u00b7  %2").arg(pct, age);
}

void ViewportWidget::setAdaptiveAllowed(bool allowed) {
  adaptiveAllowed_ = allowed;
  update();
}

void ViewportWidget::setPresenting(bool on) {
  presenting_ = on;
  update();
}

bool ViewportWidget::adaptiveActive() const {
  if (!adaptiveAllowed_ || presenting_ || !splitTechniqueId_.empty() || !renderer_) return false;
  const sl::ParamSet& shared = renderer_->rendererParams();
  return shared.has("view.adaptive") && shared.getBool("view.adaptive");
}

void ViewportWidget::renderFullSizeNow() {
  if (frameDivisor_ == 1 || !renderer_) return;
  fullSizeNext_ = true;
  repaint();
}

QString ViewportWidget::resolutionNote() const {
  QString note;
  if (frameDivisor_ > 1)
    note =
        tr("internal resolution %1\u00d7%2: frame took %3 ms")
            .arg(internalSize_.width())
            .arg(internalSize_.height())
            .arg(adaptive_.dropFrameMs() > 0 ? adaptive_.dropFrameMs() : lastFrameMs_, 0, 'f', 0);
  const QString tiles = progressText();
  if (!tiles.isEmpty()) note += (note.isEmpty() ? QString() : QStringLiteral("  \u00b7  ")) + tiles;
  return note;
}

QString ViewportWidget::progressText() const {
  if (!progressNote_ || progressNote_->shownComplete) return {};
  const int per = std::max(1, progressNote_->unitsPerTile);
  const int bands = progressNote_->done % per;
  const QString ofNext = bands ? tr(" (+ %1 of %2 bands)").arg(bands).arg(per) : QString();
  return tr("tile %1 of %2%3: drawn progressively, error when complete")
      .arg(progressNote_->done / per)
      .arg(progressNote_->total / per)
      .arg(ofNext);
}

void ViewportWidget::setProbeWanted(bool wanted) {
  if (probeWanted_ == wanted) return;
  probeWanted_ = wanted;
  if (!wanted) {
    Q_EMIT pixelProbed(std::nullopt);
  } else if (hover_.x() >= 0 && renderer_) {
    makeCurrent();
    probeHover();
    doneCurrent();
  }
}

std::optional<double> ViewportWidget::computeErrorNow() {
  if (!renderer_ || framesRendered_ == 0) return std::nullopt;
  // A frame that failed is not measured: its image is the neutral frame, not the technique's.
  if (!frameFailure_.isEmpty()) {
    errorRevision_ = viewRevision_;
    mainErrorPct_.reset();
    errorUnmeasured_ = tr("the frame failed: %1").arg(frameFailure_);
    Q_EMIT errorUnmeasured(errorUnmeasured_);
    updateOverlayWidget();
    return std::nullopt;
  }
  makeCurrent();
  std::optional<double> pct;
  bool computed = false;
  try {
    const sl::ShadowErrorStats main = renderer_->computeError().stats;
    pct = errorPercentOf(main);
    errorUnmeasured_ = unmeasuredReason(main);
    computed = true;
    if (!splitTechniqueId_.empty() && splitRenderer_) {
      const sl::ShadowErrorStats split = splitRenderer_->computeError().stats;
      splitErrorPct_ = errorPercentOf(split);
      splitErrorUnmeasured_ = unmeasuredReason(split);
    }
  } catch (const std::exception& e) {
    Q_EMIT renderProblem(
        QStringLiteral("error metric failed: %1").arg(QString::fromStdString(e.what())));
  }
  doneCurrent();
  if (!computed) return std::nullopt;
  errorRevision_ = viewRevision_;
  mainErrorPct_ = pct;
  if (!pct) {
    Q_EMIT errorUnmeasured(errorUnmeasured_);
    updateOverlayWidget();
    return std::nullopt;
  }
  Q_EMIT errorComputed(*pct);
  // The error overlay shows the reference just computed: draw it (one more frame, unless
  // paused, where the frozen frame must stay the one that was measured).
  const sl::ParamSet& shared = renderer_->rendererParams();
  if (shared.has("view.overlay") &&
      shared.getInt("view.overlay") == enumIndexOf(shared, "view.overlay", "error") && !paused_)
    update();
  updateOverlayWidget();
  return pct;
}

std::optional<std::string> ViewportWidget::reloadShaders() {
  if (!renderer_) return std::string("the renderer is not running");
  makeCurrent();
  auto error = renderer_->reloadShaders();
  doneCurrent();
  markViewChanged();
  update();
  return error;
}

void ViewportWidget::computeErrorIfStill() {
  if (errorIsCurrent()) return;
  if (dragButton_ != Qt::NoButton || !heldKeys_.empty()) {
    errorTimer_.start(kErrorDelayMs);  // still interacting: try again later
    return;
  }
  computeErrorNow();
}

std::vector<FigureCell> ViewportWidget::figureCells(int dilatePx) {
  std::vector<FigureCell> cells;
  if (!renderer_ || framesRendered_ == 0) return cells;
  renderFullSizeNow();  // a figure is never the reduced (adaptive resolution) image
  makeCurrent();
  try {
    for (sl::Renderer* r :
         {renderer_.get(), splitTechniqueId_.empty() ? nullptr : splitRenderer_.get()}) {
      if (!r) continue;
      const sl::Renderer::ErrorResult e = r->computeError();
      FigureCell c;
      c.label = r->techniqueId();
      const sl::ParamSet& ps = r->params();
      for (const sl::ParamDecl& d : ps.decls())
        if (ps.get(d.key) != d.defaultValue) c.label += " " + d.key + "=" + ps.format(d.key);
      const sl::FrameStats& st = r->stats();
      char facts[160];
      const double mib = double(st.memory.bytes()) / double(1 << 20);
      if (e.stats.covered == 0)
        std::snprintf(facts, sizeof facts, "%.3g M texels (%.3g MiB), error n/a, %.1f ms",
                      double(st.memory.texels()) / 1e6, mib, st.totalMs);
      else
        std::snprintf(facts, sizeof facts, "%.3g M texels (%.3g MiB), error %.3f %%, %.1f ms",
                      double(st.memory.texels()) / 1e6, mib, e.stats.errorPct, st.totalMs);
      c.facts = facts;
      if (const std::uint64_t debug = st.memory.debugViewBytes()) {
        char views[64];
        std::snprintf(views, sizeof views, "; debug views %.3g MiB",
                      double(debug) / double(1 << 20));
        c.facts += views;
      }
      c.shaded = e.frame.color;
      c.error = sl::makeErrorImage(e.frame.color, e.frame.hardMask, e.referenceMask, dilatePx);
      cells.push_back(std::move(c));
    }
  } catch (const std::exception& ex) {
    cells.clear();
    Q_EMIT renderProblem(
        QStringLiteral("export figure: %1").arg(QString::fromStdString(ex.what())));
  }
  doneCurrent();
  return cells;
}

void ViewportWidget::markViewChanged() {
  ++viewRevision_;
  Q_EMIT viewChanged();
}

// --- Mouse: left-drag orbit, right/middle-drag (or shift+left) pan, ctrl+left look, alt+left
// moves the light, wheel dolly.

void ViewportWidget::mousePressEvent(QMouseEvent* event) {
  constexpr Qt::KeyboardModifiers kZoomMods = Qt::ControlModifier | Qt::ShiftModifier;
  if (event->button() == Qt::LeftButton && (event->modifiers() & kZoomMods) == kZoomMods &&
      dragButton_ == Qt::NoButton) {  // the zoom inset's area
    zoomDragStart_ = event->position().toPoint();
    zoomDragging_ = QRect(zoomDragStart_, QSize(1, 1));
    event->accept();
    return;
  }
  if (dragButton_ == Qt::NoButton) {
    dragButton_ = event->button();
    lastMouse_ = event->position().toPoint();
  }
  setFocus(Qt::MouseFocusReason);
  event->accept();
}

void ViewportWidget::mouseMoveEvent(QMouseEvent* event) {
  const QPoint pos = event->position().toPoint();
  if (zoomDragging_) {
    zoomDragging_ = QRect(zoomDragStart_, pos).normalized().intersected(rect());
    updateOverlayWidget();
    return;
  }
  if (pointerHighlight_ && dragButton_ == Qt::NoButton) {
    hover_ = event->position();
    updateOverlayWidget();
  }
  if (dragButton_ == Qt::NoButton) {
    hover_ = event->position();
    if (!probeWanted_) return;  // no visible panel shows it: no readback
    makeCurrent();
    probeHover();
    doneCurrent();
    return;
  }
  const QPoint d = pos - lastMouse_;
  lastMouse_ = pos;
  if (d.isNull()) return;
  const Qt::KeyboardModifiers mods = event->modifiers();
  if (dragButton_ == Qt::LeftButton && (mods & Qt::AltModifier)) {
    dragLight(d);
    return;
  }
  if (outsideView() && dragButton_ == Qt::LeftButton && !(mods & Qt::ShiftModifier)) {
    // Outside view: the drag orbits the third camera, the main camera stays.
    const float degPerPx = sl::orbitDegPerPixel(height());
    adjustOutsideView(-d.x() * degPerPx, d.y() * degPerPx, 1.0f);
    return;
  }
  // Rates from algo/CameraNavigation: per view height, so that a drag turns or pans as far at
  // any window size (a pan keeps the point under the cursor, at the target's depth, under it).
  const float dx = static_cast<float>(d.x()), dy = static_cast<float>(d.y());
  sl::Camera cam;
  if (dragButton_ == Qt::LeftButton && (mods & Qt::ControlModifier))
    cam = sl::lookByDrag(camera_, dx, dy, height());
  else if (dragButton_ == Qt::LeftButton && !(mods & Qt::ShiftModifier))
    cam = sl::orbitByDrag(camera_, dx, dy, height());
  else
    cam = sl::panByDrag(camera_, dx, dy, height());
  if (!cam.validate()) setCamera(cam);
}

void ViewportWidget::leaveEvent(QEvent* event) {
  hover_ = QPointF(-1.0, -1.0);
  Q_EMIT pixelProbed(std::nullopt);
  if (pointerHighlight_) updateOverlayWidget();
  QOpenGLWidget::leaveEvent(event);
}

// GL current (paintGL, or made current by the caller).
void ViewportWidget::probeHover() {
  if (hover_.x() < 0 || !renderer_ || !probeWanted_) return;
  std::optional<sl::PixelProbe> probe;
  const qreal dpr = devicePixelRatioF();
  const int x = int(std::floor(hover_.x() * dpr)), y = int(std::floor(hover_.y() * dpr));
  if (!outsideView() && x < lastMainWidth_) {
    probe = renderer_->probePixel(x / frameDivisor_, y / frameDivisor_);  // internal pixels
    ++probesRead_;
  }
  Q_EMIT pixelProbed(probe);
}

void ViewportWidget::mouseReleaseEvent(QMouseEvent* event) {
  if (zoomDragging_ && event->button() == Qt::LeftButton) {
    const QRect area = *zoomDragging_;
    zoomDragging_.reset();
    // A click (no real rectangle) clears the inset.
    setZoomArea(area.width() >= 4 && area.height() >= 4 ? std::optional<QRect>(area)
                                                        : std::nullopt);
    return;
  }
  if (event->button() == dragButton_) dragButton_ = Qt::NoButton;
  if (!errorIsCurrent()) errorTimer_.start(kErrorDelayMs);
}

void ViewportWidget::wheelEvent(QWheelEvent* event) {
  const float steps = static_cast<float>(event->angleDelta().y()) / 120.0f;
  if (steps == 0.0f) return;
  if (outsideView()) {
    adjustOutsideView(0.0f, 0.0f, sl::dollyFactor(steps));
    event->accept();
    return;
  }
  // A share of the distance to the target per notch, never through it nor beyond a few scene
  // sizes (algo/CameraNavigation).
  const sl::Camera cam = sl::dollyByWheel(camera_, steps, scene_ ? scene_->bounds : sl::Aabb{});
  if (!cam.validate()) setCamera(cam);
  event->accept();
}

// --- Keys: WASD move, Q/E down/up, shift = faster. ui/WindowShortcuts sends them here from
// anywhere in the window; the view's own key events take the same way.

void ViewportWidget::keyPressEvent(QKeyEvent* event) {
  if ((event->modifiers() & (Qt::ControlModifier | Qt::AltModifier)) ||
      !flyKeyPressed(event->key(), event->isAutoRepeat())) {
    QOpenGLWidget::keyPressEvent(event);
    return;
  }
  event->accept();
}

void ViewportWidget::keyReleaseEvent(QKeyEvent* event) {
  if (!flyKeyReleased(event->key(), event->isAutoRepeat())) {
    QOpenGLWidget::keyReleaseEvent(event);
    return;
  }
  event->accept();
}

bool ViewportWidget::flyKeyPressed(int key, bool autoRepeat) {
  if (!WindowShortcuts::isFlyKey(key)) return false;
  if (!autoRepeat) heldKeys_.insert(key);
  if (!heldKeys_.empty() && !flyTimer_.isActive()) {
    flyClock_.start();
    flyTimer_.start();
    flyStep();
  }
  return true;
}

bool ViewportWidget::flyKeyReleased(int key, bool autoRepeat) {
  if (!WindowShortcuts::isFlyKey(key)) return false;
  if (!autoRepeat) heldKeys_.erase(key);
  if (heldKeys_.empty()) flyTimer_.stop();
  return true;
}

void ViewportWidget::stopFlying() {
  heldKeys_.clear();
  flyTimer_.stop();
}

void ViewportWidget::focusOutEvent(QFocusEvent* event) {
  // Held fly keys are the window's (their releases reach the view wherever the focus is);
  // a window that loses the keyboard lets go of them.
  if (event->reason() == Qt::ActiveWindowFocusReason) stopFlying();
  dragButton_ = Qt::NoButton;
  QOpenGLWidget::focusOutEvent(event);
}

void ViewportWidget::flyStep() {
  if (heldKeys_.empty()) {
    flyTimer_.stop();
    return;
  }
  // A share of the scene's size per second (algo/CameraNavigation), Shift four times faster.
  const float dtS = static_cast<float>(flyClock_.restart()) / 1000.0f;
  const bool fast = QGuiApplication::keyboardModifiers().testFlag(Qt::ShiftModifier);
  const float stepM =
      sl::flyStepM(sl::navigationScaleM(scene_ ? scene_->bounds : sl::Aabb{}, camera_), dtS, fast);
  auto axis = [this](int plus, int minus) {
    return (heldKeys_.count(plus) ? 1.0f : 0.0f) - (heldKeys_.count(minus) ? 1.0f : 0.0f);
  };
  sl::Camera cam = camera_;
  cam.fly(axis(Qt::Key_W, Qt::Key_S) * stepM, axis(Qt::Key_D, Qt::Key_A) * stepM,
          axis(Qt::Key_E, Qt::Key_Q) * stepM);
  if (!cam.validate()) setCamera(cam);
}

}  // namespace sl::ui
