// SPDX-License-Identifier: GPL-3.0-or-later
// The workbench in Brazilian Portuguese, loaded as xytune loads it (installUiLanguage): the
// menus, a dialog with Qt's own buttons, a core warning with its number, the number fields'
// decimal comma, and English again when the language is "en". The expected Portuguese strings
// are the ones chosen for translations/xytune_pt_BR.ts, written here literally (reading them
// from the catalogue would make the test circular).
#include "core/io/file_io.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/session/design_method_module.h"
#include "core/session/session.h"
#include "tests/support/gui_checks.h"
#include "ui/files/session_file.h"
#include "ui/main_window.h"
#include "ui/panels/method_parameter_editor.h"
#include "ui/panels/metrics_panel.h"
#include "ui/panels/number_field.h"
#include "ui/plots/contour_plot.h"
#include "ui/session/diagnostic_text.h"
#include "ui/session/interface_language.h"
#include "ui/session/tuning_session.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLibraryInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QSet>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTest>

#include <algorithm>
#include <stdexcept>

using namespace xyt;
using namespace xyt::ui;
using xyt::test::DialogAnswerer;

namespace {

QStringList menuTitles(const MainWindow& window) {
    QStringList titles;
    for (QAction* a : window.menuBar()->actions())
        titles << a->text();
    return titles;
}

/// The accelerator letter of @p text ('&&' is a literal ampersand), lower-case; none: empty.
QString acceleratorOf(const QString& text) {
    for (qsizetype i = 0; i + 1 < text.size(); ++i) {
        if (text[i] != QLatin1Char('&'))
            continue;
        if (text[i + 1] == QLatin1Char('&')) {
            ++i;
            continue;
        }
        return text[i + 1].toLower();
    }
    return {};
}

/// "menu: action" for every accelerator used twice within one menu (or the menu bar).
QStringList acceleratorClashes(const QString& where, const QList<QAction*>& actions) {
    QStringList clashes;
    QHash<QString, QString> taken;
    for (QAction* a : actions) {
        if (a->isSeparator() || !a->isVisible())
            continue;
        const QString key = acceleratorOf(a->text());
        if (key.isEmpty())
            continue;
        if (taken.contains(key))
            clashes << QStringLiteral("%1: '%2' and '%3'").arg(where, taken.value(key), a->text());
        taken.insert(key, a->text());
        if (a->menu())
            clashes << acceleratorClashes(a->text(), a->menu()->actions());
    }
    return clashes;
}

/// The paper's session with axis x made unstable (a1 = -100: a pole of the plant so far in the
/// right half-plane that the PI cannot hold it), as the menu test's "unstable" state.
Session unstableSession() {
    Session s = Session::paperDefault();
    s.axes[0].gt.plant.a1 = -100.0;
    return s;
}

} // namespace

class TstPortuguese : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void cleanup();
    void menusArePortuguese();
    void acceleratorsDoNotClash();
    void windowFitsA1366x768ScreenInPortuguese();
    void aboutDialogAndQtButtonsArePortuguese();
    void coreWarningIsPortugueseWithItsNumber();
    void unstableLoopWarnsInPortuguese();
    void digitalLoopWarnsWithItsSampleTime();
    void everyCatalogueCodeHasItsEnglishTemplate();
    void numberFieldAcceptsADecimalComma_data();
    void numberFieldAcceptsADecimalComma();
    void fieldErrorIsPortuguese_data();
    void fieldErrorIsPortuguese();
    void methodNameAndParameterLabelArePortuguese();
    void coreRefusalIsPortugueseWithItsField();
    void nestedReasonIsPortugueseInBothParts();
    void contourViewWarnsInPortuguese();
    void sessionFileRefusalsArePortuguese();
    void englishIsTheSource();
    void storedLanguageRoundTrips();
};

void TstPortuguese::initTestCase() {
    QStandardPaths::setTestModeEnabled(true); // the stored language stays out of $HOME
    QCoreApplication::setOrganizationName("xytune-tests");
}

