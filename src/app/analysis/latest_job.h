#pragma once
// One worker thread that computes what a panel shows, off the UI thread: the panel asks for the
// result for some input (a lens, a film point) every time the input changes, and shows the newest
// result that has finished. A request replaces any request not yet started, so a storm of edits
// costs one computation at a time and the last edit always gets its answer.

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

namespace lenslab::app {

template <class Result>
class LatestJob {
 public:
  // `finished`, when given, is called on the worker thread after each result is stored (the
  // preview's encoder wakes the UI loop with it, so that the result is shown at once).
  explicit LatestJob(std::function<void()> finished = {})
      : finished_(std::move(finished)), worker_([this] { run(); }) {}
  ~LatestJob() {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_one();
    worker_.join();
  }
  LatestJob(const LatestJob&) = delete;
  LatestJob& operator=(const LatestJob&) = delete;

  // `key` names the input (a generation counter); `work` must not touch UI state.
  void request(std::uint64_t key, std::function<Result()> work) {
    {
      std::lock_guard lock(mutex_);
      pendingKey_ = key;
      pending_ = std::move(work);
    }
    wake_.notify_one();
  }

  // The newest finished result (null before the first) and the key it was computed for.
  std::shared_ptr<const Result> latest(std::uint64_t* key = nullptr) const {
    std::lock_guard lock(mutex_);
    if (key) *key = doneKey_;
    return done_;
  }
  // A request is waiting or being computed.
  bool busy() const {
    std::lock_guard lock(mutex_);
    return static_cast<bool>(pending_) || running_;
  }

 private:
  void run() {
    std::unique_lock lock(mutex_);
    for (;;) {
      wake_.wait(lock, [this] { return stopping_ || pending_; });
      if (stopping_) return;
      auto work = std::move(pending_);
      pending_ = nullptr;
      const std::uint64_t key = pendingKey_;
      running_ = true;
      lock.unlock();
      auto result = std::make_shared<const Result>(work());
      lock.lock();
      running_ = false;
      done_ = std::move(result);
      doneKey_ = key;
      if (finished_) {
        lock.unlock();
        finished_();
        lock.lock();
      }
    }
  }

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::function<Result()> pending_;
  std::uint64_t pendingKey_ = 0;
  bool running_ = false;
  bool stopping_ = false;
  std::shared_ptr<const Result> done_;
  std::uint64_t doneKey_ = 0;
  std::function<void()> finished_;
  std::thread worker_;  // last: started once the members it uses exist
};

}  // namespace lenslab::app
