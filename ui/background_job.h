// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <atomic>
#include <thread>

class QLabel;

namespace xyt::ui {

/**
 * A computation a view runs off the GUI thread (the design-space study, the robustness
 * analysis): its id (so that a result posted by a replaced job is ignored), the cancel flag the
 * core's progress callback reads, and the thread.
 */
struct BackgroundJob {
    int id = 0;
    std::atomic<bool> cancel{false};
    std::thread thread;

    /// Asks the work to stop and waits for it (it stops after the item it is computing).
    void stop() {
        cancel = true;
        if (thread.joinable())
            thread.join();
    }
};

/// A view's status strip: the text (also as tooltip: the strip shows a few lines, the whole
/// text is one hover away), red when it reports an error.
void setStatusText(QLabel* label, const QString& text, bool isError);

} // namespace xyt::ui
