#pragma once
/// \file
/// \brief A copy of an image's sums kept by scanline, sharing the rows that did not change.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "trace/image_accumulator.h"

namespace rc {

/// The sums of an ImageAccumulator as they were, scanline by scanline. A scanline equal to
/// the one of an earlier snapshot shares its memory: a render adds to a band of scanlines
/// at a time, so snapshots taken a few thousand rays apart cost the rows in between, not
/// the image. Scanlines not begun share one scanline of zeros.
class ImageSnapshot {
public:
    ImageSnapshot() = default;
    /// Copies `image`, sharing the scanlines equal to those of `previous` (may be null).
    ImageSnapshot(const ImageAccumulator& image, const ImageSnapshot* previous);
    /// Writes the sums back into `image` (of the same size and rows as the one copied).
    void restore(ImageAccumulator& image) const;
    /// Bytes of the scanlines this snapshot does not share with the one it was made after.
    std::size_t ownBytes() const { return ownBytes_; }
    /// The scanlines, for counting memory shared between snapshots.
    const std::vector<std::shared_ptr<const std::vector<std::int64_t>>>& rows() const { return rows_; }

private:
    std::vector<std::shared_ptr<const std::vector<std::int64_t>>> rows_;
    std::shared_ptr<const std::vector<std::int64_t>> zero_;  ///< the scanline of zeros all share
    std::size_t ownBytes_ = 0;
};

}  // namespace rc
