// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/diagnostic.h"
#include "core/model/errors.h"

#include <QString>

#include <exception>

namespace xyt::ui {

/**
 * A core warning or refusal in the user's language: the translation of its code's template
 * (Qt Linguist's context is the code, the source the catalogue's English template,
 * core/model/diagnostic_catalogue.h) with its arguments, each translated in turn when it is
 * coded. An uncoded diagnostic (a number, a name) shows its text; so does a code the catalogue
 * does not know.
 */
QString diagnosticText(const Diagnostic& d);

/// A refusal as the workbench shows it: "<field>: <reason>", the reason in the user's language.
QString invalidInputText(const InvalidInput& e);

/// Any exception's message for the user: an InvalidInput's as invalidInputText, a FileError's as
/// "<path>: <reason>" with its reason translated, another's what().
QString exceptionText(const std::exception& e);

/**
 * A name the core marks with XYT_TRANSLATE_NOOP(@p context, @p text) (a method's name, a
 * parameter's label, ...) in the user's language; the English where no translation is loaded.
 */
QString coreText(const char* context, const std::string& text);

} // namespace xyt::ui
