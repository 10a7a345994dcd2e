#pragma once
/// \file
/// \brief The caption under two renders compared side by side (another cache or order, in
/// lockstep), for both front ends: the Qt GUI's compared view and the page's. RayCache's own
/// addition.
#include <string>
#include <vector>

#include "view/session_state.h"

namespace rc {

/// The lines that say how the right render compares with the left: its intersection tests
/// as a multiple of the left's, their difference, its cache misses (of every path) as a
/// multiple of the left's (or that the left has none: no cache), and how far it has to catch
/// up when it is behind.
std::vector<std::string> compareCaption(const SessionState& left, const SessionState& right);

}  // namespace rc
