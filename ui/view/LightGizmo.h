// The light drawn over the view (widget pixels): a sun's arrow down to the scene's centre,
// a bulb's rays and its foot on the ground, a spot's cone to the floor. Projected with the
// main camera; no GL.
#pragma once

#include <optional>

#include <QLineF>
#include <QPointF>
#include <QVector>

#include "algo/Camera.h"
#include "algo/Light.h"
#include "scene/Scene.h"

namespace sl::ui {

struct LightGizmo {
  QVector<QLineF> lines;
  std::optional<QPointF> point;  ///< the light's own point when on screen
};

/// The gizmo of `light` in a view of `width` x `height` widget pixels; empty without a scene.
LightGizmo lightGizmo(const sl::Scene* scene, const sl::Light& light, const sl::Camera& camera,
                      double width, double height);

}  // namespace sl::ui
