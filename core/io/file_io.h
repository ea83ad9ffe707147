// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/diagnostic.h"

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace xyt {

/**
 * A file that could not be read or written. what() reads "<path>: <reason>", the reason being
 * ours, coded (makeDiagnostic: "is not a regular file", translated by the workbench), or the
 * system's (systemErrorDiagnostic: strerror's text, uncoded).
 */
class FileError : public std::runtime_error {
public:
    FileError(std::string path, const Diagnostic& reason);
    const std::string& path() const noexcept { return path_; }
    const std::string& reason() const noexcept { return reason_.text; }
    const Diagnostic& reasonDiagnostic() const noexcept { return reason_; }

private:
    std::string path_;
    Diagnostic reason_;
};

/// The system's message for @p error (strerror), as an uncoded reason.
Diagnostic systemErrorDiagnostic(int error);

/// Appends bytes to the file being written; throws FileError when a write fails.
using ByteSink = std::function<void(std::string_view)>;

/**
 * Replaces @p path atomically: the bytes go to a temporary file in the same folder, every
 * write, the fsync and the close are checked, and only then is it renamed over @p path. On any
 * failure (a full disk, an I/O error, an exception from @p produce) the temporary file is
 * removed and the old file is left exactly as it was. The mode and, where the system permits
 * (always for root), the owner and group of a replaced file are kept.
 *
 * A symbolic link is followed: its target is replaced, or created when it does not exist (the
 * link stays a link). Since a link lets its owner choose the file we write, links are followed
 * only when that cannot hurt:
 *  - in a folder everyone may write to with the sticky bit (/tmp), a link that belongs neither
 *    to us (the effective user) nor to the folder's owner is refused, as the kernel's
 *    fs.protected_symlinks does (checked here even where it is off);
 *  - an existing target must belong to the owner of every link on the way to it (so root never
 *    replaces a system file or another user's file through a link that someone else made, nor
 *    through its own link to a user's file), and a missing target is created only through links
 *    of our own;
 *  - in such a shared sticky folder, an existing file (reached directly or through a link) that
 *    belongs neither to us nor to the folder's owner is refused, as fs.protected_regular does.
 * The temporary file is ".xytune-save-<pid>-XXXXXX" beside the target; each save first removes
 * the ones of this user whose process no longer exists (a save killed half way), never those of
 * a process still running.
 * @param produce writes the content through the sink it is given, in as many pieces as it likes
 *        (the sink buffers 64 KiB), so large outputs are streamed, never held in memory.
 * @throws FileError naming @p path with the reason, including "is not a regular file" for a
 *         folder, device, FIFO or socket (never replaced) and the refused links and files above.
 */
void writeFileAtomically(const std::string& path,
                         const std::function<void(const ByteSink&)>& produce);
void writeFileAtomically(const std::string& path, std::string_view bytes);

/**
 * Reads a regular file of at most @p maxBytes. FIFOs, devices, sockets and folders are refused
 * without blocking on them (opened non-blocking, checked with fstat), and no more than
 * @p maxBytes + 1 bytes are ever read, whatever the file claims its size is.
 * @throws FileError with the reason ("no such file", "is not a regular file", "is larger than
 *         the limit of N bytes", or the system's).
 */
std::string readRegularFile(const std::string& path, std::size_t maxBytes);

/// Test hook: the steps of writeFileAtomically whose failure a test can inject.
enum class WriteStep { None, Write, Sync, Rename };
/**
 * Makes every later writeFileAtomically fail at @p step (until called with WriteStep::None), as
 * a full disk (ENOSPC at Write) or a failing device (EIO at Sync or Rename) would. The
 * environment variable XYT_TEST_FAIL_WRITE=write|sync|rename, read at the first write, sets it
 * for a whole process, so tests can inject the failure into xytune-cli. For tests only.
 */
void injectWriteFailureForTesting(WriteStep step);

} // namespace xyt
