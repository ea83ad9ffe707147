// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// GUI test helpers: answer every modal dialog and popup a test opens, and check that what the
// workbench's plots hold is what the core computes for the presenter's state.
#include "core/analysis/parameter_locus.h"
#include "core/analysis/pole_zero_map.h"
#include "core/analysis/root_locus.h"
#include "core/session/axis_frequency.h"
#include "core/session/design_method_module.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/step_view.h"
#include "tests/support/tolerance.h"
#include "ui/main_window.h"
#include "ui/plots/bode_plot.h"
#include "ui/plots/nyquist_plot.h"
#include "ui/plots/parameter_locus_plot.h"
#include "ui/plots/pole_zero_plot.h"
#include "ui/plots/root_locus_plot.h"
#include "ui/plots/step_plot.h"
#include "ui/plots/time_response_plot.h"
#include "ui/session/tuning_session.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDialog>
#include <QFileDialog>
#include <QInputDialog>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPointer>
#include <QSet>
#include <QTabWidget>
#include <QTest>
#include <QTimer>

#include <algorithm>
#include <functional>

namespace xyt::test {

/**
 * While alive, closes every popup and answers every modal dialog within a few milliseconds:
 * with Accept, a dialog is first accepted (a message box by its default button, an input dialog
 * by OK) and rejected if it is still open on the next tick; file dialogs are always rejected, so
 * no test writes where the user would. @p onDialog sees each dialog before it is answered.
 */
class DialogAnswerer {
public:
    enum class Mode { Reject, Accept };
    explicit DialogAnswerer(Mode mode = Mode::Reject, std::function<void(QWidget*)> onDialog = {})
        : mode_(mode), onDialog_(std::move(onDialog)) {
        QObject::connect(&timer_, &QTimer::timeout, [this] { tick(); });
        timer_.start(5);
    }
    int answered() const { return answered_; }
    QStringList titles() const { return titles_; }

private:
    void tick() {
        if (QWidget* popup = QApplication::activePopupWidget()) {
            popup->close();
            return;
        }
        QWidget* modal = QApplication::activeModalWidget();
        auto* dialog = qobject_cast<QDialog*>(modal);
        if (!dialog)
            return;
        const bool seen = seen_.contains(dialog);
        if (!seen) {
            seen_.insert(dialog);
            titles_ << dialog->windowTitle();
            ++answered_;
            if (onDialog_)
                onDialog_(dialog);
        }
        if (mode_ == Mode::Reject || seen || qobject_cast<QFileDialog*>(dialog)) {
            dialog->reject();
            return;
        }
        if (auto* box = qobject_cast<QMessageBox*>(dialog)) {
            if (QAbstractButton* b = box->defaultButton())
                b->click();
            else
                box->reject();
            return;
        }
        dialog->accept();
    }

    Mode mode_;
    std::function<void(QWidget*)> onDialog_;
    QTimer timer_;
    QSet<QDialog*> seen_;
    QStringList titles_;
    int answered_ = 0;
};

/// Types @p text into a field as a user would (focus, select all, type, Return).
template <typename Field> void typeInto(Field* field, const QString& text) {
    field->setFocus();
    field->selectAll();
    QTest::keyClicks(field, text);
    QTest::keyClick(field, Qt::Key_Return);
}

/// Every action of a menu bar, submenus included (separators and submenu entries left out).
/// Menus that fill themselves when shown are filled first, so the pointers are valid until the
/// next action runs (which may rebuild them): find an action again by its path to trigger it.
inline QList<QAction*> allMenuActions(QMenuBar* bar) {
    QList<QAction*> out;
    std::function<void(QMenu*)> walk = [&](QMenu* menu) {
        emit menu->aboutToShow(); // menus that fill themselves on show (none yet) get filled
        for (QAction* a : menu->actions()) {
            if (a->isSeparator())
                continue;
            if (a->menu())
                walk(a->menu());
            else
                out << a;
        }
    };
    for (QAction* top : bar->actions())
        if (top->menu())
            walk(top->menu());
    return out;
}

/// "File/Open Recent/a.json": the menu titles and the action text, without '&'.
inline QString actionPath(QAction* action) {
    QStringList parts{action->text()};
    for (QObject* o = action->parent(); o; o = o->parent())
        if (auto* m = qobject_cast<QMenu*>(o); m && m->menuAction())
            parts.prepend(m->title());
    return parts.join('/').remove('&');
}

/// The action at @p path now (menus refilled), or nullptr.
inline QAction* findMenuAction(QMenuBar* bar, const QString& path) {
    for (QAction* a : allMenuActions(bar))
        if (actionPath(a) == path)
            return a;
    return nullptr;
}

inline bool sameComplexSet(std::vector<std::complex<double>> a,
                           QSharedPointer<QCPGraphDataContainer> data, double relTol) {
    a.erase(std::remove_if(
                a.begin(), a.end(),
                [](const auto& p) { return !std::isfinite(p.real()) || !std::isfinite(p.imag()); }),
            a.end());
    if (static_cast<int>(a.size()) != data->size())
        return false;
    // QCPGraph sorts by key (the real part): compare as sorted multisets.
    std::vector<std::complex<double>> b;
    for (auto it = data->constBegin(); it != data->constEnd(); ++it)
        b.emplace_back(it->key, it->value);
    const auto less = [](const auto& x, const auto& y) {
        return x.real() != y.real() ? x.real() < y.real() : x.imag() < y.imag();
    };
    std::sort(a.begin(), a.end(), less);
    std::sort(b.begin(), b.end(), less);
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!nearComplex(b[i], a[i], relTol, 1e-300))
            return false;
    return true;
}

