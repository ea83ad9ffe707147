// SPDX-License-Identifier: GPL-3.0-or-later
// xytune: the tuning workbench. `xytune --screenshot FILE.png [--size WxH]` renders the main
// window with the default design offscreen and exits; `xytune --report SESSION.json --pdf OUT.pdf`
// writes the session's design report as a PDF, offscreen too.
#include "app/allocator_tuning.h"
#include "ui/design_space_view.h"
#include "ui/files/session_file.h"
#include "ui/help/welcome_dialog.h"
#include "ui/main_window.h"
#include "ui/report/report_writer.h"
#include "ui/robustness_view.h"
#include "ui/session/install_paths.h"
#include "ui/session/interface_language.h"
#include "ui/session/recovery_store.h"
#include "ui/session/session_file_controller.h"
#include "ui/session/tuning_session.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QPixmap>
#include <QSettings>
#include <QTabWidget>
#include <QTimer>

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

/// A picture or a report: drawn offscreen, no display needed.
bool wantsOffscreen(int argc, char* argv[]) {
    for (int i = 1; i < argc; ++i)
        if (std::strcmp(argv[i], "--screenshot") == 0 || std::strcmp(argv[i], "--report") == 0)
            return true;
    return false;
}

} // namespace

/// The command line of xytune, on whichever application object parses it.
struct Options {
    QCommandLineOption screenshot{"screenshot", "Render the main window to FILE.png and exit.",
                                  "FILE"};
    QCommandLineOption size{"size", "Window size for --screenshot, WxH (default 1366x768).", "WxH",
                            "1366x768"};
    QCommandLineOption tab{"tab",
                           "With --screenshot: show this tab first (e.g. \"Design space\"; "
                           "a design-space or robustness study is run before the picture).",
                           "NAME"};
    QCommandLineOption printExamplesFolder{
        "print-examples-folder",
        "Print the folder of the example programs the workbench offers (installed: "
        "<prefix>/share/xytune/examples) and exit; empty when none is found."};
    QCommandLineOption report{"report",
                              "Write the design report of SESSION.json as a PDF (needs --pdf) and "
                              "exit.",
                              "SESSION.json"};
    QCommandLineOption pdf{"pdf", "With --report: the PDF file to write.", "OUT.pdf"};
    QCommandLineOption language{
        "language",
        "Language of the window: pt_BR (Brazilian Portuguese), en (English), or \"\" for the "
        "system's; overrides the one chosen in View > Language (--screenshot: en by default).",
        "CODE"};
    void addTo(QCommandLineParser& parser) const {
        parser.setApplicationDescription(
            "Tuning workbench for XY coordinate-table position controllers");
        parser.addHelpOption();
        parser.addVersionOption();
        parser.addOption(screenshot);
        parser.addOption(size);
        parser.addOption(tab);
        parser.addOption(printExamplesFolder);
        parser.addOption(report);
        parser.addOption(pdf);
        parser.addOption(language);
        parser.addPositionalArgument("session", "A session file to open.", "[SESSION.json]");
    }
};

void nameApplication() {
    QCoreApplication::setApplicationName("XY Tune");
    QCoreApplication::setOrganizationName("xytune");
    QCoreApplication::setApplicationVersion(QStringLiteral(PROJECT_VERSION_STRING));
}

/// --report SESSION.json --pdf OUT.pdf: the design report, no window shown. Exit 2 naming the
/// option or the session's path on bad input.
int writeReport(const QCommandLineParser& parser, const Options& options) {
    if (!parser.isSet(options.report)) {
        std::fprintf(stderr, "xytune: --pdf: needs --report SESSION.json\n");
        return 2;
    }
    if (!parser.isSet(options.pdf) || parser.value(options.pdf).isEmpty()) {
        std::fprintf(stderr, "xytune: --pdf: missing: --report needs --pdf OUT.pdf\n");
        return 2;
    }
    const QString sessionPath = parser.value(options.report);
    const auto loaded = xyt::files::loadSessionFile(sessionPath);
    if (!loaded.ok) {
        std::fprintf(stderr, "xytune: --report: %s: %s\n", qPrintable(sessionPath),
                     qPrintable(loaded.message()));
        return 2;
    }
    const QString path = parser.value(options.pdf);
    QString error;
    if (!xyt::ui::ReportWriter::write(loaded.session, QFileInfo(sessionPath).fileName(), path,
                                      &error)) {
        std::fprintf(stderr, "xytune: --pdf: %s\n", qPrintable(error));
        return 2;
    }
    std::printf("%s\n", qPrintable(path));
    return 0;
}

