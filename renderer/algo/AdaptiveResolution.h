// The interactive view's adaptive internal resolution, off by default: a frame slower than the
// budget makes the next ones render at half the view's size (never less: a lecturer's picture
// stays readable), and the first frame fast enough that full size (4x the pixels) would fit
// in the budget returns to full size. Plain C++: the GUI feeds it frame times (and redraws a
// still view at full size); the CLI, grabs, exports, presenter mode and the split view
// never use it.
#pragma once

namespace sl {

class AdaptiveResolution {
 public:
  /// The floor: half the view's size.
  static constexpr int kMaxDivisor = 2;
  /// Climb when 4 x the frame time stays below this share of the budget (hysteresis).
  static constexpr double kClimbShare = 0.8;

  /// The view renders at its size / divisor() (1 or 2).
  int divisor() const { return divisor_; }
  /// A frame rendered at divisor() took `frameMs` against `budgetMs`; true when the divisor
  /// changed (the next frame renders at the new size).
  bool onFrame(double frameMs, double budgetMs);
  /// Back to full size (the setting was turned off).
  void reset();
  /// The frame time that made the last drop (for "frame took 610 ms"), 0 before any.
  double dropFrameMs() const { return dropFrameMs_; }

  /// `px` at `divisor`: at least 1.
  static int scaled(int px, int divisor);

 private:
  int divisor_ = 1;
  double dropFrameMs_ = 0.0;
};

}  // namespace sl
