// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QLocale>
#include <QString>
#include <QStringList>

namespace xyt::ui {

/**
 * The languages of the workbench's text and how one is chosen and installed.
 *
 * A language is a code: "" follows the system locale, "en" is the source text (English),
 * "pt_BR" is Brazilian Portuguese (translations/xytune_pt_BR.ts, compiled into the widget
 * library as the resource `:/i18n/xytune_pt_BR.qm`). Qt's own strings (the standard dialogs'
 * buttons) come from Qt's catalogue `qtbase_<lang>.qm` in QLibraryInfo's TranslationsPath
 * (Debian: qt6-translations-l10n).
 *
 * Numbers are not localized: the text is translated, but every number is shown with a decimal
 * point (engineering convention; session files and exports stay C-locale), and the number
 * fields accept a decimal comma as well as the point (NumberField). installUiLanguage therefore
 * sets QLocale's default to C, which plots' tick labels and spin boxes follow.
 */

/// The codes offered in the Language menu and accepted by `xytune --language`, "" first.
QStringList uiLanguageCodes();

/// The language stored in the application's settings (key `ui/language`), "" when unset or
/// not one of uiLanguageCodes().
QString storedUiLanguage();

/// Stores @p code (one of uiLanguageCodes()) as the language used from the next start.
void storeUiLanguage(const QString& code);

/// The locale whose translation @p code asks for: QLocale::system() for "", else the code's.
QLocale uiLocaleFor(const QString& code);

/**
 * Installs the translations of @p code on the application (replacing any installed by an
 * earlier call) and sets the default locale to C (numbers keep their point). Call it before
 * the widgets are built: text already shown is not retranslated.
 * @return true when @p code's language is the source language or its translation loaded.
 */
bool installUiLanguage(const QString& code);

/// @p source of @p context as the translation of @p code says it (the source when it has none),
/// without installing it: a message announcing a language change in the new language.
QString translatedFor(const QString& code, const char* context, const char* source);

} // namespace xyt::ui
