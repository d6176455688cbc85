// The view's state, shared by the parts of the 3D view (ViewportWidget): what is shown
// (technique, scene, camera, light, the split view's right half) and the frame on screen
// (its images, size, number and the view it is of), paused or not. Plain data: the parts
// (CameraController, the frame loop, the measurement, the painter) read and change it; the
// widget owns it.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include <QImage>
#include <QPointF>
#include <QSize>
#include <QString>

#include "core/Renderer.h"
#include "core/ViewSide.h"

namespace sl::ui {

struct ViewModel {
  ViewModel() : shared(sl::rendererParamDecls()) { main.setSharedParams(&shared); }
  ViewModel(const ViewModel&) = delete;
  ViewModel& operator=(const ViewModel&) = delete;

  // What is shown.
  bool ready = false;  ///< the render service is running
  QString glDescription;
  sl::ParamSet shared;                ///< the view and shading parameters of both halves
  sl::ViewSide main;                  ///< the main technique (the left half in split view)
  std::optional<sl::ViewSide> split;  ///< the right half, while the split view is on
  std::string splitTechniqueId;
  std::map<std::string, std::string> splitParams;  ///< given to setSplitTechnique
  std::set<std::string> splitPublicationKeys;
  std::shared_ptr<const sl::Scene> scene;
  sl::Camera camera;
  sl::Light light;
  bool continuous = false;  ///< rendering continuously (else on demand)
  bool paused = false;
  bool pausedBadge = true;
  QPointF hover{-1.0, -1.0};  ///< the mouse over the view (widget pixels), -1: not over it

  // The frame on screen.
  QImage mainImage;      ///< its main half (internal size)
  QImage splitImage;     ///< its right half (internal size)
  int frameDivisor = 1;  ///< the adaptive divisor it was rendered at
  QSize internalSize;    ///< the main renderer's frame (device pixels)
  double lastFrameMs = 0.0;
  QString frameFailure;                 ///< the last main frame's problem (empty: it rendered)
  std::uint64_t framesRendered = 0;     ///< complete frames of the view as it was
  std::uint64_t viewRevision = 1;       ///< bumped by everything that changes the image
  std::uint64_t shownViewRevision = 0;  ///< of the frame on screen

  /// The renderer's outside view (view.outside) is on.
  bool outsideView() const { return shared.has("view.outside") && shared.getBool("view.outside"); }
};

}  // namespace sl::ui
