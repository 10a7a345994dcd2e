#pragma once
// The time one render takes, as the processor time of the thread that runs it: on a
// machine shared with other work (a build, a second benchmark) the wall clock counts the
// waits too, and the ratios of a table measured side by side drift with the load.
#include <ctime>

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

}  // namespace rc::cli
