// Every file the tools write (scenes, traces, CSVs, charts, screenshots, recordings, settings)
// goes through here, so that nothing written loses data: the bytes go to a temporary file in
// the target's own folder, which is synced and renamed over the target only when complete. A
// failed write (a full disk, a directory in the way, a folder that cannot be written) leaves the
// file that was there intact and names the target in its message. A target that is a device or
// a FIFO (/dev/null, /dev/full, a pipe) has no contents to lose: it is written in place, and a
// failure (ENOSPC on /dev/full, a FIFO without a reader) is still an error.
#pragma once

#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <system_error>

class SafeFile {
  public:
    // Opens the temporary file next to `target`; a failure is kept and reported by commit().
    explicit SafeFile(std::string target);
    ~SafeFile(); // removes the temporary file unless commit() succeeded
    SafeFile(const SafeFile&) = delete;
    SafeFile& operator=(const SafeFile&) = delete;

    // False, with commit()'s message, when the temporary file (or the device) could not be
    // opened: callers check it before long work, so that a run does not end in a lost write.
    bool opened(std::string* error = nullptr) const;
    // Where to write; writes after a failure are dropped (the stream's badbit is set).
    std::ostream& stream();
    // Flushes, syncs and renames over the target. On failure `error` (when given) reads
    // "TARGET: cannot write (REASON)", the target escaped for a terminal, and the old file stays.
    bool commit(std::string* error = nullptr);

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// The whole of `bytes` to `path` through a SafeFile.
bool writeFileSafely(const std::string& path, std::string_view bytes, std::string* error = nullptr);

// True when both paths name one existing file (same device and inode, after links): an output
// that would overwrite the input it was made from is refused by its caller.
bool sameExistingFile(const std::string& a, const std::string& b);

// Why a path whose lookup failed with `error` cannot be followed, as a message says it: "a loop
// of symbolic links (a link that leads back to itself): it names no file" for ELOOP (the system's
// "Too many levels of symbolic links" reads as if the file were there), else "cannot open the
// file: " and the system's words.
std::string unfollowablePathWhy(const std::error_code& error);
