// Tutorial 04, a wrong answer the check must reject: a finished region's successor is seeded from the next untouched pixel first, and from the deferred ones only when no untouched pixel is left
// BEGIN ANSWER
        // Keep filling the current region with cheap tests only
        if (!queue_.empty()) {
            inflight_ = queue_.front();
            queue_.pop_front();
            inflightSeed_ = false;
            return Pick{&tasks[std::size_t(slot_[inflight_])], cheapTests_ ? LookupMode::CheapOnly : LookupMode::Full};
        }
        // The region is finished: the next untouched ray, else a deferred one, seeds the next
        int seed = nextUnvisited();
        while (!pending_.empty() && seed < 0) {
            if (state_[pending_.front()] == Deferred) seed = pending_.front();
            pending_.pop_front();
        }
// END ANSWER
// KEEP SOLUTION
