// Tutorial 04, the reference solution: a FIFO seed fill with deferred pixels.
#include <deque>

#include "exercise.h"

namespace tutorial {

// [solution]
std::vector<Visit> seedFill(int width, int height, const std::vector<int>& key) {
    enum State { Unvisited, Queued, Deferred, Done };
    std::vector<State> state(std::size_t(width) * height, Unvisited);
    std::vector<Visit> visits;
    std::deque<int> queue, pending;  // the region's frontier; pixels the cache could not answer
    int scan = 0, cached = 0;
    auto grow = [&](int p) {  // queue the 4-neighbours of an answered pixel
        const int x = p % width, y = p / width;
        const int nb[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
        for (const auto& n : nb) {
            if (n[0] < 0 || n[1] < 0 || n[0] >= width || n[1] >= height) continue;
            const int q = n[1] * width + n[0];
            if (state[q] == Unvisited || state[q] == Deferred) {
                state[q] = Queued;
                queue.push_back(q);
            }
        }
    };
    for (;;) {
        // Fill the current region with cheap cache tests only
        while (!queue.empty()) {
            const int p = queue.front();
            queue.pop_front();
            if (key[p] == cached) {
                state[p] = Done;
                visits.push_back({p, false});
                grow(p);
            } else {
                state[p] = Deferred;  // a miss: it seeds a later region
                pending.push_back(p);
            }
        }
        // The region is finished: a deferred pixel, else the next untouched one, seeds the next
        int seed = -1;
        while (seed < 0 && !pending.empty()) {
            if (state[pending.front()] == Deferred) seed = pending.front();
            pending.pop_front();
        }
        while (seed < 0 && scan < width * height) {
            if (state[scan] == Unvisited) seed = scan;
            ++scan;
        }
        if (seed < 0) return visits;
        cached = key[seed];  // the complete search reloads the cache
        state[seed] = Done;
        visits.push_back({seed, true});
        grow(seed);
    }
}
// [solution]

}  // namespace tutorial
