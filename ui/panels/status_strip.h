// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

class QLabel;
class QProgressBar;

namespace xyt::ui {

/// A view's status strip: the text (also as tooltip: the strip shows a few lines, the whole
/// text is one hover away), red when it reports an error.
void setStatusText(QLabel* label, const QString& text, bool isError);

/// Shows a job's progress @p fraction in [0, 1] on @p bar (0 to 100 %).
void showProgress(QProgressBar* bar, double fraction);

} // namespace xyt::ui
