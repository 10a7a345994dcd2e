// Tutorial 05, a wrong answer the check must reject: beams grow through the 8 neighbours, so rays that touch
// only at a corner are merged into one beam.
// BEGIN ANSWER
    // Flood fill connected pixels with equal (origin, hit) keys
    int next = 0;
    std::vector<int> stack;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        if (label[i] >= 0) continue;
        label[i] = next;
        stack.push_back(int(i));
        while (!stack.empty()) {
            const Ray& q = rays[std::size_t(stack.back())];
            stack.pop_back();
            const int x = q.pixel % width_, y = q.pixel / width_;
            // The 8 neighbours: corners too
            const int nb[8][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1},
                                  {x - 1, y - 1}, {x + 1, y - 1}, {x - 1, y + 1}, {x + 1, y + 1}};
            for (const auto& n : nb) {
                if (n[0] < 0 || n[1] < 0 || n[0] >= width_ || n[1] >= height_) continue;
                const int r = index[std::size_t(n[1]) * width_ + n[0]];
                if (r >= 0 && label[r] < 0 && rays[r].sameBeam(rays[i])) {
                    label[r] = next;
                    stack.push_back(r);
                }
            }
        }
        ++next;
    }
// END ANSWER
// KEEP SOLUTION
