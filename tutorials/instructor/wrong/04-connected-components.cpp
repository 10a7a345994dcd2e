// Tutorial 04, a wrong answer the check must reject: a region is a connected piece and nothing more: a pixel the cheap test could not answer is left for the seed scan, never taken from the deferred ones (the scan has passed it)
// BEGIN ANSWER
        // Keep filling the current region with cheap tests only
        if (!queue_.empty()) {
            inflight_ = queue_.front();
            queue_.pop_front();
            inflightSeed_ = false;
            return Pick{&tasks[std::size_t(slot_[inflight_])], cheapTests_ ? LookupMode::CheapOnly : LookupMode::Full};
        }
        // The region is finished: a deferred ray, else the next untouched one, seeds the next
        int seed = -1;
        if (seed < 0) seed = nextUnvisited();
// END ANSWER
// KEEP SOLUTION
