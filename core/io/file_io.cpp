// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/file_io.h"

#include "core/model/diagnostic_catalogue.h"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <vector>

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

namespace xyt {

FileError::FileError(std::string path, const Diagnostic& reason)
    : std::runtime_error(path + ": " + reason.text), path_(std::move(path)), reason_(reason) {}

Diagnostic systemErrorDiagnostic(int error) {
    return Diagnostic(std::strerror(error));
}

namespace {

WriteStep injectedFailure = WriteStep::None;
std::once_flag environmentRead;

WriteStep failingStep() {
    std::call_once(environmentRead, [] {
        const char* v = std::getenv("XYT_TEST_FAIL_WRITE");
        if (!v)
            return;
        const std::string s(v);
        if (s == "write")
            injectedFailure = WriteStep::Write;
        else if (s == "sync")
            injectedFailure = WriteStep::Sync;
        else if (s == "rename")
            injectedFailure = WriteStep::Rename;
    });
    return injectedFailure;
}

/// The folder part of a path ("." for a bare name).
std::string folderOf(const std::string& path) {
    const auto slash = path.find_last_of('/');
    if (slash == std::string::npos)
        return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

/// Closes and removes the temporary file unless released.
class TemporaryFile {
public:
    TemporaryFile(std::string templ, int fd) : name_(std::move(templ)), fd_(fd) {}
    ~TemporaryFile() {
        if (fd_ >= 0)
            ::close(fd_);
        if (!name_.empty())
            ::unlink(name_.c_str());
    }
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;
    int fd() const { return fd_; }
    const std::string& name() const { return name_; }
    /// close(2), with its result: NFS and some full disks report a lost write only here.
    int close() {
        const int r = ::close(fd_);
        fd_ = -1;
        return r;
    }
    void release() { name_.clear(); }

private:
    std::string name_;
    int fd_;
};

/// write(2) until every byte is written; a short write is retried, an error is thrown.
void writeAll(int fd, const char* data, std::size_t size, const std::string& path) {
    while (size > 0) {
        ssize_t n;
        if (failingStep() == WriteStep::Write) {
            n = -1;
            errno = ENOSPC;
        } else {
            n = ::write(fd, data, size);
        }
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            throw FileError(path, systemErrorDiagnostic(n < 0 ? errno : EIO));
        data += n;
        size -= static_cast<std::size_t>(n);
    }
}

/// The temporary files of a save: ".xytune-save-<pid>-XXXXXX", the pid of the writing process.
constexpr const char* kTemporaryPrefix = ".xytune-save-";

/// The pid in the name of one of our temporary files, or 0 when @p name is not exactly one
/// (the prefix, 1 to 9 digits, '-', the six letters or digits mkstemp chose).
pid_t temporaryFilePid(const char* name) {
    const std::size_t prefix = std::strlen(kTemporaryPrefix);
    if (std::strncmp(name, kTemporaryPrefix, prefix) != 0)
        return 0;
    const char* p = name + prefix;
    long pid = 0;
    int digits = 0;
    for (; *p >= '0' && *p <= '9'; ++p, ++digits) {
        if (digits == 9)
            return 0;
        pid = pid * 10 + (*p - '0');
    }
    if (digits == 0 || *p != '-')
        return 0;
    ++p;
    int suffix = 0;
    for (; (*p >= '0' && *p <= '9') || (*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z'); ++p)
        ++suffix;
    return *p == '\0' && suffix == 6 ? static_cast<pid_t>(pid) : 0;
}

/// Removes the temporary files that a killed save left in @p folder: ours (our pattern exactly,
/// a regular file of this user) whose writing process no longer exists. A file of a process
/// that still runs (another instance saving now, or this one's other thread) is never touched,
/// nor one whose pid we cannot judge. Best effort: a save never fails because of this. A
/// process in another pid namespace that shares the folder is not seen by kill(2); such a setup
/// (two containers writing one folder as the same user) is not supported.
void removeStaleTemporaries(const std::string& folder) {
    const int dirFd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dirFd < 0)
        return;
    DIR* dir = ::fdopendir(dirFd);
    if (!dir) {
        ::close(dirFd);
        return;
    }
    const pid_t self = ::getpid();
    while (const dirent* entry = ::readdir(dir)) {
        const pid_t pid = temporaryFilePid(entry->d_name);
        if (pid <= 0 || pid == self)
            continue;
        struct stat st {};
        if (::fstatat(dirFd, entry->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0 ||
            !S_ISREG(st.st_mode) || st.st_uid != ::geteuid())
            continue;
        if (::kill(pid, 0) == -1 && errno == ESRCH)
            ::unlinkat(dirFd, entry->d_name, 0);
    }
    ::closedir(dir);
}

/// What a save replaces: @p path with its symbolic links followed.
struct WriteTarget {
    std::string path; ///< the file to create or replace; its last component is no link
    bool exists = false;
    struct stat st {}; ///< of the existing file
};

/// A folder that everyone may write to and only owners may delete from (/tmp): there another
/// user can plant a link or a file under the name we are about to write.
bool isSharedStickyFolder(const std::string& folder, uid_t* owner) {
    struct stat st {};
    if (::stat(folder.c_str(), &st) != 0)
        return false;
    *owner = st.st_uid;
    return S_ISDIR(st.st_mode) && (st.st_mode & S_ISVTX) && (st.st_mode & S_IWOTH);
}

std::string uidText(uid_t uid) {
    return "uid " + std::to_string(uid);
}

/// Follows the symbolic links of @p path's last component (a chain of at most 40, as the kernel
/// allows) with the ownership rules of writeFileAtomically.
WriteTarget resolveWriteTarget(const std::string& path) {
    const uid_t self = ::geteuid();
    std::string current = path;
    std::vector<uid_t> linkOwners;
    for (int hops = 0;; ++hops) {
        struct stat st {};
        if (::lstat(current.c_str(), &st) != 0) {
            if (errno != ENOENT)
                throw FileError(path, systemErrorDiagnostic(errno));
            // A new file, or the missing target of a dangling link: created only for a link of
            // our own, since another user's link would choose where we create a file.
            for (const uid_t owner : linkOwners)
                if (owner != self)
                    throw FileError(path,
                                    makeDiagnostic("io_foreign_link_to_nothing", {uidText(owner)}));
            return {current, false, {}};
        }
        uid_t folderOwner = 0;
        const bool shared = isSharedStickyFolder(folderOf(current), &folderOwner);
        if (!S_ISLNK(st.st_mode)) {
            if (S_ISDIR(st.st_mode))
                throw FileError(path, makeDiagnostic("io_is_directory"));
            if (!S_ISREG(st.st_mode))
                throw FileError(path, makeDiagnostic("io_not_regular_to_replace"));
            // A link may only lead to a file of its own owner: otherwise whoever made the link
            // chooses someone else's file for us to replace (root following a user's link onto
            // a system file, or onto another user's file).
            for (const uid_t owner : linkOwners)
                if (st.st_uid != owner)
                    throw FileError(path, makeDiagnostic("io_link_to_foreign_file",
                                                         {uidText(st.st_uid), uidText(owner)}));
            // What the kernel's protected_regular does for open(O_CREAT): in a shared sticky
            // folder a file planted by another user is not ours to fill (keeping its owner
            // would hand our content to that user).
            if (shared && st.st_uid != self && st.st_uid != folderOwner)
                throw FileError(path,
                                makeDiagnostic("io_foreign_file_in_sticky", {uidText(st.st_uid)}));
            return {current, true, st};
        }
        if (hops == 40)
            throw FileError(path, systemErrorDiagnostic(ELOOP));
        // What the kernel's protected_symlinks enforces, whether or not it is switched on: in a
        // shared sticky folder only a link of our own or of the folder's owner is followed.
        if (shared && st.st_uid != self && st.st_uid != folderOwner)
            throw FileError(path,
                            makeDiagnostic("io_foreign_link_in_sticky", {uidText(st.st_uid)}));
        linkOwners.push_back(st.st_uid);
        std::string link(PATH_MAX, '\0');
        const ssize_t n = ::readlink(current.c_str(), link.data(), link.size());
        if (n < 0)
            throw FileError(path, systemErrorDiagnostic(errno));
        if (static_cast<std::size_t>(n) == link.size())
            throw FileError(path, systemErrorDiagnostic(ENAMETOOLONG));
        link.resize(static_cast<std::size_t>(n));
        current = !link.empty() && link.front() == '/' ? link : folderOf(current) + "/" + link;
    }
}

} // namespace

void injectWriteFailureForTesting(WriteStep step) {
    failingStep(); // the environment is read first, so the call below wins
    injectedFailure = step;
}

void writeFileAtomically(const std::string& path,
                         const std::function<void(const ByteSink&)>& produce) {
    if (path.empty())
        throw FileError(path, makeDiagnostic("io_empty_file_name"));
    const WriteTarget target = resolveWriteTarget(path);
    const std::string folder = folderOf(target.path);
    removeStaleTemporaries(folder);
    std::string name = folder + "/" + kTemporaryPrefix + std::to_string(::getpid()) + "-XXXXXX";
    const int fd = ::mkstemp(name.data());
    if (fd < 0)
        throw FileError(path, systemErrorDiagnostic(errno));
    TemporaryFile temp(name, fd);
    mode_t mode;
    if (target.exists) {
        mode = target.st.st_mode & 07777;
        // Keep the owner, as editing in place would. Only root may give a file away, and a
        // member of the file's group may keep the group: what is not permitted is skipped (the
        // file then belongs to whoever wrote it, as any new file does). chown clears the
        // set-user-ID bits, so the mode is set afterwards.
        if (::fchown(fd, target.st.st_uid, target.st.st_gid) != 0)
            (void)::fchown(fd, static_cast<uid_t>(-1), target.st.st_gid);
    } else { // what open(path, O_CREAT, 0666) would have given: 0666 less the umask
        const mode_t mask = ::umask(0);
        ::umask(mask);
        mode = 0666 & ~mask;
    }
    if (::fchmod(fd, mode) != 0)
        throw FileError(path, systemErrorDiagnostic(errno));

    std::string buffer;
    constexpr std::size_t kBufferBytes = 64 * 1024;
    buffer.reserve(kBufferBytes);
    const ByteSink sink = [&](std::string_view bytes) {
        if (buffer.size() + bytes.size() > kBufferBytes) {
            writeAll(fd, buffer.data(), buffer.size(), path);
            buffer.clear();
        }
        if (bytes.size() >= kBufferBytes)
            writeAll(fd, bytes.data(), bytes.size(), path);
        else
            buffer.append(bytes);
    };
    produce(sink);
    writeAll(fd, buffer.data(), buffer.size(), path);

    if (failingStep() == WriteStep::Sync || ::fsync(fd) != 0)
        throw FileError(path,
                        systemErrorDiagnostic(failingStep() == WriteStep::Sync ? EIO : errno));
    if (temp.close() != 0)
        throw FileError(path, systemErrorDiagnostic(errno));
    if (failingStep() == WriteStep::Rename || ::rename(name.c_str(), target.path.c_str()) != 0)
        throw FileError(path,
                        systemErrorDiagnostic(failingStep() == WriteStep::Rename ? EIO : errno));
    temp.release();
    // Make the rename itself durable; the file is complete either way, so a failure here is not
    // reported.
    const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
}

void writeFileAtomically(const std::string& path, std::string_view bytes) {
    writeFileAtomically(path, [bytes](const ByteSink& sink) { sink(bytes); });
}

std::string readRegularFile(const std::string& path, std::size_t maxBytes) {
    // O_NONBLOCK: opening a FIFO without a writer must not block; it is refused below anyway.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0)
        throw FileError(path, errno == ENOENT ? makeDiagnostic("io_no_such_file")
                                              : systemErrorDiagnostic(errno));
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0)
        throw FileError(path, systemErrorDiagnostic(errno));
    if (S_ISDIR(st.st_mode))
        throw FileError(path, makeDiagnostic("io_directory_not_session"));
    if (!S_ISREG(st.st_mode))
        throw FileError(path, makeDiagnostic("io_not_regular_to_read"));
    if (static_cast<unsigned long long>(st.st_size) > maxBytes)
        throw FileError(path, makeDiagnostic("io_size_over_limit", {std::to_string(st.st_size),
                                                                    std::to_string(maxBytes)}));
    // The size can change while reading: read at most maxBytes + 1 to notice growth.
    const std::size_t cap = maxBytes + 1;
    std::string out;
    out.resize(std::min<std::size_t>(static_cast<std::size_t>(st.st_size), maxBytes) + 1);
    std::size_t have = 0;
    for (;;) {
        if (have == out.size()) {
            if (out.size() == cap)
                break;
            out.resize(std::min(cap, 2 * out.size()));
        }
        const ssize_t n = ::read(fd, out.data() + have, out.size() - have);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            throw FileError(path, systemErrorDiagnostic(errno));
        if (n == 0)
            break;
        have += static_cast<std::size_t>(n);
    }
    if (have > maxBytes)
        throw FileError(path, makeDiagnostic("io_larger_than_limit", {std::to_string(maxBytes)}));
    out.resize(have);
    return out;
}

} // namespace xyt
