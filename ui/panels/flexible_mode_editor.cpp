// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/flexible_mode_editor.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/session/shaper_advice.h"
#include "ui/panels/field_form.h"
#include "ui/panels/fold_button.h"
#include "ui/panels/number_field.h"
#include "ui/session/diagnostic_text.h"

#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>

namespace xyt::ui {

namespace {

void requireNonNegativeNumber(double v) {
    if (!(v >= 0.0))
        throw InvalidInput("value", makeDiagnostic("not_negative"));
}

/// The notch's fields, by the core's names.
const QStringList& notchFieldNames() {
    static const QStringList names{"centre", "width", "depth"};
    return names;
}

} // namespace

FlexibleModeEditor::FlexibleModeEditor(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    body_ = new QWidget(this);
    fold_ = makeFoldButton(this, tr("Flexible mode and notch"), body_);
    layout->addWidget(fold_);
    auto* form = new QFormLayout(body_);
    form->setContentsMargins(12, 0, 0, 0);
    form_ = std::make_unique<FieldForm>(form);
    shaperForm_ = std::make_unique<FieldForm>(form);
    const auto add = [&](const QString& key, const QString& label, const QString& tip) {
        form_->add(key, label, tip, requireNonNegativeNumber, this, [this] { emitIfValid(); });
    };
    add("frequency", tr("Mode (Hz)"),
        tr("The table's resonance fr above the rigid plant (belt, screw, gantry); 0: a rigid "
           "table. The design is made on the rigid plant; every run and analysis has the mode"));
    add("damping", tr("Mode damping"),
        tr("Damping ratio of the resonance, in [0, 1); its peak stands 1/(2 ζ) above the rigid "
           "plant"));
    add("anti_resonance", tr("Anti-resonance (Hz)"),
        tr("A two-mass model measured at the motor: its anti-resonance below fr; 0: the "
           "resonant pair fr² / (s² + 2 ζ fr s + fr²) alone"));
    add("anti_resonance_damping", tr("Anti-res. damping"),
        tr("Damping ratio of the anti-resonance, in [0, 1)"));
    add("centre", tr("Notch centre (Hz)"),
        tr("Notch on the error the PI reads, (s² + 2 ζz w0 s + w0²) / (s² + 2 ζp w0 s + w0²); "
           "0: none. Digital: bilinear, prewarped at the centre, below the controller's Nyquist "
           "frequency"));
    add("width", tr("Notch width (Hz)"), tr("Bandwidth of the notch's pole pair: 2 ζp f0"));
    add("depth", tr("Notch depth (dB)"), tr("Attenuation at the centre, in (0, 120] dB"));
    fromMode_ = new QPushButton(tr("Notch at the mode"), body_);
    fromMode_->setToolTip(tr("Centre on the mode, as deep as its peak (6 to 40 dB) and four "
                             "half-power bandwidths wide"));
    form->addRow(QString(), fromMode_);
    connect(fromMode_, &QPushButton::clicked, this, [this] {
        try {
            const NotchFilter n = notchForMode(mode_);
            form_->field("centre")->setValue(n.centreHz);
            form_->field("width")->setValue(n.widthHz);
            form_->field("depth")->setValue(n.depthDb);
            emitIfValid();
        } catch (const InvalidInput& e) {
            markFieldError(form_->field("frequency"), diagnosticText(e.reasonDiagnostic()));
        }
    });
    note_ = new QLabel(body_);
    note_->setWordWrap(true);
    note_->hide();
    form->addRow(note_);
    // The input shaper: the trajectory's, on both axes.
    shaperType_ = new QComboBox(body_);
    shaperType_->addItem(tr("none"));
    for (const ShaperType t : {ShaperType::Zv, ShaperType::Mzv, ShaperType::Zvd, ShaperType::Zvdd,
                               ShaperType::Ei, ShaperType::TwoHumpEi, ShaperType::ThreeHumpEi})
        shaperType_->addItem(QString(shaperName(t)).toUpper(), static_cast<int>(t));
    shaperType_->setToolTip(tr("Input shaper on both axes' reference: ZV, ZVD, ZVDD (Singer and "
                               "Seering), MZV (Klipper), EI and the multi-hump EI (Singhose et "
                               "al.)"));
    form->addRow(tr("Input shaper"), shaperType_);
    connect(shaperType_, &QComboBox::activated, this, [this] { emitShapingIfValid(); });
    const auto addShaper = [&](const QString& key, const QString& label, const QString& tip) {
        shaperForm_->add(key, label, tip, requireNonNegativeNumber, this,
                         [this] { emitShapingIfValid(); });
    };
    addShaper("frequency", tr("Shaper frequency (Hz)"),
              tr("The mode the shaper is designed for; acts on the reference at the trajectory's "
                 "step, so the controller's period does not limit it"));
    addShaper("damping", tr("Shaper damping"), tr("The damping ratio it is designed for, [0, 1)"));
    shaperAtMode_ = new QPushButton(tr("Shaper at the mode"), body_);
    shaperAtMode_->setToolTip(tr("Design the shaper for this axis' mode (ZV unless a type is "
                                 "chosen)"));
    form->addRow(QString(), shaperAtMode_);
    recommendMode_ = new QPushButton(tr("Recommend"), body_);
    recommendMode_->setToolTip(tr("Klipper's choice of shaper and frequency for this mode: the "
                                  "least vibration left for the smoothing, and the acceleration "
                                  "it allows"));
    recommendLog_ = new QPushButton(tr("From a log…"), body_);
    recommendLog_->setToolTip(tr("Klipper's choice from an accelerometer log "
                                 "(#time,accel_x,accel_y,accel_z), as calibrate_shaper.py makes "
                                 "it"));
    auto* recommendRow = new QHBoxLayout;
    recommendRow->addWidget(recommendMode_);
    recommendRow->addWidget(recommendLog_);
    form->addRow(QString(), recommendRow);
    advice_ = new QLabel(body_);
    advice_->setWordWrap(true);
    form->addRow(advice_);
    connect(recommendMode_, &QPushButton::clicked, this, [this] {
        try {
            applyRecommendation(flexibleModeSpectrum(mode_), mode_.dampingRatio,
                                tr("the %1 Hz mode").arg(formatNumber(mode_.frequencyHz)));
        } catch (const InvalidInput& e) {
            advice_->setText(tr("No recommendation: %1").arg(exceptionText(e)));
        }
    });
    connect(recommendLog_, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Accelerometer log"), QString(),
                                                          tr("Klipper CSV (*.csv);;All files (*)"));
        if (!path.isEmpty())
            recommendFromLog(path);
    });
    connect(shaperAtMode_, &QPushButton::clicked, this, [this] {
        if (!mode_.present()) {
            markFieldError(form_->field("frequency"), tr("no flexible mode to tune the shaper to"));
            return;
        }
        if (shaperType_->currentIndex() == 0)
            shaperType_->setCurrentIndex(1);
        shaperForm_->field("frequency")->setValue(mode_.frequencyHz);
        shaperForm_->field("damping")->setValue(mode_.dampingRatio);
        emitShapingIfValid();
    });
    setShaping({});
    layout->addWidget(body_);
    setSettings({}, {}, true, true);
}

