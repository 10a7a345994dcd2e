#include "render/session_checkpoint.h"

namespace rc {

std::size_t SessionCheckpoint::bytes() const {
    return sizeof(SessionCheckpoint) + image.ownBytes() + paths.bytes() + (order ? order->heldBytes() : 0) +
           (strategy ? strategy->bytes() : 0);
}

}  // namespace rc
