// Tutorial 04, a wrong answer the check must reject: grows through 8-neighbours
// KEEP SOLUTION
// BEGIN ANSWER
    auto visit = [&](int q) {
        // Untouched, or deferred by an earlier region: this region tries it
        if (state[q] != Unvisited && state[q] != Deferred) return;
        state[q] = Queued;
        queue_.push_back(q);
        // Its ray is traced soon: start fetching it now
        const char* task = reinterpret_cast<const char*>(tasks + slot[q]);
        for (std::size_t line = 0; line < sizeof(RayTask); line += 64) __builtin_prefetch(task + line);
    };
    // The 4-neighbours inside the band
    if (x > 0) visit(local - 1);
    if (x + 1 < width_) visit(local + 1);
    if (y > 0) visit(local - width_);
    if (y + 1 < rows) visit(local + width_);
    // and the diagonals
    if (x > 0 && y > 0) visit(local - width_ - 1);
    if (x + 1 < width_ && y > 0) visit(local - width_ + 1);
    if (x > 0 && y + 1 < rows) visit(local + width_ - 1);
    if (x + 1 < width_ && y + 1 < rows) visit(local + width_ + 1);
// END ANSWER
