// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/session/recovery_store.h"

#include "ui/files/session_file.h"
#include "ui/session/session_file_controller.h"
#include "ui/session/tuning_session.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QStandardPaths>
#include <QUndoStack>

#include <algorithm>

namespace xyt::ui {

namespace {
constexpr const char* kRecoveryFormat = "xytune-recovery";
constexpr qint64 kMaxRecoveryBytes = files::kMaxSessionFileBytes + 64 * 1024;

QString lockPathOf(const QString& copyPath) {
    return copyPath.left(copyPath.size() - int(sizeof(".json") - 1)) + QStringLiteral(".lock");
}
} // namespace

QString RecoveryStore::defaultDirectory() {
    return QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) +
           QStringLiteral("/recovery");
}

RecoveryStore::RecoveryStore(TuningSession* session, const QString& directory, QObject* parent)
    : QObject(parent), session_(session), directory_(directory) {
    QDir().mkpath(directory_);
    const QString base =
        QStringLiteral("%1/session-%2").arg(directory_).arg(QCoreApplication::applicationPid());
    copyPath_ = base + QStringLiteral(".json");
    lock_ = std::make_unique<QLockFile>(base + QStringLiteral(".lock"));
    lock_->setStaleLockTime(0); // only a dead owner makes a lock stale, never its age
    lock_->tryLock(0);
    timer_.setSingleShot(true);
    timer_.setInterval(3000);
    connect(&timer_, &QTimer::timeout, this, [this] { writeNow(); });
    connect(session_, &TuningSession::designChanged, this, &RecoveryStore::onChanged);
    connect(session_->undoStack(), &QUndoStack::cleanChanged, this, [this](bool clean) {
        if (clean)
            discard();
    });
}

RecoveryStore::~RecoveryStore() = default; // the copy stays: only discard() removes it

void RecoveryStore::onChanged() {
    // designChanged comes before the undo stack updates its clean state, so whether there is
    // unsaved work is decided when the timer fires (writeNow), not here.
    timer_.start();
}

bool RecoveryStore::writeNow(QString* error) {
    timer_.stop();
    if (!session_->isModified()) {
        discard();
        return true;
    }
    QJsonObject root{{"format", kRecoveryFormat},
                     {"version", 1},
                     {"file", sessionFile_},
                     {"saved_at", QDateTime::currentDateTimeUtc().toString(Qt::ISODate)},
                     {"session", files::sessionToJson(session_->session())}};
    QString why;
    if (!files::writeFileAtomically(copyPath_, QJsonDocument(root).toJson(QJsonDocument::Compact),
                                    &why)) {
        lastError_ = why;
        if (error)
            *error = why;
        return false;
    }
    lastError_.clear();
    return true;
}

void RecoveryStore::discard() {
    timer_.stop();
    QFile::remove(copyPath_);
}

std::vector<RecoveredWork> RecoveryStore::findOrphans(const QString& directory) {
    std::vector<RecoveredWork> out;
    const QDir dir(directory);
    for (const QFileInfo& info :
         dir.entryInfoList({QStringLiteral("session-*.json")}, QDir::Files)) {
        // A copy whose lock is held by a running instance (this one included) is that
        // instance's live work.
        QLockFile lock(lockPathOf(info.absoluteFilePath()));
        lock.setStaleLockTime(0);
        if (!lock.tryLock(0))
            continue;
        lock.unlock();
        if (info.size() > kMaxRecoveryBytes)
            continue;
        QFile file(info.absoluteFilePath());
        if (!file.open(QIODevice::ReadOnly))
            continue;
        const QJsonObject root = QJsonDocument::fromJson(file.read(kMaxRecoveryBytes)).object();
        if (root.value("format").toString() != QLatin1String(kRecoveryFormat))
            continue;
        const files::SessionLoadResult loaded =
            files::sessionFromJson(root.value("session").toObject());
        if (!loaded.ok)
            continue;
        RecoveredWork work;
        work.path = info.absoluteFilePath();
        work.sessionFile = root.value("file").toString();
        work.savedAt = QDateTime::fromString(root.value("saved_at").toString(), Qt::ISODate);
        if (!work.savedAt.isValid())
            work.savedAt = info.lastModified();
        work.session = loaded.session;
        out.push_back(std::move(work));
    }
    std::sort(out.begin(), out.end(),
              [](const RecoveredWork& a, const RecoveredWork& b) { return a.savedAt > b.savedAt; });
    return out;
}

void RecoveryStore::removeOrphan(const RecoveredWork& work) {
    QFile::remove(work.path);
    QFile::remove(lockPathOf(work.path));
}

bool offerRecovery(QWidget* parent, TuningSession* session, SessionFileController* files,
                   const QString& directory) {
    const auto orphans = RecoveryStore::findOrphans(directory);
    if (orphans.empty())
        return false;
    const RecoveredWork& newest = orphans.front();
    const QString from = newest.sessionFile.isEmpty()
                             ? QObject::tr("an untitled session")
                             : QObject::tr("“%1”").arg(QFileInfo(newest.sessionFile).fileName());
    QMessageBox box(
        QMessageBox::Question, QObject::tr("Recover unsaved work"),
        QObject::tr("XY Tune was closed without saving changes to %1 (last kept %2).\n\n"
                    "Restore that work?")
            .arg(from, QLocale().toString(newest.savedAt.toLocalTime(), QLocale::ShortFormat)),
        QMessageBox::NoButton, parent);
    QPushButton* restore = box.addButton(QObject::tr("&Restore"), QMessageBox::AcceptRole);
    box.addButton(QObject::tr("&Discard"), QMessageBox::DestructiveRole);
    box.setDefaultButton(restore);
    box.exec();
    const bool restored = box.clickedButton() == restore;
    if (restored) {
        if (files)
            files->adoptFile(newest.sessionFile);
        session->apply(newest.session, QObject::tr("Restore unsaved work"));
    }
    for (const RecoveredWork& w : orphans)
        RecoveryStore::removeOrphan(w);
    return restored;
}

} // namespace xyt::ui