void FlexibleModeEditor::setSettings(const FlexibleMode& mode, const NotchFilter& notch,
                                     bool continuousPlant, bool notchAllowed) {
    mode_ = mode;
    notch_ = notch;
    notchAllowed_ = notchAllowed;
    form_->field("frequency")->setValue(mode.frequencyHz);
    form_->field("damping")->setValue(mode.dampingRatio);
    form_->field("anti_resonance")->setValue(mode.antiResonanceHz);
    form_->field("anti_resonance_damping")->setValue(mode.antiResonanceDamping);
    form_->field("centre")->setValue(notch.centreHz);
    // An empty notch shows the width and depth a notch would start from.
    const NotchFilter start = notch.present() ? notch : NotchFilter{0.0, 0.0, 20.0};
    form_->field("width")->setValue(start.widthHz);
    form_->field("depth")->setValue(start.depthDb);
    for (auto it = form_->fields().begin(); it != form_->fields().end(); ++it) {
        const bool isNotch = notchFieldNames().contains(it.key());
        it.value()->setEnabled(continuousPlant && (!isNotch || notchAllowed));
    }
    form_->clearErrors();
    fromMode_->setEnabled(continuousPlant && notchAllowed);
    if (!continuousPlant)
        note_->setText(tr("A pole-placement axis' ARX model holds whatever mode its data showed: "
                          "identify it from a log that excites the mode."));
    else if (!notchAllowed)
        note_->setText(tr("LinuxCNC's pid has no notch stage: the notch is offered on "
                          "Guillemin–Truxal axes."));
    note_->setVisible(!continuousPlant || !notchAllowed);
    updateHeader();
}

void FlexibleModeEditor::emitIfValid() {
    if (form_->anyError())
        return;
    FlexibleMode mode;
    mode.frequencyHz = form_->value("frequency");
    mode.dampingRatio = form_->value("damping");
    mode.antiResonanceHz = form_->value("anti_resonance");
    mode.antiResonanceDamping = form_->value("anti_resonance_damping");
    NotchFilter notch;
    notch.centreHz = form_->value("centre");
    notch.widthHz = form_->value("width");
    notch.depthDb = form_->value("depth");
    if (!notch.present())
        notch = {};
    try {
        validateFlexibleMode(mode);
        validateNotchFilter(notch);
    } catch (const InvalidInput& e) {
        form_->markError(e);
        return;
    }
    form_->clearErrors();
    if (mode == mode_ && notch == notch_)
        return;
    mode_ = mode;
    notch_ = notch;
    updateHeader();
    emit loopElementsEdited(mode, notch);
}

