// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/session/diagnostic_text.h"

#include "core/io/file_io.h"
#include "core/model/diagnostic_catalogue.h"

#include <QCoreApplication>

#include <stdexcept>

namespace xyt::ui {

namespace {

/// %1 .. %9 of @p templ replaced by the translated @p args in one pass (an argument's own '%'
/// is not read again), as the core's fillDiagnosticTemplate does.
QString fillDiagnosticText(const QString& templ, const std::vector<Diagnostic>& args) {
    QString out;
    out.reserve(templ.size());
    for (qsizetype i = 0; i < templ.size(); ++i) {
        const QChar c = templ[i];
        if (c == QLatin1Char('%') && i + 1 < templ.size() && templ[i + 1] >= QLatin1Char('1') &&
            templ[i + 1] <= QLatin1Char('9')) {
            const auto k = static_cast<std::size_t>(templ[i + 1].unicode() - '1');
            if (k < args.size()) {
                out += diagnosticText(args[k]);
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
    if (!d.coded())
        return QString::fromStdString(d.text);
    const char* templ = nullptr;
    try {
        templ = diagnosticTemplate(d.code);
    } catch (const std::out_of_range&) {
        return QString::fromStdString(d.text);
    }
    return fillDiagnosticText(QCoreApplication::translate(d.code.c_str(), templ), d.args);
}

QString invalidInputText(const InvalidInput& e) {
    return QStringLiteral("%1: %2").arg(QString::fromStdString(e.field()),
                                        diagnosticText(e.reasonDiagnostic()));
}

QString exceptionText(const std::exception& e) {
    if (const auto* invalid = dynamic_cast<const InvalidInput*>(&e))
        return invalidInputText(*invalid);
    if (const auto* file = dynamic_cast<const FileError*>(&e))
        return QStringLiteral("%1: %2").arg(QString::fromStdString(file->path()),
                                            diagnosticText(file->reasonDiagnostic()));
    return QString::fromUtf8(e.what());
}

QString coreText(const char* context, const std::string& text) {
    return QCoreApplication::translate(context, text.c_str());
}

} // namespace xyt::ui
