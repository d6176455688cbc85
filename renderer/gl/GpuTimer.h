// Per-pass timing. On software rasterisers (llvmpipe) GL_TIME_ELAPSED is meaningless, so
// each pass is timed with glFinish + a wall clock; on real GPUs with timer queries, read
// one frame late so the CPU never waits for the GPU (the frame's stats then hold the
// previous frame's pass times; the first frame has none). The method is reported with
// every measurement. The names of the passes opened this frame are known at once, whatever
// the method (passOrder).
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "core/FrameStats.h"
#include "gl/Gl.h"

namespace sl::gl {

class GpuTimer {
 public:
  using Method = TimingMethod;
  /// `method` given: that one (tests, RendererOptions::timing). Else SHADOWLAB_TIMING=
  /// finish|query, else from GL_RENDERER (glFinish + wall clock on software rasterisers).
  explicit GpuTimer(std::optional<Method> method = std::nullopt);
  Method method() const { return method_; }
  std::string methodName() const;

  void beginFrame();
  void begin(const std::string& pass);
  void end();
  /// Finish+wallclock: this frame's pass times. Timer queries: the previous frame's, read
  /// without waiting (if the GPU has not finished them yet, the last results read are
  /// returned again and framesLate() grows).
  std::vector<PassTiming> endFrame();
  /// The results endFrame() last returned, one entry per scope in the order they ran, not
  /// summed by name (a pass repeated per tile: one entry per tile).
  const std::vector<PassTiming>& sequence() const { return sequence_; }
  /// The passes opened since beginFrame(), one name per pass in the order each was first
  /// opened (FrameStats::passOrder): this frame's, with either method, also after endFrame().
  std::vector<std::string> passOrder() const;
  /// How many frames old the timer-query results endFrame() returned are (0 for
  /// finish+wallclock; 1 normally for queries).
  int framesLate() const { return method_ == Method::TimerQuery ? late_ : 0; }

  /// RAII scope for one pass.
  class Scope {
   public:
    Scope(GpuTimer& t, const std::string& pass) : t_(t) { t_.begin(pass); }
    ~Scope() { t_.end(); }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    GpuTimer& t_;
  };
  Scope scope(const std::string& pass) { return Scope(*this, pass); }

 private:
  struct Entry {
    std::string name;
    GLuint query = 0;
    std::chrono::steady_clock::time_point start;
    double ms = 0.0;
  };
  Method method_;
  std::vector<Entry> entries_;
  std::vector<std::string> opened_;  ///< this frame's scopes in the order they opened
  std::vector<Entry> pending_;       ///< the previous frame's query entries, not yet read
  std::vector<PassTiming> lastResults_;
  std::vector<PassTiming> sequence_;                ///< lastResults_ before summing
  std::vector<Handle<QueryDeleter>> queryPool_[2];  ///< alternate frames
  int pool_ = 0, pendingPool_ = 0;
  int late_ = 0;
  size_t queriesUsed_ = 0;
  bool open_ = false;
};

}  // namespace sl::gl