/**
 * The plot shows the run: every sample when it has at most 16 384 (exactly, in order), else a
 * decimation to the extremes, which is checked as such: at most 2 x 8192 + 2 points, each one a
 * sample (t_k, y_k) of the run in increasing k, the last sample included, and (for a run without
 * a non-finite sample, whose bucket keeps that sample instead) the first sample and the run's
 * largest and smallest values drawn.
 */
inline bool sameSignal(QSharedPointer<QCPGraphDataContainer> data, const std::vector<double>& t,
                       const std::vector<double>& y) {
    if (t.size() > 16384 && data->size() < static_cast<int>(t.size())) {
        if (data->size() > 2 * 8192 + 2 || data->isEmpty())
            return false;
        std::size_t k = 0;
        double drawnMax = -INFINITY, drawnMin = INFINITY;
        for (auto it = data->constBegin(); it != data->constEnd(); ++it) {
            const auto found =
                std::lower_bound(t.begin() + static_cast<std::ptrdiff_t>(k), t.end(), it->key);
            if (found == t.end() || *found != it->key)
                return false;
            k = static_cast<std::size_t>(found - t.begin());
            if (!(it->value == y[k] || (std::isnan(it->value) && std::isnan(y[k]))))
                return false;
            if (std::isfinite(it->value)) {
                drawnMax = std::max(drawnMax, it->value);
                drawnMin = std::min(drawnMin, it->value);
            }
        }
        double runMax = -INFINITY, runMin = INFINITY;
        bool allFinite = true;
        for (double v : y) {
            allFinite = allFinite && std::isfinite(v);
            runMax = std::max(runMax, v);
            runMin = std::min(runMin, v);
        }
        return (data->constEnd() - 1)->key == t.back() &&
               (!allFinite ||
                (data->constBegin()->key == t.front() && drawnMax == runMax && drawnMin == runMin));
    }
    if (data->size() != static_cast<int>(t.size()))
        return false;
    int i = 0;
    for (auto it = data->constBegin(); it != data->constEnd(); ++it, ++i)
        if (it->key != t[static_cast<std::size_t>(i)] ||
            !(it->value == y[static_cast<std::size_t>(i)] ||
              (std::isnan(it->value) && std::isnan(y[static_cast<std::size_t>(i)]))))
            return false; // NaN samples of a diverged run must be drawn as NaN (gaps) too
    return true;
}

/**
 * Shows each plot tab of @p window in turn and checks that its data equal what the core computes
 * for the presenter's current (live) session, computed afresh here: the run's signals, the step
 * view's curves and settling marker, the root locus branches and markers, the pole-zero sets, the
 * parameter locus, or "no result" for an axis without a design. Returns "" when everything matches,
 * else what differs. Runs short enough for the exact comparison (<= 16 384 samples: no decimation)
 * are assumed.
 */
