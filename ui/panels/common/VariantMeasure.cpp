// Variants of the shown view measured on the render thread (VariantMeasure.h).
#include "panels/common/VariantMeasure.h"

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "service/RenderService.h"
#include "view/ViewportWidget.h"
#include "core/ViewSide.h"
#include "panels/common/PanelKit.h"

namespace sl::ui {

VariantMeasure::VariantMeasure(ViewportWidget* viewport, QObject* parent)
    : QObject(parent), viewport_(viewport) {}

void VariantMeasure::start(PublicationPanel* panel, const QString& tag,
                           const QList<QStringList>& variants) {
  ++serial_;
  panel_ = panel;
  tag_ = tag;
  variants_ = variants;
  next_ = 0;
  const sl::ViewSide* main = viewport_ ? viewport_->mainSide() : nullptr;
  frame_ = main ? main->publication().frameIndex : 0;
  measureNext();
}

void VariantMeasure::cancel() {
  ++serial_;
  panel_ = nullptr;
  variants_.clear();
  next_ = 0;
}

void VariantMeasure::measureNext() {
  if (!panel_ || next_ >= variants_.size()) return;
  const int index = int(next_);
  auto answer = [this, index](double pct, const QString& problem) {
    if (panel_) panel_->showVariantError(tag_, index, pct, frame_, problem);
  };
  sl::ViewSide* main = viewport_ ? viewport_->mainSide() : nullptr;
  const QSize size = viewport_ ? viewport_->frames()->frameSize() : QSize();
  if (!main || !viewport_->scene() || size.isEmpty()) {
    answer(std::numeric_limits<double>::quiet_NaN(), tr("the view has no frame yet"));
    cancel();
    return;
  }
  // What the render thread needs, copied now: the view's values, then the variant's.
  const std::string id = main->techniqueId();
  sl::ParamSet own = main->paramsOf(id);
  sl::ParamSet shared = main->rendererParams();
  for (const QString& a : variants_[next_]) {
    const std::string key = a.section(QLatin1Char('='), 0, 0).toStdString();
    const std::string value = a.section(QLatin1Char('='), 1).toStdString();
    sl::ParamSet& set = own.has(key) ? own : shared;
    if (auto e = set.setFromString(key, value)) {
      answer(std::numeric_limits<double>::quiet_NaN(), QString::fromStdString(*e));
      cancel();
      return;
    }
  }
  const sl::Camera camera = viewport_->camera()->camera();
  const sl::Light light = viewport_->camera()->light();
  const std::shared_ptr<const sl::Scene> scene = viewport_->scene();
  const int width = size.width(), height = size.height();
  const std::uint64_t serial = serial_;
  QPointer<VariantMeasure> self(this);
  viewport_->service().post(RenderTag::kVariants, [=](RenderContext& c) {
    double pct = std::numeric_limits<double>::quiet_NaN();
    std::string problem;
    try {
      sl::Renderer& r = c.renderer("variants");
      if (r.scene() != scene) r.setScene(scene);
      if (auto e = r.setTechnique(id)) throw std::runtime_error(*e);
      sl::syncParams(r.params(), own);
      sl::syncParams(r.rendererParams(), shared);
      r.resetTemporalState();
      r.setLight(light);
      r.setCamera(camera);
      if (auto e = r.renderFrame(width, height, 0)) throw std::runtime_error(*e);
      const sl::ShadowErrorStats error = r.computeError().stats;
      if (error.covered > 0)
        pct = error.errorPct;
      else
        problem = "no covered pixel";
    } catch (const std::exception& e) {
      problem = e.what();
    }
    QMetaObject::invokeMethod(
        self.data(),
        [self, serial, index, pct, problem] {
          if (!self || serial != self->serial_) return;  // a newer request replaced it
          if (self->panel_)
            self->panel_->showVariantError(self->tag_, index, pct, self->frame_,
                                           QString::fromStdString(problem));
          self->next_ = index + 1;
          self->measureNext();
        },
        Qt::QueuedConnection);
  });
}

}  // namespace sl::ui
