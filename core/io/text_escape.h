// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace xyt {

/**
 * User text (a session label, a file name) made safe to copy into generated files and onto a
 * terminal. Session files are shared between people, so what they hold must never become code
 * in an export nor a control sequence on someone's terminal.
 *
 * Both functions decode UTF-8 and keep printable characters; they never let through C0/C1
 * controls (NUL, BEL, BS, CR, LF, ESC, ...), DEL, the Unicode line and paragraph separators,
 * the bidirectional overrides and isolates ("Trojan Source", CVE-2021-42574), the BOM, or
 * malformed UTF-8.
 */

/// Where the text goes: the comment syntax whose terminators must not appear in it.
enum class CommentSyntax { C, Octave };

/**
 * One line of comment text, at most @p maxChars characters (then "..."). Forbidden characters
 * become '_'. For C, a comment delimiter is split ("*" "/" -> "* /", "/" "*" -> "/ *") and "??"
 * is split ("? ?") so that no trigraph can form; Octave comments run to the end of the line,
 * which cannot occur in the result.
 */
std::string commentText(std::string_view text, CommentSyntax syntax, std::size_t maxChars = 120);

/**
 * The text with every forbidden character shown as an escape ("\x1b", "\x00", "\u202e"), so
 * the reader sees what the file holds and the terminal receives only printable characters.
 * A backslash is doubled so the escapes cannot be forged.
 */
std::string terminalText(std::string_view text);

} // namespace xyt
