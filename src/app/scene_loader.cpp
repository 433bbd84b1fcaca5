#include "app/scene_loader.h"

#include <exception>
#include <utility>

namespace lenslab::app {

SceneLoader::SceneLoader(std::function<void()> wake)
    : wake_(std::move(wake)), thread_([this](std::stop_token stop) { work(std::move(stop)); }) {}

SceneLoader::~SceneLoader() {
  thread_.request_stop();
  // jthread's destructor joins (after the stop request has woken a waiting worker).
}

std::uint64_t SceneLoader::start(std::string path) {
  std::uint64_t request = 0;
  {
    std::lock_guard lock(mutex_);
    request = ++latest_;
    next_.emplace(request, std::move(path));
    finished_.reset();  // an older result, not taken, is no longer wanted
  }
  requested_.notify_one();
  return request;
}

std::optional<SceneLoader::Result> SceneLoader::take() {
  std::lock_guard lock(mutex_);
  if (!finished_ || finished_->request != latest_) return std::nullopt;
  taken_ = finished_->request;
  return std::exchange(finished_, std::nullopt);
}

bool SceneLoader::busy() const {
  std::lock_guard lock(mutex_);
  return taken_ != latest_;
}

void SceneLoader::work(std::stop_token stop) {
  while (true) {
    std::pair<std::uint64_t, std::string> request;
    {
      std::unique_lock lock(mutex_);
      if (!requested_.wait(lock, stop, [&] { return next_.has_value(); })) return;
      request = std::move(*std::exchange(next_, std::nullopt));
    }
    LoadedScene loaded;
    try {
      loaded = loadSceneFile(request.second);
    } catch (const std::exception& exception) {
      // Parse and build errors come back as messages; this is what escapes them (out of memory
      // for a huge mesh, an Embree failure), which must not end the program from this thread.
      loaded.error = request.second + ": cannot load the scene: " + exception.what();
    }
    {
      std::lock_guard lock(mutex_);
      // A newer request made meanwhile supersedes this one: it is next_, and loads next.
      if (request.first != latest_) continue;
      finished_ = Result{request.first, std::move(request.second), std::move(loaded)};
    }
    if (wake_) wake_();
  }
}

}  // namespace lenslab::app
