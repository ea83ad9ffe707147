// SPDX-License-Identifier: GPL-3.0-or-later
// The catalogue of the core's coded warnings and refusals: its invariants, and that the core's
// sources give the user no message without a code (so the workbench can translate each).
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <QDirIterator>
#include <QFile>
#include <QRegularExpression>
#include <QSet>
#include <QTest>

#include <set>
#include <stdexcept>

using namespace xyt;

class TstDiagnosticCatalogue : public QObject {
    Q_OBJECT

private slots:
    void codesAreUniqueAndWellFormed();
    void placeholdersAreNumberedFromOne();
    void argumentsFillTheTemplate();
    void codedArgumentsNest();
    void joinKeepsEachPartsCode();
    void unknownCodeIsRefused();
    void everyCodeUsedIsInTheCatalogue();
    void everyRefusalOfTheCoreIsCoded();
    void everyWarningOfTheCoreIsCoded();
};

namespace {

/// @p text with its comments blanked (newlines kept, so line numbers hold); string and
/// character literals kept whole.
QString withoutComments(const QString& text) {
    QString out = text;
    for (qsizetype i = 0; i < out.size(); ++i) {
        const QChar c = out[i];
        if (c == '"' || c == '\'') {
            for (++i; i < out.size() && out[i] != c; ++i)
                if (out[i] == '\\')
                    ++i;
        } else if (c == '/' && i + 1 < out.size() && out[i + 1] == '/') {
            for (; i < out.size() && out[i] != '\n'; ++i)
                out[i] = ' ';
        } else if (c == '/' && i + 1 < out.size() && out[i + 1] == '*') {
            for (; i < out.size() && !(out[i] == '*' && i + 1 < out.size() && out[i + 1] == '/');
                 ++i)
                if (out[i] != '\n')
                    out[i] = ' ';
            if (i + 1 < out.size())
                out[i] = out[i + 1] = ' ';
            ++i;
        }
    }
    return out;
}

/// The core's C++ sources without their comments, each with its path from the repository's root.
QList<QPair<QString, QString>> coreSources() {
    QList<QPair<QString, QString>> files;
    const QString root = QStringLiteral(XYT_SOURCE_DIR);
    QDirIterator it(root + "/core", {"*.cpp", "*.h"}, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString path = it.next();
        QFile f(path);
        if (f.open(QIODevice::ReadOnly))
            files.append(
                {path.mid(root.size() + 1), withoutComments(QString::fromUtf8(f.readAll()))});
    }
    return files;
}

/// The text from @p open (an opening parenthesis) to its closing one, string and character
/// literals skipped whole (a parenthesis inside them does not count).
QString balancedArguments(const QString& text, qsizetype open) {
    int depth = 0;
    for (qsizetype i = open; i < text.size(); ++i) {
        const QChar c = text[i];
        if (c == '"' || c == '\'') {
            for (++i; i < text.size() && text[i] != c; ++i)
                if (text[i] == '\\')
                    ++i;
        } else if (c == '(') {
            ++depth;
        } else if (c == ')' && --depth == 0) {
            return text.mid(open, i - open + 1);
        }
    }
    return text.mid(open);
}

int lineOf(const QString& text, qsizetype pos) {
    return static_cast<int>(text.left(pos).count('\n')) + 1;
}

/// Every call of @p callee (a regular expression ending at its opening parenthesis) whose
/// arguments name no diagnostic, as "file:line: arguments".
QStringList callsWithoutDiagnostic(const QRegularExpression& callee) {
    QStringList offenders;
    // A diagnostic by name, or a range of existing ones (warnings.insert(end, b.begin(), ...)).
    static const QRegularExpression coded(QStringLiteral("iagnostic|\\.begin\\(\\)"));
    for (const auto& [path, text] : coreSources()) {
        if (path.startsWith("core/model/errors.") || path.startsWith("core/model/diagnostic"))
            continue;
        auto it = callee.globalMatch(text);
        while (it.hasNext()) {
            const auto m = it.next();
            const QString args = balancedArguments(text, m.capturedEnd() - 1);
            if (!coded.match(args).hasMatch())
                offenders << QStringLiteral("%1:%2: %3")
                                 .arg(path)
                                 .arg(lineOf(text, m.capturedStart()))
                                 .arg(args.simplified().left(120));
        }
    }
    return offenders;
}

} // namespace

void TstDiagnosticCatalogue::codesAreUniqueAndWellFormed() {
    static const QRegularExpression name(QStringLiteral("^[a-z][a-z0-9_]*$"));
    std::set<std::string> seen, templates;
    QVERIFY(!diagnosticCatalogue().empty());
    for (const DiagnosticTemplate& t : diagnosticCatalogue()) {
        QVERIFY2(name.match(QString::fromUtf8(t.code)).hasMatch(), t.code);
        QVERIFY2(seen.insert(t.code).second, t.code); // a code names one template
        // and a sentence has one code (translated once, the same everywhere)
        QVERIFY2(templates.insert(t.englishTemplate).second, t.englishTemplate);
        QVERIFY2(t.englishTemplate && *t.englishTemplate, t.code);
        QCOMPARE(diagnosticTemplate(t.code), t.englishTemplate);
    }
}

void TstDiagnosticCatalogue::placeholdersAreNumberedFromOne() {
    // A template's placeholders are %1 .. %n with none missing: a translation fills the same
    // ones, and an argument without its placeholder would be lost.
    static const QRegularExpression placeholder(QStringLiteral("%([1-9])"));
    for (const DiagnosticTemplate& t : diagnosticCatalogue()) {
        QSet<int> used;
        auto it = placeholder.globalMatch(QString::fromUtf8(t.englishTemplate));
        while (it.hasNext())
            used.insert(it.next().captured(1).toInt());
        for (int k = 1; k <= used.size(); ++k)
            QVERIFY2(used.contains(k),
                     qPrintable(
                         QStringLiteral("%1: %%2 missing").arg(QString::fromUtf8(t.code)).arg(k)));
    }
}

