// The Light panel (LightPanel.h): rows generated from kLightFields.
#include "LightPanel.h"

#include <array>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace sl::ui {

namespace {

constexpr unsigned kDir = 1u << int(LightType::Directional);
constexpr unsigned kSpot = 1u << int(LightType::Spot);
constexpr unsigned kPoint = 1u << int(LightType::Point);

/// One editable number of sl::Light.
struct LightField {
  const char* label;
  const char* unit;
  double lo, hi, step;
  unsigned kinds;  ///< bit per LightType
  float& (*ref)(Light&);
  const char* help;
};

const std::array<LightField, 11> kLightFields = {{
    {"azimuth", "°", -180, 180, 1, kDir, [](Light& l) -> float& { return l.azimuthDeg; },
     "Degrees around the vertical, from +z towards +x"},
    {"elevation", "°", -90, 90, 1, kDir, [](Light& l) -> float& { return l.elevationDeg; },
     "Degrees above the horizon"},
    {"position x", " m", -1e4, 1e4, 0.1, kSpot | kPoint,
     [](Light& l) -> float& { return l.positionM.x; }, "World position, metres"},
    {"position y", " m", -1e4, 1e4, 0.1, kSpot | kPoint,
     [](Light& l) -> float& { return l.positionM.y; }, "World position, metres"},
    {"position z", " m", -1e4, 1e4, 0.1, kSpot | kPoint,
     [](Light& l) -> float& { return l.positionM.z; }, "World position, metres"},
    {"direction x", "", -1e3, 1e3, 0.05, kSpot, [](Light& l) -> float& { return l.direction.x; },
     "The axis the spot shines along (any length, not zero)"},
    {"direction y", "", -1e3, 1e3, 0.05, kSpot, [](Light& l) -> float& { return l.direction.y; },
     "The axis the spot shines along (any length, not zero)"},
    {"direction z", "", -1e3, 1e3, 0.05, kSpot, [](Light& l) -> float& { return l.direction.z; },
     "The axis the spot shines along (any length, not zero)"},
    {"outer cone", "°", 0.5, sl::kMaxSpotConeDeg, 1, kSpot,
     [](Light& l) -> float& { return l.outerConeDeg; },
     "Half-angle of the lit cone; outside it counts as shadowed"},
    {"inner cone", "°", 0, sl::kMaxSpotConeDeg, 1, kSpot,
     [](Light& l) -> float& { return l.innerConeDeg; },
     "Half-angle of full intensity (shading only), at most the outer one"},
    {"range", " m", 0, 1e4, 0.5, kSpot | kPoint, [](Light& l) -> float& { return l.rangeM; },
     "How far the light reaches; 0 = infinite. Beyond counts as shadowed"},
}};

}  // namespace

LightPanel::LightPanel(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("lightPanel"));
  auto* layout = new QVBoxLayout(this);
  auto* form = new QFormLayout;
  type_ = new QComboBox;
  type_->setObjectName(QStringLiteral("lightType"));
  for (LightType t : {LightType::Directional, LightType::Spot, LightType::Point})
    type_->addItem(QString::fromUtf8(lightTypeName(t).data(), int(lightTypeName(t).size())),
                   int(t));
  type_->setToolTip(
      tr("KHR_lights_punctual's three kinds. Techniques list the kinds they "
         "render; others are refused with a message."));
  connect(type_, &QComboBox::activated, this, [this] { onEdited(); });
  form->addRow(tr("type"), type_);
  for (const LightField& f : kLightFields) {
    auto* spin = new QDoubleSpinBox;
    spin->setObjectName(QStringLiteral("light ") + QString::fromUtf8(f.label));
    spin->setRange(f.lo, f.hi);
    spin->setSingleStep(f.step);
    spin->setDecimals(f.step < 1 ? 2 : 1);
    spin->setSuffix(QString::fromUtf8(f.unit));
    spin->setToolTip(tr(f.help));
    spin->setKeyboardTracking(false);
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this] { onEdited(); });
    form->addRow(tr(f.label), spin);
    fields_.push_back(spin);
    rows_.push_back(spin);
  }
  layout->addLayout(form);
  status_ = new QLabel;
  status_->setWordWrap(true);
  status_->setForegroundRole(QPalette::PlaceholderText);
  layout->addWidget(status_);
  layout->addStretch(1);
  showLight(light_);
}

void LightPanel::showLight(const Light& light) {
  light_ = light;
  {
    QSignalBlocker b(type_);
    type_->setCurrentIndex(type_->findData(int(light.type)));
  }
  for (std::size_t i = 0; i < kLightFields.size(); ++i) {
    QSignalBlocker b(fields_[i]);
    fields_[i]->setValue(double(kLightFields[i].ref(light_)));
  }
  status_->setText(QString::fromStdString(light.describe()));
  updateVisibleRows();
}

void LightPanel::updateVisibleRows() {
  const unsigned bit = 1u << type_->currentData().toInt();
  auto* form = qobject_cast<QFormLayout*>(static_cast<QVBoxLayout*>(layout())->itemAt(0)->layout());
  for (std::size_t i = 0; i < kLightFields.size(); ++i)
    if (form) form->setRowVisible(rows_[i], (kLightFields[i].kinds & bit) != 0);
}

void LightPanel::onEdited() {
  Light l = light_;
  l.type = LightType(type_->currentData().toInt());
  for (std::size_t i = 0; i < kLightFields.size(); ++i)
    if (kLightFields[i].kinds & (1u << int(l.type)))
      kLightFields[i].ref(l) = float(fields_[i]->value());
  updateVisibleRows();
  if (auto err = l.validate()) {
    status_->setText(tr("Not applied: %1").arg(QString::fromStdString(*err)));
    return;
  }
  light_ = l;
  status_->setText(QString::fromStdString(l.describe()));
  Q_EMIT lightEdited(l);
}

}  // namespace sl::ui
