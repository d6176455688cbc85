// Forward declarations of the 3D view's parts (owned by ViewportWidget, sharing its
// ViewModel), for the parts' own headers: each holds references to the others it reads.
#pragma once

class QWidget;

namespace sl::ui {

struct ViewModel;
class CameraController;
class FrameLoop;
class MeasureService;
class ViewPainter;

}  // namespace sl::ui
