// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/session/interface_language.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QPointer>
#include <QSettings>
#include <QTranslator>

namespace xyt::ui {

namespace {

const char* const kUiLanguageKey = "ui/language";
const char* const kUiTranslationsDir = ":/i18n";

/// The translators installed by installUiLanguage: the application's catalogue and Qt's.
/// Application-wide by nature (QCoreApplication holds the installed translators); kept so a
/// later call replaces rather than stacks them.
QPointer<QTranslator>& installedAppTranslator() {
    static QPointer<QTranslator> t;
    return t;
}
QPointer<QTranslator>& installedQtTranslator() {
    static QPointer<QTranslator> t;
    return t;
}

void uiLanguageRemove(QPointer<QTranslator>& t) {
    if (t) {
        QCoreApplication::removeTranslator(t);
        delete t;
    }
    t = nullptr;
}

bool uiLanguageIsSource(const QLocale& locale) {
    return locale.language() == QLocale::English || locale.language() == QLocale::C;
}

} // namespace

QStringList uiLanguageCodes() {
    return {QString(), QStringLiteral("en"), QStringLiteral("pt_BR")};
}

QString storedUiLanguage() {
    const QString code = QSettings().value(kUiLanguageKey).toString();
    return uiLanguageCodes().contains(code) ? code : QString();
}

void storeUiLanguage(const QString& code) {
    QSettings().setValue(kUiLanguageKey, code);
}

QLocale uiLocaleFor(const QString& code) {
    if (code.isEmpty())
        return QLocale::system();
    return QLocale(code);
}

bool installUiLanguage(const QString& code) {
    uiLanguageRemove(installedAppTranslator());
    uiLanguageRemove(installedQtTranslator());
    // Numbers keep the decimal point in every language (see the header).
    QLocale::setDefault(QLocale::c());
    const QLocale locale = uiLocaleFor(code);
    if (uiLanguageIsSource(locale))
        return true;
    auto* app = new QTranslator(QCoreApplication::instance());
    if (!app->load(locale, QStringLiteral("xytune"), QStringLiteral("_"), kUiTranslationsDir)) {
        delete app;
        return false;
    }
    QCoreApplication::installTranslator(app);
    installedAppTranslator() = app;
    // Qt's own text (the standard buttons) is optional: without its package the buttons stay
    // English and the rest is translated.
    auto* qt = new QTranslator(QCoreApplication::instance());
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        QCoreApplication::installTranslator(qt);
        installedQtTranslator() = qt;
    } else {
        delete qt;
    }
    return true;
}

QString translatedFor(const QString& code, const char* context, const char* source) {
    QTranslator translator;
    const QLocale locale = uiLocaleFor(code);
    if (!uiLanguageIsSource(locale) && translator.load(locale, QStringLiteral("xytune"),
                                                       QStringLiteral("_"), kUiTranslationsDir)) {
        const QString text = translator.translate(context, source);
        if (!text.isEmpty())
            return text;
    }
    return QString::fromUtf8(source);
}

} // namespace xyt::ui
