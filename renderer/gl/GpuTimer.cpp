#include "GpuTimer.h"

#include <cstdlib>
#include <cstring>

namespace sl::gl {

GpuTimer::GpuTimer() {
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  std::string r = renderer ? renderer : "";
  bool software = r.find("llvmpipe") != std::string::npos ||
                  r.find("softpipe") != std::string::npos ||
                  r.find("SwiftShader") != std::string::npos;
  method_ = software ? Method::FinishWallClock : Method::TimerQuery;
  if (const char* env = std::getenv("SHADOWLAB_TIMING")) {
    if (std::strcmp(env, "finish") == 0) method_ = Method::FinishWallClock;
    if (std::strcmp(env, "query") == 0) method_ = Method::TimerQuery;
  }
}

std::string GpuTimer::methodName() const {
  return method_ == Method::FinishWallClock ? "glFinish+wallclock" : "GL_TIME_ELAPSED";
}

void GpuTimer::beginFrame() {
  entries_.clear();
  queriesUsed_ = 0;
  open_ = false;
}

void GpuTimer::begin(const std::string& pass) {
  if (open_) end();
  Entry e;
  e.name = pass;
  if (method_ == Method::FinishWallClock) {
    glFinish();
    e.start = std::chrono::steady_clock::now();
  } else {
    if (queriesUsed_ == queryPool_.size()) {
      GLuint q = 0;
      glCreateQueries(GL_TIME_ELAPSED, 1, &q);
      queryPool_.emplace_back(q);
    }
    e.query = queryPool_[queriesUsed_++].id();
    glBeginQuery(GL_TIME_ELAPSED, e.query);
  }
  entries_.push_back(std::move(e));
  open_ = true;
}

void GpuTimer::end() {
  if (!open_) return;
  open_ = false;
  Entry& e = entries_.back();
  if (method_ == Method::FinishWallClock) {
    glFinish();
    e.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - e.start)
               .count();
  } else {
    glEndQuery(GL_TIME_ELAPSED);
  }
}

std::vector<PassTiming> GpuTimer::endFrame() {
  if (open_) end();
  std::vector<PassTiming> out;
  for (Entry& e : entries_) {
    if (method_ == Method::TimerQuery) {
      GLuint64 ns = 0;
      glGetQueryObjectui64v(e.query, GL_QUERY_RESULT, &ns);
      e.ms = double(ns) * 1e-6;
    }
    // Passes with the same name (e.g. repeated per cascade) are summed.
    bool merged = false;
    for (PassTiming& p : out)
      if (p.name == e.name) p.ms += e.ms, merged = true;
    if (!merged) out.push_back({e.name, e.ms});
  }
  return out;
}

}  // namespace sl::gl
