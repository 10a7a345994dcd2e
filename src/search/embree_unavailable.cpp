/// \file
/// \brief Built instead of embree_search.cpp when CMake does not find Embree.
#include <stdexcept>

#include "search/embree_search.h"

namespace rc {

struct EmbreeSearch::Impl {};

EmbreeSearch::EmbreeSearch(const Scene& scene) : CompleteSearch(scene) { throw std::invalid_argument("this build has no Embree (libembree-dev)"); }
EmbreeSearch::~EmbreeSearch() = default;
Answer EmbreeSearch::nearest(const Query&, Counters&) const { return {}; }
bool embreeAvailable() { return false; }

}  // namespace rc
