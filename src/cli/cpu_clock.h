#pragma once
/// \file
/// \brief The time one render takes, as the processor time of the thread that runs it: on a
/// machine shared with other work (a build, a second benchmark) the wall clock counts the
/// waits too, and the ratios of a table measured side by side drift with the load.
#include <ctime>

#if defined(__linux__)
#include <sched.h>
#endif

namespace rc::cli {

/// Seconds of processor time used so far by the calling thread.
inline double threadSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

/// Seconds of processor time used so far by every thread of the process (a render spread
/// over threads: the processor time it took, not how long one waited for it).
inline double processSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

/// Keeps the calling thread, and the threads it starts, on the processor it runs on now,
/// and returns that processor (-1 where it cannot: elsewhere than Linux). For a table of
/// ratios measured side by side: on a virtual machine two processors can differ much in
/// speed, and a thread the scheduler moves between them mid-table would compare renders
/// made at different speeds.
inline int pinToCurrentCpu() {
#if defined(__linux__)
    const int cpu = sched_getcpu();
    if (cpu < 0) return -1;
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(cpu, &one);
    return sched_setaffinity(0, sizeof one, &one) == 0 ? cpu : -1;
#else
    return -1;
#endif
}

}  // namespace rc::cli
