// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A real full disk for the write tests: a tmpfs of a few kilobytes mounted in a private mount
// namespace of the test process (so nothing outside the test sees it, and it disappears with the
// process). Needs root (CAP_SYS_ADMIN) and a kernel that allows unshare(CLONE_NEWNS); where
// either is missing the caller QSKIPs with the reason returned here.

#include <QByteArray>
#include <QFile>
#include <QString>

#include <cerrno>
#include <cstring>

#include <sched.h>
#include <sys/mount.h>

namespace xyt::test {

/// Mounts a tmpfs of @p kilobytes at the existing folder @p dir. Returns an empty string on
/// success, else why it could not (for QSKIP).
inline QString mountSmallFilesystem(const QString& dir, int kilobytes) {
    if (::unshare(CLONE_NEWNS) != 0)
        return QStringLiteral("cannot make a private mount namespace (unshare: %1); run as root "
                              "to test a real full disk")
            .arg(std::strerror(errno));
    if (::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0)
        return QStringLiteral("cannot make mounts private: %1").arg(std::strerror(errno));
    const QByteArray options = "size=" + QByteArray::number(kilobytes) + "k";
    if (::mount("tmpfs", QFile::encodeName(dir).constData(), "tmpfs", 0, options.constData()) != 0)
        return QStringLiteral("cannot mount a tmpfs: %1").arg(std::strerror(errno));
    return {};
}

/// Unmounts what mountSmallFilesystem mounted (so the temporary folder can be removed).
inline void unmountSmallFilesystem(const QString& dir) {
    ::umount2(QFile::encodeName(dir).constData(), MNT_DETACH);
}

/// Fills the filesystem holding @p dir: writes @p dir/filler until the disk refuses.
inline void fillFilesystem(const QString& dir) {
    QFile filler(dir + "/filler");
    if (!filler.open(QIODevice::WriteOnly | QIODevice::Unbuffered))
        return;
    const QByteArray block(512, 'x');
    while (filler.write(block) == block.size()) {
    }
}

} // namespace xyt::test
