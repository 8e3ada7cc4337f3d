#include "kernels/lsystem/module_pipe.h"

#include <atomic>
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "kernels/base/error.h"

namespace selfsim::lsystem {

namespace {

constexpr std::size_t batch_modules = 16384;
constexpr std::size_t batches = 8;  // at most this many in flight: memory stays small

// Batches passed from the deriving thread to the drawing one, and back to be reused.
class Pipe {
 public:
  Pipe() : storage_(batches) {
    for (ModuleString& b : storage_) free_.push_back(&b);
  }

  // Producer: an empty batch to fill; throws Cancelled once the consumer has stopped.
  ModuleString* take_free() {
    std::unique_lock<std::mutex> lock(m_);
    cv_.wait(lock, [&] { return stopped_ || !free_.empty(); });
    if (stopped_) throw Cancelled();
    ModuleString* b = free_.front();
    free_.pop_front();
    return b;
  }
  void push(ModuleString* b) {
    {
      const std::lock_guard<std::mutex> lock(m_);
      full_.push_back(b);
    }
    cv_.notify_all();
  }
  void finish(std::exception_ptr error) {
    {
      const std::lock_guard<std::mutex> lock(m_);
      done_ = true;
      error_ = error;
    }
    cv_.notify_all();
  }

  // Consumer: the next full batch, or null once the producer has finished and all are taken.
  ModuleString* take_full() {
    std::unique_lock<std::mutex> lock(m_);
    cv_.wait(lock, [&] { return done_ || !full_.empty(); });
    if (full_.empty()) return nullptr;
    ModuleString* b = full_.front();
    full_.pop_front();
    return b;
  }
  void recycle(ModuleString* b) {
    b->clear();
    {
      const std::lock_guard<std::mutex> lock(m_);
      free_.push_back(b);
    }
    cv_.notify_all();
  }
  void stop() {
    {
      const std::lock_guard<std::mutex> lock(m_);
      stopped_ = true;
    }
    halted.store(true, std::memory_order_relaxed);
    cv_.notify_all();
  }
  std::atomic<bool> halted{false};  // stop() was called: the derivation, however busy, ends
  std::exception_ptr error() {
    const std::lock_guard<std::mutex> lock(m_);
    return error_;
  }

 private:
  std::vector<ModuleString> storage_;
  std::mutex m_;
  std::condition_variable cv_;
  std::deque<ModuleString*> free_, full_;
  bool done_ = false, stopped_ = false;
  std::exception_ptr error_;
};

// The deriving thread's sink: modules gathered into batches.
class Batcher : public ModuleSink {
 public:
  explicit Batcher(Pipe& pipe) : pipe_(pipe) {}
  void module(std::uint8_t s, std::span<const double> args) override {
    if (batch_ == nullptr) batch_ = pipe_.take_free();
    batch_->push(s, args);
    if (batch_->size() >= batch_modules) flush();
  }
  void modules(const ModuleRun& r) override {
    if (batch_ == nullptr) batch_ = pipe_.take_free();
    push_run(*batch_, r);
    if (batch_->size() >= batch_modules) flush();
  }
  void flush() {
    if (batch_ != nullptr && batch_->size() > 0) pipe_.push(batch_);
    batch_ = nullptr;
  }

 private:
  Pipe& pipe_;
  ModuleString* batch_ = nullptr;
};

// The deriving thread's progress: it may ask whether to stop (from any thread), and leaves what it has
// done for the calling thread to report.
class ThreadProgress : public Progress {
 public:
  ThreadProgress(Progress& parent, const std::atomic<bool>& halted) : parent_(parent), halted_(halted) {}
  void fraction(double f) override { done_.store(f, std::memory_order_relaxed); }
  bool cancelled() override { return halted_.load(std::memory_order_relaxed) || parent_.cancelled(); }
  double done() const { return done_.load(std::memory_order_relaxed); }

 private:
  Progress& parent_;
  const std::atomic<bool>& halted_;
  std::atomic<double> done_{0};
};

}  // namespace

void rewrite_modules_piped(const Grammar& g, int level, ModuleSink& sink, const ModuleLimits& limits,
                           Progress& progress, bool interpret) {
  Pipe pipe;
  ThreadProgress derived(progress, pipe.halted);
  std::thread deriver([&] {
    try {
      Batcher batcher(pipe);
      rewrite_modules(g, level, batcher, limits, derived, interpret);
      batcher.flush();
      pipe.finish(nullptr);
    } catch (...) {
      pipe.finish(std::current_exception());
    }
  });
  try {
    while (ModuleString* b = pipe.take_full()) {
      sink.modules(run_of(*b, 0, b->size()));
      pipe.recycle(b);
      progress.fraction(derived.done());
    }
  } catch (...) {
    pipe.stop();
    deriver.join();
    throw;
  }
  deriver.join();
  if (const std::exception_ptr e = pipe.error()) std::rethrow_exception(e);
}

}  // namespace selfsim::lsystem
