#pragma once
/// \file
/// \brief Checkpoints of the GUI's render, so that going back costs a restore and a short
/// replay instead of a replay from the start.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "analysis/beam_tree.h"
#include "render/session_checkpoint.h"
#include "view/trace_recorder.h"

namespace rc {

/// One checkpoint: the render and its recorder at one step (the beam tree is built from
/// the recorder's events, SessionState::beams()).
struct StepCheckpoint {
    rc::SessionCheckpoint session;
    TraceRecorder::Mark recorder;
    std::int64_t steps() const { return session.steps; }
};

/// Checkpoints at every every()-th step, thinned out geometrically behind the render: of
/// those d spacings back, only every 2^(floor(log2 d) - 1)-th is kept. So the last two are
/// always there (Step back replays fewer than 2 x every() steps), going back a distance D
/// replays at most about D / 2, and a render of n spacings keeps about 2 log2 n + 2
/// checkpoints. Step 0 is always kept.
///
/// A checkpoint holds the fill's queued rays and the scanlines of its band, and fresh memory
/// costs a fault a page to touch, so checkpoints reuse the memory of those they drop. The
/// spacing trades the run's cost (closer checkpoints copy more) against a step back's
/// (farther ones replay more): the default keeps a step back well under the tenth of a
/// second a click may take. `build/ui/raycache_step_back_bench cube:5 512 CACHE ORDER SPACING`
/// measures both for a spacing.
class StepCheckpoints {
public:
    /// Spacing (raycache_step_back_bench measures it, see above).
    static constexpr std::int64_t kEvery = 20000;

    explicit StepCheckpoints(std::int64_t every = kEvery) : every_(every) {}

    /// Is a checkpoint due at this step? (One comparison: asked after every step.)
    bool due(std::int64_t steps) const { return steps >= next_; }
    /// The newest checkpoint, or null: a new one shares its unchanged scanlines.
    const StepCheckpoint* last() const { return list_.empty() ? nullptr : &list_.back(); }
    /// A checkpoint no longer wanted, to be overwritten by the next (empty if none).
    StepCheckpoint spare();
    /// Keeps a checkpoint taken at step `c.steps()`, a multiple of every() (after every one
    /// kept so far), and drops those the geometric spacing no longer wants.
    void add(StepCheckpoint c);
    /// The latest checkpoint at or before `step` (null if none); the ones after it are
    /// dropped (the render goes back to it, and takes them again as it passes them).
    const StepCheckpoint* backTo(std::int64_t step);

    std::int64_t every() const { return every_; }
    std::size_t size() const { return list_.size(); }
    /// Steps of the checkpoints kept, oldest first.
    std::vector<std::int64_t> steps() const;
    /// Bytes they hold, scanlines shared between checkpoints counted once.
    std::size_t bytes() const;
    /// "N checkpoints (every K steps), M MB".
    std::string summary() const;

private:
    std::int64_t every_;
    std::int64_t next_ = 0;
    std::vector<StepCheckpoint> list_;
    std::vector<StepCheckpoint> spares_;  ///< dropped, memory to reuse (at most one kept)
};

}  // namespace rc
