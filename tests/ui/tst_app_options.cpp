// SPDX-License-Identifier: GPL-3.0-or-later
// The workbench's options that need no window work on a machine without a display
// (before, --help aborted with Qt's platform-plugin error), and a mistyped option is bad input.
#include "tests/support/built_programs.h"

#include <QProcess>
#include <QProcessEnvironment>
#include <QTest>

class TstAppOptions : public QObject {
    Q_OBJECT
private slots:
    void optionsWithoutADisplay_data();
    void optionsWithoutADisplay();
};

void TstAppOptions::optionsWithoutADisplay_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("output");
    QTest::newRow("--help") << QStringList{"--help"} << 0 << "--screenshot <FILE>";
    QTest::newRow("-h") << QStringList{"-h"} << 0 << "Usage:";
    QTest::newRow("--version") << QStringList{"--version"} << 0 << PROJECT_VERSION_STRING;
    QTest::newRow("mistyped option")
        << QStringList{"--screnshot", "a.png"} << 2 << "Unknown option 'screnshot'";
    QTest::newRow("no display, no screenshot") << QStringList{} << 2 << "no display";
    // Run from the build tree, the examples are the source tree's (ui/session/install_paths.h;
    // tests/install's install_prefix checks the installed program's).
    QTest::newRow("--print-examples-folder")
        << QStringList{"--print-examples-folder"} << 0 << "/resources/examples\n";
    QTest::newRow("--help names --language") << QStringList{"--help"} << 0 << "--language <CODE>";
    QTest::newRow("unknown language")
        << QStringList{"--screenshot", "never-written.png", "--language", "xx"} << 2
        << "--language: expected pt_BR, en";
}

void TstAppOptions::optionsWithoutADisplay() {
    QFETCH(QStringList, args);
    QFETCH(int, exitCode);
    QFETCH(QString, output);
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
        env.remove(name);
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(XYT_GUI_PATH), args);
    QVERIFY(p.waitForFinished(30000));
    QCOMPARE(p.exitStatus(), QProcess::NormalExit);
    const QString text = QString::fromUtf8(p.readAllStandardOutput() + p.readAllStandardError());
    QCOMPARE(p.exitCode(), exitCode);
    QVERIFY2(text.contains(output), qPrintable(text));
    QVERIFY(!text.contains("platform plugin"));
}

QTEST_APPLESS_MAIN(TstAppOptions)
#include "tst_app_options.moc"
