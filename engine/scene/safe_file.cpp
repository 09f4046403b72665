#include "safe_file.h"

#include "printable.h"

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <streambuf>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace {

// A buffered stream onto a file descriptor that remembers its first error (errno).
class FdBuffer : public std::streambuf {
  public:
    explicit FdBuffer(int fd) : fd_(fd), buffer_(1 << 16) {
        setp(buffer_.data(), buffer_.data() + buffer_.size());
    }
    int error() const { return error_; }
    bool drain() {
        const char* p = pbase();
        std::size_t left = static_cast<std::size_t>(pptr() - pbase());
        while (left > 0 && error_ == 0) {
            const ssize_t n = ::write(fd_, p, left);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                error_ = n < 0 ? errno : EIO;
                break;
            }
            p += n, left -= static_cast<std::size_t>(n);
        }
        setp(buffer_.data(), buffer_.data() + buffer_.size());
        return error_ == 0;
    }

  protected:
    int_type overflow(int_type c) override {
        if (!drain()) return traits_type::eof();
        if (!traits_type::eq_int_type(c, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(c);
            pbump(1);
        }
        return traits_type::not_eof(c);
    }
    int sync() override { return drain() ? 0 : -1; }

  private:
    int fd_;
    int error_ = 0;
    std::vector<char> buffer_;
};

std::string folderOf(const std::string& path) {
    const std::size_t slash = path.rfind('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

std::string nameOf(const std::string& path) {
    const std::size_t slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

// The mode a new file gets (0666 less the umask, the owner always able to read and write it:
// emscripten's umask is 0777, its in-memory files checked against their modes), or the mode of
// the file it replaces.
mode_t modeFor(const struct stat* existing) {
    if (existing) return existing->st_mode & 07777;
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return (0666 & ~mask) | 0600;
}

} // namespace

struct SafeFile::Impl {
    std::string target;   // as given, for messages
    std::string resolved; // after symbolic links: the file that is replaced
    std::string temp;     // empty when written in place (a device or FIFO)
    int fd = -1;
    int openError = 0;
    std::string reason; // why it cannot be written, before any byte
    std::unique_ptr<FdBuffer> buffer;
    std::ostream stream{nullptr};
    bool committed = false;
};

SafeFile::SafeFile(std::string target) : impl_(std::make_unique<Impl>()) {
    Impl& f = *impl_;
    f.target = std::move(target);
    f.resolved = f.target;
    struct stat st {};
    const bool exists = ::stat(f.target.c_str(), &st) == 0;
    if (f.target.empty()) {
        f.reason = "an empty file name";
    } else if (exists && S_ISDIR(st.st_mode)) {
        f.reason = "a directory is in the way";
    } else if (exists && !S_ISREG(st.st_mode)) {
        // A device or a FIFO: written in place, without blocking on a FIFO nobody reads.
        f.fd = ::open(f.target.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
        if (f.fd < 0)
            f.openError = errno;
        else
            ::fcntl(f.fd, F_SETFL, ::fcntl(f.fd, F_GETFL) & ~O_NONBLOCK);
    } else {
        if (exists) {
            char real[PATH_MAX];
            if (::realpath(f.target.c_str(), real)) f.resolved = real;
        }
        std::string pattern = folderOf(f.resolved) + "/." + nameOf(f.resolved) + ".XXXXXX";
        std::vector<char> name(pattern.begin(), pattern.end());
        name.push_back('\0');
        f.fd = ::mkstemp(name.data());
        if (f.fd < 0) {
            f.openError = errno;
        } else {
            f.temp = name.data();
            ::fchmod(f.fd, modeFor(exists ? &st : nullptr));
        }
    }
    if (f.fd >= 0) {
        f.buffer = std::make_unique<FdBuffer>(f.fd);
        f.stream.rdbuf(f.buffer.get());
    } else {
        f.stream.setstate(std::ios::badbit);
    }
}

SafeFile::~SafeFile() {
    Impl& f = *impl_;
    if (f.fd >= 0) ::close(f.fd);
    if (!f.committed && !f.temp.empty()) ::unlink(f.temp.c_str());
}

namespace {
std::string failure(const std::string& target, const std::string& why) {
    return printable(target, kPrintablePath) + ": cannot write (" + why + ")";
}
} // namespace

bool SafeFile::opened(std::string* error) const {
    const Impl& f = *impl_;
    if (f.reason.empty() && f.openError == 0) return true;
    if (error)
        *error = failure(f.target, !f.reason.empty() ? f.reason : std::strerror(f.openError));
    return false;
}

std::ostream& SafeFile::stream() {
    return impl_->stream;
}

bool SafeFile::commit(std::string* error) {
    Impl& f = *impl_;
    if (f.committed) return true;
    if (f.fd < 0 && f.reason.empty() && f.openError == 0) f.reason = "already failed";
    int code = f.openError;
    if (f.reason.empty() && code == 0) {
        if (!f.buffer->drain() || f.stream.bad())
            code = f.buffer->error() ? f.buffer->error() : EIO;
        // fsync of a device or FIFO may say EINVAL: only a regular file's sync counts.
        if (code == 0 && !f.temp.empty() && ::fsync(f.fd) != 0) code = errno;
        if (::close(f.fd) != 0 && code == 0) code = errno;
        f.fd = -1;
        if (code == 0 && !f.temp.empty() && ::rename(f.temp.c_str(), f.resolved.c_str()) != 0)
            code = errno;
    }
    if (f.reason.empty() && code == 0) {
        f.committed = true;
        return true;
    }
    if (!f.temp.empty()) ::unlink(f.temp.c_str()), f.temp.clear(); // nothing left behind
    if (error) *error = failure(f.target, !f.reason.empty() ? f.reason : std::strerror(code));
    return false;
}

bool writeFileSafely(const std::string& path, std::string_view bytes, std::string* error) {
    SafeFile file(path);
    file.stream().write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return file.commit(error);
}

bool sameExistingFile(const std::string& a, const std::string& b) {
    struct stat sa {
    }, sb{};
    return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
           sa.st_ino == sb.st_ino;
}

std::string unfollowablePathWhy(const std::error_code& error) {
    if (error == std::errc::too_many_symbolic_link_levels)
        return "a loop of symbolic links (a link that leads back to itself): it names no file";
    return "cannot open the file: " + error.message();
}
