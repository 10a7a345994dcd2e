// Tutorial 04, the reference solution: a FIFO seed fill with deferred pixels.
#include <algorithm>
#include <deque>

#include "exercise.h"

namespace tutorial {

// [solution]
std::vector<Visit> seedFill(int width, int height, int band, const std::vector<int>& key) {
    enum State { Unvisited, Queued, Deferred, Done };
    std::vector<State> state(std::size_t(width) * height, Unvisited);
    std::vector<Visit> visits;
    std::deque<int> queue, pending;  // the region's frontier; pixels the cache could not answer
    if (band <= 0 || band > height) band = height;
    int scan = 0, cached = 0, bandBegin = 0, bandEnd = band * width;  // the band: pixels [begin, end)
    auto grow = [&](int p) {  // queue the 4-neighbours of an answered pixel
        const int x = p % width, y = p / width;
        const int nb[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
        for (const auto& n : nb) {
            const int q = n[1] * width + n[0];
            // Stay inside the image and inside the current band
            if (n[0] < 0 || n[0] >= width || q < bandBegin || q >= bandEnd) continue;
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
                visits.push_back({p, Step::Answer});
                grow(p);
            } else {
                state[p] = Deferred;  // a miss: it seeds a later region
                visits.push_back({p, Step::Defer});
                pending.push_back(p);
            }
        }
        // The region is finished: a deferred pixel, else the next untouched one, seeds the next
        int seed = -1;
        while (seed < 0 && !pending.empty()) {
            if (state[pending.front()] == Deferred) seed = pending.front();
            pending.pop_front();
        }
        while (seed < 0 && scan < bandEnd) {
            if (state[scan] == Unvisited) seed = scan;
            ++scan;
        }
        if (seed < 0) {
            if (bandEnd == width * height) return visits;
            bandBegin = bandEnd;  // the next band
            bandEnd = std::min(bandEnd + band * width, width * height);
            continue;
        }
        cached = key[seed];  // the complete search reloads the cache
        state[seed] = Done;
        visits.push_back({seed, Step::Seed});
        grow(seed);
    }
}
// [solution]

}  // namespace tutorial
