// SPDX-License-Identifier: GPL-3.0-or-later
// A view that builds a session and applies it itself: check_presenter_changes.cmake must refuse it.
void SomeView::useDesign() {
    Session next = session_->session();
    session_->apply(next, tr("Use the design"));
}
