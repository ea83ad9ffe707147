// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

/**
 * Marks a name the core gives the interface (a method's name, a parameter's label, a preset)
 * for translation, without Qt: XYT_TRANSLATE_NOOP(context, text) is the literal text. The build
 * tells Qt Linguist's lupdate that it spells QT_TRANSLATE_NOOP (ui/CMakeLists.txt), so the
 * workbench's catalogue holds it, and the interface shows it with
 * QCoreApplication::translate(context, text) (coreText, ui/session/diagnostic_text.h). The CLI
 * and the session file keep the English.
 */
#define XYT_TRANSLATE_NOOP(context, text) text
