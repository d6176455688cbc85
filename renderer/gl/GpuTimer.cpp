#include "GpuTimer.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace sl::gl {

GpuTimer::GpuTimer(std::optional<Method> method) {
  if (method) {
    method_ = *method;
    return;
  }
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
  opened_.clear();
  queriesUsed_ = 0;
  open_ = false;
  // Never the pool whose queries are still to be read.
  if (!pending_.empty()) pool_ = 1 - pendingPool_;
}

void GpuTimer::begin(const std::string& pass) {
  if (open_) end();
  opened_.push_back(pass);
  Entry e;
  e.name = pass;
  if (method_ == Method::FinishWallClock) {
    glFinish();
    e.start = std::chrono::steady_clock::now();
  } else {
    auto& pool = queryPool_[pool_];
    if (queriesUsed_ == pool.size()) {
      GLuint q = 0;
      glCreateQueries(GL_TIME_ELAPSED, 1, &q);
      pool.emplace_back(q);
    }
    e.query = pool[queriesUsed_++].id();
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

namespace {
/// Passes with the same name (e.g. repeated per cascade) are summed, in order of first use.
std::vector<PassTiming> sumByName(const std::vector<PassTiming>& sequence) {
  std::vector<PassTiming> out;
  for (const PassTiming& s : sequence) {
    auto it =
        std::find_if(out.begin(), out.end(), [&](const PassTiming& p) { return p.name == s.name; });
    if (it != out.end())
      it->ms += s.ms;
    else
      out.push_back(s);
  }
  return out;
}
}  // namespace

std::vector<std::string> GpuTimer::passOrder() const {
  std::vector<std::string> order;
  for (const std::string& name : opened_)
    if (std::find(order.begin(), order.end(), name) == order.end()) order.push_back(name);
  return order;
}

std::vector<PassTiming> GpuTimer::endFrame() {
  if (open_) end();
  if (method_ == Method::FinishWallClock) {
    sequence_.clear();
    for (const Entry& e : entries_) sequence_.push_back({e.name, e.ms});
    return sumByName(sequence_);
  }
  // Timer queries: read the previous frame's, without waiting for the GPU.
  bool ready = !pending_.empty();
  for (const Entry& e : pending_) {
    GLint available = 0;
    glGetQueryObjectiv(e.query, GL_QUERY_RESULT_AVAILABLE, &available);
    ready = ready && available != 0;
  }
  if (ready) {
    sequence_.clear();
    for (const Entry& e : pending_) {
      GLuint64 ns = 0;
      glGetQueryObjectui64v(e.query, GL_QUERY_RESULT, &ns);  // available: no wait
      sequence_.push_back({e.name, double(ns) * 1e-6});
    }
    lastResults_ = sumByName(sequence_);
    late_ = 1;
    pending_ = std::move(entries_);
    pendingPool_ = pool_;
  } else if (!pending_.empty()) {
    ++late_;  // keep waiting for those; this frame's queries are dropped, never waited on
  } else {
    pending_ = std::move(entries_);
    pendingPool_ = pool_;
  }
  entries_.clear();
  return lastResults_;
}

}  // namespace sl::gl
