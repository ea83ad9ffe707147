// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/file_io.h"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <mutex>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace xyt {

FileError::FileError(std::string path, const std::string& reason)
    : std::runtime_error(path + ": " + reason), path_(std::move(path)), reason_(reason) {}

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

std::string systemReason(int error) { return std::strerror(error); }

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
            throw FileError(path, systemReason(n < 0 ? errno : EIO));
        data += n;
        size -= static_cast<std::size_t>(n);
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
        throw FileError(path, "the file name is empty");
    // Replace the target of a symbolic link, not the link; refuse anything but a regular file.
    std::string target = path;
    struct stat st {};
    mode_t mode = 0;
    bool exists = false;
    if (::stat(path.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode))
            throw FileError(path, "is a directory");
        if (!S_ISREG(st.st_mode))
            throw FileError(path, "is not a regular file (a device, FIFO or socket); refusing to replace it");
        exists = true;
        mode = st.st_mode & 07777;
        char resolved[PATH_MAX];
        if (::realpath(path.c_str(), resolved))
            target = resolved;
    } else if (errno != ENOENT) {
        throw FileError(path, systemReason(errno));
    }
    std::string name = folderOf(target) + "/.xytune-save-XXXXXX";
    const int fd = ::mkstemp(name.data());
    if (fd < 0)
        throw FileError(path, systemReason(errno));
    TemporaryFile temp(name, fd);
    if (!exists) { // what open(path, O_CREAT, 0666) would have given: 0666 less the umask
        const mode_t mask = ::umask(0);
        ::umask(mask);
        mode = 0666 & ~mask;
    }
    if (::fchmod(fd, mode) != 0)
        throw FileError(path, systemReason(errno));

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
        throw FileError(path, systemReason(failingStep() == WriteStep::Sync ? EIO : errno));
    if (temp.close() != 0)
        throw FileError(path, systemReason(errno));
    if (failingStep() == WriteStep::Rename || ::rename(name.c_str(), target.c_str()) != 0)
        throw FileError(path, systemReason(failingStep() == WriteStep::Rename ? EIO : errno));
    temp.release();
    // Make the rename itself durable; the file is complete either way, so a failure here is not
    // reported.
    const int dir = ::open(folderOf(target).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
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
        throw FileError(path, errno == ENOENT ? std::string("no such file") : systemReason(errno));
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0)
        throw FileError(path, systemReason(errno));
    if (S_ISDIR(st.st_mode))
        throw FileError(path, "is a directory, not a session file");
    if (!S_ISREG(st.st_mode))
        throw FileError(path, "is not a regular file (a device, FIFO or socket); refusing to read it");
    if (static_cast<unsigned long long>(st.st_size) > maxBytes)
        throw FileError(path, std::to_string(st.st_size) + " bytes is larger than the limit of " +
                                  std::to_string(maxBytes) + " bytes");
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
            throw FileError(path, systemReason(errno));
        if (n == 0)
            break;
        have += static_cast<std::size_t>(n);
    }
    if (have > maxBytes)
        throw FileError(path, "is larger than the limit of " + std::to_string(maxBytes) + " bytes");
    out.resize(have);
    return out;
}

} // namespace xyt