void TstPortuguese::cleanup() {
    installUiLanguage(QStringLiteral("en"));
}

void TstPortuguese::menusArePortuguese() {
    QVERIFY(installUiLanguage(QStringLiteral("pt_BR")));
    TuningSession session;
    MainWindow window(&session);
    // The titles chosen in the catalogue, accelerators included (each its own letter).
    QCOMPARE(menuTitles(window),
             (QStringList{"&Arquivo", "&Editar", "&Projeto", "E&xibir", "Aj&uda"}));
    const QStringList tabs = [&] {
        QStringList all;
        for (QTabWidget* t : window.findChildren<QTabWidget*>())
            for (int i = 0; i < t->count(); ++i)
                all << t->tabText(i);
        return all;
    }();
    QVERIFY2(tabs.contains("&Lugar das raízes") && tabs.contains("&Degrau"),
             qPrintable(tabs.join(", ")));
}

void TstPortuguese::windowFitsA1366x768ScreenInPortuguese() {
    // The longer Portuguese labels made the control panel's preferred width its minimum, and
    // the window 1371 px wide: wider than the screen it is meant for. The metrics table's
    // specification column keeps room for its limits ("≤ 100" was cut to "≤ 1…").
    QVERIFY(installUiLanguage(QStringLiteral("pt_BR")));
    TuningSession session;
    MainWindow window(&session);
    window.resize(1366, 768);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY2(window.minimumSizeHint().width() <= 1366,
             qPrintable(QString::number(window.minimumSizeHint().width())));
    QCOMPARE(window.width(), 1366);
    auto* table = window.metricsPanel()->findChild<QTableWidget*>();
    QVERIFY(table);
    QVERIFY(table->item(MetricsPanel::SettleAfterMove, 2));
    const QString limit = table->item(MetricsPanel::SettleAfterMove, 2)->text();
    QCOMPARE(limit, QStringLiteral("≤ 100"));
    QVERIFY2(table->fontMetrics().horizontalAdvance(limit) + 6 <= table->columnWidth(2),
             qPrintable(QStringLiteral("%1 px for '%2'").arg(table->columnWidth(2)).arg(limit)));
}

void TstPortuguese::acceleratorsDoNotClash() {
    // A letter used twice in one menu makes Alt+letter cycle instead of act: every menu of the
    // translated window (submenus included) gives each of its actions its own letter.
    QVERIFY(installUiLanguage(QStringLiteral("pt_BR")));
    TuningSession session;
    MainWindow window(&session);
    const QStringList clashes = acceleratorClashes("menu bar", window.menuBar()->actions());
    QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join("\n")));
}