inline QString plotsMismatch(ui::MainWindow* window, ui::TuningSession* session) {
    const int axis = session->currentAxis();
    const SessionEvaluation fresh = evaluateSession(session->liveSession());
    const AxisEvaluation& e = fresh.axes[static_cast<std::size_t>(axis)];
    const AxisSettings& settings = session->session().axes[static_cast<std::size_t>(axis)];
    QStringList problems;
    QTabWidget* upper = window->upperTabs();
    QTabWidget* lower = window->lowerTabs();
    const int upperIndex = upper->currentIndex(), lowerIndex = lower->currentIndex();

    lower->setCurrentWidget(window->timePlot());
    auto* time = window->timePlot();
    if (e.ok) {
        if (!sameSignal(time->outputGraph()->data(), e.run.t, e.run.y))
            problems << "time plot: y differs from the core's run";
        if (!sameSignal(time->errorGraph()->data(), e.run.t, e.run.e))
            problems << "time plot: e differs from the core's run";
        if (!sameSignal(time->controlGraph()->data(), e.run.t, e.run.u))
            problems << "time plot: u differs from the core's run";
    } else if (!time->outputGraph()->data()->isEmpty()) {
        problems << "time plot: shows a run for an axis without a design";
    }

    // The step view: every curve the core's for this design and specification, the markers
    // at the evaluation's figures (the metrics panel's).
    lower->setCurrentWidget(window->stepPlot());
    auto* step = window->stepPlot();
    if (e.ok && e.step.stable) {
        const bool pp = e.pp && e.zpetc;
        const StepView expected = stepView(
            e.closedLoop(), e.step, ui::specificationEnvelope(session->session().spec),
            pp ? &*e.pp : nullptr, pp ? &*e.zpetc : nullptr, pp && settings.pp.zpetcEnabled);
        if (!step->hasResult())
            problems << "step plot: no response for a stable design";
        for (const StepViewCurve& c : expected.curves) {
            QCPGraph* g = step->hasResult() ? step->curveGraph(c.kind) : nullptr;
            std::vector<double> t = c.curve.t;
            for (double& v : t)
                v -= c.curve.stepAtSeconds;
            if (!g || !sameSignal(g->data(), t, c.curve.y))
                problems << QStringLiteral("step plot: curve %1 differs from the core's")
                                .arg(static_cast<int>(c.kind));
        }
        if (e.step.settlingTimeSeconds > 0.0 &&
            (step->settlingMarker()->data()->isEmpty() ||
             step->settlingMarker()->data()->at(0)->key != e.step.settlingTimeSeconds))
            problems << "step plot: the settling marker is not the evaluation's settling time";
    } else if (step->hasResult()) {
        problems << "step plot: shows a response for an axis without a stable design";
    }

    std::vector<std::complex<double>> clPoles;
    if (e.ok)
        clPoles = e.closedLoop().poles();

    upper->setCurrentWidget(window->rootLocusPlot());
    auto* rl = window->rootLocusPlot();
    if (e.ok) {
        RootLocus expected;
        if (e.gt)
            expected = rootLocus(e.gt->openLoop);
        else if (e.pp)
            expected = rootLocus(TransferFunction::fromZInverse(
                e.pp->b * e.pp->g, e.pp->a * e.pp->f, e.pp->tsSeconds));
        else // a registered method: the loop its module gives
            expected = rootLocus(axisLoop(e)->openLoop);
        if (!rl->hasResult() ||
            rl->branchCurveCount() != static_cast<int>(expected.branches.size()))
            problems << QStringLiteral("root locus: %1 branches drawn, the core has %2")
                            .arg(rl->hasResult() ? rl->branchCurveCount() : -1)
                            .arg(expected.branches.size());
        else
            for (int b = 0; b < rl->branchCurveCount(); ++b) {
                const auto& roots = expected.branches[static_cast<std::size_t>(b)].roots;
                auto data = rl->branchCurve(b)->data();
                bool same = data->size() == static_cast<int>(roots.size());
                int i = 0;
                for (auto it = data->constBegin(); same && it != data->constEnd(); ++it, ++i)
                    same = it->key == roots[static_cast<std::size_t>(i)].real() &&
                           it->value == roots[static_cast<std::size_t>(i)].imag();
                if (!same)
                    problems << QStringLiteral("root locus: branch %1 differs").arg(b);
            }
        if (!sameComplexSet(clPoles, rl->currentPolesGraph()->data(), 1e-12))
            problems << "root locus: the design's closed-loop poles differ";
    } else if (rl->hasResult() || rl->branchCurveCount() != 0 ||
               !rl->currentPolesGraph()->data()->isEmpty()) {
        problems << "root locus: shows a locus for an axis without a design";
    }

    upper->setCurrentWidget(window->poleZeroPlot());
    auto* pz = window->poleZeroPlot();
    if (e.ok) {
        std::vector<PoleZeroSet> sets = session->poleZeroSets(axis);
        if (e.gt)
            sets = gtPoleZeroSets(*e.gt);
        // View > Pole-zero map of the digital loop: the z-plane sets of the digital
        // implementation instead.
        if (window->zPlaneAction()->isChecked() && e.digital)
            sets = digitalPoleZeroSets(e);
        for (const PoleZeroSet& set : sets) {
            QCPGraph* poles = pz->polesGraph(QString::fromStdString(set.name));
            QCPGraph* zeros = pz->zerosGraph(QString::fromStdString(set.name));
            if (!poles || !zeros || !sameComplexSet(set.poles, poles->data(), 1e-12) ||
                !sameComplexSet(set.zeros, zeros->data(), 1e-12))
                problems << QStringLiteral("pole-zero map: set %1 differs")
                                .arg(QString::fromStdString(set.name));
        }
    } else if (pz->hasResult()) {
        problems << "pole-zero map: shows sets for an axis without a design";
    }

    upper->setCurrentWidget(window->parameterLocusPlot());
    auto* pl = window->parameterLocusPlot();
    if (e.ok && settings.method == DesignMethod::GuilleminTruxal) {
        const GtAxisSettings& gt = settings.gt;
        ParameterSweep sweep;
        sweep.logSpacing = true;
        sweep.from = gt.omegaNRadPerSec / 10.0;
        sweep.to = gt.omegaNRadPerSec * 10.0;
        sweep.count = 80;
        const ParameterLocus expected =
            gtParameterLocus(gt.plant, GtSweptParameter::OmegaN, sweep, gt.kp);
        if (!pl->hasResult() || pl->branchCount() != static_cast<int>(expected.branches.size()))
            problems << "parameter locus: branch count differs from the core's";
        if (!sameComplexSet(clPoles, pl->currentGraph()->data(), 1e-12))
            problems << "parameter locus: the current poles differ";
    } else if (pl->hasResult() || pl->branchCount() != 0) {
        problems << "parameter locus: shows a sweep for an axis of another method or without a "
                    "design";
    }
    // Frequency domain: the Bode curve of L and the Nyquist counts are a fresh analysis's.
    upper->setCurrentWidget(window->bodePlot());
    auto* bode = window->bodePlot();
    const AxisFrequencyAnalysis f = analyzeAxisFrequency(session->liveSession(), e);
    if (e.ok && f.ok) {
        QCPGraph* mag = bode->magnitudeGraph("open loop L");
        const auto& w = f.responses.openLoop.omegaRadPerSec;
        bool same = bode->hasResult() && mag && mag->dataCount() == static_cast<int>(w.size());
        for (int i = 0; same && i < mag->dataCount(); ++i)
            same = mag->data()->at(i)->key == w[static_cast<std::size_t>(i)] &&
                   mag->data()->at(i)->value ==
                       f.responses.openLoop.magnitudeDb[static_cast<std::size_t>(i)];
        if (!same)
            problems << "Bode: |L| differs from the core's response";
    } else if (bode->hasResult()) {
        problems << "Bode: shows a response for an axis without a design";
    }
    upper->setCurrentWidget(window->nyquistPlot());
    auto* nyquist = window->nyquistPlot();
    if (e.ok && f.ok) {
        if (!nyquist->criterionText().contains(
                QStringLiteral("Z = N + P = %1").arg(f.nyquist.closedLoopUnstablePoles)))
            problems << "Nyquist: the criterion differs from the core's counts";
    } else if (nyquist->hasResult()) {
        problems << "Nyquist: shows a curve for an axis without a design";
    }
    upper->setCurrentIndex(upperIndex);
    lower->setCurrentIndex(lowerIndex);
    return problems.join("; ");
}

} // namespace xyt::test
