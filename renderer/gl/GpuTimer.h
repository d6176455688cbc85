// Per-pass timing. On software rasterisers (llvmpipe) GL_TIME_ELAPSED is meaningless, so
// each pass is timed with glFinish + a wall clock; on real GPUs with timer queries.
// The method used is reported with every measurement.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "core/FrameStats.h"
#include "gl/Gl.h"

namespace sl::gl {

class GpuTimer {
 public:
  enum class Method { FinishWallClock, TimerQuery };
  GpuTimer();  ///< picks the method from GL_RENDERER (SHADOWLAB_TIMING=finish|query overrides)
  Method method() const { return method_; }
  std::string methodName() const;

  void beginFrame();
  void begin(const std::string& pass);
  void end();
  /// Collects the results of this frame (blocks on queries).
  std::vector<PassTiming> endFrame();

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
  std::vector<Handle<QueryDeleter>> queryPool_;
  size_t queriesUsed_ = 0;
  bool open_ = false;
};

}  // namespace sl::gl
