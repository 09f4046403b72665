// SafeFile (engine/scene/safe_file.h): a file written completely or not at all. Each failure
// below is one a root user meets too (CI runs as root, so permissions cannot make one): a full
// device, a directory in the way, a path under a regular file, a file-size limit mid-write.
#include "safe_file.h"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

// A fresh folder per test, removed after.
struct Folder {
    fs::path path;
    explicit Folder(const std::string& name) {
        path = fs::temp_directory_path() / ("safe_file_" + name + "_" + std::to_string(getpid()));
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~Folder() { fs::remove_all(path); }
    std::string operator/(const std::string& name) const { return (path / name).string(); }
};

std::string readAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Only the target is in the folder afterwards: no temporary file left behind.
std::size_t entries(const Folder& folder) {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(folder.path), {}));
}

} // namespace

TEST(SafeFile, WritesAndReplaces) {
    Folder folder("writes");
    const std::string target = folder / "out.csv";
    ASSERT_TRUE(writeFileSafely(target, "first\n"));
    ASSERT_TRUE(writeFileSafely(target, "second\n"));
    EXPECT_EQ(readAll(target), "second\n");
    EXPECT_EQ(entries(folder), 1u);
}

TEST(SafeFile, KeepsTheModeOfTheFileItReplaces) {
    Folder folder("mode");
    const std::string target = folder / "out.txt";
    std::ofstream(target) << "old";
    ASSERT_EQ(chmod(target.c_str(), 0640), 0);
    ASSERT_TRUE(writeFileSafely(target, "new"));
    struct stat st {};
    ASSERT_EQ(stat(target.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0640u);
}

TEST(SafeFile, FullDiskFailsNamingTheFile) {
    std::string error;
    EXPECT_FALSE(writeFileSafely("/dev/full", "bytes", &error));
    EXPECT_NE(error.find("/dev/full: cannot write (No space left on device)"), std::string::npos)
        << error;
}

TEST(SafeFile, DeviceIsWrittenInPlace) {
    // /dev/null is not replaced by a regular file (it has no contents to lose).
    ASSERT_TRUE(writeFileSafely("/dev/null", "bytes"));
    struct stat st {};
    ASSERT_EQ(stat("/dev/null", &st), 0);
    EXPECT_TRUE(S_ISCHR(st.st_mode));
}

TEST(SafeFile, FifoWithoutReaderFailsAtOnce) {
    Folder folder("fifo");
    const std::string fifo = folder / "pipe";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    std::string error;
    EXPECT_FALSE(writeFileSafely(fifo, "bytes", &error)); // ENXIO, without blocking
    EXPECT_NE(error.find("pipe: cannot write"), std::string::npos) << error;
}

TEST(SafeFile, DirectoryInTheWay) {
    Folder folder("dir");
    fs::create_directory(folder.path / "out.png");
    std::string error;
    EXPECT_FALSE(writeFileSafely(folder / "out.png", "bytes", &error));
    EXPECT_NE(error.find("out.png: cannot write (a directory is in the way)"), std::string::npos)
        << error;
    EXPECT_TRUE(fs::is_directory(folder.path / "out.png"));
}

TEST(SafeFile, PathUnderARegularFile) {
    Folder folder("notdir");
    const std::string file = folder / "scene.json";
    std::ofstream(file) << "{}";
    std::string error;
    EXPECT_FALSE(writeFileSafely(file + "/trace.csv", "bytes", &error));
    EXPECT_NE(error.find("scene.json/trace.csv: cannot write (Not a directory)"), std::string::npos)
        << error;
    EXPECT_EQ(readAll(file), "{}");
}

TEST(SafeFile, MissingFolder) {
    std::string error;
    EXPECT_FALSE(writeFileSafely("/nonexistent-dir/x/out.csv", "bytes", &error));
    EXPECT_NE(error.find("/nonexistent-dir/x/out.csv: cannot write (No such file or directory)"),
              std::string::npos)
        << error;
}

TEST(SafeFile, FailedWriteKeepsTheOldFile) {
    // A write that fails halfway (a file-size limit: EFBIG, as a disk filling up would give
    // ENOSPC) leaves the old file whole and no temporary file.
    Folder folder("midway");
    const std::string target = folder / "trace.csv";
    std::ofstream(target) << "the old trace\n";
    rlimit old{};
    ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
    const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit small = old;
    small.rlim_cur = 4096;
    ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
    SafeFile file(target);
    ASSERT_TRUE(file.opened());
    for (int i = 0; i < 100000; ++i) file.stream() << "0.1,2.3,4.5\n";
    std::string error;
    const bool written = file.commit(&error);
    setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, oldHandler);
    EXPECT_FALSE(written);
    EXPECT_NE(error.find("trace.csv: cannot write (File too large)"), std::string::npos) << error;
    EXPECT_EQ(readAll(target), "the old trace\n");
    EXPECT_EQ(entries(folder), 1u);
}

TEST(SafeFile, AbandonedWriteLeavesNothing) {
    Folder folder("abandoned");
    {
        SafeFile file(folder / "out.csv");
        file.stream() << "half";
    } // never committed: as a run interrupted before its end
    EXPECT_EQ(entries(folder), 0u);
}

TEST(SafeFile, ControlBytesInTheNameAreEscaped) {
    std::string error;
    EXPECT_FALSE(writeFileSafely("/nonexistent-dir/\x1b]0;owned\x07.csv", "x", &error));
    EXPECT_EQ(error.find('\x1b'), std::string::npos) << error;
    EXPECT_NE(error.find("\\x1b]0;owned\\x07.csv"), std::string::npos) << error;
}

TEST(SafeFile, SameExistingFile) {
    Folder folder("same");
    const std::string a = folder / "a.json";
    std::ofstream(a) << "{}";
    fs::create_symlink(a, folder.path / "link.json");
    EXPECT_TRUE(sameExistingFile(a, folder / "link.json"));
    EXPECT_TRUE(sameExistingFile(a, folder.path.string() + "/./a.json"));
    EXPECT_FALSE(sameExistingFile(a, folder / "b.json")); // not there: nothing to overwrite
}

TEST(SafeFile, SymbolicLinkTargetReplacesTheFileItNames) {
    Folder folder("symlink");
    const std::string real = folder / "real.csv";
    std::ofstream(real) << "old";
    fs::create_symlink(real, folder.path / "link.csv");
    ASSERT_TRUE(writeFileSafely(folder / "link.csv", "new"));
    EXPECT_TRUE(fs::is_symlink(folder.path / "link.csv"));
    EXPECT_EQ(readAll(real), "new");
}

TEST(SafeFile, NewFileIsTheOwnersWhateverTheUmask) {
    // Emscripten's umask is 0777: a new file must still be readable by its owner (the browser's
    // download reads it back).
    Folder folder("umask");
    const mode_t old = umask(0777);
    const bool written = writeFileSafely(folder / "new.json", "{}");
    umask(old);
    ASSERT_TRUE(written);
    struct stat st {};
    ASSERT_EQ(stat((folder / "new.json").c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0600, 0600u);
    EXPECT_EQ(readAll(folder / "new.json"), "{}");
}
