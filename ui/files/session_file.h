// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/diagnostic.h"
#include "core/session/session.h"
#include "ui/files/session_format_migration.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

namespace xyt::files {

inline constexpr const char* kSessionFormatName = "xytune-session";
/// Larger files are refused before parsing (a session is a few kilobytes).
inline constexpr qint64 kMaxSessionFileBytes = 8 * 1024 * 1024;

/// The outcome of reading a session: either a complete, validated session or the JSON path of
/// the first bad value with the reason. Unknown fields are reported in warnings.
struct SessionLoadResult {
    bool ok = false;
    Session session;
    QString errorPath; ///< e.g. "axes[1].gt.plant.a2" (empty for file-level errors)
    QString error;     ///< e.g. "must be a finite number"
    /// The core's coded reason when the core refused a value (`error` is its English text);
    /// uncoded for the file format's own messages.
    Diagnostic errorDiagnostic;
    QStringList warnings;
    /// "axes[1].gt.plant.a2: must be a finite number", or the file-level error.
    QString message() const { return errorPath.isEmpty() ? error : errorPath + ": " + error; }
};

/// The session as the JSON document of the file format (see README, "Session files").
QJsonObject sessionToJson(const Session& session);
/// Validates everything before returning; nothing is half-applied.
SessionLoadResult sessionFromJson(const QJsonObject& root);
SessionLoadResult sessionFromBytes(const QByteArray& bytes);
/// Reads and validates @p path (missing file, a directory, a FIFO or device, too large, not
/// JSON: clear errors). Never blocks on a special file nor reads more than the size limit.
SessionLoadResult loadSessionFile(const QString& path);
/// Atomic save (xyt::writeFileAtomically): every write and the commit are checked; on failure
/// the old file is left intact and @p error says "<path>: <system reason>".
bool saveSessionFile(const Session& session, const QString& path, QString* error);
/// Atomic write of any bytes, with the same guarantees (refuses to replace a non-regular file).
bool writeFileAtomically(const QString& path, const QByteArray& bytes, QString* error);

/// "guillemin-truxal" / "pole-placement-zpetc".
QString methodName(DesignMethod method);

} // namespace xyt::files