void TstDiagnosticCatalogue::argumentsFillTheTemplate() {
    const Diagnostic d = makeDiagnostic("contour_axis_saturated", {"x", "2.5", "0.75"});
    QCOMPARE(d.code, std::string("contour_axis_saturated"));
    QCOMPARE(d.text, std::string("x axis: |u| reached the actuator limit of 2.5 V for 0.75 s"));
    QCOMPARE(d.args.size(), std::size_t(3));
    // An argument's own '%1' is text, not read again (one pass).
    QCOMPARE(fillDiagnosticTemplate("%1 and %2", {"%2", "b"}), std::string("%2 and b"));
    // A placeholder without its argument stays as it is.
    QCOMPARE(fillDiagnosticTemplate("%1 and %2", {"a"}), std::string("a and %2"));
}

void TstDiagnosticCatalogue::codedArgumentsNest() {
    // A caught reason inside a longer sentence keeps its own code for the interface.
    const Diagnostic inner = makeDiagnostic("not_positive");
    const Diagnostic outer = makeDiagnostic("no_stability_margins", {inner});
    QCOMPARE(outer.text, std::string("no stability margins: must be greater than zero"));
    QCOMPARE(outer.args.at(0).code, std::string("not_positive"));
    try {
        requirePositive(-1.0, "kp");
        QFAIL("requirePositive accepted -1");
    } catch (const InvalidInput& e) {
        QCOMPARE(e.reasonDiagnostic(), inner);
        QCOMPARE(std::string(e.what()), std::string("kp: must be greater than zero"));
    }
}

void TstDiagnosticCatalogue::joinKeepsEachPartsCode() {
    const Diagnostic a = makeDiagnostic("at_least", {"2"});
    const Diagnostic b = makeDiagnostic("is_empty");
    const Diagnostic c("x");
    const Diagnostic j = joinDiagnostics({a, b, c});
    QCOMPARE(j.text, std::string("must be at least 2; is empty; x")); // "%1; %2" folded left
    QCOMPARE(j.code, std::string("list_semicolon"));
    QCOMPARE(j.args.at(0).args.at(0), a);
    QCOMPARE(j.args.at(0).args.at(1), b);
    QCOMPARE(joinDiagnostics({a}), a);
    QCOMPARE(joinDiagnostics({b, c}, "list_comma").text, std::string("is empty, x"));
    QVERIFY(!joinDiagnostics({}).coded());
}

void TstDiagnosticCatalogue::unknownCodeIsRefused() {
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, makeDiagnostic("no_such_code"));
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, diagnosticTemplate(""));
}

void TstDiagnosticCatalogue::everyCodeUsedIsInTheCatalogue() {
    // A code the catalogue lacks would throw std::out_of_range where the message is made.
    static const QRegularExpression use(QStringLiteral("makeDiagnostic\\(\\s*\"([^\"]*)\""));
    QStringList missing;
    int uses = 0;
    for (const auto& [path, text] : coreSources()) {
        auto it = use.globalMatch(text);
        while (it.hasNext()) {
            const auto m = it.next();
            ++uses;
            try {
                diagnosticTemplate(m.captured(1).toStdString());
            } catch (const std::out_of_range&) {
                missing << QStringLiteral("%1:%2: %3")
                               .arg(path)
                               .arg(lineOf(text, m.capturedStart()))
                               .arg(m.captured(1));
            }
        }
    }
    QVERIFY(uses > 0);
    QVERIFY2(missing.isEmpty(), qPrintable(missing.join('\n')));
}

void TstDiagnosticCatalogue::everyRefusalOfTheCoreIsCoded() {
    // Each InvalidInput and FileError the core constructs gives its reason as a diagnostic
    // (makeDiagnostic, a caught reasonDiagnostic(), the system's systemErrorDiagnostic(), or a
    // function or variable named ...Diagnostic).
    static const QRegularExpression construct(
        QStringLiteral("(?<![:\\w])(?:InvalidInput|FileError)\\s*\\("));
    const QStringList offenders = callsWithoutDiagnostic(construct);
    for (const QString& o : offenders)
        qWarning("uncoded refusal: %s", qPrintable(o));
    QVERIFY2(
        offenders.isEmpty(),
        qPrintable(QStringLiteral("%1 uncoded refusal(s), listed above").arg(offenders.size())));
}

void TstDiagnosticCatalogue::everyWarningOfTheCoreIsCoded() {
    // What the core adds to a result's warnings or notes is a diagnostic, not English text.
    static const QRegularExpression add(QStringLiteral(
        "\\b\\w*(?:[Ww]arnings?|[Nn]otes|[Ff]indings)\\w*\\s*(?:\\.|->)\\s*(?:push_back|"
        "emplace_back|insert)\\s*\\("));
    const QStringList offenders = callsWithoutDiagnostic(add);
    for (const QString& o : offenders)
        qWarning("uncoded warning: %s", qPrintable(o));
    QVERIFY2(
        offenders.isEmpty(),
        qPrintable(QStringLiteral("%1 uncoded warning(s), listed above").arg(offenders.size())));
}

QTEST_APPLESS_MAIN(TstDiagnosticCatalogue)
#include "tst_diagnostic_catalogue.moc"
