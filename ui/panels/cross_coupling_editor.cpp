// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/cross_coupling_editor.h"

#include "core/model/errors.h"
#include "ui/panels/fold_button.h"
#include "ui/panels/number_field.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>

namespace xyt::ui {

CrossCouplingEditor::CrossCouplingEditor(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    body_ = new QWidget(this);
    fold_ = makeFoldButton(this, tr("Cross-coupling"), body_);
    layout->addWidget(fold_);
    auto* form = new QFormLayout(body_);
    form->setContentsMargins(12, 0, 0, 0);
    const auto gain = [this](const QString& field) {
        return new NumberField(
            field,
            [field](double v) {
                CrossCoupling c;
                (field == "kp" ? c.kp : c.ki) = v;
                validateCrossCoupling(c, "cross_coupling");
            },
            body_);
    };
    kp_ = gain("kp");
    kp_->setToolTip(tr("Proportional gain of the coupling (V per mm of estimated contour "
                       "error); kp and ki 0: off"));
    ki_ = gain("ki");
    ki_->setToolTip(tr("Integral gain of the coupling (V per mm·s); it stops integrating while "
                       "an axis is at its limit"));
    estimate_ = new QComboBox(body_);
    estimate_->addItem(tr("circular"));
    estimate_->addItem(tr("linear"));
    estimate_->setToolTip(tr("How the contour error is estimated from the two axis errors: the "
                             "tangent line's, or the circle's with the path's curvature"));
    form->addRow(tr("kp (V/mm)"), kp_);
    form->addRow(tr("ki (V/(mm·s))"), ki_);
    form->addRow(tr("Estimate"), estimate_);
    tune_ = new QPushButton(tr("Tune…"), body_);
    tune_->setToolTip(tr("Run the contour once for each kp and ki of a small grid and pick the "
                         "gains with the smallest contour error"));
    form->addRow(QString(), tune_);
    stability_ = new QLabel(body_);
    stability_->setWordWrap(true);
    stability_->hide();
    form->addRow(stability_);
    layout->addWidget(body_);
    for (NumberField* f : {kp_, ki_})
        connect(f, &NumberField::valueAccepted, this, [this] { emitIfValid(); });
    connect(estimate_, &QComboBox::activated, this, [this] { emitIfValid(); });
    connect(tune_, &QPushButton::clicked, this, &CrossCouplingEditor::tuneRequested);
    setCoupling({});
}

void CrossCouplingEditor::setCoupling(const CrossCoupling& coupling) {
    coupling_ = coupling;
    kp_->setValue(coupling.kp);
    ki_->setValue(coupling.ki);
    estimate_->setCurrentIndex(coupling.estimate == ContourEstimateKind::Circular ? 0 : 1);
    updateHeader();
}

void CrossCouplingEditor::setStability(const QString& text, bool warning) {
    stability_->setText(text);
    stability_->setStyleSheet(warning ? QStringLiteral("color: #b00020") : QString());
    stability_->setVisible(!text.isEmpty());
}

void CrossCouplingEditor::emitIfValid() {
    if (kp_->hasError() || ki_->hasError())
        return;
    CrossCoupling next;
    next.kp = kp_->value();
    next.ki = ki_->value();
    next.estimate = estimate_->currentIndex() == 0 ? ContourEstimateKind::Circular
                                                   : ContourEstimateKind::Linear;
    if (next == coupling_)
        return;
    coupling_ = next;
    updateHeader();
    emit couplingEdited(next);
}

void CrossCouplingEditor::updateHeader() {
    if (coupling_.active()) {
        fold_->setText(tr("Cross-coupling ●"));
        fold_->setToolTip(tr("Cross-coupled contouring: kp %1 V/mm, ki %2 V/(mm·s), %3 estimate")
                              .arg(formatNumber(coupling_.kp), formatNumber(coupling_.ki),
                                   coupling_.estimate == ContourEstimateKind::Circular
                                       ? tr("circular")
                                       : tr("linear")));
    } else {
        fold_->setText(tr("Cross-coupling"));
        fold_->setToolTip(tr("Cross-coupled contouring: off (each axis follows its own "
                             "reference)"));
    }
}

} // namespace xyt::ui
