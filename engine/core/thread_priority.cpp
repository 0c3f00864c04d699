#include "core/thread_priority.h"

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace terrasol {

void lowerThisThreadsPriority() {
#if defined(__linux__)
  // Linux's nice value is per thread: PRIO_PROCESS with a thread id changes that thread alone.
  const auto tid = static_cast<id_t>(syscall(SYS_gettid));
  setpriority(PRIO_PROCESS, tid, 10);  // a failure leaves it as it was: nothing to report
#endif
}

}  // namespace terrasol
