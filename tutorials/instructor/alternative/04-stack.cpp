// Tutorial 04, an alternative answer the check must accept: a stack (depth first) instead of a FIFO queue: the same regions in another order
// BEGIN ANSWER
        // Keep filling the current region with cheap tests only
        if (!queue_.empty()) {
            // The last queued first
            inflight_ = queue_.items.back();
            queue_.items.pop_back();
            inflightSeed_ = false;
            return Pick{&tasks[std::size_t(slot_[inflight_])], cheapTests_ ? LookupMode::CheapOnly : LookupMode::Full};
        }
        // The region is finished: a deferred ray, else the next untouched one, seeds the next
        int seed = -1;
        while (!pending_.empty() && seed < 0) {
            if (state_[pending_.front()] == Deferred) seed = pending_.front();
            pending_.pop_front();
        }
        if (seed < 0) seed = nextUnvisited();
// END ANSWER
// KEEP SOLUTION
