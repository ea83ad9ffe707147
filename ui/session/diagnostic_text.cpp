// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/session/diagnostic_text.h"

#include "core/io/file_io.h"
#include "core/model/diagnostic_catalogue.h"

#include <QCoreApplication>

#include <stdexcept>

namespace xyt::ui {

QString diagnosticText(const Diagnostic& d) {
    if (!d.coded())
        return QString::fromStdString(d.text);
    const char* templ = nullptr;
    try {
        templ = diagnosticTemplate(d.code);
    } catch (const std::out_of_range&) {
        return QString::fromStdString(d.text);
    }
    // The core's one-pass fill, on the translated template with the translated arguments.
    std::vector<Diagnostic> translatedArgs;
    translatedArgs.reserve(d.args.size());
    for (const Diagnostic& arg : d.args)
        translatedArgs.emplace_back(diagnosticText(arg).toStdString());
    return QString::fromStdString(fillDiagnosticTemplate(
        QCoreApplication::translate(d.code.c_str(), templ).toStdString(), translatedArgs));
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
