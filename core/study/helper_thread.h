// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>

namespace xyt {

/**
 * Runs @p there on the process' one persistent helper thread while the calling thread runs
 * @p here, and returns when both are done (the session evaluation's two axes: a slider step
 * evaluates both). A thread started for each call would be slow to get a core while background
 * studies run: Linux's CFS places a new thread's virtual runtime after the running ones', so it
 * waited behind the design-space preview's workers for milliseconds (nice or not); a sleeping
 * thread that is woken preempts them. When the helper is busy with another caller, or cannot be
 * started, both run on the calling thread, one after the other. An exception of either is
 * rethrown here after both finished (the one of @p here first).
 */
void runAlongside(const std::function<void()>& there, const std::function<void()>& here);

} // namespace xyt
