// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

class QStackedWidget;

namespace xyt::ui {

/**
 * Makes @p stack as tall as its current page instead of its tallest one (a QStackedWidget's
 * default), now and whenever the page changes: a short page leaves no empty gap under it in
 * the left panel.
 */
void fitStackToCurrentPage(QStackedWidget* stack);

} // namespace xyt::ui
