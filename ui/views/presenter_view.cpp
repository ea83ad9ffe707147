// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/views/presenter_view.h"

#include "ui/session/diagnostic_text.h"
#include "ui/session/tuning_session.h"

#include <QWidget>

namespace xyt::ui {

PresenterView::PresenterView(TuningSession* session, QWidget* widget)
    : QObject(widget), session_(session), widget_(widget) {
    connect(session, &TuningSession::designChanged, this, &PresenterView::requestRedraw);
    connect(session, &TuningSession::currentAxisChanged, this, &PresenterView::requestRedraw);
}

void PresenterView::requestRedraw() {
    stale_ = true;
    if (!onScreen())
        return;
    draw();
    // Drawn for a window not shown (at a size it may not keep): drawn again once it is seen.
    stale_ = !widget_->isVisible();
}

bool PresenterView::onScreen() const {
    return widget_->isVisible() || !widget_->window()->isVisible();
}

void PresenterView::drawIfStale() {
    if (stale_)
        requestRedraw();
}

QString PresenterView::axisTitle() const {
    const AxisSettings& a =
        session_->session().axes.at(static_cast<std::size_t>(session_->currentAxis()));
    return tr("Axis %1 (%2)")
        .arg(QString::fromStdString(a.id).toUpper(), QString::fromStdString(a.label));
}

QStringList PresenterView::liveNotices() const {
    return session_->liveNotice().isEmpty() ? QStringList{} : QStringList{session_->liveNotice()};
}

QString PresenterView::noDesignReason(const AxisEvaluation& axis) {
    return tr("No design: %1: %2")
        .arg(QString::fromStdString(axis.errorField), diagnosticText(axis.error));
}

} // namespace xyt::ui
