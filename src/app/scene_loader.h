#pragma once
// Opens scene files on a thread of its own. Parsing a scene and building its BVH takes seconds
// for large meshes (2.0 s for a 2 M-triangle PLY on this project's machines), and the window must
// keep drawing and the current scene keep rendering meanwhile. The newest request wins: one
// asked for while another loads is loaded next, and the older one's result is dropped.

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <thread>

#include "app/preview_controller.h"

namespace lenslab::app {

class SceneLoader {
 public:
  struct Result {
    std::uint64_t request = 0;  // what start() returned for it
    std::string path;
    LoadedScene loaded;
  };

  // `wake` is called from the loading thread when a result is ready (the viewer posts an empty
  // event, so that its loop, asleep until the next frame or input, takes it at once).
  explicit SceneLoader(std::function<void()> wake = {});
  // Waits for a load in progress to finish (parsing has no cancellation point).
  ~SceneLoader();
  SceneLoader(const SceneLoader&) = delete;
  SceneLoader& operator=(const SceneLoader&) = delete;

  // Asks for `path` to be loaded; returns the request's number (increasing).
  std::uint64_t start(std::string path);
  // The newest request's result, once, when it is ready.
  std::optional<Result> take();
  // A request has been made whose result has not been taken yet.
  bool busy() const;

 private:
  void work(std::stop_token stop);

  std::function<void()> wake_;
  mutable std::mutex mutex_;
  std::condition_variable_any requested_;
  std::optional<std::pair<std::uint64_t, std::string>> next_;  // not yet started
  std::optional<Result> finished_;
  std::uint64_t latest_ = 0;  // the newest request
  std::uint64_t taken_ = 0;   // the newest request whose result was taken
  std::jthread thread_;       // last: starts after the members it uses, joins before they go
};

}  // namespace lenslab::app