FlexibleModeEditor::~FlexibleModeEditor() = default;

NumberField* FlexibleModeEditor::field(const QString& name) const {
    return form_->field(name);
}

NumberField* FlexibleModeEditor::shaperField(const QString& name) const {
    return shaperForm_->field(name);
}

QString FlexibleModeEditor::adviceText() const {
    return advice_->text();
}

void FlexibleModeEditor::recommendFromLog(const QString& path) {
    try {
        const AccelerometerLog log = readAccelerometerLogFile(path.toStdString());
        const ShaperRecommendationOptions defaults;
        const AccelerometerSpectra spectra =
            accelerometerSpectra(log, defaults.maxSpectrumFrequencyHz);
        const QString name = QFileInfo(path).fileName();
        emit accelerationLoaded(spectra, name);
        applyRecommendation(accelerometerShaperSpectrum(spectra, "sum"), defaults.dampingRatio,
                            name);
    } catch (const InvalidInput& e) {
        advice_->setText(tr("No recommendation: %1").arg(exceptionText(e)));
    }
}

void FlexibleModeEditor::applyRecommendation(const PowerSpectrum& spectrum, double dampingRatio,
                                             const QString& source) {
    ShaperRecommendationOptions options;
    options.dampingRatio = dampingRatio;
    const ShaperFit best =
        recommendShaper(spectrum, options).best(); // a copy: the result is a temporary
    advice_->setText(tr("Klipper's choice for %1: %2 at %3 Hz, %4 % vibration left, smoothing "
                        "%5 mm, max accel %6 mm/s²")
                         .arg(source, QString(shaperName(best.shaper.type)).toUpper(),
                              formatNumber(std::round(best.shaper.frequencyHz * 10.0) / 10.0),
                              formatNumber(std::round(best.remainingVibrations * 1000.0) / 10.0),
                              formatNumber(std::round(best.smoothing * 1000.0) / 1000.0),
                              formatNumber(std::round(best.maxAccelMmPerS2 / 100.0) * 100.0)));
    shaperType_->setCurrentIndex(shaperType_->findData(static_cast<int>(best.shaper.type)));
    shaperForm_->field("frequency")->setValue(best.shaper.frequencyHz);
    shaperForm_->field("damping")->setValue(best.shaper.dampingRatio);
    emitShapingIfValid();
}

void FlexibleModeEditor::setShaping(const ReferenceShaping& shaping) {
    shaping_ = shaping;
    shaperType_->setCurrentIndex(
        shaping.active() ? shaperType_->findData(static_cast<int>(shaping.type)) : 0);
    shaperForm_->field("frequency")->setValue(shaping.frequencyHz);
    shaperForm_->field("damping")->setValue(shaping.dampingRatio);
    updateHeader();
}

void FlexibleModeEditor::emitShapingIfValid() {
    if (shaperForm_->anyError())
        return;
    ReferenceShaping next;
    if (shaperType_->currentIndex() > 0) {
        next.type = static_cast<ShaperType>(shaperType_->currentData().toInt());
        next.frequencyHz = shaperForm_->value("frequency");
        next.dampingRatio = shaperForm_->value("damping");
        try {
            designInputShaper(next.type, next.frequencyHz, next.dampingRatio);
        } catch (const InvalidInput& e) {
            shaperForm_->markError(e);
            return;
        }
    }
    shaperForm_->clearErrors();
    if (next == shaping_)
        return;
    shaping_ = next;
    updateHeader();
    emit shapingEdited(next);
}

void FlexibleModeEditor::updateHeader() {
    QStringList set;
    if (mode_.present())
        set << tr("mode %1 Hz, ζ %2")
                   .arg(formatNumber(mode_.frequencyHz), formatNumber(mode_.dampingRatio));
    if (notch_.present())
        set << tr("notch %1 Hz, %2 dB")
                   .arg(formatNumber(notch_.centreHz), formatNumber(notch_.depthDb));
    if (shaping_.active())
        set << tr("%1 shaper at %2 Hz")
                   .arg(QString(shaperName(shaping_.type)).toUpper(),
                        formatNumber(shaping_.frequencyHz));
    fold_->setText(set.isEmpty() ? tr("Mode") : tr("Mode ●"));
    fold_->setToolTip(set.isEmpty() ? tr("Flexible mode and notch: none (the rigid table)")
                                    : tr("Flexible mode and notch: %1").arg(set.join(", ")));
}

} // namespace xyt::ui
