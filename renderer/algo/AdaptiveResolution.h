// The interactive view's adaptive internal resolution (issue 15 item 6): a frame slower than
// the budget makes the next ones render at 1/2, 1/4 or 1/8 of the view's size (chosen from
// how much slower it was, frame cost taken as proportional to pixels), and a frame fast
// enough that the next size up (4x the pixels) would still fit well inside the budget climbs
// one step back. Plain C++: the GUI feeds it frame times; the CLI never uses it.
#pragma once

namespace sl {

class AdaptiveResolution {
 public:
  static constexpr int kMaxDivisor = 8;
  /// Climb when 4 x the frame time stays below this share of the budget (hysteresis).
  static constexpr double kClimbShare = 0.6;

  /// The view renders at its size / divisor() (1, 2, 4 or 8).
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