int main(int argc, char* argv[]) {
    xyt::app::keepFreedMemory(); // see allocator_tuning.h: the slider re-simulates megabytes
    const Options options;
    {
        // Options that need no window (--help, --version, a mistyped option) are answered before
        // any window system is touched: they work on a machine without a display.
        QCoreApplication core(argc, argv);
        nameApplication();
        QCommandLineParser early;
        options.addTo(early);
        if (!early.parse(core.arguments())) { // a mistyped option: say which, exit 2 (bad input)
            std::fprintf(stderr, "xytune: %s (see xytune --help)\n", qPrintable(early.errorText()));
            return 2;
        }
        early.process(core); // prints and exits for --help, --help-all and --version
        if (early.isSet(options.printExamplesFolder)) {
            std::printf("%s\n", qPrintable(xyt::ui::examplesFolder()));
            return 0;
        }
        const bool displayed = !qEnvironmentVariableIsEmpty("DISPLAY") ||
                               !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY") ||
                               !qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM");
        if (!early.isSet(options.screenshot) && !early.isSet(options.report) && !displayed) {
            std::fprintf(stderr,
                         "xytune: no display (DISPLAY and WAYLAND_DISPLAY are unset): run it in a "
                         "desktop session, use --screenshot FILE.png, or xytune-cli for the "
                         "headless report\n");
            return 2;
        }
    }
    // A screenshot needs no display: use the offscreen platform unless one was chosen.
    if (wantsOffscreen(argc, argv) && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    nameApplication();

    QCommandLineParser parser;
    options.addTo(parser);
    parser.process(app);
    const QCommandLineOption& screenshot = options.screenshot;
    const QCommandLineOption& size = options.size;
    const QCommandLineOption& tab = options.tab;

    // The language, before any widget is built: --language, else English for a screenshot
    // (the same picture on every machine), else the user's choice (View > Language).
    QString languageCode =
        parser.isSet(screenshot) ? QStringLiteral("en") : xyt::ui::storedUiLanguage();
    if (parser.isSet(options.language)) {
        languageCode = parser.value(options.language);
        if (!xyt::ui::uiLanguageCodes().contains(languageCode)) {
            std::fprintf(stderr, "xytune: --language: expected pt_BR, en or \"\", got '%s'\n",
                         qPrintable(languageCode));
            return 2;
        }
    }
    xyt::ui::installUiLanguage(languageCode);

    if (parser.isSet(options.report) || parser.isSet(options.pdf))
        return writeReport(parser, options);
    xyt::ui::TuningSession session;
    if (parser.isSet(screenshot)) {
        const QStringList wh = parser.value(size).split('x');
        bool okW = false, okH = false;
        const int w = wh.size() == 2 ? wh[0].toInt(&okW) : 0;
        const int h = wh.size() == 2 ? wh[1].toInt(&okH) : 0;
        if (!okW || !okH || w < 320 || h < 240 || w > 8000 || h > 8000) {
            std::fprintf(stderr,
                         "xytune: --size: expected WxH between 320x240 and 8000x8000, got '%s'\n",
                         qPrintable(parser.value(size)));
            return 2;
        }
        QApplication::setOrganizationName("xytune-screenshot"); // never the user's layout
        if (!parser.positionalArguments().isEmpty()) {
            const auto loaded = xyt::files::loadSessionFile(parser.positionalArguments().first());
            if (!loaded.ok) {
                std::fprintf(stderr, "xytune: %s\n", qPrintable(loaded.message()));
                return 2;
            }
            session.reset(loaded.session);
        }
        xyt::ui::MainWindow window(&session);
        window.resize(w, h);
        window.show();
        for (int i = 0; i < 5; ++i)
            QApplication::processEvents();
        if (parser.isSet(tab)) {
            const QString wanted = parser.value(tab);
            bool found = false;
            for (QTabWidget* tabs : window.findChildren<QTabWidget*>())
                for (int i = 0; i < tabs->count(); ++i)
                    if (tabs->tabText(i).remove('&').compare(wanted, Qt::CaseInsensitive) == 0) {
                        tabs->setCurrentIndex(i);
                        found = true;
                    }
            if (!found) {
                std::fprintf(stderr, "xytune: --tab: no tab named '%s'\n", qPrintable(wanted));
                return 2;
            }
            // A study's tab is shown with its result (the run it would start on a click).
            const auto runShown = [](auto* view) {
                if (!view || !view->isVisible())
                    return;
                view->run();
                QElapsedTimer waited;
                waited.start();
                while (view->isRunning() && waited.elapsed() < 120000)
                    QApplication::processEvents(QEventLoop::AllEvents, 50);
            };
            runShown(window.findChild<xyt::ui::DesignSpaceView*>());
            runShown(window.findChild<xyt::ui::RobustnessView*>());
        }
        // A few passes, as a shown window gets: a plot may lay itself out again once (a title
        // wrapped, a legend in fewer columns) in a queued drawing.
        QElapsedTimer settling;
        settling.start();
        while (settling.elapsed() < 200)
            QApplication::processEvents(QEventLoop::AllEvents, 20);
        const QString path = parser.value(screenshot);
        if (!window.grab().save(path)) {
            std::fprintf(stderr, "xytune: --screenshot: cannot write '%s'\n", qPrintable(path));
            return 2;
        }
        std::printf("%s\n", qPrintable(path));
        return 0;
    }
    // Start where the user left off: the last design comes back from the settings.
    const QByteArray last = QSettings().value("session/last").toByteArray();
    if (!last.isEmpty()) {
        const auto restored = xyt::files::sessionFromBytes(last);
        if (restored.ok)
            session.reset(restored.session);
    }
    xyt::ui::MainWindow window(&session);
    if (!parser.positionalArguments().isEmpty())
        window.files()->openFile(parser.positionalArguments().first());
    window.show();
    // Work left unsaved by an instance that crashed or was killed is offered once the window is up.
    QTimer::singleShot(0, &window, [&window, &session] {
        xyt::ui::offerRecovery(&window, &session, window.files(),
                               xyt::ui::RecoveryStore::defaultDirectory());
    });
    // The first-start page: here, in the interactive path only (never for --screenshot, which
    // returned above, nor in the tests, which build the window without main()).
    if (xyt::ui::WelcomeDialog::shouldShowAtStart())
        QTimer::singleShot(0, &window, [&window] { window.showWelcome(); });
    return QApplication::exec();
}
