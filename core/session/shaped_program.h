// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/contour/feed_profile.h"
#include "core/design/input_shaper.h"

namespace xyt {

/**
 * A program's feed profile with its reference shaped by @p shaper (shapePath, the same linear
 * interpolation as the session's shaped reference of each axis): x and y shaped, the samples
 * extended by the shaper's duration at the profile's step. The path position, speed,
 * acceleration and segment of sample k are the unshaped profile's at k minus the shaper's delay
 * (its centroid, shaperDelaySeconds) in samples, where the shaped reference lies on average:
 * what the cross-coupling's directions read.
 * @throws InvalidInput as shapePath ("shaper.frequency" for a shaper longer than the program).
 */
FeedProfile shapedFeedProfile(const FeedProfile& profile, const InputShaper& shaper);

} // namespace xyt
