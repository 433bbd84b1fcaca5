#include "render/thread_priority.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace lenslab::render {

namespace {
constexpr int kRenderNice = 10;
}

LowPriorityWorkers::LowPriorityWorkers(tbb::task_arena& arena)
    : tbb::task_scheduler_observer(arena) {
  observe(true);
}

void LowPriorityWorkers::on_scheduler_entry(bool /*isWorker*/) { lowerCurrentThreadPriority(); }

void lowerCurrentThreadPriority() {
  // On Linux, PRIO_PROCESS with a thread id sets that thread's nice value alone.
  const auto thread = static_cast<id_t>(syscall(SYS_gettid));
  if (getpriority(PRIO_PROCESS, thread) < kRenderNice)
    setpriority(PRIO_PROCESS, thread, kRenderNice);
}

}  // namespace lenslab::render
