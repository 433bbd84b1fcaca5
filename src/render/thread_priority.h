#pragma once
// Render workers can run at a lower scheduling priority than the viewer's UI thread, so a
// machine with few cores stays responsive while every core renders.

#include <tbb/task_arena.h>
#include <tbb/task_scheduler_observer.h>

namespace lenslab::render {

// While alive, lowers the priority (raises the nice value) of every thread that enters `arena`.
// The change is not undone: an unprivileged thread cannot raise its priority again, and the
// threads that joined only ever render.
class LowPriorityWorkers final : public tbb::task_scheduler_observer {
 public:
  explicit LowPriorityWorkers(tbb::task_arena& arena);
  ~LowPriorityWorkers() override { observe(false); }
  void on_scheduler_entry(bool isWorker) override;
};

// Lowers the calling thread's priority to the render workers' (nice 10).
void lowerCurrentThreadPriority();

}  // namespace lenslab::render
