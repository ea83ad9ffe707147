// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session.h"

#include <QDateTime>
#include <QLockFile>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <vector>

class QWidget;

namespace xyt::ui {

class SessionFileController;
class TuningSession;

/// Unsaved work found at start-up: left behind by an instance that crashed or was killed.
struct RecoveredWork {
    QString path;        ///< the recovery file
    QString sessionFile; ///< the session file the work belonged to ("" when untitled)
    QDateTime savedAt;
    Session session;
};

/**
 * Keeps a recovery copy of unsaved work: a few seconds after each change (the timer restarts on
 * every change, so a slider drag writes once, after it), the session is written atomically to
 * `<directory>/session-<pid>.json`. A clean state (saved, loaded, undone back to the saved state)
 * or a clean quit removes the copy. Each instance holds a lock file beside its copy, so the
 * copies of running instances are never offered; the copy of an instance that died is
 * (findOrphans), with the lock's owner checked by QLockFile (a dead process' lock is stale).
 */
class RecoveryStore : public QObject {
    Q_OBJECT
public:
    /// @p directory: where copies live (created when missing); by default the application's
    /// local data location + "/recovery".
    RecoveryStore(TuningSession* session, const QString& directory, QObject* parent = nullptr);
    ~RecoveryStore() override;

    static QString defaultDirectory();
    /// Delay between the last change and the write (default 3000 ms).
    void setDelayMs(int ms) { timer_.setInterval(ms); }
    QString copyPath() const { return copyPath_; }
    /// The session file the work belongs to, recorded in the copy.
    void setSessionFile(const QString& path) { sessionFile_ = path; }
    /// Writes the copy now when the session has unsaved changes (else removes it). False with
    /// @p error when the write failed (the previous copy is then intact).
    bool writeNow(QString* error = nullptr);
    /// Removes this instance's copy (clean save or quit).
    void discard();
    /// The last write's error ("" after a successful write).
    QString lastError() const { return lastError_; }

    /// Copies left by instances that are no longer running, newest first. Unreadable copies are
    /// skipped (and kept on disk for the user to look at).
    static std::vector<RecoveredWork> findOrphans(const QString& directory);
    /// Removes an orphan's copy once it was restored or declined.
    static void removeOrphan(const RecoveredWork& work);

private:
    void onChanged();

    TuningSession* session_;
    QString directory_;
    QString copyPath_;
    QString sessionFile_;
    QString lastError_;
    std::unique_ptr<QLockFile> lock_;
    QTimer timer_;
};

/**
 * At start-up: offers the newest orphaned copy in @p directory ("Restore" or "Discard"). A
 * restored session becomes one undoable, unsaved change of @p session (so it is saved like any
 * other work) and belongs to the file it came from. Every orphan is removed afterwards.
 * Returns true when work was restored.
 */
bool offerRecovery(QWidget* parent, TuningSession* session, SessionFileController* files,
                   const QString& directory);

} // namespace xyt::ui