void TstPortuguese::aboutDialogAndQtButtonsArePortuguese() {
    // Qt's own catalogue (qt6-translations-l10n, in scripts/dev.sh's packages) translates the
    // standard buttons; without it the window would mix Portuguese text and English buttons.
    const QString qtCatalogue =
        QLibraryInfo::path(QLibraryInfo::TranslationsPath) + "/qtbase_pt_BR.qm";
    QVERIFY2(QFile::exists(qtCatalogue), qPrintable(qtCatalogue + " is missing"));
    QVERIFY(installUiLanguage(QStringLiteral("pt_BR")));
    TuningSession session;
    MainWindow window(&session);
    window.show();
    QAction* about = nullptr;
    for (QAction* menu : window.menuBar()->actions())
        for (QAction* a : menu->menu()->actions())
            if (a->text() == "&Sobre o XY Tune")
                about = a;
    QVERIFY(about);
    QString title, text;
    DialogAnswerer answerer(DialogAnswerer::Mode::Reject, [&](QWidget* dialog) {
        title = dialog->windowTitle();
        if (auto* box = qobject_cast<QMessageBox*>(dialog))
            text = box->text();
    });
    about->trigger();
    QTRY_COMPARE(answerer.answered(), 1);
    QCOMPARE(title, QStringLiteral("Sobre o XY Tune"));
    QVERIFY2(text.contains("Bancada de sintonia de controladores de posição"), qPrintable(text));
    QDialogButtonBox buttons(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    QCOMPARE(buttons.button(QDialogButtonBox::Cancel)->text(), QStringLiteral("Cancelar"));
}

void TstPortuguese::coreWarningIsPortugueseWithItsNumber() {
    QVERIFY(installUiLanguage(QStringLiteral("pt_BR")));
    // The numbers are the core's (formatNumber), substituted into the translated template.
    const Diagnostic d = makeDiagnostic("feedforward_beyond_limit", {"12.5", "10"});
    QCOMPARE(d.text, std::string("the feedforward alone needs 12.5 V on this trajectory, beyond "
                                 "the output limit of 10 V"));
    QCOMPARE(diagnosticText(d),
             QStringLiteral("a pré-alimentação sozinha precisa de 12.5 V "
                            "nesta trajetória, além do limite de saída de 10 V"));
    const Diagnostic c = makeDiagnostic("contour_axis_saturated", {"x", "2.5", "0.75"});
    QCOMPARE(diagnosticText(c),
             QStringLiteral("eixo x: |u| atingiu o limite do atuador de 2.5 V por 0.75 s"));
    // An uncoded warning (composed in the core from other messages) shows its English text.
    QCOMPARE(diagnosticText(Diagnostic("a note the catalogue does not know")),
             QStringLiteral("a note the catalogue does not know"));
}

void TstPortuguese::unstableLoopWarnsInPortuguese() {
    QVERIFY(installUiLanguage(QStringLiteral("pt_BR")));
    TuningSession session;
    session.reset(unstableSession());
    MainWindow window(&session);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    // The evaluation's coded warning (closed_loop_unstable), as the metrics panel lists it.
    const auto& warnings = session.axisEvaluation(0).warnings;
    QVERIFY(std::any_of(warnings.begin(), warnings.end(),
                        [](const Diagnostic& w) { return w.code == "closed_loop_unstable"; }));
    QTRY_VERIFY2(window.metricsPanel()->noticeText().contains("a malha fechada é instável"),
                 qPrintable(window.metricsPanel()->noticeText()));
    QVERIFY(!window.metricsPanel()->noticeText().contains("the closed loop is unstable"));
}

void TstPortuguese::digitalLoopWarnsWithItsSampleTime() {
    // The paper's PI (ωn = 2 rad/s) sampled at Ts = 2 s: the hold and the sampling at ωn Ts = 4
    // leave the digital loop's poles far less damped than the continuous design's (ζ = 1 in the
    // z-plane, below 0.8 of it: sampled_data.h). The warning carries Ts and both damping ratios
    // as the core formats them; the panel shows it in Portuguese with those numbers.
    QVERIFY(installUiLanguage(QStringLiteral("pt_BR")));
    Session s = Session::paperDefault();
    s.controllerTsSeconds = 2.0;
    TuningSession session;
    session.reset(s);
    MainWindow window(&session);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const auto& warnings = session.axisEvaluation(0).warnings;
    const auto found = std::find_if(warnings.begin(), warnings.end(), [](const Diagnostic& w) {
        return w.code == "digital_loop_less_damped";
    });
    QVERIFY(found != warnings.end());
    QCOMPARE(found->args.size(), std::size_t(3));
    QCOMPARE(found->args[0].text, std::string("2"));
    const QString expected = QStringLiteral("a malha digital com Ts = 2 s é muito menos amortecida "
                                            "que o projeto (coeficiente de amortecimento %1 "
                                            "contra %2 nos polos do plano z)")
                                 .arg(QString::fromStdString(found->args[1].text),
                                      QString::fromStdString(found->args[2].text));
    QTRY_VERIFY2(window.metricsPanel()->noticeText().contains(expected),
                 qPrintable(window.metricsPanel()->noticeText()));
}

void TstPortuguese::everyCatalogueCodeHasItsEnglishTemplate() {
    // The interface's templates are the core's English word for word (so a translation
    // translates what the CLI prints): in English, a coded warning reads as its core text.
    QVERIFY(installUiLanguage(QStringLiteral("en")));
    const std::vector<Diagnostic> args = {"A1", "B2", "C3"};
    QVERIFY(!diagnosticCatalogue().empty());
    for (const DiagnosticTemplate& t : diagnosticCatalogue()) {
        const Diagnostic d = makeDiagnostic(t.code, args);
        QCOMPARE(diagnosticText(d), QString::fromStdString(d.text));
    }
}

void TstPortuguese::numberFieldAcceptsADecimalComma_data() {
    QTest::addColumn<QString>("language");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<double>("value");
    // The field parses as the compiler reads the literal with a point (both the nearest double).
    for (const QString& lang : {QStringLiteral("pt_BR"), QStringLiteral("en")}) {
        QTest::addRow("%s 1,5", qPrintable(lang)) << lang << "1,5" << 1.5;
        QTest::addRow("%s 1.5", qPrintable(lang)) << lang << "1.5" << 1.5;
        QTest::addRow("%s -2,25e-1", qPrintable(lang)) << lang << "-2,25e-1" << -0.225;
    }
}

void TstPortuguese::numberFieldAcceptsADecimalComma() {
    QFETCH(QString, language);
    QFETCH(QString, typed);
    QFETCH(double, value);
    QVERIFY(installUiLanguage(language));
    NumberField field("kp");
    field.setText(typed);
    QVERIFY2(field.commit(), qPrintable(field.errorText()));
    QCOMPARE(field.value(),
             value); // "-2.25e-1" parses to the double nearest -0.225, as does the literal
    // Shown with a point in every language (the default locale is C).
    field.setValue(1.5);
    QCOMPARE(field.text(), QStringLiteral("1.5"));
    QCOMPARE(QLocale().decimalPoint(), QStringLiteral("."));
}

void TstPortuguese::fieldErrorIsPortuguese_data() {
    QTest::addColumn<QString>("language");
    QTest::addColumn<QString>("error");
    QTest::newRow("pt_BR") << "pt_BR"
                           << "kp: deve ser maior que zero";
    QTest::newRow("en") << "en"
                        << "kp: must be greater than zero";
}

void TstPortuguese::fieldErrorIsPortuguese() {
    // requirePositive's reason is coded (not_positive): the field shows it in the language.
    QFETCH(QString, language);
    QFETCH(QString, error);
    QVERIFY(installUiLanguage(language));
    NumberField field("kp", [](double v) { requirePositive(v, "kp"); });
    field.setText("0");
    QVERIFY(!field.commit());
    QCOMPARE(field.errorText(), error);
    try {
        requirePositive(0.0, "kp");
        QFAIL("requirePositive accepted 0");
    } catch (const InvalidInput& e) {
        QCOMPARE(e.reasonDiagnostic().code, std::string("not_positive"));
        QCOMPARE(std::string(e.what()), std::string("kp: must be greater than zero"));
    }
}

void TstPortuguese::methodNameAndParameterLabelArePortuguese() {
    // The core's names (XYT_TRANSLATE_NOOP in core/session/pid_feedforward_method.cpp): the
    // method's display name in the method list, a parameter's label in its editor.
    QVERIFY(installUiLanguage(QStringLiteral("pt_BR")));
    Session s = Session::paperDefault();
    s.axes[0].method = DesignMethod::PidFeedforward;
    TuningSession session;
    session.reset(s);
    MainWindow window(&session);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QStringList methods;
    for (const QComboBox* box : window.findChildren<QComboBox*>())
        for (int i = 0; i < box->count(); ++i)
            methods << box->itemText(i);
    QVERIFY2(methods.contains(QStringLiteral("PID + pré-alimentação")),
             qPrintable(methods.join(", ")));
    QVERIFY(!methods.contains(QStringLiteral("PID + feedforward")));
    QStringList labels;
    for (const MethodParameterEditor* editor : window.findChildren<MethodParameterEditor*>())
        for (const QLabel* label : editor->findChildren<QLabel*>())
            labels << label->text();
    QVERIFY2(labels.contains(QStringLiteral("Ganho proporcional P (V/mm)")),
             qPrintable(labels.join(", ")));
    QVERIFY(!labels.contains(QStringLiteral("Proportional gain P (V/mm)")));
    // The session keeps the English key and the core its English name.
    QCOMPARE(methodDisplayName(DesignMethod::PidFeedforward),
             QStringLiteral("PID + pré-alimentação"));
    QCOMPARE(std::string(designMethodModule(DesignMethod::PidFeedforward).displayName()),
             std::string("PID + feedforward"));
}

void TstPortuguese::coreRefusalIsPortugueseWithItsField() {
    // requirePositive's coded reason (not_positive), caught as any exception: the field stays,
    // the reason is translated; what() keeps the English for the CLI.
    QVERIFY(installUiLanguage(QStringLiteral("pt_BR")));
    try {
        requirePositive(0.0, "plant.k0");
        QFAIL("requirePositive accepted 0");
    } catch (const std::exception& e) {
        QCOMPARE(exceptionText(e), QStringLiteral("plant.k0: deve ser maior que zero"));
        QCOMPARE(std::string(e.what()), std::string("plant.k0: must be greater than zero"));
    }
    // An exception that is not a refusal shows its own text.
    QCOMPARE(exceptionText(std::runtime_error("disk full")), QStringLiteral("disk full"));
}

void TstPortuguese::nestedReasonIsPortugueseInBothParts() {
    // A reason caught and put into a longer sentence keeps its code: both are translated.
    QVERIFY(installUiLanguage(QStringLiteral("pt_BR")));
    const InvalidInput e("axes[0]",
                         makeDiagnostic("no_stability_margins", {makeDiagnostic("not_positive")}));
    QCOMPARE(std::string(e.what()),
             std::string("axes[0]: no stability margins: must be greater than zero"));
    QCOMPARE(e.reasonDiagnostic().args.at(0).code, std::string("not_positive"));
    QCOMPARE(exceptionText(e),
             QStringLiteral("axes[0]: sem margens de estabilidade: deve ser maior que zero"));
    QCOMPARE(diagnosticText(e.reasonDiagnostic()),
             QStringLiteral("sem margens de estabilidade: deve ser maior que zero"));
}

void TstPortuguese::contourViewWarnsInPortuguese() {
    // A circle traced with a 0.2 V actuator saturates both axes: the program's coded warning
    // (contour_axis_saturated, core/session/contour_run.cpp) is shown on the XY contour plot in
    // Portuguese, with the core's numbers.
    QVERIFY(installUiLanguage(QStringLiteral("pt_BR")));
    Session s = Session::paperDefault();
    s.umaxVolts = 0.2;
    s.trajectory.kind = TrajectoryKind::Gcode;
    s.trajectory.gcode.fileName = "circle.nc";
    s.trajectory.gcode.program = "G21 G90 G17\nG0 X25 Y0\nG2 X25 Y0 I-25 J0 F150\n";
    TuningSession session;
    session.reset(s);
    const auto& program = session.evaluation().program;
    QVERIFY(program);
    const auto found =
        std::find_if(program->warnings.begin(), program->warnings.end(),
                     [](const Diagnostic& w) { return w.code == "contour_axis_saturated"; });
    QVERIFY(found != program->warnings.end());
    QCOMPARE(found->args.size(), std::size_t(3));
    const QString expected =
        QStringLiteral("eixo %1: |u| atingiu o limite do atuador de %2 V por %3 s")
            .arg(QString::fromStdString(found->args[0].text),
                 QString::fromStdString(found->args[1].text),
                 QString::fromStdString(found->args[2].text));
    ContourPlot plot;
    plot.showSession(session.session(), session.evaluation());
    QVERIFY2(plot.noticeText().contains(expected), qPrintable(plot.noticeText()));
    QVERIFY(!plot.noticeText().contains(QString::fromStdString(found->text)));
}

void TstPortuguese::sessionFileRefusalsArePortuguese() {
    // File › Open's reasons: the file format's own (ui/files, translated where the workbench
    // loaded a language) and a value the format passes on to its checks, at its JSON path.
    QVERIFY(installUiLanguage(QStringLiteral("pt_BR")));
    files::SessionLoadResult r =
        files::sessionFromBytes(R"({"format": "xytune-session", "version": 99})");
    QVERIFY(!r.ok);
    QCOMPARE(r.message(), QStringLiteral("version: o arquivo tem a versão de formato 99; este XY "
                                         "Tune lê a versão %1 e anteriores: atualize o XY Tune")
                              .arg(files::kSessionFormatVersion));
    QJsonObject root = files::sessionToJson(Session::paperDefault());
    QJsonArray axes = root["axes"].toArray();
    QJsonObject x = axes[0].toObject();
    QJsonObject gt = x["gt"].toObject();
    gt["wn"] = 0.0;
    x["gt"] = gt;
    axes[0] = x;
    root["axes"] = axes;
    r = files::sessionFromBytes(QJsonDocument(root).toJson());
    QVERIFY(!r.ok);
    QCOMPARE(r.errorPath, QStringLiteral("axes[0].gt.wn"));
    const QString shown = r.errorDiagnostic.coded() ? diagnosticText(r.errorDiagnostic) : r.error;
    QCOMPARE(shown, QStringLiteral("deve ser maior que zero"));
    // A file that is not there: the core's coded FileError reason, with the path.
    const QString missing = QStringLiteral("/nonexistent-xytune-folder/none.json");
    r = files::loadSessionFile(missing);
    QVERIFY(!r.ok);
    QCOMPARE(diagnosticText(r.errorDiagnostic), missing + QStringLiteral(": arquivo inexistente"));
    try {
        readRegularFile(missing.toStdString(), 10);
        QFAIL("a missing file was read");
    } catch (const std::exception& e) {
        QCOMPARE(exceptionText(e), missing + QStringLiteral(": arquivo inexistente"));
    }
    // The CLI loads no language: the same reasons in English.
    QVERIFY(installUiLanguage(QStringLiteral("en")));
    r = files::sessionFromBytes(QJsonDocument(root).toJson());
    QCOMPARE(r.message(), QStringLiteral("axes[0].gt.wn: must be greater than zero"));
}

void TstPortuguese::englishIsTheSource() {
    QVERIFY(installUiLanguage(QStringLiteral("pt_BR")));
    QVERIFY(installUiLanguage(QStringLiteral("en"))); // replaces the Portuguese catalogue
    TuningSession session;
    MainWindow window(&session);
    QCOMPARE(menuTitles(window), (QStringList{"&File", "&Edit", "&Design", "&View", "&Help"}));
    QCOMPARE(diagnosticText(makeDiagnostic("closed_loop_unstable")),
             QStringLiteral("the closed loop is unstable"));
    QDialogButtonBox buttons(QDialogButtonBox::Cancel);
    QCOMPARE(buttons.button(QDialogButtonBox::Cancel)->text(), QStringLiteral("Cancel"));
}

void TstPortuguese::storedLanguageRoundTrips() {
    storeUiLanguage(QStringLiteral("pt_BR"));
    QCOMPARE(storedUiLanguage(), QStringLiteral("pt_BR"));
    storeUiLanguage(QString());
    QCOMPARE(storedUiLanguage(), QString());
    // The restart message speaks the chosen language, before it is installed.
    QCOMPARE(translatedFor("pt_BR", "xyt::ui::MainWindow",
                           "The language changes when XY Tune is started again."),
             QStringLiteral("O idioma muda quando o XY Tune for iniciado novamente."));
    QCOMPARE(translatedFor("en", "xyt::ui::MainWindow",
                           "The language changes when XY Tune is started again."),
             QStringLiteral("The language changes when XY Tune is started again."));
}

QTEST_MAIN(TstPortuguese)
#include "tst_portuguese.moc"
