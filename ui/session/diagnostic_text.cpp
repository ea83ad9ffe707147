// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/session/diagnostic_text.h"

#include <QCoreApplication>

#include <cstring>

namespace xyt::ui {

namespace {

struct DiagnosticTextEntry {
    const char* code;
    const char* source; ///< the core's English template, marked for translation
};

/// The translatable templates of the catalogue's codes (core/model/diagnostic_catalogue.cpp):
/// each with the same English and placeholders (tst_portuguese checks they agree).
constexpr DiagnosticTextEntry kDiagnosticTexts[] = {
    {"not_a_number", QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText", "must be a number, got NaN")},
    {"not_finite", QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText", "must be finite, got infinity")},
    {"not_positive", QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText", "must be greater than zero")},
    {"zero", QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText", "must be nonzero")},
    {"closed_loop_unstable",
     QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText", "the closed loop is unstable")},
    {"run_diverged",
     QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText",
                       "the simulated run diverged (a sample is not a finite number): it has no "
                       "tracking figures")},
    {"flexible_mode_on_arx",
     QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText",
                       "the flexible mode and the notch of gt apply to a continuous plant: this "
                       "pole-placement axis runs its ARX model, which holds whatever mode its "
                       "data showed (identify it from a log that excites the mode)")},
    {"run_ends_before_move",
     QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText",
                       "the run ends before the move does (tf): no settle figures")},
    {"no_stability_margins",
     QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText", "no stability margins: %1")},
    {"no_digital_implementation",
     QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText", "no digital implementation: %1")},
    {"pp_u_exceeds_limit",
     QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText",
                       "|u| exceeds the actuator limit (the discrete loop is simulated without "
                       "saturation)")},
    {"feedforward_beyond_limit",
     QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText",
                       "the feedforward alone needs %1 V on this trajectory, beyond the output "
                       "limit of %2 V")},
    {"ff3_acceleration_spike",
     QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText",
                       "the cubic's acceleration step becomes a %1 V spike of the FF3 term (one "
                       "controller period); the quintic move has no acceleration step")},
    {"limit_cycle_at_rest",
     QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText",
                       "a limit cycle at rest: after the move the measured position keeps "
                       "oscillating (%1 mm peak to peak, %2 turns in the last half of the rest), "
                       "caused by the encoder/DAC quantization")},
    {"digital_loop_unstable",
     QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText",
                       "the digital loop at Ts = %1 s is unstable (its largest closed-loop pole "
                       "has |z| = %2); lower the controller sample time")},
    {"digital_loop_less_damped",
     QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText",
                       "the digital loop at Ts = %1 s is much less damped than the design "
                       "(damping ratio %2 against %3 in the z-plane poles); lower the controller "
                       "sample time or the delay")},
    {"contour_axis_diverged",
     QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText",
                       "%1 axis: the simulated run diverged (a sample is not a finite number)")},
    {"contour_axis_saturated",
     QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText",
                       "%1 axis: |u| reached the actuator limit of %2 V for %3 s")},
    {"iso230_circle_too_short",
     QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText",
                       "ISO 230-4: a full circle of the program lasts fewer than 3 samples: no "
                       "figures")},
    {"circle_too_short",
     QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText",
                       "the circle lasts fewer than 3 samples: no ISO 230-4 figures")},
    {"reversal_spikes",
     QT_TRANSLATE_NOOP("xyt::ui::DiagnosticText",
                       "reversal spikes up to %1 mm at the quadrant changes (the table's "
                       "friction and backlash)")},
};

const DiagnosticTextEntry* diagnosticTextEntry(const std::string& code) {
    for (const DiagnosticTextEntry& e : kDiagnosticTexts)
        if (code == e.code)
            return &e;
    return nullptr;
}

/// %1 .. %9 of @p templ replaced by @p args in one pass (an argument's own '%' is not read
/// again), as the core's fillDiagnosticTemplate does.
QString fillDiagnosticText(const QString& templ, const std::vector<std::string>& args) {
    QString out;
    out.reserve(templ.size());
    for (qsizetype i = 0; i < templ.size(); ++i) {
        const QChar c = templ[i];
        if (c == QLatin1Char('%') && i + 1 < templ.size() && templ[i + 1] >= QLatin1Char('1') &&
            templ[i + 1] <= QLatin1Char('9')) {
            const auto k = static_cast<std::size_t>(templ[i + 1].unicode() - '1');
            if (k < args.size()) {
                out += QString::fromStdString(args[k]);
                ++i;
                continue;
            }
        }
        out += c;
    }
    return out;
}

} // namespace

QString diagnosticText(const Diagnostic& d) {
    const DiagnosticTextEntry* e = d.coded() ? diagnosticTextEntry(d.code) : nullptr;
    if (!e)
        return QString::fromStdString(d.text);
    return fillDiagnosticText(QCoreApplication::translate("xyt::ui::DiagnosticText", e->source),
                              d.args);
}

bool hasDiagnosticText(const std::string& code) {
    return diagnosticTextEntry(code) != nullptr;
}

} // namespace xyt::ui
