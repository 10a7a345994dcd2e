#include "trace/image_snapshot.h"

#include <algorithm>
#include <stdexcept>

namespace rc {

ImageSnapshot::ImageSnapshot(const ImageAccumulator& image, const ImageSnapshot* previous) {
    const std::span<const std::int64_t> sums = image.sums();
    const std::size_t row = std::size_t(image.width()) * 3;
    const std::size_t rows = row ? sums.size() / row : 0;
    if (previous && previous->rows_.size() != rows) previous = nullptr;
    rows_.reserve(rows);
    zero_ = previous ? previous->zero_ : std::make_shared<const std::vector<std::int64_t>>(row, 0);
    for (std::size_t y = 0; y < rows; ++y) {
        const std::span<const std::int64_t> now = sums.subspan(y * row, row);
        // A scanline the last snapshot holds as it is now is shared, not copied; so is
        // one not begun (all zero)
        if (previous && std::equal(now.begin(), now.end(), previous->rows_[y]->begin())) {
            rows_.push_back(previous->rows_[y]);
            continue;
        }
        if (std::all_of(now.begin(), now.end(), [](std::int64_t v) { return v == 0; })) {
            rows_.push_back(zero_);
            continue;
        }
        rows_.push_back(std::make_shared<const std::vector<std::int64_t>>(now.begin(), now.end()));
        ownBytes_ += row * sizeof(std::int64_t);
    }
}

void ImageSnapshot::restore(ImageAccumulator& image) const {
    const std::span<std::int64_t> sums = image.sums();
    const std::size_t row = std::size_t(image.width()) * 3;
    if (rows_.size() * row != sums.size()) throw std::invalid_argument("image snapshot of another image");
    for (std::size_t y = 0; y < rows_.size(); ++y) std::copy(rows_[y]->begin(), rows_[y]->end(), sums.begin() + std::ptrdiff_t(y * row));
}

}  // namespace rc
